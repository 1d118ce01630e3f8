//! Finding a WZ certificate when the claim gives none: an ansatz `R = P / D` solved by exact
//! linear algebra.
//!
//! For one term `F`, the quotients `r1 = F(n+1, k)/F(n, k)` and `r2 = F(n, k+1)/F(n, k)` are
//! rational functions ([`super::pieces::ratio`]). The WZ equation divided by `F(n, k)` is
//! `r1 − 1 = R(k+1)·r2 − R(k)`. The denominator `D` is guessed as the denominator factors of `r1`
//! (the factorials of `F` that grow with `n`, as in Gosper's algorithm), and the numerator `P` as
//! a polynomial of total degree ≤ [`MAX_DEGREE`] in every symbol and parameter with unknown
//! rational coefficients; clearing denominators gives a linear system over `Q`, row-reduced
//! exactly. A solution is only a candidate: it is returned as an expression and checked like a
//! given certificate (the WZ equation on the whole range with its boundary pieces, the ends, the
//! base case), so the search can fail to find a certificate but never proves anything itself.

use super::eval::Alg;
use super::expr::Expr;
use super::hyper::{Aff, Symbols, Term};
use super::parse;
use super::pieces::{ratio, ratio_denominator};
use super::poly::{Poly, RatFunc};
use crate::error::{Error, Result};
use crate::linalg::row_reduce;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::collections::BTreeMap;

mod modular;

/// How much cheaper a modular pass is counted than exact elimination.
const MODULAR_DISCOUNT: u128 = 32;

/// Largest total degree of the numerator tried.
pub const MAX_DEGREE: u32 = 6;
/// Most unknown coefficients in one ansatz.
const MAX_UNKNOWNS: usize = 400;

/// The work the search may spend over all degrees: Σ nonzero coefficients × min(rows, columns)
/// × (64-bit words of the largest coefficient) of its linear systems.
pub const MAX_ANSATZ_WORK: u128 = 100_000_000;

/// The polynomial terms the equations of one degree may hold (memory).
pub const MAX_ANSATZ_TERMS: usize = 400_000;

fn monomials(vars: usize, deg: u32) -> Vec<Vec<u16>> {
    let mut out = vec![Vec::new()];
    for _ in 0..vars {
        let mut next = Vec::new();
        for m in &out {
            let used: u32 = m.iter().map(|&x| u32::from(x)).sum();
            for e in 0..=(deg - used) {
                let mut m2 = m.clone();
                m2.push(e as u16);
                next.push(m2);
            }
        }
        out = next;
    }
    out
}

fn monomial(sym: &Symbols, e: &[u16]) -> RatFunc {
    let mut m = RatFunc::from_int(1);
    for (k, &x) in e.iter().enumerate() {
        for _ in 0..x {
            m = m.mul(&sym.var(&sym.names[k]));
        }
    }
    m
}

fn show_monomial(sym: &Symbols, e: &[u16]) -> String {
    let parts: Vec<String> = e
        .iter()
        .enumerate()
        .filter(|(_, &x)| x > 0)
        .map(|(k, &x)| {
            if x == 1 {
                sym.names[k].clone()
            } else {
                format!("{}^{x}", sym.names[k])
            }
        })
        .collect();
    if parts.is_empty() {
        "1".into()
    } else {
        parts.join("*")
    }
}

/// The cost of eliminating the `width` columns of `a`: each of at most min(rows, columns)
/// pivots updates the nonzero entries, on numbers of the largest entry's words.
pub(super) fn elimination_work(a: &[Vec<BigRational>], width: usize) -> u128 {
    let nonzero = a.iter().flatten().filter(|x| !x.is_zero()).count() as u128;
    let words = a
        .iter()
        .flatten()
        .map(|x| x.numer().bits() + x.denom().bits())
        .max()
        .unwrap_or(0)
        / 64
        + 1;
    nonzero * a.len().min(width) as u128 * u128::from(words)
}

/// A candidate certificate `R` for `Σ_k F(n, k)` with `F` one term, or an error saying why none
/// was found.
pub fn find(sym: &Symbols, f: &Term, n: &str, k: &str) -> Result<Expr> {
    let none = |why: String| Error::Domain(format!("no WZ certificate given, and none found: {why}"));
    if f.coef.num.is_zero() {
        return Err(none("the summand is 0".into()));
    }
    let n1 = f.subst(sym, n, &Aff::var(n).shifted(1));
    let k1 = f.subst(sym, k, &Aff::var(k).shifted(1));
    let quotient = |g: &Term| -> Result<Option<RatFunc>> {
        Ok(match ratio(sym, g, f)? {
            Some(r) => Some(g.coef.mul(&r).div(&f.coef)?),
            None => None,
        })
    };
    let (Some(r1), Some(r2)) = (quotient(&n1)?, quotient(&k1)?) else {
        return Err(none("the summand is not hypergeometric in n and k".into()));
    };
    let (affs, polys) = ratio_denominator(sym, &n1, f)?;
    let mut d = RatFunc::from_int(1);
    let mut d_text: Vec<String> = Vec::new();
    for a in &affs {
        d = d.mul(&a.to_rf(sym));
        d_text.push(format!("({a})"));
    }
    for p in &polys {
        d = d.mul(&RatFunc::poly(p.clone()));
        d_text.push(format!("({p})"));
    }
    let d1 = sym.subst_rf(&d, k, &Aff::var(k).shifted(1));
    let e0 = r1.sub(&RatFunc::from_int(1));
    let mut work: u128 = 0;
    let mut searched: Option<u32> = None;
    let mut stopped = None;
    'degree: for deg in 0..=MAX_DEGREE {
        let monos = monomials(sym.names.len(), deg);
        if monos.len() > MAX_UNKNOWNS {
            stopped = Some(format!(
                "{} unknowns, more than MAX_UNKNOWNS = {MAX_UNKNOWNS}",
                monos.len()
            ));
            break;
        }
        // E_i = m_i/D − m_i(k+1)/D(k+1) · r2; Σ c_i E_i = −E_0.
        let mut es: Vec<RatFunc> = Vec::with_capacity(monos.len());
        let mut terms = 0usize;
        for e in &monos {
            let m = monomial(sym, e);
            let m1 = sym.subst_rf(&m, k, &Aff::var(k).shifted(1));
            let a = m.div(&d)?;
            let b = m1.div(&d1)?.mul(&r2);
            let x = a.sub(&b);
            terms += x.num.len() + x.den.len();
            if terms > MAX_ANSATZ_TERMS {
                stopped = Some(format!(
                    "its equations hold more than MAX_ANSATZ_TERMS = {MAX_ANSATZ_TERMS} polynomial terms"
                ));
                break 'degree;
            }
            es.push(x);
        }
        let q = es[0].den.clone();
        if es.iter().any(|x| x.den != q) {
            return Err(none("the ansatz's denominators differ".into()));
        }
        // Σ c_i E_i.num · E0.den = −E0.num · Q, coefficient by coefficient.
        let cols: Vec<Poly> = es.iter().map(|x| x.num.mul(&e0.den)).collect();
        let rhs = e0.num.mul(&q);
        let mut over = None;
        let mut charge = |cost: u128, what: &str| -> Result<()> {
            work = work.saturating_add(cost);
            if work > MAX_ANSATZ_WORK {
                over = Some(format!(
                    "its linear system ({what}) passes MAX_ANSATZ_WORK = {MAX_ANSATZ_WORK} (nonzero coefficients × pivots × words, over all degrees)"
                ));
                return Err(Error::Domain("the search's work limit".into()));
            }
            // The search's own limit first (its message names it), then the claim's.
            sym.budget
                .draw("work of the WZ certificate search", cost, MAX_ANSATZ_WORK)
        };
        let found = solve(sym, &cols, Some(&rhs), 0, &mut charge);
        if let Some(why) = over {
            stopped = Some(why);
            break;
        }
        searched = Some(deg);
        let Some(c) = found? else {
            continue;
        };
        if c.iter().all(Zero::is_zero) && !e0.num.is_zero() {
            continue;
        }
        let terms: Vec<String> = monos
            .iter()
            .zip(&c)
            .filter(|(_, x)| !x.is_zero())
            .map(|(e, x)| {
                let m = show_monomial(sym, e);
                if x.is_one() {
                    m
                } else if (-x.clone()).is_one() {
                    format!("-{m}")
                } else {
                    format!("({x})*{m}")
                }
            })
            .collect();
        let p = if terms.is_empty() {
            "0".to_string()
        } else {
            terms.join(" + ")
        };
        let text = if d_text.is_empty() {
            format!("({p})")
        } else {
            format!("({p})/({})", d_text.join("*"))
        };
        let known: Vec<String> = sym.names.iter().cloned().collect();
        return parse::parse(&text, &known);
    }
    let tried = match searched {
        Some(deg) => format!(
            "no R = P/D with P of total degree ≤ {deg} solves the WZ equation (D from the factorials of F that grow with n)"
        ),
        None => "no degree of P could be searched".to_string(),
    };
    Err(none(match stopped {
        Some(why) => format!(
            "{tried}; the search stopped at degree {}: {why}",
            searched.map_or(0, |d| d + 1)
        ),
        None => tried,
    }))
}

/// The solution of one linear system `Σ x_i cols_i = given` (each a polynomial, denominators
/// cleared), or with no `given` a null vector whose first `first_free` entries (the `p_j`) are
/// not all zero.
///
/// `charge` is told the work of each step before it is done (with what it is for) and may stop
/// the search with an error.
pub(super) fn solve(
    sym: &Symbols,
    cols: &[Poly],
    given: Option<&Poly>,
    first_free: usize,
    charge: &mut dyn FnMut(u128, &str) -> Result<()>,
) -> Result<Option<Vec<BigRational>>> {
    let width = cols.len() + 1;
    let mut rows: BTreeMap<Vec<u16>, Vec<BigRational>> = BTreeMap::new();
    for (j, c) in cols.iter().enumerate() {
        for (e, v) in c.terms_in(sym.names.len()) {
            rows.entry(e).or_insert_with(|| vec![BigRational::zero(); width])[j] += v;
        }
    }
    if let Some(g) = given {
        for (e, v) in g.terms_in(sym.names.len()) {
            rows.entry(e).or_insert_with(|| vec![BigRational::zero(); width])[width - 1] -= v;
        }
    }
    let mut a: Vec<Vec<BigRational>> = rows.into_values().collect();
    if a.is_empty() {
        // Every column is zero: nothing to solve for (it never happens with a nonzero summand).
        return Ok(None);
    }
    let (h, w) = (a.len(), width);
    let estimate = elimination_work(&a, w);
    let system = format!("a system of {h} equations in {w} unknowns");
    // Most systems of the search have no solution: a pass modulo a prime, far cheaper than
    // exact elimination, says so first.
    charge(estimate / MODULAR_DISCOUNT, &system)?;
    let Some(basis) = modular::may_solve(&a, given.is_some(), first_free) else {
        return Ok(None);
    };
    // Exact elimination on the rows that span the system modulo the prime (almost surely its
    // rows over Q too); a solution of them is checked on every row, else all rows are used.
    let mut sub: Vec<Vec<BigRational>> = basis.iter().map(|&r| a[r].clone()).collect();
    let sub_estimate = estimate * (sub.len() as u128 + 1) / (h as u128 + 1);
    charge(sub_estimate, &system)?;
    if let Some(x) = exact(&mut sub, given.is_some(), first_free)? {
        if a.iter().all(|row| satisfied(row, &x)) {
            return Ok(Some(x));
        }
    }
    charge(estimate, &system)?;
    exact(&mut a, given.is_some(), first_free)
}

/// Whether `row · (x, −1) = 0` (the last entry of `row` is the right-hand side).
fn satisfied(row: &[BigRational], x: &[BigRational]) -> bool {
    let (rhs, lhs) = row.split_last().expect("a row has a right-hand side");
    let mut total = -rhs.clone();
    for (c, v) in lhs.iter().zip(x) {
        if !c.is_zero() && !v.is_zero() {
            total += c * v;
        }
    }
    total.is_zero()
}

/// Exact elimination of `a`: a solution (see [`solve`]) or `None`.
fn exact(a: &mut [Vec<BigRational>], given: bool, first_free: usize) -> Result<Option<Vec<BigRational>>> {
    let width = a.first().map_or(1, Vec::len);
    let pivots = row_reduce(a)?;
    if given {
        if pivots.contains(&(width - 1)) {
            return Ok(None);
        }
        let mut x = vec![BigRational::zero(); width - 1];
        for (r, &p) in pivots.iter().enumerate() {
            x[p] = a[r][width - 1].clone() / &a[r][p];
        }
        return Ok(Some(x));
    }
    // Homogeneous: a vector of the null space whose first `first_free` entries (the p_j) are
    // not all zero.
    for f in (0..width - 1).filter(|c| !pivots.contains(c)) {
        let mut x = vec![BigRational::zero(); width - 1];
        x[f] = BigRational::one();
        for (r, &p) in pivots.iter().enumerate() {
            x[p] = -a[r][f].clone() / &a[r][p];
        }
        if x[..first_free].iter().any(|v| !v.is_zero()) {
            return Ok(Some(x));
        }
    }
    Ok(None)
}
