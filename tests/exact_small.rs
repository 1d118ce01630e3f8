//! The small-number paths of the exact kernels against independent references with `==` and
//! in lowest terms: eval's nested sum on a fraction on big integers (chosen over binary
//! splitting while the denominators and the powers of `t`'s denominator stay short; equal
//! neighbouring denominators multiplied in once) and the subdivision that copies its end
//! points and reduces its middle point once.
//!
//! Curves of degree 0 to 60 whose coordinates have 1- to 6-digit denominators (so that both
//! sides of the nested sum's threshold are reached: 61 five-digit denominators are past it),
//! some 30-digit ones, zeros, integers, negative values; parameters 0, 1, small fractions
//! inside and outside [0, 1] (negative too), 20-digit ones and huge denominators. Surfaces
//! of such nets, whose point is summed row by row when the rows' denominators are words.

use casteljau::{BezierCurve, BezierSurface, BigInt, BigRational, Point};
use num_integer::Integer;
use num_traits::{One, Zero};
use proptest::prelude::*;
use proptest::test_runner::Config;

type Q = BigRational;

/// Equal and in the same form (`Debug` shows numerator and denominator).
fn same<X: PartialEq + std::fmt::Debug>(a: &X, b: &X) -> bool {
    a == b && format!("{a:?}") == format!("{b:?}")
}

/// A numerator of up to `digits` digits over a denominator of `digits` digits, any sign.
fn fraction(digits: u32) -> impl Strategy<Value = Q> {
    let top = 10u128.pow(digits);
    (any::<u128>(), any::<u128>(), any::<bool>()).prop_map(move |(a, b, negative)| {
        let num = BigInt::from(a % top);
        let den = BigInt::from(top / 10 + b % (top - top / 10));
        Q::new(if negative { -num } else { num }, den)
    })
}

fn coordinate() -> impl Strategy<Value = Q> {
    prop_oneof![
        8 => (1u32..=6).prop_flat_map(fraction),
        1 => fraction(30),
        1 => Just(Q::zero()),
        1 => (-50i64..=50).prop_map(|k| Q::from_integer(k.into())),
    ]
}

/// Curves of `n + 1` points of `dim` coordinates drawn from `value`.
fn curve_of<S: Strategy<Value = Q>>(value: S, n: usize, dim: usize) -> impl Strategy<Value = BezierCurve<Q>> {
    proptest::collection::vec(proptest::collection::vec(value, dim), n + 1)
        .prop_map(|points| BezierCurve::from_coords(points).unwrap())
}

fn curve(max_degree: usize) -> impl Strategy<Value = BezierCurve<Q>> {
    (0..=max_degree, 1..=2usize).prop_flat_map(|(n, dim)| curve_of(coordinate(), n, dim))
}

/// Three denominators `10^digits / 7 + seed` and 1.
fn denominator_pool(digits: impl Strategy<Value = u32>) -> impl Strategy<Value = Vec<BigInt>> {
    proptest::collection::vec((digits, any::<u32>()), 3).prop_map(|seeds| {
        let mut pool: Vec<BigInt> = seeds
            .into_iter()
            .map(|(digits, seed)| num_traits::pow(BigInt::from(10), digits as usize) / 7 + seed)
            .collect();
        pool.push(BigInt::one());
        pool
    })
}

fn parameter() -> impl Strategy<Value = Q> {
    prop_oneof![
        1 => Just(Q::zero()),
        1 => Just(Q::one()),
        4 => (-40i64..=40, 1i64..=13).prop_map(|(p, q)| Q::new(p.into(), q.into())),
        2 => (any::<u64>(), any::<u64>()).prop_map(|(a, b)| {
            let q = u128::from(b) % (9 * 10u128.pow(19)) + 10u128.pow(19) + 1;
            Q::new(BigInt::from(u128::from(a) % q), BigInt::from(q))
        }),
        1 => (any::<i64>(), 0u32..300).prop_map(|(a, k)| Q::new(BigInt::from(a), (BigInt::one() << 200) + k)),
    ]
}

/// `Σ C(n,i) pⁱ (q−p)^(n−i) x_i / qⁿ` over the lcm of the denominators, reduced by
/// `BigRational::new`: nothing of casteljau's.
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
                acc = acc * &s + &binomial * num_traits::pow(p.clone(), i) * (v.numer() * (&l / v.denom()));
            }
            Q::new(acc, l * num_traits::pow(q.clone(), n))
        })
        .collect();
    Point::new(coords).unwrap()
}

proptest! {
    #![proptest_config(Config::with_cases(200))]

    #[test]
    fn eval_of_small_numbers(c in curve(60), t in parameter()) {
        let fast = c.eval(&t);
        prop_assert!(same(&fast, &nested_reference(&c, &t)));
        if c.degree() <= 8 {
            prop_assert!(same(&fast, &c.eval_reference(&t)));
        }
        prop_assert!(same(&c.eval_nested(&t), &fast));
    }

    #[test]
    fn split_of_small_numbers(c in curve(8), t in parameter()) {
        let (left, right) = c.split_at(&t);
        prop_assert!(same(&(left.clone(), right.clone()), &c.split_at_reference(&t)));
        // The halves meet at b(t) and keep the curve's end points.
        prop_assert!(same(&left.points()[c.degree()], &c.eval(&t)));
        prop_assert!(same(&left.points()[0], &c.points()[0]));
        prop_assert!(same(&right.points()[c.degree()], &c.points()[c.degree()]));
    }
}

/// Denominators from a pool of four (1 among them), so that runs of equal neighbours, ones
/// between equal ones and repeats far apart all occur, of 1 to 300 digits.
fn pooled_curve() -> impl Strategy<Value = BezierCurve<Q>> {
    // Both kernels' paths: denominators and numerators within 62 bits (steps on words) or not.
    let pool = denominator_pool(prop_oneof![1u32..=17, 1u32..=300]);
    (pool, 0..=70usize, 1..=2usize).prop_flat_map(|(pool, n, dim)| {
        let value = (0..4usize, any::<i32>(), prop_oneof![Just(0u32), 0u32..40]).prop_map(move |(k, a, digits)| {
            Q::new(
                BigInt::from(a) * num_traits::pow(BigInt::from(10), digits as usize),
                pool[k].clone(),
            )
        });
        curve_of(value, n, dim)
    })
}

/// Parameters with a short, a 20-digit or a 100-digit denominator, and long numerators.
fn wide_parameter() -> impl Strategy<Value = Q> {
    prop_oneof![
        1 => Just(Q::zero()),
        1 => Just(Q::one()),
        3 => (-40i64..=40, 1i64..=13).prop_map(|(p, q)| Q::new(p.into(), q.into())),
        2 => (any::<i64>(), prop_oneof![Just(20usize), Just(100)], any::<u64>()).prop_map(|(a, digits, b)| {
            Q::new(BigInt::from(a) << 40, num_traits::pow(BigInt::from(10), digits) + b)
        }),
    ]
}

/// Curves whose sum runs on words in the fraction kernel: denominators of 14 to 17 digits
/// from a pool (runs of equal neighbours; their product past 160 bits), short numerators.
fn word_step_curve() -> impl Strategy<Value = BezierCurve<Q>> {
    let pool = denominator_pool(14u32..=17);
    (pool, 2..=24usize, 1..=2usize).prop_flat_map(|(pool, n, dim)| {
        let value = (prop_oneof![0..3usize, 0..4usize], any::<i16>())
            .prop_map(move |(k, a)| Q::new(BigInt::from(a), pool[k].clone()));
        curve_of(value, n, dim)
    })
}

proptest! {
    #![proptest_config(Config::with_cases(150))]

    #[test]
    fn eval_with_shared_denominators(c in pooled_curve(), t in wide_parameter()) {
        prop_assert!(same(&c.eval(&t), &nested_reference(&c, &t)));
    }

    #[test]
    fn eval_on_words_with_shared_denominators(
        c in word_step_curve(),
        p in prop_oneof![Just(-1i64), Just(1), Just(2)],
        q in prop_oneof![Just(2i64), Just(3), Just(5), Just(7)],
    ) {
        let t = Q::new(p.into(), q.into());
        prop_assert!(same(&c.eval(&t), &nested_reference(&c, &t)));
    }
}

/// The grid's cells on both sides of the nested sum's threshold: 5-digit denominators at
/// `t = 1/3` up to degree 60, at a 20-digit `t`, 30-digit ones at degrees 3 and 5.
#[test]
fn both_sides_of_the_nested_threshold() {
    let t_small = Q::new(1.into(), 3.into());
    let t_long = Q::new(
        BigInt::from(12_345_678_901_234_567_891u128),
        BigInt::from(98_765_432_109_876_543_211u128),
    );
    for (digits, degrees) in [(5u32, &[3usize, 5, 20, 50, 60][..]), (30, &[3, 5, 20][..])] {
        for &n in degrees {
            // Deterministic coordinates of `digits` digits, alternating signs.
            let points: Vec<Vec<Q>> = (0..=n)
                .map(|i| {
                    (0..2)
                        .map(|k| {
                            let top = 10u128.pow(digits);
                            let den = top / 10 + (i as u128 * 7919 + k * 104_729 + 1) * 6_700_417 % (top - top / 10);
                            let num = BigInt::from((i as u128 * 15_485_863 + k + 3) % top);
                            Q::new(if (i + k as usize) % 2 == 0 { -num } else { num }, BigInt::from(den))
                        })
                        .collect()
                })
                .collect();
            let c = BezierCurve::from_coords(points).unwrap();
            for t in [&t_small, &t_long, &Q::new((-7).into(), 2.into())] {
                assert!(
                    same(&c.eval(t), &nested_reference(&c, t)),
                    "{digits} digits, degree {n}, t = {t}"
                );
            }
        }
    }
}

/// A net's point by [`nested_reference`] on each row at `v`, then on their column at `u`.
fn net_reference(net: &[Vec<Point<Q>>], u: &Q, v: &Q) -> Point<Q> {
    let column: Vec<Point<Q>> = net
        .iter()
        .map(|row| nested_reference(&BezierCurve::new(row.clone()).unwrap(), v))
        .collect();
    nested_reference(&BezierCurve::new(column).unwrap(), u)
}

fn net(max_degree: usize) -> impl Strategy<Value = Vec<Vec<Point<Q>>>> {
    (0..=max_degree, 0..=max_degree, 1..=2usize).prop_flat_map(|(m, n, dim)| {
        let point = proptest::collection::vec(coordinate(), dim).prop_map(|c| Point::new(c).unwrap());
        proptest::collection::vec(proptest::collection::vec(point, n + 1), m + 1)
    })
}

proptest! {
    #![proptest_config(Config::with_cases(120))]

    #[test]
    fn surface_of_small_numbers(net in net(6), u in parameter(), v in parameter()) {
        let surface = BezierSurface::new(net.clone()).unwrap();
        let fast = surface.eval(&u, &v);
        prop_assert!(same(&fast, &net_reference(&net, &u, &v)));
        prop_assert!(same(&fast, &surface.eval_bernstein(&u, &v)));
    }
}

/// Nets of 5-digit denominators of degree (20, 20) and (20, 3), past machine words: summed row
/// by row at `t = 1/3` and `-7/2`, by `net_sum` with a 20-digit parameter.
#[test]
fn nets_past_machine_words() {
    let t_long = Q::new(
        BigInt::from(12_345_678_901_234_567_891u128),
        BigInt::from(98_765_432_109_876_543_211u128),
    );
    for (m, n) in [(20usize, 20usize), (20, 3), (3, 20)] {
        let net: Vec<Vec<Point<Q>>> = (0..=m)
            .map(|i| {
                (0..=n)
                    .map(|j| {
                        let coords = (0..2u128)
                            .map(|k| {
                                let den = 10_000 + ((i * 31 + j) as u128 * 7919 + k * 104_729 + 1) * 6_700_417 % 90_000;
                                let num = BigInt::from(((i * 31 + j) as u128 * 15_485_863 + k + 3) % 100_000);
                                Q::new(if (i + j) % 2 == 0 { -num } else { num }, BigInt::from(den))
                            })
                            .collect();
                        Point::new(coords).unwrap()
                    })
                    .collect()
            })
            .collect();
        let surface = BezierSurface::new(net.clone()).unwrap();
        for (u, v) in [
            (Q::new(1.into(), 3.into()), Q::new(1.into(), 3.into())),
            (Q::new((-7).into(), 2.into()), Q::new(2.into(), 5.into())),
            (Q::new(1.into(), 3.into()), t_long.clone()),
            (t_long.clone(), Q::new(1.into(), 3.into())),
        ] {
            assert!(
                same(&surface.eval(&u, &v), &net_reference(&net, &u, &v)),
                "({m}, {n}) at ({u}, {v})"
            );
        }
    }
}
