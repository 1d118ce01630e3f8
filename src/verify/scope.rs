//! Why a claim proved over finite ranges stays range-bound, or that it need not.
//!
//! A `proved_in_range` claim over `for` ranges is tried once more on the symbolic route of
//! [`super::symbolic`] with every constant upper bound dropped (`n = 0..=6` becomes `n = 0..`;
//! a bound depending on an earlier variable, `i = 0..=n`, is kept). The claim's verdict never
//! changes: the claim file says which range it claims. The outcome is a one-line note, either
//! the reason the symbolic route does not apply (an object of the library, a kind it does not
//! take, the step where the proof stops) or that the claim is also provable for every n, with
//! the ranges to write.
//!
//! The attempt is the symbolic proof alone (no evaluation cross-check, no counterexample
//! search: the finite ranges were just checked), within the symbolic route's own limits, and
//! claims that use library objects are answered from their expressions without translating.

use super::claims::{Claim, PolygonSpec};
use super::engine::Ctx;
use super::expr::Expr;
use super::Verdict;
use crate::error::Error;

/// The prefix of the note for a claim whose open-range version is proved.
pub const PROVABLE: &str = "also provable for every n: write";

/// The note for a claim with verdict `verdict`: for `proved_in_range`, why it stays bound to
/// its ranges, or that (and how) it is provable for every n; `None` for every other verdict.
pub fn range_bound(claim: &Claim, verdict: Verdict) -> Option<String> {
    (verdict == Verdict::ProvedInRange).then(|| reason(claim))
}

fn reason(claim: &Claim) -> String {
    if claim.kind == "theorem" {
        return theorem_reason(claim);
    }
    if claim.kind != "identity" {
        return format!(
            "kind `{}` is checked case by case; the symbolic route takes identity claims",
            claim.kind
        );
    }
    if claim.symbols.is_some() || claim.vectors.is_some() {
        return "it expands symbols or vectors exactly, which the symbolic route does not take".into();
    }
    if claim.net.is_some() || claim.surfaces.is_some() {
        let objects = library_objects(claim);
        return format!(
            "a surface: the symbolic route takes a control polygon `b[j]`, not a control net `b[i, j]`{}",
            if objects.is_empty() {
                String::new()
            } else {
                format!("; it also uses {}", listed(&objects))
            }
        );
    }
    if claim.curves.is_some() {
        return "it uses concrete curves, evaluated per degree".into();
    }
    let objects = library_objects(claim);
    if !objects.is_empty() {
        return format!(
            "uses {}: library code evaluated per degree, not a formula in n",
            listed(&objects)
        );
    }
    let (opened, written) = open_ranges(claim);
    if written.is_empty() {
        return "no range with a constant upper bound to open".into();
    }
    match attempt(&opened) {
        Ok(ranges) => format!("{PROVABLE} {}", quoted(&ranges)),
        Err((k, e)) => format!(
            "with {} the symbolic proof does not go through{}: {}",
            written.join(", "),
            step(&opened, k),
            readable(&e)
        ),
    }
}

/// ` at equality 3 of 5 (`a = b`)` for a chain of more than two sides, else empty.
fn step(claim: &Claim, k: usize) -> String {
    match claim.chain.as_ref().filter(|c| c.len() > 2) {
        Some(chain) => format!(
            " at equality {} of {} (`{} = {}`)",
            k + 1,
            chain.len() - 1,
            chain[k],
            chain[k + 1]
        ),
        None => String::new(),
    }
}

/// The sides of equality `k` (the claim's `lhs`, `rhs`, or two neighbours of its chain).
fn sides(claim: &Claim, k: usize) -> Vec<String> {
    match &claim.chain {
        Some(chain) => chain.iter().skip(k).take(2).cloned().collect(),
        None => claim.lhs.iter().chain(&claim.rhs).cloned().collect(),
    }
}

/// The symbolic proof of each equality of a claim with open ranges, in order: the index of
/// the first that does not go through, with the reason.
fn attempt_equalities(claim: &Claim) -> Result<(), (usize, Error)> {
    match &claim.chain {
        Some(chain) if chain.len() > 2 => {
            for (k, pair) in chain.windows(2).enumerate() {
                let mut c = claim.clone();
                c.chain = Some(pair.to_vec());
                super::symbolic::attempt_for_every(&c).map_err(|e| (k, e))?;
            }
            Ok(())
        }
        _ => super::symbolic::attempt_for_every(claim)
            .map(|_| ())
            .map_err(|e| (0, e)),
    }
}

/// The symbolic proof of a claim with open ranges, as written or — when the equality that
/// stops it has a sum starting at a variable bounded by an open one — with its ranges
/// reordered ([`reordered`]): `Ok` with the ranges that work, else the first failing
/// equality and the reason.
fn attempt(claim: &Claim) -> Result<Vec<String>, (usize, Error)> {
    let written = claim.ranges.clone().unwrap_or_default();
    let (k, first) = match attempt_equalities(claim) {
        Ok(()) => return Ok(written),
        Err(failed) => failed,
    };
    if let Some((rs, v)) = reordered(&written) {
        if sums_from(claim, &sides(claim, k), &v) {
            let mut c = claim.clone();
            c.ranges = Some(rs.clone());
            if attempt_equalities(&c).is_ok() {
                return Ok(rs);
            }
        }
    }
    Err((k, first))
}

/// Whether one of `texts` has a sum whose lower bound uses the variable `v`.
fn sums_from(claim: &Claim, texts: &[String], v: &str) -> bool {
    fn walk(e: &Expr, v: &str) -> bool {
        match e {
            Expr::Sum(_, a, b, body) => a.free_vars().iter().any(|x| x == v) || walk(b, v) || walk(body, v),
            Expr::Neg(a) | Expr::Fact(a) => walk(a, v),
            Expr::Bin(_, a, b) => walk(a, v) || walk(b, v),
            Expr::Call(_, args) | Expr::Index(_, args) | Expr::Tuple(args) => args.iter().any(|a| walk(a, v)),
            Expr::Matrix(rows) => rows.iter().flatten().any(|a| walk(a, v)),
            Expr::Num(_) | Expr::Var(_) => false,
        }
    }
    let Some(ctx) = closed_ctx_claim(claim) else {
        return false;
    };
    let Ok(ctx) = Ctx::new(&ctx) else {
        return false;
    };
    texts.iter().any(|t| ctx.expr(t).is_ok_and(|e| walk(&e, v)))
}

/// The claim over finite ranges (the parser of expressions takes no open range).
fn closed_ctx_claim(claim: &Claim) -> Option<Claim> {
    let rs = super::symbolic::ranges(claim).ok()?;
    Some(super::symbolic::closed_claim(claim, &rs))
}

/// `n = c..`, `j = a..=n` (constants, `c ≤ a`) written as `j = a..`, `n = j..`: the same
/// integer points, with the open variable of a sum's bound first (the WZ induction needs the
/// lower bound of its sum free of the induction variable). `None` when no range has that shape.
fn reordered(ranges: &[String]) -> Option<(Vec<String>, String)> {
    let parse = |r: &str| -> Option<(String, String, Option<String>)> {
        let (v, rest) = r.split_once('=')?;
        let (v, rest) = (v.trim().to_string(), rest.trim());
        Some(match rest.split_once("..=") {
            Some((a, b)) => (v, a.trim().to_string(), Some(b.trim().to_string())),
            None => (v, rest.strip_suffix("..")?.trim().to_string(), None),
        })
    };
    let parsed: Vec<_> = ranges.iter().map(|r| parse(r)).collect::<Option<_>>()?;
    let int = |t: &str| t.parse::<i64>().ok();
    for (k, (v, a, b)) in parsed.iter().enumerate() {
        let Some(w) = b else { continue };
        let Some(pos) = parsed.iter().position(|(x, _, hi)| x == w && hi.is_none()) else {
            continue;
        };
        let (Some(c), Some(a0)) = (int(&parsed[pos].1), int(a)) else {
            continue;
        };
        if pos > k || c > a0 {
            continue;
        }
        let mut out: Vec<String> = Vec::new();
        for (i, r) in ranges.iter().enumerate() {
            if i == pos {
                out.push(format!("{v} = {a}.."));
                out.push(format!("{w} = {v}.."));
            } else if i != k {
                out.push(r.clone());
            }
        }
        return Some((out, v.clone()));
    }
    None
}

fn quoted(ranges: &[String]) -> String {
    ranges.iter().map(|r| format!("`{r}`")).collect::<Vec<_>>().join(", ")
}

/// A theorem claim stays in its `degrees` (a theorem takes no open range); the note says
/// whether that is all that binds it, or the library code it runs.
fn theorem_reason(claim: &Claim) -> String {
    let name = claim.theorem.as_deref().unwrap_or("?");
    let head = format!("a theorem claim (`{name}`), checked for each degree of its `degrees`");
    let Some(parts) = super::theorems::identities(name) else {
        let what = super::theorems::THEOREMS
            .iter()
            .find(|(n, _)| *n == name)
            .map_or("", |(_, w)| *w);
        return format!("{head} by code of its own ({what}), not a formula in n");
    };
    let lo = claim
        .degrees
        .as_deref()
        .and_then(|d| d.split("..").next())
        .and_then(|d| d.trim().parse::<i64>().ok())
        .unwrap_or(0);
    let mut objects: Vec<(String, String)> = Vec::new();
    let mut formulas = Vec::new();
    for (min_n, ranges, chain, vars) in parts {
        let mut c = claim.clone();
        c.kind = "identity".into();
        c.theorem = None;
        c.degrees = None;
        c.polygon = Some(PolygonSpec {
            name: "b".into(),
            degree: "n".into(),
        });
        c.vars = Some(vars.iter().map(|v| v.to_string()).collect());
        c.lhs = None;
        c.rhs = None;
        c.chain = Some(chain);
        let mut rs = vec![format!("n = {}..", lo.max(min_n))];
        rs.extend(ranges);
        c.ranges = Some(rs);
        let used = objects_of(&c);
        if used.is_empty() {
            // Without control points the identity is over no polygon (a polygon's degree
            // would bound `n` from below by its symbolic index).
            if !c.chain.iter().flatten().any(|e| e.contains("b[")) {
                c.polygon = None;
            }
            formulas.push(c);
        }
        for o in used {
            if !objects.contains(&o) {
                objects.push(o);
            }
        }
    }
    if !objects.is_empty() {
        return format!(
            "{head}; it uses {}: library code evaluated per degree, not a formula in n",
            listed(&describe(&objects))
        );
    }
    let mut forms = Vec::new();
    for c in &formulas {
        let (opened, _) = open_ranges(c);
        match attempt(&opened) {
            Ok(rs) => forms.push(quoted(&rs)),
            Err((_, e)) => {
                return format!(
                    "{head}; written as an identity claim with {} the symbolic proof does not go through: {}",
                    quoted(opened.ranges.as_deref().unwrap_or_default()),
                    readable(&e)
                )
            }
        }
    }
    format!(
        "{head}; its identity is a formula, also provable for every n as an identity claim with {}",
        forms.join("; ")
    )
}

/// A range with a constant upper bound written open.
fn open_text(r: &str) -> String {
    match r.split_once("..=") {
        Some((head, to)) if is_constant(to) => format!("{}..", head.trim_end()),
        _ => r.to_string(),
    }
}

/// The claim with each constant upper bound dropped, and the opened ranges as written
/// (`n = 0..`).
fn open_ranges(claim: &Claim) -> (Claim, Vec<String>) {
    let mut c = claim.clone();
    let mut written = Vec::new();
    c.ranges = claim.ranges.as_ref().map(|rs| {
        rs.iter()
            .map(|r| {
                let open = open_text(r);
                if open != *r {
                    written.push(format!("`{open}`"));
                }
                open
            })
            .collect()
    });
    (c, written)
}

/// What a library operation of expressions ([`super::methods`]) computes.
fn operation(name: &str) -> Option<&'static str> {
    Some(match name {
        "bsum" => "the Bernstein-sum evaluation {}",
        "elev" | "elevp" => "the degree elevation {}",
        "steps" => "the repeated degree elevation {}",
        "left" | "right" | "leftp" | "rightp" => "the subdivision {}",
        "deriv" | "derivp" => "the derivative {}",
        "vfirst" => "the v-first surface evaluation {}",
        "sbsum" => "the surface Bernstein sum {}",
        "isou" | "isov" => "the isoparametric curve {}",
        "bnd" => "the boundary curve {}",
        "corner" => "the corner point {}",
        _ => return None,
    })
}

/// `a`, `a and b`, `a, b and c`.
fn listed(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    }
}

/// Whether a range bound is a constant (`6`, not `n` or `n-r`).
fn is_constant(bound: &str) -> bool {
    super::expr::parse(bound, &[])
        .and_then(|e| super::expr::eval_int(&e, &Default::default()))
        .is_ok()
}

/// An error of the symbolic route as one readable clause.
fn readable(e: &Error) -> String {
    let text = match e {
        Error::Domain(s) | Error::Parse(s) => s.clone(),
        other => other.to_string(),
    };
    // The piece where an identity does not cancel runs to hundreds of characters; the
    // failing step is the readable part (proving the claim written open prints the piece).
    const STOP: &str = " does not hold as an identity";
    match text.find(STOP) {
        Some(at) => format!("{} on a piece of the domain", &text[..at + STOP.len()]),
        None => text,
    }
}

/// The library objects and operations the claim's expressions use, each once, described.
fn library_objects(claim: &Claim) -> Vec<String> {
    describe(&objects_of(claim))
}

/// The `(phrase, name)` of each library object the claim's expressions use.
fn objects_of(claim: &Claim) -> Vec<(String, String)> {
    let Some(closed) = closed_ctx_claim(claim) else {
        return Vec::new();
    };
    let Ok(ctx) = Ctx::new(&closed) else {
        return Vec::new();
    };
    let texts = claim.lhs.iter().chain(&claim.rhs).chain(claim.chain.iter().flatten());
    let mut found = Vec::new();
    for t in texts {
        if let Ok(e) = ctx.expr(t) {
            objects_in(claim, &e, &mut found);
        }
    }
    found
}

/// One phrase per kind of object: "the derivative `deriv` and `b'(t)`".
fn describe(found: &[(String, String)]) -> Vec<String> {
    let mut kinds: Vec<(&str, Vec<String>)> = Vec::new();
    for (what, name) in found {
        let name = format!("`{name}`");
        match kinds.iter_mut().find(|(w, _)| w == what) {
            Some((_, names)) if names.contains(&name) => {}
            Some((_, names)) => names.push(name),
            None => kinds.push((what, vec![name])),
        }
    }
    kinds
        .into_iter()
        .map(|(what, names)| what.replace("{}", &listed(&names)))
        .collect()
}

/// Collects `(phrase, name)` for each library object in `e`; `{}` in the phrase is where
/// the name goes.
fn objects_in(claim: &Claim, e: &Expr, out: &mut Vec<(String, String)>) {
    let mut add = |what: &str, name: String| {
        let item = (what.to_string(), name);
        if !out.contains(&item) {
            out.push(item);
        }
    };
    let polygon = claim.polygon.as_ref().map(|p| p.name.as_str());
    let net = claim.net.as_ref().map(|p| p.name.as_str());
    match e {
        Expr::Call(name, args) => {
            let base = name.trim_end_matches('\'');
            if Some(base) == polygon {
                match (args.len(), name.ends_with('\'')) {
                    (1, false) => add("the de Casteljau evaluation {}", format!("{name}(t)")),
                    (1, true) => add("the derivative {}", format!("{name}(t)")),
                    (3, _) => add(
                        "the points {} of the de Casteljau scheme (9)",
                        format!("{name}(i, r, t)"),
                    ),
                    _ => add("the library object {}", format!("{name}(…)")),
                }
            } else if Some(base) == net {
                add("the surface evaluation {}", format!("{name}(u, v)"));
            } else if name == "delta" {
                add("the forward differences {}", name.clone());
            } else if let Some(what) = operation(name) {
                add(what, name.clone());
            }
            for a in args {
                objects_in(claim, a, out);
            }
        }
        Expr::Sum(_, a, b, body) => {
            objects_in(claim, a, out);
            objects_in(claim, b, out);
            objects_in(claim, body, out);
        }
        Expr::Neg(a) | Expr::Fact(a) => objects_in(claim, a, out),
        Expr::Bin(_, a, b) => {
            objects_in(claim, a, out);
            objects_in(claim, b, out);
        }
        Expr::Index(_, args) | Expr::Tuple(args) => {
            for a in args {
                objects_in(claim, a, out);
            }
        }
        Expr::Matrix(rows) => {
            for a in rows.iter().flatten() {
                objects_in(claim, a, out);
            }
        }
        Expr::Num(_) | Expr::Var(_) => {}
    }
}
