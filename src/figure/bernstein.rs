//! The Bernstein basis `B_i^n` on `[0, 1]` and its exact values at one parameter.

use super::svg::{indexed, Figure, Panel, Style, PALETTE, POINT, POLYGON};
use crate::bernstein::{bernstein, bernstein_all};
use crate::error::{Error, Result};
use crate::point::Point;
use crate::scalar::Scalar;
use crate::BezierCurve;

/// The graphs of `B_0^n, …, B_n^n` over `[0, 1]`, the vertical line at `t` and the points
/// `(t, B_i^n(t))`, whose exact values the notes print with their sum 1.
///
/// Each graph is drawn as what it exactly is: the graph `s ↦ (s, B_i^n(s))` is the Bézier
/// curve with control points `(j/n, δ_ij)`, because `Σ_j (j/n) B_j^n(s) = s` (linear
/// precision). `t` must lie in `[0, 1]`.
pub fn bernstein_basis<T: Scalar>(n: usize, t: &T) -> Result<Figure> {
    super::check_figure_degree(n)?;
    if n == 0 {
        return Err(Error::Domain("the Bernstein figure needs degree at least 1".into()));
    }
    if *t < T::zero() || *t > T::one() {
        return Err(Error::Domain(format!(
            "--t = {t}: the Bernstein basis is drawn on [0, 1]"
        )));
    }
    let degree = n.to_string();
    let values = bernstein_all(n, t);
    let power = sup(&degree);
    let mut fig = Figure::new(format!(
        "The Bernstein basis Bᵢ{power}(t) = C({n}, i) tⁱ (1 − t){power}⁻ⁱ on [0, 1], at t = {t}"
    ));
    let mut panel = Panel::new("").with_max_size(460.0, 300.0);
    let p = |x: T, y: T| Point::new(vec![x, y]);
    let (zero, one) = (T::zero(), T::one());
    let axes = Style::line(POLYGON, 1.0);
    panel.polyline(
        &[p(zero.clone(), zero.clone())?, p(one.clone(), zero.clone())?],
        false,
        axes,
        "axis",
        None,
    )?;
    panel.polyline(
        &[p(zero.clone(), zero.clone())?, p(zero.clone(), one.clone())?],
        false,
        axes,
        "axis",
        None,
    )?;
    panel.label(&p(zero.clone(), zero.clone())?, "0", POLYGON, -4.0, 14.0)?;
    panel.label(&p(one.clone(), zero.clone())?, "1", POLYGON, -4.0, 14.0)?;
    panel.label(&p(zero.clone(), one.clone())?, "1", POLYGON, -6.0, 4.0)?;
    panel.polyline(
        &[p(t.clone(), zero.clone())?, p(t.clone(), one.clone())?],
        false,
        Style::dashed(POINT, 1.0),
        "parameter",
        Some(format!("t = {t}")),
    )?;
    panel.label(&p(t.clone(), zero.clone())?, format!("t = {t}"), POINT, 4.0, 14.0)?;
    let abscissae: Vec<T> = (0..=n)
        .map(|j| T::from_ratio(j as i64, n as i64))
        .collect::<Result<_>>()?;
    for (i, value) in values.iter().enumerate() {
        let name = indexed("B", &i.to_string(), Some(&degree));
        let color = PALETTE[i % PALETTE.len()];
        let graph = BezierCurve::new(
            abscissae
                .iter()
                .enumerate()
                .map(|(j, x)| p(x.clone(), if i == j { one.clone() } else { zero.clone() }))
                .collect::<Result<_>>()?,
        )?;
        panel.curve(
            &graph,
            Style::line(color, 2.2),
            "curve",
            Some(format!("{name}(s), 0 ≤ s ≤ 1")),
        )?;
        let at = p(t.clone(), value.clone())?;
        panel.dot(&at, 3.5, color, format!("{name}({t}) = {value}"))?;
        // the name goes by the graph's highest point, B_i^n(i/n)
        let top = p(abscissae[i].clone(), bernstein(i, n, &abscissae[i])?)?;
        panel.label(&top, name.clone(), color, 4.0, -6.0)?;
        fig.note(Some(color), format!("{name}({t}) = {value}"));
    }
    fig.add_panel(panel);
    let sum = values.iter().fold(T::zero(), |s, v| s.add_ref(v));
    fig.note(
        None,
        format!("Σ Bᵢ{power}({t}) = {sum} (a partition of unity), every Bᵢ{power}({t}) ≥ 0"),
    );
    Ok(fig)
}

/// `n` as a superscript.
fn sup(n: &str) -> String {
    indexed("", "", Some(n))
}
