//! Fitting Bézier curves: the cubic approximation of a space curve of text 004 (general
//! least squares is in `least_squares.rs`).
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

use crate::bernstein::{bernstein, eval_power};
use crate::curve::BezierCurve;
use crate::error::{check_degree, Error, Result};
use crate::exact::fit_numbers::FitNumbers;
use crate::linalg::{solve, Matrix};
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

pub(crate) fn check_finite<T: Scalar>(p: &Point<T>, what: &str) -> Result<()> {
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

/// Text 004's fit: solves the normal equations (11) and returns `k`, `l`, the cubic (4),
/// `δ²` and diagnostics. Exact rationals run a fraction-free kernel (integers over common
/// denominators, one reduction per output number); other scalars row-reduce (11) with the
/// solver of [`crate::linalg`]. The tests compare the two with `==` on exact inputs.
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
    if let Some(fit) = T::cubic_fit([&data.x0, &data.x1, &data.xh, &data.d0, &data.d1]) {
        return fit_cubic_fraction_free(data, fit);
    }
    fit_cubic_by_elimination(data)
}

/// [`fit_cubic`] by row reduction of (11) in `T`'s own arithmetic: every type but
/// `BigRational`, and the reference the fraction-free kernel is tested against.
fn fit_cubic_by_elimination<T: Scalar>(data: &CubicFitData<T>) -> Result<CubicFit<T>> {
    let (matrix, rhs) = data.normal_equations();
    let solution = solve(&matrix, &rhs).map_err(|e| match e {
        Error::Singular(_) => Error::Singular(parallel_message(data)),
        other => other,
    })?;
    let k = solution[0].neg_ref();
    let l = solution[1].clone();
    finish_cubic_fit(data, k, l)
}

/// [`fit_cubic`] on exact rationals without a gcd per operation (num-rational reduces every
/// sum and product by a binary gcd, the cost of the row reduction on rationals).
///
/// With `ẋ(0) = a/D₀`, `ẋ(1) = b/D₁`, `x(0), x(1), x(1/2) = u/D, w/D, h/D` (integer vectors
/// over least common denominators) and `c = u + w − 2h` (so `X = c/D`), the solution of (11)
/// by Cramer's rule is, with `Δ = (a·a)(b·b) − (a·b)² > 0` and `E = 3DΔ`:
///
/// ```text
/// k = D₀ K / E,  K = 4((a·b)(b·c) − (b·b)(a·c));   l = D₁ L / E,  L = 4((a·a)(b·c) − (a·b)(a·c))
/// a1 = (3Δu + K a) / E,   a2 = (3Δw − L b) / E
/// a(1/2) − x(1/2) = R / (8DΔ),  R = 4Δc + K a − L b;   δ² = R·R / (8DΔ)²;   det G = Δ / (D₀D₁)²
/// ```
///
/// all integer arithmetic (machine words while they fit, else big integers), one reduction
/// per output number.
fn fit_cubic_fraction_free<T: Scalar>(data: &CubicFitData<T>, fit: Option<FitNumbers<T>>) -> Result<CubicFit<T>> {
    let FitNumbers {
        k,
        l,
        controls: [a1, a2],
        residual,
        delta2,
        gram_determinant,
    } = fit.ok_or_else(|| Error::Singular(parallel_message(data)))?;
    let curve = BezierCurve::new(vec![data.x0.clone(), a1, a2, data.x1.clone()])?;
    Ok(CubicFit {
        warnings: sign_warnings(&k, &l),
        k,
        l,
        curve,
        delta2,
        residual,
        gram_determinant,
    })
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
    let mut warnings = sign_warnings(&k, &l);
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

/// The warnings when `k ≤ 0` or `l ≤ 0`, which the text assumes positive.
fn sign_warnings<T: Scalar>(k: &T, l: &T) -> Vec<String> {
    let mut warnings = Vec::new();
    if *k <= T::zero() {
        warnings.push(format!(
            "k = {k} <= 0: the optimal a1 - a0 = k x'(0) does not point along x'(0); text 004 assumes k > 0"
        ));
    }
    if *l <= T::zero() {
        warnings.push(format!(
            "l = {l} <= 0: the optimal a3 - a2 = l x'(1) does not point along x'(1); text 004 assumes l > 0"
        ));
    }
    warnings
}

/// `(k, l)` by the closed form (13): `(−k, l)ᵀ = 4/3 · adj(G) (ẋ(0)·X, ẋ(1)·X)ᵀ / det G`,
/// computed literally in `T`'s arithmetic, independently of [`fit_cubic`]'s kernels so the
/// two can be compared. `det G = 0` (for floats: `|det G| ≤ 1e-12 |ẋ(0)|²|ẋ(1)|²`) is [`Error::Singular`].
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::fit_numbers::FitData;
    use crate::exact::fraction_free::Int;
    use crate::least_squares::*;
    use num_bigint::BigInt;
    use num_rational::BigRational;
    use proptest::prelude::*;
    type Q = BigRational;

    /// The kernel on the data's points, on integers `I`.
    fn fit_cubic_on<I: Int>(d: &CubicFitData<Q>) -> Option<Option<FitNumbers>> {
        let data = FitData {
            x0: &d.x0,
            x1: &d.x1,
            xh: &d.xh,
            d0: &d.d0,
            d1: &d.d1,
        };
        crate::exact::fit_numbers::fit_cubic_on::<I>(&data)
    }

    /// Coordinates from small fractions to numerators and denominators at the ends of `i64`
    /// (whose products overflow `i128`), zero among them.
    fn coordinate() -> impl Strategy<Value = Q> {
        let edge = prop_oneof![
            Just(0i64),
            Just(1),
            Just(-1),
            Just(i64::MAX),
            Just(i64::MIN + 1),
            Just(i64::MAX - 1)
        ];
        let whole = || prop_oneof![-50i64..=50, any::<i64>(), edge.clone()];
        let den = prop_oneof![1i64..=20, 1i64..=i64::MAX, Just(i64::MAX), Just(1 << 62)];
        (whole(), den).prop_map(|(n, d)| Q::new(n.into(), d.into()))
    }

    fn fit_data() -> impl Strategy<Value = CubicFitData<Q>> {
        (2usize..=4).prop_flat_map(|dim| {
            let point = move || proptest::collection::vec(coordinate(), dim).prop_map(|c| Point::new(c).unwrap());
            (point(), point(), point(), point(), point())
                .prop_map(|(x0, x1, xh, d0, d1)| CubicFitData::new(x0, x1, xh, d0, d1).unwrap())
        })
    }

    proptest! {
        /// The fraction-free kernel equals row reduction in num-rational's arithmetic, `==` on
        /// every field and on every error; its machine-word tier, when it does not overflow,
        /// equals its big-integer tier.
        #[test]
        fn fraction_free_fit_equals_elimination(mut d in fit_data(), parallel in any::<bool>(), scale in coordinate()) {
            if parallel {
                d.d1 = d.d0.scale(&scale);
            }
            let fast = fit_cubic(&d).map_err(|e| e.to_string());
            prop_assert_eq!(&fast, &fit_cubic_by_elimination(&d).map_err(|e| e.to_string()));
            if let Some(words) = fit_cubic_on::<i128>(&d) {
                prop_assert_eq!(words, fit_cubic_on::<BigInt>(&d).unwrap());
            }
        }
    }

    #[test]
    fn fraction_free_fit_runs_both_tiers() {
        let small = CubicFitData::new(p(&[0, 0]), p(&[4, 0]), p(&[2, 2]), p(&[3, 6]), p(&[3, -6])).unwrap();
        assert!(fit_cubic_on::<i128>(&small).is_some());
        let big = CubicFitData::new(
            p(&[0, 0]),
            p(&[4, 0]),
            p(&[2, 2]),
            p(&[i64::MAX, 6]),
            p(&[3, i64::MIN + 1]),
        )
        .unwrap();
        assert!(fit_cubic_on::<i128>(&big).is_none());
        for d in [small, big] {
            assert_eq!(fit_cubic(&d).unwrap(), fit_cubic_by_elimination(&d).unwrap());
        }
    }

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
