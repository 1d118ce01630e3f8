//! [`Shadow`]: an `f64` computed alongside its exact value — a kernel checker.

use crate::error::{Error, Result};
use crate::float::{nearest_f64, ulp_error, UlpError};
use crate::scalar::{forward_ring_ops, Ring, Scalar};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;
use std::cmp::Ordering;
use std::fmt;

/// An `f64` and the exact value the same operations give on the same inputs.
///
/// Every operation runs twice: in `f64`, exactly as plain float code would, and in exact
/// rationals on the same inputs. Comparisons and branches follow the `f64` value (so the
/// algorithm takes the path the float code takes), and at the end each result carries its
/// exact error. Run any generic algorithm of the crate on `Shadow` once and get the float
/// result and its error in ulps: a differential test of the whole library in one line.
///
/// ```
/// use casteljau::{Shadow, BezierCurve, Scalar};
/// let c: BezierCurve<Shadow> = BezierCurve::from_coords(vec![vec![Shadow::from_f64(0.1).unwrap()],
///     vec![Shadow::from_f64(0.2).unwrap()], vec![Shadow::from_f64(0.7).unwrap()]]).unwrap();
/// let x = c.eval(&Shadow::from_f64(0.3).unwrap()).coords()[0].clone();
/// assert_eq!(x.value(), c.try_map(|s| Ok(s.value())).unwrap().eval(&0.3).coords()[0]);
/// assert!(x.ulp_error().unwrap().ulps <= 2);
/// ```
#[derive(Clone, Debug)]
pub struct Shadow {
    value: f64,
    exact: BigRational,
}

impl Shadow {
    /// The float result.
    pub fn value(&self) -> f64 {
        self.value
    }

    /// The exact result.
    pub fn exact(&self) -> &BigRational {
        &self.exact
    }

    /// The float's error against the exact value, in ulps (an error when the float is not
    /// finite or the exact value is beyond the `f64` range).
    pub fn ulp_error(&self) -> Result<UlpError> {
        ulp_error(self.value, &self.exact)
    }
}

impl PartialEq for Shadow {
    /// By the float value: branches follow the float computation.
    fn eq(&self, other: &Self) -> bool {
        self.value == other.value
    }
}

impl PartialOrd for Shadow {
    /// By the float value.
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        self.value.partial_cmp(&other.value)
    }
}

impl fmt::Display for Shadow {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.value)
    }
}

impl Ring for Shadow {
    fn zero() -> Self {
        Shadow {
            value: 0.0,
            exact: <BigRational as Zero>::zero(),
        }
    }
    fn one() -> Self {
        Self::from_i64(1)
    }
    fn from_i64(n: i64) -> Self {
        Shadow {
            value: n as f64,
            exact: BigRational::from_integer(n.into()),
        }
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        Shadow {
            value: self.value + rhs.value,
            exact: &self.exact + &rhs.exact,
        }
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        Shadow {
            value: self.value - rhs.value,
            exact: &self.exact - &rhs.exact,
        }
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        Shadow {
            value: self.value * rhs.value,
            exact: &self.exact * &rhs.exact,
        }
    }
    fn neg_ref(&self) -> Self {
        Shadow {
            value: -self.value,
            exact: -&self.exact,
        }
    }
}

forward_ring_ops!(Shadow);

impl Scalar for Shadow {
    const EXACT: bool = false;
    const NAME: &'static str = "shadow";

    /// Whether the float is zero (the branch the float code takes).
    fn is_zero(&self) -> bool {
        self.value == 0.0
    }
    fn from_bigint(n: &BigInt) -> Result<Self> {
        Self::from_rational(&BigRational::from_integer(n.clone()))
    }
    /// The float is `r` rounded to nearest; the exact value is `r`.
    fn from_rational(r: &BigRational) -> Result<Self> {
        let value = nearest_f64(r);
        if !value.is_finite() {
            return Err(Error::NotFinite(r.to_string()));
        }
        Ok(Shadow {
            value,
            exact: r.clone(),
        })
    }
    fn from_f64(x: f64) -> Result<Self> {
        Ok(Shadow {
            value: x,
            exact: BigRational::from_f64(x)?,
        })
    }
    fn to_f64(&self) -> f64 {
        self.value
    }
    /// An error when either the float or the exact divisor is zero.
    fn checked_div(&self, rhs: &Self) -> Result<Self> {
        if rhs.value == 0.0 || Zero::is_zero(&rhs.exact) {
            return Err(Error::DivisionByZero(format!("{self} / {rhs}")));
        }
        Ok(Shadow {
            value: self.value / rhs.value,
            exact: &self.exact / &rhs.exact,
        })
    }
}
