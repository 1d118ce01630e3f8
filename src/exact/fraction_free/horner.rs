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

use crate::exact::gcd;
use crate::exact::gcd::{gcd_u64, rem_word};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};

/// A factor of one step: a machine word when it fits (`BigInt`'s in-place product by a
/// word), else a big integer.
enum Factor {
    Word(i128),
    Big(BigInt),
}

impl Factor {
    fn of(x: &BigInt) -> Self {
        match x.to_i64() {
            Some(w) => Factor::Word(i128::from(w)),
            None => Factor::Big(x.clone()),
        }
    }

    fn times(&self, o: &BigInt) -> Self {
        match (self, o.to_i64()) {
            (Factor::Word(a), Some(b)) => match a.checked_mul(i128::from(b)) {
                Some(w) => Factor::Word(w),
                None => Factor::Big(BigInt::from(*a) * o),
            },
            (Factor::Word(a), None) => Factor::Big(o * *a),
            (Factor::Big(a), _) => Factor::Big(a * o),
        }
    }

    fn apply(&self, x: &mut BigInt) {
        match self {
            Factor::Word(w) => *x *= *w,
            Factor::Big(b) => *x *= b,
        }
    }
}

/// `C(n,i) pⁱ`, advanced one `i` at a time: `C(n,i−1) (n−i+1)` is divisible by `i`.
fn advance(coefficient: Factor, n: usize, i: usize, p: &Factor) -> Factor {
    let (up, down) = ((n - i + 1) as i128, i as i128);
    match (coefficient, p) {
        (Factor::Word(c), Factor::Word(p)) => match c.checked_mul(up).map(|x| x / down).and_then(|x| x.checked_mul(*p))
        {
            Some(w) => Factor::Word(w),
            None => Factor::Big(BigInt::from(c) * up / down * *p),
        },
        (Factor::Word(c), Factor::Big(p)) => Factor::Big(BigInt::from(c) * up / down * p),
        (Factor::Big(c), p) => {
            let mut c = c * up / down;
            p.apply(&mut c);
            Factor::Big(c)
        }
    }
}

/// `Σ_i x_i B_i^n(t)` of one coordinate's values at `t = p/q` (`q > 0`), in lowest terms.
pub(super) fn fraction_sum(values: &[&BigRational], p: &BigInt, q: &BigInt) -> BigRational {
    let n = values.len() - 1;
    let s = Factor::of(&(q - p));
    let p_factor = Factor::of(p);
    let mut num = values[0].numer().clone();
    let mut den = values[0].denom().clone();
    let mut scratch = BigInt::zero();
    let mut coefficient = Factor::Word(1);
    // `D / last` while the run of equal denominators that `last` starts goes on: such a
    // value is over `D` already, `s N / D + c a / d = (s N + c a (D / d)) / D`.
    let mut last = values[0].denom();
    let mut before = keep_if_next(values, 0, BigInt::one);
    for i in 1..=n {
        coefficient = advance(coefficient, n, i, &p_factor);
        let (a, d) = (values[i].numer(), values[i].denom());
        let c = coefficient.times(a);
        if d.is_one() {
            scratch.clone_from(&den);
            s.apply(&mut num);
        } else if let (true, Some(b)) = (equal(d, last), before.as_ref()) {
            scratch.clone_from(b);
            s.apply(&mut num);
        } else {
            scratch.clone_from(&den);
            s.times(d).apply(&mut num);
            before = keep_if_next(values, i, || den.clone());
            den *= d;
            last = d;
        }
        c.apply(&mut scratch);
        num += &scratch;
    }
    reduced(num, den, q, n)
}

/// `a == b`, by the lengths and the lowest words first: distinct denominators almost always
/// differ there, and a full comparison is a call to `memcmp`.
pub(super) fn equal(a: &BigInt, b: &BigInt) -> bool {
    a.bits() == b.bits() && a.iter_u64_digits().next() == b.iter_u64_digits().next() && a == b
}

/// `Some(value())` when the value after `i` has the same denominator as value `i`.
fn keep_if_next(values: &[&BigRational], i: usize, value: impl FnOnce() -> BigInt) -> Option<BigInt> {
    values
        .get(i + 1)
        .filter(|next| equal(next.denom(), values[i].denom()))
        .map(|_| value())
}

/// `num / (den · qⁿ)` in lowest terms, `den, q > 0`: the power of `q` first (by remainders
/// and divisions by a word when `q` is one), then one gcd with `den`.
fn reduced(mut num: BigInt, mut den: BigInt, q: &BigInt, n: usize) -> BigRational {
    if num.is_zero() {
        return BigRational::new_raw(num, BigInt::one());
    }
    let power = match q.to_u64() {
        Some(w) if w > 1 => {
            let mut power = num_traits::pow(BigInt::from(w), n);
            for _ in 0..n {
                let g = gcd_u64(w, rem_word(num.magnitude(), w));
                if g == 1 {
                    break;
                }
                num /= g;
                power /= g;
            }
            power
        }
        _ => {
            let (rest, left) = gcd::reduce_by_power(num, q, n);
            num = rest;
            left
        }
    };
    let g = gcd::gcd(num.magnitude(), den.magnitude());
    match g.to_u64() {
        Some(1) => {}
        // In place, digit by digit: a division by a long divisor would copy the dividend.
        Some(w) => {
            num /= w;
            den /= w;
        }
        None => {
            let g = BigInt::from_biguint(num_bigint::Sign::Plus, g);
            num /= &g;
            den /= &g;
        }
    }
    BigRational::new_raw(num, den * power)
}
