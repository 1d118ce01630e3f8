//! The worked examples of text 000 (Bézier curves), as printed, decided exactly.
//!
//! Where the text is misprinted the test encodes what is *printed*, shows that it fails with
//! a concrete counterexample, and checks the corrected statement beside it.

use casteljau::{barycentric, linear_combination};
use casteljau::{bernstein, power_to_bernstein, reparametrize};
use casteljau::{convex_weights, hull_contains};
use casteljau::{BezierCurve, BigRational, Error, Point, Ring, Scalar};

type Q = BigRational;

fn q(p: i64, d: i64) -> Q {
    Q::from_ratio(p, d).unwrap()
}

fn pt(c: &[(i64, i64)]) -> Point<Q> {
    Point::new(c.iter().map(|&(p, d)| q(p, d)).collect()).unwrap()
}

fn ints(c: &[i64]) -> Point<Q> {
    Point::from_ints(c).unwrap()
}

/// Parameters used to spot-check identities: the ends, interior points, and points outside.
fn sample_parameters() -> Vec<Q> {
    [(0, 1), (1, 1), (1, 2), (1, 3), (2, 7), (-3, 5), (9, 4)]
        .iter()
        .map(|&(p, d)| q(p, d))
        .collect()
}

/// `Σ c_i B_i^3(t)`.
fn cubic_bernstein_sum(c: &[Q; 4], t: &Q) -> Q {
    let mut acc = Q::zero();
    for (i, ci) in c.iter().enumerate() {
        acc += &(ci * &bernstein(i, 3, t).unwrap());
    }
    acc
}

/// The Bernstein coefficients (degree 3) of `p(2t - 1)`, `p(u) = Σ coeffs[k] u^k`.
fn cubic_bernstein_of(coeffs: &[i64]) -> Vec<Q> {
    let mut c: Vec<Q> = coeffs.iter().map(|&x| Q::from_i64(x)).collect();
    c.resize(4, Q::zero()); // read as a cubic
    power_to_bernstein(&reparametrize(&c, &Q::from_i64(-1), &Q::from_i64(1))).unwrap()
}

// ---- §1.3, example 4): the Bézier points of (-u² + 1, -u³ + u), -1 ≤ u ≤ 1 ----

#[test]
fn power_to_bezier_example() {
    // coefficients of u^0..u^3 as vectors (x, y)
    let coeffs = vec![ints(&[1, 0]), ints(&[0, 1]), ints(&[-1, 0]), ints(&[0, -1])];
    let c = BezierCurve::from_power_on(&coeffs, &Q::from_i64(-1), &Q::from_i64(1)).unwrap();
    let printed = [
        pt(&[(0, 1), (0, 1)]),
        pt(&[(4, 3), (-4, 3)]),
        pt(&[(4, 3), (4, 3)]),
        pt(&[(0, 1), (0, 1)]),
    ];
    assert_eq!(c.points(), &printed[..]);
    // and the curve really is (-u² + 1, -u³ + u) with u = 2t - 1
    for t in sample_parameters() {
        let u = &(&Q::from_i64(2) * &t) - &Q::one();
        let u2 = &u * &u;
        assert_eq!(c.eval(&t), Point::new(vec![&Q::one() - &u2, &u - &(&u2 * &u)]).unwrap());
    }
}

#[test]
fn printed_x_identity_holds() {
    // printed: -(2t - 1)² + 1 = 4/3 B_1^3(t) + 4/3 B_2^3(t)
    let rhs = [q(0, 1), q(4, 3), q(4, 3), q(0, 1)];
    assert_eq!(cubic_bernstein_of(&[1, 0, -1]), rhs.to_vec());
    for t in sample_parameters() {
        let u = &(&Q::from_i64(2) * &t) - &Q::one();
        assert_eq!(&Q::one() - &(&u * &u), cubic_bernstein_sum(&rhs, &t));
    }
}

#[test]
fn printed_y_identity_is_missing_a_minus_sign() {
    // printed: (2t - 1)³ + (2t - 1) = -4/3 B_1^3(t) + 4/3 B_2^3(t)   — FALSE
    let rhs = [q(0, 1), q(-4, 3), q(4, 3), q(0, 1)];
    let printed_lhs = |t: &Q| {
        let u = &(&Q::from_i64(2) * t) - &Q::one();
        &(&(&u * &u) * &u) + &u
    };
    // Counterexample at t = 0: left -2, right 0.
    let t0 = Q::zero();
    assert_eq!(printed_lhs(&t0), Q::from_i64(-2));
    assert_eq!(cubic_bernstein_sum(&rhs, &t0), Q::zero());
    // As polynomials: the printed left side has Bézier coefficients (-2, 2/3, -2/3, 2).
    let printed = cubic_bernstein_of(&[0, 1, 0, 1]);
    assert_eq!(printed, vec![q(-2, 1), q(2, 3), q(-2, 3), q(2, 1)]);
    assert_ne!(printed, rhs.to_vec());

    // Corrected: -(2t - 1)³ + (2t - 1) = -4/3 B_1^3(t) + 4/3 B_2^3(t) holds, and it is what the
    // text actually uses for b_1, b_2 (y = -u³ + u).
    assert_eq!(cubic_bernstein_of(&[0, 1, 0, -1]), rhs.to_vec());
    for t in sample_parameters() {
        let u = &(&Q::from_i64(2) * &t) - &Q::one();
        assert_eq!(&u - &(&(&u * &u) * &u), cubic_bernstein_sum(&rhs, &t));
    }
}

// ---- §1.5: barycentric combinations, the centroid, the convex hull ----

#[test]
fn centroid_is_a_barycentric_combination() {
    let tri = vec![ints(&[0, 0]), ints(&[5, 1]), ints(&[1, 4])];
    let third = q(1, 3);
    let g = barycentric(&tri, &[third.clone(), third.clone(), third.clone()]).unwrap();
    assert_eq!(g, pt(&[(2, 1), (5, 3)]));
    // g = (b0 + b1 + b2) / 3
    let sum = tri[0].add(&tri[1]).add(&tri[2]);
    assert_eq!(g, sum.scale(&third));
    // Moving the origin moves g along: a barycentric combination does not depend on it.
    let v = ints(&[-7, 11]);
    let moved: Vec<Point<Q>> = tri.iter().map(|p| p.add(&v)).collect();
    assert_eq!(
        barycentric(&moved, &[third.clone(), third.clone(), third.clone()]).unwrap(),
        g.add(&v)
    );
    // The centroid lies in the triangle; the only certificate is (1/3, 1/3, 1/3).
    assert_eq!(
        convex_weights(&tri, &g).unwrap(),
        Some(vec![third.clone(), third.clone(), third])
    );
}

/// Checks the certificate: weights ≥ 0, summing to 1, reproducing `p`.
fn assert_inside(points: &[Point<Q>], p: &Point<Q>) {
    let w = convex_weights(points, p)
        .unwrap()
        .unwrap_or_else(|| panic!("{p} should be in the hull"));
    assert!(w.iter().all(|c| *c >= Q::zero()), "negative weight in {w:?}");
    assert_eq!(w.iter().fold(Q::zero(), |a, c| a + c), Q::one());
    assert_eq!(&linear_combination(points, &w).unwrap(), p);
}

fn assert_outside(points: &[Point<Q>], p: &Point<Q>) {
    assert!(!hull_contains(points, p).unwrap(), "{p} should be outside the hull");
}

#[test]
fn hull_example_1_segment() {
    let seg = vec![ints(&[0, 0]), ints(&[4, 2])];
    assert_inside(&seg, &ints(&[2, 1]));
    assert_inside(&seg, &ints(&[0, 0]));
    assert_inside(&seg, &pt(&[(1, 3), (1, 6)]));
    assert_outside(&seg, &ints(&[6, 3])); // on the line, past the end
    assert_outside(&seg, &ints(&[2, 2]));
}

#[test]
fn hull_example_2_triangle() {
    let tri = vec![ints(&[0, 0]), ints(&[4, 0]), ints(&[0, 4])];
    assert_inside(&tri, &ints(&[1, 1]));
    assert_inside(&tri, &ints(&[2, 2])); // on an edge
    assert_inside(&tri, &ints(&[4, 0])); // a vertex
    assert_outside(&tri, &ints(&[3, 3]));
    assert_outside(&tri, &pt(&[(-1, 1000), (1, 1)]));
}

#[test]
fn hull_example_3_tetrahedron() {
    let tet = vec![ints(&[0, 0, 0]), ints(&[1, 0, 0]), ints(&[0, 1, 0]), ints(&[0, 0, 1])];
    assert_inside(&tet, &pt(&[(1, 4), (1, 4), (1, 4)]));
    assert_inside(&tet, &pt(&[(1, 3), (1, 3), (1, 3)])); // on the far face
    assert_outside(&tet, &pt(&[(1, 3), (1, 3), (1_000_001, 3_000_000)]));
    assert_outside(&tet, &pt(&[(1, 2), (1, 2), (1, 2)]));
    assert_outside(&tet, &pt(&[(1, 10), (1, 10), (-1, 10)]));
}

#[test]
fn hull_example_4_planar_quadrilateral() {
    // Four coplanar points in space (the plane z = x + y): the hull is a quadrilateral.
    let quad = vec![ints(&[0, 0, 0]), ints(&[2, 0, 2]), ints(&[2, 2, 4]), ints(&[0, 2, 2])];
    assert_inside(&quad, &ints(&[1, 1, 2])); // centre
    assert_inside(&quad, &ints(&[2, 1, 3])); // on an edge
    assert_inside(&quad, &pt(&[(1, 2), (3, 2), (2, 1)]));
    assert_outside(&quad, &ints(&[3, 1, 4])); // in the plane, beyond an edge
    assert_outside(&quad, &ints(&[1, 1, 3])); // off the plane
}

#[test]
fn curve_stays_in_its_control_polygon() {
    // The convex-hull property on the text's example curve, with certificates.
    let c: BezierCurve<Q> = BezierCurve::new(vec![
        pt(&[(0, 1), (0, 1)]),
        pt(&[(4, 3), (-4, 3)]),
        pt(&[(4, 3), (4, 3)]),
        pt(&[(0, 1), (0, 1)]),
    ])
    .unwrap();
    for k in 0..=8 {
        assert_inside(c.points(), &c.eval(&q(k, 8)));
    }
    // Outside [0, 1] the curve leaves the hull: at t = 2 it is (-8, -24).
    assert_eq!(c.eval(&Q::from_i64(2)), ints(&[-8, -24]));
    assert_outside(c.points(), &c.eval(&Q::from_i64(2)));
}

// ---- §1.4 on the example: subdivision, tangents, elevation ----

#[test]
fn subdivision_and_tangent_on_the_example() {
    let c: BezierCurve<Q> = BezierCurve::from_ints(&[&[0, 0], &[4, -4], &[4, 4], &[0, 0]]).unwrap();
    let t0 = q(1, 3);
    let s = c.scheme(&t0);
    let (left, right) = c.split_at(&t0);
    assert_eq!(
        left.points(),
        &[
            ints(&[0, 0]),
            pt(&[(4, 3), (-4, 3)]),
            pt(&[(20, 9), (-4, 3)]),
            pt(&[(8, 3), (-8, 9)])
        ]
    );
    assert_eq!(right.points()[0], c.eval(&t0));
    assert_eq!(s.get(3, 0).unwrap(), &c.eval(&t0));
    // tangent at b(t0) along b_0^2(t0) b_1^2(t0)
    let chord = s.get(2, 1).unwrap().sub(s.get(2, 0).unwrap());
    assert_eq!(c.derivative_at(1, &t0).unwrap(), chord.scale(&Q::from_i64(3)));
    // at the ends: along b0 b1 and b2 b3
    assert_eq!(c.derivative_at(1, &Q::zero()).unwrap(), ints(&[12, -12]));
    assert_eq!(c.derivative_at(1, &Q::one()).unwrap(), ints(&[-12, -12]));
    let shown = s.to_string();
    assert!(shown.contains("b_0^3 = (8/3, -8/9)"), "{shown}");
}

#[test]
fn elevation_on_the_example() {
    let c: BezierCurve<Q> = BezierCurve::from_ints(&[&[0, 0], &[4, -4], &[4, 4], &[0, 0]]).unwrap();
    // (7): b_i^(1) = i/4 b_{i-1} + (1 - i/4) b_i
    let e = c.elevate().unwrap();
    assert_eq!(
        e.points(),
        &[
            ints(&[0, 0]),
            ints(&[3, -3]),
            ints(&[4, 0]),
            ints(&[3, 3]),
            ints(&[0, 0])
        ]
    );
    assert_eq!(c.elevate_by(5).unwrap(), c.elevate_steps(5).unwrap());
    // Theorem 1.2: the polygon approaches the curve.
    let d = c.elevation_distances(10).unwrap();
    assert!(d.windows(2).all(|w| w[1].max_norm <= w[0].max_norm));
    assert!(d[10].max_norm < d[0].max_norm);
}

// ---- degree 0 and 1 ----

#[test]
fn degree_zero_curve() {
    let c: BezierCurve<Q> = BezierCurve::from_ints(&[&[3, -1, 2]]).unwrap();
    assert_eq!(c.degree(), 0);
    for t in sample_parameters() {
        assert_eq!(c.eval(&t), ints(&[3, -1, 2]));
        assert_eq!(c.eval_bernstein(&t), ints(&[3, -1, 2]));
        assert_eq!(c.derivative_at(1, &t).unwrap(), ints(&[0, 0, 0]));
    }
    assert_eq!(c.derivative(0).unwrap(), c);
    assert!(matches!(
        c.derivative(1),
        Err(Error::DerivativeOrder { order: 1, degree: 0 })
    ));
    assert_eq!(c.to_power().unwrap(), vec![ints(&[3, -1, 2])]);
    assert_eq!(c.elevate().unwrap().points(), &[ints(&[3, -1, 2]), ints(&[3, -1, 2])]);
    let (l, r) = c.split_at(&q(1, 2));
    assert_eq!((l.clone(), r), (c.clone(), c.clone()));
    assert_inside(c.points(), &ints(&[3, -1, 2]));
    assert_outside(c.points(), &ints(&[3, -1, 3]));
}

#[test]
fn degree_one_curve() {
    let c: BezierCurve<Q> = BezierCurve::from_ints(&[&[1, 2], &[5, -2]]).unwrap();
    assert_eq!(c.eval(&q(1, 4)), ints(&[2, 1]));
    assert_eq!(c.eval(&Q::from_i64(-1)), ints(&[-3, 6]));
    assert_eq!(c.hodograph().unwrap().points(), &[ints(&[4, -4])]);
    assert_eq!(c.derivative_at(2, &q(1, 2)).unwrap(), ints(&[0, 0]));
    assert_eq!(
        c.elevate().unwrap().points(),
        &[ints(&[1, 2]), ints(&[3, 0]), ints(&[5, -2])]
    );
    assert_eq!(c.to_power().unwrap(), vec![ints(&[1, 2]), ints(&[4, -4])]);
    // a line is its own elevated polygon: distance zero
    assert!(c.elevation_distances(4).unwrap().iter().all(|d| d.max_norm.is_zero()));
}

// ---- bad input: errors, never panics ----

#[test]
fn bad_input_errors() {
    assert!(matches!(BezierCurve::<Q>::new(vec![]), Err(Error::Empty(_))));
    assert!(matches!(BezierCurve::<f64>::from_coords(vec![]), Err(Error::Empty(_))));
    assert!(matches!(
        BezierCurve::<Q>::from_ints(&[&[0, 0], &[1, 2, 3]]),
        Err(Error::DimensionMismatch {
            expected: 2,
            found: 3,
            ..
        })
    ));
    assert!(matches!(BezierCurve::<Q>::from_ints(&[&[]]), Err(Error::ZeroDimension)));
    let c: BezierCurve<Q> = BezierCurve::from_ints(&[&[0, 0], &[4, -4], &[4, 4], &[0, 0]]).unwrap();
    assert!(matches!(
        c.derivative(4),
        Err(Error::DerivativeOrder { order: 4, degree: 3 })
    ));
    assert!(matches!(c.forward_differences(9), Err(Error::DerivativeOrder { .. })));
    let huge = c.elevate_by(1_000_000_000_000).unwrap_err();
    assert!(matches!(huge, Error::TooLarge { .. }), "{huge}");
    assert!(matches!(
        c.elevate_steps(1_000_000_000_000),
        Err(Error::TooLarge { .. })
    ));
    assert!(matches!(
        c.elevation_distances(1_000_000_000_000),
        Err(Error::TooLarge { .. })
    ));
    assert!(matches!(Q::from_ratio(1, 0), Err(Error::DivisionByZero(_))));
    assert!(matches!(f64::from_ratio(1, 0), Err(Error::DivisionByZero(_))));
    assert!(matches!(
        Q::one().checked_div(&Q::zero()),
        Err(Error::DivisionByZero(_))
    ));
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(matches!(Q::from_f64(bad), Err(Error::NotFinite(_))));
        assert!(matches!(f64::from_f64(bad), Err(Error::NotFinite(_))));
    }
    let coeffs = vec![ints(&[1, 0]), ints(&[0, 1])];
    assert!(matches!(
        BezierCurve::from_power_on(&coeffs, &q(1, 2), &q(2, 4)),
        Err(Error::Domain(_))
    ));
    assert!(matches!(
        barycentric(&[ints(&[0, 0]), ints(&[1, 1])], &[q(1, 2), q(1, 3)]),
        Err(Error::NotAffine(_))
    ));
    assert!(matches!(
        c.hull_contains(&ints(&[0, 0, 0])),
        Err(Error::DimensionMismatch { .. })
    ));
    // and the message says what is wrong
    let msg = BezierCurve::<Q>::new(vec![]).unwrap_err().to_string();
    assert!(msg.contains("empty"), "{msg}");
}
