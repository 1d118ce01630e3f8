//! The greatest common divisor of big integers, and the one reduction a fraction-free kernel
//! does at its end.
//!
//! num-bigint's `gcd` is Stein's binary algorithm without a first division: the gcd of a
//! 40,000-bit and a 100-bit number takes 40,000 big subtractions, which made the common
//! denominator of a few hundred 30-digit denominators, and the final reduction, the whole
//! cost of an exact evaluation. Here the gcd of big numbers is dashu-int's (Lehmer's
//! algorithm, unbalanced operands divided first), and a denominator known as a product of
//! parts (`D qⁿ`) is reduced part by part, which is never more work and usually far less.

use num_bigint::{BigInt, BigUint, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// The greatest common divisor of two unsigned words (binary gcd, no division).
pub(crate) fn gcd_u64(mut a: u64, mut b: u64) -> u64 {
    if a == 0 {
        return b;
    }
    if b == 0 {
        return a;
    }
    let shift = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    loop {
        // Both odd; min and difference without a branch on which is larger (conditional
        // moves): that branch is a coin flip the processor mispredicts half the time.
        b >>= b.trailing_zeros();
        let difference = a.abs_diff(b);
        a = a.min(b);
        b = difference;
        if b == 0 {
            return a << shift;
        }
    }
}

/// The greatest common divisor of two unsigned double words.
pub(crate) fn gcd_u128(mut a: u128, mut b: u128) -> u128 {
    if a == 0 {
        return b;
    }
    if b == 0 {
        return a;
    }
    let shift = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    loop {
        if a <= u64::MAX as u128 && b <= u64::MAX as u128 {
            return (gcd_u64(a as u64, (b >> b.trailing_zeros()) as u64) as u128) << shift;
        }
        b >>= b.trailing_zeros();
        let difference = a.abs_diff(b);
        a = a.min(b);
        b = difference;
        if b == 0 {
            return a << shift;
        }
    }
}

/// `gcd(a, b)` of natural numbers: within two words by a machine gcd; with one operand a
/// word, by the other's remainder (no copy); otherwise by dashu-int's (its digits are
/// copied in and out: still faster than num-bigint's, `benches/exact.rs`, and than a
/// Lehmer gcd of ours on words, which `scripts/gcd_peers.py` measured at 1.19 µs against
/// dashu-int's 0.67 µs on 384-bit pairs — not kept).
pub fn gcd(a: &BigUint, b: &BigUint) -> BigUint {
    if let (Some(x), Some(y)) = (a.to_u128(), b.to_u128()) {
        return BigUint::from(gcd_u128(x, y));
    }
    for (long, short) in [(a, b), (b, a)] {
        if let Some(m) = short.to_u64() {
            if m == 0 {
                return long.clone();
            }
            return BigUint::from(gcd_u64(m, rem_word(long, m)));
        }
    }
    let g = dashu_int::ops::Gcd::gcd(&to_dashu(a), &to_dashu(b));
    from_words(g.as_words())
}

/// `x mod m` for a word `m > 0`, from `x`'s words in place.
pub(crate) fn rem_word(x: &BigUint, m: u64) -> u64 {
    if let Ok(small) = u32::try_from(m) {
        // Half words: each step a 64-bit division (an instruction, a 128-bit one a call).
        // Barrett's reduction (two multiplications a step) was no faster on this machine
        // (AMD EPYC, 2026-12-05).
        let m = u64::from(small);
        return x.iter_u64_digits().rev().fold(0u64, |r, w| {
            let r = ((r << 32) | (w >> 32)) % m;
            ((r << 32) | (w & 0xFFFF_FFFF)) % m
        });
    }
    let m = u128::from(m);
    x.iter_u64_digits()
        .rev()
        .fold(0u128, |r, w| ((r << 64) | u128::from(w)) % m) as u64
}

/// `x` in dashu-int's form: converted once where one number takes part in several gcds.
pub(crate) fn to_dashu(x: &BigUint) -> dashu_int::UBig {
    // Up to 16 words through a buffer on the stack: one allocation, dashu-int's own.
    let mut words = [0u64; 16];
    let digits = x.iter_u64_digits();
    if digits.len() > words.len() {
        return dashu_int::UBig::from_words(&x.to_u64_digits());
    }
    let len = digits.len();
    for (w, d) in words.iter_mut().zip(digits) {
        *w = d;
    }
    dashu_int::UBig::from_words(&words[..len])
}

/// A gcd of two denominators: a word in the common case, where the reductions that use it
/// are remainders and exact divisions by a word.
pub(crate) enum Shared {
    Word(u64),
    Big(BigInt),
}

impl Shared {
    /// `gcd(a, b)` of positive integers already in dashu-int's form; dashu-int's gcd
    /// copies its operands into its own buffers, so the only copies are its own.
    pub(crate) fn of_dashu(a: &dashu_int::UBig, b: &dashu_int::UBig) -> Self {
        let g = dashu_int::ops::Gcd::gcd(a, b);
        match g.as_words() {
            [w] => Shared::Word(*w),
            words => Shared::Big(BigInt::from_biguint(Sign::Plus, from_words(words))),
        }
    }

    /// `gcd(a, b)` of positive integers by [`gcd`] (no copies when both fit two words or
    /// one fits a word).
    pub(crate) fn of(a: &BigUint, b: &BigUint) -> Self {
        let g = gcd(a, b);
        match g.to_u64() {
            Some(w) => Shared::Word(w),
            None => Shared::Big(BigInt::from_biguint(Sign::Plus, g)),
        }
    }
}

/// `gcd(a, m)` and `gcd(m, c)` of positive integers (`a_natural`, `c_natural`: `a` and `c`
/// as num-bigint's) from one gcd `G = gcd(m, a c)` of denominator length, where each
/// `gcd(m, ·)` would take one: `gcd(G, a) = gcd(m, a c, a) = gcd(m, a)` as `a` divides
/// `a c`, and likewise for `c`. `G` is usually a word (the small primes the three share),
/// and the two gcds are then remainders by a word.
pub(crate) fn shared_pair(
    a: &dashu_int::UBig,
    m: &dashu_int::UBig,
    c: &dashu_int::UBig,
    a_natural: &BigUint,
    c_natural: &BigUint,
) -> (Shared, Shared) {
    let whole = dashu_int::ops::Gcd::gcd(m, &(a * c));
    let with = |x: &BigUint| match whole.as_words() {
        [1] => Shared::Word(1),
        [w] => Shared::Word(gcd_u64(*w, rem_word(x, *w))),
        words => Shared::of(&from_words(words), x),
    };
    (with(a_natural), with(c_natural))
}

/// The natural number of little-endian `words` (zero top words allowed): up to 34 words
/// the halves go through a buffer on the stack, so the only allocation is the result's.
#[inline]
pub(crate) fn from_words(words: &[u64]) -> BigUint {
    // Without its zero top words: a one-word number then stays inline in num-bigint's
    // (passed whole, a 5-digit elevation took 20% longer).
    let words = &words[..words.iter().rposition(|&w| w != 0).map_or(0, |i| i + 1)];
    let mut halves = [0u32; 68];
    if 2 * words.len() > halves.len() {
        return BigUint::new(words.iter().flat_map(|&w| [w as u32, (w >> 32) as u32]).collect());
    }
    for (pair, w) in halves.chunks_exact_mut(2).zip(words) {
        pair[0] = *w as u32;
        pair[1] = (w >> 32) as u32;
    }
    BigUint::from_slice(&halves[..2 * words.len()])
}

/// `x` as dashu-int's signed integer.
pub(crate) fn to_ibig(x: &BigInt) -> dashu_int::IBig {
    let sign = if x.sign() == Sign::Minus {
        dashu_int::Sign::Negative
    } else {
        dashu_int::Sign::Positive
    };
    dashu_int::IBig::from_parts(sign, to_dashu(x.magnitude()))
}

/// `x` as num-bigint's.
pub(crate) fn from_ibig(x: &dashu_int::IBig) -> BigInt {
    let (sign, words) = x.as_sign_words();
    let sign = match sign {
        dashu_int::Sign::Negative => Sign::Minus,
        dashu_int::Sign::Positive => Sign::Plus,
    };
    BigInt::from_biguint(sign, from_words(words))
}

/// `words / k` in place, for a `0 < k < 2^32` known to divide the number: the power of two
/// by a shift, the odd part by Hensel's exact division (a multiplication by `k⁻¹ mod 2^64`
/// per word, as GMP's `mpn_divexact_1`), where long division chains two hardware divisions
/// a word.
#[inline]
pub(crate) fn divide_exactly(words: &mut [u64], k: u32) {
    let zeros = k.trailing_zeros();
    if zeros != 0 {
        for j in 0..words.len() {
            let high = words.get(j + 1).map_or(0, |&w| w << (64 - zeros));
            words[j] = (words[j] >> zeros) | high;
        }
    }
    let odd = u64::from(k >> zeros);
    if odd == 1 {
        return;
    }
    // Newton's iteration doubles the correct low bits: 3·odd XOR 2 is right to 5 bits.
    let mut inverse = odd.wrapping_mul(3) ^ 2;
    for _ in 0..4 {
        inverse = inverse.wrapping_mul(2u64.wrapping_sub(odd.wrapping_mul(inverse)));
    }
    let mut borrow = 0u64;
    for w in words {
        let (s, below) = w.overflowing_sub(borrow);
        let q = s.wrapping_mul(inverse);
        *w = q;
        borrow = ((u128::from(q) * u128::from(odd)) >> 64) as u64 + u64::from(below);
    }
}

/// The gcds of `LANES` pairs of nonzero double words, computed together: the binary gcd is
/// a chain of dependent steps that leaves most of the processor idle, and independent
/// chains interleaved in one loop fill it (`benches/exact.rs`, `exact_big/elevate`).
///
/// Each lane holds two odd numbers `a`, `b` (or `b = 0` once finished) as high and low
/// words, and one step takes `a ← min(a, b)`, `b ← |b − a|` without its trailing zeros:
/// the difference of two odd numbers is even and nonzero below 2^128 unless they are equal,
/// so its trailing zeros are in the low word but for a low word of zeros (a branch almost
/// never taken), and the shift is a funnel shift by less than 64 — no selects between a
/// shift by less and by more than a word, no 128-bit trailing-zero count. A finished lane
/// keeps its value by a select.
fn gcd_u128_lanes<const LANES: usize>(first: [u128; LANES], second: [u128; LANES]) -> [u128; LANES] {
    let mut shift = [0u32; LANES];
    let (mut a_high, mut a_low) = ([0u64; LANES], [0u64; LANES]);
    let (mut b_high, mut b_low) = ([0u64; LANES], [0u64; LANES]);
    for lane in 0..LANES {
        shift[lane] = (first[lane] | second[lane]).trailing_zeros();
        let a = first[lane] >> first[lane].trailing_zeros();
        let b = second[lane] >> second[lane].trailing_zeros();
        (a_high[lane], a_low[lane]) = ((a >> 64) as u64, a as u64);
        (b_high[lane], b_low[lane]) = ((b >> 64) as u64, b as u64);
    }
    // Double words while any unfinished lane needs them; then single words, a third of the
    // work each. A lane finished here may hold a gcd beyond 64 bits: kept whole.
    let unfinished_high = |a_high: &[u64; LANES], b_high: &[u64; LANES], b_low: &[u64; LANES]| {
        (0..LANES).fold(0, |high, lane| {
            let finished = (b_high[lane] | b_low[lane]) == 0;
            high | if finished { 0 } else { a_high[lane] | b_high[lane] }
        })
    };
    while unfinished_high(&a_high, &b_high, &b_low) != 0 {
        for lane in 0..LANES {
            let finished = (b_high[lane] | b_low[lane]) == 0;
            let (low, borrow_low) = b_low[lane].overflowing_sub(a_low[lane]);
            let (high, borrow_high) = b_high[lane].overflowing_sub(a_high[lane]);
            let (high, borrow_carried) = high.overflowing_sub(u64::from(borrow_low));
            let negative = borrow_high | borrow_carried;
            // The smaller of the two; a finished lane keeps its `a`.
            if negative && !finished {
                (a_high[lane], a_low[lane]) = (b_high[lane], b_low[lane]);
            }
            // |b − a| by two's complement when negative.
            let mask = 0u64.wrapping_sub(u64::from(negative));
            let (low, carry) = (low ^ mask).overflowing_add(u64::from(negative));
            let high = (high ^ mask).wrapping_add(u64::from(carry));
            let (odd_high, odd_low) = if low != 0 {
                let zeros = low.trailing_zeros();
                // `(high << 1) << (63 − zeros)`: `high << (64 − zeros)` without a shift by 64.
                (high >> zeros, (low >> zeros) | ((high << 1) << (63 - zeros)))
            } else if high != 0 {
                (0, high >> high.trailing_zeros())
            } else {
                (0, 0)
            };
            (b_high[lane], b_low[lane]) = if finished { (0, 0) } else { (odd_high, odd_low) };
        }
    }
    let (mut a, mut b) = (a_low, b_low);
    loop {
        let mut left = 0;
        for lane in 0..LANES {
            let finished = b[lane] == 0;
            // |b − a| and b − a have the same trailing zeros.
            let zeros = b[lane].wrapping_sub(a[lane]).trailing_zeros() & 63;
            let smaller = a[lane].min(b[lane]);
            let odd = b[lane].abs_diff(a[lane]) >> zeros;
            a[lane] = if finished { a[lane] } else { smaller };
            b[lane] = if finished { 0 } else { odd };
            left |= b[lane];
        }
        if left == 0 {
            break;
        }
    }
    let mut out = [0u128; LANES];
    for lane in 0..LANES {
        // A lane whose gcd exceeds 64 bits finished above, its high word nonzero.
        let gcd = (u128::from(a_high[lane]) << 64) | u128::from(a[lane]);
        out[lane] = gcd << shift[lane];
    }
    out
}

/// `gcd(a, b)` for every pair of nonzero double words given (0 for those not given), two
/// pairs at a time: with the word-split steps above, two lanes were faster than four on the
/// case's 100-bit denominators (`git log -p -- docs/performance.md`, issue 24's fifth pass).
pub(crate) fn paired_gcds(pairs: impl Iterator<Item = Option<(u128, u128)>>) -> Vec<u128> {
    const LANES: usize = 2;
    let mut gcds = Vec::new();
    let mut first = [1u128; LANES];
    let mut second = [1u128; LANES];
    let mut slots = [0usize; LANES];
    let mut filled = 0;
    let flush = |first: &[u128; LANES], second: &[u128; LANES], slots: &[usize], gcds: &mut Vec<u128>| {
        for (&slot, g) in slots.iter().zip(gcd_u128_lanes(*first, *second)) {
            gcds[slot] = g;
        }
    };
    for (slot, pair) in pairs.enumerate() {
        gcds.push(0);
        if let Some((d, e)) = pair {
            (first[filled], second[filled], slots[filled]) = (d, e, slot);
            filled += 1;
            if filled == LANES {
                flush(&first, &second, &slots, &mut gcds);
                filled = 0;
            }
        }
    }
    // The unused lanes compute gcd(1, 1) and are not read.
    first[filled..].fill(1);
    second[filled..].fill(1);
    flush(&first, &second, &slots[..filled], &mut gcds);
    gcds
}

/// `gcd(a, b)` of integers, nonnegative.
pub fn gcd_int(a: &BigInt, b: &BigInt) -> BigInt {
    // Two double words: no copies of the operands.
    if let (Some(x), Some(y)) = (a.magnitude().to_u128(), b.magnitude().to_u128()) {
        return BigInt::from(gcd_u128(x, y));
    }
    BigInt::from_biguint(Sign::Plus, gcd(a.magnitude(), b.magnitude()))
}

/// `gcd(num, Π f_j)` from the gcds `h_j = gcd(num, f_j)` of `num` with each factor (the
/// `h_j ≠ 1` suffice): it is `gcd(num, Π h_j)`, a gcd with a product of short numbers
/// instead of the long product of the factors.
///
/// For a prime `p` with exponent `v` in `num` and `e_j` in `f_j`: `Π h_j` has exponent
/// `Σ_j min(v, e_j)`, which is at least `min(v, Σ_j e_j)` (the exponent in `gcd(num, Π f_j)`)
/// and at most `Σ_j e_j`; so its gcd with `num`, exponent `min(v, Σ_j min(v, e_j))`, has
/// exactly `min(v, Σ_j e_j)`.
pub fn gcd_with_product(num: &BigInt, factor_gcds: &[BigInt]) -> BigInt {
    match factor_gcds {
        [] => BigInt::one(),
        [h] => h.clone(),
        _ => gcd_int(num, &product(factor_gcds)),
    }
}

/// `Π xs` by halves, so that the long products are of balanced operands.
pub fn product(xs: &[BigInt]) -> BigInt {
    match xs {
        [] => BigInt::one(),
        [x] => x.clone(),
        _ => {
            let (left, right) = xs.split_at(xs.len() / 2);
            product(left) * product(right)
        }
    }
}

/// `num` and `base^e` divided by their gcd, `base > 0`: gcds with the base, each no
/// longer than the base (usually one, which finds the base prime to `num`), instead of one
/// gcd with the whole power. A step divides `g = gcd(gcd(num, base), left)` out of `num`
/// and of what is left of the power as often as both hold it; for a prime of exponent `f`
/// in the base, a step takes all of it from one side or at least `f` from both, so `e`
/// steps end it. A step that finds nothing in common ends it. Past a few steps, the rest is
/// one gcd with what is left of the power.
pub fn reduce_by_power(mut num: BigInt, base: &BigInt, e: usize) -> (BigInt, BigInt) {
    if num.is_zero() {
        return (num, BigInt::one());
    }
    // The base's power of two by shifts: `gcd(num, 2^(k e) o^e) = 2^min(v₂(num), k e) ·
    // gcd(num, o^e)` for an odd `o`, where the loop below would take a gcd of `q`'s length
    // per factor 2 it finds (an even 20-digit `t` at degree 20: 57% of an eval).
    if let Some(zeros) = base.trailing_zeros().filter(|&z| z > 0 && e > 0) {
        let (num, left_twos) = take_twos(num, zeros, e);
        let (num, left) = reduce_by_power(num, &(base >> zeros), e);
        return (num, left << left_twos);
    }
    let mut left = num_traits::pow(base.clone(), e);
    if e == 0 || base.is_one() {
        return (num, left);
    }
    for _ in 0..e.min(SHORT_POWER) {
        // A prime in both `num` and what is left of the power divides the base, so it
        // divides `gcd(gcd(num, base), left)`: when that is 1, the two share nothing.
        let mut g = gcd_int(&num.mod_floor(base), base);
        if !g.is_one() {
            g = gcd_int(&left.mod_floor(&g), &g);
        }
        if g.is_one() {
            return (num, left);
        }
        // All of `g` that both hold, at once: a small prime of the base that `num` holds to
        // a high power (the curve's denominators' share of it) would otherwise take a step
        // a factor, and past `SHORT_POWER` steps a gcd with the whole power.
        if let Some(w) = g.to_u32() {
            // Every prime the two share divides `g`, and this takes all of each: done.
            divide_out_word(&mut num, &mut left, w);
            return (num, left);
        }
        loop {
            num = num.div_floor(&g);
            left = left.div_floor(&g);
            if !(num.is_multiple_of(&g) && left.is_multiple_of(&g)) {
                break;
            }
        }
    }
    if e > SHORT_POWER {
        let g = gcd_int(&num, &left);
        if !g.is_one() {
            num = num.div_floor(&g);
            left = left.div_floor(&g);
        }
    }
    (num, left)
}

/// Divides `num` and `left` (both nonzero) by all they share of the primes of the odd
/// word `w > 1`: by blocks, the largest power of `w` within 32 bits, whose gcds with
/// the two are remainders by a word (`c = gcd(gcd(num, block), left)` a block, until it is
/// 1), and the divisions exact ones by a word ([`divide_exactly`]). A prime of `w` left in
/// one of them is then missing from the other.
fn divide_out_word(num: &mut BigInt, left: &mut BigInt, w: u32) {
    let mut block = w;
    while let Some(b) = block.checked_mul(w) {
        block = b;
    }
    let block = u64::from(block);
    loop {
        let a = gcd_u64(block, rem_word(num.magnitude(), block));
        let c = if a == 1 {
            1
        } else {
            gcd_u64(a, rem_word(left.magnitude(), a))
        };
        if c == 1 {
            return;
        }
        let c = u32::try_from(c).expect("a divisor of the block, which is within 32 bits");
        *num = divided_exactly(std::mem::take(num), c);
        *left = divided_exactly(std::mem::take(left), c);
    }
}

/// `x / k` for a `0 < k < 2^32` that divides `x`, by [`divide_exactly`].
fn divided_exactly(x: BigInt, k: u32) -> BigInt {
    let (sign, magnitude) = x.into_parts();
    let mut words = magnitude.to_u64_digits();
    divide_exactly(&mut words, k);
    BigInt::from_biguint(sign, from_words(&words))
}

/// `num` without the power of two it shares with `2^(zeros · e)` (a base's power of two,
/// `zeros` its trailing zeros), and the exponent of two left in that power: `gcd(num,
/// 2^(k e) o^e) = 2^min(v₂(num), k e) · gcd(num, o^e)` for an odd `o`.
pub(crate) fn take_twos(num: BigInt, zeros: u64, e: usize) -> (BigInt, u64) {
    let total = zeros * e as u64;
    let take = num.trailing_zeros().map_or(0, |z| z.min(total));
    (num >> take, total - take)
}

/// `lcm(a, b)` of positive integers.
pub fn lcm_int(a: &BigInt, b: &BigInt) -> BigInt {
    let g = gcd_int(a, b);
    if g.is_one() {
        a * b
    } else {
        a / g * b
    }
}

/// The gcds with the base that [`reduce_by_power`] takes before one gcd with the rest of
/// the power: enough for the squares and cubes of the kernels, few passes over a long `num`.
const SHORT_POWER: usize = 4;

/// One factor of a denominator: a number, or a power `base^exponent` (kept unexpanded, so
/// that a parameter's `qⁿ` is tested against its base first).
pub enum Part<'a> {
    /// The factor itself.
    Number(&'a BigInt),
    /// `base^exponent`.
    Power(&'a BigInt, usize),
}

/// `num / Π parts` in lowest terms with a positive denominator; the parts are positive.
///
/// Each part is reduced against what is left of the numerator: after part `j`, the two
/// share no prime (a prime in both would divide their gcd, which was divided out), and
/// later parts only shrink the numerator, so the product of the remainders is the reduced
/// denominator. A power whose base is prime to the numerator is skipped whole.
pub fn reduce(mut num: BigInt, parts: &[Part<'_>]) -> BigRational {
    let mut den = BigInt::one();
    for part in parts {
        let mut left = match part {
            Part::Number(d) => (*d).clone(),
            Part::Power(base, e) => {
                let (rest, left) = reduce_by_power(num, base, *e);
                num = rest;
                den *= left;
                continue;
            }
        };
        if !num.is_zero() {
            let g = gcd_int(&num, &left);
            if !g.is_one() {
                num = num.div_floor(&g);
                left = left.div_floor(&g);
            }
        }
        den *= left;
    }
    if num.is_zero() {
        return BigRational::new_raw(num, BigInt::one());
    }
    BigRational::new_raw(num, den)
}

/// `x / y` in lowest terms for reduced `x` and `y ≠ 0`, the way GMP divides two fractions
/// (Knuth, TAOCP vol. 2, 4.5.1): `(a/b) / (c/d) = (a/g₁ · d/g₂) / (b/g₂ · c/g₁)` with
/// `g₁ = gcd(a, c)`, `g₂ = gcd(b, d)` — two gcds of numbers half as long as those of the
/// product, by [`gcd_int`] instead of num-rational's binary gcd.
pub fn divide(x: &BigRational, y: &BigRational) -> BigRational {
    let (a, b, c, d) = (x.numer(), x.denom(), y.numer(), y.denom());
    if a.is_zero() {
        return BigRational::new_raw(BigInt::zero(), BigInt::one());
    }
    let part = |u: &BigInt, g: &BigInt| if g.is_one() { u.clone() } else { u / g };
    let (g1, g2) = (gcd_int(a, c), gcd_int(b, d));
    let num = part(a, &g1) * part(d, &g2);
    let den = part(b, &g2) * part(c, &g1);
    if den.is_negative() {
        BigRational::new_raw(-num, -den)
    } else {
        BigRational::new_raw(num, den)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn big(digits: &[u64]) -> BigUint {
        BigUint::from_slice(
            &digits
                .iter()
                .flat_map(|d| [*d as u32, (*d >> 32) as u32])
                .collect::<Vec<_>>(),
        )
    }

    /// Long operands, where a big-integer library switches algorithms: against num-bigint's
    /// gcd, balanced and unbalanced, with a long common factor.
    #[test]
    fn gcd_of_long_numbers_is_num_bigints() {
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut words = |n: usize| -> Vec<u64> {
            (0..n)
                .map(|_| {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    state
                })
                .collect()
        };
        for (la, lb, lc) in [
            (40, 40, 30),
            (300, 290, 250),
            (2000, 2000, 1500),
            (3000, 2, 1),
            (1, 4000, 60),
        ] {
            let c = big(&words(lc));
            let (x, y) = (big(&words(la)) * &c, big(&words(lb)) * &c);
            assert_eq!(gcd(&x, &y), Integer::gcd(&x, &y), "{la} {lb} {lc}");
        }
    }

    /// Double words of every shape the lanes meet: one, powers of two, values near 2^110 and
    /// 2^128, a shared factor wider than a word, and random ones.
    fn double_word() -> impl Strategy<Value = u128> {
        prop_oneof![
            Just(1u128),
            (0u32..128).prop_map(|k| 1u128 << k),
            (0u128..1 << 20).prop_map(|d| (1u128 << 110) - 1 - d),
            (0u128..1 << 20).prop_map(|d| u128::MAX - d),
            (1u128..)
                .prop_map(|x| x >> (x % 128) as u32)
                .prop_filter("nonzero", |&x| x != 0),
            1u128..,
        ]
    }

    /// Pairs of double words: equal, sharing a factor of 1 to 100 bits times small
    /// cofactors and powers of two, or drawn apart.
    fn double_word_pair() -> impl Strategy<Value = (u128, u128)> {
        prop_oneof![
            double_word().prop_map(|x| (x, x)),
            (any::<u128>(), 1u32..100, 1u32..1 << 24, 1u32..1 << 24, 0u32..4, 0u32..4).prop_map(
                |(common, bits, x, y, sx, sy)| {
                    let common = (common >> (128 - bits)) | (1 << (bits - 1));
                    ((common * u128::from(x)) << sx, (common * u128::from(y)) << sy)
                }
            ),
            (double_word(), double_word()),
        ]
    }

    proptest! {
        /// The interleaved word gcds against num-bigint's gcd, in lanes of two and four and
        /// through `paired_gcds`.
        #[test]
        fn word_gcd_lanes_are_num_bigints(pairs in proptest::collection::vec(double_word_pair(), 4)) {
            let want: Vec<u128> = pairs
                .iter()
                .map(|&(a, b)| Integer::gcd(&BigUint::from(a), &BigUint::from(b)).to_u128().expect("fits"))
                .collect();
            let (first, second): (Vec<u128>, Vec<u128>) = pairs.iter().copied().unzip();
            let four = gcd_u128_lanes::<4>(first.clone().try_into().expect("4"), second.clone().try_into().expect("4"));
            prop_assert_eq!(&four[..], &want[..]);
            let two = gcd_u128_lanes::<2>([first[0], first[3]], [second[0], second[3]]);
            prop_assert_eq!(two, [want[0], want[3]]);
            let skipping = pairs.iter().enumerate().map(|(i, &p)| (i != 1).then_some(p));
            let paired = paired_gcds(skipping);
            prop_assert_eq!(paired, vec![want[0], 0, want[2], want[3]]);
        }

        /// The remainder by a word against num-bigint's, for divisors of every size (1, the
        /// largest below 2^32, and above).
        #[test]
        fn remainder_by_a_word_is_num_bigints(
            x in proptest::collection::vec(any::<u64>(), 0..10),
            m in prop_oneof![Just(1u64), Just(2), Just(u64::from(u32::MAX)), 1u64..1 << 16, 1u64..1 << 32, 1u64..],
        ) {
            let x = big(&x);
            prop_assert_eq!(BigUint::from(rem_word(&x, m)), &x % m);
            let all_ones = (BigUint::one() << 640u32) - 1u32;
            prop_assert_eq!(BigUint::from(rem_word(&all_ones, m)), &all_ones % m);
        }

        /// Against num-bigint's own gcd, on numbers with common factors, near-equal lengths
        /// and very different ones, zero among them.
        #[test]
        fn gcd_is_num_bigints(
            a in proptest::collection::vec(any::<u64>(), 0..12),
            b in proptest::collection::vec(any::<u64>(), 0..12),
            c in proptest::collection::vec(any::<u64>(), 0..4),
        ) {
            let (a, b, c) = (big(&a), big(&b), big(&c));
            let (x, y) = (&a * &c, &b * &c);
            prop_assert_eq!(gcd(&x, &y), Integer::gcd(&x, &y));
            prop_assert_eq!(gcd(&a, &b), Integer::gcd(&a, &b));
            prop_assert_eq!(gcd(&x, &b), Integer::gcd(&x, &b));
        }

        /// `gcd(num, Π f_j) = gcd(num, Π gcd(num, f_j))`, on factors that repeat primes,
        /// share them, are 1, or are long, against num-bigint's gcd of the whole product.
        #[test]
        fn gcd_with_a_product_from_the_factors_gcds(
            num in proptest::collection::vec(any::<u64>(), 1..6),
            num_primes in proptest::collection::vec((0usize..8, 0u32..6), 0..6),
            factors in proptest::collection::vec(
                (proptest::collection::vec((0usize..8, 0u32..4), 0..4), proptest::collection::vec(any::<u64>(), 0..3)),
                0..12,
            ),
            negative in any::<bool>(),
        ) {
            const PRIMES: [u64; 8] = [2, 3, 5, 7, 11, 13, 1_000_003, 18_446_744_073_709_551_557];
            let with_primes = |base: BigUint, powers: &[(usize, u32)]| {
                powers.iter().fold(base, |acc, &(p, e)| acc * BigUint::from(PRIMES[p]).pow(e))
            };
            let n = with_primes(big(&num), &num_primes);
            let n = BigInt::from_biguint(if negative { Sign::Minus } else { Sign::Plus }, n);
            let factors: Vec<BigInt> = factors
                .iter()
                .map(|(powers, rest)| {
                    let rest = if rest.is_empty() { BigUint::one() } else { big(rest).max(BigUint::one()) };
                    BigInt::from_biguint(Sign::Plus, with_primes(rest, powers))
                })
                .collect();
            let gcds: Vec<BigInt> = factors.iter().map(|f| Integer::gcd(&n, f)).filter(|h| !h.is_one()).collect();
            let whole = Integer::gcd(&n, &factors.iter().product::<BigInt>());
            prop_assert_eq!(gcd_with_product(&n, &gcds), whole);
        }

        /// `reduce_by_power` is lowest terms of `num / base^e`.
        #[test]
        fn reduce_by_power_is_lowest_terms(
            n in prop_oneof![Just(0i64), any::<i64>()], k in 0u32..12, base in 1u64..60, e in 0usize..9,
        ) {
            let b = BigInt::from(base);
            let num = BigInt::from(n) * b.pow(k);
            let (reduced, den) = reduce_by_power(num.clone(), &b, e);
            let expected = BigRational::new(num, b.pow(e as u32));
            prop_assert_eq!(&reduced, expected.numer());
            prop_assert_eq!(&den, expected.denom());
        }

        /// The same with long bases (one to three words), negative numerators sharing a
        /// power of a part of the base, against `BigRational::new`.
        #[test]
        fn reduce_by_power_of_long_bases(
            digits in proptest::collection::vec(any::<u64>(), 1..4),
            part in 1u64..1000, k in 0u32..7, e in 0usize..7, n in any::<i64>(),
        ) {
            let base = BigInt::from_biguint(Sign::Plus, big(&digits).max(BigUint::one())) * part;
            let num = BigInt::from(n) * num_traits::pow(BigInt::from(part), k as usize) * num_traits::pow(base.clone(), (k / 2) as usize);
            let (reduced, den) = reduce_by_power(num.clone(), &base, e);
            let expected = BigRational::new(num, num_traits::pow(base, e));
            prop_assert_eq!(&reduced, expected.numer());
            prop_assert_eq!(&den, expected.denom());
        }

        /// A long base with a small prime that `num` holds to a high power (a curve's
        /// denominators' share of a parameter's prime), more or less often than the power
        /// does: against `BigRational::new`.
        #[test]
        fn reduce_by_power_of_a_shared_small_prime(
            digits in proptest::collection::vec(any::<u64>(), 1..3),
            prime in prop_oneof![Just(3u64), Just(5), Just(7), Just(65_521)],
            k in 0u32..40, e in 0usize..30, n in any::<i64>(),
        ) {
            let base = BigInt::from_biguint(Sign::Plus, big(&digits).max(BigUint::one())) * prime;
            let num = BigInt::from(n) * num_traits::pow(BigInt::from(prime), k as usize);
            let (reduced, den) = reduce_by_power(num.clone(), &base, e);
            let expected = BigRational::new(num, num_traits::pow(base, e));
            prop_assert_eq!(&reduced, expected.numer());
            prop_assert_eq!(&den, expected.denom());
        }

        /// The reduction part by part is `BigRational::new` on the product.
        #[test]
        fn reduce_is_lowest_terms(
            n in any::<i64>(), m in proptest::collection::vec(1u64..1000, 1..5),
            base in 1u64..50, e in 0usize..6,
        ) {
            let num = BigInt::from(n) * BigInt::from(base).pow(3) * BigInt::from(m[0]);
            let parts: Vec<BigInt> = m.iter().map(|&d| BigInt::from(d)).collect();
            let b = BigInt::from(base);
            let mut list: Vec<Part<'_>> = parts.iter().map(Part::Number).collect();
            list.push(Part::Power(&b, e));
            let den = parts.iter().product::<BigInt>() * b.pow(e as u32);
            let r = reduce(num.clone(), &list);
            prop_assert_eq!(&r, &BigRational::new(num.clone(), den.clone()));
            prop_assert_eq!(format!("{r:?}"), format!("{:?}", BigRational::new(num, den)));
        }
    }
}
