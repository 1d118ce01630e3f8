//! Fitting Bézier curves: the cubic approximation of a space curve of text 004, and general
//! least-squares fitting of sample points by a Bézier curve of any degree.
//!
//! ## Text 004: a cubic through the ends, tangent at the ends
//!
//! A curve `x(t)`, `t ∈ [0, 1]`, is approximated by the cubic `a(t)` with control points (4)
//!
//! ```text
//! a0 = x(0),   a1 = x(0) + k ẋ(0),   a2 = x(1) − l ẋ(1),   a3 = x(1),
//! ```
//!
//! choosing `k, l` to minimise `δ = |a(1/2) − x(1/2)|`. With `X = x(0) + x(1) − 2 x(1/2)`,
//! `a(1/2) − x(1/2) = X/2 + (3k/8) ẋ(0) − (3l/8) ẋ(1)` ((5), (6)), and `δ²` is a quadratic in
//! `(k, l)` whose minimum solves the 2×2 normal equations (11):
//!
//! ```text
//! 3/4 · [ẋ(0)·ẋ(0)  ẋ(0)·ẋ(1)] [−k]   [ẋ(0)·X]
//!       [ẋ(1)·ẋ(0)  ẋ(1)·ẋ(1)] [ l] = [ẋ(1)·X]
//! ```
//!
//! | text 004 | here |
//! |----------|------|
//! | data `x(0), x(1), x(1/2), ẋ(0), ẋ(1)` | [`CubicFitData`] ([`CubicFitData::from_curve`], [`CubicFitData::from_power`], [`CubicFitSource`]) |
//! | control points (2)–(4) | [`cubic_with_tangent_lengths`] |
//! | `δ²` (6) and its gradient (7), (9) | [`delta_squared`], [`delta_squared_gradient`] |
//! | normal equations (11) | [`CubicFitData::normal_equations`], solved exactly by [`fit_cubic`] |
//! | closed form (13) | [`fit_cubic_closed_form`] |
//!
//! **Misprint in the text.** Equations (8) and (10) are printed with right-hand sides
//! `X·x(0)` and `X·x(1)`; differentiating (7) and (9) gives `X·ẋ(0)` and `X·ẋ(1)` (the
//! derivatives), which is also what (11) and (13) use. This module follows (7), (9), (11)
//! and (13); `tests/fit.rs` shows the printed (8) failing and the corrected one holding
//! exactly at the optimum.
//!
//! The system (11) is singular exactly when `ẋ(0)` and `ẋ(1)` are parallel (or one is zero):
//! [`fit_cubic`] then returns [`Error::Singular`]. The text assumes `k, l > 0`; the optimum
//! need not satisfy that, and [`CubicFit::warnings`] says so when it does not. For a plane
//! curve with independent end tangents, `X/2 ∈ span(ẋ(0), ẋ(1))`, so the optimum has `δ = 0`
//! exactly (the text's remark).
//!
//! ## Least squares
//!
//! [`fit_least_squares`] fits a Bézier curve of degree `n` to samples `y_j` at parameters
//! `t_j`, minimising `E = Σ_j |b(t_j) − y_j|²`, optionally with the end points fixed and the
//! end tangent *directions* fixed (`a1 = a0 + α d0`, `a_{n−1} = a_n − β d1`, with unknown
//! `α, β`). The fitted curve is linear in the unknowns, so the minimum solves normal
//! equations, which are solved by the exact elimination of [`crate::linalg`]: for exact
//! scalars the gradient of `E` at the result is exactly zero ([`LeastSquaresFit::gradient`]).
//!
//! Parameters: any exact values can be given ([`uniform_params`] is exact). Chord-length and
//! centripetal parameters need square roots, so they are computed in `f64`
//! ([`chord_length_params`], [`centripetal_params`]); [`chord_length_params_via_f64`] turns
//! them into any scalar exactly (each float is a dyadic rational), so an exact fit is then
//! exact *for those parameters*, which are rounded chord lengths, not the irrational true ones.

use crate::bernstein::{bernstein, bernstein_all, eval_power};
use crate::curve::BezierCurve;
use crate::error::{check_degree, Error, Result};
use crate::linalg::{solve, solve_many, Matrix};
use crate::param::ParamCurveDeriv;
use crate::point::{common_dimension, Point, Vector};
use crate::scalar::Scalar;

// ---------------------------------------------------------------------------------------
// Text 004: the cubic fit
// ---------------------------------------------------------------------------------------

/// What text 004's method needs of the curve `x(t)`: `x(0)`, `x(1)`, `x(1/2)`, `ẋ(0)`, `ẋ(1)`.
///
/// The fields are public; [`CubicFitData::new`] and [`CubicFitData::validate`] check that
/// the five vectors share one dimension (at least 2) and, for floats, are finite.
#[derive(Clone, Debug, PartialEq)]
pub struct CubicFitData<T> {
    /// `x(0)`.
    pub x0: Point<T>,
    /// `x(1)`.
    pub x1: Point<T>,
    /// `x(1/2)`.
    pub xh: Point<T>,
    /// `ẋ(0)`, the derivative at `t = 0`.
    pub d0: Vector<T>,
    /// `ẋ(1)`, the derivative at `t = 1`.
    pub d1: Vector<T>,
}

/// Anything that can supply [`CubicFitData`]: the data itself and every curve with a
/// derivative ([`ParamCurveDeriv`]). [`fit_cubic_to`] accepts any of them.
pub trait CubicFitSource<T> {
    /// `x(0), x(1), x(1/2), ẋ(0), ẋ(1)` of this curve, exactly for exact scalars.
    fn cubic_fit_data(&self) -> Result<CubicFitData<T>>;
}

impl<T: Scalar> CubicFitData<T> {
    /// The data from its five vectors, validated (see [`CubicFitData::validate`]).
    pub fn new(x0: Point<T>, x1: Point<T>, xh: Point<T>, d0: Vector<T>, d1: Vector<T>) -> Result<Self> {
        let data = CubicFitData { x0, x1, xh, d0, d1 };
        data.validate()?;
        Ok(data)
    }

    /// Checks that the five vectors share one dimension, at least 2 (on a line the two end
    /// tangents are always parallel), and for floats that every coordinate is finite.
    /// Returns the dimension.
    pub fn validate(&self) -> Result<usize> {
        let dim = self.x0.dim();
        for (name, p) in self.named() {
            if p.dim() != dim {
                return Err(Error::DimensionMismatch {
                    expected: dim,
                    found: p.dim(),
                    context: format!("cubic fit data, {name}"),
                });
            }
            check_finite(p, name)?;
        }
        if dim < 2 {
            return Err(Error::Domain(
                "the cubic fit of text 004 needs points of dimension at least 2 \
                 (on a line the end tangents are always parallel)"
                    .into(),
            ));
        }
        Ok(dim)
    }

    fn named(&self) -> [(&'static str, &Point<T>); 5] {
        [
            ("x(0)", &self.x0),
            ("x(1)", &self.x1),
            ("x(1/2)", &self.xh),
            ("x'(0)", &self.d0),
            ("x'(1)", &self.d1),
        ]
    }

    /// The data of a polynomial Bézier curve, exactly: points by de Casteljau, derivatives
    /// from the hodograph. A curve of degree 0 has zero tangents (and [`fit_cubic`] will
    /// report the system singular).
    pub fn from_curve(c: &BezierCurve<T>) -> Result<Self> {
        let (zero, one, half) = (T::zero(), T::one(), T::from_ratio(1, 2)?);
        Self::new(
            c.eval(&zero),
            c.eval(&one),
            c.eval(&half),
            c.derivative_at(1, &zero)?,
            c.derivative_at(1, &one)?,
        )
    }

    /// The data of the polynomial curve `x(t) = Σ_k coeffs[k] t^k` (the power form), exactly.
    ///
    /// ```
    /// use casteljau::{CubicFitData, BigRational, Point};
    /// // x(t) = (t, t², t³)
    /// let c: Vec<Point<BigRational>> = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    ///     .iter().map(|p| Point::from_ints(p).unwrap()).collect();
    /// let d = CubicFitData::from_power(&c).unwrap();
    /// assert_eq!(d.d1, Point::from_ints(&[1, 2, 3]).unwrap());
    /// ```
    pub fn from_power(coeffs: &[Point<T>]) -> Result<Self> {
        let dim = common_dimension(coeffs, "a power-form curve")?;
        check_degree("degree", coeffs.len() as u128 - 1)?;
        let (zero, one, half) = (T::zero(), T::one(), T::from_ratio(1, 2)?);
        let per_coord: Vec<Vec<T>> = (0..dim)
            .map(|k| coeffs.iter().map(|c| c.coords()[k].clone()).collect())
            .collect();
        let deriv: Vec<Vec<T>> = per_coord
            .iter()
            .map(|c| {
                c.iter()
                    .enumerate()
                    .skip(1)
                    .map(|(i, a)| T::from_usize(i).mul_ref(a))
                    .collect()
            })
            .collect();
        let at = |polys: &[Vec<T>], t: &T| Point::new(polys.iter().map(|p| eval_power(p, t)).collect());
        Self::new(
            at(&per_coord, &zero)?,
            at(&per_coord, &one)?,
            at(&per_coord, &half)?,
            at(&deriv, &zero)?,
            at(&deriv, &one)?,
        )
    }

    /// The data of any curve given by two functions: `x(t)` and `ẋ(t)`, each called at the
    /// parameters it needs (`0`, `1/2`, `1` and `0`, `1`).
    pub fn from_functions(x: impl Fn(&T) -> Result<Point<T>>, dx: impl Fn(&T) -> Result<Vector<T>>) -> Result<Self> {
        let (zero, one, half) = (T::zero(), T::one(), T::from_ratio(1, 2)?);
        Self::new(x(&zero)?, x(&one)?, x(&half)?, dx(&zero)?, dx(&one)?)
    }

    /// The text's `X = x(0) + x(1) − 2 x(1/2)`.
    pub fn x_vector(&self) -> Vector<T> {
        let two = T::from_i64(2);
        self.x0.add(&self.x1).sub(&self.xh.scale(&two))
    }

    /// The 2×2 system (11) as `(matrix, right-hand side)` for the unknowns `(−k, l)`:
    /// `3/4 · G · (−k, l)ᵀ = (ẋ(0)·X, ẋ(1)·X)ᵀ`, with `G` the Gram matrix (12) of the tangents.
    ///
    /// # Panics
    /// If the five vectors differ in dimension (a programming error, as in [`Point`]
    /// arithmetic; [`CubicFitData::validate`] checks it).
    pub fn normal_equations(&self) -> (Matrix<T>, Vec<T>) {
        let three_quarters = T::from_ratio(3, 4).expect("3/4 is representable in every scalar");
        let g = self.gram();
        let matrix = g
            .iter()
            .map(|row| row.iter().map(|x| three_quarters.mul_ref(x)).collect())
            .collect();
        let x = self.x_vector();
        (matrix, vec![self.d0.dot(&x), self.d1.dot(&x)])
    }

    /// The Gram matrix (12) of the end tangents, `[[ẋ(0)·ẋ(0), ẋ(0)·ẋ(1)], [ẋ(1)·ẋ(0), ẋ(1)·ẋ(1)]]`.
    pub fn gram(&self) -> Matrix<T> {
        vec![
            vec![self.d0.dot(&self.d0), self.d0.dot(&self.d1)],
            vec![self.d1.dot(&self.d0), self.d1.dot(&self.d1)],
        ]
    }
}

fn check_finite<T: Scalar>(p: &Point<T>, what: &str) -> Result<()> {
    if !T::EXACT && p.coords().iter().any(|c| !c.to_f64().is_finite()) {
        return Err(Error::NotFinite(format!("{what} = {p}")));
    }
    Ok(())
}

impl<T: Scalar> CubicFitSource<T> for CubicFitData<T> {
    fn cubic_fit_data(&self) -> Result<CubicFitData<T>> {
        self.validate()?;
        Ok(self.clone())
    }
}

/// Any curve with a derivative — polynomial ([`BezierCurve`], iso-curves of surfaces),
/// rational ([`crate::RationalBezierCurve`], by the homogeneous de Casteljau algorithm and
/// the quotient rule) or a user's own: `x(t)` and `ẋ(t)` through [`ParamCurveDeriv`],
/// exactly for exact scalars. A curve without a point at 0, 1/2 or 1 is an error.
impl<T: Scalar, C> CubicFitSource<T> for C
where
    C: ParamCurveDeriv<Scalar = T, Point = Point<T>>,
{
    fn cubic_fit_data(&self) -> Result<CubicFitData<T>> {
        let (zero, one, half) = (T::zero(), T::one(), T::from_ratio(1, 2)?);
        CubicFitData::new(
            self.eval(&zero)?,
            self.eval(&one)?,
            self.eval(&half)?,
            self.deriv_at(&zero)?,
            self.deriv_at(&one)?,
        )
    }
}

/// The result of text 004's fit.
#[derive(Clone, Debug, PartialEq)]
pub struct CubicFit<T> {
    /// The tangent length at the start: `a1 = x(0) + k ẋ(0)`.
    pub k: T,
    /// The tangent length at the end: `a2 = x(1) − l ẋ(1)`.
    pub l: T,
    /// The cubic `a(t)` with control points (4).
    pub curve: BezierCurve<T>,
    /// `δ² = |a(1/2) − x(1/2)|²` at the optimum, exactly for exact scalars.
    pub delta2: T,
    /// The vector `a(1/2) − x(1/2)`; at the optimum it is orthogonal to `ẋ(0)` and `ẋ(1)`.
    pub residual: Vector<T>,
    /// `det G = (ẋ(0)·ẋ(0))(ẋ(1)·ẋ(1)) − (ẋ(0)·ẋ(1))²`, the denominator of (13); positive here.
    pub gram_determinant: T,
    /// Diagnostics in words: `k ≤ 0` or `l ≤ 0` (the text assumes both positive), or, for
    /// floats, nearly parallel end tangents. Empty when all is as the text assumes.
    pub warnings: Vec<String>,
}

impl<T: Scalar> CubicFit<T> {
    /// Whether `k > 0` and `l > 0`, as the text's method assumes.
    pub fn tangent_lengths_positive(&self) -> bool {
        self.k > T::zero() && self.l > T::zero()
    }
}

/// The cubic (4) of text 004 for given tangent lengths: control points
/// `x(0), x(0) + k ẋ(0), x(1) − l ẋ(1), x(1)`.
pub fn cubic_with_tangent_lengths<T: Scalar>(data: &CubicFitData<T>, k: &T, l: &T) -> Result<BezierCurve<T>> {
    data.validate()?;
    BezierCurve::new(vec![
        data.x0.clone(),
        data.x0.add(&data.d0.scale(k)),
        data.x1.sub(&data.d1.scale(l)),
        data.x1.clone(),
    ])
}

fn parallel_message<T: Scalar>(data: &CubicFitData<T>) -> String {
    if data.d0.is_zero() {
        return format!(
            "the tangent x'(0) is the zero vector, so the direction of a1 - a0 is undefined and the 2x2 system (11) \
             of text 004 is singular (k is not determined); x'(1) = {}",
            data.d1
        );
    }
    if data.d1.is_zero() {
        return format!(
            "the tangent x'(1) is the zero vector, so the direction of a3 - a2 is undefined and the 2x2 system (11) \
             of text 004 is singular (l is not determined); x'(0) = {}",
            data.d0
        );
    }
    format!(
        "the end tangents x'(0) = {} and x'(1) = {} are parallel{}, so the Gram matrix in (11)/(12) has determinant 0 \
         and k, l are not unique (text 004 needs independent end tangents)",
        data.d0,
        data.d1,
        if T::EXACT {
            ""
        } else {
            " (numerically, in floating point)"
        }
    )
}

/// Text 004's fit: solves the normal equations (11) with the exact solver of
/// [`crate::linalg`] and returns `k`, `l`, the cubic (4), `δ²` and diagnostics.
///
/// Parallel or zero end tangents make (11) singular: [`Error::Singular`] with a message
/// saying which. For `f64` "parallel" means numerically so (see [`crate::linalg`]).
///
/// ```
/// use casteljau::{fit_cubic, CubicFitData, BezierCurve, BigRational, Scalar};
/// // A cubic Bézier curve is recovered exactly: k = l = 1/3, δ = 0.
/// let c: BezierCurve<BigRational> = BezierCurve::from_ints(&[&[0, 0, 0], &[1, 2, 0], &[3, 2, 1], &[4, 0, 5]]).unwrap();
/// let fit = fit_cubic(&CubicFitData::from_curve(&c).unwrap()).unwrap();
/// assert_eq!(fit.k, BigRational::from_ratio(1, 3).unwrap());
/// assert_eq!(fit.curve, c);
/// assert!(fit.delta2.is_zero() && fit.warnings.is_empty());
/// ```
pub fn fit_cubic<T: Scalar>(data: &CubicFitData<T>) -> Result<CubicFit<T>> {
    data.validate()?;
    if data.d0.is_zero() || data.d1.is_zero() {
        return Err(Error::Singular(parallel_message(data)));
    }
    let (matrix, rhs) = data.normal_equations();
    let solution = solve(&matrix, &rhs).map_err(|e| match e {
        Error::Singular(_) => Error::Singular(parallel_message(data)),
        other => other,
    })?;
    let k = solution[0].neg_ref();
    let l = solution[1].clone();
    finish_cubic_fit(data, k, l)
}

/// [`fit_cubic`] for anything that supplies the data: a [`BezierCurve`], the data itself,
/// and other [`CubicFitSource`]s.
pub fn fit_cubic_to<T: Scalar, S: CubicFitSource<T> + ?Sized>(source: &S) -> Result<CubicFit<T>> {
    fit_cubic(&source.cubic_fit_data()?)
}

fn finish_cubic_fit<T: Scalar>(data: &CubicFitData<T>, k: T, l: T) -> Result<CubicFit<T>> {
    let curve = cubic_with_tangent_lengths(data, &k, &l)?;
    let residual = curve.eval(&T::from_ratio(1, 2)?).sub(&data.xh);
    let delta2 = residual.norm_squared();
    let g = data.gram();
    let gram_determinant = g[0][0].mul_ref(&g[1][1]).sub_ref(&g[0][1].mul_ref(&g[1][0]));
    let mut warnings = Vec::new();
    if k <= T::zero() {
        warnings.push(format!(
            "k = {k} <= 0: the optimal a1 - a0 = k x'(0) does not point along x'(0); text 004 assumes k > 0"
        ));
    }
    if l <= T::zero() {
        warnings.push(format!(
            "l = {l} <= 0: the optimal a3 - a2 = l x'(1) does not point along x'(1); text 004 assumes l > 0"
        ));
    }
    if !T::EXACT {
        let scale = g[0][0].mul_ref(&g[1][1]).to_f64();
        if gram_determinant.to_f64().abs() <= 1e-10 * scale {
            warnings.push(format!(
                "the end tangents are nearly parallel (det G = {gram_determinant}): k and l are ill-conditioned in \
                 floating point; use exact scalars to be sure"
            ));
        }
    }
    Ok(CubicFit {
        k,
        l,
        curve,
        delta2,
        residual,
        gram_determinant,
        warnings,
    })
}

/// `(k, l)` by the closed form (13): `(−k, l)ᵀ = 4/3 · adj(G) (ẋ(0)·X, ẋ(1)·X)ᵀ / det G`,
/// computed literally, independently of [`fit_cubic`]'s elimination so the two can be
/// compared. `det G = 0` (for floats: `|det G| ≤ 1e-12 |ẋ(0)|²|ẋ(1)|²`) is [`Error::Singular`].
pub fn fit_cubic_closed_form<T: Scalar>(data: &CubicFitData<T>) -> Result<(T, T)> {
    data.validate()?;
    let (d0, d1) = (&data.d0, &data.d1);
    let x = data.x_vector();
    let (g00, g01, g10, g11) = (d0.dot(d0), d0.dot(d1), d1.dot(d0), d1.dot(d1));
    let (p0, p1) = (d0.dot(&x), d1.dot(&x));
    let det = g00.mul_ref(&g11).sub_ref(&g01.mul_ref(&g10));
    let degenerate = if T::EXACT {
        det.is_zero()
    } else {
        det.to_f64().abs() <= 1e-12 * g00.mul_ref(&g11).to_f64()
    };
    if degenerate {
        return Err(Error::Singular(parallel_message(data)));
    }
    let factor = T::from_ratio(4, 3)?.checked_div(&det)?;
    let minus_k = factor.mul_ref(&g11.mul_ref(&p0).sub_ref(&g01.mul_ref(&p1)));
    let l = factor.mul_ref(&g00.mul_ref(&p1).sub_ref(&g10.mul_ref(&p0)));
    Ok((-minus_k, l))
}

/// `δ² = |a(1/2) − x(1/2)|²` for given `k, l`, from the definition: `a(1/2)` by de
/// Casteljau on the control points (4), not by the text's (5)/(6), so that those formulas
/// can be checked against it.
///
/// The fields of [`CubicFitData`] are public, so the data is validated first: vectors of
/// different dimensions are an error, not a panic.
pub fn delta_squared<T: Scalar>(data: &CubicFitData<T>, k: &T, l: &T) -> Result<T> {
    Ok(midpoint_residual(data, k, l)?.norm_squared())
}

fn midpoint_residual<T: Scalar>(data: &CubicFitData<T>, k: &T, l: &T) -> Result<Vector<T>> {
    data.validate()?;
    let a1 = data.x0.add(&data.d0.scale(k));
    let a2 = data.x1.sub(&data.d1.scale(l));
    let curve = BezierCurve::new(vec![data.x0.clone(), a1, a2, data.x1.clone()])?;
    Ok(curve.eval(&half()).sub(&data.xh))
}

fn half<T: Scalar>() -> T {
    T::from_ratio(1, 2).expect("1/2 is representable in every scalar")
}

/// The gradient `(∂δ²/∂k, ∂δ²/∂l)` at `(k, l)`, from the definition:
/// `∂a(1/2)/∂k = B_1^3(1/2) ẋ(0)`, `∂a(1/2)/∂l = −B_2^3(1/2) ẋ(1)`, so the gradient is
/// `(2 B_1^3(1/2) ẋ(0)·r, −2 B_2^3(1/2) ẋ(1)·r)` with `r = a(1/2) − x(1/2)`. Exactly zero at
/// the exact optimum. (The text's (9) differentiates by `−l`, the negative of the second
/// component.)
///
/// # Panics
/// If the five vectors of `data` differ in dimension (see [`delta_squared`]).
pub fn delta_squared_gradient<T: Scalar>(data: &CubicFitData<T>, k: &T, l: &T) -> Result<(T, T)> {
    let r = midpoint_residual(data, k, l)?;
    let h = half::<T>();
    let two = T::from_i64(2);
    let b1 = bernstein(1, 3, &h).expect("small binomials fit every scalar");
    let b2 = bernstein(2, 3, &h).expect("small binomials fit every scalar");
    let dk = two.mul_ref(&b1).mul_ref(&data.d0.dot(&r));
    let dl = two.mul_ref(&b2).mul_ref(&data.d1.dot(&r)).neg_ref();
    Ok((dk, dl))
}

// ---------------------------------------------------------------------------------------
// Least squares
// ---------------------------------------------------------------------------------------

/// Largest degree [`fit_least_squares`] accepts: beyond it the normal equations of the
/// Bernstein basis are hopeless in floating point and very slow in exact arithmetic.
pub const MAX_FIT_DEGREE: usize = 256;

/// Constraints for [`fit_least_squares`]; all `None` ([`FitConstraints::none`]) is a free fit.
///
/// A fixed direction `d0` means `a1 = a0 + α d0` with an unknown scalar `α` (and `d1`:
/// `a_{n−1} = a_n − β d1`); it combines with a fixed or a free end point. One fixed
/// direction needs degree ≥ 2, both need degree ≥ 3 (so that `a1` and `a_{n−1}` are
/// distinct inner points).
#[derive(Clone, Debug, PartialEq)]
pub struct FitConstraints<T> {
    /// `a0` fixed to this point.
    pub start_point: Option<Point<T>>,
    /// `a_n` fixed to this point.
    pub end_point: Option<Point<T>>,
    /// `a1 − a0` fixed to a multiple `α d0` of this (non-zero) direction.
    pub start_direction: Option<Vector<T>>,
    /// `a_n − a_{n−1}` fixed to a multiple `β d1` of this (non-zero) direction.
    pub end_direction: Option<Vector<T>>,
}

impl<T> Default for FitConstraints<T> {
    fn default() -> Self {
        FitConstraints {
            start_point: None,
            end_point: None,
            start_direction: None,
            end_direction: None,
        }
    }
}

impl<T> FitConstraints<T> {
    /// No constraint: every control point is free.
    pub fn none() -> Self {
        Self::default()
    }

    /// Both end points fixed.
    pub fn endpoints(start: Point<T>, end: Point<T>) -> Self {
        FitConstraints {
            start_point: Some(start),
            end_point: Some(end),
            ..Self::default()
        }
    }

    /// Both end points and both end tangent directions fixed (text 004's shape of constraint).
    pub fn endpoints_and_directions(start: Point<T>, end: Point<T>, d0: Vector<T>, d1: Vector<T>) -> Self {
        FitConstraints {
            start_point: Some(start),
            end_point: Some(end),
            start_direction: Some(d0),
            end_direction: Some(d1),
        }
    }
}

/// The result of [`fit_least_squares`].
#[derive(Clone, Debug, PartialEq)]
pub struct LeastSquaresFit<T> {
    /// The fitted curve.
    pub curve: BezierCurve<T>,
    /// `E = Σ_j |b(t_j) − y_j|²`, evaluated on the fitted curve (exact for exact scalars).
    pub residual_squared: T,
    /// `∇E` with respect to the unknowns (named in [`LeastSquaresFit::unknowns`]), evaluated
    /// on the fitted curve from its residuals: exactly zero for exact scalars.
    pub gradient: Vec<T>,
    /// Names of the unknowns, in the order of [`LeastSquaresFit::gradient`]: `"a3[1]"` is
    /// coordinate 1 of control point 3 (a free point, moving with the points tied to it),
    /// `"alpha"` and `"beta"` the direction scales.
    pub unknowns: Vec<String>,
    /// `α` when the start direction is fixed.
    pub alpha: Option<T>,
    /// `β` when the end direction is fixed.
    pub beta: Option<T>,
    /// Diagnostics: `α ≤ 0` or `β ≤ 0` (the fitted tangent does not point along the given
    /// direction).
    pub warnings: Vec<String>,
}

/// How each control point depends on the unknowns: `a_i = fixed_i + Σ_v c U_v + Σ_s c s dir_s`.
struct Design<T> {
    degree: usize,
    dim: usize,
    fixed: Vec<Point<T>>,
    /// `(control point index, unknown index, coefficient)` for the vector unknowns.
    vector_terms: Vec<(usize, usize, T)>,
    vector_names: Vec<usize>,
    /// `(control point index, unknown index, coefficient)` for the scalar unknowns.
    scalar_terms: Vec<(usize, usize, T)>,
    directions: Vec<Vector<T>>,
    scalar_names: Vec<&'static str>,
}

impl<T: Scalar> Design<T> {
    fn new(degree: usize, dim: usize, c: &FitConstraints<T>) -> Result<Self> {
        if degree > MAX_FIT_DEGREE {
            return Err(Error::TooLarge {
                what: "degree of a least-squares fit",
                value: degree.to_string(),
                limit: MAX_FIT_DEGREE.to_string(),
            });
        }
        for (name, p) in [
            ("start point", &c.start_point),
            ("end point", &c.end_point),
            ("start direction", &c.start_direction),
            ("end direction", &c.end_direction),
        ] {
            if let Some(p) = p {
                if p.dim() != dim {
                    return Err(Error::DimensionMismatch {
                        expected: dim,
                        found: p.dim(),
                        context: format!("fit constraint: {name}"),
                    });
                }
                check_finite(p, name)?;
            }
        }
        for (name, d) in [("start", &c.start_direction), ("end", &c.end_direction)] {
            if d.as_ref().is_some_and(Point::is_zero) {
                return Err(Error::Domain(format!(
                    "the fixed {name} tangent direction is the zero vector, which is no direction"
                )));
            }
        }
        let directions_needed = match (c.start_direction.is_some(), c.end_direction.is_some()) {
            (true, true) => 3,
            (true, false) | (false, true) => 2,
            _ => 0,
        };
        if degree < directions_needed {
            return Err(Error::Domain(format!(
                "fixing {} needs degree at least {directions_needed} (the tangent control points must be inner \
                 points), got degree {degree}",
                if directions_needed == 3 {
                    "both end directions"
                } else {
                    "an end direction"
                }
            )));
        }
        if degree == 0 {
            if let (Some(a), Some(b)) = (&c.start_point, &c.end_point) {
                if a != b {
                    return Err(Error::Domain(
                        "a degree-0 curve has one control point: it cannot start and end at different points".into(),
                    ));
                }
            }
        }
        let mut d = Design {
            degree,
            dim,
            fixed: vec![Point::origin(dim); degree + 1],
            vector_terms: Vec::new(),
            vector_names: Vec::new(),
            scalar_terms: Vec::new(),
            directions: Vec::new(),
            scalar_names: Vec::new(),
        };
        let one = T::one();
        // The end points first: the tangent points are tied to them.
        let ends: &[(usize, &Option<Point<T>>)] = if degree == 0 {
            &[(0, &c.start_point)]
        } else {
            &[(0, &c.start_point), (degree, &c.end_point)]
        };
        for &(i, fixed) in ends {
            let fixed = if degree == 0 {
                fixed.as_ref().or(c.end_point.as_ref())
            } else {
                fixed.as_ref()
            };
            match fixed {
                Some(p) => d.fixed[i] = p.clone(),
                None => d.add_vector_unknown(i),
            }
        }
        for i in 1..degree {
            if i == 1 && c.start_direction.is_some() {
                d.tie(1, 0, one.clone(), c.start_direction.clone(), "alpha");
            } else if i == degree - 1 && c.end_direction.is_some() {
                d.tie(degree - 1, degree, one.neg_ref(), c.end_direction.clone(), "beta");
            } else {
                d.add_vector_unknown(i);
            }
        }
        Ok(d)
    }

    fn add_vector_unknown(&mut self, i: usize) {
        self.vector_terms.push((i, self.vector_names.len(), T::one()));
        self.vector_names.push(i);
    }

    /// `a_i = a_base + sign · s · dir` with a new scalar unknown `s`.
    fn tie(&mut self, i: usize, base: usize, sign: T, dir: Option<Vector<T>>, name: &'static str) {
        self.fixed[i] = self.fixed[base].clone();
        let inherited: Vec<_> = self
            .vector_terms
            .iter()
            .filter(|(cp, _, _)| *cp == base)
            .map(|(_, v, c)| (i, *v, c.clone()))
            .collect();
        self.vector_terms.extend(inherited);
        self.scalar_terms.push((i, self.directions.len(), sign));
        self.directions
            .push(dir.expect("tie is called only for a given direction"));
        self.scalar_names.push(name);
    }

    fn vector_count(&self) -> usize {
        self.vector_names.len()
    }

    fn scalar_count(&self) -> usize {
        self.directions.len()
    }

    fn unknown_names(&self) -> Vec<String> {
        let mut names: Vec<String> = self
            .vector_names
            .iter()
            .flat_map(|i| (0..self.dim).map(move |c| format!("a{i}[{c}]")))
            .collect();
        names.extend(self.scalar_names.iter().map(|s| s.to_string()));
        names
    }

    /// `φ_v(t) = Σ_i coef B_i(t)` and `ψ_s(t)` for one parameter, from its Bernstein values.
    fn basis_at(&self, bern: &[T]) -> (Vec<T>, Vec<T>) {
        let mut phi = vec![T::zero(); self.vector_count()];
        for (i, v, c) in &self.vector_terms {
            phi[*v] += &c.mul_ref(&bern[*i]);
        }
        let mut psi = vec![T::zero(); self.scalar_count()];
        for (i, s, c) in &self.scalar_terms {
            psi[*s] += &c.mul_ref(&bern[*i]);
        }
        (phi, psi)
    }

    fn fixed_part_at(&self, bern: &[T]) -> Point<T> {
        let mut acc = Point::origin(self.dim);
        for (b, p) in bern.iter().zip(&self.fixed) {
            acc = acc.add(&p.scale(b));
        }
        acc
    }

    fn control_points(&self, u: &[Point<T>], s: &[T]) -> Vec<Point<T>> {
        let mut pts = self.fixed.clone();
        for (i, v, c) in &self.vector_terms {
            pts[*i] = pts[*i].add(&u[*v].scale(c));
        }
        for (i, k, c) in &self.scalar_terms {
            pts[*i] = pts[*i].add(&self.directions[*k].scale(&c.mul_ref(&s[*k])));
        }
        pts
    }

    /// `∇E` from the residuals `e_j = b(t_j) − y_j`: `2 Σ_j φ_v(t_j) e_j` per vector unknown
    /// (one entry per coordinate) and `2 Σ_j ψ_s(t_j) dir_s · e_j` per scalar unknown.
    fn gradient(&self, params: &[T], residuals: &[Vector<T>]) -> Vec<T> {
        let mut gv = vec![Point::origin(self.dim); self.vector_count()];
        let mut gs = vec![T::zero(); self.scalar_count()];
        for (t, e) in params.iter().zip(residuals) {
            let (phi, psi) = self.basis_at(&bernstein_all(self.degree, t));
            for (g, f) in gv.iter_mut().zip(&phi) {
                *g = g.add(&e.scale(f));
            }
            for ((g, f), dir) in gs.iter_mut().zip(&psi).zip(&self.directions) {
                *g += &f.mul_ref(&dir.dot(e));
            }
        }
        let two = T::from_i64(2);
        gv.iter()
            .flat_map(|p| p.coords().iter().map(|c| two.mul_ref(c)).collect::<Vec<_>>())
            .chain(gs.iter().map(|g| two.mul_ref(g)))
            .collect()
    }
}

fn check_samples<T: Scalar>(samples: &[Point<T>], params: &[T]) -> Result<usize> {
    let dim = common_dimension(samples, "a least-squares fit (samples)")?;
    if params.len() != samples.len() {
        return Err(Error::WrongCount {
            what: "a least-squares fit (one parameter per sample)",
            needed: samples.len(),
            got: params.len(),
        });
    }
    for (j, p) in samples.iter().enumerate() {
        check_finite(p, &format!("sample {j}"))?;
    }
    if !T::EXACT {
        if let Some((j, t)) = params.iter().enumerate().find(|(_, t)| !t.to_f64().is_finite()) {
            return Err(Error::NotFinite(format!("parameter {j} = {t}")));
        }
    }
    Ok(dim)
}

/// Fits a Bézier curve of degree `degree` to `samples[j]` at parameters `params[j]` by least
/// squares, `min Σ_j |b(t_j) − y_j|²`, under `constraints`.
///
/// The normal equations are solved by exact elimination ([`crate::linalg::solve_many`], the
/// direction scales by a Schur complement): for exact scalars the result is the exact
/// minimiser and [`LeastSquaresFit::gradient`] is exactly zero; for `f64` the same code runs
/// in floating point (fine for moderate degrees; the Bernstein normal equations grow
/// ill-conditioned with the degree).
///
/// Errors: no samples, mixed dimensions, a parameter count different from the sample
/// count, fewer samples than free control points (under-determined: [`Error::Singular`]),
/// too few distinct parameters or otherwise singular normal equations ([`Error::Singular`]),
/// inconsistent constraints ([`Error::Domain`]), degree above [`MAX_FIT_DEGREE`].
///
/// ```
/// use casteljau::{fit_least_squares, uniform_params, FitConstraints, BezierCurve, BigRational, Point, Scalar};
/// // Samples of a quadratic are fitted exactly by a quadratic: zero residual.
/// let c: BezierCurve<BigRational> = BezierCurve::from_ints(&[&[0, 0], &[1, 3], &[4, 1]]).unwrap();
/// let t: Vec<BigRational> = uniform_params(6).unwrap();
/// let y: Vec<Point<BigRational>> = t.iter().map(|t| c.eval(t)).collect();
/// let fit = fit_least_squares(&y, &t, 2, &FitConstraints::none()).unwrap();
/// assert_eq!(fit.curve, c);
/// assert!(fit.residual_squared.is_zero());
/// assert!(fit.gradient.iter().all(|g| g.is_zero()));
/// ```
pub fn fit_least_squares<T: Scalar>(
    samples: &[Point<T>],
    params: &[T],
    degree: usize,
    constraints: &FitConstraints<T>,
) -> Result<LeastSquaresFit<T>> {
    let dim = check_samples(samples, params)?;
    let design = Design::new(degree, dim, constraints)?;
    let (nv, ns) = (design.vector_count(), design.scalar_count());
    let m = samples.len();
    if m < nv || m * dim < nv * dim + ns {
        return Err(Error::Singular(format!(
            "under-determined: {m} samples cannot determine {nv} free control points{} of a degree-{degree} curve \
             ({} scalar unknowns, {} scalar equations); give more samples or lower the degree",
            if ns > 0 {
                format!(" and {ns} direction scales")
            } else {
                String::new()
            },
            nv * dim + ns,
            m * dim
        )));
    }
    if nv > 0 {
        let mut distinct: Vec<&T> = Vec::with_capacity(m);
        for t in params {
            if !distinct.contains(&t) {
                distinct.push(t);
            }
            if distinct.len() >= nv {
                break;
            }
        }
        if distinct.len() < nv {
            return Err(Error::Singular(format!(
                "under-determined: only {} distinct parameters for {nv} free control points",
                distinct.len()
            )));
        }
    }

    // Gram matrices of the basis functions over the samples, and the right-hand sides.
    let mut g_vv: Matrix<T> = vec![vec![T::zero(); nv]; nv];
    let mut g_vs: Matrix<T> = vec![vec![T::zero(); ns]; nv];
    let mut g_ss: Matrix<T> = vec![vec![T::zero(); ns]; ns];
    let mut r_v: Vec<Point<T>> = vec![Point::origin(dim); nv];
    let mut r_s: Vec<T> = vec![T::zero(); ns];
    for (t, y) in params.iter().zip(samples) {
        let bern = bernstein_all(degree, t);
        let (phi, psi) = design.basis_at(&bern);
        let target = y.sub(&design.fixed_part_at(&bern));
        for (v, fv) in phi.iter().enumerate() {
            if fv.is_zero() {
                continue;
            }
            // Symmetric: the upper triangle now, mirrored below after the loop.
            for (w, fw) in phi.iter().enumerate().skip(v) {
                g_vv[v][w] += &fv.mul_ref(fw);
            }
            for (s, fs) in psi.iter().enumerate() {
                g_vs[v][s] += &fv.mul_ref(fs);
            }
            r_v[v] = r_v[v].add(&target.scale(fv));
        }
        for (s, fs) in psi.iter().enumerate() {
            for (s2, fs2) in psi.iter().enumerate() {
                g_ss[s][s2] += &fs.mul_ref(fs2);
            }
            r_s[s] += &fs.mul_ref(&design.directions[s].dot(&target));
        }
    }
    for v in 1..nv {
        let (upper, lower) = g_vv.split_at_mut(v);
        for (w, row) in upper.iter().enumerate() {
            lower[0][w] = row[v].clone();
        }
    }
    let singular = |e: Error| match e {
        Error::Singular(msg) => Error::Singular(format!(
            "the normal equations of the fit are singular ({msg}): the parameters do not determine the \
             free control points"
        )),
        other => other,
    };
    // Vector part: G_vv U = R_v − G_vs (s ∘ dir); solve for [R_v | G_vs] at once.
    let (x_r, x_psi): (Vec<Point<T>>, Matrix<T>) = if nv > 0 {
        let rhs: Matrix<T> = (0..nv)
            .map(|v| r_v[v].coords().iter().chain(&g_vs[v]).cloned().collect())
            .collect();
        let x = solve_many(&g_vv, &rhs).map_err(singular)?;
        let x_r = x
            .iter()
            .map(|row| Point::new(row[..dim].to_vec()))
            .collect::<Result<_>>()?;
        let x_psi = x.iter().map(|row| row[dim..].to_vec()).collect();
        (x_r, x_psi)
    } else {
        (Vec::new(), Vec::new())
    };
    // Scalar part, the Schur complement:
    // Σ_s' [G_ss − G_vsᵀ X_ψ]_{s s'} (dir_s·dir_s') s' = r_s − Σ_w G_vs[w][s] dir_s·X_R[w].
    let scales: Vec<T> = if ns > 0 {
        let mut a: Matrix<T> = vec![vec![T::zero(); ns]; ns];
        let mut b = r_s.clone();
        for s in 0..ns {
            for s2 in 0..ns {
                let mut coef = g_ss[s][s2].clone();
                for w in 0..nv {
                    coef -= &g_vs[w][s].mul_ref(&x_psi[w][s2]);
                }
                a[s][s2] = coef.mul_ref(&design.directions[s].dot(&design.directions[s2]));
            }
            for w in 0..nv {
                b[s] -= &g_vs[w][s].mul_ref(&design.directions[s].dot(&x_r[w]));
            }
        }
        solve(&a, &b).map_err(singular)?
    } else {
        Vec::new()
    };
    let u: Vec<Point<T>> = (0..nv)
        .map(|w| {
            let mut p = x_r[w].clone();
            for (s, sv) in scales.iter().enumerate() {
                p = p.sub(&design.directions[s].scale(&x_psi[w][s].mul_ref(sv)));
            }
            p
        })
        .collect();
    let curve = BezierCurve::new(design.control_points(&u, &scales))?;
    let residuals: Vec<Vector<T>> = params.iter().zip(samples).map(|(t, y)| curve.eval(t).sub(y)).collect();
    let mut residual_squared = T::zero();
    for e in &residuals {
        residual_squared += &e.norm_squared();
    }
    let gradient = design.gradient(params, &residuals);
    let mut alpha = None;
    let mut beta = None;
    let mut warnings = Vec::new();
    for (name, value) in design.scalar_names.iter().zip(&scales) {
        if *value <= T::zero() {
            warnings.push(format!(
                "{name} = {value} <= 0: the fitted end tangent does not point along the given direction"
            ));
        }
        if *name == "alpha" {
            alpha = Some(value.clone());
        } else {
            beta = Some(value.clone());
        }
    }
    Ok(LeastSquaresFit {
        curve,
        residual_squared,
        gradient,
        unknowns: design.unknown_names(),
        alpha,
        beta,
        warnings,
    })
}

/// [`check_samples`], and the samples must have the curve's dimension.
fn check_samples_of<T: Scalar>(samples: &[Point<T>], params: &[T], curve: &BezierCurve<T>, what: &str) -> Result<()> {
    let dim = check_samples(samples, params)?;
    if dim != curve.dim() {
        return Err(Error::DimensionMismatch {
            expected: curve.dim(),
            found: dim,
            context: what.into(),
        });
    }
    Ok(())
}

/// `E = Σ_j |b(t_j) − y_j|²` for any curve: the quantity [`fit_least_squares`] minimises.
pub fn least_squares_residual<T: Scalar>(samples: &[Point<T>], params: &[T], curve: &BezierCurve<T>) -> Result<T> {
    check_samples_of(samples, params, curve, "samples of a least-squares residual")?;
    let mut acc = T::zero();
    for (t, y) in params.iter().zip(samples) {
        acc += &curve.eval(t).distance_squared(y);
    }
    Ok(acc)
}

/// `∇E` at `curve` with respect to the unknowns that `constraints` leave free (in the order
/// of [`LeastSquaresFit::unknowns`]). `E` is quadratic in them and `curve` need not be a
/// fit: the gradient vanishes exactly at the exact minimiser, and only there.
pub fn least_squares_gradient<T: Scalar>(
    samples: &[Point<T>],
    params: &[T],
    curve: &BezierCurve<T>,
    constraints: &FitConstraints<T>,
) -> Result<Vec<T>> {
    check_samples_of(samples, params, curve, "samples of a least-squares gradient")?;
    let design = Design::new(curve.degree(), curve.dim(), constraints)?;
    let residuals: Vec<Vector<T>> = params.iter().zip(samples).map(|(t, y)| curve.eval(t).sub(y)).collect();
    Ok(design.gradient(params, &residuals))
}

/// The exact uniform parameters `0, 1/(m−1), …, 1` for `m` samples (`[0]` for one sample).
pub fn uniform_params<T: Scalar>(count: usize) -> Result<Vec<T>> {
    if count == 0 {
        return Err(Error::Empty("uniform parameters"));
    }
    if count == 1 {
        return Ok(vec![T::zero()]);
    }
    let last = T::from_usize(count - 1);
    (0..count).map(|j| T::from_usize(j).checked_div(&last)).collect()
}

/// Chord-length parameters: `t_0 = 0`, `t_j − t_{j−1} ∝ |y_j − y_{j−1}|`, `t_{m−1} = 1`.
///
/// Needs square roots, so it is `f64` only (see [`chord_length_params_via_f64`] for other
/// scalars). Repeated consecutive samples get equal parameters; all samples coinciding is
/// an error (the chord length is zero).
pub fn chord_length_params(samples: &[Point<f64>]) -> Result<Vec<f64>> {
    params_by_distance(samples, |d2| d2.sqrt(), "chord-length")
}

/// Centripetal parameters: increments `∝ |y_j − y_{j−1}|^{1/2}` (Lee 1989), which follow
/// sharp turns better than chord length. `f64` only, like [`chord_length_params`].
pub fn centripetal_params(samples: &[Point<f64>]) -> Result<Vec<f64>> {
    params_by_distance(samples, |d2| d2.sqrt().sqrt(), "centripetal")
}

fn params_by_distance(samples: &[Point<f64>], step: impl Fn(f64) -> f64, what: &str) -> Result<Vec<f64>> {
    common_dimension(samples, "parameters of samples")?;
    for (j, p) in samples.iter().enumerate() {
        check_finite(p, &format!("sample {j}"))?;
    }
    let mut acc = vec![0.0];
    for w in samples.windows(2) {
        let d = step(w[1].distance_squared(&w[0]));
        acc.push(acc[acc.len() - 1] + d);
    }
    let total = acc[acc.len() - 1];
    if samples.len() == 1 {
        return Ok(acc);
    }
    if !total.is_finite() {
        return Err(Error::NotFinite(format!("total {what} length")));
    }
    if total == 0.0 {
        return Err(Error::Domain(format!(
            "all {} samples coincide: {what} parameters are undefined",
            samples.len()
        )));
    }
    let n = acc.len();
    for t in acc.iter_mut() {
        *t /= total;
    }
    // Exactly 1 at the end, whatever the rounding of the sum.
    acc[n - 1] = 1.0;
    Ok(acc)
}

/// [`chord_length_params`] for any scalar: computed in `f64` from the coordinates' `to_f64`
/// and converted back exactly (each float is a dyadic rational). For exact scalars the
/// parameters are therefore exact numbers — rounded chord lengths, not the irrational true
/// ones — and a fit with them is exact for them.
pub fn chord_length_params_via_f64<T: Scalar>(samples: &[Point<T>]) -> Result<Vec<T>> {
    let floats: Vec<Point<f64>> = samples
        .iter()
        .map(|p| Point::<f64>::new(p.to_f64()))
        .collect::<Result<_>>()?;
    chord_length_params(&floats)?.into_iter().map(T::from_f64).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;
    type Q = BigRational;

    fn p(c: &[i64]) -> Point<Q> {
        Point::from_ints(c).unwrap()
    }

    #[test]
    fn zero_and_parallel_tangents_are_clear_errors() {
        let data = CubicFitData::new(
            p(&[0, 0, 0]),
            p(&[1, 0, 0]),
            p(&[0, 1, 1]),
            p(&[0, 0, 0]),
            p(&[1, 1, 0]),
        )
        .unwrap();
        let err = fit_cubic(&data).unwrap_err();
        assert!(matches!(err, Error::Singular(_)));
        assert!(err.to_string().contains("zero vector"), "{err}");
        let data = CubicFitData::new(
            p(&[0, 0, 0]),
            p(&[1, 0, 0]),
            p(&[0, 1, 1]),
            p(&[1, 2, 3]),
            p(&[-2, -4, -6]),
        )
        .unwrap();
        let err = fit_cubic(&data).unwrap_err();
        assert!(err.to_string().contains("parallel"), "{err}");
        assert!(fit_cubic_closed_form(&data)
            .unwrap_err()
            .to_string()
            .contains("parallel"));
    }

    #[test]
    fn bad_data_is_rejected() {
        assert!(CubicFitData::new(p(&[0, 0]), p(&[1, 0, 0]), p(&[0, 1]), p(&[1, 0]), p(&[0, 1])).is_err());
        assert!(CubicFitData::new(p(&[0]), p(&[1]), p(&[0]), p(&[1]), p(&[1])).is_err());
        let nan = Point::new(vec![f64::NAN, 0.0]).unwrap();
        let z = Point::new(vec![0.0, 1.0]).unwrap();
        assert!(CubicFitData::new(nan, z.clone(), z.clone(), z.clone(), z).is_err());
        assert!(CubicFitData::<Q>::from_power(&[]).is_err());
    }

    #[test]
    fn constraints_that_cannot_hold_are_errors() {
        let y = vec![p(&[0, 0]), p(&[1, 1]), p(&[2, 0]), p(&[3, 1])];
        let t: Vec<Q> = uniform_params(4).unwrap();
        let both = FitConstraints::endpoints_and_directions(p(&[0, 0]), p(&[3, 1]), p(&[1, 0]), p(&[1, 0]));
        assert!(fit_least_squares(&y, &t, 2, &both)
            .unwrap_err()
            .to_string()
            .contains("degree at least 3"));
        let zero_dir = FitConstraints {
            start_direction: Some(p(&[0, 0])),
            ..FitConstraints::none()
        };
        assert!(fit_least_squares(&y, &t, 3, &zero_dir)
            .unwrap_err()
            .to_string()
            .contains("zero vector"));
        let wrong_dim = FitConstraints::endpoints(p(&[0, 0, 0]), p(&[1, 1, 1]));
        assert!(matches!(
            fit_least_squares(&y, &t, 3, &wrong_dim),
            Err(Error::DimensionMismatch { .. })
        ));
        assert!(fit_least_squares(&y, &t[..3], 2, &FitConstraints::none()).is_err());
        assert!(fit_least_squares(&y, &t, MAX_FIT_DEGREE + 1, &FitConstraints::none()).is_err());
    }

    #[test]
    fn uniform_and_chord_params() {
        let t: Vec<Q> = uniform_params(5).unwrap();
        assert_eq!(t[1], Q::from_ratio(1, 4).unwrap());
        assert!(uniform_params::<Q>(0).is_err());
        let y = vec![
            Point::new(vec![0.0, 0.0]).unwrap(),
            Point::new(vec![3.0, 4.0]).unwrap(),
            Point::new(vec![3.0, 4.0]).unwrap(),
            Point::new(vec![3.0, 9.0]).unwrap(),
        ];
        assert_eq!(chord_length_params(&y).unwrap(), vec![0.0, 0.5, 0.5, 1.0]);
        let c = centripetal_params(&y).unwrap();
        assert!((c[1] - 0.5).abs() < 1e-15 && c[3] == 1.0);
        let same = vec![y[1].clone(), y[1].clone()];
        assert!(chord_length_params(&same).is_err());
        assert_eq!(chord_length_params(&y[..1]).unwrap(), vec![0.0]);
        let exact: Vec<Point<Q>> = vec![p(&[0, 0]), p(&[3, 4]), p(&[3, 9])];
        assert_eq!(
            chord_length_params_via_f64(&exact).unwrap()[1],
            Q::from_ratio(1, 2).unwrap()
        );
    }
}
