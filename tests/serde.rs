//! The `serde` feature: points and curves serialise and come back equal, and what they
//! refuse to be built from (no coordinates, mixed dimensions, a wrong length) they refuse to
//! be deserialised from, with an error rather than a panic.

use casteljau::{Bezier, BezierCurve, BigRational, Point, Point2, Scalar};

#[test]
fn exact_points_and_curves_round_trip() {
    let q = |p, d| BigRational::from_ratio(p, d).unwrap();
    let point = Point::new(vec![q(-4, 3), q(1, 7), q(0, 1)]).unwrap();
    let text = serde_json::to_string(&point).unwrap();
    assert_eq!(serde_json::from_str::<Point<BigRational>>(&text).unwrap(), point);

    let curve: BezierCurve<BigRational> = BezierCurve::from_ints(&[&[0, 0], &[1, 2], &[3, 2], &[4, 0]]).unwrap();
    let curve = curve.split_at(&q(1, 3)).0;
    let text = serde_json::to_string(&curve).unwrap();
    assert_eq!(serde_json::from_str::<BezierCurve<BigRational>>(&text).unwrap(), curve);
}

#[test]
fn float_points_serialise_as_plain_arrays() {
    let p = Point2::new(0.5, -2.0);
    assert_eq!(serde_json::to_string(&p).unwrap(), "[0.5,-2.0]");
    let curve = Bezier::new(vec![p, Point2::new(1.0, 1.0)]).unwrap();
    assert_eq!(serde_json::to_string(&curve).unwrap(), "[[0.5,-2.0],[1.0,1.0]]");
    assert_eq!(
        serde_json::from_str::<Bezier<Point2<f64>>>("[[0.5,-2.0],[1.0,1.0]]").unwrap(),
        curve
    );
    assert_eq!(
        serde_json::from_str::<Point<f64>>("[0.5,-2.0]").unwrap().coords(),
        &[0.5, -2.0]
    );
}

#[test]
fn what_cannot_be_built_cannot_be_deserialised() {
    let err = |r: Result<(), serde_json::Error>| r.unwrap_err().to_string();
    let point = |s: &str| serde_json::from_str::<Point<f64>>(s).map(drop);
    let fixed = |s: &str| serde_json::from_str::<Point2<f64>>(s).map(drop);
    let curve = |s: &str| serde_json::from_str::<BezierCurve<f64>>(s).map(drop);
    assert!(
        err(point("[]")).contains("at least one coordinate"),
        "{}",
        err(point("[]"))
    );
    assert!(
        err(fixed("[1.0, 2.0, 3.0]")).contains("2 coordinates"),
        "{}",
        err(fixed("[1.0, 2.0, 3.0]"))
    );
    assert!(err(fixed("[1.0]")).contains("2 coordinates"));
    assert!(err(curve("[]")).contains("empty"), "{}", err(curve("[]")));
    let mixed = err(curve("[[0.0, 0.0], [1.0]]"));
    assert!(mixed.contains("dimension"), "{mixed}");
    assert!(curve("[[0.0, 0.0], [1.0, 2.0]]").is_ok());
}
