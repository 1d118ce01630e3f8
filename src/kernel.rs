//! The de Casteljau kernel every algorithm runs on: curve evaluation, the scheme (9),
//! subdivision, rational curves (on their homogeneous points) and both directions of
//! surfaces (whole rows or columns of the net as one point each).
//!
//! It works in place on a column of points and never allocates; [`with_column`] gives it a
//! buffer on the stack for the polygons met in practice.

use crate::space::VectorSpace;
use smallvec::SmallVec;

/// Points kept on the stack by [`with_column`]; longer polygons use one heap buffer.
pub const STACK_POINTS: usize = 24;

/// One level of the scheme in place: `column[i] ← column[i] + t (column[i+1] − column[i])`
/// for every `i` but the last, which is left as it was.
#[inline(always)]
pub fn casteljau_step<P: VectorSpace>(column: &mut [P], t: &P::Scalar) {
    let mut rest = column;
    while let [first, tail @ ..] = rest {
        let Some(next) = tail.first() else { break };
        first.lerp_assign(next, t);
        rest = tail;
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

/// Runs `f` on a mutable copy of `points`, on the stack for up to [`STACK_POINTS`] points
/// (in an array of the exact length up to four, so a cubic's loops unroll).
#[inline(always)]
pub fn with_column<P: Clone, R>(points: &[P], f: impl FnOnce(&mut [P]) -> R) -> R {
    #[inline(always)]
    fn fixed<P: Clone, R, const N: usize>(points: &[P], f: impl FnOnce(&mut [P]) -> R) -> R {
        let mut column: [P; N] = std::array::from_fn(|i| points[i].clone());
        f(&mut column)
    }
    match points.len() {
        1 => fixed::<P, R, 1>(points, f),
        2 => fixed::<P, R, 2>(points, f),
        3 => fixed::<P, R, 3>(points, f),
        4 => fixed::<P, R, 4>(points, f),
        _ => {
            let mut column: SmallVec<[P; STACK_POINTS]> = points.iter().cloned().collect();
            f(&mut column)
        }
    }
}
