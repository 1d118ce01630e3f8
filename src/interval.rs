//! [`Interval`]: a scalar that encloses the exact result, for certified float computations.
//!
//! An `Interval` is a pair of `f64` endpoints `lo ≤ hi`. Every operation rounds its lower
//! endpoint down and its upper endpoint up — exactly, not by a blanket ulp: the error-free
//! transformations give the sign of each rounding error, and an endpoint moves one float
//! outward only when the rounding went inward. So any generic algorithm of the crate (eval,
//! split, elevate, derivatives, surfaces, rational curves, fit) run on `Interval` returns an
//! enclosure of the exact result on the exact inputs.
//!
//! Comparisons are certain or absent: `a < b` holds only when `a.hi < b.lo`; overlapping
//! intervals are unordered (`partial_cmp` is `None`, so `<`, `>` are false). The filtered
//! predicates below decide signs with intervals and fall back to exact rationals only when an
//! interval straddles zero; [`filter_stats`] counts both.
//!
//! ```
//! use casteljau::{Interval, BezierCurve, Scalar};
//! let c: BezierCurve<Interval> = BezierCurve::from_coords(vec![vec![Interval::from_f64(0.1).unwrap()],
//!     vec![Interval::from_f64(0.2).unwrap()], vec![Interval::from_f64(0.7).unwrap()]]).unwrap();
//! let p = c.eval(&Interval::from_ratio(1, 3).unwrap());
//! let x = p.coords()[0];
//! assert!(x.lo() < x.hi() && x.hi() - x.lo() < 1e-15);
//! ```

use crate::conic::{classify_conic, ConicKind};
use crate::error::{Error, Result};
use crate::float::{
    add_up, gamma_computed, nearest_f64, next_down, next_up, two_product, two_sum, ulp_exponent_f64, with_scratch,
    ExactRange, Factor, UNIT_ROUNDOFF,
};
use crate::point::Point;
use crate::rational::RationalBezierCurve;
use crate::scalar::{forward_ring_ops, Ring, Scalar};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;
use std::fmt;
use std::sync::atomic::{AtomicU64, Ordering as AtomicOrdering};

// `Interval` as a `Scalar`, with the sign-split kernel of `eval` (`crate::float`), which
// imports this file: in a file of its own, so that no import goes both ways.
mod number;

/// A closed interval `[lo, hi]` of reals with `f64` endpoints.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    lo: f64,
    hi: f64,
}

/// `x` rounded down, given the exact error `e` of its rounding (`exact = x + e`).
fn down(x: f64, e: f64) -> f64 {
    if x == f64::INFINITY {
        f64::MAX
    } else if x.is_infinite() || e >= 0.0 {
        x
    } else {
        next_down(x)
    }
}

/// `x` rounded up, given the exact error `e` (`exact = x + e`).
fn up(x: f64, e: f64) -> f64 {
    -down(-x, -e)
}

impl Interval {
    /// `[lo, hi]`; an error when `lo > hi` or either is NaN.
    pub fn new(lo: f64, hi: f64) -> Result<Self> {
        if lo.is_nan() || hi.is_nan() || lo > hi {
            return Err(Error::Domain(format!("[{lo}, {hi}] is not an interval")));
        }
        Ok(Interval { lo, hi })
    }

    /// The degenerate interval `[x, x]` (NaN is an error).
    pub fn point(x: f64) -> Result<Self> {
        Self::new(x, x)
    }

    /// The lower endpoint.
    pub fn lo(&self) -> f64 {
        self.lo
    }

    /// The upper endpoint.
    pub fn hi(&self) -> f64 {
        self.hi
    }

    /// `hi − lo`, rounded up.
    pub fn width(&self) -> f64 {
        let (d, e) = two_sum(self.hi, -self.lo);
        up(d, e)
    }

    /// Whether the exact value `x` lies in the interval (decided exactly).
    pub fn contains(&self, x: &BigRational) -> bool {
        let at_least_lo = self.lo == f64::NEG_INFINITY || exact(self.lo) <= *x;
        let at_most_hi = self.hi == f64::INFINITY || *x <= exact(self.hi);
        at_least_lo && at_most_hi
    }

    /// The sign of every member, when they share one: `Some(Less)`, `Some(Greater)`, or
    /// `Some(Equal)` for `[0, 0]`; `None` when the interval straddles or touches zero.
    pub fn sign(&self) -> Option<Ordering> {
        if self.lo > 0.0 {
            Some(Ordering::Greater)
        } else if self.hi < 0.0 {
            Some(Ordering::Less)
        } else if self.lo == 0.0 && self.hi == 0.0 {
            Some(Ordering::Equal)
        } else {
            None
        }
    }

    fn mul_bounds(&self, o: &Interval) -> Interval {
        let products = [(self.lo, o.lo), (self.lo, o.hi), (self.hi, o.lo), (self.hi, o.hi)];
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for (a, b) in products {
            if a == 0.0 || b == 0.0 {
                // 0 · ∞ is 0 for the enclosure of a product of reals
                lo = lo.min(0.0);
                hi = hi.max(0.0);
                continue;
            }
            let (p, e) = two_product(a, b);
            let e = if !p.is_finite() {
                0.0
            } else if e == 0.0 && !error_is_exact(a, b) {
                // the error may have underflowed to 0 (a nonzero error keeps its sign when
                // rounded). A product rounded to 0 lies on the side of a·b's sign; any other
                // moves outward both ways.
                if p == 0.0 {
                    a.signum() * b.signum()
                } else {
                    lo = lo.min(next_down(p));
                    hi = hi.max(next_up(p));
                    continue;
                }
            } else {
                e
            };
            lo = lo.min(down(p, e));
            hi = hi.max(up(p, e));
        }
        Interval { lo, hi }
    }
}

/// Whether the rounding error of `a·b` (or the remainder of a quotient `a / b ≈ q`, with `q`
/// for `a`) is a float, so that an FMA returns it exactly: true when the exponents of the two
/// operands' last bits sum to at least `−1074`, so that `a·b` is a multiple of `2^−1074`.
fn error_is_exact(a: f64, b: f64) -> bool {
    ulp_exponent_f64(a) + ulp_exponent_f64(b) >= -1074
}

fn exact(x: f64) -> BigRational {
    BigRational::from_float(x).expect("finite endpoint")
}

fn sum_bounds(a: &Interval, b: &Interval) -> Interval {
    let (l, el) = two_sum(a.lo, b.lo);
    let (h, eh) = two_sum(a.hi, b.hi);
    let clean = |x: f64, e: f64| if x.is_finite() { e } else { 0.0 };
    Interval {
        lo: down(l, clean(l, el)),
        hi: up(h, clean(h, eh)),
    }
}

impl fmt::Display for Interval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "[{:?}, {:?}]", self.lo, self.hi)
    }
}

impl PartialOrd for Interval {
    /// Certain order only: `Less` when `hi < other.lo`, `Greater` when `lo > other.hi`,
    /// `Equal` for two equal points; `None` when they overlap otherwise.
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        if self.hi < other.lo {
            Some(Ordering::Less)
        } else if self.lo > other.hi {
            Some(Ordering::Greater)
        } else if self == other && self.lo == self.hi {
            Some(Ordering::Equal)
        } else {
            None
        }
    }
}

impl Ring for Interval {
    fn zero() -> Self {
        Interval { lo: 0.0, hi: 0.0 }
    }
    fn one() -> Self {
        Interval { lo: 1.0, hi: 1.0 }
    }
    fn from_i64(n: i64) -> Self {
        Self::from_rational(&BigRational::from_integer(n.into())).expect("every i64 is below f64::MAX")
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        sum_bounds(self, rhs)
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        sum_bounds(self, &rhs.neg_ref())
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.mul_bounds(rhs)
    }
    fn neg_ref(&self) -> Self {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

forward_ring_ops!(Interval);

/// Decisions of the filtered predicates: how many signs the intervals decided, and how many
/// needed the exact fallback.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FilterStats {
    /// decided with intervals
    pub filtered: u64,
    /// decided exactly (an interval straddled zero)
    pub exact: u64,
}

static FILTERED: AtomicU64 = AtomicU64::new(0);
static EXACT_FALLBACKS: AtomicU64 = AtomicU64::new(0);

/// The counts since the start of the process (all threads).
pub fn filter_stats() -> FilterStats {
    FilterStats {
        filtered: FILTERED.load(AtomicOrdering::Relaxed),
        exact: EXACT_FALLBACKS.load(AtomicOrdering::Relaxed),
    }
}

fn count(filtered: bool) {
    let counter = if filtered { &FILTERED } else { &EXACT_FALLBACKS };
    counter.fetch_add(1, AtomicOrdering::Relaxed);
}

/// The type of the conic carrying a rational quadratic arc with `f64` data, decided as
/// [`classify_conic`] decides it in exact arithmetic on the same floats: first with
/// intervals, exactly only when a sign is uncertain. Always the exact answer.
///
/// ```
/// use casteljau::{filtered_conic_kind, classify_conic, ConicKind, Point, RationalBezierCurve};
/// let w1 = 0.1 * 3.0; // 0.30000000000000004
/// let points = [[-1.0, 1.0], [0.0, -1.0], [1.0, 1.0]].iter().map(|c| Point::new(c.to_vec()).unwrap()).collect();
/// let arc = RationalBezierCurve::new(points, vec![1.0, w1, w1 * w1]).unwrap();
/// // w1² − w0 w2 is the rounding error of w1·w1: plain floats see 0, exactly it is positive
/// assert_eq!(classify_conic(&arc).unwrap(), ConicKind::Parabola);
/// assert_eq!(filtered_conic_kind(&arc).unwrap(), ConicKind::Hyperbola);
/// ```
pub fn filtered_conic_kind(c: &RationalBezierCurve<f64>) -> Result<ConicKind> {
    let iv = c.try_map(|x| Interval::from_f64(*x))?;
    let (w, p) = (iv.weights(), iv.points());
    if w.len() != 3 {
        return classify_conic(c);
    }
    let u = Point::sub(&p[1], &p[0]);
    let v = Point::sub(&p[2], &p[0]);
    let uv = u.dot(&v);
    let gram = u.norm_squared() * v.norm_squared() - uv * uv;
    let excess = w[1] * w[1] - w[0] * w[2];
    let weights_known = w.iter().all(|x| x.sign().is_some());
    if let (Some(g), Some(e), true) = (gram.sign(), excess.sign(), weights_known) {
        count(true);
        return Ok(if g == Ordering::Equal {
            ConicKind::DegenerateCollinear
        } else if w.iter().any(Scalar::is_zero) {
            ConicKind::DegenerateZeroWeight
        } else {
            match e {
                Ordering::Equal => ConicKind::Parabola,
                Ordering::Greater => ConicKind::Hyperbola,
                Ordering::Less => ConicKind::Ellipse,
            }
        });
    }
    count(false);
    classify_conic(&c.try_map(|x| BigRational::from_f64(*x))?)
}

/// The orientation of `p, q, r` in the plane (the sign of `(q − p) × (r − p)`), decided with
/// intervals and exactly only when the interval straddles zero: `Greater` counter-clockwise,
/// `Less` clockwise, `Equal` collinear. A coordinate that is ±inf or NaN is an error (the
/// orientation of such points has no exact answer).
pub fn filtered_orientation(p: [f64; 2], q: [f64; 2], r: [f64; 2]) -> Result<Ordering> {
    finite(&[p, q, r])?;
    Ok(orientation_of_finite(p, q, r))
}

fn finite(points: &[[f64; 2]]) -> Result<()> {
    match points.iter().flatten().find(|x| !x.is_finite()) {
        Some(x) => Err(Error::NotFinite(x.to_string())),
        None => Ok(()),
    }
}

fn orientation_of_finite(p: [f64; 2], q: [f64; 2], r: [f64; 2]) -> Ordering {
    let i = |x: f64| Interval { lo: x, hi: x };
    let det = (i(q[0]) - i(p[0])) * (i(r[1]) - i(p[1])) - (i(q[1]) - i(p[1])) * (i(r[0]) - i(p[0]));
    if let Some(s) = det.sign() {
        count(true);
        return s;
    }
    count(false);
    let e = |x: f64| exact(x);
    let det = (e(q[0]) - e(p[0])) * (e(r[1]) - e(p[1])) - (e(q[1]) - e(p[1])) * (e(r[0]) - e(p[0]));
    if Zero::is_zero(&det) {
        Ordering::Equal
    } else if det.is_positive() {
        Ordering::Greater
    } else {
        Ordering::Less
    }
}

/// Whether the planar point `p` lies in the (closed) convex hull of `points`, decided
/// exactly on the given floats with filtered orientations.
///
/// `p` (not itself a control point) is outside iff the directions `b_j − p` fit in an open
/// half-plane, i.e. iff for the clockwise-most of them, `b`, every point lies strictly left
/// of the line `p b` or on the ray from `p` through `b`.
///
/// ```
/// use casteljau::filtered_hull_contains;
/// let tri = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]];
/// assert!(filtered_hull_contains(&tri, [1.0, 1.0]).unwrap());
/// assert!(filtered_hull_contains(&tri, [2.0, 2.0]).unwrap()); // on the edge, decided exactly
/// assert!(!filtered_hull_contains(&tri, [2.0, 2.0000000000000004]).unwrap());
/// assert!(filtered_hull_contains(&tri, [f64::NAN, 0.0]).is_err());
/// ```
pub fn filtered_hull_contains(points: &[[f64; 2]], p: [f64; 2]) -> Result<bool> {
    finite(points)?;
    finite(&[p])?;
    if points.contains(&p) {
        return Ok(true);
    }
    for &b in points {
        let mut all_left = true;
        for &c in points {
            match orientation_of_finite(p, b, c) {
                Ordering::Greater => {}
                Ordering::Less => {
                    all_left = false;
                    break;
                }
                Ordering::Equal => {
                    // on the line p b: allowed only on the ray from p through b
                    let d = |k: usize, x: [f64; 2]| exact(x[k]) - exact(p[k]);
                    let dot = d(0, c) * d(0, b) + d(1, c) * d(1, b);
                    if !dot.is_positive() {
                        all_left = false;
                        break;
                    }
                }
            }
        }
        if all_left {
            return Ok(false);
        }
    }
    Ok(true)
}

/// An enclosure of `Σ b_i B_i^n(t)` for float coefficients and a float `t`; an error for a
/// non-finite input or no coefficients. No heap allocation up to
/// [`crate::float::STACK_COEFFICIENTS`] coefficients.
///
/// For `t ∈ [0, 1]` it costs two plain float triangles, on the coefficients' positive and
/// negative parts (the proof is in the source): the enclosure is `d ± E` with
/// `E ≈ γ_{3n} Σ|b_i|B_i^n(t)`, the a priori bound's width, clamped to the coefficients'
/// range. The operation-by-operation interval of [`tight_interval_de_casteljau`] (which the
/// oracle serves, and every other `t` takes) is narrower where most operations are exact.
/// Inputs up to the largest `f64` give finite enclosures.
///
/// ```
/// use casteljau::interval_de_casteljau;
/// let e = interval_de_casteljau(&[1e308, -1e308], 0.3).unwrap();
/// assert!(e.lo() <= 4e307 && 4e307 <= e.hi() && e.hi().is_finite());
/// assert!(interval_de_casteljau(&[1.0, f64::NAN], 0.3).is_err());
/// ```
#[inline]
pub fn interval_de_casteljau(b: &[f64], t: f64) -> Result<Interval> {
    if (0.0..=1.0).contains(&t) {
        if let Some(e) = sign_split_enclosure(b, t) {
            return Ok(e);
        }
    }
    tight_interval_de_casteljau(b, t)
}

/// The enclosure of [`interval_de_casteljau`] for `t ∈ [0, 1]` by two float triangles on
/// nonnegative data; `None` for no coefficients, and when a value is not finite (a
/// non-finite input, which reaches the result through every path, or an overflow).
///
/// Split the coefficients `b_i = b⁺_i − b⁻_i` into nonnegative parts, so that
/// `p = P⁺ − P⁻` with `P^± = Σ b^±_i B_i^n(t)`, and run de Casteljau's convex form
/// `fl(fl(ŝ·a) + fl(t·c))`, `ŝ = fl(1 − t)`, on each. Why it is sound: with `s = 1 − t`
/// exactly, `ŝ = s(1 + δ₀)`, and every rounding `fl(x) = x(1 + δ) + ε` (`|δ| ≤ u`,
/// `|ε| ≤ η/2`, `η = 2^−1074`, `ε` only for a product, sums of floats being exact below
/// `2^−1022`), a node on nonnegative `a, c` computes
/// `ẑ = (s a (1+δ₀)(1+δ₁) + t c (1+δ₂) + ε₁ + ε₂)(1+δ₃)`, so, with `w = s a + t c`,
/// `(1−u)³ w − 2η ≤ ẑ ≤ (1+u)³ w + 2η`. No cancellation can amplify this: every value is
/// nonnegative. By induction over the `n` levels (using `s, t ≥ 0` and `s + t = 1`),
/// `(1−u)^{3n} P − 2nη ≤ P̂ ≤ (1+u)^{3n} (P + 2nη)`, and since
/// `(1−u)^{−3n} ≤ 1/(1 − 3nu) = 1 + γ_{3n}` and `(1+u)^{−3n} ≥ 1 − 3nu`,
/// `P̂(1 − γ_{3n}) − 2nη ≤ P ≤ (P̂ + 2nη)(1 + γ_{3n})`. Subtracting,
/// `|p − (P̂⁺ − P̂⁻)| ≤ γ_{3n} (P̂⁺ + P̂⁻) + 4nη(1 + γ_{3n})`; the comments in the body
/// account for the roundings of the endpoints. A float that overflowed is infinite and
/// reaches the result (products by `s, t ≥ 0` and sums keep ∞, or make NaN with 0), so a
/// finite result had no overflow.
/// `tests/interval_enclosure.rs` checks the enclosure against the exact rational value.
#[inline]
pub(crate) fn sign_split_enclosure(b: &[f64], t: f64) -> Option<Interval> {
    sign_split_enclosure_by(b.len(), || b.iter().copied(), t)
}

/// [`sign_split_enclosure`] on the `len` coefficients `coefficients()` yields, each read
/// once (and again only when an endpoint overflowed): the public `eval` of an interval
/// curve reads them from its points without a copy.
#[inline(always)]
pub(crate) fn sign_split_enclosure_by<I: Iterator<Item = f64>>(
    len: usize,
    coefficients: impl Fn() -> I,
    t: f64,
) -> Option<Interval> {
    let n = len.checked_sub(1)?;
    if n == 0 {
        let x = coefficients().next()?;
        return x.is_finite().then_some(Interval { lo: x, hi: x });
    }
    // low degrees on arrays of constant length: unrolled, in registers
    let [pos, neg] = match len {
        2 => sign_split_triangle(&mut [[0.0; 2]; 2], coefficients(), t),
        3 => sign_split_triangle(&mut [[0.0; 2]; 3], coefficients(), t),
        4 => sign_split_triangle(&mut [[0.0; 2]; 4], coefficients(), t),
        5 => sign_split_triangle(&mut [[0.0; 2]; 5], coefficients(), t),
        len => with_scratch(len, [0.0; 2], |buf| sign_split_triangle(buf, coefficients(), t)),
    };
    rounded_outward(coefficients, n, pos, neg)
}

/// [`sign_split_enclosure`] on `N ≥ 2` coefficients known at compile time, inlined where
/// it is called (the public `eval` of an interval cubic).
#[inline(always)]
pub(crate) fn sign_split_enclosure_of<const N: usize>(b: &[f64; N], t: f64) -> Option<Interval> {
    sign_split_enclosure_by(N, || b.iter().copied(), t)
}

/// The enclosure of [`sign_split_enclosure`] from the triangles' values `P̂⁺`, `P̂⁻` at
/// degree `n ≥ 1`.
#[inline(always)]
fn rounded_outward<I: Iterator<Item = f64>>(
    coefficients: impl Fn() -> I,
    n: usize,
    pos: f64,
    neg: f64,
) -> Option<Interval> {
    // Rounded, with R = γ_{3n}·m + 4nη(1 + γ_{3n}) the reach above (m = P̂⁺ + P̂⁻ exactly):
    // d = fl(P̂⁺ − P̂⁻) is off by at most u·m (m ≥ |P̂⁺ − P̂⁻|, so |d| ≤ (1 + u)m), and
    // fl(d ± r) by at most u(|d| + r), so `d ± r` rounded to nearest are outward enough when
    // r(1 − u) ≥ (γ_{3n} + 2u + u²)·m + 4nη(1 + γ_{3n}). The product fl(c · fl(m)) is at
    // least c(1 − u)²m when normal, and c(1 − u)³ ≥ (γ_{3n} + 2u)(1 + u/2) covers the
    // first term ([`reach_factor`]).
    // The underflow term is below (4n + 1)η, as 4nγ_{3n} < 1 up to the degree limit: above
    // 2^−1000 one step up covers it (an ulp is then at least 2^−1052), below it is added,
    // with η more for a subnormal product. It is written as bits: a product with a
    // subnormal result costs a hundred cycles on some processors.
    let spread = reach_factor(n) * (pos + neg);
    let reach = if spread > NO_UNDERFLOW_BELOW {
        next_up(spread)
    } else {
        add_up(spread, f64::from_bits(4 * n as u64 + 2))
    };
    let d = pos - neg;
    let (lo, hi) = (d - reach, d + reach);
    if lo.is_finite() && hi.is_finite() {
        return Some(Interval { lo, hi });
    }
    clamped_to_coefficients(coefficients(), pos, neg, lo, hi)
}

/// The enclosure `[lo, hi]` of [`sign_split_enclosure`] when an endpoint overflowed (or an
/// input is not finite: `None`): for `t ∈ [0, 1]` the value is a convex combination of the
/// `b_i`, so within their least and largest.
#[cold]
fn clamped_to_coefficients(
    coefficients: impl Iterator<Item = f64>,
    pos: f64,
    neg: f64,
    lo: f64,
    hi: f64,
) -> Option<Interval> {
    if !(pos.is_finite() && neg.is_finite()) {
        return None;
    }
    let (min, max) = coefficients.fold((f64::INFINITY, f64::NEG_INFINITY), |(min, max), x| {
        (min.min(x), max.max(x))
    });
    Some(Interval {
        lo: lo.max(min),
        hi: hi.min(max),
    })
}

/// `c ≥ (γ_{3n} + 2u)(1 + u/2)/(1 − u)³`: `(1 + 4u)(1 − u)³ ≥ 1 + u − 9u² ≥ 1 + u/2`.
/// Looked up below degree 341, in a `const` table: where `n` is known at compile time (the
/// public `eval` of an interval cubic, inlined into another crate) the factor is a constant
/// there, not a load from a `static` of this crate through the global offset table.
#[inline(always)]
fn reach_factor(n: usize) -> f64 {
    const fn computed(n: usize) -> f64 {
        next_up(next_up(gamma_computed(3 * n) + 2.0 * UNIT_ROUNDOFF) * (1.0 + 4.0 * UNIT_ROUNDOFF))
    }
    const FACTORS: [f64; 341] = {
        let mut table = [0.0; 341];
        let mut n = 0;
        while n < table.len() {
            table[n] = computed(n);
            n += 1;
        }
        table
    };
    match FACTORS.get(n) {
        Some(c) => *c,
        None => computed(n),
    }
}

/// `2^−1000`: the ulp of a float above it, at least `2^−1052`, exceeds every underflow term
/// of [`sign_split_enclosure`] (`(4n + 1) · 2^−1074 < 2^−1058` up to degree 4096).
const NO_UNDERFLOW_BELOW: f64 = f64::from_bits((1023 - 1000) << 52);

/// De Casteljau's convex form on the pairs `(b⁺_i, b⁻_i)` of the coefficients `b` (at least
/// two) in `buf` (as many as there are coefficients), both triangles in one loop (two
/// independent lanes): `[P̂⁺, P̂⁻]`. The first level is computed as the coefficients are
/// split, from pairs held in registers: a pair stored as two halves and read back whole
/// waits for both stores.
#[inline(always)]
fn sign_split_triangle(buf: &mut [[f64; 2]], mut b: impl Iterator<Item = f64>, t: f64) -> [f64; 2] {
    let s = 1.0 - t;
    let node = |a: [f64; 2], c: [f64; 2]| [s * a[0] + t * c[0], s * a[1] + t * c[1]];
    // `max` drops a NaN; `p − c` brings it back (and makes +∞'s negative part NaN)
    let split = |c: f64| {
        let p = c.max(0.0);
        [p, p - c]
    };
    let mut a = split(b.next().unwrap_or(0.0));
    for (x, c) in buf.iter_mut().zip(b) {
        let c = split(c);
        *x = node(a, c);
        a = c;
    }
    // then two levels a sweep, the middle level in registers: a level's values stored and
    // loaded back once for every two levels
    let mut values = buf.len().saturating_sub(1);
    while values >= 3 {
        let (mut left, mut right) = (buf[0], buf[1]);
        let mut middle = node(left, right);
        for i in 0..values - 2 {
            (left, right) = (right, buf[i + 2]);
            let next = node(left, right);
            buf[i] = node(middle, next);
            middle = next;
        }
        values -= 2;
    }
    if values == 2 {
        buf[0] = node(buf[0], buf[1]);
    }
    buf[0]
}

/// An enclosure of `Σ b_i B_i^n(t)` for float coefficients and a float `t`, by de Casteljau
/// in the convex form `[1 − t]·a + [t]·b` (with `[1 − t]` the two floats around `1 − t`
/// when it is no float), every operation rounded outward exactly as the [`Interval`]
/// operations round it: the oracle's `float_eval` answers (recorded byte for byte) come
/// from here. Unlike the lerp form `a + t·(b − a)` of the generic algorithm, its
/// intermediate values stay within the coefficients' range for `t ∈ [0, 1]`, so inputs up to
/// the largest `f64` give finite enclosures. An error for a non-finite input or no
/// coefficients. No heap allocation up to [`crate::float::STACK_COEFFICIENTS`]
/// coefficients.
///
/// ```
/// use casteljau::tight_interval_de_casteljau;
/// let e = tight_interval_de_casteljau(&[1e308, -1e308], 0.3).unwrap();
/// assert!(e.lo() <= 4e307 && 4e307 <= e.hi() && e.hi().is_finite());
/// ```
pub fn tight_interval_de_casteljau(b: &[f64], t: f64) -> Result<Interval> {
    let t = Interval::from_f64(t)?;
    if b.is_empty() {
        return Err(Error::Domain("de Casteljau needs at least one coefficient".into()));
    }
    if let Some(x) = b.iter().find(|x| !x.is_finite()) {
        return Err(Error::NotFinite(x.to_string()));
    }
    let (s, rho) = two_sum(1.0, -t.lo);
    let s = Interval {
        lo: down(s, rho),
        hi: up(s, rho),
    };
    let fill = |buf: &mut [Interval]| {
        for (x, y) in buf.iter_mut().zip(b) {
            *x = Interval { lo: *y, hi: *y };
        }
    };
    Ok(with_scratch(b.len(), Interval::zero(), |buf| {
        fill(buf);
        if t.lo > 0.0 && t.lo < 1.0 {
            if let Some(x) = convex_triangle(buf, s, t.lo) {
                return x;
            }
            fill(buf);
        }
        for len in (1..buf.len()).rev() {
            for i in 0..len {
                buf[i] = s * buf[i] + t * buf[i + 1];
            }
        }
        buf[0]
    }))
}

/// `[s]·a + [t]·b` for every node of de Casteljau's triangle in place, for `0 < t < 1`
/// (so `0 < s.lo ≤ s.hi`): the same endpoints as the interval operations, computed with
/// the two products each endpoint needs instead of four (the sign of `a`'s endpoint picks
/// `s.lo` or `s.hi`; rounding down is monotone, so the other candidates never win). That
/// holds while every rounding error is a float and nothing nears overflow: `None` when a
/// value left that range (the buffer is then spent).
#[inline(always)]
fn convex_triangle(buf: &mut [Interval], s: Interval, t: f64) -> Option<Interval> {
    let (s_lo, s_hi, by_t) = (Factor::new(s.lo), Factor::new(s.hi), Factor::new(t));
    // products below 2^1020 (t, s ≤ 1), so their sums stay finite
    let range = ExactRange::exact(&[s_lo, s_hi, by_t]).capped(MAX_ENDPOINT);
    let in_range = |x: &Interval| range.contains(x.lo) & range.contains(x.hi);
    let halves = |x: &Interval| (Factor::halves(x.lo), Factor::halves(x.hi));
    // `+ 0.0` makes a product's −0 the +0 the interval product gives it
    let product_down = |x: f64, h, f: &Factor, k: f64| {
        let p = k * x;
        down(p, f.error(x, h, p)) + 0.0
    };
    let product_up = |x: f64, h, f: &Factor, k: f64| {
        let p = k * x;
        up(p, f.error(x, h, p)) + 0.0
    };
    let mut ok = true;
    for len in (1..buf.len()).rev() {
        let mut a = buf[0];
        let mut a_halves = halves(&a);
        ok &= in_range(&a);
        for i in 0..len {
            let b = buf[i + 1];
            let b_halves = halves(&b);
            ok &= in_range(&b);
            let lo = {
                let (f, k) = if a.lo >= 0.0 { (&s_lo, s.lo) } else { (&s_hi, s.hi) };
                let x = product_down(a.lo, a_halves.0, f, k);
                let y = product_down(b.lo, b_halves.0, &by_t, t);
                let (l, e) = two_sum(x, y);
                down(l, e)
            };
            let hi = {
                let (f, k) = if a.hi >= 0.0 { (&s_hi, s.hi) } else { (&s_lo, s.lo) };
                let x = product_up(a.hi, a_halves.1, f, k);
                let y = product_up(b.hi, b_halves.1, &by_t, t);
                let (h, e) = two_sum(x, y);
                up(h, e)
            };
            buf[i] = Interval { lo, hi };
            (a, a_halves) = (b, b_halves);
        }
    }
    ok.then_some(buf[0])
}

/// The largest endpoint [`convex_triangle`] takes: `2^1020`.
const MAX_ENDPOINT: f64 = f64::from_bits((1020 + 1023) << 52);
