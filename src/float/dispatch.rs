//! The kernel of `Bezier::eval` for interval points: a curve whose coordinates are
//! [`Interval`]s ([`Point<Interval>`], or [`PointN`] of `Interval` in 1 to 3 dimensions),
//! evaluated at a point `t ∈ [0, 1]`, is enclosed per coordinate by the sign-split kernel of
//! [`crate::interval_de_casteljau`] (two float triangles) instead of the generic algorithm's
//! interval operations. Every other curve, an interval `t` and a `t` outside `[0, 1]` take
//! the generic algorithm.
//!
//! `Interval`'s `Scalar` implementation chooses it (its `curve_eval` methods): a method of
//! the type, so the code for other scalars keeps no trace of it.

use crate::coords::{Point, PointN, INLINE_COORDS};
use crate::interval::{sign_split_enclosure_by, sign_split_enclosure_of, Interval};
use crate::scalar::Ring;
use crate::space::VectorSpace;
use std::cell::Cell;

/// The first `dim ≤ INLINE_COORDS` coordinates of a point, coordinate `k` the expression
/// given (an `Option`: `None` if any is), the rest zero. A macro, not a function taking a
/// closure: each coordinate is computed where it is written, in registers, and the point's
/// buffer is written from them at once. Filled by a loop, it was stored one coordinate at a
/// time and copied into the point with loads that straddled those stores (a failed
/// store-to-load forwarding each, about as long as the kernel in all); a closure called for
/// each coordinate was not inlined, and its result came back through memory.
macro_rules! inline_coords {
    ($dim:expr, $k:ident => $coordinate:expr) => {
        'coords: {
            let (dim, z) = ($dim, Interval::zero());
            let c0 = {
                let $k = 0;
                match $coordinate {
                    Some(c) => c,
                    None => break 'coords None,
                }
            };
            let c1 = if dim > 1 {
                let $k = 1;
                match $coordinate {
                    Some(c) => c,
                    None => break 'coords None,
                }
            } else {
                z
            };
            let c2 = if dim > 2 {
                let $k = 2;
                match $coordinate {
                    Some(c) => c,
                    None => break 'coords None,
                }
            } else {
                z
            };
            let c3 = if dim > 3 {
                let $k = 3;
                match $coordinate {
                    Some(c) => c,
                    None => break 'coords None,
                }
            } else {
                z
            };
            Some([c0, c1, c2, c3])
        }
    };
}

/// `t` as a float when it is a point of `[0, 1]` (where the Bernstein weights are
/// nonnegative), else `None`.
#[inline(always)]
fn unit_point(t: &Interval) -> Option<f64> {
    if t.lo() != t.hi() || !(0.0..=1.0).contains(&t.lo()) {
        return None;
    }
    Some(t.lo())
}

/// `b(t)` for interval points of run-time dimension by the sign-split enclosure, when `t`
/// is a point of `[0, 1]`; by `generic` (the generic algorithm, which gives its own
/// enclosure) otherwise, and when a coefficient is not finite. Inlined into `eval`, so that
/// an interval cubic whose points have at most 4 coordinates (a point's inline capacity) is
/// enclosed and its point written in place, where the caller keeps it; every other curve
/// goes out of line. The point is returned, not an `Option` of it: the `Option` was a
/// temporary that the other paths wrote too, the point 8 bytes into it after the tag,
/// written there with 8-byte stores and copied out with 16-byte loads, each of which
/// straddled two stores (failed store-to-load forwardings: 1.8x the kernel at degree 3).
#[inline(always)]
pub(crate) fn enclose_points(
    points: &[Point<Interval>],
    t: &Interval,
    generic: impl FnOnce() -> Point<Interval>,
) -> Point<Interval> {
    let Some(t) = unit_point(t) else {
        return cold(generic);
    };
    if let [p0, p1, p2, p3] = points {
        // each point's coordinates looked up once
        let coords = [p0.coords(), p1.coords(), p2.coords(), p3.coords()];
        let dim = coords[0].len();
        if dim <= INLINE_COORDS && coords.iter().all(|c| c.len() == dim) {
            return match inline_coords!(dim, k => enclose_gathered(coords.map(|c| c[k]), t)) {
                Some(c) => Point::from_inline_prefix(c, dim),
                None => cold(generic),
            };
        }
    }
    curve_of_points(points, t, generic)
}

/// `f()` out of line: the generic algorithm where the kernel does not apply (a `t` that is an
/// interval or outside `[0, 1]`, a coefficient not finite), so that its code stays out of `eval`'s.
#[cold]
#[inline(never)]
fn cold<R>(f: impl FnOnce() -> R) -> R {
    f()
}

/// `b(t)` for interval points of fixed dimension `D` (1 to 3; `None` for more, which take
/// the generic algorithm), as [`enclose_points`].
#[inline(always)]
pub(crate) fn enclose_fixed<const D: usize>(
    points: &[PointN<Interval, D>],
    t: &Interval,
) -> Option<PointN<Interval, D>> {
    if D > 3 {
        return None;
    }
    fixed(points, unit_point(t)?)
}

/// Any other curve of points of run-time dimension, coordinate by coordinate.
#[inline(never)]
fn curve_of_points(points: &[Point<Interval>], t: f64, generic: impl FnOnce() -> Point<Interval>) -> Point<Interval> {
    let dim = points[0].dim();
    let point = if dim <= INLINE_COORDS {
        inline_coords!(dim, k => enclose_coordinate(points, k, t)).map(|c| Point::from_inline_prefix(c, dim))
    } else {
        let coords: Option<Vec<Interval>> = (0..dim).map(|k| enclose_coordinate(points, k, t)).collect();
        coords.map(Point::from_valid)
    };
    point.unwrap_or_else(generic)
}

#[inline(never)]
fn fixed<const D: usize>(points: &[PointN<Interval, D>], t: f64) -> Option<PointN<Interval, D>> {
    let mut coords = [Interval::zero(); D];
    for (k, x) in coords.iter_mut().enumerate() {
        *x = enclose_coordinate(points, k, t)?;
    }
    Some(PointN(coords))
}

/// Coordinate `k` of the curve on `points` at `t ∈ [0, 1]`: the Bernstein weights are
/// nonnegative there, so the values over the coefficients' intervals run from the curve on
/// their lower endpoints to the curve on their upper ones, each enclosed by
/// [`sign_split_enclosure_by`] (once when every coefficient is a point). A cubic's endpoints
/// are gathered into arrays of constant length, so that the kernel is inlined for it.
#[inline]
fn enclose_coordinate<Q: VectorSpace<Scalar = Interval>>(points: &[Q], k: usize, t: f64) -> Option<Interval> {
    match points {
        [p0, p1, p2, p3] => enclose_gathered([p0, p1, p2, p3].map(|p| p.coords()[k]), t),
        _ => {
            // read where the kernel reads them, with no copy in between
            let points_only = Cell::new(true);
            let lower = || {
                points.iter().map(|p| {
                    let c = p.coords()[k];
                    points_only.set(points_only.get() & (c.lo() == c.hi()));
                    c.lo()
                })
            };
            let low = sign_split_enclosure_by(points.len(), lower, t)?;
            joined(low, points_only.get(), || {
                sign_split_enclosure_by(points.len(), || points.iter().map(|p| p.coords()[k].hi()), t)
            })
        }
    }
}

/// [`enclose_coordinate`] on the coefficients of one coordinate, `N` known at compile time.
/// Every coefficient a point is tested before the kernel, and wider ones go out of line,
/// given by value and answered in registers: tested after the kernel, the coefficients
/// stayed live across it and were spilled to the stack; given by reference, they were
/// stored before the test; answered as an `Option`, through memory, the kernel's result
/// was stored and loaded again to meet it.
#[inline(always)]
fn enclose_gathered<const N: usize>(coefficients: [Interval; N], t: f64) -> Option<Interval> {
    if coefficients.iter().all(|c| c.lo() == c.hi()) {
        return sign_split_enclosure_of(&coefficients.map(|c| c.lo()), t);
    }
    let (lo, hi) = enclose_wide(coefficients, t);
    // NaN is `enclose_wide`'s `None`: no enclosure has a NaN endpoint
    if lo.is_nan() {
        return None;
    }
    Interval::new(lo, hi).ok()
}

/// [`enclose_gathered`] when a coefficient is not a point: the enclosure's endpoints, or
/// NaN for none.
#[inline(never)]
fn enclose_wide<const N: usize>(coefficients: [Interval; N], t: f64) -> (f64, f64) {
    let low = sign_split_enclosure_of(&coefficients.map(|c| c.lo()), t);
    let enclosure =
        low.and_then(|low| joined(low, false, || sign_split_enclosure_of(&coefficients.map(|c| c.hi()), t)));
    enclosure.map_or((f64::NAN, f64::NAN), |e| (e.lo(), e.hi()))
}

/// The enclosure over interval coefficients from `low`, the curve's on their lower
/// endpoints, and `high()`, on their upper ones, needed only when a coefficient is not a
/// point.
#[inline(always)]
fn joined(low: Interval, points_only: bool, high: impl FnOnce() -> Option<Interval>) -> Option<Interval> {
    if points_only {
        return Some(low);
    }
    Interval::new(low.lo(), high()?.hi()).ok()
}
