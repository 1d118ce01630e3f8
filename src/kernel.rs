//! The de Casteljau kernel every algorithm runs on: curve evaluation, the scheme (9),
//! subdivision, rational curves (on their homogeneous points) and both directions of
//! surfaces (whole rows or columns of the net as one point each). A float cubic alone is
//! evaluated otherwise, by [`eval_cubic`]: fewer operations and a smaller error.
//!
//! It works in place on a column of points and never allocates; [`with_column`] gives it a
//! buffer on the stack for the polygons met in practice.

use crate::error::Result;
use crate::scalar::{Ring, Scalar};
use crate::space::VectorSpace;

/// Points kept on the stack by [`with_column`]; longer polygons use one heap buffer.
pub const STACK_POINTS: usize = 24;

/// One level of the scheme in place: `column[i] ← column[i] + t (column[i+1] − column[i])`
/// for every `i` but the last, which is left as it was.
#[inline(always)]
pub fn casteljau_step<P: VectorSpace>(column: &mut [P], t: &P::Scalar) {
    for i in 1..column.len() {
        let (done, rest) = column.split_at_mut(i);
        done[i - 1].lerp_assign(&rest[0], t);
    }
}

/// de Casteljau's algorithm (1) in place on the `n + 1` points of `column`: after it,
/// `column[0]` is `b(t)`. `each_level` sees column `r` of the scheme (9), `b_0^r … b_{n-r}^r`,
/// after each level `r = 1..=n`.
#[inline(always)]
pub fn de_casteljau<P: VectorSpace>(column: &mut [P], t: &P::Scalar, mut each_level: impl FnMut(&[P])) {
    for len in (1..column.len()).rev() {
        casteljau_step(&mut column[..=len], t);
        each_level(&column[..len]);
    }
}

/// `b(t)` of the cubic with control points `b`. Exact scalars take de Casteljau's
/// algorithm (1), the fewest multiplications; floats the Bernstein sum nested in `t`,
///
/// `b(t) = ((t b_3 + 3s b_2) t + 3s² b_1) t + s³ b_0`, `s = 1 − t`,
///
/// 14 floating-point operations per coordinate pair instead of de Casteljau's 18, and a
/// smaller error. On `[0, 1]` every `b_i` reaches the result through at most 8 roundings
/// with nonnegative weights, so the error is at most `γ_8 Σ |b_i| B_i^3(t)`
/// (`tests/float_bounds.rs` checks it exactly), below the `γ_9` of the convex form
/// `s b_i + t b_{i+1}`; the form `b_i + t (b_{i+1} − b_i)` rounds relative to `b_i` rather
/// than to its share of the result and has no bound of that shape (its error reached 52
/// `u Σ |b_i| B_i^3(t)` on 20,000 random cubics and 175 on 20,000 near a triple root; this
/// form's, 3.8 and 3.1). It is exact at
/// `t = 0` and `t = 1`, and groups the products as kurbo does, so the two agree bit for bit.
#[inline(always)]
pub fn eval_cubic<P: VectorSpace>(b: &[P; 4], t: &P::Scalar) -> P
where
    P::Scalar: Scalar,
{
    if <P::Scalar as Scalar>::EXACT {
        let mut column = b.clone();
        de_casteljau(&mut column, t, |_| {});
        let [p, ..] = column;
        return p;
    }
    let s = P::Scalar::one().sub_ref(t);
    let three = P::Scalar::from_i64(3);
    let s2 = s.mul_ref(&s);
    let mut v = b[3].clone();
    v.scale_assign(t);
    v.add_scaled_assign(&s.mul_ref(&three), &b[2]);
    v.scale_assign(t);
    v.add_scaled_assign(&s2.mul_ref(&three), &b[1]);
    v.scale_assign(t);
    v.add_scaled_assign(&s2.mul_ref(&s), &b[0]);
    v
}

/// Subdivision (Lemma 1.3) of the `N` points `right` at `t`, in place: `right` becomes the
/// right boundary of the scheme (9), `b_0^n, b_1^{n-1}, …, b_n^0`, and the array returned
/// the left one, `b_0^0, b_0^1, …, b_0^n`. The same steps as [`de_casteljau`]; with `N` a
/// constant the levels unroll into straight-line code.
#[inline(always)]
pub fn split_fixed<P: VectorSpace, const N: usize>(right: &mut [P; N], t: &P::Scalar) -> [P; N] {
    let mut left = right.clone();
    for len in (1..N).rev() {
        casteljau_step(&mut right[..=len], t);
        left[N - len] = right[0].clone();
    }
    left
}

/// Runs `f` on a mutable copy of `points`, on the stack for up to [`STACK_POINTS`] points:
/// in an array of the exact length up to four (so a cubic's loops unroll), else in an array
/// of 8, 16 or 24 whose tail repeats the last point (at most twice the points needed).
#[inline(always)]
pub fn with_column<P: Clone, R>(points: &[P], f: impl FnOnce(&mut [P]) -> R) -> R {
    #[inline(always)]
    fn fixed<P: Clone, R, const N: usize>(points: &[P], f: impl FnOnce(&mut [P]) -> R) -> R {
        let last = points.len() - 1;
        let mut column: [P; N] = std::array::from_fn(|i| points[i.min(last)].clone());
        f(&mut column[..=last])
    }
    match points.len() {
        1 => fixed::<P, R, 1>(points, f),
        2 => fixed::<P, R, 2>(points, f),
        3 => fixed::<P, R, 3>(points, f),
        4 => fixed::<P, R, 4>(points, f),
        5..=8 => fixed::<P, R, 8>(points, f),
        9..=16 => fixed::<P, R, 16>(points, f),
        17..=STACK_POINTS => fixed::<P, R, STACK_POINTS>(points, f),
        _ => f(&mut points.to_vec()),
    }
}

/// `1/(n+1)`, the step of the weights of (7), divided once: its multiples `i · 1/(n+1)`
/// are the weights `i/(n+1)`, exactly for exact scalars, with one rounding more for floats.
#[inline(always)]
pub(crate) fn elevation_step<T: Scalar>(n: usize) -> Result<T> {
    T::one().checked_div(&T::from_usize(n + 1))
}

/// Point `i` of the polygon (7) elevated from the `n + 1` `points`, given `step = 1/(n+1)`.
#[inline(always)]
pub(crate) fn elevated_point<T: Scalar, P: VectorSpace<Scalar = T>>(points: &[P], i: usize, step: &T) -> P {
    let n = points.len() - 1;
    if i == 0 {
        points[0].clone()
    } else if i > n {
        points[n].clone()
    } else {
        points[i].lerp_to(&points[i - 1], &T::from_usize(i).mul_ref(step))
    }
}

/// The two halves of the curve with control points `points` split at `t0`, as
/// [`Bezier::split_at`](crate::Bezier::split_at) computes them.
#[inline(always)]
pub(crate) fn split_points<T: Scalar, P: VectorSpace<Scalar = T>, const N: usize>(
    points: &[P; N],
    t0: &T,
) -> ([P; N], [P; N]) {
    let mut right = points.clone();
    let left = split_fixed(&mut right, t0);
    (left, right)
}

/// One step of degree elevation (7) of the `N` points `points` into `M = N + 1` points, as
/// [`Bezier::elevate`](crate::Bezier::elevate) computes it.
#[inline(always)]
pub(crate) fn elevate_points<T: Scalar, P: VectorSpace<Scalar = T>, const N: usize, const M: usize>(
    points: &[P; N],
) -> [P; M] {
    debug_assert_eq!(M, N + 1);
    let Ok(step) = elevation_step::<T>(N - 1) else {
        unreachable!("1/N divides by a nonzero count")
    };
    std::array::from_fn(|i| elevated_point(points, i, &step))
}
