//! `gcd(N, f)` for each factor `f` of a long number's denominator, without a division or
//! a gcd of `N`'s length: each odd factor of two words or more takes Hensel's remainder
//! (Montgomery's reduction, GMP's `redc`) `R ≡ N · 2^(−64 s) (mod f)`, where `2^(−64 s)` is
//! a unit, so that `gcd(f, R) = gcd(f, N)` is a gcd of the factor's length. A row of the
//! remainder is one word times the factor added in: no quotient to estimate, where long
//! division corrects one a word (dashu-int's and num-bigint's remainders of a 7,000-bit
//! number by 21 factors of 333 bits took 36 µs, these 11 µs; 2026-12-06).
//!
//! The powers of two are taken apart by trailing zeros, and the odd part of a factor of one
//! word takes Hensel's remainder by a word ([`gcd_odd_word`]).

use num_bigint::{BigInt, BigUint};
use num_traits::{One, ToPrimitive, Zero};

use crate::exact::gcd::{self, gcd_u128, gcd_u64};

/// Whether `gcd(N, Π f)` of `factors` factors of `bits` bits in all takes
/// [`factor_gcds`] rather than one gcd or a remainder tree: two factors or more, of two
/// words or more on average, 3,000 to 24,000 bits in all. The remainders take about
/// `bits² / 64²` products of words; past that size the remainder tree's divisions, on
/// dashu-int's subquadratic products, cost less, and below it one gcd is as fast.
/// Measured against both (2026-12-06, every eval, rational eval and surface eval cell of
/// `exact_grid` to degree 200, two alternating runs each): 4 to 21 factors of 1,000 bits
/// and 21 to 51 of 333 bits took 4% to 16% less time; 4 of 333 bits 6% to 8% more; 51 of
/// 1,000 bits 6% to 10% more, 201 of 333 bits 6% to 20% more, and the 441 factors of a
/// 100-digit degree-(20, 20) surface 22% to 26% more; factors of 100 bits (30-digit
/// denominators) up to 24% more (docs/performance.md, "The final gcd by factors").
pub(crate) fn pays(factors: usize, bits: u64) -> bool {
    factors >= 2 && bits >= 128 * factors as u64 && (LEAST_BITS..=24_000).contains(&bits)
}

/// The fewest bits of a product for [`pays`].
pub(crate) const LEAST_BITS: u64 = 3_000;

/// `−f⁻¹ mod 2^64` for an odd `f`: Newton's steps from an inverse to 5 bits
/// (`3 f ⊕ 2`), each doubling the bits.
fn negated_inverse(f: u64) -> u64 {
    debug_assert!(f % 2 == 1);
    let mut x = f.wrapping_mul(3) ^ 2;
    for _ in 0..4 {
        x = x.wrapping_mul(2u64.wrapping_sub(f.wrapping_mul(x)));
    }
    x.wrapping_neg()
}

/// `gcd(x, m)` for an odd `m > 1`: Hensel's remainder by a word (GMP's
/// `mpn_modexact_1_odd`), two products a word where a remainder by a word past 32 bits
/// chains 128-bit divisions (a call each). For the words `s_i` of `x` from the lowest, with
/// `c_0 = 0`: `l = (s_i − c_i) m⁻¹ mod 2^64` and `c_{i+1}` the high word of `l m` plus the
/// borrow, so that `s_i = c_i + l m − c_{i+1} 2^64` and `x ≡ −c_k 2^(64 k) (mod m)`: `gcd(m,
/// x) = gcd(m, c_k)`, `c_k ≤ m`.
pub(crate) fn gcd_odd_word(x: &BigUint, m: u64) -> u64 {
    debug_assert!(m % 2 == 1 && m > 1);
    let inverse = negated_inverse(m).wrapping_neg();
    let c = x.iter_u64_digits().fold(0u64, |c, s| {
        let (s, borrow) = s.overflowing_sub(c);
        let l = s.wrapping_mul(inverse);
        ((u128::from(l) * u128::from(m)) >> 64) as u64 + u64::from(borrow)
    });
    gcd_u64(m, c)
}

/// One row of the remainder: `t += u · f` (as long as `f`), clearing `t[0]`; the row's
/// carry-out. Inlined where the length is a constant, the row is unrolled.
#[inline(always)]
fn row(t: &mut [u64], f: &[u64], u: u64) -> u64 {
    let mut carry = 0u64;
    for (r, &w) in t.iter_mut().zip(f) {
        let v = u128::from(u) * u128::from(w) + u128::from(*r) + u128::from(carry);
        *r = v as u64;
        carry = (v >> 64) as u64;
    }
    carry
}

/// Hensel's remainder of `t` (the dividend's words and one zero word on top) by the odd
/// `m`-word `f`, whose rows `add_row` adds: `t`'s words from `s = len − 1 − m` on hold
/// `R ≡ N · 2^(−64 s) (mod f)`, `R < 2^(64 m) + f` (`N + Σ u_i f 2^(64 i) < 2^(64 (len − 1))
/// + 2^(64 s) f`).
#[inline(always)]
fn remainder_by(t: &mut [u64], m: usize, f0: u64, add_row: impl Fn(&mut [u64], u64) -> u64) -> usize {
    let steps = t.len() - 1 - m;
    let negated = negated_inverse(f0);
    // Each row's carry-out goes into the word above the row, and that addition's own carry
    // (one bit) into the next row's: the rows stay m words long.
    let mut pending = 0u64;
    for i in 0..steps {
        let (head, rest) = t[i..].split_at_mut(m);
        let u = head[0].wrapping_mul(negated);
        let carry = add_row(head, u);
        let (s, c1) = rest[0].overflowing_add(carry);
        let (s, c2) = s.overflowing_add(pending);
        rest[0] = s;
        pending = u64::from(c1 | c2);
    }
    // The last row's bit: the word above it is the zero word on top, or within reach of it.
    let mut k = steps + m;
    while pending != 0 {
        let (s, c) = t[k].overflowing_add(pending);
        t[k] = s;
        pending = u64::from(c);
        k += 1;
    }
    steps
}

/// [`remainder_by`] on a factor of `M` words: rows of a constant length.
fn remainder<const M: usize>(t: &mut [u64], f: &[u64]) -> usize {
    let f: &[u64; M] = f.try_into().expect("the factor has M words");
    remainder_by(t, M, f[0], |head, u| {
        let head: &mut [u64; M] = head.try_into().expect("M words");
        row(head, f, u)
    })
}

/// [`remainder_by`] on a factor of any number of words.
fn remainder_any(t: &mut [u64], f: &[u64]) -> usize {
    remainder_by(t, f.len(), f[0], |head, u| row(head, f, u))
}

/// `gcd(n, f)` for the odd `f` of at least two words (no zero top word) and `n`'s words
/// (any length, not all zero), `scratch` reused.
fn odd_gcd(n: &[u64], f: &[u64], scratch: &mut Vec<u64>) -> BigUint {
    let m = f.len();
    scratch.clear();
    scratch.extend_from_slice(n);
    // At least M + 1 words, the top one zero: a shorter `n` is its own remainder.
    scratch.resize(n.len().max(m) + 1, 0);
    let steps = match m {
        2 => remainder::<2>(scratch, f),
        3 => remainder::<3>(scratch, f),
        4 => remainder::<4>(scratch, f),
        5 => remainder::<5>(scratch, f),
        6 => remainder::<6>(scratch, f),
        7 => remainder::<7>(scratch, f),
        8 => remainder::<8>(scratch, f),
        _ => remainder_any(scratch, f),
    };
    let r = &mut scratch[steps..];
    if m == 2 {
        // R < 2^128 + f: one subtraction of f when R has a third word.
        let (mut low, high) = (u128::from(r[0]) | u128::from(r[1]) << 64, r[2]);
        let f = u128::from(f[0]) | u128::from(f[1]) << 64;
        if high != 0 {
            low = low.wrapping_sub(f);
        }
        return BigUint::from(if low == 0 { f } else { gcd_u128(f, low) });
    }
    if r.iter().all(|&w| w == 0) {
        return gcd::from_words(f);
    }
    // Straight from the words to dashu-int's (through num-bigint's, two more copies).
    let g = dashu_int::ops::Gcd::gcd(&dashu_int::UBig::from_words(r), &dashu_int::UBig::from_words(f));
    gcd::from_words(g.as_words())
}

/// `gcd(num, Π f)` of the factors `f > 0`, for `num ≠ 0`, from the gcds with each factor
/// ([`factor_gcds`], [`gcd::gcd_with_product`]).
pub(crate) fn gcd_with_factors<'a>(num: &BigInt, factors: impl IntoIterator<Item = &'a BigInt>) -> BigInt {
    let shared: Vec<BigInt> = factor_gcds(num.magnitude(), factors.into_iter().map(|f| f.magnitude()))
        .into_iter()
        .filter(|h| !h.is_one())
        .map(BigInt::from)
        .collect();
    gcd::gcd_with_product(num, &shared)
}

/// `gcd(num, f)` for every factor `f > 0`, in order, for `num ≠ 0`.
fn factor_gcds<'a>(num: &BigUint, factors: impl IntoIterator<Item = &'a BigUint>) -> Vec<BigUint> {
    debug_assert!(!num.is_zero());
    let words = num.to_u64_digits();
    let num_twos = num.trailing_zeros().expect("num is not zero");
    let mut scratch = Vec::with_capacity(words.len() + 2);
    factors
        .into_iter()
        .map(|f| {
            if f.is_one() {
                return BigUint::one();
            }
            // A word's odd part by Hensel's remainder by a word: two products a word of
            // `num`, where a remainder chains one or two divisions a word.
            let by_word = |odd: u64| if odd == 1 { 1 } else { gcd_odd_word(num, odd) };
            let twos = f.trailing_zeros().expect("a factor is positive");
            let h = match f.to_u64() {
                // A factor of one word, without a copy of its words.
                Some(w) => BigUint::from(by_word(w >> twos)),
                None => {
                    let odd = (f >> twos).to_u64_digits();
                    match odd[..] {
                        [w] => BigUint::from(by_word(w)),
                        _ => odd_gcd(&words, &odd, &mut scratch),
                    }
                }
            };
            h << twos.min(num_twos)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_integer::Integer;
    use proptest::prelude::*;

    fn natural(limbs: &[u64]) -> BigUint {
        gcd::from_words(limbs)
    }

    /// Words with runs of zeros and of all ones, where carries propagate.
    fn limbs(len: std::ops::Range<usize>) -> impl Strategy<Value = Vec<u64>> {
        proptest::collection::vec(prop_oneof![any::<u64>(), Just(0u64), Just(u64::MAX)], len)
    }

    #[test]
    fn inverses() {
        for f in [1u64, 3, 5, 0xFFFF_FFFF_FFFF_FFFF, 0x8000_0000_0000_0001, 12_345_678_901] {
            assert_eq!(f.wrapping_mul(negated_inverse(f)), u64::MAX, "{f}");
        }
    }

    proptest! {
        /// Against num-bigint's gcd: odd words of every size, numbers sharing a part with
        /// them, of all ones, zero.
        #[test]
        fn odd_word_gcds_are_num_bigints(
            x in limbs(0..30),
            m in prop_oneof![3u64..1000, any::<u64>(), Just(u64::MAX)],
            common in 1u64..1_000_000,
        ) {
            let m = m | 1;
            prop_assume!(m > 1);
            let x = natural(&x) * common;
            let m = m.wrapping_mul(common | 1) | 1;
            prop_assume!(m > 1);
            prop_assert_eq!(BigUint::from(gcd_odd_word(&x, m)), x.gcd(&BigUint::from(m)));
        }

        /// Against num-bigint's gcd: factors of one to twelve words with a shared part and
        /// powers of two (more or fewer than the number's), numbers shorter and longer
        /// than the factors.
        #[test]
        fn factor_gcds_are_num_bigints(
            num in limbs(1..40),
            factors in proptest::collection::vec((limbs(1..13), 0u32..140, 0u32..3), 1..6),
            common in limbs(0..4),
            num_twos in 0u32..140,
        ) {
            let common = natural(&common).max(BigUint::one());
            let num = (natural(&num).max(BigUint::one()) * &common) << num_twos;
            let factors: Vec<BigUint> = factors
                .iter()
                .map(|(f, twos, with_common)| {
                    let f = natural(f).max(BigUint::one()) << twos;
                    if *with_common > 0 { f * &common } else { f }
                })
                .collect();
            let got = factor_gcds(&num, &factors);
            for (g, f) in got.iter().zip(&factors) {
                prop_assert_eq!(g, &num.gcd(f));
            }
        }
    }
}
