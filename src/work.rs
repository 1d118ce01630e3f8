//! The work model: a rough count of the exact work of a kernel on given numbers, so that
//! absurd requests (the oracle's) and figures are refused before any computation.
//!
//! The unit is one bit² of gcd-reduced rational arithmetic; each estimate follows the kernel
//! it models, with constants set so that [`HALF_SECOND`] units take about half a second of
//! CPU on one core of a busy 2-core machine (`tests/calibration.rs` runs the largest
//! admitted oracle request of every op and fails above one second).

use crate::curve::BezierCurve;
use crate::fit::CubicFitData;
use crate::rational::RationalBezierCurve;
use crate::surface::BezierSurface;
use num_rational::BigRational;

/// About half a second of CPU, in work units.
pub(crate) const HALF_SECOND: f64 = 5.0e11;

fn bits(r: &BigRational) -> f64 {
    (r.numer().bits() + r.denom().bits()) as f64
}

/// How many bits each de Casteljau level adds when the parameter is `t`.
fn growth_bits(t: &BigRational) -> f64 {
    t.numer().bits().max(t.denom().bits()) as f64
}

/// Whether `t`'s denominator is a power of two (gcds against its powers are cheap shifts).
fn is_dyadic(t: &BigRational) -> bool {
    t.denom().trailing_zeros().is_none_or(|z| z + 1 == t.denom().bits())
}

/// What the denominators of some numbers are: one unit of a model costs very different CPU
/// time on each (a power of two reduces by shifts, a divisor of a power of ten by a few small
/// factors, unrelated denominators by full gcds), so estimates are calibrated per kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum NumberKind {
    /// Every denominator is 1.
    Integer,
    /// Every denominator is a power of two (floats).
    Dyadic,
    /// Every denominator divides a power of ten (decimals).
    Decimal,
    /// Anything else.
    General,
}

/// The kinds of denominators among `numbers`, as a set: bit `k` for [`NumberKind`] `k`.
///
/// A request is charged by every kind it holds, not only by the most general: a model unit
/// costs less on decimals or fractions than on integers (their models count denominators
/// that the kernels share), so one `"0.1"` among 40-digit integers must not make the
/// integers' work cheap.
pub(crate) fn number_kinds<'a>(numbers: impl IntoIterator<Item = &'a BigRational>) -> u8 {
    let mut kinds = 0u8;
    let mut last: Option<&num_bigint::BigInt> = None;
    for r in numbers {
        let d = r.denom();
        // runs of one denominator (decimals of one scale) are classified once
        if last == Some(d) {
            continue;
        }
        last = Some(d);
        kinds |= 1 << denominator_kind(d) as u8;
        if kinds == 0b1111 {
            break;
        }
    }
    kinds
}

/// The kinds in a set of [`number_kinds`].
pub(crate) fn kinds_in(set: u8) -> impl Iterator<Item = NumberKind> {
    [
        NumberKind::Integer,
        NumberKind::Dyadic,
        NumberKind::Decimal,
        NumberKind::General,
    ]
    .into_iter()
    .filter(move |k| set & (1 << *k as u8) != 0)
}

/// The kind of one number's denominator.
pub(crate) fn kind_of(r: &BigRational) -> NumberKind {
    denominator_kind(r.denom())
}

fn denominator_kind(d: &num_bigint::BigInt) -> NumberKind {
    let twos = d.trailing_zeros().unwrap_or(0);
    let odd = d >> twos;
    if odd == num_bigint::BigInt::from(1) {
        return if twos == 0 {
            NumberKind::Integer
        } else {
            NumberKind::Dyadic
        };
    }
    // a power of five has about bits / log2(5) factors: the two exponents that fit its size;
    // their low words first, so that a general denominator costs no power
    let guess = ((odd.bits() - 1) as f64 / 5f64.log2()) as u32;
    let low = odd.iter_u64_digits().next().unwrap_or(0);
    let five = num_bigint::BigInt::from(5);
    if (guess..=guess + 1).any(|m| 5u64.wrapping_pow(m) == low && five.pow(m) == odd) {
        NumberKind::Decimal
    } else {
        NumberKind::General
    }
}

fn max_bits<'a>(numbers: impl IntoIterator<Item = &'a BigRational>) -> f64 {
    numbers.into_iter().map(bits).fold(0.0, f64::max)
}

fn curve_bits(c: &BezierCurve<BigRational>) -> f64 {
    max_bits(c.points().iter().flat_map(|p| p.coords()))
}

/// How many bits a combination of several inputs may add to the denominator: none when
/// every denominator is a power of two (their lcm is the largest), else the largest.
fn den_growth<'a>(numbers: impl IntoIterator<Item = &'a BigRational>) -> f64 {
    let mut dyadic = true;
    let mut most = 0u64;
    for r in numbers {
        let d = r.denom();
        most = most.max(d.bits());
        dyadic &= is_dyadic(r);
    }
    if dyadic {
        0.0
    } else {
        most as f64
    }
}

fn curve_den_growth(c: &BezierCurve<BigRational>) -> f64 {
    den_growth(c.points().iter().flat_map(|p| p.coords()))
}

/// Relative cost of the gcds on the input numbers: unrelated denominators make every
/// reduction a full gcd, while numbers grown inside one algorithm mostly share theirs.
const INPUT_WEIGHT: f64 = 25.0;

/// Cost of one exact operation on input numbers of `b_in` bits, grown inside the
/// algorithm by `shared` bits (powers of a common denominator: cheap reductions) and by
/// `mixed` bits (products of unrelated denominators: every gcd is a full one). Gcd
/// reduction is quadratic in the size.
fn op_cost(b_in: f64, shared: f64, mixed: f64) -> f64 {
    let b = b_in + mixed + 64.0;
    INPUT_WEIGHT * b * b + SHARED_WEIGHT * shared * shared
}

/// Relative cost of the reductions by the elevation weights `C(n,j)C(r,i−j)/C(n+r,i)`.
const ELEVATION_WEIGHT: f64 = 20.0;

/// Relative cost of bits grown inside one algorithm (binomial factors, powers of one
/// parameter): `to_bezier` of degree 360 with one-digit integers takes about 2 s at weight 1.
const SHARED_WEIGHT: f64 = 6.0;

/// How much slower the generic de Casteljau triangle (`split`, `derivative` at `t`) runs
/// than its units say: every lerp reduces three fractions by binary gcds, whose cost with
/// a small operand (a parameter such as 1/3) is still quadratic in the other's size. Set by
/// the slowest kind of input in `tests/calibration.rs` (one-digit integers at `t = 1/3`).
const TRIANGLE_WEIGHT: f64 = 16.0;

/// Relative cost of numbers grown by a dyadic parameter (powers of two in the
/// denominators reduce by shifts, but the numerators still grow).
/// Calibrated by `scripts/work_calibration.rs`: `split` of 64-D floats of degree 53 at
/// `t = 0.1` took 6.8 s at weight 3, so the weight is 6.
const DYADIC_WEIGHT: f64 = 6.0;

/// Work of the de Casteljau triangle on `n + 1` points of dimension `dim` whose
/// coordinates have `b` bits, at the parameter `t`, with inputs whose denominators add
/// `den` bits per level: level `r` has `n − r + 1` lerps on numbers grown by `r` times
/// the parameter's and the denominators' bits. Measured on unstructured data, where
/// nothing cancels; a parameter that is not dyadic makes every reduction a full gcd.
fn triangle_work(n: usize, dim: usize, b: f64, t: &BigRational, den: f64) -> f64 {
    let bt = growth_bits(t);
    let (dyadic, full) = if is_dyadic(t) { (bt, 0.0) } else { (0.0, bt) };
    (1..=n)
        .map(|r| {
            let r_f = r as f64;
            let dyadic_growth = r_f * dyadic;
            (n - r + 1) as f64 * (op_cost(b, 0.0, r_f * (den + full)) + DYADIC_WEIGHT * dyadic_growth * dyadic_growth)
        })
        .sum::<f64>()
        * dim as f64
        * TRIANGLE_WEIGHT
}

/// The common denominator of `numbers`: its bits, bounded by the sum of the distinct
/// denominators' bits (without computing it), and the work of computing it. The kernels
/// take it as a running lcm, each step a binary gcd of the lcm so far with the next
/// denominator, quadratic in the lcm's size: `Σ_k S_k²` over the running sums of bits
/// (powers of two cost nothing: their lcm is the largest).
fn common_denominator<'a>(numbers: impl Iterator<Item = &'a BigRational> + Clone) -> (f64, f64) {
    if numbers.clone().all(is_dyadic) {
        let most = numbers.map(|c| c.denom().bits()).max().unwrap_or(0);
        return (most as f64, 0.0);
    }
    let mut denominators: Vec<&num_bigint::BigInt> = numbers.map(|c| c.denom()).collect();
    denominators.sort();
    denominators.dedup();
    let (mut bits, mut work) = (0.0, 0.0);
    for d in denominators {
        bits += d.bits() as f64;
        work += LCM_WEIGHT * bits * bits;
    }
    (bits, work)
}

/// Set by `eval` of 30-digit fractions with distinct denominators in
/// `tests/calibration.rs`, where the running lcm is most of the work.
const LCM_WEIGHT: f64 = 3.0;

/// The steps of the fraction-free kernels ([`BezierCurve::eval_nested`] and its rational and
/// surface forms) on integers of `start` bits: each of the `n(n+1)/2` steps per coordinate
/// two products of a number grown by `r` times the parameter's bits with the parameter's
/// numerator or denominator. These word-sized products run about eight times faster per
/// unit than the gcd-bound operations the units are set by.
fn nested_steps(start: f64, n: usize, dim: usize, t: &BigRational) -> f64 {
    let grow = growth_bits(t);
    // a product with the parameter's numerator or denominator costs at least a machine word
    let word = grow.max(64.0);
    let steps: f64 = (1..=n)
        .map(|r| (n - r + 1) as f64 * 2.0 * (start + 64.0 + r as f64 * grow) * word)
        .sum();
    dim as f64 * steps / 8.0
}

/// The one reduction per coordinate that ends a fraction-free evaluation.
fn final_reduction(bits: f64, dim: usize) -> f64 {
    dim as f64 * INPUT_WEIGHT * (bits + 64.0) * (bits + 64.0)
}

/// Work of [`BezierCurve::eval_nested`] (and of the rational form, on the homogeneous
/// points): integers over one common denominator, the nested sum, one reduction.
fn fraction_free_work<'a>(
    numbers: impl Iterator<Item = &'a BigRational> + Clone,
    numerators: f64,
    n: usize,
    dim: usize,
    t: &BigRational,
) -> f64 {
    let (common, lcm) = common_denominator(numbers);
    let start = numerators + common;
    lcm + nested_steps(start, n, dim, t) + final_reduction(start + n as f64 * growth_bits(t), dim)
}

/// [`BezierCurve::eval_nested`] at `t` (the oracle's `eval` and `float_eval`).
pub(crate) fn eval_work(curve: &BezierCurve<BigRational>, t: &BigRational) -> f64 {
    let coords = curve.points().iter().flat_map(|p| p.coords());
    fraction_free_work(coords.clone(), max_bits(coords), curve.degree(), curve.dim(), t)
}

/// The de Casteljau triangle at `t` (subdivision, the scheme).
pub(crate) fn split_work(curve: &BezierCurve<BigRational>, t: &BigRational) -> f64 {
    triangle_work(
        curve.degree(),
        curve.dim(),
        curve_bits(curve),
        t,
        curve_den_growth(curve),
    )
}

/// Elevation by `by` steps.
pub(crate) fn elevate_work(curve: &BezierCurve<BigRational>, by: usize) -> f64 {
    let (n, total) = (curve.degree(), curve.degree() + by);
    // every output point combines up to n + 1 inputs with weights C(n,j)C(r,i−j)/C(n+r,i)
    // of about 2·total bits; each term is a multiplication and an addition, of an input
    // number by a weight: linear in the weight's size (calibrated by
    // `scripts/work_calibration.rs`: a cubic elevated by 1717 takes 0.04 s)
    let terms = (total + 1) as f64 * (n.min(by) + 1) as f64 * curve.dim() as f64;
    let mixed = (n.min(by) + 1) as f64 * curve_den_growth(curve);
    // in lowest terms a weight has at most about 2·total bits, and at most
    // about log2(total) per factor of its smaller binomial (a cubic elevated by
    // 1717: a few dozen bits)
    let few = (n.min(by) + 1) as f64 * ((total + 1) as f64).log2();
    let weight_bits = few.min(2.0 * total as f64);
    let b = curve_bits(curve) + mixed + 64.0;
    // each term's sum reduces a fraction over the weight's denominator: a binary
    // gcd on numbers of the weight's size (a cubic elevated by 1717 takes 0.04 s;
    // one-digit integers of degree 364 elevated by 364, 13 s at weight 0)
    terms * (INPUT_WEIGHT * b * b + ELEVATION_WEIGHT * (b + weight_bits) * (b + weight_bits)) + (total as f64).powi(3)
}

/// The `order`-th derivative curve, and with `at` its vector there: the work of the
/// differences and that of the evaluation (the kernels spend their units differently).
pub(crate) fn derivative_work(curve: &BezierCurve<BigRational>, order: usize, at: Option<&BigRational>) -> (f64, f64) {
    let (n, k) = (curve.degree(), order.min(curve.degree()));
    // Δ^k grows by k bits, the factor n!/(n−k)! has about k·log2(n) bits
    let shared = k as f64 * (1.0 + (n.max(2) as f64).log2());
    let mixed = (k + 1) as f64 * curve_den_growth(curve);
    let diffs = (k.max(1) * (n + 1)) as f64 * curve.dim() as f64 * op_cost(curve_bits(curve), shared, mixed);
    let b = curve_bits(curve) + shared + mixed;
    let level = curve_den_growth(curve);
    (
        diffs,
        at.map_or(0.0, |t| triangle_work(n - k, curve.dim(), b, t, level)),
    )
}

/// `x(t)` of a rational curve: the fraction-free kernel on the homogeneous points `(w b, w)`.
pub(crate) fn rational_eval_work(curve: &RationalBezierCurve<BigRational>, t: &BigRational) -> f64 {
    let coords = curve.points().iter().flat_map(|p| p.coords());
    let numerators = max_bits(coords.clone()) + max_bits(curve.weights());
    fraction_free_work(
        coords.chain(curve.weights()),
        numerators,
        curve.degree(),
        curve.dim() + 1,
        t,
    )
}

/// The type and implicit equation of a rational quadratic arc's conic.
pub(crate) fn conic_work(curve: &RationalBezierCurve<BigRational>) -> f64 {
    let numbers = curve.points().iter().flat_map(|p| p.coords()).chain(curve.weights());
    // a few hundred products of up to about eight input numbers
    300.0 * op_cost(8.0 * max_bits(numbers), 0.0, 0.0)
}

/// `b(u, v)` of a surface by the fraction-free kernel: one common denominator for the
/// whole net, every row at v, the column of their results at u, one reduction.
pub(crate) fn surface_eval_work(surface: &BezierSurface<BigRational>, u: &BigRational, v: &BigRational) -> f64 {
    let (m, n) = surface.degrees();
    let coords = surface.net().iter().flatten().flat_map(|p| p.coords());
    let (common, lcm) = common_denominator(coords.clone());
    let start = max_bits(coords) + common;
    let rows = (m + 1) as f64 * nested_steps(start, n, surface.dim(), v);
    let grown = start + n as f64 * growth_bits(v);
    let column = nested_steps(grown, m, surface.dim(), u);
    lcm + rows + column + final_reduction(grown + m as f64 * growth_bits(u), surface.dim())
}

/// Text 004's cubic fit from its five data points.
pub(crate) fn fit_cubic_work(data: &CubicFitData<BigRational>) -> f64 {
    let d = data;
    let numbers = [&d.x0, &d.x1, &d.xh, &d.d0, &d.d1].into_iter().flat_map(|p| p.coords());
    // Gram matrix, right-hand side, a 2×2 solve and δ²: a few dozen operations per
    // coordinate on products of up to about ten input numbers; calibrated by
    // `scripts/work_calibration.rs` (64-D points of 32-digit fractions took 14–48 s
    // at weight 1 on a busy machine, so the weight is 15)
    // sums over the coordinates of products with unrelated denominators grow by the common
    // denominator's bits (`tests/calibration.rs`: 30-digit fractions take dim^2.8)
    let (common, _) = common_denominator(numbers.clone());
    15.0 * (60 * d.x0.dim() + 100) as f64 * op_cost(10.0 * max_bits(numbers) + common, 0.0, 0.0)
}

/// The Bézier points of a curve given in the power basis, `power[k][i]` coordinate `k`'s
/// coefficient of `t^i`.
pub(crate) fn to_bezier_work(power: &[Vec<BigRational>]) -> f64 {
    let n = power.first().map_or(0, |c| c.len().saturating_sub(1));
    let b = max_bits(power.iter().flatten());
    let mixed = (n + 1) as f64 * den_growth(power.iter().flatten());
    3.0 * (n + 1) as f64 * (n + 1) as f64 * power.len() as f64 * op_cost(b, 2.0 * n as f64, mixed)
}
