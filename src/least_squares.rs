//! Least-squares fitting of sample points by a Bézier curve of any degree.
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

use crate::bernstein::bernstein_all;
use crate::curve::BezierCurve;
use crate::error::{Error, Result};
use crate::fit::check_finite;
use crate::linalg::{solve, solve_many, Matrix};
use crate::point::{common_dimension, Point, Vector};
use crate::scalar::Scalar;

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
