//! `interval_de_casteljau`'s two-triangle enclosure (`t ∈ [0, 1]`) holds the exact value
//! of the curve on its float inputs, decided in rationals, on random curves of every scale:
//! subnormal, ordinary, near `f64::MAX`, mixed, with signed zeros and cancellation; its width
//! stays within the a priori bound's order, `6(n + 1)u max|b_i|`, and non-finite inputs or
//! no coefficients are errors, never a panic. The public `BezierCurve<Interval>::eval` (and
//! `Bezier<Point2<Interval>>`) at a point `t ∈ [0, 1]` gives that enclosure per coordinate,
//! also for coefficients that are intervals; elsewhere the generic algorithm's.

#[path = "support/rng.rs"]
mod rng;

use casteljau::float::{eval_dyadic, UNIT_ROUNDOFF};
use casteljau::{interval_de_casteljau, tight_interval_de_casteljau};
use casteljau::{Bezier, BezierCurve, BigRational, Interval, Point2, Scalar};
use rng::Rng;

fn exact_value(b: &[f64], t: f64) -> BigRational {
    let curve: BezierCurve<BigRational> =
        BezierCurve::from_coords(b.iter().map(|x| vec![BigRational::from_f64(*x).unwrap()]).collect()).unwrap();
    eval_dyadic(&curve, &BigRational::from_f64(t).unwrap())
        .unwrap()
        .coords()[0]
        .clone()
}

fn coefficient(rng: &mut Rng, scale: f64) -> f64 {
    const SPECIALS: [f64; 9] = [
        0.0,
        -0.0,
        5e-324,
        -1e-310,
        f64::MIN_POSITIVE,
        1.0,
        -0.5,
        f64::MAX,
        -f64::MAX,
    ];
    if rng.next() % 8 == 0 {
        SPECIALS[(rng.next() % SPECIALS.len() as u64) as usize]
    } else {
        (2.0 * rng.unit() - 1.0) * scale
    }
}

#[test]
fn the_enclosure_holds_the_exact_value_at_every_scale() {
    let mut rng = Rng(24);
    let ts = [0.0, 1.0, 0.5, 0.3, 1e-310, 5e-324, 0.9999999999999999, 1e-20, 0.7500001];
    let mut wider = 0.0f64;
    for case in 0..4_000 {
        let n = [0, 1, 2, 3, 5, 10, 20, 40, 63, 64][case % 10];
        let scale = match case % 6 {
            0 => 1.0,
            1 => 1e-300,
            2 => 1e300,
            3 => 1e-310,
            4 => f64::MAX,
            _ => 2f64.powi((rng.next() % 2000) as i32 - 1000),
        };
        let b: Vec<f64> = (0..=n).map(|_| coefficient(&mut rng, scale)).collect();
        let t = if case % 3 == 0 {
            ts[(rng.next() % ts.len() as u64) as usize]
        } else {
            rng.unit()
        };
        let e = interval_de_casteljau(&b, t).unwrap();
        let exact = exact_value(&b, t);
        assert!(e.contains(&exact), "{e} misses the exact value: {b:?} at {t:e}");
        assert!(e.lo().is_finite() && e.hi().is_finite(), "{e}: {b:?} at {t:e}");
        // against the tight interval (printed): wider where most of its operations are exact;
        // the absolute slack skips subnormal widths
        let tight = tight_interval_de_casteljau(&b, t).unwrap();
        let slack = 1e-300 * f64::MIN_POSITIVE;
        if tight.width() > slack {
            wider = wider.max(e.width() / tight.width());
        }
        let abs_sum: f64 = b.iter().map(|x| x.abs() / 4.0).fold(0.0, f64::max) * 4.0;
        let reach = 6.0 * (n as f64 + 1.0) * UNIT_ROUNDOFF * abs_sum;
        assert!(
            e.width() <= 2.0 * reach + 1e-320 || !reach.is_finite(),
            "{e} is wider than 6(n+1)u max|b_i|: {b:?} at {t:e}"
        );
    }
    println!("widest against the tight interval: {wider:.2}×");
}

#[test]
fn a_cancellation_near_a_root_is_still_enclosed() {
    // (t − 3/4)^3 near its triple root: the enclosure straddles zero, narrowly
    let b = [-0.421875, 0.140625, -0.046875, 0.015625];
    for k in 0..400 {
        let t = 0.75 + (k as f64 - 200.0) * 1e-9;
        let e = interval_de_casteljau(&b, t).unwrap();
        assert!(e.contains(&exact_value(&b, t)), "{e} at {t}");
        assert!(e.width() < 1e-15, "{e} at {t}");
    }
}

#[test]
fn bad_input_is_an_error() {
    for b in [
        vec![1.0, f64::NAN],
        vec![f64::INFINITY, 1.0, 2.0],
        vec![0.0, f64::NEG_INFINITY],
        vec![f64::NAN],
    ] {
        for t in [0.0, 0.3, 1.0, 1.5, -0.25] {
            assert!(interval_de_casteljau(&b, t).is_err(), "{b:?} at {t}");
        }
    }
    assert!(interval_de_casteljau(&[1.0, 2.0], f64::NAN).is_err());
    assert!(interval_de_casteljau(&[1.0, 2.0], f64::INFINITY).is_err());
    assert!(interval_de_casteljau(&[], 0.3).is_err());
    assert!(tight_interval_de_casteljau(&[], 0.3).is_err());
}

#[test]
fn outside_the_unit_interval_it_is_the_tight_interval() {
    let b = [0.1, -2.5, 3.25, 1e-3];
    for t in [-0.25, 1.5, -1e-300] {
        assert_eq!(
            interval_de_casteljau(&b, t).unwrap(),
            tight_interval_de_casteljau(&b, t).unwrap()
        );
    }
}

fn interval_curve(coords: &[&[f64]]) -> BezierCurve<Interval> {
    let len = coords[0].len();
    BezierCurve::from_coords(
        (0..len)
            .map(|i| coords.iter().map(|b| Interval::point(b[i]).unwrap()).collect())
            .collect(),
    )
    .unwrap()
}

/// The public operation picks the sign-split kernel for a point `t ∈ [0, 1]`: the same
/// enclosure, coordinate by coordinate, on the run-time and the fixed dimension points, and
/// it holds the exact value at every scale.
#[test]
fn the_public_eval_is_the_enclosure_at_every_scale() {
    let mut rng = Rng(2024);
    let ts = [0.0, 1.0, 0.5, 0.3, 1e-310, 5e-324, 0.9999999999999999, 1e-20, 0.7500001];
    for case in 0..2_000 {
        let n = [0, 1, 2, 3, 5, 10, 20, 40, 63][case % 9];
        let scale = [
            1.0,
            1e-300,
            1e300,
            1e-310,
            f64::MAX,
            2f64.powi((rng.next() % 2000) as i32 - 1000),
        ][case % 6];
        let x: Vec<f64> = (0..=n).map(|_| coefficient(&mut rng, scale)).collect();
        let y: Vec<f64> = (0..=n).map(|_| coefficient(&mut rng, scale)).collect();
        let t = if case % 3 == 0 {
            ts[(rng.next() % ts.len() as u64) as usize]
        } else {
            rng.unit()
        };
        let ti = Interval::point(t).unwrap();
        let p = interval_curve(&[&x, &y]).eval(&ti);
        let fixed: Bezier<Point2<Interval>> = Bezier::from_points(
            x.iter()
                .zip(&y)
                .map(|(a, b)| Point2::new(Interval::point(*a).unwrap(), Interval::point(*b).unwrap())),
        )
        .unwrap();
        let q = fixed.eval(&ti);
        for (k, b) in [&x, &y].into_iter().enumerate() {
            let e = p.coords()[k];
            assert_eq!(q.0[k], e, "Point2 and Point differ: {b:?} at {t:e}");
            assert!(
                e.contains(&exact_value(b, t)),
                "{e} misses the exact value: {b:?} at {t:e}"
            );
            // the triangles on |b_i| ≤ 2^1000 stay finite: the kernel answered, not the generic path
            if b.iter().all(|c| c.abs() < 1e300) {
                assert_eq!(
                    e,
                    interval_de_casteljau(b, t).unwrap(),
                    "not the kernel: {b:?} at {t:e}"
                );
            }
        }
    }
}

/// Points of 1 to 6 coordinates (up to 4 are kept inline in a point, more on the heap): the
/// public eval's coordinate `k` is the kernel's enclosure of coordinate `k` alone, for a
/// cubic (its own path) and for other degrees.
#[test]
fn every_dimension_is_coordinate_by_coordinate() {
    let mut rng = Rng(606);
    for case in 0..600 {
        let dim = 1 + case % 6;
        let n = [3, 3, 1, 2, 4, 7][(case / 6) % 6];
        let coords: Vec<Vec<f64>> = (0..dim)
            .map(|_| (0..=n).map(|_| coefficient(&mut rng, 1.0)).collect())
            .collect();
        let rows: Vec<&[f64]> = coords.iter().map(Vec::as_slice).collect();
        let t = rng.unit();
        let p = interval_curve(&rows).eval(&Interval::point(t).unwrap());
        assert_eq!(p.dim(), dim);
        for (k, b) in coords.iter().enumerate() {
            assert_eq!(
                p.coords()[k],
                interval_de_casteljau(b, t).unwrap(),
                "dim {dim}, degree {n}, coordinate {k}"
            );
        }
    }
}

/// Coefficients that are intervals: the curve over them runs from the curve on the lower
/// endpoints to the one on the upper endpoints (nonnegative weights on `[0, 1]`), and the
/// public eval encloses both, and a curve in between; an interval `t` or one outside
/// `[0, 1]` takes the generic algorithm, as `eval_reference` does.
#[test]
fn interval_coefficients_and_other_parameters() {
    let mut rng = Rng(77);
    for case in 0..1_000 {
        let n = [1, 2, 3, 7, 10, 20][case % 6];
        let lo: Vec<f64> = (0..=n).map(|_| 2.0 * rng.unit() - 1.0).collect();
        let width: Vec<f64> = (0..=n)
            .map(|i| if (case + i) % 3 == 0 { 0.0 } else { rng.unit() * 1e-3 })
            .collect();
        let hi: Vec<f64> = lo.iter().zip(&width).map(|(l, w)| l + w).collect();
        let mid: Vec<f64> = lo.iter().zip(&hi).map(|(l, h)| l + (h - l) / 2.0).collect();
        let c = BezierCurve::from_coords(
            lo.iter()
                .zip(&hi)
                .map(|(l, h)| vec![Interval::new(*l, *h).unwrap()])
                .collect(),
        )
        .unwrap();
        let t = rng.unit();
        let e = c.eval(&Interval::point(t).unwrap()).coords()[0];
        for b in [&lo, &hi, &mid] {
            assert!(e.contains(&exact_value(b, t)), "{e}: {b:?} at {t}");
        }
        // the kernel's enclosure on the lower endpoints joined with the one on the upper
        // endpoints, bit for bit (the cubic's is computed out of line)
        let (low, high) = (
            interval_de_casteljau(&lo, t).unwrap(),
            interval_de_casteljau(&hi, t).unwrap(),
        );
        assert_eq!(e, Interval::new(low.lo(), high.hi()).unwrap(), "{lo:?}, {hi:?} at {t}");
        for t in [
            Interval::point(1.0 + t).unwrap(),
            Interval::point(-t).unwrap(),
            Interval::new(t / 2.0, t).unwrap(),
        ] {
            assert_eq!(c.eval(&t), c.eval_reference(&t));
        }
    }
}

/// Ill-conditioned curves through the public eval: the enclosure holds near a root of
/// multiplicity 3, 7 and 15, where plain de Casteljau has no correct digit.
#[test]
fn the_public_eval_encloses_near_multiple_roots() {
    for m in [3usize, 7, 15] {
        // (t − 3/4)^m in Bernstein form, exact in floats: (−3/4)^(m−i) (1/4)^i
        let b: Vec<f64> = (0..=m)
            .map(|i| (-0.75f64).powi((m - i) as i32) * 0.25f64.powi(i as i32))
            .collect();
        let c = interval_curve(&[&b]);
        for k in 0..200 {
            let t = 0.75 + (k as f64 - 100.0) * 1e-7;
            let e = c.eval(&Interval::point(t).unwrap()).coords()[0];
            assert!(e.contains(&exact_value(&b, t)), "{e} at {t}, multiplicity {m}");
        }
    }
}

/// The check can fail: where the enclosure is as narrow as it gets (clamped to the largest
/// coefficient, which is the exact value at `t = 0`), one ulp less misses the exact value;
/// so does the plain float value as a point near a triple root.
#[test]
fn a_shrunk_enclosure_misses_the_exact_value() {
    let b = [f64::MAX, -f64::MAX, 0.5];
    let e = interval_curve(&[&b]).eval(&Interval::point(0.0).unwrap()).coords()[0];
    let exact = exact_value(&b, 0.0);
    assert!(e.contains(&exact) && e.hi() == f64::MAX, "{e}");
    let shrunk = Interval::new(e.lo(), casteljau::float::next_down(e.hi())).unwrap();
    assert!(!shrunk.contains(&exact), "{shrunk}");
    let b = [-0.421875, 0.140625, -0.046875, 0.015625];
    let t = 0.7500001;
    let plain = casteljau::float::de_casteljau(&b, t);
    assert!(!Interval::point(plain).unwrap().contains(&exact_value(&b, t)));
    assert!(interval_curve(&[&b]).eval(&Interval::point(t).unwrap()).coords()[0].contains(&exact_value(&b, t)));
}
