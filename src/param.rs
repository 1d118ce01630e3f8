//! Capability traits over curve kinds, in the spirit of kurbo's `ParamCurve`: generic code
//! (the cubic fit, a user's checks) takes any curve that can be evaluated, split and, for
//! [`ParamCurveDeriv`], differentiated — polynomial curves ([`crate::Bezier`], including the
//! iso-curves of surfaces) and rational ones ([`crate::RationalBezierCurve`]).

use crate::error::Result;
use crate::scalar::{RefOps, Scalar};

/// A parametric curve `t ↦ x(t)`.
pub trait ParamCurve: Sized {
    /// The parameter and coordinate type.
    type Scalar: Clone;
    /// What the curve evaluates to.
    type Point;

    /// `x(t)`; an error where the curve has no point (a rational curve whose weight vanishes).
    fn eval(&self, t: &Self::Scalar) -> Result<Self::Point>;
    /// The pieces `x(t0 t)` and `x(t0 + (1 − t0) t)`.
    fn split_at(&self, t0: &Self::Scalar) -> Result<(Self, Self)>;
    /// The polynomial degree (of the numerator and denominator for a rational curve).
    fn degree(&self) -> usize;

    /// The piece `x(t0 + (t1 − t0) t)`, `0 ≤ t ≤ 1`: the curve between the parameters `t0` and
    /// `t1` (reversed when `t1 < t0`). Only `t0 = 1, t1 = 0` is refused (a division by zero).
    fn subsegment(&self, t0: &Self::Scalar, t1: &Self::Scalar) -> Result<Self>
    where
        Self::Scalar: Scalar,
        for<'a> &'a Self::Scalar: RefOps<Self::Scalar>,
    {
        let one = Self::Scalar::one();
        if *t0 != one {
            let (_, right) = self.split_at(t0)?;
            let s = (t1 - t0).checked_div(&(&one - t0))?;
            Ok(right.split_at(&s)?.0)
        } else {
            let (left, _) = self.split_at(t1)?;
            let s = t0.checked_div(t1)?;
            Ok(left.split_at(&s)?.1)
        }
    }
}

/// A curve with a derivative curve.
pub trait ParamCurveDeriv: ParamCurve {
    /// The derivative's kind: a polynomial curve of one degree less, or a rational curve.
    type Deriv: ParamCurve<Scalar = Self::Scalar, Point = Self::Point>;

    /// The derivative curve `ẋ`.
    fn deriv(&self) -> Result<Self::Deriv>;

    /// `ẋ(t)`, without building the derivative curve where a kind can do better.
    fn deriv_at(&self, t: &Self::Scalar) -> Result<Self::Point> {
        self.deriv()?.eval(t)
    }
}

impl<T: Scalar, P: crate::VectorSpace<Scalar = T>> ParamCurve for crate::Bezier<P>
where
    for<'a> &'a T: RefOps<T>,
{
    type Scalar = T;
    type Point = P;

    fn eval(&self, t: &T) -> Result<P> {
        Ok(crate::Bezier::eval(self, t))
    }
    fn split_at(&self, t0: &T) -> Result<(Self, Self)> {
        Ok(crate::Bezier::split_at(self, t0))
    }
    fn degree(&self) -> usize {
        crate::Bezier::degree(self)
    }
}

/// The hodograph; a constant curve's derivative is the constant zero curve.
impl<T: Scalar, P: crate::VectorSpace<Scalar = T>> ParamCurveDeriv for crate::Bezier<P>
where
    for<'a> &'a T: RefOps<T>,
{
    type Deriv = Self;

    fn deriv(&self) -> Result<Self> {
        if self.degree() == 0 {
            return crate::Bezier::from_points([crate::VectorSpace::zero_like(&self.points()[0])]);
        }
        self.derivative(1)
    }
}
