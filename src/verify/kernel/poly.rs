//! Exact multivariate rational functions with rational coefficients, for claims about
//! arbitrary vectors and unknowns (text 004): both sides are expanded and compared, which is
//! a proof by algebra rather than by sampling.

use super::alg::{rational_sqrt, Alg};
use crate::error::{Error, Result};
use crate::scalar;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::borrow::Cow;
use std::collections::btree_map::Entry;
use std::collections::BTreeMap;
use std::fmt;
use std::rc::Rc;

/// Largest number of terms a polynomial may reach before the claim is refused.
pub const MAX_TERMS: usize = 200_000;

/// A polynomial: monomial exponents (one per variable) → coefficient, no zero coefficients.
///
/// A constant may be built without names ([`Alg::from_rat`] has no context): it takes the
/// names of the first polynomial it meets, so no variable list has to be set beforehand.
#[derive(Clone, Debug, PartialEq)]
pub struct Poly {
    names: Rc<[String]>,
    terms: BTreeMap<Vec<u16>, BigRational>,
}

/// Two polynomials over one variable list: a constant built without names is lifted to the
/// other's names.
fn aligned<'a>(a: &'a Poly, b: &'a Poly) -> (Cow<'a, Poly>, Cow<'a, Poly>) {
    match (a.names.len(), b.names.len()) {
        (0, m) if m > 0 => (Cow::Owned(a.over(&b.names)), Cow::Borrowed(b)),
        (m, 0) if m > 0 => (Cow::Borrowed(a), Cow::Owned(b.over(&a.names))),
        _ => {
            debug_assert!(a.names == b.names, "polynomials over different variables");
            (Cow::Borrowed(a), Cow::Borrowed(b))
        }
    }
}

impl Poly {
    /// A constant built without names, over `names`.
    fn over(&self, names: &Rc<[String]>) -> Poly {
        debug_assert!(self.names.is_empty() && self.as_constant().is_some());
        Poly::constant(names, &self.as_constant().unwrap_or_default())
    }
    /// The constant `c` over the variables `names`.
    pub fn constant(names: &Rc<[String]>, c: &BigRational) -> Poly {
        let mut terms = BTreeMap::new();
        if !c.is_zero() {
            terms.insert(vec![0; names.len()], c.clone());
        }
        Poly {
            names: names.clone(),
            terms,
        }
    }
    /// The variable number `k`.
    pub fn var(names: &Rc<[String]>, k: usize) -> Poly {
        let mut e = vec![0; names.len()];
        e[k] = 1;
        let mut terms = BTreeMap::new();
        terms.insert(e, BigRational::one());
        Poly {
            names: names.clone(),
            terms,
        }
    }
    /// Whether this is the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }
    /// The number of variables it is written over (0 for a constant built without names).
    pub fn var_count(&self) -> usize {
        self.names.len()
    }
    /// The number of terms.
    pub fn len(&self) -> usize {
        self.terms.len()
    }
    /// The machine words of its coefficients (numerators and denominators), at least one per
    /// term: what one pass over it costs.
    pub fn words(&self) -> u128 {
        self.terms
            .values()
            .map(|c| u128::from((c.numer().bits() + c.denom().bits()) / 64 + 1))
            .sum()
    }
    /// The constant value, when the polynomial is constant.
    pub fn as_constant(&self) -> Option<BigRational> {
        match self.terms.len() {
            0 => Some(BigRational::zero()),
            1 => {
                let (e, c) = self.terms.iter().next().expect("one term");
                e.iter().all(|&x| x == 0).then(|| c.clone())
            }
            _ => None,
        }
    }
    fn add_scaled(&self, o: &Poly, sign: bool) -> Poly {
        let (a, o) = aligned(self, o);
        let mut terms = a.terms.clone();
        for (e, c) in &o.terms {
            let entry = terms.entry(e.clone()).or_insert_with(BigRational::zero);
            if sign {
                *entry += c;
            } else {
                *entry -= c;
            }
            if entry.is_zero() {
                terms.remove(e);
            }
        }
        Poly {
            names: a.names.clone(),
            terms,
        }
    }
    /// `self · o`.
    pub fn mul(&self, o: &Poly) -> Poly {
        let (a, o) = aligned(self, o);
        let mut terms: BTreeMap<Vec<u16>, BigRational> = BTreeMap::new();
        for (e1, c1) in &a.terms {
            for (e2, c2) in &o.terms {
                let e: Vec<u16> = e1.iter().zip(e2).map(|(a, b)| a.saturating_add(*b)).collect();
                let entry = terms.entry(e.clone()).or_insert_with(BigRational::zero);
                *entry += c1 * c2;
                if entry.is_zero() {
                    terms.remove(&e);
                }
            }
        }
        Poly {
            names: a.names.clone(),
            terms,
        }
    }
    fn scale(&self, c: &BigRational) -> Poly {
        if c.is_zero() {
            return Poly::constant(&self.names, c);
        }
        Poly {
            names: self.names.clone(),
            terms: self.terms.iter().map(|(e, x)| (e.clone(), x * c)).collect(),
        }
    }
    /// The terms (exponents, coefficient), in increasing monomial order, over a list of
    /// `vars` variables (the polynomial's own, or any list for a constant built without names).
    pub fn terms_in(&self, vars: usize) -> Vec<(Vec<u16>, BigRational)> {
        debug_assert!(self.names.is_empty() || self.names.len() == vars);
        self.terms
            .iter()
            .map(|(e, c)| {
                let mut e = e.clone();
                e.resize(vars, 0);
                (e, c.clone())
            })
            .collect()
    }

    /// `self / d` when the polynomial `d` divides `self` exactly, else `None` (also `None`
    /// when the division would take more than [`MAX_TERMS`] steps: a refusal, never a guess).
    ///
    /// Division by leading terms in the lexicographic monomial order: if `self = q·d` then the
    /// leading term of `self` is that of `q` times that of `d`, so a leading term that the
    /// leading term of `d` does not divide proves that `d` does not divide `self`.
    pub fn exact_div(&self, d: &Poly) -> Option<Poly> {
        let (num, d) = aligned(self, d);
        let (ed, cd) = d.terms.iter().next_back()?;
        // The remainder is updated in place: each step touches only the terms of `d`.
        let mut rem = num.into_owned();
        let mut q = BTreeMap::new();
        for _ in 0..MAX_TERMS {
            let Some((er, cr)) = rem.terms.iter().next_back() else {
                return Some(Poly {
                    names: rem.names,
                    terms: q,
                });
            };
            if er.iter().zip(ed).any(|(a, b)| a < b) {
                return None;
            }
            let mono: Vec<u16> = er.iter().zip(ed).map(|(a, b)| a - b).collect();
            let c = cr / cd;
            for (e, x) in &d.terms {
                let at: Vec<u16> = e.iter().zip(&mono).map(|(a, b)| a.saturating_add(*b)).collect();
                match rem.terms.entry(at) {
                    Entry::Occupied(mut o) => {
                        *o.get_mut() -= x * &c;
                        if o.get().is_zero() {
                            o.remove();
                        }
                    }
                    Entry::Vacant(v) => {
                        v.insert(-(x * &c));
                    }
                }
            }
            q.insert(mono, c);
        }
        None
    }

    /// `self − o`.
    pub fn sub(&self, o: &Poly) -> Poly {
        self.add_scaled(o, false)
    }

    /// `self · x^e` over the variables `names` (the exponents `e` one per name; a constant built
    /// without names is lifted to them): the exponents shifted, no arithmetic.
    pub fn times_monomial(&self, names: &Rc<[String]>, e: &[u16]) -> Poly {
        debug_assert!(self.names.is_empty() || self.names.len() == names.len());
        let terms = self
            .terms
            .iter()
            .map(|(x, c)| {
                let mut m = e.to_vec();
                for (a, b) in m.iter_mut().zip(x) {
                    *a = a.saturating_add(*b);
                }
                (m, c.clone())
            })
            .collect();
        Poly {
            names: names.clone(),
            terms,
        }
    }

    /// The value at `point` (one rational per variable).
    pub fn eval(&self, point: &[BigRational]) -> BigRational {
        let mut acc = BigRational::zero();
        for (e, c) in &self.terms {
            let mut term = c.clone();
            for (x, &k) in point.iter().zip(e) {
                for _ in 0..k {
                    term *= x;
                }
            }
            acc += term;
        }
        acc
    }
}

impl fmt::Display for Poly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.terms.is_empty() {
            return write!(f, "0");
        }
        let mut first = true;
        for (e, c) in self.terms.iter().rev() {
            let mono: Vec<String> = e
                .iter()
                .enumerate()
                .filter(|(_, &k)| k > 0)
                .map(|(i, &k)| {
                    if k == 1 {
                        self.names[i].clone()
                    } else {
                        format!("{}^{k}", self.names[i])
                    }
                })
                .collect();
            let neg = c < &BigRational::zero();
            let mag = if neg { -c } else { c.clone() };
            if first {
                if neg {
                    write!(f, "-")?;
                }
            } else {
                write!(f, "{}", if neg { " - " } else { " + " })?;
            }
            first = false;
            if mono.is_empty() {
                write!(f, "{mag}")?;
            } else if mag.is_one() {
                write!(f, "{}", mono.join("*"))?;
            } else {
                write!(f, "{mag}*{}", mono.join("*"))?;
            }
        }
        Ok(())
    }
}

/// A rational function `num / den` (the denominator is never the zero polynomial).
#[derive(Clone, Debug)]
pub struct RatFunc {
    /// The numerator.
    pub num: Poly,
    /// The denominator.
    pub den: Poly,
}

impl RatFunc {
    /// The polynomial `p`.
    pub fn poly(p: Poly) -> RatFunc {
        let one = Poly::constant(&p.names, &BigRational::one());
        RatFunc { num: p, den: one }
    }
    fn normal(num: Poly, den: Poly) -> RatFunc {
        // A constant denominator is folded into the numerator, keeping most values polynomials.
        match den.as_constant() {
            Some(c) if !c.is_zero() && !c.is_one() => {
                let inv = BigRational::one() / c;
                RatFunc::poly(num.scale(&inv))
            }
            _ => RatFunc { num, den },
        }
    }
    /// `num1 · den2 − num2 · den1`: zero exactly when the two functions are equal.
    pub fn cleared_difference(&self, o: &RatFunc) -> Poly {
        self.num.mul(&o.den).add_scaled(&o.num.mul(&self.den), false)
    }
    fn size_check(&self) -> Result<()> {
        if self.num.len() > MAX_TERMS || self.den.len() > MAX_TERMS {
            return Err(Error::TooLarge {
                what: "symbolic expansion",
                value: format!("{} terms", self.num.len().max(self.den.len())),
                limit: MAX_TERMS.to_string(),
            });
        }
        Ok(())
    }
}

impl fmt::Display for RatFunc {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den.as_constant().is_some_and(|c| c.is_one()) {
            write!(f, "{}", self.num)
        } else {
            write!(f, "({}) / ({})", self.num, self.den)
        }
    }
}

impl scalar::Ring for RatFunc {
    fn zero() -> Self {
        Self::from_rat(&<BigRational as Zero>::zero())
    }
    fn one() -> Self {
        Self::from_rat(&<BigRational as One>::one())
    }
    fn from_i64(n: i64) -> Self {
        Self::from_rat(&BigRational::from_integer(n.into()))
    }
    fn add_ref(&self, o: &Self) -> Self {
        if self.den == o.den {
            return RatFunc::normal(self.num.add_scaled(&o.num, true), self.den.clone());
        }
        RatFunc::normal(
            self.num.mul(&o.den).add_scaled(&o.num.mul(&self.den), true),
            self.den.mul(&o.den),
        )
    }
    fn sub_ref(&self, o: &Self) -> Self {
        self.add_ref(&o.neg_ref())
    }
    fn mul_ref(&self, o: &Self) -> Self {
        RatFunc::normal(self.num.mul(&o.num), self.den.mul(&o.den))
    }
    fn neg_ref(&self) -> Self {
        RatFunc {
            num: self.num.scale(&-<BigRational as One>::one()),
            den: self.den.clone(),
        }
    }
}

impl Alg for RatFunc {
    fn from_rat(r: &BigRational) -> Self {
        RatFunc::poly(Poly::constant(&Rc::from(Vec::new()), r))
    }
    fn div(&self, o: &Self) -> Result<Self> {
        if o.num.is_zero() {
            return Err(Error::DivisionByZero(format!(
                "division by the zero polynomial ({self} / 0)"
            )));
        }
        let r = RatFunc::normal(self.num.mul(&o.den), self.den.mul(&o.num));
        r.size_check()?;
        Ok(r)
    }
    fn sqrt_rat(r: &BigRational) -> Result<Self> {
        Ok(Self::from_rat(&rational_sqrt(r)?))
    }
    fn equals(&self, o: &Self) -> Option<bool> {
        Some(self.cleared_difference(o).is_zero())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_division() {
        let names: Rc<[String]> = Rc::from(vec!["x".to_string(), "y".to_string()]);
        let x = RatFunc::poly(Poly::var(&names, 0));
        let y = RatFunc::poly(Poly::var(&names, 1));
        let a = x.add(&y).mul(&x.sub(&y)).mul(&x); // x³ − x y²
        let d = x.add(&y);
        let q = a.num.exact_div(&d.num).unwrap();
        assert_eq!(q.to_string(), "x^2 - x*y");
        assert!(a.num.exact_div(&y.add(&RatFunc::from_int(1)).num).is_none());
        assert!(x.num.exact_div(&y.num).is_none());
        assert_eq!(x.num.exact_div(&x.num).unwrap().as_constant(), Some(BigRational::one()));
    }

    #[test]
    fn exact_division_of_a_product_and_shifts_by_monomials() {
        let names: Rc<[String]> = Rc::from(vec!["x".to_string(), "y".to_string(), "z".to_string()]);
        let v = |k| RatFunc::poly(Poly::var(&names, k));
        let half = RatFunc::from_rat(&BigRational::new(1.into(), 2.into()));
        // (x + y/2 + z + 1)^4 · (x·y − 3z + 2), divided by each factor in turn.
        let f = v(0).add(&v(1).mul(&half)).add(&v(2)).add(&RatFunc::from_int(1));
        let g = v(0)
            .mul(&v(1))
            .sub(&RatFunc::from_int(3).mul(&v(2)))
            .add(&RatFunc::from_int(2));
        let f4 = f.mul(&f).mul(&f).mul(&f);
        let p = f4.mul(&g).num;
        assert_eq!(p.exact_div(&g.num), Some(f4.num.clone()));
        assert_eq!(p.exact_div(&f4.num), Some(g.num.clone()));
        assert!(p.exact_div(&v(0).add(&v(2)).num).is_none());
        // x·y²·g, by shifting g's exponents.
        let shifted = g.num.times_monomial(&names, &[1, 2, 0]);
        assert_eq!(shifted, v(0).mul(&v(1)).mul(&v(1)).mul(&g).num);
        assert_eq!(shifted.sub(&shifted).len(), 0);
    }

    #[test]
    fn expands_and_compares() {
        let names: Rc<[String]> = Rc::from(vec!["x".to_string(), "y".to_string()]);
        let x = RatFunc::poly(Poly::var(&names, 0));
        let y = RatFunc::poly(Poly::var(&names, 1));
        let lhs = x.add(&y).mul(&x.add(&y));
        let rhs = x.mul(&x).add(&RatFunc::from_int(2).mul(&x).mul(&y)).add(&y.mul(&y));
        assert_eq!(lhs.equals(&rhs), Some(true));
        assert_eq!(lhs.equals(&x.mul(&x)), Some(false));
        let q = x.div(&y).unwrap();
        assert_eq!(q.mul(&y).equals(&x), Some(true));
        assert!(x.div(&x.sub(&x)).is_err());
        assert_eq!(lhs.to_string(), "x^2 + 2*x*y + y^2");
    }
}
