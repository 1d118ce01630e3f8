//! The two routes of [`super::prove`] for claims whose sums are not one stated recurrence
//! proved by one certificate (issue 46, classes 2 and 3), both checked by the kernel's
//! creative telescoping for every `n ≥ n₀` (`kernel::recurrence`):
//!
//! - **two forms of one sequence**, `c₁ Σ_k F₁(n, k) + c₂ Σ_k F₂(n, k) + rest(n) = 0` with
//!   constants `c₁, c₂ ≠ 0` and different summands: a recurrence is searched for one sum, and a
//!   certificate of *the same* recurrence for the other; the kernel checks both telescoping
//!   equations, that the coefficients are equal, that `rest` satisfies the recurrence with the
//!   two sums' telescoped ends, and the initial values past the leading coefficient's zeros;
//! - **an inhomogeneous stated recurrence** `Σ_j q_j S(n+j) + rest(n) = 0` whose `rest` is no
//!   telescoped end of a certificate with the coefficients `q_j` (`S(n+1) − 2 S(n) = 2^n` for
//!   `S(n) = Σ_k k C(n, k)`): its sums are one sum of `h = Σ_j q_j F(n+j, k)` — a rational
//!   multiple of `F` — plus the terms past `b(n)`, so the claim is a closed form of `Σ_k h`,
//!   proved by `h`'s own recurrence.
//!
//! Only the search's proposals come from here; every identity is the kernel's to prove.

use super::super::kernel::checked::Method;
use super::super::kernel::eval::Alg;
use super::super::kernel::hyper::{lin_mul, Aff, Lin, Symbols, Term};
use super::super::kernel::pieces::{ratio, Domain};
use super::super::kernel::poly::RatFunc;
use super::super::kernel::recurrence::{self, Other, StatedSums, SumShape};
use super::super::telescope::{self, Coefficients};
use super::super::translate::Translator;
use super::Part;
use crate::error::{Error, Result};

/// The induction variable `n` of a sum `Σ_{k=a}^{n+c}`, its least value `n₀` on `d` and the
/// domain of the other integers: `None` unless `n` has one lower bound `n ≥ n₀` (free of the
/// others) and no upper bound.
fn induction(d: &Domain, a: &Aff, b: &Aff, k: &str) -> Option<(String, Aff, Domain)> {
    let n =
        b.v.iter()
            .find(|(x, c)| **c == 1 && a.coef(x) == 0 && x.as_str() != k)?
            .0
            .clone();
    let on_n: Vec<&Aff> = d.cons.iter().filter(|c| c.coef(&n) != 0).collect();
    let [low] = on_n[..] else { return None };
    if low.coef(&n) != 1 || low.v.len() != 1 {
        return None;
    }
    let n0 = Aff::constant(-low.c);
    let rest = Domain {
        cons: d.cons.iter().filter(|c| c.coef(&n) == 0).cloned().collect(),
    };
    Some((n, n0, rest))
}

/// Whether `c` is a nonzero constant.
fn constant(sym: &Symbols, c: &RatFunc) -> bool {
    let free = |p| !sym.poly_has_ints(p) && !sym.poly_has_conts(p);
    !c.num.is_zero() && free(&c.num) && free(&c.den)
}

/// Two sums of different summands (see the module documentation); `Ok(None)` when the claim
/// has another shape or is not proved so (the caller's reason stands, the log as it was).
pub(super) fn two_forms(
    tr: &mut Translator<'_>,
    sums: &[Part],
    rest: &[Term],
    k: &str,
    d: &Domain,
) -> Result<Option<()>> {
    let mark = tr.log.len();
    let out = try_two_forms(tr, sums, rest, k, d);
    if !matches!(out, Ok(Some(()))) {
        tr.log.truncate(mark);
    }
    Ok(out.ok().flatten())
}

fn try_two_forms(tr: &mut Translator<'_>, sums: &[Part], rest: &[Term], k: &str, d: &Domain) -> Result<Option<()>> {
    let sym = tr.sym();
    let [p1, p2] = sums else { return Ok(None) };
    if !constant(sym, &p1.coef) || !constant(sym, &p2.coef) {
        return Ok(None);
    }
    let Some((n, n0, dom)) = induction(d, &p1.a, &p1.b, k) else {
        return Ok(None);
    };
    if p2.b.coef(&n) != 1 || p2.a.coef(&n) != 0 {
        return Ok(None);
    }
    // c₁ S₁ + c₂ S₂ + rest = 0 as S₁ = (−c₂/c₁) S₂ + (−1/c₁) rest.
    let inv = RatFunc::from_int(1).div(&p1.coef)?.neg();
    let mut f2 = p2.summand.clone();
    f2.coef = f2.coef.mul(&p2.coef).mul(&inv);
    let rhs: Lin = lin_mul(&[Term::scalar(inv)], rest)?;
    let f1 = &p1.summand;
    let shape = SumShape {
        k,
        a: &p1.a,
        b: &p1.b,
        n: &n,
        n0: &n0,
        rest: &dom,
    };
    // The induction on n ≥ n₀ and the other integers' domain must cover the claim's domain.
    if !dom.with(Aff::var(&n).minus(&n0)).cons.iter().all(|c| d.implies_ge(c)) {
        return Ok(None);
    }
    let what = format!(
        "Σ_{{{k}={}}}^{{{}}} and Σ_{{{k}={}}}^{{{}}} (two forms of one sequence)",
        p1.a, p1.b, p2.a, p2.b
    );
    // A recurrence of either sum, and the other's certificate of the same one.
    let found = |first: &Term, second: &Term| -> Result<(_, _)> {
        let t = telescope::find(sym, first, &n, k, Coefficients::Search)?;
        let u = telescope::find(sym, second, &n, k, Coefficients::Given(&t.p))?;
        Ok((t, u))
    };
    let (t1, t2) = match found(f1, &f2) {
        Ok(pair) => pair,
        Err(e) => match found(&f2, f1) {
            Ok((t2, t1)) => (t1, t2),
            Err(_) => return Err(Error::Domain(format!("{what}: {e}"))),
        },
    };
    let other: Other<'_> = (&f2, &t2, &p2.a, &p2.b);
    let (discharged, text) =
        recurrence::check_telescoper(sym, f1, &t1, &shape, (&rhs, Some(&other)), &what, &mut tr.log)?;
    tr.evidence.push(discharged);
    tr.recurrences.push((
        Method::Telescoping,
        format!("{text}; the right sum by the same recurrence, R = {}", t2.r),
    ));
    Ok(Some(()))
}

/// A stated recurrence whose other terms are no telescoped ends (see the module
/// documentation), for every `n ≥ n₀`: `f` the summand of `S`, `stated` its coefficients.
#[allow(clippy::too_many_arguments)]
pub(super) fn inhomogeneous(
    tr: &mut Translator<'_>,
    stated: &StatedSums,
    f: &Term,
    (k, a, b): (&str, &Aff, &Aff),
    rest: &[Term],
    d: &Domain,
    what: &str,
) -> Result<Option<()>> {
    let sym = tr.sym();
    let Some((n, n0, dom)) = induction(d, a, b, k) else {
        return Ok(None);
    };
    // h = Σ_j q_j F(n+j, k) = F(n+J, k) · Σ_j q_j F(n+j, k)/F(n+J, k): over the factorials
    // of the highest shift the quotients have no pole in k (C(n, k)/C(n+1, k) = (n+1−k)/(n+1)),
    // so neither has h's certificate at the ends.
    let shift = |j: usize| f.subst(sym, &n, &Aff::var(&n).shifted(j as i64));
    let top = shift(stated.coefficients().len() - 1);
    let mut coef = RatFunc::from_int(0);
    for (j, q) in stated.coefficients().iter().enumerate() {
        let fj = shift(j);
        let Some(r) = ratio(sym, &fj, &top)? else {
            return Ok(None);
        };
        coef = coef.add(&q.mul(&fj.coef).mul(&r));
    }
    if coef.num.is_zero() {
        return Ok(None);
    }
    let h = Term { coef, ..top };
    let shape = SumShape {
        k,
        a,
        b,
        n: &n,
        n0: &n0,
        rest: &dom,
    };
    let what = format!("{what}, inhomogeneous: Σ_{k} h({n}, {k}) with h = Σ_j q_j F({n}+j, {k})");
    let t = telescope::find(sym, &h, &n, k, Coefficients::Search).map_err(|e| Error::Domain(format!("{what}: {e}")))?;
    let (discharged, text) =
        recurrence::check_inhomogeneous(sym, (stated, f, &h), &t, &shape, rest, d, &what, &mut tr.log)?;
    tr.evidence.push(discharged);
    tr.recurrences.push((Method::Telescoping, text));
    Ok(Some(()))
}
