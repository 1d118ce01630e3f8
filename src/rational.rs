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
use crate::exact::fraction_free;
use crate::kernel::{casteljau_step, with_column};
use crate::point::{common_dimension, Point};
use crate::quadratic::QuadraticIrrational;
use crate::scalar::{Ring, Scalar};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

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

/// `x / w`, `w ≠ 0`; exact rationals by Knuth's two gcds ([`crate::exact::gcd::divide`]),
/// where num-rational's division runs its binary gcd on the products.
fn quotient<T: Scalar>(x: &T, w: &T) -> Result<T> {
    if let Some(q) = T::quotient(x, w) {
        return Ok(q);
    }
    x.checked_div(w)
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

    pub(crate) fn vanishing(&self, t: &T) -> Error {
        Error::DivisionByZero(format!(
            "the denominator w(t) = Σ w_i B_i(t) of the rational curve vanishes at t = {t}, where the curve has no point"
        ))
    }

    /// `x(t) = Σ w_i b_i B_i(t) / Σ w_i B_i(t)` by de Casteljau on the homogeneous points,
    /// then projection. An error when `w(t) = 0`. Defined for every `t`, not only `[0, 1]`.
    ///
    /// Exact rationals take the homogeneous curve's point by [`BezierCurve::eval`]'s exact
    /// kernels, then one quotient per coordinate ([`RationalBezierCurve::eval_nested`]).
    pub fn eval(&self, t: &T) -> Result<Point<T>> {
        if let Some(point) = self.on_exact_kernel(t, T::rational_eval(self.homogeneous.points(), t)) {
            return point;
        }
        self.eval_reference(t)
    }

    /// A kernel's answer (`Some(None)`: the denominator vanishes at `t`) as the result of
    /// the method that ran it.
    fn on_exact_kernel(&self, t: &T, answer: Option<Option<Point<T>>>) -> Option<Result<Point<T>>> {
        Some(answer?.ok_or_else(|| self.vanishing(t)))
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
                points.push(Point::new(v.iter().map(|x| quotient(x, w)).collect::<Result<_>>()?)?);
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
    ///
    /// Exact rationals take the column's two points by [`BezierCurve::eval`]'s kernels
    /// ([`RationalBezierCurve::derivative_at_nested`]).
    pub fn derivative_at(&self, t: &T) -> Result<Point<T>> {
        if let Some(point) = self.on_exact_kernel(t, T::rational_derivative_at(self.homogeneous.points(), t)) {
            return point;
        }
        self.derivative_at_reference(t)
    }

    /// [`Self::derivative_at`] by de Casteljau's steps on the scalar type itself: the
    /// reference the exact kernel is tested against.
    pub fn derivative_at_reference(&self, t: &T) -> Result<Point<T>> {
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

    pub(crate) fn conic_weights(&self) -> Result<(&T, &T, &T)> {
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

impl RationalBezierCurve<BigRational> {
    /// `x(t)` as the homogeneous curve's point by [`BezierCurve::eval`]'s exact kernels,
    /// then `x = X / W` by the gcds of the two numerators and of the two denominators
    /// ([`crate::exact::gcd::divide`]); equals [`RationalBezierCurve::eval`], and a vanishing
    /// denominator `w(t) = 0` is the same error.
    ///
    /// ```
    /// use casteljau::{BigRational, RationalBezierCurve, Scalar};
    /// let arc = RationalBezierCurve::<BigRational>::from_ints(&[&[1, 0], &[1, 1], &[0, 1]], &[1, 1, 2]).unwrap();
    /// let t = BigRational::from_ratio(2, 5).unwrap();
    /// assert_eq!(arc.eval_nested(&t).unwrap(), arc.eval(&t).unwrap());
    /// ```
    pub fn eval_nested(&self, t: &BigRational) -> Result<Point<BigRational>> {
        fraction_free::rational_eval(self.homogeneous().points(), t).ok_or_else(|| self.vanishing(t))
    }

    /// `x'(t) = n (h₁ w₀ − h₀ w₁) / w(t)²`, with `(h₀, w₀)` and `(h₁, w₁)` the homogeneous
    /// curves of the points `0..n` and `1..=n` at `t` (the last-but-one column of de
    /// Casteljau's scheme) by [`BezierCurve::eval`]'s kernels, and one reduction per
    /// coordinate; equals [`RationalBezierCurve::derivative_at`], and a vanishing `w(t)` is
    /// the same error.
    ///
    /// With `h₀ = a/b`, `h₁ = c/d`, `w₀ = a_w/b_w`, `w₁ = c_w/d_w` in lowest terms and
    /// `t = p/q`: `w(t) = W / (q b_w d_w)`, `W = (q − p) a_w d_w + p c_w b_w`, and
    ///
    /// ```text
    /// x'(t) = n (c a_w b d_w − a c_w d b_w) q² b_w d_w / (b d W²).
    /// ```
    ///
    /// The two columns' denominators `b` and `d` share most of their factors; with
    /// `g = gcd(b, d)`, `b = g b'`, `d = g d'`, the numerator is
    /// `n (c a_w b' d_w − a c_w d' b_w) q² b_w d_w` over `g b' d' W²`, reduced part by part
    /// (`W²` by gcds with `W`, `exact::gcd::reduce_by_power`).
    ///
    /// ```
    /// use casteljau::{BigRational, RationalBezierCurve, Scalar};
    /// let arc = RationalBezierCurve::<BigRational>::from_ints(&[&[1, 0], &[1, 1], &[0, 1]], &[1, 1, 2]).unwrap();
    /// let t = BigRational::from_ratio(2, 5).unwrap();
    /// assert_eq!(arc.derivative_at_nested(&t).unwrap(), arc.derivative_at_reference(&t).unwrap());
    /// ```
    pub fn derivative_at_nested(&self, t: &BigRational) -> Result<Point<BigRational>> {
        let points = self.homogeneous().points();
        if points.len() == 1 {
            return self.derivative_at_reference(t);
        }
        fraction_free::rational_derivative_at(points, t).ok_or_else(|| self.vanishing(t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::conic::*;

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
