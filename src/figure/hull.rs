//! The convex hull of the control points, a point, and its certificate weights.

use super::svg::{indexed, Figure, Panel, Style, CURVE, POINT, POLYGON};
use super::{list, planar, planar_curve};
use crate::error::Result;
use crate::point::Point;
use crate::scalar::Scalar;
use crate::BezierCurve;

/// The curve, the convex hull of its control points (shaded), the point `p` and the convex
/// weights `λ_i` of [`BezierCurve::hull_weights`] (the certificate `p = Σ λ_i b_i`,
/// `λ_i ≥ 0`, `Σ λ_i = 1`), each written beside its control point; or the statement that
/// `p` lies outside the hull.
pub fn hull<T: Scalar>(curve: &BezierCurve<T>, p: &Point<T>) -> Result<Figure> {
    super::check_figure_degree(curve.degree())?;
    let weights = curve.hull_weights(p)?;
    let mut fig = Figure::new(match &weights {
        Some(_) => format!("The convex hull contains {p}: its certificate weights"),
        None => format!("{p} lies outside the convex hull of the control points"),
    });
    let mut panel = Panel::new("");
    let pts = curve.points();
    let drawn = pts.iter().map(planar).collect::<Result<Vec<_>>>()?;
    let hull = convex_hull(&drawn);
    panel.polyline(
        &hull,
        true,
        Style {
            fill: Some("#f4d03f"),
            ..Style::line("#b7950b", 1.2)
        },
        "hull",
        Some("the convex hull of the control points".into()),
    )?;
    panel.polyline(&drawn, false, Style::dashed(POLYGON, 1.2), "polygon", None)?;
    panel.curve(
        &planar_curve(curve)?,
        Style::line(CURVE, 2.5),
        "curve",
        Some(format!("b(t), control points {}", list(pts))),
    )?;
    let q = planar(p)?;
    for (i, (b, d)) in pts.iter().zip(&drawn).enumerate() {
        let name = indexed("b", &i.to_string(), None);
        let lambda = indexed("λ", &i.to_string(), None);
        let text = match &weights {
            Some(w) => {
                if !w[i].is_zero() {
                    panel.polyline(
                        &[q.clone(), d.clone()],
                        false,
                        Style::dashed(POINT, 1.0),
                        "weight",
                        None,
                    )?;
                }
                format!("{name}: {lambda} = {}", w[i])
            }
            None => name.clone(),
        };
        panel.dot(d, 3.5, POLYGON, format!("{name} = {b}"))?;
        panel.label(d, text, "#222222", 6.0, -7.0)?;
    }
    panel.dot(&q, 5.0, POINT, format!("p = {p}"))?;
    panel.label(&q, "p", POINT, 7.0, 15.0)?;
    fig.add_panel(panel);
    match weights {
        Some(w) => {
            let terms: Vec<String> = w
                .iter()
                .enumerate()
                .map(|(i, l)| format!("{} = {l}", indexed("λ", &i.to_string(), None)))
                .collect();
            fig.note(Some(POINT), format!("p = {p} = Σ λᵢ bᵢ with {}", terms.join(", ")));
            fig.note(
                None,
                "every λᵢ ≥ 0 and Σ λᵢ = 1, checked exactly: the certificate that p lies in the hull",
            );
        }
        None => fig.note(
            Some(POINT),
            format!("p = {p}: no convex weights exist (decided exactly)"),
        ),
    }
    Ok(fig)
}

/// The convex hull of planar points, counter-clockwise (Andrew's monotone chain, exact).
fn convex_hull<T: Scalar>(points: &[Point<T>]) -> Vec<Point<T>> {
    let mut pts: Vec<Point<T>> = points.to_vec();
    pts.sort_by(|a, b| {
        let (a, b) = (a.coords(), b.coords());
        a[0].partial_cmp(&b[0])
            .unwrap_or(std::cmp::Ordering::Equal)
            .then(a[1].partial_cmp(&b[1]).unwrap_or(std::cmp::Ordering::Equal))
    });
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let cross = |o: &Point<T>, a: &Point<T>, b: &Point<T>| -> T {
        let (o, a, b) = (o.coords(), a.coords(), b.coords());
        a[0].sub_ref(&o[0])
            .mul_ref(&b[1].sub_ref(&o[1]))
            .sub_ref(&a[1].sub_ref(&o[1]).mul_ref(&b[0].sub_ref(&o[0])))
    };
    let mut lower: Vec<Point<T>> = Vec::new();
    for p in &pts {
        while lower.len() >= 2 && cross(&lower[lower.len() - 2], &lower[lower.len() - 1], p) <= T::zero() {
            lower.pop();
        }
        lower.push(p.clone());
    }
    let mut upper: Vec<Point<T>> = Vec::new();
    for p in pts.iter().rev() {
        while upper.len() >= 2 && cross(&upper[upper.len() - 2], &upper[upper.len() - 1], p) <= T::zero() {
            upper.pop();
        }
        upper.push(p.clone());
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}
