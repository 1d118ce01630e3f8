//! One neighbour pair of an elevation or derivative step, `(±α x/d + β y/e) / total`, for
//! numerators and denominators of up to 16 words (300-digit fractions have 16) when the
//! denominators' gcd is below 2^32: the same steps as `elevation_words::pair_big` (see that
//! module's documentation for why they give lowest terms), on numbers kept on the stack, so
//! that nothing is allocated but the two integers of the result, and with the remainders by
//! the weights taken by multiplications ([`Residues`]) instead of chained divisions.
//!
//! Inputs within 110 bits keep `elevation_words`' own kernel on four fixed words: this one
//! on two-word inputs took 1.1 to 1.55 times as long there (a 30-digit derivative of degree
//! 50: 38.9–41.5 against 32.9–34.7 µs; a 5-digit elevation of degree 20: 12.5–13.7 against
//! 8.8–9.4 µs; 2026-12-05).

use num_bigint::{BigInt, BigUint, Sign};
use num_rational::BigRational;
use std::cmp::Ordering;

use crate::exact::gcd::{self, gcd_u64};

/// Inputs longer than this many words take `pair_big`.
pub(crate) const INPUT_WORDS: usize = 16;

/// The words of the longest number a pair holds: a product of two inputs times two factors
/// below 2^32 has at most `2 · INPUT_WORDS + 1` words, and one more for a sum of two such
/// products.
pub(crate) const RESIDUE_WORDS: usize = 2 * INPUT_WORDS + 2;

/// A natural number of at most `N` words, little-endian; `len` counts the words up to the
/// highest nonzero one (zero has none), and the words past it are zero (sums and
/// differences read them). Inputs are `Long<I>`, sums of products `Long<P>`
/// with `P = 2 I + 2`: kept as short as the inputs allow, since every copy and every
/// cleared buffer is as long as `N`.
#[derive(Clone, Copy)]
pub(crate) struct Long<const N: usize> {
    words: [u64; N],
    len: usize,
}

impl<const N: usize> Long<N> {
    /// `x` when it has at most `N` words.
    fn of(x: &BigUint) -> Option<Self> {
        let digits = x.iter_u64_digits();
        let len = digits.len();
        if len > N {
            return None;
        }
        let mut words = [0u64; N];
        for (w, d) in words.iter_mut().zip(digits) {
            *w = d;
        }
        Some(Long { words, len })
    }

    fn digits(&self) -> &[u64] {
        &self.words[..self.len]
    }

    const ZERO: Self = Long { words: [0; N], len: 0 };

    fn trim(&mut self) {
        while self.len > 0 && self.words[self.len - 1] == 0 {
            self.len -= 1;
        }
    }

    fn is_zero(&self) -> bool {
        self.len == 0
    }

    /// `out = self · o` for a zero `out` of `M ≥ self.len + o.len` words (written in place:
    /// a returned product was copied out). The first row is stored, not added to a cleared
    /// buffer: the clearing's wide stores and the first row's loads of them stalled, a third
    /// of this function's samples on one instruction.
    fn times<const M: usize>(&self, o: &Self, out: &mut Long<M>) {
        debug_assert!(out.is_zero() && out.words.iter().all(|&w| w == 0));
        let (Some((&first, rest)), false) = (self.digits().split_first(), o.is_zero()) else {
            return;
        };
        let mut carry = 0u64;
        for (r, &b) in out.words.iter_mut().zip(o.digits()) {
            let v = u128::from(first) * u128::from(b) + u128::from(carry);
            *r = v as u64;
            carry = (v >> 64) as u64;
        }
        out.words[o.len] = carry;
        for (i, &a) in rest.iter().enumerate() {
            let row = &mut out.words[i + 1..i + o.len + 2];
            let (last, row) = row.split_last_mut().expect("a row has a carry word");
            let mut carry = 0u64;
            for (r, &b) in row.iter_mut().zip(o.digits()) {
                let v = u128::from(a) * u128::from(b) + u128::from(*r) + u128::from(carry);
                *r = v as u64;
                carry = (v >> 64) as u64;
            }
            *last = carry;
        }
        out.len = self.len + o.len;
        out.trim();
    }

    /// `self · k` for `0 < k < 2^32`, in place.
    fn scale(&mut self, k: u32) {
        let mut carry = 0u64;
        for w in &mut self.words[..self.len] {
            let v = u128::from(*w) * u128::from(k) + u128::from(carry);
            *w = v as u64;
            carry = (v >> 64) as u64;
        }
        if carry != 0 {
            self.words[self.len] = carry;
            self.len += 1;
        }
    }

    fn compare(&self, o: &Self) -> Ordering {
        self.len
            .cmp(&o.len)
            .then_with(|| self.digits().iter().rev().cmp(o.digits().iter().rev()))
    }

    /// `self + o`, in place.
    fn add(&mut self, o: &Self) {
        let len = self.len.max(o.len);
        let mut carry = false;
        for (a, &b) in self.words[..len].iter_mut().zip(&o.words[..len]) {
            let (s, c1) = a.overflowing_add(b);
            let (s, c2) = s.overflowing_add(u64::from(carry));
            *a = s;
            carry = c1 || c2;
        }
        self.len = len;
        if carry {
            self.words[len] = 1;
            self.len += 1;
        }
    }

    /// `self − o` for `self ≥ o`, in place.
    fn subtract(&mut self, o: &Self) {
        let mut borrow = false;
        for (a, &b) in self.words[..self.len].iter_mut().zip(&o.words[..self.len]) {
            let (s, b1) = a.overflowing_sub(b);
            let (s, b2) = s.overflowing_sub(u64::from(borrow));
            *a = s;
            borrow = b1 || b2;
        }
        self.trim();
    }

    /// `self / k` for a `0 < k < 2^32` known to divide `self`, in place
    /// ([`gcd::divide_exactly`]).
    fn divide_exactly(&mut self, k: u32) {
        gcd::divide_exactly(&mut self.words[..self.len], k);
        self.trim();
    }

    fn natural(&self) -> BigUint {
        gcd::from_words(self.digits())
    }
}

/// Remainders by one `0 < k < 2^32` through `2^(64 j) mod k` for the words `j` up to a
/// length fixed at construction: a remainder is then a sum of independent products and
/// three divisions, where long division chains two divisions a word.
pub(crate) struct Residues {
    k: u32,
    /// `2^64 mod k`.
    word: u64,
    word_weights: [u64; RESIDUE_WORDS],
    len: usize,
}

impl Residues {
    /// Weights for numbers of up to `len ≤ RESIDUE_WORDS` words.
    pub(crate) fn new(k: u32, len: usize) -> Self {
        let m = u64::from(k);
        let word = (u64::MAX % m + 1) % m;
        let mut word_weights = [0u64; RESIDUE_WORDS];
        let mut weight = 1 % m;
        for w in &mut word_weights[..len] {
            *w = weight;
            // Both below 2^32: the product fits a word.
            weight = weight * word % m;
        }
        Residues {
            k,
            word,
            word_weights,
            len,
        }
    }

    /// `x mod k`: each term is below `2^96` and at most [`RESIDUE_WORDS`] of them sum below
    /// `2^102`.
    fn of<const N: usize>(&self, x: &Long<N>) -> u64 {
        assert!(x.len <= self.len, "residue weights cover the number");
        let sum: u128 = x
            .digits()
            .iter()
            .zip(&self.word_weights)
            .map(|(&w, &weight)| u128::from(w) * u128::from(weight))
            .sum();
        let m = u64::from(self.k);
        let (high, low) = ((sum >> 64) as u64, sum as u64);
        // high < 2^38 and word < 2^32: the product fits a word.
        ((high % m) * self.word % m + low % m) % m
    }

    /// `gcd(k, x)`.
    fn gcd_with<const N: usize>(&self, x: &Long<N>) -> u32 {
        gcd_u64(u64::from(self.k), self.of(x)) as u32
    }
}

/// One signed fraction's numerator and denominator, on the stack.
#[derive(Clone, Copy)]
pub(crate) struct LongFraction<const I: usize> {
    pub(crate) negative: bool,
    num: Long<I>,
    den: Long<I>,
}

impl<const I: usize> LongFraction<I> {
    /// `x` when its numerator and denominator have at most `I` words.
    pub(crate) fn of(x: &BigRational) -> Option<Self> {
        Some(LongFraction {
            negative: x.numer().sign() == Sign::Minus,
            num: Long::of(x.numer().magnitude())?,
            den: Long::of(x.denom().magnitude())?,
        })
    }
}

/// `(α x + β y) / total` in lowest terms for reduced `x`, `y`, given `g = gcd(den x, den y)
/// < 2^32`, on `P = 2 I + 2` words. The weights' residues cover at least the denominators'
/// lengths (`alpha`, `beta`) and `P` words (`total`); `α β < 2^32`.
// Inlined into each `on_words`: called, it took 1–3% longer on 40- to 100-digit curves.
#[inline(always)]
pub(crate) fn pair_long<const I: usize, const P: usize>(
    x: &LongFraction<I>,
    alpha: &Residues,
    y: &LongFraction<I>,
    beta: &Residues,
    total: &Residues,
    g: u32,
) -> BigRational {
    const { assert!(P == 2 * I + 2 && P <= RESIDUE_WORDS) };
    let (mut dx, mut dy) = (x.den, y.den);
    if g != 1 {
        dx.divide_exactly(g);
        dy.divide_exactly(g);
    }
    // t = α x dy + β y dx, with signs.
    let (mut t, mut v) = (Long::<P>::ZERO, Long::<P>::ZERO);
    x.num.times(&dy, &mut t);
    t.scale(alpha.k);
    y.num.times(&dx, &mut v);
    v.scale(beta.k);
    let negative = if x.negative == y.negative {
        t.add(&v);
        x.negative
    } else if t.compare(&v).is_ge() {
        t.subtract(&v);
        x.negative
    } else {
        v.subtract(&t);
        std::mem::swap(&mut t, &mut v);
        y.negative
    };
    if t.is_zero() {
        return BigRational::new_raw(BigInt::from(0u8), BigInt::from(1u8));
    }
    // gcd(t, dx) = gcd(α, dx) and gcd(t, dy) = gcd(β, dy), coprime to each other.
    let (hx, hy) = (alpha.gcd_with(&dx), beta.gcd_with(&dy));
    if hx * hy != 1 {
        t.divide_exactly(hx * hy);
        dx.divide_exactly(hx);
        dy.divide_exactly(hy);
    }
    let mut shared = g;
    if g != 1 {
        let h = Residues::new(g, t.len).gcd_with(&t);
        if h != 1 {
            t.divide_exactly(h);
            shared /= h;
        }
    }
    // The derivative's total is 1.
    let h = if total.k == 1 { 1 } else { total.gcd_with(&t) };
    if h != 1 {
        t.divide_exactly(h);
    }
    let mut den = Long::<P>::ZERO;
    dx.times(&dy, &mut den);
    den.scale(shared);
    den.scale(total.k / h);
    let sign = if negative { Sign::Minus } else { Sign::Plus };
    BigRational::new_raw(
        BigInt::from_biguint(sign, t.natural()),
        BigInt::from_biguint(Sign::Plus, den.natural()),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_integer::Integer;
    use num_traits::One;
    use proptest::prelude::*;

    fn natural(limbs: &[u64]) -> BigUint {
        BigUint::new(limbs.iter().flat_map(|&w| [w as u32, (w >> 32) as u32]).collect())
    }

    /// Words with runs of zeros and of all ones, where carries and borrows propagate.
    fn limbs(len: std::ops::Range<usize>) -> impl Strategy<Value = Vec<u64>> {
        proptest::collection::vec(prop_oneof![any::<u64>(), Just(0u64), Just(u64::MAX)], len)
    }

    /// The pair on `I`-word inputs, or `None` where they do not fit.
    fn pair<const I: usize, const P: usize>(
        a: &BigRational,
        b: &BigRational,
        weights: (u32, u32, u32),
        g: u32,
        negate_first: bool,
    ) -> Option<BigRational> {
        let (alpha, beta, total) = weights;
        let mut x = LongFraction::<I>::of(a)?;
        let y = LongFraction::<I>::of(b)?;
        x.negative ^= negate_first;
        let residues = |k| Residues::new(k, RESIDUE_WORDS);
        Some(pair_long::<I, P>(
            &x,
            &residues(alpha),
            &y,
            &residues(beta),
            &residues(total),
            g,
        ))
    }

    proptest! {
        #[test]
        fn residues_are_remainders(x in limbs(0..RESIDUE_WORDS + 1), k in prop_oneof![1u32..70, any::<u32>().prop_map(|k| k.max(1))]) {
            let mut words = [0u64; RESIDUE_WORDS];
            words[..x.len()].copy_from_slice(&x);
            let mut long = Long::<RESIDUE_WORDS> { words, len: x.len() };
            long.trim();
            let want = natural(&x) % k;
            prop_assert_eq!(BigUint::from(Residues::new(k, RESIDUE_WORDS).of(&long)), want);
        }

        /// Against num-rational's own arithmetic, in lowest terms: numerators and
        /// denominators of 1 to 16 words, denominators sharing a factor below 2^32 and small
        /// primes with the weights and the total, either sign, zero, and the derivative's
        /// negated first term; each input length (16, 8 and 4 words) where the numbers fit it.
        #[test]
        fn pair_is_num_rationals(
            (x, y) in (limbs(0..17), limbs(0..17)),
            (d, e) in (limbs(1..15), limbs(1..15)),
            common in prop_oneof![Just(1u32), 2u32..64, any::<u32>().prop_map(|c| c.max(1))],
            (small_d, small_e) in (0u32..6, 0u32..6),
            (signs, negate_first) in (any::<(bool, bool)>(), any::<bool>()),
            (alpha, beta, total) in (1u32..70, 1u32..70, 1u32..70),
        ) {
            let smooth = |k: u32| BigUint::from(2u32.pow(k) * 3u32.pow(k % 3) * 5u32.pow(k % 2) * 7u32.pow(k / 3));
            let d = natural(&d).max(BigUint::one()) * common * smooth(small_d);
            let e = natural(&e).max(BigUint::one()) * common * smooth(small_e);
            let signed = |n: BigUint, negative: bool| BigInt::from_biguint(if negative { Sign::Minus } else { Sign::Plus }, n);
            let a = BigRational::new(signed(natural(&x) * smooth(small_e), signs.0), BigInt::from(d));
            let b = BigRational::new(signed(natural(&y), signs.1), BigInt::from(e));
            // The pair takes reduced inputs and their denominators' gcd.
            let Ok(g) = u32::try_from(a.denom().magnitude().gcd(b.denom().magnitude())) else { return Ok(()) };
            let first = if negate_first { -&a } else { a.clone() };
            let want = (first * BigInt::from(alpha) + &b * BigInt::from(beta)) / BigInt::from(total);
            let weights = (alpha, beta, total);
            let long = pair::<16, 34>(&a, &b, weights, g, negate_first);
            prop_assert!(long.is_some() || a.numer().bits() > 1024 || a.denom().bits() > 1024);
            let shorter = [
                pair::<8, 18>(&a, &b, weights, g, negate_first),
                pair::<4, 10>(&a, &b, weights, g, negate_first),
            ];
            for got in [long].into_iter().chain(shorter).flatten() {
                prop_assert_eq!(format!("{got:?}"), format!("{want:?}"));
                prop_assert_eq!(got, want.clone());
            }
        }
    }
}
