//! The fraction-free kernels, and the public operations that choose them for `BigRational`,
//! against the naive generic algorithms (the `*_reference` methods, a gcd per step), with `==`
//! and in lowest terms: random exact curves, rational curves and surfaces, parameters inside
//! and outside [0, 1], and large values that push the machine-word path into big integers.

use casteljau::exact::fraction_free::bernstein_numerator;
use casteljau::exact::BernsteinTable;
use casteljau::strategies::{
    exact_curve, exact_points, large_exact_curve, large_rational, small_rational, wide_parameter,
};
use casteljau::{BezierCurve, BezierSurface, BigInt, BigRational, Point, RationalBezierCurve, Ring, Scalar};
use proptest::prelude::*;
use proptest::test_runner::Config;

type Q = BigRational;

/// Equal and in the same form: `Debug` shows numerator and denominator, so a result left
/// unreduced (or with a negative denominator) differs from the reference.
fn same<X: PartialEq + std::fmt::Debug>(a: &X, b: &X) -> bool {
    a == b && format!("{a:?}") == format!("{b:?}")
}

/// Parameters: the usual wide ones, and ones with large numerators and denominators.
fn parameter() -> impl Strategy<Value = Q> {
    prop_oneof![3 => wide_parameter(), 1 => large_rational()]
}

/// Small and large curves (large ones overflow machine words at once).
fn curve() -> impl Strategy<Value = BezierCurve<Q>> {
    prop_oneof![3 => exact_curve(0..=12, 1..=3), 1 => large_exact_curve(0..=8, 1..=2)]
}

fn rational_curve() -> impl Strategy<Value = RationalBezierCurve<Q>> {
    (0..=7usize, 1..=3usize)
        .prop_flat_map(|(n, d)| {
            (
                exact_points(n + 1, d),
                proptest::collection::vec(small_rational(), n + 1),
            )
        })
        .prop_filter_map("all weights zero", |(points, weights)| {
            RationalBezierCurve::new(points, weights).ok()
        })
}

fn surface() -> impl Strategy<Value = BezierSurface<Q>> {
    (0..=4usize, 0..=4usize, 1..=3usize)
        .prop_flat_map(|(m, n, d)| proptest::collection::vec(exact_points(n + 1, d), m + 1))
        .prop_map(|net| BezierSurface::new(net).unwrap())
}

proptest! {
    #![proptest_config(Config::with_cases(256))]

    #[test]
    fn eval_and_derivatives_at_a_point(c in curve(), t in parameter()) {
        let reference = c.eval_reference(&t);
        prop_assert!(same(&c.eval_nested(&t), &reference));
        prop_assert!(same(&c.eval(&t), &reference));
        for k in 0..=c.degree() + 1 {
            let reference = if k > c.degree() {
                Point::origin(c.dim())
            } else {
                c.derivative_reference(k).unwrap().eval_reference(&t)
            };
            prop_assert!(same(&c.derivative_at_nested(k, &t), &reference));
            prop_assert!(same(&c.derivative_at(k, &t).unwrap(), &reference));
        }
    }

    #[test]
    fn scheme_and_split(c in curve(), t in parameter()) {
        let scheme = c.scheme_reference(&t);
        prop_assert!(same(&c.scheme_fraction_free(&t), &scheme));
        prop_assert!(same(&c.scheme(&t), &scheme));
        let split = c.split_at_reference(&t);
        prop_assert!(same(&c.split_fraction_free(&t), &split));
        prop_assert!(same(&c.split_at(&t), &split));
    }

    #[test]
    fn elevation_and_derivative_curves(c in curve(), r in 0usize..=6) {
        let elevated = c.elevate_reference().unwrap();
        prop_assert!(same(&c.elevate_fraction_free().unwrap(), &elevated));
        prop_assert!(same(&c.elevate().unwrap(), &elevated));
        let elevated = c.elevate_by_reference(r).unwrap();
        prop_assert!(same(&c.elevate_by_fraction_free(r).unwrap(), &elevated));
        prop_assert!(same(&c.elevate_by(r).unwrap(), &elevated));
        for k in 0..=c.degree() {
            let derivative = c.derivative_reference(k).unwrap();
            prop_assert!(same(&c.derivative_fraction_free(k).unwrap(), &derivative));
            prop_assert!(same(&c.derivative(k).unwrap(), &derivative));
        }
        prop_assert!(c.derivative_fraction_free(c.degree() + 1).is_err());
        prop_assert!(c.derivative(c.degree() + 1).is_err());
    }

    #[test]
    fn rational_curves(c in rational_curve(), t in parameter()) {
        let reference = c.eval_reference(&t);
        for fast in [c.eval_nested(&t), c.eval(&t)] {
            match (&fast, &reference) {
                (Ok(a), Ok(b)) => prop_assert!(same(a, b)),
                (Err(a), Err(b)) => prop_assert_eq!(a.to_string(), b.to_string()),
                (a, b) => prop_assert!(false, "{:?} vs {:?}", a, b),
            }
        }
    }

    #[test]
    fn surfaces(s in surface(), u in parameter(), v in parameter()) {
        // `eval` runs the nested kernel; the Bernstein double sum on `BigRational` and the
        // v-first isoparametric route are independent of it.
        let fast = s.eval(&u, &v);
        prop_assert!(same(&fast, &s.eval_bernstein(&u, &v)));
        prop_assert!(same(&fast, &s.eval_v_first(&u, &v)));
    }

    /// A wrong answer would not go unnoticed: moving `b_0` by `δ ≠ 0` moves `b(t)` by
    /// `δ (1 − t)ⁿ`, exactly, and the left half's first point by `δ`.
    #[test]
    fn a_moved_control_point_moves_the_results(c in curve(), t in parameter(), delta in small_rational()) {
        prop_assume!(!delta.is_zero() && t != Q::from_i64(1));
        let mut points = c.points().to_vec();
        let shift = Point::new(vec![delta.clone(); c.dim()]).unwrap();
        points[0] = &points[0] + &shift;
        let moved = BezierCurve::new(points).unwrap();
        let weight = (Q::from_i64(1) - &t).powi(c.degree() as u32);
        let expected = c.eval(&t) + &(shift.clone() * &weight);
        prop_assert_ne!(moved.eval(&t), c.eval(&t));
        prop_assert_eq!(moved.eval(&t), expected);
        let (left, _) = moved.split_at(&t);
        prop_assert_eq!(&left.points()[0], &(c.points()[0].clone() + &shift));
        prop_assert_ne!(moved.elevate().unwrap(), c.elevate().unwrap());
    }

    #[test]
    fn bernstein_numerators_and_tables(
        x in proptest::collection::vec(-1_000_000i64..=1_000_000, 1..=12),
        t in parameter(),
    ) {
        let n = x.len() - 1;
        let xs: Vec<BigInt> = x.iter().map(|&v| BigInt::from(v)).collect();
        let row = BernsteinTable::shared().at_rational(n, &t).unwrap();
        let sum = xs.iter().zip(row.values()).fold(Q::from_i64(0), |acc, (xi, b)| acc + b * Q::from_integer(xi.clone()));
        let numerator = bernstein_numerator(&xs, t.numer(), t.denom());
        prop_assert_eq!(Q::new(numerator, row.denominator().clone()), sum);
        let by_numerators = xs.iter().zip(row.numerators()).fold(BigInt::from(0), |acc, (a, b)| acc + a * b);
        prop_assert_eq!(bernstein_numerator(&xs, t.numer(), t.denom()), by_numerators);
    }
}

/// Values at the edge of the machine words: the kernel must notice the overflow and give the
/// exact value through big integers.
#[test]
fn word_overflow_falls_back_to_big_integers() {
    let big = i64::MAX;
    let c = BezierCurve::<Q>::from_ints(&[&[big, -big], &[-big, big], &[big, big - 1], &[1, i64::MIN]]).unwrap();
    for t in [
        Q::from_ratio(big - 1, big).unwrap(),
        Q::from_ratio(-big, 3).unwrap(),
        Q::from_ratio(1, 3).unwrap(),
        Q::from_i64(0),
        Q::from_i64(1),
    ] {
        assert!(same(&c.eval(&t), &c.eval_reference(&t)), "t = {t}");
        assert!(same(&c.split_at(&t), &c.split_at_reference(&t)), "t = {t}");
        let derivative = c.derivative_reference(1).unwrap().eval_reference(&t);
        assert!(same(&c.derivative_at(1, &t).unwrap(), &derivative));
    }
    assert!(same(&c.elevate_by(40).unwrap(), &c.elevate_by_reference(40).unwrap()));
    // A high degree at t = 1/3: 3^60 overflows i128's products midway.
    let coords: Vec<Vec<i64>> = (0..=60).map(|i| vec![i * i - 30, 7 - i]).collect();
    let refs: Vec<&[i64]> = coords.iter().map(Vec::as_slice).collect();
    let c = BezierCurve::<Q>::from_ints(&refs).unwrap();
    let t = Q::from_ratio(1, 3).unwrap();
    assert!(same(&c.eval(&t), &c.eval_reference(&t)));
    assert!(same(&c.split_at(&t), &c.split_at_reference(&t)));
    let s = BezierSurface::new(vec![c.points().to_vec(), c.points().iter().rev().cloned().collect()]).unwrap();
    assert!(same(&s.eval(&t, &t), &s.eval_bernstein(&t, &t)));
    let w = RationalBezierCurve::new(c.points().to_vec(), (0..=60).map(|i| Q::from_i64(1 + i % 4)).collect()).unwrap();
    assert!(same(&w.eval(&t).unwrap(), &w.eval_reference(&t).unwrap()));
}

#[test]
fn vanishing_weight_is_the_same_error() {
    // w(t) = (1 - t)^2 - t^2 = 1 - 2t vanishes at t = 1/2.
    let c = RationalBezierCurve::<Q>::from_ints(&[&[0, 0], &[1, 1], &[2, 0]], &[1, 0, -1]).unwrap();
    let half = Q::from_ratio(1, 2).unwrap();
    let (a, b) = (c.eval(&half).unwrap_err(), c.eval_reference(&half).unwrap_err());
    assert_eq!(a.to_string(), b.to_string());
}
