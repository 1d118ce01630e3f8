//! Like terms gathered into one: terms that differ only in their coefficients, or also in
//! powers of one base whose exponents differ by constants (`i·t^(i−1)(1−t)^(n−i)` and
//! `(n−i)·t^i(1−t)^(n−i−1)`), become one hypergeometric term with a rational coefficient, so
//! that one WZ certificate can cover a summand of several terms. The gathered sum is only a
//! proposal: the caller has the kernel prove it equal to the terms it replaces.

use super::super::kernel::eval::Alg;
use super::super::kernel::hyper::{Aff, Base, Lin, Term};
use crate::error::Result;

/// `l` with like terms gathered (those whose coefficients cancel dropped); `l`'s own terms
/// where two of them cannot be written over one power product.
pub(super) fn gather(l: &[Term]) -> Result<Lin> {
    let mut out: Lin = Vec::new();
    for t in l {
        let mut placed = false;
        for o in out.iter_mut() {
            if let Some(shifts) = shifts(o, t) {
                *o = merged(o, t, &shifts)?;
                placed = true;
                break;
            }
        }
        if !placed {
            out.push(t.clone());
        }
    }
    out.retain(|t| !t.coef.num.is_zero());
    Ok(out)
}

/// The same elements, counted with multiplicity.
fn same_multiset<T: PartialEq>(a: &[T], b: &[T]) -> bool {
    a.len() == b.len()
        && a.iter()
            .all(|x| a.iter().filter(|y| *y == x).count() == b.iter().filter(|y| *y == x).count())
}

/// Powers with pairwise distinct bases (else `None`: they are not gathered).
fn distinct_bases(t: &Term) -> Option<&[(Base, Aff)]> {
    let p = &t.pows;
    p.iter()
        .enumerate()
        .all(|(i, (b, _))| p[..i].iter().all(|(c, _)| c != b))
        .then_some(p.as_slice())
}

/// Whether `a` and `b` agree but for their coefficients and constant shifts of the exponents
/// of the same bases; then `b`'s exponent minus `a`'s for each of `a`'s powers.
fn shifts(a: &Term, b: &Term) -> Option<Vec<i64>> {
    let same = same_multiset(&a.facts, &b.facts)
        && same_multiset(&a.support, &b.support)
        && same_multiset(&a.deltas, &b.deltas)
        && same_multiset(&a.defined, &b.defined)
        && same_multiset(&a.nonzero, &b.nonzero)
        && a.bdeg == b.bdeg;
    let (pa, pb) = (distinct_bases(a)?, distinct_bases(b)?);
    if !same || pa.len() != pb.len() {
        return None;
    }
    pa.iter()
        .map(|(base, e)| {
            let (_, f) = pb.iter().find(|(c, _)| c == base)?;
            let d = f.minus(e);
            d.is_const().then_some(d.c)
        })
        .collect()
}

/// `a + b` as one term: each base at the lesser exponent, the rest of each power moved into
/// the coefficient as a polynomial.
fn merged(a: &Term, b: &Term, shifts: &[i64]) -> Result<Term> {
    let mut out = a.clone();
    let (mut ca, mut cb) = (a.coef.clone(), b.coef.clone());
    for ((base, e), &s) in out.pows.iter_mut().zip(shifts) {
        let r = base.to_rf();
        if s >= 0 {
            cb = cb.mul(&r.pow(s)?);
        } else {
            ca = ca.mul(&r.pow(-s)?);
            *e = e.shifted(s);
        }
    }
    out.coef = ca.add(&cb);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::verify::kernel::hyper::Symbols;
    use crate::verify::kernel::poly::RatFunc;

    #[test]
    fn coefficients_add_and_shifted_powers_move_into_the_coefficient() {
        let sym = Symbols::new(&["n".into(), "i".into()], &["t".into()]);
        let t = Base::Poly(sym.var("t").num.clone());
        let term = |coef: RatFunc, e: Aff| Term {
            pows: vec![(t.clone(), e)],
            ..Term::scalar(coef)
        };
        let i = Aff::var("i");
        // i·t^(i−1) + n·t^i = (i + n·t)·t^(i−1)
        let g = gather(&[term(sym.var("i"), i.shifted(-1)), term(sym.var("n"), i.clone())]).unwrap();
        assert_eq!(g.len(), 1);
        assert_eq!(g[0].pows[0].1, i.shifted(-1));
        let want = sym.var("i").add(&sym.var("n").mul(&sym.var("t")));
        assert!(g[0].coef.sub(&want).num.is_zero(), "{}", g[0].coef);
        // opposite coefficients cancel; a symbolic shift is not gathered
        let g = gather(&[term(sym.var("n"), i.clone()), term(sym.var("n").neg(), i.clone())]).unwrap();
        assert!(g.is_empty());
        let g = gather(&[term(sym.var("n"), i.clone()), term(sym.var("n"), Aff::var("n"))]).unwrap();
        assert_eq!(g.len(), 2);
    }
}
