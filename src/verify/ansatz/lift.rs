//! The solution of a solvable system of the certificate searches by elimination modulo a few
//! primes, combined by the Chinese remainder theorem and lifted to rationals (rational
//! reconstruction), instead of exact elimination over Q, whose numbers grow with every pivot.
//!
//! The lifted vector is the one exact elimination returns (the reduced row echelon form is
//! unique, so is the solution with every free entry 0 but one) whenever the primes divide no
//! pivot of it; it is returned only after it satisfies every row exactly, so a lift gone wrong
//! is a fall back to exact elimination, never a wrong solution. Nothing lifted is trusted
//! anyway: the kernel checks every certificate built from it.

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

use super::Row;

/// The primes tried, the six largest below `2^62` (so that a sum of two residues fits in a `u64`).
const PRIMES: [u64; 6] = [
    4_611_686_018_427_387_847,
    4_611_686_018_427_387_817,
    4_611_686_018_427_387_787,
    4_611_686_018_427_387_761,
    4_611_686_018_427_387_751,
    4_611_686_018_427_387_737,
];

fn mul(a: u64, b: u64, p: u64) -> u64 {
    (u128::from(a) * u128::from(b) % u128::from(p)) as u64
}

fn sub(a: u64, b: u64, p: u64) -> u64 {
    if a >= b {
        a - b
    } else {
        a + p - b
    }
}

fn power(mut base: u64, mut e: u64, p: u64) -> u64 {
    let mut out = 1;
    while e > 0 {
        if e & 1 == 1 {
            out = mul(out, base, p);
        }
        base = mul(base, base, p);
        e >>= 1;
    }
    out
}

fn residue(v: &BigInt, p: u64) -> u64 {
    let m = BigInt::from(p);
    v.mod_floor(&m).to_u64().unwrap_or(0)
}

/// `x mod p`, `None` when `p` divides its denominator.
fn reduce(x: &BigRational, p: u64) -> Option<u64> {
    let d = residue(x.denom(), p);
    (d != 0).then(|| mul(residue(x.numer(), p), power(d, p - 2, p), p))
}

/// The solution modulo `p` (as [`super::exact`] picks it) and the pivot columns and free
/// column that determine it; `None` when there is none modulo `p` or `p` divides a
/// denominator.
fn solve_mod(a: &[&Row], width: usize, given: bool, first_free: usize, p: u64) -> Option<(Vec<u64>, Vec<usize>)> {
    let mut m = Vec::with_capacity(a.len());
    for sparse in a {
        let mut row = vec![0u64; width];
        for (j, x) in sparse.iter() {
            row[*j] = reduce(x, p)?;
        }
        m.push(row);
    }
    let mut pivots = Vec::new();
    let mut at = 0;
    for col in 0..width {
        if at == m.len() {
            break;
        }
        let Some(r) = (at..m.len()).find(|&r| m[r][col] != 0) else {
            continue;
        };
        m.swap(at, r);
        let inv = power(m[at][col], p - 2, p);
        m[at].iter_mut().for_each(|x| *x = mul(*x, inv, p));
        let pivot_row = m[at].clone();
        for (r, other) in m.iter_mut().enumerate() {
            let f = other[col];
            if r == at || f == 0 {
                continue;
            }
            for (x, y) in other.iter_mut().zip(&pivot_row).skip(col) {
                *x = sub(*x, mul(f, *y, p), p);
            }
        }
        pivots.push(col);
        at += 1;
    }
    let mut x = vec![0u64; width - 1];
    if given {
        if pivots.contains(&(width - 1)) {
            return None;
        }
        for (r, &c) in pivots.iter().enumerate() {
            x[c] = m[r][width - 1];
        }
        let mut key = pivots;
        key.push(width);
        return Some((x, key));
    }
    for f in (0..width - 1).filter(|c| !pivots.contains(c)) {
        x.iter_mut().for_each(|v| *v = 0);
        x[f] = 1;
        for (r, &c) in pivots.iter().enumerate() {
            x[c] = sub(0, m[r][f], p);
        }
        if x[..first_free].iter().any(|&v| v != 0) {
            let mut key = pivots;
            key.push(f);
            return Some((x, key));
        }
    }
    None
}

/// The fraction `n/d` with `|n|, d ≤ √(m/2)` and `n ≡ u·d (mod m)`, if there is one.
fn rational(u: &BigInt, m: &BigInt) -> Option<BigRational> {
    let bound = (m / 2u32).sqrt();
    let (mut r0, mut r1) = (m.clone(), u.clone());
    let (mut t0, mut t1) = (BigInt::zero(), BigInt::one());
    while r1 > bound {
        let q = &r0 / &r1;
        let r2 = &r0 - &q * &r1;
        let t2 = &t0 - &q * &t1;
        (r0, r1, t0, t1) = (r1, r2, t1, t2);
    }
    if t1.is_zero() || t1.abs() > bound || !r1.gcd(&t1).is_one() {
        return None;
    }
    Some(BigRational::new(r1, t1))
}

/// The solution of the rows `basis` of `a` (see [`super::solve`]) lifted from its values
/// modulo [`PRIMES`], checked on every row of `a`; `None` when no lift up to the last prime
/// satisfies them (the caller then eliminates exactly).
pub(super) fn solve(
    a: &[Row],
    basis: &[usize],
    width: usize,
    given: bool,
    first_free: usize,
) -> Option<Vec<BigRational>> {
    let rows: Vec<&Row> = basis.iter().map(|&r| &a[r]).collect();
    let mut modulus = BigInt::one();
    let mut values: Vec<BigInt> = Vec::new();
    let mut shape: Option<Vec<usize>> = None;
    for &p in &PRIMES {
        let (x, key) = solve_mod(&rows, width, given, first_free, p)?;
        // Another pivot set: one of the primes divides a pivot; exact elimination decides.
        if shape.get_or_insert_with(|| key.clone()) != &key {
            return None;
        }
        // Chinese remainders: v ≡ old (mod modulus), v ≡ x (mod p).
        let big_p = BigInt::from(p);
        let inv = BigInt::from(power(residue(&modulus, p), p - 2, p));
        if values.is_empty() {
            values = x.iter().map(|&v| BigInt::from(v)).collect();
        } else {
            for (old, &new) in values.iter_mut().zip(&x) {
                let diff = (BigInt::from(new) - &*old).mod_floor(&big_p);
                let step = (diff * &inv).mod_floor(&big_p);
                *old += step * &modulus;
            }
        }
        modulus *= &big_p;
        let lifted: Option<Vec<BigRational>> = values.iter().map(|v| rational(v, &modulus)).collect();
        if let Some(x) = lifted {
            if a.iter().all(|row| super::satisfied(row, width, &x)) {
                return Some(x);
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn is_prime(p: u64) -> bool {
        // Deterministic Miller–Rabin for 64-bit numbers.
        let (mut d, mut s) = (p - 1, 0);
        while d % 2 == 0 {
            d /= 2;
            s += 1;
        }
        [2u64, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37].iter().all(|&a| {
            let mut x = power(a % p, d, p);
            if x == 1 || x == p - 1 {
                return true;
            }
            (1..s).any(|_| {
                x = mul(x, x, p);
                x == p - 1
            })
        })
    }

    fn rat(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    fn rows(r: &[&[BigRational]]) -> Vec<Row> {
        r.iter()
            .map(|row| {
                row.iter()
                    .enumerate()
                    .filter(|(_, x)| !x.is_zero())
                    .map(|(j, x)| (j, x.clone()))
                    .collect()
            })
            .collect()
    }

    #[test]
    fn the_primes_are_primes_below_2_to_the_62() {
        for p in PRIMES {
            assert!(is_prime(p) && p < 1 << 62, "{p}");
        }
        assert!(!is_prime(PRIMES[0] - 2));
    }

    #[test]
    fn lifts_what_exact_elimination_finds() {
        // x/3 + y = 1, 2x − y/5 = 7/2: one solution, with large numerators after CRT.
        let a = rows(&[&[rat(1, 3), rat(1, 1), rat(1, 1)], &[rat(2, 1), rat(-1, 5), rat(7, 2)]]);
        let mut dense: Vec<Vec<BigRational>> = a
            .iter()
            .map(|r| {
                let mut v = vec![BigRational::zero(); 3];
                for (j, x) in r {
                    v[*j] = x.clone();
                }
                v
            })
            .collect();
        let exact = super::super::exact(&mut dense, true, 0).unwrap();
        assert_eq!(solve(&a, &[0, 1], 3, true, 0), exact);
        // Homogeneous: x − 2y + 0z = 0, z = 0; the null vector with y = 1 (y is the first free
        // column) is (2, 1, 0).
        let h = rows(&[
            &[rat(1, 1), rat(-2, 1), rat(0, 1), rat(0, 1)],
            &[rat(0, 1), rat(0, 1), rat(1, 1), rat(0, 1)],
        ]);
        assert_eq!(
            solve(&h, &[0, 1], 4, false, 1),
            Some(vec![rat(2, 1), rat(1, 1), rat(0, 1)])
        );
        // A solution whose entries pass one prime's reconstruction bound (2^31) needs several.
        let big = BigRational::new(BigInt::from(3).pow(50), BigInt::from(7).pow(30));
        let s = rows(&[&[rat(1, 1), big.clone()]]);
        assert_eq!(solve(&s, &[0], 2, true, 0), Some(vec![big]));
        // Inconsistent modulo every prime: none.
        let bad = rows(&[&[rat(1, 1), rat(1, 1)], &[rat(2, 1), rat(3, 1)]]);
        assert_eq!(solve(&bad, &[0, 1], 2, true, 0), None);
    }
}
