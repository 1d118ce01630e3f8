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

use super::claims::{Claim, Decls, Identity, IntRange, Kind, Sides, Theorem};
use super::context::Ctx;
use super::identity::Goal;
use super::kernel::checked::Verdict;
use super::kernel::expr::Expr;
use crate::error::Error;

/// The prefix of the note for a claim whose open-range version is proved.
pub const PROVABLE: &str = "also provable for every n: write";

/// The note for a claim with verdict `verdict`: for `proved_in_range`, why it stays bound to
/// its ranges, or that (and how) it is provable for every n; `None` for every other verdict.
pub fn range_bound(claim: &Claim, verdict: Verdict) -> Option<String> {
    (verdict == Verdict::ProvedInRange).then(|| match super::kinds::elaborate(claim) {
        Ok(ctx) => reason(claim, &ctx),
        Err(e) => readable(&e),
    })
}

/// [`range_bound`] for a claim already elaborated (`ctx`, its context).
pub(crate) fn range_bound_in(claim: &Claim, ctx: &Ctx<'_>, verdict: Verdict) -> Option<String> {
    (verdict == Verdict::ProvedInRange).then(|| reason(claim, ctx))
}

fn reason(claim: &Claim, ctx: &Ctx<'_>) -> String {
    if let Kind::Theorem(t) = &claim.kind {
        return theorem_reason(ctx, t);
    }
    let Some(identity) = claim.kind.identity() else {
        return format!(
            "kind `{}` is checked case by case; the symbolic route takes identity claims",
            claim.kind.name()
        );
    };
    let decls = &claim.decls;
    if decls.symbolic() {
        return "it expands symbols or vectors exactly, which the symbolic route does not take".into();
    }
    if decls.curves.is_some() || decls.surfaces.is_some() {
        return "it uses concrete curves or surfaces, evaluated per degree".into();
    }
    let goal = Goal {
        ctx: ctx.clone(),
        identity: identity.into_owned(),
    };
    let objects = library_objects(&goal);
    if !objects.is_empty() {
        return format!(
            "uses {}: library code evaluated per degree, not a formula in n (a proof for every n reads a polygon's objects only through lemmas the claim cites, `uses`)",
            listed(&objects)
        );
    }
    let (ranges, written) = open_ranges(&goal);
    if written.is_empty() {
        return "no range with a constant upper bound to open".into();
    }
    let outcome = match goal.ctx.with_ranges(ranges) {
        Ok(ctx) => {
            let opened = Goal { ctx, ..goal };
            attempt(&opened).map_err(|(k, e)| (step(&opened, k), e))
        }
        Err(e) => Err((String::new(), e)),
    };
    match outcome {
        Ok(ranges) => format!("{PROVABLE} {}", quoted(&ranges)),
        Err((at, e)) => format!(
            "with {} the symbolic proof does not go through{at}: {}",
            written.join(", "),
            readable(&e)
        ),
    }
}

/// ` at equality 3 of 5 (`a = b`)` for a chain of more than two sides, else empty.
fn step(goal: &Goal<'_>, k: usize) -> String {
    match &goal.identity.sides {
        Sides::Chain(chain) if chain.len() > 2 => format!(
            " at equality {} of {} (`{} = {}`)",
            k + 1,
            chain.len() - 1,
            chain[k],
            chain[k + 1]
        ),
        _ => String::new(),
    }
}

/// The sides of equality `k` (the claim's `lhs`, `rhs`, or two neighbours of its chain).
fn sides(goal: &Goal<'_>, k: usize) -> Vec<String> {
    goal.identity.sides.members().into_iter().skip(k).take(2).collect()
}

/// The symbolic proof of each equality of a goal with open ranges, in order: the index of
/// the first that does not go through, with the reason.
fn attempt_equalities(goal: &Goal<'_>) -> Result<(), (usize, Error)> {
    let attempt = |identity: &Identity| super::symbolic::attempt_for_every(&goal.ctx, identity);
    match &goal.identity.sides {
        Sides::Chain(chain) if chain.len() > 2 => {
            for (k, pair) in chain.windows(2).enumerate() {
                let step = Identity {
                    sides: Sides::Chain(pair.to_vec()),
                    certificates: goal.identity.certificates.clone(),
                    induction: None,
                };
                attempt(&step).map_err(|e| (k, e))?;
            }
            Ok(())
        }
        _ => attempt(&goal.identity).map(|_| ()).map_err(|e| (0, e)),
    }
}

/// The symbolic proof of a goal with open ranges, as written or — when the equality that
/// stops it has a sum starting at a variable bounded by an open one — with its ranges
/// reordered ([`reordered`]): `Ok` with the ranges that work, else the first failing
/// equality and the reason.
fn attempt(goal: &Goal<'_>) -> Result<Vec<IntRange>, (usize, Error)> {
    let written = &goal.ctx.decls.ranges;
    let (k, first) = match attempt_equalities(goal) {
        Ok(()) => return Ok(written.clone()),
        Err(failed) => failed,
    };
    if let Some((rs, v)) = reordered(written) {
        if sums_from(goal, &sides(goal, k), &v) {
            if let Ok(ctx) = goal.ctx.with_ranges(rs.clone()) {
                let again = Goal {
                    ctx,
                    identity: goal.identity.clone(),
                };
                if attempt_equalities(&again).is_ok() {
                    return Ok(rs);
                }
            }
        }
    }
    Err((k, first))
}

/// Whether one of `texts` has a sum whose lower bound uses the variable `v`.
fn sums_from(goal: &Goal<'_>, texts: &[String], v: &str) -> bool {
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
    // The sides parse alike over any bounds of the same range variables.
    texts.iter().any(|t| goal.ctx.expr(t).is_ok_and(|e| walk(&e, v)))
}

/// `n = c..`, `j = a..=n` (constants, `c ≤ a`) written as `j = a..`, `n = j..`: the same
/// integer points, with the open variable of a sum's bound first (the WZ induction needs the
/// lower bound of its sum free of the induction variable). `None` when no range has that shape.
fn reordered(ranges: &[IntRange]) -> Option<(Vec<IntRange>, String)> {
    let int = |t: &str| t.parse::<i64>().ok();
    for (k, r) in ranges.iter().enumerate() {
        let Some(w) = &r.to else { continue };
        let Some(pos) = ranges.iter().position(|x| &x.var == w && x.is_open()) else {
            continue;
        };
        let (Some(c), Some(a0)) = (int(&ranges[pos].from), int(&r.from)) else {
            continue;
        };
        if pos > k || c > a0 {
            continue;
        }
        let mut out: Vec<IntRange> = Vec::new();
        for (i, x) in ranges.iter().enumerate() {
            if i == pos {
                out.push(IntRange {
                    var: r.var.clone(),
                    from: r.from.clone(),
                    to: None,
                });
                out.push(IntRange {
                    var: w.clone(),
                    from: r.var.clone(),
                    to: None,
                });
            } else if i != k {
                out.push(x.clone());
            }
        }
        return Some((out, r.var.clone()));
    }
    None
}

fn quoted(ranges: &[IntRange]) -> String {
    ranges.iter().map(|r| format!("`{r}`")).collect::<Vec<_>>().join(", ")
}

/// A theorem claim stays in its `degrees` (a theorem takes no open range); the note says
/// whether that is all that binds it, or the library code it runs.
fn theorem_reason(ctx: &Ctx<'_>, theorem: &Theorem) -> String {
    let name = theorem.theorem.as_str();
    let head = format!("a theorem claim (`{name}`), checked for each degree of its `degrees`");
    let Some(parts) = super::theorems::identities(name) else {
        let what = super::theorems::THEOREMS
            .iter()
            .find(|(n, _)| *n == name)
            .map_or("", |(_, w)| *w);
        return format!("{head} by code of its own ({what}), not a formula in n");
    };
    let lo = theorem
        .degrees
        .as_deref()
        .and_then(|d| d.split("..").next())
        .and_then(|d| d.trim().parse::<i64>().ok())
        .unwrap_or(0);
    let mut objects: Vec<(String, String)> = Vec::new();
    let mut formulas = Vec::new();
    for (min_n, ranges, chain, vars) in parts {
        let part = super::theorems::part_decls(format!("n = {}..", lo.max(min_n)), &ranges, &vars);
        let Ok(part) = part.and_then(|decls| ctx.with_declarations(decls)) else {
            continue;
        };
        let mut goal = Goal {
            ctx: part,
            identity: Identity {
                sides: Sides::Chain(chain),
                certificates: Vec::new(),
                induction: None,
            },
        };
        let used = objects_of(&goal);
        if used.is_empty() {
            // Without control points the identity is over no polygon (a polygon's degree
            // would bound `n` from below by its symbolic index).
            if !goal.identity.sides.members().iter().any(|e| e.contains("b[")) {
                let without = Decls {
                    polygon: None,
                    ..Decls::clone(&goal.ctx.decls)
                };
                if let Ok(ctx) = ctx.with_declarations(without) {
                    goal = Goal { ctx, ..goal };
                }
            }
            formulas.push(goal);
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
    for g in &formulas {
        let (ranges, _) = open_ranges(g);
        let outcome = g.ctx.with_ranges(ranges.clone()).map_err(|e| (0, e)).and_then(|ctx| {
            attempt(&Goal {
                ctx,
                identity: g.identity.clone(),
            })
        });
        match outcome {
            Ok(rs) => forms.push(quoted(&rs)),
            Err((_, e)) => {
                return format!(
                    "{head}; written as an identity claim with {} the symbolic proof does not go through: {}",
                    quoted(&ranges),
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
fn open_range(r: &IntRange) -> IntRange {
    match &r.to {
        Some(to) if is_constant(to) => IntRange { to: None, ..r.clone() },
        _ => r.clone(),
    }
}

/// The ranges of the goal with each constant upper bound dropped, and the opened ranges as
/// written (`n = 0..`).
fn open_ranges(goal: &Goal<'_>) -> (Vec<IntRange>, Vec<String>) {
    let mut written = Vec::new();
    let ranges = goal
        .ctx
        .decls
        .ranges
        .iter()
        .map(|r| {
            let open = open_range(r);
            if open != *r {
                written.push(format!("`{open}`"));
            }
            open
        })
        .collect();
    (ranges, written)
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
    super::parse::parse(bound, &[])
        .and_then(|e| super::kernel::expr::eval_int(&e, &Default::default()))
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

/// The library objects and operations the goal's expressions use, each once, described.
fn library_objects(goal: &Goal<'_>) -> Vec<String> {
    describe(&objects_of(goal))
}

/// The `(phrase, name)` of each library object the goal's expressions use.
fn objects_of(goal: &Goal<'_>) -> Vec<(String, String)> {
    let mut found = Vec::new();
    for t in goal.identity.sides.members() {
        if let Ok(e) = goal.ctx.expr(&t) {
            objects_in(&goal.ctx.decls, &e, &mut found);
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
fn objects_in(decls: &Decls, e: &Expr, out: &mut Vec<(String, String)>) {
    let mut add = |what: &str, name: String| {
        let item = (what.to_string(), name);
        if !out.contains(&item) {
            out.push(item);
        }
    };
    let polygon = decls.polygon.as_ref().map(|p| p.name.as_str());
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
            } else if name == "delta" {
                add("the forward differences {}", name.clone());
            } else if let Some(what) = operation(name) {
                add(what, name.clone());
            }
            for a in args {
                objects_in(decls, a, out);
            }
        }
        Expr::Sum(_, a, b, body) => {
            objects_in(decls, a, out);
            objects_in(decls, b, out);
            objects_in(decls, body, out);
        }
        Expr::Neg(a) | Expr::Fact(a) => objects_in(decls, a, out),
        Expr::Bin(_, a, b) => {
            objects_in(decls, a, out);
            objects_in(decls, b, out);
        }
        Expr::Index(_, args) | Expr::Tuple(args) => {
            for a in args {
                objects_in(decls, a, out);
            }
        }
        Expr::Matrix(rows) => {
            for a in rows.iter().flatten() {
                objects_in(decls, a, out);
            }
        }
        Expr::Num(_) | Expr::Var(_) => {}
    }
}
