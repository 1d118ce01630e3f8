//! The curve properties of `curve_props.rs` on `f64`, with stated tolerances, and the
//! f64 results measured against the exact result of the *same* inputs.
//!
//! Inputs: degree ≤ 12, dimension ≤ 3, coordinates in [-100, 100], parameters in [0, 1]
//! unless said otherwise. `M` is the largest coordinate magnitude of the control points.
//!
//! * f64 algorithms against each other: agreement within `REL_TOL · max(M, 1)` where the
//!   algorithms are backward stable (de Casteljau, Bernstein sum, elevation, subdivision);
//!   the power basis is ill-conditioned, so its tolerance is scaled by `(1 + 2|t|)^n`, the
//!   growth of the power coefficients `C(n,i) Δ^i b_0`.
//! * f64 against exact (every f64 input converted exactly with `from_f64`, the exact path run
//!   on it, the error computed exactly): the error, in units in the last place of `M`, stays
//!   below bounds derived from the operation counts, e.g. `5n` ulp for de Casteljau (each of
//!   the `n` levels `a + t(b - a)` commits at most `5u·M` and never amplifies earlier errors
//!   when `0 ≤ t ≤ 1`).

use casteljau::eval_power;
use casteljau::strategies::{f64_curve, unit_parameter_f64, wide_parameter_f64};
use casteljau::{BezierCurve, BigRational, Point, Ring, Scalar};
use proptest::prelude::*;
use proptest::test_runner::Config;

type Q = BigRational;

/// Relative tolerance for backward-stable f64 algorithms, degree ≤ 12, |coordinates| ≤ 100.
const REL_TOL: f64 = 1e-12;

fn max_abs(c: &BezierCurve<f64>) -> f64 {
    c.points()
        .iter()
        .flat_map(|p| p.coords())
        .fold(0.0, |m: f64, x| m.max(x.abs()))
}

fn close(a: &Point<f64>, b: &Point<f64>, abs_tol: f64) -> bool {
    a.dim() == b.dim() && a.coords().iter().zip(b.coords()).all(|(x, y)| (x - y).abs() <= abs_tol)
}

fn exact(c: &BezierCurve<f64>) -> BezierCurve<Q> {
    // Cannot fail: the strategies produce finite floats only.
    c.try_map(|&x| Q::from_f64(x)).unwrap()
}

fn exact_scalar(x: f64) -> Q {
    Q::from_f64(x).unwrap()
}

/// The unit in the last place of `x` (a power of two), as an exact rational; `x` finite, > 0.
fn ulp(x: f64) -> Q {
    let x = x.abs();
    exact_scalar(f64::from_bits(x.to_bits() + 1)) - exact_scalar(x)
}

/// The largest coordinate error of `float` against `exact`, in ulps of `scale` (computed
/// exactly). With `scale == 0` any error at all counts as infinite.
fn error_in_ulps(float: &Point<f64>, exact: &Point<Q>, scale: f64) -> f64 {
    let mut worst = Q::zero();
    for (f, e) in float.coords().iter().zip(exact.coords()) {
        let err = (exact_scalar(*f) - e).abs();
        if err > worst {
            worst = err;
        }
    }
    if worst.is_zero() {
        return 0.0;
    }
    if scale == 0.0 {
        return f64::INFINITY;
    }
    worst.checked_div(&ulp(scale)).unwrap().to_f64()
}

fn eval_power_points(coeffs: &[Point<f64>], t: f64) -> Point<f64> {
    let dim = coeffs[0].dim();
    Point::new(
        (0..dim)
            .map(|k| eval_power(&coeffs.iter().map(|a| a.coords()[k]).collect::<Vec<_>>(), &t))
            .collect(),
    )
    .unwrap()
}

proptest! {
    #![proptest_config(Config::with_cases(96))]

    // ---- f64 against f64 ----

    #[test]
    fn evaluations_agree(c in f64_curve(0..=12, 1..=3, 100.0), t in unit_parameter_f64()) {
        let m = max_abs(&c).max(1.0);
        let p = c.eval(&t);
        prop_assert!(close(&p, &c.eval_bernstein(&t), REL_TOL * m));
        let growth = (1.0 + 2.0 * t.abs()).powi(c.degree() as i32);
        prop_assert!(close(&p, &eval_power_points(&c.to_power().unwrap(), t), REL_TOL * m * growth));
    }

    #[test]
    fn elevation_and_split_agree(
        c in f64_curve(0..=12, 1..=3, 100.0),
        r in 0..=5usize,
        t0 in unit_parameter_f64(),
        t in unit_parameter_f64(),
    ) {
        let tol = REL_TOL * max_abs(&c).max(1.0);
        let e = c.elevate_by(r).unwrap();
        prop_assert!(close(&e.eval(&t), &c.eval(&t), tol));
        for (a, b) in e.points().iter().zip(c.elevate_steps(r).unwrap().points()) {
            prop_assert!(close(a, b, tol));
        }
        let (left, right) = c.split_at(&t0);
        prop_assert!(close(&left.eval(&t), &c.eval(&(t0 * t)), tol));
        prop_assert!(close(&right.eval(&t), &c.eval(&(t0 + (1.0 - t0) * t)), tol));
    }

    /// Outside [0, 1] de Casteljau amplifies rounding by up to (|t| + |1 - t|)^n.
    #[test]
    fn extrapolation_within_amplified_tolerance(c in f64_curve(0..=12, 1..=3, 100.0), t in wide_parameter_f64()) {
        let growth = (t.abs() + (1.0 - t).abs()).powi(c.degree() as i32);
        let tol = REL_TOL * max_abs(&c).max(1.0) * growth;
        prop_assert!(close(&c.eval(&t), &c.eval_bernstein(&t), tol));
        prop_assert!(close(&c.elevate().unwrap().eval(&t), &c.eval(&t), tol));
    }

    #[test]
    fn derivative_and_tangent_agree(c in f64_curve(1..=12, 1..=3, 100.0), t in unit_parameter_f64()) {
        let n = c.degree();
        let m = max_abs(&c).max(1.0);
        // |b'| ≤ 2nM; the scheme difference is computed from values of size M.
        let s = c.scheme(&t);
        let chord = s.get(n - 1, 1).unwrap().sub(s.get(n - 1, 0).unwrap()).scale(&(n as f64));
        prop_assert!(close(&c.derivative_at(1, &t).unwrap(), &chord, REL_TOL * 2.0 * n as f64 * m));
        prop_assert!(c.derivative_at(n + 1, &t).unwrap().is_zero());
    }

    /// The allocation-free fast path performs the very same operations: bit-for-bit equal.
    #[test]
    fn eval_array_is_bitwise_eval(c in f64_curve(0..=24, 1..=3, 100.0), t in wide_parameter_f64()) {
        let slow = c.eval(&t);
        let fast: Vec<f64> = match c.dim() {
            1 => c.eval_array::<1>(t).unwrap().to_vec(),
            2 => c.eval_array::<2>(t).unwrap().to_vec(),
            _ => c.eval_array::<3>(t).unwrap().to_vec(),
        };
        let same_bits = fast.iter().zip(slow.coords()).all(|(a, b)| a.to_bits() == b.to_bits());
        prop_assert!(same_bits, "{:?} vs {:?}", fast, slow.coords());
        prop_assert!(c.eval_array::<4>(t).is_err());
    }

    // ---- f64 against the exact result of the same inputs ----

    /// de Casteljau: at most 5n ulp(M); the Bernstein sum: at most 4n + 2 ulp(M).
    #[test]
    fn eval_error_in_ulps(c in f64_curve(0..=12, 1..=3, 100.0), t in unit_parameter_f64()) {
        let n = c.degree() as f64;
        let m = max_abs(&c);
        let oracle = exact(&c).eval(&exact_scalar(t));
        let e1 = error_in_ulps(&c.eval(&t), &oracle, m);
        prop_assert!(e1 <= 5.0 * n, "de Casteljau error {} ulp at degree {}", e1, n);
        let e2 = error_in_ulps(&c.eval_bernstein(&t), &oracle, m);
        prop_assert!(e2 <= 4.0 * n + 2.0, "Bernstein-sum error {} ulp at degree {}", e2, n);
    }

    /// Subdivision: every control point of both halves within 5n ulp(M).
    #[test]
    fn split_error_in_ulps(c in f64_curve(0..=12, 1..=3, 100.0), t0 in unit_parameter_f64()) {
        let n = c.degree() as f64;
        let m = max_abs(&c);
        let (l, r) = c.split_at(&t0);
        let (le, re) = exact(&c).split_at(&exact_scalar(t0));
        for (f, e) in l.points().iter().chain(r.points()).zip(le.points().iter().chain(re.points())) {
            prop_assert!(error_in_ulps(f, e, m) <= 5.0 * n);
        }
    }

    /// Elevation: one step (7) within 7 ulp(M) per point; r steps by (8) within n + 3 ulp(M).
    #[test]
    fn elevation_error_in_ulps(c in f64_curve(0..=12, 1..=3, 100.0), r in 1..=6usize) {
        let m = max_abs(&c);
        let x = exact(&c);
        for (f, e) in c.elevate().unwrap().points().iter().zip(x.elevate().unwrap().points()) {
            prop_assert!(error_in_ulps(f, e, m) <= 7.0);
        }
        let bound = c.degree() as f64 + 3.0;
        for (f, e) in c.elevate_by(r).unwrap().points().iter().zip(x.elevate_by(r).unwrap().points()) {
            let err = error_in_ulps(f, e, m);
            prop_assert!(err <= bound, "elevate_by({}) error {} ulp, bound {}", r, err, bound);
        }
    }

    /// Derivative control points n!/(n-k)! Δ^k b_j: within (k + 1) ulp of their a-priori size
    /// n!/(n-k)! 2^k M (k levels of differences, one scaling).
    #[test]
    fn derivative_error_in_ulps(c in f64_curve(1..=12, 1..=3, 100.0), k in 1..=4usize) {
        let n = c.degree();
        let k = k.min(n);
        let factor: f64 = ((n - k + 1)..=n).map(|m| m as f64).product();
        let scale = factor * 2f64.powi(k as i32) * max_abs(&c);
        let f = c.derivative(k).unwrap();
        let e = exact(&c).derivative(k).unwrap();
        for (a, b) in f.points().iter().zip(e.points()) {
            prop_assert!(error_in_ulps(a, b, scale) <= (k + 1) as f64);
        }
    }
}

/// The worst errors actually seen are far below the bounds; this pins one hard case: a
/// degree-12 curve with alternating ±100 control points (maximal cancellation) at t = 1/3.
#[test]
fn alternating_degree_12_at_one_third() {
    let coords: Vec<Vec<f64>> = (0..=12)
        .map(|i| vec![if i % 2 == 0 { 100.0 } else { -100.0 }])
        .collect();
    let c = BezierCurve::from_coords(coords).unwrap();
    let t = 1.0 / 3.0;
    let oracle = exact(&c).eval(&exact_scalar(t));
    let err = error_in_ulps(&c.eval(&t), &oracle, 100.0);
    assert!(err <= 60.0, "{err}");
    // The exact value is 100 (1 - 2t)^12 at the float nearest 1/3, about 100/3^12.
    let value = oracle.coords()[0].to_f64();
    assert!((value - 100.0 / 531_441.0).abs() < 1e-9, "{value}");
}
