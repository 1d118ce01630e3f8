//! Exact linear algebra over any [`Scalar`]: Gaussian elimination to reduced row echelon
//! form, rank, solving square and consistent over-determined systems.
//!
//! For exact scalars every pivot test is `== 0`, so the rank is the true rank. For `f64`
//! the largest pivot is chosen (partial pivoting); a pivot below `1e-12` times the largest
//! entry counts as zero.

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

#[cfg(test)]
mod tests {
    use super::*;
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
    fn float_solve() {
        let x = solve(&[vec![1e-20, 1.0], vec![1.0, 1.0]], &[1.0, 2.0]).unwrap();
        assert!((x[0] - 1.0).abs() < 1e-12 && (x[1] - 1.0).abs() < 1e-12);
    }
}
