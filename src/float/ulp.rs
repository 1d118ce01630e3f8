//! Units in the last place: the spacing of `f64`s, correct rounding of a rational, and the
//! error of a float approximation measured against an exact value.
//!
//! An `f64` is `m·2^e`, so most exact values met here (results of float inputs through
//! additions and multiplications) have a power-of-two denominator: those are rounded and
//! compared by shifting integers, with no gcd. Other rationals take one integer division.

use crate::error::{Error, Result};
use num_bigint::{BigInt, BigUint, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};

/// How far a float approximation is from the exact value, for one coordinate.
#[derive(Clone, Debug, PartialEq)]
pub struct UlpError {
    /// The correctly rounded value (nearest `f64`, ties to even).
    pub nearest: f64,
    /// `f64` steps between the approximation and `nearest` (0 iff correctly rounded).
    pub ulps: u64,
    /// `|approx − exact| / ulp(exact)`, exactly computed, rounded to nearest `f64`; `+∞`
    /// when that quotient is beyond the largest `f64`.
    pub error_ulps: f64,
}

/// A finite `f64` as `(negative, m, e)` with value `±m·2^e` (`m` is 0 for zeros).
#[inline]
pub fn decompose(x: f64) -> (bool, u64, i64) {
    let bits = x.to_bits();
    let negative = bits >> 63 == 1;
    let exp = ((bits >> 52) & 0x7ff) as i64;
    let frac = bits & ((1u64 << 52) - 1);
    if exp == 0 {
        (negative, frac, -1074)
    } else {
        (negative, frac | (1u64 << 52), exp - 1075)
    }
}

/// `±m·2^e` rounded to the nearest `f64` (ties to even); `sticky` says that the exact value
/// is slightly larger in magnitude than `m·2^e` (by less than `2^e`), so that a tie is not
/// one. Beyond the range it is `±∞`.
pub fn round_scaled(negative: bool, m: &BigUint, e: i64, sticky: bool) -> f64 {
    let signed = |x: f64| if negative { -x } else { x };
    if m.is_zero() {
        return signed(0.0);
    }
    let top = m.bits() as i64 - 1 + e; // floor(log2 |value|) (sticky cannot change it)
    if top > 1023 {
        return signed(f64::INFINITY);
    }
    let q = (top - 52).max(-1074); // exponent of the ulp at this magnitude
    let mut mant: u64;
    let mut q = q;
    if q <= e {
        // exact: m·2^(e−q) has at most 53 bits
        mant = (m << ((e - q) as u64)).to_u64().expect("at most 53 bits");
    } else {
        let shift = (q - e) as u64;
        let kept = m >> shift;
        mant = kept.to_u64().expect("at most 53 bits");
        let half = m.bit(shift - 1);
        let below = sticky || m.trailing_zeros().is_some_and(|z| z < shift - 1);
        if half && (below || mant & 1 == 1) {
            mant += 1;
            if mant == 1 << 53 {
                mant >>= 1;
                q += 1;
            }
        }
    }
    signed(compose(mant, q))
}

/// `mant·2^q` for `mant < 2^53` with `q` the ulp exponent of the result (or `mant = 2^52…`):
/// built from its bits, `+∞` past the largest float.
fn compose(mant: u64, q: i64) -> f64 {
    if mant == 0 {
        return 0.0;
    }
    if mant >> 52 == 0 {
        // subnormal (q = −1074) or a normal number written with a smaller mantissa
        let shift = 52 - (63 - mant.leading_zeros() as i64);
        let (m2, q2) = (mant << shift, q - shift);
        if q2 < -1074 {
            debug_assert_eq!(q, -1074);
            return f64::from_bits(mant);
        }
        return compose(m2, q2);
    }
    let biased = q + 52 + 1023;
    if biased >= 0x7ff {
        return f64::INFINITY;
    }
    f64::from_bits(((biased as u64) << 52) | (mant & ((1u64 << 52) - 1)))
}

/// `Some(k)` when `d = 2^k` (a dyadic denominator).
fn power_of_two(d: &BigInt) -> Option<u64> {
    let z = d.trailing_zeros()?;
    (z + 1 == d.bits()).then_some(z)
}

/// `floor(log2 a)` for `a = n/d > 0`, exactly.
fn floor_log2(n: &BigUint, d: &BigUint) -> i64 {
    let e0 = n.bits() as i64 - d.bits() as i64;
    // 2^(bits−1) ≤ n < 2^bits, so a lies in (2^(e0−1), 2^(e0+1)): floor is e0 or e0 − 1.
    let at_least = if e0 >= 0 {
        *n >= d << (e0 as u64)
    } else {
        n << e0.unsigned_abs() >= *d
    };
    if at_least {
        e0
    } else {
        e0 - 1
    }
}

/// The exponent of `ulp(x)`: `max(e, −1022) − 52` where `2^e ≤ |x| < 2^(e+1)`, and
/// `−1074` for `x = 0`.
pub fn ulp_exponent(x: &BigRational) -> i64 {
    if x.is_zero() {
        return -1074;
    }
    let (n, d) = (x.numer().magnitude(), x.denom().magnitude());
    let log = match power_of_two(x.denom()) {
        Some(k) => n.bits() as i64 - 1 - k as i64,
        None => floor_log2(n, d),
    };
    log.max(-1022) - 52
}

/// The exponent of `ulp(x)` for a float `x` (as [`ulp_exponent`]).
#[inline]
pub fn ulp_exponent_f64(x: f64) -> i64 {
    let (_, m, e) = decompose(x);
    if m == 0 {
        return -1074;
    }
    (63 - m.leading_zeros() as i64 + e).max(-1022) - 52
}

/// `2^q` exactly.
pub fn pow2_exact(q: i64) -> BigRational {
    let one = BigInt::from(1);
    if q >= 0 {
        BigRational::from_integer(one << (q as u64))
    } else {
        BigRational::new_raw(one.clone(), one << q.unsigned_abs())
    }
}

/// `ulp(x)`, exactly: `2^(e−52)` for `2^e ≤ |x| < 2^(e+1)` and `e ≥ −1022`, and `2^−1074`
/// below (the subnormal range, exact 0 included).
///
/// ```
/// use casteljau::{float::ulp, BigRational, Ring, Scalar};
/// assert_eq!(ulp(&BigRational::from_i64(1)), BigRational::from_f64(f64::EPSILON).unwrap());
/// assert_eq!(ulp(&BigRational::from_i64(0)), BigRational::from_f64(f64::from_bits(1)).unwrap());
/// ```
pub fn ulp(x: &BigRational) -> BigRational {
    pow2_exact(ulp_exponent(x))
}

/// The `f64` nearest to `x`, ties to even (infinite when `|x|` rounds past `f64::MAX`).
///
/// ```
/// use casteljau::{float::nearest_f64, parse_exact};
/// assert_eq!(nearest_f64(&parse_exact("0.1").unwrap()), 0.1);
/// assert_eq!(nearest_f64(&parse_exact("1/3").unwrap()), 1.0 / 3.0);
/// ```
pub fn nearest_f64(x: &BigRational) -> f64 {
    if x.is_zero() {
        return 0.0;
    }
    let negative = x.is_negative();
    let n = x.numer().magnitude();
    if let Some(k) = power_of_two(x.denom()) {
        return round_scaled(negative, n, -(k as i64), false);
    }
    let d = x.denom().magnitude();
    let top = floor_log2(n, d);
    if top > 1023 {
        return if negative { f64::NEG_INFINITY } else { f64::INFINITY };
    }
    // m = |x| / 2^s with s two below the ulp exponent: an integer quotient of 55 bits at
    // most plus a sticky remainder, rounded by `round_scaled`.
    let s = (top - 52).max(-1074) - 2;
    let (num, den) = if s >= 0 {
        (n.clone(), d << (s as u64))
    } else {
        (n << s.unsigned_abs(), d.clone())
    };
    let (m, rem) = num.div_rem(&den);
    round_scaled(negative, &m, s, !rem.is_zero())
}

/// How many `f64` steps lie between `a` and `b` (`+0` and `−0` are the same point).
pub fn ulp_distance(a: f64, b: f64) -> u64 {
    fn key(x: f64) -> i128 {
        let bits = x.to_bits();
        let magnitude = (bits & !(1u64 << 63)) as i128;
        if bits >> 63 == 1 {
            -magnitude
        } else {
            magnitude
        }
    }
    (key(a) - key(b)).unsigned_abs() as u64
}

/// The error of the approximation `approx` of the exact `exact`; an error when `approx` is
/// not finite or `exact` rounds beyond the largest `f64` (no finite float to count from).
///
/// ```
/// use casteljau::{float::ulp_error, parse_exact};
/// let e = ulp_error(0.1 + 0.2, &parse_exact("0.3").unwrap()).unwrap();
/// assert_eq!((e.nearest, e.ulps), (0.3, 1));
/// assert!(e.error_ulps > 0.5 && e.error_ulps < 1.5);
/// ```
pub fn ulp_error(approx: f64, exact: &BigRational) -> Result<UlpError> {
    if !approx.is_finite() {
        return Err(Error::NotFinite(approx.to_string()));
    }
    let nearest = nearest_f64(exact);
    if !nearest.is_finite() {
        // Round-to-nearest overflows to ±inf: there is no finite f64 to count steps from.
        return Err(Error::Domain(
            "an exact coordinate is beyond the largest f64 (about 1.8e308): it has no finite nearest f64, so no error in ulps"
                .into(),
        ));
    }
    let q = ulp_exponent(exact);
    let (neg, m, e) = decompose(approx);
    let a = BigInt::from_biguint(if neg { Sign::Minus } else { Sign::Plus }, BigUint::from(m));
    let error_ulps = match power_of_two(exact.denom()) {
        Some(k) => {
            // |a·2^e − x·2^−k| / 2^q with everything over 2^min(e, −k)
            let low = e.min(-(k as i64));
            let diff = (a << ((e - low) as u64)) - (exact.numer() << ((-(k as i64) - low) as u64));
            round_scaled(false, diff.magnitude(), low - q, false)
        }
        None => {
            // |a·2^e·d − n| / (d·2^q)
            let d = exact.denom();
            let scaled = if e >= 0 { (a * d) << (e as u64) } else { a * d };
            let n = if e >= 0 {
                exact.numer().clone()
            } else {
                exact.numer() << e.unsigned_abs()
            };
            let diff = BigRational::new((scaled - n).abs(), d.clone()) * pow2_exact(e.min(0) - q);
            nearest_f64(&diff)
        }
    };
    Ok(UlpError {
        nearest,
        ulps: ulp_distance(approx, nearest),
        error_ulps,
    })
}

/// The exact value of a finite float, in lowest terms without a gcd (strip the mantissa's
/// trailing zeros); `None` for NaN and infinities.
///
/// ```
/// use casteljau::{float::f64_to_rational, BigRational};
/// assert_eq!(f64_to_rational(0.375), Some(BigRational::new(3.into(), 8.into())));
/// assert_eq!(f64_to_rational(f64::NAN), None);
/// ```
pub fn f64_to_rational(x: f64) -> Option<BigRational> {
    if !x.is_finite() {
        return None;
    }
    let (negative, m, e) = decompose(x);
    if m == 0 {
        return Some(BigRational::zero());
    }
    let z = (m.trailing_zeros() as i64).min(-e.min(0));
    let (m, e) = (m >> z, e + z);
    let n = BigInt::from(m);
    let n = if negative { -n } else { n };
    Some(if e >= 0 {
        BigRational::from_integer(n << e as u64)
    } else {
        let k = e.unsigned_abs();
        // a denominator below 2^64 is made from one word, without a shift of a BigInt
        let d = if k < 64 {
            BigInt::from(1u64 << k)
        } else {
            BigInt::from(1) << k
        };
        BigRational::new_raw(n, d)
    })
}

/// `x` when it is exactly an `f64` (every finite float is a dyadic rational), else `None`.
pub fn exact_f64(x: &BigRational) -> Option<f64> {
    let k = power_of_two(x.denom())?;
    if let (Some(n), true) = (x.numer().magnitude().to_u64(), k <= 1022) {
        if n < 1 << 53 {
            // n and 2^−k are floats and the exact product n·2^−k is one too (at most 53
            // bits from 2^−k up, and 2^−k ≥ 2^−1022), so the multiplication is exact
            let f = n as f64 * f64::from_bits((1023 - k) << 52);
            return Some(if x.numer().sign() == Sign::Minus { -f } else { f });
        }
    }
    let f = nearest_f64(x);
    if !f.is_finite() {
        return None;
    }
    let (_, m, e) = decompose(f);
    // f = m·2^e equals n/2^k iff n·2^e... compare n with m·2^(e+k) by shifting
    let n = x.numer().magnitude();
    let shift = e + k as i64;
    let same = if shift >= 0 {
        *n == BigUint::from(m) << shift as u64
    } else {
        n << shift.unsigned_abs() == BigUint::from(m)
    };
    same.then_some(f)
}

/// `x · 2^k` rounded up in magnitude (exact unless it leaves the normal range).
pub fn scale_pow2_up(x: f64, k: i64) -> f64 {
    if x == 0.0 || x.is_nan() {
        return x;
    }
    let mut y = x;
    let mut k = k;
    while k != 0 {
        let step = k.clamp(-600, 600);
        y *= f64::from_bits(((step + 1023) as u64) << 52);
        k -= step;
    }
    if y.is_finite() && y != x * 0.0 && y.abs() >= f64::MIN_POSITIVE {
        y
    } else if y == 0.0 && x != 0.0 {
        f64::from_bits(1).copysign(x)
    } else {
        // subnormal or overflowed: one float outward covers the lost bits
        let up = f64::from_bits(y.abs().to_bits() + u64::from(y.is_finite()));
        up.copysign(y)
    }
}

/// Whether `|approx − exact| ≤ bound`, decided exactly (`bound` a nonnegative float or `+∞`);
/// never for an `approx` that is `±∞` or NaN.
pub fn error_at_most(approx: f64, exact: &BigRational, bound: f64) -> bool {
    if !approx.is_finite() || bound.is_nan() || bound < 0.0 {
        return false;
    }
    if bound == f64::INFINITY {
        return true;
    }
    let (neg, m, e) = decompose(approx);
    let (_, bm, be) = decompose(bound);
    let a = BigInt::from_biguint(if neg { Sign::Minus } else { Sign::Plus }, BigUint::from(m));
    match power_of_two(exact.denom()) {
        Some(k) => {
            let low = e.min(-(k as i64)).min(be);
            let diff = (a << ((e - low) as u64)) - (exact.numer() << ((-(k as i64) - low) as u64));
            *diff.magnitude() <= BigUint::from(bm) << ((be - low) as u64)
        }
        None => {
            let err = Signed::abs(&(BigRational::from_float(approx).expect("finite") - exact));
            err <= BigRational::from_float(bound).expect("finite")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::{parse_exact, Scalar};
    use proptest::prelude::*;

    fn q(s: &str) -> BigRational {
        parse_exact(s).unwrap()
    }

    #[test]
    fn nearest_is_correctly_rounded() {
        for s in [
            "0.1",
            "1e-320",
            "4.9406564584124654e-324",
            "2.4703282292062327e-324",
            "2.4703282292062328e-324",
            "1.7976931348623157e308",
            "1.7976931348623158e308",
            "1.7976931348623159e308",
            "9007199254740993",
            "9007199254740995",
            "2.2250738585072011e-308",
            "2.2250738585072014e-308",
            "2.2250738585072009e-308",
        ] {
            assert_eq!(nearest_f64(&q(s)).to_bits(), s.parse::<f64>().unwrap().to_bits(), "{s}");
            let neg = format!("-{s}");
            assert_eq!(
                nearest_f64(&q(&neg)).to_bits(),
                neg.parse::<f64>().unwrap().to_bits(),
                "{neg}"
            );
        }
        assert_eq!(nearest_f64(&q("1/3")), 1.0 / 3.0);
        assert_eq!(nearest_f64(&q("-2/3")), -2.0 / 3.0);
        assert_eq!(nearest_f64(&q("-414/43")), -414.0 / 43.0);
        assert_eq!(nearest_f64(&q("2e308")), f64::INFINITY);
        assert_eq!(nearest_f64(&q("0")), 0.0);
        // dyadic ties: 2^53 + 1 is halfway, rounds to even 2^53; 2^53 + 3 rounds up
        assert_eq!(nearest_f64(&q("9007199254740993")), 9007199254740992.0);
        assert_eq!(nearest_f64(&q("9007199254740995")), 9007199254740996.0);
    }

    #[test]
    fn exactness_scaling_and_error_comparison() {
        assert_eq!(exact_f64(&q("0.5")), Some(0.5));
        assert_eq!(exact_f64(&q("0.1")), None);
        assert_eq!(exact_f64(&q("1/3")), None);
        assert_eq!(exact_f64(&q("9007199254740993")), None);
        assert_eq!(exact_f64(&BigRational::from_f64(0.1).unwrap()), Some(0.1));
        // both sides of the short-numerator path: tiny, subnormal, huge, negative, zero
        for x in [
            -0.1,
            0.0,
            f64::MIN_POSITIVE,
            f64::MIN_POSITIVE / 3.0,
            f64::from_bits(1),
            2f64.powi(-1022) * 1.5,
            -1e300,
            9007199254740991.0,
            9007199254740992.0,
            f64::MAX,
        ] {
            assert_eq!(exact_f64(&BigRational::from_f64(x).unwrap()), Some(x), "{x:e}");
        }
        assert_eq!(exact_f64(&q("9007199254740993/1024")), None);
        assert_eq!(scale_pow2_up(3.0, 4), 48.0);
        assert!(scale_pow2_up(1.0, -1074) >= f64::from_bits(1));
        assert_eq!(scale_pow2_up(1.0, -1080), f64::from_bits(1));
        assert_eq!(scale_pow2_up(1.0, 1030), f64::INFINITY);
        let third = q("1/3");
        let x = 1.0 / 3.0;
        let err = Signed::abs(&(BigRational::from_f64(x).unwrap() - &third));
        let e = Scalar::to_f64(&err);
        assert!(error_at_most(x, &third, e * 1.0000001) && !error_at_most(x, &third, e * 0.9999999));
        assert!(error_at_most(0.5, &q("0.5"), 0.0) && !error_at_most(0.5, &q("0.25"), 0.2));
        assert!(error_at_most(0.5, &q("0.25"), 0.25) && error_at_most(0.5, &q("0.25"), f64::INFINITY));
    }

    #[test]
    fn ulps_of_known_values() {
        let third = q("1/3");
        let e = ulp_error(1.0 / 3.0, &third).unwrap();
        assert_eq!(e.ulps, 0);
        assert!(e.error_ulps > 0.0 && e.error_ulps <= 0.5, "{e:?}");
        let off = f64::from_bits((1.0f64 / 3.0).to_bits() + 2);
        assert_eq!(ulp_error(off, &third).unwrap().ulps, 2);
        let e = ulp_error(1.0, &q("1")).unwrap();
        assert_eq!((e.ulps, e.error_ulps), (0, 0.0));
        let e = ulp_error(f64::from_bits(1.0f64.to_bits() - 1), &q("1")).unwrap();
        assert_eq!((e.ulps, e.error_ulps), (1, 0.5));
        let e = ulp_error(-0.0, &q("0")).unwrap();
        assert_eq!((e.ulps, e.error_ulps), (0, 0.0));
        let e = ulp_error(f64::from_bits(3), &q("0")).unwrap();
        assert_eq!((e.ulps, e.error_ulps), (3, 3.0));
        assert_eq!(ulp_distance(-f64::from_bits(1), f64::from_bits(1)), 2);
        // an error beyond the f64 range is +∞ ulps, not a failure
        let e = ulp_error(1e-15, &q("0")).unwrap();
        assert_eq!(e.error_ulps, f64::INFINITY);
        assert!(ulp_error(f64::NAN, &q("0")).is_err());
    }

    fn reference_error_ulps(a: f64, x: &BigRational) -> f64 {
        let a = BigRational::from_f64(a).unwrap();
        let err = Signed::abs(&(&a - x)) / ulp(x);
        Scalar::to_f64(&err)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        #[test]
        fn nearest_matches_float_parsing(m in any::<u64>(), e in -330i32..310) {
            let s = format!("{m}e{e}");
            prop_assert_eq!(nearest_f64(&q(&s)).to_bits(), s.parse::<f64>().unwrap().to_bits());
        }

        #[test]
        fn nearest_of_a_float_is_itself(bits in any::<u64>()) {
            let x = f64::from_bits(bits);
            prop_assume!(x.is_finite());
            let exact = BigRational::from_f64(x).unwrap();
            prop_assert_eq!(nearest_f64(&exact), x);
            prop_assert_eq!(&exact, &BigRational::from_float(x).unwrap());
            prop_assert_eq!(ulp_exponent(&exact), ulp_exponent_f64(x));
            let e = ulp_error(x, &exact).unwrap();
            prop_assert_eq!((e.ulps, e.error_ulps), (0, 0.0));
        }

        #[test]
        fn dyadic_and_general_paths_agree(a in -1e6f64..1e6, b in -1e6f64..1e6, num in 1i64..1000, den in 1i64..1000) {
            // a dyadic exact value (sum of floats) and a general one (a fraction)
            let x = BigRational::from_f64(a).unwrap() + BigRational::from_f64(b).unwrap();
            prop_assert_eq!(ulp_error(a + b, &x).unwrap().error_ulps, reference_error_ulps(a + b, &x));
            let y = BigRational::new(num.into(), den.into());
            let approx = num as f64 / den as f64 + a * 1e-20;
            prop_assert_eq!(ulp_error(approx, &y).unwrap().error_ulps, reference_error_ulps(approx, &y));
            prop_assert_eq!(nearest_f64(&x), Scalar::to_f64(&x));
        }
    }
}
