//! Arithmetic modulo the prime `2^61 − 1`, for a quick pass over a linear system of the
//! telescoping search: most of its systems have no solution, which this says far faster than
//! exact elimination.

use num_bigint::{BigInt, Sign};
use num_rational::BigRational;
use num_traits::ToPrimitive;

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

/// Whether the system (its last column the right-hand side) may have a solution — with
/// `given` false, a null vector whose first `first_free` entries are not all zero — and if
/// so, rows spanning it modulo the prime. `None` is then also the answer over Q (a rational
/// solution reduces to one modulo the prime, unless the prime divides a denominator or
/// every entry of its first part: a candidate is then merely missed); every row when the
/// data does not reduce.
pub(super) fn may_solve(a: &[Vec<BigRational>], given: bool, first_free: usize) -> Option<Vec<usize>> {
    let all = || Some((0..a.len()).collect());
    let Some(mut m) = a
        .iter()
        .map(|r| r.iter().map(reduce).collect::<Option<Vec<u64>>>())
        .collect::<Option<Vec<Vec<u64>>>>()
    else {
        return all();
    };
    let mut origin: Vec<usize> = (0..m.len()).collect();
    let width = m.first().map_or(0, Vec::len);
    let mut pivots = Vec::new();
    for col in 0..width {
        let row = pivots.len();
        let Some(p) = (row..m.len()).find(|&r| m[r][col] != 0) else {
            continue;
        };
        m.swap(row, p);
        origin.swap(row, p);
        let inv = inverse(m[row][col]);
        m[row].iter_mut().for_each(|x| *x = mul(*x, inv));
        let pivot_row = m[row].clone();
        for (r, other) in m.iter_mut().enumerate() {
            let f = other[col];
            if r == row || f == 0 {
                continue;
            }
            for (x, y) in other.iter_mut().zip(&pivot_row) {
                *x = (*x + PRIME - mul(f, *y)) % PRIME;
            }
        }
        pivots.push(col);
        if pivots.len() == m.len() {
            break;
        }
    }
    let solvable = if given {
        !pivots.contains(&(width - 1))
    } else {
        (0..width - 1)
            .filter(|c| !pivots.contains(c))
            .any(|f| f < first_free || pivots.iter().enumerate().any(|(r, &p)| p < first_free && m[r][f] != 0))
    };
    solvable.then(|| origin[..pivots.len()].to_vec())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rows(r: &[&[i64]]) -> Vec<Vec<BigRational>> {
        r.iter()
            .map(|row| row.iter().map(|&x| BigRational::from_integer(x.into())).collect())
            .collect()
    }

    #[test]
    fn decides_solvability_and_picks_spanning_rows() {
        // x + y = 2, 2x + 2y = 5: inconsistent.
        assert_eq!(may_solve(&rows(&[&[1, 1, 2], &[2, 2, 5]]), true, 0), None);
        // x = 1, y = 2, x + y = 3: consistent, two rows span it.
        assert_eq!(
            may_solve(&rows(&[&[1, 0, 1], &[0, 1, 2], &[1, 1, 3]]), true, 0).map(|b| b.len()),
            Some(2)
        );
        // x − y = 0: the null vector (1, 1) has x ≠ 0; with x = 0 forced, none has.
        assert!(may_solve(&rows(&[&[1, -1, 0]]), false, 1).is_some());
        assert_eq!(may_solve(&rows(&[&[1, 0, 0], &[0, 1, 0]]), false, 1), None);
        // A fraction reduces through its inverse: x/2 = 1/2 ⇔ x = 1.
        let half = BigRational::new(1.into(), 2.into());
        assert!(may_solve(&[vec![half.clone(), half]], true, 0).is_some());
    }
}
