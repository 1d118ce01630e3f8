//! The subdivision of curves with long numbers against de Casteljau's steps on
//! `BigRational` (`split_at_reference`), with `==` and in lowest terms: both kernels `split`
//! chooses between (over the lcm of the denominators, and pair by pair on reduced fractions)
//! are reached, since the choice depends on the lengths of the denominators and of `t`'s.
//!
//! Curves of degree 1 to 8 whose coordinates are 30-, 100- or 300-digit fractions of either
//! sign, zeros, integers, values over one denominator shared by the whole curve, and
//! denominators sharing a long factor and small primes; parameters 0, 1, small fractions
//! inside and outside [0, 1], and fractions with 20- and 100-digit denominators, inside and
//! outside [0, 1].

use casteljau::{BezierCurve, BigInt, BigRational, Point};
use num_traits::{One, Zero};
use proptest::prelude::*;
use proptest::test_runner::Config;

type Q = BigRational;

/// Equal and in the same form (`Debug` shows numerator and denominator).
fn same<X: PartialEq + std::fmt::Debug>(a: &X, b: &X) -> bool {
    a == b && format!("{a:?}") == format!("{b:?}")
}

/// A `digits`-digit positive integer from random words (enough of them for 300 digits).
fn sized(words: &[u64], digits: u32) -> BigInt {
    let low = num_traits::pow(BigInt::from(10), digits as usize - 1);
    let raw = words.iter().fold(BigInt::zero(), |acc, &w| (acc << 64) + w);
    &low + raw % (&low * 9)
}

fn words() -> impl Strategy<Value = Vec<u64>> {
    proptest::collection::vec(any::<u64>(), 17)
}

/// Small factors the denominators may share with each other, with `t`'s and the weights.
fn smooth() -> impl Strategy<Value = BigInt> {
    (0u32..6, 0u32..4, 0u32..3, 0u32..2)
        .prop_map(|(a, b, c, d)| BigInt::from(2u64.pow(a) * 3u64.pow(b) * 5u64.pow(c) * 7u64.pow(d)))
}

/// How a coordinate's value is drawn.
#[derive(Clone, Debug)]
enum Kind {
    /// A `digits`-digit numerator over a `digits`-digit denominator.
    Free,
    /// Over the curve's long common factor times a small one and a short cofactor.
    Shared,
    /// Over the one denominator of the whole curve.
    Equal,
    Integer,
    Zero,
}

fn kind() -> impl Strategy<Value = Kind> {
    prop_oneof![
        4 => Just(Kind::Free),
        3 => Just(Kind::Shared),
        1 => Just(Kind::Equal),
        1 => Just(Kind::Integer),
        1 => Just(Kind::Zero),
    ]
}

/// A curve of degree 1 to 8 in 1 to 3 dimensions whose numbers have 30, 100 or 300 digits.
fn curve() -> impl Strategy<Value = BezierCurve<Q>> {
    (
        1usize..=8,
        1usize..=3,
        prop_oneof![Just(30u32), Just(100), Just(300)],
        words(),
        words(),
    )
        .prop_flat_map(|(n, dim, digits, common, equal)| {
            let coordinate = (kind(), words(), words(), smooth(), any::<bool>());
            proptest::collection::vec(proptest::collection::vec(coordinate, dim), n + 1).prop_map(move |points| {
                let common = sized(&common, digits / 2);
                let equal = sized(&equal, digits);
                let coords: Vec<Vec<Q>> = points
                    .into_iter()
                    .map(|point| {
                        point
                            .into_iter()
                            .map(|(kind, a, b, small, negative)| {
                                let num = sized(&a, digits);
                                let num = if negative { -num } else { num };
                                match kind {
                                    Kind::Free => Q::new(num, sized(&b, digits) * small),
                                    Kind::Shared => Q::new(num, &common * small * sized(&b, digits / 3)),
                                    Kind::Equal => Q::new(num, equal.clone()),
                                    Kind::Integer => Q::from_integer(num),
                                    Kind::Zero => Q::zero(),
                                }
                            })
                            .collect()
                    })
                    .collect();
                BezierCurve::from_coords(coords).unwrap()
            })
        })
}

fn parameter() -> impl Strategy<Value = Q> {
    let long = |digits: u32| {
        (words(), words(), -1i64..=2, smooth()).prop_map(move |(a, b, whole, small)| {
            let q = sized(&b, digits) * small;
            let p = sized(&a, digits) % &q + &q * whole;
            Q::new(p, q)
        })
    };
    prop_oneof![
        1 => Just(Q::zero()),
        1 => Just(Q::one()),
        2 => (-40i64..=40, 1i64..=13).prop_map(|(p, q)| Q::new(p.into(), q.into())),
        3 => long(20),
        2 => long(100),
    ]
}

proptest! {
    #![proptest_config(Config::with_cases(160))]

    #[test]
    fn split_of_long_numbers(c in curve(), t in parameter()) {
        let (left, right) = c.split_at(&t);
        prop_assert!(same(&(left.clone(), right.clone()), &c.split_at_reference(&t)));
        let n = c.degree();
        prop_assert!(same(&left.points()[n], &right.points()[0]));
        prop_assert!(same(&left.points()[n], &c.eval(&t)));
    }
}

/// The grid's cells (`scripts/exact_grid.py`) at degrees 1 to 8: distinct 30-, 100- and
/// 300-digit denominators, at `t = 1/3`, a 20-digit and a 100-digit `t`, and outside [0, 1].
#[test]
fn grid_sized_curves() {
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    for digits in [30u32, 100, 300] {
        for n in 1..=8usize {
            let coords: Vec<Vec<Q>> = (0..=n)
                .map(|i| {
                    (0..2)
                        .map(|_| {
                            let w: Vec<u64> = (0..17).map(|_| next()).collect();
                            let v: Vec<u64> = (0..17).map(|_| next()).collect();
                            let num = sized(&w, digits);
                            Q::new(if i % 2 == 0 { -num } else { num }, sized(&v, digits))
                        })
                        .collect()
                })
                .collect();
            let c = BezierCurve::from_coords(coords).unwrap();
            let w: Vec<u64> = (0..17).map(|_| next()).collect();
            let (q20, q100) = (sized(&w, 20), sized(&w, 100));
            for t in [
                Q::new(1.into(), 3.into()),
                Q::new(&q20 / 3, q20.clone()),
                Q::new(&q100 / 7, q100.clone()),
                Q::new(&q20 * 2 + 1, q20.clone()),
                Q::new(-(&q100 / BigInt::from(5)), q100.clone()),
            ] {
                let split = c.split_at(&t);
                assert!(
                    same(&split, &c.split_at_reference(&t)),
                    "{digits} digits, degree {n}, t = {t}"
                );
            }
        }
    }
}

/// Degenerate columns: every point the same, all zero, all integers, and two points only.
#[test]
fn degenerate_curves() {
    let big = |k: u32| {
        Q::new(
            num_traits::pow(BigInt::from(10), 40) + k,
            num_traits::pow(BigInt::from(7), 60),
        )
    };
    let cases: Vec<Vec<Q>> = vec![
        vec![big(1); 5],
        vec![Q::zero(); 4],
        (0..6)
            .map(|k| Q::from_integer(num_traits::pow(BigInt::from(3), 80) * k))
            .collect(),
        vec![big(1), big(2)],
        vec![big(1), Q::zero(), big(2), Q::zero()],
    ];
    let t_long = Q::new(
        num_traits::pow(BigInt::from(10), 30) + 7,
        num_traits::pow(BigInt::from(10), 31) + 9,
    );
    for values in cases {
        let c = BezierCurve::new(
            values
                .into_iter()
                .map(|v| Point::new(vec![v.clone(), -v]).unwrap())
                .collect(),
        )
        .unwrap();
        for t in [
            Q::zero(),
            Q::one(),
            Q::new(1.into(), 3.into()),
            t_long.clone(),
            Q::new(5.into(), 2.into()),
        ] {
            assert!(same(&c.split_at(&t), &c.split_at_reference(&t)), "t = {t}");
        }
    }
}
