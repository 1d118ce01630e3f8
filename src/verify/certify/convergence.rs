//! The bounded evidence of Theorem 1.2 (`verified`, `docs/certificates.md` "Verdict
//! `verified`"): each curve's control points and its exact max-norm distances between the
//! `r`-times elevated polygon and the curve at `i/(n + r)`, for `r = 0..=steps`.
//!
//! The re-check elevates and evaluates again with the library (as `prove` did) and the kernel
//! checks the listed distances are the computed ones, never increase and stay within the
//! bound `n(n−1)/(2(n+r))·max_j|Δ²b_j|_∞`. That is evidence for the limit, not a proof of it:
//! the verdict stays `verified`.

use super::computation::{rationals, strings};
use super::{array, field, string, Res};
use crate::curve::BezierCurve;
use crate::point::Point;
use crate::verify::kernel::certificate::recheck_bounded;
use crate::verify::outcome::Computed;
use crate::verify::theorems::elevation_bound;
use serde_json::{json, Map, Value as Json};

/// Most elevation steps a file may ask for (as a claim may).
const MAX_STEPS: u64 = 512;

/// The `convergence` data of bounded evidence, or why it has none.
pub(super) fn fields(computed: &[Computed], out: &mut Map<String, Json>) -> Res<()> {
    let Some(Computed::Convergence { steps, curves }) = computed.first() else {
        return Err("bounded evidence, not a proof: no data in this version".into());
    };
    let curves: Vec<Json> = curves
        .iter()
        .map(|(name, points, distances)| {
            let points: Vec<Vec<String>> = points.iter().map(|p| strings(p)).collect();
            json!({"name": name, "points": points, "distances": strings(distances)})
        })
        .collect();
    out.insert("convergence".into(), json!({"steps": steps, "curves": curves}));
    Ok(())
}

/// Re-checks the bounded evidence of a `verified` file; what was re-checked.
pub(super) fn recheck(cert: &Json) -> Res<String> {
    let c = field(cert, "convergence", "certificate")?;
    let steps = field(c, "steps", "convergence")?
        .as_u64()
        .filter(|&s| s <= MAX_STEPS)
        .ok_or_else(|| format!("convergence.steps: not an integer 0..={MAX_STEPS}"))?;
    let curves = array(c, "curves", "convergence")?;
    if curves.is_empty() {
        return Err("convergence.curves: none".into());
    }
    let mut names = Vec::new();
    for (i, entry) in curves.iter().enumerate() {
        let at = format!("convergence.curves[{i}]");
        names.push(string(entry, "name", &at)?.to_string());
        let mut points = Vec::new();
        for (j, p) in array(entry, "points", &at)?.iter().enumerate() {
            let coords = rationals(p, &format!("{at}.points[{j}]"))?;
            points.push(Point::new(coords).map_err(|e| format!("{at}.points[{j}]: {e}"))?);
        }
        let curve = BezierCurve::new(points).map_err(|e| format!("{at}: {e}"))?;
        let listed = rationals(field(entry, "distances", &at)?, &format!("{at}.distances"))?;
        let computed = curve
            .elevation_distances(steps as usize)
            .map_err(|e| format!("{at}: {e}"))?;
        let distances: Vec<_> = computed.into_iter().map(|d| d.max_norm).collect();
        let bounds = (0..=steps as usize)
            .map(|r| elevation_bound(&curve, r))
            .collect::<crate::error::Result<Vec<_>>>()
            .map_err(|e| format!("{at}: {e}"))?;
        recheck_bounded(&listed, &distances, &bounds).map_err(|e| format!("{at}: {e}"))?;
    }
    Ok(format!(
        "verified (bounded evidence, not a proof of the limit): {} ({}), r = 0..={steps}: the distances computed again \
         are the listed ones, never increase and stay within n(n−1)/(2(n+r))·max|Δ²b|",
        names.len(),
        names.join(", ")
    ))
}
