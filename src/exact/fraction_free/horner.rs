//! The nested Bernstein sum of one coordinate on an unreduced fraction.
//!
//! `acc ← s·acc + C(n,i) pⁱ x_i` as in the module's nested sum, but with `acc = N / D` kept as
//! a fraction: `N ← s d_i N + C(n,i) pⁱ a_i D`, `D ← d_i D` for `x_i = a_i / d_i`. No lcm of the
//! denominators is formed (a gcd and a product per point) and no numerator is scaled by
//! `L / d_i` (a division each): a step is three products by short factors and a sum, and
//! the one reduction is at the end, against `D qⁿ`. `D` is then the product of the
//! denominators, not their lcm, so the caller takes this kernel only while that product is
//! short (`choice::horner_wins`), and a run of equal neighbouring denominators is multiplied
//! in once. In a profile of the lcm form on 5-digit values at degree 20, the lcm and the
//! divisions `L / d_i` were 37% of the time.
//!
//! `N` and `D` are vectors of words, never num-bigint's integers (which take three
//! products, a copy and a sum per step, each with its own allocation): when every step's
//! two factors are below `2^62` (`word_steps`) a step is one pass (`fused_step`), else
//! products row by row into reused buffers (`horner_long`). The reduction takes the power
//! of `q` from one remainder by the largest power of `q` within half a word.

use crate::exact::gcd;
use crate::exact::gcd::{gcd_u64, rem_word};
use crate::exact::hensel;
use num_bigint::{BigInt, Sign};
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// `Σ_i x_i B_i^n(t)` of one coordinate's values at `t = p/q` (`q > 0`), in lowest terms,
/// on words of 64 bits when every step's factors fit ([`word_steps`]); `None` otherwise
/// (then `horner_long` takes words of any length).
pub(super) fn word_fraction_sum(values: &[&BigRational], p: &BigInt, q: &BigInt) -> Option<BigRational> {
    let (s, steps) = word_steps(values, p, q)?;
    Some(word_sum(values, s, &steps, q))
}

/// `a == b`, by the lengths and the lowest words first: distinct denominators almost always
/// differ there, and a full comparison is a call to `memcmp`.
pub(super) fn equal(a: &BigInt, b: &BigInt) -> bool {
    a.bits() == b.bits() && a.iter_u64_digits().next() == b.iter_u64_digits().next() && a == b
}

/// `Some(value())` when the value after `i` has the same denominator as value `i`.
pub(super) fn keep_if_next<T>(values: &[&BigRational], i: usize, value: impl FnOnce() -> T) -> Option<T> {
    values
        .get(i + 1)
        .filter(|next| equal(next.denom(), values[i].denom()))
        .map(|_| value())
}

/// `num / (den · qⁿ)` in lowest terms, `den, q > 0`: the power of `q` first (by remainders
/// and divisions by a word when `q` is one), then the gcd with `den`: one gcd, or, when
/// `factors` (whose product is `den`, or empty) are long enough ([`hensel::pays`]), the gcds
/// with each factor ([`hensel::gcd_with_factors`]).
pub(super) fn reduced(mut num: BigInt, den: BigInt, q: &BigInt, n: usize, factors: &[&BigInt]) -> BigRational {
    if num.is_zero() {
        return BigRational::new_raw(num, BigInt::one());
    }
    let power = match q.to_u64() {
        Some(w) if w > 1 => {
            // qⁿ's power of two by trailing zeros and one shift: the rounds below would
            // take it a factor of q at a time, each with a division of num.
            let (rest, left_twos) = gcd::take_twos(num, u64::from(w.trailing_zeros()), n);
            num = rest;
            let odd = w >> w.trailing_zeros();
            let mut power = match u32::try_from(n).ok().and_then(|e| odd.checked_pow(e)) {
                Some(x) => BigInt::from(x),
                None => num_traits::pow(BigInt::from(odd), n),
            };
            // gcd(num, o^m) for the largest power o^m of q's odd part within half a word
            // (`rem_word`'s fast path: 64-bit divisions), from one remainder, or of o itself
            // by Hensel's remainder past half a word: for a prime of exponent f in o, each
            // round divides out min(v, m f) of what is left of its exponent v; rounds go on
            // while something divides and the powers taken stay within oⁿ.
            let mut left = if odd > 1 { n } else { 0 };
            while left > 0 {
                let (mut block, mut m) = (odd, 1);
                while m < left {
                    match block.checked_mul(odd).filter(|&b| b <= u64::from(u32::MAX)) {
                        Some(b) => (block, m) = (b, m + 1),
                        None => break,
                    }
                }
                let g = if block <= u64::from(u32::MAX) {
                    gcd_u64(block, rem_word(num.magnitude(), block))
                } else {
                    hensel::gcd_odd_word(num.magnitude(), block)
                };
                if g == 1 {
                    break;
                }
                num /= g;
                power /= g;
                left -= m;
            }
            power << left_twos
        }
        _ => {
            let (rest, left) = gcd::reduce_by_power(num, q, n);
            num = rest;
            left
        }
    };
    let g = if hensel::pays(factors.len(), den.bits()) {
        hensel::gcd_with_factors(&num, factors.iter().copied()).into_parts().1
    } else {
        gcd::gcd(num.magnitude(), den.magnitude())
    };
    let (sign, magnitude) = num.into_parts();
    let mut den = den.into_parts().1;
    let mut magnitude = magnitude;
    match g.to_u64() {
        Some(1) => {}
        // In place, digit by digit.
        Some(w) => {
            magnitude /= w;
            den /= w;
        }
        // By value: num-bigint's division of a borrowed dividend copies it first.
        None => {
            magnitude = std::mem::take(&mut magnitude) / g.clone();
            den = std::mem::take(&mut den) / g;
        }
    }
    BigRational::new_raw(
        BigInt::from_biguint(sign, magnitude),
        BigInt::from_biguint(Sign::Plus, den) * power,
    )
}

/// One step of [`word_sum`]: `s d_i`, `C(n,i) pⁱ a_i` and `d_i`.
struct WordStep {
    s_d: i64,
    c_a: i64,
    d: u64,
}

/// The nested sum's steps on words, when `s`, every `s d_i` and every `C(n,i) pⁱ a_i`
/// are below `2^62` in magnitude (then a step's sum fits `i128`, see [`fused_step`]);
/// `None` otherwise.
fn word_steps(values: &[&BigRational], p: &BigInt, q: &BigInt) -> Option<(i64, Vec<WordStep>)> {
    const LIMIT: i128 = 1 << 62;
    let small = |x: i128| (x.abs() < LIMIT).then_some(x as i64);
    let n = values.len() - 1;
    let p = i128::from(p.to_i64()?);
    let s = small(i128::from(q.to_i64()?) - p)?;
    let mut coefficient: i128 = 1;
    let mut steps = Vec::with_capacity(n);
    for (i, v) in values.iter().enumerate().skip(1) {
        coefficient = coefficient.checked_mul((n - i + 1) as i128)?;
        // A 64-bit division where it fits (a 128-bit one is a library call).
        coefficient = match i64::try_from(coefficient) {
            Ok(c) => i128::from(c / i as i64),
            Err(_) => coefficient / i as i128,
        };
        coefficient = coefficient.checked_mul(p)?;
        let a = i128::from(v.numer().to_i64()?);
        let d = v.denom().to_u64()?;
        steps.push(WordStep {
            s_d: small(i128::from(s).checked_mul(i128::from(d))?)?,
            c_a: small(coefficient.checked_mul(a)?)?,
            d,
        });
    }
    Some((s, steps))
}

/// `N ← N·a + src·b` for `N = ±num` (`negative` its sign) and `|a|, |b| < 2^62`, in one pass:
/// each word's `num_j a + src_j b + carry` is below `2^127` in magnitude, so it is one
/// `i128`; a negative total (its top carry negative) is negated in two's complement.
fn fused_step(num: &mut Vec<u64>, negative: &mut bool, a: i64, src: &[u64], b: i64) {
    let a = if *negative { -i128::from(a) } else { i128::from(a) };
    let b = i128::from(b);
    if num.len() < src.len() {
        num.resize(src.len(), 0);
    }
    let mut carry: i128 = 0;
    let (low, high) = num.split_at_mut(src.len());
    for (x, &y) in low.iter_mut().zip(src) {
        let v = i128::from(*x) * a + i128::from(y) * b + carry;
        *x = v as u64;
        carry = v >> 64;
    }
    for x in high {
        let v = i128::from(*x) * a + carry;
        *x = v as u64;
        carry = v >> 64;
    }
    num.push(carry as u64);
    *negative = carry < 0;
    if *negative {
        let mut one = true;
        for x in num.iter_mut() {
            let (v, o) = (!*x).overflowing_add(u64::from(one));
            *x = v;
            one = o;
        }
    }
    trim(num);
}

/// `x ← x·m` for a magnitude `x` and a word `m`.
pub(super) fn times_word(x: &mut Vec<u64>, m: u64) {
    let mut carry = 0u64;
    for w in x.iter_mut() {
        let v = u128::from(*w) * u128::from(m) + u128::from(carry);
        *w = v as u64;
        carry = (v >> 64) as u64;
    }
    if carry != 0 {
        x.push(carry);
    }
}

pub(super) fn words_of(x: &BigInt) -> Vec<u64> {
    x.iter_u64_digits().collect()
}

/// `x` without its zero top words.
pub(super) fn trim(x: &mut Vec<u64>) {
    while x.last() == Some(&0) {
        x.pop();
    }
}

/// The nested sum on vectors of words (see [`word_steps`]): `N` as a magnitude and a sign,
/// `D` and `D / last` as magnitudes; each step one pass ([`fused_step`]) and, where `D`
/// grows, one product by a word.
fn word_sum(values: &[&BigRational], s: i64, steps: &[WordStep], q: &BigInt) -> BigRational {
    let n = values.len() - 1;
    let mut num = words_of(values[0].numer());
    let mut negative = values[0].numer().is_negative();
    let mut den = words_of(values[0].denom());
    // Denominators as words (`None`: the first, longer than a word, equal to no other).
    let mut last = values[0].denom().to_u64();
    let next_is = |k: usize, d: Option<u64>| d.is_some() && steps.get(k).map(|st| st.d) == d;
    let mut before = next_is(0, last).then(|| vec![1u64]);
    for (k, step) in steps.iter().enumerate() {
        if step.d == 1 {
            fused_step(&mut num, &mut negative, s, &den, step.c_a);
        } else if let (true, Some(b)) = (Some(step.d) == last, before.as_ref()) {
            fused_step(&mut num, &mut negative, s, b, step.c_a);
        } else {
            fused_step(&mut num, &mut negative, step.s_d, &den, step.c_a);
            before = next_is(k + 1, Some(step.d)).then(|| den.clone());
            times_word(&mut den, step.d);
            last = Some(step.d);
        }
    }
    let sign = if num.is_empty() {
        Sign::NoSign
    } else if negative {
        Sign::Minus
    } else {
        Sign::Plus
    };
    let num = BigInt::from_biguint(sign, gcd::from_words(&num));
    let den = BigInt::from_biguint(Sign::Plus, gcd::from_words(&den));
    reduced(num, den, q, n, &[])
}
