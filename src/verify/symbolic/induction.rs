//! Induction on a range variable (`induction = "r"`): an identity whose left side is a library
//! object defined by a recursion (the scheme `b(i, r, t)`, the differences `delta(b, k, j)`) is
//! proved for every `r ≥ lo` from
//!
//! - the **base**: the claim at `r = lo`, the objects there read by the base of their
//!   recursion (`b(i, 0, t) = b[i]`), proved for every value of the other variables;
//! - the **step**: the claim at `r + 1` for every `lo ≤ r < hi`, the objects at `r + 1`
//!   unfolded by one step of their recursion (down to `r`), and the objects at exactly `r`
//!   replaced by the claim itself at `r` — the induction hypothesis, used only as stated: only at
//!   `r`, only within the claim's other ranges at `r` (each use an obligation shown on the step's
//!   domain). The induction variable may not be the polygon's degree (the hypothesis would be
//!   about another polygon).
//!
//! Both are proved by the symbolic route ([`super::prove_sides`]), the claim's other lemmas
//! (`uses`) available to both.

use super::super::claims::{Identity, IntRange};
use super::super::context::Ctx;
use super::super::kernel::checked::Step;
use super::super::kernel::expr::Expr;
use super::super::kernel::Discharged;
use super::super::lemma::{self, Lemma, Rewritten, Unfold};
use super::super::parse::parse;
use super::super::rewrite::substitute;
use super::{parsed_sides, prove_sides};
use crate::error::{Error, Result};

/// The certificate, the log, and the obligations the kernel checked for the base and for the
/// step.
type Induction = (String, Vec<Step>, Vec<Discharged>, Vec<Discharged>);

/// The proof by induction on `var` (see the module documentation).
pub(super) fn prove(ctx: &Ctx<'_>, identity: &Identity, var: &str, lemmas: &[Lemma]) -> Result<Induction> {
    let decls = &*ctx.decls;
    let Some(k) = decls.ranges.iter().position(|r| r.var == var) else {
        return Err(Error::Domain(format!(
            "induction on {var}: it is not a range variable of the claim"
        )));
    };
    if decls.polygon.as_ref().is_some_and(|p| p.degree.trim() == var) {
        return Err(Error::Domain(format!(
            "induction on {var}: it is the polygon's degree (the hypothesis would be about another polygon)"
        )));
    }
    let range = &decls.ranges[k];
    let lo = parse(&range.from, &[])?;
    let hypothesis = Lemma::from_parts(ctx, identity)?.hypothesis(var)?;
    // The sides parse alike over any bounds of the same range variables.
    let sides = parsed_sides(ctx, identity)?;
    let name = [var.to_string()];

    // The base: the claim at var = lo, its other ranges there (and lo within var's range).
    let mut base = Rewritten::default();
    if let Some(to) = &range.to {
        base.assumptions.push(Expr::sub(parse(to, &[])?, lo.clone()));
    }
    let at_lo: Vec<Expr> = sides
        .iter()
        .map(|s| {
            lemma::unfold(
                &substitute(s, &name, std::slice::from_ref(&lo)),
                decls,
                &Unfold::Base(&lo),
                &mut base,
            )
        })
        .collect::<Result<_>>()?;
    let base_ctx = ctx.with_ranges(ranges_at(&decls.ranges, k, None, &lo)?)?;
    let (base_cert, mut log, base_evidence) = prove_part(&base_ctx, at_lo, base, lemmas, &identity.certificates)?;

    // The step: var from lo while var + 1 is in range, the later ranges at var + 1.
    let next = Expr::add(Expr::Var(var.into()), Expr::int(1));
    let mut step = Rewritten::default();
    let at_next: Vec<Expr> = sides
        .iter()
        .map(|s| {
            lemma::unfold(
                &substitute(s, &name, std::slice::from_ref(&next)),
                decls,
                &Unfold::Step(var),
                &mut step,
            )
        })
        .collect::<Result<_>>()?;
    let own_range = IntRange {
        to: match &range.to {
            Some(to) => Some(Expr::sub(parse(to, &[])?, Expr::int(1)).to_string()),
            None => None,
        },
        ..range.clone()
    };
    let step_ctx = ctx.with_ranges(ranges_at(&decls.ranges, k, Some(own_range), &next)?)?;
    let mut with_hypothesis = lemmas.to_vec();
    with_hypothesis.push(hypothesis);
    let (step_cert, step_log, step_evidence) =
        prove_part(&step_ctx, at_next, step, &with_hypothesis, &identity.certificates)?;
    log.extend(step_log);
    Ok((
        format!(
            "by induction on {var} from {lo}, the objects unfolded by their recursions — the base {var} = {lo}: {base_cert}; the step {var} → {var} + 1, the claim at {var} its only hypothesis: {step_cert}"
        ),
        log,
        base_evidence,
        step_evidence,
    ))
}

/// The ranges with range `k` replaced by `own` (or dropped) and `value` for its variable in
/// the later ranges' bounds.
fn ranges_at(ranges: &[IntRange], k: usize, own: Option<IntRange>, value: &Expr) -> Result<Vec<IntRange>> {
    let var = [ranges[k].var.clone()];
    let at = |text: &str| -> Result<String> {
        Ok(substitute(&parse(text, &[])?, &var, std::slice::from_ref(value)).to_string())
    };
    let mut out: Vec<IntRange> = ranges[..k].to_vec();
    out.extend(own);
    for r in &ranges[k + 1..] {
        out.push(IntRange {
            var: r.var.clone(),
            from: at(&r.from)?,
            to: r.to.as_deref().map(at).transpose()?,
        });
    }
    Ok(out)
}

/// One part of the induction (its context `part`): its objects replaced by `lemmas`, proved
/// on its ranges.
fn prove_part(
    part: &Ctx<'_>,
    sides: Vec<Expr>,
    unfolded: Rewritten,
    lemmas: &[Lemma],
    certificates: &[String],
) -> Result<(String, Vec<Step>, Vec<Discharged>)> {
    let decls = &*part.decls;
    let mut rewritten = lemma::apply(&sides, decls, lemmas)?;
    rewritten.obligations.extend(unfolded.obligations);
    rewritten.assumptions.extend(unfolded.assumptions);
    let mut definitions = unfolded.definitions;
    definitions.extend(rewritten.definitions);
    rewritten.definitions = definitions;
    let closed = part.closed_after(1)?;
    // The base and the step are parts of the induction, whatever argument each took.
    prove_sides(decls, &closed, rewritten, certificates).map(|(cert, log, _, evidence)| (cert, log, evidence))
}
