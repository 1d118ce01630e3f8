//! The fraction-free kernel of text 004's cubic fit (`crate::fit_cubic`) for exact
//! rationals: every number of the fit over integers, one reduction per output number
//! (`crate::fit` says how).

use crate::coords::Point;
use crate::exact::fraction_free::{common_denominator, Int};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

/// What the fit reads: `x(0)`, `x(1)`, `x(1/2)`, `ẋ(0)`, `ẋ(1)` (the fields of
/// `CubicFitData`, validated: one dimension, nonzero tangents).
pub(crate) struct FitData<'a> {
    pub(crate) x0: &'a Point<BigRational>,
    pub(crate) x1: &'a Point<BigRational>,
    pub(crate) xh: &'a Point<BigRational>,
    pub(crate) d0: &'a Point<BigRational>,
    pub(crate) d1: &'a Point<BigRational>,
}

/// The fit's numbers, on machine words while they fit, else on big integers; `None` when
/// the end tangents are parallel.
pub(crate) fn fit_cubic(data: &FitData<'_>) -> Option<FitNumbers> {
    match fit_cubic_on::<i128>(data) {
        Some(fit) => fit,
        None => fit_cubic_on::<BigInt>(data).expect("big integers do not overflow"),
    }
}

/// The numbers of a cubic fit that [`fit_cubic`] computes on integers, each reduced once:
/// the tangent lengths, the inner control points `a1, a2`, the midpoint residual, δ² and
/// the Gram determinant. Generic: the kernel method of `Scalar` that returns them is.
#[doc(hidden)]
#[derive(Debug, PartialEq)]
pub struct FitNumbers<T = BigRational> {
    pub k: T,
    pub l: T,
    pub controls: [Point<T>; 2],
    pub residual: Point<T>,
    pub delta2: T,
    pub gram_determinant: T,
}

/// [`FitNumbers`] on integers `I`: `None` on overflow, `Some(None)` when the tangents are
/// parallel.
pub(crate) fn fit_cubic_on<I: Int>(data: &FitData<'_>) -> Option<Option<FitNumbers>> {
    let a = common_denominator::<I>(data.d0.coords().iter())?;
    let b = common_denominator::<I>(data.d1.coords().iter())?;
    let dim = data.x0.dim();
    let x = common_denominator::<I>([&data.x0, &data.x1, &data.xh].into_iter().flat_map(|p| p.coords()))?;
    let (u, w, h) = (&x.nums[..dim], &x.nums[dim..2 * dim], &x.nums[2 * dim..]);
    let c = (0..dim)
        .map(|i| u[i].add(&w[i])?.sub(&h[i].add(&h[i])?))
        .collect::<Option<Vec<I>>>()?;
    let dot = |p: &[I], q: &[I]| p.iter().zip(q).try_fold(I::zero(), |acc, (x, y)| acc.add(&x.mul(y)?));
    let (aa, ab, bb) = (dot(&a.nums, &a.nums)?, dot(&a.nums, &b.nums)?, dot(&b.nums, &b.nums)?);
    let (ac, bc) = (dot(&a.nums, &c)?, dot(&b.nums, &c)?);
    let delta = aa.mul(&bb)?.sub(&ab.mul(&ab)?)?;
    if delta.clone().into_big().is_zero() {
        return Some(None);
    }
    let four = I::from_u64(4);
    let big_k = four.mul(&ab.mul(&bc)?.sub(&bb.mul(&ac)?)?)?;
    let big_l = four.mul(&aa.mul(&bc)?.sub(&ab.mul(&ac)?)?)?;
    let three_delta = I::from_u64(3).mul(&delta)?;
    let e = three_delta.mul(&x.den)?;
    let k = I::ratio(a.den.mul(&big_k)?, e.clone());
    let l = I::ratio(b.den.mul(&big_l)?, e.clone());
    let control = |ends: &[I], v: &[I], factor: &I| {
        let coords = (0..dim)
            .map(|i| {
                Some(I::ratio(
                    three_delta.mul(&ends[i])?.add(&factor.mul(&v[i])?)?,
                    e.clone(),
                ))
            })
            .collect::<Option<Vec<_>>>()?;
        Some(Point::from_valid(coords))
    };
    let minus_l = I::zero().sub(&big_l)?;
    let controls = [control(u, &a.nums, &big_k)?, control(w, &b.nums, &minus_l)?];
    let r = (0..dim)
        .map(|i| {
            four.mul(&delta)?
                .mul(&c[i])?
                .add(&big_k.mul(&a.nums[i])?)?
                .add(&minus_l.mul(&b.nums[i])?)
        })
        .collect::<Option<Vec<I>>>()?;
    let r_den = I::from_u64(8).mul(&delta)?.mul(&x.den)?;
    let delta2 = I::ratio(dot(&r, &r)?, r_den.mul(&r_den)?);
    let residual = Point::from_valid(r.into_iter().map(|ri| I::ratio(ri, r_den.clone())));
    let dens = a.den.mul(&b.den)?;
    let gram_determinant = I::ratio(delta, dens.mul(&dens)?);
    Some(Some(FitNumbers {
        k,
        l,
        controls,
        residual,
        delta2,
        gram_determinant,
    }))
}
