//! Exact convex-hull membership: is a point a convex combination of given points?
//!
//! The answer comes with a certificate. By Carathéodory's theorem a point of the hull of
//! points in `R^d` is a convex combination of at most `d + 1` affinely independent ones, so
//! the search runs over such subsets and solves the barycentric system exactly; a hit is
//! returned as weights `c_j ≥ 0`, `Σ c_j = 1`, `Σ c_j b_j = p`, which anyone can re-check.
//! For exact scalars the answer is exact; for `f64` it is only as good as the float solve.

use crate::error::{Error, Result};
use crate::linalg::solve_consistent;
use crate::point::{common_dimension, Point};
use crate::scalar::Scalar;

/// Largest number of subsets the search may try (a bound on work, not on correctness).
pub const MAX_SUBSETS: u128 = 2_000_000;

/// Weights `c` with `c ≥ 0`, `Σ c = 1`, `Σ c_j points[j] = p` if `p` lies in the convex hull
/// of `points`, `None` otherwise.
///
/// ```
/// use casteljau::{convex_weights, Point, BigRational};
/// let tri: Vec<Point<BigRational>> = [[0, 0], [4, 0], [0, 4]].iter().map(|c| Point::from_ints(c).unwrap()).collect();
/// assert!(convex_weights(&tri, &Point::from_ints(&[1, 1]).unwrap()).unwrap().is_some());
/// assert!(convex_weights(&tri, &Point::from_ints(&[3, 3]).unwrap()).unwrap().is_none());
/// ```
pub fn convex_weights<T: Scalar>(points: &[Point<T>], p: &Point<T>) -> Result<Option<Vec<T>>> {
    let dim = common_dimension(points, "convex hull")?;
    if p.dim() != dim {
        return Err(Error::DimensionMismatch {
            expected: dim,
            found: p.dim(),
            context: "point tested against the hull".into(),
        });
    }
    // Repeated control points add nothing to the hull.
    let mut distinct: Vec<usize> = Vec::new();
    for (i, q) in points.iter().enumerate() {
        if !distinct.iter().any(|&j| points[j] == *q) {
            distinct.push(i);
        }
    }
    let m = distinct.len();
    let max_size = (dim + 1).min(m);
    let work: u128 = (1..=max_size).map(|k| choose(m as u128, k as u128)).sum();
    if work > MAX_SUBSETS {
        return Err(Error::TooLarge {
            what: "convex hull search",
            value: format!("{m} distinct points in dimension {dim}"),
            limit: format!("{MAX_SUBSETS} subsets"),
        });
    }
    for size in 1..=max_size {
        let mut subset: Vec<usize> = (0..size).collect();
        loop {
            if let Some(w) = simplex_weights(points, &distinct, &subset, p)? {
                let mut full = vec![T::zero(); points.len()];
                for (k, &s) in subset.iter().enumerate() {
                    full[distinct[s]] = w[k].clone();
                }
                return Ok(Some(full));
            }
            if !next_subset(&mut subset, m) {
                break;
            }
        }
    }
    Ok(None)
}

/// Whether `p` lies in the convex hull of `points` (see [`convex_weights`]).
pub fn hull_contains<T: Scalar>(points: &[Point<T>], p: &Point<T>) -> Result<bool> {
    Ok(convex_weights(points, p)?.is_some())
}

/// Barycentric weights of `p` in the simplex `subset` if `p` is inside and the simplex is
/// non-degenerate.
fn simplex_weights<T: Scalar>(
    points: &[Point<T>],
    distinct: &[usize],
    subset: &[usize],
    p: &Point<T>,
) -> Result<Option<Vec<T>>> {
    let dim = p.dim();
    // Rows: each coordinate, then the affine row Σ c = 1.
    let mut a: Vec<Vec<T>> = (0..dim)
        .map(|k| {
            subset
                .iter()
                .map(|&s| points[distinct[s]].coords()[k].clone())
                .collect()
        })
        .collect();
    a.push(vec![T::one(); subset.len()]);
    let mut b: Vec<T> = p.coords().to_vec();
    b.push(T::one());
    match solve_consistent(&a, &b) {
        Ok(Some(w)) if w.iter().all(|c| *c >= T::zero()) => Ok(Some(w)),
        Ok(_) => Ok(None),
        Err(Error::Singular(_)) => Ok(None), // affinely dependent: a smaller subset covers it
        Err(e) => Err(e),
    }
}

/// The next `k`-subset of `0..m` in lexicographic order (`false` after the last).
pub(crate) fn next_subset(subset: &mut [usize], m: usize) -> bool {
    let k = subset.len();
    for i in (0..k).rev() {
        if subset[i] < m - k + i {
            subset[i] += 1;
            for j in i + 1..k {
                subset[j] = subset[j - 1] + 1;
            }
            return true;
        }
    }
    false
}

fn choose(n: u128, k: u128) -> u128 {
    if k > n {
        return 0;
    }
    let mut acc: u128 = 1;
    for i in 0..k {
        acc = acc.saturating_mul(n - i) / (i + 1);
    }
    acc
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Ring;
    use num_rational::BigRational;
    type Q = BigRational;

    fn pts(c: &[&[i64]]) -> Vec<Point<Q>> {
        c.iter().map(|c| Point::from_ints(c).unwrap()).collect()
    }

    #[test]
    fn certificate_reproduces_the_point() {
        let square = pts(&[&[0, 0], &[2, 0], &[2, 2], &[0, 2]]);
        let p = Point::from_ints(&[1, 1]).unwrap();
        let w = convex_weights(&square, &p).unwrap().unwrap();
        assert_eq!(crate::point::barycentric(&square, &w).unwrap(), p);
        assert!(w.iter().all(|c| *c >= Q::from_i64(0)));
    }

    #[test]
    fn boundary_inside_outside() {
        let tet = pts(&[&[0, 0, 0], &[1, 0, 0], &[0, 1, 0], &[0, 0, 1]]);
        assert!(hull_contains(&tet, &Point::from_ints(&[0, 0, 0]).unwrap()).unwrap());
        let face = Point::new(vec![
            Q::from_ratio(1, 3).unwrap(),
            Q::from_ratio(1, 3).unwrap(),
            Q::from_ratio(1, 3).unwrap(),
        ])
        .unwrap();
        assert!(hull_contains(&tet, &face).unwrap());
        let out = Point::new(vec![
            Q::from_ratio(1, 3).unwrap(),
            Q::from_ratio(1, 3).unwrap(),
            Q::from_ratio(1, 3).unwrap() + Q::from_ratio(1, 1_000_000).unwrap(),
        ])
        .unwrap();
        assert!(!hull_contains(&tet, &out).unwrap());
        // Collinear points in 2D: the hull is a segment.
        let seg = pts(&[&[0, 0], &[1, 1], &[3, 3]]);
        assert!(hull_contains(&seg, &Point::from_ints(&[2, 2]).unwrap()).unwrap());
        assert!(!hull_contains(&seg, &Point::from_ints(&[2, 1]).unwrap()).unwrap());
    }

    #[test]
    fn bad_input() {
        assert!(hull_contains::<Q>(&[], &Point::from_ints(&[0]).unwrap()).is_err());
        assert!(hull_contains(&pts(&[&[0, 0]]), &Point::from_ints(&[0]).unwrap()).is_err());
    }
}
