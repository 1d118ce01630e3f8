//! [`VectorSpace`]: what the Bézier algorithms need of a control point, and [`PointN`], the
//! fixed-dimension point that makes the `f64` path as fast as a hand-written loop.
//!
//! The algorithms of [`crate::curve`] are generic over the point type. Two implement the
//! trait: [`crate::Point`], whose dimension is known at run time (what the command line,
//! the oracle and the claims read), and [`PointN`], whose dimension is a type parameter —
//! `Copy` for `f64`, stored inline, with mismatched dimensions a type error.

use crate::error::{Error, Result};
use crate::scalar::{to_fixed, to_points, Scalar};
use std::fmt;
use std::ops::{Index, IndexMut};
use std::str::FromStr;

/// A control point: an element of a vector space over [`VectorSpace::Scalar`], worked on
/// by reference so that exact coordinates are not cloned needlessly.
///
/// Points and vectors share one type (a curve's derivative is a curve of vectors).
pub trait VectorSpace: Clone + PartialEq + fmt::Debug + 'static {
    /// The coordinate type.
    type Scalar;

    /// The number of coordinates.
    fn dim(&self) -> usize;
    /// The coordinates.
    fn coords(&self) -> &[Self::Scalar];
    /// The zero vector of the same dimension.
    fn zero_like(&self) -> Self;
    /// `self ← self + t (other − self)`: the step of de Casteljau's algorithm.
    fn lerp_assign(&mut self, other: &Self, t: &Self::Scalar);
    /// `self ← self + s v`.
    fn add_scaled_assign(&mut self, s: &Self::Scalar, v: &Self);
    /// `self ← s self`.
    fn scale_assign(&mut self, s: &Self::Scalar);
    /// `self ← self + other`.
    fn add_assign_ref(&mut self, other: &Self);
    /// `self ← self − other`.
    fn sub_assign_ref(&mut self, other: &Self);

    /// `(1 − t) self + t other`.
    fn lerp_to(&self, other: &Self, t: &Self::Scalar) -> Self {
        let mut out = self.clone();
        out.lerp_assign(other, t);
        out
    }
    /// `self − other`.
    fn minus(&self, other: &Self) -> Self {
        let mut out = self.clone();
        out.sub_assign_ref(other);
        out
    }

    // The kernel choice of the generic curve code: a point type's curve kernel for one
    // operation, `None` (the default) for the generic algorithm (which `curve_eval` is given
    // as a closure and runs itself). `Point` and `PointN` hand
    // the choice to their scalar type (the kernel methods of `Scalar`). Hidden: how the public
    // methods choose, not an API of their own.

    /// `b(t)` for the curve on `points`, by `generic` (the generic algorithm) where there is
    /// no kernel: the point itself, not an `Option` (see `Scalar::curve_eval`).
    #[doc(hidden)]
    #[inline(always)]
    fn curve_eval(points: &[Self], t: &Self::Scalar, generic: impl FnOnce() -> Self) -> Self {
        let _ = (points, t);
        generic()
    }
    /// The `k`-th derivative vector at `t`, `k` at most the degree.
    #[doc(hidden)]
    #[inline(always)]
    fn curve_derivative_at(points: &[Self], k: usize, t: &Self::Scalar) -> Option<Self> {
        let _ = (points, k, t);
        None
    }
    /// One step of degree elevation.
    #[doc(hidden)]
    #[inline(always)]
    fn curve_elevate(points: &[Self]) -> Option<Result<Vec<Self>>> {
        let _ = points;
        None
    }
    /// `r` steps of degree elevation.
    #[doc(hidden)]
    #[inline(always)]
    fn curve_elevate_by(points: &[Self], r: usize) -> Option<Result<Vec<Self>>> {
        let _ = (points, r);
        None
    }
    /// The two halves of the subdivision at `t`.
    #[doc(hidden)]
    #[inline(always)]
    fn curve_split(points: &[Self], t: &Self::Scalar) -> Option<(Vec<Self>, Vec<Self>)> {
        let _ = (points, t);
        None
    }
    /// The `k`-th derivative curve.
    #[doc(hidden)]
    #[inline(always)]
    fn curve_derivative(points: &[Self], k: usize) -> Option<Result<Vec<Self>>> {
        let _ = (points, k);
        None
    }
}

pub use crate::coords::PointN;

/// A kernel's points back as fixed-dimension points.
fn all_fixed<T, const N: usize>(points: Vec<crate::coords::Point<T>>) -> Vec<PointN<T, N>> {
    points.into_iter().map(to_fixed).collect()
}

/// Checks that `points` is non-empty and of one dimension; returns that dimension.
pub(crate) fn common_dim<P: VectorSpace>(points: &[P], what: &'static str) -> Result<usize> {
    let first = points.first().ok_or(Error::Empty(what))?;
    let dim = first.dim();
    for (i, p) in points.iter().enumerate() {
        if p.dim() != dim {
            return Err(Error::DimensionMismatch {
                expected: dim,
                found: p.dim(),
                context: format!("{what}, point {i}"),
            });
        }
    }
    Ok(dim)
}

/// A point of the plane.
pub type Point2<T> = PointN<T, 2>;
/// A point of space.
pub type Point3<T> = PointN<T, 3>;

impl<T> PointN<T, 2> {
    /// The point `(x, y)`.
    pub const fn new(x: T, y: T) -> Self {
        PointN([x, y])
    }
}

impl<T> PointN<T, 3> {
    /// The point `(x, y, z)`.
    pub const fn new(x: T, y: T, z: T) -> Self {
        PointN([x, y, z])
    }
}

impl<T, const N: usize> PointN<T, N> {
    /// The coordinates.
    pub fn coords(&self) -> &[T; N] {
        &self.0
    }
}

impl<T, const N: usize> From<[T; N]> for PointN<T, N> {
    fn from(coords: [T; N]) -> Self {
        PointN(coords)
    }
}

impl<T, const N: usize> From<PointN<T, N>> for [T; N] {
    fn from(p: PointN<T, N>) -> Self {
        p.0
    }
}

impl<T, const N: usize> Index<usize> for PointN<T, N> {
    type Output = T;
    fn index(&self, k: usize) -> &T {
        &self.0[k]
    }
}

impl<T, const N: usize> IndexMut<usize> for PointN<T, N> {
    fn index_mut(&mut self, k: usize) -> &mut T {
        &mut self.0[k]
    }
}

impl<T: Scalar, const N: usize> VectorSpace for PointN<T, N> {
    type Scalar = T;

    fn dim(&self) -> usize {
        N
    }
    fn coords(&self) -> &[T] {
        &self.0
    }
    fn zero_like(&self) -> Self {
        PointN(std::array::from_fn(|_| T::zero()))
    }
    #[inline]
    fn lerp_assign(&mut self, other: &Self, t: &T) {
        for (a, b) in self.0.iter_mut().zip(&other.0) {
            let d = b.sub_ref(&*a);
            *a += &t.mul_ref(&d);
        }
    }
    #[inline]
    fn add_scaled_assign(&mut self, s: &T, v: &Self) {
        for (a, b) in self.0.iter_mut().zip(&v.0) {
            *a += &s.mul_ref(b);
        }
    }
    #[inline]
    fn scale_assign(&mut self, s: &T) {
        for a in &mut self.0 {
            *a = a.mul_ref(s);
        }
    }
    #[inline]
    fn add_assign_ref(&mut self, other: &Self) {
        for (a, b) in self.0.iter_mut().zip(&other.0) {
            *a += b;
        }
    }
    #[inline]
    fn sub_assign_ref(&mut self, other: &Self) {
        for (a, b) in self.0.iter_mut().zip(&other.0) {
            *a -= b;
        }
    }
    // The kernel choice: the scalar type's kernel, if any, for evaluation its own for
    // fixed-dimension points; the others on the points as `Point`s, and only when the scalar
    // type has curve kernels (a constant: other types keep no trace of the conversion).
    #[inline(always)]
    fn curve_eval(points: &[Self], t: &T, generic: impl FnOnce() -> Self) -> Self {
        T::curve_eval_fixed(points, t, generic)
    }
    #[inline(always)]
    fn curve_derivative_at(points: &[Self], k: usize, t: &T) -> Option<Self> {
        if !T::CURVE_KERNELS {
            return None;
        }
        T::curve_derivative_at(&to_points(points), k, t).map(to_fixed)
    }
    #[inline(always)]
    fn curve_elevate(points: &[Self]) -> Option<Result<Vec<Self>>> {
        if !T::CURVE_KERNELS {
            return None;
        }
        Some(T::curve_elevate(&to_points(points))?.map(all_fixed))
    }
    #[inline(always)]
    fn curve_elevate_by(points: &[Self], r: usize) -> Option<Result<Vec<Self>>> {
        if !T::CURVE_KERNELS {
            return None;
        }
        Some(T::curve_elevate_by(&to_points(points), r)?.map(all_fixed))
    }
    #[inline(always)]
    fn curve_split(points: &[Self], t: &T) -> Option<(Vec<Self>, Vec<Self>)> {
        if !T::CURVE_KERNELS {
            return None;
        }
        let (left, right) = T::curve_split(&to_points(points), t)?;
        Some((all_fixed(left), all_fixed(right)))
    }
    #[inline(always)]
    fn curve_derivative(points: &[Self], k: usize) -> Option<Result<Vec<Self>>> {
        if !T::CURVE_KERNELS {
            return None;
        }
        Some(T::curve_derivative(&to_points(points), k)?.map(all_fixed))
    }
}

/// The operators `+`, `-` (binary and unary), `+=`, `-=` and `* scalar` on points by value,
/// written once for a point type through its [`VectorSpace`] methods.
macro_rules! point_ops {
    ([$($gen:tt)*] $point:ty, $scalar:ty) => {
        impl<$($gen)*> ::std::ops::Add<$point> for $point {
            type Output = $point;
            fn add(mut self, rhs: $point) -> $point {
                $crate::space::VectorSpace::add_assign_ref(&mut self, &rhs);
                self
            }
        }
        impl<$($gen)*> ::std::ops::Add<&$point> for $point {
            type Output = $point;
            fn add(mut self, rhs: &$point) -> $point {
                $crate::space::VectorSpace::add_assign_ref(&mut self, rhs);
                self
            }
        }
        impl<$($gen)*> ::std::ops::Sub<$point> for $point {
            type Output = $point;
            fn sub(mut self, rhs: $point) -> $point {
                $crate::space::VectorSpace::sub_assign_ref(&mut self, &rhs);
                self
            }
        }
        impl<$($gen)*> ::std::ops::Sub<&$point> for $point {
            type Output = $point;
            fn sub(mut self, rhs: &$point) -> $point {
                $crate::space::VectorSpace::sub_assign_ref(&mut self, rhs);
                self
            }
        }
        impl<$($gen)*> ::std::ops::AddAssign<&$point> for $point {
            fn add_assign(&mut self, rhs: &$point) {
                $crate::space::VectorSpace::add_assign_ref(self, rhs);
            }
        }
        impl<$($gen)*> ::std::ops::SubAssign<&$point> for $point {
            fn sub_assign(&mut self, rhs: &$point) {
                $crate::space::VectorSpace::sub_assign_ref(self, rhs);
            }
        }
        impl<$($gen)*> ::std::ops::Mul<$scalar> for $point {
            type Output = $point;
            fn mul(mut self, rhs: $scalar) -> $point {
                $crate::space::VectorSpace::scale_assign(&mut self, &rhs);
                self
            }
        }
        impl<$($gen)*> ::std::ops::Mul<&$scalar> for $point {
            type Output = $point;
            fn mul(mut self, rhs: &$scalar) -> $point {
                $crate::space::VectorSpace::scale_assign(&mut self, rhs);
                self
            }
        }
        impl<$($gen)*> ::std::ops::Neg for $point {
            type Output = $point;
            fn neg(self) -> $point {
                let mut out = $crate::space::VectorSpace::zero_like(&self);
                $crate::space::VectorSpace::sub_assign_ref(&mut out, &self);
                out
            }
        }
    };
}
pub(crate) use point_ops;

/// The same operators on borrowed points, `&a - &b`, for the scalars of this crate.
///
/// They are written per scalar type rather than for every `T: Scalar`: a generic impl of
/// `&Point<T>: Add` would make the compiler's search for `&T: Add` (the [`RefOps`] bound)
/// recurse through `Point<Point<…>>`.
macro_rules! point_ref_ops {
    ([$($gen:tt)*] $point:ty, $scalar:ty) => {
        impl<$($gen)*> ::std::ops::Add<&$point> for &$point {
            type Output = $point;
            fn add(self, rhs: &$point) -> $point {
                let mut out = self.clone();
                $crate::space::VectorSpace::add_assign_ref(&mut out, rhs);
                out
            }
        }
        impl<$($gen)*> ::std::ops::Sub<&$point> for &$point {
            type Output = $point;
            fn sub(self, rhs: &$point) -> $point {
                $crate::space::VectorSpace::minus(self, rhs)
            }
        }
        impl<$($gen)*> ::std::ops::Mul<&$scalar> for &$point {
            type Output = $point;
            fn mul(self, rhs: &$scalar) -> $point {
                let mut out = self.clone();
                $crate::space::VectorSpace::scale_assign(&mut out, rhs);
                out
            }
        }
        impl<$($gen)*> ::std::ops::Neg for &$point {
            type Output = $point;
            fn neg(self) -> $point {
                let mut out = $crate::space::VectorSpace::zero_like(self);
                $crate::space::VectorSpace::sub_assign_ref(&mut out, self);
                out
            }
        }
            };
}
pub(crate) use point_ref_ops;

point_ops!([T: Scalar, const N: usize] PointN<T, N>, T);
point_ref_ops!([const N: usize] PointN<f64, N>, f64);
point_ref_ops!([const N: usize] PointN<num_rational::BigRational, N>, num_rational::BigRational);

impl<T: fmt::Display, const N: usize> fmt::Display for PointN<T, N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_tuple(f, &self.0)
    }
}

/// Writes coordinates as `(a, b, …)`, the form [`parse_tuple`] reads back.
pub(crate) fn write_tuple<T: fmt::Display>(f: &mut fmt::Formatter<'_>, coords: &[T]) -> fmt::Result {
    write!(f, "(")?;
    for (i, c) in coords.iter().enumerate() {
        if i > 0 {
            write!(f, ", ")?;
        }
        write!(f, "{c}")?;
    }
    write!(f, ")")
}

/// Reads `(a, b, …)` (parentheses optional, coordinates separated by commas), each
/// coordinate by `T`'s own `FromStr`.
pub(crate) fn parse_tuple<T: FromStr>(text: &str) -> Result<Vec<T>> {
    let s = text.trim();
    let inner = s.strip_prefix('(').and_then(|r| r.strip_suffix(')')).unwrap_or(s);
    if inner.trim().is_empty() {
        return Err(Error::ZeroDimension);
    }
    inner
        .split(',')
        .map(|c| {
            c.trim()
                .parse()
                .map_err(|_| Error::Parse(format!("'{}' is not a coordinate (in '{text}')", c.trim())))
        })
        .collect()
}

impl<T: FromStr, const N: usize> FromStr for PointN<T, N> {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        let coords: Vec<T> = parse_tuple(s)?;
        let found = coords.len();
        coords.try_into().map(PointN).map_err(|_| Error::DimensionMismatch {
            expected: N,
            found,
            context: format!("the point '{s}'"),
        })
    }
}

#[cfg(feature = "serde")]
impl<T: serde::Serialize, const N: usize> serde::Serialize for PointN<T, N> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        serializer.collect_seq(&self.0)
    }
}

#[cfg(feature = "serde")]
impl<'de, T: serde::Deserialize<'de>, const N: usize> serde::Deserialize<'de> for PointN<T, N> {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> std::result::Result<Self, D::Error> {
        let coords = Vec::<T>::deserialize(deserializer)?;
        let found = coords.len();
        coords
            .try_into()
            .map(PointN)
            .map_err(|_| serde::de::Error::invalid_length(found, &format!("{N} coordinates").as_str()))
    }
}
