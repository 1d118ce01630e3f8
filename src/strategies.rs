//! [proptest](mod@proptest) strategies for random exact and floating-point Bézier data (cargo feature
//! `strategies`).
//!
//! The point of casteljau's exact path is to be an oracle: generate random *exact* inputs,
//! run your float code and the exact code on the same inputs, and compare. These strategies
//! produce the inputs — small rationals (whose arithmetic stays cheap), exact points, exact
//! curves of a chosen degree and dimension range, parameters in `[0, 1]` or beyond, exact
//! affine maps and barycentric weights, and finite `f64` curves.
//!
//! Every float strategy yields finite values only, so converting a sample exactly with
//! [`Scalar::from_f64`] (or [`BezierCurve::try_map`]) never fails: the exact result of the
//! *same* input is always available.
//!
//! ```
//! use casteljau::strategies::{exact_curve, unit_parameter};
//! use casteljau::{BigRational, Scalar};
//! use proptest::prelude::*;
//! use proptest::test_runner::{Config, TestRunner};
//!
//! // Property: the f64 evaluation of a rounded curve is close to the exact value.
//! let mut runner = TestRunner::new(Config::with_cases(32));
//! runner
//!     .run(&(exact_curve(1..=6, 1..=3), unit_parameter()), |(curve, t)| {
//!         let exact = curve.eval(&t);
//!         let float = curve.try_map(f64::from_rational).unwrap().eval(&t.to_f64());
//!         for (e, f) in exact.coords().iter().zip(float.coords()) {
//!             prop_assert!((e.to_f64() - f).abs() <= 1e-12 * 50.0);
//!         }
//!         Ok(())
//!     })
//!     .unwrap();
//! ```
//!
//! Strategy constructors take bounds chosen by the test author, not user data; bounds that
//! cannot produce a value (an empty range, a zero denominator bound, dimension zero) are
//! programming errors and panic with a message saying which bound is wrong.

use crate::curve::BezierCurve;
use crate::error::{MAX_DEGREE, MAX_DIMENSION};
use crate::point::{AffineMap, Point};
use crate::scalar::{Ring, Scalar};
use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::prelude::*;
use std::fmt::Debug;
use std::ops::RangeInclusive;

/// Largest numerator magnitude of [`small_rational`].
pub const SMALL_NUMERATOR: i64 = 50;
/// Largest denominator of [`small_rational`].
pub const SMALL_DENOMINATOR: i64 = 20;
/// Largest numerator magnitude of [`large_rational`].
pub const LARGE_NUMERATOR: i64 = 1_000_000_000_000;
/// Largest denominator of [`large_rational`].
pub const LARGE_DENOMINATOR: i64 = 1_000_000_000;
/// Largest denominator of the parameters from [`unit_parameter`] and [`wide_parameter`].
pub const PARAMETER_DENOMINATOR: i64 = 64;

/// Exact rationals `p/q` with `|p| ≤ max_numerator` and `1 ≤ q ≤ max_denominator`
/// (not necessarily in lowest terms when drawn, always reduced as values).
///
/// # Panics
/// If `max_numerator < 0` or `max_denominator < 1`.
///
/// ```
/// use casteljau::strategies::rational;
/// use proptest::strategy::{Strategy, ValueTree};
/// use proptest::test_runner::TestRunner;
/// let r = rational(3, 2).new_tree(&mut TestRunner::default()).unwrap().current();
/// assert!(r.numer().magnitude() <= &3u32.into() && r.denom() <= &2.into());
/// ```
pub fn rational(max_numerator: i64, max_denominator: i64) -> BoxedStrategy<BigRational> {
    assert!(
        max_numerator >= 0,
        "rational: max_numerator must be ≥ 0, got {max_numerator}"
    );
    assert!(
        max_denominator >= 1,
        "rational: max_denominator must be ≥ 1, got {max_denominator}"
    );
    (-max_numerator..=max_numerator, 1..=max_denominator)
        .prop_map(|(p, q)| BigRational::new(BigInt::from(p), BigInt::from(q)))
        .boxed()
}

/// Exact rationals with `|p| ≤ 50`, `1 ≤ q ≤ 20`: cheap to compute with, yet with enough
/// different denominators to catch any rounding or missing term.
pub fn small_rational() -> BoxedStrategy<BigRational> {
    rational(SMALL_NUMERATOR, SMALL_DENOMINATOR)
}

/// Exact rationals with `|p| ≤ 10^12`, `1 ≤ q ≤ 10^9`: values whose products no machine
/// integer holds, to exercise the big-number path.
pub fn large_rational() -> BoxedStrategy<BigRational> {
    rational(LARGE_NUMERATOR, LARGE_DENOMINATOR)
}

/// Exact rationals in `[lo, hi]` with denominators `1..=max_denominator`; both ends can occur.
///
/// # Panics
/// If `lo > hi` or `max_denominator < 1`.
pub fn rational_in(lo: i64, hi: i64, max_denominator: i64) -> BoxedStrategy<BigRational> {
    assert!(lo <= hi, "rational_in: empty range [{lo}, {hi}]");
    assert!(
        max_denominator >= 1,
        "rational_in: max_denominator must be ≥ 1, got {max_denominator}"
    );
    (1..=max_denominator)
        .prop_flat_map(move |q| {
            // lo*q ..= hi*q in i128, so wide ranges cannot overflow.
            let (a, b) = (i128::from(lo) * i128::from(q), i128::from(hi) * i128::from(q));
            (a..=b).prop_map(move |p| BigRational::new(BigInt::from(p), BigInt::from(q)))
        })
        .boxed()
}

/// Exact parameters `t = p/q` in `[0, 1]`, `q ≤ 64`, including the ends `0` and `1`.
pub fn unit_parameter() -> BoxedStrategy<BigRational> {
    rational_in(0, 1, PARAMETER_DENOMINATOR)
}

/// Exact parameters in `[-2, 3]`, `q ≤ 64`: the curve formulas hold for every real `t`, not
/// only on `[0, 1]`, and extrapolation is where sign mistakes hide.
pub fn wide_parameter() -> BoxedStrategy<BigRational> {
    rational_in(-2, 3, PARAMETER_DENOMINATOR)
}

/// `f64` parameters in `[0, 1]`.
pub fn unit_parameter_f64() -> BoxedStrategy<f64> {
    (0.0..=1.0f64).boxed()
}

/// `f64` parameters in `[-2, 3]`.
pub fn wide_parameter_f64() -> BoxedStrategy<f64> {
    (-2.0..=3.0f64).boxed()
}

/// Finite `f64` values in `[-max_abs, max_abs]`.
///
/// # Panics
/// If `max_abs` is not finite and positive.
pub fn f64_coordinate(max_abs: f64) -> BoxedStrategy<f64> {
    assert!(
        max_abs.is_finite() && max_abs > 0.0,
        "f64_coordinate: max_abs must be finite and positive, got {max_abs}"
    );
    (-max_abs..=max_abs).boxed()
}

/// Points of dimension `dim` whose coordinates come from `coord`.
///
/// # Panics
/// If `dim` is 0 or above [`MAX_DIMENSION`].
pub fn point_with<T, S>(coord: S, dim: usize) -> BoxedStrategy<Point<T>>
where
    T: Scalar,
    S: Strategy<Value = T> + 'static,
{
    assert!(
        (1..=MAX_DIMENSION).contains(&dim),
        "point_with: dimension must be in 1..={MAX_DIMENSION}, got {dim}"
    );
    proptest::collection::vec(coord, dim)
        // Cannot fail: the dimension was checked above.
        .prop_map(|c| Point::new(c).expect("dimension in range"))
        .boxed()
}

/// Exact points of dimension `dim` with [`small_rational`] coordinates.
pub fn exact_point(dim: usize) -> BoxedStrategy<Point<BigRational>> {
    point_with(small_rational(), dim)
}

/// `count` exact points of one dimension `dim`.
pub fn exact_points(count: usize, dim: usize) -> BoxedStrategy<Vec<Point<BigRational>>> {
    proptest::collection::vec(exact_point(dim), count).boxed()
}

/// Bézier curves with degree in `degrees` and dimension in `dims`, coordinates from `coord`.
///
/// # Panics
/// If a range is empty, a dimension is 0 or above [`MAX_DIMENSION`], or a degree is above
/// [`MAX_DEGREE`].
pub fn curve_with<T, S>(
    coord: S,
    degrees: RangeInclusive<usize>,
    dims: RangeInclusive<usize>,
) -> BoxedStrategy<BezierCurve<T>>
where
    T: Scalar,
    S: Strategy<Value = T> + Clone + 'static,
{
    assert!(!degrees.is_empty(), "curve_with: empty degree range {degrees:?}");
    assert!(!dims.is_empty(), "curve_with: empty dimension range {dims:?}");
    assert!(
        *degrees.end() <= MAX_DEGREE,
        "curve_with: degree {} exceeds MAX_DEGREE",
        degrees.end()
    );
    assert!(
        *dims.start() >= 1 && *dims.end() <= MAX_DIMENSION,
        "curve_with: dimensions must lie in 1..={MAX_DIMENSION}, got {dims:?}"
    );
    (degrees, dims)
        .prop_flat_map(move |(n, d)| proptest::collection::vec(point_with(coord.clone(), d), n + 1))
        // Cannot fail: at least one point, one dimension, degree within MAX_DEGREE.
        .prop_map(|points| BezierCurve::new(points).expect("valid by construction"))
        .boxed()
}

/// Exact curves with [`small_rational`] coordinates, degree in `degrees`, dimension in `dims`.
///
/// ```
/// use casteljau::strategies::exact_curve;
/// use proptest::strategy::{Strategy, ValueTree};
/// use proptest::test_runner::TestRunner;
/// let c = exact_curve(2..=4, 3..=3).new_tree(&mut TestRunner::default()).unwrap().current();
/// assert!((2..=4).contains(&c.degree()) && c.dim() == 3);
/// ```
pub fn exact_curve(
    degrees: RangeInclusive<usize>,
    dims: RangeInclusive<usize>,
) -> BoxedStrategy<BezierCurve<BigRational>> {
    curve_with(small_rational(), degrees, dims)
}

/// Exact curves with [`large_rational`] coordinates.
pub fn large_exact_curve(
    degrees: RangeInclusive<usize>,
    dims: RangeInclusive<usize>,
) -> BoxedStrategy<BezierCurve<BigRational>> {
    curve_with(large_rational(), degrees, dims)
}

/// `f64` curves with coordinates in `[-max_abs, max_abs]`.
///
/// Convert a sample exactly with `curve.try_map(|&x| BigRational::from_f64(x))` to get the
/// exact oracle for the very same input.
pub fn f64_curve(
    degrees: RangeInclusive<usize>,
    dims: RangeInclusive<usize>,
    max_abs: f64,
) -> BoxedStrategy<BezierCurve<f64>> {
    curve_with(f64_coordinate(max_abs), degrees, dims)
}

/// Exact affine maps from dimension `input_dim` to `output_dim` with [`small_rational`]
/// entries (not necessarily invertible: invariance must hold for every affine map).
///
/// # Panics
/// If a dimension is 0 or above [`MAX_DIMENSION`].
pub fn exact_affine_map(input_dim: usize, output_dim: usize) -> BoxedStrategy<AffineMap<BigRational>> {
    assert!(
        (1..=MAX_DIMENSION).contains(&input_dim) && (1..=MAX_DIMENSION).contains(&output_dim),
        "exact_affine_map: dimensions must lie in 1..={MAX_DIMENSION}, got {input_dim} → {output_dim}"
    );
    (
        proptest::collection::vec(proptest::collection::vec(small_rational(), input_dim), output_dim),
        proptest::collection::vec(small_rational(), output_dim),
    )
        // Cannot fail: rectangular matrix, translation of the output dimension.
        .prop_map(|(m, c)| AffineMap::new(m, c).expect("valid by construction"))
        .boxed()
}

/// `count` exact weights summing to exactly one, of any sign (barycentric, not necessarily
/// convex).
///
/// # Panics
/// If `count` is 0.
pub fn affine_weights(count: usize) -> BoxedStrategy<Vec<BigRational>> {
    assert!(count >= 1, "affine_weights: need at least one weight");
    proptest::collection::vec(small_rational(), count - 1)
        .prop_map(|mut w| {
            let sum = w.iter().fold(<BigRational as Ring>::zero(), |acc, x| acc + x);
            w.push(<BigRational as Ring>::one() - sum);
            w
        })
        .boxed()
}

/// `count` exact weights `≥ 0` summing to exactly one (a convex combination).
///
/// # Panics
/// If `count` is 0.
pub fn nonnegative_weights(count: usize) -> BoxedStrategy<Vec<BigRational>> {
    assert!(count >= 1, "nonnegative_weights: need at least one weight");
    proptest::collection::vec(0..=20i64, count)
        .prop_map(|raw| {
            let total: i64 = raw.iter().sum();
            raw.iter()
                .map(|&x| {
                    if total == 0 {
                        // All drawn zero: fall back to the uniform weights.
                        BigRational::new(1.into(), BigInt::from(raw.len()))
                    } else {
                        BigRational::new(x.into(), total.into())
                    }
                })
                .collect()
        })
        .boxed()
}

/// Samples one value; handy in doc examples and quick experiments, not in properties.
pub fn sample<T: Debug>(strategy: &BoxedStrategy<T>, runner: &mut proptest::test_runner::TestRunner) -> T {
    use proptest::strategy::ValueTree;
    // A boxed strategy built here never rejects, so a tree is always produced.
    strategy.new_tree(runner).expect("strategy does not reject").current()
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::test_runner::{Config, TestRunner};

    fn q(p: i64, d: i64) -> BigRational {
        BigRational::new(p.into(), d.into())
    }

    proptest! {
        #![proptest_config(Config::with_cases(64))]

        #[test]
        fn rationals_respect_bounds(r in small_rational(), t in unit_parameter(), w in wide_parameter()) {
            prop_assert!(r.numer().magnitude() <= &BigInt::from(SMALL_NUMERATOR).magnitude().clone());
            prop_assert!(r.denom() <= &BigInt::from(SMALL_DENOMINATOR));
            prop_assert!(t >= q(0, 1) && t <= q(1, 1));
            prop_assert!(w >= q(-2, 1) && w <= q(3, 1));
        }

        #[test]
        fn curves_have_requested_shape(c in exact_curve(0..=5, 1..=3), f in f64_curve(2..=2, 4..=4, 10.0)) {
            prop_assert!(c.degree() <= 5 && (1..=3).contains(&c.dim()));
            prop_assert!(f.degree() == 2 && f.dim() == 4);
            prop_assert!(f.points().iter().flat_map(|p| p.coords()).all(|x| x.abs() <= 10.0));
        }

        #[test]
        fn weights_sum_to_one(a in affine_weights(4), b in nonnegative_weights(3)) {
            let one = <BigRational as Ring>::one();
            prop_assert_eq!(a.iter().fold(q(0, 1), |s, x| s + x), one.clone());
            prop_assert_eq!(b.iter().fold(q(0, 1), |s, x| s + x), one);
            prop_assert!(b.iter().all(|x| *x >= q(0, 1)));
        }

        #[test]
        fn affine_maps_have_requested_dimensions(m in exact_affine_map(3, 2)) {
            prop_assert_eq!((m.input_dim(), m.output_dim()), (3, 2));
        }
    }

    #[test]
    fn sample_draws_a_value() {
        let mut runner = TestRunner::deterministic();
        let p = sample(&exact_point(2), &mut runner);
        assert_eq!(p.dim(), 2);
    }

    #[test]
    #[should_panic(expected = "max_denominator")]
    fn zero_denominator_bound_is_refused() {
        let _ = rational(1, 0);
    }
}
