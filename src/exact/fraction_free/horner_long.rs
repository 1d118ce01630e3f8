//! [`super::horner`]'s nested sum on an unreduced fraction when its factors are longer than
//! a word: `N ← A·N + B·S` with `A = s d_i`, `B = C(n,i) pⁱ a_i` and `S` the denominator so
//! far, all on vectors of words. Each step writes its products row by row into one buffer
//! that is reused (the two buffers of `N` and of `D` are swapped, never reallocated once
//! long enough), where num-bigint allocates a product, a copy and a sum per step; the
//! coefficient `C(n,i) pⁱ` is advanced in place by a product and an exact division by words.
//!
//! Signs: `N`'s and `B`'s are kept beside their magnitudes, `S` is positive and `A` has
//! `s`'s sign. When the two products' signs differ the second is subtracted row by row in
//! two's complement; the running value only decreases from the first product, so it wraps
//! below zero at most once, and a wrap means the result is negative (its magnitude is the
//! two's complement of the buffer).

use super::horner::{equal, keep_if_next, reduced, times_word, trim, words_of};
use crate::exact::gcd::{self, divide_exactly};
use crate::exact::hensel;
use num_bigint::{BigInt, Sign};
use num_rational::BigRational;
use num_traits::Signed;

/// A signed integer as its magnitude's words (little-endian, no zero top word) and a sign.
#[derive(Clone, Default)]
struct Signed64 {
    words: Vec<u64>,
    negative: bool,
}

impl Signed64 {
    fn of(x: &BigInt) -> Self {
        Signed64 {
            words: words_of(x),
            negative: x.is_negative(),
        }
    }

    fn to_bigint(&self) -> BigInt {
        let sign = match (self.words.is_empty(), self.negative) {
            (true, _) => Sign::NoSign,
            (false, true) => Sign::Minus,
            (false, false) => Sign::Plus,
        };
        BigInt::from_biguint(sign, gcd::from_words(&self.words))
    }
}

/// `out += x·m` from `out`'s first word, the carry taken up as far as it goes; `out` is
/// longer than `x` and the sum fits it.
#[inline]
fn add_row(out: &mut [u64], x: &[u64], m: u64) {
    let (low, high) = out.split_at_mut(x.len());
    let mut carry = 0u64;
    for (o, &w) in low.iter_mut().zip(x) {
        let v = u128::from(w) * u128::from(m) + u128::from(*o) + u128::from(carry);
        *o = v as u64;
        carry = (v >> 64) as u64;
    }
    for o in high {
        if carry == 0 {
            break;
        }
        let (v, c) = o.overflowing_add(carry);
        *o = v;
        carry = u64::from(c);
    }
}

/// `out −= x·m` modulo `2^(64·len)`; whether it wrapped below zero.
#[inline]
fn sub_row(out: &mut [u64], x: &[u64], m: u64) -> bool {
    let (low, high) = out.split_at_mut(x.len());
    // What is still to subtract at this word: `w m + borrow < 2^128 − 2^64`, so its high
    // word plus one borrow bit stays within a word.
    let mut borrow = 0u64;
    for (o, &w) in low.iter_mut().zip(x) {
        let v = u128::from(w) * u128::from(m) + u128::from(borrow);
        let (r, b) = o.overflowing_sub(v as u64);
        *o = r;
        borrow = (v >> 64) as u64 + u64::from(b);
    }
    for o in high {
        if borrow == 0 {
            break;
        }
        let (r, b) = o.overflowing_sub(borrow);
        *o = r;
        borrow = u64::from(b);
    }
    borrow != 0
}

/// `out += x·y`, the row of `y`'s word `j` from `out`'s word `j` on, or `out −= x·y`
/// (`subtract`); whether a subtraction wrapped below zero. Two rows a pass over `out`
/// (carries of up to 66 bits) measured slower (2026-12-06: 30-digit values, degree 50,
/// 97 against 91 µs).
fn accumulate(out: &mut [u64], x: &[u64], y: &[u64], subtract: bool) -> bool {
    let mut wrapped = false;
    for (j, &m) in y.iter().enumerate() {
        if subtract {
            wrapped |= sub_row(&mut out[j..], x, m);
        } else {
            add_row(&mut out[j..], x, m);
        }
    }
    wrapped
}

/// `out = x·m`, its words pushed onto an empty `out` (no clearing, no reads of it).
#[inline]
fn store_row(out: &mut Vec<u64>, x: &[u64], m: u64) {
    let mut carry = 0u64;
    out.extend(x.iter().map(|&w| {
        let v = u128::from(w) * u128::from(m) + u128::from(carry);
        carry = (v >> 64) as u64;
        v as u64
    }));
    out.push(carry);
}

/// `out = x·y` of magnitudes (the shorter operand by rows; the first row stored).
fn multiply_into(out: &mut Vec<u64>, x: &[u64], y: &[u64]) {
    let (long, short) = if x.len() >= y.len() { (x, y) } else { (y, x) };
    out.clear();
    let Some((&first, rest)) = short.split_first() else {
        return;
    };
    store_row(out, long, first);
    out.resize(long.len() + short.len(), 0);
    accumulate(&mut out[1..], long, rest, false);
    trim(out);
}

/// `out = a·x + b·src` (`a`, `b` and `x` signed, `src` positive); `out`'s old contents are
/// overwritten.
fn fused(out: &mut Signed64, a: &Signed64, x: &Signed64, b: &Signed64, src: &[u64]) {
    let first_negative = a.negative != x.negative;
    let len = (x.words.len() + a.words.len()).max(src.len() + b.words.len()) + 1;
    let buffer = &mut out.words;
    buffer.clear();
    if let Some((&first, rest)) = a.words.split_first() {
        store_row(buffer, &x.words, first);
        buffer.resize(len, 0);
        accumulate(&mut buffer[1..], &x.words, rest, false);
    } else {
        buffer.resize(len, 0);
    }
    out.negative = first_negative;
    let subtract = b.negative != first_negative;
    if accumulate(buffer, src, &b.words, subtract) {
        // The magnitude of a negative two's complement value: `!x + 1`.
        let mut one = true;
        for w in buffer.iter_mut() {
            let (v, o) = (!*w).overflowing_add(u64::from(one));
            *w = v;
            one = o;
        }
        out.negative = !first_negative;
    }
    trim(buffer);
    if buffer.is_empty() {
        out.negative = false;
    }
}

/// `Σ_i x_i B_i^n(t)` of one coordinate's values at `t = p/q` (`q > 0`), in lowest terms,
/// by the steps of `horner`'s nested sum on words of any length.
pub(super) fn long_sum(values: &[&BigRational], p: &BigInt, q: &BigInt) -> BigRational {
    let n = values.len() - 1;
    let s = Signed64::of(&(q - p));
    let p_words = Signed64::of(p);
    let mut num = Signed64::of(values[0].numer());
    let mut den: Vec<u64> = values[0].denom().iter_u64_digits().collect();
    let (mut next_num, mut next_den) = (Signed64::default(), Vec::new());
    // `C(n,i) pⁱ` and its product by the value's numerator; `s d_i`.
    let mut coefficient = Signed64 {
        words: vec![1],
        negative: false,
    };
    let (mut b, mut a) = (Signed64::default(), Signed64::default());
    let (mut value, mut d) = (Signed64::default(), Vec::new());
    // `D / last` while the run of equal denominators that `last` starts goes on.
    let mut last = values[0].denom();
    let mut before: Option<Vec<u64>> = keep_if_next(values, 0, || vec![1]);
    // The factors of `den`, kept when the final gcd may take them (`hensel::pays`): a list
    // of every short curve's factors cost 4% of a 30-digit cubic's eval.
    let keep = values.iter().map(|v| v.denom().bits()).sum::<u64>() >= hensel::LEAST_BITS;
    let mut factors = Vec::new();
    if keep {
        factors.reserve(values.len());
        factors.push(values[0].denom());
    }
    for i in 1..=n {
        advance(&mut coefficient, n, i, &p_words, &mut next_den);
        let (numer, denom) = (values[i].numer(), values[i].denom());
        value.words.clear();
        value.words.extend(numer.iter_u64_digits());
        value.negative = numer.is_negative();
        multiply_into(&mut b.words, &coefficient.words, &value.words);
        b.negative = coefficient.negative != value.negative;
        if denom.bits() == 1 {
            fused(&mut next_num, &s, &num, &b, &den);
        } else if let (true, Some(kept)) = (equal(denom, last), before.as_ref()) {
            fused(&mut next_num, &s, &num, &b, kept);
        } else {
            d.clear();
            d.extend(denom.iter_u64_digits());
            multiply_into(&mut a.words, &s.words, &d);
            a.negative = s.negative;
            fused(&mut next_num, &a, &num, &b, &den);
            before = keep_if_next(values, i, || den.clone());
            if keep {
                factors.push(denom);
            }
            if let [word] = d[..] {
                times_word(&mut den, word);
            } else {
                multiply_into(&mut next_den, &den, &d);
                std::mem::swap(&mut den, &mut next_den);
            }
            last = denom;
        }
        std::mem::swap(&mut num, &mut next_num);
    }
    let den = BigInt::from_biguint(Sign::Plus, gcd::from_words(&den));
    reduced(num.to_bigint(), den, q, n, &factors)
}

/// `C(n,i−1) pⁱ⁻¹` to `C(n,i) pⁱ` in place: times `n − i + 1`, divided exactly by `i`
/// (`C(n,i−1)(n−i+1) = i C(n,i)`), times `p`; `scratch` is overwritten.
fn advance(coefficient: &mut Signed64, n: usize, i: usize, p: &Signed64, scratch: &mut Vec<u64>) {
    let c = &mut coefficient.words;
    times_word(c, (n - i + 1) as u64);
    match u32::try_from(i) {
        Ok(k) => divide_exactly(c, k),
        Err(_) => {
            let quotient = gcd::from_words(c) / num_bigint::BigUint::from(i);
            *c = quotient.iter_u64_digits().collect();
        }
    }
    trim(c);
    if p.words != [1] {
        multiply_into(scratch, c, &p.words);
        std::mem::swap(c, scratch);
    }
    coefficient.negative ^= p.negative;
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::{One, Zero};
    use proptest::prelude::*;

    /// `Σ C(n,i) x_i tⁱ (1−t)^(n−i)` term by term on fractions.
    fn naive(values: &[BigRational], t: &BigRational) -> BigRational {
        let n = values.len() - 1;
        let one = BigRational::one();
        let mut sum = BigRational::zero();
        let mut binomial = BigInt::one();
        for (i, x) in values.iter().enumerate() {
            if i > 0 {
                binomial = binomial * BigInt::from(n - i + 1) / BigInt::from(i);
            }
            let term = BigRational::from(binomial.clone())
                * x
                * num_traits::pow(t.clone(), i)
                * num_traits::pow(&one - t, n - i);
            sum += term;
        }
        sum
    }

    fn big(words: &[u64], negative: bool) -> BigInt {
        let m = BigInt::from_biguint(Sign::Plus, gcd::from_words(words));
        if negative {
            -m
        } else {
            m
        }
    }

    fn fraction() -> impl Strategy<Value = BigRational> {
        (
            proptest::collection::vec(any::<u64>(), 0..4),
            any::<bool>(),
            proptest::collection::vec(any::<u64>(), 0..4),
            0u64..4,
        )
            .prop_map(|(n, negative, d, small)| {
                // Small denominators, repeated ones and 1 as well as long ones.
                let den = if d.is_empty() {
                    BigInt::from(small + 1)
                } else {
                    big(&d, false) + 1
                };
                BigRational::new(big(&n, negative), den)
            })
    }

    proptest! {
        /// Equal to the term-by-term sum and in lowest terms: signs of every kind, `t`
        /// outside `[0, 1]`, long and one-word factors, runs of equal denominators.
        #[test]
        fn long_sum_is_the_bernstein_sum(
            values in proptest::collection::vec(fraction(), 1..9),
            repeat in any::<bool>(),
            t in fraction(),
        ) {
            let mut values = values;
            if repeat && values.len() > 2 {
                let d = values[1].denom().clone();
                values[2] = BigRational::new(values[2].numer().clone(), d.clone());
                let k = 3 % values.len();
                values[k] = BigRational::new(values[0].numer().clone(), d);
            }
            let refs: Vec<&BigRational> = values.iter().collect();
            let (got, want) = (long_sum(&refs, t.numer(), t.denom()), naive(&values, &t));
            prop_assert_eq!((got.numer(), got.denom()), (want.numer(), want.denom()));
        }

        /// The final gcd by factors ([`hensel::pays`]), in lowest terms (num-rational's `==`
        /// compares values): 6 to 9 denominators of 6 to 12
        /// words, half of them sharing a part with each other, with powers of two, and
        /// with runs of equal denominators.
        #[test]
        fn long_sum_reduces_by_factors(
            values in proptest::collection::vec(
                (proptest::collection::vec(any::<u64>(), 0..12), any::<bool>(), proptest::collection::vec(any::<u64>(), 6..13), 0u32..70),
                6..10,
            ),
            common in proptest::collection::vec(any::<u64>(), 1..3),
            repeat in any::<bool>(),
            t in fraction(),
        ) {
            let common = big(&common, false).max(BigInt::one());
            let mut values: Vec<BigRational> = values
                .iter()
                .enumerate()
                .map(|(i, (n, negative, d, twos))| {
                    let d = (big(d, false).max(BigInt::one()) << twos) * if i % 2 == 0 { common.clone() } else { BigInt::one() };
                    BigRational::new(big(n, *negative), d)
                })
                .collect();
            if repeat {
                values[2] = BigRational::new(values[2].numer().clone(), values[1].denom().clone());
            }
            let refs: Vec<&BigRational> = values.iter().collect();
            let bits: u64 = values.iter().map(|v| v.denom().bits()).sum();
            prop_assume!(crate::exact::hensel::pays(values.len(), bits));
            let (got, want) = (long_sum(&refs, t.numer(), t.denom()), naive(&values, &t));
            prop_assert_eq!((got.numer(), got.denom()), (want.numer(), want.denom()));
        }
    }
}
