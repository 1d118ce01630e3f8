//! Working copies for the `f64` evaluators, on the stack up to [`STACK_COEFFICIENTS`]
//! coefficients: de Casteljau's triangle works in place on a copy of its inputs, and a heap
//! `Vec` per call used to cost more than the arithmetic at low degrees.
//!
//! The copy lives in an array of 4, 8, 16, 32 or 64 entries (the smallest that fits, so that
//! a cubic does not clear 64), of which the first `len` are handed out; longer inputs take
//! one `Vec`. `tests/alloc.rs` checks that every evaluator allocates nothing up to the limit.

/// Coefficients (per buffer) an evaluator keeps on the stack: curves up to degree 63 are
/// evaluated with no heap allocation.
pub const STACK_COEFFICIENTS: usize = 64;

/// Runs `f` on a buffer of `len` copies of `fill`, on the stack up to
/// [`STACK_COEFFICIENTS`].
#[inline(always)]
pub(crate) fn with_scratch<T: Copy, R>(len: usize, fill: T, f: impl FnOnce(&mut [T]) -> R) -> R {
    #[inline(always)]
    fn on_stack<T: Copy, R, const N: usize>(len: usize, fill: T, f: impl FnOnce(&mut [T]) -> R) -> R {
        let mut buf = [fill; N];
        f(&mut buf[..len])
    }
    match len {
        0..=4 => on_stack::<T, R, 4>(len, fill, f),
        5..=8 => on_stack::<T, R, 8>(len, fill, f),
        9..=16 => on_stack::<T, R, 16>(len, fill, f),
        17..=32 => on_stack::<T, R, 32>(len, fill, f),
        33..=STACK_COEFFICIENTS => on_stack::<T, R, STACK_COEFFICIENTS>(len, fill, f),
        _ => f(&mut vec![fill; len]),
    }
}

/// [`with_scratch`] with two buffers of `len` each.
#[inline(always)]
pub(crate) fn with_scratch2<T: Copy, R>(len: usize, fill: T, f: impl FnOnce(&mut [T], &mut [T]) -> R) -> R {
    #[inline(always)]
    fn on_stack<T: Copy, R, const N: usize>(len: usize, fill: T, f: impl FnOnce(&mut [T], &mut [T]) -> R) -> R {
        let (mut a, mut b) = ([fill; N], [fill; N]);
        f(&mut a[..len], &mut b[..len])
    }
    match len {
        0..=4 => on_stack::<T, R, 4>(len, fill, f),
        5..=8 => on_stack::<T, R, 8>(len, fill, f),
        9..=16 => on_stack::<T, R, 16>(len, fill, f),
        17..=32 => on_stack::<T, R, 32>(len, fill, f),
        33..=STACK_COEFFICIENTS => on_stack::<T, R, STACK_COEFFICIENTS>(len, fill, f),
        _ => f(&mut vec![fill; len], &mut vec![fill; len]),
    }
}

/// Runs `f` on a stack copy of `b` (a `Vec` above [`STACK_COEFFICIENTS`]).
#[inline(always)]
pub(crate) fn with_copy<R>(b: &[f64], f: impl FnOnce(&mut [f64]) -> R) -> R {
    with_scratch(b.len(), 0.0, |buf| {
        buf.copy_from_slice(b);
        f(buf)
    })
}

/// Runs `f` on a stack buffer holding `map(b_i)` for every coefficient.
#[inline(always)]
pub(crate) fn with_mapped<R>(b: &[f64], map: impl Fn(f64) -> f64, f: impl FnOnce(&mut [f64]) -> R) -> R {
    with_scratch(b.len(), 0.0, |buf| {
        for (x, y) in buf.iter_mut().zip(b) {
            *x = map(*y);
        }
        f(buf)
    })
}
