//! One degree-elevation step (7) point by point, on machine words where the numbers allow.
//!
//! Each new coordinate `(α x/d + β y/e) / (n+1)`, `α = i`, `β = n+1−i`, combines two
//! neighbouring inputs whose denominators are unrelated in general, so a denominator common
//! to the whole curve would make every output as long as all inputs together; instead each
//! output is brought to lowest terms on its own, with one gcd of the two denominators and
//! gcds of small words, the way GMP adds two fractions (Knuth, TAOCP vol. 2, 4.5.1):
//!
//! - `g = gcd(d, e)`, `d = g d'`, `e = g e'`, and `t = α x e' + β y d'`: the sum is
//!   `t / (g d' e')`;
//! - `gcd(t, d') = gcd(α, d')`, because `d'` is prime to `x` (the input is reduced) and to
//!   `e'`; likewise `gcd(t, e') = gcd(β, e')` once that is divided out — gcds of a word;
//! - what is left of `t` is divided by its gcd with `g` and then by its gcd with `n + 1`,
//!   one factor after the other, which divides out exactly its gcd with `g (n+1)`: for a
//!   prime of exponent `v` in `t` and `e₁, e₂` in the factors, `min(v, e₁ + e₂) =
//!   min(v, e₁) + min(v − min(v, e₁), e₂)`.
//!
//! When every input numerator and denominator has at most 119 bits (35-digit fractions
//! have 117), `t` and the denominator fit 256 bits and nothing is allocated but the two
//! integers of the result; otherwise, up to 16 words and with `g` below 2^32, the same
//! steps run on the stack (`exact::long_pair`), and past that on big integers
//! (`pair_big`).
//!
//! The gcds `g` of all neighbouring denominators are computed first, two interleaved
//! binary gcds at a time (`gcd::paired_gcds`); the small gcds need residues modulo `α`,
//! `β` and `n + 1`, taken word by word with independent divisions (`SmallModulus`), and
//! the divisions by those gcds (and by `g`) are exact, done by multiplying by an inverse
//! modulo `2^64`. The tests compare both with `==` against
//! [`BezierCurve::elevate_reference`](crate::BezierCurve::elevate_reference).

use crate::coords::Point;
use crate::exact::gcd;
use crate::exact::gcd::{gcd_u64, Shared};
use crate::exact::long_pair::{pair_long, LongFraction, Residues, INPUT_WORDS, RESIDUE_WORDS};
use num_bigint::{BigInt, BigUint, Sign};
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::borrow::Cow;

/// Inputs longer than this many bits take the big-integer path: with `α, n+1 < 2^16` (the
/// word path's moduli), every intermediate then fits 256 bits (`2^16 · 2^119 · 2^119 · 2 =
/// 2^255`); the products and sums are checked all the same.
const WORD_INPUT_BITS: u64 = 119;

/// A nonnegative integer below 2^256, little-endian 64-bit words.
#[derive(Clone, Copy, PartialEq, Eq)]
struct U256([u64; 4]);

impl U256 {
    const ZERO: U256 = U256([0; 4]);

    fn product(a: u128, b: u128) -> Self {
        let (a0, a1) = (a as u64 as u128, a >> 64);
        let (b0, b1) = (b as u64 as u128, b >> 64);
        let (low, cross_a, cross_b, high) = (a0 * b0, a0 * b1, a1 * b0, a1 * b1);
        // Below 3·2^64: no overflow.
        let middle = (low >> 64) + (cross_a as u64 as u128) + (cross_b as u64 as u128);
        // The whole product is below 2^256, so this sum is below 2^128.
        let top = high + (cross_a >> 64) + (cross_b >> 64) + (middle >> 64);
        U256([low as u64, middle as u64, top as u64, (top >> 64) as u64])
    }

    fn times(self, k: u64) -> Option<Self> {
        let mut out = [0u64; 4];
        let mut carry = 0u128;
        for (o, w) in out.iter_mut().zip(self.0) {
            let v = u128::from(w) * u128::from(k) + carry;
            *o = v as u64;
            carry = v >> 64;
        }
        (carry == 0).then_some(U256(out))
    }

    fn plus(self, o: Self) -> Option<Self> {
        let mut out = [0u64; 4];
        let mut carry = false;
        for ((r, a), b) in out.iter_mut().zip(self.0).zip(o.0) {
            let (s, c1) = a.overflowing_add(b);
            let (s, c2) = s.overflowing_add(u64::from(carry));
            *r = s;
            carry = c1 || c2;
        }
        (!carry).then_some(U256(out))
    }

    /// `self − o` for `self ≥ o`.
    fn minus(self, o: Self) -> Self {
        let mut out = [0u64; 4];
        let mut borrow = false;
        for ((r, a), b) in out.iter_mut().zip(self.0).zip(o.0) {
            let (s, b1) = a.overflowing_sub(b);
            let (s, b2) = s.overflowing_sub(u64::from(borrow));
            *r = s;
            borrow = b1 || b2;
        }
        U256(out)
    }

    fn greater_or_equal(&self, o: &Self) -> bool {
        self.0.iter().rev().cmp(o.0.iter().rev()).is_ge()
    }

    /// The 32-bit halves up to the highest nonzero word, most significant first.
    fn halves(&self) -> impl Iterator<Item = (usize, u64)> + '_ {
        let top = self.0.iter().rposition(|&w| w != 0).map_or(0, |i| 2 * i + 2);
        (0..top)
            .rev()
            .map(move |h| (h, (self.0[h / 2] >> (32 * (h % 2))) & 0xFFFF_FFFF))
    }

    /// `self mod k`, `0 < k < 2^32`: 32 bits at a time, so that each step is a 64-bit
    /// division (a machine instruction, where a 128-bit one is a library call).
    fn rem_small(&self, k: u32) -> u32 {
        let k = u64::from(k);
        self.halves().fold(0u64, |r, (_, h)| ((r << 32) | h) % k) as u32
    }

    /// `self / k` for a `0 < k < 2^32` known to divide `self` ([`gcd::divide_exactly`]).
    #[inline]
    fn div_exact_small(&self, k: u32) -> Self {
        let mut words = self.0;
        gcd::divide_exactly(&mut words, k);
        U256(words)
    }

    fn is_zero(&self) -> bool {
        *self == U256::ZERO
    }

    /// [`gcd::from_words`] for four fixed words, kept apart: the 30-digit degree-50
    /// derivative took 32.5 µs this way and 34.9 µs through the general one (medians of
    /// eight alternating runs, 2026-12-05).
    fn to_biguint(self) -> BigUint {
        let mut halves = [0u32; 8];
        for (pair, w) in halves.chunks_exact_mut(2).zip(self.0) {
            pair[0] = w as u32;
            pair[1] = (w >> 32) as u32;
        }
        let len = halves.iter().rposition(|&h| h != 0).map_or(0, |i| i + 1);
        // One allocation of the right length, the digits of the result.
        BigUint::from_slice(&halves[..len])
    }
}

/// Residues modulo one small `k` (below 2^16: the weights `i`, `n+1−i` and `n+1`, as the
/// degree limit keeps them), from one hardware division per word that do not wait for each
/// other, where the long division of [`U256::rem_small`] chains them.
#[derive(Clone, Copy)]
struct SmallModulus {
    k: u64,
    /// `2^(64 j) mod k` for the words `j = 0..4`.
    word_weights: [u64; 4],
}

impl SmallModulus {
    fn new(k: u16) -> Self {
        let k = u64::from(k);
        let w1 = (u64::MAX % k + 1) % k;
        let w2 = w1 * w1 % k;
        SmallModulus {
            k,
            word_weights: [1 % k, w1, w2, w2 * w1 % k],
        }
    }

    fn value(&self) -> u32 {
        self.k as u32
    }

    /// Each term is below `2^32`, so the four add up without overflow.
    fn of_words(&self, words: &[u64]) -> u64 {
        let sum: u64 = words
            .iter()
            .zip(self.word_weights)
            .map(|(w, weight)| (w % self.k) * weight)
            .sum();
        sum % self.k
    }

    fn of_u128(&self, x: u128) -> u64 {
        self.of_words(&[x as u64, (x >> 64) as u64])
    }

    /// `gcd(k, x)`, a word.
    fn gcd_with(&self, x: u64) -> u32 {
        gcd_u64(self.k, x) as u32
    }
}

/// A reduced fraction `±num/den` on words.
#[derive(Clone, Copy)]
struct WordFraction {
    negative: bool,
    num: u128,
    den: u128,
}

impl WordFraction {
    fn of(x: &BigRational) -> Option<Self> {
        if x.numer().bits() > WORD_INPUT_BITS || x.denom().bits() > WORD_INPUT_BITS {
            return None;
        }
        Some(WordFraction {
            negative: x.is_negative(),
            num: x.numer().magnitude().to_u128()?,
            den: x.denom().magnitude().to_u128()?,
        })
    }
}

/// `x / k` for a `0 < k < 2^32` known to divide `x`, by [`U256::div_exact_small`]: a
/// 128-bit division is a library call several times as long.
fn div_exact_u128(x: u128, k: u32) -> u128 {
    if k == 1 {
        return x;
    }
    let quotient = U256([x as u64, (x >> 64) as u64, 0, 0]).div_exact_small(k).0;
    u128::from(quotient[0]) | (u128::from(quotient[1]) << 64)
}

/// `(α x + β y) / total` in lowest terms, on words, given `g = gcd(den x, den y)`; `None`
/// when `g` does not fit 32 bits (or a bound is exceeded), for the big-integer path.
fn pair_words(
    x: WordFraction,
    alpha: &SmallModulus,
    y: WordFraction,
    beta: &SmallModulus,
    total: &SmallModulus,
    g: u128,
) -> Option<BigRational> {
    let g = u32::try_from(g).ok()?;
    let (mut dx, mut dy) = if g == 1 {
        (x.den, y.den)
    } else {
        (div_exact_u128(x.den, g), div_exact_u128(y.den, g))
    };
    // t = α x dy + β y dx, with signs.
    let u = U256::product(x.num, dy).times(alpha.k)?;
    let v = U256::product(y.num, dx).times(beta.k)?;
    let (negative, mut t) = if x.negative == y.negative {
        (x.negative, u.plus(v)?)
    } else if u.greater_or_equal(&v) {
        (x.negative, u.minus(v))
    } else {
        (y.negative, v.minus(u))
    };
    if t.is_zero() {
        return Some(BigRational::new_raw(BigInt::zero(), BigInt::from(1u8)));
    }
    // gcd(t, dx) = gcd(α, dx) and gcd(t, dy) = gcd(β, dy), coprime to each other: see the
    // module documentation.
    let (hx, hy) = (alpha.gcd_with(alpha.of_u128(dx)), beta.gcd_with(beta.of_u128(dy)));
    if hx * hy != 1 {
        t = t.div_exact_small(hx * hy);
        dx = div_exact_u128(dx, hx);
        dy = div_exact_u128(dy, hy);
    }
    let mut shared = g;
    if g != 1 {
        let h = gcd_u64(u64::from(g), u64::from(t.rem_small(g))) as u32;
        if h != 1 {
            t = t.div_exact_small(h);
            shared /= h;
        }
    }
    // The derivative's total is 1.
    let h = if total.value() == 1 {
        1
    } else {
        total.gcd_with(total.of_words(&t.0))
    };
    if h != 1 {
        t = t.div_exact_small(h);
    }
    // dx · shared ≤ den x < 2^119; the whole denominator is below 2^254.
    let den = U256::product(dx * u128::from(shared), dy).times(u64::from(total.value() / h))?;
    let sign = if negative { Sign::Minus } else { Sign::Plus };
    Some(BigRational::new_raw(
        BigInt::from_biguint(sign, t.to_biguint()),
        BigInt::from_biguint(Sign::Plus, den.to_biguint()),
    ))
}

/// `(±α a + β b) / total` in lowest terms on big integers (`−` with `negate_first`), the
/// way GMP adds two fractions (Knuth, TAOCP vol. 2, 4.5.1) with the word path's small gcds
/// (see the module documentation): with `a = x/d`, `b = y/e`, `g = gcd(d, e)` (given: the
/// caller converts each denominator to dashu-int's form once, not once per pair), `d = g d'`,
/// `e = g e'`, the sum is `s / (g d' e' total)` with `s = ±α x e' + β y d'`;
/// `gcd(s, d') = gcd(α, d')` and `gcd(s, e') = gcd(β, e')` are gcds of a word, and what is
/// left of `s` is reduced against `g` (none when `g = 1`, a remainder when `g` is a word,
/// else one gcd of denominator length) and then against `total` (a word).
fn pair_big(
    a: &BigRational,
    negate_first: bool,
    alpha: u32,
    b: &BigRational,
    beta: u32,
    total: u32,
    g: &Shared,
) -> BigRational {
    let (x, d, y, e) = (a.numer(), a.denom(), b.numer(), b.denom());
    // `d'` and `e'`, borrowed when `g = 1` (61% of random pairs): no copies.
    let (mut d1, mut e1) = match g {
        Shared::Word(1) => (Cow::Borrowed(d), Cow::Borrowed(e)),
        Shared::Word(w) => (Cow::Owned(d / *w), Cow::Owned(e / *w)),
        Shared::Big(g) => (Cow::Owned(d / g), Cow::Owned(e / g)),
    };
    let mut first = x * &*e1;
    first *= alpha;
    let mut second = y * &*d1;
    second *= beta;
    let mut s = if negate_first { second - first } else { first + second };
    if s.is_zero() {
        return BigRational::new_raw(s, BigInt::one());
    }
    let small_gcd = |m: &BigInt, weight: u32| {
        let weight = u64::from(weight);
        gcd_u64(weight, gcd::rem_word(m.magnitude(), weight)) as u32
    };
    let (hx, hy) = (small_gcd(&d1, alpha), small_gcd(&e1, beta));
    if hx != 1 {
        *d1.to_mut() /= hx;
    }
    if hy != 1 {
        *e1.to_mut() /= hy;
    }
    if hx * hy != 1 {
        s /= hx * hy;
    }
    let mut den = &*d1 * &*e1;
    match g {
        Shared::Word(1) => {}
        Shared::Word(w) => {
            let h = gcd_u64(*w, gcd::rem_word(s.magnitude(), *w));
            if h != 1 {
                s /= h;
            }
            den *= *w / h;
        }
        Shared::Big(g) => {
            let h = gcd::gcd_int(&s, g);
            if h.is_one() {
                den *= g;
            } else {
                s /= &h;
                den *= g / h;
            }
        }
    }
    if total != 1 {
        let h = small_gcd(&s, total);
        if h != 1 {
            s /= h;
        }
        den *= total / h;
    }
    BigRational::new_raw(s, den)
}

/// The gcds of neighbouring denominators for the big-integer path: each denominator longer
/// than two words is converted to dashu-int's form once (it takes part in two pairs), and
/// the gcds of pairs `m` and `m + 1` (denominators `d_{m−1}, d_m` and `d_m, d_{m+1}`) come
/// from one gcd `gcd(d_m, d_{m−1} d_{m+1})` ([`gcd::shared_pair`]) for odd `m`: half as
/// many gcds of denominator length, the largest cost of a pair.
struct BigDenominators {
    dashu: Vec<Option<dashu_int::UBig>>,
    /// By pair slot `j` (coordinates `j` and `j + dim`), where computed ahead.
    gcds: Vec<Option<Shared>>,
}

impl BigDenominators {
    fn new(points: &[Point<BigRational>]) -> Self {
        let dim = points[0].dim();
        let n = points.len() - 1;
        let coords: Vec<&BigRational> = points.iter().flat_map(|p| p.coords()).collect();
        // The shorter ones have their gcds from `gcd::paired_gcds`.
        let dashu: Vec<Option<dashu_int::UBig>> = coords
            .iter()
            .map(|c| (c.denom().bits() > 128).then(|| gcd::to_dashu(c.denom().magnitude())))
            .collect();
        let mut gcds: Vec<Option<Shared>> = (0..n * dim).map(|_| None).collect();
        for k in 0..dim {
            for m in (1..n).step_by(2) {
                let (before, middle, after) = ((m - 1) * dim + k, m * dim + k, (m + 1) * dim + k);
                if let (Some(a), Some(d), Some(c)) = (&dashu[before], &dashu[middle], &dashu[after]) {
                    let natural = |j: usize| coords[j].denom().magnitude();
                    let (left, right) = gcd::shared_pair(a, d, c, natural(before), natural(after));
                    // Pair m is slot `before`, pair m + 1 slot `middle`.
                    gcds[before] = Some(left);
                    gcds[middle] = Some(right);
                }
            }
        }
        BigDenominators { dashu, gcds }
    }

    /// `gcd` of the denominators of coordinates `j` and `j + dim` (`a` and `b`).
    fn shared(&mut self, j: usize, dim: usize, a: &BigRational, b: &BigRational) -> Shared {
        if let Some(g) = self.gcds[j].take() {
            return g;
        }
        match (&self.dashu[j], &self.dashu[j + dim]) {
            (Some(d), Some(e)) => Shared::of_dashu(d, e),
            _ => Shared::of(a.denom().magnitude(), b.denom().magnitude()),
        }
    }
}

/// The residues [`pair_long`] takes by the weights: `total`'s once, `α`'s and `β`'s for the
/// pair at hand (shared by its coordinates).
struct LongWeights {
    total: Residues,
    denominator_words: usize,
    pair: Option<(u32, u32, Residues, Residues)>,
}

impl LongWeights {
    fn new(total: u32, denominator_words: usize) -> Self {
        LongWeights {
            total: Residues::new(total, RESIDUE_WORDS),
            denominator_words,
            pair: None,
        }
    }

    fn at(&mut self, alpha: u32, beta: u32) -> (&Residues, &Residues, &Residues) {
        let words = self.denominator_words;
        if !matches!(self.pair, Some((a, b, _, _)) if (a, b) == (alpha, beta)) {
            self.pair = Some((alpha, beta, Residues::new(alpha, words), Residues::new(beta, words)));
        }
        let (_, _, a, b) = self.pair.as_ref().expect("just set");
        (a, b, &self.total)
    }
}

/// [`pair_long`] on `I`-word inputs, when `a` and `b` fit: the caller picks 4 words (256
/// bits: 40-digit fractions have 133), 8 (100-digit ones have 333) or 16 by the inputs'
/// length, since every copy and cleared buffer is as long as the type.
fn on_words<const I: usize, const P: usize>(
    a: &BigRational,
    negate_first: bool,
    alpha: &Residues,
    b: &BigRational,
    beta: &Residues,
    total: &Residues,
    g: u32,
) -> Option<BigRational> {
    let mut x = LongFraction::<I>::of(a)?;
    let y = LongFraction::<I>::of(b)?;
    x.negative ^= negate_first;
    Some(pair_long::<I, P>(&x, alpha, &y, beta, total, g))
}

/// The most words of any denominator of the points, at most [`INPUT_WORDS`] (the longer
/// ones take `pair_big`).
fn long_denominators(points: &[Point<BigRational>]) -> usize {
    points
        .iter()
        .flat_map(|p| p.coords())
        .map(|c| c.denom().iter_u64_digits().len())
        .filter(|&len| len <= INPUT_WORDS)
        .max()
        .unwrap_or(0)
}

/// One elevation step (7) of the points, each new coordinate reduced on its own.
pub(crate) fn elevate_pairwise(points: &[Point<BigRational>]) -> Vec<Point<BigRational>> {
    let n = points.len() - 1;
    let total = u32::try_from(n + 1).expect("degrees are limited far below 2^32");
    let mut out = Vec::with_capacity(n + 2);
    out.push(points[0].clone());
    out.extend(combine_neighbours(points, |i| (i, total - i), total, false));
    out.push(points[n].clone());
    out
}

/// The first derivative curve's points `n (b_{i+1} − b_i)`, each coordinate reduced on its
/// own: the same combination of neighbours as elevation, with weights `−n` and `n`.
pub(crate) fn derivative_pairwise(points: &[Point<BigRational>]) -> Vec<Point<BigRational>> {
    let n = u32::try_from(points.len() - 1).expect("degrees are limited far below 2^32");
    combine_neighbours(points, |_| (n, n), 1, true)
}

/// `(±α_i b_{i−1} + β_i b_i) / total` for `i = 1..=n`, coordinate by coordinate (the sign
/// of the first term is `−` with `negate_first`).
fn combine_neighbours(
    points: &[Point<BigRational>],
    weights: impl Fn(u32) -> (u32, u32),
    total: u32,
    negate_first: bool,
) -> Vec<Point<BigRational>> {
    let n = points.len() - 1;
    let dim = points[0].dim();
    let words: Vec<Option<WordFraction>> = points
        .iter()
        .flat_map(|p| p.coords().iter().map(WordFraction::of))
        .collect();
    // The word path's small moduli need weights below 2^16, which the degree limit keeps.
    let small = u16::try_from(total).ok().map(SmallModulus::new);
    // Every denominator within two words, not only the word path's: past its 119 bits the
    // interleaved binary gcd is still the cheapest (a 35-digit derivative of degree 50
    // spent 40% of its time in one-at-a-time gcds of its 116-bit denominators).
    let double_word = |j: usize| points[j / dim].coords()[j % dim].denom().magnitude().to_u128();
    // The word path's denominators as it read them: reading every one again took 2–4% longer
    // on a 30-digit derivative.
    let gcds = gcd::paired_gcds((0..n * dim).map(|j| match words[j] {
        Some(x) => Some((
            x.den,
            words[j + dim].map_or_else(|| double_word(j + dim), |y| Some(y.den))?,
        )),
        None => Some((double_word(j)?, double_word(j + dim)?)),
    }));
    // Built on the first coordinate past the word path: none where all fit.
    let mut big: Option<BigDenominators> = None;
    let mut long_weights: Option<LongWeights> = None;
    let mut out = Vec::with_capacity(n);
    for i in 1..=n {
        let (alpha, beta) = weights(i as u32);
        let moduli = match (small, u16::try_from(alpha), u16::try_from(beta)) {
            (Some(total), Ok(a), Ok(b)) => Some((SmallModulus::new(a), SmallModulus::new(b), total)),
            _ => None,
        };
        let (before, here) = (points[i - 1].coords(), points[i].coords());
        let coords = (0..dim).map(|k| {
            let j = (i - 1) * dim + k;
            let fast = match (moduli, words[j], words[j + dim]) {
                (Some((alpha, beta, total)), Some(mut x), Some(y)) => {
                    x.negative ^= negate_first;
                    pair_words(x, &alpha, y, &beta, &total, gcds[j])
                }
                _ => None,
            };
            fast.unwrap_or_else(|| {
                let g = match gcds[j] {
                    0 => big
                        .get_or_insert_with(|| BigDenominators::new(points))
                        .shared(j, dim, &before[k], &here[k]),
                    g => match u64::try_from(g) {
                        Ok(w) => Shared::Word(w),
                        Err(_) => Shared::Big(BigInt::from(g)),
                    },
                };
                let on_stack = match (&g, &moduli) {
                    (Shared::Word(g), Some(_)) => u32::try_from(*g).ok(),
                    _ => None,
                };
                let pair = on_stack.and_then(|g| {
                    let weights =
                        long_weights.get_or_insert_with(|| LongWeights::new(total, long_denominators(points)));
                    let (alpha, beta, total) = weights.at(alpha, beta);
                    let (a, b) = (&before[k], &here[k]);
                    let words = [a.numer().bits(), a.denom().bits(), b.numer().bits(), b.denom().bits()]
                        .into_iter()
                        .max()
                        .map_or(0, |bits| bits.div_ceil(64));
                    match words {
                        0..=4 => on_words::<4, 10>(a, negate_first, alpha, b, beta, total, g),
                        5..=8 => on_words::<8, 18>(a, negate_first, alpha, b, beta, total, g),
                        _ => on_words::<INPUT_WORDS, RESIDUE_WORDS>(a, negate_first, alpha, b, beta, total, g),
                    }
                });
                pair.unwrap_or_else(|| pair_big(&before[k], negate_first, alpha, &here[k], beta, total, &g))
            })
        });
        out.push(Point::from_valid(coords));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::gcd::gcd_u128;
    use proptest::prelude::*;

    /// Double words with shared factors of every size: products of a random common part and
    /// random cofactors, shifted by up to 40 bits.
    fn related_pair() -> impl Strategy<Value = (u128, u128)> {
        (1u64.., 1u64.., 1u64.., 0u32..40, 0u32..40).prop_map(|(common, x, y, sx, sy)| {
            let common = u128::from(common >> (common % 64));
            (
                (common * u128::from(x)).max(1) << sx,
                (common * u128::from(y >> 20)).max(1) << sy,
            )
        })
    }

    /// Pairs whose gcd is wider than a word: a 70- to 100-bit common part times small cofactors.
    fn wide_gcd_pair() -> impl Strategy<Value = (u128, u128)> {
        (any::<u128>(), 70u32..100, 1u32..1 << 20, 1u32..1 << 20).prop_map(|(common, bits, x, y)| {
            let common = (common >> (128 - bits)) | (1 << (bits - 1));
            (common * u128::from(x), common * u128::from(y))
        })
    }

    proptest! {
        #[test]
        fn lanes_agree_with_one_gcd_at_a_time(
            pairs in proptest::collection::vec(prop_oneof![related_pair(), wide_gcd_pair(), (1u128.., 1u128..)], 0..11),
            skipped in proptest::collection::vec(any::<bool>(), 11),
        ) {
            let input: Vec<Option<(u128, u128)>> =
                pairs.iter().zip(&skipped).map(|(&p, &skip)| (!skip).then_some(p)).collect();
            let got = gcd::paired_gcds(input.iter().copied());
            let want: Vec<u128> = input.iter().map(|p| p.map_or(0, |(a, b)| gcd_u128(a, b))).collect();
            prop_assert_eq!(got, want);
        }

        /// The big-integer pair against num-rational's own arithmetic, in lowest terms: long
        /// numerators and denominators (1 to 8 words) that share a factor of any length with
        /// each other (`g` of several words) and small primes with the weights and the total,
        /// negative values, zero, and the derivative's negated first term.
        #[test]
        fn big_pair_is_num_rationals(
            (x, y) in (proptest::collection::vec(any::<u64>(), 0..8), proptest::collection::vec(any::<u64>(), 0..8)),
            (d, e, common) in (proptest::collection::vec(any::<u64>(), 1..6), proptest::collection::vec(any::<u64>(), 1..6), proptest::collection::vec(any::<u64>(), 0..4)),
            (small_d, small_e) in (0usize..6, 0usize..6),
            (signs, negate_first) in (any::<(bool, bool)>(), any::<bool>()),
            (alpha, beta, total) in (1u32..70, 1u32..70, 1u32..70),
        ) {
            let big = |limbs: &[u64]| BigInt::from_biguint(Sign::Plus, BigUint::new(limbs.iter().flat_map(|&w| [w as u32, (w >> 32) as u32]).collect()));
            // Small primes the weights and the total may share, to every power up to 5.
            let smooth = |k: usize| BigInt::from(2u32.pow(k as u32) * 3u32.pow((k % 3) as u32) * 5u32.pow((k % 2) as u32) * 7u32.pow((k / 3) as u32));
            let common = big(&common).max(BigInt::one());
            let d = (big(&d).max(BigInt::one())) * &common * smooth(small_d);
            let e = (big(&e).max(BigInt::one())) * &common * smooth(small_e);
            let sign = |n: BigInt, negative: bool| if negative { -n } else { n };
            let a = BigRational::new(sign(big(&x) * smooth(small_e), signs.0), d);
            let b = BigRational::new(sign(big(&y), signs.1), e);
            let first = if negate_first { -&a } else { a.clone() };
            let want = (first * BigInt::from(alpha) + &b * BigInt::from(beta)) / BigInt::from(total);
            // `g` both ways the caller computes it: from dashu-int's copies, or directly.
            let (da, db) = (gcd::to_dashu(a.denom().magnitude()), gcd::to_dashu(b.denom().magnitude()));
            for g in [Shared::of_dashu(&da, &db), Shared::of(a.denom().magnitude(), b.denom().magnitude())] {
                let got = pair_big(&a, negate_first, alpha, &b, beta, total, &g);
                prop_assert_eq!(format!("{got:?}"), format!("{want:?}"));
                prop_assert_eq!(got, want.clone());
            }
        }

        #[test]
        fn exact_division_of_a_double_word(q in any::<u128>(), shift in 0u32..128, k in 1u32..) {
            // Quotients of every length, the product below 2^128.
            let q = (q >> shift) >> 32;
            prop_assert_eq!(div_exact_u128(q * u128::from(k), k), q);
            prop_assert_eq!(div_exact_u128(q, 1), q);
        }

        #[test]
        fn exact_division_by_a_small_divisor(q in any::<[u64; 3]>(), k in 1u32.., residues in 1u16..) {
            let quotient = U256([q[0], q[1], q[2], 0]);
            let Some(t) = quotient.times(u64::from(k)) else { return Ok(()) };
            prop_assert!(t.div_exact_small(k) == quotient);
            let modulus = SmallModulus::new(residues);
            prop_assert_eq!(u64::from(t.rem_small(u32::from(residues))), modulus.of_words(&t.0));
        }
    }
}
