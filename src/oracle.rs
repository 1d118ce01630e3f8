//! The JSON-lines oracle: exact answers for other programs (`casteljau oracle`).
//!
//! A program that computes Bézier geometry in floating point writes one JSON request per
//! line and reads back one JSON response per line with the exact answer, so it can measure
//! its own error. The loop ([`serve`]) never stops on a bad request: every line gets exactly
//! one response line, in order, flushed at once; only end of input ends it.
//!
//! ```
//! use casteljau::oracle::handle_line;
//! let out = handle_line(r#"{"id": 7, "op": "eval", "points": [[0, 0], [1, 2], [2, 0]], "t": "1/3"}"#);
//! assert_eq!(out, r#"{"id":7,"ok":true,"point":["2/3","8/9"]}"#);
//! let bad = handle_line(r#"{"op": "eval", "points": [], "t": 0}"#);
//! assert!(bad.starts_with(r#"{"error":"#) && bad.contains(r#""ok":false"#));
//! ```
//!
//! # Protocol
//!
//! Requests are JSON objects with an `"op"` and the op's fields; an `"id"` (any JSON value)
//! is echoed in the response. Numbers follow [`crate::input`]: strings (`"1/3"`, `"0.25"`,
//! `"1e-3"`) are exact, JSON numbers are exactly the `f64` they parse to. Exact results are
//! strings in lowest terms. Every response has `"ok"`; failures carry `"error"`. Unknown
//! fields are errors (a misspelt optional field would otherwise be silently ignored).
//!
//! | op           | fields                                   | answer                     |
//! |--------------|------------------------------------------|----------------------------|
//! | `eval`       | `points`, `t`, optional `approx`         | `point` (+ `ulps`, `error_ulps`, `nearest`) |
//! | `elevate`    | `points`, `by`                           | `points`                   |
//! | `split`      | `points`, `t`                            | `left`, `right`            |
//! | `derivative` | `points`, `order`, optional `t`          | `points`, or `vector` with `t` |
//! | `to_bezier`  | `power` (one array per coordinate, `t^0..t^n`) | `points`             |
//! | `rational_eval` | `points`, `weights`, `t`, optional `approx` | `point` (+ ulps)      |
//! | `conic`      | `points` (three 2D points), `weights` (three) | `type`, `implicit`    |
//! | `surface_eval` | `net` (rows `i = 0..m` of points `j = 0..n`), `u`, `v`, optional `approx` | `point` (+ ulps) |
//! | `fit_cubic`  | `x0`, `x1`, `xh` = x(1/2), `d0` = ẋ(0), `d1` = ẋ(1) | `k`, `l`, `points`, `delta2`, `warnings` |
//!
//! `conic`'s `type` is `"ellipse"`, `"parabola"`, `"hyperbola"` or `"degenerate (…)"`;
//! `implicit` is `[A, B, C, D, E, F]` of `A x² + B xy + C y² + D x + E y + F = 0` scaled to
//! coprime integers with the first non-zero one positive (`null` when the control points
//! are collinear: no unique conic carries the arc). `surface_eval` is
//! `Σ_i Σ_j b_ij B_i^m(u) B_j^n(v)` with `net[i][j] = b_ij`.
//!
//! # `ulps`
//!
//! For `eval` with `approx` (the caller's float result, one JSON number per coordinate),
//! per coordinate, with `x` the exact value and `a` the approximation:
//! - `nearest`: the `f64` nearest to `x` (ties to even), i.e. the correctly rounded result;
//! - `ulps`: how many `f64` steps `a` is from `nearest` — `0` exactly when `a` is correctly
//!   rounded (an integer; `+0` and `-0` count as the same);
//! - `error_ulps`: `|a − x| / ulp(x)` computed exactly, then rounded to a JSON number, where
//!   `ulp(x) = 2^(e−52)` for `2^e ≤ |x| < 2^(e+1)` and `e ≥ −1022`, and `ulp(x) = 2^−1074`
//!   for `|x| < 2^−1022` (subnormal range, exact 0 included). A correctly rounded `a` has
//!   `error_ulps ≤ 0.5`.
//!
//! # Limits
//!
//! No request can exhaust memory or time: lines are read at most [`MAX_LINE_BYTES`] at a
//! time (longer lines are answered with an error and skipped without being stored); curves
//! have at most [`MAX_POINTS`] points, degrees stay at most [`MAX_DEGREE`] (after elevation
//! too), points at most [`MAX_DIMENSION`] coordinates; numbers at most
//! [`crate::scalar::MAX_NUMBER_LEN`] characters and decimal exponents within
//! ±[`crate::scalar::MAX_DECIMAL_EXPONENT`]. Exact arithmetic grows numbers, so each request
//! is also given a work estimate ([`Op::work`], roughly Σ bits² over its rational
//! operations) which must stay below [`MAX_WORK`]; beyond it the request is refused before
//! any computation.

use crate::curve::BezierCurve;
use crate::error::{Error, Result};
use crate::fit::{fit_cubic, CubicFit, CubicFitData};
use crate::input::{
    count_from_json, describe, format_points, in_context, net_from_json, number_from_json, number_to_json,
    numbers_from_json, point_from_json, point_to_json, points_from_json, points_to_json,
};
use crate::point::Point;
use crate::rational::{classify_conic, implicit_conic, ConicKind, RationalBezierCurve};
use crate::scalar::Scalar;
use crate::surface::BezierSurface;
use num_bigint::{BigInt, BigUint};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::Signed;
use serde_json::{json, Map, Value};
use std::io::{self, BufRead, Write};

/// Longest request line, in bytes (1 MiB).
pub const MAX_LINE_BYTES: usize = 1 << 20;

/// Most control points in one curve (or one row or column of a net).
pub const MAX_POINTS: usize = 4097;

/// Highest degree of any input or result (after elevation too).
pub use crate::error::MAX_DEGREE;

/// Most coordinates per point.
pub const MAX_DIMENSION: usize = 64;

/// Largest work estimate ([`Op::work`]) a request may have.
///
/// The unit is one bit² of gcd-reduced rational arithmetic. Calibrated on unstructured
/// data (where nothing cancels), a release build does 1.5·10^11 to 3·10^11 units per
/// second on one core of a busy 2-core machine, so the slowest accepted request takes a
/// few seconds. Typical requests (degree ≤ 50, float or short decimal inputs) are far
/// below. For scale: a planar curve of degree 300 at `t = 1/3` is accepted (about 1 s),
/// degree 400 is not; at the float `t = 0.1`, degree 120 is accepted.
pub const MAX_WORK: f64 = 5.0e11;

/// One request, parsed and checked: exact inputs, sizes within the limits.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Op {
    /// `b(t)`; with `approx`, also the caller's rounding error.
    Eval {
        /// the curve
        curve: BezierCurve<BigRational>,
        /// the parameter
        t: BigRational,
        /// the caller's float result, one per coordinate
        approx: Option<Vec<f64>>,
    },
    /// Degree elevation by `by` steps.
    Elevate {
        /// the curve
        curve: BezierCurve<BigRational>,
        /// number of steps `r`
        by: usize,
    },
    /// Subdivision at `t`.
    Split {
        /// the curve
        curve: BezierCurve<BigRational>,
        /// the parameter
        t: BigRational,
    },
    /// The control points of the `order`-th derivative curve, or with `at` its value there.
    Derivative {
        /// the curve
        curve: BezierCurve<BigRational>,
        /// the order `k`
        order: usize,
        /// evaluate the derivative vector at this parameter instead
        at: Option<BigRational>,
    },
    /// The Bézier points of a polynomial curve given in the power basis on `[0, 1]`.
    ToBezier {
        /// `power[k][i]`: coordinate `k`'s coefficient of `t^i`
        power: Vec<Vec<BigRational>>,
    },
    /// `x(t)` of a rational Bézier curve; with `approx`, also the caller's rounding error.
    RationalEval {
        /// the curve
        curve: RationalBezierCurve<BigRational>,
        /// the parameter
        t: BigRational,
        /// the caller's float result, one per coordinate
        approx: Option<Vec<f64>>,
    },
    /// The type and implicit equation of the conic carrying a rational quadratic arc.
    Conic {
        /// the arc: three planar points and their weights
        curve: RationalBezierCurve<BigRational>,
    },
    /// `b(u, v)` of a tensor-product surface; with `approx`, also the caller's error.
    SurfaceEval {
        /// the surface
        surface: BezierSurface<BigRational>,
        /// the first parameter (the direction of the net's rows index `i`)
        u: BigRational,
        /// the second parameter
        v: BigRational,
        /// the caller's float result, one per coordinate
        approx: Option<Vec<f64>>,
    },
    /// Text 004's cubic fit.
    FitCubic {
        /// `x(0), x(1), x(1/2), ẋ(0), ẋ(1)`
        data: CubicFitData<BigRational>,
    },
}

/// How far a float approximation is from the exact value, for one coordinate.
#[derive(Clone, Debug, PartialEq)]
pub struct UlpError {
    /// The correctly rounded value (nearest `f64`, ties to even).
    pub nearest: f64,
    /// `f64` steps between the approximation and `nearest` (0 iff correctly rounded).
    pub ulps: u64,
    /// `|approx − exact| / ulp(exact)`, exactly computed, rounded to `f64`.
    pub error_ulps: f64,
}

/// The exact result of an [`Op`].
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Answer {
    /// A point of a curve, with the caller's error when it sent an approximation.
    Point {
        /// the exact point
        point: Point<BigRational>,
        /// per coordinate, when `approx` was given
        ulps: Option<Vec<UlpError>>,
    },
    /// Control points.
    Points(Vec<Point<BigRational>>),
    /// A vector (a derivative at a parameter).
    Vector(Point<BigRational>),
    /// The two halves of a subdivision.
    Split {
        /// `b(t0 t)`
        left: Vec<Point<BigRational>>,
        /// `b(t0 + (1 - t0) t)`
        right: Vec<Point<BigRational>>,
    },
    /// The conic carrying a rational quadratic arc.
    Conic {
        /// its affine type
        kind: ConicKind,
        /// `[A, B, C, D, E, F]` as coprime integers, first non-zero positive; `None` when
        /// the control points are collinear
        implicit: Option<[BigInt; 6]>,
    },
    /// Text 004's cubic fit.
    Fit(Box<CubicFit<BigRational>>),
}

impl Answer {
    /// The response fields (without `ok` and `id`).
    pub fn to_json(&self) -> Map<String, Value> {
        let mut m = Map::new();
        match self {
            Answer::Point { point, ulps } => {
                m.insert("point".into(), point_to_json(point));
                if let Some(u) = ulps {
                    m.insert("ulps".into(), u.iter().map(|e| json!(e.ulps)).collect());
                    m.insert("error_ulps".into(), u.iter().map(|e| json!(e.error_ulps)).collect());
                    m.insert("nearest".into(), u.iter().map(|e| json!(e.nearest)).collect());
                }
            }
            Answer::Points(p) => {
                m.insert("points".into(), points_to_json(p));
            }
            Answer::Vector(v) => {
                m.insert("vector".into(), point_to_json(v));
            }
            Answer::Split { left, right } => {
                m.insert("left".into(), points_to_json(left));
                m.insert("right".into(), points_to_json(right));
            }
            Answer::Conic { kind, implicit } => {
                m.insert("type".into(), json!(kind.as_str()));
                let implicit = implicit
                    .as_ref()
                    .map_or(Value::Null, |k| k.iter().map(|c| json!(c.to_string())).collect());
                m.insert("implicit".into(), implicit);
            }
            Answer::Fit(fit) => {
                m.insert("k".into(), number_to_json(&fit.k));
                m.insert("l".into(), number_to_json(&fit.l));
                m.insert("points".into(), points_to_json(fit.curve.points()));
                m.insert("delta2".into(), number_to_json(&fit.delta2));
                m.insert("warnings".into(), json!(fit.warnings));
            }
        }
        m
    }

    /// The answer as text for people, in exact fractions; lists of points are written so
    /// that [`crate::input::parse_points`] reads them back.
    pub fn to_text(&self) -> String {
        match self {
            Answer::Point { point, .. } => point.to_string(),
            Answer::Points(p) => format_points(p),
            Answer::Vector(v) => v.to_string(),
            Answer::Split { left, right } => {
                format!("left:  {}\nright: {}", format_points(left), format_points(right))
            }
            Answer::Conic { kind, implicit } => match implicit {
                Some(k) => format!("type: {}\nimplicit: {} = 0", kind.as_str(), conic_polynomial(k)),
                None => format!(
                    "type: {}\nimplicit: none (no unique conic through collinear points)",
                    kind.as_str()
                ),
            },
            Answer::Fit(fit) => {
                let mut text = format!(
                    "k = {}\nl = {}\npoints: {}\ndelta2 = {}",
                    fit.k,
                    fit.l,
                    format_points(fit.curve.points()),
                    fit.delta2
                );
                for w in &fit.warnings {
                    text.push_str(&format!("\nwarning: {w}"));
                }
                text
            }
        }
    }
}

/// `A x^2 + B xy + C y^2 + D x + E y + F` with zero terms left out and signs folded in,
/// e.g. `4x^2 + 3y^2 - 10y + 3`.
pub fn conic_polynomial(k: &[BigInt; 6]) -> String {
    const MONOMIALS: [&str; 6] = ["x^2", "xy", "y^2", "x", "y", ""];
    let mut out = String::new();
    for (c, mono) in k.iter().zip(MONOMIALS) {
        if num_traits::Zero::is_zero(c) {
            continue;
        }
        let negative = c.is_negative();
        let magnitude = c.abs();
        let digits = if num_traits::One::is_one(&magnitude) && !mono.is_empty() {
            String::new()
        } else {
            magnitude.to_string()
        };
        match (out.is_empty(), negative) {
            (true, true) => out.push('-'),
            (true, false) => {}
            (false, true) => out.push_str(" - "),
            (false, false) => out.push_str(" + "),
        }
        out.push_str(&digits);
        out.push_str(mono);
    }
    if out.is_empty() {
        out.push('0');
    }
    out
}

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
    INPUT_WEIGHT * b * b + shared * shared
}

/// Relative cost of numbers grown by a dyadic parameter (powers of two in the
/// denominators reduce by shifts, but the numerators still grow).
const DYADIC_WEIGHT: f64 = 3.0;

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
}

/// Work of [`BezierCurve::eval_fraction_free`]: integers over one common denominator (its
/// size bounded by the sum of the distinct denominators' bits, without computing it), each
/// of the `n(n+1)/2` steps per coordinate two products of a number grown by `r` times the
/// parameter's bits with the parameter's numerator or denominator, then one reduction.
fn fraction_free_work(curve: &BezierCurve<BigRational>, t: &BigRational) -> f64 {
    let mut denominators: Vec<&num_bigint::BigInt> = curve
        .points()
        .iter()
        .flat_map(|p| p.coords())
        .map(|c| c.denom())
        .collect();
    denominators.sort();
    denominators.dedup();
    let common = denominators.iter().map(|d| d.bits() as f64).sum::<f64>();
    let numerators = max_bits(curve.points().iter().flat_map(|p| p.coords()));
    // Numbers grow by the parameter's bits per level; a product with the parameter's
    // numerator or denominator costs at least a machine word.
    let (n, grow) = (curve.degree(), growth_bits(t));
    let start = numerators + common + 64.0;
    let word = grow.max(64.0);
    let steps: f64 = (1..=n)
        .map(|r| (n - r + 1) as f64 * 2.0 * (start + r as f64 * grow) * word)
        .sum();
    let last = start + n as f64 * grow;
    // Calibrated like the rest (MAX_WORK ≈ a few seconds): these word-sized products run
    // about eight times faster per unit than the gcd-bound operations the units are set by
    // (degree 3000 at t = 1/3: 0.9 s; degree 500 with unrelated 50-bit denominators: 1.5 s).
    curve.dim() as f64 * (steps / 8.0 + INPUT_WEIGHT * last * last)
}

impl Op {
    /// A rough count of the work this request needs (Σ bits² over its rational operations,
    /// see [`MAX_WORK`]), computed before anything else so that absurd requests are refused
    /// at once.
    pub fn work(&self) -> f64 {
        match self {
            Op::Eval { curve, t, .. } => fraction_free_work(curve, t),
            Op::Split { curve, t } => triangle_work(
                curve.degree(),
                curve.dim(),
                curve_bits(curve),
                t,
                curve_den_growth(curve),
            ),
            Op::Elevate { curve, by } => {
                let (n, total) = (curve.degree(), curve.degree() + by);
                // every output point combines up to n + 1 inputs with weights C(n,j)C(r,i−j)/C(n+r,i)
                // of about 2·total bits; each term is a multiplication and an addition
                let terms = (total + 1) as f64 * (n.min(*by) + 1) as f64 * curve.dim() as f64;
                let mixed = (n.min(*by) + 1) as f64 * curve_den_growth(curve);
                3.0 * terms * op_cost(curve_bits(curve), 2.0 * total as f64, mixed) + (total as f64).powi(3)
            }
            Op::Derivative { curve, order, at } => {
                let (n, k) = (curve.degree(), (*order).min(curve.degree()));
                // Δ^k grows by k bits, the factor n!/(n−k)! has about k·log2(n) bits
                let shared = k as f64 * (1.0 + (n.max(2) as f64).log2());
                let mixed = (k + 1) as f64 * curve_den_growth(curve);
                let diffs =
                    (k.max(1) * (n + 1)) as f64 * curve.dim() as f64 * op_cost(curve_bits(curve), shared, mixed);
                let b = curve_bits(curve) + shared + mixed;
                let level = curve_den_growth(curve);
                diffs
                    + at.as_ref()
                        .map_or(0.0, |t| triangle_work(n - k, curve.dim(), b, t, level))
            }
            Op::RationalEval { curve, t, .. } => {
                let numbers = curve.points().iter().flat_map(|p| p.coords()).chain(curve.weights());
                let b = 2.0 * max_bits(numbers.clone());
                triangle_work(curve.degree(), curve.dim() + 1, b, t, den_growth(numbers))
                    + curve.dim() as f64 * op_cost(b + curve.degree() as f64 * growth_bits(t), 0.0, 0.0)
            }
            Op::Conic { curve } => {
                let numbers = curve.points().iter().flat_map(|p| p.coords()).chain(curve.weights());
                // a few hundred products of up to about eight input numbers
                300.0 * op_cost(8.0 * max_bits(numbers), 0.0, 0.0)
            }
            Op::SurfaceEval { surface, u, v, .. } => {
                let (m, n) = surface.degrees();
                let numbers = || surface.net().iter().flatten().flat_map(|p| p.coords());
                let (b, den) = (max_bits(numbers()), den_growth(numbers()));
                // u first: n + 1 columns reduced at u, then one curve in v of grown numbers
                let columns = (n + 1) as f64 * triangle_work(m, surface.dim(), b, u, den);
                let grown = b + m as f64 * (growth_bits(u) + den);
                columns + triangle_work(n, surface.dim(), grown, v, den)
            }
            Op::FitCubic { data } => {
                let d = &data;
                let numbers = [&d.x0, &d.x1, &d.xh, &d.d0, &d.d1].into_iter().flat_map(|p| p.coords());
                // Gram matrix, right-hand side, a 2×2 solve and δ²: a few dozen operations per
                // coordinate on products of up to about ten input numbers
                (60 * d.x0.dim() + 100) as f64 * op_cost(10.0 * max_bits(numbers), 0.0, 0.0)
            }
            Op::ToBezier { power } => {
                let n = power.first().map_or(0, |c| c.len().saturating_sub(1));
                let b = max_bits(power.iter().flatten());
                let mixed = (n + 1) as f64 * den_growth(power.iter().flatten());
                3.0 * (n + 1) as f64 * (n + 1) as f64 * power.len() as f64 * op_cost(b, 2.0 * n as f64, mixed)
            }
        }
    }

    /// Checks the size limits and the work estimate.
    pub fn check_limits(&self) -> Result<()> {
        let degree = |c: &BezierCurve<BigRational>| -> Result<()> {
            if c.points().len() > MAX_POINTS {
                return Err(too_large("number of points", c.points().len(), MAX_POINTS));
            }
            if c.dim() > MAX_DIMENSION {
                return Err(too_large("dimension", c.dim(), MAX_DIMENSION));
            }
            Ok(())
        };
        match self {
            Op::Eval { curve, .. } | Op::Split { curve, .. } | Op::Derivative { curve, .. } => degree(curve)?,
            Op::Elevate { curve, by } => {
                degree(curve)?;
                let total = curve.degree() as u128 + *by as u128;
                if total > MAX_DEGREE as u128 {
                    return Err(Error::TooLarge {
                        what: "degree after elevation",
                        value: total.to_string(),
                        limit: MAX_DEGREE.to_string(),
                    });
                }
            }
            Op::RationalEval { curve, .. } | Op::Conic { curve } => {
                if curve.points().len() > MAX_POINTS {
                    return Err(too_large("number of points", curve.points().len(), MAX_POINTS));
                }
                if curve.dim() > MAX_DIMENSION {
                    return Err(too_large("dimension", curve.dim(), MAX_DIMENSION));
                }
            }
            Op::SurfaceEval { surface, .. } => {
                let (m, n) = surface.degrees();
                if m.max(n) >= MAX_POINTS {
                    return Err(too_large(
                        "number of points in a net row or column",
                        m.max(n) + 1,
                        MAX_POINTS,
                    ));
                }
                if surface.dim() > MAX_DIMENSION {
                    return Err(too_large("dimension", surface.dim(), MAX_DIMENSION));
                }
            }
            Op::FitCubic { data } => {
                if data.x0.dim() > MAX_DIMENSION {
                    return Err(too_large("dimension", data.x0.dim(), MAX_DIMENSION));
                }
            }
            Op::ToBezier { power } => {
                if power.is_empty() {
                    return Err(Error::Empty("a power-basis curve (no coordinates)"));
                }
                if power.len() > MAX_DIMENSION {
                    return Err(too_large("dimension", power.len(), MAX_DIMENSION));
                }
                let len = power[0].len();
                if len == 0 {
                    return Err(Error::Empty("a power-basis curve (no coefficients)"));
                }
                if len > MAX_POINTS {
                    return Err(too_large("number of coefficients", len, MAX_POINTS));
                }
                if let Some((k, c)) = power.iter().enumerate().find(|(_, c)| c.len() != len) {
                    return Err(Error::Parse(format!(
                        "ragged power coefficients: coordinate 0 has {len} coefficients but coordinate {k} has {}",
                        c.len()
                    )));
                }
            }
        }
        let work = self.work();
        // NaN cannot arise (finite sums of squares), but would be refused too
        if work.is_nan() || work > MAX_WORK {
            return Err(Error::TooLarge {
                what: "request (estimated exact work)",
                value: format!("{work:.2e}"),
                limit: format!("{MAX_WORK:.0e}; use fewer points, a lower degree or shorter numbers"),
            });
        }
        Ok(())
    }

    /// Computes the exact answer (after [`Op::check_limits`]).
    pub fn run(&self) -> Result<Answer> {
        self.check_limits()?;
        Ok(match self {
            Op::Eval { curve, t, approx } => {
                // Same value as `curve.eval(t)` (a property test pins it), without a gcd per step;
                // the work estimate above stays that of the generic algorithm, conservatively.
                let point = curve.eval_fraction_free(t);
                let ulps = ulps_of(approx.as_deref(), &point)?;
                Answer::Point { point, ulps }
            }
            Op::Elevate { curve, by } => Answer::Points(curve.elevate_by(*by)?.into_points()),
            Op::Split { curve, t } => {
                let (l, r) = curve.split_at(t);
                Answer::Split {
                    left: l.into_points(),
                    right: r.into_points(),
                }
            }
            Op::Derivative { curve, order, at: None } => Answer::Points(curve.derivative(*order)?.into_points()),
            Op::Derivative {
                curve,
                order,
                at: Some(t),
            } => Answer::Vector(curve.derivative_at(*order, t)?),
            Op::RationalEval { curve, t, approx } => {
                let point = curve.eval(t)?;
                let ulps = ulps_of(approx.as_deref(), &point)?;
                Answer::Point { point, ulps }
            }
            Op::Conic { curve } => {
                if curve.points().len() != 3 {
                    return Err(Error::WrongCount {
                        what: "a conic arc",
                        needed: 3,
                        got: curve.points().len(),
                    });
                }
                if curve.dim() != 2 {
                    return Err(Error::DimensionMismatch {
                        expected: 2,
                        found: curve.dim(),
                        context: "the control points of a conic arc (planar)".into(),
                    });
                }
                let kind = classify_conic(curve)?;
                let implicit = if kind == ConicKind::DegenerateCollinear {
                    None
                } else {
                    Some(implicit_conic(curve)?.to_primitive_integers())
                };
                Answer::Conic { kind, implicit }
            }
            Op::SurfaceEval { surface, u, v, approx } => {
                let point = surface.eval(u, v);
                let ulps = ulps_of(approx.as_deref(), &point)?;
                Answer::Point { point, ulps }
            }
            Op::FitCubic { data } => Answer::Fit(Box::new(fit_cubic(data)?)),
            Op::ToBezier { power } => {
                let coeffs = (0..power[0].len())
                    .map(|i| Point::new(power.iter().map(|c| c[i].clone()).collect()))
                    .collect::<Result<Vec<_>>>()?;
                Answer::Points(BezierCurve::from_power(&coeffs)?.into_points())
            }
        })
    }

    /// Parses a request object (its `op` and fields; `id` is allowed and ignored).
    pub fn from_json(request: &Value) -> Result<Op> {
        let obj = request
            .as_object()
            .ok_or_else(|| Error::Parse(format!("a request must be a JSON object, got {}", describe(request))))?;
        let op = match obj.get("op") {
            Some(Value::String(s)) => s.as_str(),
            Some(other) => {
                return Err(Error::Parse(format!(
                    "field 'op' must be a string, got {}",
                    describe(other)
                )))
            }
            None => return Err(Error::Parse(format!("missing field 'op' (one of {})", OPS.join(", ")))),
        };
        let fields: &[&str] = match op {
            "eval" => &["points", "t", "approx"],
            "elevate" => &["points", "by"],
            "split" => &["points", "t"],
            "derivative" => &["points", "order", "t"],
            "to_bezier" => &["power"],
            "rational_eval" => &["points", "weights", "t", "approx"],
            "conic" => &["points", "weights"],
            "surface_eval" => &["net", "u", "v", "approx"],
            "fit_cubic" => &["x0", "x1", "xh", "d0", "d1"],
            other => {
                return Err(Error::Parse(format!(
                    "unknown op {:?} (known ops: {})",
                    truncate(other),
                    OPS.join(", ")
                )))
            }
        };
        if let Some(k) = obj
            .keys()
            .find(|k| *k != "op" && *k != "id" && !fields.contains(&k.as_str()))
        {
            return Err(Error::Parse(format!(
                "unknown field {:?} for op '{op}' (its fields: {})",
                truncate(k),
                fields.join(", ")
            )));
        }
        let req = Fields { obj, op };
        let op = match op {
            "eval" => Op::Eval {
                curve: req.curve("points")?,
                t: req.number("t")?,
                approx: req.approx()?,
            },
            "elevate" => Op::Elevate {
                curve: req.curve("points")?,
                by: req.in_field("by", count_from_json(req.get("by")?, "by"))?,
            },
            "split" => Op::Split {
                curve: req.curve("points")?,
                t: req.number("t")?,
            },
            "derivative" => Op::Derivative {
                curve: req.curve("points")?,
                order: req.in_field("order", count_from_json(req.get("order")?, "order"))?,
                at: match obj.get("t") {
                    None => None,
                    Some(v) => Some(req.in_field("t", number_from_json(v))?),
                },
            },
            "to_bezier" => {
                let v = req.get("power")?;
                let coords = v.as_array().ok_or_else(|| {
                    Error::Parse(format!(
                        "field 'power': expected an array with one array of coefficients per coordinate, got {}",
                        describe(v)
                    ))
                })?;
                if coords.len() > MAX_DIMENSION {
                    return Err(too_large("dimension", coords.len(), MAX_DIMENSION));
                }
                Op::ToBezier {
                    power: coords
                        .iter()
                        .enumerate()
                        .map(|(k, c)| {
                            numbers_from_json(c, MAX_POINTS)
                                .map_err(|e| in_context(&format!("field 'power': coordinate {k}"), e))
                        })
                        .collect::<Result<_>>()?,
                }
            }
            "rational_eval" => Op::RationalEval {
                curve: req.rational_curve()?,
                t: req.number("t")?,
                approx: req.approx()?,
            },
            "conic" => Op::Conic {
                curve: req.rational_curve()?,
            },
            "surface_eval" => {
                let net = req.in_field("net", net_from_json(req.get("net")?, MAX_POINTS))?;
                if net[0][0].dim() > MAX_DIMENSION {
                    return Err(too_large("dimension", net[0][0].dim(), MAX_DIMENSION));
                }
                Op::SurfaceEval {
                    surface: req.in_field("net", BezierSurface::new(net))?,
                    u: req.number("u")?,
                    v: req.number("v")?,
                    approx: req.approx()?,
                }
            }
            "fit_cubic" => {
                let point = |name: &str| req.in_field(name, point_from_json(req.get(name)?));
                Op::FitCubic {
                    data: CubicFitData::new(point("x0")?, point("x1")?, point("xh")?, point("d0")?, point("d1")?)?,
                }
            }
            _ => unreachable!("op names were matched above"),
        };
        op.check_limits()?;
        Ok(op)
    }
}

/// One weight per control point, said in those words.
pub fn check_weight_count(points: usize, weights: usize) -> Result<()> {
    if points != weights {
        return Err(Error::Parse(format!(
            "{weights} weights for {points} control points (give one weight per control point)"
        )));
    }
    Ok(())
}

/// Per coordinate errors of the caller's approximation, when it sent one.
fn ulps_of(approx: Option<&[f64]>, point: &Point<BigRational>) -> Result<Option<Vec<UlpError>>> {
    let Some(a) = approx else { return Ok(None) };
    if a.len() != point.dim() {
        return Err(Error::DimensionMismatch {
            expected: point.dim(),
            found: a.len(),
            context: "field 'approx'".into(),
        });
    }
    Ok(Some(
        a.iter()
            .zip(point.coords())
            .map(|(a, x)| ulp_error(*a, x))
            .collect::<Result<_>>()?,
    ))
}

/// The names of the ops, for error messages.
pub const OPS: &[&str] = &[
    "eval",
    "elevate",
    "split",
    "derivative",
    "to_bezier",
    "rational_eval",
    "conic",
    "surface_eval",
    "fit_cubic",
];

fn too_large(what: &'static str, value: usize, limit: usize) -> Error {
    Error::TooLarge {
        what,
        value: value.to_string(),
        limit: limit.to_string(),
    }
}

fn truncate(s: &str) -> String {
    if s.chars().count() > 40 {
        format!("{}…", s.chars().take(40).collect::<String>())
    } else {
        s.to_string()
    }
}

struct Fields<'a> {
    obj: &'a Map<String, Value>,
    op: &'a str,
}

impl Fields<'_> {
    fn get(&self, name: &str) -> Result<&Value> {
        self.obj
            .get(name)
            .ok_or_else(|| Error::Parse(format!("op '{}' needs the field '{name}'", self.op)))
    }

    fn in_field<T>(&self, name: &str, r: Result<T>) -> Result<T> {
        r.map_err(|e| in_context(&format!("field '{name}'"), e))
    }

    fn number(&self, name: &str) -> Result<BigRational> {
        self.in_field(name, number_from_json(self.get(name)?))
    }

    fn approx(&self) -> Result<Option<Vec<f64>>> {
        match self.obj.get("approx") {
            None => Ok(None),
            Some(v) => Ok(Some(self.in_field("approx", floats_from_json(v))?)),
        }
    }

    fn rational_curve(&self) -> Result<RationalBezierCurve<BigRational>> {
        let points = self.in_field("points", points_from_json(self.get("points")?, MAX_POINTS))?;
        if points[0].dim() > MAX_DIMENSION {
            return Err(too_large("dimension", points[0].dim(), MAX_DIMENSION));
        }
        let weights = self.in_field("weights", numbers_from_json(self.get("weights")?, MAX_POINTS))?;
        check_weight_count(points.len(), weights.len())?;
        RationalBezierCurve::new(points, weights)
    }

    fn curve(&self, name: &str) -> Result<BezierCurve<BigRational>> {
        let points = self.in_field(name, points_from_json(self.get(name)?, MAX_POINTS))?;
        if points[0].dim() > MAX_DIMENSION {
            return Err(too_large("dimension", points[0].dim(), MAX_DIMENSION));
        }
        self.in_field(name, BezierCurve::new(points))
    }
}

fn floats_from_json(v: &Value) -> Result<Vec<f64>> {
    let items = v.as_array().ok_or_else(|| {
        Error::Parse(format!(
            "expected an array of JSON numbers (one per coordinate), got {}",
            describe(v)
        ))
    })?;
    if items.len() > MAX_DIMENSION {
        return Err(too_large("dimension", items.len(), MAX_DIMENSION));
    }
    items
        .iter()
        .enumerate()
        .map(|(k, x)| {
            x.as_f64().ok_or_else(|| {
                Error::Parse(format!(
                    "coordinate {k}: the approximation must be a JSON number (a float), got {}",
                    describe(x)
                ))
            })
        })
        .collect()
}

/// `floor(log2 a)` for `a > 0`, exactly.
fn floor_log2(a: &BigRational) -> i64 {
    let (n, d) = (a.numer().magnitude(), a.denom().magnitude());
    let e0 = n.bits() as i64 - d.bits() as i64;
    // 2^(bits−1) ≤ n < 2^bits, so a lies in (2^(e0−1), 2^(e0+1)): floor is e0 or e0 − 1.
    let at_least = if e0 >= 0 {
        *n >= d << (e0 as u64)
    } else {
        n << (e0.unsigned_abs()) >= *d
    };
    if at_least {
        e0
    } else {
        e0 - 1
    }
}

/// `2^q` as an `f64`, for `−1074 ≤ q ≤ 1023`.
fn pow2(q: i64) -> f64 {
    debug_assert!((-1074..=1023).contains(&q));
    if q >= -1022 {
        f64::from_bits(((q + 1023) as u64) << 52)
    } else {
        f64::from_bits(1u64 << (q + 1074))
    }
}

/// The exponent of `ulp(x)`: `max(e, −1022) − 52` where `2^e ≤ |x| < 2^(e+1)`, and
/// `−1074` for `x = 0`.
fn ulp_exponent(x: &BigRational) -> i64 {
    if num_traits::Zero::is_zero(x) {
        return -1074;
    }
    floor_log2(&Signed::abs(x)).max(-1022) - 52
}

/// `ulp(x)` as defined in the module documentation, exactly.
///
/// ```
/// use casteljau::{oracle::ulp, BigRational, Scalar};
/// assert_eq!(ulp(&BigRational::from_i64(1)), BigRational::from_f64(f64::EPSILON).unwrap());
/// assert_eq!(ulp(&BigRational::from_i64(0)), BigRational::from_f64(f64::from_bits(1)).unwrap());
/// ```
pub fn ulp(x: &BigRational) -> BigRational {
    pow2_exact(ulp_exponent(x))
}

fn pow2_exact(q: i64) -> BigRational {
    let one = BigInt::from(1);
    if q >= 0 {
        BigRational::from_integer(one << (q as u64))
    } else {
        BigRational::new(one.clone(), one << q.unsigned_abs())
    }
}

/// The `f64` nearest to `x`, ties to even (infinite when `|x|` rounds past `f64::MAX`).
///
/// ```
/// use casteljau::{oracle::nearest_f64, scalar::parse_exact};
/// assert_eq!(nearest_f64(&parse_exact("0.1").unwrap()), 0.1);
/// assert_eq!(nearest_f64(&parse_exact("1/3").unwrap()), 1.0 / 3.0);
/// ```
pub fn nearest_f64(x: &BigRational) -> f64 {
    if num_traits::Zero::is_zero(x) {
        return 0.0;
    }
    let negative = x.is_negative();
    let a = Signed::abs(x);
    if floor_log2(&a) > 1023 {
        return if negative { f64::NEG_INFINITY } else { f64::INFINITY };
    }
    let q = ulp_exponent(&a);
    // m = a / 2^q has at most 53 bits before the point; round it to an integer.
    let (n, d): (BigUint, BigUint) = if q >= 0 {
        (a.numer().magnitude().clone(), a.denom().magnitude() << (q as u64))
    } else {
        (a.numer().magnitude() << q.unsigned_abs(), a.denom().magnitude().clone())
    };
    let (mut m, rem) = n.div_rem(&d);
    let twice = rem << 1u8;
    if twice > d || (twice == d && m.is_odd()) {
        m += 1u8;
    }
    // Rounding up may carry into 2^1024, past the largest finite f64.
    if m.bits() as i64 + q > 1024 {
        return if negative { f64::NEG_INFINITY } else { f64::INFINITY };
    }
    // m ≤ 2^53 converts exactly, and m · 2^q is representable, so the product is exact.
    let m = num_traits::ToPrimitive::to_f64(&m).expect("m ≤ 2^53 fits in f64");
    let value = m * pow2(q);
    if negative {
        -value
    } else {
        value
    }
}

/// How many `f64` steps lie between `a` and `b` (`+0` and `−0` are the same point).
pub fn ulp_distance(a: f64, b: f64) -> u64 {
    fn key(x: f64) -> i128 {
        let bits = x.to_bits();
        let magnitude = (bits & !(1u64 << 63)) as i128;
        if bits >> 63 == 1 {
            -magnitude
        } else {
            magnitude
        }
    }
    (key(a) - key(b)).unsigned_abs() as u64
}

/// The error of the approximation `approx` of the exact `exact`.
pub fn ulp_error(approx: f64, exact: &BigRational) -> Result<UlpError> {
    let a = <BigRational as Scalar>::from_f64(approx)?;
    let nearest = nearest_f64(exact);
    if !nearest.is_finite() {
        // Round-to-nearest overflows to ±inf: there is no finite f64 to count steps from.
        return Err(Error::Domain(
            "an exact coordinate is beyond the largest f64 (about 1.8e308): it has no finite nearest f64, so no error in ulps"
                .into(),
        ));
    }
    let err = Signed::abs(&(&a - exact));
    let error_ulps = (&err * &pow2_exact(-ulp_exponent(exact))).to_f64();
    Ok(UlpError {
        nearest,
        ulps: ulp_distance(approx, nearest),
        error_ulps,
    })
}

/// Answers one request line with one response line (no newline).
///
/// Never panics on any input: a panic inside a handler would be a bug, and is caught and
/// answered with `"internal error"` so that the loop goes on.
pub fn handle_line(line: &str) -> String {
    let outcome = std::panic::catch_unwind(|| respond(line));
    match outcome {
        Ok(v) => v.to_string(),
        Err(_) => {
            json!({"ok": false, "error": "internal error (a bug in casteljau: please report the request)"}).to_string()
        }
    }
}

fn respond(line: &str) -> Value {
    let request: Value = match serde_json::from_str(line) {
        Ok(v) => v,
        Err(e) => {
            let msg = if line.trim().is_empty() {
                "empty line: expected one JSON request object per line".to_string()
            } else {
                format!("not valid JSON: {e}")
            };
            return json!({"ok": false, "error": msg});
        }
    };
    let id = request.get("id").cloned();
    let mut out = match Op::from_json(&request).and_then(|op| op.run()) {
        Ok(answer) => {
            let mut m = answer.to_json();
            m.insert("ok".into(), Value::Bool(true));
            m
        }
        Err(e) => {
            let mut m = Map::new();
            m.insert("ok".into(), Value::Bool(false));
            m.insert("error".into(), Value::String(e.to_string()));
            m
        }
    };
    if let Some(id) = id {
        out.insert("id".into(), id);
    }
    Value::Object(out)
}

/// One line read by [`read_line_bounded`].
#[derive(Debug, PartialEq, Eq)]
pub enum Line {
    /// A complete line (without its `\n`), at most the limit long.
    Text(Vec<u8>),
    /// A line longer than the limit; its bytes were skipped, not stored.
    TooLong,
    /// End of input.
    Eof,
}

/// Reads one line of at most `limit` bytes. A longer line is skipped to its end in
/// chunks, so it never takes more memory than the limit. The final line needs no `\n`.
pub fn read_line_bounded<R: BufRead>(reader: &mut R, limit: usize) -> io::Result<Line> {
    let mut line = Vec::new();
    let mut too_long = false;
    let mut seen_any = false;
    loop {
        let buf = match reader.fill_buf() {
            Ok(b) => b,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if buf.is_empty() {
            return Ok(match (seen_any, too_long) {
                (false, _) => Line::Eof,
                (true, true) => Line::TooLong,
                (true, false) => Line::Text(line),
            });
        }
        seen_any = true;
        let (chunk, found) = match buf.iter().position(|&b| b == b'\n') {
            Some(i) => (&buf[..i], Some(i)),
            None => (buf, None),
        };
        if !too_long {
            if line.len() + chunk.len() > limit {
                too_long = true;
                line = Vec::new();
            } else {
                line.extend_from_slice(chunk);
            }
        }
        let used = found.map_or(buf.len(), |i| i + 1);
        reader.consume(used);
        if found.is_some() {
            return Ok(if too_long { Line::TooLong } else { Line::Text(line) });
        }
    }
}

/// The JSON-lines loop: one response line per request line, flushed after each, until end
/// of input. Only I/O errors (such as a closed output) end it early.
pub fn serve<R: BufRead, W: Write>(mut reader: R, mut writer: W) -> io::Result<()> {
    loop {
        let response = match read_line_bounded(&mut reader, MAX_LINE_BYTES)? {
            Line::Eof => return Ok(()),
            Line::TooLong => json!({
                "ok": false,
                "error": format!("request line longer than {MAX_LINE_BYTES} bytes; it was skipped")
            })
            .to_string(),
            Line::Text(bytes) => match String::from_utf8(bytes) {
                Ok(s) => handle_line(s.trim_end_matches('\r')),
                Err(_) => json!({"ok": false, "error": "request line is not valid UTF-8"}).to_string(),
            },
        };
        writer.write_all(response.as_bytes())?;
        writer.write_all(b"\n")?;
        writer.flush()?;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::number_to_json;
    use crate::scalar::parse_exact;
    use proptest::prelude::*;

    fn ask(line: &str) -> Value {
        serde_json::from_str(&handle_line(line)).unwrap()
    }

    fn q(s: &str) -> BigRational {
        parse_exact(s).unwrap()
    }

    #[test]
    fn ulps_of_a_value_beyond_the_f64_range_is_a_clear_error() {
        let r = ask(r#"{"id":3,"op":"eval","points":[["1e400"]],"t":0,"approx":[1e308]}"#);
        assert_eq!(r["ok"], json!(false), "{r}");
        assert!(r["error"].as_str().unwrap().contains("beyond the largest f64"), "{r}");
        // Just inside the range it is measured.
        let r = ask(r#"{"op":"eval","points":[["1e308"]],"t":0,"approx":[1e308]}"#);
        assert_eq!(r["ulps"], json!([0]), "{r}");
    }

    #[test]
    fn eval_is_exact_and_echoes_the_id() {
        let r = ask(r#"{"id":"a","op":"eval","points":[[0,0],["4/3","-4/3"],["4/3","4/3"],[0,0]],"t":"1/2"}"#);
        assert_eq!(r, json!({"id": "a", "ok": true, "point": ["1", "0"]}));
        let r = ask(r#"{"id":[1,{"x":2}],"op":"eval","points":[[1]],"t":5}"#);
        assert_eq!(r, json!({"id": [1, {"x": 2}], "ok": true, "point": ["1"]}));
    }

    #[test]
    fn every_op_answers() {
        let r = ask(r#"{"op":"elevate","points":[[0,0],[1,2],[2,0]],"by":1}"#);
        assert_eq!(
            r["points"],
            json!([["0", "0"], ["2/3", "4/3"], ["4/3", "4/3"], ["2", "0"]])
        );
        let r = ask(r#"{"op":"split","points":[[0],[1],[3]],"t":"1/2"}"#);
        assert_eq!(r["left"], json!([["0"], ["1/2"], ["5/4"]]));
        assert_eq!(r["right"], json!([["5/4"], ["2"], ["3"]]));
        let r = ask(r#"{"op":"derivative","points":[[0],[1],[3]],"order":1}"#);
        assert_eq!(r["points"], json!([["2"], ["4"]]));
        let r = ask(r#"{"op":"derivative","points":[[0],[1],[3]],"order":2}"#);
        assert_eq!(r["points"], json!([["2"]]));
        let r = ask(r#"{"op":"derivative","points":[[0],[1],[3]],"order":1,"t":"1/2"}"#);
        assert_eq!(r, json!({"ok": true, "vector": ["3"]}));
        let r = ask(r#"{"op":"derivative","points":[[0],[1],[3]],"order":5,"t":"1/2"}"#);
        assert_eq!(r, json!({"ok": true, "vector": ["0"]}));
        // 4t - 4t² as a quadratic: Bézier points 0, 2, 0
        let r = ask(r#"{"op":"to_bezier","power":[[0,4,-4],[1,0,0]]}"#);
        assert_eq!(r["points"], json!([["0", "1"], ["2", "1"], ["0", "1"]]));
    }

    #[test]
    fn rational_conic_surface_fit_answer() {
        // text 001, Example 3: the arc (-1,1), (0,-1), (1,1) with weights 1, 1/2, 1
        let r = ask(r#"{"op":"conic","points":[[-1,1],[0,-1],[1,1]],"weights":[1,"1/2",1]}"#);
        assert_eq!(
            r,
            json!({"ok": true, "type": "ellipse", "implicit": ["4", "0", "3", "0", "-10", "3"]})
        );
        let r = ask(r#"{"op":"conic","points":[[-1,1],[0,-1],[1,1]],"weights":[1,2,1]}"#);
        assert_eq!(r["type"], json!("hyperbola"));
        let r = ask(r#"{"op":"conic","points":[[0,0],[1,1],[2,2]],"weights":[1,1,1]}"#);
        assert_eq!(r["implicit"], Value::Null);
        assert!(r["type"].as_str().unwrap().starts_with("degenerate"));
        // the quarter circle: x(1/2) = (3/5, 4/5), and 0.6, 0.8 are its correctly rounded floats
        let r = ask(
            r#"{"op":"rational_eval","points":[[1,0],[1,1],[0,1]],"weights":[1,1,2],"t":"1/2","approx":[0.6,0.8]}"#,
        );
        assert_eq!(r["point"], json!(["3/5", "4/5"]));
        assert_eq!(r["ulps"], json!([0, 0]));
        let r = ask(r#"{"op":"rational_eval","points":[[1,0],[1,1],[0,1]],"weights":[1,-1,1],"t":"1/2"}"#);
        assert!(r["error"].as_str().unwrap().contains("vanishes"), "{r}");
        // text 003: the bilinear patch z = xy
        let r = ask(r#"{"op":"surface_eval","net":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]],"u":"1/3","v":"3/4"}"#);
        assert_eq!(r["point"], json!(["1/3", "3/4", "1/4"]));
        // text 004: a cubic is its own fit, k = l = 1/3, δ² = 0
        let r = ask(r#"{"op":"fit_cubic","x0":[0,0,0],"x1":[4,0,5],"xh":[2,"3/2",1],"d0":[3,6,0],"d1":[3,-6,12]}"#);
        assert_eq!(
            r,
            json!({"ok": true, "k": "1/3", "l": "1/3", "delta2": "0", "warnings": [],
                   "points": [["0", "0", "0"], ["1", "2", "0"], ["3", "2", "1"], ["4", "0", "5"]]})
        );
        let r = ask(r#"{"op":"fit_cubic","x0":[0,0],"x1":[1,0],"xh":[0,1],"d0":[1,0],"d1":[2,0]}"#);
        assert!(r["error"].as_str().unwrap().contains("parallel"), "{r}");
        for (line, needle) in [
            (
                r#"{"op":"conic","points":[[-1,1],[0,-1]],"weights":[1,1]}"#,
                "needs 3 points",
            ),
            (
                r#"{"op":"conic","points":[[-1,1,0],[0,-1,0],[1,1,0]],"weights":[1,1,1]}"#,
                "planar",
            ),
            (
                r#"{"op":"rational_eval","points":[[1,0],[1,1]],"weights":[1],"t":0}"#,
                "1 weights for 2",
            ),
            (
                r#"{"op":"rational_eval","points":[[1,0],[1,1]],"weights":[0,0],"t":0}"#,
                "all weights",
            ),
            (
                r#"{"op":"surface_eval","net":[[[0,0]],[[0,1],[1,1]]],"u":0,"v":0}"#,
                "ragged",
            ),
            (r#"{"op":"surface_eval","net":[],"u":0,"v":0}"#, "empty"),
            (
                r#"{"op":"fit_cubic","x0":[0,0],"x1":[1,0],"xh":[0,1],"d0":[1,0]}"#,
                "'d1'",
            ),
            (
                r#"{"op":"fit_cubic","x0":[0,0],"x1":[1,0,0],"xh":[0,1],"d0":[1,0],"d1":[0,1]}"#,
                "dimension",
            ),
        ] {
            let r = ask(line);
            assert_eq!(r["ok"], json!(false), "{line}");
            assert!(r["error"].as_str().unwrap().contains(needle), "{line}: {r}");
        }
    }

    #[test]
    fn conic_equations_read_like_the_text() {
        let k = |c: [i64; 6]| conic_polynomial(&c.map(BigInt::from));
        assert_eq!(k([4, 0, 3, 0, -10, 3]), "4x^2 + 3y^2 - 10y + 3");
        assert_eq!(k([-1, 1, 0, 0, 0, 0]), "-x^2 + xy");
        assert_eq!(k([0, 0, 0, 0, 0, -1]), "-1");
        assert_eq!(k([0, 0, 0, 0, 0, 0]), "0");
    }

    #[test]
    fn bad_requests_get_clear_errors() {
        let cases: &[(&str, &str)] = &[
            ("not json", "not valid JSON"),
            ("", "empty line"),
            ("[1,2]", "must be a JSON object"),
            (r#"{"points":[[0]]}"#, "missing field 'op'"),
            (r#"{"op":"frobnicate"}"#, "unknown op"),
            (r#"{"op":7}"#, "'op' must be a string"),
            (r#"{"op":"eval","points":[[0]]}"#, "needs the field 't'"),
            (
                r#"{"op":"eval","points":[[0]],"t":0,"aprox":[0.5]}"#,
                "unknown field \"aprox\"",
            ),
            (r#"{"op":"eval","points":[],"t":0}"#, "empty"),
            (r#"{"op":"eval","points":[[0,0],[1]],"t":0}"#, "dimension mismatch"),
            (r#"{"op":"eval","points":[[0]],"t":"1/0"}"#, "zero denominator"),
            (r#"{"op":"eval","points":[[0]],"t":"abc"}"#, "not a number"),
            (r#"{"op":"eval","points":[[0]],"t":"NaN"}"#, "not a number"),
            (r#"{"op":"eval","points":[[0]],"t":"1e999999999"}"#, "too large"),
            (r#"{"op":"eval","points":[[0]],"t":null}"#, "field 't'"),
            (r#"{"op":"eval","points":"0,0","t":0}"#, "field 'points'"),
            (
                r#"{"op":"eval","points":[[0]],"t":0,"approx":[1,2]}"#,
                "dimension mismatch",
            ),
            (
                r#"{"op":"eval","points":[[0]],"t":0,"approx":["0.5"]}"#,
                "must be a JSON number",
            ),
            (
                r#"{"op":"elevate","points":[[0]],"by":1000000000000}"#,
                "degree after elevation is too large",
            ),
            (r#"{"op":"elevate","points":[[0]],"by":-1}"#, "non-negative integer"),
            (r#"{"op":"elevate","points":[[0]],"by":"x"}"#, "non-negative integer"),
            (r#"{"op":"derivative","points":[[0],[1]],"order":2}"#, "order 2"),
            (r#"{"op":"to_bezier","power":[[0,1],[1]]}"#, "ragged"),
            (r#"{"op":"to_bezier","power":[]}"#, "empty"),
            (r#"{"op":"eval","points":[[1e400]],"t":0}"#, "not valid JSON"),
        ];
        for (line, needle) in cases {
            let r = ask(line);
            assert_eq!(r["ok"], json!(false), "{line} -> {r}");
            let msg = r["error"].as_str().unwrap();
            assert!(msg.contains(needle), "{line}: {msg:?} should mention {needle:?}");
        }
    }

    #[test]
    fn huge_requests_are_refused_quickly() {
        let many: Vec<Value> = (0..5000).map(|i| json!([i])).collect();
        let r = ask(&json!({"op": "eval", "points": many, "t": "1/3"}).to_string());
        assert!(
            r["error"].as_str().unwrap().contains("number of points is too large"),
            "{r}"
        );
        let wide: Vec<Value> = (0..65).map(|i| json!(i)).collect();
        let r = ask(&json!({"op": "eval", "points": [wide], "t": 0}).to_string());
        assert!(r["error"].as_str().unwrap().contains("dimension is too large"), "{r}");
        // degree 4000 at a parameter with 1000-digit numerator: far beyond the work limit
        let pts: Vec<Value> = (0..4000).map(|i| json!([i])).collect();
        let t = format!("1/{}", "7".repeat(1000));
        let r = ask(&json!({"op": "eval", "points": pts, "t": t}).to_string());
        assert!(r["error"].as_str().unwrap().contains("estimated exact work"), "{r}");
    }

    #[test]
    fn work_limit_matches_its_documentation() {
        let request = |op: &str, n: i64, t: Value| {
            let points: Vec<Value> = (0..n).map(|i| json!([(i * 7919) % 1000, (i * 104729) % 997])).collect();
            Op::from_json(&json!({"op": op, "points": points, "t": t}))
        };
        let planar = |n: i64, t: Value| request("split", n, t);
        assert!(planar(301, json!("1/3")).is_ok());
        assert!(planar(401, json!("1/3"))
            .unwrap_err()
            .to_string()
            .contains("estimated exact work"));
        assert!(planar(121, json!(0.1)).is_ok());
        assert!(planar(301, json!(0.1)).is_err());
        // eval runs the fraction-free algorithm: far higher degrees within the same time
        assert!(request("eval", 3001, json!("1/3")).is_ok());
        assert!(request("eval", 4097, json!("1/3")).is_err());
        assert!(request("eval", 1001, json!(0.1)).is_ok());
        assert!(request("eval", 2001, json!(0.1)).is_err());
        // the everyday case is far below the limit
        let op = planar(21, json!(0.1)).unwrap();
        assert!(op.work() < MAX_WORK / 1000.0, "{}", op.work());
    }

    #[test]
    fn nearest_is_correctly_rounded() {
        for s in [
            "0.1",
            "1e-320",
            "4.9406564584124654e-324",
            "2.4703282292062327e-324",
            "2.4703282292062328e-324",
            "1.7976931348623157e308",
            "1.7976931348623158e308",
            "1.7976931348623159e308",
            "9007199254740993",
            "2.2250738585072011e-308",
            "2.2250738585072014e-308",
        ] {
            assert_eq!(nearest_f64(&q(s)).to_bits(), s.parse::<f64>().unwrap().to_bits(), "{s}");
            let neg = format!("-{s}");
            assert_eq!(
                nearest_f64(&q(&neg)).to_bits(),
                neg.parse::<f64>().unwrap().to_bits(),
                "{neg}"
            );
        }
        assert_eq!(nearest_f64(&q("1/3")), 1.0 / 3.0);
        assert_eq!(nearest_f64(&q("-2/3")), -2.0 / 3.0);
        assert_eq!(nearest_f64(&q("-414/43")), -414.0 / 43.0);
        assert_eq!(nearest_f64(&q("2e308")), f64::INFINITY);
        assert_eq!(nearest_f64(&q("0")), 0.0);
    }

    #[test]
    fn ulps_of_known_values() {
        let third = q("1/3");
        let e = ulp_error(1.0 / 3.0, &third).unwrap();
        assert_eq!(e.ulps, 0);
        assert!(e.error_ulps > 0.0 && e.error_ulps <= 0.5, "{e:?}");
        let off = f64::from_bits((1.0f64 / 3.0).to_bits() + 2);
        assert_eq!(ulp_error(off, &third).unwrap().ulps, 2);
        let e = ulp_error(1.0, &q("1")).unwrap();
        assert_eq!((e.ulps, e.error_ulps), (0, 0.0));
        // one step below 1 is half an ulp of 1 away in the binade of 1
        let e = ulp_error(f64::from_bits(1.0f64.to_bits() - 1), &q("1")).unwrap();
        assert_eq!((e.ulps, e.error_ulps), (1, 0.5));
        let e = ulp_error(-0.0, &q("0")).unwrap();
        assert_eq!((e.ulps, e.error_ulps), (0, 0.0));
        let e = ulp_error(f64::from_bits(3), &q("0")).unwrap();
        assert_eq!((e.ulps, e.error_ulps), (3, 3.0));
        assert_eq!(ulp_distance(-f64::from_bits(1), f64::from_bits(1)), 2);
    }

    #[test]
    fn bounded_reader_skips_long_lines() {
        let input = format!("{}\nshort\n{}", "x".repeat(100), "y".repeat(5));
        let mut r = io::BufReader::with_capacity(7, input.as_bytes());
        assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::TooLong);
        assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::Text(b"short".to_vec()));
        assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::Text(b"yyyyy".to_vec()));
        assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::Eof);
        let mut r = io::BufReader::new(&b"\n\n"[..]);
        assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::Text(vec![]));
        assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::Text(vec![]));
        assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::Eof);
    }

    #[test]
    fn serve_answers_every_line_in_order() {
        let input = "{\"id\":1,\"op\":\"eval\",\"points\":[[0],[2]],\"t\":\"1/4\"}\nnope\r\n\n\u{FFFD}\n{\"id\":2,\"op\":\"eval\",\"points\":[[0],[2]],\"t\":0.5}";
        let mut out = Vec::new();
        serve(input.as_bytes(), &mut out).unwrap();
        let lines: Vec<Value> = String::from_utf8(out)
            .unwrap()
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect();
        assert_eq!(lines.len(), 5);
        assert_eq!(lines[0], json!({"id": 1, "ok": true, "point": ["1/2"]}));
        assert_eq!(lines[1]["ok"], json!(false));
        assert_eq!(lines[2]["ok"], json!(false));
        assert_eq!(lines[3]["ok"], json!(false));
        assert_eq!(lines[4], json!({"id": 2, "ok": true, "point": ["1"]}));
        let mut out = Vec::new();
        serve(&[b'{', 0xff, b'}', b'\n'][..], &mut out).unwrap();
        assert!(String::from_utf8(out).unwrap().contains("not valid UTF-8"));
    }

    fn small_rational() -> impl Strategy<Value = BigRational> {
        (-1000i64..1000, 1i64..100).prop_map(|(p, d)| BigRational::new(p.into(), d.into()))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        #[test]
        fn oracle_eval_equals_library_eval(
            coords in prop::collection::vec(prop::collection::vec(small_rational(), 2), 1..8),
            t in small_rational(),
        ) {
            let curve = BezierCurve::from_coords(coords.clone()).unwrap();
            let exact = curve.eval(&t);
            let points: Vec<Value> = coords.iter().map(|p| p.iter().map(number_to_json).collect()).collect();
            let approx: Vec<f64> = exact.coords().iter().map(nearest_f64).collect();
            let r = ask(&json!({"op": "eval", "points": points, "t": number_to_json(&t), "approx": approx}).to_string());
            prop_assert_eq!(&r["ok"], &json!(true));
            let got: Vec<BigRational> = r["point"].as_array().unwrap().iter().map(|c| q(c.as_str().unwrap())).collect();
            prop_assert_eq!(got.as_slice(), exact.coords());
            prop_assert_eq!(&r["ulps"], &json!([0, 0]));
            for e in r["error_ulps"].as_array().unwrap() {
                prop_assert!(e.as_f64().unwrap() <= 0.5);
            }
        }

        #[test]
        fn nearest_matches_float_parsing(m in any::<u64>(), e in -330i32..310) {
            let s = format!("{m}e{e}");
            prop_assert_eq!(nearest_f64(&q(&s)).to_bits(), s.parse::<f64>().unwrap().to_bits());
        }

        #[test]
        fn nearest_of_a_float_is_itself(bits in any::<u64>()) {
            let x = f64::from_bits(bits);
            prop_assume!(x.is_finite());
            let exact = <BigRational as Scalar>::from_f64(x).unwrap();
            prop_assert_eq!(nearest_f64(&exact), x);
            prop_assert_eq!(ulp_error(x, &exact).unwrap().ulps, 0);
            prop_assert_eq!(ulp_error(x, &exact).unwrap().error_ulps, 0.0);
        }
    }
}
