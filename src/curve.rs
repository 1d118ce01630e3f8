//! Polynomial Bézier curves of any degree and dimension (text 000).
//!
//! `b(t) = Σ_{i=0}^n b_i B_i^n(t)`. Everything here is generic over [`Scalar`]: on exact
//! rationals the results are exact and identities are decided with `==`; on `f64` the same
//! code runs in floating point.
//!
//! | text 000                       | here                                   |
//! |--------------------------------|----------------------------------------|
//! | de Casteljau (1), scheme (9)   | [`BezierCurve::eval`], [`BezierCurve::scheme`] |
//! | Bernstein sum                  | [`BezierCurve::eval_bernstein`]        |
//! | power basis ↔ Bernstein        | [`BezierCurve::from_power_on`], [`BezierCurve::to_power`] |
//! | degree elevation (7), (8)      | [`BezierCurve::elevate`], [`BezierCurve::elevate_by`] |
//! | Theorem 1.2 (convergence)      | [`BezierCurve::elevation_distances`]   |
//! | subdivision, Lemma 1.3         | [`BezierCurve::split_at`]              |
//! | forward differences, derivatives | [`BezierCurve::forward_differences`], [`BezierCurve::derivative`] |
//! | affine invariance, convex hull | [`BezierCurve::transform`], [`BezierCurve::hull_weights`] |

use crate::bernstein::{bernstein_all, bernstein_to_power, binomial_row, power_to_bernstein, reparametrize};
use crate::error::{check_degree, Error, Result};
use crate::hull::convex_weights;
use crate::kernel::{
    de_casteljau, elevate_points, elevated_point, elevation_step, eval_cubic, split_points, with_column,
};
use crate::param::{ParamCurve, ParamCurveDeriv};
use crate::point::{common_dimension, AffineMap, Point, PointList};
use crate::scalar::Scalar;
use crate::space::{common_dim, PointN, VectorSpace};
use num_bigint::BigInt;
use num_rational::BigRational;
use smallvec::SmallVec;
use std::fmt;

mod exact;
mod scheme;
pub use scheme::DeCasteljauScheme;

/// Control points kept inline by a curve: neither a cubic nor its elevation, a quartic,
/// needs a heap allocation.
const INLINE_POINTS: usize = 5;

/// The control points of a cubic, the degree the fast paths are written for.
const CUBIC_POINTS: usize = 4;

/// A Bézier curve with control points `b_0, …, b_n` of type `P` (all of one dimension, at
/// least one point). Up to five control points are stored inline.
///
/// `P` is any [`VectorSpace`]: [`crate::Point2`] and other [`PointN`] for a dimension fixed
/// at compile time (the fast `f64` path), [`Point`] for one known at run time
/// ([`BezierCurve`]). A curve whose degree is fixed when the code is written can be held as a
/// [`crate::BezierN`] ([`crate::Cubic`], [`crate::Quad`]) instead: the same results, without
/// the length to test; the two convert both ways.
///
/// ```
/// use casteljau::{Bezier, Point2};
/// let c = Bezier::from_points([Point2::new(0.0, 0.0), Point2::new(1.0, 2.0), Point2::new(3.0, 2.0), Point2::new(4.0, 0.0)]).unwrap();
/// assert_eq!(c.eval(&0.5), Point2::new(2.0, 1.5));
/// let (left, right) = c.split_at(&0.5);
/// assert_eq!(left.points()[3], right.points()[0]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Bezier<P> {
    points: SmallVec<[P; INLINE_POINTS]>,
}

/// A Bézier curve whose dimension is known at run time: what the command line, the oracle
/// and the claims build.
///
/// ```
/// use casteljau::{BezierCurve, BigRational, Scalar};
/// let q = |p, d| BigRational::from_ratio(p, d).unwrap();
/// // text 000, §1.3: the Bézier points of (-u² + 1, -u³ + u) on [-1, 1]
/// let c = BezierCurve::from_ints(&[&[0, 0], &[4, -4], &[4, 4], &[0, 0]]).unwrap();
/// let c = c.transform(&casteljau::AffineMap::scaling(2, &q(1, 3))).unwrap();
/// let t = q(1, 4);
/// let u = &(&q(2, 1) * &t) - &q(1, 1); // u = 2t - 1
/// let p = c.eval(&t);
/// assert_eq!(p.coords()[0], &q(1, 1) - &(&u * &u));
/// assert_eq!(p.coords()[1], &u - &(&(&u * &u) * &u));
/// ```
pub type BezierCurve<T> = Bezier<Point<T>>;

/// How far the `r`-times elevated control polygon is from the curve (Theorem 1.2):
/// the distances between `b_i^{(r)}` and `b(i/(n+r))`, maximised over `i`.
#[derive(Clone, Debug, PartialEq)]
pub struct ElevationDistance<T> {
    /// Number of elevation steps.
    pub r: usize,
    /// `max_i max_k |b_i^{(r)} - b(i/(n+r))|_k`, the maximum-norm distance (exact).
    pub max_norm: T,
    /// `max_i |b_i^{(r)} - b(i/(n+r))|²`, the squared Euclidean distance (exact).
    pub max_squared: T,
}

impl<T: Scalar, P: VectorSpace<Scalar = T>> Bezier<P> {
    /// A curve from its control points; empty polygons, mixed dimensions and degrees above
    /// [`crate::MAX_DEGREE`] are errors.
    pub fn new(points: Vec<P>) -> Result<Self> {
        Self::from_points(points)
    }

    /// [`Self::new`] from any collection of points, such as an array (stored inline up to a
    /// cubic, without a heap allocation).
    pub fn from_points(points: impl IntoIterator<Item = P>) -> Result<Self> {
        let points: SmallVec<[P; INLINE_POINTS]> = points.into_iter().collect();
        common_dim(&points, "a Bézier curve")?;
        check_degree("degree", points.len() as u128 - 1)?;
        Ok(Bezier { points })
    }

    /// The curve of points known to be valid: non-empty, of one dimension, within the degree
    /// limit.
    pub(crate) fn from_valid(points: impl IntoIterator<Item = P>) -> Self {
        Bezier {
            points: points.into_iter().collect(),
        }
    }

    /// [`Self::from_valid`] from a vector: a polygon past the inline length keeps the
    /// vector's buffer (the exact kernels' results), where collecting moves every point.
    pub(crate) fn from_valid_vec(points: Vec<P>) -> Self {
        Bezier {
            points: SmallVec::from_vec(points),
        }
    }

    /// The control points as an array when there are exactly `N` of them, stored inline.
    /// Asking for the inline buffer, not only the length, spares the fast paths the test of
    /// where a `SmallVec` keeps its items: one comparison, on its length, remains.
    #[inline(always)]
    fn inline_array<const N: usize>(&self) -> Option<&[P; N]> {
        if self.points.spilled() {
            return None;
        }
        self.points[..].try_into().ok()
    }

    /// The curve of `N < INLINE_POINTS` valid points pushed onto an empty vector, whose
    /// length and capacity the compiler follows through the pushes (no test is left): the
    /// unused tail is not written, as [`Self::from_inline`] pads it. A split cubic's halves
    /// cost 1.08x `Cubic`'s this way, 1.20x padded; an elevated quadratic's points did not
    /// gain (the quadratic's and the cubic's elevation merge their stores), so elevation
    /// keeps [`Self::from_inline`].
    #[inline(always)]
    fn from_pushed<const N: usize>(points: [P; N]) -> Self {
        const { assert!(N < INLINE_POINTS) };
        let mut inline = SmallVec::new();
        for p in points {
            inline.push(p);
        }
        Bezier { points: inline }
    }

    /// The curve of `N` valid points, `N ≤ INLINE_POINTS`, written into the inline buffer
    /// at once (its unused tail repeats the last point): no capacity test per point, as a
    /// push or a collect would make.
    #[inline(always)]
    fn from_inline<const N: usize>(points: [P; N]) -> Self {
        let pad = points[N - 1].clone();
        let mut points = points.into_iter();
        let buf = std::array::from_fn(|_| points.next().unwrap_or_else(|| pad.clone()));
        Bezier {
            points: SmallVec::from_buf_and_len(buf, N),
        }
    }

    /// The degree `n`.
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }

    /// The dimension of the control points.
    pub fn dim(&self) -> usize {
        self.points[0].dim()
    }

    /// The control points.
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The control points, by value.
    pub fn into_points(self) -> Vec<P> {
        self.points.into_vec()
    }

    /// `b(t)` by de Casteljau's algorithm (1). Defined for every `t`, not only `[0, 1]`.
    ///
    /// A cubic on floats is evaluated as its nested Bernstein sum instead, fewer operations
    /// and a smaller error (`((t b₃ + 3s b₂) t + 3s² b₁) t + s³ b₀` with `s = 1 − t`).
    ///
    /// Exact rational points are evaluated by the nested Bernstein sum over integers
    /// ([`BezierCurve::eval_nested`]): the same value, with one reduction at the end.
    /// [`Interval`](crate::Interval) points at a point `t ∈ [0, 1]` are enclosed by the
    /// kernel of [`interval_de_casteljau`](crate::interval_de_casteljau), per coordinate.
    #[inline]
    pub fn eval(&self, t: &T) -> P {
        P::curve_eval(&self.points, t, || self.eval_generic(t))
    }

    /// [`Self::eval`] by the generic algorithm, where the point type has no kernel.
    #[inline(always)]
    fn eval_generic(&self, t: &T) -> P {
        // A cubic, the common case, is tested for first and worked on as an array of
        // constant length: no loop, and no other degree's code is inlined here.
        if let Some(points) = self.inline_array::<CUBIC_POINTS>() {
            return eval_cubic(points, t);
        }
        self.eval_any(t)
    }

    /// [`Self::eval`] by de Casteljau's algorithm (1) on the scalar type itself, whatever it
    /// is (a float cubic by its nested sum, as [`Self::eval`]): the reference the exact
    /// kernel is tested against.
    pub fn eval_reference(&self, t: &T) -> P {
        self.eval_any(t)
    }

    /// [`Self::eval`] for any number of points. Cold, so that the cubic's code is the one
    /// that falls through at the call site.
    #[cold]
    pub(crate) fn eval_any(&self, t: &T) -> P {
        if let Ok(points) = <&[P; CUBIC_POINTS]>::try_from(&self.points[..]) {
            return eval_cubic(points, t);
        }
        with_column(&self.points, |column| {
            de_casteljau(column, t, |_| {});
            column[0].clone()
        })
    }

    /// `b(t) = Σ b_i B_i^n(t)`, the Bernstein sum.
    pub fn eval_bernstein(&self, t: &T) -> P {
        let basis = bernstein_all(self.degree(), t);
        let mut acc = self.points[0].zero_like();
        for (b, p) in basis.iter().zip(&self.points) {
            acc.add_scaled_assign(b, p);
        }
        acc
    }

    /// One step of degree elevation (7): the same curve with `n + 2` control points,
    /// `b'_i = i/(n+1) b_{i-1} + (1 − i/(n+1)) b_i`.
    ///
    /// Exact rational points are elevated over integers with one common denominator
    /// ([`BezierCurve::elevate_fraction_free`]).
    // Always inlined, as `elevate_reference`: on floats a quadratic's or a cubic's points
    // then go straight to where the caller keeps the result, as for `BezierN`. Exact points
    // take an out-of-line call.
    #[inline(always)]
    pub fn elevate(&self) -> Result<Self> {
        if T::EXACT {
            if let Some(c) = self.elevate_exact() {
                return c;
            }
        }
        self.elevate_reference()
    }

    /// [`Self::elevate`] by the fraction-free kernel, when the points are exact rationals.
    #[cold]
    fn elevate_exact(&self) -> Option<Result<Self>> {
        Some(P::curve_elevate(&self.points)?.map(Bezier::from_valid_vec))
    }

    /// [`Self::elevate`] by the steps of (7) on the scalar type itself, whatever it is: the
    /// reference the exact kernel is tested against.
    ///
    /// A quadratic and a cubic are elevated by the fixed-degree kernel (the weights
    /// constants, for floats folded at compile time) straight into the inline buffer; the
    /// result cannot exceed the degree limit, so no test is made.
    // Always inlined: called, its `Result` of up to five points comes back through memory
    // and is copied out again.
    #[inline(always)]
    pub fn elevate_reference(&self) -> Result<Self> {
        if let Some(points) = self.inline_array::<3>() {
            return Ok(Self::from_inline::<4>(elevate_points(points)));
        }
        if let Some(points) = self.inline_array::<CUBIC_POINTS>() {
            return Ok(Self::from_inline::<5>(elevate_points(points)));
        }
        // Unwrapped and wrapped again, not returned as it is: returned, the call writes the
        // result where the fast paths' points go too, so the caller keeps them in memory and
        // copies them out; moved, the fast paths' points can stay in registers.
        let curve = self.elevate_any()?;
        Ok(curve)
    }

    /// [`Self::elevate`] for any degree, by the same steps as the fixed-degree kernel. Out
    /// of line and cold: only the quadratic's and the cubic's code is inlined at the callers.
    #[cold]
    #[inline(never)]
    fn elevate_any(&self) -> Result<Self> {
        let points = &self.points[..];
        let n = points.len() - 1;
        check_degree("degree after elevation", n as u128 + 1)?;
        let step = elevation_step::<T>(n)?;
        Ok(Bezier {
            points: (0..n + 2).map(|i| elevated_point(points, i, &step)).collect(),
        })
    }

    /// `r` steps of elevation by the closed form (8):
    /// `b_i^{(r)} = Σ_j C(n,j) C(r,i-j) / C(n+r,i) b_j`.
    ///
    /// ```
    /// use casteljau::{BezierCurve, BigRational};
    /// let c: BezierCurve<BigRational> = BezierCurve::from_ints(&[&[0, 0], &[1, 2], &[3, 1]]).unwrap();
    /// assert_eq!(c.elevate_by(3).unwrap(), c.elevate().unwrap().elevate().unwrap().elevate().unwrap());
    /// assert!(c.elevate_by(1_000_000_000_000).is_err());
    /// ```
    pub fn elevate_by(&self, r: usize) -> Result<Self> {
        if T::EXACT {
            if let Some(points) = P::curve_elevate_by(&self.points, r) {
                return Ok(Bezier::from_valid_vec(points?));
            }
        }
        self.elevate_by_reference(r)
    }

    /// [`Self::elevate_by`] on the scalar type itself: the reference for the exact kernel.
    pub fn elevate_by_reference(&self, r: usize) -> Result<Self> {
        let n = self.degree();
        let total = check_degree("degree after elevation", n as u128 + r as u128)?;
        // Whole rows, not one binomial at a time: C(n+r, i) for every i separately costs
        // O((n+r)^2) big multiplications, hours at the degree limit.
        let cn = binomial_row(n);
        let cr = binomial_row(r);
        let ct = binomial_row(total);
        let mut out = SmallVec::with_capacity(total + 1);
        for (i, denom) in ct.iter().enumerate() {
            let mut acc = self.points[0].zero_like();
            for j in i.saturating_sub(r)..=i.min(n) {
                let w = T::from_rational(&BigRational::new(&cn[j] * &cr[i - j], denom.clone()))?;
                acc.add_scaled_assign(&w, &self.points[j]);
            }
            out.push(acc);
        }
        Ok(Bezier { points: out })
    }

    /// `r` single steps of (7), one after another.
    pub fn elevate_steps(&self, r: usize) -> Result<Self> {
        check_degree("degree after elevation", self.degree() as u128 + r as u128)?;
        let mut c = self.clone();
        for _ in 0..r {
            c = c.elevate()?;
        }
        Ok(c)
    }

    /// Subdivision at `t0` (Lemma 1.3): the curves `c1(t) = b(t0 t)` and
    /// `c2(t) = b(t0 + (1 - t0) t)`, whose control points are the two boundaries of the
    /// scheme (9). Any `t0` works; outside `(0, 1)` the pieces extrapolate. The halves share
    /// their common point `b_0^n(t0)`, the same value in both. On floats it is de Casteljau's
    /// last level and may differ in the last bits from [`Self::eval`] of a cubic (the nested
    /// Bernstein sum); exact scalars agree.
    ///
    /// Exact rational points are split by de Casteljau's steps over integers
    /// ([`BezierCurve::split_fraction_free`]), each point reduced once, or, for long
    /// denominators at a low degree, pair by pair on reduced fractions.
    #[inline]
    pub fn split_at(&self, t0: &T) -> (Self, Self) {
        if T::EXACT {
            if let Some((left, right)) = self.split_exact(t0) {
                return (left, right);
            }
        }
        self.split_at_reference(t0)
    }

    /// [`Self::split_at`] by the fraction-free kernel, when the points are exact rationals.
    #[cold]
    fn split_exact(&self, t0: &T) -> Option<(Self, Self)> {
        let (left, right) = P::curve_split(&self.points, t0)?;
        Some((Bezier::from_valid_vec(left), Bezier::from_valid_vec(right)))
    }

    /// [`Self::split_at`] by de Casteljau's steps on the scalar type itself, whatever it
    /// is: the reference the exact kernel is tested against.
    #[inline]
    pub fn split_at_reference(&self, t0: &T) -> (Self, Self) {
        // A cubic is split as an array of constant length, so that the levels unroll and
        // both halves are written at once.
        if let Some(points) = self.inline_array::<CUBIC_POINTS>() {
            let (left, right) = split_points(points, t0);
            return (Self::from_pushed(left), Self::from_pushed(right));
        }
        self.split_any(t0)
    }

    /// [`Self::split_at`] for any number of points. In place, level by level, the column
    /// ends as b_0^n, b_1^{n-1}, …, b_n^0: the right boundary of the scheme; the left one is
    /// its first point after each level.
    fn split_any(&self, t0: &T) -> (Self, Self) {
        let mut right = self.points.clone();
        let mut left = self.points.clone();
        let mut r = 0;
        de_casteljau(&mut right, t0, |level| {
            r += 1;
            left[r] = level[0].clone();
        });
        (Bezier { points: left }, Bezier { points: right })
    }

    /// The forward differences `Δ^k b_j`, `j = 0..=n-k`; `k > n` is an error.
    pub fn forward_differences(&self, k: usize) -> Result<Vec<P>> {
        let n = self.degree();
        if k > n {
            return Err(Error::DerivativeOrder { order: k, degree: n });
        }
        let mut d = self.points.to_vec();
        for _ in 0..k {
            d = d.windows(2).map(|w| w[1].minus(&w[0])).collect();
        }
        Ok(d)
    }

    /// The `k`-th derivative curve `n!/(n-k)! Σ_j Δ^k b_j B_j^{n-k}(t)`, of degree `n - k`.
    /// `k > n` is an error (the derivative is zero, but no curve of degree `n - k` exists).
    ///
    /// Exact rational points are differenced over integers
    /// ([`BezierCurve::derivative_fraction_free`]).
    pub fn derivative(&self, k: usize) -> Result<Self> {
        if T::EXACT {
            if let Some(points) = P::curve_derivative(&self.points, k) {
                return Ok(Bezier::from_valid_vec(points?));
            }
        }
        self.derivative_reference(k)
    }

    /// [`Self::derivative`] on the scalar type itself: the reference for the exact kernel.
    pub fn derivative_reference(&self, k: usize) -> Result<Self> {
        let n = self.degree();
        let diffs = self.forward_differences(k)?;
        let mut factor = BigInt::from(1);
        for m in n - k + 1..=n {
            factor *= m;
        }
        let f = T::from_bigint(&factor)?;
        Ok(Bezier {
            points: diffs
                .into_iter()
                .map(|mut d| {
                    d.scale_assign(&f);
                    d
                })
                .collect(),
        })
    }

    /// The hodograph: the first derivative curve `n Σ Δb_j B_j^{n-1}(t)`.
    pub fn hodograph(&self) -> Result<Self> {
        self.derivative(1)
    }

    /// The `k`-th derivative vector at `t`: zero when `k` exceeds the degree.
    ///
    /// Exact rationals take the fraction-free kernel ([`BezierCurve::derivative_at_nested`]).
    pub fn derivative_at(&self, k: usize, t: &T) -> Result<P> {
        if k > self.degree() {
            return Ok(self.points[0].zero_like());
        }
        if T::EXACT {
            if let Some(p) = P::curve_derivative_at(&self.points, k, t) {
                return Ok(p);
            }
        }
        Ok(self.derivative(k)?.eval(t))
    }
}

impl<T: Scalar, P: VectorSpace<Scalar = T>> ParamCurve for Bezier<P> {
    type Scalar = T;
    type Point = P;

    fn eval(&self, t: &T) -> Result<P> {
        Ok(Bezier::eval(self, t))
    }
    fn split_at(&self, t0: &T) -> Result<(Self, Self)> {
        Ok(Bezier::split_at(self, t0))
    }
    fn degree(&self) -> usize {
        Bezier::degree(self)
    }
}

/// The hodograph; a constant curve's derivative is the constant zero curve.
impl<T: Scalar, P: VectorSpace<Scalar = T>> ParamCurveDeriv for Bezier<P> {
    type Deriv = Self;

    fn deriv(&self) -> Result<Self> {
        if self.degree() == 0 {
            return Bezier::from_points([VectorSpace::zero_like(&self.points()[0])]);
        }
        self.derivative(1)
    }
}

impl<P> TryFrom<Vec<P>> for Bezier<P>
where
    P: VectorSpace,
    P::Scalar: Scalar,
{
    type Error = Error;
    fn try_from(points: Vec<P>) -> Result<Self> {
        Bezier::new(points)
    }
}

impl<P> From<Bezier<P>> for Vec<P> {
    fn from(c: Bezier<P>) -> Vec<P> {
        c.points.into_vec()
    }
}

#[cfg(feature = "serde")]
impl<P: serde::Serialize> serde::Serialize for Bezier<P> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        serializer.collect_seq(&self.points)
    }
}

#[cfg(feature = "serde")]
impl<'de, P> serde::Deserialize<'de> for Bezier<P>
where
    P: VectorSpace + serde::Deserialize<'de>,
    P::Scalar: Scalar,
{
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> std::result::Result<Self, D::Error> {
        Bezier::new(Vec::<P>::deserialize(deserializer)?).map_err(serde::de::Error::custom)
    }
}

impl<T: Scalar> BezierCurve<T> {
    /// A curve from coordinate lists.
    pub fn from_coords(coords: Vec<Vec<T>>) -> Result<Self> {
        Self::new(coords.into_iter().map(Point::new).collect::<Result<Vec<_>>>()?)
    }

    /// A curve with integer control points.
    pub fn from_ints(coords: &[&[i64]]) -> Result<Self> {
        Self::new(coords.iter().map(|c| Point::from_ints(c)).collect::<Result<Vec<_>>>()?)
    }

    /// The Bézier form of `Σ_k a_k t^k` on `[0, 1]`; `coeffs[k]` is the vector `a_k`.
    ///
    /// Exact rationals take Newton's forward formula over integers (`exact::power_basis`).
    pub fn from_power(coeffs: &[Point<T>]) -> Result<Self> {
        let dim = common_dimension(coeffs, "a power-basis curve")?;
        if T::CURVE_KERNELS {
            check_degree("degree", coeffs.len() as u128 - 1)?;
            if let Some(points) = T::curve_from_power(coeffs) {
                return Ok(BezierCurve::from_valid(points));
            }
        }
        let per_coord: Vec<Vec<T>> = (0..dim)
            .map(|k| power_to_bernstein(&coeffs.iter().map(|a| a.coords()[k].clone()).collect::<Vec<_>>()))
            .collect::<Result<_>>()?;
        Self::from_coords(
            (0..coeffs.len())
                .map(|i| per_coord.iter().map(|c| c[i].clone()).collect())
                .collect(),
        )
    }

    /// The Bézier form of the polynomial curve `Σ_k a_k u^k`, `a ≤ u ≤ b`, reparametrised by
    /// `u = a + (b - a) t` to `0 ≤ t ≤ 1` (text 000, §1.3); `a = b` is an error.
    pub fn from_power_on(coeffs: &[Point<T>], a: &T, b: &T) -> Result<Self> {
        if a == b {
            return Err(Error::Domain(format!("the parameter interval [{a}, {b}] is empty")));
        }
        let dim = common_dimension(coeffs, "a power-basis curve")?;
        let shifted: Vec<Vec<T>> = (0..dim)
            .map(|k| reparametrize(&coeffs.iter().map(|c| c.coords()[k].clone()).collect::<Vec<_>>(), a, b))
            .collect();
        let points: Vec<Point<T>> = (0..coeffs.len())
            .map(|i| Point::new(shifted.iter().map(|c| c[i].clone()).collect()))
            .collect::<Result<_>>()?;
        Self::from_power(&points)
    }

    /// The power-basis coefficients `a_0..a_n` (vectors) with `b(t) = Σ a_k t^k`.
    ///
    /// Exact rationals take forward differences over integers with one reduction per
    /// coefficient (`exact::power_basis`).
    pub fn to_power(&self) -> Result<Vec<Point<T>>> {
        if T::CURVE_KERNELS {
            check_degree("degree", self.degree() as u128)?;
            if let Some(power) = T::curve_to_power(self.points()) {
                return Ok(power);
            }
        }
        self.to_power_reference()
    }

    /// [`Self::to_power`] by forward differences on the scalar type itself: the reference
    /// for the exact kernel.
    pub fn to_power_reference(&self) -> Result<Vec<Point<T>>> {
        let per_coord: Vec<Vec<T>> = (0..self.dim())
            .map(|k| bernstein_to_power(&self.points.iter().map(|p| p.coords()[k].clone()).collect::<Vec<_>>()))
            .collect::<Result<_>>()?;
        (0..self.points.len())
            .map(|i| Point::new(per_coord.iter().map(|c| c[i].clone()).collect()))
            .collect()
    }

    /// Converts the coordinates to another scalar type (e.g. exact → `f64`).
    pub fn try_map<U: Scalar>(&self, f: impl Fn(&T) -> Result<U> + Copy) -> Result<BezierCurve<U>> {
        BezierCurve::new(self.points.iter().map(|p| p.try_map(f)).collect::<Result<Vec<_>>>()?)
    }

    /// The whole triangular scheme (9) at `t`; over integers
    /// ([`BezierCurve::scheme_fraction_free`]) for exact rationals.
    pub fn scheme(&self, t: &T) -> DeCasteljauScheme<T> {
        if let Some(columns) = T::curve_scheme(self.points(), t) {
            return DeCasteljauScheme { t: t.clone(), columns };
        }
        self.scheme_reference(t)
    }

    /// [`Self::scheme`] by de Casteljau's steps on the scalar type itself: the reference
    /// for the exact kernel.
    pub fn scheme_reference(&self, t: &T) -> DeCasteljauScheme<T> {
        let mut columns = vec![self.points.to_vec()];
        let mut column = self.points.to_vec();
        de_casteljau(&mut column, t, |level| columns.push(level.to_vec()));
        DeCasteljauScheme { t: t.clone(), columns }
    }

    /// The image of the curve under an affine map: the curve of the mapped control points.
    pub fn transform(&self, map: &AffineMap<T>) -> Result<Self> {
        Self::new(map.apply_all(&self.points)?)
    }

    /// Convex weights expressing `p` through the control points when `p` lies in their
    /// convex hull, `None` otherwise (see [`crate::hull::convex_weights`]).
    pub fn hull_weights(&self, p: &Point<T>) -> Result<Option<Vec<T>>> {
        convex_weights(&self.points, p)
    }

    /// Whether `p` lies in the convex hull of the control points.
    pub fn hull_contains(&self, p: &Point<T>) -> Result<bool> {
        Ok(self.hull_weights(p)?.is_some())
    }

    /// The distance between the `r`-times elevated polygon and the curve (Theorem 1.2),
    /// measured at the Greville-like parameters `i/(n+r)`.
    pub fn elevation_distance(&self, r: usize) -> Result<ElevationDistance<T>> {
        Ok(self.distance_of_elevated(&self.elevate_by(r)?, r))
    }

    /// [`Self::elevation_distance`] for `r = 0..=r_max`, elevating one step at a time.
    pub fn elevation_distances(&self, r_max: usize) -> Result<Vec<ElevationDistance<T>>> {
        check_degree("degree after elevation", self.degree() as u128 + r_max as u128)?;
        let mut c = self.clone();
        let mut out = Vec::with_capacity(r_max + 1);
        for r in 0..=r_max {
            if r > 0 {
                c = c.elevate()?;
            }
            out.push(self.distance_of_elevated(&c, r));
        }
        Ok(out)
    }

    /// [`Self::elevation_distance`] of `elevated`, this curve already elevated `r` times.
    pub(crate) fn distance_of_elevated(&self, elevated: &Self, r: usize) -> ElevationDistance<T> {
        let total = elevated.degree();
        let mut max_norm = T::zero();
        let mut max_squared = T::zero();
        for (i, p) in elevated.points.iter().enumerate() {
            let t = if total == 0 {
                T::zero()
            } else {
                T::from_usize(i).checked_div(&T::from_usize(total)).expect("total > 0")
            };
            let on_curve = self.eval(&t);
            let m = p.max_norm_distance(&on_curve);
            let s = p.distance_squared(&on_curve);
            if m > max_norm {
                max_norm = m;
            }
            if s > max_squared {
                max_squared = s;
            }
        }
        ElevationDistance {
            r,
            max_norm,
            max_squared,
        }
    }
}

impl BezierCurve<f64> {
    /// `b(t)` as a fixed-size array, by exactly the steps of [`BezierCurve::eval`] (so the
    /// result is bit-for-bit the same), on the stack for curves of at most 24 points (the
    /// kernel's stack buffer). A dimension other than `D` is an error.
    ///
    /// ```
    /// use casteljau::BezierCurve;
    /// let c: BezierCurve<f64> = BezierCurve::from_ints(&[&[0, 0], &[1, 2], &[3, 2], &[4, 0]]).unwrap();
    /// let p: [f64; 2] = c.eval_array(0.25).unwrap();
    /// assert_eq!(&p[..], c.eval(&0.25).coords());
    /// assert!(c.eval_array::<3>(0.25).is_err());
    /// ```
    pub fn eval_array<const D: usize>(&self, t: f64) -> Result<[f64; D]> {
        if self.dim() != D {
            return Err(Error::DimensionMismatch {
                expected: D,
                found: self.dim(),
                context: "eval_array: the array size must be the curve's dimension".into(),
            });
        }
        let len = self.points.len();
        let point = |i: usize| PointN(std::array::from_fn(|k| self.points[i.min(len - 1)].coords()[k]));
        let eval = |column: &mut [PointN<f64, D>]| {
            de_casteljau(column, &t, |_| {});
            column[0].0
        };
        // Cubics and below get a small buffer: filling the large one would cost as much as
        // the work. A cubic takes the form `eval` takes.
        Ok(if len == CUBIC_POINTS {
            eval_cubic(&std::array::from_fn(point), &t).0
        } else if len <= 4 {
            eval(&mut std::array::from_fn::<_, 4, _>(point)[..len])
        } else if len <= crate::kernel::STACK_POINTS {
            eval(&mut std::array::from_fn::<_, { crate::kernel::STACK_POINTS }, _>(point)[..len])
        } else {
            eval(&mut (0..len).map(point).collect::<Vec<_>>())
        })
    }
}

impl<T: fmt::Display> fmt::Display for BezierCurve<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        PointList(&self.points).fmt(f)
    }
}

#[cfg(test)]
mod tests;
