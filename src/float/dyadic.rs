//! Exact evaluation on dyadic inputs (every float is `m·2^e`): integers over one power of
//! two, so no gcd at all — one shift reduces the result to lowest terms.

use crate::curve::BezierCurve;
use crate::point::Point;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

/// `Some(k)` when `d = 2^k`.
fn power_of_two(d: &BigInt) -> Option<u64> {
    let z = d.trailing_zeros()?;
    (z + 1 == d.bits()).then_some(z)
}

/// `n / 2^k` in lowest terms, built without a gcd.
pub fn dyadic_ratio(n: BigInt, k: u64) -> BigRational {
    if n.is_zero() {
        return BigRational::zero();
    }
    let z = n.trailing_zeros().unwrap_or(0).min(k);
    BigRational::new_raw(n >> z, BigInt::one() << (k - z))
}

/// `b(t)` exactly when `t` and every control point coordinate are dyadic (a power of two
/// below the fraction bar, as every float is): with `t = m/2^j` and `s = 2^j − m`, the
/// integer sum `Σ_i C(n, i) m^i s^(n−i) B_i` over the coordinates `B_i` scaled to one power
/// of two, then one shift. The weights `C(n, i) m^i s^(n−i)` are shared by every coordinate,
/// so a point costs `n + 1` products per coordinate (de Casteljau's triangle costs `n(n + 1)`).
/// `None` when some input is not dyadic. Equal to [`BezierCurve::eval`] (tests pin it).
///
/// ```
/// use casteljau::{float::eval_dyadic, BezierCurve, BigRational, Scalar};
/// let c = BezierCurve::<BigRational>::from_ints(&[&[0, 0], &[1, 2], &[3, 2], &[4, 0]]).unwrap();
/// let t = BigRational::from_f64(0.1).unwrap();
/// assert_eq!(eval_dyadic(&c, &t), Some(c.eval(&t)));
/// assert_eq!(eval_dyadic(&c, &BigRational::from_ratio(1, 3).unwrap()), None);
/// ```
pub fn eval_dyadic(curve: &BezierCurve<BigRational>, t: &BigRational) -> Option<Point<BigRational>> {
    let j = power_of_two(t.denom())?;
    let mut k = 0;
    for c in curve.points().iter().flat_map(|p| p.coords()) {
        k = k.max(power_of_two(c.denom())?);
    }
    let (n, dim) = (curve.degree(), curve.dim());
    let m = t.numer();
    let s = (BigInt::one() << j) - m;
    let weights = bernstein_weights(n, m, &s);
    let mut sums = vec![BigInt::zero(); dim];
    for (p, w) in curve.points().iter().zip(&weights) {
        for (sum, c) in sums.iter_mut().zip(p.coords()) {
            if !c.numer().is_zero() {
                let scaled = c.numer() << (k - c.denom().trailing_zeros().unwrap_or(0));
                *sum += scaled * w;
            }
        }
    }
    let shift = k + n as u64 * j;
    let coords = sums.into_iter().map(|x| dyadic_ratio(x, shift)).collect();
    Some(Point::new(coords).expect("the curve's dimension"))
}

/// `C(n, i) m^i s^(n−i)` for `i = 0..=n`: the Bernstein values at `m/(m + s)` times
/// `(m + s)^n`, from one table of powers of `s` and a running power of `m`.
fn bernstein_weights(n: usize, m: &BigInt, s: &BigInt) -> Vec<BigInt> {
    let mut powers_of_s = Vec::with_capacity(n + 1);
    powers_of_s.push(BigInt::one());
    for i in 1..=n {
        let next = &powers_of_s[i - 1] * s;
        powers_of_s.push(next);
    }
    let mut weights = Vec::with_capacity(n + 1);
    let (mut binomial, mut power_of_m) = (BigInt::one(), BigInt::one());
    for i in 0..=n {
        // the end weights are plain powers: no product to form
        let mut w = match i {
            0 => powers_of_s[n].clone(),
            _ if i == n => power_of_m.clone(),
            _ => &power_of_m * &powers_of_s[n - i],
        };
        if !binomial.is_one() {
            w *= &binomial;
        }
        weights.push(w);
        if i < n {
            binomial = binomial * (n - i) / (i + 1);
            power_of_m *= m;
        }
    }
    weights
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Scalar;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        #[test]
        fn equals_the_generic_exact_eval(
            coords in prop::collection::vec(prop::collection::vec(prop_oneof![Just(0.0), -1e3f64..1e3], 2), 1..12),
            scale in -80i32..80,
            t in prop_oneof![Just(0.0), Just(1.0), Just(0.5), -2.0f64..3.0],
        ) {
            let exact: Vec<Vec<BigRational>> = coords
                .iter()
                .map(|p| p.iter().map(|x| BigRational::from_f64(x * 2f64.powi(scale)).unwrap()).collect())
                .collect();
            let curve = BezierCurve::from_coords(exact).unwrap();
            let t = BigRational::from_f64(t).unwrap();
            prop_assert_eq!(eval_dyadic(&curve, &t).unwrap(), curve.eval(&t));
        }
    }
}
