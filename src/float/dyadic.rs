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
/// below the fraction bar, as every float is): de Casteljau on integers scaled by a common
/// power of two, `B_i ← (2^j − m) B_i + m B_{i+1}` for `t = m/2^j`, then one shift. `None`
/// when some input is not dyadic. Equal to [`BezierCurve::eval`] (tests pin it).
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
    let mut buf: Vec<BigInt> = curve
        .points()
        .iter()
        .flat_map(|p| p.coords())
        .map(|c| c.numer() << (k - c.denom().trailing_zeros().unwrap_or(0)))
        .collect();
    for r in 1..=n {
        for i in 0..=n - r {
            for d in 0..dim {
                let next = &buf[(i + 1) * dim + d] * m;
                let here = &mut buf[i * dim + d];
                *here *= &s;
                *here += next;
            }
        }
    }
    buf.truncate(dim);
    let shift = k + n as u64 * j;
    let coords = buf.into_iter().map(|x| dyadic_ratio(x, shift)).collect();
    Some(Point::new(coords).expect("the curve's dimension"))
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
            coords in prop::collection::vec(prop::collection::vec(-1e3f64..1e3, 2), 1..12),
            scale in -80i32..80,
            t in -2.0f64..3.0,
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
