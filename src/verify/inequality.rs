//! The `inequality` kind: `lhs ≥ rhs` (or `>`) for every parameter `t` in `[a, b]`, proved by a
//! Bernstein certificate or refuted at an exact rational point.
//!
//! `p = lhs − rhs` is expanded exactly as `P(t)/Q(t)`. The denominator must be shown > 0 on
//! `[a, b]`; then `p ≥ 0` ⟺ `P ≥ 0` there. `P(a + (b−a)s)` is written in the Bernstein basis of
//! its degree d on `[0, 1]`: since `B_j^d(s) ≥ 0` and `Σ_j B_j^d(s) = 1`, all coefficients ≥ 0
//! prove `P ≥ 0` on the interval, and all ≥ 0 with the two end coefficients (the values at the
//! ends) > 0 prove `P > 0` (in the open interval every `B_j^d > 0`). Otherwise the interval is
//! halved by de Casteljau's algorithm (exact) up to [`MAX_DEPTH`](super::kernel::bernstein::MAX_DEPTH) times. A refutation is an
//! exact evaluation: an end coefficient is the value at that end, and each halving evaluates
//! `P` at the midpoint; a value < 0 (≤ 0 for `>`) with `Q > 0` is a counterexample. An interval
//! that neither proves nor refutes within the limit (a double root at a non-dyadic point) is an
//! error with the reason.
//!
//! With an open range (`for = ["n = 0..", "i = 0..=n"]`) the claim is proved for every n by
//! [`super::symbolic::nonneg_for_every`] (each term a product of factors ≥ 0 on `[a, b]`), after
//! the first values are evaluated as above.

use super::claims::{Inequality, Relation};
use super::context::Ctx;
use super::kernel::bernstein::poly_sign;
use super::kernel::bernstein::Sign;
use super::kernel::check_bernstein;
use super::kernel::checked::Step;
use super::kernel::checked::Verdict;
use super::kernel::eval::{Alg, Deg, Evaluator, Value, VarEnv};
use super::kernel::expr::Expr;
use super::kernel::poly::{Poly, RatFunc};
use super::outcome::Checked;
use crate::error::{Error, Result};
use num_rational::BigRational;
use num_traits::Zero;
use std::collections::BTreeMap;
use std::rc::Rc;

/// Why an inequality's certificate suffices, as `--explain` prints it.
pub const ARGUMENT: &[&str] = &[
    "On [a, b], P(a + (b − a)s) = Σ_j c_j B_j^d(s) with B_j^d(s) ≥ 0 and Σ_j B_j^d(s) = 1, so P is at least",
    "its least Bernstein coefficient; halving by de Casteljau's algorithm gives the coefficients of each half.",
    "All coefficients ≥ 0 on every subinterval prove P ≥ 0 (and > 0 when the end values are > 0); a value",
    "< 0 at an end or a midpoint, computed exactly, refutes the claim.",
];

/// The argument for every n (after the first values are checked as above).
pub const ARGUMENT_FOR_EVERY: &[&str] = &[
    "For every n: on each piece of the domain every live term of lhs − rhs is a product of factors ≥ 0",
    "on [a, b] (positive constants and factorials of arguments ≥ 0, powers with exponent ≥ 0 of",
    "polynomials with Bernstein coefficients ≥ 0), so their sum is ≥ 0.",
];

fn interval(ctx: &Ctx<'_>, ineq: &Inequality) -> Result<(BigRational, BigRational)> {
    let [a, b] = ineq
        .interval
        .clone()
        .ok_or_else(|| Error::Parse(format!("claim {} needs interval = [a, b]", ctx.id)))?;
    let (a, b): (BigRational, BigRational) = (
        super::objects::constant(&a.text()?)?,
        super::objects::constant(&b.text()?)?,
    );
    if a >= b {
        return Err(Error::Domain(format!("the interval [{a}, {b}] is empty or a point")));
    }
    Ok((a, b))
}

/// Checks an `inequality` claim.
pub fn check_inequality(ctx: &Ctx<'_>, ineq: &Inequality, detail: bool) -> Result<Checked> {
    let strict = ineq.relation == Relation::Greater;
    let (a, b) = interval(ctx, ineq)?;
    let lhs = ctx.expr(&ineq.lhs)?;
    let rhs = ctx.expr(ineq.rhs.as_deref().unwrap_or("0"))?;
    let p = Expr::sub(lhs, rhs);
    let params = ctx.params(&[&p]);
    if params.len() > 1 {
        return Err(Error::Domain(format!(
            "an inequality in one parameter, not {}",
            params.join(", ")
        )));
    }
    let t = params.first().cloned().unwrap_or_else(|| "t".to_string());
    let names: Rc<[String]> = Rc::from(vec![t.clone()]);
    let mut lines = Vec::new();
    let mut least: Option<(String, BigRational)> = None;
    // Every case's value, for the kernel to check.
    let mut values: Vec<RatFunc> = Vec::new();
    let mut pieces = 0usize;
    for ints in ctx.instances()? {
        let at: Vec<String> = ints.iter().map(|(k, v)| format!("{k} = {v}")).collect();
        let at = if at.is_empty() {
            String::new()
        } else {
            format!("{}: ", at.join(", "))
        };
        let degrees = std::iter::once((t.clone(), Value::S(Deg::var(&t)))).collect();
        super::kernel::eval::check_symbolic_degrees(degrees, &ints, &[&p])?;
        let mut vars = BTreeMap::new();
        vars.insert(t.clone(), Value::S(RatFunc::poly(Poly::var(&names, 0))));
        let env = VarEnv(vars);
        let v = Evaluator::new(&env, ints.clone()).scalar(&p)?;
        // The denominator must be > 0 on [a, b] (its sign is then the numerator's).
        let den = RatFunc::poly(v.den.clone());
        let den_sign = poly_sign(&den, &a, &b, true);
        let (num, flip) = match den_sign {
            Ok(Sign::Holds(_)) => (v.num.clone(), false),
            _ => match poly_sign(&den.neg(), &a, &b, true) {
                Ok(Sign::Holds(_)) => (v.num.clone(), true),
                _ => {
                    return Err(Error::Domain(format!(
                        "{at}the denominator {} is not shown to keep one sign on [{a}, {b}]",
                        v.den
                    )))
                }
            },
        };
        let num = if flip {
            RatFunc::poly(num).neg()
        } else {
            RatFunc::poly(num)
        };
        values.push(v.clone());
        match poly_sign(&num, &a, &b, strict)? {
            Sign::Fails(x) => {
                let value = eval_at(&v, &x)?;
                return Ok(Checked::fails(format!(
                    "{at}at {t} = {x}: left side − right side = {value}, {} 0 (an exact evaluation in [{a}, {b}])",
                    if strict { "not > " } else { "<" }
                )));
            }
            Sign::Holds(parts) => {
                pieces += parts.len();
                let m = parts
                    .iter()
                    .map(|p| p.2.clone())
                    .min()
                    .unwrap_or_else(BigRational::zero);
                if least.as_ref().is_none_or(|(_, l)| &m < l) {
                    least = Some((at.trim_end_matches(": ").to_string(), m.clone()));
                }
                if detail {
                    let list: Vec<String> = parts
                        .iter()
                        .map(|(lo, hi, l)| format!("[{lo}, {hi}]: least coefficient {l}"))
                        .collect();
                    lines.push(Step::text(format!(
                        "{at}numerator {} (denominator {}), Bernstein coefficients on {} subinterval{}: {}",
                        v.num,
                        v.den,
                        parts.len(),
                        if parts.len() == 1 { "" } else { "s" },
                        list.join("; ")
                    )));
                }
            }
        }
    }
    let (where_, m) = least.unwrap_or_default();
    let proof = check_bernstein(&values, &a, &b, strict)
        .ok_or_else(|| Error::Domain("the kernel refuses the certificate: a negative Bernstein coefficient".into()))?;
    let mut out = Checked::proved(
        proof,
        format!(
            "on [{a}, {b}] the numerator of left side − right side (the denominator shown > 0) has Bernstein coefficients {} on {pieces} subinterval{} (least coefficient {m}{}): proof",
            if strict { "≥ 0 and > 0 at the ends" } else { "≥ 0" },
            if pieces == 1 { "" } else { "s" },
            if where_.is_empty() { String::new() } else { format!(" at {where_}") }
        ),
    );
    out.steps = lines;
    Ok(out)
}

fn eval_at(v: &RatFunc, x: &BigRational) -> Result<BigRational> {
    let den = v.den.eval(std::slice::from_ref(x));
    if den.is_zero() {
        return Err(Error::DivisionByZero(format!("at {x}")));
    }
    Ok(v.num.eval(std::slice::from_ref(x)) / den)
}

/// Checks an `inequality` claim with open ranges: the first values by [`check_inequality`],
/// every value by [`super::symbolic::nonneg_for_every`].
/// `claim` is the claim's context, over its open ranges.
pub fn check_for_every(claim: &Ctx<'_>, ineq: &Inequality, detail: bool) -> Result<Checked> {
    let (id, decls) = (claim.id, &*claim.decls);
    if ineq.relation == Relation::Greater {
        return Err(Error::Domain(format!(
            "claim {id}: a strict inequality for every n is not supported (only ≥ by nonnegative factors)"
        )));
    }
    let ctx = claim.closed_after(super::symbolic::CROSS_CHECK)?;
    let evaluated = check_inequality(&ctx, ineq, false)?;
    if evaluated.verdict() == Verdict::Fails {
        return Ok(evaluated);
    }
    let (a, b) = interval(&ctx, ineq)?;
    let lhs = ctx.expr(&ineq.lhs)?;
    let rhs = ctx.expr(ineq.rhs.as_deref().unwrap_or("0"))?;
    let mut out = super::symbolic::nonneg_for_every(decls, &ctx, (&lhs, &rhs), (&a, &b), detail)?;
    out.certificate = format!(
        "{} on [{a}, {b}]; also evaluated exactly for the first {} values of each open range",
        out.certificate,
        super::symbolic::CROSS_CHECK + 1
    );
    Ok(out)
}
