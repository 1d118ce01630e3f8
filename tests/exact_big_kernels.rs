//! The big-number kernels — eval by binary splitting, elevation and the first derivative on
//! words, `from_power`, and the rational and surface points and the rational derivative
//! built on them — against the
//! step-by-step references with `==` and in lowest terms, on the inputs they exist for:
//! 30-digit rationals each with its own denominator, negative values, zero coordinates,
//! coordinates sharing one long denominator, and parameters 0, 1, outside [0, 1], with 20
//! digits or with a huge denominator.
//!
//! Above degree 20 the reference for eval is an independent nested sum over the lcm of the
//! denominators, reduced by num-rational itself (`BigRational::new`): de Casteljau's steps
//! on `BigRational` take minutes there.

use casteljau::{BezierCurve, BezierSurface, BigInt, BigRational, Point, RationalBezierCurve};
use num_integer::Integer;
use num_traits::{One, Zero};
use proptest::prelude::*;
use proptest::test_runner::Config;

type Q = BigRational;

/// Equal and in the same form (`Debug` shows numerator and denominator).
fn same<X: PartialEq + std::fmt::Debug>(a: &X, b: &X) -> bool {
    a == b && format!("{a:?}") == format!("{b:?}")
}

fn ten_to(k: u32) -> u128 {
    10u128.pow(k)
}

/// A 30-digit numerator (or fewer, or zero) over a 30-digit denominator, any sign.
fn thirty_digits() -> impl Strategy<Value = Q> {
    (any::<u128>(), any::<u128>(), any::<bool>()).prop_map(|(a, b, negative)| {
        let num = BigInt::from(a % ten_to(30));
        let den = BigInt::from(ten_to(29) + b % (9 * ten_to(29)));
        Q::new(if negative { -num } else { num }, den)
    })
}

/// One coordinate: mostly 30-digit fractions, sometimes zero, a small integer, or a value
/// over the curve's shared denominator `shared`.
fn coordinate(shared: BigInt) -> impl Strategy<Value = Q> {
    prop_oneof![
        6 => thirty_digits(),
        1 => Just(Q::zero()),
        1 => (-50i64..=50).prop_map(|k| Q::from_integer(k.into())),
        2 => any::<i128>().prop_map(move |k| Q::new(k.into(), shared.clone())),
    ]
}

/// Curves of the given degrees, in 1 or 2 dimensions; with `all_shared`, every coordinate
/// is over one 30-digit denominator (the elevation's gcd of two denominators is then that
/// whole denominator, and the eval kernel puts the numerators over it).
fn big_curve(degrees: &'static [usize]) -> impl Strategy<Value = BezierCurve<Q>> {
    (
        proptest::sample::select(degrees),
        1..=2usize,
        any::<u128>(),
        any::<bool>(),
    )
        .prop_flat_map(|(n, dim, shared, all_shared)| {
            let shared = BigInt::from(ten_to(29) + shared % (9 * ten_to(29)));
            let coordinate = if all_shared {
                any::<i128>()
                    .prop_map(move |k| Q::new(k.into(), shared.clone()))
                    .boxed()
            } else {
                coordinate(shared).boxed()
            };
            proptest::collection::vec(proptest::collection::vec(coordinate, dim), n + 1)
                .prop_map(|points| BezierCurve::from_coords(points).unwrap())
        })
}

/// Parameters: 0, 1, 20-digit ones in (0, 1), outside [0, 1], and huge denominators.
fn parameter() -> impl Strategy<Value = Q> {
    prop_oneof![
        1 => Just(Q::zero()),
        1 => Just(Q::one()),
        4 => (any::<u64>(), any::<u64>()).prop_map(|(a, b)| {
            let q = u128::from(b) % (9 * ten_to(19)) + ten_to(19) + 1;
            Q::new(BigInt::from(u128::from(a) % q), BigInt::from(q))
        }),
        2 => (-40i64..=40, 1i64..=13).prop_map(|(p, q)| Q::new(p.into(), q.into())),
        1 => (any::<u64>(), 0u32..300).prop_map(|(a, k)| Q::new(BigInt::from(a), (BigInt::one() << 200) + k)),
        1 => thirty_digits(),
    ]
}

/// `Σ C(n,i) pⁱ (q−p)^(n−i) x_i / qⁿ` by the nested sum over the lcm of the denominators,
/// reduced by `BigRational::new`: nothing of casteljau's.
fn nested_reference(c: &BezierCurve<Q>, t: &Q) -> Point<Q> {
    let n = c.degree();
    let (p, q) = (t.numer(), t.denom());
    let s = q - p;
    let coords = (0..c.dim())
        .map(|k| {
            let values: Vec<&Q> = c.points().iter().map(|pt| &pt.coords()[k]).collect();
            let l = values.iter().fold(BigInt::one(), |l, v| l.lcm(v.denom()));
            let mut acc = BigInt::zero();
            let mut binomial = BigInt::one();
            for (i, v) in values.iter().enumerate() {
                if i > 0 {
                    binomial = binomial * (n - i + 1) / i;
                }
                let x = v.numer() * (&l / v.denom());
                acc = acc * &s + &binomial * num_traits::pow(p.clone(), i) * x;
            }
            // The nested sum above weighs term i by s^(n−i) through the accumulator.
            Q::new(acc, l * num_traits::pow(q.clone(), n))
        })
        .collect();
    Point::new(coords).unwrap()
}

proptest! {
    #![proptest_config(Config::with_cases(160))]

    #[test]
    fn eval_by_binary_splitting(c in big_curve(&[0, 1, 2, 3, 7, 20]), t in parameter()) {
        let fast = c.eval(&t);
        prop_assert!(same(&fast, &nested_reference(&c, &t)));
        if c.degree() <= 7 {
            prop_assert!(same(&fast, &c.eval_reference(&t)));
        }
        prop_assert!(same(&c.eval_nested(&t), &fast));
    }

    #[test]
    fn elevation_on_words(c in big_curve(&[0, 1, 2, 3, 20])) {
        let reference = c.elevate_reference().unwrap();
        prop_assert!(same(&c.elevate().unwrap(), &reference));
        prop_assert!(same(&c.elevate_fraction_free().unwrap(), &reference));
    }

    /// Power coefficients by integer differences over the lcm, against the differences on
    /// `BigRational`, and summed at `t` against the curve's point.
    #[test]
    fn power_basis(c in big_curve(&[0, 1, 2, 3, 7, 20]), t in parameter()) {
        let fast = c.to_power().unwrap();
        prop_assert!(same(&fast, &c.to_power_reference().unwrap()));
        let mut sum = Point::origin(c.dim());
        let mut power = Q::one();
        for a in &fast {
            sum = sum.add(&a.scale(&power));
            power *= &t;
        }
        prop_assert!(same(&sum, &c.eval(&t)));
    }

    /// The net's power coefficients (columns, then rows) against the same on `BigRational`:
    /// rows are a curve's points scaled and shifted, so columns differ too.
    #[test]
    fn net_power_basis(c in big_curve(&[0, 1, 3, 6]), rows in 1..=4usize, shift in thirty_digits()) {
        let net: Vec<Vec<Point<Q>>> = (0..rows)
            .map(|r| c.points().iter().map(|p| {
                let s = p.scale(&Q::new(BigInt::from(r as u64 + 2), BigInt::from(r as u64 * 3 + 1)));
                Point::new(s.coords().iter().map(|x| x + &shift * Q::from_integer(BigInt::from(r as u64))).collect()).unwrap()
            }).collect())
            .collect();
        let surface = BezierSurface::new(net).unwrap();
        prop_assert!(same(&surface.to_power().unwrap(), &surface.to_power_reference().unwrap()));
    }

    /// Nets of 30-digit fractions, each over its own denominator (or zero, small integers,
    /// a shared denominator), at independent `u` and `v`, against the Bernstein double sum
    /// on `BigRational`.
    #[test]
    fn net_points(
        net in (1..=4usize, 1..=5usize, any::<u128>()).prop_flat_map(|(rows, columns, shared)| {
            let shared = BigInt::from(ten_to(29) + shared % (9 * ten_to(29)));
            proptest::collection::vec(proptest::collection::vec(proptest::collection::vec(coordinate(shared), 2), columns), rows)
        }),
        u in parameter(),
        v in parameter(),
    ) {
        let surface = BezierSurface::new(net.into_iter().map(|row| row.into_iter().map(|p| Point::new(p).unwrap()).collect()).collect()).unwrap();
        prop_assert!(same(&surface.eval(&u, &v), &surface.eval_bernstein(&u, &v)));
    }

    #[test]
    fn split_of_big_numbers(c in big_curve(&[0, 1, 2, 3, 6]), t in parameter()) {
        prop_assert!(same(&c.split_at(&t), &c.split_at_reference(&t)));
    }
}

proptest! {
    #![proptest_config(Config::with_cases(40))]

    /// The hodograph combines neighbours pairwise on words (derivative 1); its point at t
    /// from degree 64 on is that hodograph's point.
    #[test]
    fn first_derivative_pairwise(c in big_curve(&[1, 2, 3, 20]), t in parameter()) {
        let reference = c.derivative_reference(1).unwrap();
        prop_assert!(same(&c.derivative(1).unwrap(), &reference));
        prop_assert!(same(&c.derivative_at(1, &t).unwrap(), &reference.eval_reference(&t)));
    }

    /// The rational curve's point (nested sum below degree 64) and the surface's point (its
    /// columns by the curve kernels) against the step-by-step references.
    #[test]
    fn rational_and_surface_points(c in big_curve(&[1, 2, 3, 7]), weights in proptest::collection::vec(1u64.., 8), t in parameter()) {
        let w: Vec<Q> = c.points().iter().zip(&weights).map(|(_, &w)| Q::new(BigInt::from(w), BigInt::from(w % 97 + 1))).collect();
        let rational = RationalBezierCurve::new(c.points().to_vec(), w).unwrap();
        prop_assert!(same(&rational.eval(&t).ok(), &rational.eval_reference(&t).ok()));
        let rows: Vec<Vec<Point<Q>>> = (0..3).map(|r| c.points().iter().map(|p| p.scale(&Q::from_integer(BigInt::from(r + 1)))).collect()).collect();
        let surface = BezierSurface::new(rows).unwrap();
        prop_assert!(same(&surface.eval(&t, &t), &surface.eval_bernstein(&t, &t)));
    }
}

/// `b_j = Σ_{i≤j} C(j,i)/C(n,i) a_i` per coordinate on num-rational: nothing of casteljau's.
fn from_power_reference(coeffs: &[Point<Q>]) -> Vec<Point<Q>> {
    let n = coeffs.len() - 1;
    let binomial = |n: usize, k: usize| (0..k).fold(BigInt::one(), |c, i| c * (n - i) / (i + 1));
    (0..=n)
        .map(|j| {
            let coords = (0..coeffs[0].dim())
                .map(|k| {
                    (0..=j).fold(Q::zero(), |acc, i| {
                        acc + Q::new(binomial(j, i), binomial(n, i)) * &coeffs[i].coords()[k]
                    })
                })
                .collect();
            Point::new(coords).unwrap()
        })
        .collect()
}

proptest! {
    #![proptest_config(Config::with_cases(60))]

    /// Newton's forward formula over prefix lcms, reduced against the primes that can
    /// cancel, against the plain sum; and back by `to_power`.
    #[test]
    fn from_power_over_integers(c in big_curve(&[0, 1, 2, 3, 7, 20])) {
        let coeffs = c.points();
        let fast = BezierCurve::from_power(coeffs).unwrap();
        let expected = from_power_reference(coeffs);
        prop_assert!(same(&fast.points().to_vec(), &expected));
        prop_assert!(same(&fast.to_power().unwrap(), &coeffs.to_vec()));
    }

    /// The rational curve's derivative vector from the two points of the last-but-one
    /// column against de Casteljau's steps, weights of both signs (and so vanishing
    /// denominators) included, short or 30-digit fractions each over its own denominator.
    #[test]
    fn rational_derivative_at(
        c in big_curve(&[1, 2, 3, 7, 20]),
        weights in proptest::collection::vec((-3i64..=3, 1u64.., thirty_digits()), 21),
        long_weights in any::<bool>(),
        t in parameter(),
    ) {
        let w: Vec<Q> = c.points().iter().zip(&weights).map(|(_, (sign, w, long))| {
            let w = if long_weights && !long.is_zero() {
                num_traits::Signed::abs(long)
            } else {
                Q::new(BigInt::from(*w), BigInt::from(w % 97 + 1))
            };
            if *sign < 0 { -w } else { w }
        }).collect();
        let Ok(rational) = RationalBezierCurve::new(c.points().to_vec(), w) else { return Ok(()) };
        let fast = rational.derivative_at(&t);
        let reference = rational.derivative_at_reference(&t);
        prop_assert_eq!(fast.is_ok(), reference.is_ok());
        prop_assert!(same(&fast.ok(), &reference.ok()));
    }
}

/// Inputs a wrong kernel gets wrong: a vanishing `w(t)` (weights 1, −1 at t = 1/2) is the
/// reference's error; points over one shared denominator and over coprime ones give the
/// reference's reduced vector; `from_power` of `t^n` is `0, …, 0, 1`.
#[test]
fn rational_derivative_and_from_power_edges() {
    let q = |a: i64, b: i64| Q::new(a.into(), b.into());
    let line = RationalBezierCurve::new(
        vec![Point::new(vec![q(0, 1)]).unwrap(), Point::new(vec![q(1, 1)]).unwrap()],
        vec![q(1, 1), q(-1, 1)],
    )
    .unwrap();
    assert!(line.derivative_at(&q(1, 2)).is_err());
    assert!(line.derivative_at_reference(&q(1, 2)).is_err());
    let shared = RationalBezierCurve::new(
        vec![
            Point::new(vec![q(1, 6), q(-5, 6)]).unwrap(),
            Point::new(vec![q(7, 6), q(0, 1)]).unwrap(),
            Point::new(vec![q(-1, 6), q(5, 6)]).unwrap(),
        ],
        vec![q(2, 3), q(1, 9), q(4, 5)],
    )
    .unwrap();
    for t in [q(0, 1), q(1, 1), q(1, 3), q(-2, 7), q(9, 4)] {
        assert!(same(
            &shared.derivative_at(&t).unwrap(),
            &shared.derivative_at_reference(&t).unwrap()
        ));
    }
    let n = 9;
    let mut coeffs = vec![Point::new(vec![q(0, 1)]).unwrap(); n + 1];
    coeffs[n] = Point::new(vec![q(1, 1)]).unwrap();
    let curve = BezierCurve::from_power(&coeffs).unwrap();
    let expected: Vec<Point<Q>> = (0..=n)
        .map(|i| Point::new(vec![q(i64::from(i == n), 1)]).unwrap())
        .collect();
    assert!(same(&curve.points().to_vec(), &expected));
}

proptest! {
    #![proptest_config(Config::with_cases(6))]

    #[test]
    fn degree_200_derivatives_and_rational_point(c in big_curve(&[70, 200]), t in parameter()) {
        let hodograph = c.derivative_reference(1).unwrap();
        prop_assert!(same(&c.derivative(1).unwrap(), &hodograph));
        prop_assert!(same(&c.derivative_at(1, &t).unwrap(), &nested_reference(&hodograph, &t)));
        let w: Vec<Q> = (0..=c.degree()).map(|i| Q::new(BigInt::from(i as u64 * 7 + 3), BigInt::from(i as u64 % 5 + 2))).collect();
        let rational = RationalBezierCurve::new(c.points().to_vec(), w).unwrap();
        // Independent: the homogeneous point by the test's own nested sum, divided by
        // num-rational.
        let h = nested_reference(&rational.lift(), &t);
        let (w, x) = h.coords().split_last().unwrap();
        let expected = (!w.is_zero()).then(|| Point::new(x.iter().map(|c| c / w).collect()).unwrap());
        prop_assert!(same(&rational.eval(&t).ok(), &expected));
    }

    #[test]
    fn degree_200(c in big_curve(&[200]), t in parameter()) {
        prop_assert!(same(&c.eval(&t), &nested_reference(&c, &t)));
        prop_assert!(same(&c.elevate().unwrap(), &c.elevate_reference().unwrap()));
        prop_assert!(same(&c.to_power().unwrap(), &c.to_power_reference().unwrap()));
        let coeffs = c.points();
        prop_assert!(same(&BezierCurve::from_power(coeffs).unwrap().to_power().unwrap(), &coeffs.to_vec()));
    }
}

/// The bench's case shape at degree 1000: splitmix-drawn 30-digit fractions, a 20-digit t.
#[test]
fn degree_1000_eval() {
    let mut state = 7u64;
    let mut next = move || {
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        u128::from(z ^ (z >> 31))
    };
    let mut digits = |k: u32| ten_to(k - 1) + ((next() << 64) | next()) % (9 * ten_to(k - 1));
    let coords: Vec<Vec<Q>> = (0..=1000)
        .map(|i| {
            (0..2)
                .map(|k| {
                    let num = BigInt::from(digits(30));
                    let num = if (i + k) % 3 == 0 { -num } else { num };
                    Q::new(num, BigInt::from(digits(30)))
                })
                .collect()
        })
        .collect();
    let c = BezierCurve::from_coords(coords).unwrap();
    let (p, q) = (digits(20), digits(20));
    let t = Q::new(BigInt::from(p.min(q)), BigInt::from(p.max(q) + 1));
    assert!(same(&c.eval(&t), &nested_reference(&c, &t)));
}

/// Denominators sharing a factor wider than 32 bits, and inputs wider than the 110 bits the
/// word path takes: the elevation's big-integer path, coordinate by coordinate.
#[test]
fn elevation_beyond_words() {
    let wide = BigInt::from(ten_to(35)) + BigInt::from(7);
    let shared = BigInt::from(4_294_967_311u64) * BigInt::from(4_294_967_357u64);
    let coords = vec![
        vec![
            Q::new(BigInt::from(3), shared.clone() * BigInt::from(5)),
            Q::new(wide.clone(), BigInt::from(7)),
        ],
        vec![
            Q::new(BigInt::from(-11), shared.clone() * BigInt::from(6)),
            Q::new(BigInt::from(1), wide.clone()),
        ],
        vec![
            Q::new(BigInt::from(13), shared.clone()),
            Q::new(BigInt::from(-2), BigInt::from(9)),
        ],
        vec![
            Q::new(BigInt::from(2), BigInt::from(3)),
            Q::new(-wide.clone(), BigInt::from(5)),
        ],
    ];
    let c = BezierCurve::from_coords(coords).unwrap();
    assert!(same(&c.elevate().unwrap(), &c.elevate_reference().unwrap()));
    let t = Q::new(BigInt::from(5), BigInt::from(9));
    assert!(same(&c.eval(&t), &c.eval_reference(&t)));
}
