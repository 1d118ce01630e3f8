//! Facts about a sum's range used before its evaluation: where its terms start, a domain
//! without redundant bounds, and the ends of the parameter interval.

use super::super::kernel::hyper::{Aff, Term};
use super::super::kernel::pieces::Domain;
use super::super::kernel::poly::RatFunc;
use super::{UNIT, UNIT2};
use num_traits::{CheckedDiv, One, Zero};

/// Whether the polynomial `g` is the end `0` (`Some(false)`) or `1` (`Some(true)`) of the
/// parameter interval.
pub(super) fn end_point(g: &RatFunc) -> Option<bool> {
    let c = g.num.as_constant()?.checked_div(&g.den.as_constant()?)?;
    if c.is_zero() {
        Some(false)
    } else if c.is_one() {
        Some(true)
    } else {
        None
    }
}

/// The first index where a sum's terms can be nonzero: `X` when every term has the support
/// condition `v − X ≥ 0` or the factor `1/(v − X)!` (so is zero below `X`: `1/m! = 0` for a
/// negative integer `m`, as `C(r, j)` for `r < j`) and `a ≤ X ≤ b + 1` on the domain; else `a`.
pub(super) fn support_start(v: &str, a: &Aff, b: &Aff, terms: &[Term], d: &Domain) -> Aff {
    let Some(first) = terms.first() else {
        return a.clone();
    };
    let zero_below = |t: &Term, s: &Aff| {
        t.support.contains(s) || (t.facts.contains(&(s.clone(), -1)) && !t.facts.contains(&(s.clone(), 1)))
    };
    let candidates = first
        .support
        .iter()
        .chain(first.facts.iter().filter(|(_, e)| *e == -1).map(|(x, _)| x));
    for s in candidates.filter(|s| s.coef(v) == 1) {
        let start = Aff::var(v).minus(s);
        if start.coef(v) == 0
            && terms.iter().all(|t| zero_below(t, s))
            && d.implies_ge(&start.minus(a))
            && d.implies_ge(&b.minus(&start).shifted(1))
        {
            return start;
        }
    }
    a.clone()
}

/// The last index where a sum's terms can be nonzero: `X` when every term has the support
/// condition `X − v ≥ 0` (so is zero above `X`) and `a − 1 ≤ X ≤ b` on the domain; else `b`.
/// `Σ_{i=j}^{n+r} C(r, i − j) …` becomes `Σ_{i=j}^{j+r}`, whose bound has one open variable.
pub(super) fn support_end(v: &str, a: &Aff, b: &Aff, terms: &[Term], d: &Domain) -> Aff {
    let Some(first) = terms.first() else {
        return b.clone();
    };
    first
        .support
        .iter()
        .filter(|s| s.coef(v) == -1 && terms.iter().all(|t| t.support.contains(s)))
        .map(|s| s.plus(&Aff::var(v)))
        .find(|end| end.coef(v) == 0 && d.implies_ge(&b.minus(end)) && d.implies_ge(&end.minus(a).shifted(1)))
        .unwrap_or_else(|| b.clone())
}

/// `d` without the constraints that `pick` selects and the others imply through a constraint
/// on a unit index (the same integer points): the bounds `0 ≤ ĵ ≤ n` of the unit polygon's
/// index make a range's own `n ≥ 0` redundant, and a sum over `n` must see `n ≥ ĵ` alone. A
/// range's bounds as written are kept (they say which variable an induction runs on) unless
/// `any`: then every constraint the others imply goes (`n ≥ 0` beside `n ≥ j`, `j ≥ 0`).
pub(super) fn without_redundant(d: &Domain, any: bool, pick: impl Fn(&Aff) -> bool) -> Domain {
    let on_unit = |c: &Aff| c.coef(UNIT) != 0 || c.coef(UNIT2) != 0;
    let mut cons = d.cons.clone();
    let mut k = 0;
    while k < cons.len() {
        if pick(&cons[k]) && !on_unit(&cons[k]) {
            let others: Vec<Aff> = cons
                .iter()
                .enumerate()
                .filter(|(j, _)| *j != k)
                .map(|(_, c)| c.clone())
                .collect();
            let without_unit = Domain {
                cons: others.iter().filter(|c| !on_unit(c)).cloned().collect(),
            };
            let others = Domain { cons: others };
            if others.implies_ge(&cons[k]) && (any || !without_unit.implies_ge(&cons[k])) {
                cons.remove(k);
                continue;
            }
        }
        k += 1;
    }
    Domain { cons }
}

/// The terms as they are on the sum's range, where every condition the range implies holds:
/// those conditions (support, definedness) are dropped, and each pair `x! · 1/x!` with `x ≥ 0`
/// cancels. A WZ certificate times the terms is read one past the range (`G(n, b + 1)`); there
/// it keeps the value of its formula instead of a cut-off (`Σ_{k=0}^{r} C(r, k) …` reads
/// `C(r, r + 1)` through its shifted factorials) or an undefined pair (`B(i, n, t)/C(n, i)` at
/// `i = n + 1`). The sum's value is unchanged: on the range each dropped factor is 1.
pub(super) fn on_range(terms: &mut [Term], range: &Domain) {
    for t in terms {
        t.support.retain(|s| !range.implies_ge(s));
        t.defined.retain(|s| !range.implies_ge(s));
        let mut k = 0;
        while k < t.facts.len() {
            let (x, e) = t.facts[k].clone();
            let partner = t.facts.iter().position(|(y, f)| *y == x && *f == -e);
            match partner {
                Some(p) if range.implies_ge(&x) => {
                    let (hi, lo) = (k.max(p), k.min(p));
                    t.facts.remove(hi);
                    t.facts.remove(lo);
                    k = 0;
                }
                _ => k += 1,
            }
        }
    }
}
