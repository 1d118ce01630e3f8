//! Fraction-free exact kernels: integers over a common denominator, one reduction at the end.
//!
//! The generic algorithms on [`BigRational`] reduce a fraction (a big-integer gcd) at every
//! step. Here the values of each coordinate are first written over their common denominator
//! `D`, a parameter `t = p/q` stays the pair of integers `(p, q)`, and every step is integer
//! arithmetic; each output coordinate is reduced once, part by part ([`crate::exact::gcd`]).
//! The integers are machine words (`i128`, every operation overflow-checked) while they fit;
//! on the first overflow the whole kernel runs again on [`BigInt`] (a curve's point skips
//! the words when its denominators are clearly too long, `words_hopeless`). Four kernels
//! change algorithm there: the point of a curve is then summed nested on an unreduced
//! fraction (`horner`) while its denominators and `t`'s stay short (`horner_wins`), else
//! by binary splitting (`exact::splitting`); a surface's point row by row when its rows'
//! are words (`rows_first`), else by binary splitting too; one elevation step combines
//! neighbouring points pairwise, on 256-bit words where they fit
//! (`exact::elevation_words`), and so does a subdivision's triangle with long denominators
//! at a low degree (`split`, chosen by `choice::pairs_win`). The public generic methods
//! choose these kernels for exact rationals (the kernel methods of `BigRational`'s
//! [`Scalar`](crate::Scalar) implementation); the tests compare them with `==` against the
//! step-by-step `*_reference` methods.
//!
//! | kernel | method | reference |
//! |---|---|---|
//! | one point, O(n) nested Bernstein sum | [`BezierCurve::eval_nested`](crate::BezierCurve::eval_nested) | [`BezierCurve::eval_reference`](crate::BezierCurve::eval_reference) |
//! | derivative vector at `t` (the first past machine words: `splitting::first_derivative_sum`) | [`BezierCurve::derivative_at_nested`](crate::BezierCurve::derivative_at_nested) | [`BezierCurve::derivative_reference`](crate::BezierCurve::derivative_reference) then [`BezierCurve::eval_reference`](crate::BezierCurve::eval_reference) |
//! | de Casteljau triangle, subdivision | [`BezierCurve::scheme_fraction_free`](crate::BezierCurve::scheme_fraction_free), [`BezierCurve::split_fraction_free`](crate::BezierCurve::split_fraction_free) | [`BezierCurve::scheme_reference`](crate::BezierCurve::scheme_reference), [`BezierCurve::split_at_reference`](crate::BezierCurve::split_at_reference) |
//! | degree elevation (7), (8) | [`BezierCurve::elevate_fraction_free`](crate::BezierCurve::elevate_fraction_free), [`BezierCurve::elevate_by_fraction_free`](crate::BezierCurve::elevate_by_fraction_free) | [`BezierCurve::elevate_reference`](crate::BezierCurve::elevate_reference), [`BezierCurve::elevate_by_reference`](crate::BezierCurve::elevate_by_reference) |
//! | derivative curve | [`BezierCurve::derivative_fraction_free`](crate::BezierCurve::derivative_fraction_free) | [`BezierCurve::derivative_reference`](crate::BezierCurve::derivative_reference) |
//! | rational curve point (homogeneous point, then one quotient) | [`RationalBezierCurve::eval_nested`](crate::RationalBezierCurve::eval_nested) | [`RationalBezierCurve::eval_reference`](crate::RationalBezierCurve::eval_reference) |
//! | rational curve's derivative vector at `t` (two homogeneous points, one reduction) | [`RationalBezierCurve::derivative_at_nested`](crate::RationalBezierCurve::derivative_at_nested) | [`RationalBezierCurve::derivative_at_reference`](crate::RationalBezierCurve::derivative_at_reference) |
//! | surface point | [`BezierSurface::eval_nested`](crate::BezierSurface::eval_nested) | [`BezierSurface::eval_bernstein`](crate::BezierSurface::eval_bernstein) |
//!
//! The nested evaluation (Volk–Schumaker, Horner in Bernstein form) of `t = p/q`, `s = q − p`:
//! `qⁿ D b(t) = Σ_i C(n,i) pⁱ s^(n−i) (D b_i)`, accumulated as `acc ← s·acc + C(n,i) pⁱ (D b_i)`
//! with the coefficient `C(n,i) pⁱ` carried along — `n` steps instead of de Casteljau's
//! `n(n+1)/2`, and no gcd until the end. In exact arithmetic every algorithm gives the same
//! value, so the cheapest one wins.

use crate::coords::Point;
use crate::error::{check_degree, Error, Result};
use crate::exact::gcd::{self, Part};
use crate::exact::{elevation_words, splitting};
use choice::{horner_wins, pairs_win, powers_overflow, rows_first, words_hopeless};

mod choice;
mod horner;
mod horner_long;
mod int;
mod split;
use int::power;
pub(crate) use int::Int;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

/// Runs `kernel` on machine words and, if they overflow, on big integers.
fn words_then_big<R>(kernel: impl Fn(Tier) -> Option<R>) -> R {
    kernel(Tier::Words).unwrap_or_else(|| kernel(Tier::Big).expect("big integers do not overflow"))
}

/// [`words_then_big`] for the kernels whose outputs have the parameters' denominators to
/// the powers `powers` (a point of a curve or of its `k`-th derivative, the scheme's level
/// `n`, a surface's point): straight to big integers when their product is past the words
/// ([`powers_overflow`]), where the word kernel would fail for certain.
fn words_then_big_at<R>(powers: &[(usize, &BigInt)], kernel: impl Fn(Tier) -> Option<R>) -> R {
    if powers_overflow(powers) {
        return kernel(Tier::Big).expect("big integers do not overflow");
    }
    words_then_big(kernel)
}

/// Which integers a kernel runs on (see [`words_then_big`]).
#[derive(Clone, Copy)]
enum Tier {
    Words,
    Big,
}

/// Calls the generic `$f::<i128>(args)` or `$f::<BigInt>(args)` for a tier.
macro_rules! on_tier {
    ($tier:expr, $f:ident ( $($arg:expr),* )) => {
        match $tier {
            Tier::Words => $f::<i128>($($arg),*),
            Tier::Big => $f::<BigInt>($($arg),*),
        }
    };
}

/// Exact coordinates over one common denominator: `values[i] = nums[i] / den`, `den > 0`.
pub(crate) struct OverDenominator<I> {
    pub(crate) nums: Vec<I>,
    pub(crate) den: I,
}

/// Writes `values` over their least common denominator.
pub(crate) fn common_denominator<'a, I: Int>(
    values: impl Iterator<Item = &'a BigRational>,
) -> Option<OverDenominator<I>> {
    let mut nums = Vec::with_capacity(values.size_hint().0);
    let mut dens = Vec::new();
    let mut den = I::one();
    for (i, v) in values.enumerate() {
        nums.push(I::from_big(v.numer())?);
        // Denominators are positive; `bits() == 1` is the allocation-free test for 1.
        if v.denom().bits() != 1 {
            let d = I::from_big(v.denom())?;
            den = den.lcm(&d)?;
            dens.push((i, d));
        }
    }
    if !dens.is_empty() {
        // x = n/d becomes n (den/d); `dens` lists the d ≠ 1 in index order.
        let mut others = dens.iter().peekable();
        for (i, x) in nums.iter_mut().enumerate() {
            let factor = match others.next_if(|(j, _)| *j == i) {
                Some((_, d)) => den.div_exact(d),
                None => den.clone(),
            };
            *x = x.mul(&factor)?;
        }
    }
    Some(OverDenominator { nums, den })
}

/// Exact points, the output of the kernels.
type Points = Vec<Point<BigRational>>;

/// `(p, q, s = q − p)` for `t = p/q`.
fn parameter<I: Int>(t: &BigRational) -> Option<(I, I, I)> {
    let p = I::from_big(t.numer())?;
    let q = I::from_big(t.denom())?;
    let s = q.sub(&p)?;
    Some((p, q, s))
}

/// `Σ_i C(n,i) pⁱ s^(n−i) x_i` for `n + 1` vectors of `dim` integers stored flat in `x`,
/// by the nested (Horner) scheme; the result has `dim` integers.
fn nested_sum<I: Int>(x: &[I], dim: usize, p: &I, s: &I) -> Option<Vec<I>> {
    let n = x.len() / dim - 1;
    let mut acc: Vec<I> = x[..dim].to_vec();
    // coefficient = C(n, i) pⁱ, updated by C(n,i) = C(n,i−1) (n−i+1) / i before the factor p.
    let mut coefficient = I::one();
    for (i, row) in x.chunks_exact(dim).enumerate().skip(1) {
        coefficient = coefficient
            .mul(&I::from_u64((n - i + 1) as u64))?
            .div_exact(&I::from_u64(i as u64))
            .mul(p)?;
        for (a, xi) in acc.iter_mut().zip(row) {
            a.step(s, &coefficient, xi)?;
        }
    }
    Some(acc)
}

/// The point `nums / den` (one reduction per coordinate).
fn point_over<I: Int>(nums: Vec<I>, den: &I) -> Point<BigRational> {
    Point::new(nums.into_iter().map(|c| I::ratio(c, den.clone())).collect())
        .expect("as many coordinates as a valid point")
}

/// The flat control coordinates of a curve.
fn coordinates(points: &[Point<BigRational>]) -> impl Iterator<Item = &BigRational> {
    points.iter().flat_map(|p| p.coords())
}

/// The values of coordinate `k` of the points.
fn coordinate(points: &[Point<BigRational>], k: usize) -> impl Iterator<Item = &BigRational> {
    points.iter().map(move |p| &p.coords()[k])
}

/// The point whose coordinate `k` is `each(k)`.
fn point_by_coordinate(dim: usize, each: impl FnMut(usize) -> Option<BigRational>) -> Option<Point<BigRational>> {
    let coords = (0..dim).map(each).collect::<Option<Vec<_>>>()?;
    Some(Point::new(coords).expect("as many coordinates as a valid point"))
}

// One coordinate at a time, each over its own common denominator: with unrelated
// denominators in the coordinates, a denominator shared by all would be their product,
// and every integer of the sum that much longer.
fn curve_eval(c: &Curve<'_>, t: &BigRational) -> Point<BigRational> {
    point_by_coordinate(c.dim(), |k| {
        let values: Vec<&BigRational> = coordinate(c.points(), k).collect();
        Some(coordinate_sum(&values, t))
    })
    .expect("every coordinate has a sum")
}

/// `Σ x_i B_i^n(t)` of one coordinate's values, reduced: on machine words nested over
/// their common denominator; on big integers nested on a fraction (`horner`) while
/// [`horner_wins`], else by binary splitting.
fn coordinate_sum_on<I: Int>(values: &[&BigRational], t: &BigRational) -> Option<BigRational> {
    if I::IS_BIG {
        if horner_wins(values, t.denom()) {
            let (p, q) = (t.numer(), t.denom());
            return Some(
                horner::word_fraction_sum(values, p, q).unwrap_or_else(|| horner_long::long_sum(values, p, q)),
            );
        }
        // Past that the sum is split in balanced halves (see `splitting`).
        return Some(splitting::bernstein_sum(values, t.numer(), t.denom()));
    }
    let (p, q, s) = parameter::<I>(t)?;
    let x = common_denominator::<I>(values.iter().copied())?;
    let acc = nested_sum(&x.nums, 1, &p, &s)?.pop()?;
    I::ratio_over_power(acc, &x.den, &q, values.len() - 1)
}

/// [`coordinate_sum_on`] on machine words while they may fit, else on big integers.
fn coordinate_sum(values: &[&BigRational], t: &BigRational) -> BigRational {
    if words_hopeless(values, 160) {
        return coordinate_sum_on::<BigInt>(values, t).expect("big integers do not overflow");
    }
    words_then_big_at(&[(values.len() - 1, t.denom())], |tier| {
        on_tier!(tier, coordinate_sum_on(values, t))
    })
}

/// The `k`-th forward differences of the flat vectors `x` (`dim` integers each).
fn differences<I: Int>(mut x: Vec<I>, dim: usize, k: usize) -> Option<Vec<I>> {
    for _ in 0..k {
        for j in 0..x.len() - dim {
            let (left, right) = x.split_at_mut(j + dim);
            left[j].sub_from(&right[0])?;
        }
        x.truncate(x.len() - dim);
    }
    Some(x)
}

/// `n!/(n−k)!`.
fn falling_factorial<I: Int>(n: usize, k: usize) -> Option<I> {
    (n - k + 1..=n).try_fold(I::one(), |acc, m| acc.mul(&I::from_u64(m as u64)))
}

fn curve_derivative_at<I: Int>(c: &Curve<'_>, k: usize, t: &BigRational) -> Option<Point<BigRational>> {
    let n = c.degree();
    let (p, q, s) = parameter::<I>(t)?;
    let factor = falling_factorial::<I>(n, k)?;
    point_by_coordinate(c.dim(), |j| {
        if I::IS_BIG {
            // The first derivative as one binary-splitting sum; the others over the lcm as a
            // tree of short factors, reduced by a remainder tree, not a gcd of long numbers.
            let values: Vec<&BigRational> = coordinate(c.points(), j).collect();
            if k == 1 {
                if let Some(d) = splitting::first_derivative_sum(&values, t.numer(), t.denom()) {
                    return Some(d);
                }
            }
            let (nums, tree) = splitting::over_lcm(&values);
            let diffs = differences(nums, 1, k)?;
            let (p, s, q) = (p.clone().into_big(), s.clone().into_big(), q.clone().into_big());
            let acc = nested_sum(&diffs, 1, &p, &s)?.pop()? * factor.clone().into_big();
            return Some(splitting::reduce_over(acc, tree.as_ref(), &[(&q, n - k)]));
        }
        let x = common_denominator::<I>(coordinate(c.points(), j))?;
        let diffs = differences(x.nums, 1, k)?;
        let acc = nested_sum(&diffs, 1, &p, &s)?.pop()?.mul(&factor)?;
        I::ratio_over_power(acc, &x.den, &q, n - k)
    })
}

fn curve_derivative<I: Int>(c: &Curve<'_>, k: usize) -> Option<Vec<Point<BigRational>>> {
    let (n, dim) = (c.degree(), c.dim());
    let x = common_denominator::<I>(coordinates(c.points()))?;
    let factor = falling_factorial::<I>(n, k)?;
    let diffs = differences(x.nums, dim, k)?;
    diffs
        .chunks_exact(dim)
        .map(|d| {
            let scaled = d.iter().map(|v| v.mul(&factor)).collect::<Option<Vec<_>>>()?;
            Some(point_over(scaled, &x.den))
        })
        .collect()
}

/// The columns of the fraction-free de Casteljau triangle of coordinate `k`: calls
/// `visit(r, column, den, q)` for `r = 0..=n`, where `column` holds the `n − r + 1` values
/// `b_i^r(t)` as numerators over `den · q^r`.
fn casteljau_columns<I: Int>(
    c: &Curve<'_>,
    k: usize,
    t: &BigRational,
    mut visit: impl FnMut(usize, &[I], &I, &I) -> Option<()>,
) -> Option<()> {
    let n = c.degree();
    let (p, q, s) = parameter::<I>(t)?;
    let x = common_denominator::<I>(coordinate(c.points(), k))?;
    let mut buf = x.nums;
    visit(0, &buf, &x.den, &q)?;
    for r in 1..=n {
        for j in 0..n + 1 - r {
            let next = buf[j + 1].clone();
            buf[j].step(&s, &p, &next)?;
        }
        visit(r, &buf[..n + 1 - r], &x.den, &q)?;
    }
    Some(())
}

/// Points from the values `values[i][k]` of coordinate `k` of point `i`.
pub(crate) fn transpose(values: Vec<Vec<BigRational>>, count: usize) -> Points {
    let mut points: Vec<Vec<BigRational>> = (0..count).map(|_| Vec::with_capacity(values.len())).collect();
    for column in values {
        for (point, v) in points.iter_mut().zip(column) {
            point.push(v);
        }
    }
    points
        .into_iter()
        .map(|coords| Point::new(coords).expect("as many coordinates as a valid point"))
        .collect()
}

fn curve_split<I: Int>(c: &Curve<'_>, t: &BigRational) -> Option<(Points, Points)> {
    let (n, dim) = (c.degree(), c.dim());
    let mut left = Vec::with_capacity(dim);
    let mut right = Vec::with_capacity(dim);
    for k in 0..dim {
        // Long denominators, low degree: pair by pair on reduced fractions.
        let values = I::IS_BIG.then(|| coordinate(c.points(), k).collect::<Vec<_>>());
        let pairs = values.filter(|v| pairs_win(v, t.denom()));
        if let Some((l, r)) = pairs.and_then(|v| split::split_coordinate(&v, t)) {
            left.push(l);
            right.push(r);
            continue;
        }
        let (mut l, mut r) = (Vec::with_capacity(n + 1), Vec::with_capacity(n + 1));
        casteljau_columns::<I>(c, k, t, |level, column, den, q| {
            if level == 0 {
                // The halves start at the curve's end points: the inputs, already reduced.
                l.push(c.points()[0].coords()[k].clone());
                r.push(c.points()[n].coords()[k].clone());
                return Some(());
            }
            let first = I::ratio_over_power(column[0].clone(), den, q, level)?;
            // The last level's one value is both halves' common point: reduced once.
            let last = if level == n {
                first.clone()
            } else {
                I::ratio_over_power(column[n - level].clone(), den, q, level)?
            };
            l.push(first);
            r.push(last);
            Some(())
        })?;
        r.reverse();
        left.push(l);
        right.push(r);
    }
    Some((transpose(left, n + 1), transpose(right, n + 1)))
}

fn curve_scheme<I: Int>(c: &Curve<'_>, t: &BigRational) -> Option<Vec<Vec<Point<BigRational>>>> {
    let (n, dim) = (c.degree(), c.dim());
    // values[k][r][i]: coordinate k of b_i^r.
    let mut values = Vec::with_capacity(dim);
    for k in 0..dim {
        let mut columns = Vec::with_capacity(n + 1);
        casteljau_columns::<I>(c, k, t, |r, column, den, q| {
            let den = den.mul(&power(q, r)?)?;
            columns.push(
                column
                    .iter()
                    .map(|v| I::ratio(v.clone(), den.clone()))
                    .collect::<Vec<_>>(),
            );
            Some(())
        })?;
        values.push(columns);
    }
    Some(
        (0..=n)
            .map(|r| {
                transpose(
                    values
                        .iter_mut()
                        .map(|columns| std::mem::take(&mut columns[r]))
                        .collect(),
                    n + 1 - r,
                )
            })
            .collect(),
    )
}

/// `C(m, 0), …, C(m, m)`, checked.
fn binomials<I: Int>(m: usize) -> Option<Vec<I>> {
    let mut row = Vec::with_capacity(m + 1);
    let mut c = I::one();
    row.push(c.clone());
    for k in 0..m {
        c = c
            .mul(&I::from_u64((m - k) as u64))?
            .div_exact(&I::from_u64(k as u64 + 1));
        row.push(c.clone());
    }
    Some(row)
}

fn curve_elevate_by<I: Int>(c: &Curve<'_>, r: usize) -> Option<Vec<Point<BigRational>>> {
    let (n, dim) = (c.degree(), c.dim());
    let x = common_denominator::<I>(coordinates(c.points()))?;
    let (cn, cr, ct) = (binomials::<I>(n)?, binomials::<I>(r)?, binomials::<I>(n + r)?);
    let mut out = Vec::with_capacity(n + r + 1);
    for (i, total) in ct.iter().enumerate() {
        // (8): b_i^(r) = Σ_j C(n,j) C(r,i−j) b_j / C(n+r,i), over D C(n+r,i).
        let mut acc = vec![I::zero(); dim];
        for j in i.saturating_sub(r)..=i.min(n) {
            let w = cn[j].mul(&cr[i - j])?;
            for (a, xj) in acc.iter_mut().zip(&x.nums[j * dim..(j + 1) * dim]) {
                *a = a.add(&w.mul(xj)?)?;
            }
        }
        out.push(point_over(acc, &x.den.mul(total)?));
    }
    Some(out)
}

fn curve_elevate<I: Int>(c: &Curve<'_>) -> Option<Vec<Point<BigRational>>> {
    let (n, dim) = (c.degree(), c.dim());
    let x = common_denominator::<I>(coordinates(c.points()))?;
    let n1 = I::from_u64(n as u64 + 1);
    let den = x.den.mul(&n1)?;
    let row = |j: usize| &x.nums[j * dim..(j + 1) * dim];
    let mut out = Vec::with_capacity(n + 2);
    for i in 0..=n + 1 {
        // (7): b_i' = (i b_{i−1} + (n+1−i) b_i) / (n+1).
        let coords = (0..dim)
            .map(|k| {
                let left = if i > 0 {
                    row(i - 1)[k].mul(&I::from_u64(i as u64))?
                } else {
                    I::zero()
                };
                let right = if i <= n {
                    row(i)[k].mul(&I::from_u64((n + 1 - i) as u64))?
                } else {
                    I::zero()
                };
                left.add(&right)
            })
            .collect::<Option<Vec<_>>>()?;
        out.push(point_over(coords, &den));
    }
    Some(out)
}

/// `q_u^m q_v^n D b(u, v)` of one coordinate whose net values are `x` over `D`, in rows
/// of `n + 1`: each row's nested sum at `v`, then the column of those at `u`.
fn net_numerator<I: Int>(x: &[I], n: usize, (pu, su): (&I, &I), (pv, sv): (&I, &I)) -> Option<I> {
    let mut rows = Vec::with_capacity(x.len() / (n + 1));
    for row in x.chunks_exact(n + 1) {
        rows.extend(nested_sum(row, 1, pv, sv)?);
    }
    nested_sum(&rows, 1, pu, su)?.pop()
}

// One coordinate at a time over its own common denominator, as `curve_eval`.
fn surface_eval<I: Int>(sf: &Net<'_>, u: &BigRational, v: &BigRational) -> Option<Point<BigRational>> {
    let (m, n) = sf.degrees();
    let (pu, qu, su) = parameter::<I>(u)?;
    let (pv, qv, sv) = parameter::<I>(v)?;
    point_by_coordinate(sf.dim(), |k| {
        if I::IS_BIG {
            let net: Vec<Vec<&BigRational>> = sf
                .net()
                .iter()
                .map(|row| row.iter().map(|p| &p.coords()[k]).collect())
                .collect();
            if net.iter().all(|row| rows_first(row, v)) {
                // Each row's point at `v` reduced, then their column at `u`.
                let column: Vec<BigRational> = net.iter().map(|row| coordinate_sum(row, v)).collect();
                return Some(coordinate_sum(&column.iter().collect::<Vec<_>>(), u));
            }
            return Some(splitting::net_sum(&net, u, v));
        }
        let x = common_denominator::<I>(sf.net().iter().flatten().map(|p| &p.coords()[k]))?;
        let acc = net_numerator(&x.nums, n, (&pu, &su), (&pv, &sv))?;
        Some(I::ratio(acc, x.den.mul(&power(&qv, n)?)?.mul(&power(&qu, m)?)?))
    })
}

/// A curve's control points as the kernels read them (the names of the curve's methods, so
/// that the kernels read as they did on the curve type).
struct Curve<'a>(&'a [Point<BigRational>]);

impl Curve<'_> {
    fn points(&self) -> &[Point<BigRational>] {
        self.0
    }
    fn degree(&self) -> usize {
        self.0.len() - 1
    }
    fn dim(&self) -> usize {
        self.0[0].dim()
    }
}

/// A surface's net of control points as the kernels read it.
struct Net<'a>(&'a [Vec<Point<BigRational>>]);

impl Net<'_> {
    fn net(&self) -> &[Vec<Point<BigRational>>] {
        self.0
    }
    fn degrees(&self) -> (usize, usize) {
        (self.0.len() - 1, self.0[0].len() - 1)
    }
    fn dim(&self) -> usize {
        self.0[0][0].dim()
    }
}

// The kernels on control points (a valid curve's: at least one point, one dimension), what
// `BigRational`'s `Scalar` methods and the curve types' `*_nested` / `*_fraction_free`
// methods run.

/// `b(t)` by the nested (Horner) Bernstein sum over integers.
pub(crate) fn eval(points: &[Point<BigRational>], t: &BigRational) -> Point<BigRational> {
    // The curve passes through its end points, (1) at t = 0 and 1: no sum to form.
    if t.is_zero() {
        return points[0].clone();
    }
    if t.is_one() {
        return points[points.len() - 1].clone();
    }
    curve_eval(&Curve(points), t)
}

/// The `k`-th derivative vector at `t`, `k` at most the degree.
pub(crate) fn derivative_at(points: &[Point<BigRational>], k: usize, t: &BigRational) -> Point<BigRational> {
    let c = &Curve(points);
    words_then_big_at(&[(c.degree().saturating_sub(k), t.denom())], |tier| {
        on_tier!(tier, curve_derivative_at(c, k, t))
    })
}

/// The `k`-th derivative curve's points; `k > n` is [`Error::DerivativeOrder`].
pub(crate) fn derivative(points: &[Point<BigRational>], k: usize) -> Result<Vec<Point<BigRational>>> {
    let c = &Curve(points);
    if k > c.degree() {
        return Err(Error::DerivativeOrder {
            order: k,
            degree: c.degree(),
        });
    }
    if k == 1 {
        // Neighbours combined pairwise: each point over its own two denominators, where a
        // denominator common to the whole curve makes every point as long as all inputs.
        // The word kernel puts the whole curve over one denominator.
        let short = !words_hopeless(&coordinates(points).collect::<Vec<_>>(), 64);
        if let Some(points) = short.then(|| curve_derivative::<i128>(c, 1)).flatten() {
            return Ok(points);
        }
        return Ok(elevation_words::derivative_pairwise(points));
    }
    Ok(words_then_big(|tier| on_tier!(tier, curve_derivative(c, k))))
}

/// The columns of de Casteljau's triangle (9) at `t`.
pub(crate) fn scheme(points: &[Point<BigRational>], t: &BigRational) -> Vec<Vec<Point<BigRational>>> {
    let c = &Curve(points);
    words_then_big_at(&[(c.degree(), t.denom())], |tier| on_tier!(tier, curve_scheme(c, t)))
}

/// The two halves of the subdivision at `t0`.
pub(crate) fn split(points: &[Point<BigRational>], t0: &BigRational) -> (Points, Points) {
    let c = &Curve(points);
    words_then_big_at(&[(c.degree(), t0.denom())], |tier| on_tier!(tier, curve_split(c, t0)))
}

/// One degree elevation step (7); beyond [`crate::MAX_DEGREE`] an error.
pub(crate) fn elevate(points: &[Point<BigRational>]) -> Result<Vec<Point<BigRational>>> {
    let c = &Curve(points);
    check_degree("degree after elevation", c.degree() as u128 + 1)?;
    Ok(curve_elevate::<i128>(c).unwrap_or_else(|| elevation_words::elevate_pairwise(points)))
}

/// `r` elevation steps by the closed form (8).
///
/// One step (`r = 1`) combines each point with its neighbour over their own denominators,
/// not (8) over the common denominator of the whole curve: with distinct denominators every
/// point of (8) is as long as all `n + 1` inputs together, so one step would cost time
/// quadratic in the degree. Several steps keep (8): taken one by one they re-reduce every
/// point at every step, which the oracle's calibration measured slower on integers, floats
/// and decimals (its work estimate is made for (8)).
pub(crate) fn elevate_by(points: &[Point<BigRational>], r: usize) -> Result<Vec<Point<BigRational>>> {
    let c = &Curve(points);
    check_degree("degree after elevation", c.degree() as u128 + r as u128)?;
    match r {
        0 => Ok(points.to_vec()),
        1 => elevate(points),
        _ => Ok(words_then_big(|tier| on_tier!(tier, curve_elevate_by(c, r)))),
    }
}

/// A rational curve at `t` from its homogeneous points: the homogeneous point by [`eval`],
/// then `x = X / W` by the gcds of the two numerators and of the two denominators
/// ([`gcd::divide`]); `None` when the denominator `w(t)` vanishes.
pub(crate) fn rational_eval(homogeneous: &[Point<BigRational>], t: &BigRational) -> Option<Point<BigRational>> {
    let h = eval(homogeneous, t);
    let (w, x) = h.coords().split_last().expect("dim + 1 ≥ 2 homogeneous coordinates");
    if w.is_zero() {
        return None;
    }
    Some(Point::new(x.iter().map(|c| gcd::divide(c, w)).collect()).expect("as many coordinates as a valid point"))
}

/// A rational curve's derivative at `t` from its homogeneous points of degree `n ≥ 1`
/// (`RationalBezierCurve::derivative_at_nested` says how); `None` when `w(t)` vanishes.
pub(crate) fn rational_derivative_at(points: &[Point<BigRational>], t: &BigRational) -> Option<Point<BigRational>> {
    let n = points.len() - 1;
    let column = |range: std::ops::Range<usize>| eval(&points[range], t);
    let (h0, h1) = (column(0..n), column(1..n + 1));
    let (w0, h0) = h0.coords().split_last().expect("dim + 1 ≥ 2 homogeneous coordinates");
    let (w1, h1) = h1.coords().split_last().expect("dim + 1 ≥ 2 homogeneous coordinates");
    let (p, q) = (t.numer(), t.denom());
    let (a_w, b_w, c_w, d_w) = (w0.numer(), w0.denom(), w1.numer(), w1.denom());
    let big_w = (q - p) * a_w * d_w + p * c_w * b_w;
    if big_w.is_zero() {
        return None;
    }
    let common = BigInt::from(n) * q * q * b_w * d_w;
    let coords = h0.iter().zip(h1).map(|(x0, x1)| {
        let (a, b, c, d) = (x0.numer(), x0.denom(), x1.numer(), x1.denom());
        // `b` and `d` share the factors of the points 1..n−1: over `g b' d'` the
        // numerator is shorter than over `b d` by the length of `g`.
        let g = gcd::gcd_int(b, d);
        let (b1, d1) = if g.is_one() {
            (b.clone(), d.clone())
        } else {
            (b / &g, d / &g)
        };
        let num = (c * a_w * &b1 * d_w - a * c_w * &d1 * b_w) * &common;
        gcd::reduce(
            num,
            &[
                Part::Number(&b1),
                Part::Number(&d1),
                Part::Number(&g),
                Part::Power(&big_w, 2),
            ],
        )
    });
    Some(Point::new(coords.collect()).expect("as many coordinates as a valid point"))
}

/// A surface at `(u, v)` by nested sums over integers, rows at `v` then the column at `u`,
/// one reduction per coordinate.
pub(crate) fn surface_point(net: &[Vec<Point<BigRational>>], u: &BigRational, v: &BigRational) -> Point<BigRational> {
    let sf = &Net(net);
    let (m, n) = sf.degrees();
    words_then_big_at(&[(m, u.denom()), (n, v.denom())], |tier| {
        on_tier!(tier, surface_eval(sf, u, v))
    })
}

/// `Σ_i C(n,i) pⁱ (q−p)^(n−i) x_i` for integer `x_0..x_n` and `t = p/q`, exactly: the
/// numerator of `Σ x_i B_i^n(t)` over `qⁿ`. On machine words while they fit.
///
/// ```
/// use casteljau::exact::fraction_free::bernstein_numerator;
/// use casteljau::BigInt;
/// // at t = 2 (p = 2, q = 1): Σ x_i B_i^2(2) = 1·1 + 0·(−4) + 1·4
/// let x: Vec<BigInt> = [1, 0, 1].into_iter().map(BigInt::from).collect();
/// assert_eq!(bernstein_numerator(&x, &2.into(), &1.into()), BigInt::from(5));
/// ```
pub fn bernstein_numerator(x: &[BigInt], p: &BigInt, q: &BigInt) -> BigInt {
    if x.is_empty() {
        return <BigInt as Zero>::zero();
    }
    fn run<I: Int>(x: &[BigInt], p: &BigInt, q: &BigInt) -> Option<BigInt> {
        let xs = x.iter().map(I::from_big).collect::<Option<Vec<I>>>()?;
        let (p, q) = (I::from_big(p)?, I::from_big(q)?);
        let s = q.sub(&p)?;
        let acc = nested_sum(&xs, 1, &p, &s)?.pop()?;
        Some(acc.into_big())
    }
    words_then_big(|tier| on_tier!(tier, run(x, p, q)))
}
