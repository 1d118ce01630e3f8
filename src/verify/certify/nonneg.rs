//! Certificates of inequalities for every value (`docs/certificates.md`, "Inequalities for
//! every value"): the goal `lhs >= rhs` (or `<=`) over integer ranges and an interval of its
//! one real symbol, and the nonnegativity obligation of every live term on every piece of the
//! domain (each factor, why it is ≥ 0, the Bernstein coefficients of a polynomial factor).
//! The re-check proves the goal again by the kernel's own check (`inequality::check_for_every`,
//! as `prove` does: the first values evaluated, then `check_nonneg_pieces`) and accepts the
//! file only when the obligations it lists are the kernel's, exactly.

use super::super::claims::{Decls, Inequality, IntRange, Number, Relation};
use super::super::context::Ctx;
use super::super::kernel::certificate::Data;
use super::super::kernel::checked::{Method, Verdict};
use super::super::kernel::nonneg::{check_record, Factor, LiveTerm, Nonneg, NonnegGoal, Piece};
use super::{array, field, method_name, not_self_contained, rational, string, Res};
use serde_json::{json, Map, Value as Json};
use std::borrow::Cow;

/// The goal of a for-every inequality as a certificate writes it.
pub(super) fn goal_json(g: &NonnegGoal) -> Json {
    let mut symbols = vec![json!({"name": g.real, "sort": "real"})];
    symbols.extend(g.for_all.iter().map(|(n, ..)| json!({"name": n, "sort": "integer"})));
    let for_all: Vec<Json> = g
        .for_all
        .iter()
        .map(|(n, from, to)| json!({"name": n, "from": from, "to": to}))
        .collect();
    json!({"relation": ">=", "symbols": symbols, "for_all": for_all,
           "interval": {"name": g.real, "from": g.interval.0.to_string(), "to": g.interval.1.to_string()},
           "inequality": {"lhs": g.lhs, "rhs": g.rhs}})
}

fn factor_json(f: &Factor) -> Json {
    let mut out = json!({"factor": f.factor, "why": f.why.name(), "bernstein": super::strings(&f.bernstein)});
    if let Some(e) = &f.exponent {
        out["exponent"] = json!(e);
    }
    out
}

fn pieces_json(pieces: &[Piece]) -> Json {
    let list: Vec<Json> = pieces
        .iter()
        .map(|p| {
            let terms: Vec<Json> = p
                .terms
                .iter()
                .map(|t: &LiveTerm| {
                    json!({"term": t.term, "coefficient": factor_json(&t.coefficient),
                           "factorials": t.factorials,
                           "powers": t.powers.iter().map(factor_json).collect::<Vec<_>>()})
                })
                .collect();
            json!({"region": p.region, "terms": terms})
        })
        .collect();
    Json::Array(list)
}

/// The goal and the `pieces` data of a for-every inequality, or why they cannot be written.
pub(super) fn fields(n: &Nonneg, out: &mut Map<String, Json>) -> Res<()> {
    let known: Vec<String> = std::iter::once(n.goal.real.clone())
        .chain(n.goal.for_all.iter().map(|r| r.0.clone()))
        .collect();
    for side in [&n.goal.lhs, &n.goal.rhs] {
        if let Some(why) = not_self_contained(side, &known, &[]) {
            return Err(format!("the goal uses {why}"));
        }
    }
    out.insert("goal".into(), goal_json(&n.goal));
    out.insert(
        "pieces".into(),
        json!({"certificates": [], "nonnegative": pieces_json(&n.pieces)}),
    );
    Ok(())
}

/// Whether a goal is an inequality's (its relation `>=` or `<=`).
pub(super) fn is_inequality(cert: &Json) -> bool {
    let relation = cert.get("goal").and_then(|g| g.get("relation")).and_then(Json::as_str);
    matches!(relation, Some(">=" | "<="))
}

/// Reads a for-every inequality's goal (`<=` read as its sides swapped); `whole` names it in
/// errors.
pub(super) fn read_goal(g: &Json, whole: &str) -> Res<NonnegGoal> {
    let swap = match string(g, "relation", whole)? {
        ">=" => false,
        "<=" => true,
        other => return Err(format!("{whole}.relation: '{other}' is not >= or <=")),
    };
    let (reals, ints) = super::hyper::read_symbols(g, whole)?;
    let iv = field(g, "interval", whole)?;
    let at = format!("{whole}.interval");
    let real = string(iv, "name", &at)?.to_string();
    if reals != [real.clone()] {
        return Err(format!("{at}.name: the goal's one real symbol is the interval's"));
    }
    let end = |k: &str| rational(string(iv, k, &at)?).map_err(|e| format!("{at}.{k}: {e}"));
    let (a, b) = (end("from")?, end("to")?);
    if a >= b {
        return Err(format!("{at}: [{a}, {b}] is empty or a point"));
    }
    let for_all = super::hyper::read_for_all(g, whole, &ints)?;
    let sides = field(g, "inequality", whole)?;
    let at = format!("{whole}.inequality");
    let (l, r) = (
        string(sides, "lhs", &at)?.to_string(),
        string(sides, "rhs", &at)?.to_string(),
    );
    let (lhs, rhs) = if swap { (r, l) } else { (l, r) };
    Ok(NonnegGoal {
        real,
        for_all,
        lhs,
        rhs,
        interval: (a, b),
    })
}

/// The first place where the file's obligations differ from the kernel's.
fn first_difference(file: &Json, derived: &Json) -> String {
    let (f, d) = (file.as_array(), derived.as_array());
    let (f, d) = (f.map_or(&[][..], Vec::as_slice), d.map_or(&[][..], Vec::as_slice));
    if f.len() != d.len() {
        return format!("{} pieces, the kernel's proof has {}", f.len(), d.len());
    }
    for (i, (x, y)) in f.iter().zip(d).enumerate() {
        let (tx, ty) = (
            x.get("terms").and_then(Json::as_array),
            y.get("terms").and_then(Json::as_array),
        );
        if x.get("region") != y.get("region") {
            return format!("piece {i}: the region is not the kernel's ({})", y["region"]);
        }
        match (tx, ty) {
            (Some(tx), Some(ty)) if tx.len() == ty.len() => {
                if let Some(k) = tx.iter().zip(ty).position(|(a, b)| a != b) {
                    return format!("piece {i}, term {k}: the kernel's obligation is {}", ty[k]);
                }
            }
            _ => return format!("piece {i}: the live terms are not the kernel's"),
        }
    }
    "the obligations differ".into()
}

/// Re-checks a for-every inequality: the goal proved again by the kernel's own check, whose
/// obligations must be the file's.
pub(super) fn recheck(cert: &Json, method: &str) -> Res<String> {
    let verdict = string(cert, "verdict", "certificate")?;
    if verdict != Verdict::Proved.as_str() {
        return Err("verdict: an inequality for every value is proved".into());
    }
    let goal = read_goal(field(cert, "goal", "certificate")?, "goal")?;
    let p = field(cert, "pieces", "certificate")?;
    if !array(p, "certificates", "pieces")?.is_empty() {
        return Err("pieces.certificates: an inequality's proof has no WZ certificate".into());
    }
    let listed = field(p, "nonnegative", "pieces")?;
    let decls = Decls {
        vars: Some(vec![goal.real.clone()]),
        ranges: goal
            .for_all
            .iter()
            .map(|(var, from, to)| IntRange {
                var: var.clone(),
                from: from.clone(),
                to: to.clone(),
            })
            .collect(),
        ..Decls::default()
    };
    let ctx = Ctx::new("certificate", Cow::Borrowed(&decls), Vec::new()).map_err(|e| format!("goal: {e}"))?;
    for side in [&goal.lhs, &goal.rhs] {
        let e = ctx.expr(side).map_err(|e| format!("goal.inequality: {e}"))?;
        if &e.to_string() != side {
            return Err(format!("goal.inequality: '{side}' does not print back to itself"));
        }
    }
    let ineq = Inequality {
        lhs: goal.lhs.clone(),
        rhs: Some(goal.rhs.clone()),
        relation: Relation::AtLeast,
        interval: Some([
            Number::Text(goal.interval.0.to_string()),
            Number::Text(goal.interval.1.to_string()),
        ]),
    };
    let checked = super::super::inequality::check_for_every(&ctx, &ineq, false)
        .map_err(|e| format!("the kernel's proof of the goal: {e}"))?;
    if checked.verdict() != Verdict::Proved {
        return Err(format!(
            "the goal is not proved: {} ({})",
            checked.verdict().as_str(),
            checked.certificate
        ));
    }
    let derived = method_name(checked.method().unwrap_or(Method::Pieces));
    if derived != method {
        return Err(format!(
            "method: the file says {method}, the kernel's proof is {derived}"
        ));
    }
    let Data::Nonneg(n) = checked.data() else {
        return Err("the kernel's proof records no obligations (a factor shown ≥ 0 only by halving)".into());
    };
    if n.goal != goal {
        return Err("goal: not the goal the kernel proved".into());
    }
    let mine = pieces_json(&n.pieces);
    if *listed != mine {
        return Err(format!("pieces.nonnegative: {}", first_difference(listed, &mine)));
    }
    if !check_record(&n.pieces) {
        return Err("pieces.nonnegative: a factor's Bernstein coefficients do not show its reason".into());
    }
    let terms: usize = n.pieces.iter().map(|p| p.terms.len()).sum();
    Ok(format!(
        "for every value of the open ranges: the inequality proved again on {} pieces, the {terms} live terms' nonnegativity obligations are the file's (Bernstein coefficients on [{}, {}])",
        n.pieces.len(),
        goal.interval.0,
        goal.interval.1
    ))
}
