//! Text 001's picture: a parabola in space, projected from the origin to the plane `z = 1`,
//! is a conic arc, and the projected control points with the heights as weights are its
//! rational Bézier form (10).

use super::svg::{indexed, Figure, Panel, Style, CURVE, POINT, POLYGON};
use super::{planar, planar_curve, AnyCurve, PROJECTION_HEADING};
use crate::error::{Error, Result};
use crate::point::Point;
use crate::rational::RationalBezierCurve;
use crate::scalar::Scalar;
use crate::BezierCurve;

/// The quadratic `p(t) = Σ p_i B_i^2(t)` in space (every `p_i = (w_i b_i, w_i)` with height
/// `w_i > 0`), the plane `z = 1`, the rays from the origin through the control points and
/// through `p(1/2)`, and the conic `x(t) = p(t)/w(t)` on the plane with its control points
/// `b_i` and weights `w_i` ([`RationalBezierCurve::from_homogeneous`]).
pub fn conic_projection<T: Scalar>(parabola: &BezierCurve<T>) -> Result<Figure> {
    if parabola.dim() != 3 || parabola.degree() != 2 {
        return Err(Error::Domain(format!(
            "the projection figure draws a quadratic in space (3 control points (x, y, z)), not {} points of dimension {}",
            parabola.points().len(),
            parabola.dim()
        )));
    }
    if let Some(p) = parabola.points().iter().find(|p| p.coords()[2] <= T::zero()) {
        return Err(Error::Domain(format!(
            "the projection figure needs every control point above the origin's plane (z > 0), not {p}"
        )));
    }
    let conic = RationalBezierCurve::from_homogeneous(parabola)?;
    let (b, w) = (conic.points(), conic.weights());
    let one = T::one();
    let lift = |q: &Point<T>| Point::new(vec![q.coords()[0].clone(), q.coords()[1].clone(), one.clone()]);
    let lifted: Vec<Point<T>> = b.iter().map(lift).collect::<Result<_>>()?;
    let origin = Point::origin(3);
    let mut fig = Figure::new("A parabola in space projected to the plane z = 1 is a conic (text 001, (10))");
    let mut panel = Panel::new(PROJECTION_HEADING);
    // the part of the plane z = 1 over the conic's polygon and the origin's foot
    let (mut lo, mut hi) = (vec![T::zero(), T::zero()], vec![T::zero(), T::zero()]);
    for q in b {
        for k in 0..2 {
            if q.coords()[k] < lo[k] {
                lo[k] = q.coords()[k].clone();
            }
            if q.coords()[k] > hi[k] {
                hi[k] = q.coords()[k].clone();
            }
        }
    }
    let pad = T::from_ratio(1, 5)?;
    let (x0, y0, x1, y1) = (
        lo[0].sub_ref(&pad),
        lo[1].sub_ref(&pad),
        hi[0].add_ref(&pad),
        hi[1].add_ref(&pad),
    );
    let corner = |x: &T, y: &T| Point::new(vec![x.clone(), y.clone(), one.clone()]).and_then(|p| planar(&p));
    panel.polyline(
        &[
            corner(&x0, &y0)?,
            corner(&x1, &y0)?,
            corner(&x1, &y1)?,
            corner(&x0, &y1)?,
        ],
        true,
        Style {
            fill: Some("#e8eef6"),
            ..Style::line("#9aa9bb", 1.0)
        },
        "plane",
        Some("the plane z = 1".into()),
    )?;
    let o = planar(&origin)?;
    // rays from the origin to the farther of p_i and its projection b_i
    for (p, q) in parabola.points().iter().zip(&lifted) {
        let end = if p.coords()[2] >= one { p } else { q };
        panel.polyline(
            &[o.clone(), planar(end)?],
            false,
            Style::dashed(POLYGON, 0.9),
            "ray",
            None,
        )?;
    }
    panel.polyline(
        &parabola.points().iter().map(planar).collect::<Result<Vec<_>>>()?,
        false,
        Style::dashed(POLYGON, 1.2),
        "polygon",
        None,
    )?;
    panel.polyline(
        &lifted.iter().map(planar).collect::<Result<Vec<_>>>()?,
        false,
        Style::line(POLYGON, 1.0),
        "polygon",
        None,
    )?;
    panel.curve(
        &planar_curve(parabola)?,
        Style::line("#d95f02", 2.4),
        "parabola",
        Some(format!("p(t), control points {}", super::list(parabola.points()))),
    )?;
    let on_plane = RationalBezierCurve::new(lifted.clone(), w.to_vec())?;
    panel.polyline_f64(
        AnyCurve::Rational(on_plane).drawn_samples(160)?,
        Style::line(CURVE, 2.4),
        "curve",
        Some(format!(
            "x(t) on z = 1, control points {}, weights {}",
            super::list(b),
            weights(w)
        )),
    );
    let half = T::from_ratio(1, 2)?;
    let (p_half, x_half) = (parabola.eval(&half), conic.eval(&half)?);
    let x_lifted = lift(&x_half)?;
    let far = if p_half.coords()[2] >= one { &p_half } else { &x_lifted };
    panel.polyline(
        &[o.clone(), planar(far)?],
        false,
        Style::dashed(POINT, 1.0),
        "ray",
        None,
    )?;
    panel.dot(&o, 3.5, "#222222", "the centre of projection O = (0, 0, 0)".into())?;
    panel.label(&o, "O", "#222222", -8.0, 14.0)?;
    for (i, (p, q)) in parabola.points().iter().zip(&lifted).enumerate() {
        let (pn, bn) = (indexed("p", &i.to_string(), None), indexed("b", &i.to_string(), None));
        panel.dot(&planar(p)?, 3.5, "#d95f02", format!("{pn} = {p}"))?;
        panel.label(&planar(p)?, pn, "#d95f02", 6.0, -7.0)?;
        panel.dot(&planar(q)?, 3.5, CURVE, format!("{bn} = {}, weight {}", b[i], w[i]))?;
        panel.label(&planar(q)?, bn, CURVE, 6.0, -7.0)?;
    }
    panel.dot(&planar(&p_half)?, 4.0, POINT, format!("p(1/2) = {p_half}"))?;
    panel.label(&planar(&p_half)?, "p(1/2)", POINT, 7.0, 14.0)?;
    panel.dot(&planar(&x_lifted)?, 4.0, POINT, format!("x(1/2) = {x_half}"))?;
    panel.label(&planar(&x_lifted)?, "x(1/2)", POINT, 7.0, 14.0)?;
    fig.add_panel(panel);
    fig.note(
        Some("#d95f02"),
        format!(
            "p(t) = Σ pᵢ Bᵢ²(t), a parabola in space: {}",
            super::list(parabola.points())
        ),
    );
    fig.note(
        Some(CURVE),
        format!(
            "x(t) = (x/z, y/z) of p(t), on z = 1: bᵢ = {}, weights wᵢ = {}",
            super::list(b),
            weights(w)
        ),
    );
    fig.note(Some(POINT), format!("p(1/2) = {p_half} projects to x(1/2) = {x_half}"));
    fig.note(
        None,
        "the projection (x, y, z) → (x/z, y/z, 1) from O; the heights of the pᵢ are the weights wᵢ",
    );
    Ok(fig)
}

fn weights<T: std::fmt::Display>(w: &[T]) -> String {
    w.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", ")
}
