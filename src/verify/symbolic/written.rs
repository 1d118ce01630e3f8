//! The goal of a for-every proof written as data (`docs/certificates.md`, method `pieces`):
//! the chain the translation into hypergeometric terms read, over the claim's ranges, with
//! its polygon or net and its WZ certificates, so that `casteljau check` can translate it
//! again and run the same kernel checks (and, as `prove` does, evaluate its first values).
//! A goal that rests on lemmas or on assumptions
//! beyond its ranges is not written (not done in this version).

use super::super::claims::Decls;
use super::super::context::Ctx;
use super::super::identity::check_identity;
use super::super::kernel::certificate::Symbolic;
use super::super::kernel::checked::Verdict;
use super::super::kernel::expr::Expr;
use super::super::lemma::Rewritten;
use super::prove_sides;
use crate::error::{Error, Result};
use std::borrow::Cow;

/// The written goal of a proof of `rewritten` in `ctx` (the claim's open ranges), or `None`
/// when it rests on more than its own text.
pub(super) fn written(ctx: &Ctx<'_>, rewritten: &Rewritten, certificates: &[String]) -> Option<Symbolic> {
    let r = rewritten;
    if !r.lemmas.is_empty() || !r.assumptions.is_empty() || !r.obligations.is_empty() {
        return None;
    }
    let d = &ctx.decls;
    let ints: Vec<&str> = d.ranges.iter().map(|r| r.var.as_str()).collect();
    let refs: Vec<&Expr> = r.sides.iter().collect();
    let reals = ctx
        .params(&refs)
        .into_iter()
        .filter(|v| !ints.contains(&v.as_str()))
        .collect();
    Some(Symbolic {
        reals,
        for_all: d
            .ranges
            .iter()
            .map(|r| (r.var.clone(), r.from.clone(), r.to.clone()))
            .collect(),
        polygon: d.polygon.as_ref().map(|p| (p.name.clone(), p.degree.clone())),
        net: d.net.as_ref().map(|n| (n.name.clone(), n.degree.clone())),
        members: r.sides.iter().map(ToString::to_string).collect(),
        certificates: certificates.to_vec(),
    })
}

/// The declarations a written goal's text is read in: its ranges, parameters, polygon or net.
pub(crate) fn declarations(goal: &Symbolic) -> Decls {
    Decls {
        vars: Some(goal.reals.clone()),
        ranges: goal
            .for_all
            .iter()
            .map(|(var, from, to)| super::super::claims::IntRange {
                var: var.clone(),
                from: from.clone(),
                to: to.clone(),
            })
            .collect(),
        polygon: goal
            .polygon
            .as_ref()
            .map(|(name, degree)| super::super::claims::PolygonSpec {
                name: name.clone(),
                degree: degree.clone(),
            }),
        net: goal.net.as_ref().map(|(name, degree)| super::super::claims::NetSpec {
            name: name.clone(),
            degree: degree.clone(),
        }),
        ..Decls::default()
    }
}

/// Translates a written goal again and proves it by the same kernel checks as `prove` did:
/// the kernel's method and the number of checks it passed (each obligation of the pieces, a
/// WZ evaluation with its own obligations). The members must print back
/// to their text.
pub(crate) fn prove_written(goal: &Symbolic) -> Result<(super::Method, usize)> {
    let decls = declarations(goal);
    let ctx = Ctx::new("certificate", Cow::Borrowed(&decls), Vec::new())?;
    let mut sides = Vec::with_capacity(goal.members.len());
    for m in &goal.members {
        let e = ctx.expr(m)?;
        if &e.to_string() != m {
            return Err(Error::Parse(format!("'{m}' does not print back to itself")));
        }
        sides.push(e);
    }
    // As `prove` does: the first values evaluated, so a goal `prove` would refuse (a range
    // empty at some value, a polygon of negative degree) or that fails there is refused.
    let closed = ctx.closed_after(super::CROSS_CHECK)?;
    let first = check_identity(&closed, &goal.members, false)?;
    if first.verdict() != Verdict::ProvedInRange {
        return Err(Error::Domain(format!(
            "the first values of the ranges: {} ({})",
            first.verdict().as_str(),
            first.certificate
        )));
    }
    let rewritten = Rewritten {
        sides,
        ..Rewritten::default()
    };
    let (_, _, method, evidence) = prove_sides(&decls, &ctx, rewritten, &goal.certificates)?;
    let proof = super::check_discharged(method, &evidence)
        .ok_or_else(|| Error::Domain(format!("the kernel refuses a for-every proof by {method:?}")))?;
    Ok((proof.method(), evidence.len()))
}
