//! Lehmer's gcd of numbers of a few words, on little-endian `u64` limbs.
//!
//! Euclid's algorithm on numbers of a few hundred bits spends its time in multi-word
//! divisions whose quotients are almost all below 4. Lehmer's algorithm (Knuth, TAOCP vol. 2,
//! 4.5.2) runs Euclid on the leading 61 bits of both numbers instead, for as long as the
//! quotients are certainly those of the whole numbers (Jebelean's condition), collecting
//! them in a 2×2 cofactor matrix, and then applies the matrix to the whole numbers in one
//! pass — about 30 bits of both numbers per pass, with word arithmetic in between. A pass
//! that finds no certain quotient (a first quotient beyond a word) takes one long division instead.
//!
//! The matrix is applied into scratch buffers and checked: a result that would be negative
//! (which the condition rules out), or a pass that does not shrink the smaller number, is
//! not used, and a long division is taken instead. The matrix is a product of Euclid steps
//! (determinant ±1), so two nonnegative results have the gcd of the inputs: the answer is
//! right and the loop ends whatever the cofactors.

use super::{gcd_u128, gcd_u64};
use num_bigint::BigUint;

/// `gcd(a, b)` of natural numbers given as little-endian limbs (high zero limbs allowed),
/// as limbs without high zeros (empty for 0).
pub(super) fn gcd_limbs(mut a: Vec<u64>, mut b: Vec<u64>) -> Vec<u64> {
    trim(&mut a);
    trim(&mut b);
    if less(&a, &b) {
        std::mem::swap(&mut a, &mut b);
    }
    let (mut next_a, mut next_b) = (Vec::with_capacity(a.len()), Vec::with_capacity(a.len()));
    loop {
        // a ≥ b here.
        match (a.len(), b.len()) {
            (_, 0) => return a,
            (1, _) => return vec![gcd_u64(a[0], b[0])],
            (_, 1) => return vec![gcd_u64(b[0], rem_word(&a, b[0]))],
            (2, _) => {
                let g = gcd_u128(
                    u128::from(a[0]) | (u128::from(a[1]) << 64),
                    u128::from(b[0]) | (u128::from(b[1]) << 64),
                );
                return limbs_of_u128(g);
            }
            _ => {}
        }
        // A pass must shrink the smaller number (each Euclid step does): a check that costs
        // a comparison and makes termination independent of the cofactors' test.
        let stepped =
            cofactors(&a, &b).is_some_and(|m| apply(&m, &a, &b, &mut next_a, &mut next_b) && less(&next_b, &b));
        if stepped {
            std::mem::swap(&mut a, &mut next_a);
            std::mem::swap(&mut b, &mut next_b);
            if less(&a, &b) {
                std::mem::swap(&mut a, &mut b);
            }
        } else {
            // (a, b) ← (b, a mod b).
            let r = rem_long(&a, &b);
            a = std::mem::replace(&mut b, r);
        }
    }
}

fn trim(x: &mut Vec<u64>) {
    while x.last() == Some(&0) {
        x.pop();
    }
}

/// `x < y` for limbs without high zeros.
fn less(x: &[u64], y: &[u64]) -> bool {
    x.len() < y.len() || (x.len() == y.len() && x.iter().rev().lt(y.iter().rev()))
}

fn limbs_of_u128(x: u128) -> Vec<u64> {
    let mut limbs = vec![x as u64, (x >> 64) as u64];
    trim(&mut limbs);
    limbs
}

/// `x mod m` for one word `m > 0`.
fn rem_word(x: &[u64], m: u64) -> u64 {
    let m = u128::from(m);
    x.iter().rev().fold(0u128, |r, &w| ((r << 64) | u128::from(w)) % m) as u64
}

/// `x mod y` by num-bigint's long division (taken once per unbalanced pair, or when a pass
/// finds no quotient).
fn rem_long(x: &[u64], y: &[u64]) -> Vec<u64> {
    let big = |limbs: &[u64]| BigUint::new(limbs.iter().flat_map(|&w| [w as u32, (w >> 32) as u32]).collect());
    let mut r = (big(x) % big(y)).to_u64_digits();
    trim(&mut r);
    r
}

/// The cofactor matrix `[[A, B], [C, D]]` of the quotients of Euclid's algorithm on the
/// leading 61 bits `x` of `a` and `y` of `b` (shifted alike) that are certainly quotients
/// of `a`, `b` themselves: the next pair is `(A a + B b, C a + D b)`. `None` when not even
/// the first one is.
///
/// Jebelean's condition (Jebelean 1993, "Improving the multiprecision Euclidean
/// algorithm"): with `r_i = u_i x + v_i y` the remainders, the quotient that makes `r_{i+1}`
/// is kept while `r_{i+1} ≥ |u_{i+1}|, |v_{i+1}|` and `r_i − r_{i+1} ≥ |u_{i+1} − u_i|,
/// |v_{i+1} − v_i|` (both cofactors tested, where the paper tests one by parity: stricter,
/// so still sufficient) — one quotient and comparisons per step, where Knuth's test takes
/// two quotients. Below 2^61, every cofactor and difference fits an `i64`: an accepted
/// `|u_i| ≤ r_i`, so `|q u_i| ≤ r_{i−1} < 2^61`.
fn cofactors(a: &[u64], b: &[u64]) -> Option<[i64; 4]> {
    let n = a.len();
    let shift = a[n - 1].leading_zeros();
    let top = |x: &[u64]| {
        let high = x.get(n - 1).copied().unwrap_or(0);
        let low = x.get(n - 2).copied().unwrap_or(0);
        let word = if shift == 0 {
            high
        } else {
            (high << shift) | (low >> (64 - shift))
        };
        (word >> 3) as i64
    };
    let (mut r0, mut r1) = (top(a), top(b));
    let (mut u0, mut u1, mut v0, mut v1) = (1i64, 0i64, 0i64, 1i64);
    while r1 > 0 {
        let q = quotient(r0 as u64, r1 as u64) as i64;
        let (r2, u2, v2) = (r0 - q * r1, u0 - q * u1, v0 - q * v1);
        if r2 < u2.abs().max(v2.abs()) || r1 - r2 < (u2 - u1).abs().max((v2 - v1).abs()) {
            break;
        }
        (r0, r1, u0, u1, v0, v1) = (r1, r2, u1, u2, v1, v2);
    }
    (v0 != 0).then_some([u0, v0, u1, v1])
}

/// `⌊x / y⌋`, `y > 0`: Euclid's quotients are mostly 1 to 3, found by subtraction.
fn quotient(x: u64, y: u64) -> u64 {
    let r = x.wrapping_sub(y);
    if x < y {
        0
    } else if r < y {
        1
    } else if r - y < y {
        2
    } else {
        x / y
    }
}

/// `(A a + B b, C a + D b)` into `next_a`, `next_b`; false (and the buffers unspecified) when
/// either would be negative.
fn apply(m: &[i64; 4], a: &[u64], b: &[u64], next_a: &mut Vec<u64>, next_b: &mut Vec<u64>) -> bool {
    combine(m[0], m[1], a, b, next_a) && combine(m[2], m[3], a, b, next_b)
}

/// `out ← p a + q b`, for `p`, `q` of opposite signs (or one zero), magnitudes below 2^64:
/// the positive product minus the negative one, limb by limb with a carry for each and a
/// borrow between them. False when the result would be negative.
fn combine(p: i64, q: i64, a: &[u64], b: &[u64], out: &mut Vec<u64>) -> bool {
    let (pm, qm) = (p.unsigned_abs(), q.unsigned_abs());
    if p < 0 && q < 0 || p > 0 && q > 0 {
        return false;
    }
    // (plus, of_a): the positive cofactor and whether it multiplies `a`.
    let (plus, minus, plus_on_a) = if p >= 0 { (pm, qm, true) } else { (qm, pm, false) };
    out.clear();
    let (mut carry_plus, mut carry_minus, mut borrow) = (0u64, 0u64, false);
    for i in 0..a.len() {
        let (ai, bi) = (a[i], b.get(i).copied().unwrap_or(0));
        let (on_plus, on_minus) = if plus_on_a { (ai, bi) } else { (bi, ai) };
        let positive = u128::from(plus) * u128::from(on_plus) + u128::from(carry_plus);
        let negative = u128::from(minus) * u128::from(on_minus) + u128::from(carry_minus);
        let (d, b1) = (positive as u64).overflowing_sub(negative as u64);
        let (d, b2) = d.overflowing_sub(u64::from(borrow));
        out.push(d);
        (carry_plus, carry_minus, borrow) = ((positive >> 64) as u64, (negative >> 64) as u64, b1 | b2);
    }
    // The words above `a`'s: the result is nonnegative only if they come to zero.
    let (d, b1) = carry_plus.overflowing_sub(carry_minus);
    let (d, b2) = d.overflowing_sub(u64::from(borrow));
    if b1 || b2 {
        return false;
    }
    if d != 0 {
        out.push(d);
    }
    trim(out);
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_integer::Integer;
    use proptest::prelude::*;

    fn big(limbs: &[u64]) -> BigUint {
        BigUint::new(limbs.iter().flat_map(|&w| [w as u32, (w >> 32) as u32]).collect())
    }

    fn check(a: &BigUint, b: &BigUint) -> Result<(), TestCaseError> {
        let got = big(&gcd_limbs(a.to_u64_digits(), b.to_u64_digits()));
        prop_assert_eq!(got, Integer::gcd(a, b), "{} {}", a, b);
        Ok(())
    }

    /// Numbers of 0 to 22 limbs of every shape Lehmer's passes meet: zero, one, powers of
    /// two, all ones, top words equal or nearly (long runs of quotient 1), random.
    fn number() -> impl Strategy<Value = BigUint> {
        prop_oneof![
            Just(BigUint::from(0u8)),
            Just(BigUint::from(1u8)),
            (0u64..1400).prop_map(|k| BigUint::from(1u8) << k),
            (1u64..1400).prop_map(|k| (BigUint::from(1u8) << k) - 1u8),
            proptest::collection::vec(any::<u64>(), 0..23).prop_map(|l| big(&l)),
            (proptest::collection::vec(any::<u64>(), 1..12), 0u64..700).prop_map(|(l, s)| big(&l) << s),
        ]
    }

    /// Consecutive Fibonacci numbers: every quotient 1, the longest Euclid runs.
    fn fibonacci(k: usize) -> (BigUint, BigUint) {
        let (mut x, mut y) = (BigUint::from(0u8), BigUint::from(1u8));
        for _ in 0..k {
            (x, y) = (y.clone(), x + y);
        }
        (x, y)
    }

    #[test]
    fn edge_cases_are_euclids() {
        let zero = BigUint::from(0u8);
        let one = BigUint::from(1u8);
        let long = big(&[u64::MAX; 9]);
        for (a, b) in [
            (&zero, &zero),
            (&zero, &long),
            (&long, &zero),
            (&one, &long),
            (&long, &long),
        ] {
            check(a, b).unwrap();
        }
        for k in [100, 200, 500, 1000, 1800] {
            let (x, y) = fibonacci(k);
            check(&x, &y).unwrap();
            check(&(&x * 3u8), &(&y * 3u8)).unwrap();
        }
        // A quotient beyond a word in the middle of the run.
        let x = big(&[7, 0, 0, 1 << 40, 5]);
        check(&(&x * 12345u32 + 1u8), &x).unwrap();
    }

    proptest! {
        #[test]
        fn gcd_limbs_is_num_bigints(a in number(), b in number(), c in number()) {
            check(&a, &b)?;
            // A common factor of any length, and very unbalanced sizes.
            check(&(&a * &c), &(&b * &c))?;
            check(&(&a * &c * &c), &c)?;
            check(&a, &a)?;
        }
    }
}
