//! `∫_0^1` of hypergeometric terms in the variable of integration, symbolic in the integers:
//! Euler's Beta integral `∫_0^1 t^a (1−t)^b dt = a! b! / (a+b+1)!` for integers `a, b ≥ 0`.
//!
//! A term (see [`super::hyper::Term`]) qualifies when `t` occurs only as `t^e` and `(1−t)^e`
//! with affine exponents, in a polynomial numerator of its coefficient (each power `t^β`
//! of which adds β to the exponent of `t`) and as powers of `t` and `1 − t` dividing its
//! denominator; its other factors do not depend on `t` and come out of the integral. The
//! exponents must be shown ≥ 0 wherever the term is nonzero (every support condition and
//! reciprocal factorial argument ≥ 0, on the domain), so the formula is only used where the
//! integral converges and the result's conditions say nothing new; an exponent negative only
//! where a factor of the coefficient is 0 splits the term there ([`integrate_term`]).
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
    let mut out = Vec::new();
    for term in lin {
        integrate_term(sym, term, (t, tx), d, MAX_SPLITS, &mut out)?;
    }
    Ok(out)
}

/// Most splits of one term at the zeros of its coefficient.
const MAX_SPLITS: u8 = 4;

/// `c = x + j` (`1 ≤ j ≤ 3`) when it is an affine factor of the coefficient of `term`, whose
/// denominator is constant (so the term is 0 where `c = 0`, see [`vanishes`]), and `c = 0`
/// somewhere on `live`.
fn zero_of_coefficient(sym: &Symbols, term: &Term, x: &Aff, live: &Domain) -> Option<Aff> {
    term.coef.den.as_constant()?;
    (1..=3).map(|j| x.shifted(j)).find(|c| {
        let factor = c.to_rf(sym).num;
        factor.as_constant().is_none()
            && live.with(c.clone()).with(c.scaled(-1)).feasible()
            && term.coef.num.exact_div(&factor).is_some()
    })
}

/// One term of [`integrate`], appended to `out`. An exponent `x` not shown ≥ 0 whose term's
/// coefficient has a factor `c = x + j` (`(n − i)·(1 − t)^(n−i−1)`, of `(B_i^n)'`) splits the
/// term into the parts where `c ≥ 1` and `c ≤ −1` (at most `splits` times): where `c = 0` the
/// integrand is 0. A part on an empty domain shows every exponent ≥ 0.
fn integrate_term(
    sym: &Symbols,
    term: &Term,
    (t, tx): (&str, usize),
    d: &Domain,
    splits: u8,
    out: &mut Lin,
) -> Result<()> {
    let names = &sym.names;
    let t_poly = Poly::var(names, tx);
    let one_minus_t = RatFunc::from_int(1).sub(&RatFunc::poly(t_poly.clone())).num;
    let mentions_t = |p: &Poly| {
        p.terms_in(sym.names.len())
            .iter()
            .any(|(e, _)| e.get(tx).is_some_and(|&x| x > 0))
    };
    {
        // A power of t or 1 − t dividing the coefficient's denominator is a negative exponent
        // (while the denominator mentions t: each step lowers its degree).
        let (mut a, mut b) = (Aff::constant(0), Aff::constant(0));
        let mut term = term.clone();
        for (base, e) in [(&t_poly, &mut a), (&one_minus_t, &mut b)] {
            while let Some(q) = term.coef.den.exact_div(base).filter(|_| mentions_t(&term.coef.den)) {
                term.coef.den = q;
                *e = e.shifted(-1);
            }
        }
        let term = &term;
        if mentions_t(&term.coef.den) {
            return Err(refuse(format!(
                "the coefficient of {} has {t} in its denominator",
                term.show()
            )));
        }
        let mut rest = term.clone();
        rest.pows.clear();
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
        if splits < MAX_SPLITS && !live.feasible() {
            // A part of a split that is 0 on the whole domain.
            return Ok(());
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
        let mut parts = Vec::new();
        for (beta, part) in by_power {
            let ab = a.shifted(i64::from(beta));
            for (x, name) in [(&ab, "t"), (&b, "1 − t")] {
                if live.implies_ge(x) {
                    continue;
                }
                let zero = zero_of_coefficient(sym, term, x, &live)
                    .filter(|c| vanishes(term, &live, c, [&t_poly, &one_minus_t]));
                if let Some(c) = zero.filter(|_| splits > 0) {
                    for side in [c.shifted(-1), c.scaled(-1).shifted(-1)] {
                        let mut piece = term.clone();
                        piece.support.push(side);
                        integrate_term(sym, &piece, (t, tx), d, splits - 1, out)?;
                    }
                    return Ok(());
                }
                return Err(refuse(format!(
                    "the exponent {x} of {name} in {} is not shown ≥ 0 where the term is nonzero (the integral may diverge)",
                    term.show()
                )));
            }
            let mut out_term = rest.clone();
            out_term.coef = RatFunc {
                num: from_terms(names, &part),
                den: term.coef.den.clone(),
            };
            out_term.facts.push((ab.clone(), 1));
            out_term.facts.push((b.clone(), 1));
            out_term.facts.push((ab.plus(&b).shifted(1), -1));
            parts.push(out_term);
        }
        out.extend(parts);
    }
    Ok(())
}

/// Whether `term` is 0 where `c = 0` on `live` beside its factor `c`: its numerator factorials
/// are of arguments ≥ 0 there and its powers other than of `t` and `1 − t` are of nonzero
/// constants (so no other factor is infinite or undefined on `0 < t < 1`).
fn vanishes(term: &Term, live: &Domain, c: &Aff, t_bases: [&Poly; 2]) -> bool {
    let zero = live.with(c.clone()).with(c.scaled(-1));
    term.facts
        .iter()
        .filter(|(_, s)| *s > 0)
        .all(|(x, _)| zero.implies_ge(x))
        && term.pows.iter().all(|(base, _)| match base {
            Base::Const(k) => !k.is_zero(),
            Base::Poly(q) => t_bases.contains(&q),
        })
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
