//! Degree elevation converging to the curve (Theorem 1.2), with the exact distances.

use super::svg::{indexed, Figure, Panel, Style, CURVE, PALETTE, POLYGON};
use super::{planar, planar_curve};
use crate::error::{Error, Result};
use crate::scalar::Scalar;
use crate::BezierCurve;

/// The largest number of elevation steps a figure draws (each polygon is drawn and its
/// distance computed exactly; beyond this the polygons are indistinguishable from the curve).
pub const MAX_FIGURE_ELEVATION: usize = 1024;

/// The control polygons of the curve elevated `r` times for each `r` in `steps` (formula (8),
/// [`BezierCurve::elevate_by`]), over the curve, with the exact distance
/// `max_i |b_i^(r) − b(i/(n+r))|_∞` of each ([`BezierCurve::elevation_distance`]).
pub fn elevation<T: Scalar>(curve: &BezierCurve<T>, steps: &[usize]) -> Result<Figure> {
    if let Some(r) = steps.iter().find(|&&r| r > MAX_FIGURE_ELEVATION) {
        return Err(Error::TooLarge {
            what: "elevation steps in a figure",
            value: r.to_string(),
            limit: MAX_FIGURE_ELEVATION.to_string(),
        });
    }
    super::check_figure_degree(curve.degree())?;
    let n = curve.degree();
    let mut fig = Figure::new(format!(
        "Degree elevation r = {} converging to the curve (Theorem 1.2)",
        steps.iter().map(|r| r.to_string()).collect::<Vec<_>>().join(", ")
    ));
    let mut panel = Panel::new("");
    let original = curve.points().iter().map(planar).collect::<Result<Vec<_>>>()?;
    panel.polyline(&original, false, Style::line(POLYGON, 1.3), "polygon", None)?;
    for (i, p) in curve.points().iter().enumerate() {
        panel.dot(
            &original[i],
            3.0,
            POLYGON,
            format!("{} = {p}", indexed("b", &i.to_string(), None)),
        )?;
    }
    let d0 = curve.distance_of_elevated(curve, 0);
    fig.note(Some(POLYGON), format!("r = 0: maxᵢ |bᵢ − b(i/{n})|∞ = {}", d0.max_norm));
    for (k, &r) in steps.iter().enumerate() {
        let color = PALETTE[k % PALETTE.len()];
        let elevated = curve.elevate_by(r)?;
        let drawn = elevated.points().iter().map(planar).collect::<Result<Vec<_>>>()?;
        let d = curve.distance_of_elevated(&elevated, r);
        let b_ir = indexed("b", "ᵢ", Some(&format!("({r})")));
        let title = format!(
            "r = {r}: the {} Bézier points of degree {}; maxᵢ |{b_ir} − b(i/{})|∞ = {}",
            elevated.points().len(),
            n + r,
            n + r,
            d.max_norm
        );
        panel.polyline(&drawn, false, Style::line(color, 1.2), "polygon", Some(title))?;
        if drawn.len() <= 40 {
            for (i, (p, q)) in elevated.points().iter().zip(&drawn).enumerate() {
                let name = indexed("b", &i.to_string(), Some(&format!("({r})")));
                panel.dot(q, 2.0, color, format!("{name} = {p}"))?;
            }
        }
        fig.note(
            Some(color),
            format!(
                "r = {r}: maxᵢ |{b_ir} − b(i/{})|∞ = {}, |·|₂² = {}",
                n + r,
                d.max_norm,
                d.max_squared
            ),
        );
    }
    panel.curve(
        &planar_curve(curve)?,
        Style::line(CURVE, 2.5),
        "curve",
        Some(format!("b(t), control points {}", super::list(curve.points()))),
    )?;
    fig.add_panel(panel);
    fig.note(
        Some(CURVE),
        "the curve b(t); the polygons approach it as r grows (|·|₂²: squared Euclidean distance)",
    );
    Ok(fig)
}
