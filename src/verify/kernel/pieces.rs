//! Exact proofs that a finite sum of hypergeometric terms ([`super::hyper::Term`]) is zero
//! for every integer point of a polyhedral domain: the domain split by affine conditions
//! (Fourier–Motzkin with integer tightening), each piece divided by its first live term.

use super::checked::Step;
use super::eval::Alg;
use super::hyper::*;
use super::poly::{Poly, RatFunc};
use crate::error::{Error, Result};
use num_traits::{One, Signed};
use std::collections::{BTreeMap, BTreeSet};
/// Most constraints Fourier–Motzkin may hold while eliminating one variable (beyond it the
/// test answers "maybe feasible", which only costs splits, never soundness).
const MAX_FM: usize = 4_000;

// ---------------------------------------------------------------------------------------
// Domains: integer points of {x : a(x) ≥ 0 for every constraint}.

/// A domain: the integer points where every constraint is ≥ 0.
#[derive(Clone, Debug, Default)]
pub struct Domain {
    /// The constraints `a ≥ 0`.
    pub cons: Vec<Aff>,
}

impl Domain {
    /// The domain with one more constraint.
    pub fn with(&self, c: Aff) -> Domain {
        let mut d = self.clone();
        d.cons.push(c);
        d
    }
    /// The domain with `name` replaced by `by`.
    pub fn subst(&self, name: &str, by: &Aff) -> Domain {
        Domain {
            cons: self.cons.iter().map(|c| c.subst(name, by)).collect(),
        }
    }
    /// Whether the domain may have an integer point (false: it certainly has none).
    pub fn feasible(&self) -> bool {
        feasible(&self.cons)
    }
    /// Whether `a ≥ 0` at every integer point of the domain (a proof when true).
    pub fn implies_ge(&self, a: &Aff) -> bool {
        !self.with(a.scaled(-1).shifted(-1)).feasible()
    }
    /// Readable form.
    pub fn show(&self) -> String {
        if self.cons.is_empty() {
            return "every integer point".into();
        }
        self.cons
            .iter()
            .map(|c| format!("{c} ≥ 0"))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

fn gcd(a: i128, b: i128) -> i128 {
    let (mut a, mut b) = (a.abs(), b.abs());
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// Normalises `a·x + c ≥ 0` over the integers: divides by the gcd of `a`, rounding `c` down.
fn tighten(mut a: Vec<i128>, c: i128) -> (Vec<i128>, i128) {
    let g = a.iter().fold(0, |g, &x| gcd(g, x));
    if g > 1 {
        for x in &mut a {
            *x /= g;
        }
        return (a, c.div_euclid(g));
    }
    (a, c)
}

/// Fourier–Motzkin: false only when the constraints have no rational (so no integer) solution.
fn feasible(cons: &[Aff]) -> bool {
    let vars: Vec<String> = cons
        .iter()
        .flat_map(|c| c.v.keys().cloned())
        .collect::<BTreeSet<_>>()
        .into_iter()
        .collect();
    let mut rows: BTreeSet<(Vec<i128>, i128)> = cons
        .iter()
        .map(|c| {
            let a: Vec<i128> = vars.iter().map(|v| i128::from(c.coef(v))).collect();
            tighten(a, i128::from(c.c))
        })
        .collect();
    for k in 0..vars.len() {
        let (mut pos, mut neg, mut keep) = (Vec::new(), Vec::new(), BTreeSet::new());
        for r in rows {
            match r.0[k].signum() {
                1 => pos.push(r),
                -1 => neg.push(r),
                _ => {
                    keep.insert(r);
                }
            }
        }
        if pos.len() * neg.len() + keep.len() > MAX_FM {
            return true;
        }
        for (pa, pc) in &pos {
            for (na, nc) in &neg {
                let (x, y) = (pa[k], -na[k]);
                // y·p + x·q, checked: on overflow the test answers "maybe feasible", which
                // only costs splits, never soundness.
                let combine = |p: i128, q: i128| y.checked_mul(p)?.checked_add(x.checked_mul(q)?);
                let a: Option<Vec<i128>> = pa.iter().zip(na).map(|(p, q)| combine(*p, *q)).collect();
                let (Some(a), Some(c)) = (a, combine(*pc, *nc)) else {
                    return true;
                };
                if a.iter().chain(std::iter::once(&c)).any(|v| v.abs() > (1i128 << 100)) {
                    return true;
                }
                keep.insert(tighten(a, c));
            }
        }
        rows = keep;
    }
    rows.iter().all(|(_, c)| *c >= 0)
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Class {
    Always,
    Never,
    Mixed,
}

/// Whether the term `t`, which is defined only where `a ≥ 0`, is defined on all of `d`: an
/// error where it never is, a split where it is on part of `d`, `None` where it always is.
fn defined_split(d: &Domain, t: &Term, a: &Aff) -> Result<Option<Split>> {
    match class_ge(d, a) {
        Class::Never => Err(Error::Domain(format!(
            "the term {} is undefined where {a} < 0 (on {})",
            t.show(),
            d.show()
        ))),
        Class::Mixed => Ok(Some(Split::Ge(a.clone()))),
        Class::Always => Ok(None),
    }
}

fn class_ge(d: &Domain, a: &Aff) -> Class {
    if d.implies_ge(a) {
        Class::Always
    } else if !d.with(a.clone()).feasible() {
        Class::Never
    } else {
        Class::Mixed
    }
}

fn class_eq(d: &Domain, a: &Aff) -> Class {
    if a.is_const() {
        return if a.c == 0 { Class::Always } else { Class::Never };
    }
    if !d.with(a.clone()).with(a.scaled(-1)).feasible() {
        Class::Never
    } else if d.implies_ge(a) && d.implies_ge(&a.scaled(-1)) {
        Class::Always
    } else {
        Class::Mixed
    }
}

/// How `a = 0` is substituted: a variable with coefficient ±1 and its value.
fn solve_for(a: &Aff) -> Result<(String, Aff)> {
    let (name, k) =
        a.v.iter()
            .find(|(_, k)| k.abs() == 1)
            .map(|(n, k)| (n.clone(), *k))
            .ok_or_else(|| {
                Error::Domain(format!(
                    "cannot split the domain on {a} = 0: no variable has coefficient ±1"
                ))
            })?;
    let mut rest = a.clone();
    rest.v.remove(&name);
    // k·x + rest = 0 ⇒ x = −rest / k, with k = ±1.
    Ok((name, rest.scaled(-k)))
}

/// What [`prove_zero`] found.
#[derive(Clone, Debug)]
pub enum ZeroOutcome {
    /// Zero at every integer point of the domain; the number of pieces checked.
    Zero(usize),
    /// In this piece the quotient by the first live term is a nonzero rational function.
    NonZero {
        /// The piece.
        region: String,
        /// The nonzero numerator.
        residue: String,
    },
}

enum Split {
    Ge(Aff),
    Eq(Aff),
}

fn pick_split(lin: &[Term], d: &Domain, alive: &mut [bool]) -> Result<Option<Split>> {
    // What every term needs to be defined at all (a divisor that must not vanish).
    for t in lin {
        for a in &t.defined {
            if let Some(split) = defined_split(d, t, a)? {
                return Ok(Some(split));
            }
        }
    }
    // First the conditions that make a term vanish.
    for (t, live) in lin.iter().zip(alive.iter_mut()) {
        let zeroing = t
            .support
            .iter()
            .chain(t.facts.iter().filter(|(_, e)| *e < 0).map(|(a, _)| a));
        for a in zeroing {
            match class_ge(d, a) {
                Class::Never => *live = false,
                Class::Mixed => return Ok(Some(Split::Ge(a.clone()))),
                Class::Always => {}
            }
            if !*live {
                break;
            }
        }
        if !*live {
            continue;
        }
        for a in &t.deltas {
            match class_eq(d, a) {
                Class::Never => {
                    *live = false;
                    break;
                }
                Class::Mixed => return Ok(Some(Split::Eq(a.clone()))),
                Class::Always => {}
            }
        }
    }
    // Then, for the live terms, that their numerator factorials are defined.
    for (t, live) in lin.iter().zip(alive.iter()) {
        if !*live {
            continue;
        }
        for a in t.facts.iter().filter(|(_, e)| *e > 0).map(|(a, _)| a) {
            if let Some(split) = defined_split(d, t, a)? {
                return Ok(Some(split));
            }
        }
    }
    for t in lin {
        for a in &t.nonzero {
            match class_eq(d, a) {
                Class::Never => {}
                Class::Always => {
                    return Err(Error::DivisionByZero(format!(
                        "a division by {a}, which is 0 on {}",
                        d.show()
                    )))
                }
                Class::Mixed => return Ok(Some(Split::Eq(a.clone()))),
            }
        }
    }
    Ok(None)
}

/// Proves `Σ lin = 0` at every integer point of `d` (see the module documentation), logging
/// each piece to `log`.
pub fn prove_zero(sym: &Symbols, lin: &[Term], d: &Domain, log: &mut Vec<Step>) -> Result<ZeroOutcome> {
    let mut check =
        |live: &[&Term], _: &Domain, place: &str, log: &mut Vec<Step>| classes_cancel(sym, live, place, log);
    prove_pieces(sym, lin, d, log, &mut check)
}

/// What a piece must satisfy: given its live terms (every condition decided, every factorial
/// argument ≥ 0), the piece and its description, `None` when it does, else the reason.
pub type PieceCheck<'a> = dyn FnMut(&[&Term], &Domain, &str, &mut Vec<Step>) -> Result<Option<String>> + 'a;

/// Splits `d` into pieces on which every term of `lin` is decided, and runs `check` on each.
pub fn prove_pieces(
    sym: &Symbols,
    lin: &[Term],
    d: &Domain,
    log: &mut Vec<Step>,
    check: &mut PieceCheck<'_>,
) -> Result<ZeroOutcome> {
    let mut count = 0usize;
    let out = prove_rec(sym, lin.to_vec(), d.clone(), Vec::new(), log, &mut count, check)?;
    Ok(match out {
        None => ZeroOutcome::Zero(count),
        Some((region, residue)) => ZeroOutcome::NonZero { region, residue },
    })
}

type Found = Option<(String, String)>;

/// The work the pieces of one symbolic proof may take: Σ over the sums of similar terms of the
/// products of their coefficients' sizes in machine words (each product of two words of
/// rational coefficients is a few microseconds: a big-integer gcd), drawn from the claim's
/// budget (this much is all of it).
pub const MAX_PIECES_WORK: u128 = 500_000;

fn prove_rec(
    sym: &Symbols,
    lin: Lin,
    d: Domain,
    path: Vec<String>,
    log: &mut Vec<Step>,
    count: &mut usize,
    check: &mut PieceCheck<'_>,
) -> Result<Found> {
    if !d.feasible() {
        return Ok(None);
    }
    *count += 1;
    if *count > MAX_REGIONS {
        return Err(Error::TooLarge {
            what: "domain pieces of a symbolic proof",
            value: count.to_string(),
            limit: MAX_REGIONS.to_string(),
        });
    }
    let mut alive = vec![true; lin.len()];
    match pick_split(&lin, &d, &mut alive)? {
        Some(Split::Ge(a)) => {
            for piece in [a.clone(), a.scaled(-1).shifted(-1)] {
                let mut p = path.clone();
                p.push(format!("{piece} ≥ 0"));
                if let Some(found) = prove_rec(sym, lin.clone(), d.with(piece), p, log, count, check)? {
                    return Ok(Some(found));
                }
            }
            Ok(None)
        }
        Some(Split::Eq(a)) => {
            for piece in [a.shifted(-1), a.scaled(-1).shifted(-1)] {
                let mut p = path.clone();
                p.push(format!("{piece} ≥ 0"));
                if let Some(found) = prove_rec(sym, lin.clone(), d.with(piece), p, log, count, check)? {
                    return Ok(Some(found));
                }
            }
            let (x, by) = solve_for(&a)?;
            let mut p = path;
            p.push(format!("{x} = {by}"));
            let sub = lin_subst(sym, &lin, &x, &by);
            prove_rec(sym, sub, d.subst(&x, &by), p, log, count, check)
        }
        None => {
            // A piece that is thinner than it looks (i ≥ 0 and −i ≥ 0): substitute the
            // equality, so the rational identity is asked only where it must hold.
            let flat = d
                .cons
                .iter()
                .find(|c| !c.is_const() && d.implies_ge(&c.scaled(-1)) && c.v.values().any(|k| k.abs() == 1));
            if let Some(c) = flat {
                let (x, by) = solve_for(c)?;
                let mut p = path;
                p.push(format!("{x} = {by}"));
                let sub = lin_subst(sym, &lin, &x, &by);
                return prove_rec(sym, sub, d.subst(&x, &by), p, log, count, check);
            }
            if let Some(t) = lin.iter().zip(&alive).find(|(t, a)| **a && t.coef.den.is_zero()) {
                return Err(Error::DivisionByZero(format!(
                    "the term {} has the denominator 0 on {}",
                    t.0.show(),
                    d.show()
                )));
            }
            let live: Vec<&Term> = lin
                .iter()
                .zip(&alive)
                .filter(|(t, a)| **a && !t.coef.num.is_zero())
                .map(|(t, _)| t)
                .collect();
            let place = if path.is_empty() {
                d.show()
            } else {
                format!("{} (piece {})", d.show(), path.join(", "))
            };
            if live.is_empty() {
                log.push(Step::vanishes(place));
                return Ok(None);
            }
            Ok(check(&live, &d, &place, log)?.map(|why| (place, why)))
        }
    }
}

/// The live terms of a piece sum to zero: each class of similar terms (rational quotients)
/// cancels on its own (enough for the sum to vanish; a class that does not cancel is
/// reported, never taken as a disproof).
fn classes_cancel(sym: &Symbols, live: &[&Term], place: &str, log: &mut Vec<Step>) -> Result<Option<String>> {
    let mut classes: Vec<(&Term, RatFunc, usize)> = Vec::new();
    for t in live {
        let mut placed = false;
        for (first, total, size) in classes.iter_mut() {
            if let Some(r) = ratio(sym, t, first)? {
                // Each product of polynomials costs about the product of their sizes in words.
                let words = |f: &RatFunc| f.num.words() + f.den.words();
                let term = t.coef.mul(&r);
                let cost = words(&t.coef) * words(&r) + words(total) * words(&term);
                sym.budget
                    .draw("work of the pieces of a symbolic proof", cost, MAX_PIECES_WORK)?;
                *total = total.add(&term);
                *size += 1;
                placed = true;
                break;
            }
        }
        if !placed {
            classes.push((t, t.coef.clone(), 1));
        }
    }
    for (first, total, size) in &classes {
        if !total.num.is_zero() {
            return Ok(Some(format!(
                "the quotient's numerator is {} (the {size} terms similar to {})",
                total.num,
                first.show()
            )));
        }
    }
    log.push(Step::text(format!(
        "on {place}: {} live term{} in {} class{} of similar terms, each Σ T_j / T_0 = 0 identically",
        live.len(),
        if live.len() == 1 { "" } else { "s" },
        classes.len(),
        if classes.len() == 1 { "" } else { "es" },
    )));
    Ok(None)
}

/// The factorials of `H_t / H_0` grouped by linear part: for each, the constants of the
/// factorials upstairs (from `t`) and downstairs (from `first`).
type FactorialGroups = BTreeMap<BTreeMap<String, i64>, (Vec<i64>, Vec<i64>)>;

fn factorial_groups(t: &Term, first: &Term) -> FactorialGroups {
    let mut groups = FactorialGroups::new();
    let both = t
        .facts
        .iter()
        .map(|(a, e)| (a, *e))
        .chain(first.facts.iter().map(|(a, e)| (a, -*e)));
    for (a, e) in both {
        let g = groups.entry(a.linear()).or_default();
        if e > 0 {
            g.0.push(a.c);
        } else {
            g.1.push(a.c);
        }
    }
    groups
}

/// `H_t / H_0` (the factorial and power parts; the coefficients are not included), a rational
/// function valid where every factorial argument is ≥ 0; `None` when the terms are not similar.
pub fn ratio(sym: &Symbols, t: &Term, first: &Term) -> Result<Option<RatFunc>> {
    let mut out = RatFunc::from_int(1);
    let groups = factorial_groups(t, first);
    for (lin, (mut up, mut down)) in groups {
        if lin.is_empty() {
            for c in up {
                out = out.mul(&factorial(c)?);
            }
            for c in down {
                out = out.div(&factorial(c)?)?;
            }
            continue;
        }
        if up.len() != down.len() {
            // The factorials of this linear part do not pair: not a rational quotient.
            return Ok(None);
        }
        up.sort_unstable();
        down.sort_unstable();
        let l = Aff { c: 0, v: lin };
        for (p, q) in up.into_iter().zip(down) {
            // (L+p)! / (L+q)!
            let (lo, hi, inv) = if p >= q { (q, p, false) } else { (p, q, true) };
            let mut prod = RatFunc::from_int(1);
            for m in lo + 1..=hi {
                prod = prod.mul(&l.shifted(m).to_rf(sym));
            }
            out = if inv { out.div(&prod)? } else { out.mul(&prod) };
        }
    }
    // Powers: exponents per base must differ by constants.
    for (b, e) in power_quotient(sym, t, first)? {
        if !e.is_const() {
            return Ok(None);
        }
        out = out.mul(&b.to_rf().pow(e.c)?);
    }
    Ok(Some(out))
}

/// The powers of `H_t / H_0`, one per base with the exponents summed. A base with a symbolic
/// exponent that another base divides is split (`((1 − s)(1 − t))^e = (1 − s)^e (1 − t)^e`,
/// true for every integer `e`), so one product of powers written two ways is recognized as
/// one; each split lowers the total degree of the bases, so the splitting ends.
fn power_quotient(sym: &Symbols, t: &Term, first: &Term) -> Result<Vec<(Base, Aff)>> {
    let mut bases: Vec<(Base, Aff)> = Vec::new();
    fn add(bases: &mut Vec<(Base, Aff)>, b: &Base, e: Aff) {
        if let Some(slot) = bases.iter_mut().find(|(x, _)| x == b) {
            slot.1 = slot.1.plus(&e);
        } else {
            bases.push((b.clone(), e));
        }
    }
    for (b, e) in &t.pows {
        add(&mut bases, b, e.clone());
    }
    for (b, e) in &first.pows {
        add(&mut bases, b, e.scaled(-1));
    }
    loop {
        let split = bases.iter().enumerate().find_map(|(i, (p, e))| match p {
            Base::Poly(p) if !e.is_const() => bases.iter().enumerate().find_map(|(j, (q, _))| match q {
                Base::Poly(q) if j != i => p.exact_div(q).map(|rest| (i, j, rest)),
                _ => None,
            }),
            _ => None,
        });
        let Some((i, j, rest)) = split else {
            return Ok(super::powers::constant_bases(bases));
        };
        let divisor = bases[j].0.clone();
        let (_, e) = bases.remove(i);
        add(&mut bases, &divisor, e.clone());
        for (b, x) in power_of(sym, &rest, &e)? {
            add(&mut bases, &b, x);
        }
    }
}

/// The factors of the denominator of `H_t / H_0`: affine forms (from factorials) and
/// polynomials in the parameters (from powers with negative exponent differences).
pub fn ratio_denominator(sym: &Symbols, t: &Term, first: &Term) -> Result<(Vec<Aff>, Vec<Poly>)> {
    let groups = factorial_groups(t, first);
    let mut affs = Vec::new();
    for (lin, (mut up, mut down)) in groups {
        if lin.is_empty() || up.len() != down.len() {
            continue;
        }
        up.sort_unstable();
        down.sort_unstable();
        let l = Aff { c: 0, v: lin };
        for (p, q) in up.into_iter().zip(down) {
            for m in p + 1..=q {
                affs.push(l.shifted(m));
            }
        }
    }
    let mut polys = Vec::new();
    for (b, e) in power_quotient(sym, t, first)? {
        if let (Base::Poly(q), true) = (&b, e.is_const() && e.c < 0) {
            for _ in 0..e.c.unsigned_abs() {
                polys.push(q.clone());
            }
        }
    }
    Ok((affs, polys))
}

fn factorial(c: i64) -> Result<RatFunc> {
    if !(0..=super::expr::MAX_FACTORIAL).contains(&c) {
        return Err(Error::Domain(format!("factorial of {c}")));
    }
    let mut f = num_bigint::BigInt::one();
    for k in 2..=c {
        f *= k;
    }
    Ok(RatFunc::from_bigint(&f))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fourier_motzkin_decides_simple_domains() {
        let n = Aff::var("n");
        let i = Aff::var("i");
        // 0 ≤ i ≤ n and i ≥ n + 1: empty.
        let d = Domain {
            cons: vec![i.clone(), n.minus(&i), i.minus(&n).shifted(-1)],
        };
        assert!(!d.feasible());
        let d = Domain {
            cons: vec![i.clone(), n.minus(&i)],
        };
        assert!(d.feasible());
        assert!(d.implies_ge(&n));
        assert!(!d.implies_ge(&n.shifted(-1)));
        // 2i = 1 has no integer solution: 2i − 1 ≥ 0 and 1 − 2i ≥ 0 tighten to i ≥ 1, i ≤ 0.
        let d = Domain {
            cons: vec![i.scaled(2).shifted(-1), i.scaled(-2).shifted(1)],
        };
        assert!(!d.feasible());
    }

    #[test]
    fn a_divisor_registers_its_integer_zeros() {
        let sym = Symbols::new(&["n".into(), "m".into()], &["t".into()]);
        let v = |x: &str| sym.var(x);
        let c = |k: i64| RatFunc::from_int(k);
        let zeros = |r: RatFunc| {
            sym.integer_zeros(&r.num)
                .map(|z| z.iter().map(|a| a.to_string()).collect::<Vec<_>>())
        };
        // n (n − 1) t + n (n − 1): zero polynomial in t exactly at n = 0 and n = 1.
        let p = v("n").mul(&v("n").sub(&c(1))).mul(&v("t").add(&c(1)));
        assert_eq!(zeros(p).unwrap(), ["n", "n - 1"]);
        // (2n − 4) t: at n = 2; (n² + 1) t and (2n − 1) t: at no integer.
        assert_eq!(zeros(v("n").mul(&c(2)).sub(&c(4)).mul(&v("t"))).unwrap(), ["2n - 4"]);
        assert!(zeros(v("n").mul(&v("n")).add(&c(1)).mul(&v("t"))).unwrap().is_empty());
        assert!(zeros(v("n").mul(&c(2)).sub(&c(1)).mul(&v("t"))).unwrap().is_empty());
        // n t + m: zero only where n = m = 0 — one of its coefficients is constant-free, the
        // other (m) is affine: m ≠ 0 suffices.
        assert_eq!(zeros(v("n").mul(&v("t")).add(&v("m"))).unwrap(), ["m"]);
        // n m + 1 has no affine description that this finds: refused, never ignored.
        assert!(zeros(v("n").mul(&v("m")).add(&c(1)).mul(&v("t"))).is_err());
        assert!(zeros(c(0)).is_err());
    }
}
