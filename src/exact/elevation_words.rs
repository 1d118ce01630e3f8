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
//! When every input numerator and denominator has at most 110 bits (30-digit fractions
//! have 100), `t` and the denominator fit 256 bits and nothing is allocated but the two
//! integers of the result; otherwise, or when `g` is longer than a word, the coordinate is
//! computed on big integers (`pair_big`). The tests compare both with `==` against
//! [`BezierCurve::elevate_reference`](crate::BezierCurve::elevate_reference).

use crate::exact::gcd::{self, Part};
use crate::exact::small_rational::{gcd_u128, gcd_u64};
use crate::point::Point;
use num_bigint::{BigInt, BigUint, Sign};
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};

/// Inputs longer than this many bits take the big-integer path: with `α, n+1 < 2^32`, every
/// intermediate then fits 256 bits (`2^32 · 2^110 · 2^110 · 2 < 2^256`).
const WORD_INPUT_BITS: u64 = 110;

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

    /// `self / k` for a `0 < k < 2^32` known to divide `self`.
    fn div_small(&self, k: u32) -> Self {
        let k = u64::from(k);
        let mut out = [0u64; 4];
        let mut r = 0u64;
        for (h, half) in self.halves() {
            let v = (r << 32) | half;
            out[h / 2] |= (v / k) << (32 * (h % 2));
            r = v % k;
        }
        U256(out)
    }

    fn is_zero(&self) -> bool {
        *self == U256::ZERO
    }

    fn to_biguint(self) -> BigUint {
        let mut bytes = [0u8; 32];
        for (chunk, w) in bytes.chunks_exact_mut(8).zip(self.0) {
            chunk.copy_from_slice(&w.to_le_bytes());
        }
        // One allocation, the digits of the result.
        BigUint::from_bytes_le(&bytes)
    }
}

/// `x mod k` of a double word by `0 < k < 2^32`, in 64-bit divisions.
fn rem_u128_small(x: u128, k: u32) -> u32 {
    U256([x as u64, (x >> 64) as u64, 0, 0]).rem_small(k)
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

/// `(α x + β y) / total` in lowest terms, on words; `None` when `gcd(den x, den y)` does
/// not fit 32 bits (or a bound is exceeded), for the big-integer path.
fn pair_words(x: WordFraction, alpha: u32, y: WordFraction, beta: u32, total: u32) -> Option<BigRational> {
    let g = gcd_u128(x.den, y.den);
    let g = u32::try_from(g).ok()?;
    let (mut dx, mut dy) = if g == 1 {
        (x.den, y.den)
    } else {
        (x.den / u128::from(g), y.den / u128::from(g))
    };
    // t = α x dy + β y dx, with signs.
    let u = U256::product(x.num, dy).times(u64::from(alpha))?;
    let v = U256::product(y.num, dx).times(u64::from(beta))?;
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
    // gcd(t, dx) = gcd(α, dx) and then gcd(t, dy) = gcd(β, dy): see the module documentation.
    let h = gcd_u64(u64::from(alpha), u64::from(rem_u128_small(dx, alpha))) as u32;
    if h != 1 {
        t = t.div_small(h);
        dx /= u128::from(h);
    }
    let h = gcd_u64(u64::from(beta), u64::from(rem_u128_small(dy, beta))) as u32;
    if h != 1 {
        t = t.div_small(h);
        dy /= u128::from(h);
    }
    let mut shared = g;
    if g != 1 {
        let h = gcd_u64(u64::from(g), u64::from(t.rem_small(g))) as u32;
        if h != 1 {
            t = t.div_small(h);
            shared /= h;
        }
    }
    let mut total = total;
    let h = gcd_u64(u64::from(total), u64::from(t.rem_small(total))) as u32;
    if h != 1 {
        t = t.div_small(h);
        total /= h;
    }
    // dx · shared ≤ den x < 2^110; the whole denominator is below 2^252.
    let den = U256::product(dx * u128::from(shared), dy).times(u64::from(total))?;
    let sign = if negative { Sign::Minus } else { Sign::Plus };
    Some(BigRational::new_raw(
        BigInt::from_biguint(sign, t.to_biguint()),
        BigInt::from_biguint(Sign::Plus, den.to_biguint()),
    ))
}

/// `(α a + β b) / total` in lowest terms on big integers.
fn pair_big(a: &BigRational, alpha: u32, b: &BigRational, beta: u32, total: &BigInt) -> BigRational {
    // a = x/d, b = y/e over L = lcm(d, e).
    let l = gcd::lcm_int(a.denom(), b.denom());
    let x = a.numer() * (&l / a.denom()) * alpha;
    let y = b.numer() * (&l / b.denom()) * beta;
    gcd::reduce(x + y, &[Part::Number(&l), Part::Number(total)])
}

/// One elevation step (7) of the points, each new coordinate reduced on its own.
pub(crate) fn elevate_pairwise(points: &[Point<BigRational>]) -> Vec<Point<BigRational>> {
    let n = points.len() - 1;
    let total = u32::try_from(n + 1).expect("degrees are limited far below 2^32");
    let total_big = BigInt::from(total);
    let dim = points[0].dim();
    let words: Vec<Option<WordFraction>> = points
        .iter()
        .flat_map(|p| p.coords().iter().map(WordFraction::of))
        .collect();
    let mut out = Vec::with_capacity(n + 2);
    out.push(points[0].clone());
    for i in 1..=n {
        let (alpha, beta) = (i as u32, total - i as u32);
        let (before, here) = (points[i - 1].coords(), points[i].coords());
        let coords = (0..dim).map(|k| {
            let fast = match (words[(i - 1) * dim + k], words[i * dim + k]) {
                (Some(x), Some(y)) => pair_words(x, alpha, y, beta, total),
                _ => None,
            };
            fast.unwrap_or_else(|| pair_big(&before[k], alpha, &here[k], beta, &total_big))
        });
        out.push(Point::from_valid(coords));
    }
    out.push(points[n].clone());
    out
}
