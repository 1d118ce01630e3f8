//! Tensor-product Bézier surfaces: every example of text 003 checked exactly, the printed
//! two-stage bilinear construction, the Enneper verdict for Example 5, and property tests of
//! every identity on random exact nets (with `f64` counterparts under stated tolerances).

use casteljau::{bernstein, binomial};
use casteljau::{enneper_net, enneper_power, BezierSurface, EnneperMatch};
use casteljau::{AffineMap, BigRational, Error, Point, Ring, Scalar};
use proptest::prelude::*;

type Q = BigRational;
type S = BezierSurface<Q>;

fn q(p: i64, d: i64) -> Q {
    Q::from_ratio(p, d).unwrap()
}

fn z(n: i64) -> Q {
    Q::from_i64(n)
}

fn pt(c: &[i64]) -> Point<Q> {
    Point::from_ints(c).unwrap()
}

fn pq(c: [Q; 3]) -> Point<Q> {
    Point::new(c.to_vec()).unwrap()
}

/// Parameters on and inside the unit square, plus two outside it.
fn params() -> Vec<Q> {
    vec![q(0, 1), q(1, 1), q(1, 2), q(1, 3), q(3, 4), q(2, 7), q(-1, 2), q(5, 3)]
}

// ---------------------------------------------------------------- text 003, the nets

fn example_1() -> S {
    S::from_ints(&[
        &[&[0, 0, 0], &[1, 0, 1], &[2, 0, 0]],
        &[&[0, 1, 1], &[1, 1, 2], &[2, 1, 1]],
        &[&[0, 2, 0], &[1, 2, 1], &[2, 2, 0]],
    ])
    .unwrap()
}

fn example_2() -> S {
    S::from_ints(&[
        &[&[-1, -1, 0], &[-1, 0, 2], &[-1, 1, 0]],
        &[&[0, -1, -2], &[0, 0, 0], &[0, 1, -2]],
        &[&[1, -1, 0], &[1, 0, 2], &[1, 1, 0]],
    ])
    .unwrap()
}

fn example_3() -> S {
    S::from_ints(&[
        &[&[2, 0, 2], &[4, 0, 2], &[4, 0, 0]],
        &[&[2, 2, 2], &[4, 4, 2], &[4, 4, 0]],
        &[&[0, 2, 2], &[0, 4, 2], &[0, 4, 0]],
    ])
    .unwrap()
}

fn example_4() -> S {
    S::from_ints(&[
        &[&[1, 0, 0], &[1, 0, 1], &[0, 0, 1]],
        &[&[1, 1, 0], &[1, 1, 1], &[0, 0, 1]],
        &[&[0, 1, 0], &[0, 1, 1], &[0, 0, 1]],
    ])
    .unwrap()
}

/// Example 5 exactly as printed.
fn example_5() -> S {
    let p = |x: Q, y: Q, zz: i64| pq([x, y, z(zz)]);
    S::new(vec![
        vec![
            p(z(-22), z(-22), 0),
            p(z(10), z(-18), 16),
            p(z(10), z(18), 16),
            p(z(-22), z(22), 0),
        ],
        vec![
            p(z(-18), z(10), -16),
            p(q(-22, 3), q(-22, 3), 0),
            p(q(-22, 3), q(22, 3), 0),
            p(z(-18), z(-10), -16),
        ],
        vec![
            p(z(18), z(10), -16),
            p(q(22, 3), q(-22, 3), 0),
            p(q(22, 3), q(22, 3), 0),
            p(z(18), z(-10), -16),
        ],
        vec![
            p(z(22), z(-22), 0),
            p(z(-10), z(-18), 16),
            p(z(-10), z(18), 16),
            p(z(22), z(22), 0),
        ],
    ])
    .unwrap()
}

/// All three evaluations agree exactly and equal `expected`.
fn assert_value(s: &S, u: &Q, v: &Q, expected: &Point<Q>) {
    assert_eq!(&s.eval(u, v), expected, "u-first at ({u}, {v})");
    assert_eq!(&s.eval_v_first(u, v), expected, "v-first at ({u}, {v})");
    assert_eq!(&s.eval_bernstein(u, v), expected, "Bernstein sum at ({u}, {v})");
}

/// The closed form holds on a grid fine enough to decide a polynomial identity: a polynomial
/// of degree ≤ d in each variable that vanishes on a (d+1)×(d+1) grid is zero. Biquadratic
/// nets and quadratic-in-each closed forms need 3 values; 8 are used.
fn assert_closed_form(s: &S, f: impl Fn(&Q, &Q) -> Point<Q>) {
    for u in params() {
        for v in params() {
            assert_value(s, &u, &v, &f(&u, &v));
        }
    }
}

/// Corners are `b00, bm0, b0n, bmn` and the surface passes through them (text 003, c)).
fn assert_corners(s: &S) {
    let (m, n) = s.degrees();
    let net = s.net();
    let c = s.corners();
    assert_eq!(
        c,
        [
            net[0][0].clone(),
            net[m][0].clone(),
            net[0][n].clone(),
            net[m][n].clone()
        ]
    );
    assert_value(s, &z(0), &z(0), &net[0][0]);
    assert_value(s, &z(1), &z(0), &net[m][0]);
    assert_value(s, &z(0), &z(1), &net[0][n]);
    assert_value(s, &z(1), &z(1), &net[m][n]);
}

/// Boundary curves are the net's edges and trace the surface's edges.
fn assert_boundary(s: &S) {
    let (m, n) = s.degrees();
    let net = s.net();
    let [v0, u1, v1, u0] = s.boundary();
    let col = |j: usize| net.iter().map(|r| r[j].clone()).collect::<Vec<_>>();
    assert_eq!(v0.points(), &col(0)[..]);
    assert_eq!(u1.points(), &net[m][..]);
    assert_eq!(v1.points(), &col(n)[..]);
    assert_eq!(u0.points(), &net[0][..]);
    for t in params() {
        assert_eq!(v0.eval(&t), s.eval(&t, &z(0)));
        assert_eq!(u1.eval(&t), s.eval(&z(1), &t));
        assert_eq!(v1.eval(&t), s.eval(&t, &z(1)));
        assert_eq!(u0.eval(&t), s.eval(&z(0), &t));
    }
}

/// The text's iso-curve formula: the `v = v0` curve has control points `Σ_j b_ij B_j^n(v0)`.
fn assert_iso_curves(s: &S) {
    let (m, n) = s.degrees();
    for v0 in params() {
        let iso = s.iso_v(&v0);
        assert_eq!(iso.degree(), m);
        for i in 0..=m {
            let mut acc = Point::origin(s.dim());
            for j in 0..=n {
                acc = acc.add(&s.net()[i][j].scale(&bernstein(j, n, &v0).unwrap()));
            }
            assert_eq!(iso.points()[i], acc, "iso_v control point {i} at v0 = {v0}");
        }
        for u in params() {
            assert_eq!(iso.eval(&u), s.eval(&u, &v0));
            assert_eq!(s.iso_u(&u).eval(&v0), s.eval(&u, &v0));
        }
    }
}

#[test]
fn bilinear_example_gives_u_v_uv_and_z_equals_xy() {
    let s = S::bilinear(pt(&[0, 0, 0]), pt(&[0, 1, 0]), pt(&[1, 0, 0]), pt(&[1, 1, 1])).unwrap();
    assert_eq!(s.degrees(), (1, 1));
    assert_closed_form(&s, |u, v| pq([u.clone(), v.clone(), u * v]));
    // as a polynomial: x(u, v) = (1,0,0) u + (0,1,0) v + (0,0,1) uv
    assert_eq!(
        s.to_power().unwrap(),
        vec![
            vec![pt(&[0, 0, 0]), pt(&[0, 1, 0])],
            vec![pt(&[1, 0, 0]), pt(&[0, 0, 1])]
        ]
    );
    for u in params() {
        for v in params() {
            let p = s.eval(&u, &v);
            let c = p.coords();
            assert_eq!(c[2], &c[0] * &c[1], "z = xy");
        }
    }
    assert_corners(&s);
    assert_boundary(&s);
    assert_iso_curves(&s);
}

/// The text calls the bilinear patch through four distinct points a hyperbolic paraboloid;
/// that needs the points not to be coplanar. Four distinct coplanar points give a planar patch.
#[test]
fn bilinear_patch_of_coplanar_points_is_planar() {
    let s = S::bilinear(pt(&[0, 0, 0]), pt(&[0, 1, 0]), pt(&[1, 0, 0]), pt(&[2, 3, 0])).unwrap();
    for u in params() {
        for v in params() {
            assert!(s.eval(&u, &v).coords()[2].is_zero());
        }
    }
    // ... while the text's example, whose points are not coplanar, has the saddle z = xy:
    // its mixed partial ∂²z/∂u∂v = 1 ≠ 0 everywhere.
    let h = S::bilinear(pt(&[0, 0, 0]), pt(&[0, 1, 0]), pt(&[1, 0, 0]), pt(&[1, 1, 1])).unwrap();
    assert_eq!(h.derivative(1, 1).unwrap().net(), &[vec![pt(&[0, 0, 1])]]);
}

/// The two-stage construction as printed uses `b_{1,0}^{(0,1)} = (1 − v) b_{1,0} + v b_{0,1}`;
/// the bilinear formula needs `b_{1,1}` there. The printed version does not even pass through
/// `b_{1,1}`; the corrected one reproduces the bilinear patch exactly.
#[test]
fn two_stage_bilinear_construction_printed_fails_corrected_holds() {
    let (b00, b01, b10, b11) = (pt(&[0, 0, 0]), pt(&[0, 1, 0]), pt(&[1, 0, 0]), pt(&[1, 1, 1]));
    let s = S::bilinear(b00.clone(), b01.clone(), b10.clone(), b11.clone()).unwrap();
    let two_stage = |u: &Q, v: &Q, second: &Point<Q>| {
        let first = b00.lerp(&b01, v); // b_{0,0}^{(0,1)} = (1 − v) b00 + v b01
        let other = b10.lerp(second, v); // b_{1,0}^{(0,1)} = (1 − v) b10 + v · second
        first.lerp(&other, u) // (1 − u) b_{0,0}^{(0,1)} + u b_{1,0}^{(0,1)}
    };
    // as printed (second = b01): wrong
    assert_eq!(
        two_stage(&z(1), &z(1), &b01),
        b01,
        "printed version ends at b01, not b11"
    );
    assert_ne!(two_stage(&z(1), &z(1), &b01), s.eval(&z(1), &z(1)));
    assert_ne!(two_stage(&q(1, 2), &q(1, 2), &b01), s.eval(&q(1, 2), &q(1, 2)));
    // corrected (second = b11): equal to the bilinear formula everywhere
    for u in params() {
        for v in params() {
            assert_eq!(two_stage(&u, &v, &b11), s.eval(&u, &v));
            // and to the written-out formula x(u, v) of the text
            let (iu, iv) = (&z(1) - &u, &z(1) - &v);
            let x = b00
                .scale(&(&iu * &iv))
                .add(&b01.scale(&(&iu * &v)))
                .add(&b10.scale(&(&u * &iv)))
                .add(&b11.scale(&(&u * &v)));
            assert_eq!(x, s.eval_bernstein(&u, &v));
        }
    }
    // the printed version fails for generic points too, not only for this example
    let (c00, c01, c10, c11) = (pt(&[1, 2, 3]), pt(&[-2, 5, 1]), pt(&[4, -1, 0]), pt(&[7, 3, -2]));
    let g = S::bilinear(c00.clone(), c01.clone(), c10.clone(), c11).unwrap();
    let printed = c00.lerp(&c01, &q(1, 2)).lerp(&c10.lerp(&c01, &q(1, 2)), &q(1, 2));
    assert_ne!(printed, g.eval(&q(1, 2), &q(1, 2)));
}

/// Example 1: `x = 2v`, `y = 2u`, `z = 2u(1−u) + 2v(1−v)`, i.e. `z = x + y − (x² + y²)/2`.
#[test]
fn example_1_closed_form() {
    let s = example_1();
    assert_closed_form(&s, |u, v| {
        let two = z(2);
        let zz = &(&(&two * u) * &(&z(1) - u)) + &(&(&two * v) * &(&z(1) - v));
        pq([&two * v, &two * u, zz])
    });
    for u in params() {
        for v in params() {
            let p = s.eval(&u, &v);
            let [x, y, zz] = [&p.coords()[0], &p.coords()[1], &p.coords()[2]];
            let rhs = &(x + y) - &(&(x * x) + &(y * y)).checked_div(&z(2)).unwrap();
            assert_eq!(*zz, rhs);
        }
    }
    assert_value(&s, &q(1, 2), &q(1, 2), &pt(&[1, 1, 1]));
    assert_corners(&s);
    assert_boundary(&s);
    assert_iso_curves(&s);
}

/// Example 2: `x = 2u − 1`, `y = 2v − 1`, `z = x² − y²` (a hyperbolic paraboloid).
#[test]
fn example_2_is_z_equals_x2_minus_y2() {
    let s = example_2();
    assert_closed_form(&s, |u, v| {
        let x = &(&z(2) * u) - &z(1);
        let y = &(&z(2) * v) - &z(1);
        let zz = &(&x * &x) - &(&y * &y);
        pq([x, y, zz])
    });
    // in power form over [-1, 1]²: exactly (u, v, u² − v²)
    let (m1, one) = (z(-1), z(1));
    let c = s.to_power_on((&m1, &one), (&m1, &one)).unwrap();
    let mut expect = vec![vec![pt(&[0, 0, 0]); 3]; 3];
    expect[1][0] = pt(&[1, 0, 0]);
    expect[0][1] = pt(&[0, 1, 0]);
    expect[2][0] = pt(&[0, 0, 1]);
    expect[0][2] = pt(&[0, 0, -1]);
    assert_eq!(c, expect);
    assert_value(&s, &q(1, 2), &q(1, 2), &pt(&[0, 0, 0]));
    // the iso-curve v = 1/2 is the parabola (x, 0, x²), control points (-1,0,1),(0,0,-1),(1,0,1)
    assert_eq!(
        s.iso_v(&q(1, 2)).points(),
        &[pt(&[-1, 0, 1]), pt(&[0, 0, -1]), pt(&[1, 0, 1])]
    );
    assert_corners(&s);
    assert_boundary(&s);
    assert_iso_curves(&s);
}

/// Example 3: with `ρ(v) = 2 + 4v − 2v²`: `x = ρ(v)(1 − u²)`, `y = ρ(v) u(2 − u)`,
/// `z = 2 − 2v²` — the profile `(ρ, z)` swept along the quadratic quarter-"circle"
/// `(1 − u², u(2 − u))` (a polynomial surface, so not exactly of revolution).
#[test]
fn example_3_closed_form() {
    let s = example_3();
    assert_closed_form(&s, |u, v| {
        let rho = &(&z(2) + &(&z(4) * v)) - &(&z(2) * &(v * v));
        let x = &rho * &(&z(1) - &(u * u));
        let y = &rho * &(u * &(&z(2) - u));
        pq([x, y, &z(2) - &(&z(2) * &(v * v))])
    });
    assert_value(&s, &q(1, 2), &q(1, 2), &pq([q(21, 8), q(21, 8), q(3, 2)]));
    // the quarter-"circle" is not a circle: at u = 1/2 the point (3/4, 3/4) has radius² 9/8 ≠ 1
    let p = s.eval(&q(1, 2), &z(0));
    assert_eq!(p, pq([q(3, 2), q(3, 2), z(2)]));
    assert_ne!(&p.coords()[0] * &p.coords()[0] + &p.coords()[1] * &p.coords()[1], z(4));
    assert_corners(&s);
    assert_boundary(&s);
    assert_iso_curves(&s);
}

/// Example 4: `x = (1 − u²)(1 − v²)`, `y = u(2 − u)(1 − v²)`, `z = v(2 − v)`. The whole
/// `v = 1` edge of the net is the single point (0, 0, 1): a degenerate (pole) boundary.
#[test]
fn example_4_closed_form_and_degenerate_edge() {
    let s = example_4();
    assert_closed_form(&s, |u, v| {
        let w = &z(1) - &(v * v);
        pq([&(&z(1) - &(u * u)) * &w, &(u * &(&z(2) - u)) * &w, v * &(&z(2) - v)])
    });
    assert_value(&s, &q(1, 2), &q(1, 2), &pq([q(9, 16), q(9, 16), q(3, 4)]));
    let [_, _, v1, _] = s.boundary();
    assert!(v1.points().iter().all(|p| *p == pt(&[0, 0, 1])));
    for u in params() {
        assert_eq!(s.eval(&u, &z(1)), pt(&[0, 0, 1]));
    }
    assert_corners(&s);
    assert_boundary(&s);
    assert_iso_curves(&s);
}

/// Example 5 is exactly Enneper's surface: the printed net is `3 ×` the Bézier net of
/// `E(u, v) = (u − u³/3 + uv², v − v³/3 + vu², u² − v²)` on `[−2, 2]²`, i.e.
/// `b(s, t) = 3 E(4s − 2, 4t − 2)`; every one of the 16 printed points is right.
#[test]
fn example_5_is_exactly_an_enneper_patch() {
    let printed = example_5();
    let true_net = enneper_net(&z(2))
        .unwrap()
        .transform(&AffineMap::scaling(3, &z(3)))
        .unwrap();
    assert_eq!(printed.net_differences(&true_net).unwrap(), vec![]);
    assert_eq!(printed, true_net);

    // Decided from the power form alone: the only (α, β, γ, δ, λ) with b(s,t) = λE(αs+β, γt+δ)
    // (parameters possibly swapped) is α = γ = 4, β = δ = −2, λ = 3, unswapped.
    let found = printed.enneper_matches().unwrap();
    assert_eq!(
        found,
        vec![EnneperMatch {
            swapped: false,
            alpha: z(4),
            beta: z(-2),
            gamma: z(4),
            delta: z(-2),
            lambda: z(3),
        }]
    );

    // Over [−1, 1]² the printed net is (6u − 8u³ + 24uv², 6v − 8v³ + 24u²v, 12u² − 12v²).
    let (m1, one) = (z(-1), z(1));
    let c = printed.to_power_on((&m1, &one), (&m1, &one)).unwrap();
    let mut expect = vec![vec![pt(&[0, 0, 0]); 4]; 4];
    expect[1][0] = pt(&[6, 0, 0]);
    expect[3][0] = pt(&[-8, 0, 0]);
    expect[1][2] = pt(&[24, 0, 0]);
    expect[0][1] = pt(&[0, 6, 0]);
    expect[0][3] = pt(&[0, -8, 0]);
    expect[2][1] = pt(&[0, 24, 0]);
    expect[2][0] = pt(&[0, 0, 12]);
    expect[0][2] = pt(&[0, 0, -12]);
    assert_eq!(c, expect);

    // Independently of the formula: the patch is conformal (|b_s|² = |b_t|², b_s·b_t = 0) and
    // harmonic (b_ss + b_tt = 0), hence minimal. Each identity is a polynomial of degree ≤ 6 in
    // each variable, so vanishing on an 8×8 grid proves it.
    let grid: Vec<Q> = (0..8).map(|k| q(k - 2, 3)).collect();
    for s in &grid {
        for t in &grid {
            let bs = printed.partial_at(1, 0, s, t).unwrap();
            let bt = printed.partial_at(0, 1, s, t).unwrap();
            assert_eq!(bs.norm_squared(), bt.norm_squared());
            assert!(bs.dot(&bt).is_zero());
            let lap = printed
                .partial_at(2, 0, s, t)
                .unwrap()
                .add(&printed.partial_at(0, 2, s, t).unwrap());
            assert!(lap.is_zero());
        }
    }
    assert_corners(&printed);
    assert_boundary(&printed);
    assert_iso_curves(&printed);
}

/// The matcher is not a rubber stamp: one wrong entry is caught and located, and
/// reparametrised or transposed Enneper patches are recognised with the right parameters.
#[test]
fn enneper_matcher_detects_misprints_and_reparametrisations() {
    let printed = example_5();
    let mut net = printed.net().to_vec();
    net[1][2] = pq([q(-22, 3), q(23, 3), z(0)]);
    let wrong = S::new(net).unwrap();
    assert!(wrong.enneper_matches().unwrap().is_empty());
    assert_eq!(wrong.net_differences(&printed).unwrap(), vec![(1, 2)]);

    // u → −u (rows reversed): α = −4, β = 2
    let mut rev = printed.net().to_vec();
    rev.reverse();
    let found = S::new(rev).unwrap().enneper_matches().unwrap();
    assert_eq!(found.len(), 1);
    assert_eq!((found[0].alpha.clone(), found[0].beta.clone()), (z(-4), z(2)));

    // s and t exchanged
    let found = printed.transpose().enneper_matches().unwrap();
    assert_eq!(found.len(), 1);
    assert!(found[0].swapped);
    assert_eq!(found[0].lambda, z(3));

    // an elevated net is the same surface
    let found = printed
        .elevate_u()
        .unwrap()
        .elevate_v()
        .unwrap()
        .enneper_matches()
        .unwrap();
    assert_eq!(found.len(), 1);

    // other surfaces are not Enneper
    for s in [example_1(), example_2(), example_3(), example_4()] {
        assert!(s.enneper_matches().unwrap().is_empty());
    }

    // enneper_net(r) is a different patch of the same surface for every r
    let e = enneper_net(&q(3, 2)).unwrap();
    let found = e.enneper_matches().unwrap();
    assert_eq!(found[0].alpha, z(3));
    assert_eq!(found[0].beta, q(-3, 2));
    assert_eq!(found[0].lambda, z(1));
    assert_eq!(enneper_power::<Q>().unwrap().len(), 4);
}

#[test]
fn bad_input_gives_errors() {
    assert!(matches!(S::new(vec![]), Err(Error::Empty(_))));
    assert!(S::new(vec![vec![]]).is_err());
    assert!(S::new(vec![vec![pt(&[0])], vec![]]).is_err());
    assert!(S::from_ints(&[&[&[0, 0], &[1, 1]], &[&[2, 2]]]).is_err());
    assert!(matches!(
        S::from_ints(&[&[&[0, 0], &[1, 1]], &[&[2, 2], &[3, 3, 3]]]),
        Err(Error::DimensionMismatch { .. })
    ));
    assert!(S::from_ints(&[&[&[]]]).is_err());
    assert!(S::bilinear(pt(&[0]), pt(&[0, 1]), pt(&[1]), pt(&[1])).is_err());
    let s = example_2();
    assert!(matches!(
        s.derivative_u(3),
        Err(Error::DerivativeOrder { order: 3, degree: 2 })
    ));
    assert!(matches!(
        s.derivative_v(3),
        Err(Error::DerivativeOrder { order: 3, degree: 2 })
    ));
    assert!(s.derivative(0, 5).is_err());
    assert!(s.transform(&AffineMap::scaling(2, &z(1))).is_err());
    assert!(s.hull_weights(&pt(&[0, 0])).is_err());
    assert!(s.net_differences(&example_5()).is_err());
    assert!(S::from_power_on(&[vec![pt(&[1])], vec![]], (&z(0), &z(1)), (&z(0), &z(1))).is_err());
    assert!(S::from_power_on(&[vec![pt(&[1])]], (&z(0), &z(1)), (&z(2), &z(2))).is_err());
    assert!(s.to_power_on((&z(2), &z(2)), (&z(0), &z(1))).is_err());
}

// ---------------------------------------------------------------- property tests

fn arb_q() -> impl Strategy<Value = Q> {
    (-20i64..=20, 1i64..=6).prop_map(|(p, d)| q(p, d))
}

fn arb_param() -> impl Strategy<Value = Q> {
    (-12i64..=24, 1i64..=12).prop_map(|(p, d)| q(p, d))
}

fn arb_unit() -> impl Strategy<Value = Q> {
    (1i64..=12)
        .prop_flat_map(|d| (0..=d, Just(d)))
        .prop_map(|(p, d)| q(p, d))
}

fn arb_surface(max_m: usize, max_n: usize) -> impl Strategy<Value = S> {
    (0..=max_m, 0..=max_n, 1usize..=3).prop_flat_map(|(m, n, dim)| {
        prop::collection::vec(prop::collection::vec(prop::collection::vec(arb_q(), dim), n + 1), m + 1).prop_map(
            |net| {
                S::new(
                    net.into_iter()
                        .map(|row| row.into_iter().map(|c| Point::new(c).unwrap()).collect())
                        .collect(),
                )
                .unwrap()
            },
        )
    })
}

fn falling(n: usize, k: usize) -> Q {
    (n + 1 - k..=n).fold(z(1), |acc, f| acc * z(f as i64))
}

/// `∂^{ku+kv}/∂u^{ku}∂v^{kv} Σ c_kl u^k v^l` at `(u, v)`, straight from the power form.
fn power_partial(c: &[Vec<Point<Q>>], ku: usize, kv: usize, u: &Q, v: &Q) -> Point<Q> {
    let mut acc = Point::origin(c[0][0].dim());
    for (k, row) in c.iter().enumerate() {
        for (l, p) in row.iter().enumerate() {
            if k < ku || l < kv {
                continue;
            }
            let w = falling(k, ku) * falling(l, kv) * u.powi((k - ku) as u32) * v.powi((l - kv) as u32);
            acc = acc.add(&p.scale(&w));
        }
    }
    acc
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn three_evaluations_agree(s in arb_surface(6, 6), u in arb_param(), v in arb_param()) {
        let p = s.eval(&u, &v);
        prop_assert_eq!(&p, &s.eval_v_first(&u, &v));
        prop_assert_eq!(&p, &s.eval_bernstein(&u, &v));
    }

    #[test]
    fn iso_curves_lie_on_the_surface(s in arb_surface(6, 6), u in arb_param(), v in arb_param()) {
        let (m, n) = s.degrees();
        let iso_v = s.iso_v(&v);
        let iso_u = s.iso_u(&u);
        prop_assert_eq!(iso_v.degree(), m);
        prop_assert_eq!(iso_u.degree(), n);
        prop_assert_eq!(iso_v.eval(&u), s.eval(&u, &v));
        prop_assert_eq!(iso_u.eval(&v), s.eval(&u, &v));
        // the text's formula for the control points of the v = v0 curve
        for i in 0..=m {
            let mut acc = Point::origin(s.dim());
            for j in 0..=n {
                acc = acc.add(&s.net()[i][j].scale(&bernstein(j, n, &v).unwrap()));
            }
            prop_assert_eq!(&iso_v.points()[i], &acc);
        }
    }

    #[test]
    fn boundaries_and_corners(s in arb_surface(6, 6), t in arb_param()) {
        let [v0, u1, v1, u0] = s.boundary();
        prop_assert_eq!(v0.eval(&t), s.eval(&t, &z(0)));
        prop_assert_eq!(u1.eval(&t), s.eval(&z(1), &t));
        prop_assert_eq!(v1.eval(&t), s.eval(&t, &z(1)));
        prop_assert_eq!(u0.eval(&t), s.eval(&z(0), &t));
        let [c00, c10, c01, c11] = s.corners();
        prop_assert_eq!(c00, s.eval(&z(0), &z(0)));
        prop_assert_eq!(c10, s.eval(&z(1), &z(0)));
        prop_assert_eq!(c01, s.eval(&z(0), &z(1)));
        prop_assert_eq!(c11, s.eval(&z(1), &z(1)));
    }

    #[test]
    fn split_halves_reproduce_the_surface(
        s in arb_surface(6, 6), c in arb_param(), a in arb_param(), b in arb_param()
    ) {
        let (l, r) = s.split_u(&c);
        prop_assert_eq!(l.eval(&a, &b), s.eval(&(&c * &a), &b));
        prop_assert_eq!(r.eval(&a, &b), s.eval(&(&c + &(&(&z(1) - &c) * &a)), &b));
        let (l, r) = s.split_v(&c);
        prop_assert_eq!(l.eval(&a, &b), s.eval(&a, &(&c * &b)));
        prop_assert_eq!(r.eval(&a, &b), s.eval(&a, &(&c + &(&(&z(1) - &c) * &b))));
        let quads = s.split_at(&c, &c);
        let map = |x: &Q, hi: bool| if hi { &c + &(&(&z(1) - &c) * x) } else { &c * x };
        for (k, p) in quads.iter().enumerate() {
            prop_assert_eq!(p.eval(&a, &b), s.eval(&map(&a, k % 2 == 1), &map(&b, k >= 2)));
        }
    }

    #[test]
    fn elevation_keeps_the_surface(s in arb_surface(6, 6), u in arb_param(), v in arb_param()) {
        let (m, n) = s.degrees();
        let eu = s.elevate_u().unwrap();
        let ev = s.elevate_v().unwrap();
        prop_assert_eq!(eu.degrees(), (m + 1, n));
        prop_assert_eq!(ev.degrees(), (m, n + 1));
        prop_assert_eq!(eu.eval(&u, &v), s.eval(&u, &v));
        prop_assert_eq!(ev.eval(&u, &v), s.eval(&u, &v));
    }

    #[test]
    fn derivatives_match_the_power_form(
        s in arb_surface(5, 5), u in arb_param(), v in arb_param(), ku in 0usize..=3, kv in 0usize..=3
    ) {
        let c = s.to_power().unwrap();
        prop_assert_eq!(s.partial_at(ku, kv, &u, &v).unwrap(), power_partial(&c, ku, kv, &u, &v));
        let (m, n) = s.degrees();
        if ku <= m && kv <= n {
            let d = s.derivative(ku, kv).unwrap();
            prop_assert_eq!(d.degrees(), (m - ku, n - kv));
            prop_assert_eq!(d.clone(), s.derivative_v(kv).unwrap().derivative_u(ku).unwrap());
            prop_assert_eq!(d.eval(&u, &v), power_partial(&c, ku, kv, &u, &v));
        } else {
            prop_assert!(s.derivative(ku, kv).is_err());
        }
    }

    #[test]
    fn affine_invariance(
        s in arb_surface(4, 4), u in arb_param(), v in arb_param(), out_dim in 1usize..=3,
        entries in prop::collection::vec(arb_q(), 12)
    ) {
        let d = s.dim();
        let matrix: Vec<Vec<Q>> = (0..out_dim).map(|r| (0..d).map(|c| entries[r * 3 + c].clone()).collect()).collect();
        let translation: Vec<Q> = (0..out_dim).map(|r| entries[9 + r].clone()).collect();
        let map = AffineMap::new(matrix, translation).unwrap();
        let image = s.transform(&map).unwrap();
        prop_assert_eq!(image.eval(&u, &v), map.apply(&s.eval(&u, &v)).unwrap());
    }

    #[test]
    fn surface_points_lie_in_the_hull_of_the_net(s in arb_surface(3, 3), u in arb_unit(), v in arb_unit()) {
        let p = s.eval(&u, &v);
        let w = s.hull_weights(&p).unwrap();
        prop_assert!(w.is_some(), "point {} of the surface outside the hull", p);
        let w = w.unwrap();
        let flat: Vec<Point<Q>> = s.net().iter().flatten().cloned().collect();
        prop_assert!(w.iter().all(|c| *c >= z(0)));
        prop_assert_eq!(casteljau::barycentric(&flat, &w).unwrap(), p);
    }

    #[test]
    fn power_round_trips(
        s in arb_surface(6, 6), a in arb_q(), b in arb_q(), c in arb_q(), d in arb_q(),
        u in arb_param(), v in arb_param()
    ) {
        prop_assert_eq!(&S::from_power(&s.to_power().unwrap()).unwrap(), &s);
        prop_assume!(a != b && c != d);
        let coeffs = s.to_power_on((&a, &b), (&c, &d)).unwrap();
        prop_assert_eq!(&S::from_power_on(&coeffs, (&a, &b), (&c, &d)).unwrap(), &s);
        // from_power_on(coeffs): b(s, t) = Σ c_kl x^k y^l with x = a + (b − a)s, y = c + (d − c)t
        let x = &a + &(&(&b - &a) * &u);
        let y = &c + &(&(&d - &c) * &v);
        prop_assert_eq!(s.eval(&u, &v), power_partial(&coeffs, 0, 0, &x, &y));
    }

    #[test]
    fn f64_agrees_with_exact(s in arb_surface(6, 6), u in arb_unit(), v in arb_unit(), c in arb_unit()) {
        // Tolerance: coordinates ≤ 20 in magnitude, convex combinations on [0, 1]²: 1e-9
        // relative is far above the rounding error of ≤ 12 levels of lerps.
        const TOL: f64 = 1e-9;
        let f = s.try_map(|x| Ok(x.to_f64())).unwrap();
        let (uf, vf, cf) = (u.to_f64(), v.to_f64(), c.to_f64());
        let exact = s.eval(&u, &v).try_map(|x| Ok(x.to_f64())).unwrap();
        prop_assert!(f.eval(&uf, &vf).approx_eq(&exact, TOL));
        prop_assert!(f.eval_v_first(&uf, &vf).approx_eq(&exact, TOL));
        prop_assert!(f.eval_bernstein(&uf, &vf).approx_eq(&exact, TOL));
        prop_assert!(f.iso_v(&vf).eval(&uf).approx_eq(&exact, TOL));
        prop_assert!(f.elevate_u().unwrap().elevate_v().unwrap().eval(&uf, &vf).approx_eq(&exact, TOL));
        let (l, _) = f.split_u(&cf);
        let at = s.eval(&(&c * &u), &v).try_map(|x| Ok(x.to_f64())).unwrap();
        prop_assert!(l.eval(&uf, &vf).approx_eq(&at, TOL));
        let d_exact = s.partial_at(1, 1, &u, &v).unwrap().try_map(|x| Ok(x.to_f64())).unwrap();
        // derivatives scale by m·n ≤ 36 and differences of coordinates: 1e-8
        prop_assert!(f.partial_at(1, 1, &uf, &vf).unwrap().approx_eq(&d_exact, 1e-8));
        let back = BezierSurface::<f64>::from_power(&f.to_power().unwrap()).unwrap();
        prop_assert!(back.eval(&uf, &vf).approx_eq(&exact, 1e-7));
    }
}

#[test]
fn binomial_sanity_for_the_derivative_factor() {
    // m!/(m-k)! used by derivative nets equals k! C(m, k)
    for m in 0..7usize {
        for k in 0..=m {
            let fact: i64 = (1..=k as i64).product();
            assert_eq!(falling(m, k), Q::from_bigint(&(binomial(m, k) * fact)).unwrap());
        }
    }
}
