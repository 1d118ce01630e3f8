//! Subdivision at `t` (Lemma 1.3): both halves' control polygons, read off the scheme.

use super::svg::{indexed, Figure, Panel, Style, PALETTE, POINT, POLYGON};
use super::{list, planar, planar_curve};
use crate::error::Result;
use crate::scalar::Scalar;
use crate::BezierCurve;

/// The curve split at `t` by [`BezierCurve::split_at`]: the left piece's polygon
/// `b_0^0, b_0^1, …, b_0^n` and the right piece's `b_0^n, b_1^{n−1}, …, b_n^0`, each drawn with
/// its own piece of the curve.
pub fn subdivision<T: Scalar>(curve: &BezierCurve<T>, t: &T) -> Result<Figure> {
    super::check_figure_degree(curve.degree())?;
    let (left, right) = curve.split_at(t);
    let n = curve.degree();
    let mut fig = Figure::new(format!("Subdivision at t = {t} (Lemma 1.3), degree {n}"));
    let mut panel = Panel::new("");
    let original = curve.points().iter().map(planar).collect::<Result<Vec<_>>>()?;
    panel.polyline(&original, false, Style::dashed(POLYGON, 1.0), "polygon", None)?;
    for (k, p) in curve.points().iter().enumerate() {
        panel.dot(
            &original[k],
            2.5,
            POLYGON,
            format!("{} = {p}", indexed("b", &k.to_string(), None)),
        )?;
    }
    for (piece, name, color) in [(&left, "left", PALETTE[0]), (&right, "right", PALETTE[1])] {
        let drawn = piece.points().iter().map(planar).collect::<Result<Vec<_>>>()?;
        panel.curve(
            &planar_curve(piece)?,
            Style::line(color, 2.5),
            "curve",
            Some(format!("the {name} piece: control points {}", list(piece.points()))),
        )?;
        panel.polyline(&drawn, false, Style::line(color, 1.4), "polygon", None)?;
        let mut values = Vec::new();
        for (k, (p, q)) in piece.points().iter().zip(&drawn).enumerate() {
            // left: b_0^k(t); right: b_k^{n−k}(t)
            let label = if name == "left" {
                indexed("b", "0", Some(&k.to_string()))
            } else {
                indexed("b", &k.to_string(), Some(&(n - k).to_string()))
            };
            let title = format!("{label}({t}) = {p}");
            let at_split = (name == "left" && k == n) || (name == "right" && k == 0);
            if !at_split {
                panel.dot(q, 3.5, color, title.clone())?;
                let dy = if name == "left" { -8.0 } else { 16.0 };
                panel.label(q, label, color, 6.0, dy)?;
            }
            values.push(title);
        }
        fig.note(Some(color), format!("{name} piece: {}", values.join(", ")));
    }
    // b(t) is where the pieces meet: the left piece's last point, exactly
    let split = left.points()[n].clone();
    panel.dot(&planar(&split)?, 5.0, POINT, format!("b({t}) = {split}"))?;
    panel.label(&planar(&split)?, format!("b({t})"), POINT, 8.0, -10.0)?;
    fig.add_panel(panel);
    fig.note(
        Some(POINT),
        format!("b({t}) = {split}: the last point of the left piece, the first of the right"),
    );
    fig.note(
        None,
        format!("left(s) = b({t}·s), right(s) = b({t} + (1 − {t})·s) for 0 ≤ s ≤ 1"),
    );
    Ok(fig)
}
