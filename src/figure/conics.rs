//! Rational conic arcs of one control polygon for several middle weights (text 001).

use super::svg::{indexed, Figure, Panel, Style, POLYGON};
use super::{planar, AnyCurve};
use crate::conic::{classify_conic, conic_arc_passes_infinity, ConicKind};
use crate::error::{Error, Result};
use crate::point::Point;
use crate::rational::RationalBezierCurve;
use crate::scalar::Scalar;

/// The arcs `x(t) = Σ w_i b_i B_i^2(t) / Σ w_i B_i^2(t)` over one planar polygon `b_0 b_1 b_2`
/// with end weights `w0`, `w2` and each middle weight of `middles`, coloured by the conic
/// the library's [`classify_conic`] finds (`w_1² < w_0 w_2` ellipse, `=` parabola,
/// `>` hyperbola). Arcs that pass through infinity are refused.
pub fn conics<T: Scalar>(points: &[Point<T>], w0: &T, w2: &T, middles: &[T]) -> Result<Figure> {
    if points.len() != 3 {
        return Err(Error::WrongCount {
            what: "a conic arc figure",
            needed: 3,
            got: points.len(),
        });
    }
    if middles.is_empty() {
        return Err(Error::Domain(
            "a conic arc figure needs at least one middle weight".into(),
        ));
    }
    let mut fig = Figure::new(format!(
        "Conic arcs of one control polygon, w₀ = {w0}, w₂ = {w2}, middle weight w₁ = {}",
        middles.iter().map(|w| w.to_string()).collect::<Vec<_>>().join(", ")
    ));
    let mut panel = Panel::new("");
    let drawn = points.iter().map(planar).collect::<Result<Vec<_>>>()?;
    panel.polyline(&drawn, false, Style::line(POLYGON, 1.3), "polygon", None)?;
    for (i, (p, q)) in points.iter().zip(&drawn).enumerate() {
        let name = indexed("b", &i.to_string(), None);
        panel.dot(q, 3.5, POLYGON, format!("{name} = {p}"))?;
        panel.label(q, name, POLYGON, 6.0, -7.0)?;
    }
    let mut seen: Vec<&'static str> = Vec::new();
    for (k, w1) in middles.iter().enumerate() {
        let arc = RationalBezierCurve::new(points.to_vec(), vec![w0.clone(), w1.clone(), w2.clone()])?;
        if conic_arc_passes_infinity(&arc)? {
            return Err(Error::Domain(format!(
                "the arc with weights ({w0}, {w1}, {w2}) passes through infinity; a figure draws finite arcs"
            )));
        }
        let kind = classify_conic(&arc)?;
        let color = kind_color(&kind);
        let ratio = w1.mul_ref(w1).checked_div(&w0.mul_ref(w2))?;
        let samples = AnyCurve::Rational(arc.clone()).drawn_samples(160)?;
        let what = format!("w₁ = {w1}: {kind} (w₁²/(w₀w₂) = {ratio})");
        // a second arc of the same kind (two hyperbolas) is dashed to tell them apart
        let style = if seen.contains(&color) {
            Style::dashed(color, 2.3)
        } else {
            Style::line(color, 2.3)
        };
        seen.push(color);
        panel.polyline_f64(samples, style, "curve", Some(what.clone()));
        let mid = arc.eval(&T::from_ratio(1, 2)?)?;
        panel.dot(&planar(&mid)?, 3.0, color, format!("x(1/2) = {mid} for w₁ = {w1}"))?;
        // labels are staggered so that midpoints on one line (a symmetric polygon) stay legible
        panel.label(&planar(&mid)?, format!("w₁ = {w1}"), color, 8.0, 4.0 - 15.0 * k as f64)?;
        fig.note(Some(color), format!("{what}; x(1/2) = {mid}"));
    }
    fig.add_panel(panel);
    fig.note(
        None,
        "ellipse: w₁² < w₀w₂ (blue), parabola: w₁² = w₀w₂ (green), hyperbola: w₁² > w₀w₂ (red)",
    );
    Ok(fig)
}

/// The colour of a conic kind in figures.
pub(crate) fn kind_color(kind: &ConicKind) -> &'static str {
    match kind {
        ConicKind::Ellipse => "#2c7fb8",
        ConicKind::Parabola => "#1b9e77",
        ConicKind::Hyperbola => "#c0392b",
        _ => "#555555",
    }
}
