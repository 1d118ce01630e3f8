//! Quadratic irrationals `a + b√d`: an exact [`Scalar`] for control points such as
//! `(3, -2√2)` (text 001, Example 2); everything about them is on [`QuadraticIrrational`].

use crate::error::{Error, Result};
use crate::scalar::{forward_ring_ops, parse_exact, sign, Ring, Scalar};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::fmt;
use std::str::FromStr;

/// Largest `|d|` accepted as a radicand: square-freeness is checked by trial division, and
/// a larger `d` is far more likely a typo than a field anyone computes in.
pub const MAX_RADICAND: i64 = 1 << 40;

/// Which field a value lives in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Field {
    /// `b = 0`: a rational, compatible with every field.
    Rational,
    /// `Q(√d)` with `b ≠ 0`.
    Sqrt(i64),
    /// The poison of mixing `Q(√d)` and `Q(√e)`.
    Mixed(i64, i64),
}

/// The number `a + b√d`, with `a, b` exact rationals and `d` a square-free
/// integer other than 0 and 1. Within one field `Q(√d)` the arithmetic is exact and closed
/// (division included: `1/(a + b√d) = (a - b√d)/(a² - b²d)`), so the generic Bézier code of
/// the crate runs on it unchanged and identities are decided with `==`.
///
/// # Which `d`
/// * `d` must be square-free and `≠ 0, 1`, with `|d| ≤` [`MAX_RADICAND`];
///   [`QuadraticIrrational::new`] rejects anything else. [`QuadraticIrrational::sqrt`] is more
///   forgiving: it takes any integer and pulls out square factors (`sqrt(8) = 2√2`,
///   `sqrt(9) = 3`).
/// * Negative `d` is allowed (`√-1` is the imaginary unit): arithmetic and `==` stay exact,
///   but such numbers are not real, so `partial_cmp` returns `None` for them and `to_f64`
///   gives NaN.
/// * For `d > 0` the order is exact: the sign of `a + b√d` is decided by comparing `a²`
///   with `b²d`, never in floating point.
///
/// # Mixing fields
/// Operators cannot return `Result`, so mixing is designed to never yield a wrong number:
/// * a value with `b = 0` is rational and belongs to no field: it combines with any field
///   (`2 + √3` is fine, and `√2·√2 = 2` becomes field-free again);
/// * combining two irrational values of different fields (`√2 + √3`) yields a *poisoned*
///   value. A poisoned value stays poisoned through every operation, compares unequal to
///   everything (itself included) and is unordered, prints as `<invalid: ...>`, and makes
///   [`Scalar::checked_div`], [`Scalar::check`], [`QuadraticIrrational::is_valid`] and the
///   conversions report [`Error::MixedField`]. `to_f64` gives NaN.
/// * constructors from user data ([`QuadraticIrrational::new`], [`QuadraticIrrational::sqrt`],
///   parsing) return `Result`.
///
/// `Display` writes `3 - 2*sqrt(2)`, which [`QuadraticIrrational::parse`] (and `FromStr`)
/// read back; `√` is accepted on input too (`3 - 2√2`).
///
/// ```
/// use casteljau::{QuadraticIrrational, Ring, Scalar, BigRational};
/// let r2 = QuadraticIrrational::sqrt(2).unwrap();
/// let x = QuadraticIrrational::from_i64(3) - &(&QuadraticIrrational::from_i64(2) * &r2);
/// assert_eq!(x.to_string(), "3 - 2*sqrt(2)");
/// assert_eq!(x.norm(), BigRational::from_i64(1)); // 9 - 4·2
/// assert!(x > QuadraticIrrational::from_i64(0)); // 3 > 2√2, decided exactly
/// assert_eq!("3 - 2*sqrt(2)".parse::<QuadraticIrrational>().unwrap(), x);
/// let mixed = &r2 + &QuadraticIrrational::sqrt(3).unwrap();
/// assert!(!mixed.is_valid());
/// assert!(mixed.check().is_err());
/// ```
#[derive(Clone, Debug)]
pub struct QuadraticIrrational {
    a: BigRational,
    b: BigRational,
    field: Field,
}

fn q0() -> BigRational {
    <BigRational as Zero>::zero()
}

/// Whether `n ≠ 0` has no square factor `> 1`.
fn is_square_free(n: i64) -> bool {
    let m = n.unsigned_abs();
    let mut p: u64 = 2;
    while p * p <= m {
        if m % (p * p) == 0 {
            return false;
        }
        p += 1;
    }
    true
}

fn check_radicand_size(d: i64) -> Result<()> {
    if d.unsigned_abs() > MAX_RADICAND as u64 {
        return Err(Error::TooLarge {
            what: "radicand",
            value: d.to_string(),
            limit: MAX_RADICAND.to_string(),
        });
    }
    Ok(())
}

/// `n = s² m` with `m` square-free (sign kept in `m`); `n ≠ 0`.
fn square_part(n: i64) -> (i64, i64) {
    let negative = n < 0;
    let mut m = n.unsigned_abs();
    let mut s: u64 = 1;
    let mut p: u64 = 2;
    while p * p <= m {
        while m % (p * p) == 0 {
            m /= p * p;
            s *= p;
        }
        p += 1;
    }
    let m = m as i64;
    (s as i64, if negative { -m } else { m })
}

impl QuadraticIrrational {
    /// `a + b√d`; `d` must be square-free, `≠ 0, 1`, and at most [`MAX_RADICAND`] in size.
    ///
    /// ```
    /// use casteljau::{QuadraticIrrational, BigRational};
    /// let q = |n: i64| BigRational::from_integer(n.into());
    /// assert_eq!(QuadraticIrrational::new(q(3), q(-2), 2).unwrap().to_string(), "3 - 2*sqrt(2)");
    /// assert!(QuadraticIrrational::new(q(1), q(1), 8).is_err()); // 8 = 2²·2 is not square-free
    /// assert!(QuadraticIrrational::new(q(1), q(1), 1).is_err());
    /// ```
    pub fn new(a: BigRational, b: BigRational, d: i64) -> Result<Self> {
        check_radicand_size(d)?;
        if d == 0 || d == 1 {
            return Err(Error::Domain(format!(
                "sqrt({d}) is rational: a quadratic irrational needs a square-free d other than 0 and 1"
            )));
        }
        if !is_square_free(d) {
            let (s, m) = square_part(d);
            return Err(Error::Domain(format!(
                "d = {d} is not square-free ({d} = {}·{m}); write b√{d} as {s}b√{m}, or use QuadraticIrrational::sqrt",
                s * s
            )));
        }
        Ok(Self::normalized(a, b, d))
    }

    /// `√n` for any integer `n`, square factors pulled out: `sqrt(8) = 2√2`, `sqrt(9) = 3`,
    /// `sqrt(0) = 0`, `sqrt(-4) = 2√-1`.
    ///
    /// ```
    /// use casteljau::{QuadraticIrrational, Ring, Scalar};
    /// let s8 = QuadraticIrrational::sqrt(8).unwrap();
    /// assert_eq!(s8.to_string(), "2*sqrt(2)");
    /// assert_eq!(&s8 * &s8, QuadraticIrrational::from_i64(8));
    /// assert_eq!(QuadraticIrrational::sqrt(9).unwrap(), QuadraticIrrational::from_i64(3));
    /// ```
    pub fn sqrt(n: i64) -> Result<Self> {
        check_radicand_size(n)?;
        if n == 0 {
            return Ok(Self::rational(q0()));
        }
        let (s, m) = square_part(n);
        let s = BigRational::from_integer(s.into());
        if m == 1 {
            return Ok(Self::rational(s));
        }
        Ok(Self::normalized(q0(), s, m))
    }

    /// `√r` for a rational `r`, exactly: `√(p/q) = √(pq)/q` (a negative `r` gives an
    /// imaginary value, like [`Self::sqrt`]). An error only when `|pq|` exceeds
    /// [`MAX_RADICAND`].
    ///
    /// ```
    /// use casteljau::{QuadraticIrrational, BigRational, Scalar};
    /// let r = QuadraticIrrational::sqrt_rational(&BigRational::new(9.into(), 2.into())).unwrap();
    /// assert_eq!(r.to_string(), "3/2*sqrt(2)");
    /// assert_eq!(&r * &r, QuadraticIrrational::from_ratio(9, 2).unwrap());
    /// ```
    pub fn sqrt_rational(r: &BigRational) -> Result<Self> {
        let pq: BigInt = r.numer() * r.denom();
        let n = pq
            .to_i64()
            .filter(|n| n.unsigned_abs() <= MAX_RADICAND as u64)
            .ok_or_else(|| Error::TooLarge {
                what: "radicand",
                value: pq.to_string(),
                limit: MAX_RADICAND.to_string(),
            })?;
        let root = Self::sqrt(n)?;
        let inv_q = BigRational::new(1.into(), r.denom().clone());
        Ok(root.scale(&inv_q))
    }

    /// The rational `r` (`b = 0`), compatible with every field.
    pub fn rational(r: BigRational) -> Self {
        QuadraticIrrational {
            a: r,
            b: q0(),
            field: Field::Rational,
        }
    }

    fn normalized(a: BigRational, b: BigRational, d: i64) -> Self {
        let field = if Zero::is_zero(&b) {
            Field::Rational
        } else {
            Field::Sqrt(d)
        };
        QuadraticIrrational { a, b, field }
    }

    fn poisoned(field: Field) -> Self {
        QuadraticIrrational {
            a: q0(),
            b: q0(),
            field,
        }
    }

    /// `(a, b, d)` with the value `a + b√d`; `d` is `None` for a rational (`b = 0`).
    /// An error for a poisoned value.
    pub fn parts(&self) -> Result<(&BigRational, &BigRational, Option<i64>)> {
        match self.field {
            Field::Rational => Ok((&self.a, &self.b, None)),
            Field::Sqrt(d) => Ok((&self.a, &self.b, Some(d))),
            Field::Mixed(d, e) => Err(Error::MixedField(d, e)),
        }
    }

    /// The rational part `a` (zero for a poisoned value; see [`Self::parts`]).
    pub fn rational_part(&self) -> &BigRational {
        &self.a
    }

    /// The coefficient `b` of `√d` (zero for a poisoned value; see [`Self::parts`]).
    pub fn irrational_part(&self) -> &BigRational {
        &self.b
    }

    /// The radicand `d` of the field, `None` for a rational or a poisoned value.
    pub fn radicand(&self) -> Option<i64> {
        match self.field {
            Field::Sqrt(d) => Some(d),
            _ => None,
        }
    }

    /// Whether `b = 0` (and the value is not poisoned).
    pub fn is_rational(&self) -> bool {
        self.field == Field::Rational
    }

    /// The rational value, when `b = 0`.
    pub fn to_rational(&self) -> Option<BigRational> {
        self.is_rational().then(|| self.a.clone())
    }

    /// Whether this value is a genuine number (not the poison of mixing two fields).
    pub fn is_valid(&self) -> bool {
        !matches!(self.field, Field::Mixed(..))
    }

    /// The conjugate `a - b√d`.
    pub fn conjugate(&self) -> Self {
        QuadraticIrrational {
            a: self.a.clone(),
            b: -&self.b,
            field: self.field,
        }
    }

    /// The field norm `(a + b√d)(a - b√d) = a² - b²d`, a rational; zero exactly for zero.
    /// Zero for a poisoned value (check [`Self::is_valid`]).
    pub fn norm(&self) -> BigRational {
        let d = match self.field {
            Field::Sqrt(d) => BigRational::from_integer(d.into()),
            _ => q0(),
        };
        &self.a * &self.a - &self.b * &self.b * d
    }

    /// The sign (-1, 0, 1) of a real value, exactly; `None` for a non-real or poisoned one.
    pub fn signum_exact(&self) -> Option<i32> {
        match self.field {
            Field::Rational => Some(sign(&self.a)),
            Field::Mixed(..) => None,
            Field::Sqrt(d) if d < 0 => None,
            Field::Sqrt(d) => {
                let (sa, sb) = (sign(&self.a), sign(&self.b));
                if sa == 0 || sa == sb {
                    return Some(sb);
                }
                // Opposite signs: the larger of a² and b²d wins (they differ, d is no square).
                let a2 = &self.a * &self.a;
                let b2d = &self.b * &self.b * BigRational::from_integer(d.into());
                Some(if a2 > b2d { sa } else { sb })
            }
        }
    }

    /// Parses `3 - 2*sqrt(2)` and the like: a sum of signed terms, each a
    /// rational (`3`, `-1/3`, `0.25`) or `[c*]sqrt(n)` / `[c*]√n` with `c` rational and `n`
    /// an integer. Different radicands in one expression are an error.
    ///
    /// ```
    /// use casteljau::QuadraticIrrational;
    /// let x = QuadraticIrrational::parse("-1/2 + 3/4*sqrt(2)").unwrap();
    /// assert_eq!(x.to_string(), "-1/2 + 3/4*sqrt(2)");
    /// assert_eq!(QuadraticIrrational::parse("2√2").unwrap().to_string(), "2*sqrt(2)");
    /// assert!(QuadraticIrrational::parse("sqrt(2) + sqrt(3)").is_err());
    /// assert!(QuadraticIrrational::parse("sqrt(x)").is_err());
    /// ```
    pub fn parse(text: &str) -> Result<Self> {
        let s = text.trim();
        if s.is_empty() {
            return Err(Error::Parse("empty number".into()));
        }
        if s.len() > crate::scalar::MAX_NUMBER_LEN {
            return Err(Error::TooLarge {
                what: "number literal",
                value: format!("{} characters", s.len()),
                limit: format!("{} characters", crate::scalar::MAX_NUMBER_LEN),
            });
        }
        let mut acc = Self::zero();
        for term in split_terms(s) {
            let value = parse_term(term.trim(), text)?;
            acc += &value;
            acc.check()?;
        }
        Ok(acc)
    }

    fn scale(&self, r: &BigRational) -> Self {
        match self.field {
            Field::Mixed(..) => self.clone(),
            Field::Rational => Self::rational(&self.a * r),
            Field::Sqrt(d) => Self::normalized(&self.a * r, &self.b * r, d),
        }
    }

    /// The radicand of `self ∘ other`, or the poisoned field when they cannot combine.
    fn combine(&self, other: &Self) -> std::result::Result<i64, Field> {
        match (self.field, other.field) {
            (Field::Mixed(..), _) => Err(self.field),
            (_, Field::Mixed(..)) => Err(other.field),
            (Field::Sqrt(d), Field::Sqrt(e)) if d != e => Err(Field::Mixed(d, e)),
            (Field::Sqrt(d), _) | (_, Field::Sqrt(d)) => Ok(d),
            // Both rational: b = b' = 0, the radicand is never used.
            (Field::Rational, Field::Rational) => Ok(0),
        }
    }
}

/// Splits at top-level `+`/`-` that start a term (not an exponent sign, not inside parentheses).
fn split_terms(s: &str) -> Vec<&str> {
    let mut terms = Vec::new();
    let mut depth = 0i32;
    let mut start = 0;
    let mut prev: Option<char> = None;
    for (i, ch) in s.char_indices() {
        match ch {
            '(' => depth += 1,
            ')' => depth -= 1,
            '+' | '-' if depth == 0 && i > start => {
                let after_operand = matches!(prev, Some(p) if p.is_ascii_alphanumeric() || p == ')' || p == '.')
                    && !matches!(prev, Some('e' | 'E'));
                if after_operand {
                    terms.push(&s[start..i]);
                    start = i;
                }
            }
            _ => {}
        }
        if !ch.is_whitespace() {
            prev = Some(ch);
        }
    }
    terms.push(&s[start..]);
    terms
}

fn parse_term(term: &str, whole: &str) -> Result<QuadraticIrrational> {
    let bad = || {
        Error::Parse(format!(
            "'{whole}' is not a quadratic irrational (write terms like 3, -1/2, 2*sqrt(2), or 2√2)"
        ))
    };
    let (negative, body) = match term.strip_prefix('-') {
        Some(rest) => (true, rest.trim()),
        None => (false, term.strip_prefix('+').unwrap_or(term).trim()),
    };
    let root_at = body.find("sqrt").or_else(|| body.find('√'));
    let value = match root_at {
        None => QuadraticIrrational::rational(parse_exact(body)?),
        Some(i) => {
            let coef_text = body[..i].trim();
            let coef = if coef_text.is_empty() {
                BigRational::from_integer(1.into())
            } else {
                let c = coef_text.strip_suffix('*').unwrap_or(coef_text).trim();
                if c.is_empty() || c.starts_with(['+', '-']) {
                    return Err(bad());
                }
                parse_exact(c)?
            };
            let rest = &body[i..];
            let radicand_text = if let Some(r) = rest.strip_prefix("sqrt") {
                r.trim()
                    .strip_prefix('(')
                    .and_then(|r| r.strip_suffix(')'))
                    .ok_or_else(bad)?
            } else {
                rest.strip_prefix('√').ok_or_else(bad)?
            };
            let n: i64 = radicand_text.trim().parse().map_err(|_| bad())?;
            QuadraticIrrational::sqrt(n)?.scale(&coef)
        }
    };
    Ok(if negative { -value } else { value })
}

impl FromStr for QuadraticIrrational {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        Self::parse(s)
    }
}

impl PartialEq for QuadraticIrrational {
    fn eq(&self, other: &Self) -> bool {
        match (self.field, other.field) {
            (Field::Mixed(..), _) | (_, Field::Mixed(..)) => false,
            // b ≠ 0 in both: √d and √e are linearly independent over Q for d ≠ e.
            (Field::Sqrt(d), Field::Sqrt(e)) => d == e && self.a == other.a && self.b == other.b,
            (Field::Rational, Field::Rational) => self.a == other.a,
            _ => false,
        }
    }
}

impl PartialOrd for QuadraticIrrational {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        if self == other {
            return Some(Ordering::Equal);
        }
        // Values of different fields stay unordered: their difference is poisoned.
        match self.sub_ref(other).signum_exact()? {
            -1 => Some(Ordering::Less),
            1 => Some(Ordering::Greater),
            _ => Some(Ordering::Equal),
        }
    }
}

impl fmt::Display for QuadraticIrrational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.field {
            Field::Rational => write!(f, "{}", self.a),
            Field::Mixed(d, e) => write!(f, "<invalid: mixes sqrt({d}) and sqrt({e})>"),
            Field::Sqrt(d) => {
                let negative = self.b.is_negative();
                let magnitude = Signed::abs(&self.b);
                let root = if magnitude == BigRational::from_integer(1.into()) {
                    format!("sqrt({d})")
                } else {
                    format!("{magnitude}*sqrt({d})")
                };
                if Zero::is_zero(&self.a) {
                    write!(f, "{}{root}", if negative { "-" } else { "" })
                } else {
                    write!(f, "{} {} {root}", self.a, if negative { '-' } else { '+' })
                }
            }
        }
    }
}

impl Ring for QuadraticIrrational {
    fn zero() -> Self {
        Self::rational(q0())
    }
    fn one() -> Self {
        Self::rational(BigRational::from_integer(1.into()))
    }
    fn from_i64(n: i64) -> Self {
        Self::rational(BigRational::from_integer(n.into()))
    }

    fn add_ref(&self, other: &Self) -> Self {
        match self.combine(other) {
            Ok(d) => Self::normalized(&self.a + &other.a, &self.b + &other.b, d),
            Err(field) => Self::poisoned(field),
        }
    }

    fn sub_ref(&self, other: &Self) -> Self {
        match self.combine(other) {
            Ok(d) => Self::normalized(&self.a - &other.a, &self.b - &other.b, d),
            Err(field) => Self::poisoned(field),
        }
    }

    fn mul_ref(&self, other: &Self) -> Self {
        match self.combine(other) {
            Ok(d) => {
                let mut a = &self.a * &other.a;
                if !Zero::is_zero(&self.b) && !Zero::is_zero(&other.b) {
                    a += &self.b * &other.b * BigRational::from_integer(d.into());
                }
                let b = &self.a * &other.b + &self.b * &other.a;
                Self::normalized(a, b, d)
            }
            Err(field) => Self::poisoned(field),
        }
    }

    fn neg_ref(&self) -> Self {
        QuadraticIrrational {
            a: -&self.a,
            b: -&self.b,
            field: self.field,
        }
    }
}

forward_ring_ops!(QuadraticIrrational);

impl Scalar for QuadraticIrrational {
    const EXACT: bool = true;
    const NAME: &'static str = "quadratic";

    fn is_zero(&self) -> bool {
        self.field == Field::Rational && Zero::is_zero(&self.a)
    }
    fn from_bigint(n: &BigInt) -> Result<Self> {
        Ok(Self::rational(BigRational::from_integer(n.clone())))
    }
    fn from_rational(r: &BigRational) -> Result<Self> {
        Ok(Self::rational(r.clone()))
    }
    fn from_f64(x: f64) -> Result<Self> {
        Ok(Self::rational(<BigRational as Scalar>::from_f64(x)?))
    }
    fn to_f64(&self) -> f64 {
        let d = match self.field {
            Field::Rational => return Scalar::to_f64(&self.a),
            Field::Mixed(..) => return f64::NAN,
            Field::Sqrt(d) if d < 0 => return f64::NAN,
            Field::Sqrt(d) => d,
        };
        let root = (d as f64).sqrt();
        let (a, b) = (Scalar::to_f64(&self.a), Scalar::to_f64(&self.b));
        if a.signum() == b.signum() {
            return a + b * root;
        }
        // Opposite signs cancel: a + b√d = (a² - b²d) / (a - b√d), whose terms add up.
        let norm = Scalar::to_f64(&self.norm());
        norm / (a - b * root)
    }
    fn checked_div(&self, rhs: &Self) -> Result<Self> {
        self.check()?;
        rhs.check()?;
        if Scalar::is_zero(rhs) {
            return Err(Error::DivisionByZero(format!("{self} / 0")));
        }
        // 1/(c + e√d) = (c - e√d) / (c² - e²d); the norm vanishes only at zero (d no square).
        let inv_norm = BigRational::from_integer(1.into()) / rhs.norm();
        Ok(self.mul_ref(&rhs.conjugate()).scale(&inv_norm))
    }
    fn abs(&self) -> Self {
        if self.signum_exact() == Some(-1) {
            self.neg_ref()
        } else {
            self.clone()
        }
    }
    fn check(&self) -> Result<()> {
        match self.field {
            Field::Mixed(d, e) => Err(Error::MixedField(d, e)),
            _ => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> BigRational {
        BigRational::new(p.into(), d.into())
    }

    fn qi(a: i64, b: i64, d: i64) -> QuadraticIrrational {
        QuadraticIrrational::new(q(a, 1), q(b, 1), d).unwrap()
    }

    #[test]
    fn arithmetic_in_one_field() {
        let x = qi(3, -2, 2);
        let y = qi(3, 2, 2);
        assert_eq!(&x * &y, QuadraticIrrational::from_i64(1));
        assert!((&x * &y).is_rational());
        assert_eq!(x.checked_div(&x).unwrap(), QuadraticIrrational::one());
        assert_eq!(QuadraticIrrational::one().checked_div(&x).unwrap(), y);
        assert!(x.checked_div(&QuadraticIrrational::zero()).is_err());
        assert_eq!(&x + &y, QuadraticIrrational::from_i64(6));
    }

    #[test]
    fn ordering_is_exact_near_cancellation() {
        // 99/70 is a convergent of √2: 99 - 70√2 ≈ 0.00505 > 0, 140 - 99√2 < 0
        assert_eq!(qi(99, -70, 2).signum_exact(), Some(1));
        assert_eq!(qi(140, -99, 2).signum_exact(), Some(-1));
        assert!(qi(99, -70, 2).to_f64() > 0.0);
        assert!((qi(99, -70, 2).to_f64() - (99.0 - 70.0 * 2f64.sqrt())).abs() < 1e-12);
        assert!(QuadraticIrrational::sqrt(2).unwrap() < QuadraticIrrational::from_ratio(3, 2).unwrap());
        assert!(QuadraticIrrational::sqrt(2).unwrap() > QuadraticIrrational::from_ratio(7, 5).unwrap());
    }

    #[test]
    fn mixing_fields_poisons() {
        let m = QuadraticIrrational::sqrt(2).unwrap() * QuadraticIrrational::sqrt(3).unwrap();
        assert!(!m.is_valid());
        assert_ne!(m, m.clone());
        assert_eq!(m.partial_cmp(&m), None);
        assert_eq!(m.check(), Err(Error::MixedField(2, 3)));
        assert!(QuadraticIrrational::one().checked_div(&m).is_err());
        assert!(m.to_f64().is_nan());
        let still = &(&m * &QuadraticIrrational::zero()) + &QuadraticIrrational::one();
        assert!(!still.is_valid(), "poison must survive multiplication by zero");
        // A rational-valued result leaves its field: √2·√2 = 2 combines with √3.
        let two = QuadraticIrrational::sqrt(2).unwrap() * QuadraticIrrational::sqrt(2).unwrap();
        assert!((two + QuadraticIrrational::sqrt(3).unwrap()).is_valid());
        assert_ne!(
            QuadraticIrrational::sqrt(2).unwrap(),
            QuadraticIrrational::sqrt(3).unwrap()
        );
        assert_eq!(
            QuadraticIrrational::sqrt(2)
                .unwrap()
                .partial_cmp(&QuadraticIrrational::sqrt(3).unwrap()),
            None
        );
    }

    #[test]
    fn constructors_validate() {
        assert!(QuadraticIrrational::new(q(0, 1), q(1, 1), 0).is_err());
        assert!(QuadraticIrrational::new(q(0, 1), q(1, 1), 12).is_err());
        assert!(QuadraticIrrational::new(q(0, 1), q(1, 1), i64::MIN).is_err());
        assert!(QuadraticIrrational::sqrt(i64::MAX).is_err());
        assert_eq!(QuadraticIrrational::sqrt(-4).unwrap().to_string(), "2*sqrt(-1)");
        let i = QuadraticIrrational::sqrt(-1).unwrap();
        assert_eq!(&i * &i, QuadraticIrrational::from_i64(-1));
        assert_eq!(i.partial_cmp(&QuadraticIrrational::zero()), None);
        assert_eq!(QuadraticIrrational::sqrt(12).unwrap(), qi(0, 2, 3));
    }

    #[test]
    fn display_round_trips() {
        for x in [
            qi(3, -2, 2),
            qi(0, -1, 5),
            qi(0, 1, 7),
            QuadraticIrrational::new(q(-1, 3), q(5, 7), 3).unwrap(),
            QuadraticIrrational::from_ratio(-4, 9).unwrap(),
            QuadraticIrrational::zero(),
            qi(2, 1, -1),
        ] {
            let s = x.to_string();
            assert_eq!(QuadraticIrrational::parse(&s).unwrap(), x, "{s}");
        }
        assert_eq!(
            QuadraticIrrational::parse("1e-3 + 2*sqrt(2) - sqrt(2)")
                .unwrap()
                .to_string(),
            "1/1000 + sqrt(2)"
        );
        for bad in ["", "sqrt", "sqrt()", "2*", "*sqrt(2)", "sqrt(2)+sqrt(3)", "1/0", "abc"] {
            assert!(QuadraticIrrational::parse(bad).is_err(), "{bad}");
        }
    }
}
