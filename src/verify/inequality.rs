//! The `inequality` kind: `lhs ≥ rhs` (or `>`) for every parameter `t` in `[a, b]`, proved by a
//! Bernstein certificate or refuted at an exact rational point.
//!
//! `p = lhs − rhs` is expanded exactly as `P(t)/Q(t)`. The denominator must be shown > 0 on
//! `[a, b]`; then `p ≥ 0` ⟺ `P ≥ 0` there. `P(a + (b−a)s)` is written in the Bernstein basis of
//! its degree d on `[0, 1]`: since `B_j^d(s) ≥ 0` and `Σ_j B_j^d(s) = 1`, all coefficients ≥ 0
//! prove `P ≥ 0` on the interval, and all ≥ 0 with the two end coefficients (the values at the
//! ends) > 0 prove `P > 0` (in the open interval every `B_j^d > 0`). Otherwise the interval is
//! halved by de Casteljau's algorithm (exact) up to [`MAX_DEPTH`] times. A refutation is an
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
use super::kernel::check_bernstein;
use super::kernel::checked::Verdict;
use super::kernel::checked::{Checked, Step};
use super::kernel::eval::{Alg, Deg, Evaluator, Value, VarEnv};
use super::kernel::expr::Expr;
use super::kernel::poly::{Poly, RatFunc};
use crate::bernstein::{power_to_bernstein, reparametrize};
use crate::error::{Error, Result};
use num_rational::BigRational;
use num_traits::{Signed, Zero};
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

/// Most halvings of `[a, b]` (so at most 2^`MAX_DEPTH` subintervals).
pub const MAX_DEPTH: usize = 12;

/// What the Bernstein check found.
#[derive(Clone, Debug)]
pub enum Sign {
    /// Every subinterval's coefficients are ≥ 0 (> 0 at the ends for strict): the subintervals
    /// and their least coefficients.
    Holds(Vec<(BigRational, BigRational, BigRational)>),
    /// The value at this point is < 0 (≤ 0 for strict).
    Fails(BigRational),
}

fn eval(coeffs: &[BigRational], t: &BigRational) -> BigRational {
    coeffs.iter().rev().fold(BigRational::zero(), |acc, c| acc * t + c)
}

/// Decides `P ≥ 0` (`P > 0` when `strict`) on `[a, b]` for `P` given by power coefficients.
pub fn bernstein_sign(power: &[BigRational], a: &BigRational, b: &BigRational, strict: bool) -> Result<Sign> {
    let bad = |v: &BigRational| if strict { !v.is_positive() } else { v.is_negative() };
    let local = reparametrize(power, a, b);
    let coeffs = power_to_bernstein(&local)?;
    let mut work = vec![(a.clone(), b.clone(), coeffs, 0usize)];
    let mut done = Vec::new();
    while let Some((lo, hi, c, depth)) = work.pop() {
        let (first, last) = (c[0].clone(), c[c.len() - 1].clone());
        if bad(&first) {
            return Ok(Sign::Fails(lo));
        }
        if bad(&last) {
            return Ok(Sign::Fails(hi));
        }
        if c.iter().all(|x| !x.is_negative()) {
            let least = c.iter().min().cloned().unwrap_or_else(BigRational::zero);
            done.push((lo, hi, least));
            continue;
        }
        let two = BigRational::from_integer(2.into());
        let mid = (&lo + &hi) / &two;
        let at = eval(power, &mid);
        if bad(&at) {
            return Ok(Sign::Fails(mid));
        }
        if depth >= MAX_DEPTH {
            return Err(Error::TooLarge {
                what: "halvings of the interval for a Bernstein certificate",
                value: format!("more than {MAX_DEPTH} on [{lo}, {hi}] (a double root at a non-dyadic point?)"),
                limit: format!("MAX_DEPTH = {MAX_DEPTH}"),
            });
        }
        // de Casteljau at 1/2: the left and right Bernstein coefficients.
        let mut row = c.clone();
        let (mut left, mut right) = (vec![row[0].clone()], vec![row[row.len() - 1].clone()]);
        while row.len() > 1 {
            row = row.windows(2).map(|w| (&w[0] + &w[1]) / &two).collect();
            left.push(row[0].clone());
            right.push(row[row.len() - 1].clone());
        }
        right.reverse();
        work.push((mid.clone(), hi, right, depth + 1));
        work.push((lo, mid, left, depth + 1));
    }
    done.sort();
    Ok(Sign::Holds(done))
}

fn coeffs_1d(p: &Poly) -> Vec<BigRational> {
    let mut out = Vec::new();
    for (e, c) in p.terms_in(1) {
        let k = e[0] as usize;
        if out.len() <= k {
            out.resize(k + 1, BigRational::zero());
        }
        out[k] = c;
    }
    if out.is_empty() {
        out.push(BigRational::zero());
    }
    out
}

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

/// `q ≥ 0` (`> 0`) on `[a, b]` for a rational function of one variable with constant
/// denominator, or a polynomial.
fn poly_sign(q: &RatFunc, a: &BigRational, b: &BigRational, strict: bool) -> Result<Sign> {
    let d = q
        .den
        .as_constant()
        .ok_or_else(|| Error::Domain("a polynomial was expected".into()))?;
    let mut c = coeffs_1d(&q.num);
    if d.is_negative() {
        for x in &mut c {
            *x = -x.clone();
        }
    }
    bernstein_sign(&c, a, b, strict)
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
    // Every subinterval's least coefficient, for the kernel to check.
    let mut leasts: Vec<BigRational> = Vec::new();
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
                leasts.extend(parts.iter().map(|p| p.2.clone()));
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
    let proof = check_bernstein(&leasts)
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
    let p = Expr::sub(lhs, rhs);
    let nonneg = |q: &RatFunc, strict: bool| -> Result<bool> {
        // q is over the symbol list of the symbolic proof: one parameter, no integers.
        let one: Vec<Vec<BigRational>> = vec![coeffs_last(q)];
        let d = q
            .den
            .as_constant()
            .ok_or_else(|| Error::Domain("a polynomial was expected".into()))?;
        let mut c = one.into_iter().next().unwrap_or_default();
        if d.is_negative() {
            for x in &mut c {
                *x = -x.clone();
            }
        }
        Ok(matches!(bernstein_sign(&c, &a, &b, strict)?, Sign::Holds(_)))
    };
    let mut out = super::symbolic::nonneg_for_every(decls, &ctx, &p, &nonneg, detail)?;
    out.certificate = format!(
        "{} on [{a}, {b}]; also evaluated exactly for the first {} values of each open range",
        out.certificate,
        super::symbolic::CROSS_CHECK + 1
    );
    Ok(out)
}

/// The power coefficients of a polynomial in the last variable of its list (the parameter of a
/// symbolic proof; the integer symbols must not occur).
fn coeffs_last(q: &RatFunc) -> Vec<BigRational> {
    let mut out = Vec::new();
    for (e, c) in q.num.terms_in(q.num.var_count()) {
        let k = *e.last().unwrap_or(&0) as usize;
        if out.len() <= k {
            out.resize(k + 1, BigRational::zero());
        }
        out[k] += c;
    }
    if out.is_empty() {
        out.push(BigRational::zero());
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn certificates_and_refutations() {
        let (zero, one) = (q(0, 1), q(1, 1));
        // (2t − 1)² = 4t² − 4t + 1 ≥ 0: one halving (the root is at 1/2).
        match bernstein_sign(&[q(1, 1), q(-4, 1), q(4, 1)], &zero, &one, false).unwrap() {
            Sign::Holds(parts) => assert_eq!(parts.len(), 2),
            other => panic!("{other:?}"),
        }
        // ... but not > 0: the midpoint value 0 refutes it.
        match bernstein_sign(&[q(1, 1), q(-4, 1), q(4, 1)], &zero, &one, true).unwrap() {
            Sign::Fails(x) => assert_eq!(x, q(1, 2)),
            other => panic!("{other:?}"),
        }
        // t² − t + 1/5 < 0 at t = 1/2 (−1/20), though ≥ 0 at both ends.
        match bernstein_sign(&[q(1, 5), q(-1, 1), q(1, 1)], &zero, &one, false).unwrap() {
            Sign::Fails(x) => assert_eq!(x, q(1, 2)),
            other => panic!("{other:?}"),
        }
        // (t − 1/3)² ≥ 0 has its root at a non-dyadic point: undecided within the limit.
        assert!(bernstein_sign(&[q(1, 9), q(-2, 3), q(1, 1)], &zero, &one, false).is_err());
    }
}
