//! Creative telescoping (Zeilberger's method, found by a bounded ansatz): a recurrence in `n`
//! with polynomial coefficients for a sum `S(n) = Σ_{k=a}^{b(n)} F(n, k)` of one
//! hypergeometric term, and the identities that prove a closed form from it.
//!
//! The search looks for polynomials `p_0(n), …, p_J(n)` (in every symbol but `k`, so also in
//! the continuous parameters) and a certificate `G = R·F` with
//!
//! `Σ_j p_j(n) F(n+j, k) = G(n, k+1) − G(n, k)`.
//!
//! Divided by `F(n, k)` this is `Σ_j p_j r_j = R(k+1)·F(n, k+1)/F(n, k) − R(k)` with
//! `r_j = F(n+j, k)/F(n, k)` rational ([`super::kernel::pieces::ratio`]). `R = P / (D·c)`: `D` the
//! factors of the denominator of `r_J` (the factorials of `F` that grow with `n`, as in
//! Gosper's algorithm), `c` the numerator of `F`'s rational coefficient (so `G` is `P` times
//! `F` without it), and `P` a polynomial with unknown coefficients, like the `p_j`. Cleared of
//! denominators it is a linear system over `Q`, row-reduced exactly; its solutions with some
//! `p_j ≠ 0` are candidates. With the `p_j` given ([`Coefficients::Given`]), only `P` is
//! unknown (a claim that *states* a recurrence).
//!
//! Nothing found here is trusted: the kernel (`kernel::recurrence`) builds from a candidate
//! the identities that prove a closed form (the telescoping equation, the telescoped ends, the
//! initial values past the leading coefficient's zeros) and proves each on every piece of the
//! domain; a wrong candidate can only be rejected.

use super::ansatz::solve;
use super::kernel::eval::Alg;
use super::kernel::hyper::{Aff, Symbols, Term};
use super::kernel::pieces::{ratio, ratio_denominator};
use super::kernel::poly::{Poly, RatFunc};
use super::kernel::recurrence::Telescoper;
use crate::error::{Error, Result};
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// Highest order `J` of the recurrence searched.
pub const MAX_ORDER: usize = 3;
/// Highest total degree of the coefficients `p_j` searched.
pub const MAX_COEFFICIENT_DEGREE: u32 = 4;
/// Most unknowns in one linear system of the search.
pub const MAX_UNKNOWNS: usize = 400;
/// The work the search may spend over all orders and degrees (about a microsecond each): the
/// polynomial terms it builds (16 per term), and Σ nonzero coefficients × min(rows, columns) ×
/// (64-bit words of the largest coefficient) of its linear systems (a 32nd of it for the
/// modular pass that rules most of them out).
pub const MAX_TELESCOPE_WORK: u128 = 5_000_000;
/// The coefficients `p_j` of the recurrence: searched, or given by the claim.
pub enum Coefficients<'a> {
    /// Unknown, up to [`MAX_ORDER`] and [`MAX_COEFFICIENT_DEGREE`].
    Search,
    /// `p_0, …, p_J` as stated.
    Given(&'a [RatFunc]),
}

/// The exponent vectors of `p` over every symbol (a constant built without names has none).
fn terms(sym: &Symbols, p: &Poly) -> Vec<(Vec<u16>, BigRational)> {
    p.terms_in(sym.names.len()).into_iter().collect()
}

fn total_degree(sym: &Symbols, p: &Poly) -> u32 {
    terms(sym, p)
        .iter()
        .map(|(e, _)| e.iter().map(|&x| u32::from(x)).sum())
        .max()
        .unwrap_or(0)
}

/// Exponent vectors of total degree ≤ `deg` in the variables `vars` (indices), 0 elsewhere.
fn monomials(width: usize, vars: &[usize], deg: u32) -> Vec<Vec<u16>> {
    let mut out = vec![vec![0u16; width]];
    for &v in vars {
        let mut next = Vec::new();
        for m in &out {
            let used: u32 = m.iter().map(|&x| u32::from(x)).sum();
            for e in 0..=(deg - used) {
                let mut m2 = m.clone();
                m2[v] = e as u16;
                next.push(m2);
            }
        }
        out = next;
    }
    out
}

fn monomial(sym: &Symbols, e: &[u16]) -> Poly {
    let mut m = Poly::constant(&sym.names, &BigRational::one());
    for (k, &x) in e.iter().enumerate() {
        for _ in 0..x {
            m = m.mul(&Poly::var(&sym.names, k));
        }
    }
    m
}

fn one(sym: &Symbols) -> Poly {
    Poly::constant(&sym.names, &BigRational::one())
}

/// `g / f` as a rational function (coefficients included), `None` when not similar.
fn quotient(sym: &Symbols, g: &Term, f: &Term) -> Result<Option<RatFunc>> {
    Ok(match ratio(sym, g, f)? {
        Some(r) => Some(g.coef.mul(&r).div(&f.coef)?),
        None => None,
    })
}

/// Multiplies (`up`) or divides the term by the affine factor `a`, cancelling against a
/// factorial when one fits: `a / a! = 1/(a−1)!`, `a · (a−1)! = a!`, `1/(a · (a−1)!) = 1/a!`,
/// `a!/a = (a−1)!`; a divisor that cancels nothing becomes a `nonzero` condition.
pub(crate) fn cancel(t: &mut Term, a: &Aff, up: bool, sym: &Symbols) {
    let find = |t: &Term, arg: &Aff, e: i8| t.facts.iter().position(|(x, s)| x == arg && *s == e);
    if up {
        if let Some(p) = find(t, a, -1) {
            t.facts[p].0 = a.shifted(-1);
        } else if let Some(p) = find(t, &a.shifted(-1), 1) {
            t.facts[p].0 = a.clone();
        } else {
            t.coef = t.coef.mul(&a.to_rf(sym));
        }
    } else if let Some(p) = find(t, &a.shifted(-1), -1) {
        t.facts[p].0 = a.clone();
    } else if let Some(p) = find(t, a, 1) {
        t.facts[p].0 = a.shifted(-1);
    } else {
        t.coef = RatFunc {
            num: t.coef.num.clone(),
            den: t.coef.den.mul(&a.to_rf(sym).num),
        };
        t.nonzero.push(a.clone());
    }
}

/// What one order of the search works with: the quotients and the certificate's denominator.
struct Shifts {
    /// `r_j = F(n+j, k)/F(n, k)`, j = 0..=J.
    r: Vec<RatFunc>,
    /// `F(n, k+1)/F(n, k)`.
    r2: RatFunc,
    /// The affine factors of `D` (cancelled against factorials in `G`).
    affs: Vec<Aff>,
    /// The polynomial factors of `D` (in the parameters).
    polys: Vec<Poly>,
    /// `D·c` as a rational function, and at `k + 1`.
    dc: RatFunc,
    dc1: RatFunc,
}

fn shifts(sym: &Symbols, f: &Term, n: &str, k: &str, order: usize) -> Result<Shifts> {
    let not_hyper = || Error::Domain("the summand is not hypergeometric in n and k".into());
    let mut r = Vec::with_capacity(order + 1);
    for j in 0..=order {
        let fj = f.subst(sym, n, &Aff::var(n).shifted(j as i64));
        r.push(quotient(sym, &fj, f)?.ok_or_else(not_hyper)?);
    }
    let k1 = f.subst(sym, k, &Aff::var(k).shifted(1));
    let r2 = quotient(sym, &k1, f)?.ok_or_else(not_hyper)?;
    let fj = f.subst(sym, n, &Aff::var(n).shifted(order as i64));
    let (affs, polys) = ratio_denominator(sym, &fj, f)?;
    let mut dc = RatFunc::poly(f.coef.num.clone());
    for a in &affs {
        dc = dc.mul(&a.to_rf(sym));
    }
    for p in &polys {
        dc = dc.mul(&RatFunc::poly(p.clone()));
    }
    let dc1 = sym.subst_rf(&dc, k, &Aff::var(k).shifted(1));
    Ok(Shifts {
        r,
        r2,
        affs,
        polys,
        dc,
        dc1,
    })
}

/// A common multiple `M` of the denominators (their product, skipping those that already
/// divide it) and the cofactor `M / d` of each.
fn cofactors(sym: &Symbols, dens: &[&Poly]) -> Result<Vec<Poly>> {
    let mut m = one(sym);
    for d in dens {
        if m.exact_div(d).is_none() {
            m = m.mul(d);
        }
    }
    dens.iter()
        .map(|d| {
            m.exact_div(d).ok_or_else(|| {
                Error::Domain("creative telescoping: a denominator does not divide their product".into())
            })
        })
        .collect()
}

/// Adds `cost` to the search's work (and draws it from the claim's budget), or stops it at
/// [`MAX_TELESCOPE_WORK`].
fn charge(sym: &Symbols, work: &mut u128, cost: u128, what: &str) -> Result<()> {
    *work = work.saturating_add(cost);
    if *work > MAX_TELESCOPE_WORK {
        return Err(Error::TooLarge {
            what:
                "creative telescoping work (polynomial terms built, nonzero coefficients × pivots × words eliminated)",
            value: format!("{} ({what})", *work),
            limit: MAX_TELESCOPE_WORK.to_string(),
        });
    }
    // The search's own limit first (its message names it), then the claim's.
    sym.budget
        .draw("work of creative telescoping", cost, MAX_TELESCOPE_WORK)
}

fn poly_of(sym: &Symbols, monos: &[Vec<u16>], x: &[BigRational]) -> Poly {
    let mut p = Poly::constant(&sym.names, &BigRational::zero());
    for (e, c) in monos.iter().zip(x) {
        if !c.is_zero() {
            p = RatFunc::poly(p)
                .add(&RatFunc::poly(monomial(sym, e).mul(&Poly::constant(&sym.names, c))))
                .num;
        }
    }
    p
}

/// Scales `x` so that its first `count` entries are integers with gcd 1, the last nonzero of
/// them positive (the leading coefficient of the recurrence, for a readable certificate).
fn normalise(x: &mut [BigRational], count: usize) {
    let head = &x[..count];
    let l = head.iter().fold(BigInt::one(), |l, c| l.lcm(c.denom()));
    let g = head
        .iter()
        .filter(|c| !c.is_zero())
        .fold(BigInt::zero(), |g, c| g.gcd(&(c.numer() * (&l / c.denom()))));
    if g.is_zero() {
        return;
    }
    let sign = head
        .iter()
        .rev()
        .find(|c| !c.is_zero())
        .map_or(1, |c| if c.is_negative() { -1 } else { 1 });
    let s = BigRational::new(l * sign, g);
    for v in x.iter_mut() {
        *v = &*v * &s;
    }
}

/// Builds `G = P / (D·c) · F` as a term: `F` with its coefficient's numerator replaced by `P`,
/// the affine factors of `D` cancelled against its factorials.
fn certificate_term(sym: &Symbols, f: &Term, sh: &Shifts, p: &Poly) -> Result<(Term, String)> {
    let mut g = f.clone();
    g.coef = RatFunc {
        num: p.clone(),
        den: f.coef.den.clone(),
    };
    for a in &sh.affs {
        cancel(&mut g, a, false, sym);
    }
    for q in &sh.polys {
        g.coef = g.coef.div(&RatFunc::poly(q.clone()))?;
    }
    let mut den: Vec<String> = sh.affs.iter().map(|a| format!("({a})")).collect();
    den.extend(sh.polys.iter().map(|q| format!("({q})")));
    if f.coef.num.as_constant().is_none_or(|c| !c.is_one()) {
        den.push(format!("({})", f.coef.num));
    }
    let text = if den.is_empty() {
        format!("{p}")
    } else {
        format!("({p})/({})", den.join("*"))
    };
    Ok((g, text))
}

/// Finds the recurrence and certificate of `Σ_k F(n, k)` (see the module documentation), or
/// says how far the search went.
pub fn find(sym: &Symbols, f: &Term, n: &str, k: &str, coefficients: Coefficients<'_>) -> Result<Telescoper> {
    let none = |why: String| Error::Domain(format!("creative telescoping found no recurrence: {why}"));
    if f.coef.num.is_zero() {
        return Err(none("the summand is 0".into()));
    }
    let width = sym.names.len();
    let kx = sym
        .index(k)
        .ok_or_else(|| none(format!("{k} is not a symbol of the claim")))?;
    let all: Vec<usize> = (0..width).collect();
    let not_k: Vec<usize> = (0..width).filter(|&x| x != kx).collect();
    let mut work = 0u128;
    let mut reached = String::from("nothing searched");
    let orders: Vec<usize> = match &coefficients {
        Coefficients::Search => (1..=MAX_ORDER).collect(),
        Coefficients::Given(p) if !p.is_empty() => vec![p.len() - 1],
        Coefficients::Given(_) => return Err(none("no coefficients".into())),
    };
    let degrees: Vec<u32> = match &coefficients {
        Coefficients::Search => (0..=MAX_COEFFICIENT_DEGREE).collect(),
        Coefficients::Given(_) => vec![0],
    };
    for &order in &orders {
        let sh = shifts(sym, f, n, k, order).map_err(|e| none(e.to_string()))?;
        let deg_d = total_degree(sym, &sh.dc.num);
        // The denominators: of each r_j, of the certificate's part (D·c)(k)·(D·c)(k+1)·r2.den,
        // and of the given part; the system is multiplied by a common multiple of them.
        let q_den = sh.dc.num.mul(&sh.dc1.num).mul(&sh.r2.den);
        let given_rf = match &coefficients {
            Coefficients::Given(p) => {
                let mut s = RatFunc::from_int(0);
                for (pj, rj) in p.iter().zip(&sh.r) {
                    s = s.add(&pj.mul(rj));
                }
                Some(s)
            }
            Coefficients::Search => None,
        };
        let mut dens: Vec<&Poly> = sh.r.iter().map(|r| &r.den).collect();
        dens.push(&q_den);
        if let Some(g) = &given_rf {
            dens.push(&g.den);
        }
        let cof = cofactors(sym, &dens)?;
        let cof_r = &cof[..sh.r.len()];
        let cof_q = &cof[sh.r.len()];
        let cert_a = sh.dc.den.mul(&sh.dc1.num).mul(&sh.r2.den).mul(cof_q);
        let cert_b = sh.dc1.den.mul(&sh.r2.num).mul(&sh.dc.num).mul(cof_q);
        let given = given_rf.map(|g| g.num.mul(&cof[sh.r.len() + 1]));
        let extra: Vec<u32> = match &coefficients {
            Coefficients::Search => vec![1],
            Coefficients::Given(_) => (0..=MAX_COEFFICIENT_DEGREE + 2).collect(),
        };
        for &dp in &degrees {
            for &x in &extra {
                let d_cert = deg_d + dp + x;
                let pmonos = match &coefficients {
                    Coefficients::Search => monomials(width, &not_k, dp),
                    Coefficients::Given(_) => Vec::new(),
                };
                let cmonos = monomials(width, &all, d_cert);
                let unknowns = (order + 1) * pmonos.len() + cmonos.len();
                if unknowns > MAX_UNKNOWNS {
                    return Err(none(format!(
                        "{reached}; at order {order}, coefficient degree {dp} and certificate degree {d_cert}: {unknowns} unknowns, more than MAX_UNKNOWNS = {MAX_UNKNOWNS}"
                    )));
                }
                // Building the columns: each multiplies a monomial into these products.
                let size = |p: &Poly| p.len() as u128;
                let build = (cmonos.len() as u128) * (size(&cert_a) + size(&cert_b))
                    + (pmonos.len() as u128)
                        * cof_r
                            .iter()
                            .zip(&sh.r)
                            .map(|(c, r)| size(c) * size(&r.num))
                            .sum::<u128>();
                charge(sym, &mut work, 16 * build, &format!("building the system of order {order}, coefficient degree {dp}, certificate degree {d_cert}")).map_err(|e| {
                    none(format!("{reached}; stopped at order {order}, coefficient degree {dp}, certificate degree {d_cert}: {e}"))
                })?;
                let mut cols = Vec::with_capacity(unknowns);
                for (r, cof) in sh.r.iter().zip(cof_r) {
                    let base = r.num.mul(cof);
                    cols.extend(pmonos.iter().map(|e| monomial(sym, e).mul(&base)));
                }
                // −R(k+1)·r2 + R(k) with R = m/(D·c), over the common denominator.
                for e in &cmonos {
                    let m = monomial(sym, e);
                    let m1 = sym.subst_poly(&m, k, &Aff::var(k).shifted(1));
                    cols.push(RatFunc::poly(m.mul(&cert_a)).cleared_difference(&RatFunc::poly(m1.mul(&cert_b))));
                }
                let first_free = (order + 1) * pmonos.len();
                let found = solve(sym, &cols, given.as_ref(), first_free, &mut |cost, what| {
                    charge(sym, &mut work, cost, what)
                })
                .map_err(|e| {
                    none(format!(
                        "{reached}; stopped at order {order}, coefficient degree {dp}, certificate degree {d_cert}: {e}"
                    ))
                })?;
                reached = match &coefficients {
                    Coefficients::Search => format!(
                        "none of order ≤ {order} with coefficients of degree ≤ {dp} (certificate numerators of degree ≤ {d_cert})"
                    ),
                    Coefficients::Given(_) => {
                        format!("no certificate numerator of degree ≤ {d_cert} for the stated recurrence")
                    }
                };
                let Some(mut x) = found else { continue };
                let p: Vec<RatFunc> = match &coefficients {
                    Coefficients::Search => {
                        normalise(&mut x, first_free);
                        (0..=order)
                            .map(|j| {
                                let part = &x[j * pmonos.len()..(j + 1) * pmonos.len()];
                                RatFunc::poly(poly_of(sym, &pmonos, part))
                            })
                            .collect()
                    }
                    Coefficients::Given(p) => p.to_vec(),
                };
                // The order actually used: the last nonzero coefficient.
                let top = p.iter().rposition(|q| !q.num.is_zero()).unwrap_or(0);
                let p = p[..=top].to_vec();
                let cert = poly_of(sym, &cmonos, &x[first_free..]);
                let (g, r) = certificate_term(sym, f, &sh, &cert)?;
                return Ok(Telescoper { p, g, r });
            }
        }
    }
    Err(none(format!(
        "{reached} (MAX_ORDER = {MAX_ORDER}, MAX_COEFFICIENT_DEGREE = {MAX_COEFFICIENT_DEGREE})"
    )))
}
