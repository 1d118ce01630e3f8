//! Exact power-basis coefficients over integers: `to_power` of curves and surfaces.
//!
//! `a_j = C(n,j) Δ^j b_0` (text 000, §1.3). On [`BigRational`] the forward differences
//! reduce a fraction at every one of their `n(n+1)/2` steps, each a gcd of numbers as long
//! as the lcm of all denominators. Here each coordinate is written over that lcm `L` once,
//! the differences are integer subtractions, and each coefficient is reduced once.
//!
//! `L` is kept as the product of short factors `f_i = d_i / gcd(L_{i−1}, d_i)` (with
//! `L_{i−1}` the lcm of the earlier denominators), so the one reduction of a coefficient
//! against `L` is a remainder tree over the `f_i` and gcds of short numbers
//! (`splitting::reduce_over_tree`), not a gcd of two long numbers. Inputs whose lcm and
//! differences fit `i128` stay on machine words.

use crate::exact::fraction_free::{common_denominator, transpose, Int};
use crate::exact::splitting;
use crate::point::Point;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::One;

/// `C(n,j) Δ^j x_0` for `j = 0..=n`, over the same denominator as `x`.
fn power_numerators<I: Int>(mut x: Vec<I>) -> Option<Vec<I>> {
    let n = x.len() - 1;
    let mut out = Vec::with_capacity(n + 1);
    let mut binomial = I::one();
    for j in 0..=n {
        out.push(x[0].mul(&binomial)?);
        for i in 0..n - j {
            let (left, right) = x.split_at_mut(i + 1);
            left[i].sub_from(&right[0])?;
        }
        x.pop();
        binomial = binomial
            .mul(&I::from_u64((n - j) as u64))?
            .div_exact(&I::from_u64(j as u64 + 1));
    }
    Some(out)
}

/// A linear map on the integers of a coordinate, done the same over any common
/// denominator.
trait Transform {
    fn apply<I: Int>(&self, x: Vec<I>) -> Option<Vec<I>>;
}

/// The power coefficients of one curve coordinate.
struct Curve;

impl Transform for Curve {
    fn apply<I: Int>(&self, x: Vec<I>) -> Option<Vec<I>> {
        power_numerators(x)
    }
}

/// The power coefficients of one surface coordinate, the net flat in rows of `columns`:
/// the curve's map on every column, then on every row.
struct Net {
    columns: usize,
}

impl Transform for Net {
    fn apply<I: Int>(&self, x: Vec<I>) -> Option<Vec<I>> {
        let (rows, columns) = (x.len() / self.columns, self.columns);
        let mut x = x;
        for j in 0..columns {
            let column = (0..rows).map(|i| x[i * columns + j].clone()).collect();
            for (i, v) in power_numerators(column)?.into_iter().enumerate() {
                x[i * columns + j] = v;
            }
        }
        let mut out = Vec::with_capacity(x.len());
        for row in x.chunks_exact(columns) {
            out.extend(power_numerators(row.to_vec())?);
        }
        Some(out)
    }
}

/// `values` mapped by `f` exactly: on machine words when they fit, else over the lcm of the
/// denominators as a product tree, with one reduction per output value.
fn over_integers(values: &[&BigRational], f: &impl Transform) -> Vec<BigRational> {
    let words = common_denominator::<i128>(values.iter().copied()).and_then(|x| {
        let out = f.apply(x.nums)?;
        Some(out.into_iter().map(|a| i128::ratio(a, x.den)).collect())
    });
    if let Some(out) = words {
        return out;
    }
    let tree = splitting::lcm_tree(values.iter().map(|v| v.denom()));
    let numerators = match &tree {
        None => values.iter().map(|v| v.numer().clone()).collect(),
        Some(tree) => values
            .iter()
            .map(|v| {
                if v.denom().is_one() {
                    v.numer() * tree.product()
                } else {
                    v.numer() * (tree.product() / v.denom())
                }
            })
            .collect(),
    };
    let out = f.apply::<BigInt>(numerators).expect("big integers do not overflow");
    out.into_iter()
        .map(|a| match &tree {
            None => BigRational::from_integer(a),
            Some(tree) => splitting::reduce_over_tree(a, tree, &<BigInt as One>::one(), 0),
        })
        .collect()
}

/// The power coefficients `a_0..a_n` (points) of a curve with control points `points`.
pub(crate) fn curve_power(points: &[Point<BigRational>]) -> Vec<Point<BigRational>> {
    let dim = points[0].dim();
    let per_coordinate: Vec<Vec<BigRational>> = (0..dim)
        .map(|k| {
            let values: Vec<&BigRational> = points.iter().map(|p| &p.coords()[k]).collect();
            over_integers(&values, &Curve)
        })
        .collect();
    transpose(per_coordinate, points.len())
}

/// The power coefficients `c_{k,l}` of a surface with control net `net`.
pub(crate) fn net_power(net: &[Vec<Point<BigRational>>]) -> Vec<Vec<Point<BigRational>>> {
    let (dim, columns) = (net[0][0].dim(), net[0].len());
    let per_coordinate: Vec<Vec<BigRational>> = (0..dim)
        .map(|k| {
            let values: Vec<&BigRational> = net.iter().flatten().map(|p| &p.coords()[k]).collect();
            over_integers(&values, &Net { columns })
        })
        .collect();
    let flat = transpose(per_coordinate, net.len() * columns);
    flat.chunks_exact(columns).map(<[_]>::to_vec).collect()
}
