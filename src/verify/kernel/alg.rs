//! The algebras the evaluator computes in ([`Alg`]): exact numbers (rationals, machine-word
//! rationals, quadratic irrationals), degree bounds ([`Deg`]), and, in [`super::poly`],
//! symbolic rational functions.

use super::expr::check_index;
use crate::bernstein::binomial_signed;
use crate::error::{Error, Result};
use crate::scalar::Ring;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use smallvec::SmallVec;
use std::fmt;
use std::sync::Arc;

/// What the evaluator computes in: a [`Ring`] with the rational constants, a checked
/// division and a decidable (or undecidable) equality.
pub trait Alg: Ring {
    /// The rational constant `r`.
    fn from_rat(r: &BigRational) -> Self;
    /// `self / o`; an error when `o` is zero.
    fn div(&self, o: &Self) -> Result<Self>;
    /// `√r` of a rational constant; an error when it is not in this algebra.
    fn sqrt_rat(r: &BigRational) -> Result<Self>;
    /// Exact equality (`None` for algebras without one, like degree bounds).
    fn equals(&self, o: &Self) -> Option<bool>;

    /// `B_i^n(self)`, zero outside `0 ≤ i ≤ n` (the formula; an algebra may serve it from a
    /// cached table).
    fn bernstein(&self, i: i64, n: i64) -> Result<Self> {
        bernstein_formula(i, n, self)
    }

    /// The integer `n` ([`Ring::from_i64`] under the evaluator's name).
    fn from_int(n: i64) -> Self {
        Self::from_i64(n)
    }
    /// `self + o` ([`Ring::add_ref`] under the evaluator's name).
    fn add(&self, o: &Self) -> Self {
        self.add_ref(o)
    }
    /// `self - o` ([`Ring::sub_ref`] under the evaluator's name).
    fn sub(&self, o: &Self) -> Self {
        self.sub_ref(o)
    }
    /// `self * o` ([`Ring::mul_ref`] under the evaluator's name).
    fn mul(&self, o: &Self) -> Self {
        self.mul_ref(o)
    }
    /// `-self` ([`Ring::neg_ref`] under the evaluator's name).
    fn neg(&self) -> Self {
        self.neg_ref()
    }
    /// The big integer `n`.
    fn from_bigint(n: &BigInt) -> Self {
        Self::from_rat(&BigRational::from_integer(n.clone()))
    }
    /// `self^k` for an integer `k` (negative: `1 / self^|k|`).
    fn pow(&self, k: i64) -> Result<Self> {
        check_index(k)?;
        let mut base = self.clone();
        let mut acc = Self::one();
        let mut e = k.unsigned_abs();
        while e > 0 {
            if e & 1 == 1 {
                acc = acc.mul_ref(&base);
            }
            e >>= 1;
            if e > 0 {
                base = base.mul_ref(&base);
            }
        }
        if k < 0 {
            Self::one().div(&acc)
        } else {
            Ok(acc)
        }
    }
}

/// `√r` for a rational that is the square of a rational; other square roots need the
/// quadratic irrationals.
pub fn rational_sqrt(r: &BigRational) -> Result<BigRational> {
    if r.is_negative() {
        return Err(Error::Domain(format!(
            "sqrt({r}): the square root of a negative number is not real"
        )));
    }
    let (n, d) = (r.numer().sqrt(), r.denom().sqrt());
    if &(&n * &n) == r.numer() && &(&d * &d) == r.denom() {
        Ok(BigRational::new(n, d))
    } else {
        Err(Error::Domain(format!(
            "sqrt({r}) is irrational (not a square of a rational)"
        )))
    }
}

impl Alg for BigRational {
    fn from_rat(r: &BigRational) -> Self {
        r.clone()
    }
    fn div(&self, o: &Self) -> Result<Self> {
        if o.is_zero() {
            return Err(Error::DivisionByZero(format!("{self} / 0")));
        }
        Ok(self / o)
    }
    fn sqrt_rat(r: &BigRational) -> Result<Self> {
        rational_sqrt(r)
    }
    fn equals(&self, o: &Self) -> Option<bool> {
        Some(self == o)
    }
    fn bernstein(&self, i: i64, n: i64) -> Result<Self> {
        // Claims sample at the same parameters, so rows are shared across claims; where the
        // table declines (its size limits), the formula decides as before.
        crate::exact::BernsteinTable::shared()
            .bernstein(i, n, self)
            .or_else(|_| bernstein_formula(i, n, self))
    }
}

/// The prover's rationals: the same exact values as `BigRational`, on machine words while
/// they fit (most sample values do), so no heap and no big gcd per operation.
impl Alg for crate::exact::SmallRational {
    fn from_rat(r: &BigRational) -> Self {
        r.into()
    }
    fn div(&self, o: &Self) -> Result<Self> {
        crate::scalar::Scalar::checked_div(self, o)
    }
    fn sqrt_rat(r: &BigRational) -> Result<Self> {
        rational_sqrt(r).map(Self::from)
    }
    fn equals(&self, o: &Self) -> Option<bool> {
        Some(self == o)
    }
    fn from_bigint(n: &BigInt) -> Self {
        BigRational::from_integer(n.clone()).into()
    }
    fn bernstein(&self, i: i64, n: i64) -> Result<Self> {
        // As for BigRational: a shared row, the formula where the table declines.
        if i < 0 || i > n {
            return Ok(Self::from_int(0));
        }
        match crate::exact::BernsteinTable::shared().at_small(n as usize, self) {
            Ok(row) => Ok(row[i as usize].clone()),
            Err(_) => bernstein_formula(i, n, self),
        }
    }
}

impl Alg for crate::quadratic::QuadraticIrrational {
    fn from_rat(r: &BigRational) -> Self {
        crate::quadratic::QuadraticIrrational::rational(r.clone())
    }
    fn div(&self, o: &Self) -> Result<Self> {
        crate::scalar::Scalar::checked_div(self, o)
    }
    fn sqrt_rat(r: &BigRational) -> Result<Self> {
        if r.is_negative() {
            return Err(Error::Domain(format!(
                "sqrt({r}): the square root of a negative number is not real"
            )));
        }
        if let Ok(q) = rational_sqrt(r) {
            return Ok(Self::from_rat(&q));
        }
        crate::quadratic::QuadraticIrrational::sqrt_rational(r)
    }
    fn equals(&self, o: &Self) -> Option<bool> {
        // Mixing two fields (√2 and √3) poisons a value: it cannot be compared.
        (self.is_valid() && o.is_valid()).then(|| self == o)
    }
}

/// Degree bounds of a rational function: for each parameter `v`, the value is `P/Q` with
/// `deg_v P ≤ num` and `deg_v Q ≤ den`, where `P` and `Q` are the formal numerator and
/// denominator the evaluator builds (`a/b = (Pa Qb)/(Qa Pb)`, `a+b = (Pa Qb + Pb Qa)/(Qa Qb)`).
/// `affine` is the degree in a symbolic control polygon (must stay ≤ 1).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Deg {
    /// `var → (num, den)`, sorted by name, each name once; missing vars are `(0, 0)`. A
    /// goal has a few parameters: kept inline, names shared, so the bounds of a long written
    /// side are derived without allocating.
    vars: SmallVec<[Bound; 2]>,
    /// Degree in the symbolic control points.
    pub poly: u64,
}

/// One parameter's name and its `(num, den)` bounds.
type Bound = (Arc<str>, (u64, u64));

const DEG_LIMIT: u64 = 1 << 40;

impl Deg {
    /// The bound of a single parameter `v`.
    pub fn var(v: &str) -> Deg {
        let mut vars = SmallVec::new();
        vars.push((Arc::from(v), (1, 0)));
        Deg { vars, poly: 0 }
    }
    /// A control point of a symbolic polygon (degree 1 in the polygon, 0 in the parameters).
    pub fn control_point() -> Deg {
        Deg {
            vars: SmallVec::new(),
            poly: 1,
        }
    }
    /// `(num, den)` for `v`.
    pub fn get(&self, v: &str) -> (u64, u64) {
        self.vars.iter().find(|(k, _)| &**k == v).map_or((0, 0), |(_, nd)| *nd)
    }
    /// Each parameter with its `(num, den)`, in name order.
    pub fn vars(&self) -> impl Iterator<Item = (&str, (u64, u64))> {
        self.vars.iter().map(|(k, nd)| (&**k, *nd))
    }
    /// `f` of both bounds in each parameter of either (a merge of the two sorted lists).
    fn zip(&self, o: &Deg, poly: u64, f: impl Fn((u64, u64), (u64, u64)) -> (u64, u64)) -> Deg {
        let mut vars = SmallVec::new();
        let (mut a, mut b) = (self.vars.iter().peekable(), o.vars.iter().peekable());
        loop {
            let (k, x, y) = match (a.peek(), b.peek()) {
                (None, None) => break,
                (Some((ka, xa)), Some((kb, _))) if ka < kb => {
                    a.next();
                    (ka, *xa, (0, 0))
                }
                (Some((ka, xa)), Some((kb, xb))) if ka == kb => {
                    a.next();
                    b.next();
                    (ka, *xa, *xb)
                }
                (_, Some((kb, xb))) => {
                    b.next();
                    (kb, (0, 0), *xb)
                }
                (Some((ka, xa)), None) => {
                    a.next();
                    (ka, *xa, (0, 0))
                }
            };
            let (n, d) = f(x, y);
            vars.push((Arc::clone(k), (n.min(DEG_LIMIT), d.min(DEG_LIMIT))));
        }
        Deg { vars, poly }
    }
    /// Each parameter's bound mapped by `f`, and the control points' degree `poly`.
    fn map(&self, poly: u64, f: impl Fn((u64, u64)) -> (u64, u64)) -> Deg {
        Deg {
            vars: self.vars.iter().map(|(k, nd)| (Arc::clone(k), f(*nd))).collect(),
            poly,
        }
    }
    /// The bound of `g ↦ p(g)` for a polynomial `p` of degree `n` with constant coefficients
    /// (`Σ c_k P^k Q^(n-k) / Q^n`). The bound is a function of the inner bound in every
    /// component: a `g` of degree `d` in the control points gives degree `n·d` in them.
    pub fn compose(&self, n: u64) -> Deg {
        self.map(n.saturating_mul(self.poly).min(DEG_LIMIT), |(num, den)| {
            (
                n.saturating_mul(num.max(den)).min(DEG_LIMIT),
                n.saturating_mul(den).min(DEG_LIMIT),
            )
        })
    }
    /// The bound of a value affine in the symbolic control points with coefficients bounded
    /// by `self` (a control point times `self`).
    pub fn times_control_point(mut self) -> Deg {
        self.poly = self.poly.saturating_add(1);
        self
    }
    /// Whether the value is a polynomial in every parameter (no parameter in a denominator).
    pub fn is_polynomial(&self) -> bool {
        self.vars.iter().all(|(_, (_, d))| *d == 0)
    }
}

impl fmt::Display for Deg {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let parts: Vec<String> = self
            .vars()
            .filter(|&(_, (n, d))| n > 0 || d > 0)
            .map(|(v, (n, d))| {
                if d == 0 {
                    format!("{v}:{n}")
                } else {
                    format!("{v}:{n}/{d}")
                }
            })
            .collect();
        if parts.is_empty() {
            write!(f, "const")
        } else {
            write!(f, "{}", parts.join(","))
        }
    }
}

impl Ring for Deg {
    fn zero() -> Self {
        Deg::default()
    }
    fn one() -> Self {
        Deg::default()
    }
    fn from_i64(_: i64) -> Self {
        Deg::default()
    }
    fn add_ref(&self, o: &Self) -> Self {
        self.zip(o, self.poly.max(o.poly), |(na, da), (nb, db)| {
            if da == 0 && db == 0 {
                (na.max(nb), 0)
            } else {
                (na.saturating_add(db).max(nb.saturating_add(da)), da.saturating_add(db))
            }
        })
    }
    fn sub_ref(&self, o: &Self) -> Self {
        self.add_ref(o)
    }
    fn mul_ref(&self, o: &Self) -> Self {
        self.zip(
            o,
            self.poly.saturating_add(o.poly).min(DEG_LIMIT),
            |(na, da), (nb, db)| (na.saturating_add(nb), da.saturating_add(db)),
        )
    }
    fn neg_ref(&self) -> Self {
        self.clone()
    }
}

impl Alg for Deg {
    fn from_rat(_: &BigRational) -> Self {
        Deg::default()
    }
    fn div(&self, o: &Self) -> Result<Self> {
        if o.poly > 0 {
            return Err(Error::Domain(
                "division by an expression in the symbolic control points (not affine in them)".into(),
            ));
        }
        Ok(self.zip(o, self.poly, |(na, da), (nb, db)| {
            (na.saturating_add(db), da.saturating_add(nb))
        }))
    }
    fn sqrt_rat(_: &BigRational) -> Result<Self> {
        Ok(Deg::default())
    }
    fn equals(&self, _: &Self) -> Option<bool> {
        None
    }
    fn pow(&self, k: i64) -> Result<Self> {
        check_index(k)?;
        let m = k.unsigned_abs();
        let scaled = self.map(self.poly.saturating_mul(m).min(DEG_LIMIT), |(n, d)| {
            (n.saturating_mul(m).min(DEG_LIMIT), d.saturating_mul(m).min(DEG_LIMIT))
        });
        if k < 0 {
            Deg::default().div(&scaled)
        } else {
            Ok(scaled)
        }
    }
}

/// `B_i^n(g)` by its formula: the reference every table is checked against.
pub fn bernstein_formula<A: Alg>(i: i64, n: i64, g: &A) -> Result<A> {
    if i < 0 || i > n {
        return Ok(A::from_int(0));
    }
    let c = A::from_bigint(&binomial_signed(n, i));
    Ok(c.mul_ref(&g.pow(i)?).mul_ref(&A::from_int(1).sub_ref(g).pow(n - i)?))
}
