//! [`Interval`] as a [`Scalar`]: outward-rounded arithmetic, and the sign-split kernel of
//! `Bezier::eval` as its kernel choice.

use super::*;
use crate::coords::PointN;
use crate::float::{enclose_fixed, enclose_points};

impl Scalar for Interval {
    const EXACT: bool = false;
    const NAME: &'static str = "interval";

    /// Only `[0, 0]` is zero (an interval that merely contains 0 is not known to be zero).
    fn is_zero(&self) -> bool {
        self.lo == 0.0 && self.hi == 0.0
    }
    fn from_bigint(n: &BigInt) -> Result<Self> {
        Self::from_rational(&BigRational::from_integer(n.clone()))
    }
    /// The float nearest to `r` when it is `r`, else the two floats around it.
    fn from_rational(r: &BigRational) -> Result<Self> {
        let x = nearest_f64(r);
        if !x.is_finite() {
            return Err(Error::NotFinite(r.to_string()));
        }
        if exact(x) == *r {
            return Ok(Interval { lo: x, hi: x });
        }
        Ok(Interval {
            lo: next_down(x),
            hi: next_up(x),
        })
    }
    fn from_f64(x: f64) -> Result<Self> {
        if !x.is_finite() {
            return Err(Error::NotFinite(x.to_string()));
        }
        Ok(Interval { lo: x, hi: x })
    }
    /// The midpoint.
    fn to_f64(&self) -> f64 {
        if self.lo == self.hi {
            return self.lo;
        }
        self.lo / 2.0 + self.hi / 2.0
    }
    /// An error when the divisor contains 0.
    fn checked_div(&self, rhs: &Self) -> Result<Self> {
        if rhs.lo <= 0.0 && rhs.hi >= 0.0 {
            return Err(Error::DivisionByZero(format!(
                "{self} / {rhs} (the divisor contains 0)"
            )));
        }
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for a in [self.lo, self.hi] {
            for b in [rhs.lo, rhs.hi] {
                let q = a / b;
                // the remainder a − q·b is exact (fma), and its sign over b's is the error's
                let r = (-q).mul_add(b, a);
                if q.is_finite() && b.is_finite() && r == 0.0 && q != 0.0 && !error_is_exact(q, b) {
                    // the remainder a − q·b may have underflowed to 0: move outward both ways
                    lo = lo.min(next_down(q));
                    hi = hi.max(next_up(q));
                    continue;
                }
                let e = if q.is_finite() && b.is_finite() {
                    r * b.signum()
                } else {
                    0.0
                };
                lo = lo.min(down(q, e));
                hi = hi.max(up(q, e));
            }
        }
        Ok(Interval { lo, hi })
    }
    fn abs(&self) -> Self {
        if self.lo >= 0.0 {
            *self
        } else if self.hi <= 0.0 {
            -self
        } else {
            Interval {
                lo: 0.0,
                hi: self.hi.max(-self.lo),
            }
        }
    }

    // The sign-split enclosure of `Bezier::eval` (`crate::float`).
    #[inline(always)]
    fn curve_eval(points: &[Point<Self>], t: &Self, generic: impl FnOnce() -> Point<Self>) -> Point<Self> {
        enclose_points(points, t, generic)
    }
    #[inline(always)]
    fn curve_eval_fixed<const N: usize>(
        points: &[PointN<Self, N>],
        t: &Self,
        generic: impl FnOnce() -> PointN<Self, N>,
    ) -> PointN<Self, N> {
        enclose_fixed(points, t).unwrap_or_else(generic)
    }
}
