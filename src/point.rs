//! Points and vectors of any dimension, barycentric combinations and affine maps.
//!
//! The texts use one letter for points and difference vectors alike, and so does this
//! module: [`Point`] is a coordinate tuple, [`Vector`] an alias for it. What makes a
//! combination of points meaningful is that its weights sum to one ([`barycentric`]), which
//! is exactly why Bézier curves are invariant under [`AffineMap`]s.

use crate::error::{Error, Result, MAX_DIMENSION};
use crate::scalar::Scalar;
use crate::space::{parse_tuple, point_ops, point_ref_ops, write_tuple, VectorSpace};
use smallvec::SmallVec;
use std::fmt;
use std::ops::{Index, IndexMut};
use std::str::FromStr;

pub use crate::coords::Point;

/// A difference of two points; the same type as [`Point`].
pub type Vector<T> = Point<T>;

impl<T: Scalar> Point<T> {
    /// A point from its coordinates; at least one, at most [`MAX_DIMENSION`].
    pub fn new(coords: Vec<T>) -> Result<Self> {
        if coords.is_empty() {
            return Err(Error::ZeroDimension);
        }
        if coords.len() > MAX_DIMENSION {
            return Err(Error::TooLarge {
                what: "dimension",
                value: coords.len().to_string(),
                limit: MAX_DIMENSION.to_string(),
            });
        }
        Ok(Point {
            coords: SmallVec::from_vec(coords),
        })
    }

    /// A point with integer coordinates, convenient for literals.
    ///
    /// ```
    /// use casteljau::{Point, BigRational};
    /// let p: Point<BigRational> = Point::from_ints(&[1, -2]).unwrap();
    /// assert_eq!(p.dim(), 2);
    /// ```
    pub fn from_ints(coords: &[i64]) -> Result<Self> {
        Self::new(coords.iter().map(|&c| T::from_i64(c)).collect())
    }

    /// The origin of dimension `dim`.
    pub fn origin(dim: usize) -> Self {
        Point {
            coords: SmallVec::from_elem(T::zero(), dim),
        }
    }

    /// Converts every coordinate to another scalar type.
    pub fn try_map<U: Scalar>(&self, f: impl Fn(&T) -> Result<U>) -> Result<Point<U>> {
        Ok(Point {
            coords: self.coords.iter().map(f).collect::<Result<_>>()?,
        })
    }

    /// `self + v`.
    pub fn add(&self, v: &Vector<T>) -> Point<T> {
        self.zip(v, |a, b| a.add_ref(b))
    }

    /// `self - other`, the vector from `other` to `self`.
    pub fn sub(&self, other: &Point<T>) -> Vector<T> {
        self.zip(other, |a, b| a.sub_ref(b))
    }

    /// `s * self`.
    pub fn scale(&self, s: &T) -> Vector<T> {
        Point {
            coords: self.coords.iter().map(|c| c.mul_ref(s)).collect(),
        }
    }

    /// `-self`.
    pub fn neg(&self) -> Vector<T> {
        Point {
            coords: self.coords.iter().map(|c| c.neg_ref()).collect(),
        }
    }

    /// `(1 - t) self + t other`: the point dividing the segment in the ratio `t : 1 - t`,
    /// the step of de Casteljau's algorithm (1).
    pub fn lerp(&self, other: &Point<T>, t: &T) -> Point<T> {
        self.zip(other, |a, b| a.add_ref(&t.mul_ref(&b.sub_ref(a))))
    }

    /// The dot product.
    pub fn dot(&self, other: &Vector<T>) -> T {
        self.check_dim(other);
        let mut acc = T::zero();
        for (a, b) in self.coords.iter().zip(&other.coords) {
            acc += &a.mul_ref(b);
        }
        acc
    }

    /// `|self|²`, exact for exact scalars.
    pub fn norm_squared(&self) -> T {
        self.dot(self)
    }

    /// `|self - other|²`, exact for exact scalars.
    pub fn distance_squared(&self, other: &Point<T>) -> T {
        self.sub(other).norm_squared()
    }

    /// `max_k |self_k - other_k|`, the maximum-norm distance, exact for exact scalars.
    pub fn max_norm_distance(&self, other: &Point<T>) -> T {
        self.check_dim(other);
        let mut best = T::zero();
        for (a, b) in self.coords.iter().zip(&other.coords) {
            let d = a.sub_ref(b).abs();
            if d > best {
                best = d;
            }
        }
        best
    }

    /// Whether every coordinate is zero.
    pub fn is_zero(&self) -> bool {
        self.coords.iter().all(Scalar::is_zero)
    }

    /// Coordinates as floats, for display and plotting.
    pub fn to_f64(&self) -> Vec<f64> {
        self.coords.iter().map(Scalar::to_f64).collect()
    }

    /// Equality within `tol` per coordinate for floats, exact equality for exact scalars.
    pub fn approx_eq(&self, other: &Point<T>, tol: f64) -> bool {
        self.dim() == other.dim() && self.coords.iter().zip(&other.coords).all(|(a, b)| a.approx_eq(b, tol))
    }

    pub(crate) fn add_scaled_assign(&mut self, s: &T, v: &Vector<T>) {
        VectorSpace::add_scaled_assign(self, s, v);
    }

    fn zip(&self, other: &Point<T>, f: impl Fn(&T, &T) -> T) -> Point<T> {
        self.check_dim(other);
        Point {
            coords: self.coords.iter().zip(&other.coords).map(|(a, b)| f(a, b)).collect(),
        }
    }

    fn check_dim(&self, other: &Point<T>) {
        assert_eq!(self.dim(), other.dim(), "dimension mismatch between points");
    }
}

impl<T: Scalar> VectorSpace for Point<T> {
    type Scalar = T;

    fn dim(&self) -> usize {
        self.coords.len()
    }
    fn coords(&self) -> &[T] {
        &self.coords
    }
    fn zero_like(&self) -> Self {
        Point::origin(self.dim())
    }
    #[inline]
    fn lerp_assign(&mut self, other: &Self, t: &T) {
        self.check_dim(other);
        for (a, b) in self.coords.iter_mut().zip(&other.coords) {
            let d = b.sub_ref(&*a);
            *a += &t.mul_ref(&d);
        }
    }
    fn add_scaled_assign(&mut self, s: &T, v: &Self) {
        self.check_dim(v);
        for (a, b) in self.coords.iter_mut().zip(&v.coords) {
            *a += &s.mul_ref(b);
        }
    }
    fn scale_assign(&mut self, s: &T) {
        for a in &mut self.coords {
            *a = a.mul_ref(s);
        }
    }
    fn add_assign_ref(&mut self, other: &Self) {
        self.check_dim(other);
        for (a, b) in self.coords.iter_mut().zip(&other.coords) {
            *a += b;
        }
    }
    fn sub_assign_ref(&mut self, other: &Self) {
        self.check_dim(other);
        for (a, b) in self.coords.iter_mut().zip(&other.coords) {
            *a -= b;
        }
    }
    // The kernel choice: the scalar type's kernel, if any.
    #[inline(always)]
    fn curve_eval(points: &[Self], t: &T, generic: impl FnOnce() -> Self) -> Self {
        T::curve_eval(points, t, generic)
    }
    #[inline(always)]
    fn curve_derivative_at(points: &[Self], k: usize, t: &T) -> Option<Self> {
        T::curve_derivative_at(points, k, t)
    }
    #[inline(always)]
    fn curve_elevate(points: &[Self]) -> Option<Result<Vec<Self>>> {
        T::curve_elevate(points)
    }
    #[inline(always)]
    fn curve_elevate_by(points: &[Self], r: usize) -> Option<Result<Vec<Self>>> {
        T::curve_elevate_by(points, r)
    }
    #[inline(always)]
    fn curve_split(points: &[Self], t: &T) -> Option<(Vec<Self>, Vec<Self>)> {
        T::curve_split(points, t)
    }
    #[inline(always)]
    fn curve_derivative(points: &[Self], k: usize) -> Option<Result<Vec<Self>>> {
        T::curve_derivative(points, k)
    }
}

point_ops!([T: Scalar] Point<T>, T);
point_ref_ops!([] Point<f64>, f64);
point_ref_ops!([] Point<num_rational::BigRational>, num_rational::BigRational);
point_ref_ops!([] Point<crate::QuadraticIrrational>, crate::QuadraticIrrational);

impl<T> Index<usize> for Point<T> {
    type Output = T;
    fn index(&self, k: usize) -> &T {
        &self.coords[k]
    }
}

impl<T> IndexMut<usize> for Point<T> {
    fn index_mut(&mut self, k: usize) -> &mut T {
        &mut self.coords[k]
    }
}

impl<T: Scalar, const N: usize> From<[T; N]> for Point<T> {
    /// The point with these coordinates; `N` must be at least 1 (a zero-dimensional point
    /// is a programming error and panics).
    fn from(coords: [T; N]) -> Self {
        assert!(
            N > 0 && N <= MAX_DIMENSION,
            "a point needs 1 to {MAX_DIMENSION} coordinates"
        );
        Point::from_valid(coords)
    }
}

impl<T: Scalar> TryFrom<Vec<T>> for Point<T> {
    type Error = Error;
    fn try_from(coords: Vec<T>) -> Result<Self> {
        Point::new(coords)
    }
}

impl<T> From<Point<T>> for Vec<T> {
    fn from(p: Point<T>) -> Vec<T> {
        p.coords.into_vec()
    }
}

/// Reads what `Display` prints: `(a, b, …)`, each coordinate by `T`'s `FromStr` (for
/// [`crate::BigRational`]: integers and fractions `p/q`).
impl<T: Scalar + FromStr> FromStr for Point<T> {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        Point::new(parse_tuple(s)?)
    }
}

#[cfg(feature = "serde")]
impl<T: serde::Serialize> serde::Serialize for Point<T> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        serializer.collect_seq(&self.coords)
    }
}

/// A list of coordinates, checked as [`Point::new`] checks it.
#[cfg(feature = "serde")]
impl<'de, T: Scalar + serde::Deserialize<'de>> serde::Deserialize<'de> for Point<T> {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> std::result::Result<Self, D::Error> {
        Point::new(Vec::<T>::deserialize(deserializer)?).map_err(serde::de::Error::custom)
    }
}

impl<T: fmt::Display> fmt::Display for Point<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_tuple(f, &self.coords)
    }
}

/// Displays a list of points as `(x0, y0); (x1, y1); …`, the form the command line reads
/// back: one format for control polygons, net rows and answers.
pub struct PointList<'a, T>(pub &'a [Point<T>]);

impl<T: fmt::Display> fmt::Display for PointList<'_, T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, p) in self.0.iter().enumerate() {
            if i > 0 {
                write!(f, "; ")?;
            }
            write!(f, "{p}")?;
        }
        Ok(())
    }
}

/// Checks that `points` is non-empty and all of one dimension; returns that dimension.
pub fn common_dimension<T: Scalar>(points: &[Point<T>], what: &'static str) -> Result<usize> {
    crate::space::common_dim(points, what)
}

/// `Σ c_i p_i` with arbitrary coefficients: a linear combination, meaningful for vectors.
pub fn linear_combination<T: Scalar>(points: &[Point<T>], coeffs: &[T]) -> Result<Point<T>> {
    let dim = common_dimension(points, "linear combination")?;
    if coeffs.len() != points.len() {
        return Err(Error::WrongCount {
            what: "linear combination coefficients",
            needed: points.len(),
            got: coeffs.len(),
        });
    }
    let mut acc = Point::origin(dim);
    for (p, c) in points.iter().zip(coeffs) {
        acc.add_scaled_assign(c, p);
    }
    Ok(acc)
}

/// The barycentric combination `Σ c_i b_i` with `Σ c_i = 1` (text 000, §1.5).
///
/// For exact scalars the weights must sum to exactly one; for floats, to within `1e-12`
/// relative to `Σ|c_i|`. Otherwise the combination depends on the origin and is an error.
///
/// ```
/// use casteljau::{barycentric, Point, BigRational, Scalar};
/// let tri: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]).unwrap(), Point::from_ints(&[3, 0]).unwrap(), Point::from_ints(&[0, 3]).unwrap()];
/// let third = BigRational::from_ratio(1, 3).unwrap();
/// let g = barycentric(&tri, &[third.clone(), third.clone(), third]).unwrap();
/// assert_eq!(g, Point::from_ints(&[1, 1]).unwrap());
/// ```
pub fn barycentric<T: Scalar>(points: &[Point<T>], weights: &[T]) -> Result<Point<T>> {
    let mut sum = T::zero();
    let mut abs_sum = 0.0f64;
    for w in weights {
        sum += w;
        abs_sum += w.to_f64().abs();
    }
    let affine = if T::EXACT {
        sum == T::one()
    } else {
        (sum.to_f64() - 1.0).abs() <= 1e-12 * abs_sum.max(1.0)
    };
    if !affine {
        return Err(Error::NotAffine(sum.to_string()));
    }
    linear_combination(points, weights)
}

/// An affine map `x ↦ A x + c` from dimension `A.cols` to dimension `A.rows`.
///
/// ```
/// use casteljau::{AffineMap, Point};
/// let shear = AffineMap::new(vec![vec![1.0, 2.0], vec![0.0, 1.0]], vec![1.0, 0.0]).unwrap();
/// assert_eq!(shear.apply(&Point::new(vec![1.0, 1.0]).unwrap()).unwrap().coords(), &[4.0, 1.0]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct AffineMap<T> {
    matrix: Vec<Vec<T>>,
    translation: Vec<T>,
}

impl<T: Scalar> AffineMap<T> {
    /// The map with matrix `matrix` (one row per output coordinate) and translation.
    pub fn new(matrix: Vec<Vec<T>>, translation: Vec<T>) -> Result<Self> {
        let cols = matrix.first().map(Vec::len).ok_or(Error::Empty("affine map matrix"))?;
        if cols == 0 {
            return Err(Error::ZeroDimension);
        }
        for (i, row) in matrix.iter().enumerate() {
            if row.len() != cols {
                return Err(Error::DimensionMismatch {
                    expected: cols,
                    found: row.len(),
                    context: format!("affine map matrix row {i}"),
                });
            }
        }
        if translation.len() != matrix.len() {
            return Err(Error::DimensionMismatch {
                expected: matrix.len(),
                found: translation.len(),
                context: "affine map translation".into(),
            });
        }
        Ok(AffineMap { matrix, translation })
    }

    /// The translation by `v`.
    pub fn translation(v: &Vector<T>) -> Self {
        let d = v.dim();
        let matrix = (0..d)
            .map(|i| (0..d).map(|j| if i == j { T::one() } else { T::zero() }).collect())
            .collect();
        AffineMap {
            matrix,
            translation: v.coords().to_vec(),
        }
    }

    /// The uniform scaling by `s` about the origin in dimension `dim`.
    pub fn scaling(dim: usize, s: &T) -> Self {
        let matrix = (0..dim)
            .map(|i| (0..dim).map(|j| if i == j { s.clone() } else { T::zero() }).collect())
            .collect();
        AffineMap {
            matrix,
            translation: vec![T::zero(); dim],
        }
    }

    /// Input dimension.
    pub fn input_dim(&self) -> usize {
        self.matrix[0].len()
    }

    /// Output dimension.
    pub fn output_dim(&self) -> usize {
        self.matrix.len()
    }

    /// `A p + c`.
    pub fn apply(&self, p: &Point<T>) -> Result<Point<T>> {
        if p.dim() != self.input_dim() {
            return Err(Error::DimensionMismatch {
                expected: self.input_dim(),
                found: p.dim(),
                context: "affine map input".into(),
            });
        }
        let coords = self.matrix.iter().zip(&self.translation).map(|(row, c)| {
            let mut acc = c.clone();
            for (a, x) in row.iter().zip(p.coords()) {
                acc += &a.mul_ref(x);
            }
            acc
        });
        Ok(Point::from_valid(coords))
    }

    /// Applies the map to every point.
    pub fn apply_all(&self, points: &[Point<T>]) -> Result<Vec<Point<T>>> {
        points.iter().map(|p| self.apply(p)).collect()
    }

    /// `self ∘ inner`: first `inner`, then `self`.
    pub fn compose(&self, inner: &AffineMap<T>) -> Result<AffineMap<T>> {
        if inner.output_dim() != self.input_dim() {
            return Err(Error::DimensionMismatch {
                expected: self.input_dim(),
                found: inner.output_dim(),
                context: "composition of affine maps".into(),
            });
        }
        let matrix = self
            .matrix
            .iter()
            .map(|row| {
                (0..inner.input_dim())
                    .map(|j| {
                        let mut acc = T::zero();
                        for (k, a) in row.iter().enumerate() {
                            acc += &a.mul_ref(&inner.matrix[k][j]);
                        }
                        acc
                    })
                    .collect()
            })
            .collect();
        let translation = self
            .apply(&Point::from_valid(inner.translation.iter().cloned()))?
            .into_coords();
        Ok(AffineMap { matrix, translation })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Ring;
    use num_rational::BigRational;

    type Q = BigRational;

    fn p(c: &[i64]) -> Point<Q> {
        Point::from_ints(c).unwrap()
    }

    #[test]
    fn barycentric_requires_exact_unit_sum() {
        let pts = vec![p(&[0, 0]), p(&[2, 0])];
        let half = Q::from_ratio(1, 2).unwrap();
        assert_eq!(barycentric(&pts, &[half.clone(), half.clone()]).unwrap(), p(&[1, 0]));
        let err = barycentric(&pts, &[half.clone(), half.clone() + Q::from_ratio(1, 1000).unwrap()]).unwrap_err();
        assert!(matches!(err, Error::NotAffine(_)));
        assert!(barycentric(&pts, &[half]).is_err());
        assert!(barycentric::<Q>(&[], &[]).is_err());
    }

    #[test]
    fn mixed_dimensions_are_reported() {
        let err = common_dimension(&[p(&[0, 0]), p(&[1, 2, 3])], "polygon").unwrap_err();
        assert!(err.to_string().contains("expected 2"), "{err}");
        assert!(Point::<Q>::new(vec![]).is_err());
    }

    #[test]
    fn affine_maps_compose() {
        let a = AffineMap::new(
            vec![
                vec![Q::from_i64(2), Q::from_i64(1)],
                vec![Q::from_i64(0), Q::from_i64(1)],
            ],
            vec![Q::from_i64(1), Q::from_i64(-1)],
        )
        .unwrap();
        let b = AffineMap::translation(&p(&[3, 4]));
        let ab = a.compose(&b).unwrap();
        let x = p(&[5, -7]);
        assert_eq!(ab.apply(&x).unwrap(), a.apply(&b.apply(&x).unwrap()).unwrap());
        assert!(a.apply(&p(&[1, 2, 3])).is_err());
        assert!(AffineMap::<Q>::new(vec![vec![Q::from_i64(1)], vec![]], vec![Q::from_i64(0), Q::from_i64(0)]).is_err());
    }

    #[test]
    fn lerp_divides_in_ratio() {
        let t = Q::from_ratio(1, 4).unwrap();
        assert_eq!(p(&[0, 0]).lerp(&p(&[4, 8]), &t), p(&[1, 2]));
    }
}
