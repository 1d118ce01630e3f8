//! `∫_0^1` of hypergeometric terms in the variable of integration, symbolic in the integers:
//! Euler's Beta integral `∫_0^1 t^a (1−t)^b dt = a! b! / (a+b+1)!` for integers `a, b ≥ 0`.
//!
//! A term (see [`super::hyper::Term`]) qualifies when `t` occurs only as `t^e` and `(1−t)^e`
//! with affine exponents and in a polynomial numerator of its coefficient (each power `t^β`
//! of which adds β to the exponent of `t`); its other factors do not depend on `t` and come
//! out of the integral. The exponents must be shown ≥ 0 wherever the term is nonzero (every
//! support condition and reciprocal factorial argument ≥ 0, on the domain), so the formula is
//! only used where the integral converges and the result's conditions say nothing new.
//! Anything else is an error (the claim can still be checked on a finite range).

use super::eval::Alg;
use super::expr::Expr;
use super::hyper::{Aff, Base, Lin, Symbols, Term};
use super::pieces::Domain;
use super::poly::{Poly, RatFunc};
use crate::error::{Error, Result};
use num_rational::BigRational;
use num_traits::Zero;
use std::collections::BTreeMap;

fn refuse(why: String) -> Error {
    Error::Domain(format!("∫_0^1 for symbolic integers: {why}"))
}

/// Euler's Beta rule applied to `∫_0^1 Σ lin dt` on `d` (see [`integrate`]): its value, and
/// the rule's use as evidence for the proof.
pub fn check_beta(sym: &Symbols, lin: &[Term], t: &str, d: &Domain) -> Result<(Lin, super::Discharged)> {
    let value = integrate(sym, lin, t, d)?;
    Ok((value, super::Discharged::new(super::checked::Method::Beta)))
}

/// `∫_0^1 Σ lin dt` as a sum of terms, on the domain `d` (see the module documentation).
pub fn integrate(sym: &Symbols, lin: &[Term], t: &str, d: &Domain) -> Result<Lin> {
    let Some(tx) = sym.index(t).filter(|_| sym.is_cont(t)) else {
        return Err(refuse(format!(
            "the variable of integration {t} must be a continuous parameter"
        )));
    };
    let names = &sym.names;
    let t_poly = Poly::var(names, tx);
    let one_minus_t = RatFunc::from_int(1).sub(&RatFunc::poly(t_poly.clone())).num;
    let mentions_t = |p: &Poly| {
        p.terms_in(sym.names.len())
            .iter()
            .any(|(e, _)| e.get(tx).is_some_and(|&x| x > 0))
    };
    let mut out = Vec::new();
    for term in lin {
        if mentions_t(&term.coef.den) {
            return Err(refuse(format!(
                "the coefficient of {} has {t} in its denominator",
                term.show()
            )));
        }
        let mut rest = term.clone();
        rest.pows.clear();
        let (mut a, mut b) = (Aff::constant(0), Aff::constant(0));
        for (base, e) in &term.pows {
            match base {
                Base::Poly(q) if *q == t_poly => a = a.plus(e),
                Base::Poly(q) if *q == one_minus_t => b = b.plus(e),
                Base::Poly(q) if mentions_t(q) => {
                    return Err(refuse(format!(
                        "the factor {base}^({e}) of {} is not t^e or (1 − t)^e",
                        term.show()
                    )))
                }
                _ => rest.pows.push((base.clone(), e.clone())),
            }
        }
        // Where the term lives (its zeroing conditions hold), the exponents must be ≥ 0.
        let mut live = d.clone();
        for c in term
            .support
            .iter()
            .chain(term.facts.iter().filter(|(_, s)| *s < 0).map(|(x, _)| x))
        {
            live = live.with(c.clone());
        }
        // The coefficient's numerator by powers of t: Σ_β c_β t^β.
        let mut by_power: BTreeMap<u16, Vec<(Vec<u16>, BigRational)>> = BTreeMap::new();
        for (mut e, c) in term.coef.num.terms_in(sym.names.len()) {
            let beta = e.get(tx).copied().unwrap_or(0);
            if let Some(x) = e.get_mut(tx) {
                *x = 0;
            }
            by_power.entry(beta).or_default().push((e, c));
        }
        for (beta, part) in by_power {
            let ab = a.shifted(i64::from(beta));
            for (x, name) in [(&ab, "t"), (&b, "1 − t")] {
                if !live.implies_ge(x) {
                    return Err(refuse(format!(
                        "the exponent {x} of {name} in {} is not shown ≥ 0 where the term is nonzero (the integral may diverge)",
                        term.show()
                    )));
                }
            }
            let mut out_term = rest.clone();
            out_term.coef = RatFunc {
                num: from_terms(names, &part),
                den: term.coef.den.clone(),
            };
            out_term.facts.push((ab.clone(), 1));
            out_term.facts.push((b.clone(), 1));
            out_term.facts.push((ab.plus(&b).shifted(1), -1));
            out.push(out_term);
        }
    }
    Ok(out)
}

fn from_terms(names: &std::rc::Rc<[String]>, terms: &[(Vec<u16>, BigRational)]) -> Poly {
    let mut out = RatFunc::poly(Poly::constant(names, &BigRational::zero()));
    for (e, c) in terms {
        let mut m = Poly::constant(names, c);
        for (k, &x) in e.iter().enumerate() {
            for _ in 0..x {
                m = m.mul(&Poly::var(names, k));
            }
        }
        out = out.add(&RatFunc::poly(m));
    }
    out.num
}

/// The variables of integration of `integral(e, t, a, b)` in `e`, appended to `out`.
pub(crate) fn integral_vars(e: &Expr, out: &mut Vec<String>) {
    match e {
        Expr::Call(name, args) => {
            if let (true, Some(Expr::Var(t))) = (name == "integral" && args.len() == 4, args.get(1)) {
                if !out.contains(t) {
                    out.push(t.clone());
                }
            }
            args.iter().for_each(|a| integral_vars(a, out));
        }
        Expr::Sum(_, a, b, body) => {
            integral_vars(a, out);
            integral_vars(b, out);
            integral_vars(body, out);
        }
        Expr::Neg(a) | Expr::Fact(a) => integral_vars(a, out),
        Expr::Bin(_, a, b) => {
            integral_vars(a, out);
            integral_vars(b, out);
        }
        Expr::Index(_, args) | Expr::Tuple(args) => args.iter().for_each(|a| integral_vars(a, out)),
        Expr::Matrix(rows) => rows.iter().flatten().for_each(|a| integral_vars(a, out)),
        Expr::Num(_) | Expr::Var(_) => {}
    }
}

/// Whether the bounds of an integral are exactly 0 and 1.
pub(crate) fn is_unit_interval(lo: &Expr, hi: &Expr) -> bool {
    let value = |e: &Expr| super::expr::eval_int(e, &Default::default()).ok();
    value(lo) == Some(0) && value(hi) == Some(1)
}
