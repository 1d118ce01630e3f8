//! One curve type for data that may be polynomial or rational: claim files, figures and the
//! report hold an [`AnyCurve`] and use it through [`ParamCurve`] and [`ParamCurveDeriv`].

use crate::curve::BezierCurve;
use crate::error::Result;
use crate::param::{ParamCurve, ParamCurveDeriv};
use crate::point::Point;
use crate::rational::RationalBezierCurve;
use crate::scalar::Scalar;

/// A polynomial or a rational Bézier curve.
#[derive(Clone, Debug)]
pub enum AnyCurve<T> {
    /// `Σ b_i B_i^n(t)`.
    Polynomial(BezierCurve<T>),
    /// `Σ w_i b_i B_i^n(t) / Σ w_i B_i^n(t)`.
    Rational(RationalBezierCurve<T>),
}

impl<T: Scalar> AnyCurve<T> {
    /// The control points.
    pub fn points(&self) -> &[Point<T>] {
        match self {
            AnyCurve::Polynomial(c) => c.points(),
            AnyCurve::Rational(c) => c.points(),
        }
    }

    /// The dimension of the points.
    pub fn dim(&self) -> usize {
        match self {
            AnyCurve::Polynomial(c) => c.dim(),
            AnyCurve::Rational(c) => c.dim(),
        }
    }
}

impl<T: Scalar> ParamCurve for AnyCurve<T> {
    type Scalar = T;
    type Point = Point<T>;

    /// The point at `t`; for a rational curve an error where the weight sum vanishes.
    fn eval(&self, t: &T) -> Result<Point<T>> {
        match self {
            AnyCurve::Polynomial(c) => Ok(c.eval(t)),
            AnyCurve::Rational(c) => c.eval(t),
        }
    }
    fn split_at(&self, t0: &T) -> Result<(Self, Self)> {
        Ok(match self {
            AnyCurve::Polynomial(c) => {
                let (a, b) = c.split_at(t0);
                (AnyCurve::Polynomial(a), AnyCurve::Polynomial(b))
            }
            AnyCurve::Rational(c) => {
                let (a, b) = c.split_at(t0)?;
                (AnyCurve::Rational(a), AnyCurve::Rational(b))
            }
        })
    }
    fn degree(&self) -> usize {
        match self {
            AnyCurve::Polynomial(c) => c.degree(),
            AnyCurve::Rational(c) => c.degree(),
        }
    }
}

impl<T: Scalar> ParamCurveDeriv for AnyCurve<T> {
    type Deriv = Self;

    /// The hodograph: polynomial of degree `n − 1`, or rational of degree `2n`.
    fn deriv(&self) -> Result<Self> {
        Ok(match self {
            AnyCurve::Polynomial(c) => AnyCurve::Polynomial(ParamCurveDeriv::deriv(c)?),
            AnyCurve::Rational(c) => AnyCurve::Rational(ParamCurveDeriv::deriv(c)?),
        })
    }
    fn deriv_at(&self, t: &T) -> Result<Point<T>> {
        match self {
            AnyCurve::Polynomial(c) => c.deriv_at(t),
            AnyCurve::Rational(c) => c.deriv_at(t),
        }
    }
}

impl<T: Scalar> From<BezierCurve<T>> for AnyCurve<T> {
    fn from(c: BezierCurve<T>) -> Self {
        AnyCurve::Polynomial(c)
    }
}

impl<T: Scalar> From<RationalBezierCurve<T>> for AnyCurve<T> {
    fn from(c: RationalBezierCurve<T>) -> Self {
        AnyCurve::Rational(c)
    }
}
