//! One `f64` curve at many parameters: [`BezierN::eval_many`] and [`Bezier::eval_many`]
//! (and their `sample`, which returns a `Vec`).
//!
//! The work is vectorised across parameters, with the operations of the per-point
//! evaluator in the same order, each rounded once, so every point has the same bits as
//! [`BezierN::eval`] at its parameter. A cubic is the per-point nested Bernstein sum in a
//! loop over the parameters, which the compiler vectorises across them (one parameter a
//! lane); other degrees take de Casteljau's steps `a + t (b − a)` on [`LANES`] parameters
//! at a time, each coordinate in an array of `LANES` floats. Both are compiled for the
//! widest vectors the CPU has, chosen at run time (`multiversion`): the default x86-64
//! target has only 128-bit SSE2, two floats a vector, while almost every machine has AVX2.
//! No fused multiply-add is formed (Rust never contracts `a * b + c`), so the choice changes
//! the speed, never the bits.

use crate::curve::Bezier;
use crate::error::{Error, Result};
use crate::fixed::BezierN;
use crate::kernel::STACK_POINTS;
use crate::space::PointN;
use multiversion::multiversion;

/// Parameters evaluated together by de Casteljau's steps (above degree 3): two AVX2
/// vectors, four of SSE2.
pub const LANES: usize = 8;

type Lanes = [f64; LANES];

/// `b(t)` of the cubic `b` by the nested Bernstein sum of [`crate::kernel::eval_cubic`],
/// `((t b₃ + 3s b₂) t + 3s² b₁) t + s³ b₀` with `s = 1 − t`: its operations in its order.
#[inline(always)]
fn cubic_point<const D: usize>(b: &[PointN<f64, D>; 4], t: f64) -> PointN<f64, D> {
    let s = 1.0 - t;
    let s2 = s * s;
    let (w2, w1, w0) = (s * 3.0, s2 * 3.0, s2 * s);
    let mut p = [0.0; D];
    for (k, x) in p.iter_mut().enumerate() {
        let mut v = b[3].0[k] * t;
        v += w2 * b[2].0[k];
        v *= t;
        v += w1 * b[1].0[k];
        v *= t;
        *x = v + w0 * b[0].0[k];
    }
    PointN(p)
}

/// The points at `LANES` parameters `t` of the curve of the control points `b` (at most
/// [`STACK_POINTS`]), by de Casteljau's steps `a ← a + t (b − a)`, as
/// [`crate::kernel::de_casteljau`] takes them.
#[inline(always)]
fn casteljau_lanes<const D: usize>(b: &[PointN<f64, D>], t: &Lanes, out: &mut [PointN<f64, D>]) {
    let mut column = [[0.0; LANES]; STACK_POINTS];
    let column = &mut column[..b.len()];
    for k in 0..D {
        for (c, p) in column.iter_mut().zip(b) {
            *c = [p.0[k]; LANES];
        }
        for len in (1..column.len()).rev() {
            for i in 0..len {
                let next = column[i + 1];
                let a = &mut column[i];
                for j in 0..LANES {
                    a[j] += t[j] * (next[j] - a[j]);
                }
            }
        }
        for (p, x) in out.iter_mut().zip(column[0]) {
            p.0[k] = x;
        }
    }
}

/// The cubic `b` at every parameter of `ts` into `out` (of the same length), one parameter
/// a vector lane. One version per instruction set, the best chosen at run time.
#[multiversion(targets("x86_64+avx512f+avx512vl+avx2+avx+fma", "x86_64+avx2+avx+fma"))]
fn cubic_many<const D: usize>(b: &[PointN<f64, D>; 4], ts: &[f64], out: &mut [PointN<f64, D>]) {
    for (t, o) in ts.iter().zip(out.iter_mut()) {
        *o = cubic_point(b, *t);
    }
}

/// Every whole group of `LANES` parameters of `ts` into `out` (of the same length) by de
/// Casteljau's steps on the at most [`STACK_POINTS`] points `b`; the rest, fewer than
/// `LANES`, is left to the caller. One version per instruction set, the best chosen at run
/// time.
#[multiversion(targets("x86_64+avx2+avx+fma"))]
fn casteljau_groups<const D: usize>(b: &[PointN<f64, D>], ts: &[f64], out: &mut [PointN<f64, D>]) {
    for (t, o) in ts.chunks_exact(LANES).zip(out.chunks_exact_mut(LANES)) {
        let Ok(t) = <&Lanes>::try_from(t) else {
            unreachable!("chunks of LANES")
        };
        casteljau_lanes(b, t, o);
    }
}

/// `b` at every parameter of `ts` into `out` (of the same length), the cubic's way for four
/// points, de Casteljau's for 1 to [`STACK_POINTS`] others, point by point by `each` above.
#[inline(always)]
fn many_into<const D: usize>(
    b: &[PointN<f64, D>],
    ts: &[f64],
    out: &mut [PointN<f64, D>],
    each: impl Fn(f64) -> PointN<f64, D>,
) {
    if let Ok(cubic) = <&[PointN<f64, D>; 4]>::try_from(b) {
        return cubic_many(cubic, ts, out);
    }
    let whole = if b.len() <= STACK_POINTS {
        let whole = ts.len() - ts.len() % LANES;
        casteljau_groups(b, &ts[..whole], &mut out[..whole]);
        whole
    } else {
        0
    };
    for (t, o) in ts[whole..].iter().zip(&mut out[whole..]) {
        *o = each(*t);
    }
}

/// `out` must have one point per parameter.
fn check_lengths<P>(ts: &[f64], out: &[P]) -> Result<()> {
    if ts.len() == out.len() {
        return Ok(());
    }
    Err(Error::WrongCount {
        what: "the output of eval_many (one point per parameter)",
        needed: ts.len(),
        got: out.len(),
    })
}

/// `eval_many` and `sample` of one `f64` curve type: the same kernels ([`many_into`]) for
/// the fixed-degree and the any-degree curve, each with its own documentation.
macro_rules! many_methods {
    ($curve:literal, impl[$($generics:tt)*] $ty:ty, $(#[$doc:meta])*) => {
        impl<$($generics)*> $ty {
            $(#[$doc])*
            pub fn eval_many(&self, ts: &[f64], out: &mut [PointN<f64, D>]) -> Result<()> {
                check_lengths(ts, out)?;
                many_into(self.points(), ts, out, |t| self.eval(&t));
                Ok(())
            }

            #[doc = concat!("The points `b(t)` at the parameters `ts`, as [`", $curve, "::eval_many`] computes them.")]
            pub fn sample(&self, ts: &[f64]) -> Vec<PointN<f64, D>> {
                let mut out = vec![PointN([0.0; D]); ts.len()];
                let Ok(()) = self.eval_many(ts, &mut out) else {
                    unreachable!("out has one point per parameter")
                };
                out
            }
        }
    };
}

many_methods!(
    "BezierN",
    impl[const D: usize, const N: usize] BezierN<PointN<f64, D>, N>,
    /// `b(t)` at every parameter of `ts`, written to `out[i]` for `ts[i]`: the same bits as
    /// [`BezierN::eval`] at each of them, vectorised across parameters with the widest
    /// vector instructions the CPU has (chosen at run time). No allocation up to degree 23;
    /// above, point by point. `out`
    /// of another length than `ts` is an [`Error::WrongCount`] (and nothing is written).
    ///
    /// ```
    /// use casteljau::{Cubic, Point2};
    /// let c = Cubic::new([Point2::new(0.0, 0.0), Point2::new(1.0, 2.0), Point2::new(3.0, 2.0), Point2::new(4.0, 0.0)]);
    /// let ts: Vec<f64> = (0..=100).map(|i| i as f64 / 100.0).collect();
    /// let mut out = vec![Point2::new(0.0, 0.0); ts.len()];
    /// c.eval_many(&ts, &mut out).unwrap();
    /// assert!(ts.iter().zip(&out).all(|(t, p)| *p == c.eval(t)));
    /// assert!(c.eval_many(&ts, &mut out[1..]).is_err());
    /// ```
);

many_methods!(
    "Bezier",
    impl[const D: usize] Bezier<PointN<f64, D>>,
    /// `b(t)` at every parameter of `ts`, written to `out[i]` for `ts[i]`: the same bits as
    /// [`Bezier::eval`] at each of them, vectorised across parameters as
    /// [`BezierN::eval_many`] (the same kernels). No allocation up to degree 23; above,
    /// point by point. `out` of another length than `ts` is an
    /// [`Error::WrongCount`] (and nothing is written).
    ///
    /// ```
    /// use casteljau::{Bezier, Point2};
    /// let c = Bezier::from_points((0..7).map(|i| Point2::new(i as f64, (i * i % 5) as f64))).unwrap();
    /// let ts = [0.0, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0, 1.5, -0.5, 0.3];
    /// let points = c.sample(&ts);
    /// assert!(ts.iter().zip(&points).all(|(t, p)| *p == c.eval(t)));
    /// ```
);
