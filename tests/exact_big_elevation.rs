//! Elevation and the first derivative on numbers longer than two words (the big-integer
//! pair, whose gcd of neighbouring denominators runs on dashu-int's copies made once per
//! curve) against the naive formulas on `BigRational`, with `==` and in lowest terms:
//! 100-digit-sized numerators and denominators of any sign, zero coordinates, equal
//! denominators, denominators sharing a long, a one-word or a small factor, and
//! denominators sharing small primes with the weights `i`, `n+1−i`, `n+1` and `n`; and
//! curves mixing every length the kernels tell apart (words, 4, 8, 16 words, longer).

use casteljau::{BezierCurve, BigInt, BigRational, Point};
use num_traits::{One, Zero};
use proptest::prelude::*;
use proptest::test_runner::Config;

type Q = BigRational;

/// Equal and in the same form (`Debug` shows numerator and denominator).
fn same<X: PartialEq + std::fmt::Debug>(a: &X, b: &X) -> bool {
    a == b && format!("{a:?}") == format!("{b:?}")
}

/// A natural number of up to 384 bits from three double words, shortened by `shift` bits.
fn long(words: [u128; 3], shift: u32) -> BigInt {
    let whole = words
        .iter()
        .rev()
        .fold(BigInt::zero(), |acc, &w| (acc << 128) + BigInt::from(w));
    whole >> shift
}

/// What the curve's denominators share: nothing, a small smooth number, a word, or a
/// 200-bit number.
fn common_factor() -> impl Strategy<Value = BigInt> {
    prop_oneof![
        Just(BigInt::one()),
        (0u32..8, 0u32..5).prop_map(|(a, b)| BigInt::from(2u64.pow(a) * 3u64.pow(b))),
        (1u64..).prop_map(BigInt::from),
        any::<[u128; 3]>().prop_map(|w| long(w, 184) | BigInt::one()),
    ]
}

/// One coordinate over a denominator of the given kind: its own long one (above 2^300),
/// the common factor times a long cofactor, exactly the common factor times 2^130 (every
/// such coordinate of the curve has that one denominator), or a long one times a power of
/// 2, 3, 5 and 7 (primes the weights share); or zero.
fn coordinate(common: BigInt) -> impl Strategy<Value = Q> {
    (
        any::<[u128; 3]>(),
        0u32..300,
        any::<bool>(),
        any::<[u128; 3]>(),
        0u32..6,
        (0u32..12, 0u32..5, 0u32..3, 0u32..3),
    )
        .prop_map(move |(num, shift, negative, den, kind, (a, b, c, d))| {
            let cofactor = long(den, 60) | (BigInt::one() << 300);
            let den = match kind {
                0 => cofactor,
                1 => &common * long([den[0], den[1], 0], 0).max(BigInt::one()),
                2 => &common << 130,
                3 => cofactor * BigInt::from(2u64.pow(a) * 3u64.pow(b) * 5u64.pow(c) * 7u64.pow(d)),
                4 => return Q::zero(),
                _ => BigInt::from(2u64.pow(a) * 3u64.pow(b)) << 200,
            };
            let num = long(num, shift);
            Q::new(if negative { -num } else { num }, den)
        })
}

fn long_curve() -> impl Strategy<Value = BezierCurve<Q>> {
    (
        proptest::sample::select(&[1usize, 2, 3, 4, 5, 8, 20][..]),
        1..=2usize,
        common_factor(),
    )
        .prop_flat_map(|(n, dim, common)| {
            proptest::collection::vec(proptest::collection::vec(coordinate(common), dim), n + 1)
                .prop_map(|points| BezierCurve::from_coords(points).unwrap())
        })
}

/// `(i b_{i−1} + (n+1−i) b_i) / (n+1)` on `BigRational`, which reduces every step.
fn naive_elevation(c: &BezierCurve<Q>) -> Vec<Point<Q>> {
    let b = c.points();
    let n = b.len() - 1;
    let total = Q::from_integer(BigInt::from(n + 1));
    (0..=n + 1)
        .map(|i| {
            let coords = (0..c.dim()).map(|k| {
                let before = if i == 0 {
                    Q::zero()
                } else {
                    b[i - 1].coords()[k].clone()
                };
                let here = if i > n { Q::zero() } else { b[i].coords()[k].clone() };
                (before * Q::from_integer(BigInt::from(i)) + here * Q::from_integer(BigInt::from(n + 1 - i))) / &total
            });
            Point::new(coords.collect()).unwrap()
        })
        .collect()
}

/// `n (b_{i+1} − b_i)` on `BigRational`.
fn naive_derivative(c: &BezierCurve<Q>) -> Vec<Point<Q>> {
    let b = c.points();
    let n = Q::from_integer(BigInt::from(b.len() - 1));
    b.windows(2)
        .map(|w| {
            let coords = (0..c.dim()).map(|k| (&w[1].coords()[k] - &w[0].coords()[k]) * &n);
            Point::new(coords.collect()).unwrap()
        })
        .collect()
}

proptest! {
    #![proptest_config(Config::with_cases(200))]

    #[test]
    fn elevation_of_long_numbers_is_the_naive_formula(c in long_curve()) {
        let got = c.elevate().unwrap();
        prop_assert!(same(&got.points().to_vec(), &naive_elevation(&c)));
    }

    #[test]
    fn derivative_of_long_numbers_is_the_naive_formula(c in long_curve()) {
        let got = c.derivative(1).unwrap();
        prop_assert!(same(&got.points().to_vec(), &naive_derivative(&c)));
    }
}

/// A mutant: one coordinate changed by 1 in its last digit changes the elevation, so the
/// comparison above can fail.
#[test]
fn a_changed_input_changes_the_elevation() {
    let den: BigInt = (BigInt::one() << 330) + 7u32;
    let coords = |last: i64| {
        (0..4i64)
            .map(|i| vec![Q::new((BigInt::one() << 320) * (i + 2) + last * i, den.clone() + i)])
            .collect::<Vec<_>>()
    };
    let c = BezierCurve::from_coords(coords(1)).unwrap();
    let mutant = BezierCurve::from_coords(coords(2)).unwrap();
    assert!(same(&c.elevate().unwrap().points().to_vec(), &naive_elevation(&c)));
    assert!(!same(
        &c.elevate().unwrap().points().to_vec(),
        &naive_elevation(&mutant)
    ));
    assert!(!same(
        &c.derivative(1).unwrap().points().to_vec(),
        &naive_derivative(&mutant)
    ));
}

/// A natural number from 64-bit limbs, at least 1.
fn from_limbs(limbs: &[u64]) -> BigInt {
    limbs
        .iter()
        .rev()
        .fold(BigInt::zero(), |acc, &w| (acc << 64) + BigInt::from(w))
        .max(BigInt::one())
}

/// One coordinate of any length the kernels tell apart: within the word path (up to 119
/// bits), two words (on either side of 119 bits: past it, the stack pairs with the gcds of
/// two words), 3 to 4, 5 to 8, 9 to 16 words (the stack types of `long_pair`) and 17 to 20
/// (past them), its denominator times a factor the curve shares (a word below 2^32, one
/// above, or 1) and a power of 2 and 3 (which the weights share).
fn mixed_coordinate(common: u64) -> impl Strategy<Value = Q> {
    let limbs = |words: std::ops::RangeInclusive<usize>| {
        words.prop_flat_map(|len| proptest::collection::vec(any::<u64>(), len))
    };
    let length = prop_oneof![
        limbs(1..=1),
        limbs(2..=2),
        limbs(3..=4),
        limbs(5..=8),
        limbs(9..=16),
        limbs(17..=20)
    ];
    (length.clone(), length, any::<bool>(), (0u32..6, 0u32..4), any::<bool>()).prop_map(
        move |(num, den, negative, (a, b), shares)| {
            let shared = if shares { BigInt::from(common) } else { BigInt::one() };
            let den = from_limbs(&den) * shared * BigInt::from(2u64.pow(a) * 3u64.pow(b));
            let num = from_limbs(&num);
            Q::new(if negative { -num } else { num }, den)
        },
    )
}

fn mixed_curve() -> impl Strategy<Value = BezierCurve<Q>> {
    (
        1usize..=9,
        1..=3usize,
        prop_oneof![Just(1u64), 2u64..1 << 32, any::<u64>()],
    )
        .prop_flat_map(|(n, dim, common)| {
            proptest::collection::vec(proptest::collection::vec(mixed_coordinate(common), dim), n + 1)
                .prop_map(|points| BezierCurve::from_coords(points).unwrap())
        })
}

proptest! {
    #![proptest_config(Config::with_cases(150))]

    /// Curves whose coordinates take every path at once (words, the stack pairs of 4, 8
    /// and 16 words, big integers), with shared factors below and above 2^32.
    #[test]
    fn elevation_and_derivative_of_mixed_lengths(c in mixed_curve()) {
        prop_assert!(same(&c.elevate().unwrap().points().to_vec(), &naive_elevation(&c)));
        prop_assert!(same(&c.derivative(1).unwrap().points().to_vec(), &naive_derivative(&c)));
    }
}
