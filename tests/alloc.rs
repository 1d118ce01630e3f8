//! The `f64` fast path allocates nothing: a counting global allocator around cubic
//! evaluation, subdivision and elevation, on the any-degree and the fixed-degree curves.

use casteljau::{Bezier, Cubic, ParamCurve, Point2, Quad};

/// Allocations made by `f` on this thread (the counting global allocator is the
/// `allocation-counter` crate's, so this test needs no `unsafe` of its own).
fn allocations<R>(f: impl FnOnce() -> R) -> (usize, R) {
    let mut result = None;
    let info = allocation_counter::measure(|| result = Some(f()));
    (info.count_total as usize, result.expect("the closure ran"))
}

fn cubic() -> Bezier<Point2<f64>> {
    Bezier::from_points([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]].map(Point2::from)).unwrap()
}

#[test]
fn cubic_eval_and_split_allocate_nothing() {
    let c = cubic();
    let (n, p) = allocations(|| c.eval(&0.3));
    assert_eq!(n, 0, "eval allocated");
    let (n, (left, right)) = allocations(|| c.split_at(&0.3));
    assert_eq!(n, 0, "split_at allocated");
    // the halves share one point: de Casteljau's, within a few roundings of eval's
    assert_eq!(left.points()[3], right.points()[0]);
    assert!((left.points()[3].0[0] - p.0[0]).abs() <= 1e-15 && (left.points()[3].0[1] - p.0[1]).abs() <= 1e-15);
    let quad = Bezier::from_points([[0.0, 0.0], [1.0, 2.0], [3.0, 0.5]].map(Point2::from)).unwrap();
    let (n, cubic) = allocations(|| quad.elevate().unwrap());
    assert_eq!(n, 0, "elevate allocated");
    assert_eq!(cubic.degree(), 3);
    let (n, quartic) = allocations(|| cubic.elevate().unwrap());
    assert_eq!(n, 0, "elevate of a cubic allocated");
    assert_eq!(quartic.degree(), 4);
    // five points inline (a cubic's elevation) and the length word
    assert_eq!(std::mem::size_of::<Bezier<Point2<f64>>>(), 5 * 16 + 8);
}

#[test]
fn fixed_cubic_eval_split_and_elevation_allocate_nothing() {
    let c = Cubic::try_from(&cubic()).unwrap();
    let (n, _) = allocations(|| c.eval(&0.3));
    assert_eq!(n, 0, "eval allocated");
    let (n, (left, right)) = allocations(|| c.split_at(&0.3));
    assert_eq!(n, 0, "split_at allocated");
    assert_eq!(left.points()[3], right.points()[0]);
    assert_eq!(Bezier::from(left), cubic().split_at(&0.3).0);
    let (n, piece) = allocations(|| c.subsegment(&0.2, &0.7));
    assert_eq!(n, 0, "subsegment allocated");
    assert!(piece.is_ok());
    let quad = Quad::new([[0.0, 0.0], [1.0, 2.0], [3.0, 0.5]].map(Point2::from));
    let (n, elevated) = allocations(|| quad.elevate());
    assert_eq!(n, 0, "elevate allocated");
    let (n, quartic) = allocations(|| elevated.elevate());
    assert_eq!(n, 0, "elevate of a cubic allocated");
    let (n, hodograph) = allocations(|| c.deriv());
    assert_eq!(n, 0, "deriv allocated");
    assert_eq!((quartic.degree(), hodograph.degree()), (4, 2));
}

#[test]
fn high_degree_eval_allocates_nothing_below_the_stack_limit() {
    let c = Bezier::from_points((0..21).map(|i| Point2::new(i as f64, (i * i % 11) as f64))).unwrap();
    let (n, _) = allocations(|| c.eval(&0.3));
    assert_eq!(n, 0);
}

#[test]
fn the_counter_counts() {
    let (n, v) = allocations(|| vec![1u8; 100]);
    assert!(n >= 1);
    drop(v);
}

#[test]
fn runtime_dimension_points_are_inline() {
    let c: casteljau::BezierCurve<f64> =
        casteljau::BezierCurve::from_ints(&[&[0, 0], &[1, 2], &[3, 2], &[4, 0]]).unwrap();
    let (n, _) = allocations(|| c.eval(&0.3));
    assert_eq!(n, 0, "BezierCurve<f64>::eval allocated");
    let (n, _) = allocations(|| c.split_at(&0.3));
    assert_eq!(n, 0, "BezierCurve<f64>::split_at allocated");
}

/// Every `f64` evaluator of `casteljau::float` (plain, lerp, running bound, a priori
/// bounds, compensated value, derivative and surface) and `interval_de_casteljau` work on
/// stack copies: no allocation at any degree up to the documented limit, and the counter does
/// see the heap copy one coefficient beyond it.
#[test]
fn float_evaluators_allocate_nothing_up_to_the_stack_limit() {
    use casteljau::float::*;
    use casteljau::interval_de_casteljau;
    fn evaluate_all(b: &[f64], t: f64) -> f64 {
        let mut acc = de_casteljau(b, t);
        acc += lerp_de_casteljau(b, t) + lerp_bound(b, t);
        acc += abs_bernstein_sum(b, t) + a_priori_bound(b, t);
        let (v, e) = de_casteljau_running(b, t);
        acc += v + e;
        let (v, e) = compensated_de_casteljau(b, t);
        acc += v + e + compensated_a_priori_bound(b, t, v);
        let (v, e) = compensated_derivative(b, t);
        acc += v + e;
        let iv = interval_de_casteljau(b, t).expect("finite");
        acc + iv.lo() + iv.hi()
    }
    for len in 1..=STACK_COEFFICIENTS {
        let b: Vec<f64> = (0..len).map(|i| ((i * 7919) % 13) as f64 / 6.5 - 1.0).collect();
        for t in [0.3, 0.75, 1.0, 0.0, -0.5, 1e-310] {
            let (n, value) = allocations(|| evaluate_all(&b, t));
            assert_eq!(n, 0, "an evaluator allocated at degree {} and t = {t}", len - 1);
            assert!(value.is_finite());
        }
        // a value near underflow sends the compensated and interval triangles to their
        // second run, which must not allocate either
        let mut tiny = b.clone();
        tiny[0] = 1e-300;
        let (n, _) = allocations(|| evaluate_all(&tiny, 0.3));
        assert_eq!(n, 0, "a second run allocated at degree {}", len - 1);
    }
    let net: Vec<Vec<f64>> = (0..8)
        .map(|i| (0..6).map(|j| (i * j % 5) as f64 - 2.0).collect())
        .collect();
    let (n, _) = allocations(|| compensated_surface(&net, 0.3, 0.6));
    assert_eq!(n, 0, "compensated_surface allocated");
    let long = vec![0.5; STACK_COEFFICIENTS + 1];
    let (n, _) = allocations(|| compensated_de_casteljau(&long, 0.3));
    assert!(n > 0, "the counter misses the heap copy above the stack limit");
}

/// The generic algorithm on `Interval` scalars keeps its column on the stack too (up to the
/// kernel's `STACK_POINTS` points).
#[test]
fn generic_interval_eval_allocates_nothing() {
    use casteljau::{BezierCurve, Interval, Scalar};
    for len in [4, 11, 21] {
        let c: BezierCurve<Interval> = BezierCurve::from_coords(
            (0..len)
                .map(|i| vec![Interval::from_f64(((i * 7919) % 13) as f64 / 6.5 - 1.0).unwrap()])
                .collect(),
        )
        .unwrap();
        // a point of [0, 1] takes the sign-split kernel, the others the generic algorithm
        for t in [0.3, 0.0, 1.0, 1.5] {
            let t = Interval::from_f64(t).unwrap();
            let (n, p) = allocations(|| c.eval(&t));
            assert_eq!(n, 0, "BezierCurve<Interval>::eval allocated at degree {}", len - 1);
            assert!(p.coords()[0].lo() <= p.coords()[0].hi());
        }
        let t = Interval::new(0.25, 0.5).unwrap();
        let (n, _) = allocations(|| c.eval(&t));
        assert_eq!(n, 0, "BezierCurve<Interval>::eval allocated at an interval t");
    }
}

/// The sign-split kernel inside the public eval keeps its coefficients on the stack up to
/// `STACK_COEFFICIENTS`, in two and three run-time dimensions, on fixed-dimension points, and
/// for coefficients that are intervals (two triangles per coordinate).
#[test]
fn interval_eval_in_the_unit_interval_allocates_nothing_up_to_the_stack_limit() {
    use casteljau::float::STACK_COEFFICIENTS;
    use casteljau::{BezierCurve, Interval, Point2, Scalar};
    let coefficient = |i: usize| ((i * 7919) % 13) as f64 / 6.5 - 1.0;
    let t = Interval::from_f64(0.3).unwrap();
    for len in 1..=STACK_COEFFICIENTS {
        for dim in [2, 3] {
            let c: BezierCurve<Interval> = BezierCurve::from_coords(
                (0..len)
                    .map(|i| {
                        (0..dim)
                            .map(|k| Interval::new(coefficient(i + k), coefficient(i + k) + (k as f64)).unwrap())
                            .collect()
                    })
                    .collect(),
            )
            .unwrap();
            let (n, p) = allocations(|| c.eval(&t));
            assert_eq!(n, 0, "eval allocated at degree {} in {dim} dimensions", len - 1);
            assert_eq!(p.coords().len(), dim);
        }
        let fixed = Bezier::from_points((0..len).map(|i| {
            Point2::new(
                Interval::from_f64(coefficient(i)).unwrap(),
                Interval::from_f64(coefficient(i + 1)).unwrap(),
            )
        }))
        .unwrap();
        let (n, _) = allocations(|| fixed.eval(&t));
        assert_eq!(n, 0, "Bezier<Point2<Interval>>::eval allocated at degree {}", len - 1);
    }
}

#[test]
fn eval_many_allocates_nothing_up_to_degree_23() {
    let ts: Vec<f64> = (0..100).map(|i| i as f64 / 99.0).collect();
    let mut out = vec![Point2::new(0.0, 0.0); ts.len()];
    let c = Cubic::try_from(&cubic()).unwrap();
    let (n, r) = allocations(|| c.eval_many(&ts, &mut out));
    assert_eq!((n, r), (0, Ok(())), "Cubic::eval_many allocated");
    assert_eq!(out[37], c.eval(&ts[37]));
    let (n, r) = allocations(|| cubic().eval_many(&ts, &mut out));
    assert_eq!((n, r), (0, Ok(())), "Bezier::eval_many allocated");
    let high = Bezier::from_points((0..24).map(|i| Point2::new(i as f64, (i % 5) as f64))).unwrap();
    let (n, r) = allocations(|| high.eval_many(&ts, &mut out));
    assert_eq!((n, r), (0, Ok(())), "eval_many at degree 23 allocated");
    assert_eq!(out[99], high.eval(&ts[99]));
}
