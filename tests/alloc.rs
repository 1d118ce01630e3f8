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
    assert_eq!(left.points()[3], p);
    assert_eq!(right.points()[0], p);
    let quad = Bezier::from_points([[0.0, 0.0], [1.0, 2.0], [3.0, 0.5]].map(Point2::from)).unwrap();
    let (n, cubic) = allocations(|| quad.elevate().unwrap());
    assert_eq!(n, 0, "elevate allocated");
    assert_eq!(cubic.degree(), 3);
}

#[test]
fn fixed_cubic_eval_split_and_elevation_allocate_nothing() {
    let c = Cubic::try_from(&cubic()).unwrap();
    let (n, p) = allocations(|| c.eval(&0.3));
    assert_eq!(n, 0, "eval allocated");
    let (n, (left, right)) = allocations(|| c.split_at(&0.3));
    assert_eq!(n, 0, "split_at allocated");
    assert_eq!((left.points()[3], right.points()[0]), (p, p));
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
