//! Error-free transformations: a float operation together with its exact rounding error.
//!
//! `two_sum(a, b) = (s, e)` with `s = fl(a + b)` and `s + e = a + b` exactly;
//! `two_product(a, b) = (p, e)` with `p = fl(a·b)` and `p + e = a·b` exactly (barring
//! underflow of `e` below the subnormal range, and overflow). They are the building blocks of
//! compensated algorithms, which carry the errors along and add them back at the end.

/// Knuth's TwoSum: `s = fl(a + b)` and the exact error `e = (a + b) − s`, for any finite
/// `a`, `b` (no ordering needed; six float operations).
///
/// ```
/// use casteljau::float::two_sum;
/// let (s, e) = two_sum(1.0, 1e-20);
/// assert_eq!((s, e), (1.0, 1e-20));
/// ```
#[inline]
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

/// TwoProduct: `p = fl(a·b)` and the exact error `e = a·b − p`, by one fused multiply-add
/// (exact unless `e` falls below the subnormal range).
///
/// ```
/// use casteljau::float::two_product;
/// let x = 1.0 + f64::EPSILON;
/// let (p, e) = two_product(x, x);
/// assert_eq!((p, e), (1.0 + 2.0 * f64::EPSILON, f64::EPSILON * f64::EPSILON));
/// ```
#[inline]
pub fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
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
