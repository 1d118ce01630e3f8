//! Error-free transformations: a float operation together with its exact rounding error.
//!
//! `two_sum(a, b) = (s, e)` with `s = fl(a + b)` and `s + e = a + b` exactly;
//! `two_product(a, b) = (p, e)` with `p = fl(a·b)` and `p + e = a·b` exactly (barring
//! underflow of `e` below the subnormal range, and overflow). They are the building blocks of
//! compensated algorithms, which carry the errors along and add them back at the end.
//!
//! TwoProduct is chosen at compile time ([`TWO_PRODUCT_METHOD`]): one fused multiply-add when
//! the target has the instruction (`cfg(target_feature = "fma")`, e.g. built with
//! `-C target-cpu=native` on a recent x86-64), else Dekker's product on Veltkamp's split,
//! which needs no FMA. Without the instruction `f64::mul_add` is a call to a software `fma`
//! that takes tens of nanoseconds; Dekker's product is 17 plain operations.
//!
//! Both give the same bits: the exact error, rounded once. Dekker's product is exact when
//! nothing in it overflows or underflows (Boldo, *Pitfalls of a full floating-point proof*,
//! 2006): here when `|p| ∈ [2^−967, 2^1023)` and `|a|, |b| ≤ 2^995`. Then `a·b` is a multiple
//! of `2^−1074`, so every partial product is a float and the error is too. Outside that range
//! it scales the larger operand by `2^−64` (products near overflow: the error of the scaled
//! product, scaled back, is exact), and takes `f64::mul_add` for products below `2^−967`,
//! zeros, infinities and NaN: rare, and then exactly what an FMA returns, so the certified
//! bounds, which count the error of a TwoProduct as the rounded exact error, hold on every
//! target.

/// Which TwoProduct this build uses: `"fma"` or `"dekker"`.
pub const TWO_PRODUCT_METHOD: &str = if cfg!(target_feature = "fma") { "fma" } else { "dekker" };

/// Knuth's TwoSum: `s = fl(a + b)` and the exact error `e = (a + b) − s`, for any finite
/// `a`, `b` (no ordering needed; six float operations).
///
/// ```
/// use casteljau::float::two_sum;
/// let (s, e) = two_sum(1.0, 1e-20);
/// assert_eq!((s, e), (1.0, 1e-20));
/// ```
#[inline(always)]
pub fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// Dekker's FastTwoSum, valid when `|a| ≥ |b|` (or `a = 0`): three float operations.
#[inline]
pub fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// TwoProduct: `p = fl(a·b)` and the exact error `e = a·b − p`, rounded once (exact unless
/// `e` falls below the subnormal range). By a fused multiply-add where the target has one,
/// else by Dekker's product ([`TWO_PRODUCT_METHOD`]; the two give the same bits).
///
/// ```
/// use casteljau::float::two_product;
/// let x = 1.0 + f64::EPSILON;
/// let (p, e) = two_product(x, x);
/// assert_eq!((p, e), (1.0 + 2.0 * f64::EPSILON, f64::EPSILON * f64::EPSILON));
/// ```
#[inline(always)]
pub fn two_product(a: f64, b: f64) -> (f64, f64) {
    #[cfg(target_feature = "fma")]
    {
        two_product_fma(a, b)
    }
    #[cfg(not(target_feature = "fma"))]
    {
        two_product_dekker(a, b)
    }
}

/// TwoProduct by one fused multiply-add: `e = fma(a, b, −p)`. On a target without the
/// instruction this is a call to the C library's software `fma` (slow, and still exact).
#[inline]
pub fn two_product_fma(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// TwoProduct by Dekker's product on Veltkamp's split (no FMA needed), with the same result
/// as [`two_product_fma`] for every input: out of the range where Dekker's product is exact
/// (module documentation) it scales, or falls back to `f64::mul_add`.
#[inline]
pub fn two_product_dekker(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let ap = p.abs();
    if (MIN_EXACT_PRODUCT..MAX_EXACT_PRODUCT).contains(&ap) && a.abs() <= MAX_SPLIT && b.abs() <= MAX_SPLIT {
        return (p, dekker_error(split(a), split(b), p));
    }
    (p, dekker_edge(a, b, p))
}

/// The error of `a·b ≈ p` outside Dekker's range: scaled near overflow, else by `mul_add`.
#[cold]
fn dekker_edge(a: f64, b: f64, p: f64) -> f64 {
    if p.is_finite() && p.abs() >= MIN_EXACT_PRODUCT {
        // |a·b| < 2^1024 with |a·b| ≥ 2^1023 or one operand beyond 2^995 (not both: `p`
        // would overflow). The larger operand is then at least 2^511, so scaled by 2^−64 it
        // stays far from underflow, the scaled product (below 2^960) and its partial products
        // are exact, and so is its error scaled back.
        let (big, small) = if a.abs() >= b.abs() { (a, b) } else { (b, a) };
        let scaled = big * TWO_POW_M64;
        let q = scaled * small;
        return dekker_error(split(scaled), split(small), q) * TWO_POW_64;
    }
    a.mul_add(b, -p)
}

/// `2^27 + 1`: Veltkamp's constant for splitting a 53-bit significand into two halves of
/// at most 26 bits each.
const SPLITTER: f64 = 134_217_729.0;
/// The largest operand Veltkamp's split takes without overflow (`SPLITTER·a` must be finite).
pub(crate) const MAX_SPLIT: f64 = f64::from_bits(((995 + 1023) as u64) << 52); // 2^995
/// Products at least this large have an error that is a float (`|a·b| ≥ 2^−968` forces
/// the last bits of `a` and `b` to weigh at least `2^−1074` together).
const MIN_EXACT_PRODUCT: f64 = f64::from_bits(((1023 - 967) as u64) << 52); // 2^−967
/// Products below this one leave room for the partial products (at most `|a·b|(1 + 2^−25)`).
const MAX_EXACT_PRODUCT: f64 = f64::from_bits(((1023 + 1023) as u64) << 52); // 2^1023
const TWO_POW_M64: f64 = f64::from_bits(((1023 - 64) as u64) << 52);
const TWO_POW_64: f64 = f64::from_bits(((1023 + 64) as u64) << 52);

/// Veltkamp's split: `a = hi + lo` exactly, each half with at most 26 significant bits
/// (for `|a| ≤ 2^995`; correct under gradual underflow).
#[inline(always)]
pub(crate) fn split(a: f64) -> (f64, f64) {
    let c = SPLITTER * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// Dekker's product error `a·b − p` from the splits of `a` and `b` and `p = fl(a·b)`.
#[inline(always)]
pub(crate) fn dekker_error((ah, al): (f64, f64), (bh, bl): (f64, f64), p: f64) -> f64 {
    ((ah * bh - p) + ah * bl + al * bh) + al * bl
}

/// A float `k` that multiplies many others, ready for TwoProduct: split once for Dekker's
/// product, with the range of factors `x` for which the error of `k·x` is exact by it.
///
/// Used by the loops of compensated and interval de Casteljau: [`Factor::error`] costs
/// seven operations (one FMA on targets that have it), and the loop checks with
/// [`ExactRange::contains`] that every factor was in range, redoing the work with
/// [`two_product`] otherwise.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Factor {
    #[cfg(target_feature = "fma")]
    value: f64,
    #[cfg(not(target_feature = "fma"))]
    halves: (f64, f64),
    /// `x` with `min_abs ≤ |x| ≤ max_abs` (or `x = ±0`) have an exact error, by Dekker's
    /// product too, and `|k·x| < 2^1022`.
    range: ExactRange,
}

/// The halves of a factor's partner as [`Factor::error`] wants them (nothing with an FMA).
#[cfg(not(target_feature = "fma"))]
pub(crate) type Halves = (f64, f64);
/// The halves of a factor's partner as [`Factor::error`] wants them (nothing with an FMA).
#[cfg(target_feature = "fma")]
#[derive(Clone, Copy, Debug)]
pub(crate) struct Halves;

impl Factor {
    /// `k` prepared; for a `k` out of Dekker's range (`|k| > 2^995`, non-finite) no
    /// nonzero `x` is in its exact range.
    #[inline(always)]
    pub(crate) fn new(k: f64) -> Self {
        let ak = k.abs();
        let range = if ak == 0.0 {
            // 0·x has the error +0 by either method, for every x that splits
            ExactRange {
                min_abs: 0.0,
                max_abs: MAX_SPLIT,
            }
        } else if ak <= MAX_SPLIT {
            // The error of k·x is a float when the last bits of k and x weigh at least
            // 2^−1074 together; that of a normal x ≥ 2^e weighs at least 2^(e − 52).
            // |k| < 2^(last_bit + 53), so |x| ≤ 2^(969 − last_bit) keeps |k·x| below 2^1022
            // (room for the partial products), and x must split: |x| ≤ 2^995.
            let last_bit = super::ulp::ulp_exponent_f64(k);
            ExactRange {
                min_abs: pow2((-1022 - last_bit).max(-1022)),
                max_abs: pow2((969 - last_bit).min(995)),
            }
        } else {
            ExactRange::NOTHING
        };
        Factor {
            #[cfg(target_feature = "fma")]
            value: k,
            #[cfg(not(target_feature = "fma"))]
            halves: split(k),
            range,
        }
    }

    /// The halves of `x` for [`Factor::error`]: split once, used with several factors.
    #[inline(always)]
    pub(crate) fn halves(x: f64) -> Halves {
        #[cfg(target_feature = "fma")]
        {
            let _ = x;
            Halves
        }
        #[cfg(not(target_feature = "fma"))]
        {
            split(x)
        }
    }

    /// The error `k·x − p` of `p = fl(k·x)`, given `x` and its [`Factor::halves`]: the one
    /// [`two_product`] gives when `x` is in [`ExactRange::agreeing`] with this factor.
    #[inline(always)]
    pub(crate) fn error(&self, x: f64, halves: Halves, p: f64) -> f64 {
        #[cfg(target_feature = "fma")]
        {
            let Halves = halves;
            self.value.mul_add(x, -p)
        }
        #[cfg(not(target_feature = "fma"))]
        {
            let _ = x;
            dekker_error(self.halves, halves, p)
        }
    }
}

/// A set of floats: `±0` and `min_abs ≤ |x| ≤ max_abs` (never NaN; ±∞ only when
/// `max_abs` is).
#[derive(Clone, Copy, Debug)]
pub(crate) struct ExactRange {
    min_abs: f64,
    max_abs: f64,
}

impl ExactRange {
    const NOTHING: ExactRange = ExactRange {
        min_abs: f64::INFINITY,
        max_abs: 0.0,
    };

    /// The `x` for which [`Factor::error`] agrees with [`two_product`] for every one of
    /// `factors`: every float but NaN with an FMA, [`ExactRange::exact`] with Dekker's
    /// product.
    #[inline(always)]
    pub(crate) fn agreeing(factors: &[Factor]) -> Self {
        if cfg!(target_feature = "fma") {
            ExactRange {
                min_abs: 0.0,
                max_abs: f64::INFINITY,
            }
        } else {
            Self::exact(factors)
        }
    }

    /// The `x` whose products with every one of `factors` have an error that is a float,
    /// computed exactly by [`Factor::error`] (either method), with `|k·x| < 2^1022`.
    #[inline(always)]
    pub(crate) fn exact(factors: &[Factor]) -> Self {
        let mut range = ExactRange {
            min_abs: 0.0,
            max_abs: f64::INFINITY,
        };
        for f in factors {
            range.min_abs = range.min_abs.max(f.range.min_abs);
            range.max_abs = range.max_abs.min(f.range.max_abs);
        }
        range
    }

    /// This range without the values above `cap`.
    pub(crate) fn capped(self, cap: f64) -> Self {
        ExactRange {
            min_abs: self.min_abs,
            max_abs: self.max_abs.min(cap),
        }
    }

    /// Whether `x` is in the range.
    #[inline(always)]
    pub(crate) fn contains(&self, x: f64) -> bool {
        let ax = x.abs();
        ((ax >= self.min_abs) & (ax <= self.max_abs)) | (x == 0.0)
    }
}

/// `2^e` for `−1022 ≤ e ≤ 1023`.
fn pow2(e: i64) -> f64 {
    f64::from_bits(((e + 1023) as u64) << 52)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Scalar;
    use num_rational::BigRational;
    use proptest::prelude::*;

    fn exact(x: f64) -> BigRational {
        BigRational::from_f64(x).unwrap()
    }

    proptest! {
        #[test]
        fn transformations_are_error_free(a in -1e100f64..1e100, b in -1e100f64..1e100, scale in -60i32..60) {
            let b = b * 2f64.powi(scale);
            let (s, e) = two_sum(a, b);
            prop_assert_eq!(s, a + b);
            prop_assert_eq!(exact(s) + exact(e), exact(a) + exact(b));
            let (p, e) = two_product(a, b * 1e-100);
            prop_assert_eq!(exact(p) + exact(e), exact(a) * exact(b * 1e-100));
            let (big, small) = if a.abs() >= b.abs() { (a, b) } else { (b, a) };
            let (s, e) = fast_two_sum(big, small);
            prop_assert_eq!(exact(s) + exact(e), exact(a) + exact(b));
        }
    }
}
