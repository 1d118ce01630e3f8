//! Exact linear algebra over any [`Scalar`]: Gaussian elimination to reduced row echelon
//! form, rank, solving square and consistent over-determined systems, several right-hand
//! sides at once, the inverse, and the determinant by fraction-free (Bareiss) elimination.
//!
//! For exact scalars every pivot test is `== 0`, so the rank is the true rank and a
//! "singular" verdict is a proof. For `f64` the largest pivot is chosen (partial pivoting);
//! in the elimination routines a pivot below `1e-12` times the largest entry counts as zero,
//! so a float "singular" means "numerically singular", not a proof.
//!
//! | task | function |
//! |------|----------|
//! | reduced row echelon form, rank | [`row_reduce`], [`rank`] |
//! | `A x = b`, unique solution | [`solve`] (square), [`solve_consistent`] (over-determined) |
//! | `A X = B`, several right-hand sides | [`solve_many`] |
//! | `A⁻¹` | [`inverse`] |
//! | `det A` | [`determinant`] (Bareiss), [`determinant_cofactor`] (Laplace, a reference for small sizes) |
//! | products | [`mat_mul`], [`mat_vec`], [`transpose`], [`identity`], [`dot`] |
//! | over any [`Ring`] (no division) | [`determinant_division_free`], [`characteristic_coefficients`], [`adjugate`] |
//!
//! The division-free functions serve every [`Ring`], also those that are not scalars: the
//! prover evaluates `det` and `inv` in its degree-bound and rational-function algebras with
//! them.

use crate::error::{Error, Result};
use crate::scalar::{Ring, Scalar};

/// A dense matrix as rows.
pub type Matrix<T> = Vec<Vec<T>>;

fn check_rectangular<T>(a: &[Vec<T>], what: &str) -> Result<usize> {
    let cols = a
        .first()
        .map(Vec::len)
        .ok_or_else(|| Error::Singular(format!("{what}: empty matrix")))?;
    for (i, row) in a.iter().enumerate() {
        if row.len() != cols {
            return Err(Error::DimensionMismatch {
                expected: cols,
                found: row.len(),
                context: format!("{what}, row {i}"),
            });
        }
    }
    Ok(cols)
}

/// Row-reduces `a` in place to reduced row echelon form; returns the pivot columns.
pub fn row_reduce<T: Scalar>(a: &mut [Vec<T>]) -> Result<Vec<usize>> {
    if a.is_empty() {
        return Ok(Vec::new());
    }
    let cols = check_rectangular(a, "row reduction")?;
    let scale = if T::EXACT {
        0.0
    } else {
        a.iter().flatten().map(|x| x.to_f64().abs()).fold(0.0, f64::max) * 1e-12
    };
    let mut pivots = Vec::new();
    let mut row = 0;
    for col in 0..cols {
        if row == a.len() {
            break;
        }
        // Exact: any non-zero pivot will do; float: the largest, for stability.
        let mut best: Option<usize> = None;
        for r in row..a.len() {
            let v = &a[r][col];
            if v.is_zero() || (!T::EXACT && v.to_f64().abs() <= scale) {
                continue;
            }
            if T::EXACT {
                best = Some(r);
                break;
            }
            if best.is_none_or(|b| v.abs() > a[b][col].abs()) {
                best = Some(r);
            }
        }
        let Some(p) = best else { continue };
        a.swap(row, p);
        let inv = T::one().checked_div(&a[row][col])?;
        for x in a[row].iter_mut() {
            *x *= &inv;
        }
        let pivot_row = a[row].clone();
        for (r, other) in a.iter_mut().enumerate() {
            if r == row || other[col].is_zero() {
                continue;
            }
            let f = other[col].clone();
            for (x, y) in other.iter_mut().zip(&pivot_row) {
                *x -= &f.mul_ref(y);
            }
        }
        pivots.push(col);
        row += 1;
    }
    Ok(pivots)
}

/// The rank of `a`.
pub fn rank<T: Scalar>(a: &[Vec<T>]) -> Result<usize> {
    let mut m = a.to_vec();
    Ok(row_reduce(&mut m)?.len())
}

/// Solves `a x = b` when the solution exists and is unique: `Ok(Some(x))`; `Ok(None)` when
/// the system is inconsistent; an error when `a` has dependent columns (many solutions).
/// `a` may have more rows than columns.
pub fn solve_consistent<T: Scalar>(a: &[Vec<T>], b: &[T]) -> Result<Option<Vec<T>>> {
    let cols = check_rectangular(a, "linear system")?;
    if b.len() != a.len() {
        return Err(Error::DimensionMismatch {
            expected: a.len(),
            found: b.len(),
            context: "right-hand side".into(),
        });
    }
    let mut m: Matrix<T> = a
        .iter()
        .zip(b)
        .map(|(row, bi)| row.iter().cloned().chain(std::iter::once(bi.clone())).collect())
        .collect();
    let pivots = row_reduce(&mut m)?;
    if pivots.last() == Some(&cols) {
        return Ok(None);
    }
    if pivots.len() < cols {
        return Err(Error::Singular(format!(
            "rank {} < {} unknowns: the solution is not unique",
            pivots.len(),
            cols
        )));
    }
    Ok(Some(m.iter().take(cols).map(|row| row[cols].clone()).collect()))
}

/// Solves the square system `a x = b`; a singular matrix is an error.
///
/// ```
/// use casteljau::{linalg::solve, BigRational, Ring, Scalar};
/// let q = |n| BigRational::from_i64(n);
/// let x = solve(&[vec![q(2), q(1)], vec![q(1), q(3)]], &[q(3), q(5)]).unwrap();
/// assert_eq!(x, vec![BigRational::from_ratio(4, 5).unwrap(), BigRational::from_ratio(7, 5).unwrap()]);
/// ```
pub fn solve<T: Scalar>(a: &[Vec<T>], b: &[T]) -> Result<Vec<T>> {
    let cols = check_rectangular(a, "linear system")?;
    if cols != a.len() {
        return Err(Error::DimensionMismatch {
            expected: a.len(),
            found: cols,
            context: "square system (columns)".into(),
        });
    }
    solve_consistent(a, b)?.ok_or_else(|| Error::Singular("the matrix is singular".into()))
}

fn check_square<T>(a: &[Vec<T>], what: &str) -> Result<usize> {
    let cols = check_rectangular(a, what)?;
    if cols != a.len() {
        return Err(Error::Domain(format!(
            "{what} needs a square matrix, got {} rows and {cols} columns",
            a.len()
        )));
    }
    Ok(cols)
}

/// The `n × n` identity matrix.
pub fn identity<T: Scalar>(n: usize) -> Matrix<T> {
    (0..n)
        .map(|i| (0..n).map(|j| if i == j { T::one() } else { T::zero() }).collect())
        .collect()
}

/// The transpose of a rectangular matrix.
pub fn transpose<T: Clone>(a: &[Vec<T>]) -> Result<Matrix<T>> {
    let cols = check_rectangular(a, "transpose")?;
    Ok((0..cols)
        .map(|j| a.iter().map(|row| row[j].clone()).collect())
        .collect())
}

/// The product `a b`; the inner dimensions must agree.
pub fn mat_mul<T: Scalar>(a: &[Vec<T>], b: &[Vec<T>]) -> Result<Matrix<T>> {
    let inner = check_rectangular(a, "matrix product (left factor)")?;
    let cols = check_rectangular(b, "matrix product (right factor)")?;
    if inner != b.len() {
        return Err(Error::DimensionMismatch {
            expected: inner,
            found: b.len(),
            context: "matrix product: rows of the right factor must equal columns of the left".into(),
        });
    }
    Ok(a.iter()
        .map(|row| {
            (0..cols)
                .map(|j| {
                    let mut acc = T::zero();
                    for (x, brow) in row.iter().zip(b) {
                        acc += &x.mul_ref(&brow[j]);
                    }
                    acc
                })
                .collect()
        })
        .collect())
}

/// The product `a x` of a matrix and a column vector.
pub fn mat_vec<T: Scalar>(a: &[Vec<T>], x: &[T]) -> Result<Vec<T>> {
    let cols = check_rectangular(a, "matrix-vector product")?;
    if cols != x.len() {
        return Err(Error::DimensionMismatch {
            expected: cols,
            found: x.len(),
            context: "matrix-vector product: vector length must equal the number of columns".into(),
        });
    }
    Ok(a.iter()
        .map(|row| {
            let mut acc = T::zero();
            for (u, v) in row.iter().zip(x) {
                acc += &u.mul_ref(v);
            }
            acc
        })
        .collect())
}

/// Solves the square system `a X = b` for several right-hand sides at once: `b` has one row
/// per equation and one column per right-hand side; the result has one row per unknown.
///
/// One elimination serves every column, which is what a least-squares fit of points in
/// several coordinates needs. A singular `a` is [`Error::Singular`].
///
/// ```
/// use casteljau::{linalg::solve_many, BigRational, Ring, Scalar};
/// let q = |n| BigRational::from_i64(n);
/// let a = vec![vec![q(2), q(0)], vec![q(0), q(4)]];
/// let x = solve_many(&a, &[vec![q(2), q(4)], vec![q(4), q(8)]]).unwrap();
/// assert_eq!(x, vec![vec![q(1), q(2)], vec![q(1), q(2)]]);
/// ```
pub fn solve_many<T: Scalar>(a: &[Vec<T>], b: &[Vec<T>]) -> Result<Matrix<T>> {
    let n = check_square(a, "solving a linear system")?;
    if b.len() != n {
        return Err(Error::DimensionMismatch {
            expected: n,
            found: b.len(),
            context: "right-hand side rows".into(),
        });
    }
    let r = check_rectangular(b, "right-hand sides")?;
    let mut m: Matrix<T> = a
        .iter()
        .zip(b)
        .map(|(row, rhs)| row.iter().chain(rhs).cloned().collect())
        .collect();
    let pivots = row_reduce(&mut m)?;
    // The first n columns are the matrix: full rank means pivots 0..n, in order.
    if pivots.len() < n || pivots[n - 1] != n - 1 {
        let rank = pivots.iter().filter(|&&c| c < n).count();
        return Err(Error::Singular(format!(
            "the {n}×{n} matrix has rank {rank} < {n}, so the solution is not unique"
        )));
    }
    Ok(m.into_iter().map(|row| row[n..n + r].to_vec()).collect())
}

/// The inverse of a square matrix, by Gauss–Jordan elimination of `[a | I]`; a singular
/// matrix is [`Error::Singular`].
///
/// ```
/// use casteljau::{linalg::{inverse, mat_mul, identity}, BigRational, Ring};
/// let q = |n| BigRational::from_i64(n);
/// let a = vec![vec![q(2), q(1)], vec![q(7), q(4)]];
/// let inv = inverse(&a).unwrap();
/// assert_eq!(inv, vec![vec![q(4), q(-1)], vec![q(-7), q(2)]]);
/// assert_eq!(mat_mul(&a, &inv).unwrap(), identity(2));
/// assert!(inverse(&[vec![q(1), q(2)], vec![q(2), q(4)]]).is_err());
/// ```
pub fn inverse<T: Scalar>(a: &[Vec<T>]) -> Result<Matrix<T>> {
    let n = check_square(a, "the inverse")?;
    solve_many(a, &identity(n)).map_err(|e| match e {
        Error::Singular(m) => Error::Singular(format!("no inverse: {m}")),
        other => other,
    })
}

/// The determinant of a square matrix by Bareiss' fraction-free elimination.
///
/// Step `k` replaces every entry below and right of the pivot by
/// `(m_ij m_kk − m_ik m_kj) / p`, where `p` is the previous pivot; the division is always
/// exact (Sylvester's identity: every intermediate entry is a minor of the input). So over
/// the integers, and over any exact scalar, the intermediate entries stay as small as the
/// minors of the input — no growth from repeated fractions — and the result is exact. For
/// `f64` the largest available pivot is used and the result is only as good as floating
/// point allows (no tolerance: a float determinant is never rounded to zero on purpose).
///
/// An empty or non-square matrix is an error; a singular matrix has determinant zero.
///
/// ```
/// use casteljau::{linalg::determinant, BigRational, Ring, Scalar};
/// let q = |n| BigRational::from_i64(n);
/// let a = vec![vec![q(2), q(-1), q(0)], vec![q(-1), q(2), q(-1)], vec![q(0), q(-1), q(2)]];
/// assert_eq!(determinant(&a).unwrap(), q(4));
/// ```
pub fn determinant<T: Scalar>(a: &[Vec<T>]) -> Result<T> {
    let n = check_square(a, "the determinant")?;
    let mut m = a.to_vec();
    let mut negate = false;
    let mut prev = T::one();
    for k in 0..n {
        // Exact: any non-zero pivot; float: the largest, for stability.
        let mut best: Option<usize> = None;
        for r in k..n {
            if m[r][k].is_zero() {
                continue;
            }
            if T::EXACT {
                best = Some(r);
                break;
            }
            if best.is_none_or(|b| m[r][k].abs() > m[b][k].abs()) {
                best = Some(r);
            }
        }
        let Some(p) = best else {
            return Ok(T::zero());
        };
        if p != k {
            m.swap(p, k);
            negate = !negate;
        }
        let (top, below) = m.split_at_mut(k + 1);
        let pivot_row = &top[k];
        for row in below.iter_mut() {
            let f = row[k].clone();
            for j in k + 1..n {
                let num = row[j].mul_ref(&pivot_row[k]).sub_ref(&f.mul_ref(&pivot_row[j]));
                row[j] = num.checked_div(&prev)?;
            }
            row[k] = T::zero();
        }
        prev = m[k][k].clone();
    }
    if !T::EXACT && !prev.to_f64().is_finite() {
        return Err(Error::NotFinite(format!(
            "the determinant of a {n}×{n} float matrix overflowed; use exact scalars"
        )));
    }
    Ok(if negate { -prev } else { prev })
}

/// Largest size [`determinant_cofactor`] accepts: Laplace expansion costs `n!` products.
pub const MAX_COFACTOR_SIZE: usize = 8;

/// The determinant by Laplace (cofactor) expansion along the first row: `n!` products, no
/// division at all. A slow, obviously correct reference for [`determinant`]; sizes above
/// [`MAX_COFACTOR_SIZE`] are [`Error::TooLarge`].
pub fn determinant_cofactor<T: Scalar>(a: &[Vec<T>]) -> Result<T> {
    let n = check_square(a, "the determinant")?;
    if n > MAX_COFACTOR_SIZE {
        return Err(Error::TooLarge {
            what: "matrix for cofactor expansion",
            value: format!("{n}×{n}"),
            limit: format!("{MAX_COFACTOR_SIZE}×{MAX_COFACTOR_SIZE}"),
        });
    }
    Ok(laplace(a))
}

/// `Σ a_i b_i` over the common length.
pub fn dot<T: Ring>(a: &[T], b: &[T]) -> T {
    let mut acc = T::zero();
    for (x, y) in a.iter().zip(b) {
        acc = acc.add_ref(&x.mul_ref(y));
    }
    acc
}

/// Largest size [`determinant_division_free`] and [`adjugate`] expand by cofactors; beyond,
/// Berkowitz's algorithm takes `O(n⁴)` products instead of `n!`.
const LAPLACE_SIZE: usize = 4;

/// The determinant of a square matrix from ring operations alone: Laplace expansion up to
/// 4 × 4 (at most 24 products, and in an algebra of degree bounds the tightest bounds),
/// beyond that the constant term of Berkowitz's [`characteristic_coefficients`].
///
/// The matrix must be square (the caller checks; this function only indexes).
pub fn determinant_division_free<T: Ring>(m: &[Vec<T>]) -> T {
    if m.len() > LAPLACE_SIZE {
        let p = characteristic_coefficients(m);
        let last = p[m.len()].clone();
        return if m.len() % 2 == 0 { last } else { last.neg_ref() };
    }
    laplace(m)
}

/// The coefficients `1, p_1, …, p_n` of `det(xI − M) = x^n + p_1 x^{n−1} + … + p_n`, by the
/// Samuelson–Berkowitz recursion: with `M = [a R; C M₁]`, the vector is the lower-triangular
/// Toeplitz matrix of `1, −a, −RC, −RM₁C, …, −RM₁^{n−2}C` times the vector of `M₁`.
pub fn characteristic_coefficients<T: Ring>(m: &[Vec<T>]) -> Vec<T> {
    let n = m.len();
    if n == 0 {
        return vec![T::one()];
    }
    let a = &m[0][0];
    let row = &m[0][1..];
    let sub: Vec<Vec<T>> = m[1..].iter().map(|r| r[1..].to_vec()).collect();
    let mut column: Vec<T> = m[1..].iter().map(|r| r[0].clone()).collect();
    let mut diagonals = vec![T::one(), a.neg_ref()];
    for k in 0..n.saturating_sub(1) {
        if k > 0 {
            column = sub.iter().map(|r| dot(r, &column)).collect();
        }
        diagonals.push(dot(row, &column).neg_ref());
    }
    let inner = characteristic_coefficients(&sub);
    (0..=n)
        .map(|i| {
            let mut acc = T::zero();
            for (j, v) in inner.iter().enumerate().take(i + 1) {
                acc = acc.add_ref(&diagonals[i - j].mul_ref(v));
            }
            acc
        })
        .collect()
}

/// The adjugate `adj(M)`, so that `M⁻¹ = adj(M) / det M`: cofactors up to 4 × 4, beyond that
/// `adj(M) = (−1)^{n+1} (M^{n−1} + p_1 M^{n−2} + … + p_{n−1} I)` (Cayley–Hamilton, the `p_k`
/// from [`characteristic_coefficients`]) by Horner's rule, `O(n⁴)` products.
///
/// The matrix must be square (the caller checks; this function only indexes).
pub fn adjugate<T: Ring>(m: &[Vec<T>]) -> Matrix<T> {
    let n = m.len();
    if n > LAPLACE_SIZE {
        return adjugate_cayley_hamilton(m);
    }
    let mut out = vec![vec![T::zero(); n]; n];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, cell) in row.iter_mut().enumerate() {
            // adj[i][j] is the cofactor of (j, i)
            let minor: Vec<Vec<T>> = m
                .iter()
                .enumerate()
                .filter(|(r, _)| *r != j)
                .map(|(_, r)| {
                    r.iter()
                        .enumerate()
                        .filter(|(c, _)| *c != i)
                        .map(|(_, x)| x.clone())
                        .collect()
                })
                .collect();
            let c = determinant_division_free(&minor);
            *cell = if (i + j) % 2 == 0 { c } else { c.neg_ref() };
        }
    }
    out
}

fn adjugate_cayley_hamilton<T: Ring>(m: &[Vec<T>]) -> Matrix<T> {
    let n = m.len();
    let p = characteristic_coefficients(m);
    let scaled_identity = |c: &T| -> Matrix<T> {
        (0..n)
            .map(|i| (0..n).map(|j| if i == j { c.clone() } else { T::zero() }).collect())
            .collect()
    };
    let mut acc = scaled_identity(&T::one());
    for pk in &p[1..n] {
        let mut next = scaled_identity(pk);
        for (i, row) in next.iter_mut().enumerate() {
            for (j, cell) in row.iter_mut().enumerate() {
                for (k, mk) in m[i].iter().enumerate() {
                    *cell = cell.add_ref(&mk.mul_ref(&acc[k][j]));
                }
            }
        }
        acc = next;
    }
    if n % 2 == 0 {
        // (−1)^{n+1} is −1 for even n
        for x in acc.iter_mut().flatten() {
            *x = x.neg_ref();
        }
    }
    acc
}

/// Laplace expansion along the first row, by minors.
fn laplace<T: Ring>(m: &[Vec<T>]) -> T {
    match m.len() {
        0 => T::one(),
        1 => m[0][0].clone(),
        2 => m[0][0].mul_ref(&m[1][1]).sub_ref(&m[0][1].mul_ref(&m[1][0])),
        n => {
            let mut acc = T::zero();
            for j in 0..n {
                let minor: Vec<Vec<T>> = m[1..]
                    .iter()
                    .map(|r| {
                        r.iter()
                            .enumerate()
                            .filter(|(k, _)| *k != j)
                            .map(|(_, x)| x.clone())
                            .collect()
                    })
                    .collect();
                let term = m[0][j].mul_ref(&laplace(&minor));
                acc = if j % 2 == 0 {
                    acc.add_ref(&term)
                } else {
                    acc.sub_ref(&term)
                };
            }
            acc
        }
    }
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
    fn rank_and_singularity() {
        let a = vec![vec![q(1), q(2)], vec![q(2), q(4)]];
        assert_eq!(rank(&a).unwrap(), 1);
        assert!(matches!(solve(&a, &[q(1), q(2)]), Err(Error::Singular(_))));
        assert!(solve(&[vec![q(1), q(2)], vec![q(1)]], &[q(1), q(2)]).is_err());
    }

    #[test]
    fn overdetermined_consistent_and_not() {
        let a = vec![vec![q(1), q(0)], vec![q(0), q(1)], vec![q(1), q(1)]];
        assert_eq!(
            solve_consistent(&a, &[q(1), q(2), q(3)]).unwrap(),
            Some(vec![q(1), q(2)])
        );
        assert_eq!(solve_consistent(&a, &[q(1), q(2), q(4)]).unwrap(), None);
    }

    #[test]
    fn bareiss_keeps_integer_minors_and_handles_zero_pivots() {
        // A zero in the leading position forces a row swap (a sign change).
        let a = vec![vec![q(0), q(1), q(2)], vec![q(3), q(4), q(5)], vec![q(6), q(7), q(9)]];
        assert_eq!(determinant(&a).unwrap(), determinant_cofactor(&a).unwrap());
        assert_eq!(determinant(&a).unwrap(), q(-3));
        let singular = vec![vec![q(1), q(2), q(3)], vec![q(2), q(4), q(6)], vec![q(0), q(1), q(1)]];
        assert_eq!(determinant(&singular).unwrap(), q(0));
        assert!(determinant::<Q>(&[]).is_err());
        assert!(determinant(&[vec![q(1), q(2)]]).is_err());
        assert_eq!(determinant(&[vec![q(7)]]).unwrap(), q(7));
    }

    #[test]
    fn inverse_and_many_right_hand_sides() {
        let a = vec![vec![q(1), q(2)], vec![q(3), q(4)]];
        let inv = inverse(&a).unwrap();
        assert_eq!(mat_mul(&inv, &a).unwrap(), identity(2));
        let err = inverse(&[vec![q(1), q(2)], vec![q(2), q(4)]]).unwrap_err();
        assert!(err.to_string().contains("rank 1 < 2"), "{err}");
        assert!(solve_many(&a, &[vec![q(1)]]).is_err());
        assert!(inverse(&[vec![q(1), q(2)]]).unwrap_err().to_string().contains("square"));
    }

    /// A deterministic matrix of small fractions, different for each `seed`.
    fn matrix(n: usize, seed: u64) -> Vec<Vec<Q>> {
        let mut state = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        (0..n)
            .map(|_| {
                (0..n)
                    .map(|_| frac((next() % 19) as i64 - 9, (next() % 5) as i64 + 1))
                    .collect()
            })
            .collect()
    }

    fn frac(p: i64, d: i64) -> Q {
        Q::new(p.into(), d.into())
    }

    #[test]
    fn berkowitz_agrees_with_laplace_and_bareiss_and_the_adjugate_inverts() {
        for n in 0..=7 {
            for seed in 0..6 {
                let m = matrix(n, seed + 100 * n as u64);
                let p = characteristic_coefficients(&m);
                let det_b = if n % 2 == 0 { p[n].clone() } else { -p[n].clone() };
                assert_eq!(det_b, laplace(&m), "n = {n}, seed {seed}");
                assert_eq!(determinant_division_free(&m), det_b, "n = {n}, seed {seed}");
                if n == 0 {
                    continue;
                }
                assert_eq!(determinant(&m).unwrap(), det_b, "n = {n}, seed {seed}");
                // M · adj(M) = det(M) · I, by cofactors and by Cayley–Hamilton alike.
                for adj in [adjugate(&m), adjugate_cayley_hamilton(&m)] {
                    let product = mat_mul(&m, &adj).unwrap();
                    for (i, row) in product.iter().enumerate() {
                        for (j, x) in row.iter().enumerate() {
                            let want = if i == j { det_b.clone() } else { q(0) };
                            assert_eq!(*x, want, "M·adj(M) at ({i}, {j}), n = {n}");
                        }
                    }
                }
            }
        }
        // A Vandermonde determinant: the product of the differences.
        let xs = [frac(1, 2), q(-2), q(3), frac(5, 7), q(0), q(4)];
        let v: Vec<Vec<Q>> = xs
            .iter()
            .map(|x| (0..xs.len()).map(|k| num_traits::pow(x.clone(), k)).collect())
            .collect();
        let mut expected = q(1);
        for j in 0..xs.len() {
            for i in 0..j {
                expected *= &xs[j] - &xs[i];
            }
        }
        assert_eq!(determinant_division_free(&v), expected);
        // A singular 5 × 5 matrix (two equal rows) has determinant 0.
        let mut s = matrix(5, 7);
        s[4] = s[1].clone();
        assert_eq!(determinant_division_free(&s), q(0));
    }

    #[test]
    fn float_solve() {
        let x = solve(&[vec![1e-20, 1.0], vec![1.0, 1.0]], &[1.0, 2.0]).unwrap();
        assert!((x[0] - 1.0).abs() < 1e-12 && (x[1] - 1.0).abs() < 1e-12);
    }
}
