//! The goal of a for-every proof written as data (`docs/certificates.md`, methods `pieces`,
//! `wz` and `induction`): the claim's chain as parsed (its objects not yet replaced), over the
//! claim's ranges, with its polygon or net, its WZ certificates, the induction variable and the
//! goals of the lemmas it cites, so that `casteljau check` can read the lemmas from those
//! goals, translate the goal again and run the same kernel checks (and, as `prove` does,
//! evaluate its first values). That each lemma's goal is proved is checked by `certify`
//! against the lemma's own file.

use super::super::claims::{Decls, Identity, Sides};
use super::super::context::Ctx;
use super::super::identity::check_identity;
use super::super::kernel::certificate::Symbolic;
use super::super::kernel::checked::Verdict;
use super::super::kernel::expr::Expr;
use super::super::lemma::{self, Lemma};
use super::prove_sides;
use crate::error::{Error, Result};
use std::borrow::Cow;

/// The written goal of a proof of `identity` in `ctx` (the claim's open ranges) with the
/// members `sides`, citing `lemmas`; `None` when a lemma's own goal was not written.
pub(super) fn written(ctx: &Ctx<'_>, sides: &[Expr], identity: &Identity, lemmas: &[Lemma]) -> Option<Symbolic> {
    let lemmas = lemmas
        .iter()
        .map(|l| l.statement.as_ref().map(|g| (l.id.clone(), (**g).clone())))
        .collect::<Option<Vec<_>>>()?;
    let d = &ctx.decls;
    let ints: Vec<&str> = d.ranges.iter().map(|r| r.var.as_str()).collect();
    let refs: Vec<&Expr> = sides.iter().collect();
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
        members: sides.iter().map(ToString::to_string).collect(),
        certificates: identity.certificates.clone(),
        lemmas,
        induction: identity.induction.clone(),
    })
}

/// A cited lemma's goal as its own certificate writes it: the statement alone.
pub(crate) fn statement(goal: &Symbolic) -> Symbolic {
    Symbolic {
        certificates: Vec::new(),
        lemmas: Vec::new(),
        induction: None,
        ..goal.clone()
    }
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

/// Translates a written goal again and proves it by the same kernel checks as `prove` did,
/// the lemmas read from their goals (assumed here): the kernel's method and the number of
/// checks it passed (each obligation of the pieces, a WZ evaluation with its own obligations;
/// the base's and the step's for an induction). The members must print back to their text.
pub(crate) fn prove_written(goal: &Symbolic) -> Result<(super::Method, usize)> {
    let decls = declarations(goal);
    let ctx = Ctx::new("certificate", Cow::Borrowed(&decls), Vec::new())?;
    let sides = parsed(&ctx, &goal.members)?;
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
    let lemmas: Vec<Lemma> = goal
        .lemmas
        .iter()
        .map(|(id, g)| read_lemma(id, g))
        .collect::<Result<_>>()?;
    let refused = |m| Error::Domain(format!("the kernel refuses a for-every proof by {m:?}"));
    if let Some(var) = &goal.induction {
        let identity = identity_of(goal);
        let (_, _, base, step) = super::induction::prove(&ctx, &identity, var, &lemmas)?;
        let proof = super::check_induction(&base, &step).ok_or_else(|| refused(super::Method::Induction))?;
        return Ok((proof.method(), base.len() + step.len()));
    }
    let rewritten = lemma::apply(&sides, &decls, &lemmas)?;
    let (_, _, method, evidence) = prove_sides(&decls, &ctx, rewritten, &goal.certificates)?;
    let proof = super::check_discharged(method, &evidence).ok_or_else(|| refused(method))?;
    Ok((proof.method(), evidence.len()))
}

/// The members parsed in `ctx`; each must print back to its text.
fn parsed(ctx: &Ctx<'_>, members: &[String]) -> Result<Vec<Expr>> {
    let mut sides = Vec::with_capacity(members.len());
    for m in members {
        let e = ctx.expr(m)?;
        if &e.to_string() != m {
            return Err(Error::Parse(format!("'{m}' does not print back to itself")));
        }
        sides.push(e);
    }
    Ok(sides)
}

/// The identity a written goal states.
fn identity_of(goal: &Symbolic) -> Identity {
    Identity {
        sides: Sides::Chain(goal.members.clone()),
        certificates: goal.certificates.clone(),
        induction: goal.induction.clone(),
    }
}

/// The lemma a cited claim's written goal states (its id `id`), as `prove` read it from the
/// claim.
fn read_lemma(id: &str, goal: &Symbolic) -> Result<Lemma> {
    let decls = declarations(goal);
    let ctx = Ctx::new(id, Cow::Borrowed(&decls), Vec::new())?;
    parsed(&ctx, &goal.members)?;
    Lemma::from_parts(&ctx, &identity_of(goal))
}
