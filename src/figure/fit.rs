//! Text 004's fit: the curve, the fitted cubic and δ.

use super::svg::{Figure, Panel, Style, CURVE, PALETTE, POINT, POLYGON};
use super::{planar, planar_curve, AnyCurve};
use crate::error::Result;
use crate::fit::fit_cubic_to;
use crate::param::ParamCurve;
use crate::scalar::Scalar;

/// The curve `x(t)` (exact samples), text 004's cubic `a(t)` with control points
/// `x(0), x(0) + k ẋ(0), x(1) − l ẋ(1), x(1)` ([`fit_cubic_to`]), and the residual
/// `a(1/2) − x(1/2)` whose squared length is `δ²`, all exact; space curves in the fixed
/// projection.
pub fn fit<T: Scalar>(curve: &AnyCurve<T>) -> Result<Figure> {
    super::check_figure_degree(curve.points().len() - 1)?;
    let result = fit_cubic_to(curve)?;
    let half = T::from_ratio(1, 2)?;
    let xh = curve.eval(&half)?;
    let ah = result.curve.eval(&half);
    let mut fig = Figure::new(format!(
        "Text 004's cubic fit: k = {}, l = {}, δ² = {}",
        result.k, result.l, result.delta2
    ));
    let mut panel = Panel::new(if curve.dim() == 3 {
        super::PROJECTION_HEADING
    } else {
        ""
    });
    let a = result.curve.points();
    let drawn = a.iter().map(planar).collect::<Result<Vec<_>>>()?;
    panel.polyline(&drawn, false, Style::dashed(POLYGON, 1.1), "polygon", None)?;
    for (i, (p, q)) in a.iter().zip(&drawn).enumerate() {
        panel.dot(q, 3.0, POLYGON, format!("a_{i} = {p}"))?;
        panel.label(q, super::svg::indexed("a", &i.to_string(), None), POLYGON, 6.0, -7.0)?;
    }
    panel.polyline_f64(
        curve.drawn_samples(200)?,
        Style::line(CURVE, 3.0),
        "curve",
        Some(format!("x(t), control points {}", super::list(curve.points()))),
    );
    panel.curve(
        &planar_curve(&result.curve)?,
        Style::dashed(PALETTE[0], 2.0),
        "fit",
        Some(format!("a(t), control points {}", super::list(a))),
    )?;
    panel.polyline(
        &[planar(&xh)?, planar(&ah)?],
        false,
        Style::line(POINT, 2.0),
        "residual",
        Some(format!("a(1/2) − x(1/2) = {}", result.residual)),
    )?;
    panel.dot(&planar(&xh)?, 3.5, CURVE, format!("x(1/2) = {xh}"))?;
    panel.dot(&planar(&ah)?, 3.5, PALETTE[0], format!("a(1/2) = {ah}"))?;
    panel.label(&planar(&xh)?, "x(1/2)", CURVE, -8.0, 14.0)?;
    panel.label(&planar(&ah)?, "a(1/2)", PALETTE[0], 8.0, -6.0)?;
    fig.add_panel(panel);
    fig.note(
        Some(CURVE),
        format!(
            "x(t): x(0) = {}, x(1/2) = {xh}, x(1) = {}",
            curve.eval(&T::zero())?,
            curve.eval(&T::one())?
        ),
    );
    fig.note(
        Some(PALETTE[0]),
        format!(
            "a(t): k = {}, l = {}, control points {}",
            result.k,
            result.l,
            super::list(a)
        ),
    );
    fig.note(
        Some(POINT),
        format!(
            "δ² = |a(1/2) − x(1/2)|² = {} (δ ≈ {:.6}), a(1/2) − x(1/2) = {}",
            result.delta2,
            result.delta2.to_f64().sqrt(),
            result.residual
        ),
    );
    for w in &result.warnings {
        fig.note(None, format!("note: {w}"));
    }
    Ok(fig)
}
