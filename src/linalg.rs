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
//! | products | [`mat_mul`], [`mat_vec`], [`transpose`], [`identity`] |

use crate::error::{Error, Result};
use crate::scalar::{RefOps, Scalar};

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
pub fn row_reduce<T: Scalar>(a: &mut [Vec<T>]) -> Result<Vec<usize>>
where
    for<'a> &'a T: RefOps<T>,
{
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
            *x = &*x * &inv;
        }
        let pivot_row = a[row].clone();
        for (r, other) in a.iter_mut().enumerate() {
            if r == row || other[col].is_zero() {
                continue;
            }
            let f = other[col].clone();
            for (x, y) in other.iter_mut().zip(&pivot_row) {
                *x -= &(&f * y);
            }
        }
        pivots.push(col);
        row += 1;
    }
    Ok(pivots)
}

/// The rank of `a`.
pub fn rank<T: Scalar>(a: &[Vec<T>]) -> Result<usize>
where
    for<'a> &'a T: RefOps<T>,
{
    let mut m = a.to_vec();
    Ok(row_reduce(&mut m)?.len())
}

/// Solves `a x = b` when the solution exists and is unique: `Ok(Some(x))`; `Ok(None)` when
/// the system is inconsistent; an error when `a` has dependent columns (many solutions).
/// `a` may have more rows than columns.
pub fn solve_consistent<T: Scalar>(a: &[Vec<T>], b: &[T]) -> Result<Option<Vec<T>>>
where
    for<'a> &'a T: RefOps<T>,
{
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
/// use casteljau::{linalg::solve, BigRational, Scalar};
/// let q = |n| BigRational::from_i64(n);
/// let x = solve(&[vec![q(2), q(1)], vec![q(1), q(3)]], &[q(3), q(5)]).unwrap();
/// assert_eq!(x, vec![BigRational::from_ratio(4, 5).unwrap(), BigRational::from_ratio(7, 5).unwrap()]);
/// ```
pub fn solve<T: Scalar>(a: &[Vec<T>], b: &[T]) -> Result<Vec<T>>
where
    for<'a> &'a T: RefOps<T>,
{
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
pub fn identity<T: Scalar>(n: usize) -> Matrix<T>
where
    for<'a> &'a T: RefOps<T>,
{
    (0..n)
        .map(|i| (0..n).map(|j| if i == j { T::one() } else { T::zero() }).collect())
        .collect()
}

/// The transpose of a rectangular matrix.
pub fn transpose<T: Scalar>(a: &[Vec<T>]) -> Result<Matrix<T>>
where
    for<'a> &'a T: RefOps<T>,
{
    let cols = check_rectangular(a, "transpose")?;
    Ok((0..cols)
        .map(|j| a.iter().map(|row| row[j].clone()).collect())
        .collect())
}

/// The product `a b`; the inner dimensions must agree.
pub fn mat_mul<T: Scalar>(a: &[Vec<T>], b: &[Vec<T>]) -> Result<Matrix<T>>
where
    for<'a> &'a T: RefOps<T>,
{
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
                        acc += &(x * &brow[j]);
                    }
                    acc
                })
                .collect()
        })
        .collect())
}

/// The product `a x` of a matrix and a column vector.
pub fn mat_vec<T: Scalar>(a: &[Vec<T>], x: &[T]) -> Result<Vec<T>>
where
    for<'a> &'a T: RefOps<T>,
{
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
                acc += &(u * v);
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
/// use casteljau::{linalg::solve_many, BigRational, Scalar};
/// let q = |n| BigRational::from_i64(n);
/// let a = vec![vec![q(2), q(0)], vec![q(0), q(4)]];
/// let x = solve_many(&a, &[vec![q(2), q(4)], vec![q(4), q(8)]]).unwrap();
/// assert_eq!(x, vec![vec![q(1), q(2)], vec![q(1), q(2)]]);
/// ```
pub fn solve_many<T: Scalar>(a: &[Vec<T>], b: &[Vec<T>]) -> Result<Matrix<T>>
where
    for<'a> &'a T: RefOps<T>,
{
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
/// use casteljau::{linalg::{inverse, mat_mul, identity}, BigRational, Scalar};
/// let q = |n| BigRational::from_i64(n);
/// let a = vec![vec![q(2), q(1)], vec![q(7), q(4)]];
/// let inv = inverse(&a).unwrap();
/// assert_eq!(inv, vec![vec![q(4), q(-1)], vec![q(-7), q(2)]]);
/// assert_eq!(mat_mul(&a, &inv).unwrap(), identity(2));
/// assert!(inverse(&[vec![q(1), q(2)], vec![q(2), q(4)]]).is_err());
/// ```
pub fn inverse<T: Scalar>(a: &[Vec<T>]) -> Result<Matrix<T>>
where
    for<'a> &'a T: RefOps<T>,
{
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
/// use casteljau::{linalg::determinant, BigRational, Scalar};
/// let q = |n| BigRational::from_i64(n);
/// let a = vec![vec![q(2), q(-1), q(0)], vec![q(-1), q(2), q(-1)], vec![q(0), q(-1), q(2)]];
/// assert_eq!(determinant(&a).unwrap(), q(4));
/// ```
pub fn determinant<T: Scalar>(a: &[Vec<T>]) -> Result<T>
where
    for<'a> &'a T: RefOps<T>,
{
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
                let num = &(&row[j] * &pivot_row[k]) - &(&f * &pivot_row[j]);
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
pub fn determinant_cofactor<T: Scalar>(a: &[Vec<T>]) -> Result<T>
where
    for<'a> &'a T: RefOps<T>,
{
    let n = check_square(a, "the determinant")?;
    if n > MAX_COFACTOR_SIZE {
        return Err(Error::TooLarge {
            what: "matrix for cofactor expansion",
            value: format!("{n}×{n}"),
            limit: format!("{MAX_COFACTOR_SIZE}×{MAX_COFACTOR_SIZE}"),
        });
    }
    let cols: Vec<usize> = (0..n).collect();
    Ok(cofactor_expand(a, 0, &cols))
}

fn cofactor_expand<T: Scalar>(a: &[Vec<T>], row: usize, cols: &[usize]) -> T
where
    for<'a> &'a T: RefOps<T>,
{
    if cols.is_empty() {
        return T::one();
    }
    let mut acc = T::zero();
    for (idx, &c) in cols.iter().enumerate() {
        if a[row][c].is_zero() {
            continue;
        }
        let rest: Vec<usize> = cols.iter().copied().filter(|&x| x != c).collect();
        let term = &a[row][c] * &cofactor_expand(a, row + 1, &rest);
        if idx % 2 == 0 {
            acc += &term;
        } else {
            acc -= &term;
        }
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

    #[test]
    fn float_solve() {
        let x = solve(&[vec![1e-20, 1.0], vec![1.0, 1.0]], &[1.0, 2.0]).unwrap();
        assert!((x[0] - 1.0).abs() < 1e-12 && (x[1] - 1.0).abs() < 1e-12);
    }
}
