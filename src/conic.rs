//! Conics of rational quadratic arcs (text 001, §1.6): the affine type from the weights, the
//! shape factor, and the implicit equation `A x² + B xy + C y² + D x + E y + F = 0` of the arc.

use crate::error::{Error, Result};
use crate::point::Point;
use crate::rational::RationalBezierCurve;
use crate::scalar::Scalar;
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::fmt;

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
    /// An implicit conic with `B² − 4AC < 0` and no real points, like `x² + y² + 1 = 0` (only
    /// from [`ImplicitConic::kind`]).
    ImaginaryEllipse,
    /// An implicit equation with `A = B = C = 0`: a line or nothing, not a conic (only from
    /// [`ImplicitConic::kind`]).
    NoQuadraticTerms,
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
            ConicKind::ImaginaryEllipse => "imaginary ellipse (no real points)",
            ConicKind::NoQuadraticTerms => "not a conic (no quadratic terms)",
        }
    }

    /// The name a claim file gives the kind (`conic = "…"`): the three types, `degenerate`
    /// for every degenerate case, and the two implicit equations without a real conic.
    pub fn family(&self) -> &'static str {
        match self {
            ConicKind::Ellipse => "ellipse",
            ConicKind::Parabola => "parabola",
            ConicKind::Hyperbola => "hyperbola",
            ConicKind::DegenerateCollinear | ConicKind::DegenerateZeroWeight | ConicKind::DegenerateSingular => {
                "degenerate"
            }
            ConicKind::ImaginaryEllipse | ConicKind::NoQuadraticTerms => self.as_str(),
        }
    }

    /// Whether this is one of the degenerate cases (the arc or the conic is a line, a line pair
    /// or a point, or the equation has no quadratic terms).
    pub fn is_degenerate(&self) -> bool {
        matches!(
            self,
            ConicKind::DegenerateCollinear
                | ConicKind::DegenerateZeroWeight
                | ConicKind::DegenerateSingular
                | ConicKind::NoQuadraticTerms
        )
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

    /// The affine type by `B² − 4AC`; [`ConicKind::NoQuadraticTerms`] when `A = B = C = 0`,
    /// [`ConicKind::DegenerateSingular`] when [`Self::matrix_determinant`] is zero, and
    /// [`ConicKind::ImaginaryEllipse`] for `B² − 4AC < 0` with `(A + C)·det > 0` (no real
    /// points). Exact for exact scalars: every sign is decided.
    pub fn kind(&self) -> ConicKind {
        if [&self.a, &self.b, &self.c].iter().all(|x| x.is_zero()) {
            return ConicKind::NoQuadraticTerms;
        }
        let det = self.matrix_determinant();
        if det.is_zero() {
            return ConicKind::DegenerateSingular;
        }
        let disc = self.discriminant();
        if disc.is_zero() {
            ConicKind::Parabola
        } else if disc > T::zero() {
            ConicKind::Hyperbola
        } else if self.a.add_ref(&self.c).mul_ref(&det) < T::zero() {
            ConicKind::Ellipse
        } else {
            ConicKind::ImaginaryEllipse
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
