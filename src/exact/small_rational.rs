//! [`SmallRational`]: an exact rational that computes on machine words while it can.
//!
//! Most numbers in Bézier geometry are small: integer control points, parameters like 1/3.
//! [`BigRational`] puts even those on the heap and reduces every result with a big-integer
//! gcd. A `SmallRational` keeps `p/q` in two `i64`s, computes in `i128` (where no product of
//! two `i64`s can overflow) and reduces with machine gcds; only a result that does not fit
//! moves to a boxed [`BigRational`]. Nothing wraps and nothing panics: overflow is a change of
//! representation, never a wrong value.
//!
//! The representation is canonical — lowest terms, positive denominator, and *small exactly
//! when the value fits* — so the derived `==` and `Hash` are exact value equality.
//! [`BigRational`] stays the type users exchange: convert with `From` both ways.
//!
//! ```
//! use casteljau::{BigRational, Ring, Scalar, SmallRational};
//! let third = SmallRational::from_ratio(1, 3).unwrap();
//! assert_eq!(&third + &third + &third, SmallRational::one());
//! // Past i64 the value moves to a big integer, exactly.
//! let big = SmallRational::from_i64(i64::MAX) * SmallRational::from_i64(4);
//! assert!(!big.is_small());
//! assert_eq!(BigRational::from(big), BigRational::from_i64(i64::MAX) * BigRational::from_i64(4));
//! ```

use crate::error::{Error, Result};
use crate::exact::gcd::{gcd_u128, gcd_u64};
use crate::scalar::{forward_ring_ops, Ring, Scalar};
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::fmt;

/// An exact rational number: two machine words while the value fits, a [`BigRational`]
/// beyond. See the [module documentation](self).
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct SmallRational(Repr);

#[derive(Clone, PartialEq, Eq, Hash)]
enum Repr {
    /// `num/den` in lowest terms, `den > 0`.
    Small { num: i64, den: i64 },
    /// A value that does not fit `Small` (never one that does: the form is canonical).
    Big(Box<BigRational>),
}

impl SmallRational {
    /// The integer `n` (always small).
    pub const fn from_int(n: i64) -> Self {
        SmallRational(Repr::Small { num: n, den: 1 })
    }

    /// Whether the value is held in machine words (it is exactly when it fits two `i64`s).
    pub fn is_small(&self) -> bool {
        matches!(self.0, Repr::Small { .. })
    }

    /// The numerator and (positive) denominator when the value is small.
    pub fn as_words(&self) -> Option<(i64, i64)> {
        match self.0 {
            Repr::Small { num, den } => Some((num, den)),
            Repr::Big(_) => None,
        }
    }

    /// The value as a [`BigRational`] (allocates).
    pub fn to_big(&self) -> BigRational {
        match &self.0 {
            Repr::Small { num, den } => BigRational::new_raw((*num).into(), (*den).into()),
            Repr::Big(b) => (**b).clone(),
        }
    }

    /// `num/den` for a fraction already in lowest terms with `den > 0`, small if it fits.
    fn from_reduced_i128(num: i128, den: i128) -> Self {
        debug_assert!(den > 0);
        if num == 0 {
            return SmallRational::from_int(0);
        }
        match (i64::try_from(num), i64::try_from(den)) {
            (Ok(num), Ok(den)) => SmallRational(Repr::Small { num, den }),
            _ => SmallRational(Repr::Big(Box::new(BigRational::new_raw(num.into(), den.into())))),
        }
    }

    /// `num/den` for any `den ≠ 0`: reduced and signed canonically.
    fn from_i128_ratio(num: i128, den: i128) -> Self {
        debug_assert!(den != 0);
        let g = gcd_u128(num.unsigned_abs(), den.unsigned_abs());
        // Dividing by g ≥ 1 cannot overflow except i128::MIN / 1, which `neg` below
        // would overflow: go through big integers for that single case.
        let (mut n, mut d) = match (num.checked_div(g as i128), den.checked_div(g as i128)) {
            (Some(n), Some(d)) if g <= i128::MAX as u128 => (n, d),
            _ => return Self::from_big(BigRational::new(num.into(), den.into())),
        };
        if d < 0 {
            match (n.checked_neg(), d.checked_neg()) {
                (Some(a), Some(b)) => (n, d) = (a, b),
                _ => return Self::from_big(BigRational::new(num.into(), den.into())),
            }
        }
        Self::from_reduced_i128(n, d)
    }

    /// A reduced [`BigRational`] in canonical form: small when it fits.
    fn from_big(r: BigRational) -> Self {
        match (r.numer().to_i64(), r.denom().to_i64()) {
            (Some(num), Some(den)) => SmallRational(Repr::Small { num, den }),
            _ => SmallRational(Repr::Big(Box::new(r))),
        }
    }

    /// Applies `small` to two small operands, or `big` to the values as [`BigRational`]s.
    #[inline]
    fn binary(
        &self,
        rhs: &Self,
        small: impl FnOnce(i64, i64, i64, i64) -> Self,
        big: impl FnOnce(&BigRational, &BigRational) -> BigRational,
    ) -> Self {
        match (&self.0, &rhs.0) {
            (&Repr::Small { num: a, den: b }, &Repr::Small { num: c, den: d }) => small(a, b, c, d),
            _ => Self::from_big(big(&self.to_big(), &rhs.to_big())),
        }
    }
}

/// `a/b + c/d` for reduced operands (Knuth 4.5.1: one gcd of the denominators, one of the
/// result, both on words).
#[inline]
fn add_small(a: i64, b: i64, c: i64, d: i64) -> SmallRational {
    if b == 1 && d == 1 {
        if let Some(s) = a.checked_add(c) {
            return SmallRational(Repr::Small { num: s, den: 1 });
        }
    }
    add_small_i128(a, b, c as i128, d)
}

/// `a/b - c/d` for reduced operands.
#[inline]
fn sub_small(a: i64, b: i64, c: i64, d: i64) -> SmallRational {
    if b == 1 && d == 1 {
        if let Some(s) = a.checked_sub(c) {
            return SmallRational(Repr::Small { num: s, den: 1 });
        }
    }
    // -c never overflows in i128.
    add_small_i128(a, b, -(c as i128), d)
}

/// `a/b + c/d` where `c` may be `-(i64::MIN)`: `|c| ≤ 2^63` keeps every product in `i128`.
fn add_small_i128(a: i64, b: i64, c: i128, d: i64) -> SmallRational {
    let g = gcd_u64(b as u64, d as u64) as i64;
    if g == 1 {
        // Reduced already: gcd(a d + c b, b d) = 1 when gcd(b, d) = 1.
        let num = a as i128 * d as i128 + c * b as i128;
        return SmallRational::from_reduced_i128(num, b as i128 * d as i128);
    }
    let (bg, dg) = ((b / g) as i128, (d / g) as i128);
    let t = a as i128 * dg + c * bg;
    // gcd(t, b d / g) = gcd(t, g): reduce by it.
    // g2 divides g ≤ d, so d / g2 stays on words; an i128 division only when g2 > 1.
    let g2 = gcd_u64((t.unsigned_abs() % g as u128) as u64, g as u64) as i64;
    if g2 == 1 {
        return SmallRational::from_reduced_i128(t, bg * d as i128);
    }
    SmallRational::from_reduced_i128(t / g2 as i128, bg * (d / g2) as i128)
}

/// `(a/b)(c/d)` for reduced operands: cross-cancel first, so the product is reduced.
#[inline]
fn mul_small(a: i64, b: i64, c: i64, d: i64) -> SmallRational {
    if b == 1 && d == 1 {
        if let Some(p) = a.checked_mul(c) {
            return SmallRational(Repr::Small { num: p, den: 1 });
        }
    }
    // Denominators are ≥ 1, so both gcds are ≥ 1; each divides a positive i64 (d or b), so
    // it is an i64 too and the divisions stay on words (an i128 division is a library call).
    let g1 = gcd_u64(a.unsigned_abs(), d as u64) as i64;
    let g2 = gcd_u64(c.unsigned_abs(), b as u64) as i64;
    let num = (a / g1) as i128 * (c / g2) as i128;
    let den = (b / g2) as i128 * (d / g1) as i128;
    SmallRational::from_reduced_i128(num, den)
}

impl Ring for SmallRational {
    fn zero() -> Self {
        SmallRational::from_int(0)
    }
    fn one() -> Self {
        SmallRational::from_int(1)
    }
    fn from_i64(n: i64) -> Self {
        SmallRational::from_int(n)
    }

    #[inline]
    fn add_ref(&self, rhs: &Self) -> Self {
        self.binary(rhs, add_small, |x, y| x + y)
    }

    #[inline]
    fn sub_ref(&self, rhs: &Self) -> Self {
        // -c never overflows in i128, so subtraction is addition of the negated numerator.
        self.binary(rhs, sub_small, |x, y| x - y)
    }

    #[inline]
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.binary(rhs, mul_small, |x, y| x * y)
    }

    #[inline]
    fn neg_ref(&self) -> Self {
        match &self.0 {
            Repr::Small { num, den } => match num.checked_neg() {
                Some(n) => SmallRational(Repr::Small { num: n, den: *den }),
                None => Self::from_reduced_i128(-(*num as i128), *den as i128),
            },
            Repr::Big(b) => Self::from_big(-(**b).clone()),
        }
    }
}

forward_ring_ops!(SmallRational);

impl Ord for SmallRational {
    fn cmp(&self, other: &Self) -> Ordering {
        match (&self.0, &other.0) {
            // Denominators are positive: compare a d with c b, exact in i128.
            (&Repr::Small { num: a, den: b }, &Repr::Small { num: c, den: d }) => {
                (a as i128 * d as i128).cmp(&(c as i128 * b as i128))
            }
            _ => self.to_big().cmp(&other.to_big()),
        }
    }
}

impl PartialOrd for SmallRational {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl From<i64> for SmallRational {
    fn from(n: i64) -> Self {
        SmallRational::from_int(n)
    }
}

impl From<BigRational> for SmallRational {
    /// Exact; `BigRational` values are reduced with a positive denominator already.
    fn from(r: BigRational) -> Self {
        SmallRational::from_big(r)
    }
}

impl From<&BigRational> for SmallRational {
    fn from(r: &BigRational) -> Self {
        match (r.numer().to_i64(), r.denom().to_i64()) {
            (Some(num), Some(den)) => SmallRational(Repr::Small { num, den }),
            _ => SmallRational(Repr::Big(Box::new(r.clone()))),
        }
    }
}

impl From<SmallRational> for BigRational {
    fn from(r: SmallRational) -> Self {
        match r.0 {
            Repr::Small { num, den } => BigRational::new_raw(num.into(), den.into()),
            Repr::Big(b) => *b,
        }
    }
}

impl From<&SmallRational> for BigRational {
    fn from(r: &SmallRational) -> Self {
        r.to_big()
    }
}

/// `p` or `p/q`, as [`BigRational`] prints.
impl fmt::Display for SmallRational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Repr::Small { num, den: 1 } => write!(f, "{num}"),
            Repr::Small { num, den } => write!(f, "{num}/{den}"),
            Repr::Big(b) => write!(f, "{b}"),
        }
    }
}

impl fmt::Debug for SmallRational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{self}")
    }
}

impl Default for SmallRational {
    fn default() -> Self {
        SmallRational::from_int(0)
    }
}

impl Scalar for SmallRational {
    const EXACT: bool = true;
    const NAME: &'static str = "small rational";

    fn is_zero(&self) -> bool {
        // Zero is small (it fits), so a big value is never zero.
        matches!(self.0, Repr::Small { num: 0, .. })
    }
    fn from_bigint(n: &BigInt) -> Result<Self> {
        Ok(match n.to_i64() {
            Some(num) => SmallRational::from_int(num),
            None => SmallRational(Repr::Big(Box::new(BigRational::from_integer(n.clone())))),
        })
    }
    fn from_rational(r: &BigRational) -> Result<Self> {
        Ok(SmallRational::from(r))
    }
    fn from_ratio(p: i64, q: i64) -> Result<Self> {
        // On words: the default goes through a BigRational.
        SmallRational::from_i128_pair(p.into(), q.into())
    }
    fn from_f64(x: f64) -> Result<Self> {
        BigRational::from_float(x)
            .map(SmallRational::from_big)
            .ok_or_else(|| Error::NotFinite(x.to_string()))
    }
    fn to_f64(&self) -> f64 {
        match &self.0 {
            // Both words below 2^53 convert exactly, so one division rounds correctly.
            Repr::Small { num, den } if num.unsigned_abs() < 1 << 53 && *den < 1 << 53 => *num as f64 / *den as f64,
            _ => ToPrimitive::to_f64(&self.to_big()).unwrap_or(f64::NAN),
        }
    }
    fn checked_div(&self, rhs: &Self) -> Result<Self> {
        if rhs.is_zero() {
            return Err(Error::DivisionByZero(format!("{self} / 0")));
        }
        Ok(match (&self.0, &rhs.0) {
            (&Repr::Small { num: a, den: b }, &Repr::Small { num: c, den: d }) => {
                // (a/b) / (c/d) = (a d) / (b c): cross-cancel as in `mul`, then fix the sign.
                let g1 = gcd_u64(a.unsigned_abs(), c.unsigned_abs()).max(1) as i128;
                let g2 = gcd_u64(b as u64, d as u64) as i128;
                let mut num = (a as i128 / g1) * (d as i128 / g2);
                let mut den = (b as i128 / g2) * (c as i128 / g1);
                if den < 0 {
                    // |den| ≤ 2^126: negation cannot overflow.
                    (num, den) = (-num, -den);
                }
                SmallRational::from_reduced_i128(num, den)
            }
            _ => SmallRational::from_big(self.to_big() / rhs.to_big()),
        })
    }
    fn abs(&self) -> Self {
        match &self.0 {
            Repr::Small { num, .. } if *num >= 0 => self.clone(),
            Repr::Small { .. } => self.neg_ref(),
            Repr::Big(b) => SmallRational::from_big(Signed::abs(&**b)),
        }
    }
}

impl SmallRational {
    /// The ratio `num/den` of two `i128`s, reduced; `den = 0` is an error.
    pub fn from_i128_pair(num: i128, den: i128) -> Result<Self> {
        if den == 0 {
            return Err(Error::DivisionByZero(format!("{num}/0")));
        }
        Ok(Self::from_i128_ratio(num, den))
    }

    /// Whether the value is an integer.
    pub fn is_integer(&self) -> bool {
        match &self.0 {
            Repr::Small { den, .. } => *den == 1,
            Repr::Big(b) => b.is_integer(),
        }
    }

    /// Whether the value is negative.
    pub fn is_negative(&self) -> bool {
        match &self.0 {
            Repr::Small { num, .. } => *num < 0,
            Repr::Big(b) => b.is_negative(),
        }
    }

    /// Whether the representation is canonical (lowest terms, positive denominator, big only
    /// when the value does not fit words): what makes the derived `==` exact.
    #[doc(hidden)]
    pub fn invariant_holds(&self) -> bool {
        match &self.0 {
            Repr::Small { num, den } => *den > 0 && num.unsigned_abs().gcd(&(*den as u64)) == 1,
            Repr::Big(b) => {
                !Zero::is_zero(&**b)
                    && b.denom().is_positive()
                    && (b.numer().to_i64().is_none() || b.denom().to_i64().is_none())
                    && b.numer().gcd(b.denom()) == BigInt::from(1)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s(p: i64, q: i64) -> SmallRational {
        SmallRational::from_i128_pair(p.into(), q.into()).unwrap()
    }

    #[test]
    fn gcds() {
        assert_eq!(gcd_u64(12, 18), 6);
        assert_eq!(gcd_u64(0, 7), 7);
        assert_eq!(gcd_u64(u64::MAX, u64::MAX), u64::MAX);
        assert_eq!(gcd_u128(1 << 100, 3 << 90), 1 << 90);
        assert_eq!(gcd_u128(u128::MAX, 5), 5);
    }

    #[test]
    fn edges_of_i64_move_to_big_and_back() {
        let min = SmallRational::from_int(i64::MIN);
        let neg = -&min;
        assert!(!neg.is_small() && neg.invariant_holds());
        assert_eq!(BigRational::from(neg.clone()), -BigRational::from_i64(i64::MIN));
        assert_eq!(-&neg, min);
        assert!((-&neg).is_small());
        assert_eq!(min.abs(), neg);
        let back = &neg - &SmallRational::from_int(1);
        assert!(back.is_small());
        assert_eq!(back, SmallRational::from_int(i64::MAX));
        let q = s(1, i64::MAX).checked_div(&s(i64::MIN, 1)).unwrap();
        assert!(q.invariant_holds(), "{q}");
        assert_eq!(
            q.to_big(),
            BigRational::new(BigInt::from(-1), BigInt::from(i64::MAX) * i64::MIN.unsigned_abs())
        );
        assert!(s(1, 2).checked_div(&SmallRational::from_int(0)).is_err());
        let huge = SmallRational::from_i128_pair(i128::MIN, -1).unwrap();
        assert!(huge.invariant_holds());
        assert_eq!(huge.to_big(), BigRational::from_integer(BigInt::from(1) << 127));
        assert_eq!(
            SmallRational::from_i128_pair(i128::MIN, i128::MIN).unwrap(),
            SmallRational::from_int(1)
        );
        assert_eq!(
            SmallRational::from_i128_pair(i128::MIN, 2).unwrap().to_big(),
            BigRational::from_integer(-(BigInt::from(1) << 126u32))
        );
        assert_eq!(s(-4, -6).to_string(), "2/3");
    }
}
