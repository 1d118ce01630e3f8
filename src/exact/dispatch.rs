//! The kernel choice inside the public generic operations: a curve whose points are exact
//! rationals ([`Point<BigRational>`], or [`PointN`] of `BigRational` in 1 to 3 dimensions) is
//! handed to the fraction-free kernels of [`super::fraction_free`]; every other type runs
//! the generic algorithm.
//!
//! The choice is by type identity ([`Any`]), a constant once the generic code is
//! instantiated: the `f64` code keeps no trace of it. Stable Rust has no specialisation, and
//! asking callers to name the fast kernel is what this module exists to avoid.

use crate::curve::{Bezier, BezierCurve};
use crate::point::Point;
use crate::scalar::Scalar;
use crate::space::{PointN, VectorSpace};
use num_rational::BigRational;
use std::any::{Any, TypeId};
use std::borrow::Cow;

/// `value` as a `B` when `A` is `B`, else `value` back.
pub(crate) fn cast<A: 'static, B: 'static>(value: A) -> Result<B, A> {
    let mut slot = Some(value);
    match (&mut slot as &mut dyn Any).downcast_mut::<Option<B>>() {
        Some(b) => Ok(b.take().expect("just filled")),
        None => Err(slot.expect("untouched")),
    }
}

/// The parameter as an exact rational, when `T` is [`BigRational`].
#[inline(always)]
pub(crate) fn exact_scalar<T: 'static>(t: &T) -> Option<&BigRational> {
    (t as &dyn Any).downcast_ref::<BigRational>()
}

/// The curve as one of run-time dimension, when its points are exact rationals: borrowed
/// for [`Point`], copied for [`PointN`].
#[inline(always)]
pub(crate) fn exact_curve<P: 'static>(c: &Bezier<P>) -> Option<Cow<'_, BezierCurve<BigRational>>> {
    let any = c as &dyn Any;
    if let Some(c) = any.downcast_ref::<BezierCurve<BigRational>>() {
        return Some(Cow::Borrowed(c));
    }
    fn fixed<const D: usize>(any: &dyn Any) -> Option<BezierCurve<BigRational>> {
        let c = any.downcast_ref::<Bezier<PointN<BigRational, D>>>()?;
        Some(Bezier::from_valid(
            c.points().iter().map(|p| Point::from_valid(p.0.iter().cloned())),
        ))
    }
    fixed::<1>(any)
        .or_else(|| fixed::<2>(any))
        .or_else(|| fixed::<3>(any))
        .map(Cow::Owned)
}

/// An exact point as the point type `P` it was computed for (see [`exact_curve`]).
pub(crate) fn point_back<P: 'static>(p: Point<BigRational>) -> P {
    fn fixed<P: 'static, const D: usize>(coords: &mut Vec<BigRational>) -> Option<P> {
        if coords.len() != D || TypeId::of::<P>() != TypeId::of::<PointN<BigRational, D>>() {
            return None;
        }
        let coords: [BigRational; D] = std::mem::take(coords).try_into().ok()?;
        cast::<PointN<BigRational, D>, P>(PointN(coords)).ok()
    }
    if TypeId::of::<P>() == TypeId::of::<Point<BigRational>>() {
        if let Ok(p) = cast::<Point<BigRational>, P>(p) {
            return p;
        }
        unreachable!("the types are equal");
    }
    let mut coords = p.into_coords();
    if let Some(p) = fixed::<P, 1>(&mut coords) {
        return p;
    }
    if let Some(p) = fixed::<P, 2>(&mut coords) {
        return p;
    }
    if let Some(p) = fixed::<P, 3>(&mut coords) {
        return p;
    }
    unreachable!("points come back as the type exact_curve accepted")
}

/// An exact curve as the curve type `Bezier<P>` it was computed for.
pub(crate) fn curve_back<P: VectorSpace>(c: BezierCurve<BigRational>) -> Bezier<P>
where
    P::Scalar: Scalar,
{
    match cast::<BezierCurve<BigRational>, Bezier<P>>(c) {
        Ok(c) => c,
        Err(c) => Bezier::from_valid(c.into_points().into_iter().map(point_back)),
    }
}

/// The value as a `B` when `A` is `B` (used for the scalars of a result).
pub(crate) fn scalar_back<A: 'static, B: 'static>(value: A) -> Option<B> {
    cast::<A, B>(value).ok()
}
