//! The integers the fraction-free kernels run on: `i128`, every operation checked, and
//! [`BigInt`].

use crate::exact::gcd::gcd_u128;
use crate::exact::gcd::{self, Part};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive};

/// The integers a kernel runs on: `i128` with checked arithmetic (`None` on overflow) or
/// [`BigInt`] (never `None`).
pub(crate) trait Int: Clone + Sized {
    /// Whether this is [`BigInt`] (the tier that never overflows).
    const IS_BIG: bool;
    fn from_big(x: &BigInt) -> Option<Self>;
    fn from_u64(x: u64) -> Self;
    fn zero() -> Self {
        Self::from_u64(0)
    }
    fn one() -> Self {
        Self::from_u64(1)
    }
    fn add(&self, o: &Self) -> Option<Self>;
    fn sub(&self, o: &Self) -> Option<Self>;
    /// `self ← o − self`.
    fn sub_from(&mut self, o: &Self) -> Option<()> {
        *self = o.sub(self)?;
        Some(())
    }
    fn mul(&self, o: &Self) -> Option<Self>;
    /// `self / o` for an `o` known to divide `self`.
    fn div_exact(&self, o: &Self) -> Self;
    /// The least common multiple of two positive integers.
    fn lcm(&self, o: &Self) -> Option<Self>;
    /// `self ← s·self + c·x`, the step of both the nested and the de Casteljau kernels.
    fn step(&mut self, s: &Self, c: &Self, x: &Self) -> Option<()> {
        *self = self.mul(s)?.add(&c.mul(x)?)?;
        Some(())
    }
    /// The reduced rational `num / den`, `den ≠ 0`.
    fn ratio(num: Self, den: Self) -> BigRational;
    /// The reduced rational `num / (den · base^e)`, `den, base > 0`; `None` on overflow.
    fn ratio_over_power(num: Self, den: &Self, base: &Self, e: usize) -> Option<BigRational> {
        Some(Self::ratio(num, den.mul(&power(base, e)?)?))
    }
    fn into_big(self) -> BigInt;
}

impl Int for i128 {
    const IS_BIG: bool = false;
    fn from_big(x: &BigInt) -> Option<Self> {
        x.to_i128()
    }
    fn from_u64(x: u64) -> Self {
        x as i128
    }
    #[inline]
    fn add(&self, o: &Self) -> Option<Self> {
        self.checked_add(*o)
    }
    #[inline]
    fn sub(&self, o: &Self) -> Option<Self> {
        self.checked_sub(*o)
    }
    #[inline]
    fn mul(&self, o: &Self) -> Option<Self> {
        // Products of two values below 2^63 in magnitude cannot overflow: skip the check.
        if (*self as i64 as i128 == *self) && (*o as i64 as i128 == *o) {
            Some(self * o)
        } else {
            self.checked_mul(*o)
        }
    }
    fn div_exact(&self, o: &Self) -> Self {
        // Small operands divide in one machine instruction instead of a 128-bit routine.
        match (i64::try_from(*self), i64::try_from(*o)) {
            (Ok(a), Ok(b)) if b != -1 => (a / b) as i128,
            _ => self / o,
        }
    }
    fn lcm(&self, o: &Self) -> Option<Self> {
        let g = gcd_u128(self.unsigned_abs(), o.unsigned_abs()) as i128;
        (self / g).checked_mul(*o)
    }
    #[inline]
    fn step(&mut self, s: &Self, c: &Self, x: &Self) -> Option<()> {
        *self = Int::mul(self, s)?.checked_add(Int::mul(c, x)?)?;
        Some(())
    }
    fn ratio(num: Self, den: Self) -> BigRational {
        let g = gcd_u128(num.unsigned_abs(), den.unsigned_abs());
        // g ≤ |den| ≤ 2^127; |num|/g and |den|/g fit u128, the sign goes separately.
        let (n, d) = (num.unsigned_abs() / g, den.unsigned_abs() / g);
        let negative = (num < 0) != (den < 0);
        // Through u64 when it fits: BigInt's u128 conversion builds its digits one by one.
        let big = |x: u128| u64::try_from(x).map_or_else(|_| BigInt::from(x), BigInt::from);
        let n = if negative { -big(n) } else { big(n) };
        BigRational::new_raw(n, big(d))
    }
    fn into_big(self) -> BigInt {
        BigInt::from(self)
    }
}

impl Int for BigInt {
    const IS_BIG: bool = true;
    fn from_big(x: &BigInt) -> Option<Self> {
        Some(x.clone())
    }
    fn from_u64(x: u64) -> Self {
        BigInt::from(x)
    }
    fn add(&self, o: &Self) -> Option<Self> {
        Some(self + o)
    }
    fn sub(&self, o: &Self) -> Option<Self> {
        Some(self - o)
    }
    fn sub_from(&mut self, o: &Self) -> Option<()> {
        // `o − self` into self's digits: no fresh integer per step.
        *self = o - std::mem::take(self);
        Some(())
    }
    fn mul(&self, o: &Self) -> Option<Self> {
        Some(self * o)
    }
    fn div_exact(&self, o: &Self) -> Self {
        self / o
    }
    fn lcm(&self, o: &Self) -> Option<Self> {
        Some(gcd::lcm_int(self, o))
    }
    fn step(&mut self, s: &Self, c: &Self, x: &Self) -> Option<()> {
        // In place: one temporary for c·x instead of three fresh integers.
        *self *= s;
        *self += c * x;
        Some(())
    }
    fn ratio(num: Self, den: Self) -> BigRational {
        // A rational curve's weight w(t) may be negative: the sign goes to the numerator.
        let (num, den) = if den.is_negative() { (-num, -den) } else { (num, den) };
        gcd::reduce(num, &[Part::Number(&den)])
    }
    fn ratio_over_power(num: Self, den: &Self, base: &Self, e: usize) -> Option<BigRational> {
        Some(gcd::reduce(num, &[Part::Power(base, e), Part::Number(den)]))
    }
    fn into_big(self) -> BigInt {
        self
    }
}

/// `base^e`, checked.
pub(super) fn power<I: Int>(base: &I, e: usize) -> Option<I> {
    let mut acc = I::one();
    let mut b = base.clone();
    let mut e = e;
    while e > 0 {
        if e & 1 == 1 {
            acc = acc.mul(&b)?;
        }
        e >>= 1;
        if e > 0 {
            b = b.mul(&b)?;
        }
    }
    Some(acc)
}
