//! De Casteljau's algorithm in `f64` with certified error bounds (its compensated form is
//! in the sibling module `compensated`).
//!
//! Each level computes `b_i ← fl(fl(s·b_i) + fl(t·b_{i+1}))` with `s = fl(1 − t)`: a
//! convex combination for `t ∈ [0, 1]`. Every path from an input `b_i` to the result passes
//! `n` levels, each with one product and one sum (two roundings), plus the rounding of `s`
//! on the paths through `s` when `1 − t` is not a float. Hence the a priori bound
//!
//! `|p̂(t) − p(t)| ≤ γ_k · Σ |b_i| |B_i^n(t)|`, `γ_k = k·u / (1 − k·u)`, `u = 2^−53`,
//!
//! with `k = 2n` when `1 − t` is exactly a float (every `t ∈ [1/2, 1]`, and `0`) and
//! `k = 3n` otherwise. It holds for every float `t` (with `|B_i^n(t)|` built from `|t|` and
//! `|1 − t|`) as long as nothing underflows. Underflow adds an absolute term: a product that
//! lands below `2^−1022` is off by up to half a subnormal, `η ≤ 2^−1075`, instead of a
//! relative `u` (a sum never underflows: the sum of two floats in the subnormal range is
//! exact). Every such `η` reaches the result through the later levels, each multiplying it by
//! at most `(|s| + |t|)(1 + u)²`; level `r` has `n − r + 1` nodes of two products each, so
//! the term is at most
//!
//! `U_n = 2^−1074 · Σ_{r=1}^{n} (n − r + 1) G^{n−r} (1 + u)^{2n} ≤ 2^−1074 · n(n+1)/2 · G^{n−1} · (1 + 10^−9)`,
//! `G = max(1, |s| + |t|)`,
//!
//! and the bounds returned here add it (see `docs/float-bounds.md` for every method's
//! bound). The tests check them exactly, in rationals, on random and subnormal curves.
//!
//! The running (a posteriori) bound follows the computation node by node.
//!
//! Every evaluator works on a copy of its inputs on the stack (no heap allocation up to
//! [`super::STACK_COEFFICIENTS`] coefficients).
//!
//! Every bound returned is an `f64` that is at least the exact bound: computed with
//! nonnegative terms, then enlarged by a factor covering its own rounding errors.

use super::eft::two_sum;
use super::scratch::{with_copy, with_scratch2};

/// The unit roundoff of `f64`, `u = 2^−53`.
pub const UNIT_ROUNDOFF: f64 = f64::EPSILON / 2.0;

/// The smallest positive subnormal, `2^−1074`: the absolute error an underflowing
/// operation can add.
pub(crate) const ETA: f64 = 5e-324;

/// `γ_k = k u / (1 − k u)`, rounded up; `+∞` when `k u ≥ 1`.
///
/// ```
/// use casteljau::float::{gamma, UNIT_ROUNDOFF};
/// assert!(gamma(6) > 6.0 * UNIT_ROUNDOFF && gamma(6) < 6.0000001 * UNIT_ROUNDOFF);
/// ```
#[inline]
pub fn gamma(k: usize) -> f64 {
    // the bounds ask for γ at every call: a division and four steps, more than a low-degree
    // triangle costs, so the common indices are looked up (the same bits, computed once)
    match GAMMAS.get(k) {
        Some(g) => *g,
        None => gamma_computed(k),
    }
}

/// [`gamma`] computed: `next_up(next_up(ku / next_down(1 − ku)))`.
pub(crate) const fn gamma_computed(k: usize) -> f64 {
    let ku = k as f64 * UNIT_ROUNDOFF; // exact below 2^53
    if ku >= 1.0 {
        return f64::INFINITY;
    }
    next_up(next_up(ku / next_down(1.0 - ku)))
}

/// `γ_k` for `k < 1024` (degrees up to 340 at `3n`), evaluated at compile time by
/// [`gamma_computed`] itself.
static GAMMAS: [f64; 1024] = {
    let mut table = [0.0; 1024];
    let mut k = 0;
    while k < table.len() {
        table[k] = gamma_computed(k);
        k += 1;
    }
    table
};

/// `γ_k = k u / (1 − k u)` exactly, for checking bounds in rationals.
///
/// ```
/// use casteljau::float::{gamma, gamma_exact};
/// assert!(casteljau::BigRational::from_float(gamma(6)).unwrap() >= gamma_exact(6));
/// ```
pub fn gamma_exact(k: usize) -> num_rational::BigRational {
    use num_rational::BigRational;
    let ku = BigRational::from_integer(k.into()) * BigRational::new(1.into(), num_bigint::BigInt::from(1u8) << 53);
    &ku / (BigRational::from_integer(1.into()) - &ku)
}

/// The next float above `x` (for finite `x`; `+∞` stays).
#[inline]
pub const fn next_up(x: f64) -> f64 {
    // the bounds' case first, one step up in the bits of a positive finite float: the
    // bounds chain a dozen of these, and the tests below cost as much as the step
    if x > 0.0 && x < f64::INFINITY {
        return f64::from_bits(x.to_bits() + 1);
    }
    if x.is_nan() || x == f64::INFINITY {
        return x;
    }
    if x == 0.0 {
        return f64::from_bits(1);
    }
    let bits = x.to_bits();
    f64::from_bits(if x > 0.0 { bits + 1 } else { bits - 1 })
}

/// The next float below `x`.
#[inline]
pub const fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

/// `(s, ρ)`: `s = fl(1 − t)` and its exact error `ρ = (1 − t) − s`.
#[inline]
pub(crate) fn one_minus(t: f64) -> (f64, f64) {
    two_sum(1.0, -t)
}

/// The index `k` of the a priori bound `γ_k` for degree `n` at `t`: `2n` when `1 − t` is a
/// float, else `3n`.
pub fn a_priori_index(n: usize, t: f64) -> usize {
    if one_minus(t).1 == 0.0 {
        2 * n
    } else {
        3 * n
    }
}

/// `γ` enlarged to cover the float evaluation of a bound with `ops` roundings on each path.
#[inline]
pub(crate) fn inflate(x: f64, ops: usize) -> f64 {
    next_up(x * (1.0 + 2.0 * gamma(ops + 2)))
}

/// The absolute term for underflow of a triangle of `n` levels whose nodes each add at most
/// `per_node` subnormals (`2^−1074` each) and whose levels grow an error by at most
/// `growth` (times `(1 + u)²`): `per_node · 2^−1074 · n(n+1)/2 · max(1, growth)^{n−1}`,
/// with a margin of `10^−9` covering the `(1 + u)` factors up to degree `10^6` and the
/// rounding of this very computation, rounded up. `+∞` when it overflows.
#[inline]
pub fn underflow_term(n: usize, per_node: f64, growth: f64) -> f64 {
    if n == 0 {
        return 0.0;
    }
    if let Some(term) = underflow_term_near_one(n, per_node, growth) {
        return term;
    }
    let g = growth.max(1.0);
    let nodes = (n as f64) * (n as f64 + 1.0) / 2.0;
    // a factor at least 1, then one product with 2^−1074: if that lands in the subnormal
    // range its rounding is absolute, and the step up covers it
    let factor = per_node * nodes * g.powi(n as i32 - 1) * (1.0 + 1e-9);
    next_up(factor * ETA)
}

/// [`underflow_term`] without its `powi` when the growth is at most `1 + 2^−48` (every
/// `t ∈ [0, 1]`: `|s| + |t|` is 1 within a few ulps), the count `K = per_node · n(n+1)/2`
/// a whole number up to `10^8` and `n ≤ 2^12`: the same bits. Why: the factor computed
/// there, `K · g^{n−1} · (1 + 10^−9)`, lies in `(K, K + 1/2)` (`g^{n−1} ≤ 1 + 2^−35` and
/// the roundings add less than `K · 2^−50`), and its product with `2^−1074` is subnormal, so
/// it rounds to `K · 2^−1074`, whose next float up is `(K + 1) · 2^−1074`. A unit test
/// compares both ways on every degree up to 600.
#[inline]
fn underflow_term_near_one(n: usize, per_node: f64, growth: f64) -> Option<f64> {
    const NEAR_ONE: f64 = 1.0 + 1.0 / (1u64 << 48) as f64;
    let nodes = (n as f64) * (n as f64 + 1.0) / 2.0;
    let count = per_node * nodes;
    // a whole number up to 10^8 converts to an integer and back unchanged (one instruction
    // each way, where `trunc` is a call without SSE4.1)
    let whole = (0.0..=1e8).contains(&count) && count as i64 as f64 == count;
    (growth <= NEAR_ONE && n <= 1 << 12 && whole).then(|| f64::from_bits(count as u64 + 1))
}

/// `a + b` rounded up (for nonnegative `a`, `b`): the exact sum lies between the rounded one
/// and its neighbours, so the next float up is at least the sum.
#[inline]
pub(crate) fn add_up(a: f64, b: f64) -> f64 {
    next_up(a + b)
}

/// `a · b` rounded up (for nonnegative `a`, `b`), subnormal results included.
#[inline]
pub(crate) fn mul_up(a: f64, b: f64) -> f64 {
    next_up(a * b)
}

/// `max(1, |s| + |t|)` rounded up: how much one level of de Casteljau's triangle may grow
/// an absolute error, for `s = fl(1 − t)`.
#[inline]
pub(crate) fn level_growth(t: f64) -> f64 {
    let s = 1.0 - t;
    add_up(s.abs(), t.abs()).max(1.0)
}

/// Plain de Casteljau on one coordinate's coefficients (at least one), the convex form
/// `fl(fl(s·a) + fl(t·b))` with `s = fl(1 − t)`.
///
/// ```
/// use casteljau::float::de_casteljau;
/// assert_eq!(de_casteljau(&[0.0, 1.0, 3.0], 0.5), 1.25);
/// ```
pub fn de_casteljau(b: &[f64], t: f64) -> f64 {
    with_copy(b, |buf| convex_triangle(buf, 1.0 - t, t))
}

/// de Casteljau's triangle in the convex form `fl(fl(s·a) + fl(t·b))`, in place: the value.
#[inline(always)]
pub(crate) fn convex_triangle(buf: &mut [f64], s: f64, t: f64) -> f64 {
    for len in (1..buf.len()).rev() {
        for i in 0..len {
            buf[i] = s * buf[i] + t * buf[i + 1];
        }
    }
    buf[0]
}

/// `Σ |b_i| |B_i^n(t)|` (the condition-number numerator), computed in floats and rounded so
/// that the result is at least the exact value (for the exact `1 − t`).
pub fn abs_bernstein_sum(b: &[f64], t: f64) -> f64 {
    with_copy(b, |buf| abs_bernstein_sum_in(buf, t))
}

/// [`abs_bernstein_sum`] of the coefficients in `buf` (their signs ignored), using `buf` as
/// the triangle's working space.
pub(crate) fn abs_bernstein_sum_in(buf: &mut [f64], t: f64) -> f64 {
    let n = buf.len() - 1;
    let (s, t) = abs_factors(t);
    for x in buf.iter_mut() {
        *x = x.abs();
    }
    abs_sum_rounded_up(convex_triangle(buf, s, t), n, s, t)
}

/// The factors `(s', |t|)` of the triangle of [`abs_bernstein_sum_in`]: `s' ≥ |1 − t|`.
#[inline(always)]
pub(crate) fn abs_factors(t: f64) -> (f64, f64) {
    let (s, rho) = one_minus(t);
    // |1 − t| ≤ |s| + |ρ|, and a float de Casteljau on nonnegative inputs is within γ_2n
    (next_up(s.abs() + rho.abs()), t.abs())
}

/// `Σ |b_i| |B_i^n(t)|` rounded up from the float triangle's `sum` on `|b_i|` with the
/// factors `s, t` of [`abs_factors`].
#[inline(always)]
pub(crate) fn abs_sum_rounded_up(sum: f64, n: usize, s: f64, t: f64) -> f64 {
    add_up(inflate(sum, 2 * n), underflow_term(n, 1.0, add_up(s, t)))
}

/// The a priori bound `γ_k Σ |b_i| |B_i^n(t)|` on the error of [`de_casteljau`] (`k` from
/// [`a_priori_index`]), as an `f64` at least the exact bound.
pub fn a_priori_bound(b: &[f64], t: f64) -> f64 {
    let n = b.len() - 1;
    if n == 0 {
        return 0.0;
    }
    add_up(
        mul_up(gamma(a_priori_index(n, t)), abs_bernstein_sum(b, t)),
        underflow_term(n, 1.0, level_growth(t)),
    )
}

/// Plain de Casteljau with a running error bound: `(p̂, e)` with `|p̂ − p(t)| ≤ e`.
///
/// For one node `c = fl(x + y)`, `x = fl(s a)`, `y = fl(t b)`, with `ŝ − (1 − t) = −ρ`
/// and the children's bounds `e_a`, `e_b`:
/// `e_c = u|c| + u|x| + u|y| + |s| e_a + |t| e_b + |ρ| (|a| + e_a) + 2^−1074`,
/// the last term for the two products' underflow (half a subnormal each). The bound itself
/// is computed in floats: its relative rounding is covered by a final factor, the underflow
/// of its own four products by two more subnormals per node.
/// Usually far tighter than the a priori bound, at about twice the cost.
pub fn de_casteljau_running(b: &[f64], t: f64) -> (f64, f64) {
    let n = b.len() - 1;
    let u = UNIT_ROUNDOFF;
    let (s, rho) = one_minus(t);
    let (abs_s, abs_t, abs_rho) = (s.abs(), t.abs(), rho.abs());
    let (value, err) = with_scratch2(n + 1, 0.0, |val, err| {
        val.copy_from_slice(b);
        for len in (1..=n).rev() {
            for i in 0..len {
                let (a, bb) = (val[i], val[i + 1]);
                let (x, y) = (s * a, t * bb);
                let c = x + y;
                err[i] = u * (c.abs() + x.abs() + y.abs())
                    + abs_s * err[i]
                    + abs_t * err[i + 1]
                    + abs_rho * (a.abs() + err[i])
                    + 4.0 * ETA;
                val[i] = c;
            }
        }
        (val[0], err[0])
    });
    (value, inflate(err, 8 * n))
}

/// The a priori bound for a rational curve evaluated in floats as de Casteljau on the
/// homogeneous points `(w_i b_i, w_i)` (the products `w_i b_i` rounded first), then one
/// division per coordinate: per coordinate `k`, with `e_N = γ_{K+1} Σ|w_i b_ik||B_i|`,
/// `e_D = γ_K Σ|w_i||B_i|` and the exact value `x`,
/// `|x̂_k − x_k| ≤ β + u(|x_k| + β)`, `β = (e_N + |x_k| e_D) / (|D̂| − 2e_D)`.
/// `coords[k]` holds coordinate `k` of every control point; `x[k]` is an `f64` within one
/// ulp of the exact value. `+∞` when the denominator may vanish (`|D̂| ≤ 2e_D`).
pub fn rational_a_priori_bound(coords: &[Vec<f64>], weights: &[f64], t: f64, x: &[f64]) -> Vec<f64> {
    let n = weights.len() - 1;
    let k = a_priori_index(n, t);
    let u = UNIT_ROUNDOFF;
    // underflow: the triangles' terms, and for the numerator the products w_i b_i (half a
    // subnormal each, through weights summing to at most growth^n)
    let growth = level_growth(t);
    let under = underflow_term(n, 1.0, growth);
    let products_under = mul_up(ETA, growth.powi(n as i32) * (1.0 + 1e-9));
    let e_d = add_up(mul_up(gamma(k), abs_bernstein_sum(weights, t)), under);
    let d = de_casteljau(weights, t).abs();
    let room = d - 2.0 * e_d * (1.0 + 4.0 * u);
    coords
        .iter()
        .zip(x)
        .map(|(c, xk)| {
            if room <= 0.0 {
                return f64::INFINITY;
            }
            let products: Vec<f64> = c.iter().zip(weights).map(|(b, w)| b * w).collect();
            let e_n = next_up(gamma(k + 1) * abs_bernstein_sum(&products, t) * (1.0 + 2.0 * u));
            let e_n = add_up(add_up(e_n, under), products_under);
            let xa = next_up(xk.abs() * (1.0 + 2.0 * u));
            let beta = (e_n + xa * e_d) / room;
            // the division may underflow too: half a subnormal, counted as one
            add_up(inflate(beta + u * (xa + beta), 8), ETA)
        })
        .collect()
}

/// The a priori bound `γ_{K_u + K_v} Σ_i Σ_j |b_ij| |B_i^m(u)| |B_j^n(v)|` for a tensor-product
/// surface evaluated by de Casteljau in one direction, then the other (either order);
/// `net[i][j]` is one coordinate of the control point `b_ij`.
pub fn surface_a_priori_bound(net: &[Vec<f64>], u: f64, v: f64) -> f64 {
    let (m, n) = (net.len() - 1, net[0].len() - 1);
    let columns: Vec<f64> = (0..=n)
        .map(|j| abs_bernstein_sum(&net.iter().map(|row| row[j]).collect::<Vec<_>>(), u))
        .collect();
    let sum = abs_bernstein_sum(&columns, v);
    // underflow in either order: each direction's term carried through the other's levels
    let (gu, gv) = (level_growth(u), level_growth(v));
    let carry = gu.powi(m as i32).max(gv.powi(n as i32)) * (1.0 + 1e-9);
    let under = mul_up(add_up(underflow_term(m, 1.0, gu), underflow_term(n, 1.0, gv)), carry);
    add_up(mul_up(gamma(a_priori_index(m, u) + a_priori_index(n, v)), sum), under)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_gamma_table_is_gamma() {
        for k in 0..2048 {
            assert_eq!(gamma(k).to_bits(), gamma_computed(k).to_bits(), "γ_{k}");
        }
        assert_eq!(gamma(1 << 60), f64::INFINITY);
    }

    /// The shortcut of `underflow_term` gives the bits of the full computation.
    #[test]
    fn the_underflow_shortcut_is_the_full_term() {
        fn full(n: usize, per_node: f64, growth: f64) -> f64 {
            let g = growth.max(1.0);
            let nodes = (n as f64) * (n as f64 + 1.0) / 2.0;
            next_up(per_node * nodes * g.powi(n as i32 - 1) * (1.0 + 1e-9) * ETA)
        }
        let mut near_one = vec![0.5, 1.0 - UNIT_ROUNDOFF, 1.0, 1.0 + 1.0 / (1u64 << 48) as f64];
        near_one.extend((1..=4).map(|k| 1.0 + k as f64 * f64::EPSILON));
        near_one.extend([0.0, 0.3, 0.5, 0.7, 1e-310, 1.0].iter().map(|t| level_growth(*t)));
        for n in (1..=600).chain([1000, 2000, 4096]) {
            for per_node in [1.0, 3.0, 0.5, 2.5] {
                for &g in &near_one {
                    let term = underflow_term(n, per_node, g);
                    assert_eq!(term.to_bits(), full(n, per_node, g).to_bits(), "n {n}, {per_node}, {g}");
                }
            }
        }
        assert_eq!(underflow_term(3, 1.0, 2.0), full(3, 1.0, 2.0));
    }

    #[test]
    fn gamma_is_rounded_up() {
        assert_eq!(gamma(0), next_up(next_up(0.0)));
        assert!(gamma(1) > UNIT_ROUNDOFF);
        assert_eq!(gamma(usize::MAX), f64::INFINITY);
        assert_eq!(a_priori_index(3, 0.5), 6);
        assert_eq!(a_priori_index(3, 0.1), 9);
        assert_eq!(a_priori_index(3, 0.0), 6);
    }
}
