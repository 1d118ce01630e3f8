//! `SmallRational` against `BigRational`: every operation on random values — small ones,
//! values at and near the `i64` limits, and values beyond them — gives the same value
//! (compared with `==` after conversion), in canonical form, without wrapping or panicking.

use casteljau::exact::SmallRational;
use casteljau::strategies::{exact_curve, wide_parameter};
use casteljau::{BigInt, BigRational, Ring, Scalar};
use proptest::prelude::*;
use proptest::test_runner::Config;

/// Integers that stress the word arithmetic: small, near ±2^63, near ±2^31, anywhere in i64.
fn word() -> impl Strategy<Value = i64> {
    prop_oneof![
        -20i64..=20,
        (0i64..=8).prop_map(|k| i64::MAX - k),
        (0i64..=8).prop_map(|k| i64::MIN + k),
        (-4i64..=4).prop_map(|k| (1i64 << 31) + k),
        (-4i64..=4).prop_map(|k| -(1i64 << 32) + k),
        any::<i64>(),
    ]
}

/// Rationals built from such integers (num/den, den ≠ 0), plus some just beyond i64.
fn value() -> impl Strategy<Value = BigRational> {
    prop_oneof![
        4 => (word(), word().prop_filter("nonzero", |d| *d != 0))
            .prop_map(|(n, d)| BigRational::new(n.into(), d.into())),
        1 => (any::<i128>(), 1i128..=i128::MAX).prop_map(|(n, d)| BigRational::new(n.into(), d.into())),
        1 => word().prop_map(|n| BigRational::from_integer(BigInt::from(n) * 3)),
    ]
}

fn small(r: &BigRational) -> SmallRational {
    let s = SmallRational::from(r);
    assert!(s.invariant_holds(), "{r} converted to a non-canonical {s}");
    s
}

fn check(s: SmallRational, expect: BigRational) -> Result<(), TestCaseError> {
    prop_assert!(s.invariant_holds(), "non-canonical result {} (expected {})", s, expect);
    prop_assert_eq!(BigRational::from(&s), expect.clone());
    prop_assert_eq!(s.to_string(), expect.to_string());
    prop_assert_eq!(s, SmallRational::from(expect));
    Ok(())
}

proptest! {
    #![proptest_config(Config::with_cases(2_000))]

    #[test]
    fn arithmetic_matches_big_rational(a in value(), b in value()) {
        let (x, y) = (small(&a), small(&b));
        check(&x + &y, &a + &b)?;
        check(&x - &y, &a - &b)?;
        check(&x * &y, &a * &b)?;
        check(-&x, -&a)?;
        check(x.abs(), Scalar::abs(&a))?;
        match (x.checked_div(&y), a.checked_div(&b)) {
            (Ok(q), Ok(expect)) => check(q, expect)?,
            (Err(_), Err(_)) => {}
            (got, expect) => prop_assert!(false, "{:?} vs {:?}", got, expect),
        }
        // Value and assigning forms are the same operation.
        let mut z = x.clone();
        z += &y;
        z *= y.clone();
        z -= &x;
        check(z, &(&(&a + &b) * &b) - &a)?;
        prop_assert_eq!(x.partial_cmp(&y), a.partial_cmp(&b));
        prop_assert_eq!(x == y, a == b);
        prop_assert_eq!(x.is_zero(), Scalar::is_zero(&a));
        prop_assert_eq!(x.is_integer(), a.is_integer());
        prop_assert_eq!(Scalar::to_f64(&x), Scalar::to_f64(&a));
    }

    #[test]
    fn ratios_of_words(p in word(), q in word()) {
        match (SmallRational::from_ratio(p, q), BigRational::from_ratio(p, q)) {
            (Ok(s), Ok(r)) => check(s, r)?,
            (Err(_), Err(_)) => prop_assert_eq!(q, 0),
            (s, r) => prop_assert!(false, "{:?} vs {:?}", s, r),
        }
    }

    #[test]
    fn words_are_used_exactly_when_the_value_fits(a in value()) {
        let fits = i64::try_from(a.numer()).is_ok() && i64::try_from(a.denom()).is_ok();
        prop_assert_eq!(small(&a).is_small(), fits);
    }

    #[test]
    fn generic_eval_matches_big_rational(c in exact_curve(0..=10, 1..=3), t in wide_parameter()) {
        let s = c.try_map(SmallRational::from_rational).unwrap();
        let got = s.eval(&SmallRational::from(&t));
        let expect = c.eval(&t);
        for (g, e) in got.coords().iter().zip(expect.coords()) {
            prop_assert_eq!(&BigRational::from(g), e);
        }
    }
}

#[test]
fn overflow_moves_to_big_integers_at_every_limit() {
    let max = SmallRational::from_int(i64::MAX);
    let min = SmallRational::from_int(i64::MIN);
    let one = SmallRational::one();
    let big = |x: &SmallRational| BigRational::from(x);
    let m = BigRational::from_i64(i64::MAX);
    assert_eq!(big(&(&max + &one)), &m + BigRational::from_i64(1));
    assert!(!(&max + &one).is_small());
    assert_eq!(
        big(&(&min - &one)),
        BigRational::from_i64(i64::MIN) - BigRational::from_i64(1)
    );
    assert_eq!(
        big(&(&min * &min)),
        BigRational::from_i64(i64::MIN) * BigRational::from_i64(i64::MIN)
    );
    assert_eq!(big(&(&max * &max)), &m * &m);
    // 1/MAX + 1/(MAX - 1): a denominator past i64, then back to words.
    let a = SmallRational::from_i128_pair(1, i64::MAX as i128).unwrap();
    let b = SmallRational::from_i128_pair(1, i64::MAX as i128 - 1).unwrap();
    let sum = &a + &b;
    assert!(!sum.is_small());
    assert_eq!((&sum - &b), a);
    assert!((&sum - &b).is_small());
    assert_eq!(min.checked_div(&SmallRational::from_int(-1)).unwrap(), -&min);
    assert!(min < max && -&max > min);
}
