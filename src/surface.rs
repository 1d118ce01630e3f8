//! Tensor-product Bézier surfaces (text 003).

use crate::bernstein::{bernstein_all, bernstein_to_power, power_to_bernstein, reparametrize};
use crate::curve::BezierCurve;
use crate::error::{check_degree, Error, Result};
use crate::hull::convex_weights;
use crate::kernel::{de_casteljau, STACK_POINTS};
use crate::point::{common_dimension, AffineMap, Point};
use crate::scalar::Scalar;
use num_rational::BigRational;
use smallvec::SmallVec;
use std::fmt;

/// A tensor-product Bézier surface of degrees `(m, n)`: its control net `b_{i,j}`,
/// `i = 0..=m` (the `u` direction), `j = 0..=n` (the `v` direction), all points of one
/// dimension.
///
/// `b^{m,n}(u, v) = Σ_{i=0}^m Σ_{j=0}^n b_{i,j} B_i^m(u) B_j^n(v)`: a curve of degree `m` in
/// `u` whose control points move along curves of degree `n` in `v`. The `(m+1)(n+1)` points
/// `b_{i,j}` form the Bézier (control) net; `net[i][j]` is `b_{i,j}`, `i` running in the
/// `u` direction and `j` in the `v` direction.
///
/// Every operation reduces to curve operations on the rows (`i` fixed, a curve in `v`) or
/// the columns (`j` fixed, a curve in `u`) of the net, so all of them are exact for exact
/// scalars and identities such as "u first = v first" are decided with `==`.
///
/// | text 003                                   | here                                         |
/// |--------------------------------------------|----------------------------------------------|
/// | bilinear interpolation, hyperbolic paraboloid | [`BezierSurface::bilinear`]               |
/// | two-stage construction, tensor product     | [`BezierSurface::eval`], [`BezierSurface::eval_v_first`] |
/// | double Bernstein sum                       | [`BezierSurface::eval_bernstein`]            |
/// | isoparametric curves                       | [`BezierSurface::iso_v`], [`BezierSurface::iso_u`] |
/// | a) affine invariance                       | [`BezierSurface::transform`]                 |
/// | b) convex hull property                    | [`BezierSurface::hull_weights`]              |
/// | c) boundary curves, the four corners       | [`BezierSurface::boundary`], [`BezierSurface::corners`] |
/// | Example 5 (Enneper surface)                | [`enneper_net`], [`BezierSurface::enneper_matches`] |
///
/// Beyond the text: partial derivatives ([`BezierSurface::derivative_u`],
/// [`BezierSurface::partial_at`]), subdivision ([`BezierSurface::split_u`]), degree
/// elevation ([`BezierSurface::elevate_u`]) and conversion to and from the power basis
/// ([`BezierSurface::from_power_on`], [`BezierSurface::to_power`]).
///
/// ```
/// use casteljau::{BezierSurface, BigRational, Point, Scalar};
/// let q = |p, d| BigRational::from_ratio(p, d).unwrap();
/// // text 003: bilinear interpolation of four points gives x(u, v) = (u, v, uv), z = xy
/// let s: BezierSurface<BigRational> = BezierSurface::bilinear(
///     Point::from_ints(&[0, 0, 0]).unwrap(),
///     Point::from_ints(&[0, 1, 0]).unwrap(),
///     Point::from_ints(&[1, 0, 0]).unwrap(),
///     Point::from_ints(&[1, 1, 1]).unwrap(),
/// )
/// .unwrap();
/// let (u, v) = (q(1, 3), q(3, 4));
/// assert_eq!(s.eval(&u, &v), Point::new(vec![u.clone(), v.clone(), &u * &v]).unwrap());
/// assert_eq!(s.eval(&u, &v), s.eval_v_first(&u, &v));
/// assert_eq!(s.eval(&u, &v), s.eval_bernstein(&u, &v));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BezierSurface<T> {
    net: Vec<Vec<Point<T>>>,
}

/// A way of writing a surface as a scaled, reparametrised Enneper surface, found by
/// [`BezierSurface::enneper_matches`]:
/// `surface(s, t) = λ E(α s + β, γ t + δ)`, or, when `swapped`, `λ E(γ t + δ, α s + β)`,
/// where `E(u, v) = (u − u³/3 + u v², v − v³/3 + v u², u² − v²)`.
#[derive(Clone, Debug, PartialEq)]
pub struct EnneperMatch<T> {
    /// Whether the surface parameters are swapped (`s` drives Enneper's `v`).
    pub swapped: bool,
    /// `α` in `u = α s + β` (or `v = α s + β` when swapped).
    pub alpha: T,
    /// `β`.
    pub beta: T,
    /// `γ` in `v = γ t + δ` (or `u = γ t + δ` when swapped).
    pub gamma: T,
    /// `δ`.
    pub delta: T,
    /// The scale `λ`.
    pub lambda: T,
}

impl<T: Scalar> BezierSurface<T> {
    /// A surface from its net `net[i][j] = b_{i,j}`. Empty nets, empty rows, ragged nets (rows
    /// of different lengths), mixed dimensions and degrees above [`crate::MAX_DEGREE`] are
    /// errors.
    pub fn new(net: Vec<Vec<Point<T>>>) -> Result<Self> {
        check_net(&net, "a Bézier net")?;
        Ok(BezierSurface { net })
    }

    /// A surface with integer control points: `net[i][j]` are the coordinates of `b_{i,j}`.
    pub fn from_ints(net: &[&[&[i64]]]) -> Result<Self> {
        Self::new(
            net.iter()
                .map(|row| row.iter().map(|c| Point::from_ints(c)).collect::<Result<_>>())
                .collect::<Result<_>>()?,
        )
    }

    /// The bilinear patch through four points (text 003):
    /// `x(u, v) = (1-u)(1-v) b00 + (1-u) v b01 + u (1-v) b10 + u v b11`, a hyperbolic paraboloid
    /// when the points are not coplanar.
    pub fn bilinear(b00: Point<T>, b01: Point<T>, b10: Point<T>, b11: Point<T>) -> Result<Self> {
        Self::new(vec![vec![b00, b01], vec![b10, b11]])
    }

    /// The Bézier net over the unit square of the polynomial surface `Σ_k Σ_l c_{k,l} u^k v^l`
    /// on `[a, b] × [c, d]` (`coeffs[k][l]` is the vector `c_{k,l}`), reparametrised by
    /// `u = a + (b - a) s`, `v = c + (d - c) t`. Degrees are `(coeffs.len() - 1,
    /// coeffs[0].len() - 1)`. Empty intervals and ragged coefficient arrays are errors.
    ///
    /// ```
    /// use casteljau::{Ring, BezierSurface, BigRational, Point, Scalar};
    /// let q = BigRational::from_i64;
    /// let c = |v: &[i64]| Point::from_ints(v).unwrap();
    /// // (u, v, u² - v²) on [-1, 1]²: text 003, Example 2
    /// let coeffs = vec![
    ///     vec![c(&[0, 0, 0]), c(&[0, 1, 0]), c(&[0, 0, -1])],
    ///     vec![c(&[1, 0, 0]), c(&[0, 0, 0]), c(&[0, 0, 0])],
    ///     vec![c(&[0, 0, 1]), c(&[0, 0, 0]), c(&[0, 0, 0])],
    /// ];
    /// let s = BezierSurface::from_power_on(&coeffs, (&q(-1), &q(1)), (&q(-1), &q(1))).unwrap();
    /// assert_eq!(s.net()[0][1], c(&[-1, 0, 2]));
    /// assert_eq!(s.to_power_on((&q(-1), &q(1)), (&q(-1), &q(1))).unwrap(), coeffs);
    /// ```
    pub fn from_power_on(coeffs: &[Vec<Point<T>>], u_range: (&T, &T), v_range: (&T, &T)) -> Result<Self> {
        let (_, _, dim) = check_net(coeffs, "power-basis coefficients")?;
        for (a, b) in [u_range, v_range] {
            if a == b {
                return Err(Error::Domain(format!("the parameter interval [{a}, {b}] is empty")));
            }
        }
        let per_coord: Vec<Vec<Vec<T>>> = (0..dim)
            .map(|k| {
                let m = coordinate(coeffs, k);
                let m = map_rows(&m, |r| Ok(reparametrize(r, v_range.0, v_range.1)))?;
                let m = map_cols(&m, |c| Ok(reparametrize(c, u_range.0, u_range.1)))?;
                let m = map_rows(&m, power_to_bernstein)?;
                map_cols(&m, power_to_bernstein)
            })
            .collect::<Result<_>>()?;
        Self::new(assemble(&per_coord)?)
    }

    /// [`Self::from_power_on`] on the unit square.
    pub fn from_power(coeffs: &[Vec<Point<T>>]) -> Result<Self> {
        let (zero, one) = (T::zero(), T::one());
        Self::from_power_on(coeffs, (&zero, &one), (&zero, &one))
    }

    /// The power-basis coefficients over the unit square: `out[k][l]` is the vector `c_{k,l}`
    /// with `b(u, v) = Σ_k Σ_l c_{k,l} u^k v^l`.
    ///
    /// Exact rationals take forward differences over integers with one reduction per
    /// coefficient (`exact::power_basis`).
    pub fn to_power(&self) -> Result<Vec<Vec<Point<T>>>> {
        if T::CURVE_KERNELS {
            let (m, n) = self.degrees();
            check_degree("degree", m as u128)?;
            check_degree("degree", n as u128)?;
            if let Some(power) = T::surface_to_power(self.net()) {
                return Ok(power);
            }
        }
        self.to_power_reference()
    }

    /// [`Self::to_power`] by forward differences on the scalar type itself: the reference
    /// for the exact kernel.
    pub fn to_power_reference(&self) -> Result<Vec<Vec<Point<T>>>> {
        let per_coord: Vec<Vec<Vec<T>>> = (0..self.dim())
            .map(|k| {
                let m = coordinate(&self.net, k);
                let m = map_cols(&m, bernstein_to_power)?;
                map_rows(&m, bernstein_to_power)
            })
            .collect::<Result<_>>()?;
        assemble(&per_coord)
    }

    /// The inverse of [`Self::from_power_on`]: the coefficients `c_{k,l}` of the polynomial
    /// in `(u, v)` whose restriction to `[a, b] × [c, d]` this surface is, i.e.
    /// `b(s, t) = Σ c_{k,l} u^k v^l` with `u = a + (b - a) s`, `v = c + (d - c) t`.
    pub fn to_power_on(&self, u_range: (&T, &T), v_range: (&T, &T)) -> Result<Vec<Vec<Point<T>>>> {
        let inverse = |(a, b): (&T, &T)| -> Result<(T, T)> {
            // s = (u - a)/(b - a) maps [a, b] to [0, 1]: s = a' + (b' - a') u
            // with a' = -a/(b - a), b' = (1 - a)/(b - a).
            let h = b.sub_ref(a);
            if h.is_zero() {
                return Err(Error::Domain(format!("the parameter interval [{a}, {b}] is empty")));
            }
            Ok((a.neg_ref().checked_div(&h)?, T::one().sub_ref(a).checked_div(&h)?))
        };
        let (ua, ub) = inverse(u_range)?;
        let (va, vb) = inverse(v_range)?;
        let power = self.to_power()?;
        let per_coord: Vec<Vec<Vec<T>>> = (0..self.dim())
            .map(|k| {
                let m = coordinate(&power, k);
                let m = map_rows(&m, |r| Ok(reparametrize(r, &va, &vb)))?;
                map_cols(&m, |c| Ok(reparametrize(c, &ua, &ub)))
            })
            .collect::<Result<_>>()?;
        assemble(&per_coord)
    }

    /// The degrees `(m, n)`: `m` in `u`, `n` in `v`.
    pub fn degrees(&self) -> (usize, usize) {
        (self.net.len() - 1, self.net[0].len() - 1)
    }

    /// The dimension of the control points.
    pub fn dim(&self) -> usize {
        self.net[0][0].dim()
    }

    /// The control net, `net()[i][j] = b_{i,j}`.
    pub fn net(&self) -> &[Vec<Point<T>>] {
        &self.net
    }

    /// The control net, by value.
    pub fn into_net(self) -> Vec<Vec<Point<T>>> {
        self.net
    }

    /// The control point `b_{i,j}`, if the indices are in range.
    pub fn get(&self, i: usize, j: usize) -> Option<&Point<T>> {
        self.net.get(i)?.get(j)
    }

    /// The same surface with `u` and `v` exchanged: `b'(u, v) = b(v, u)`, net transposed.
    pub fn transpose(&self) -> Self {
        BezierSurface {
            net: transpose(&self.net),
        }
    }

    /// Converts the coordinates to another scalar type (e.g. exact → `f64`).
    pub fn try_map<U: Scalar>(&self, f: impl Fn(&T) -> Result<U> + Copy) -> Result<BezierSurface<U>> {
        BezierSurface::new(
            self.net
                .iter()
                .map(|row| row.iter().map(|p| p.try_map(f)).collect::<Result<_>>())
                .collect::<Result<_>>()?,
        )
    }

    /// `b(u, v)` by the tensor de Casteljau algorithm, `u` first: each column `b_{·,j}` is
    /// reduced at `u` (giving the control points of the `u = u0` curve), then that curve is
    /// evaluated at `v`. Defined for every `(u, v)`, not only the unit square.
    ///
    /// Exact rationals take nested sums over integers with one reduction per coordinate
    /// ([`BezierSurface::eval_nested`]).
    pub fn eval(&self, u: &T, v: &T) -> Point<T> {
        if let Some(p) = T::surface_eval(self.net(), u, v) {
            return p;
        }
        self.iso_u(u).eval(v)
    }

    /// `b(u, v)` by the tensor de Casteljau algorithm, `v` first: each row `b_{i,·}` is
    /// reduced at `v` (the control points of the `v = v0` curve of the text), then that curve
    /// is evaluated at `u`. Equal to [`Self::eval`] exactly for exact scalars.
    pub fn eval_v_first(&self, u: &T, v: &T) -> Point<T> {
        self.iso_v(v).eval(u)
    }

    /// `b(u, v) = Σ_i Σ_j b_{i,j} B_i^m(u) B_j^n(v)`, the double Bernstein sum.
    pub fn eval_bernstein(&self, u: &T, v: &T) -> Point<T> {
        let (m, n) = self.degrees();
        let bu = bernstein_all(m, u);
        let bv = bernstein_all(n, v);
        let mut acc = Point::origin(self.dim());
        for (row, wu) in self.net.iter().zip(&bu) {
            for (p, wv) in row.iter().zip(&bv) {
                acc.add_scaled_assign(&wu.mul_ref(wv), p);
            }
        }
        acc
    }

    /// The isoparametric curve `v = v0`: a curve in `u` of degree `m` whose control points
    /// are `Σ_j b_{i,j} B_j^n(v0)`, `i = 0..=m` (text 003).
    pub fn iso_v(&self, v0: &T) -> BezierCurve<T> {
        let points = self.net.iter().map(|row| reduce(row.iter().cloned(), v0)).collect();
        BezierCurve::new(points).expect("rows are non-empty and of one dimension")
    }

    /// The isoparametric curve `u = u0`: a curve in `v` of degree `n` with control points
    /// `Σ_i b_{i,j} B_i^m(u0)`, `j = 0..=n`.
    pub fn iso_u(&self, u0: &T) -> BezierCurve<T> {
        let n = self.degrees().1;
        let points = (0..=n)
            .map(|j| reduce(self.net.iter().map(|row| row[j].clone()), u0))
            .collect();
        BezierCurve::new(points).expect("columns are non-empty and of one dimension")
    }

    /// The four boundary curves, each in the direction of increasing parameter:
    /// `[v = 0 (b_{0,0} → b_{m,0}), u = 1 (b_{m,0} → b_{m,n}), v = 1 (b_{0,n} → b_{m,n}),
    /// u = 0 (b_{0,0} → b_{0,n})]`. Their control points are the edges of the net
    /// (text 003, c)).
    pub fn boundary(&self) -> [BezierCurve<T>; 4] {
        let (m, n) = self.degrees();
        let col = |j: usize| self.net.iter().map(|row| row[j].clone()).collect::<Vec<_>>();
        let curve = |pts| BezierCurve::new(pts).expect("edges of a valid net are valid polygons");
        [
            curve(col(0)),
            curve(self.net[m].clone()),
            curve(col(n)),
            curve(self.net[0].clone()),
        ]
    }

    /// The four corners the surface passes through, `[b_{0,0}, b_{m,0}, b_{0,n}, b_{m,n}]`
    /// (text 003, c)), i.e. `b(0,0), b(1,0), b(0,1), b(1,1)`.
    pub fn corners(&self) -> [Point<T>; 4] {
        let (m, n) = self.degrees();
        [
            self.net[0][0].clone(),
            self.net[m][0].clone(),
            self.net[0][n].clone(),
            self.net[m][n].clone(),
        ]
    }

    /// The net of `∂^k b / ∂u^k`: `m!/(m-k)! Δ_u^k b_{i,j}`, degrees `(m - k, n)`.
    /// `k > m` is [`Error::DerivativeOrder`].
    pub fn derivative_u(&self, k: usize) -> Result<Self> {
        let cols = transpose(&self.net)
            .into_iter()
            .map(|col| Ok(curve_of(col).derivative(k)?.into_points()))
            .collect::<Result<Vec<_>>>()?;
        Self::new(transpose(&cols))
    }

    /// The net of `∂^k b / ∂v^k`: `n!/(n-k)! Δ_v^k b_{i,j}`, degrees `(m, n - k)`.
    /// `k > n` is [`Error::DerivativeOrder`].
    pub fn derivative_v(&self, k: usize) -> Result<Self> {
        let rows = self
            .net
            .iter()
            .map(|row| Ok(curve_of(row.clone()).derivative(k)?.into_points()))
            .collect::<Result<Vec<_>>>()?;
        Self::new(rows)
    }

    /// The net of the mixed partial `∂^{ku+kv} b / ∂u^{ku} ∂v^{kv}`, degrees
    /// `(m - ku, n - kv)`; orders beyond the degrees are [`Error::DerivativeOrder`].
    pub fn derivative(&self, ku: usize, kv: usize) -> Result<Self> {
        self.derivative_u(ku)?.derivative_v(kv)
    }

    /// The partial derivative `∂^{ku+kv} b / ∂u^{ku} ∂v^{kv}` at `(u, v)`. When an order
    /// exceeds its degree the derivative is the zero vector (as for curves); use
    /// [`Self::derivative`] for the net, which rejects such orders.
    pub fn partial_at(&self, ku: usize, kv: usize, u: &T, v: &T) -> Result<Point<T>> {
        let (m, n) = self.degrees();
        if ku > m || kv > n {
            return Ok(Point::origin(self.dim()));
        }
        Ok(self.derivative(ku, kv)?.eval(u, v))
    }

    /// Subdivision at `u = u0`: the surfaces `b(u0 s, v)` and `b(u0 + (1 - u0) s, v)`
    /// (every column split by de Casteljau). Any `u0` works; outside `(0, 1)` the pieces
    /// extrapolate.
    pub fn split_u(&self, u0: &T) -> (Self, Self) {
        let (left, right): (Vec<_>, Vec<_>) = transpose(&self.net)
            .into_iter()
            .map(|col| {
                let (l, r) = curve_of(col).split_at(u0);
                (l.into_points(), r.into_points())
            })
            .unzip();
        (
            BezierSurface { net: transpose(&left) },
            BezierSurface { net: transpose(&right) },
        )
    }

    /// Subdivision at `v = v0`: the surfaces `b(u, v0 t)` and `b(u, v0 + (1 - v0) t)`.
    pub fn split_v(&self, v0: &T) -> (Self, Self) {
        let (left, right): (Vec<_>, Vec<_>) = self
            .net
            .iter()
            .map(|row| {
                let (l, r) = curve_of(row.clone()).split_at(v0);
                (l.into_points(), r.into_points())
            })
            .unzip();
        (BezierSurface { net: left }, BezierSurface { net: right })
    }

    /// Subdivision at `(u0, v0)` into four patches, in the order
    /// `[u ≤ u0 ∧ v ≤ v0, u ≥ u0 ∧ v ≤ v0, u ≤ u0 ∧ v ≥ v0, u ≥ u0 ∧ v ≥ v0]`.
    pub fn split_at(&self, u0: &T, v0: &T) -> [Self; 4] {
        let (a, b) = self.split_u(u0);
        let (a0, a1) = a.split_v(v0);
        let (b0, b1) = b.split_v(v0);
        [a0, b0, a1, b1]
    }

    /// Degree elevation in `u`: the same surface with degrees `(m + 1, n)` (every column
    /// elevated by (7) of text 000).
    pub fn elevate_u(&self) -> Result<Self> {
        let cols = transpose(&self.net)
            .into_iter()
            .map(|col| Ok(curve_of(col).elevate()?.into_points()))
            .collect::<Result<Vec<_>>>()?;
        Self::new(transpose(&cols))
    }

    /// Degree elevation in `v`: the same surface with degrees `(m, n + 1)`.
    pub fn elevate_v(&self) -> Result<Self> {
        let rows = self
            .net
            .iter()
            .map(|row| Ok(curve_of(row.clone()).elevate()?.into_points()))
            .collect::<Result<Vec<_>>>()?;
        Self::new(rows)
    }

    /// The image under an affine map: the surface of the mapped net (text 003, a)).
    pub fn transform(&self, map: &AffineMap<T>) -> Result<Self> {
        Self::new(self.net.iter().map(|row| map.apply_all(row)).collect::<Result<_>>()?)
    }

    /// Convex weights expressing `p` through the control points when `p` lies in the convex
    /// hull of the net, `None` otherwise (text 003, b); see [`crate::hull::convex_weights`]).
    /// The weights are in row-major order: weight of `b_{i,j}` at index `i (n + 1) + j`.
    pub fn hull_weights(&self, p: &Point<T>) -> Result<Option<Vec<T>>> {
        let all: Vec<Point<T>> = self.net.iter().flatten().cloned().collect();
        convex_weights(&all, p)
    }

    /// Whether `p` lies in the convex hull of the control net.
    pub fn hull_contains(&self, p: &Point<T>) -> Result<bool> {
        Ok(self.hull_weights(p)?.is_some())
    }

    /// The positions `(i, j)` where the nets of `self` and `other` differ (exactly, with `==`),
    /// in row-major order. Different degrees or dimensions are an error.
    pub fn net_differences(&self, other: &Self) -> Result<Vec<(usize, usize)>> {
        if self.degrees() != other.degrees() {
            let (a, b) = (self.degrees(), other.degrees());
            return Err(Error::Domain(format!(
                "nets of different degrees: ({}, {}) and ({}, {})",
                a.0, a.1, b.0, b.1
            )));
        }
        if self.dim() != other.dim() {
            return Err(Error::DimensionMismatch {
                expected: self.dim(),
                found: other.dim(),
                context: "comparison of nets".into(),
            });
        }
        let mut out = Vec::new();
        for (i, (r1, r2)) in self.net.iter().zip(&other.net).enumerate() {
            for (j, (p1, p2)) in r1.iter().zip(r2).enumerate() {
                if p1 != p2 {
                    out.push((i, j));
                }
            }
        }
        Ok(out)
    }

    /// All ways of writing this surface exactly as `λ E(α s + β, γ t + δ)` (or with `s` and
    /// `t` exchanged), where `E` is Enneper's surface
    /// `(u − u³/3 + u v², v − v³/3 + v u², u² − v²)`, with `α, γ, λ ≠ 0`. Empty when it is
    /// not such a surface. Degrees may exceed 3 (an elevated net still matches).
    ///
    /// The parameters are read off a few power coefficients (`α = −3 x_{30}/z_{20}`,
    /// `λ = z_{20}/α²`, `β = z_{10}/(2λα)`, `γ = 3 y_{03}/z_{02}`, `δ = −z_{01}/(2λγ)`) and then
    /// *every* coefficient is compared with `==`. A verdict is never decided in floating
    /// point, so inexact scalars are an error. The surface must be in 3D.
    ///
    /// ```
    /// use casteljau::{Ring, enneper_net, BezierSurface, BigRational, Scalar};
    /// let e = enneper_net(&BigRational::from_i64(1)).unwrap();
    /// let found = e.enneper_matches().unwrap();
    /// assert_eq!(found.len(), 1);
    /// assert_eq!(found[0].alpha, BigRational::from_i64(2)); // u = 2s - 1
    /// ```
    pub fn enneper_matches(&self) -> Result<Vec<EnneperMatch<T>>> {
        if !T::EXACT {
            return Err(Error::Domain(format!(
                "matching against the Enneper surface is an exact verdict; use exact scalars, not {}",
                T::NAME
            )));
        }
        if self.dim() != 3 {
            return Err(Error::DimensionMismatch {
                expected: 3,
                found: self.dim(),
                context: "Enneper surface match".into(),
            });
        }
        let mut out = Vec::new();
        if let Some(found) = match_enneper_power(&self.to_power()?, false)? {
            out.push(found);
        }
        if let Some(found) = match_enneper_power(&self.transpose().to_power()?, true)? {
            out.push(found);
        }
        Ok(out)
    }
}

/// The power coefficients `c[k][l]` (of `u^k v^l`) of Enneper's minimal surface
/// `E(u, v) = (u − u³/3 + u v², v − v³/3 + v u², u² − v²)`, a 4×4 array of 3D vectors.
pub fn enneper_power<T: Scalar>() -> Result<Vec<Vec<Point<T>>>> {
    let third = T::from_ratio(-1, 3)?;
    let mut c = vec![vec![[T::zero(), T::zero(), T::zero()]; 4]; 4];
    c[1][0][0] = T::one();
    c[3][0][0] = third.clone();
    c[1][2][0] = T::one();
    c[0][1][1] = T::one();
    c[0][3][1] = third;
    c[2][1][1] = T::one();
    c[2][0][2] = T::one();
    c[0][2][2] = -T::one();
    c.into_iter()
        .map(|row| row.into_iter().map(|p| Point::new(p.to_vec())).collect())
        .collect()
}

/// The exact bicubic Bézier net of Enneper's surface on `[−r, r]²` (over the unit square,
/// `u = r(2s − 1)`, `v = r(2t − 1)`). `r = 0` is an error.
///
/// ```
/// use casteljau::{Ring, enneper_net, AffineMap, BigRational, Scalar};
/// // text 003, Example 5 is 3 × (Enneper on [−2, 2]²)
/// let e = enneper_net(&BigRational::from_i64(2)).unwrap();
/// let e = e.transform(&AffineMap::scaling(3, &BigRational::from_i64(3))).unwrap();
/// assert_eq!(e.net()[0][0], casteljau::Point::from_ints(&[-22, -22, 0]).unwrap());
/// ```
pub fn enneper_net<T: Scalar>(r: &T) -> Result<BezierSurface<T>> {
    let minus_r = r.neg_ref();
    BezierSurface::from_power_on(&enneper_power()?, (&minus_r, r), (&minus_r, r))
}

/// Tries `power(s, t) = λ E(α s + β, γ t + δ)` with `power` the coefficients of a surface.
fn match_enneper_power<T: Scalar>(power: &[Vec<Point<T>>], swapped: bool) -> Result<Option<EnneperMatch<T>>> {
    let zero = T::zero();
    let c = |k: usize, l: usize, coord: usize| -> &T {
        power
            .get(k)
            .and_then(|row| row.get(l))
            .map_or(&zero, |p| &p.coords()[coord])
    };
    let (x30, y03, z20, z10, z02, z01) = (c(3, 0, 0), c(0, 3, 1), c(2, 0, 2), c(1, 0, 2), c(0, 2, 2), c(0, 1, 2));
    if z20.is_zero() || z02.is_zero() || x30.is_zero() || y03.is_zero() {
        return Ok(None);
    }
    let three = T::from_i64(3);
    let two = T::from_i64(2);
    // z = λ(u² − v²) gives z20 = λα², z10 = 2λαβ, z02 = −λγ², z01 = −2λγδ;
    // x30 = −λα³/3 and y03 = −λγ³/3.
    let alpha = three.neg_ref().mul_ref(x30).checked_div(z20)?;
    let lambda = z20.checked_div(&alpha.mul_ref(&alpha))?;
    let beta = z10.checked_div(&two.mul_ref(&lambda).mul_ref(&alpha))?;
    let gamma = three.mul_ref(y03).checked_div(z02)?;
    let delta = z01.neg_ref().checked_div(&two.mul_ref(&lambda).mul_ref(&gamma))?;
    let alpha_plus_beta = alpha.add_ref(&beta);
    let gamma_plus_delta = gamma.add_ref(&delta);
    let candidate = BezierSurface::<T>::from_power_on(
        &enneper_power()?,
        (&beta, &alpha_plus_beta),
        (&delta, &gamma_plus_delta),
    )?
    .transform(&AffineMap::scaling(3, &lambda))?
    .to_power()?;
    let rows = power.len().max(candidate.len());
    let cols = power[0].len().max(candidate[0].len());
    for k in 0..rows {
        for l in 0..cols {
            for coord in 0..3 {
                let theirs = candidate
                    .get(k)
                    .and_then(|row| row.get(l))
                    .map_or(&zero, |p| &p.coords()[coord]);
                if c(k, l, coord) != theirs {
                    return Ok(None);
                }
            }
        }
    }
    Ok(Some(EnneperMatch {
        swapped,
        alpha,
        beta,
        gamma,
        delta,
        lambda,
    }))
}

/// Validates a rectangular array of points; returns `(m, n, dim)`.
fn check_net<T: Scalar>(net: &[Vec<Point<T>>], what: &'static str) -> Result<(usize, usize, usize)> {
    let first = net.first().ok_or(Error::Empty(what))?;
    let cols = first.len();
    let dim = common_dimension(first, what)?;
    for (i, row) in net.iter().enumerate() {
        if row.is_empty() {
            return Err(Error::Domain(format!("{what}: row {i} is empty")));
        }
        if row.len() != cols {
            return Err(Error::Domain(format!(
                "{what} is ragged: row 0 has {cols} points, row {i} has {}",
                row.len()
            )));
        }
        for (j, p) in row.iter().enumerate() {
            if p.dim() != dim {
                return Err(Error::DimensionMismatch {
                    expected: dim,
                    found: p.dim(),
                    context: format!("{what}, point ({i}, {j})"),
                });
            }
        }
    }
    let m = check_degree("degree in u", net.len() as u128 - 1)?;
    let n = check_degree("degree in v", cols as u128 - 1)?;
    Ok((m, n, dim))
}

/// `Σ_i p_i B_i^m(t)` for the `m + 1` points given: de Casteljau's algorithm (1) on a
/// column of the net, on the stack.
fn reduce<T: Scalar>(points: impl IntoIterator<Item = Point<T>>, t: &T) -> Point<T> {
    if T::EXACT {
        // Exact rationals: the curve's point by the exact kernels of `BezierCurve::eval`,
        // where de Casteljau's steps reduce a fraction at every step.
        return curve_of(points.into_iter().collect()).eval(t);
    }
    let mut column: SmallVec<[Point<T>; STACK_POINTS]> = points.into_iter().collect();
    de_casteljau(&mut column, t, |_| {});
    column.swap_remove(0)
}

fn curve_of<T: Scalar>(points: Vec<Point<T>>) -> BezierCurve<T> {
    BezierCurve::new(points).expect("rows and columns of a valid net are valid polygons")
}

fn transpose<P: Clone>(net: &[Vec<P>]) -> Vec<Vec<P>> {
    let cols = net.first().map_or(0, Vec::len);
    (0..cols)
        .map(|j| net.iter().map(|row| row[j].clone()).collect())
        .collect()
}

/// The `k`-th coordinates of a rectangular array of points.
fn coordinate<T: Scalar>(net: &[Vec<Point<T>>], k: usize) -> Vec<Vec<T>> {
    net.iter()
        .map(|row| row.iter().map(|p| p.coords()[k].clone()).collect())
        .collect()
}

/// Points from per-coordinate arrays: `out[i][j] = (per_coord[0][i][j], …)`.
fn assemble<T: Scalar>(per_coord: &[Vec<Vec<T>>]) -> Result<Vec<Vec<Point<T>>>> {
    let first = per_coord.first().ok_or(Error::ZeroDimension)?;
    (0..first.len())
        .map(|i| {
            (0..first[i].len())
                .map(|j| Point::new(per_coord.iter().map(|c| c[i][j].clone()).collect()))
                .collect()
        })
        .collect()
}

fn map_rows<T: Clone>(m: &[Vec<T>], f: impl Fn(&[T]) -> Result<Vec<T>>) -> Result<Vec<Vec<T>>> {
    m.iter().map(|row| f(row)).collect()
}

fn map_cols<T: Clone>(m: &[Vec<T>], f: impl Fn(&[T]) -> Result<Vec<T>>) -> Result<Vec<Vec<T>>> {
    Ok(transpose(&map_rows(&transpose(m), f)?))
}

impl<T: fmt::Display> fmt::Display for BezierSurface<T> {
    /// One row of the net per line: `b_{i,0}; b_{i,1}; …`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, row) in self.net.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            write!(f, "{}", crate::point::PointList(row))?;
        }
        Ok(())
    }
}

impl BezierSurface<BigRational> {
    /// `b(u, v)` by nested sums over integers, rows at `v` then the column at `u`, one
    /// reduction per coordinate; equals [`BezierSurface::eval`], which runs it for exact
    /// rationals.
    pub fn eval_nested(&self, u: &BigRational, v: &BigRational) -> Point<BigRational> {
        crate::exact::fraction_free::surface_point(self.net(), u, v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Ring;
    use num_rational::BigRational;
    type Q = BigRational;

    fn q(p: i64, d: i64) -> Q {
        Q::from_ratio(p, d).unwrap()
    }

    #[test]
    fn bad_nets_are_errors() {
        assert!(matches!(BezierSurface::<Q>::new(vec![]), Err(Error::Empty(_))));
        assert!(BezierSurface::<Q>::new(vec![vec![]]).is_err());
        assert!(BezierSurface::<Q>::from_ints(&[&[&[0]], &[]]).is_err());
        let ragged = BezierSurface::<Q>::from_ints(&[&[&[0], &[1]], &[&[2]]]).unwrap_err();
        assert!(ragged.to_string().contains("ragged"), "{ragged}");
        assert!(matches!(
            BezierSurface::<Q>::from_ints(&[&[&[0, 0], &[1, 0]], &[&[2, 0], &[1]]]),
            Err(Error::DimensionMismatch { .. })
        ));
        let s = BezierSurface::<Q>::from_ints(&[&[&[0], &[1]], &[&[2], &[3]]]).unwrap();
        assert!(matches!(
            s.derivative_u(2),
            Err(Error::DerivativeOrder { order: 2, degree: 1 })
        ));
        assert!(matches!(s.derivative_v(3), Err(Error::DerivativeOrder { .. })));
        assert_eq!(
            s.partial_at(2, 0, &q(1, 2), &q(1, 2)).unwrap(),
            Point::from_ints(&[0]).unwrap()
        );
        assert!(s.enneper_matches().is_err());
        let zero = Q::from_i64(0);
        let one = Q::from_i64(1);
        assert!(BezierSurface::from_power_on(s.net(), (&one, &one), (&zero, &one)).is_err());
        assert!(enneper_net(&zero).is_err());
        let f = s.try_map(|x| Ok(x.to_f64())).unwrap();
        assert!(f.enneper_matches().is_err());
    }

    #[test]
    fn degree_zero_surface() {
        let s = BezierSurface::<Q>::from_ints(&[&[&[4, 5]]]).unwrap();
        assert_eq!(s.degrees(), (0, 0));
        assert_eq!(s.eval(&q(1, 3), &q(7, 2)), Point::from_ints(&[4, 5]).unwrap());
        assert_eq!(s.elevate_u().unwrap().degrees(), (1, 0));
        assert_eq!(s.to_power().unwrap(), vec![vec![Point::from_ints(&[4, 5]).unwrap()]]);
    }
}
