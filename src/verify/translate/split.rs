//! A symbol of a sum's upper bound with two lower bounds, neither implied by the other
//! (`n ≥ 0` and `n ≥ j − 1` on `0 ≤ j ≤ n + 1`): the domain split by which bound is larger,
//! so that on each piece one bound holds alone and the induction runs from it.

use super::super::kernel::hyper::Aff;
use super::super::kernel::pieces::Domain;

/// A piece of the domain, with the symbol its constraints fix (`j ≥ 0` and `j ≤ 0`) and its
/// value there, if any: the caller puts it in.
pub(super) type Piece = (Domain, Option<(String, Aff)>);

/// The pieces of `d` (the feasible ones, at least one) on which the upper bound `b`'s symbol
/// `x` has one lower bound, the other dropped where it is implied; `None` unless `x` has
/// exactly two lower bounds `x ≥ L₁`, `x ≥ L₂` and the lower bound `a` is free of it. The
/// pieces `L₁ ≥ L₂` and `L₂ ≥ L₁ + 1` cover every integer point of `d`.
pub(super) fn by_lower_bound(d: &Domain, a: &Aff, b: &Aff) -> Option<Vec<Piece>> {
    b.v.iter()
        .filter(|(x, c)| **c == 1 && a.coef(x) == 0)
        .find_map(|(x, _)| pieces(d, x))
}

fn pieces(d: &Domain, x: &str) -> Option<Vec<Piece>> {
    let lower: Vec<&Aff> = d.cons.iter().filter(|c| c.coef(x) > 0).collect();
    let [c1, c2] = lower[..] else {
        return None;
    };
    if c1.coef(x) != 1 || c2.coef(x) != 1 {
        return None;
    }
    // x + r₁ ≥ 0 and x + r₂ ≥ 0: where r₂ ≥ r₁ the first implies the second.
    let (r1, r2) = (c1.minus(&Aff::var(x)), c2.minus(&Aff::var(x)));
    let mut out = Vec::new();
    for (keep, drop, order) in [(c1, c2, r2.minus(&r1)), (c2, c1, r1.minus(&r2).shifted(-1))] {
        let piece = d.with(order);
        if !piece.feasible() {
            continue;
        }
        let alone = Domain {
            cons: piece.cons.iter().filter(|c| *c != drop).cloned().collect(),
        };
        if !alone.implies_ge(drop) || !alone.cons.contains(keep) {
            return None;
        }
        out.extend(fixed(&alone, x));
    }
    (!out.is_empty()).then_some(out)
}

/// Most values of another symbol written out one by one in a piece where it is bounded by
/// constants.
const MAX_VALUES: i64 = 16;

/// A piece with the values of a symbol other than `x` that constants bound on it (`0 ≤ j ≤ 1`)
/// written out, each as its own piece (the sum's number of terms at the first value is then
/// fixed); the piece alone when there is none.
fn fixed(d: &Domain, x: &str) -> Vec<Piece> {
    let bound = |y: &str, sign: i64| {
        d.cons
            .iter()
            .filter(|c| c.v.len() == 1 && c.coef(y) == sign)
            .map(|c| -c.c * sign)
            .reduce(|p, q| if sign > 0 { p.max(q) } else { p.min(q) })
    };
    let pinned = d
        .cons
        .iter()
        .flat_map(|c| c.v.keys())
        .filter(|y| *y != x)
        .find_map(|y| {
            let (lo, hi) = (bound(y, 1)?, bound(y, -1)?);
            (hi - lo < MAX_VALUES).then(|| (y.clone(), lo, hi))
        });
    match pinned {
        Some((y, lo, hi)) => (lo..=hi)
            .map(|m| {
                let at = Aff::constant(m);
                (
                    d.with(Aff::var(&y).minus(&at)).with(at.minus(&Aff::var(&y))),
                    Some((y.clone(), at)),
                )
            })
            .collect(),
        None => vec![(d.clone(), None)],
    }
}
