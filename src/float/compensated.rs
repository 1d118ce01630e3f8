//! Compensated de Casteljau (Jiang, Li, Cheng, Su 2010): the rounding error of every
//! operation, obtained by [`two_sum`] and TwoProduct, is carried through a second
//! de Casteljau triangle and added back: `|res − p| ≤ u|p| + 2γ_{3n}² Σ |b_i| |B_i^n(t)|`, as
//! accurate as plain de Casteljau in twice the working precision, then rounded once.
//!
//! The products of a level are all by `s = fl(1 − t)` or by `t`, so both are prepared once
//! ([`Factor`]: split for Dekker's product on a target without FMA) and each node costs its
//! partner's split and two products' errors. The loop also checks that every value stays in
//! the range where that error is exact; if one left it (values near overflow or underflow,
//! NaN), the triangle is run again with [`two_product`], which handles every input. Both
//! runs give the same bits; the first is just faster. For `t ∈ [0, 1]` and degrees 1 to 63
//! a third form runs first, two nodes per step with no check per node (the sibling module
//! `compensated_pairs`, which proves when that is exact), again with the same bits. Working
//! copies are on the stack up to [`super::STACK_COEFFICIENTS`] coefficients: no heap
//! allocation.

use super::casteljau::{
    abs_bernstein_sum_in, abs_factors, abs_sum_rounded_up, add_up, convex_triangle, gamma, inflate, level_growth,
    mul_up, next_up, one_minus, underflow_term, ETA, UNIT_ROUNDOFF,
};
use super::compensated_pairs::{compensated_in_unit_interval, compensated_in_unit_interval_by};
use super::eft::{two_product, two_sum, ExactRange, Factor};
use super::scratch::{with_copy, with_scratch, with_scratch2};

/// Compensated de Casteljau (Jiang, Li, Cheng, Su 2010): `(res, e)` with `|res − p(t)| ≤ e`,
/// where `e` is `u|p| + 2γ_{3n}² Σ|b_i||B_i^n(t)|` (with `|p| ≤ (|res| + …)/(1 − u)`).
///
/// ```
/// use casteljau::float::{compensated_de_casteljau, de_casteljau};
/// // (t − 3/4)^3 in Bernstein form near its triple root
/// let b = [-0.421875, 0.140625, -0.046875, 0.015625];
/// let t = 0.7500001;
/// let exact = (t - 0.75f64).powi(3); // t − 3/4 is exact here; the cube is within 2 ulps
/// let (res, bound) = compensated_de_casteljau(&b, t);
/// assert!((res - exact).abs() < 1e-13 * exact && bound < 1e-30); // 13 digits
/// assert!((de_casteljau(&b, t) - exact).abs() > 100.0 * exact); // none
/// ```
///
/// TwoProduct is by a fused multiply-add where the CPU has the instruction, chosen at run
/// time for `t ∈ [0, 1]` (else as the build's target has it, [`super::TWO_PRODUCT_METHOD`]):
/// the same bits either way ([`compensated_de_casteljau_by`]).
#[inline]
pub fn compensated_de_casteljau(b: &[f64], t: f64) -> (f64, f64) {
    if let Some(result) = compensated_in_unit_interval(b, t) {
        return result;
    }
    compensated_checked(b, t)
}

/// [`compensated_de_casteljau`] with TwoProduct by the formulas of a fused multiply-add
/// (`fma`) or by Dekker's product, whatever this CPU has: the same value, bit for bit, as
/// [`compensated_de_casteljau`] for every input, and the same bound by the method it takes
/// on this CPU (by the other, where its fast path declines a triangle of values near
/// underflow, the checked triangle's bound, also valid). Without the instruction, each
/// fused multiply-add is a call to the C library's correctly rounded `fma` (slow): this is
/// for checking that the methods agree and for measuring them.
///
/// ```
/// use casteljau::float::{compensated_de_casteljau, compensated_de_casteljau_by};
/// let b = [-0.421875, 0.140625, -0.046875, 0.015625];
/// let (fma, dekker) = (compensated_de_casteljau_by(&b, 0.7500001, true), compensated_de_casteljau_by(&b, 0.7500001, false));
/// assert_eq!(fma.0.to_bits(), dekker.0.to_bits());
/// assert_eq!(fma.0.to_bits(), compensated_de_casteljau(&b, 0.7500001).0.to_bits());
/// ```
pub fn compensated_de_casteljau_by(b: &[f64], t: f64, fma: bool) -> (f64, f64) {
    let fast = if fma {
        compensated_in_unit_interval_by::<true>(b, t)
    } else {
        compensated_in_unit_interval_by::<false>(b, t)
    };
    fast.unwrap_or_else(|| compensated_checked(b, t))
}

/// [`compensated_de_casteljau`] by the node-by-node triangle that checks each value's range.
fn compensated_checked(b: &[f64], t: f64) -> (f64, f64) {
    let n = b.len() - 1;
    // low degrees on arrays of constant length: unrolled, in registers (the same steps)
    let (hi, lo, abs_triangle) = match b.len() {
        2 => compensated_with_abs(&mut [0.0; 2], &mut [0.0; 2], &mut [0.0; 2], b, t),
        3 => compensated_with_abs(&mut [0.0; 3], &mut [0.0; 3], &mut [0.0; 3], b, t),
        4 => compensated_with_abs(&mut [0.0; 4], &mut [0.0; 4], &mut [0.0; 4], b, t),
        5 => compensated_with_abs(&mut [0.0; 5], &mut [0.0; 5], &mut [0.0; 5], b, t),
        len => with_scratch2(len, 0.0, |hi, lo| {
            with_scratch(len, 0.0, |abs| compensated_with_abs(hi, lo, abs, b, t))
        }),
    };
    let res = hi + lo;
    if n == 0 {
        return (res, 0.0);
    }
    let (s_abs, t_abs) = abs_factors(t);
    let abs_sum = abs_sum_rounded_up(abs_triangle, n, s_abs, t_abs);
    (
        res,
        compensated_bound(res, n, abs_sum, 0.0, compensated_underflow(n, t)),
    )
}

/// The compensated triangle of `b` in `hi`, `lo` (run again by [`two_product`] when a value
/// left the fast triangle's range) and the float triangle of [`abs_bernstein_sum_in`] on
/// `|b_i|` in `abs`, all as long as `b`: `(hi, lo, the |b_i| triangle's value)`.
#[inline(always)]
fn compensated_with_abs(hi: &mut [f64], lo: &mut [f64], abs: &mut [f64], b: &[f64], t: f64) -> (f64, f64, f64) {
    let fill = |hi: &mut [f64], lo: &mut [f64]| {
        hi.copy_from_slice(b);
        lo.fill(0.0);
    };
    fill(hi, lo);
    let (hi_part, lo_part) = match compensated_triangle(hi, lo, t) {
        Some(parts) => parts,
        None => {
            fill(hi, lo);
            compensated_triangle_any(hi, lo, t)
        }
    };
    for (x, y) in abs.iter_mut().zip(b) {
        *x = y.abs();
    }
    let (s_abs, t_abs) = abs_factors(t);
    (hi_part, lo_part, convex_triangle(abs, s_abs, t_abs))
}

/// The underflow term of compensated de Casteljau: per node, the two TwoProduct errors may
/// each be rounded (half a subnormal) and the three products of the low part may underflow
/// (half a subnormal each): 2.5 subnormals, counted as 3 to cover the second-order effect
/// of the low triangle's own roundings on them.
fn compensated_underflow(n: usize, t: f64) -> f64 {
    underflow_term(n, 3.0, level_growth(t))
}

/// The bound of [`compensated_de_casteljau`] for a result `res` of degree `n`, given
/// `abs_sum = Σ|b_i||B_i|` (from [`abs_bernstein_sum_in`]), plus an input term
/// `extra · abs_sum` (second-order input errors) and the absolute underflow term `under`.
fn compensated_bound(res: f64, n: usize, abs_sum: f64, extra: f64, under: f64) -> f64 {
    let u = UNIT_ROUNDOFF;
    let g = gamma(3 * n);
    let second = add_up(mul_up(next_up(2.0 * g * g + extra), abs_sum), under);
    // |res − p| ≤ u|p| + c  and  |p| ≤ |res| + |res − p|  give  |res − p| ≤ (u|res| + c)/(1 − u)
    inflate(add_up(u * res.abs(), second) / (1.0 - u), 4)
}

/// The a priori bound of compensated de Casteljau given (a float near) the exact value `p`:
/// `u|p| + 2γ_{3n}² Σ|b_i||B_i| + U`, for judging another program's compensated evaluation.
pub fn compensated_a_priori_bound(b: &[f64], t: f64, p: f64) -> f64 {
    let n = b.len() - 1;
    if n == 0 {
        return 0.0;
    }
    let g = gamma(3 * n);
    let second = add_up(
        mul_up(next_up(2.0 * g * g), with_copy(b, |buf| abs_bernstein_sum_in(buf, t))),
        compensated_underflow(n, t),
    );
    inflate(add_up(mul_up(UNIT_ROUNDOFF, p.abs()), second), 4)
}

/// The two parts `(hi, lo)` of compensated de Casteljau on `len` inputs `b_i + d_i` that
/// `fill(b, d)` writes (`d_i` the low parts, exact corrections of the inputs, usually 0):
/// the result is `fl(hi + lo)`. `fill` runs a second time when the fast triangle met a
/// value out of its range.
#[inline]
fn compensated_parts(len: usize, fill: impl Fn(&mut [f64], &mut [f64]), t: f64) -> (f64, f64) {
    with_scratch2(len, 0.0, |hi, lo| {
        fill(hi, lo);
        if let Some(parts) = compensated_triangle(hi, lo, t) {
            return parts;
        }
        fill(hi, lo);
        compensated_triangle_any(hi, lo, t)
    })
}

/// The compensated triangle in place, each product's error by a prepared [`Factor`];
/// `None` when a value left the range where those errors are exact (the buffers are then
/// spent).
#[inline(always)]
fn compensated_triangle(hi: &mut [f64], lo: &mut [f64], t: f64) -> Option<(f64, f64)> {
    let (s, rho) = one_minus(t);
    let (by_s, by_t) = (Factor::new(s), Factor::new(t));
    let range = ExactRange::agreeing(&[by_s, by_t]);
    let mut exact = true;
    for len in (1..hi.len()).rev() {
        // each value is split once, for its product by t (node i − 1) and by s (node i)
        let mut a = hi[0];
        let mut a_halves = Factor::halves(a);
        exact &= range.contains(a);
        for i in 0..len {
            let b = hi[i + 1];
            let b_halves = Factor::halves(b);
            exact &= range.contains(b);
            let p1 = s * a;
            let e1 = by_s.error(a, a_halves, p1);
            let p2 = t * b;
            let e2 = by_t.error(b, b_halves, p2);
            let (sum, e3) = two_sum(p1, p2);
            let w = e1 + e2 + e3 + rho * a;
            lo[i] = w + s * lo[i] + t * lo[i + 1];
            hi[i] = sum;
            (a, a_halves) = (b, b_halves);
        }
    }
    exact.then(|| (hi[0], lo[0]))
}

/// The compensated triangle in place by [`two_product`], for every input.
#[cold]
fn compensated_triangle_any(hi: &mut [f64], lo: &mut [f64], t: f64) -> (f64, f64) {
    let (s, rho) = one_minus(t);
    for len in (1..hi.len()).rev() {
        for i in 0..len {
            let (p1, e1) = two_product(s, hi[i]);
            let (p2, e2) = two_product(t, hi[i + 1]);
            let (sum, e3) = two_sum(p1, p2);
            let w = e1 + e2 + e3 + rho * hi[i];
            lo[i] = w + s * lo[i] + t * lo[i + 1];
            hi[i] = sum;
        }
    }
    (hi[0], lo[0])
}

/// The derivative `p'(t) = n Σ Δb_i B_i^{n−1}(t)` by compensated de Casteljau on the exact
/// differences (each `Δb_i` split by [`two_sum`] into a float and its error): `(res, e)`
/// with `|res − p'(t)| ≤ e`. A curve of degree 0 has derivative 0.
pub fn compensated_derivative(b: &[f64], t: f64) -> (f64, f64) {
    let n = b.len() - 1;
    if n == 0 {
        return (0.0, 0.0);
    }
    let differences = |hi: &mut [f64], lo: &mut [f64]| {
        for (i, w) in b.windows(2).enumerate() {
            (hi[i], lo[i]) = two_sum(w[1], -w[0]);
        }
    };
    let (h, l) = compensated_parts(n, differences, t);
    let nf = n as f64;
    let (p, e) = two_product(nf, h);
    let res = p + (e + nf * l);
    // the low parts enter one more first-order rounding each (|lo_i| ≤ u|hi_i|): a term
    // u γ_3(n−1) Σ|Δb_i||B_i| on top of the compensated bound, then the factor n
    let m = n - 1;
    let extra = 2.0 * UNIT_ROUNDOFF * gamma(3 * m + 3);
    // (a line's derivative too is rounded once, in `res`: its bound is u|res|/(1 − u) and
    // more, not 0)
    let abs_sum = with_scratch(n, 0.0, |scaled| {
        for (x, w) in scaled.iter_mut().zip(b.windows(2)) {
            *x = two_sum(w[1], -w[0]).0 * nf;
        }
        abs_bernstein_sum_in(scaled, t)
    });
    // underflow: the low triangle's term times n, then TwoProduct(n, h) and n·l (half a
    // subnormal each), and the scaled coefficients' own rounding: two subnormals more
    let under = add_up(mul_up(nf, compensated_underflow(m, t)), 2.0 * ETA);
    (
        res,
        compensated_bound(res, m, abs_sum, extra + 4.0 * UNIT_ROUNDOFF * UNIT_ROUNDOFF, under),
    )
}

/// A tensor-product surface by compensated de Casteljau: each row `net[i]` in `v`, giving a
/// double-double value `h_i + l_i` per row, then the column `(h_i, l_i)` in `u`, rounded once at
/// the end. `net[i][j]` is one coordinate of `b_ij`. Returns `(res, e)` with `|res − s(u, v)| ≤ e`:
///
/// `e ≥ (u|res| + 2γ_{3n}² T + 2γ_{3m}² Σ|h_i||B_i^m(u)| + 2γ_{3m+3} Σ|l_i||B_i^m(u)|) / (1 − u)`,
/// `T = Σ_i Σ_j |b_ij| |B_i^m(u)| |B_j^n(v)|`: the rows' compensated errors carried through the
/// column exactly, the column's own compensated error, and the rounding of the rows' low parts
/// on their way through the column's `m` levels.
///
/// ```
/// use casteljau::float::compensated_surface;
/// // s(u, v) = (u − 1/4)^2 (v − 1/4)^2, a double root in each direction near the point
/// let c = [1.0 / 16.0, -3.0 / 16.0, 9.0 / 16.0];
/// let net: Vec<Vec<f64>> = c.iter().map(|a| c.iter().map(|b| a * b).collect()).collect();
/// let d = 0.3 - 0.25; // exact
/// let exact = d * d * d * d; // within 2 ulps
/// let (res, e) = compensated_surface(&net, 0.3, 0.3);
/// assert!((res - exact).abs() < 1e-15 * exact && e < 1e-20);
/// ```
pub fn compensated_surface(net: &[Vec<f64>], u: f64, v: f64) -> (f64, f64) {
    let m = net.len() - 1;
    let n = net[0].len() - 1;
    let row_parts = |row: &[f64]| {
        let fill = |hi: &mut [f64], lo: &mut [f64]| {
            hi.copy_from_slice(row);
            lo.fill(0.0);
        };
        compensated_parts(row.len(), fill, v)
    };
    let column = |h: &mut [f64], l: &mut [f64]| {
        for (row, (h, l)) in net.iter().zip(h.iter_mut().zip(l.iter_mut())) {
            (*h, *l) = row_parts(row);
        }
    };
    let (hi, lo, h_sum, l_sum) = with_scratch2(m + 1, 0.0, |h, l| {
        column(h, l);
        let (hi, lo) = compensated_parts(
            m + 1,
            |hi, lo| {
                hi.copy_from_slice(h);
                lo.copy_from_slice(l);
            },
            u,
        );
        (hi, lo, abs_bernstein_sum_in(h, u), abs_bernstein_sum_in(l, u))
    });
    let res = hi + lo;
    let t_sum = with_scratch(m + 1, 0.0, |rows| {
        for (x, row) in rows.iter_mut().zip(net) {
            *x = with_copy(row, |buf| abs_bernstein_sum_in(buf, v));
        }
        abs_bernstein_sum_in(rows, u)
    });
    let (gn, gm) = (gamma(3 * n), gamma(3 * m));
    // underflow: each row's term carried through the column (growth^m), and the column's own
    let rows_under = mul_up(
        compensated_underflow(n, v),
        level_growth(u).powi(m as i32) * (1.0 + 1e-9),
    );
    let under = add_up(rows_under, compensated_underflow(m, u));
    let second =
        next_up(2.0 * gn * gn * t_sum) + next_up(2.0 * gm * gm * h_sum) + next_up(2.0 * gamma(3 * m + 3) * l_sum);
    let second = add_up(next_up(second), under);
    (
        res,
        inflate((UNIT_ROUNDOFF * res.abs() + second) / (1.0 - UNIT_ROUNDOFF), 6),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::float::{a_priori_bound, de_casteljau_running};

    #[test]
    fn running_and_compensated_agree_on_easy_values() {
        let b = [0.0, 1.0, 3.0];
        assert_eq!(de_casteljau_running(&b, 0.5).0, 1.25);
        assert_eq!(compensated_de_casteljau(&b, 0.5).0, 1.25);
        assert_eq!(compensated_derivative(&b, 0.5).0, 3.0);
        assert_eq!(compensated_derivative(&[2.0], 0.5), (0.0, 0.0));
        assert_eq!(a_priori_bound(&[2.0], 0.3), 0.0);
    }

    /// A line's derivative `b_1 − b_0` is rounded once: its bound is not 0 (it was).
    #[test]
    fn a_lines_derivative_has_a_sound_bound() {
        use crate::float::error_at_most;
        use crate::scalar::Scalar;
        use num_rational::BigRational;
        let b = [0.1, 1e20];
        let (res, e) = compensated_derivative(&b, 0.3);
        let exact = BigRational::from_f64(1e20).unwrap() - BigRational::from_f64(0.1).unwrap();
        assert!(e > 0.0 && error_at_most(res, &exact, e), "{res} ± {e}");
    }
}
