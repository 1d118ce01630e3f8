//! Other programs' ways to evaluate a Bézier polynomial in `f64`, and an a priori bound for
//! each: the lerp form of de Casteljau, Horner's rule in the power basis and the Bernstein
//! sum. The convex form and compensated de Casteljau are in the sibling module. Every bound
//! is `γ_k` times a sum of absolute values plus an absolute term for underflow; the
//! derivations are in `docs/float-bounds.md` and the tests check each bound exactly.

use super::casteljau::{abs_bernstein_sum, add_up, gamma, mul_up, next_up, underflow_term};
use super::scratch::{with_copy, with_mapped};
use super::ulp::{round_scaled, scale_pow2_up};
use num_bigint::{BigInt, BigUint, Sign};
use num_traits::{One, Zero};

/// De Casteljau in the lerp form `a + t·(b − a)` (three roundings per node).
///
/// ```
/// use casteljau::float::lerp_de_casteljau;
/// assert_eq!(lerp_de_casteljau(&[0.0, 1.0, 3.0], 0.5), 1.25);
/// ```
pub fn lerp_de_casteljau(b: &[f64], t: f64) -> f64 {
    with_copy(b, |buf| {
        for len in (1..buf.len()).rev() {
            for i in 0..len {
                buf[i] += t * (buf[i + 1] - buf[i]);
            }
        }
        buf[0]
    })
}

/// The a priori bound of [`lerp_de_casteljau`]: `γ_{4n} Σ|b_i| L_i(t) + U`, where `L_i` are
/// the weights of de Casteljau's triangle with `(|1 − t| + |t|, |t|)` in place of
/// `(1 − t, t)` (the product `t·(b − a)` errs relative to `|a| + |b|`, not to the convex
/// combination), and `U` the underflow term with growth `|1 − t| + 2|t|`.
pub fn lerp_bound(b: &[f64], t: f64) -> f64 {
    let n = b.len() - 1;
    if n == 0 {
        return 0.0;
    }
    // |1 − t| ≤ |fl(1 − t)| + |ρ|
    let (s, rho) = super::eft::two_sum(1.0, -t);
    let alpha = add_up(s.abs(), rho.abs());
    let beta = t.abs();
    let wa = add_up(alpha, beta);
    let sum = with_mapped(b, f64::abs, |buf| {
        for len in (1..buf.len()).rev() {
            for i in 0..len {
                buf[i] = add_up(mul_up(wa, buf[i]), mul_up(beta, buf[i + 1]));
            }
        }
        buf[0]
    });
    add_up(mul_up(gamma(4 * n), sum), underflow_term(n, 1.0, add_up(wa, beta)))
}

/// The power-basis coefficients `a_0..a_n` of `Σ b_i B_i^n(t) = Σ a_i t^i`, each rounded to
/// the nearest `f64` (ties to even; `±∞` beyond the range), computed exactly from the floats
/// `b_i` (`a_i = C(n, i) Δ^i b_0`, the forward differences).
///
/// ```
/// use casteljau::float::power_coefficients;
/// // 0·(1−t)² + 1·2t(1−t) + 3·t² = 2t + t²
/// assert_eq!(power_coefficients(&[0.0, 1.0, 3.0]), vec![0.0, 2.0, 1.0]);
/// ```
pub fn power_coefficients(b: &[f64]) -> Vec<f64> {
    // every b_j as an integer over one power of two 2^−low
    let parts: Vec<(bool, u64, i64)> = b.iter().map(|x| super::ulp::decompose(*x)).collect();
    let low = parts.iter().filter(|p| p.1 != 0).map(|p| p.2).min().unwrap_or(0);
    let mut diffs: Vec<BigInt> = parts
        .iter()
        .map(|&(neg, m, e)| {
            let v = BigInt::from(m) << ((e - low) as u64);
            if neg {
                -v
            } else {
                v
            }
        })
        .collect();
    let n = b.len() - 1;
    let mut binomial = BigInt::one();
    let mut out = Vec::with_capacity(n + 1);
    for i in 0..=n {
        let a = &binomial * &diffs[0];
        out.push(round_scaled(a.sign() == Sign::Minus, a.magnitude(), low, false));
        if i < n {
            for j in 0..n - i {
                diffs[j] = &diffs[j + 1] - &diffs[j];
            }
            binomial = binomial * (n - i) / (i + 1);
        }
    }
    out
}

/// Horner's rule on power-basis coefficients, `r ← r·t + a_i` from `a_n` down.
pub fn horner(a: &[f64], t: f64) -> f64 {
    let mut r = a[a.len() - 1];
    for x in a[..a.len() - 1].iter().rev() {
        r = r * t + x;
    }
    r
}

/// The a priori bound of Horner's rule (with or without a fused multiply-add) on the
/// correctly rounded power-basis coefficients `â_i` ([`power_coefficients`]) of the curve:
/// `γ_{2n+1} Σ|â_i||t|^i + (n + 1)·2^−1074·max(1, |t|)^n` — `γ_{2n}` for Horner, one `u`
/// for rounding the coefficients, and half a subnormal per product and per coefficient.
/// `+∞` when a coefficient is beyond the `f64` range.
pub fn horner_bound(a: &[f64], t: f64) -> f64 {
    let n = a.len() - 1;
    if a.iter().any(|x| !x.is_finite()) {
        return f64::INFINITY;
    }
    let at = t.abs();
    let mut sum = a[n].abs();
    for x in a[..n].iter().rev() {
        sum = add_up(mul_up(sum, at), x.abs());
    }
    let g = at.max(1.0).powi(n as i32) * (1.0 + 1e-9);
    let under = mul_up(mul_up(n as f64 + 1.0, g), 5e-324);
    add_up(mul_up(gamma(2 * n + 1), sum), under)
}

/// `C(n, i)` for `i = 0..=n`, each rounded to the nearest `f64` (`+∞` past the range).
pub fn binomials(n: usize) -> Vec<f64> {
    let mut c = BigUint::one();
    let mut out = Vec::with_capacity(n + 1);
    for i in 0..=n {
        out.push(round_scaled(false, &c, 0, false));
        if i < n {
            c = c * (n - i) / (i + 1);
        }
    }
    out
}

/// The Bernstein sum `Σ b_i · C(n, i) t^i (1 − t)^{n−i}`: `C(n, i)` correctly rounded,
/// the powers by repeated multiplication, `s = fl(1 − t)`, the terms summed left to right.
///
/// ```
/// use casteljau::float::bernstein_sum;
/// assert_eq!(bernstein_sum(&[0.0, 1.0, 3.0], 0.5), 1.25);
/// ```
pub fn bernstein_sum(b: &[f64], t: f64) -> f64 {
    let n = b.len() - 1;
    let s = 1.0 - t;
    let c = binomials(n);
    let mut sum = 0.0;
    for (i, bi) in b.iter().enumerate() {
        let mut term = c[i];
        for _ in 0..i {
            term *= t;
        }
        for _ in 0..n - i {
            term *= s;
        }
        sum += term * bi;
    }
    sum
}

/// The a priori bound of a Bernstein sum evaluated as [`bernstein_sum`] — or in any order of
/// the `n + 1` multiplications of each term and of the summation — with `C(n, i)` correctly
/// rounded and `s = fl(1 − t)`: `γ_{3n+2} Σ|b_i||B_i(t)| + U`. Each term passes `n + 1`
/// products, one rounding of `C(n, i)`, `n − i` factors of `s`'s rounding and at most `n`
/// additions; each product that underflows adds half a subnormal, multiplied by the factors
/// still to come: `U = (n+1)/2 · 2^−1074 · Σ Ĉ_i max(1,|t|)^i max(1,|s|)^{n−i} max(1,|b_i|)`.
pub fn bernstein_bound(b: &[f64], t: f64) -> f64 {
    let n = b.len() - 1;
    if n == 0 {
        return 0.0;
    }
    let c = binomials(n);
    if c.iter().any(|x| !x.is_finite()) {
        return f64::INFINITY;
    }
    let s = 1.0 - t;
    let (gt, gs) = (t.abs().max(1.0), s.abs().max(1.0));
    let mut under = 0.0;
    for (i, bi) in b.iter().enumerate() {
        // max(1, |b_i|)·2^−1074 first, so that no intermediate overflows
        let mut w = scale_pow2_up(bi.abs().max(1.0), -1074);
        w = mul_up(w, c[i]);
        for _ in 0..i {
            w = mul_up(w, gt);
        }
        for _ in 0..n - i {
            w = mul_up(w, gs);
        }
        under = add_up(under, w);
    }
    let under = mul_up(under, (n as f64 + 1.0) / 2.0 * (1.0 + 1e-9));
    add_up(mul_up(gamma(3 * n + 2), abs_bernstein_sum(b, t)), under)
}

/// The condition number `Σ|b_i||B_i(t)| / |p(t)|` of evaluating the polynomial at `t`, from
/// a float `p` near the exact value (`+∞` when `p` is 0): how much a relative perturbation
/// of the coefficients can move the value, relatively. An estimate good to a few ulps.
pub fn condition_number(b: &[f64], t: f64, p: f64) -> f64 {
    let s = abs_bernstein_sum(b, t);
    if p == 0.0 {
        return if s.is_zero() { 0.0 } else { f64::INFINITY };
    }
    next_up(s / p.abs())
}
