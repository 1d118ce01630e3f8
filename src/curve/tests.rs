use super::*;
type Q = BigRational;

fn q(p: i64, d: i64) -> Q {
    Q::from_ratio(p, d).unwrap()
}

fn text_example() -> BezierCurve<Q> {
    let a = |c: &[i64]| Point::from_ints(c).unwrap();
    // (-u² + 1, -u³ + u): coefficients of u^0..u^3
    let coeffs = vec![a(&[1, 0]), a(&[0, 1]), a(&[-1, 0]), a(&[0, -1])];
    BezierCurve::from_power_on(&coeffs, &q(-1, 1), &q(1, 1)).unwrap()
}

#[test]
fn text_000_power_to_bezier_example() {
    let c = text_example();
    let expect = [
        Point::new(vec![q(0, 1), q(0, 1)]).unwrap(),
        Point::new(vec![q(4, 3), q(-4, 3)]).unwrap(),
        Point::new(vec![q(4, 3), q(4, 3)]).unwrap(),
        Point::new(vec![q(0, 1), q(0, 1)]).unwrap(),
    ];
    assert_eq!(c.points(), &expect[..]);
}

#[test]
fn scheme_boundary_is_split() {
    let c = text_example();
    let t = q(1, 3);
    let s = c.scheme(&t);
    let (l, r) = c.split_at(&t);
    assert_eq!(s.point(), &c.eval(&t));
    for k in 0..=3 {
        assert_eq!(&l.points()[k], s.get(k, 0).unwrap());
        assert_eq!(&r.points()[k], s.get(3 - k, k).unwrap());
    }
    let shown = s.to_string();
    assert!(shown.contains("b_0^3 = "), "{shown}");
}

#[test]
fn elevate_by_many_steps_of_a_line() {
    // The elevated polygon of a segment is the segment divided evenly; r = 2000 also
    // exercises the binomial rows at a size where C(n+r, i) one at a time would be slow.
    let c: BezierCurve<Q> = BezierCurve::from_ints(&[&[0, 0], &[2001, -4002]]).unwrap();
    let e = c.elevate_by(2000).unwrap();
    assert_eq!(e.degree(), 2001);
    for (i, p) in e.points().iter().enumerate() {
        assert_eq!(p, &Point::from_ints(&[i as i64, -2 * i as i64]).unwrap());
    }
}

#[test]
fn eval_array_is_bitwise_eval() {
    // below and above the stack buffer, in 1 and 3 dimensions, inside and outside [0, 1]
    for n in [0usize, 1, 3, 15, 16, 30] {
        let coords: Vec<Vec<f64>> = (0..=n)
            .map(|i| vec![(i as f64 * 0.37).sin() * 100.0, i as f64 / 7.0, -(i as f64)])
            .collect();
        let c = BezierCurve::from_coords(coords).unwrap();
        for t in [0.0, 0.1, 1.0 / 3.0, 1.0, -0.7, 2.5] {
            let fast: [f64; 3] = c.eval_array(t).unwrap();
            assert_eq!(&fast[..], c.eval(&t).coords(), "n = {n}, t = {t}");
        }
        let line = BezierCurve::from_coords((0..=n).map(|i| vec![i as f64]).collect()).unwrap();
        assert_eq!(line.eval_array::<1>(0.5).unwrap()[0], line.eval(&0.5).coords()[0]);
        assert!(matches!(c.eval_array::<2>(0.5), Err(Error::DimensionMismatch { .. })));
    }
}

#[test]
fn degree_zero_and_one() {
    let c0: BezierCurve<Q> = BezierCurve::from_ints(&[&[5, 7]]).unwrap();
    assert_eq!(c0.eval(&q(3, 4)), Point::from_ints(&[5, 7]).unwrap());
    assert!(c0.hodograph().is_err());
    assert_eq!(
        c0.derivative_at(1, &q(1, 2)).unwrap(),
        Point::from_ints(&[0, 0]).unwrap()
    );
    assert_eq!(c0.elevate().unwrap().points().len(), 2);
    let c1: BezierCurve<Q> = BezierCurve::from_ints(&[&[0], &[4]]).unwrap();
    assert_eq!(c1.eval(&q(1, 4)).coords(), &[q(1, 1)]);
    assert_eq!(c1.hodograph().unwrap().points(), &[Point::from_ints(&[4]).unwrap()]);
}

#[test]
fn bad_input_is_an_error() {
    assert!(matches!(BezierCurve::<Q>::new(vec![]), Err(Error::Empty(_))));
    assert!(matches!(
        BezierCurve::<Q>::from_ints(&[&[0, 0], &[1]]),
        Err(Error::DimensionMismatch { .. })
    ));
    let c = text_example();
    assert!(matches!(
        c.derivative(4),
        Err(Error::DerivativeOrder { order: 4, degree: 3 })
    ));
    assert!(matches!(c.elevate_by(usize::MAX), Err(Error::TooLarge { .. })));
    assert!(c.elevate_steps(1 << 40).is_err());
}

#[test]
fn elevation_distance_decreases() {
    let c = text_example();
    let d = c.elevation_distances(8).unwrap();
    assert_eq!(d[0].r, 0);
    assert!(d.windows(2).all(|w| w[1].max_squared <= w[0].max_squared));
    assert_eq!(d[3], c.elevation_distance(3).unwrap());
}
