//! The filtered predicates agree with exact arithmetic on the same floats, and fall back to
//! it only when the interval straddles zero (counted).

use casteljau::{classify_conic, BigRational, Point, RationalBezierCurve, Ring, Scalar};
use casteljau::{filter_stats, filtered_conic_kind, filtered_hull_contains, filtered_orientation};
use std::cmp::Ordering;

fn exact_orientation(p: [f64; 2], q: [f64; 2], r: [f64; 2]) -> Ordering {
    let e = |x: f64| BigRational::from_f64(x).unwrap();
    let det = (e(q[0]) - e(p[0])) * (e(r[1]) - e(p[1])) - (e(q[1]) - e(p[1])) * (e(r[0]) - e(p[0]));
    det.partial_cmp(&BigRational::from_i64(0)).unwrap()
}

#[test]
fn orientation_is_exact_and_mostly_filtered() {
    let before = filter_stats();
    let mut state = 12345u64;
    let mut unit = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    for i in 0..2000 {
        let p = [unit(), unit()];
        let q = [unit(), unit()];
        // every other r is on the line pq up to rounding: the hard cases
        let r = if i % 2 == 0 {
            let s = unit();
            [p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])]
        } else {
            [unit(), unit()]
        };
        assert_eq!(
            filtered_orientation(p, q, r).unwrap(),
            exact_orientation(p, q, r),
            "{p:?} {q:?} {r:?}"
        );
    }
    let after = filter_stats();
    let (filtered, exact) = (after.filtered - before.filtered, after.exact - before.exact);
    // (the counters are global: the other tests of this file may add to them meanwhile)
    assert!(filtered + exact >= 2000);
    assert!(filtered >= 1000 && exact > 0, "filtered {filtered}, exact {exact}");
}

#[test]
fn hull_membership_matches_the_exact_hull() {
    let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let exact: Vec<Point<BigRational>> = square
        .iter()
        .map(|c| Point::new(c.iter().map(|x| BigRational::from_f64(*x).unwrap()).collect()).unwrap())
        .collect();
    for p in [
        [0.5, 0.5],
        [1.0, 0.3],
        [1.0 + 1e-16, 0.3],
        [0.1 * 3.0, 0.3],
        [-1e-300, 0.5],
        [0.0, 0.0],
        [2.0, 2.0],
    ] {
        let q = Point::new(p.iter().map(|x| BigRational::from_f64(*x).unwrap()).collect()).unwrap();
        let want = casteljau::convex_weights(&exact, &q).unwrap().is_some();
        assert_eq!(filtered_hull_contains(&square, p).unwrap(), want, "{p:?}");
    }
    // a degenerate hull: a segment, with p on it and just off it
    let segment = [[0.0, 0.0], [1.0, 1.0]];
    assert!(filtered_hull_contains(&segment, [0.5, 0.5]).unwrap());
    assert!(!filtered_hull_contains(&segment, [0.5, 0.5000000000000001]).unwrap());
    assert!(!filtered_hull_contains(&segment, [1.5, 1.5]).unwrap());
}

#[test]
fn conic_kind_agrees_with_exact_classification() {
    let pts = |c: [[f64; 2]; 3]| c.iter().map(|p| Point::new(p.to_vec()).unwrap()).collect::<Vec<_>>();
    for (points, weights) in [
        ([[-1.0, 1.0], [0.0, -1.0], [1.0, 1.0]], [1.0, 0.5, 1.0]),
        ([[-1.0, 1.0], [0.0, -1.0], [1.0, 1.0]], [1.0, 0.1 * 3.0, 0.09]),
        ([[-1.0, 1.0], [0.0, -1.0], [1.0, 1.0]], [1.0, 0.3, 0.3 * 0.3]),
        ([[0.0, 0.0], [0.1, 0.2], [0.3, 0.6000000000000001]], [1.0, 1.0, 1.0]),
        ([[0.0, 0.0], [0.1, 0.2], [0.2, 0.4]], [1.0, 2.0, 1.0]),
        ([[-1.0, 1.0], [0.0, -1.0], [1.0, 1.0]], [1.0, 0.0, 1.0]),
    ] {
        let arc = RationalBezierCurve::new(pts(points), weights.to_vec()).unwrap();
        let exact = classify_conic(&arc.try_map(|x| BigRational::from_f64(*x)).unwrap()).unwrap();
        assert_eq!(filtered_conic_kind(&arc).unwrap(), exact, "{points:?} {weights:?}");
    }
}
