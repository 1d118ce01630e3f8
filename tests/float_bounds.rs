//! The float bounds checked exactly: on random curves (degrees 3, 5, 10, 20, coefficients in
//! [−1, 1], t in [0, 1]) and near multiple roots, every bound is compared with the exact
//! error in rationals. The full 100,000-case run is `cargo run --release --example
//! float_errors`; this test runs a smaller sample of the same sets.

use casteljau::float::{
    a_priori_bound, a_priori_index, compensated_de_casteljau, compensated_derivative, compensated_surface,
    de_casteljau, de_casteljau_running, error_at_most, gamma_exact, ulp_error, UNIT_ROUNDOFF,
};
use casteljau::Interval;
use casteljau::Shadow;
use casteljau::{BezierCurve, BigRational, Scalar};
use num_traits::Signed;

#[path = "support/rng.rs"]
mod rng;
use rng::Rng;

fn q(x: f64) -> BigRational {
    BigRational::from_f64(x).unwrap()
}

/// The exact `p(t)` and `Σ|b_i| B_i(t)` (t in [0, 1]).
fn exact_value_and_sum(b: &[f64], t: f64) -> (BigRational, BigRational) {
    let curve = |c: Vec<BigRational>| BezierCurve::from_coords(c.into_iter().map(|x| vec![x]).collect()).unwrap();
    let p = curve(b.iter().map(|x| q(*x)).collect()).eval_nested(&q(t)).coords()[0].clone();
    let s = curve(b.iter().map(|x| q(f64::abs(*x))).collect())
        .eval_nested(&q(t))
        .coords()[0]
        .clone();
    (p, s)
}

/// Checks every bound on one case; panics with the case on a violation.
fn check_case(b: &[f64], t: f64) {
    let n = b.len() - 1;
    let (p, sum) = exact_value_and_sum(b, t);
    let err = |x: f64| Signed::abs(&(q(x) - &p));
    let plain = de_casteljau(b, t);
    // the a priori bound with its exact constant, and the float bound returned
    let exact_bound = gamma_exact(a_priori_index(n, t)) * &sum;
    assert!(err(plain) <= exact_bound, "a priori bound violated: {b:?} at {t}");
    assert!(error_at_most(plain, &p, a_priori_bound(b, t)), "{b:?} at {t}");
    let (value, running) = de_casteljau_running(b, t);
    assert_eq!(value.to_bits(), plain.to_bits());
    assert!(
        error_at_most(plain, &p, running),
        "running bound violated: {b:?} at {t}"
    );
    // compensated: u|p| + γ_{3n}² Σ|b_i|B_i (the constant, without the paper's 2)
    let (comp, comp_bound) = compensated_de_casteljau(b, t);
    let g = gamma_exact(3 * n);
    let tight = q(UNIT_ROUNDOFF) * Signed::abs(&p) + &g * &g * &sum;
    assert!(err(comp) <= tight, "compensated bound violated: {b:?} at {t}");
    assert!(error_at_most(comp, &p, comp_bound), "{b:?} at {t}");
    // the generic f64 evaluation of a cubic, the nested Bernstein sum: every b_i reaches the
    // result through at most 8 roundings with nonnegative weights, so γ_8 Σ|b_i|B_i bounds it
    if n == 3 {
        let curve = BezierCurve::from_coords(b.iter().map(|x| vec![*x]).collect()).unwrap();
        let value = curve.eval(&t).coords()[0];
        assert!(
            err(value) <= gamma_exact(8) * &sum,
            "generic cubic eval bound violated: {b:?} at {t}"
        );
    }
    // the interval scalar through the generic algorithm encloses the exact value
    let iv: BezierCurve<Interval> =
        BezierCurve::from_coords(b.iter().map(|x| vec![Interval::from_f64(*x).unwrap()]).collect()).unwrap();
    let e = iv.eval(&Interval::from_f64(t).unwrap()).coords()[0];
    assert!(e.contains(&p), "interval {e} misses the exact value: {b:?} at {t}");
}

fn random_coefficients(rng: &mut Rng, n: usize) -> Vec<f64> {
    (0..=n).map(|_| 2.0 * rng.unit() - 1.0).collect()
}

/// Bernstein coefficients of `(t − r)^n`, rounded to floats: a root of multiplicity `n`.
fn multiple_root(n: usize, r: f64) -> Vec<f64> {
    (0..=n)
        .map(|i| {
            let v = (-q(r)).pow((n - i) as i32) * (BigRational::from_integer(1.into()) - q(r)).pow(i as i32);
            Scalar::to_f64(&v)
        })
        .collect()
}

#[test]
fn bounds_hold_exactly_on_random_curves() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for &n in &[3usize, 5, 10, 20] {
        for _ in 0..150 {
            let b = random_coefficients(&mut rng, n);
            check_case(&b, rng.unit());
        }
    }
}

#[test]
fn bounds_hold_exactly_near_multiple_roots() {
    let mut rng = Rng(42);
    for &n in &[3usize, 5, 10] {
        for _ in 0..60 {
            let r = 0.2 + 0.6 * rng.unit();
            let b = multiple_root(n, r);
            let t = r + (rng.unit() - 0.5) * 10f64.powi(-(1 + (rng.next() % 7) as i32));
            check_case(&b, t);
        }
    }
}

/// The bound `compensated_de_casteljau` returns, in rationals, where its fast path for
/// `t ∈ [0, 1]` decides by itself whether Dekker's products are exact: coefficients from
/// subnormal to `1e300` (past the fast path's `Σ|b_i| ≤ 2^994`), zeros, mixed scales, `t`
/// at and near the ends of `[0, 1]`, and degrees up to 63 (with values fine enough that the
/// triangle rescans its grid, or gives up to the checked loop).
#[test]
fn compensated_bound_holds_at_the_edges() {
    let mut rng = Rng(0xC0_4E57);
    let scales = [
        1.0,
        1e-300,
        1e-310,
        5e-324,
        1e299,
        1e300,
        2f64.powi(-970),
        2f64.powi(-900),
    ];
    let ts = [0.0, 1.0, 0.5, 0.3, 1e-310, 1e-20, 1.0 - f64::EPSILON / 2.0, 0.7500001];
    for case in 0..600 {
        let n = [1, 2, 3, 4, 5, 6, 10, 17, 20, 40, 63][case % 11];
        let scale = scales[(rng.next() % scales.len() as u64) as usize];
        let b: Vec<f64> = (0..=n)
            .map(|_| match rng.next() % 10 {
                0 => 0.0,
                1 => 2f64.powi(-((rng.next() % 60) as i32)) * scale,
                _ => (2.0 * rng.unit() - 1.0) * scale,
            })
            .collect();
        let t = if case % 2 == 0 {
            ts[(rng.next() % ts.len() as u64) as usize]
        } else {
            rng.unit()
        };
        let (p, _) = exact_value_and_sum(&b, t);
        let (res, bound) = compensated_de_casteljau(&b, t);
        assert!(error_at_most(res, &p, bound), "{b:?} at {t}: {res:e} ± {bound:e}");
    }
}

#[test]
fn compensated_is_within_one_ulp_on_random_curves() {
    let mut rng = Rng(7);
    let mut worse = 0;
    let total = 400;
    for i in 0..total {
        let n = [3, 5, 10, 20][i % 4];
        let b = random_coefficients(&mut rng, n);
        let t = rng.unit();
        let (p, _) = exact_value_and_sum(&b, t);
        let (comp, _) = compensated_de_casteljau(&b, t);
        if ulp_error(comp, &p).unwrap().ulps > 1 {
            worse += 1;
        }
    }
    assert!(
        worse == 0,
        "{worse} of {total} more than 1 ulp from the correctly rounded value"
    );
}

#[test]
fn compensated_derivative_is_within_its_bound() {
    let mut rng = Rng(11);
    for i in 0..200 {
        let n = [1, 3, 5, 10, 20][i % 5];
        let b = random_coefficients(&mut rng, n);
        let t = rng.unit();
        let curve = BezierCurve::from_coords(b.iter().map(|x| vec![q(*x)]).collect()).unwrap();
        let exact = curve.derivative_at(1, &q(t)).unwrap().coords()[0].clone();
        let (d, bound) = compensated_derivative(&b, t);
        assert!(error_at_most(d, &exact, bound), "{b:?} at {t}");
    }
}

#[test]
fn the_shadow_scalar_reports_the_generic_algorithms_float_error() {
    let mut rng = Rng(5);
    for _ in 0..50 {
        let b = random_coefficients(&mut rng, 10);
        let t = rng.unit();
        let shadow: BezierCurve<Shadow> =
            BezierCurve::from_coords(b.iter().map(|x| vec![Shadow::from_f64(*x).unwrap()]).collect()).unwrap();
        let s = shadow.eval(&Shadow::from_f64(t).unwrap()).coords()[0].clone();
        let plain: BezierCurve<f64> = BezierCurve::from_coords(b.iter().map(|x| vec![*x]).collect()).unwrap();
        // the float side is bit for bit the f64 run; the exact side is the exact value
        assert_eq!(s.value().to_bits(), plain.eval(&t).coords()[0].to_bits());
        let (p, _) = exact_value_and_sum(&b, t);
        assert_eq!(s.exact(), &p);
        assert_eq!(s.ulp_error().unwrap(), ulp_error(s.value(), &p).unwrap());
    }
}

#[test]
fn intervals_enclose_split_and_derivatives_too() {
    let mut rng = Rng(3);
    for _ in 0..40 {
        let b = random_coefficients(&mut rng, 6);
        let t = rng.unit();
        let exact = BezierCurve::from_coords(b.iter().map(|x| vec![q(*x)]).collect()).unwrap();
        let iv: BezierCurve<Interval> =
            BezierCurve::from_coords(b.iter().map(|x| vec![Interval::from_f64(*x).unwrap()]).collect()).unwrap();
        let ti = Interval::from_f64(t).unwrap();
        let (l, r) = iv.split_at(&ti);
        let (el, er) = exact.split_at(&q(t));
        for (a, e) in l
            .points()
            .iter()
            .chain(r.points())
            .zip(el.points().iter().chain(er.points()))
        {
            assert!(a.coords()[0].contains(&e.coords()[0]));
        }
        let d = iv.derivative_at(2, &ti).unwrap().coords()[0];
        assert!(d.contains(&exact.derivative_at(2, &q(t)).unwrap().coords()[0]));
        // a non-float parameter enters as the two floats around it
        let third = Interval::from_ratio(1, 3).unwrap();
        let x = iv.eval(&third).coords()[0];
        assert!(x.contains(&exact.eval(&BigRational::new(1.into(), 3.into())).coords()[0]));
    }
}

/// The exact `s(u, v)` and `T = Σ_i Σ_j |b_ij| B_i^m(u) B_j^n(v)` (u, v in [0, 1]).
fn exact_surface(net: &[Vec<f64>], u: f64, v: f64) -> (BigRational, BigRational) {
    let eval = |abs: bool| {
        let rows: Vec<BigRational> = net
            .iter()
            .map(|row| {
                let coefs = row.iter().map(|x| if abs { q(f64::abs(*x)) } else { q(*x) }).collect();
                exact_on_curve(coefs, v)
            })
            .collect();
        exact_on_curve(rows, u)
    };
    (eval(false), eval(true))
}

fn exact_on_curve(coefs: Vec<BigRational>, t: f64) -> BigRational {
    BezierCurve::from_coords(coefs.into_iter().map(|x| vec![x]).collect())
        .unwrap()
        .eval_nested(&q(t))
        .coords()[0]
        .clone()
}

#[test]
fn compensated_surface_is_within_its_bound() {
    let mut rng = Rng(23);
    let mut within_one_ulp = 0;
    let total = 240;
    for i in 0..total {
        let (m, n) = [(0, 0), (1, 3), (3, 3), (5, 2), (6, 6), (10, 4)][i % 6];
        let (mut u, mut v) = (rng.unit(), rng.unit());
        let net: Vec<Vec<f64>> = if i % 2 == 0 {
            (0..=m).map(|_| random_coefficients(&mut rng, n)).collect()
        } else {
            // (u − 1/4)^m (v − 1/4)^n, whose coefficients 3^k / 4^d are exact floats, near its
            // multiple roots: heavy cancellation, the second-order terms of the bound matter
            u = 0.25 + (rng.unit() - 0.5) * 10f64.powi(-(1 + (rng.next() % 5) as i32));
            v = 0.25 + (rng.unit() - 0.5) * 10f64.powi(-(1 + (rng.next() % 5) as i32));
            let (a, b) = (multiple_root(m, 0.25), multiple_root(n, 0.25));
            a.iter().map(|x| b.iter().map(|y| x * y).collect()).collect()
        };
        let (p, t_sum) = exact_surface(&net, u, v);
        let (res, bound) = compensated_surface(&net, u, v);
        assert!(error_at_most(res, &p, bound), "{net:?} at ({u}, {v})");
        // the stated constant, exactly: u|p| + (2γ_{3n}² + 2γ_{3m}²(1 + γ_{3n}) + 2γ_{3m+3}·2γ_{3n}) T
        let (gn, gm) = (gamma_exact(3 * n), gamma_exact(3 * m));
        let one = BigRational::from_integer(1.into());
        let two = BigRational::from_integer(2.into());
        let c = &two * &gn * &gn + &two * &gm * &gm * (&one + &gn) + &two * gamma_exact(3 * m + 3) * &two * &gn;
        let tight = q(UNIT_ROUNDOFF) * Signed::abs(&p) + c * &t_sum;
        assert!(Signed::abs(&(q(res) - &p)) <= tight, "{net:?} at ({u}, {v})");
        if i % 2 == 0 && ulp_error(res, &p).unwrap().ulps <= 1 {
            within_one_ulp += 1;
        }
    }
    assert_eq!(within_one_ulp, total / 2, "compensated surface more than 1 ulp off");
}
