//! Text 004 (cubic fit of a space curve) and least-squares fitting, checked exactly.
//!
//! Equations of text 004 are encoded *as printed*; where the print is wrong the test shows
//! the failure and checks the corrected form beside it.

use casteljau::bernstein;
use casteljau::linalg::{determinant, inverse, mat_mul, solve};
use casteljau::{
    chord_length_params, cubic_with_tangent_lengths, delta_squared, delta_squared_gradient, fit_cubic,
    fit_cubic_closed_form, fit_cubic_to, fit_least_squares, least_squares_gradient, least_squares_residual,
    uniform_params, CubicFitData, FitConstraints,
};
use casteljau::{BezierCurve, BigRational, Error, Point, Ring, Scalar};
use proptest::prelude::*;

type Q = BigRational;

fn q(p: i64, d: i64) -> Q {
    Q::from_ratio(p, d).unwrap()
}

fn p(c: &[i64]) -> Point<Q> {
    Point::from_ints(c).unwrap()
}

fn rat() -> impl Strategy<Value = Q> {
    (-30i64..=30, 1i64..=7).prop_map(|(n, d)| q(n, d))
}

fn point(dim: usize) -> impl Strategy<Value = Point<Q>> {
    prop::collection::vec(rat(), dim).prop_map(|c| Point::new(c).unwrap())
}

fn data_in(dim: usize) -> impl Strategy<Value = CubicFitData<Q>> {
    (point(dim), point(dim), point(dim), point(dim), point(dim))
        .prop_map(|(a, b, c, d, e)| CubicFitData::new(a, b, c, d, e).unwrap())
}

fn data() -> impl Strategy<Value = CubicFitData<Q>> {
    (2usize..=5).prop_flat_map(data_in)
}

fn gram_det(d: &CubicFitData<Q>) -> Q {
    let g = d.gram();
    &(&g[0][0] * &g[1][1]) - &(&g[0][1] * &g[1][0])
}

/// The quartic space curve x(t) = (t, 1 + t², t⁴) of the worked example below.
fn quartic() -> CubicFitData<Q> {
    let coeffs = vec![
        p(&[0, 1, 0]),
        p(&[1, 0, 0]),
        p(&[0, 1, 0]),
        p(&[0, 0, 0]),
        p(&[0, 0, 1]),
    ];
    CubicFitData::from_power(&coeffs).unwrap()
}

// ---- worked example ----------------------------------------------------------------------

#[test]
fn worked_example_quartic_space_curve() {
    // x(0) = (0,1,0), x(1) = (1,2,1), x(1/2) = (1/2, 5/4, 1/16), ẋ(0) = (1,0,0), ẋ(1) = (1,2,4).
    let d = quartic();
    assert_eq!(d.xh, Point::new(vec![q(1, 2), q(5, 4), q(1, 16)]).unwrap());
    assert_eq!(d.d1, p(&[1, 2, 4]));
    assert_eq!(d.x_vector(), Point::new(vec![q(0, 1), q(1, 2), q(7, 8)]).unwrap());
    // By hand from (13): det G = 20, (−k, l) = 4/60 · (−9/2, 9/2).
    let fit = fit_cubic(&d).unwrap();
    assert_eq!((fit.k.clone(), fit.l.clone()), (q(3, 10), q(3, 10)));
    assert_eq!(fit.gram_determinant, q(20, 1));
    assert_eq!(fit.residual, Point::new(vec![q(0, 1), q(1, 40), q(-1, 80)]).unwrap());
    assert_eq!(fit.delta2, q(1, 1280));
    assert!(fit.warnings.is_empty() && fit.tangent_lengths_positive());
    assert_eq!(fit_cubic_closed_form(&d).unwrap(), (q(3, 10), q(3, 10)));
}

// ---- printed equations of text 004 --------------------------------------------------------

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// (1): the printed power form equals the Bernstein form. Both sides are cubics in t, so
    /// agreement at 4 distinct parameters is a proof; we check 5.
    #[test]
    fn equation_1_power_form_is_the_bezier_cubic(pts in prop::collection::vec(point(3), 4)) {
        let c = BezierCurve::new(pts.clone()).unwrap();
        let (a0, a1, a2, a3) = (&pts[0], &pts[1], &pts[2], &pts[3]);
        let three = q(3, 1);
        let c1 = a0.sub(a1).scale(&-&three);                                   // −3(a0 − a1)
        let c2 = a0.sub(&a1.scale(&q(2, 1))).add(a2).scale(&three);            // 3(a0 − 2a1 + a2)
        let c3 = a0.sub(&a1.scale(&three)).add(&a2.scale(&three)).sub(a3).neg(); // −(a0 − 3a1 + 3a2 − a3)
        for t in [q(0, 1), q(1, 3), q(1, 2), q(2, 1), q(-5, 7)] {
            let printed = a0.add(&c1.scale(&t)).add(&c2.scale(&t.powi(2))).add(&c3.scale(&t.powi(3)));
            prop_assert_eq!(printed, c.eval_bernstein(&t));
        }
    }

    /// (5) and both lines of (6) equal δ² computed from the definition (de Casteljau).
    #[test]
    fn equations_5_and_6_hold(d in data(), k in rat(), l in rat()) {
        let a = cubic_with_tangent_lengths(&d, &k, &l).unwrap();
        let (k38, l38) = (&q(3, 8) * &k, &q(3, 8) * &l);
        // (5)
        let a_half = d.x0.add(&d.x1).scale(&q(1, 2)).add(&d.d0.scale(&k38)).sub(&d.d1.scale(&l38));
        prop_assert_eq!(&a_half, &a.eval(&q(1, 2)));
        // (6), first line
        let line1 = a_half.sub(&d.xh).norm_squared();
        // (6), second line: (X/2 + 3k/8 ẋ(0) − 3l/8 ẋ(1))·(same)
        let v = d.x_vector().scale(&q(1, 2)).add(&d.d0.scale(&k38)).sub(&d.d1.scale(&l38));
        let line2 = v.dot(&v);
        let defined = delta_squared(&d, &k, &l).unwrap();
        prop_assert_eq!(&line1, &defined);
        prop_assert_eq!(&line2, &defined);
    }

    /// (7) and (9), both printed forms, equal the derivatives of δ² computed from the
    /// definition (the library's gradient), at arbitrary (k, l). (9) differentiates by −l.
    #[test]
    fn equations_7_and_9_hold(d in data(), k in rat(), l in rat()) {
        let (dk, dl) = delta_squared_gradient(&d, &k, &l).unwrap();
        let x = d.x_vector();
        let v = x.scale(&q(1, 2)).add(&d.d0.scale(&(&q(3, 8) * &k))).sub(&d.d1.scale(&(&q(3, 8) * &l)));
        let (g00, g01, g11) = (d.d0.dot(&d.d0), d.d0.dot(&d.d1), d.d1.dot(&d.d1));
        let (k34, l34) = (&q(3, 4) * &k, &q(3, 4) * &l);
        // (7)
        prop_assert_eq!(&(&q(3, 4) * &d.d0.dot(&v)), &dk);
        prop_assert_eq!(&(&q(3, 8) * &(&(&d.d0.dot(&x) + &(&k34 * &g00)) - &(&l34 * &g01))), &dk);
        // (9): ∂/∂(−l) = −∂/∂l
        let d_minus_l = -&dl;
        prop_assert_eq!(&(&q(3, 4) * &d.d1.dot(&v)), &d_minus_l);
        prop_assert_eq!(&(&q(3, 8) * &(&(&d.d1.dot(&x) + &(&k34 * &g01)) - &(&l34 * &g11))), &d_minus_l);
        // And the gradient itself is the derivative: δ² is quadratic, so central differences
        // with any step are exact.
        let h = q(1, 5);
        let fd_k = (&delta_squared(&d, &(&k + &h), &l).unwrap() - &delta_squared(&d, &(&k - &h), &l).unwrap()).checked_div(&(&q(2, 1) * &h)).unwrap();
        let fd_l = (&delta_squared(&d, &k, &(&l + &h)).unwrap() - &delta_squared(&d, &k, &(&l - &h)).unwrap()).checked_div(&(&q(2, 1) * &h)).unwrap();
        prop_assert_eq!(fd_k, dk);
        prop_assert_eq!(fd_l, dl);
    }

    /// (11) is the corrected (8), (10); (12) is the Gram factorisation; (13)'s adjugate
    /// formula is the inverse of G.
    #[test]
    fn equations_11_12_13_hold(d in data()) {
        let (m, rhs) = d.normal_equations();
        let x = d.x_vector();
        let g = d.gram();
        // (11) row by row against the corrected (8) and (10), for the unknowns (−k, l).
        prop_assert_eq!(&m[0][0], &(&q(3, 4) * &d.d0.dot(&d.d0)));
        prop_assert_eq!(&m[0][1], &(&q(3, 4) * &d.d0.dot(&d.d1)));
        prop_assert_eq!(&m[1][0], &(&q(3, 4) * &d.d1.dot(&d.d0)));
        prop_assert_eq!(&m[1][1], &(&q(3, 4) * &d.d1.dot(&d.d1)));
        prop_assert_eq!(&rhs, &vec![d.d0.dot(&x), d.d1.dot(&x)]);
        // (12): G = (ẋ(0); ẋ(1)) (ẋ(0) ẋ(1)), a 2×dim times dim×2 product.
        let rows = vec![d.d0.coords().to_vec(), d.d1.coords().to_vec()];
        let cols: Vec<Vec<Q>> = (0..d.d0.dim()).map(|i| vec![d.d0.coords()[i].clone(), d.d1.coords()[i].clone()]).collect();
        prop_assert_eq!(&mat_mul(&rows, &cols).unwrap(), &g);
        // (13): adj(G)/det G is G⁻¹ (when it exists).
        let det = gram_det(&d);
        prop_assert_eq!(&determinant(&g).unwrap(), &det);
        if !det.is_zero() {
            let adj = [vec![g[1][1].clone(), -&g[0][1]], vec![-&g[1][0], g[0][0].clone()]];
            let by_adj: Vec<Vec<Q>> = adj.iter().map(|r| r.iter().map(|a| a.checked_div(&det).unwrap()).collect()).collect();
            prop_assert_eq!(by_adj, inverse(&g).unwrap());
        }
    }

    /// The closed form (13) equals the exact solution of (11); the gradient of δ² vanishes
    /// exactly there and nowhere else nearby; the minimum is not beaten by neighbours.
    #[test]
    fn closed_form_equals_solver_and_is_the_minimum(d in data(), dk in rat(), dl in rat()) {
        if gram_det(&d).is_zero() {
            prop_assert!(matches!(fit_cubic(&d), Err(Error::Singular(_))));
            prop_assert!(matches!(fit_cubic_closed_form(&d), Err(Error::Singular(_))));
            return Ok(());
        }
        let fit = fit_cubic(&d).unwrap();
        let (k, l) = fit_cubic_closed_form(&d).unwrap();
        prop_assert_eq!(&k, &fit.k);
        prop_assert_eq!(&l, &fit.l);
        let (gk, gl) = delta_squared_gradient(&d, &k, &l).unwrap();
        prop_assert!(gk.is_zero() && gl.is_zero());
        prop_assert_eq!(&fit.delta2, &delta_squared(&d, &k, &l).unwrap());
        prop_assert!(d.d0.dot(&fit.residual).is_zero() && d.d1.dot(&fit.residual).is_zero());
        // G is positive definite here, so any other (k, l) has a larger δ² and a non-zero gradient.
        if !(dk.is_zero() && dl.is_zero()) {
            let (k2, l2) = (&k + &dk, &l + &dl);
            prop_assert!(delta_squared(&d, &k2, &l2).unwrap() > fit.delta2);
            let (gk2, gl2) = delta_squared_gradient(&d, &k2, &l2).unwrap();
            prop_assert!(!(gk2.is_zero() && gl2.is_zero()));
        }
        // Diagnostics are exactly the sign conditions the text assumes.
        prop_assert_eq!(fit.warnings.is_empty(), k > Q::zero() && l > Q::zero());
        prop_assert_eq!(fit.warnings.len(), usize::from(k <= Q::zero()) + usize::from(l <= Q::zero()));
    }

    /// The text's remark: a plane curve with independent end tangents is matched at t = 1/2.
    #[test]
    fn plane_case_gives_delta_zero(d in data_in(2)) {
        if gram_det(&d).is_zero() {
            return Ok(());
        }
        let fit = fit_cubic(&d).unwrap();
        prop_assert!(fit.delta2.is_zero());
        prop_assert_eq!(fit.curve.eval(&q(1, 2)), d.xh.clone());
    }

    /// A cubic Bézier curve with independent end tangents is its own fit: k = l = 1/3, δ = 0.
    #[test]
    fn cubic_is_recovered(pts in prop::collection::vec(point(3), 4)) {
        let c = BezierCurve::new(pts).unwrap();
        let d = CubicFitData::from_curve(&c).unwrap();
        if gram_det(&d).is_zero() {
            return Ok(());
        }
        let fit = fit_cubic_to(&c).unwrap();
        prop_assert_eq!(&fit.k, &q(1, 3));
        prop_assert_eq!(&fit.l, &q(1, 3));
        prop_assert_eq!(&fit.curve, &c);
        prop_assert!(fit.delta2.is_zero());
    }

    /// The power form and the Bézier form of the same curve give the same data.
    #[test]
    fn power_and_bezier_data_agree(coeffs in (1usize..=6).prop_flat_map(|n| prop::collection::vec(point(3), n))) {
        let c = BezierCurve::from_power(&coeffs).unwrap();
        prop_assert_eq!(CubicFitData::from_power(&coeffs).unwrap(), CubicFitData::from_curve(&c).unwrap());
    }

    /// f64 runs the same code: it agrees with the exact fit to 1e-9 (relative), on data
    /// whose end tangents are not nearly parallel (det G ≥ 1e-3 |ẋ(0)|²|ẋ(1)|²).
    #[test]
    fn f64_agrees_with_exact(d in data()) {
        let g = d.gram();
        let det = gram_det(&d);
        if det.is_zero() || det.to_f64() < 1e-3 * (&g[0][0] * &g[1][1]).to_f64() {
            return Ok(());
        }
        let exact = fit_cubic(&d).unwrap();
        let to_f = |p: &Point<Q>| p.try_map(f64::from_rational).unwrap();
        let df = CubicFitData::new(to_f(&d.x0), to_f(&d.x1), to_f(&d.xh), to_f(&d.d0), to_f(&d.d1)).unwrap();
        let float = fit_cubic(&df).unwrap();
        prop_assert!(float.k.approx_eq(&exact.k.to_f64(), 1e-9), "{} vs {}", float.k, exact.k);
        prop_assert!(float.l.approx_eq(&exact.l.to_f64(), 1e-9), "{} vs {}", float.l, exact.l);
        let scale = 1.0 + d.x_vector().norm_squared().to_f64();
        prop_assert!((float.delta2 - exact.delta2.to_f64()).abs() <= 1e-9 * scale);
        let (kc, lc) = fit_cubic_closed_form(&df).unwrap();
        prop_assert!(kc.approx_eq(&float.k, 1e-9) && lc.approx_eq(&float.l, 1e-9));
    }
}

/// The printed (8) and (10) have `X·x(0)` and `X·x(1)` on the right; the derivation (7), (9)
/// and the matrix form (11) have `X·ẋ(0)`, `X·ẋ(1)`. At the optimum the corrected equations
/// hold and the printed ones fail.
#[test]
fn printed_equations_8_and_10_fail_corrected_hold() {
    let d = quartic();
    let fit = fit_cubic(&d).unwrap();
    let (k, l) = (&fit.k, &fit.l);
    let x = d.x_vector();
    let (g00, g01, g10, g11) = (d.d0.dot(&d.d0), d.d0.dot(&d.d1), d.d1.dot(&d.d0), d.d1.dot(&d.d1));
    let lhs8 = &(&(-&q(3, 4)) * &(&g00 * k)) + &(&q(3, 4) * &(&g01 * l));
    let lhs10 = &(&(-&q(3, 4)) * &(&g10 * k)) + &(&q(3, 4) * &(&g11 * l));
    // Corrected: right-hand sides X·ẋ(0), X·ẋ(1).
    assert_eq!(lhs8, x.dot(&d.d0));
    assert_eq!(lhs10, x.dot(&d.d1));
    // As printed: X·x(0) = 1/2 and X·x(1) = 15/8, but the left-hand sides are 0 and 9/2.
    assert_eq!((lhs8.clone(), lhs10.clone()), (q(0, 1), q(9, 2)));
    assert_eq!(x.dot(&d.x0), q(1, 2));
    assert_eq!(x.dot(&d.x1), q(15, 8));
    assert_ne!(lhs8, x.dot(&d.x0));
    assert_ne!(lhs10, x.dot(&d.x1));

    // Solving the printed (8), (10) gives a point that is not the minimum: the gradient of δ²
    // does not vanish there and δ² is larger.
    let (m, _) = d.normal_equations();
    let printed = solve(&m, &[x.dot(&d.x0), x.dot(&d.x1)]).unwrap();
    let (kp, lp) = (-&printed[0], printed[1].clone());
    let (gk, gl) = delta_squared_gradient(&d, &kp, &lp).unwrap();
    assert!(!(gk.is_zero() && gl.is_zero()));
    assert!(delta_squared(&d, &kp, &lp).unwrap() > fit.delta2);

    // And the printed version is not even translation invariant, while δ² is: moving the
    // curve by (0, 5, 0) changes the printed solution but not the true one.
    let shift = p(&[0, 5, 0]);
    let moved = CubicFitData::new(
        d.x0.add(&shift),
        d.x1.add(&shift),
        d.xh.add(&shift),
        d.d0.clone(),
        d.d1.clone(),
    )
    .unwrap();
    assert_eq!(fit_cubic(&moved).unwrap().k, fit.k);
    let printed_moved = solve(&m, &[x.dot(&moved.x0), x.dot(&moved.x1)]).unwrap();
    assert_ne!(printed_moved, printed);
}

#[test]
fn negative_tangent_lengths_are_flagged() {
    // With orthonormal tangents, k = −4/3 X·ẋ(0) and l = 4/3 X·ẋ(1).
    // x(1/2) = (10, −3, 1): X = (−19, 6, −2), k = 76/3, l = 8: as the text assumes.
    let d = CubicFitData::new(
        p(&[0, 0, 0]),
        p(&[1, 0, 0]),
        p(&[10, -3, 1]),
        p(&[1, 0, 0]),
        p(&[0, 1, 0]),
    )
    .unwrap();
    let fit = fit_cubic(&d).unwrap();
    assert_eq!((fit.k.clone(), fit.l.clone()), (q(76, 3), q(8, 1)));
    assert!(fit.warnings.is_empty());
    // x(1/2) = (−10, −3, 1): X = (21, 6, −2), k = −28 < 0: flagged.
    let d = CubicFitData::new(
        p(&[0, 0, 0]),
        p(&[1, 0, 0]),
        p(&[-10, -3, 1]),
        p(&[1, 0, 0]),
        p(&[0, 1, 0]),
    )
    .unwrap();
    let fit = fit_cubic(&d).unwrap();
    assert_eq!((fit.k.clone(), fit.l.clone()), (q(-28, 1), q(8, 1)));
    assert!(!fit.tangent_lengths_positive());
    assert_eq!(fit.warnings.len(), 1);
    assert!(
        fit.warnings[0].contains("k = ") && fit.warnings[0].contains("assumes k > 0"),
        "{:?}",
        fit.warnings
    );
}

#[test]
fn float_nearly_parallel_tangents_are_flagged() {
    let z = |c: [f64; 3]| Point::new(c.to_vec()).unwrap();
    let d = CubicFitData::new(
        z([0.0, 0.0, 0.0]),
        z([1.0, 0.0, 0.0]),
        z([0.5, 0.2, 0.1]),
        z([1.0, 0.0, 0.0]),
        z([1.0, 1e-6, 0.0]),
    )
    .unwrap();
    let fit = fit_cubic(&d).unwrap();
    assert!(
        fit.warnings.iter().any(|w| w.contains("nearly parallel")),
        "{:?}",
        fit.warnings
    );
}

// ---- least squares --------------------------------------------------------------------------

/// Random distinct exact parameters in [0, 1] plus samples.
fn ls_problem(dim: usize, count: usize) -> impl Strategy<Value = (Vec<Point<Q>>, Vec<Q>)> {
    (
        prop::collection::vec(point(dim), count),
        prop::collection::btree_set(0i64..=60, count),
    )
        .prop_map(|(y, ts)| (y, ts.into_iter().map(|t| q(t, 60)).collect()))
}

/// `Bᵀ (B P − Y)`, the normal-equation residual, computed directly from the Bernstein
/// polynomials (one value at a time, not the library's recurrence).
fn normal_equation_residual(y: &[Point<Q>], t: &[Q], c: &BezierCurve<Q>) -> Vec<Point<Q>> {
    let n = c.degree();
    (0..=n)
        .map(|i| {
            let mut acc = Point::origin(c.dim());
            for (tj, yj) in t.iter().zip(y) {
                let mut bp = Point::origin(c.dim());
                for (k, pk) in c.points().iter().enumerate() {
                    bp = bp.add(&pk.scale(&bernstein(k, n, tj).unwrap()));
                }
                acc = acc.add(&bp.sub(yj).scale(&bernstein(i, n, tj).unwrap()));
            }
            acc
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Unconstrained: the normal equations hold exactly, Bᵀ(B P − Y) = 0, and the library's
    /// gradient is exactly zero; any perturbation of one control point does not lower E.
    #[test]
    fn free_fit_satisfies_normal_equations(
        (y, t) in (2usize..=3, 5usize..=9).prop_flat_map(|(dim, m)| ls_problem(dim, m)),
        degree in 0usize..=3,
        bump in point(1),
    ) {
        let fit = fit_least_squares(&y, &t, degree, &FitConstraints::none()).unwrap();
        prop_assert!(normal_equation_residual(&y, &t, &fit.curve).iter().all(Point::is_zero));
        prop_assert!(fit.gradient.iter().all(Scalar::is_zero));
        prop_assert_eq!(fit.gradient.len(), (degree + 1) * y[0].dim());
        prop_assert_eq!(&fit.residual_squared, &least_squares_residual(&y, &t, &fit.curve).unwrap());
        let mut pts = fit.curve.points().to_vec();
        let mut delta = Point::origin(pts[0].dim());
        delta = delta.add(&Point::new(vec![bump.coords()[0].clone(); pts[0].dim()]).unwrap());
        pts[degree / 2] = pts[degree / 2].add(&delta);
        let other = BezierCurve::new(pts).unwrap();
        prop_assert!(least_squares_residual(&y, &t, &other).unwrap() >= fit.residual_squared);
        if !bump.is_zero() {
            prop_assert!(!least_squares_gradient(&y, &t, &other, &FitConstraints::none()).unwrap().iter().all(Scalar::is_zero));
        }
    }

    /// End points and end directions fixed: the constraints hold exactly, the gradient over
    /// the remaining unknowns (free inner points, α, β) is exactly zero, and changing α or β
    /// does not lower E.
    #[test]
    fn constrained_fit_is_optimal(
        (y, t) in (2usize..=3, 6usize..=9).prop_flat_map(|(dim, m)| ls_problem(dim, m)),
        degree in 3usize..=4,
        d0 in point(3), d1 in point(3), step in rat(),
    ) {
        let dim = y[0].dim();
        let cut = |p: &Point<Q>| Point::new(p.coords()[..dim].to_vec()).unwrap();
        let (d0, d1) = (cut(&d0), cut(&d1));
        prop_assume!(!d0.is_zero() && !d1.is_zero());
        let (start, end) = (y[0].clone(), y[y.len() - 1].clone());
        let cons = FitConstraints::endpoints_and_directions(start.clone(), end.clone(), d0.clone(), d1.clone());
        let fit = match fit_least_squares(&y, &t, degree, &cons) {
            Ok(f) => f,
            // Only a genuinely singular system may fail: e.g. parameters where B_1 and B_{n−1}
            // cannot be told apart from the inner basis functions.
            Err(Error::Singular(_)) => return Ok(()),
            Err(e) => return Err(TestCaseError::fail(e.to_string())),
        };
        let pts = fit.curve.points();
        let (alpha, beta) = (fit.alpha.clone().unwrap(), fit.beta.clone().unwrap());
        prop_assert_eq!(&pts[0], &start);
        prop_assert_eq!(&pts[degree], &end);
        prop_assert_eq!(&pts[1], &start.add(&d0.scale(&alpha)));
        prop_assert_eq!(&pts[degree - 1], &end.sub(&d1.scale(&beta)));
        prop_assert!(fit.gradient.iter().all(Scalar::is_zero));
        prop_assert_eq!(fit.gradient.len(), (degree - 3) * dim + 2);
        prop_assert_eq!(&least_squares_gradient(&y, &t, &fit.curve, &cons).unwrap(), &fit.gradient);
        let mut moved = pts.to_vec();
        moved[1] = moved[1].add(&d0.scale(&step));
        moved[degree - 1] = moved[degree - 1].sub(&d1.scale(&step));
        let other = BezierCurve::new(moved).unwrap();
        prop_assert!(least_squares_residual(&y, &t, &other).unwrap() >= fit.residual_squared);
        prop_assert_eq!(fit.warnings.len(), usize::from(alpha <= Q::zero()) + usize::from(beta <= Q::zero()));
    }

    /// Samples of a degree-n curve are fitted exactly by degree n, with or without
    /// constraints consistent with that curve.
    #[test]
    fn samples_on_a_curve_are_recovered(pts in (1usize..=4).prop_flat_map(|n| prop::collection::vec(point(3), n + 1))) {
        let c = BezierCurve::new(pts).unwrap();
        let n = c.degree();
        let t: Vec<Q> = uniform_params(n + 3).unwrap();
        let y: Vec<Point<Q>> = t.iter().map(|t| c.eval(t)).collect();
        let fit = fit_least_squares(&y, &t, n, &FitConstraints::none()).unwrap();
        prop_assert_eq!(&fit.curve, &c);
        prop_assert!(fit.residual_squared.is_zero());
        let cons = FitConstraints::endpoints(c.points()[0].clone(), c.points()[n].clone());
        prop_assert_eq!(&fit_least_squares(&y, &t, n, &cons).unwrap().curve, &c);
    }

    /// f64 agrees with the exact fit within 1e-8 (relative to the data size) for degree ≤ 3
    /// on well-spread parameters.
    #[test]
    fn least_squares_f64_agrees_with_exact(
        (y, t) in (2usize..=3, 7usize..=10).prop_flat_map(|(dim, m)| ls_problem(dim, m)),
        degree in 1usize..=3,
    ) {
        let spread = &t[t.len() - 1] - &t[0];
        prop_assume!(spread >= q(1, 2));
        let exact = fit_least_squares(&y, &t, degree, &FitConstraints::none()).unwrap();
        let yf: Vec<Point<f64>> = y.iter().map(|p| p.try_map(f64::from_rational).unwrap()).collect();
        let tf: Vec<f64> = t.iter().map(Scalar::to_f64).collect();
        let float = fit_least_squares(&yf, &tf, degree, &FitConstraints::none()).unwrap();
        for (a, b) in float.curve.points().iter().zip(exact.curve.points()) {
            for (x, e) in a.coords().iter().zip(b.to_f64()) {
                prop_assert!((x - e).abs() <= 1e-8 * (1.0 + e.abs()) * 100.0, "{} vs {}", x, e);
            }
        }
        prop_assert!(float.gradient.iter().all(|g| g.abs() < 1e-6));
    }
}

#[test]
fn under_determined_and_repeated_parameters_are_errors() {
    let y = vec![p(&[0, 0]), p(&[1, 1]), p(&[2, 0])];
    let t: Vec<Q> = uniform_params(3).unwrap();
    let err = fit_least_squares(&y, &t, 3, &FitConstraints::none()).unwrap_err();
    assert!(matches!(err, Error::Singular(_)));
    assert!(err.to_string().contains("under-determined"), "{err}");
    // Fixing both ends leaves 2 free points: 3 samples can suffice for degree 3, but not at
    // t = 0, 1/2, 1, where only t = 1/2 sees a1 and a2 (B_1 and B_2 vanish at the ends).
    let cons = FitConstraints::endpoints(p(&[0, 0]), p(&[2, 0]));
    let err = fit_least_squares(&y, &t, 3, &cons).unwrap_err();
    assert!(
        matches!(err, Error::Singular(_)) && err.to_string().contains("normal equations"),
        "{err}"
    );
    let inner = vec![q(1, 4), q(1, 2), q(3, 4)];
    let fit = fit_least_squares(&y, &inner, 3, &cons).unwrap();
    assert!(fit.gradient.iter().all(Scalar::is_zero));
    let same = vec![q(1, 2); 3];
    let err = fit_least_squares(&y, &same, 2, &FitConstraints::none()).unwrap_err();
    assert!(err.to_string().contains("distinct parameters"), "{err}");
    assert!(matches!(
        fit_least_squares::<Q>(&[], &[], 1, &FitConstraints::none()),
        Err(Error::Empty(_))
    ));
    let nan = vec![0.0, f64::NAN, 1.0];
    let yf = vec![Point::new(vec![0.0, 0.0]).unwrap(); 3];
    assert!(matches!(
        fit_least_squares(&yf, &nan, 1, &FitConstraints::none()),
        Err(Error::NotFinite(_))
    ));
}

#[test]
fn chord_length_fit_in_f64() {
    // Points on a straight line, unevenly spaced: chord-length parameters are the true
    // (affine) parameters, so a line fits with residual ~0.
    let y: Vec<Point<f64>> = [0.0, 0.1, 0.5, 0.6, 2.0]
        .iter()
        .map(|&s| Point::new(vec![1.0 + 3.0 * s, 2.0 - 4.0 * s]).unwrap())
        .collect();
    let t = chord_length_params(&y).unwrap();
    let fit = fit_least_squares(&y, &t, 1, &FitConstraints::none()).unwrap();
    assert!(fit.residual_squared < 1e-24, "{}", fit.residual_squared);
    assert!(fit.curve.points()[1].approx_eq(&Point::new(vec![7.0, -6.0]).unwrap(), 1e-12));
}

#[test]
fn text_004_as_a_least_squares_problem() {
    // Text 004's problem is the constrained least-squares fit with a single sample x(1/2):
    // end points fixed, end directions ẋ(0), ẋ(1): then α = k and β = l.
    let d = quartic();
    let cons = FitConstraints::endpoints_and_directions(d.x0.clone(), d.x1.clone(), d.d0.clone(), d.d1.clone());
    let fit = fit_least_squares(std::slice::from_ref(&d.xh), &[q(1, 2)], 3, &cons).unwrap();
    let cubic = fit_cubic(&d).unwrap();
    assert_eq!(fit.alpha, Some(cubic.k.clone()));
    assert_eq!(fit.beta, Some(cubic.l.clone()));
    assert_eq!(fit.curve, cubic.curve);
    assert_eq!(fit.residual_squared, cubic.delta2);
    assert_eq!(fit.unknowns, vec!["alpha".to_string(), "beta".to_string()]);
}

#[test]
fn rational_quarter_circle_is_fitted_exactly_in_the_plane() {
    // Text 001, Example 1: x(t) = ((1-t²)/(1+t²), 2t/(1+t²)), a quarter of the unit circle.
    let circle = casteljau::RationalBezierCurve::new(
        vec![p(&[1, 0]), p(&[1, 1]), p(&[0, 1])],
        vec![q(1, 1), q(1, 1), q(2, 1)],
    )
    .unwrap();
    let data = casteljau::CubicFitSource::cubic_fit_data(&circle).unwrap();
    assert_eq!(data.xh, Point::new(vec![q(3, 5), q(4, 5)]).unwrap());
    assert_eq!(data.d0, p(&[0, 2]));
    assert_eq!(data.d1, p(&[-1, 0]));
    let fit = fit_cubic(&data).unwrap();
    // A plane curve with independent end tangents: δ = 0 exactly (text 004's remark).
    assert_eq!(fit.delta2, q(0, 1));
    assert_eq!(fit.curve.eval(&q(1, 2)), data.xh);
}

#[test]
fn hand_built_data_of_mixed_dimensions_is_an_error_not_a_panic() {
    // CubicFitData's fields are public: delta_squared and its gradient validate them.
    let d = CubicFitData {
        x0: p(&[0, 0]),
        x1: p(&[1, 0, 0]),
        xh: p(&[0, 1]),
        d0: p(&[1, 0]),
        d1: p(&[0, 1]),
    };
    assert!(matches!(
        delta_squared(&d, &q(1, 1), &q(1, 1)),
        Err(casteljau::Error::DimensionMismatch { .. })
    ));
    assert!(delta_squared_gradient(&d, &q(1, 1), &q(1, 1)).is_err());
    assert!(fit_cubic(&d).is_err());
}
