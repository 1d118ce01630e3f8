//! Exact power-basis coefficients over integers: `to_power` of curves and surfaces, and
//! `from_power` of curves.
//!
//! `a_j = C(n,j) Δ^j b_0` (text 000, §1.3). On [`BigRational`] the forward differences
//! reduce a fraction at every one of their `n(n+1)/2` steps, each a gcd of numbers as long
//! as the lcm of all denominators. Here each coordinate is written over that lcm `L` once,
//! the differences are integer subtractions, and each coefficient is reduced once.
//!
//! On big integers a curve's coefficient `a_j` is computed over the lcm of the first `j + 1`
//! denominators and reduced only against the primes that can cancel (`PrefixLcm`); a
//! surface is its columns' curves, then its rows'. Inputs whose lcm and differences fit
//! `i128` stay on machine words.

use crate::coords::Point;
use crate::exact::fraction_free::{common_denominator, transpose, Int};
use crate::exact::gcd;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

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

/// `values` mapped by `f` on machine words, when they fit.
fn on_words(values: &[&BigRational], f: &impl Transform) -> Option<Vec<BigRational>> {
    let x = common_denominator::<i128>(values.iter().copied())?;
    let out = f.apply(x.nums)?;
    Some(out.into_iter().map(|a| i128::ratio(a, x.den)).collect())
}

/// The power coefficients of one curve coordinate: on machine words when they fit, else
/// point by point on big integers.
fn coordinate_power(values: &[&BigRational]) -> Vec<BigRational> {
    on_words(values, &Curve).unwrap_or_else(|| curve_power_big(values))
}

/// The power coefficients of one surface coordinate (the net flat in rows of `columns`):
/// on machine words when the whole net fits, else each column's curve map, then each
/// row's, every curve over the lcm of its own denominators. One lcm for the whole net
/// would make every coefficient as long as all the net's denominators together.
fn net_coordinate_power(values: &[&BigRational], columns: usize) -> Vec<BigRational> {
    if let Some(out) = on_words(values, &Net { columns }) {
        return out;
    }
    let rows = values.len() / columns;
    let mut x = vec![BigRational::zero(); values.len()];
    for j in 0..columns {
        let column: Vec<&BigRational> = (0..rows).map(|i| values[i * columns + j]).collect();
        for (i, v) in coordinate_power(&column).into_iter().enumerate() {
            x[i * columns + j] = v;
        }
    }
    x.chunks_exact(columns)
        .flat_map(|row| coordinate_power(&row.iter().collect::<Vec<_>>()))
        .collect()
}

/// The power coefficients of one curve coordinate on big integers, point by point: `a_j`
/// depends on `b_0..b_j` alone, so it is computed over the lcm `L_j` of their denominators.
/// The diagonal `e_k = Δ^k b_{j−k}`, `k = 0..=j`, takes `b_{j+1}` as `e'_0` and
/// `e'_{k+1} = e'_k − e_k`; when `L` grows by a factor, so do the `e_k`.
///
/// **The reduction** of `a_j = C(n,j) Δ^j x_0` (the `x_i = c_i L_j / d_i` integers) against
/// `L_j` needs only the primes `p` of `L_j` that are at most `n` or divide two of the
/// denominators: for any other `p`, exactly one `d_i`, `i ≤ j`, has it, and modulo `p`
/// every `x_k`, `k ≠ i`, vanishes (`p | L_j / d_k`), leaving
/// `a_j ≡ ± C(n,j) C(j,i) c_i (L_j / d_i)`, a product of factors prime to `p` (`p > n`,
/// `c_i / d_i` is reduced, and `L_j / d_i` has lost all of `p`). The part `R_j` of `L_j`
/// made of those primes is short, and `gcd(a_j, L_j) = gcd(a_j, R_j)`.
fn curve_power_big(values: &[&BigRational]) -> Vec<BigRational> {
    let n = values.len() - 1;
    let mut prefix = PrefixLcm::new(values, <BigInt as One>::one());
    let mut diagonal: Vec<BigInt> = Vec::with_capacity(n + 1);
    let mut binomial = <BigInt as One>::one();
    let mut out = Vec::with_capacity(n + 1);
    for (j, v) in values.iter().enumerate() {
        let mut next = prefix.next(j, v, &mut diagonal);
        for e in &mut diagonal {
            let old = std::mem::replace(e, next);
            next = &*e - old;
        }
        diagonal.push(next);
        out.push(prefix.reduce(&diagonal[j] * &binomial, prefix.lcm.clone()));
        binomial = binomial * (n - j) / (j + 1);
    }
    out
}

/// The lcm `L_j` of the first `j + 1` denominators, grown one value at a time, and the part
/// `R_j` of `L_j` (times a given start) made of the primes that may cancel in a value over
/// it: those up to `n` and those of the gcds between a denominator and the lcm of the ones
/// before it (a prime of two denominators divides the later one's).
struct PrefixLcm {
    /// `f_i = d_i / gcd(L_{i−1}, d_i)`, the factor by which `L` grows at value `i`.
    factors: Vec<BigInt>,
    /// The product of the primes that may cancel (some more than once).
    base: BigInt,
    lcm: BigInt,
    risky: BigInt,
}

impl PrefixLcm {
    fn new(values: &[&BigRational], risky: BigInt) -> Self {
        let mut lcm = <BigInt as One>::one();
        let mut factors = Vec::with_capacity(values.len());
        let mut base = primorial(values.len() - 1);
        for v in values {
            let d = v.denom();
            let g = gcd::gcd_int(&lcm, d);
            let f = if g.is_one() { d.clone() } else { d / &g };
            if !g.is_one() {
                base *= g;
            }
            lcm *= &f;
            factors.push(f);
        }
        PrefixLcm {
            factors,
            base,
            lcm: <BigInt as One>::one(),
            risky,
        }
    }

    /// Value `j` as an integer over `L_j`; the integers of `over_previous` (over `L_{j−1}`)
    /// are brought over `L_j` too.
    fn next(&mut self, j: usize, v: &BigRational, over_previous: &mut [BigInt]) -> BigInt {
        let f = &self.factors[j];
        if !f.is_one() {
            for e in over_previous {
                *e *= f;
            }
            self.lcm *= f;
            self.risky *= part_over(f, &self.base);
        }
        let d = v.denom();
        if d.is_one() {
            v.numer() * &self.lcm
        } else {
            v.numer() * (&self.lcm / d)
        }
    }

    /// `a / den` in lowest terms, for a `den > 0` whose primes that can divide `a` are all
    /// in the current `R_j` (times the start).
    fn reduce(&self, a: BigInt, den: BigInt) -> BigRational {
        if a.is_zero() {
            return BigRational::new_raw(a, <BigInt as One>::one());
        }
        let g = gcd::gcd_int(&a, &self.risky);
        if g.is_one() {
            BigRational::new_raw(a, den)
        } else {
            BigRational::new_raw(a / &g, den / &g)
        }
    }
}

/// The Bernstein points of one coordinate from its power coefficients `values`:
/// `b_j = Σ_{k≤j} C(j,k) y_k` with `y_k = a_k / C(n,k) = Δ^k b_0` (Newton's forward
/// formula), point by point: `b_j` depends on `a_0..a_j` alone, so it is computed over
/// `n! L_j`, `L_j` the lcm of their denominators, where `y_k` is the integer
/// `c_k k! (n−k)! L_j / d_k`. The diagonal `e_k = Δ^k b_{j−k}` takes `y_{j+1}` as
/// `e'_{j+1}` and `e'_k = e_k + e'_{k+1}`; when `L` grows by a factor, so do the `e_k`.
///
/// **The reduction** of `b_j = e_0 / (n! L_j)`: a prime `p > n` of exactly one `d_i`,
/// `i ≤ j`, stays whole in the denominator (only the term `C(j,i)/C(n,i) · c_i/d_i` of the
/// sum has it, and `p` divides neither `c_i` nor the binomials), so
/// `gcd(e_0, n! L_j) = gcd(e_0, n! R_j)` with `R_j` the part of `L_j` made of the primes up
/// to `n` and those shared by two denominators, as in [`curve_power_big`] ([`PrefixLcm`]).
fn curve_from_power_big(values: &[&BigRational]) -> Vec<BigRational> {
    let n = values.len() - 1;
    let mut factorials = vec![<BigInt as One>::one()];
    for k in 1..=n {
        let next = &factorials[k - 1] * k;
        factorials.push(next);
    }
    let n_factorial = &factorials[n];
    let mut prefix = PrefixLcm::new(values, n_factorial.clone());
    let mut diagonal: Vec<BigInt> = Vec::with_capacity(n + 1);
    let mut out = Vec::with_capacity(n + 1);
    for (j, v) in values.iter().enumerate() {
        let over_lcm = prefix.next(j, v, &mut diagonal);
        diagonal.push(over_lcm * &factorials[j] * &factorials[n - j]);
        for k in (0..j).rev() {
            let (left, right) = diagonal.split_at_mut(k + 1);
            left[k] += &right[0];
        }
        out.push(prefix.reduce(diagonal[0].clone(), &prefix.lcm * n_factorial));
    }
    out
}

/// The largest divisor of `f > 0` made of primes that divide `base > 0`.
fn part_over(f: &BigInt, base: &BigInt) -> BigInt {
    let (mut rest, mut part) = (f.clone(), <BigInt as One>::one());
    let mut h = gcd::gcd_int(&rest, base);
    while !h.is_one() {
        rest /= &h;
        part *= &h;
        h = gcd::gcd_int(&rest, &h);
    }
    part
}

/// The product of the primes up to `n`.
fn primorial(n: usize) -> BigInt {
    let mut composite = vec![false; n + 1];
    let mut product = <BigInt as One>::one();
    for p in 2..=n {
        if !composite[p] {
            product *= p;
            for m in (p * p..=n).step_by(p) {
                composite[m] = true;
            }
        }
    }
    product
}

/// The power coefficients `a_0..a_n` (points) of a curve with control points `points`.
pub(crate) fn curve_power(points: &[Point<BigRational>]) -> Vec<Point<BigRational>> {
    let dim = points[0].dim();
    let per_coordinate: Vec<Vec<BigRational>> = (0..dim)
        .map(|k| {
            let values: Vec<&BigRational> = points.iter().map(|p| &p.coords()[k]).collect();
            coordinate_power(&values)
        })
        .collect();
    transpose(per_coordinate, points.len())
}

/// The control points of the curve `Σ_k a_k t^k`, `a_k = coeffs[k]` (points).
pub(crate) fn curve_from_power(coeffs: &[&Point<BigRational>]) -> Vec<Point<BigRational>> {
    let dim = coeffs[0].dim();
    let per_coordinate: Vec<Vec<BigRational>> = (0..dim)
        .map(|k| curve_from_power_big(&coeffs.iter().map(|p| &p.coords()[k]).collect::<Vec<_>>()))
        .collect();
    transpose(per_coordinate, coeffs.len())
}

/// The power coefficients `c_{k,l}` of a surface with control net `net`.
pub(crate) fn net_power(net: &[Vec<Point<BigRational>>]) -> Vec<Vec<Point<BigRational>>> {
    let (dim, columns) = (net[0][0].dim(), net[0].len());
    let per_coordinate: Vec<Vec<BigRational>> = (0..dim)
        .map(|k| {
            let values: Vec<&BigRational> = net.iter().flatten().map(|p| &p.coords()[k]).collect();
            net_coordinate_power(&values, columns)
        })
        .collect();
    let flat = transpose(per_coordinate, net.len() * columns);
    flat.chunks_exact(columns).map(<[_]>::to_vec).collect()
}
