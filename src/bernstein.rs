//! Binomial coefficients, the Bernstein basis, and conversion between the power basis and
//! the Bernstein basis (text 000, §1.3).
//!
//! `B_i^n(t) = C(n,i) t^i (1-t)^(n-i)`. A polynomial written in the power basis on an
//! interval `[a, b]` becomes a Bézier curve on `[0, 1]` by the affine change of parameter
//! `u = a + (b - a) t` ([`reparametrize`]) followed by [`power_to_bernstein`].

use crate::error::{check_degree, Result};
use crate::scalar::Scalar;
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// The exact binomial coefficient `C(n, k)`, zero when `k > n`.
///
/// ```
/// assert_eq!(casteljau::binomial(5, 2), 10.into());
/// assert_eq!(casteljau::binomial(3, 4), 0.into());
/// ```
pub fn binomial(n: usize, k: usize) -> BigInt {
    if k > n {
        return BigInt::zero();
    }
    let k = k.min(n - k);
    let mut acc = BigInt::one();
    for i in 0..k {
        // acc * (n - i) / (i + 1) is always an integer: it is C(n, i + 1) * ...
        acc = acc * BigInt::from(n - i) / BigInt::from(i + 1);
    }
    acc
}

/// `C(n, k)` for signed arguments, zero outside `0 ≤ k ≤ n`: the convention formulas like
/// (8) rely on when their index ranges run past the ends.
pub fn binomial_signed(n: i64, k: i64) -> BigInt {
    if n < 0 || k < 0 || k > n {
        BigInt::zero()
    } else {
        binomial(n as usize, k as usize)
    }
}

/// The row `C(n, 0), …, C(n, n)`.
pub fn binomial_row(n: usize) -> Vec<BigInt> {
    let mut row = Vec::with_capacity(n + 1);
    let mut c = BigInt::one();
    row.push(c.clone());
    for k in 0..n {
        c = c * BigInt::from(n - k) / BigInt::from(k + 1);
        row.push(c.clone());
    }
    row
}

/// `C(n, k)` as a scalar (an error for `f64` only when it does not fit).
pub fn binomial_scalar<T: Scalar>(n: usize, k: usize) -> Result<T> {
    T::from_bigint(&binomial(n, k))
}

/// The Bernstein polynomial `B_i^n(t)`; zero for `i > n`.
///
/// ```
/// use casteljau::{bernstein, BigRational, Scalar};
/// let half = BigRational::from_ratio(1, 2).unwrap();
/// assert_eq!(bernstein(1, 2, &half).unwrap(), half);
/// ```
pub fn bernstein<T: Scalar>(i: usize, n: usize, t: &T) -> Result<T> {
    if i > n {
        return Ok(T::zero());
    }
    let s = T::one().sub_ref(t);
    let c = binomial_scalar::<T>(n, i)?;
    Ok(c.mul_ref(&t.powi(i as u32)).mul_ref(&s.powi((n - i) as u32)))
}

/// All of `B_0^n(t), …, B_n^n(t)`, by the recurrence `B_i^n = (1-t) B_i^{n-1} + t B_{i-1}^{n-1}`
/// (no binomials, so no overflow in `f64`).
pub fn bernstein_all<T: Scalar>(n: usize, t: &T) -> Vec<T> {
    let s = T::one().sub_ref(t);
    let mut b = Vec::with_capacity(n + 1);
    b.push(T::one());
    for k in 1..=n {
        let mut prev = T::zero();
        for bi in b.iter_mut() {
            let cur = bi.clone();
            *bi = s.mul_ref(&cur).add_ref(&t.mul_ref(&prev));
            prev = cur;
        }
        b.push(t.mul_ref(&prev));
        debug_assert_eq!(b.len(), k + 1);
    }
    b
}

/// Evaluates `Σ a_k t^k` by Horner's rule.
pub fn eval_power<T: Scalar>(coeffs: &[T], t: &T) -> T {
    let mut acc = T::zero();
    for a in coeffs.iter().rev() {
        acc = acc.mul_ref(t).add_ref(a);
    }
    acc
}

/// Bernstein coefficients `b_0..b_n` of the polynomial `Σ_{i=0}^n a_i t^i`:
/// `b_j = Σ_{i≤j} C(j,i)/C(n,i) a_i`.
///
/// ```
/// use casteljau::{Ring, power_to_bernstein, BigRational, Scalar};
/// // 4t - 4t² = 4/3 B_1^3 + 4/3 B_2^3 (text 000, §1.3, read as a cubic)
/// let a: Vec<BigRational> = [0, 4, -4, 0].iter().map(|&c| BigRational::from_i64(c)).collect();
/// let b = power_to_bernstein(&a).unwrap();
/// let four_thirds = BigRational::from_ratio(4, 3).unwrap();
/// assert_eq!(b, vec![BigRational::from_i64(0), four_thirds.clone(), four_thirds, BigRational::from_i64(0)]);
/// ```
pub fn power_to_bernstein<T: Scalar>(coeffs: &[T]) -> Result<Vec<T>> {
    if coeffs.is_empty() {
        return Ok(Vec::new());
    }
    let n = check_degree("degree", coeffs.len() as u128 - 1)?;
    // a_i / C(n,i) once, then b_j = Σ_i C(j,i) (a_i / C(n,i)).
    let row = binomial_row(n);
    let scaled: Vec<T> = coeffs
        .iter()
        .zip(&row)
        .map(|(a, c)| a.checked_div(&T::from_bigint(c)?))
        .collect::<Result<_>>()?;
    let mut out = Vec::with_capacity(n + 1);
    for j in 0..=n {
        let cj = binomial_row(j);
        let mut acc = T::zero();
        for (i, a) in scaled.iter().enumerate().take(j + 1) {
            acc += &((T::from_bigint(&cj[i])?).mul_ref(a));
        }
        out.push(acc);
    }
    Ok(out)
}

/// Power coefficients `a_0..a_n` of `Σ b_j B_j^n(t)`:
/// `a_i = C(n,i) Σ_{j≤i} (-1)^{i-j} C(i,j) b_j` (the forward difference `C(n,i) Δ^i b_0`).
pub fn bernstein_to_power<T: Scalar>(bern: &[T]) -> Result<Vec<T>> {
    if bern.is_empty() {
        return Ok(Vec::new());
    }
    let n = check_degree("degree", bern.len() as u128 - 1)?;
    // Successive forward differences: after step i, diffs[0] = Δ^i b_0.
    let mut diffs = bern.to_vec();
    let row = binomial_row(n);
    let mut out = Vec::with_capacity(n + 1);
    for c in &row {
        out.push((T::from_bigint(c)?).mul_ref(&diffs[0]));
        for j in 0..diffs.len() - 1 {
            diffs[j] = (diffs[j + 1]).sub_ref(&diffs[j]);
        }
        diffs.pop();
    }
    Ok(out)
}

/// Coefficients in `t` of `p(a + (b - a) t)`, where `p(u) = Σ c_k u^k`: the polynomial on
/// `[a, b]` carried to `[0, 1]`. Exact for exact scalars (Taylor shift, then scaling).
///
/// ```
/// use casteljau::{Ring, reparametrize, BigRational, Scalar};
/// let q = |n| BigRational::from_i64(n);
/// // -u² + 1 with u = 2t - 1 is 4t - 4t²
/// let c = reparametrize(&[q(1), q(0), q(-1)], &q(-1), &q(1));
/// assert_eq!(c, vec![q(0), q(4), q(-4)]);
/// ```
pub fn reparametrize<T: Scalar>(coeffs: &[T], a: &T, b: &T) -> Vec<T> {
    // Horner in polynomial arithmetic: acc(t) = acc(t) * (a + h t) + c_k.
    let h = b.sub_ref(a);
    let mut acc: Vec<T> = Vec::with_capacity(coeffs.len());
    for c in coeffs.iter().rev() {
        let mut next = vec![T::zero(); acc.len() + 1];
        for (k, x) in acc.iter().enumerate() {
            next[k] += &x.mul_ref(a);
            next[k + 1] += &x.mul_ref(&h);
        }
        next[0] += c;
        acc = next;
    }
    acc
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Ring;
    use num_rational::BigRational;
    type Q = BigRational;

    fn q(n: i64) -> Q {
        Q::from_i64(n)
    }

    #[test]
    fn binomials() {
        assert_eq!(binomial(0, 0), 1.into());
        assert_eq!(binomial(10, 3), 120.into());
        assert_eq!(
            binomial_row(4),
            vec![1, 4, 6, 4, 1].into_iter().map(BigInt::from).collect::<Vec<_>>()
        );
        assert_eq!(binomial_signed(4, -1), 0.into());
        assert_eq!(binomial(100, 50).to_string(), "100891344545564193334812497256");
    }

    #[test]
    fn bernstein_partition_of_unity_and_recurrence_agree() {
        let t = Q::from_ratio(2, 7).unwrap();
        for n in 0..8 {
            let all = bernstein_all(n, &t);
            let sum = all.iter().fold(q(0), |acc, b| acc + b);
            assert_eq!(sum, q(1));
            for (i, b) in all.iter().enumerate() {
                assert_eq!(*b, bernstein(i, n, &t).unwrap());
            }
        }
    }

    #[test]
    fn power_bernstein_round_trip() {
        let a = vec![q(3), q(-1), q(4), q(1), q(-5)];
        let b = power_to_bernstein(&a).unwrap();
        assert_eq!(bernstein_to_power(&b).unwrap(), a);
        let t = Q::from_ratio(3, 5).unwrap();
        let via_bernstein = b
            .iter()
            .enumerate()
            .fold(q(0), |acc, (i, bi)| acc + bi * &bernstein(i, 4, &t).unwrap());
        assert_eq!(via_bernstein, eval_power(&a, &t));
    }

    #[test]
    fn reparametrize_matches_composition() {
        let c = vec![q(2), q(-3), q(0), q(5)];
        let (a, b) = (Q::from_ratio(-1, 2).unwrap(), q(3));
        let r = reparametrize(&c, &a, &b);
        let t = Q::from_ratio(2, 9).unwrap();
        assert_eq!(eval_power(&r, &t), eval_power(&c, &(&a + &(&(&b - &a) * &t))));
    }
}
