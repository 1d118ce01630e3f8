//! The de Casteljau construction at `t`: every level of the scheme (9), labelled `b_i^r`.

use super::svg::{indexed, Figure, Panel, Style, CURVE, PALETTE, POINT, POLYGON};
use super::{planar, planar_curve};
use crate::error::Result;
use crate::scalar::Scalar;
use crate::BezierCurve;

/// The construction of `b(t)` by the scheme (9): the control polygon, each level
/// `b_0^r … b_{n−r}^r` joined and labelled, the point `b_0^n(t)` on the curve. Each point's
/// tooltip is its exact value; the notes list every level.
pub fn construction<T: Scalar>(curve: &BezierCurve<T>, t: &T) -> Result<Figure> {
    super::check_figure_degree(curve.degree())?;
    let scheme = curve.scheme(t);
    let n = scheme.degree();
    let mut fig = Figure::new(format!("de Casteljau's construction of b({t}), degree {n}"));
    let mut panel = Panel::new("");
    panel.curve(
        &planar_curve(curve)?,
        Style::line(CURVE, 2.5),
        "curve",
        Some(format!(
            "b(t), 0 ≤ t ≤ 1; control points {}",
            super::list(curve.points())
        )),
    )?;
    for (r, column) in scheme.columns.iter().enumerate() {
        let color = if r == 0 {
            POLYGON
        } else {
            PALETTE[(r - 1) % PALETTE.len()]
        };
        let drawn = column.iter().map(planar).collect::<Result<Vec<_>>>()?;
        if drawn.len() > 1 {
            let style = if r == 0 {
                Style::line(POLYGON, 1.3)
            } else {
                Style::line(color, 1.6)
            };
            panel.polyline(&drawn, false, style, if r == 0 { "polygon" } else { "level" }, None)?;
        }
        let mut values = Vec::new();
        for (i, (p, q)) in column.iter().zip(&drawn).enumerate() {
            let last = r == n;
            let name = if r == 0 {
                indexed("b", &i.to_string(), None)
            } else {
                indexed("b", &i.to_string(), Some(&r.to_string()))
            };
            let title = if r == 0 {
                format!("{name} = {p}")
            } else {
                format!("{name}({t}) = {p}")
            };
            let (radius, c) = if last { (5.0, POINT) } else { (3.5, color) };
            panel.dot(q, radius, c, title.clone())?;
            // levels alternate their labels above and below the points to keep them apart
            let dy = if r % 2 == 0 { -8.0 } else { 16.0 };
            if last {
                panel.label(q, format!("{name} = b({t})"), c, -8.0, -8.0)?;
            } else {
                panel.label(q, name, c, 6.0, dy)?;
            }
            values.push(title);
        }
        let swatch = if r == n { POINT } else { color };
        fig.note(Some(swatch), format!("r = {r}: {}", values.join(", ")));
    }
    fig.add_panel(panel);
    fig.note(
        Some(CURVE),
        format!(
            "b(t) = Σ bᵢ Bᵢ{}(t);  bᵢʳ(t) = (1 − t) bᵢʳ⁻¹(t) + t bᵢ₊₁ʳ⁻¹(t), r = 1..{n}",
            indexed("", "", Some(&n.to_string()))
        ),
    );
    Ok(fig)
}
