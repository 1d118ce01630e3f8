//! The identity goal: the members of a chain over a claim's declarations, checked for every
//! value of the parameters and every case of the finite ranges, in the number field the
//! expressions need. Identity, implicit and lowered claims (a power form's points, a theorem's
//! parts, the symbolic route's evaluation check) all end here.

use super::claims::{CurveSpec, Decls, Identity, Number};
use super::context::Ctx;
use super::expansion::check_chain_symbolic;
use super::kernel::expr::Expr;
use super::outcome::Checked;
use super::sampling::check_chain;
use crate::error::Result;
use crate::quadratic::QuadraticIrrational;

/// Checks `members[0] = members[1] = …` in the claim's context; a proof over finite ranges
/// is `proved_in_range` with the ranges.
pub fn check_identity(ctx: &Ctx<'_>, members: &[String], detail: bool) -> Result<Checked> {
    let sides: Vec<Expr> = members.iter().map(|s| ctx.expr(s)).collect::<Result<_>>()?;
    let out = if ctx.symbolic() {
        check_chain_symbolic(ctx, &sides, detail)?
    } else {
        chain_in_field(ctx, &sides, detail)?
    };
    if ctx.decls.ranges.is_empty() {
        return Ok(out);
    }
    Ok(out.in_range(ctx.range_text()))
}

/// Whether the expressions or the declared objects' numbers take a square root: then the
/// claim is checked in `Q(√d)`.
pub fn uses_sqrt(decls: &Decls, exprs: &[Expr]) -> bool {
    let in_number = |n: &Number| matches!(n, Number::Text(t) if t.contains("sqrt"));
    let in_curve = |c: &CurveSpec| {
        c.points
            .iter()
            .flatten()
            .chain(c.weights.iter().flatten())
            .any(in_number)
    };
    exprs.iter().any(|e| e.called_names().iter().any(|n| n == "sqrt"))
        || decls.curves.iter().flat_map(|m| m.values()).any(in_curve)
        || decls
            .surfaces
            .iter()
            .flat_map(|m| m.values())
            .any(|s| s.net.iter().flatten().flatten().any(in_number))
}

/// Checks a chain in exact rationals, or in the quadratic irrationals when a `sqrt` occurs.
pub fn chain_in_field(ctx: &Ctx<'_>, sides: &[Expr], detail: bool) -> Result<Checked> {
    if uses_sqrt(&ctx.decls, sides) {
        let mut out = check_chain::<QuadraticIrrational>(ctx, sides, detail)?;
        out.certificate = format!("{} (exact arithmetic in Q(√d))", out.certificate);
        Ok(out)
    } else {
        check_chain::<crate::exact::SmallRational>(ctx, sides, detail)
    }
}

/// An identity to prove in a claim's context: what identity claims are, and what other
/// claims (a claim written with its ranges opened) lower to.
pub struct Goal<'c> {
    /// The elaborated declarations.
    pub ctx: Ctx<'c>,
    /// The chain to prove.
    pub identity: Identity,
}
