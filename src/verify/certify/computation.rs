//! Certificates of proofs by a library computation (`docs/certificates.md`, method
//! `computation`): each computation's inputs and result. Written for the conic types (the
//! type of an implicit conic from its equation, of a rational quadratic from its weights,
//! exact rationals or `a + b√d`), for text 004's cubic fit ([`fit`]), and for the convex hull
//! and the affine invariance of text 000 as facts resting on cited lemmas ([`hull`]).
//!
//! The re-check runs the named library computation again on the file's inputs and compares
//! its result with the file's; the verdict still rests on that computation (`rests_on`), as the
//! proof did. For an implicit conic the coefficients are derived again from the equation; for
//! a fit the normal equations are checked solved exactly by the listed `k, l`.

use super::sqrt::{number, number_json};
use super::{array, field, not_self_contained, rational, string, Res};
use crate::conic::{classify_conic, ConicKind, ImplicitConic};
use crate::point::Point;
use crate::quadratic::QuadraticIrrational;
use crate::rational::RationalBezierCurve;

use crate::verify::kernel::check_computed;
use crate::verify::kernel::Trusted;
use crate::verify::kinds::conic_coefficients;
use crate::verify::outcome::Computed;
use crate::verify::parse::parse;
use num_rational::BigRational;
use serde_json::{json, Map, Value as Json};

mod fit;
mod hull;

pub(super) fn strings(v: &[BigRational]) -> Vec<String> {
    v.iter().map(ToString::to_string).collect()
}

const XY: [&str; 2] = ["x", "y"];

/// The `computation` data of a proof's library computations, or why it cannot be written.
pub(super) fn fields(computed: &[Computed], out: &mut Map<String, Json>) -> Res<()> {
    if computed.is_empty() {
        return Err("method computation: this version records no data for it (not done)".into());
    }
    let known: Vec<String> = XY.iter().map(|v| v.to_string()).collect();
    let (mut facts, mut lemmas) = (Vec::new(), Vec::new());
    for c in computed {
        if let Some((fact, cited)) = hull::fact(c) {
            facts.push(fact);
            lemmas.extend(cited);
            continue;
        }
        facts.push(match c {
            Computed::ConicKind {
                lhs,
                rhs,
                coefficients,
                kind,
            } => {
                let (l, r) = (lhs.to_string(), rhs.to_string());
                for side in [&l, &r] {
                    if let Some(why) = not_self_contained(side, &known, &[]) {
                        return Err(format!("the equation uses {why}"));
                    }
                }
                json!({"computation": Trusted::ConicKind.name(), "lhs": l, "rhs": r,
                       "coefficients": strings(coefficients), "kind": kind})
            }
            Computed::WeightType { points, weights, kind } => {
                let points: Vec<Vec<Json>> = points.iter().map(|p| p.iter().map(number_json).collect()).collect();
                let weights: Vec<Json> = weights.iter().map(number_json).collect();
                json!({"computation": Trusted::ClassifyConic.name(), "points": points,
                       "weights": weights, "kind": kind})
            }
            Computed::CubicFit { .. } => fit::fact(c)?,
            Computed::Convergence { .. } => return Err("bounded evidence is not a computation's fact".into()),
            Computed::ConvexHull { .. } | Computed::AffineInvariance { .. } => {
                return Err("a fact resting on lemmas is written above".into())
            }
        });
    }
    out.insert("computation".into(), json!({ "facts": facts }));
    if !lemmas.is_empty() {
        out.insert("lemmas".into(), Json::Array(lemmas));
    }
    Ok(())
}

pub(super) fn rationals(v: &Json, at: &str) -> Res<Vec<BigRational>> {
    let list = v.as_array().ok_or_else(|| format!("{at}: not a list"))?;
    list.iter()
        .enumerate()
        .map(|(i, x)| {
            let s = x.as_str().ok_or_else(|| format!("{at}[{i}]: not a string"))?;
            rational(s).map_err(|e| format!("{at}[{i}]: {e}"))
        })
        .collect()
}

/// The type of a rational quadratic with these control points and weights, by the library.
fn weight_type(fact: &Json, at: &str) -> Res<String> {
    let mut points = Vec::new();
    for (i, p) in array(fact, "points", at)?.iter().enumerate() {
        let at = format!("{at}.points[{i}]");
        let list = p.as_array().ok_or_else(|| format!("{at}: not a list"))?;
        let coords = list
            .iter()
            .enumerate()
            .map(|(j, x)| number(x, &format!("{at}[{j}]")))
            .collect::<Res<Vec<_>>>()?;
        points.push(coords);
    }
    let weights = array(fact, "weights", at)?
        .iter()
        .enumerate()
        .map(|(j, x)| number(x, &format!("{at}.weights[{j}]")))
        .collect::<Res<Vec<_>>>()?;
    // One real field Q(√d): a control point or weight of another field, or a non-real one,
    // is not a real conic's data (the library's arithmetic would poison, not refuse, it).
    let mut fields = points
        .iter()
        .flatten()
        .chain(&weights)
        .filter_map(QuadraticIrrational::radicand);
    if let Some(d) = fields.next() {
        if d < 0 {
            return Err(format!("{at}: √{d} is not real"));
        }
        if let Some(e) = fields.find(|&e| e != d) {
            return Err(format!("{at}: numbers of two fields, √{d} and √{e}"));
        }
    }
    let all: Option<Vec<Vec<BigRational>>> = points
        .iter()
        .chain(std::iter::once(&weights))
        .map(|p| p.iter().map(QuadraticIrrational::to_rational).collect())
        .collect();
    let kind = match all {
        // Exact rationals: the library's rational arithmetic, as `prove` ran it.
        Some(mut r) => {
            let w = r.pop().unwrap_or_default();
            classified(r, w, at)?
        }
        None => classified(points, weights, at)?,
    };
    Ok(kind.as_str().to_string())
}

/// The library's type of the rational quadratic on `points` with `weights`, in `T`.
fn classified<T: crate::scalar::Scalar>(points: Vec<Vec<T>>, weights: Vec<T>, at: &str) -> Res<ConicKind> {
    let points = points
        .into_iter()
        .enumerate()
        .map(|(i, c)| Point::new(c).map_err(|e| format!("{at}.points[{i}]: {e}")))
        .collect::<Res<Vec<_>>>()?;
    let curve = RationalBezierCurve::new(points, weights).map_err(|e| format!("{at}: {e}"))?;
    classify_conic(&curve).map_err(|e| format!("{at}: {e}"))
}

/// One fact computed again: the library computation it rests on, once its result is the
/// file's (an error names the first difference).
fn recompute(fact: &Json, at: &str) -> Res<Trusted> {
    let (trusted, computed) = match string(fact, "computation", at)? {
        "ImplicitConic::kind" => {
            let known: Vec<String> = XY.iter().map(|v| v.to_string()).collect();
            let side = |k: &str| parse(string(fact, k, at)?, &known).map_err(|e| format!("{at}.{k}: {e}"));
            let (l, r) = (side("lhs")?, side("rhs")?);
            for v in l.free_vars().into_iter().chain(r.free_vars()) {
                if !known.contains(&v) {
                    return Err(format!("{at}: the equation names '{v}', not x or y"));
                }
            }
            let coef = conic_coefficients(&l, &r).map_err(|e| format!("{at}: {e}"))?;
            let listed = rationals(field(fact, "coefficients", at)?, &format!("{at}.coefficients"))?;
            if listed != coef {
                return Err(format!(
                    "{at}.coefficients: ({}), the equation's are ({})",
                    strings(&listed).join(", "),
                    strings(&coef).join(", ")
                ));
            }
            let kind = ImplicitConic::from_coefficients(coef).kind().family().to_string();
            (Trusted::ConicKind, kind)
        }
        "classify_conic" => (Trusted::ClassifyConic, weight_type(fact, at)?),
        "fit_cubic" => return fit::recheck(fact, at).map(|()| Trusted::CubicFit),
        other => return Err(format!("{at}.computation: '{other}' records no data in this version")),
    };
    let said = string(fact, "kind", at)?;
    if computed != said {
        return Err(format!(
            "{at}: {} gives '{computed}', the file says '{said}'",
            trusted.name()
        ));
    }
    Ok(trusted)
}

/// Re-checks a `computation` certificate: every listed computation run again on its inputs
/// gives the listed result, and the file's `rests_on` names it; the proof is the kernel's
/// `check_computed` on those facts.
pub(super) fn recheck(cert: &Json, method: &str) -> Res<String> {
    if method != "computation" {
        return Err(format!("method: the file says {method}, the data is computation"));
    }
    let c = field(cert, "computation", "certificate")?;
    let facts = array(c, "facts", "computation")?;
    if facts.is_empty() {
        return Err("computation.facts: none".into());
    }
    let rests: Vec<&str> = array(cert, "rests_on", "certificate")?
        .iter()
        .filter_map(Json::as_str)
        .collect();
    let lemmas = super::hyper::lemmas(cert)?;
    let (mut trusted, mut holds, mut from_lemmas) = (Vec::new(), Vec::new(), Vec::new());
    for (i, fact) in facts.iter().enumerate() {
        let at = format!("computation.facts[{i}]");
        let ts = match hull::recheck(fact, &at, &lemmas)? {
            Some((ts, argument)) => {
                from_lemmas.push(argument);
                ts
            }
            None => vec![recompute(fact, &at)?],
        };
        for t in ts {
            if !rests.contains(&t.name()) {
                return Err(format!(
                    "rests_on: the proof rests on {}, the file does not say so",
                    t.name()
                ));
            }
            trusted.push(t);
        }
        holds.push(true);
    }
    let proof = check_computed(&holds, &trusted).ok_or("the kernel refuses the computation")?;
    let names: Vec<&str> = proof.rests_on().iter().map(|t| t.name()).collect();
    if !from_lemmas.is_empty() {
        let others = match facts.len() - from_lemmas.len() {
            0 => String::new(),
            k => format!(", {k} other library computations run again"),
        };
        return Ok(format!(
            "from the cited lemmas' goals: {}{others}; rests on {}",
            from_lemmas.join("; "),
            names.join(", ")
        ));
    }
    Ok(format!(
        "{} library computations run again on the file's inputs, with the file's results; rests on {}",
        facts.len(),
        names.join(", ")
    ))
}
