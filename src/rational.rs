//! Rational Bézier curves and conics (text 001, §1.6).
//!
//! `x(t) = Σ w_i b_i B_i^n(t) / Σ w_i B_i^n(t)`: control points `b_i` with weights `w_i`,
//! of any degree and dimension. Every algorithm works on the homogeneous form: the
//! polynomial curve one dimension up with control points `p_i = (w_i b_i, w_i)`
//! ([`RationalBezierCurve::lift`]), followed by the central projection
//! `(x, w) ↦ x / w` onto the hyperplane `w = 1` — exactly the text's proof of (10), where
//! a conic is the projection of a parabola of `R³` onto `z = 1`.
//!
//! | text 001                                   | here                                        |
//! |--------------------------------------------|---------------------------------------------|
//! | rational quadratic form (10)               | [`RationalBezierCurve::eval`]               |
//! | `p_i = (w_i b_i, w_i)`, `p(t) = (w x, w)`  | [`RationalBezierCurve::lift`], [`RationalBezierCurve::from_homogeneous`] |
//! | equal weights give a parabola              | [`RationalBezierCurve::polynomial`]         |
//! | Fig. 7c: the weights decide the conic      | [`classify_conic`], [`conic_shape_factor`] |
//! | the equations `4x² + 3y² − 10y + 3 = 0` …  | [`implicit_conic`], [`ImplicitConic`]       |
//!
//! Exact scalars ([`crate::BigRational`], [`crate::QuadraticIrrational`] for control points
//! such as `(3, −2√2)`) give exact curves and verdicts; `f64` runs the same code.
//!
//! Zero and negative weights are allowed (all-zero weights are not). Where the denominator
//! `w(t)` vanishes the curve has no point, and [`RationalBezierCurve::eval`] says so. A
//! homogeneous control point `(v, 0)` with `v ≠ 0` (a point at infinity, which elevation or
//! subdivision can produce from weights of mixed signs) has no `(b, w)` form here, and
//! [`RationalBezierCurve::from_homogeneous`] reports it instead of inventing one.
//!
//! ```
//! use casteljau::{RationalBezierCurve, Point, BigRational, Scalar, classify_conic, ConicKind};
//! let q = |p, d| BigRational::from_ratio(p, d).unwrap();
//! // text 001, Example 1: a quarter of the unit circle
//! let arc = RationalBezierCurve::from_ints(&[&[1, 0], &[1, 1], &[0, 1]], &[1, 1, 2]).unwrap();
//! let p = arc.eval(&q(1, 2)).unwrap();
//! assert_eq!(p, Point::new(vec![q(3, 5), q(4, 5)]).unwrap()); // ((1-t²)/(1+t²), 2t/(1+t²))
//! assert_eq!(p.norm_squared(), q(1, 1));
//! assert_eq!(classify_conic(&arc).unwrap(), ConicKind::Ellipse);
//! ```

use crate::bernstein::binomial_row;
use crate::curve::BezierCurve;
use crate::error::{check_degree, Error, Result, MAX_DIMENSION};
use crate::kernel::{casteljau_step, with_column};
use crate::point::{common_dimension, Point};
use crate::quadratic::QuadraticIrrational;
use crate::scalar::{Ring, Scalar};
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::fmt;

/// A rational Bézier curve: control points `b_0..b_n` (one dimension, at least one point)
/// and weights `w_0..w_n`, not all zero.
///
/// It keeps its homogeneous form `(w_i b_i, w_i)` beside the points and weights, so that
/// evaluation, subdivision and elevation run the polynomial algorithms on it directly.
/// Two curves are equal when their points and weights are.
#[derive(Clone, Debug)]
pub struct RationalBezierCurve<T> {
    points: Vec<Point<T>>,
    weights: Vec<T>,
    homogeneous: BezierCurve<T>,
}

impl<T: PartialEq> PartialEq for RationalBezierCurve<T> {
    fn eq(&self, other: &Self) -> bool {
        self.points == other.points && self.weights == other.weights
    }
}

impl<T: Scalar> RationalBezierCurve<T> {
    /// A curve from control points and their weights. Errors: no points, mixed dimensions,
    /// a weight count different from the point count, all weights zero, a degree above
    /// [`crate::MAX_DEGREE`], a dimension that leaves no room for the homogeneous
    /// coordinate, or an invalid scalar ([`Scalar::check`]).
    pub fn new(points: Vec<Point<T>>, weights: Vec<T>) -> Result<Self> {
        Self::validate(&points, &weights)?;
        let homogeneous = Self::homogeneous_of(&points, &weights);
        Ok(RationalBezierCurve {
            points,
            weights,
            homogeneous,
        })
    }

    /// The checks of [`Self::new`].
    fn validate(points: &[Point<T>], weights: &[T]) -> Result<()> {
        let dim = common_dimension(points, "a rational Bézier curve")?;
        check_degree("degree", points.len() as u128 - 1)?;
        if weights.len() != points.len() {
            return Err(Error::WrongCount {
                what: "the weights of a rational Bézier curve (one per control point)",
                needed: points.len(),
                got: weights.len(),
            });
        }
        if dim >= MAX_DIMENSION {
            return Err(Error::TooLarge {
                what: "dimension of a rational curve (its homogeneous form has one more)",
                value: dim.to_string(),
                limit: (MAX_DIMENSION - 1).to_string(),
            });
        }
        for w in weights {
            w.check()?;
        }
        for p in points {
            for c in p.coords() {
                c.check()?;
            }
        }
        if weights.iter().all(Scalar::is_zero) {
            return Err(Error::Domain(
                "all weights of a rational Bézier curve are zero: its denominator vanishes everywhere".into(),
            ));
        }
        Ok(())
    }

    /// The homogeneous control points `(w_i b_i, w_i)` of valid points and weights.
    fn homogeneous_of(points: &[Point<T>], weights: &[T]) -> BezierCurve<T> {
        let lifted = points
            .iter()
            .zip(weights)
            .map(|(p, w)| Point::from_valid(p.coords().iter().map(|c| c.mul_ref(w)).chain([w.clone()])))
            .collect();
        BezierCurve::new(lifted).expect("count, degree and dimension checked in new")
    }

    /// A curve with integer control points and integer weights.
    pub fn from_ints(coords: &[&[i64]], weights: &[i64]) -> Result<Self> {
        let points = coords.iter().map(|c| Point::from_ints(c)).collect::<Result<_>>()?;
        Self::new(points, weights.iter().map(|&w| T::from_i64(w)).collect())
    }

    /// The polynomial curve `c` as a rational one with all weights 1 (the same curve).
    pub fn polynomial(c: &BezierCurve<T>) -> Self {
        Self::new(c.points().to_vec(), vec![T::one(); c.points().len()])
            .expect("a valid polynomial curve with unit weights is a valid rational curve")
    }

    /// The degree `n`.
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }

    /// The dimension of the control points.
    pub fn dim(&self) -> usize {
        self.points[0].dim()
    }

    /// The control points `b_i`.
    pub fn points(&self) -> &[Point<T>] {
        &self.points
    }

    /// The weights `w_i`.
    pub fn weights(&self) -> &[T] {
        &self.weights
    }

    /// Converts every coordinate and weight to another scalar type (e.g. exact → `f64`).
    pub fn try_map<U: Scalar>(&self, f: impl Fn(&T) -> Result<U> + Copy) -> Result<RationalBezierCurve<U>> {
        RationalBezierCurve::new(
            self.points.iter().map(|p| p.try_map(f)).collect::<Result<_>>()?,
            self.weights.iter().map(f).collect::<Result<_>>()?,
        )
    }

    /// The denominator `w(t) = Σ w_i B_i^n(t)`, by de Casteljau on the homogeneous points.
    pub fn weight_at(&self, t: &T) -> T {
        let h = self.homogeneous.eval(t);
        h.coords()[self.dim()].clone()
    }

    fn vanishing(&self, t: &T) -> Error {
        Error::DivisionByZero(format!(
            "the denominator w(t) = Σ w_i B_i(t) of the rational curve vanishes at t = {t}, where the curve has no point"
        ))
    }

    /// `x(t) = Σ w_i b_i B_i(t) / Σ w_i B_i(t)` by de Casteljau on the homogeneous points,
    /// then projection. An error when `w(t) = 0`. Defined for every `t`, not only `[0, 1]`.
    ///
    /// Exact rationals take the nested sum over integers
    /// ([`RationalBezierCurve::eval_nested`]): one reduction per coordinate, no division.
    pub fn eval(&self, t: &T) -> Result<Point<T>> {
        if T::EXACT {
            let exact = (self as &dyn std::any::Any).downcast_ref::<RationalBezierCurve<BigRational>>();
            if let (Some(c), Some(t)) = (exact, crate::exact::dispatch::exact_scalar(t)) {
                let point = c.eval_nested(t)?;
                return Ok(crate::exact::dispatch::scalar_back(point).expect("T is BigRational"));
            }
        }
        self.eval_reference(t)
    }

    /// [`Self::eval`] by de Casteljau's steps on the scalar type itself: the reference the
    /// exact kernel is tested against.
    pub fn eval_reference(&self, t: &T) -> Result<Point<T>> {
        self.project(&self.homogeneous.eval_reference(t), t)
    }

    /// The central projection `(x, w) ↦ x / w` of a homogeneous point of this curve at `t`.
    fn project(&self, h: &Point<T>, t: &T) -> Result<Point<T>> {
        let (w, x) = h
            .coords()
            .split_last()
            .expect("the homogeneous point has dim + 1 ≥ 2 coordinates");
        if w.is_zero() {
            return Err(self.vanishing(t));
        }
        Point::new(x.iter().map(|c| c.checked_div(w)).collect::<Result<_>>()?)
    }

    /// The polynomial curve one dimension up with control points `p_i = (w_i b_i, w_i)`
    /// (the text's proof of (10)); its central projection is `self`.
    pub fn lift(&self) -> BezierCurve<T> {
        self.homogeneous.clone()
    }

    /// The homogeneous form, borrowed.
    pub fn homogeneous(&self) -> &BezierCurve<T> {
        &self.homogeneous
    }

    /// The rational curve whose homogeneous form is `c`: the last coordinate of each control
    /// point is the weight `w_i`, the others are `w_i b_i`. A control point `(0, 0)` becomes
    /// `b_i = 0` with weight 0; `(v, 0)` with `v ≠ 0` (a point at infinity) is an error, as
    /// are fewer than two coordinates and all weights zero.
    pub fn from_homogeneous(c: &BezierCurve<T>) -> Result<Self> {
        Self::from_homogeneous_owned(c.clone())
    }

    /// [`Self::from_homogeneous`], keeping `c` itself as the homogeneous form.
    fn from_homogeneous_owned(c: BezierCurve<T>) -> Result<Self> {
        if c.dim() < 2 {
            return Err(Error::Domain(format!(
                "a homogeneous curve needs at least 2 coordinates (point and weight), it has {}",
                c.dim()
            )));
        }
        let mut points = Vec::with_capacity(c.points().len());
        let mut weights = Vec::with_capacity(c.points().len());
        for (i, p) in c.points().iter().enumerate() {
            let (w, v) = p.coords().split_last().expect("dimension at least 2 checked above");
            if w.is_zero() {
                if v.iter().any(|x| !x.is_zero()) {
                    return Err(Error::Domain(format!(
                        "homogeneous control point {i} {p} has weight 0: a point at infinity has no (b, w) form"
                    )));
                }
                points.push(Point::origin(v.len()));
            } else {
                points.push(Point::new(v.iter().map(|x| x.checked_div(w)).collect::<Result<_>>()?)?);
            }
            weights.push(w.clone());
        }
        Self::validate(&points, &weights)?;
        Ok(RationalBezierCurve {
            points,
            weights,
            homogeneous: c,
        })
    }

    /// One step of degree elevation, done on the homogeneous form: the same curve with
    /// `n + 2` control points.
    pub fn elevate(&self) -> Result<Self> {
        Self::from_homogeneous_owned(self.homogeneous.elevate()?)
    }

    /// `r` steps of degree elevation at once, on the homogeneous form.
    pub fn elevate_by(&self, r: usize) -> Result<Self> {
        Self::from_homogeneous_owned(self.homogeneous.elevate_by(r)?)
    }

    /// Subdivision at `t0` on the homogeneous form: the pieces `x(t0 t)` and
    /// `x(t0 + (1 - t0) t)`. An error when `w(t0) = 0` (the shared end point does not exist).
    pub fn split_at(&self, t0: &T) -> Result<(Self, Self)> {
        let (left, right) = self.homogeneous.split_at(t0);
        if left.points()[self.degree()].coords()[self.dim()].is_zero() {
            return Err(self.vanishing(t0));
        }
        Ok((
            Self::from_homogeneous_owned(left)?,
            Self::from_homogeneous_owned(right)?,
        ))
    }

    /// The first derivative `x'(t) = (P'(t) w(t) - P(t) w'(t)) / w(t)²`, with `P = w x` and
    /// `w` from the last-but-one column of the homogeneous de Casteljau scheme. Exact for
    /// exact scalars; an error when `w(t) = 0`.
    pub fn derivative_at(&self, t: &T) -> Result<Point<T>> {
        let h = self.dim() + 1;
        let n = self.degree();
        if n == 0 {
            if self.weights[0].is_zero() {
                return Err(self.vanishing(t));
            }
            return Ok(Point::origin(self.dim()));
        }
        // The last-but-one column of the scheme: h0, h1 with H(t) = (1 - t) h0 + t h1 and
        // H'(t) = n (h1 - h0).
        let (h0, h1) = with_column(self.homogeneous.points(), |column| {
            for len in (2..column.len()).rev() {
                casteljau_step(&mut column[..=len], t);
            }
            (column[0].clone(), column[1].clone())
        });
        let (col0, col1) = (h0.coords(), h1.coords());
        let nn = T::from_usize(n);
        let value: Vec<T> = (0..h)
            .map(|k| col0[k].add_ref(&t.mul_ref(&col1[k].sub_ref(&col0[k]))))
            .collect();
        let slope: Vec<T> = (0..h).map(|k| nn.mul_ref(&col1[k].sub_ref(&col0[k]))).collect();
        let (w, dw) = (&value[h - 1], &slope[h - 1]);
        if w.is_zero() {
            return Err(self.vanishing(t));
        }
        let w2 = w.mul_ref(w);
        Point::new(
            (0..h - 1)
                .map(|k| slope[k].mul_ref(w).sub_ref(&value[k].mul_ref(dw)).checked_div(&w2))
                .collect::<Result<_>>()?,
        )
    }

    /// The same curve, same parametrisation, with every weight multiplied by `s ≠ 0`.
    pub fn scale_weights(&self, s: &T) -> Result<Self> {
        if s.is_zero() {
            return Err(Error::Domain("scaling the weights by 0 leaves no curve".into()));
        }
        Self::new(self.points.clone(), self.weights.iter().map(|w| w.mul_ref(s)).collect())
    }

    /// The same curve with `w_0 = 1` (weights divided by `w_0`); an error when `w_0 = 0`.
    pub fn with_unit_first_weight(&self) -> Result<Self> {
        let w0 = &self.weights[0];
        if w0.is_zero() {
            return Err(Error::Domain("w_0 = 0 cannot be scaled to 1".into()));
        }
        Self::new(
            self.points.clone(),
            self.weights.iter().map(|w| w.checked_div(w0)).collect::<Result<_>>()?,
        )
    }

    /// Weights `w_i c^i` (`c ≠ 0`): the same curve under the parameter change
    /// `u = c t / ((1 - t) + c t)`, i.e. the new curve at `t` is the old one at `u`. For
    /// `c > 0` this maps `[0, 1]` onto itself, so the arc is kept.
    ///
    /// ```
    /// use casteljau::{RationalBezierCurve, BigRational, Scalar};
    /// let q = |p, d| BigRational::from_ratio(p, d).unwrap();
    /// let c = RationalBezierCurve::from_ints(&[&[1, 0], &[1, 1], &[0, 1]], &[1, 1, 2]).unwrap();
    /// let r = c.reparametrize_weights(&q(3, 1)).unwrap();
    /// assert_eq!(r.weights(), &[q(1, 1), q(3, 1), q(18, 1)]);
    /// let t = q(1, 3); // u = 1 / (2/3 + 1) = 3/5
    /// assert_eq!(r.eval(&t).unwrap(), c.eval(&q(3, 5)).unwrap());
    /// ```
    pub fn reparametrize_weights(&self, c: &T) -> Result<Self> {
        if c.is_zero() {
            return Err(Error::Domain(
                "the weight reparametrisation factor c must not be 0".into(),
            ));
        }
        let mut power = T::one();
        let mut weights = Vec::with_capacity(self.weights.len());
        for w in &self.weights {
            weights.push(w.mul_ref(&power));
            power *= c;
        }
        Self::new(self.points.clone(), weights)
    }

    fn conic_weights(&self) -> Result<(&T, &T, &T)> {
        match self.weights.as_slice() {
            [w0, w1, w2] => Ok((w0, w1, w2)),
            _ => Err(Error::WrongCount {
                what: "a conic (rational quadratic arc)",
                needed: 3,
                got: self.points.len(),
            }),
        }
    }
}

/// Exact square roots where the scalar type has them, for the standard form of a conic.
pub trait ExactSqrt: Sized {
    /// The non-negative square root of `self`, or an error when it is not representable
    /// exactly in this type (or `self < 0`).
    fn exact_sqrt(&self) -> Result<Self>;
}

impl ExactSqrt for f64 {
    fn exact_sqrt(&self) -> Result<Self> {
        if *self < 0.0 || !self.is_finite() {
            return Err(Error::Domain(format!("no real square root of {self}")));
        }
        Ok(self.sqrt())
    }
}

fn bigint_sqrt(n: &BigInt) -> Option<BigInt> {
    if n.is_negative() {
        return None;
    }
    let r = n.sqrt();
    (&r * &r == *n).then_some(r)
}

fn rational_sqrt(r: &BigRational) -> Option<BigRational> {
    Some(BigRational::new(bigint_sqrt(r.numer())?, bigint_sqrt(r.denom())?))
}

impl ExactSqrt for BigRational {
    fn exact_sqrt(&self) -> Result<Self> {
        rational_sqrt(self).ok_or_else(|| {
            Error::Domain(format!(
                "{self} is not the square of a rational (use QuadraticIrrational for an exact root)"
            ))
        })
    }
}

impl ExactSqrt for QuadraticIrrational {
    /// Rationals `r ≥ 0` always have a root (`√r` lies in `Q(√r)`); `a + b√d` has one in its
    /// field when `a + b√d = (x + y√d)²` with rational `x, y`, `x + y√d ≥ 0`.
    fn exact_sqrt(&self) -> Result<Self> {
        self.check()?;
        let not_square = || Error::Domain(format!("{self} has no square root in its quadratic field"));
        if *self < Self::zero() {
            return Err(Error::Domain(format!("no real square root of {self}")));
        }
        let (a, b, d) = self.parts()?;
        let Some(d) = d else {
            return QuadraticIrrational::sqrt_rational(a);
        };
        if d < 0 {
            return Err(not_square());
        }
        // (x + y√d)² = x² + d y² + 2xy√d: x² = (a ± √(a² - b²d)) / 2, y = b / (2x).
        let root_norm = rational_sqrt(&self.norm()).ok_or_else(not_square)?;
        let two = BigRational::from_integer(2.into());
        for x2 in [(a + &root_norm) / &two, (a - &root_norm) / &two] {
            if let Some(x) = rational_sqrt(&x2).filter(|x| !Zero::is_zero(x)) {
                let y = b / (&two * &x);
                let candidate = QuadraticIrrational::new(x, y, d)?;
                let root = Scalar::abs(&candidate);
                if &(&root * &root) == self {
                    return Ok(root);
                }
            }
        }
        Err(not_square())
    }
}

impl<T: Scalar + ExactSqrt> RationalBezierCurve<T> {
    /// The standard form of a conic arc, `w_0 = w_2 = 1`: the same arc (reparametrised by
    /// [`Self::reparametrize_weights`] with `c = √(w_0/w_2) > 0`, then scaled), with middle
    /// weight `±w_1/√(w_0 w_2)`. Needs `w_0 w_2 > 0` and a root that exists exactly in `T`
    /// (always for [`QuadraticIrrational`] with rational weights).
    ///
    /// ```
    /// use casteljau::{RationalBezierCurve, BigRational, QuadraticIrrational, Scalar};
    /// let c = RationalBezierCurve::<QuadraticIrrational>::from_ints(&[&[1, 0], &[1, 1], &[0, 1]], &[1, 1, 2]).unwrap();
    /// let s = c.conic_standard_form().unwrap();
    /// assert_eq!(s.weights()[1].to_string(), "1/2*sqrt(2)"); // the circle's cos 45°
    /// ```
    pub fn conic_standard_form(&self) -> Result<Self> {
        let (w0, _, w2) = self.conic_weights()?;
        if w0.is_zero() || w2.is_zero() || (w0.mul_ref(w2)) < T::zero() {
            return Err(Error::Domain(format!(
                "the standard form w0 = w2 = 1 needs w0·w2 > 0, the weights are {w0}, {w2}"
            )));
        }
        let c = w0.checked_div(w2)?.exact_sqrt()?;
        let mut out = self.reparametrize_weights(&c)?.with_unit_first_weight()?;
        // c² w2 / w0 = 1 in exact arithmetic; pin the end weight to 1 so f64 rounding does
        // not leave 0.9999999999999999 behind.
        out.weights[2] = T::one();
        Self::new(out.points, out.weights)
    }
}

/// The affine type of a conic, or why the arc or the conic is degenerate.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ConicKind {
    /// No real points at infinity (`w_1² < w_0 w_2`, `B² − 4AC < 0`).
    Ellipse,
    /// One (double) point at infinity (`w_1² = w_0 w_2`, `B² − 4AC = 0`).
    Parabola,
    /// Two real points at infinity (`w_1² > w_0 w_2`, `B² − 4AC > 0`).
    Hyperbola,
    /// The three control points are collinear (or coincide): the arc lies on a line.
    DegenerateCollinear,
    /// Some weight is zero (the control points are not collinear): the arc lies on a
    /// line, and the conic through it is a pair of lines or a double line.
    DegenerateZeroWeight,
    /// An implicit conic whose 3×3 matrix is singular: a pair of lines, a double line or a
    /// point (only from [`ImplicitConic::kind`]).
    DegenerateSingular,
}

impl ConicKind {
    /// `"ellipse"`, `"parabola"`, `"hyperbola"`, or `"degenerate (...)"`.
    pub fn as_str(&self) -> &'static str {
        match self {
            ConicKind::Ellipse => "ellipse",
            ConicKind::Parabola => "parabola",
            ConicKind::Hyperbola => "hyperbola",
            ConicKind::DegenerateCollinear => "degenerate (collinear control points)",
            ConicKind::DegenerateZeroWeight => "degenerate (zero weight)",
            ConicKind::DegenerateSingular => "degenerate (singular conic)",
        }
    }

    /// Whether this is one of the degenerate cases.
    pub fn is_degenerate(&self) -> bool {
        !matches!(self, ConicKind::Ellipse | ConicKind::Parabola | ConicKind::Hyperbola)
    }
}

impl fmt::Display for ConicKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// Whether `b0, b1, b2` lie on one line (any dimension): the Gram determinant of
/// `b1 - b0, b2 - b0` vanishes.
fn collinear<T: Scalar>(p: &[Point<T>]) -> bool {
    let u = p[1].sub(&p[0]);
    let v = p[2].sub(&p[0]);
    let uv = u.dot(&v);
    (u.norm_squared().mul_ref(&v.norm_squared()) - uv.mul_ref(&uv)).is_zero()
}

/// The shape invariant `w_1² / (w_0 w_2)` of a conic arc: unchanged by scaling the weights
/// and by [`RationalBezierCurve::reparametrize_weights`]; `< 1` ellipse, `= 1` parabola,
/// `> 1` hyperbola (for non-collinear control points and non-zero weights). An error when
/// `w_0 w_2 = 0` or the curve is not quadratic.
pub fn conic_shape_factor<T: Scalar>(c: &RationalBezierCurve<T>) -> Result<T> {
    let (w0, w1, w2) = c.conic_weights()?;
    w1.mul_ref(w1).checked_div(&w0.mul_ref(w2))
}

/// Classifies the conic carrying a rational quadratic arc by its weights (text 001, Fig. 7c).
///
/// Collinear control points give [`ConicKind::DegenerateCollinear`], otherwise a zero weight
/// gives [`ConicKind::DegenerateZeroWeight`]. Otherwise the conic is non-degenerate and its
/// points at infinity are the roots of `w(t)`, so the sign of `w_1² − w_0 w_2` decides:
/// ellipse, parabola, hyperbola. This holds for weights of any signs: a negative weight
/// does not change the conic's type, only which of its arcs is traced on `[0, 1]` (see
/// [`conic_arc_passes_infinity`]). Exact for exact scalars; for `f64` the tests `= 0` are
/// float comparisons. Errors: not exactly three control points.
///
/// ```
/// use casteljau::{classify_conic, ConicKind, RationalBezierCurve, BigRational};
/// let pts: &[&[i64]] = &[&[-1, 1], &[0, -1], &[1, 1]];
/// let kind = |w: &[i64]| classify_conic(&RationalBezierCurve::<BigRational>::from_ints(pts, w).unwrap()).unwrap();
/// assert_eq!(kind(&[2, 1, 2]), ConicKind::Ellipse);
/// assert_eq!(kind(&[1, 1, 1]), ConicKind::Parabola);
/// assert_eq!(kind(&[1, 2, 1]), ConicKind::Hyperbola);
/// assert_eq!(kind(&[1, 0, 1]), ConicKind::DegenerateZeroWeight);
/// ```
pub fn classify_conic<T: Scalar>(c: &RationalBezierCurve<T>) -> Result<ConicKind> {
    let (w0, w1, w2) = c.conic_weights()?;
    if collinear(c.points()) {
        return Ok(ConicKind::DegenerateCollinear);
    }
    if w0.is_zero() || w1.is_zero() || w2.is_zero() {
        return Ok(ConicKind::DegenerateZeroWeight);
    }
    let excess = w1.mul_ref(w1).sub_ref(&w0.mul_ref(w2));
    Ok(if excess.is_zero() {
        ConicKind::Parabola
    } else if excess > T::zero() {
        ConicKind::Hyperbola
    } else {
        ConicKind::Ellipse
    })
}

/// Whether the denominator `w(t)` of a rational quadratic arc vanishes somewhere on
/// `[0, 1]`, so that the arc runs through infinity. Never for positive weights (the arc then
/// lies in the triangle of its control points). Decided exactly by signs: with `w_0, w_2`
/// of one sign, a root in `(0, 1)` exists iff `w_1` has the other sign and `w_1² ≥ w_0 w_2`.
pub fn conic_arc_passes_infinity<T: Scalar>(c: &RationalBezierCurve<T>) -> Result<bool> {
    let (w0, w1, w2) = c.conic_weights()?;
    let zero = T::zero();
    if w0.is_zero() || w2.is_zero() || (w0.mul_ref(w2)) < zero {
        return Ok(true);
    }
    let opposite = (w0.mul_ref(w1)) < zero;
    Ok(opposite && w1.mul_ref(w1) >= w0.mul_ref(w2))
}

/// A conic `A x² + B xy + C y² + D x + E y + F = 0`.
#[derive(Clone, Debug, PartialEq)]
pub struct ImplicitConic<T> {
    /// coefficient of `x²`
    pub a: T,
    /// coefficient of `xy`
    pub b: T,
    /// coefficient of `y²`
    pub c: T,
    /// coefficient of `x`
    pub d: T,
    /// coefficient of `y`
    pub e: T,
    /// constant term
    pub f: T,
}

impl<T: Scalar> ImplicitConic<T> {
    /// The conic with coefficients `[A, B, C, D, E, F]`.
    pub fn from_coefficients([a, b, c, d, e, f]: [T; 6]) -> Self {
        ImplicitConic { a, b, c, d, e, f }
    }

    /// The conic with integer coefficients `[A, B, C, D, E, F]`.
    pub fn from_ints(k: [i64; 6]) -> Self {
        Self::from_coefficients(k.map(T::from_i64))
    }

    /// `[A, B, C, D, E, F]`.
    pub fn coefficients(&self) -> [T; 6] {
        [
            self.a.clone(),
            self.b.clone(),
            self.c.clone(),
            self.d.clone(),
            self.e.clone(),
            self.f.clone(),
        ]
    }

    /// `A x² + B xy + C y² + D x + E y + F`.
    pub fn eval(&self, x: &T, y: &T) -> T {
        // (A x + B y + D) x + (C y + E) y + F
        let lin_x = self.a.mul_ref(x).add_ref(&self.b.mul_ref(y)).add_ref(&self.d);
        let lin_y = self.c.mul_ref(y).add_ref(&self.e);
        lin_x.mul_ref(x).add_ref(&lin_y.mul_ref(y)).add_ref(&self.f)
    }

    /// `B² − 4AC`: negative for an ellipse, zero for a parabola, positive for a hyperbola
    /// (for a non-degenerate conic).
    pub fn discriminant(&self) -> T {
        self.b
            .mul_ref(&self.b)
            .sub_ref(&T::from_i64(4).mul_ref(&self.a.mul_ref(&self.c)))
    }

    /// `det [[2A, B, D], [B, 2C, E], [D, E, 2F]]` (8 times the determinant of the conic's
    /// symmetric matrix): zero exactly for degenerate conics (line pairs, double lines,
    /// points).
    pub fn matrix_determinant(&self) -> T {
        let two = T::from_i64(2);
        let (a2, c2, f2) = (two.mul_ref(&self.a), two.mul_ref(&self.c), two.mul_ref(&self.f));
        let (b, d, e) = (&self.b, &self.d, &self.e);
        let m1 = c2.mul_ref(&f2).sub_ref(&e.mul_ref(e));
        let m2 = b.mul_ref(&f2).sub_ref(&e.mul_ref(d));
        let m3 = b.mul_ref(e).sub_ref(&c2.mul_ref(d));
        a2.mul_ref(&m1).sub_ref(&b.mul_ref(&m2)).add_ref(&d.mul_ref(&m3))
    }

    /// The affine type by `B² − 4AC`, or [`ConicKind::DegenerateSingular`] when
    /// [`Self::matrix_determinant`] is zero.
    pub fn kind(&self) -> ConicKind {
        if self.matrix_determinant().is_zero() {
            return ConicKind::DegenerateSingular;
        }
        let disc = self.discriminant();
        if disc.is_zero() {
            ConicKind::Parabola
        } else if disc > T::zero() {
            ConicKind::Hyperbola
        } else {
            ConicKind::Ellipse
        }
    }

    /// Whether every coefficient is zero (the equation `0 = 0`, not a conic).
    pub fn is_zero(&self) -> bool {
        self.coefficients().iter().all(Scalar::is_zero)
    }

    /// The same conic scaled so that the first non-zero of `A, …, F` is 1 (the normal form
    /// [`implicit_conic`] returns). An error for the zero equation.
    pub fn normalized(&self) -> Result<Self> {
        let k = self.coefficients();
        let lead = k
            .iter()
            .find(|x| !x.is_zero())
            .ok_or_else(|| Error::Domain("the zero equation 0 = 0 is not a conic".into()))?;
        Ok(Self::from_coefficients(
            k.iter()
                .map(|x| x.checked_div(lead))
                .collect::<Result<Vec<_>>>()?
                .try_into()
                .expect("six coefficients in, six out"),
        ))
    }

    /// Whether `self = λ · other` for some `λ ≠ 0`, i.e. both describe the same conic
    /// equation (exactly, for exact scalars: all 2×2 minors of the coefficient pair vanish).
    /// The zero equation is a multiple of nothing.
    ///
    /// ```
    /// use casteljau::{ImplicitConic, BigRational};
    /// let printed = ImplicitConic::<BigRational>::from_ints([4, 0, 3, 0, -10, 3]);
    /// assert!(printed.is_multiple_of(&ImplicitConic::from_ints([-8, 0, -6, 0, 20, -6])));
    /// assert!(!printed.is_multiple_of(&ImplicitConic::from_ints([4, 0, 3, 0, -10, 2])));
    /// ```
    pub fn is_multiple_of(&self, other: &ImplicitConic<T>) -> bool {
        if self.is_zero() || other.is_zero() {
            return false;
        }
        let (s, o) = (self.coefficients(), other.coefficients());
        (0..6).all(|i| (i + 1..6).all(|j| s[i].mul_ref(&o[j]) == s[j].mul_ref(&o[i])))
    }

    /// [`Self::is_multiple_of`] for floats: both divided by their coefficient at the index
    /// where `self` is largest in magnitude, then compared coefficient by coefficient within
    /// `tol`.
    pub fn approx_multiple_of(&self, other: &ImplicitConic<T>, tol: f64) -> bool {
        let s: Vec<f64> = self.coefficients().iter().map(Scalar::to_f64).collect();
        let o: Vec<f64> = other.coefficients().iter().map(Scalar::to_f64).collect();
        let Some(i) = (0..6).max_by(|&i, &j| s[i].abs().total_cmp(&s[j].abs())) else {
            return false;
        };
        let (si, oi) = (s[i], o[i]);
        if si == 0.0 || oi == 0.0 || !si.is_finite() || !oi.is_finite() {
            return false;
        }
        s.iter().zip(&o).all(|(x, y)| (x / si - y / oi).abs() <= tol)
    }
}

impl ImplicitConic<BigRational> {
    /// The coefficients as coprime integers with the first non-zero one positive: the way
    /// textbooks print them (`4x² + 3y² − 10y + 3 = 0`). All zero for the zero equation.
    pub fn to_primitive_integers(&self) -> [BigInt; 6] {
        let k = self.coefficients();
        let lcm = k.iter().fold(BigInt::from(1), |l, x| l.lcm(x.denom()));
        let ints: Vec<BigInt> = k
            .iter()
            .map(|x| (x * BigRational::from_integer(lcm.clone())).to_integer())
            .collect();
        let mut g = ints.iter().fold(BigInt::zero(), |g, x| g.gcd(x));
        if Zero::is_zero(&g) {
            return ints.try_into().expect("six coefficients");
        }
        if ints
            .iter()
            .find(|x| !Zero::is_zero(*x))
            .is_some_and(|x| x.is_negative())
        {
            g = -g;
        }
        ints.iter()
            .map(|x| x / &g)
            .collect::<Vec<_>>()
            .try_into()
            .expect("six coefficients")
    }
}

impl<T: fmt::Display + Scalar> fmt::Display for ImplicitConic<T> {
    /// `4*x^2 + 3*y^2 - 10*y + 3 = 0`; compound coefficients are parenthesised.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let monomials = ["x^2", "x*y", "y^2", "x", "y", ""];
        let mut first = true;
        for (k, m) in self.coefficients().iter().zip(monomials) {
            if k.is_zero() {
                continue;
            }
            let text = k.to_string();
            let (negative, magnitude) = match text.strip_prefix('-') {
                Some(rest) if !rest.contains([' ', '+', '-']) => (true, rest.to_string()),
                _ if text.contains(' ') => (false, format!("({text})")),
                _ => (false, text.clone()),
            };
            if first {
                write!(f, "{}", if negative { "-" } else { "" })?;
            } else {
                write!(f, " {} ", if negative { '-' } else { '+' })?;
            }
            first = false;
            match (magnitude.as_str(), m) {
                (_, "") => write!(f, "{magnitude}")?,
                ("1", _) => write!(f, "{m}")?,
                _ => write!(f, "{magnitude}*{m}")?,
            }
        }
        if first {
            write!(f, "0")?;
        }
        write!(f, " = 0")
    }
}

/// `α x + β y + γ` as a triple.
type Affine<T> = [T; 3];

fn affine_product<T: Scalar>(p: &Affine<T>, q: &Affine<T>) -> [T; 6] {
    [
        p[0].mul_ref(&q[0]),
        p[0].mul_ref(&q[1]).add_ref(&p[1].mul_ref(&q[0])),
        p[1].mul_ref(&q[1]),
        p[0].mul_ref(&q[2]).add_ref(&p[2].mul_ref(&q[0])),
        p[1].mul_ref(&q[2]).add_ref(&p[2].mul_ref(&q[1])),
        p[2].mul_ref(&q[2]),
    ]
}

/// `Δ · τ` for the barycentric coordinate belonging to the vertex opposite `(u, v)`:
/// `det(u - P, v - P)` as an affine function of `P = (x, y)`.
fn scaled_barycentric<T: Scalar>(u: &[T], v: &[T]) -> Affine<T> {
    // (u_x - x)(v_y - y) - (v_x - x)(u_y - y)
    [
        u[1].sub_ref(&v[1]),
        v[0].sub_ref(&u[0]),
        u[0].mul_ref(&v[1]).sub_ref(&v[0].mul_ref(&u[1])),
    ]
}

/// The exact implicit equation of the conic carrying a planar rational quadratic arc,
/// normalised so that the first non-zero of `A, …, F` is 1 (compare with a printed equation
/// by [`ImplicitConic::is_multiple_of`]; for rationals [`ImplicitConic::to_primitive_integers`]
/// gives the textbook form).
///
/// With barycentric coordinates `τ_i` of `(x, y)` with respect to `b_0 b_1 b_2`, the arc has
/// `τ_i = w_i B_i(t) / w(t)`, so `τ_0 τ_2 = w_0 w_2 t²(1-t)² / w²` and `τ_1² = 4 w_1² t²(1-t)² / w²`:
/// the conic is `4 w_1² τ_0 τ_2 − w_0 w_2 τ_1² = 0`. Multiplying out `Δ τ_i` (affine in
/// `x, y`, `Δ` twice the signed area) gives `A..F` exactly.
///
/// Errors: not three control points, not 2-D, collinear control points (the arc lies on a
/// line; no unique conic), or `w_1 = 0 = w_0 w_2` (every point satisfies the equation).
///
/// ```
/// use casteljau::{implicit_conic, ImplicitConic, RationalBezierCurve, BigRational};
/// // text 001, Example 3
/// let arc = RationalBezierCurve::<BigRational>::new(
///     vec![casteljau::Point::from_ints(&[-1, 1]).unwrap(), casteljau::Point::from_ints(&[0, -1]).unwrap(),
///          casteljau::Point::from_ints(&[1, 1]).unwrap()],
///     vec![BigRational::from_integer(1.into()), BigRational::new(1.into(), 2.into()), BigRational::from_integer(1.into())],
/// ).unwrap();
/// let conic = implicit_conic(&arc).unwrap();
/// assert!(conic.is_multiple_of(&ImplicitConic::from_ints([4, 0, 3, 0, -10, 3])));
/// assert_eq!(conic.to_primitive_integers().map(|k| k.to_string()), ["4", "0", "3", "0", "-10", "3"]);
/// ```
pub fn implicit_conic<T: Scalar>(c: &RationalBezierCurve<T>) -> Result<ImplicitConic<T>> {
    let (w0, w1, w2) = c.conic_weights()?;
    if c.dim() != 2 {
        return Err(Error::DimensionMismatch {
            expected: 2,
            found: c.dim(),
            context: "the implicit equation of a conic needs planar control points".into(),
        });
    }
    let p = c.points();
    if collinear(p) {
        return Err(Error::Domain(
            "the control points are collinear: the arc lies on a line and no unique conic carries it".into(),
        ));
    }
    let (b0, b1, b2) = (p[0].coords(), p[1].coords(), p[2].coords());
    let l0 = scaled_barycentric(b1, b2);
    let l1 = scaled_barycentric(b2, b0);
    let l2 = scaled_barycentric(b0, b1);
    let four_w1_sq = T::from_i64(4).mul_ref(&w1.mul_ref(w1));
    let w0w2 = w0.mul_ref(w2);
    let p02 = affine_product(&l0, &l2);
    let p11 = affine_product(&l1, &l1);
    let k: Vec<T> = p02
        .iter()
        .zip(&p11)
        .map(|(x, y)| four_w1_sq.mul_ref(x).sub_ref(&w0w2.mul_ref(y)))
        .collect();
    let conic = ImplicitConic::from_coefficients(k.try_into().expect("six coefficients"));
    if conic.is_zero() {
        return Err(Error::Domain(
            "w1 = 0 and w0·w2 = 0: the arc degenerates to a control point and carries no conic equation".into(),
        ));
    }
    conic.normalized()
}

impl<T: Scalar> crate::param::ParamCurve for RationalBezierCurve<T> {
    type Scalar = T;
    type Point = Point<T>;

    fn eval(&self, t: &T) -> Result<Point<T>> {
        RationalBezierCurve::eval(self, t)
    }
    fn split_at(&self, t0: &T) -> Result<(Self, Self)> {
        RationalBezierCurve::split_at(self, t0)
    }
    fn degree(&self) -> usize {
        RationalBezierCurve::degree(self)
    }
}

/// The derivative of a rational curve of degree `n` is rational of degree `2n`:
/// `ẋ = (Ẋ W − X Ẇ) / W²` with `(X, W)` the homogeneous form.
impl<T: Scalar> crate::param::ParamCurveDeriv for RationalBezierCurve<T> {
    type Deriv = Self;

    /// An error when a Bernstein coefficient of `W²` vanishes where the numerator's does not
    /// (a control point at infinity, see [`RationalBezierCurve::from_homogeneous`]).
    fn deriv(&self) -> Result<Self> {
        let n = self.degree();
        let dim = self.dim();
        if n == 0 {
            return Self::new(vec![Point::origin(dim)], vec![T::one()]);
        }
        let h = self.homogeneous.points();
        let x: Vec<Point<T>> = h
            .iter()
            .map(|p| Point::from_valid(p.coords()[..dim].iter().cloned()))
            .collect();
        let w: Vec<T> = h.iter().map(|p| p.coords()[dim].clone()).collect();
        let nn = T::from_usize(n);
        let dx: Vec<Point<T>> = x.windows(2).map(|p| p[1].sub(&p[0]).scale(&nn)).collect();
        let dw: Vec<T> = w.windows(2).map(|p| nn.mul_ref(&p[1].sub_ref(&p[0]))).collect();
        // Ẋ W − X Ẇ has degree 2n − 1; one elevation brings it to W²'s degree 2n.
        let first = bernstein_product(&dx, &w)?;
        let second = bernstein_product(&x, &dw)?;
        let numerator: Vec<Point<T>> = first.iter().zip(&second).map(|(a, b)| a.sub(b)).collect();
        let numerator = BezierCurve::new(numerator)?.elevate()?;
        let w_points: Vec<Point<T>> = w.iter().map(|c| Point::from_valid([c.clone()])).collect();
        let denominator = bernstein_product(&w_points, &w)?;
        let lifted = numerator
            .points()
            .iter()
            .zip(&denominator)
            .map(|(a, d)| Point::from_valid(a.coords().iter().chain(d.coords()).cloned()))
            .collect();
        Self::from_homogeneous_owned(BezierCurve::new(lifted)?)
    }

    fn deriv_at(&self, t: &T) -> Result<Point<T>> {
        self.derivative_at(t)
    }
}

/// The Bernstein coefficients of the product of `Σ a_i B_i^m` and `Σ b_j B_j^p`:
/// `c_k = Σ_{i+j=k} C(m,i) C(p,j) / C(m+p,k) b_j a_i`.
fn bernstein_product<T: Scalar>(a: &[Point<T>], b: &[T]) -> Result<Vec<Point<T>>> {
    let (m, p) = (a.len() - 1, b.len() - 1);
    let (cm, cp, cmp) = (binomial_row(m), binomial_row(p), binomial_row(m + p));
    (0..=m + p)
        .map(|k| {
            let mut acc = Point::origin(a[0].dim());
            for i in k.saturating_sub(p)..=k.min(m) {
                let j = k - i;
                let c = T::from_rational(&BigRational::new(&cm[i] * &cp[j], cmp[k].clone()))?;
                acc.add_scaled_assign(&c.mul_ref(&b[j]), &a[i]);
            }
            Ok(acc)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    type Q = BigRational;

    fn q(p: i64, d: i64) -> Q {
        Q::new(p.into(), d.into())
    }

    fn arc(w: &[i64]) -> RationalBezierCurve<Q> {
        RationalBezierCurve::from_ints(&[&[-1, 1], &[0, -1], &[1, 1]], w).unwrap()
    }

    #[test]
    fn bad_input_is_an_error() {
        let pts = vec![
            Point::<Q>::from_ints(&[0, 0]).unwrap(),
            Point::from_ints(&[1, 0]).unwrap(),
        ];
        assert!(RationalBezierCurve::new(pts.clone(), vec![q(1, 1)]).is_err());
        assert!(RationalBezierCurve::new(pts.clone(), vec![q(0, 1), q(0, 1)]).is_err());
        assert!(RationalBezierCurve::<Q>::new(vec![], vec![]).is_err());
        let line = RationalBezierCurve::new(pts, vec![q(1, 1), q(-1, 1)]).unwrap();
        assert!(matches!(line.eval(&q(1, 2)), Err(Error::DivisionByZero(_))));
        assert!(line.derivative_at(&q(1, 2)).is_err());
        assert!(line.split_at(&q(1, 2)).is_err());
        // (1, -1) elevates to weights (1, 0, -1) with a point at infinity in the middle.
        assert!(line.elevate().is_err());
        assert!(classify_conic(&line).is_err());
        assert!(implicit_conic(&line).is_err());
        let space = RationalBezierCurve::<Q>::from_ints(&[&[0, 0, 0], &[1, 0, 0], &[0, 1, 0]], &[1, 1, 1]).unwrap();
        assert!(matches!(implicit_conic(&space), Err(Error::DimensionMismatch { .. })));
        assert_eq!(classify_conic(&space).unwrap(), ConicKind::Parabola);
        let flat = RationalBezierCurve::<Q>::from_ints(&[&[0, 0], &[1, 1], &[3, 3]], &[1, 5, 1]).unwrap();
        assert_eq!(classify_conic(&flat).unwrap(), ConicKind::DegenerateCollinear);
        assert!(implicit_conic(&flat).is_err());
        assert!(implicit_conic(&arc(&[0, 0, 1])).is_err());
        let cubic = RationalBezierCurve::<Q>::from_ints(&[&[0, 0], &[1, 0], &[1, 1], &[0, 1]], &[1, 1, 1, 1]).unwrap();
        assert!(matches!(
            classify_conic(&cubic),
            Err(Error::WrongCount { needed: 3, got: 4, .. })
        ));
        assert!(implicit_conic(&cubic).is_err());
        assert!(cubic.conic_standard_form().is_err());
        assert!(conic_shape_factor(&arc(&[0, 1, 1])).is_err());
    }

    #[test]
    fn zero_weights_give_line_pairs() {
        let c = implicit_conic(&arc(&[0, 1, 1])).unwrap();
        assert_eq!(c.kind(), ConicKind::DegenerateSingular);
        let t = q(1, 3);
        let p = arc(&[0, 1, 1]).eval(&t).unwrap();
        assert_eq!(c.eval(&p.coords()[0], &p.coords()[1]), q(0, 1));
    }

    #[test]
    fn exact_sqrt() {
        assert_eq!(q(9, 4).exact_sqrt().unwrap(), q(3, 2));
        assert!(q(2, 1).exact_sqrt().is_err());
        let x = QuadraticIrrational::new(q(3, 1), q(2, 1), 2).unwrap(); // (1 + √2)²
        assert_eq!(x.exact_sqrt().unwrap().to_string(), "1 + sqrt(2)");
        let y = QuadraticIrrational::new(q(3, 1), q(-2, 1), 2).unwrap(); // (√2 - 1)²
        assert_eq!(y.exact_sqrt().unwrap().to_string(), "-1 + sqrt(2)");
        assert!(QuadraticIrrational::sqrt(2).unwrap().exact_sqrt().is_err());
    }

    #[test]
    fn display_of_conics() {
        assert_eq!(
            ImplicitConic::<Q>::from_ints([4, 0, 3, 0, -10, 3]).to_string(),
            "4*x^2 + 3*y^2 - 10*y + 3 = 0"
        );
        assert_eq!(
            ImplicitConic::<Q>::from_ints([-1, 1, 0, 0, 0, -1]).to_string(),
            "-x^2 + x*y - 1 = 0"
        );
        let r2 = QuadraticIrrational::sqrt(2).unwrap();
        let k = ImplicitConic::from_coefficients([
            QuadraticIrrational::one(),
            QuadraticIrrational::zero(),
            &QuadraticIrrational::one() - &r2,
            QuadraticIrrational::zero(),
            QuadraticIrrational::zero(),
            -r2,
        ]);
        assert_eq!(k.to_string(), "x^2 + (1 - sqrt(2))*y^2 - sqrt(2) = 0");
    }
}
