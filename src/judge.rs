//! A float answer judged against its exact value, for your own `#[test]`s: how many ulps it
//! is off, whether it is within the a priori bound of the algorithm that computed it, and a
//! message that says all of it ([`assert_within_bound!`](crate::assert_within_bound)).
//!
//! ```
//! use casteljau::float::{a_priori_bound, de_casteljau, f64_to_rational};
//! use casteljau::judge::judge;
//! use casteljau::{BezierCurve, BigRational};
//!
//! let b = [0.1, 0.7, 0.3];
//! let t = 0.3;
//! let curve = BezierCurve::<BigRational>::from_coords(
//!     b.iter().map(|x| vec![f64_to_rational(*x).unwrap()]).collect(),
//! )
//! .unwrap();
//! let exact = curve.eval(&f64_to_rational(t).unwrap()).coords()[0].clone();
//! let j = judge(de_casteljau(&b, t), &exact, a_priori_bound(&b, t)).unwrap();
//! assert!(j.within_bound && j.ulps <= 1);
//! // an answer 1e-10 off is far outside de Casteljau's bound
//! let off = judge(de_casteljau(&b, t) + 1e-10, &exact, a_priori_bound(&b, t)).unwrap();
//! assert!(!off.within_bound);
//! assert!(off.to_string().contains("outside the bound"));
//! ```

use crate::error::Result;
use crate::float::{error_at_most, nearest_f64, scale_pow2_up, ulp_distance, ulp_error, ulp_exponent, UlpError};
use num_rational::BigRational;

/// A float answer judged against its exact value and an absolute error bound.
#[derive(Clone, Debug, PartialEq)]
pub struct Judged {
    /// the float answer
    pub approx: f64,
    /// the exact value
    pub exact: BigRational,
    /// its error: `nearest` (the correctly rounded value), `ulps` (float steps from it,
    /// `u64::MAX` for NaN), `error_ulps` (`|approx − exact| / ulp(exact)`)
    pub error: UlpError,
    /// the bound in ulps of the exact value, rounded up (`+∞` for none)
    pub bound_ulps: f64,
    /// whether `|approx − exact| ≤ bound`, decided exactly
    pub within_bound: bool,
    /// a sentence when the answer is `±∞` or NaN
    pub verdict: Option<&'static str>,
}

/// A float's error when it may be `±∞` or NaN: `(error, verdict)`. An infinity is one step
/// past `±f64::MAX`, so its `ulps` count from the nearest float and its `error_ulps` is
/// `+∞`; a NaN has `ulps` `u64::MAX` and `error_ulps` NaN.
pub fn float_error(approx: f64, exact: &BigRational) -> Result<(UlpError, Option<&'static str>)> {
    if approx.is_finite() {
        return Ok((ulp_error(approx, exact)?, None));
    }
    let nearest = nearest_f64(exact);
    if approx.is_nan() {
        let e = UlpError {
            nearest,
            ulps: u64::MAX,
            error_ulps: f64::NAN,
        };
        return Ok((e, Some("nan: the float is NaN, the exact value is a number")));
    }
    let verdict = if nearest.is_finite() {
        if approx > 0.0 {
            "overflow: the float is inf, the exact value is finite"
        } else {
            "overflow: the float is -inf, the exact value is finite"
        }
    } else if nearest == approx {
        "correctly rounded: the exact value is beyond the largest f64"
    } else {
        "wrong sign: the exact value is beyond the largest f64 on the other side"
    };
    let e = UlpError {
        nearest,
        ulps: ulp_distance(approx, nearest),
        error_ulps: f64::INFINITY,
    };
    Ok((e, Some(verdict)))
}

/// `bound` with NaN read as `+∞` (a bound whose float arithmetic met `∞ · 0` bounds nothing).
fn no_nan(bound: f64) -> f64 {
    if bound.is_nan() {
        f64::INFINITY
    } else {
        bound
    }
}

/// Judges `approx` against `exact` with the absolute error bound `bound` of the algorithm
/// that computed it (for instance [`crate::float::a_priori_bound`] for de Casteljau, or
/// the bounds of [`crate::float::split_bounds`], [`crate::float::elevate_bounds`],
/// [`crate::float::derivative_bounds`], [`crate::float::to_bezier_bounds`]). An error only
/// when `exact` is beyond the f64 range and `approx` is finite (no ulp measures it).
pub fn judge(approx: f64, exact: &BigRational, bound: f64) -> Result<Judged> {
    let (error, verdict) = float_error(approx, exact)?;
    let bound = no_nan(bound);
    let correctly_rounded_overflow = approx.is_infinite() && error.nearest == approx;
    Ok(Judged {
        approx,
        exact: exact.clone(),
        error,
        bound_ulps: no_nan(scale_pow2_up(bound, -ulp_exponent(exact))),
        within_bound: correctly_rounded_overflow || error_at_most(approx, exact, bound),
        verdict,
    })
}

impl Judged {
    /// Float steps from the correctly rounded value (0 exactly when it is).
    pub fn ulps(&self) -> u64 {
        self.error.ulps
    }
}

impl std::fmt::Display for Judged {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let exact = crate::scalar::format_exact(&self.exact);
        let exact = if exact.chars().count() > 80 {
            format!(
                "{}… ({} characters)",
                exact.chars().take(80).collect::<String>(),
                exact.len()
            )
        } else {
            exact
        };
        write!(
            f,
            "{:?} is {} ulps ({:?} ulp) from the exact value {exact} (nearest float {:?}); bound {:?} ulps: {}",
            self.approx,
            self.error.ulps,
            self.error.error_ulps,
            self.error.nearest,
            self.bound_ulps,
            if self.within_bound {
                "within the bound"
            } else {
                "outside the bound"
            }
        )?;
        if let Some(v) = self.verdict {
            write!(f, " ({v})")?;
        }
        Ok(())
    }
}

/// Asserts that a float answer is within an absolute error bound of its exact value
/// (decided exactly); on failure the message gives the ulps, the bound and the exact value.
///
/// `assert_within_bound!(approx, &exact, bound)`, or with a condition number to print too:
/// `assert_within_bound!(approx, &exact, bound, condition)`.
///
/// ```
/// use casteljau::assert_within_bound;
/// use casteljau::float::{derivative_bounds, f64_to_rational};
/// let b = [0.1, 0.7];
/// let d = 1.0 * (b[1] - b[0]); // the hodograph of a line
/// let exact = f64_to_rational(0.7).unwrap() - f64_to_rational(0.1).unwrap();
/// assert_within_bound!(d, &exact, derivative_bounds(&b, 1)[0].bound);
/// let caught = std::panic::catch_unwind(|| {
///     assert_within_bound!(d + 1e-12, &exact, derivative_bounds(&b, 1)[0].bound);
/// });
/// assert!(caught.is_err());
/// ```
#[macro_export]
macro_rules! assert_within_bound {
    ($approx:expr, $exact:expr, $bound:expr $(,)?) => {{
        match $crate::judge::judge($approx, $exact, $bound) {
            Ok(j) if j.within_bound => {}
            Ok(j) => panic!("assert_within_bound failed: {}", j),
            Err(e) => panic!("assert_within_bound: {}", e),
        }
    }};
    ($approx:expr, $exact:expr, $bound:expr, $condition:expr $(,)?) => {{
        match $crate::judge::judge($approx, $exact, $bound) {
            Ok(j) if j.within_bound => {}
            Ok(j) => panic!("assert_within_bound failed: {}; condition {:?}", j, $condition),
            Err(e) => panic!("assert_within_bound: {}", e),
        }
    }};
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::float::f64_to_rational;

    #[test]
    fn infinities_and_nan_are_judged_and_said() {
        let big = f64_to_rational(f64::MAX).unwrap() * BigRational::from_integer(4.into());
        let j = judge(f64::INFINITY, &big, 0.0).unwrap();
        assert!(j.within_bound && j.verdict.unwrap().starts_with("correctly rounded"));
        let one = f64_to_rational(1.0).unwrap();
        let j = judge(f64::NAN, &one, 1.0).unwrap();
        assert!(!j.within_bound && j.error.ulps == u64::MAX, "{j}");
        let j = judge(1.0, &one, f64::NAN).unwrap();
        assert_eq!(j.bound_ulps, f64::INFINITY);
        assert!(judge(1.0, &big, 0.0).is_err());
    }
}
