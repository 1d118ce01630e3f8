//! De Casteljau's algorithm in `f64` with certified error bounds, and its compensated form.
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
//! The running (a posteriori) bound follows the computation node by node; the compensated
//! algorithm (Jiang, Li, Cheng, Su 2010) carries the rounding error of every operation,
//! obtained by [`two_sum`] and [`two_product`], through a second de Casteljau triangle and
//! adds it back: `|res − p| ≤ u|p| + 2γ_{3n}² Σ |b_i| |B_i^n(t)|`, as accurate as plain
//! de Casteljau in twice the working precision, then rounded once.
//!
//! Every bound returned is an `f64` that is at least the exact bound: computed with
//! nonnegative terms, then enlarged by a factor covering its own rounding errors.

use super::eft::{two_product, two_sum};

/// The unit roundoff of `f64`, `u = 2^−53`.
pub const UNIT_ROUNDOFF: f64 = f64::EPSILON / 2.0;

/// The smallest positive subnormal, `2^−1074`: the absolute error an underflowing
/// operation can add.
const ETA: f64 = 5e-324;

/// `γ_k = k u / (1 − k u)`, rounded up; `+∞` when `k u ≥ 1`.
///
/// ```
/// use casteljau::float::{gamma, UNIT_ROUNDOFF};
/// assert!(gamma(6) > 6.0 * UNIT_ROUNDOFF && gamma(6) < 6.0000001 * UNIT_ROUNDOFF);
/// ```
pub fn gamma(k: usize) -> f64 {
    let ku = k as f64 * UNIT_ROUNDOFF; // exact below 2^53
    if ku >= 1.0 {
        return f64::INFINITY;
    }
    next_up(next_up(ku / next_down(1.0 - ku)))
}

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
pub fn next_up(x: f64) -> f64 {
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
pub fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

/// `(s, ρ)`: `s = fl(1 − t)` and its exact error `ρ = (1 − t) − s`.
fn one_minus(t: f64) -> (f64, f64) {
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
fn inflate(x: f64, ops: usize) -> f64 {
    next_up(x * (1.0 + 2.0 * gamma(ops + 2)))
}

/// The absolute term for underflow of a triangle of `n` levels whose nodes each add at most
/// `per_node` subnormals (`2^−1074` each) and whose levels grow an error by at most
/// `growth` (times `(1 + u)²`): `per_node · 2^−1074 · n(n+1)/2 · max(1, growth)^{n−1}`,
/// with a margin of `10^−9` covering the `(1 + u)` factors up to degree `10^6` and the
/// rounding of this very computation, rounded up. `+∞` when it overflows.
pub fn underflow_term(n: usize, per_node: f64, growth: f64) -> f64 {
    if n == 0 {
        return 0.0;
    }
    let g = growth.max(1.0);
    let nodes = (n as f64) * (n as f64 + 1.0) / 2.0;
    // a factor at least 1, then one product with 2^−1074: if that lands in the subnormal
    // range its rounding is absolute, and the step up covers it
    let factor = per_node * nodes * g.powi(n as i32 - 1) * (1.0 + 1e-9);
    next_up(factor * ETA)
}

/// `a + b` rounded up (for nonnegative `a`, `b`): the exact sum lies between the rounded one
/// and its neighbours, so the next float up is at least the sum.
pub(crate) fn add_up(a: f64, b: f64) -> f64 {
    next_up(a + b)
}

/// `a · b` rounded up (for nonnegative `a`, `b`), subnormal results included.
pub(crate) fn mul_up(a: f64, b: f64) -> f64 {
    next_up(a * b)
}

/// `max(1, |s| + |t|)` rounded up: how much one level of de Casteljau's triangle may grow
/// an absolute error, for `s = fl(1 − t)`.
fn level_growth(t: f64) -> f64 {
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
    let s = 1.0 - t;
    let mut buf = b.to_vec();
    let n = b.len() - 1;
    for r in 1..=n {
        for i in 0..=n - r {
            buf[i] = s * buf[i] + t * buf[i + 1];
        }
    }
    buf[0]
}

/// `Σ |b_i| |B_i^n(t)|` (the condition-number numerator), computed in floats and rounded so
/// that the result is at least the exact value (for the exact `1 − t`).
pub fn abs_bernstein_sum(b: &[f64], t: f64) -> f64 {
    let n = b.len() - 1;
    let (s, rho) = one_minus(t);
    // |1 − t| ≤ |s| + |ρ|, and a float de Casteljau on nonnegative inputs is within γ_2n
    let (s, t) = (next_up(s.abs() + rho.abs()), t.abs());
    let mut buf: Vec<f64> = b.iter().map(|x| x.abs()).collect();
    for r in 1..=n {
        for i in 0..=n - r {
            buf[i] = s * buf[i] + t * buf[i + 1];
        }
    }
    add_up(inflate(buf[0], 2 * n), underflow_term(n, 1.0, add_up(s, t)))
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
    let mut val = b.to_vec();
    let mut err = vec![0.0; n + 1];
    for r in 1..=n {
        for i in 0..=n - r {
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
    (val[0], inflate(err[0], 8 * n))
}

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
pub fn compensated_de_casteljau(b: &[f64], t: f64) -> (f64, f64) {
    let (hi, lo) = compensated_parts(b, &vec![0.0; b.len()], t);
    let res = hi + lo;
    let n = b.len() - 1;
    (res, compensated_bound(res, b, 0.0, t, compensated_underflow(n, t)))
}

/// The underflow term of compensated de Casteljau: per node, the two TwoProduct errors may
/// each be rounded (half a subnormal) and the three products of the low part may underflow
/// (half a subnormal each): 2.5 subnormals, counted as 3 to cover the second-order effect
/// of the low triangle's own roundings on them.
fn compensated_underflow(n: usize, t: f64) -> f64 {
    underflow_term(n, 3.0, level_growth(t))
}

/// The bound of [`compensated_de_casteljau`] for a result `res`, plus an input term
/// `extra · Σ|b_i||B_i|` (second-order input errors) and the absolute underflow term `under`.
fn compensated_bound(res: f64, b: &[f64], extra: f64, t: f64, under: f64) -> f64 {
    let n = b.len() - 1;
    if n == 0 {
        return 0.0;
    }
    let u = UNIT_ROUNDOFF;
    let g = gamma(3 * n);
    let second = add_up(mul_up(next_up(2.0 * g * g + extra), abs_bernstein_sum(b, t)), under);
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
        mul_up(next_up(2.0 * g * g), abs_bernstein_sum(b, t)),
        compensated_underflow(n, t),
    );
    inflate(add_up(mul_up(UNIT_ROUNDOFF, p.abs()), second), 4)
}

/// The two parts `(hi, lo)` of compensated de Casteljau on inputs `b_i + d_i` (`d_i` the
/// low parts, exact corrections of the inputs, usually 0): the result is `fl(hi + lo)`.
fn compensated_parts(b: &[f64], d: &[f64], t: f64) -> (f64, f64) {
    let n = b.len() - 1;
    let (s, rho) = one_minus(t);
    let mut hi = b.to_vec();
    let mut lo = d.to_vec();
    for r in 1..=n {
        for i in 0..=n - r {
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
    let (hi, lo): (Vec<f64>, Vec<f64>) = b.windows(2).map(|w| two_sum(w[1], -w[0])).unzip();
    let (h, l) = compensated_parts(&hi, &lo, t);
    let nf = n as f64;
    let (p, e) = two_product(nf, h);
    let res = p + (e + nf * l);
    // the low parts enter one more first-order rounding each (|lo_i| ≤ u|hi_i|): a term
    // u γ_3(n−1) Σ|Δb_i||B_i| on top of the compensated bound, then the factor n
    let m = n - 1;
    let extra = 2.0 * UNIT_ROUNDOFF * gamma(3 * m + 3);
    let scaled: Vec<f64> = hi.iter().map(|x| x * nf).collect();
    // underflow: the low triangle's term times n, then TwoProduct(n, h) and n·l (half a
    // subnormal each), and the scaled coefficients' own rounding: two subnormals more
    let under = add_up(mul_up(nf, compensated_underflow(m, t)), 2.0 * ETA);
    (
        res,
        compensated_bound(res, &scaled, extra + 4.0 * UNIT_ROUNDOFF * UNIT_ROUNDOFF, t, under),
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
    let (h, l): (Vec<f64>, Vec<f64>) = net
        .iter()
        .map(|row| compensated_parts(row, &vec![0.0; row.len()], v))
        .unzip();
    let (hi, lo) = compensated_parts(&h, &l, u);
    let res = hi + lo;
    let n = net[0].len() - 1;
    let rows: Vec<f64> = net.iter().map(|row| abs_bernstein_sum(row, v)).collect();
    let t_sum = abs_bernstein_sum(&rows, u);
    let (gn, gm) = (gamma(3 * n), gamma(3 * m));
    // underflow: each row's term carried through the column (growth^m), and the column's own
    let rows_under = mul_up(
        compensated_underflow(n, v),
        level_growth(u).powi(m as i32) * (1.0 + 1e-9),
    );
    let under = add_up(rows_under, compensated_underflow(m, u));
    let second = next_up(2.0 * gn * gn * t_sum)
        + next_up(2.0 * gm * gm * abs_bernstein_sum(&h, u))
        + next_up(2.0 * gamma(3 * m + 3) * abs_bernstein_sum(&l, u));
    let second = add_up(next_up(second), under);
    (
        res,
        inflate((UNIT_ROUNDOFF * res.abs() + second) / (1.0 - UNIT_ROUNDOFF), 6),
    )
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
    fn gamma_is_rounded_up() {
        assert_eq!(gamma(0), next_up(next_up(0.0)));
        assert!(gamma(1) > UNIT_ROUNDOFF);
        assert_eq!(gamma(usize::MAX), f64::INFINITY);
        assert_eq!(a_priori_index(3, 0.5), 6);
        assert_eq!(a_priori_index(3, 0.1), 9);
        assert_eq!(a_priori_index(3, 0.0), 6);
    }

    #[test]
    fn running_and_compensated_agree_on_easy_values() {
        let b = [0.0, 1.0, 3.0];
        assert_eq!(de_casteljau_running(&b, 0.5).0, 1.25);
        assert_eq!(compensated_de_casteljau(&b, 0.5).0, 1.25);
        assert_eq!(compensated_derivative(&b, 0.5).0, 3.0);
        assert_eq!(compensated_derivative(&[2.0], 0.5), (0.0, 0.0));
        assert_eq!(a_priori_bound(&[2.0], 0.3), 0.0);
    }
}
