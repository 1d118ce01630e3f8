//! Powers of rational constants with symbolic exponents, written one way: `c^e` as
//! `(−1)^e · Π p^(a_p·e)` over the factors `p` of `|c|` (primes below [`TRIAL`], one cofactor
//! left whole), and `(−1)^e` with each coefficient of `e` taken mod 2. Each step holds for
//! every integer value of the exponent, so `(−2)^n`, `(−1)^n 2^n`, `4^n`, `2^(2n)`,
//! `(−1)^(2n)` and `1` are recognized as the same powers.

use super::hyper::{Aff, Base};
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed};

/// Trial divisors of a constant base below this; the rest of it stays one base.
const TRIAL: u32 = 1 << 10;

/// `bases` (a product of powers, each base once) with every constant base written as above
/// and the powers of equal bases gathered; a base whose exponents would overflow stays as it
/// is.
pub(crate) fn constant_bases(bases: Vec<(Base, Aff)>) -> Vec<(Base, Aff)> {
    let mut out: Vec<(Base, Aff)> = Vec::new();
    let add = |out: &mut Vec<(Base, Aff)>, b: Base, e: Aff| match out.iter_mut().find(|(x, _)| *x == b) {
        Some(slot) => slot.1 = slot.1.plus(&e),
        None => out.push((b, e)),
    };
    for (b, e) in bases {
        match &b {
            Base::Const(c) => match split(c, &e) {
                Some(parts) => parts.into_iter().for_each(|(p, x)| add(&mut out, p, x)),
                None => add(&mut out, b, e),
            },
            Base::Poly(_) => add(&mut out, b, e),
        }
    }
    for (b, e) in &mut out {
        if *b == Base::Const(-BigRational::one()) {
            *e = parity(e);
        }
    }
    out.retain(|(b, e)| !(e.c == 0 && e.v.is_empty()) && *b != Base::Const(BigRational::one()));
    out
}

/// `(−1)^e = (−1)^(e mod 2)`, coefficient by coefficient.
fn parity(e: &Aff) -> Aff {
    let mut out = Aff::constant(e.c.rem_euclid(2));
    for (x, k) in &e.v {
        if k.rem_euclid(2) == 1 {
            out = out.plus(&Aff::var(x));
        }
    }
    out
}

/// `c^e` as powers of `−1`, of small primes and of one cofactor each for the numerator and
/// the denominator; `None` when an exponent would overflow.
fn split(c: &BigRational, e: &Aff) -> Option<Vec<(Base, Aff)>> {
    let mut out = Vec::new();
    if c.is_negative() {
        out.push((Base::Const(-BigRational::one()), e.clone()));
    }
    for (mut x, sign) in [(c.numer().abs(), 1i64), (c.denom().clone(), -1)] {
        let mut d = 2u32;
        while d < TRIAL && x > BigInt::one() {
            let p = BigInt::from(d);
            let mut a = 0i64;
            while x.is_multiple_of(&p) {
                x /= &p;
                a += 1;
            }
            if a > 0 {
                out.push((Base::Const(BigRational::from_integer(p)), scaled(e, sign * a)?));
            }
            d += 1;
        }
        if x > BigInt::one() {
            out.push((Base::Const(BigRational::from_integer(x)), scaled(e, sign)?));
        }
    }
    Some(out)
}

/// `k·e`, `None` on overflow.
fn scaled(e: &Aff, k: i64) -> Option<Aff> {
    let mut out = Aff::constant(e.c.checked_mul(k)?);
    for (x, a) in &e.v {
        let m = a.checked_mul(k)?;
        if m != 0 {
            out.v.insert(x.clone(), m);
        }
    }
    (out.v.values().all(|a| a.abs() < i64::MAX / 4) && out.c.abs() < i64::MAX / 4).then_some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(n: i64, d: i64) -> Base {
        Base::Const(BigRational::new(n.into(), d.into()))
    }

    #[test]
    fn equal_powers_are_written_alike() {
        let n = Aff::var("n");
        let two_n = n.scaled(2);
        // (−2)^n = (−1)^n 2^n; 4^n = 2^(2n); (−1)^(2n+1) = (−1)^1; 6^n (1/3)^n = 2^n
        assert_eq!(
            constant_bases(vec![(c(-2, 1), n.clone())]),
            vec![(c(-1, 1), n.clone()), (c(2, 1), n.clone())]
        );
        assert_eq!(
            constant_bases(vec![(c(4, 1), n.clone())]),
            vec![(c(2, 1), two_n.clone())]
        );
        assert_eq!(
            constant_bases(vec![(c(-1, 1), two_n.shifted(1))]),
            vec![(c(-1, 1), Aff::constant(1))]
        );
        assert_eq!(
            constant_bases(vec![(c(6, 1), n.clone()), (c(1, 3), n.clone())]),
            vec![(c(2, 1), n.clone())]
        );
        // (1/2)^n 2^n = 1; (−1)^(−n) = (−1)^n
        assert!(constant_bases(vec![(c(1, 2), n.clone()), (c(2, 1), n.clone())]).is_empty());
        assert_eq!(
            constant_bases(vec![(c(-1, 1), n.scaled(-1))]),
            vec![(c(-1, 1), n.clone())]
        );
        // a large prime stays whole; 1024 = 2^10
        let p = 1_000_003;
        assert_eq!(constant_bases(vec![(c(p, 1), n.clone())]), vec![(c(p, 1), n.clone())]);
        assert_eq!(
            constant_bases(vec![(c(1024, 1), n.clone())]),
            vec![(c(2, 1), n.scaled(10))]
        );
        // different numbers stay different
        assert_ne!(
            constant_bases(vec![(c(2, 1), n.clone())]),
            constant_bases(vec![(c(3, 1), n.clone())])
        );
    }
}
