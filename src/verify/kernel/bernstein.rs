//! Signs of polynomials of one variable on an interval from their Bernstein coefficients,
//! computed here from the power coefficients (`crate::bernstein` changes the basis), halving
//! the interval by de Casteljau's algorithm: what [`super::check_bernstein`] proves with, and
//! the nonnegativity of a sum of hypergeometric terms on the pieces of a domain
//! ([`check_nonneg_pieces`]).

use super::checked::{Method, Step};
use super::eval::Alg;
use super::hyper::{Aff, Base, Symbols, Term};
use super::nonneg::{Factor, LiveTerm, Piece, Why};
use super::pieces::{prove_pieces, Domain, ZeroOutcome};
use super::poly::{Poly, RatFunc};
use super::Discharged;
use crate::bernstein::{power_to_bernstein, reparametrize};
use crate::error::{Error, Result};
use num_rational::BigRational;
use num_traits::{Signed, Zero};

/// Most halvings of `[a, b]` (so at most 2^`MAX_DEPTH` subintervals).
pub const MAX_DEPTH: usize = 12;

/// What the Bernstein check found.
#[derive(Clone, Debug)]
pub enum Sign {
    /// Every subinterval's coefficients are ≥ 0 (> 0 at the ends for strict): the subintervals
    /// and their least coefficients.
    Holds(Vec<(BigRational, BigRational, BigRational)>),
    /// The value at this point is < 0 (≤ 0 for strict).
    Fails(BigRational),
}

fn eval(coeffs: &[BigRational], t: &BigRational) -> BigRational {
    coeffs.iter().rev().fold(BigRational::zero(), |acc, c| acc * t + c)
}

/// Decides `P ≥ 0` (`P > 0` when `strict`) on `[a, b]` for `P` given by power coefficients.
pub fn bernstein_sign(power: &[BigRational], a: &BigRational, b: &BigRational, strict: bool) -> Result<Sign> {
    let bad = |v: &BigRational| if strict { !v.is_positive() } else { v.is_negative() };
    let local = reparametrize(power, a, b);
    let coeffs = power_to_bernstein(&local)?;
    let mut work = vec![(a.clone(), b.clone(), coeffs, 0usize)];
    let mut done = Vec::new();
    while let Some((lo, hi, c, depth)) = work.pop() {
        let (first, last) = (c[0].clone(), c[c.len() - 1].clone());
        if bad(&first) {
            return Ok(Sign::Fails(lo));
        }
        if bad(&last) {
            return Ok(Sign::Fails(hi));
        }
        if c.iter().all(|x| !x.is_negative()) {
            let least = c.iter().min().cloned().unwrap_or_else(BigRational::zero);
            done.push((lo, hi, least));
            continue;
        }
        let two = BigRational::from_integer(2.into());
        let mid = (&lo + &hi) / &two;
        let at = eval(power, &mid);
        if bad(&at) {
            return Ok(Sign::Fails(mid));
        }
        if depth >= MAX_DEPTH {
            return Err(Error::TooLarge {
                what: "halvings of the interval for a Bernstein certificate",
                value: format!("more than {MAX_DEPTH} on [{lo}, {hi}] (a double root at a non-dyadic point?)"),
                limit: format!("MAX_DEPTH = {MAX_DEPTH}"),
            });
        }
        // de Casteljau at 1/2: the left and right Bernstein coefficients.
        let mut row = c.clone();
        let (mut left, mut right) = (vec![row[0].clone()], vec![row[row.len() - 1].clone()]);
        while row.len() > 1 {
            row = row.windows(2).map(|w| (&w[0] + &w[1]) / &two).collect();
            left.push(row[0].clone());
            right.push(row[row.len() - 1].clone());
        }
        right.reverse();
        work.push((mid.clone(), hi, right, depth + 1));
        work.push((lo, mid, left, depth + 1));
    }
    done.sort();
    Ok(Sign::Holds(done))
}

/// The power coefficients of a polynomial in its first variable.
pub fn coeffs_1d(p: &Poly) -> Vec<BigRational> {
    let mut out = Vec::new();
    for (e, c) in p.terms_in(1) {
        let k = e[0] as usize;
        if out.len() <= k {
            out.resize(k + 1, BigRational::zero());
        }
        out[k] = c;
    }
    if out.is_empty() {
        out.push(BigRational::zero());
    }
    out
}

/// `q ≥ 0` (`> 0`) on `[a, b]` for a rational function of one variable with constant
/// denominator, or a polynomial.
pub fn poly_sign(q: &RatFunc, a: &BigRational, b: &BigRational, strict: bool) -> Result<Sign> {
    let d = q
        .den
        .as_constant()
        .ok_or_else(|| Error::Domain("a polynomial was expected".into()))?;
    let mut c = coeffs_1d(&q.num);
    if d.is_negative() {
        for x in &mut c {
            *x = -x.clone();
        }
    }
    bernstein_sign(&c, a, b, strict)
}

/// Whether `v = P / Q`, a rational function of one variable, is ≥ 0 (> 0 when `strict`) on
/// `[a, b]`, decided from Bernstein coefficients computed here: `Q` keeps one sign (> 0 or
/// < 0 on every subinterval), and `P` with that sign has no negative coefficient on any
/// subinterval (and values > 0 at the ends of each when `strict`).
pub(super) fn nonnegative(v: &RatFunc, a: &BigRational, b: &BigRational, strict: bool) -> bool {
    if v.num.var_count() > 1 || v.den.var_count() > 1 {
        return false;
    }
    let holds = |q: &RatFunc, strict| matches!(poly_sign(q, a, b, strict), Ok(Sign::Holds(_)));
    let den = RatFunc::poly(v.den.clone());
    let num = RatFunc::poly(v.num.clone());
    if holds(&den, true) {
        holds(&num, strict)
    } else {
        holds(&den.neg(), true) && holds(&num.neg(), strict)
    }
}

/// The power coefficients of a polynomial in the last symbol of `sym` (its one continuous
/// parameter); `None` when another symbol occurs.
fn coeffs_last(sym: &Symbols, q: &Poly) -> Option<Vec<BigRational>> {
    let width = sym.names.len();
    let mut out = vec![BigRational::zero()];
    for (e, c) in q.terms_in(width) {
        let (last, rest) = e.split_last().map_or((0, &[][..]), |(l, r)| (*l, r));
        if rest.iter().any(|&x| x > 0) {
            return None;
        }
        let k = last as usize;
        if out.len() <= k {
            out.resize(k + 1, BigRational::zero());
        }
        out[k] += c;
    }
    Some(out)
}

/// Whether `q`, a rational function of the continuous parameter with constant denominator, is
/// ≥ 0 (> 0 when `strict`) on `[a, b]` by its Bernstein coefficients.
fn param_nonneg(sym: &Symbols, q: &RatFunc, (a, b): (&BigRational, &BigRational), strict: bool) -> Result<bool> {
    let Some(c) = signed_coeffs(sym, q)? else {
        return Ok(false);
    };
    Ok(matches!(bernstein_sign(&c, a, b, strict)?, Sign::Holds(_)))
}

/// The power coefficients of `q` (constant denominator) in the continuous parameter, the
/// denominator's sign folded in; `None` when an integer symbol occurs.
fn signed_coeffs(sym: &Symbols, q: &RatFunc) -> Result<Option<Vec<BigRational>>> {
    let d = q
        .den
        .as_constant()
        .ok_or_else(|| Error::Domain("a polynomial was expected".into()))?;
    let Some(mut c) = coeffs_last(sym, &q.num) else {
        return Ok(None);
    };
    let d_inv = BigRational::from_integer(1.into()) / d;
    for x in &mut c {
        *x = x.clone() * &d_inv;
    }
    Ok(Some(c))
}

/// The Bernstein coefficients of `q` on the whole of `[a, b]` in the degree of its numerator
/// (what a certificate records of a factor shown ≥ 0 by them; empty when they cannot be
/// written).
fn whole_interval(sym: &Symbols, q: &RatFunc, (a, b): (&BigRational, &BigRational)) -> Vec<BigRational> {
    let Ok(Some(mut c)) = signed_coeffs(sym, q) else {
        return Vec::new();
    };
    while c.len() > 1 && c.last().is_some_and(Zero::is_zero) {
        c.pop();
    }
    power_to_bernstein(&reparametrize(&c, a, b)).unwrap_or_default()
}

/// Every factor of the live term `t` shown ≥ 0 on the piece `d` and `[a, b]`, each with its
/// reason (`Ok`), else the reason one is not.
fn term_nonneg(
    sym: &Symbols,
    t: &Term,
    d: &Domain,
    ab: (&BigRational, &BigRational),
) -> Result<std::result::Result<LiveTerm, String>> {
    let zero = BigRational::zero();
    let coef_why = if sym.poly_has_ints(&t.coef.num) || sym.poly_has_ints(&t.coef.den) {
        // An affine coefficient in the integers (n, i + 1, …) shown ≥ 0 on the piece, or a
        // polynomial with coefficients ≥ 0 in variables ≥ 0 (n t, with n ≥ 0, t ∈ [0, 1]).
        let affine = sym.rf_to_aff(&t.coef).is_some_and(|a| d.implies_ge(&a));
        let mut monomials = t.coef.den.as_constant().is_some_and(|c| c > zero);
        for (e, c) in t.coef.num.terms_in(sym.names.len()) {
            monomials &= c > zero;
            for (k, &x) in e.iter().enumerate() {
                if x == 0 || !monomials {
                    continue;
                }
                let name = &sym.names[k];
                monomials &= if k < sym.ints {
                    d.implies_ge(&Aff::var(name))
                } else {
                    param_nonneg(sym, &sym.var(name), ab, false)?
                };
            }
        }
        if affine {
            Some(Why::AffineOnPiece)
        } else {
            monomials.then_some(Why::PositiveMonomials)
        }
    } else {
        (t.coef.den.as_constant().is_some() && param_nonneg(sym, &t.coef, ab, false)?).then_some(Why::Bernstein)
    };
    let Some(why) = coef_why else {
        return Ok(Err(format!("the coefficient of {} is not shown ≥ 0", t.show())));
    };
    let coefficient = Factor {
        factor: t.coef.to_string(),
        exponent: None,
        why,
        bernstein: if why == Why::Bernstein {
            whole_interval(sym, &t.coef, ab)
        } else {
            Vec::new()
        },
    };
    let mut powers = Vec::with_capacity(t.pows.len());
    for (base, e) in &t.pows {
        let (why, bernstein) = match base {
            Base::Const(c) => ((c > &zero).then_some(Why::PositiveConstant), Vec::new()),
            Base::Poly(q) => {
                let q = RatFunc::poly(q.clone());
                let why = if param_nonneg(sym, &q, ab, true)? {
                    Some(Why::BernsteinPositive)
                } else if d.implies_ge(e) && param_nonneg(sym, &q, ab, false)? {
                    Some(Why::ExponentNonneg)
                } else {
                    None
                };
                (why, whole_interval(sym, &q, ab))
            }
        };
        let Some(why) = why else {
            return Ok(Err(format!("the factor {base}^({e}) of {} is not shown ≥ 0", t.show())));
        };
        powers.push(Factor {
            factor: base.to_string(),
            exponent: Some(e.to_string()),
            why,
            bernstein,
        });
    }
    let factorials = t
        .facts
        .iter()
        .map(|(a, e)| if *e > 0 { format!("({a})!") } else { format!("1/({a})!") })
        .collect();
    Ok(Ok(LiveTerm {
        term: t.show(),
        coefficient,
        factorials,
        powers,
    }))
}

/// `Σ lin ≥ 0` at every integer point of `dom` and every value of the one continuous parameter
/// of `sym` in `[a, b]`: on each piece of the domain every live term is a product of factors
/// ≥ 0 — a coefficient shown ≥ 0 (affine in the integers and ≥ 0 on the piece, a polynomial
/// with positive coefficients in variables ≥ 0, or a polynomial in the parameter with Bernstein
/// coefficients ≥ 0 on `[a, b]`), factorials (of arguments ≥ 0 on a piece), powers of positive
/// constants, and powers with exponent ≥ 0 of polynomials ≥ 0 on `[a, b]` (any exponent of a
/// positive one there). The obligation, the number of pieces and each piece's live terms with the
/// reason each factor is ≥ 0 (what a certificate records); the steps go to `log`.
pub fn check_nonneg_pieces(
    sym: &Symbols,
    lin: &[Term],
    dom: &Domain,
    (a, b): (&BigRational, &BigRational),
    log: &mut Vec<Step>,
) -> Result<(Discharged, usize, Vec<Piece>)> {
    if sym.names.len() > sym.ints + 1 || a >= b {
        return Err(Error::Domain(
            "nonnegativity on pieces needs one continuous parameter on a nonempty interval".into(),
        ));
    }
    let mut record = Vec::new();
    let mut check = |live: &[&Term], d: &Domain, place: &str, log: &mut Vec<Step>| -> Result<Option<String>> {
        let mut terms = Vec::with_capacity(live.len());
        for t in live {
            match term_nonneg(sym, t, d, (a, b))? {
                Ok(term) => terms.push(term),
                Err(why) => return Ok(Some(why)),
            }
        }
        record.push(Piece {
            region: place.to_string(),
            terms,
        });
        log.push(Step::text(format!(
            "on {place}: {} live terms, each a product of factors ≥ 0",
            live.len()
        )));
        Ok(None)
    };
    match prove_pieces(sym, lin, dom, log, &mut check)? {
        ZeroOutcome::Zero(pieces) => Ok((Discharged::new(Method::Pieces), pieces, record)),
        ZeroOutcome::NonZero { region, residue } => Err(Error::Domain(format!(
            "cannot show the inequality on {region}: {residue} (a product-of-nonnegative-factors argument only)"
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::super::check_bernstein;
    use super::*;
    use std::rc::Rc;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    /// `Σ_j c_j t^j / Σ_j d_j t^j`.
    fn rf(num: &[i64], den: &[i64]) -> RatFunc {
        let names: Rc<[String]> = Rc::from(vec!["t".to_string()]);
        let t = RatFunc::poly(Poly::var(&names, 0));
        let p = |c: &[i64]| {
            let mut out = RatFunc::from_int(0);
            for (j, &x) in c.iter().enumerate() {
                out = out.add(&RatFunc::from_int(x).mul(&t.pow(j as i64).expect("a power")));
            }
            out.num
        };
        RatFunc {
            num: p(num),
            den: p(den),
        }
    }

    #[test]
    fn certificates_and_refutations() {
        let (zero, one) = (q(0, 1), q(1, 1));
        // (2t − 1)² = 4t² − 4t + 1 ≥ 0: one halving (the root is at 1/2).
        match bernstein_sign(&[q(1, 1), q(-4, 1), q(4, 1)], &zero, &one, false).unwrap() {
            Sign::Holds(parts) => assert_eq!(parts.len(), 2),
            other => panic!("{other:?}"),
        }
        // ... but not > 0: the midpoint value 0 refutes it.
        match bernstein_sign(&[q(1, 1), q(-4, 1), q(4, 1)], &zero, &one, true).unwrap() {
            Sign::Fails(x) => assert_eq!(x, q(1, 2)),
            other => panic!("{other:?}"),
        }
        // t² − t + 1/5 < 0 at t = 1/2 (−1/20), though ≥ 0 at both ends.
        match bernstein_sign(&[q(1, 5), q(-1, 1), q(1, 1)], &zero, &one, false).unwrap() {
            Sign::Fails(x) => assert_eq!(x, q(1, 2)),
            other => panic!("{other:?}"),
        }
        // (t − 1/3)² ≥ 0 has its root at a non-dyadic point: undecided within the limit.
        assert!(bernstein_sign(&[q(1, 9), q(-2, 3), q(1, 1)], &zero, &one, false).is_err());
    }

    #[test]
    fn check_bernstein_computes_the_coefficients_itself() {
        let (zero, one, two) = (q(0, 1), q(1, 1), q(2, 1));
        let square = rf(&[1, -4, 4], &[1]);
        assert!(check_bernstein(std::slice::from_ref(&square), &zero, &one, false).is_some());
        assert!(check_bernstein(std::slice::from_ref(&square), &zero, &one, true).is_none());
        // Negative inside though not at the ends, or only past the interval's end.
        assert!(check_bernstein(&[rf(&[1, -5, 5], &[5])], &zero, &one, false).is_none());
        let late = rf(&[3, -2], &[1]);
        assert!(check_bernstein(std::slice::from_ref(&late), &zero, &one, true).is_some());
        assert!(check_bernstein(std::slice::from_ref(&late), &zero, &two, false).is_none());
        // One false case among true ones; no case; an empty interval.
        assert!(check_bernstein(&[square.clone(), late.clone()], &zero, &one, false).is_some());
        assert!(check_bernstein(&[square.clone(), rf(&[-1], &[1])], &zero, &one, false).is_none());
        assert!(check_bernstein(&[], &zero, &one, false).is_none());
        assert!(check_bernstein(std::slice::from_ref(&square), &one, &zero, false).is_none());
        // A denominator < 0 on the interval flips the sign; one with a root there is refused.
        assert!(check_bernstein(&[rf(&[-1], &[-2, 1])], &zero, &one, true).is_some());
        assert!(check_bernstein(&[rf(&[1], &[-2, 1])], &zero, &one, false).is_none());
        assert!(check_bernstein(&[rf(&[1], &[-1, 2])], &zero, &one, false).is_none());
    }
}
