//! The number traits every algorithm of casteljau is generic over: [`Ring`] (what every
//! number can do, the prover's algebras included) and [`Scalar`] (a number the Bézier
//! algorithms run on).
//!
//! Two kinds of scalars run the same code: `f64`, for speed, and exact ones such as
//! [`BigRational`] (and the quadratic irrationals of [`crate::quadratic`]), to decide
//! identities with `==`. Exact scalars are `Clone`, not `Copy`, so generic code does its
//! arithmetic on references with the [`Ring`] methods (`a.mul_ref(&b)`), which need no
//! bound beyond `T: Scalar`.
//!
//! Exact scalars never overflow: [`BigRational`] is arbitrary precision. Conversions into
//! an exact type are exact (every finite `f64` is a dyadic rational); conversions that
//! cannot be exact (NaN, infinities, a rational too large for `f64`) are errors.

use crate::coords::{Point, PointN};
use crate::error::{Error, Result};
use crate::exact::fit_numbers::{self, FitNumbers};
use crate::exact::{fraction_free, power_basis};
use num_bigint::{BigInt, Sign};
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::ops::{Add, AddAssign, Mul, MulAssign, Neg, Sub, SubAssign};

mod ops;
mod ring;

pub(crate) use ops::forward_ring_ops;
pub use ring::Ring;

/// Operators on borrowed numbers: `&a + &b`, `&a - &b`, `&a * &b`, `-&a`.
///
/// Implemented automatically for `&T` whenever those operators exist. Generic code does not
/// need it (the [`Ring`] methods do the same on references); it names the bound
/// `for<'a> &'a T: RefOps<T>` for code written against operators.
pub trait RefOps<T>:
    Sized + Add<Self, Output = T> + Sub<Self, Output = T> + Mul<Self, Output = T> + Neg<Output = T>
{
}

impl<'a, T: 'a> RefOps<T> for &'a T where
    &'a T: Add<&'a T, Output = T> + Sub<&'a T, Output = T> + Mul<&'a T, Output = T> + Neg<Output = T>
{
}

/// A number type the Bézier algorithms can run on.
///
/// Division is not an operator: it is [`Scalar::checked_div`], so a zero divisor is an
/// error for every scalar, `f64` included.
///
/// ```
/// use casteljau::{BigRational, Ring, Scalar};
/// let third = BigRational::from_ratio(1, 3).unwrap();
/// assert!(BigRational::EXACT);
/// assert_eq!(&third + &third + &third, BigRational::one());
/// assert!(BigRational::from_ratio(1, 0).is_err());
/// ```
pub trait Scalar:
    Ring
    + PartialEq
    + PartialOrd
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Neg<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
    + for<'a> AddAssign<&'a Self>
    + for<'a> SubAssign<&'a Self>
    + for<'a> MulAssign<&'a Self>
{
    /// Whether arithmetic in this type is exact (comparisons by `==` decide identities).
    const EXACT: bool;
    /// A short name for reports ("f64", "rational", ...).
    const NAME: &'static str;

    /// Whether this is exactly zero.
    fn is_zero(&self) -> bool;
    /// The big integer `n`; an error for `f64` when it does not fit.
    fn from_bigint(n: &BigInt) -> Result<Self>;
    /// The rational `r`, exactly for exact types, rounded to nearest for `f64`.
    fn from_rational(r: &BigRational) -> Result<Self>;
    /// The float `x`: exactly its dyadic value for exact types; NaN and infinities are errors.
    fn from_f64(x: f64) -> Result<Self>;
    /// An approximation for display and for float comparisons.
    fn to_f64(&self) -> f64;
    /// `self / rhs`, or [`Error::DivisionByZero`].
    fn checked_div(&self, rhs: &Self) -> Result<Self>;

    /// The ratio `p/q`; `q = 0` is an error.
    fn from_ratio(p: i64, q: i64) -> Result<Self> {
        if q == 0 {
            return Err(Error::DivisionByZero(format!("{p}/{q}")));
        }
        Self::from_rational(&BigRational::new(p.into(), q.into()))
    }
    /// The count `n` as a scalar.
    fn from_usize(n: usize) -> Self {
        Self::from_i64(n as i64)
    }
    /// `|self|`.
    fn abs(&self) -> Self {
        if *self < Self::zero() {
            self.neg_ref()
        } else {
            self.clone()
        }
    }
    /// `self^k` by repeated squaring.
    fn powi(&self, mut k: u32) -> Self {
        let mut base = self.clone();
        let mut acc = Self::one();
        while k > 0 {
            if k & 1 == 1 {
                acc *= &base;
            }
            k >>= 1;
            if k > 0 {
                base = base.mul_ref(&base);
            }
        }
        acc
    }
    /// `Ok` for a genuine number. Scalars whose operators can produce an invalid value say
    /// why here: a [`crate::QuadraticIrrational`] that mixed `√2` with `√3` reports
    /// [`Error::MixedField`]. The default (f64, rationals) is always `Ok`.
    fn check(&self) -> Result<()> {
        Ok(())
    }
    /// Whether two values are equal: exactly for exact types, within `tol` (relative to the
    /// larger magnitude, absolute below 1) for floats.
    fn approx_eq(&self, other: &Self, tol: f64) -> bool {
        if Self::EXACT {
            return self == other;
        }
        let (a, b) = (self.to_f64(), other.to_f64());
        (a - b).abs() <= tol * a.abs().max(b.abs()).max(1.0)
    }

    // The kernel choice of the generic curve, surface and fitting code: each method below is
    // a type's own kernel for one operation, `None` (the default) when the type has none and
    // the caller runs its generic algorithm (`curve_eval` runs it itself, given as a
    // closure). Overridden for `BigRational` (the fraction-free kernels of `crate::exact`)
    // and `Interval` (the sign-split enclosure of `eval`). A method of the type, not a test
    // of type identity, so that the kernels need to import only numbers and points; the
    // default is inlined, so other types keep no trace of it.
    // Hidden: they are how the public methods choose, not an API of their own.

    /// Whether the curve kernels below run for this type (for [`PointN`] curves, which are
    /// handed to them as [`Point`]s only then).
    #[doc(hidden)]
    const CURVE_KERNELS: bool = false;
    /// `b(t)`, by `generic` (the generic algorithm) where the type has no kernel for it.
    /// The point itself is returned, not an `Option` of it: the `Option`'s tag put the
    /// point 8 bytes into a temporary, written there and copied out with loads that
    /// straddled the stores (an interval cubic's eval took 1.8x its kernel).
    #[doc(hidden)]
    #[inline(always)]
    fn curve_eval(points: &[Point<Self>], t: &Self, generic: impl FnOnce() -> Point<Self>) -> Point<Self> {
        let _ = (points, t);
        generic()
    }
    /// `b(t)` for a curve of fixed-dimension points: by the kernel for [`Point`]s when there
    /// is one, else by `generic`.
    #[doc(hidden)]
    #[inline(always)]
    fn curve_eval_fixed<const N: usize>(
        points: &[PointN<Self, N>],
        t: &Self,
        generic: impl FnOnce() -> PointN<Self, N>,
    ) -> PointN<Self, N> {
        if !Self::CURVE_KERNELS {
            return generic();
        }
        to_fixed(Self::curve_eval(&to_points(points), t, || {
            Point::from_valid(generic().0)
        }))
    }
    /// The `k`-th derivative vector at `t`, `k` at most the degree.
    #[doc(hidden)]
    #[inline(always)]
    fn curve_derivative_at(points: &[Point<Self>], k: usize, t: &Self) -> Option<Point<Self>> {
        let _ = (points, k, t);
        None
    }
    /// One step of degree elevation.
    #[doc(hidden)]
    #[inline(always)]
    fn curve_elevate(points: &[Point<Self>]) -> Option<Result<Vec<Point<Self>>>> {
        let _ = points;
        None
    }
    /// `r` steps of degree elevation.
    #[doc(hidden)]
    #[inline(always)]
    fn curve_elevate_by(points: &[Point<Self>], r: usize) -> Option<Result<Vec<Point<Self>>>> {
        let _ = (points, r);
        None
    }
    /// The two halves of a subdivision at `t`.
    #[doc(hidden)]
    #[inline(always)]
    #[allow(clippy::type_complexity)] // the two halves' points, named once here
    fn curve_split(points: &[Point<Self>], t: &Self) -> Option<(Vec<Point<Self>>, Vec<Point<Self>>)> {
        let _ = (points, t);
        None
    }
    /// The control points of the `k`-th derivative curve.
    #[doc(hidden)]
    #[inline(always)]
    fn curve_derivative(points: &[Point<Self>], k: usize) -> Option<Result<Vec<Point<Self>>>> {
        let _ = (points, k);
        None
    }
    /// The columns of the de Casteljau scheme at `t`, the control points first.
    #[doc(hidden)]
    #[inline(always)]
    fn curve_scheme(points: &[Point<Self>], t: &Self) -> Option<Vec<Vec<Point<Self>>>> {
        let _ = (points, t);
        None
    }
    /// The power-basis coefficients of a curve (its degree already checked).
    #[doc(hidden)]
    #[inline(always)]
    fn curve_to_power(points: &[Point<Self>]) -> Option<Vec<Point<Self>>> {
        let _ = points;
        None
    }
    /// The control points of the curve with power-basis coefficients `coeffs` (the degree
    /// already checked).
    #[doc(hidden)]
    #[inline(always)]
    fn curve_from_power(coeffs: &[Point<Self>]) -> Option<Vec<Point<Self>>> {
        let _ = coeffs;
        None
    }
    /// `x / w`, `w ≠ 0`.
    #[doc(hidden)]
    #[inline(always)]
    fn quotient(x: &Self, w: &Self) -> Option<Self> {
        let _ = (x, w);
        None
    }
    /// A rational curve at `t`, from its homogeneous control points; `Some(None)` when its
    /// denominator vanishes there.
    #[doc(hidden)]
    #[inline(always)]
    fn rational_eval(homogeneous: &[Point<Self>], t: &Self) -> Option<Option<Point<Self>>> {
        let _ = (homogeneous, t);
        None
    }
    /// A rational curve's derivative at `t`, from its homogeneous control points;
    /// `Some(None)` when its denominator vanishes there.
    #[doc(hidden)]
    #[inline(always)]
    fn rational_derivative_at(homogeneous: &[Point<Self>], t: &Self) -> Option<Option<Point<Self>>> {
        let _ = (homogeneous, t);
        None
    }
    /// A tensor-product surface at `(u, v)`.
    #[doc(hidden)]
    #[inline(always)]
    fn surface_eval(net: &[Vec<Point<Self>>], u: &Self, v: &Self) -> Option<Point<Self>> {
        let _ = (net, u, v);
        None
    }
    /// A surface's power-basis coefficients (its degrees already checked).
    #[doc(hidden)]
    #[inline(always)]
    fn surface_to_power(net: &[Vec<Point<Self>>]) -> Option<Vec<Vec<Point<Self>>>> {
        let _ = net;
        None
    }
    /// Text 004's cubic fit from `x(0)`, `x(1)`, `x(1/2)`, `ẋ(0)`, `ẋ(1)` (validated):
    /// `Some(None)` when the end tangents are parallel.
    #[doc(hidden)]
    #[inline(always)]
    fn cubic_fit(data: [&Point<Self>; 5]) -> Option<Option<FitNumbers<Self>>> {
        let _ = data;
        None
    }
}

/// Fixed-dimension points as [`Point`]s, for the kernels on [`Point`]s.
pub(crate) fn to_points<T: Clone, const N: usize>(points: &[PointN<T, N>]) -> Vec<Point<T>> {
    points.iter().map(|p| Point::from_valid(p.0.iter().cloned())).collect()
}

/// A kernel's point back as the fixed-dimension point it was computed for (the kernels keep
/// the dimension of the points they are given).
pub(crate) fn to_fixed<T, const N: usize>(p: Point<T>) -> PointN<T, N> {
    match p.into_coords().try_into() {
        Ok(coords) => PointN(coords),
        Err(_) => unreachable!("the kernels keep the dimension"),
    }
}

impl Scalar for f64 {
    const EXACT: bool = false;
    const NAME: &'static str = "f64";

    #[inline]
    fn is_zero(&self) -> bool {
        *self == 0.0
    }
    #[inline]
    fn from_bigint(n: &BigInt) -> Result<Self> {
        finite(n.to_f64().unwrap_or(f64::INFINITY), || n.to_string())
    }
    #[inline]
    fn from_rational(r: &BigRational) -> Result<Self> {
        finite(ToPrimitive::to_f64(r).unwrap_or(f64::NAN), || r.to_string())
    }
    #[inline]
    fn from_f64(x: f64) -> Result<Self> {
        finite(x, || x.to_string())
    }
    #[inline]
    fn to_f64(&self) -> f64 {
        *self
    }
    #[inline]
    fn checked_div(&self, rhs: &Self) -> Result<Self> {
        if *rhs == 0.0 {
            return Err(Error::DivisionByZero(format!("{self} / 0")));
        }
        Ok(self / rhs)
    }
}

fn finite(x: f64, shown: impl FnOnce() -> String) -> Result<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(Error::NotFinite(shown()))
    }
}

impl Scalar for BigRational {
    const EXACT: bool = true;
    const NAME: &'static str = "rational";

    fn is_zero(&self) -> bool {
        Zero::is_zero(self)
    }
    fn from_bigint(n: &BigInt) -> Result<Self> {
        Ok(BigRational::from_integer(n.clone()))
    }
    fn from_rational(r: &BigRational) -> Result<Self> {
        Ok(r.clone())
    }
    fn from_f64(x: f64) -> Result<Self> {
        crate::float::f64_to_rational(x).ok_or_else(|| Error::NotFinite(x.to_string()))
    }
    fn to_f64(&self) -> f64 {
        ToPrimitive::to_f64(self).unwrap_or(f64::NAN)
    }
    fn checked_div(&self, rhs: &Self) -> Result<Self> {
        if Zero::is_zero(rhs) {
            return Err(Error::DivisionByZero(format!("{self} / 0")));
        }
        Ok(self / rhs)
    }
    fn abs(&self) -> Self {
        Signed::abs(self)
    }

    // The fraction-free kernels of `crate::exact`: out of line, so that the generic code
    // that chooses them stays small.
    const CURVE_KERNELS: bool = true;
    #[inline(never)]
    fn curve_eval(points: &[Point<Self>], t: &Self, _generic: impl FnOnce() -> Point<Self>) -> Point<Self> {
        fraction_free::eval(points, t)
    }
    #[inline(never)]
    fn curve_derivative_at(points: &[Point<Self>], k: usize, t: &Self) -> Option<Point<Self>> {
        Some(fraction_free::derivative_at(points, k, t))
    }
    #[inline(never)]
    fn curve_elevate(points: &[Point<Self>]) -> Option<Result<Vec<Point<Self>>>> {
        Some(fraction_free::elevate(points))
    }
    #[inline(never)]
    fn curve_elevate_by(points: &[Point<Self>], r: usize) -> Option<Result<Vec<Point<Self>>>> {
        Some(fraction_free::elevate_by(points, r))
    }
    #[inline(never)]
    fn curve_split(points: &[Point<Self>], t: &Self) -> Option<(Vec<Point<Self>>, Vec<Point<Self>>)> {
        Some(fraction_free::split(points, t))
    }
    #[inline(never)]
    fn curve_derivative(points: &[Point<Self>], k: usize) -> Option<Result<Vec<Point<Self>>>> {
        Some(fraction_free::derivative(points, k))
    }
    #[inline(never)]
    fn curve_scheme(points: &[Point<Self>], t: &Self) -> Option<Vec<Vec<Point<Self>>>> {
        Some(fraction_free::scheme(points, t))
    }
    fn curve_to_power(points: &[Point<Self>]) -> Option<Vec<Point<Self>>> {
        Some(power_basis::curve_power(points))
    }
    fn curve_from_power(coeffs: &[Point<Self>]) -> Option<Vec<Point<Self>>> {
        let coeffs: Vec<&Point<Self>> = coeffs.iter().collect();
        Some(power_basis::curve_from_power(&coeffs))
    }
    /// By Knuth's two gcds ([`crate::exact::gcd::divide`]), where num-rational's division
    /// runs its binary gcd on the products.
    fn quotient(x: &Self, w: &Self) -> Option<Self> {
        Some(crate::exact::gcd::divide(x, w))
    }
    fn rational_eval(homogeneous: &[Point<Self>], t: &Self) -> Option<Option<Point<Self>>> {
        Some(fraction_free::rational_eval(homogeneous, t))
    }
    fn rational_derivative_at(homogeneous: &[Point<Self>], t: &Self) -> Option<Option<Point<Self>>> {
        // a constant curve's derivative is the reference's (zero)
        (homogeneous.len() > 1).then(|| fraction_free::rational_derivative_at(homogeneous, t))
    }
    fn surface_eval(net: &[Vec<Point<Self>>], u: &Self, v: &Self) -> Option<Point<Self>> {
        Some(fraction_free::surface_point(net, u, v))
    }
    fn surface_to_power(net: &[Vec<Point<Self>>]) -> Option<Vec<Vec<Point<Self>>>> {
        Some(power_basis::net_power(net))
    }
    fn cubic_fit([x0, x1, xh, d0, d1]: [&Point<Self>; 5]) -> Option<Option<FitNumbers<Self>>> {
        Some(fit_numbers::fit_cubic(&fit_numbers::FitData { x0, x1, xh, d0, d1 }))
    }
}

/// Largest decimal exponent [`parse_exact`] accepts: `1e999999999` would need a billion
/// digits, which is a typo or an attack, not a coordinate.
pub const MAX_DECIMAL_EXPONENT: i64 = 4_096;

/// Largest number of characters [`parse_exact`] accepts in one number.
pub const MAX_NUMBER_LEN: usize = 10_000;

/// Parses an exact rational written as an integer (`-3`), a fraction (`4/3`, `-1/2`), or a
/// decimal with optional exponent (`0.25`, `1e-3`, `-2.5E+2`). The value is exact: `0.1`
/// is `1/10`, not the nearest float.
///
/// ```
/// use casteljau::parse_exact;
/// use casteljau::BigRational;
/// assert_eq!(parse_exact("0.1").unwrap(), BigRational::new(1.into(), 10.into()));
/// assert_eq!(parse_exact("-4/6").unwrap(), BigRational::new((-2).into(), 3.into()));
/// assert!(parse_exact("1/0").is_err());
/// assert!(parse_exact("1e999999999").is_err());
/// ```
pub fn parse_exact(text: &str) -> Result<BigRational> {
    let s = text.trim();
    if s.is_empty() {
        return Err(Error::Parse("empty number".into()));
    }
    if s.len() > MAX_NUMBER_LEN {
        return Err(Error::TooLarge {
            what: "number literal",
            value: format!("{} characters", s.len()),
            limit: format!("{MAX_NUMBER_LEN} characters"),
        });
    }
    if let Some((p, q)) = s.split_once('/') {
        if let Some(r) = word_fraction(p.trim(), q.trim()) {
            return Ok(r);
        }
        let num = parse_decimal(p.trim(), text)?;
        let den = parse_decimal(q.trim(), text)?;
        if Zero::is_zero(&den) {
            return Err(Error::DivisionByZero(format!("'{text}' has a zero denominator")));
        }
        return Ok(quotient(num, den));
    }
    parse_decimal(s, text)
}

fn parse_decimal(s: &str, whole: &str) -> Result<BigRational> {
    let bad = || {
        Error::Parse(format!(
            "'{whole}' is not a number (write an integer, p/q, or a decimal like 0.25 or 1e-3)"
        ))
    };
    let (negative, body) = match s.as_bytes().first() {
        Some(b'-') => (true, &s[1..]),
        Some(b'+') => (false, &s[1..]),
        _ => (false, s),
    };
    let (mantissa, exponent) = match body.find(['e', 'E']) {
        Some(i) => {
            let exp_text = &body[i + 1..];
            let digits = exp_text.trim_start_matches(['+', '-']);
            if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) || exp_text.len() - digits.len() > 1 {
                return Err(bad());
            }
            let magnitude: i64 = if digits.len() > 9 {
                i64::MAX
            } else {
                digits.parse().map_err(|_| bad())?
            };
            let exp = if exp_text.starts_with('-') {
                -magnitude
            } else {
                magnitude
            };
            (&body[..i], exp)
        }
        None => (body, 0),
    };
    let (int_part, frac_part) = match mantissa.split_once('.') {
        Some((a, b)) => (a, b),
        None => (mantissa, ""),
    };
    if int_part.is_empty() && frac_part.is_empty()
        || !int_part.bytes().all(|b| b.is_ascii_digit())
        || !frac_part.bytes().all(|b| b.is_ascii_digit())
    {
        return Err(bad());
    }
    let digits = format!("{int_part}{frac_part}");
    let mut value = BigInt::parse_bytes(digits.as_bytes(), 10).ok_or_else(bad)?;
    if negative {
        value = -value;
    }
    let scale = exponent.saturating_sub(frac_part.len() as i64);
    if Zero::is_zero(&value) {
        return Ok(<BigRational as Zero>::zero());
    }
    if scale.abs() > MAX_DECIMAL_EXPONENT {
        return Err(Error::TooLarge {
            what: "decimal exponent",
            value: if exponent.abs() > 999_999_999 {
                "more than 999999999".to_string()
            } else {
                exponent.to_string()
            },
            limit: format!("±{MAX_DECIMAL_EXPONENT}"),
        });
    }
    if let Some(small) = small_decimal(&value, scale) {
        return Ok(small);
    }
    let ten = BigInt::from(10);
    let power = num_traits::pow(ten, scale.unsigned_abs() as usize);
    Ok(if scale >= 0 {
        BigRational::from_integer(value * power)
    } else {
        BigRational::new(value, power)
    })
}

/// `p/q` in lowest terms on machine words when both are integers of at most 38 digits and
/// `q ≠ 0` (anything else takes the general path, and its errors): no big integer is built
/// before the result, since an oracle request of 30-digit fractions is thousands of them.
fn word_fraction(p: &str, q: &str) -> Option<BigRational> {
    fn integer(s: &str) -> Option<(bool, u128)> {
        let (negative, digits) = match s.as_bytes().first()? {
            b'-' => (true, &s[1..]),
            b'+' => (false, &s[1..]),
            _ => (false, s),
        };
        // 10^38 < 2^127: 38 digits cannot overflow
        if digits.is_empty() || digits.len() > 38 {
            return None;
        }
        let mut value = 0u128;
        for b in digits.bytes() {
            if !b.is_ascii_digit() {
                return None;
            }
            value = value * 10 + u128::from(b - b'0');
        }
        Some((negative, value))
    }
    let ((p_negative, p), (q_negative, q)) = (integer(p)?, integer(q)?);
    if q == 0 {
        return None;
    }
    let g = crate::exact::gcd::gcd_u128(p, q);
    let (p, q) = (BigInt::from(p / g), BigInt::from(q / g));
    Some(BigRational::new_raw(if p_negative != q_negative { -p } else { p }, q))
}

/// `value · 10^scale` in lowest terms on machine words, when `value` and `10^|scale|` fit
/// 64 bits: the oracle reads thousands of short decimals, and `BigRational::new` reduces
/// each with num-bigint's binary gcd.
fn small_decimal(value: &BigInt, scale: i64) -> Option<BigRational> {
    let v = value.to_i64()?;
    let power = 10u64.checked_pow(u32::try_from(scale.unsigned_abs()).ok()?)?;
    if scale >= 0 {
        let n = i128::from(v) * i128::from(power);
        return Some(BigRational::from_integer(BigInt::from(n)));
    }
    let g = crate::exact::gcd::gcd_u128(u128::from(v.unsigned_abs()), u128::from(power)) as u64;
    let (num, den) = (v / g as i64, power / g);
    Some(BigRational::new_raw(BigInt::from(num), BigInt::from(den)))
}

/// `num / den` of two parsed numbers, `den ≠ 0`, on machine words when both are integers of
/// 64 bits (the usual `"p/q"`).
fn quotient(num: BigRational, den: BigRational) -> BigRational {
    if num.denom().is_one() && den.denom().is_one() {
        if let (Some(p), Some(q)) = (num.numer().to_i64(), den.numer().to_i64()) {
            let negative = (p < 0) != (q < 0);
            let (p, q) = (u128::from(p.unsigned_abs()), u128::from(q.unsigned_abs()));
            let g = crate::exact::gcd::gcd_u128(p, q);
            // |p|/g and |q|/g fit 64 bits unsigned; the sign goes to the numerator.
            let (p, q) = ((p / g) as i128, (q / g) as i128);
            return BigRational::new_raw(BigInt::from(if negative { -p } else { p }), BigInt::from(q));
        }
    }
    // Knuth's two gcds by Lehmer's algorithm, not num-rational's division (its binary gcd of
    // the whole numbers was two thirds of reading a request of 100-digit fractions).
    crate::exact::gcd::divide(&num, &den)
}

/// Formats an exact rational in lowest terms as `p` or `p/q` with a positive denominator.
///
/// What `Display` prints, without its padding machinery; a power-of-two denominator (every
/// exact value computed from floats has one) is written from a per-thread cache, since the
/// same few powers come back in every answer.
pub fn format_exact(r: &BigRational) -> String {
    // num-rational keeps ratios reduced with a positive denominator.
    let mut s = r.numer().to_str_radix(10);
    let d = r.denom();
    if !d.is_one() {
        s.push('/');
        match d.trailing_zeros() {
            Some(k) if k + 1 == d.bits() && k < POWER_OF_TWO_CACHE as u64 => push_power_of_two(&mut s, k as usize),
            _ => s.push_str(&d.to_str_radix(10)),
        }
    }
    s
}

/// Powers of two `2^k`, `k <` this, whose decimal digits [`format_exact`] keeps (about
/// 0.3 MB when all are used): the exponents of f64 results up to degree 4 or so.
const POWER_OF_TWO_CACHE: usize = 1536;

fn push_power_of_two(s: &mut String, k: usize) {
    thread_local! {
        static DIGITS: std::cell::RefCell<Vec<Option<Box<str>>>> = const { std::cell::RefCell::new(Vec::new()) };
    }
    DIGITS.with_borrow_mut(|cache| {
        if cache.len() <= k {
            cache.resize(k + 1, None);
        }
        let digits = cache[k].get_or_insert_with(|| (BigInt::one() << k).to_str_radix(10).into_boxed_str());
        s.push_str(digits);
    })
}

/// The sign of an exact rational as -1, 0 or 1.
pub fn sign(r: &BigRational) -> i32 {
    match r.numer().sign() {
        Sign::Minus => -1,
        Sign::NoSign => 0,
        Sign::Plus => 1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> BigRational {
        BigRational::new(p.into(), d.into())
    }

    /// The machine-word paths of decimals and `p/q` give what `BigRational::new` gives, in
    /// the same canonical form, at and beyond the edges of 64 bits.
    #[test]
    fn short_decimals_and_fractions_are_exact() {
        let big = |s: &str| s.parse::<BigInt>().unwrap();
        let cases: [(&str, BigRational); 12] = [
            ("668.45", BigRational::new(big("66845"), big("100"))),
            ("-0.0040", BigRational::new(big("-40"), big("10000"))),
            ("12e3", BigRational::from_integer(big("12000"))),
            (
                "9223372036854775807.5",
                BigRational::new(big("92233720368547758075"), big("10")),
            ),
            (
                "-9.223372036854775808",
                BigRational::new(big("-9223372036854775808"), big("1000000000000000000")),
            ),
            ("1e-19", BigRational::new(big("1"), big("10000000000000000000"))),
            ("1e-20", BigRational::new(big("1"), big("100000000000000000000"))),
            ("-744/12", BigRational::new(big("-744"), big("12"))),
            ("744/-12", BigRational::new(big("744"), big("-12"))),
            (
                "-9223372036854775808/-9223372036854775808",
                BigRational::from_integer(big("1")),
            ),
            ("0/-5", BigRational::from_integer(big("0"))),
            ("3/4.5", BigRational::new(big("2"), big("3"))),
        ];
        for (text, expected) in cases {
            let parsed = parse_exact(text).unwrap();
            assert_eq!(format!("{parsed:?}"), format!("{expected:?}"), "{text}");
        }
    }

    #[test]
    fn format_exact_prints_what_display_prints() {
        let mut values = vec![q(0, 1), q(-7, 1), q(6, -4), q(1, 3), q(-5, 12)];
        for k in [
            1usize,
            2,
            63,
            64,
            65,
            200,
            POWER_OF_TWO_CACHE - 1,
            POWER_OF_TWO_CACHE,
            3000,
        ] {
            let d = BigInt::one() << k;
            values.push(BigRational::new(BigInt::from(-3), d.clone()));
            values.push(BigRational::new((BigInt::one() << (k + 7)) + 1u32, d.clone()));
            values.push(BigRational::new(BigInt::one(), d * 3u32));
        }
        for _ in 0..2 {
            // the second round reads the cache the first one filled
            for v in &values {
                assert_eq!(format_exact(v), v.to_string());
            }
        }
    }

    #[test]
    fn parses_exact_numbers() {
        assert_eq!(parse_exact("3").unwrap(), q(3, 1));
        assert_eq!(parse_exact(" -4/6 ").unwrap(), q(-2, 3));
        assert_eq!(parse_exact("0.25").unwrap(), q(1, 4));
        assert_eq!(parse_exact("1e-3").unwrap(), q(1, 1000));
        assert_eq!(parse_exact("-2.5E+2").unwrap(), q(-250, 1));
        assert_eq!(parse_exact(".5").unwrap(), q(1, 2));
        assert_eq!(parse_exact("1.5/0.5").unwrap(), q(3, 1));
        assert_eq!(parse_exact("0e999999999").unwrap(), q(0, 1));
    }

    #[test]
    fn rejects_bad_numbers() {
        for bad in [
            "",
            "abc",
            "1/0",
            "1e",
            "1e+-3",
            "--1",
            "1.2.3",
            ".",
            "1e999999999",
            "1e-99999",
            "nan",
            "inf",
        ] {
            assert!(parse_exact(bad).is_err(), "{bad} should be rejected");
        }
        let msg = parse_exact("1e999999999").unwrap_err().to_string();
        assert!(msg.contains("too large"), "{msg}");
    }

    #[test]
    fn f64_to_rational_is_exact() {
        let r = BigRational::from_f64(0.1).unwrap();
        assert_ne!(r, q(1, 10));
        assert_eq!(r, BigRational::new(3602879701896397u64.into(), (1u64 << 55).into()));
        assert!(BigRational::from_f64(f64::NAN).is_err());
        assert!(BigRational::from_f64(f64::INFINITY).is_err());
        assert_eq!(Scalar::to_f64(&r), 0.1);
    }

    #[test]
    fn division_by_zero_is_an_error_for_every_scalar() {
        assert!(1.0f64.checked_div(&0.0).is_err());
        assert!(q(1, 2).checked_div(&q(0, 1)).is_err());
        assert_eq!(q(1, 2).checked_div(&q(1, 4)).unwrap(), q(2, 1));
    }

    #[test]
    fn huge_rational_does_not_become_infinite_float() {
        let huge = parse_exact("1e400").unwrap();
        assert!(f64::from_rational(&huge).is_err());
    }

    #[test]
    fn powi_matches_repeated_multiplication() {
        assert_eq!(q(2, 3).powi(5), q(32, 243));
        assert_eq!(q(2, 3).powi(0), q(1, 1));
        assert_eq!(3.0f64.powi(4), 81.0);
    }
}
