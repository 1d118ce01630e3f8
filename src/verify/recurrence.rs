//! Claims that state a recurrence of a sum: `Σ_s q_s(n) Σ_{k=a}^{b(n)+j_s} F(n+j_s, k) + rest(n) = 0`
//! (e.g. Franel's `(n+2)² f(n+2) − (7n² + 21n + 16) f(n+1) − 8(n+1)² f(n) = 0` with
//! `f(m) = Σ_k C(m, k)³`), proved for every `n` by creative telescoping with the stated
//! coefficients.
//!
//! Both sides are split into their additive parts; each part holding a sum must be a
//! coefficient (a rational function, no conditions) times one sum with a symbolic bound, and
//! the sums must be one summand at shifted `n`: the same lower bound `a` (free of `n`), upper
//! bounds `b(n) + j_s`, and summands `T_s(k) = F(n+j_s, k)` on `a ≤ k ≤ b(n)+j_s` — which is
//! proved, so `Σ_k T_s = S(n+j_s)` for `S(n) = Σ_{k=a}^{b(n)} F(n, k)`. With
//! `p_j = Σ_{j_s = j} q_s`, [`super::telescope::find`] looks for `G` with
//! `Σ_j p_j F(n+j, k) = G(n, k+1) − G(n, k)`, and two identities prove the claim at every
//! point of the domain, no induction needed:
//!
//! 1. that telescoping equation for every `a ≤ k ≤ b(n)`;
//! 2. `G(n, b(n)+1) − G(n, a) + Σ_j p_j Σ_{m=1}^{j} F(n+j, b(n)+m) + rest(n) = 0` — the sum of
//!    1 over `k`, with the terms of `S(n+j)` past `b(n)` added, is the claim.
//!
//! The kernel (`kernel::recurrence`) checks the summands' shifts, that the recurrence found has
//! the stated coefficients, and both identities. A claim of another shape is not for this
//! route (the caller keeps its own reason).

use super::kernel::checked::Method;
use super::kernel::eval::Alg;
use super::kernel::expr::{Expr, Op};
use super::kernel::hyper::{lin_neg, Aff, Lin, Term};
use super::kernel::pieces::Domain;
use super::kernel::poly::RatFunc;
use super::kernel::recurrence::{self, Bounds};
use super::telescope::{self, Coefficients};
use super::translate::Translator;
use crate::error::{Error, Result};

mod forms;

/// The additive parts of `e`, with their signs.
fn parts(e: &Expr, plus: bool, out: &mut Vec<(bool, Expr)>) {
    match e {
        Expr::Bin(Op::Add, a, b) => {
            parts(a, plus, out);
            parts(b, plus, out);
        }
        Expr::Bin(Op::Sub, a, b) => {
            parts(a, plus, out);
            parts(b, !plus, out);
        }
        Expr::Neg(a) => parts(a, !plus, out),
        _ => out.push((plus, e.clone())),
    }
}

pub(crate) fn has_sum(e: &Expr) -> bool {
    match e {
        Expr::Sum(..) => true,
        Expr::Neg(a) | Expr::Fact(a) => has_sum(a),
        Expr::Bin(_, a, b) => has_sum(a) || has_sum(b),
        Expr::Call(_, args) | Expr::Index(_, args) | Expr::Tuple(args) => args.iter().any(has_sum),
        Expr::Matrix(rows) => rows.iter().flatten().any(has_sum),
        Expr::Num(_) | Expr::Var(_) => false,
    }
}

/// `coefficient · sum`: the sum and the coefficient (the other factors of a product).
pub(crate) fn coefficient_times_sum(e: &Expr) -> Option<(Expr, Expr)> {
    match e {
        Expr::Sum(..) => Some((Expr::int(1), e.clone())),
        Expr::Neg(a) => coefficient_times_sum(a).map(|(c, s)| (Expr::Neg(Box::new(c)), s)),
        Expr::Bin(Op::Mul, a, b) => match (has_sum(a), has_sum(b)) {
            (true, false) => coefficient_times_sum(a).map(|(c, s)| (Expr::Bin(Op::Mul, Box::new(c), b.clone()), s)),
            (false, true) => coefficient_times_sum(b).map(|(c, s)| (Expr::Bin(Op::Mul, a.clone(), Box::new(c)), s)),
            _ => None,
        },
        Expr::Bin(Op::Div, a, b) if !has_sum(b) => {
            coefficient_times_sum(a).map(|(c, s)| (Expr::Bin(Op::Div, Box::new(c), b.clone()), s))
        }
        _ => None,
    }
}

/// One sum of the claim: its coefficient, bounds and summand (over the common variable).
struct Part {
    coef: RatFunc,
    a: Aff,
    b: Aff,
    summand: Term,
}

/// Proves `lhs = rhs` on `d` when it is a recurrence of one sum (see the module
/// documentation): `Ok(None)` when the claim has another shape.
pub(crate) fn prove(tr: &mut Translator<'_>, lhs: &Expr, rhs: &Expr, d: &Domain) -> Result<Option<()>> {
    let mut all = Vec::new();
    parts(lhs, true, &mut all);
    parts(rhs, false, &mut all);
    let sym = tr.sym();
    let mut rest: Lin = Vec::new();
    let mut sums: Vec<Part> = Vec::new();
    let mut k: Option<String> = None;
    for (plus, e) in &all {
        if !has_sum(e) {
            let Ok(l) = tr.lin(e, d) else {
                return Ok(None);
            };
            rest.extend(if *plus { l } else { lin_neg(&l) });
            continue;
        }
        let Some((c, Expr::Sum(v, a, b, body))) = coefficient_times_sum(e) else {
            return Ok(None);
        };
        let Some(coef) = tr.scalar(&c, d) else {
            return Ok(None);
        };
        let coef = if *plus { coef } else { coef.neg() };
        let (Ok(a), Ok(b)) = (tr.affine(&a), tr.affine(&b)) else {
            return Ok(None);
        };
        let dk = d.with(Aff::var(&v).minus(&a)).with(b.minus(&Aff::var(&v)));
        let Ok(body) = tr.lin(&body, &dk) else {
            return Ok(None);
        };
        let [t] = &body[..] else {
            return Ok(None);
        };
        if !t.deltas.is_empty() || t.bdeg > 0 {
            return Ok(None);
        }
        let kk = k.get_or_insert_with(|| v.clone()).clone();
        if v != kk && t.mentions(sym, &kk) {
            // Renaming v to the first sum's variable would capture a free k.
            return Ok(None);
        }
        let summand = if v == kk {
            t.clone()
        } else {
            t.subst(sym, &v, &Aff::var(&kk))
        };
        sums.push(Part { coef, a, b, summand });
    }
    let (Some(k), Some(first)) = (k, sums.first()) else {
        return Ok(None);
    };
    // One lower bound; upper bounds b(n) + j_s with constant j_s ≥ 0 from the least. Else
    // two sums may be two forms of one sequence.
    let base = sums.iter().min_by_key(|p| p.b.c).expect("not empty");
    if sums.len() < 2 || sums.iter().any(|p| p.a != first.a || !p.b.minus(&base.b).is_const()) || first.a.coef(&k) != 0
    {
        return forms::two_forms(tr, &sums, &rest, &k, d);
    }
    let (a, b) = (first.a.clone(), base.b.clone());
    let Some(n) =
        b.v.iter()
            .filter(|(x, c)| **c == 1 && a.coef(x) == 0)
            .map(|(x, _)| x.clone())
            .next()
    else {
        return Ok(None);
    };
    let f = base.summand.clone();
    let what = format!("the recurrence of Σ_{{{k}={a}}}^{{{b}}}");
    let bounds = Bounds {
        k: &k,
        a: &a,
        b: &b,
        n: &n,
    };
    let parts: Vec<(RatFunc, Aff, Term)> = sums
        .iter()
        .map(|s| (s.coef.clone(), s.b.clone(), s.summand.clone()))
        .collect();
    let Some(stated) = recurrence::stated_sums(sym, &parts, &f, &bounds, d, &what, &mut tr.log)? else {
        return forms::two_forms(tr, &sums, &rest, &k, d);
    };
    if !d.implies_ge(&b.minus(&a).shifted(1)) {
        return Err(Error::Domain(format!("{what}: cannot show b − a ≥ −1 on {}", d.show())));
    }
    let rec = match telescope::find(sym, &f, &n, &k, Coefficients::Given(stated.coefficients())) {
        Ok(rec) => rec,
        // No certificate whose ends are the other terms: the recurrence may still hold, with
        // them its inhomogeneous part, for every n past a first value.
        Err(e) => {
            let mark = tr.log.len();
            return match forms::inhomogeneous(tr, &stated, &f, (&k, &a, &b), &rest, d, &what) {
                Ok(Some(())) => Ok(Some(())),
                _ => {
                    tr.log.truncate(mark);
                    Err(Error::Domain(format!("{what}: {e}")))
                }
            };
        }
    };
    let discharged = recurrence::check_stated_recurrence(sym, &stated, &f, &rec, &bounds, rest, d, &what, &mut tr.log)?;
    tr.evidence.push(discharged);
    tr.recurrences.push((
        Method::StatedRecurrence,
        format!(
            "{what}: creative telescoping: {} = G({n}, {}) − G({n}, {a}) + the terms past {b}, R = {}",
            rec.show("S", &n),
            b.shifted(1),
            rec.r
        ),
    ));
    Ok(Some(()))
}
