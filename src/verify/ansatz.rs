//! Finding a WZ certificate when the claim gives none: an ansatz `R = P / D` solved by exact
//! linear algebra.
//!
//! For one term `F`, the quotients `r1 = F(n+1, k)/F(n, k)` and `r2 = F(n, k+1)/F(n, k)` are
//! rational functions ([`super::kernel::pieces::ratio`]). The WZ equation divided by `F(n, k)` is
//! `r1 − 1 = R(k+1)·r2 − R(k)`. The denominator `D` is guessed as the denominator factors of `r1`
//! (the factorials of `F` that grow with `n`, as in Gosper's algorithm), and the numerator `P` as
//! a polynomial of total degree ≤ [`MAX_DEGREE`] in every symbol and parameter with unknown
//! rational coefficients; clearing denominators gives a linear system over `Q`, row-reduced
//! exactly. A solution is only a candidate: it is returned as an expression and checked like a
//! given certificate (the WZ equation on the whole range with its boundary pieces, the ends, the
//! base case), so the search can fail to find a certificate but never proves anything itself.

use super::kernel::eval::Alg;
use super::kernel::expr::Expr;
use super::kernel::hyper::{Aff, Symbols, Term};
use super::kernel::pieces::{ratio, ratio_denominator};
use super::kernel::poly::{Poly, RatFunc};
use super::parse;
use crate::error::{Error, Result};
use crate::linalg::row_reduce;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::collections::BTreeMap;

mod lift;
mod modular;

/// How much cheaper a modular pass is counted than exact elimination.
const MODULAR_DISCOUNT: u128 = 32;

/// Largest total degree of the numerator tried.
pub const MAX_DEGREE: u32 = 6;
/// Most unknown coefficients in one ansatz.
const MAX_UNKNOWNS: usize = 400;

/// The work the search may spend over all degrees: 16 per polynomial term built (or pair of
/// terms multiplied) for its equations, and Σ nonzero coefficients × min(rows, columns) ×
/// (64-bit words of the largest coefficient) of its linear systems.
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

/// One equation of a linear system: its nonzero entries `(column, coefficient)`, the last
/// column the right-hand side.
pub(super) type Row = Vec<(usize, BigRational)>;

/// The cost of eliminating the `width` columns of `a`: each of at most min(rows, columns)
/// pivots updates the nonzero entries, on numbers of the largest entry's words.
pub(super) fn elimination_work(a: &[Row], width: usize) -> u128 {
    let nonzero = a.iter().map(Vec::len).sum::<usize>() as u128;
    let words = a
        .iter()
        .flatten()
        .map(|(_, x)| x.numer().bits() + x.denom().bits())
        .max()
        .unwrap_or(0)
        / 64
        + 1;
    nonzero * a.len().min(width) as u128 * u128::from(words)
}

/// The rows `a` written out in full, `width` entries each, for exact elimination.
fn dense(a: &[&Row], width: usize) -> Vec<Vec<BigRational>> {
    a.iter()
        .map(|row| {
            let mut out = vec![BigRational::zero(); width];
            for (j, x) in row.iter() {
                out[*j] = x.clone();
            }
            out
        })
        .collect()
}

/// The work of one search: its own limit ([`MAX_ANSATZ_WORK`]) and the claim's budget.
struct Work<'a> {
    sym: &'a Symbols,
    spent: u128,
    /// Why the search's own limit stopped it, once it has.
    over: Option<String>,
}

impl Work<'_> {
    /// Adds `cost` (for `what`), or stops the search: at its own limit first (its message names
    /// it), then at the claim's budget.
    fn charge(&mut self, cost: u128, what: &str) -> Result<()> {
        self.spent = self.spent.saturating_add(cost);
        if self.spent > MAX_ANSATZ_WORK {
            self.over = Some(format!(
                "its linear system ({what}) passes MAX_ANSATZ_WORK = {MAX_ANSATZ_WORK} (polynomial terms built, nonzero coefficients × pivots × words, over all degrees)"
            ));
            return Err(Error::Domain("the search's work limit".into()));
        }
        self.sym
            .budget
            .draw("work of the WZ certificate search", cost, MAX_ANSATZ_WORK)
    }
}

/// The product of `parts` over every symbol (`one` is 1 over them), its work charged as it is
/// built (16 per pair of terms multiplied).
fn product(work: &mut Work<'_>, one: &Poly, parts: &[&Poly]) -> Result<Poly> {
    let mut p = one.clone();
    for q in parts {
        work.charge(16 * p.len() as u128 * q.len() as u128, "building its equations")?;
        p = p.mul(q);
    }
    Ok(p)
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
    let mut d_text: Vec<String> = affs.iter().map(|a| format!("({a})")).collect();
    d_text.extend(polys.iter().map(|p| format!("({p})")));
    let e0 = r1.sub(&RatFunc::from_int(1));
    let kx = sym
        .index(k)
        .ok_or_else(|| none(format!("{k} is not a symbol of the claim")))?;
    let mut work = Work {
        sym,
        spent: 0,
        over: None,
    };
    // With D the product of those factors, and r2 = A/B,
    // E_i = m_i/D − m_i(k+1)/D(k+1) · r2 = (m_i·U − m_i(k+1)·V) / Q over Q = D·D(k+1)·B,
    // and Σ c_i E_i = −E0 times Q·E0.den is Σ c_i (m_i·U − m_i(k+1)·V)·E0.den = −E0.num·Q: U,
    // V and the right side are built once, and each column is two of them shifted by a
    // monomial (no arithmetic).
    let one = Poly::constant(&sym.names, &BigRational::one());
    let stop = |work: &mut Work<'_>, e: Error| match work.over.take() {
        Some(why) => none(format!("the search stopped before degree 0: {why}")),
        None => e,
    };
    // Each side a list of factors: D and D(k+1) factor by factor, the rest as polynomials.
    let mut d_parts: Vec<Poly> = affs.iter().map(|a| a.to_rf(sym).num).collect();
    d_parts.extend(polys.iter().cloned());
    let d1_parts: Vec<Poly> = d_parts
        .iter()
        .map(|f| sym.subst_poly(f, k, &Aff::var(k).shifted(1)))
        .collect();
    let joined = |a: &[&Poly], b: &[Poly], c: &[&Poly]| -> Vec<Poly> {
        a.iter()
            .map(|p| (*p).clone())
            .chain(b.iter().cloned())
            .chain(c.iter().map(|p| (*p).clone()))
            .collect()
    };
    let mut sides = [
        joined(&[&r2.den, &e0.den], &d1_parts, &[]),
        joined(&[&r2.num, &e0.den], &d_parts, &[]),
        joined(&[&e0.num, &r2.den], &d_parts, &d1_parts.iter().collect::<Vec<_>>()),
    ];
    // A factor of D or D(k+1) that divides U, V and the right side divides every equation:
    // dividing it out leaves the same solutions (polynomials have no zero divisors) in fewer
    // and smaller equations.
    for f in d_parts.iter().chain(&d1_parts).filter(|f| f.as_constant().is_none()) {
        loop {
            let mut at = Vec::with_capacity(3);
            for side in &sides {
                let cost: u128 = side.iter().map(|p| p.len() as u128).sum::<u128>() * f.len() as u128;
                if let Err(e) = work.charge(16 * cost, "dividing out common factors") {
                    return Err(stop(&mut work, e));
                }
                match side
                    .iter()
                    .enumerate()
                    .find_map(|(i, p)| p.exact_div(f).map(|q| (i, q)))
                {
                    Some(found) => at.push(found),
                    None => break,
                }
            }
            if at.len() < 3 {
                break;
            }
            for (side, (i, q)) in sides.iter_mut().zip(at) {
                side[i] = q;
            }
        }
    }
    let mut built = Vec::with_capacity(3);
    for side in &sides {
        match product(&mut work, &one, &side.iter().collect::<Vec<_>>()) {
            Ok(p) => built.push(p),
            Err(e) => return Err(stop(&mut work, e)),
        }
    }
    let (u, v, rhs) = (built.remove(0), built.remove(0), built.remove(0));
    // V·(k+1)^j, for the powers of k in the monomials: m(k+1) = (m/k^j)·(k+1)^j.
    let k_plus_1 = Poly::var(&sym.names, kx).sub(&Poly::constant(&sym.names, &-BigRational::one()));
    let mut v_pows = vec![v];
    let mut searched: Option<u32> = None;
    let mut stopped = None;
    for deg in 0..=MAX_DEGREE {
        let monos = monomials(sym.names.len(), deg);
        if monos.len() > MAX_UNKNOWNS {
            stopped = Some(format!(
                "{} unknowns, more than MAX_UNKNOWNS = {MAX_UNKNOWNS}",
                monos.len()
            ));
            break;
        }
        let terms: usize = monos
            .iter()
            .map(|e| {
                let j = usize::from(e[kx]);
                u.len() + v_pows.get(j).map_or(v_pows[0].len() * (j + 1), Poly::len)
            })
            .sum();
        if terms > MAX_ANSATZ_TERMS {
            stopped = Some(format!(
                "its equations hold more than MAX_ANSATZ_TERMS = {MAX_ANSATZ_TERMS} polynomial terms"
            ));
            break;
        }
        if let Err(e) = work.charge(16 * terms as u128, "building its equations") {
            match work.over.take() {
                Some(why) => {
                    stopped = Some(why);
                    break;
                }
                None => return Err(e),
            }
        }
        while v_pows.len() <= deg as usize {
            let next = v_pows[v_pows.len() - 1].mul(&k_plus_1);
            v_pows.push(next);
        }
        let cols: Vec<Poly> = monos
            .iter()
            .map(|e| {
                let mut below_k = e.clone();
                below_k[kx] = 0;
                u.times_monomial(&sym.names, e)
                    .sub(&v_pows[usize::from(e[kx])].times_monomial(&sym.names, &below_k))
            })
            .collect();
        let found = solve(sym, &cols, Some(&rhs), 0, &mut |cost, what| work.charge(cost, what));
        if let Some(why) = work.over.take() {
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
    // Sparse rows: a system has many more equations than unknowns, most entries 0.
    let mut rows: BTreeMap<Vec<u16>, Row> = BTreeMap::new();
    for (j, c) in cols.iter().enumerate() {
        for (e, v) in c.terms_in(sym.names.len()) {
            rows.entry(e).or_default().push((j, v));
        }
    }
    if let Some(g) = given {
        for (e, v) in g.terms_in(sym.names.len()) {
            rows.entry(e).or_default().push((width - 1, -v));
        }
    }
    let a: Vec<Row> = rows.into_values().collect();
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
    let Some(basis) = modular::may_solve(&a, width, given.is_some(), first_free) else {
        return Ok(None);
    };
    // The rows that span the system modulo the prime (almost surely its rows over Q too),
    // solved modulo more primes and lifted, or else by exact elimination; a solution of them is
    // checked on every row, else all rows are eliminated. The work is counted as exact
    // elimination's, so the lift changes how fast a search ends, not where.
    let sub_estimate = estimate * (basis.len() as u128 + 1) / (h as u128 + 1);
    charge(sub_estimate, &system)?;
    if let Some(x) = lift::solve(&a, &basis, width, given.is_some(), first_free) {
        return Ok(Some(x));
    }
    let mut sub = dense(&basis.iter().map(|&r| &a[r]).collect::<Vec<_>>(), width);
    if let Some(x) = exact(&mut sub, given.is_some(), first_free)? {
        if a.iter().all(|row| satisfied(row, width, &x)) {
            return Ok(Some(x));
        }
    }
    charge(estimate, &system)?;
    exact(
        &mut dense(&a.iter().collect::<Vec<_>>(), width),
        given.is_some(),
        first_free,
    )
}

/// Whether `row · (x, −1) = 0` (column `width − 1` is the right-hand side).
fn satisfied(row: &Row, width: usize, x: &[BigRational]) -> bool {
    let mut total = BigRational::zero();
    for (j, c) in row {
        if *j == width - 1 {
            total -= c;
        } else if !x[*j].is_zero() {
            total += c * &x[*j];
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
