//! Subdivision by de Casteljau's steps on reduced fractions, pair by pair: what `split`
//! runs for one coordinate with long denominators at a low degree ([`super::choice::pairs_win`]).
//!
//! Over the lcm of the denominators (the fraction-free kernel) every output is reduced by a
//! gcd with the whole lcm, as long as all `n + 1` denominators together; here each value of
//! the triangle, `(s a + p b) / q` for `t = p/q`, `s = q − p`, is brought to lowest terms
//! from its two neighbours the way GMP adds two fractions (Knuth, TAOCP vol. 2, 4.5.1), as
//! the elevation step does (`exact::elevation_words`), so that the gcds are of one or two
//! neighbours' denominators. The facts it rests on hold because every input of a level is
//! reduced (the curve's values, then the previous level's outputs):
//!
//! - `g = gcd(d, e)`, `d = g d'`, `e = g e'`, and `T = s x e' + p y d'`: the value is
//!   `T / (g d' e' q)`;
//! - `gcd(T, d') = gcd(s, d')`, because `d'` is prime to `x` (`x/d` is reduced) and to
//!   `e'`; likewise `gcd(T, e') = gcd(p, e')`. Those are `gcd(σ, d')` for any `σ` between
//!   `gcd(s, D)` and `s` in divisibility, `D` the lcm of the coordinate's input
//!   denominators: every `d'` divides `D q^(r−1)` and `s` is prime to `q`. `σ = gcd(s, Π
//!   d_i)` is computed once per coordinate and is usually 1, which skips the gcd;
//! - what is left of `T` is divided by its gcd with `g` and then by its gcd with `q`, which
//!   divides out exactly its gcd with `g q` (for a prime of exponent `v` in `T` and `e₁`,
//!   `e₂` in the factors, `min(v, e₁ + e₂) = min(v, e₁) + min(v − min(v, e₁), e₂)`).
//!
//! The integers are dashu-int's, whose gcd the module `gcd` uses anyway: converted once on
//! the way in and out, not at every gcd as from num-bigint's; the remainders by `q` use a
//! divisor prepared once (`ConstDivisor`). The gcds of neighbouring denominators that fit two
//! words are computed two at a time (`gcd::paired_gcds`).

use crate::exact::gcd::{from_ibig, from_words, paired_gcds, to_dashu, to_ibig};
use dashu_int::fast_div::ConstDivisor;
use dashu_int::ops::{BitTest, Gcd};
use dashu_int::{IBig, UBig};
use num_bigint::BigInt;
use num_rational::BigRational;
use std::borrow::Cow;

/// A reduced fraction in dashu-int's integers, `den > 0`.
struct Fraction {
    num: IBig,
    den: UBig,
}

impl Fraction {
    #[cfg(test)]
    fn of(x: &BigRational) -> Self {
        Fraction {
            num: to_ibig(x.numer()),
            den: to_dashu(x.denom().magnitude()),
        }
    }
    fn to_rational(&self) -> BigRational {
        BigRational::new_raw(
            from_ibig(&self.num),
            BigInt::from_biguint(num_bigint::Sign::Plus, from_words(self.den.as_words())),
        )
    }
}

/// `t = p/q` with `s = q − p`, as the steps read it, and for the coordinate at hand the parts
/// of `s` and `p` that the denominators can share.
struct Parameter {
    p: IBig,
    q: UBig,
    q_divisor: ConstDivisor,
    s: IBig,
    /// A number between `gcd(s, D)` and `s` in divisibility, `D` the lcm of the coordinate's
    /// input denominators: `gcd(s, d') = gcd(s_part, d')` for every `d'` of the triangle.
    s_part: UBig,
    p_part: UBig,
}

/// `gcd(w, P)` for the product `P` of the input denominators: between `gcd(w, D)` and `w`.
fn weight_part(w: &IBig, product: &UBig) -> UBig {
    if w.is_zero() {
        return product.clone();
    }
    product.gcd(w)
}

/// `(s a + p b) / q` in lowest terms for reduced `a = x/d`, `b = y/e`, given `g = gcd(d, e)`:
/// with `d = g d'`, `e = g e'`, the value is `T / (g d' e' q)`, `T = s x e' + p y d'`;
/// `gcd(T, d') = gcd(s, d')` and `gcd(T, e') = gcd(p, e')` (`x` and `e'` are prime to
/// `d'`), and what is left of `T` is reduced against `g`, then against `q`.
fn step(a: &Fraction, b: &Fraction, mut g: UBig, t: &Parameter) -> Fraction {
    let (x, d, y, e) = (&a.num, &a.den, &b.num, &b.den);
    let (mut d1, mut e1) = if g.is_one() {
        (Cow::Borrowed(d), Cow::Borrowed(e))
    } else {
        (Cow::Owned(d / &g), Cow::Owned(e / &g))
    };
    let mut num = &t.s * x * &*e1;
    num += &t.p * y * &*d1;
    if num.is_zero() {
        return Fraction { num, den: UBig::ONE };
    }
    if !t.s_part.is_one() {
        let hx = (&*d1).gcd(&t.s_part);
        if !hx.is_one() {
            num /= &hx;
            *d1.to_mut() /= &hx;
        }
    }
    if !t.p_part.is_one() {
        let hy = (&*e1).gcd(&t.p_part);
        if !hy.is_one() {
            num /= &hy;
            *e1.to_mut() /= &hy;
        }
    }
    if !g.is_one() {
        let h = (&num).gcd(&g);
        if !h.is_one() {
            num /= &h;
            g /= &h;
        }
    }
    let mut den = &*d1 * &*e1;
    if !g.is_one() {
        den *= g;
    }
    if !t.q.is_one() {
        let r = &num % &t.q_divisor;
        let h = r.gcd(&t.q);
        if h.is_one() {
            den *= &t.q;
        } else {
            num /= &h;
            den *= &t.q / h;
        }
    }
    Fraction { num, den }
}

/// The gcds of the denominators of neighbouring values: machine gcds two at a time where
/// both fit two words.
fn neighbour_gcds<'a>(dens: impl ExactSizeIterator<Item = &'a UBig> + Clone) -> Vec<UBig> {
    let words: Vec<Option<u128>> = dens.clone().map(|d| u128::try_from(d).ok()).collect();
    let pairs = words.windows(2).map(|w| Some((w[0]?, w[1]?)));
    let gcds = paired_gcds(pairs);
    gcds.into_iter()
        .zip(dens.clone().zip(dens.skip(1)))
        .map(|(g, (d, e))| if g != 0 { UBig::from(g) } else { d.gcd(e) })
        .collect()
}

/// Whether an estimate of the lcm's length from the denominators' and their neighbours'
/// gcds, `Σ bits(d_i) − Σ bits(gcd(d_i, d_(i+1)))` (exact when each shares factors only
/// with its neighbours), is at least 1.5 times the longest denominator: the pairs' gain is
/// the lcm's length, and with denominators that share most of their factors it is short.
///
/// Measured (2026-12-05, both kernels, 30- to 300-digit planar curves at `t = 1/3` and a
/// 20-digit `t`, one run each): with all values over one denominator (then reduced, so that
/// they differ by small factors) the lcm won at degrees 3 and 5 (300 digits: 37.5 µs
/// against 47.7 and 69.8 against 114); with denominators sharing a factor of two thirds of
/// their length (estimate twice the longest at degree 3), or one denominator to every two
/// neighbouring points, the pairs won at degree 3 (300 digits: 74 against 99 µs, 70
/// against 89) and tied at degree 5. A refusal costs the denominators' conversion and
/// gcds, which are exact divisions when they share that much: 2 µs in 40 at 300 digits.
fn lcm_is_long(dens: &[UBig], gcds: &[UBig]) -> bool {
    let bits = |x: &UBig| x.bit_len() as u64;
    let total: u64 = dens.iter().map(bits).sum();
    let shared: u64 = gcds.iter().map(bits).sum();
    let longest = dens.iter().map(bits).max().unwrap_or(0);
    2 * total.saturating_sub(shared) >= 3 * longest
}

/// One coordinate's halves of the subdivision at `t`: the left one `b_0^0, …, b_0^n` and
/// the right one `b_0^n, b_1^(n−1), …, b_n^0`, each value of the triangle a reduced fraction;
/// `None`, when the denominators share most of their factors ([`lcm_is_long`]), for the
/// kernel over their lcm.
pub(super) fn split_coordinate(
    values: &[&BigRational],
    t: &BigRational,
) -> Option<(Vec<BigRational>, Vec<BigRational>)> {
    // The denominators first: their gcds decide, and the numerators are converted only then.
    let dens: Vec<UBig> = values.iter().map(|v| to_dashu(v.denom().magnitude())).collect();
    let gcds = neighbour_gcds(dens.iter());
    if !lcm_is_long(&dens, &gcds) {
        return None;
    }
    let column = values
        .iter()
        .zip(dens)
        .map(|(v, den)| Fraction {
            num: to_ibig(v.numer()),
            den,
        })
        .collect();
    Some(triangle(values, column, gcds, t))
}

/// [`split_coordinate`]'s halves from the values as fractions and their neighbours' gcds.
fn triangle(
    values: &[&BigRational],
    mut column: Vec<Fraction>,
    mut gcds: Vec<UBig>,
    t: &BigRational,
) -> (Vec<BigRational>, Vec<BigRational>) {
    let n = values.len() - 1;
    let q = to_dashu(t.denom().magnitude());
    let p = to_ibig(t.numer());
    let product: UBig = column.iter().map(|v| &v.den).product();
    let s = IBig::from(q.clone()) - &p;
    let t = Parameter {
        s_part: weight_part(&s, &product),
        p_part: weight_part(&p, &product),
        s,
        p,
        q_divisor: ConstDivisor::new(q.clone()),
        q,
    };
    let mut left = Vec::with_capacity(n + 1);
    let mut right = Vec::with_capacity(n + 1);
    left.push(values[0].clone());
    right.push(values[n].clone());
    for r in 1..=n {
        if r > 1 {
            gcds = neighbour_gcds(column[..=n + 1 - r].iter().map(|v| &v.den));
        }
        for (j, g) in gcds.drain(..).enumerate() {
            column[j] = step(&column[j], &column[j + 1], g, &t);
        }
        let first = column[0].to_rational();
        // The last level's one value is both halves' common point: converted once.
        let last = if r == n {
            first.clone()
        } else {
            column[n - r].to_rational()
        };
        left.push(first);
        right.push(last);
    }
    right.reverse();
    (left, right)
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::{One, Zero};
    use proptest::prelude::*;

    /// A number from 0 to 5 words, times a factor the column shares and a small one.
    fn value() -> impl Strategy<Value = (Vec<u64>, Vec<u64>, u32, u8, bool)> {
        (
            proptest::collection::vec(any::<u64>(), 0..5),
            proptest::collection::vec(any::<u64>(), 0..5),
            0u32..4,
            0u8..5,
            any::<bool>(),
        )
    }

    fn natural(words: &[u64]) -> BigInt {
        words.iter().fold(BigInt::zero(), |acc, &w| (acc << 64) + w)
    }

    /// De Casteljau's steps `(1 − t) a + t b` in num-rational's arithmetic.
    fn reference(values: &[BigRational], t: &BigRational) -> (Vec<BigRational>, Vec<BigRational>) {
        let mut column = values.to_vec();
        let n = column.len() - 1;
        let (mut left, mut right) = (vec![column[0].clone()], vec![column[n].clone()]);
        for r in 1..=n {
            for j in 0..=n - r {
                column[j] = (BigRational::one() - t) * &column[j] + t * &column[j + 1];
            }
            left.push(column[0].clone());
            right.push(column[n - r].clone());
        }
        right.reverse();
        (left, right)
    }

    proptest! {
        /// Against the reference, equal and in the same form: short and long numerators
        /// and denominators sharing a long factor and small primes, zeros, integers, and
        /// parameters 0, 1, short and long, inside and outside [0, 1].
        #[test]
        fn pairs_are_de_casteljaus_steps(
            column in proptest::collection::vec(value(), 1..8),
            common in proptest::collection::vec(any::<u64>(), 0..3),
            (p, q, whole) in (proptest::collection::vec(any::<u64>(), 0..3), proptest::collection::vec(any::<u64>(), 0..3), -2i64..3),
            special in 0u8..4,
        ) {
            let common = natural(&common).max(BigInt::one());
            let values: Vec<BigRational> = column
                .iter()
                .map(|(num, den, shared, small, negative)| {
                    let num = if *negative { -natural(num) } else { natural(num) };
                    let den = natural(den).max(BigInt::one())
                        * num_traits::pow(common.clone(), *shared as usize)
                        * BigInt::from([1u32, 2, 6, 12, 35][*small as usize]);
                    BigRational::new(num, den)
                })
                .collect();
            let t = match special {
                0 => BigRational::zero(),
                1 => BigRational::one(),
                _ => {
                    let q = natural(&q).max(BigInt::one()) * (&common % 1000u32 + 1u32);
                    BigRational::new(natural(&p) % &q + &q * whole, q)
                }
            };
            let refs: Vec<&BigRational> = values.iter().collect();
            // The triangle whether or not `split_coordinate` would leave it to the lcm.
            let column: Vec<Fraction> = refs.iter().map(|v| Fraction::of(v)).collect();
            let gcds = neighbour_gcds(column.iter().map(|v| &v.den));
            let got = triangle(&refs, column, gcds, &t);
            let want = reference(&values, &t);
            if let Some(chosen) = split_coordinate(&refs, &t) {
                prop_assert_eq!(&chosen, &got);
            }
            prop_assert_eq!(format!("{got:?}"), format!("{want:?}"));
            prop_assert_eq!(got, want);
        }
    }
}
