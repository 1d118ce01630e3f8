//! Text 004's fit: the curve, the fitted cubic and δ.

use super::sample::polynomial;
use super::svg::{xy, Figure, Panel, Style, CURVE, PALETTE, POINT, POLYGON};
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
    })
    .with_max_size(400.0, 420.0);
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
    // The residual a(1/2) − x(1/2) with its two ends, on the main panel and in the inset.
    let mark_residual = |p: &mut Panel| -> Result<()> {
        p.polyline(
            &[planar(&xh)?, planar(&ah)?],
            false,
            Style::line(POINT, 2.0),
            "residual",
            Some(format!("a(1/2) − x(1/2) = {}", result.residual)),
        )?;
        p.dot(&planar(&xh)?, 3.5, CURVE, format!("x(1/2) = {xh}"))?;
        p.dot(&planar(&ah)?, 3.5, PALETTE[0], format!("a(1/2) = {ah}"))?;
        p.label(&planar(&xh)?, "x(1/2)", CURVE, -8.0, 14.0)?;
        p.label(&planar(&ah)?, "a(1/2)", PALETTE[0], 8.0, -6.0)
    };
    mark_residual(&mut panel)?;
    let (xd, ad) = (xy(&planar(&xh)?)?, xy(&planar(&ah)?)?);
    // δ is a few pixels at the curve's scale: a magnified view of the window around it
    let half = 1.5 * (xd[0] - ad[0]).abs().max((xd[1] - ad[1]).abs());
    let window = (half > 0.0).then(|| {
        let c = [(xd[0] + ad[0]) / 2.0, (xd[1] + ad[1]) / 2.0];
        [c[0] - half, c[1] - half, c[0] + half, c[1] + half]
    });
    if let Some(w) = window {
        panel.polyline_f64(frame(w), Style::line("#888888", 1.0), "window", None);
    }
    fig.add_panel(panel);
    if let Some(w) = window {
        let fitted = planar_curve(&result.curve)?
            .points()
            .iter()
            .map(xy)
            .collect::<Result<Vec<_>>>()?;
        let (x_samples, a_samples) = (curve.drawn_samples(INSET_SAMPLES)?, polynomial(&fitted, INSET_SAMPLES));
        let inset = |heading: String| -> Result<Panel> {
            let mut p = Panel::new(heading).with_max_size(200.0, 200.0);
            p.polyline_f64(frame(w), Style::line("#888888", 1.0), "window", None);
            for run in clip(&x_samples, w) {
                p.polyline_f64(run, Style::line(CURVE, 3.0), "curve", None);
            }
            for run in clip(&a_samples, w) {
                p.polyline_f64(run, Style::dashed(PALETTE[0], 2.0), "fit", None);
            }
            mark_residual(&mut p)?;
            Ok(p)
        };
        let mut with_inset = fig.clone();
        with_inset.add_panel(inset(String::new())?);
        let maps = with_inset.layout().panels;
        let zoom = maps[1].scale / maps[0].scale;
        fig.add_panel(inset(format!("the grey square, magnified ×{zoom:.0}"))?);
    }
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

/// Samples of each curve for the magnified view: fine enough that its chords stay within a
/// fraction of a pixel at the magnification (the window is a few pixels of the whole curve).
const INSET_SAMPLES: usize = 4000;

/// The closed square `[x0, y0, x1, y1]` as a polyline.
fn frame(w: [f64; 4]) -> Vec<[f64; 2]> {
    vec![[w[0], w[1]], [w[2], w[1]], [w[2], w[3]], [w[0], w[3]], [w[0], w[1]]]
}

/// The parts of a polyline inside the window `[x0, y0, x1, y1]` (Liang–Barsky per segment).
fn clip(pts: &[[f64; 2]], w: [f64; 4]) -> Vec<Vec<[f64; 2]>> {
    let mut runs: Vec<Vec<[f64; 2]>> = Vec::new();
    let mut open = false;
    for s in pts.windows(2) {
        let (a, b) = (s[0], s[1]);
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let (mut lo, mut hi) = (0.0f64, 1.0f64);
        for (p, q) in [
            (-dx, a[0] - w[0]),
            (dx, w[2] - a[0]),
            (-dy, a[1] - w[1]),
            (dy, w[3] - a[1]),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    (lo, hi) = (1.0, 0.0);
                }
            } else if p < 0.0 {
                lo = lo.max(q / p);
            } else {
                hi = hi.min(q / p);
            }
        }
        if lo > hi {
            open = false;
            continue;
        }
        let at = |t: f64| [a[0] + t * dx, a[1] + t * dy];
        if !open || lo > 0.0 {
            runs.push(vec![at(lo)]);
        }
        runs.last_mut().expect("a run").push(at(hi));
        open = hi >= 1.0;
    }
    runs
}
