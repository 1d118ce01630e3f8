//! Arithmetic modulo the prime `2^61 − 1`, for a quick pass over a linear system of the
//! telescoping search: most of its systems have no solution, which this says far faster than
//! exact elimination.

use num_bigint::{BigInt, Sign};
use num_rational::BigRational;
use num_traits::ToPrimitive;

use super::Row;

const PRIME: u64 = (1 << 61) - 1;

/// `a · b mod PRIME` for `a, b < PRIME`, by the Mersenne folding `2^61 ≡ 1` (no division).
fn mul(a: u64, b: u64) -> u64 {
    let x = u128::from(a) * u128::from(b);
    let folded = (x as u64 & PRIME) + (x >> 61) as u64;
    let r = (folded & PRIME) + (folded >> 61);
    if r >= PRIME {
        r - PRIME
    } else {
        r
    }
}

/// `a − b mod PRIME` for `a, b < PRIME`.
fn sub(a: u64, b: u64) -> u64 {
    if a >= b {
        a - b
    } else {
        a + PRIME - b
    }
}

fn inverse(a: u64) -> u64 {
    let (mut base, mut e, mut out) = (a, PRIME - 2, 1u64);
    while e > 0 {
        if e & 1 == 1 {
            out = mul(out, base);
        }
        base = mul(base, base);
        e >>= 1;
    }
    out
}

fn reduce(x: &BigRational) -> Option<u64> {
    let n = residue(x.numer());
    match residue(x.denom()) {
        0 => None,
        _ if n == 0 => Some(0),
        1 => Some(n),
        d => Some(mul(n, inverse(d))),
    }
}

/// `v mod PRIME`, digit by digit (most entries of a system are 0 or small).
fn residue(v: &BigInt) -> u64 {
    if let Some(small) = v.to_i64() {
        return small.rem_euclid(PRIME as i64) as u64;
    }
    let (sign, digits) = v.to_u64_digits();
    let r = digits.iter().rev().fold(0u64, |acc, &d| {
        (((u128::from(acc) << 64) | u128::from(d)) % u128::from(PRIME)) as u64
    });
    if sign == Sign::Minus && r != 0 {
        PRIME - r
    } else {
        r
    }
}

/// Whether the system (its rows sparse, `width` columns, the last the right-hand side) may
/// have a solution — with `given` false, a null vector whose first `first_free` entries are
/// not all zero — and if so, rows spanning it modulo the prime. `None` is then also the answer
/// over Q (a rational solution reduces to one modulo the prime, unless the prime divides a
/// denominator or every entry of its first part: a candidate is then merely missed); every
/// row when the data does not reduce.
///
/// The rows are taken one at a time against a reduced basis of those before (at most `width`
/// rows of `width` entries), so the memory is that of the basis and an inconsistent system
/// stops at the first row that shows it.
pub(super) fn may_solve(a: &[Row], width: usize, given: bool, first_free: usize) -> Option<Vec<usize>> {
    let all = || Some((0..a.len()).collect());
    // (pivot column, row scaled to 1 there and 0 at every other pivot, its index in `a`).
    let mut basis: Vec<(usize, Vec<u64>, usize)> = Vec::new();
    let mut pivot_of: Vec<Option<usize>> = vec![None; width];
    for (index, sparse) in a.iter().enumerate() {
        let mut row = vec![0u64; width];
        for (j, x) in sparse {
            let Some(r) = reduce(x) else {
                return all();
            };
            row[*j] = r;
        }
        // A basis row is 0 at every other pivot, so reducing by it changes no other pivot
        // column: the row's own entries say which basis rows to reduce by.
        for (j, _) in sparse {
            let Some(at) = pivot_of[*j] else { continue };
            let f = row[*j];
            if f != 0 {
                for (x, y) in row.iter_mut().zip(&basis[at].1) {
                    *x = sub(*x, mul(f, *y));
                }
            }
        }
        let Some(col) = row.iter().position(|&x| x != 0) else {
            continue;
        };
        if given && col == width - 1 {
            // 0 = c ≠ 0: no solution.
            return None;
        }
        let inv = inverse(row[col]);
        row.iter_mut().for_each(|x| *x = mul(*x, inv));
        for (_, b, _) in &mut basis {
            let f = b[col];
            if f != 0 {
                for (x, y) in b.iter_mut().zip(&row) {
                    *x = sub(*x, mul(f, *y));
                }
            }
        }
        pivot_of[col] = Some(basis.len());
        basis.push((col, row, index));
        if basis.len() == width {
            break;
        }
    }
    let is_pivot = |c: usize| pivot_of[c].is_some();
    let solvable = if given {
        !is_pivot(width - 1)
    } else {
        (0..width - 1)
            .filter(|&c| !is_pivot(c))
            .any(|f| f < first_free || basis.iter().any(|(p, b, _)| *p < first_free && b[f] != 0))
    };
    solvable.then(|| basis.iter().map(|(_, _, i)| *i).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rows(r: &[&[i64]]) -> Vec<Row> {
        r.iter()
            .map(|row| {
                row.iter()
                    .enumerate()
                    .filter(|(_, &x)| x != 0)
                    .map(|(j, &x)| (j, BigRational::from_integer(x.into())))
                    .collect()
            })
            .collect()
    }

    #[test]
    fn decides_solvability_and_picks_spanning_rows() {
        // x + y = 2, 2x + 2y = 5: inconsistent.
        assert_eq!(may_solve(&rows(&[&[1, 1, 2], &[2, 2, 5]]), 3, true, 0), None);
        // x = 1, y = 2, x + y = 3: consistent, two rows span it.
        assert_eq!(
            may_solve(&rows(&[&[1, 0, 1], &[0, 1, 2], &[1, 1, 3]]), 3, true, 0).map(|b| b.len()),
            Some(2)
        );
        // x − y = 0: the null vector (1, 1) has x ≠ 0; with x = 0 forced, none has.
        assert!(may_solve(&rows(&[&[1, -1, 0]]), 3, false, 1).is_some());
        assert_eq!(may_solve(&rows(&[&[1, 0, 0], &[0, 1, 0]]), 3, false, 1), None);
        // A fraction reduces through its inverse: x/2 = 1/2 ⇔ x = 1.
        let half = BigRational::new(1.into(), 2.into());
        assert!(may_solve(&[vec![(0, half.clone()), (1, half)]], 2, true, 0).is_some());
    }
}
