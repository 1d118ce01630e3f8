//! The hodograph b′(t) and the tangents at the ends.

use super::svg::{indexed, Figure, Panel, Style, CURVE, PALETTE, POINT, POLYGON};
use super::{list, planar, planar_curve};
use crate::error::{Error, Result};
use crate::point::Point;
use crate::scalar::Scalar;
use crate::BezierCurve;

/// Left: the curve with its tangent vectors at the ends, `b′(0) = n(b_1 − b_0)` and
/// `b′(1) = n(b_n − b_{n−1})` drawn at 1/n scale (so the first lies on the first leg of the
/// polygon). Right: the hodograph, the curve `b′(t)` of degree n − 1 with control vectors
/// `n Δb_i`, drawn from the origin.
pub fn hodograph<T: Scalar>(curve: &BezierCurve<T>) -> Result<Figure> {
    super::check_figure_degree(curve.degree())?;
    let n = curve.degree();
    if n == 0 {
        return Err(Error::Domain("a hodograph needs a curve of degree at least 1".into()));
    }
    let d = curve.derivative(1)?;
    let (zero, one) = (T::zero(), T::one());
    let (d0, d1) = (d.eval(&zero), d.eval(&one));
    let inv_n = T::one().checked_div(&T::from_usize(n))?;
    let mut fig = Figure::new(format!("Hodograph and end tangents, degree {n}"));

    // two panels side by side, each at most 410 px wide: the figure stays under 924 px, so
    // that printed on A4 (693 px wide) its 16 px print font is still 9 pt
    let mut left = Panel::new("the curve and its end tangents b′(0)/n, b′(1)/n").with_max_size(410.0, 375.0);
    let pts = curve.points();
    let drawn = pts.iter().map(planar).collect::<Result<Vec<_>>>()?;
    left.polyline(&drawn, false, Style::line(POLYGON, 1.2), "polygon", None)?;
    for (i, (p, q)) in pts.iter().zip(&drawn).enumerate() {
        left.dot(q, 3.0, POLYGON, format!("{} = {p}", indexed("b", &i.to_string(), None)))?;
        left.label(q, indexed("b", &i.to_string(), None), POLYGON, 6.0, -7.0)?;
    }
    left.curve(
        &planar_curve(curve)?,
        Style::line(CURVE, 2.5),
        "curve",
        Some(format!("b(t), control points {}", list(pts))),
    )?;
    let start_tip = pts[0].add(&d0.scale(&inv_n));
    let end_tip = pts[n].add(&d1.scale(&inv_n));
    left.arrow(
        &drawn[0],
        &planar(&start_tip)?,
        Style::line(POINT, 2.2),
        "tangent",
        Some(format!("b′(0) = {n}(b₁ − b₀) = {d0}")),
    )?;
    left.arrow(
        &drawn[n],
        &planar(&end_tip)?,
        Style::line(PALETTE[1], 2.2),
        "tangent",
        Some(format!("b′(1) = {n}({} − {}) = {d1}", b(n), b(n - 1))),
    )?;
    fig.add_panel(left);

    let mut right = Panel::new("the hodograph b′(t) from the origin").with_max_size(410.0, 375.0);
    let origin = Point::origin(curve.dim());
    let o = planar(&origin)?;
    let dpts = d.points();
    let ddrawn = dpts.iter().map(planar).collect::<Result<Vec<_>>>()?;
    right.dot(&o, 3.0, "#000000", format!("origin {origin}"))?;
    right.label(&o, "0", "#000000", -6.0, 14.0)?;
    if dpts.len() > 1 {
        right.polyline(&ddrawn, false, Style::line(POLYGON, 1.2), "polygon", None)?;
    }
    for (i, (p, q)) in dpts.iter().zip(&ddrawn).enumerate() {
        let name = format!("{n}Δ{}", indexed("b", &i.to_string(), None));
        right.dot(q, 3.0, POLYGON, format!("{name} = {n}({} − {}) = {p}", b(i + 1), b(i)))?;
        right.label(q, name, POLYGON, 6.0, -7.0)?;
    }
    right.curve(
        &planar_curve(&d)?,
        Style::line(CURVE, 2.5),
        "curve",
        Some(format!("b′(t), control points {}", list(dpts))),
    )?;
    right.arrow(
        &o,
        &ddrawn[0],
        Style::line(POINT, 2.0),
        "tangent",
        Some(format!("b′(0) = {d0}")),
    )?;
    right.arrow(
        &o,
        &ddrawn[dpts.len() - 1],
        Style::line(PALETTE[1], 2.0),
        "tangent",
        Some(format!("b′(1) = {d1}")),
    )?;
    fig.add_panel(right);

    fig.note(Some(POINT), format!("b′(0) = {n}(b₁ − b₀) = {d0}"));
    fig.note(Some(PALETTE[1]), format!("b′(1) = {n}({} − {}) = {d1}", b(n), b(n - 1)));
    fig.note(
        Some(CURVE),
        format!(
            "b′(t) = {n} Σ Δbᵢ Bᵢ{}(t), control vectors {}",
            indexed("", "", Some(&(n - 1).to_string())),
            list(dpts)
        ),
    );
    Ok(fig)
}

fn b(i: usize) -> String {
    indexed("b", &i.to_string(), None)
}
