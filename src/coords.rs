//! The storage of the two point types, [`Point`] and [`PointN`], with the accessors that need
//! nothing of their coordinates: the bottom layer, so that the number trait
//! ([`crate::Scalar`]) and the exact and float kernels can name points without importing
//! what points do (`point`, `space`, which import the number trait).

use smallvec::SmallVec;

/// Coordinates kept inline, without a heap allocation: enough for a homogeneous point of
/// space.
pub(crate) const INLINE_COORDS: usize = 4;

/// A point (or vector) whose dimension is known at run time, with coordinates of type `T`;
/// up to four coordinates are stored inline. For a dimension fixed at compile time use
/// [`crate::PointN`].
///
/// Arithmetic between points of different dimensions is a programming error and panics;
/// curves, surfaces and nets check dimensions when they are built, so their algorithms
/// never meet one.
///
/// ```
/// use casteljau::{Point, BigRational};
/// let p: Point<BigRational> = "(1/2, -3)".parse().unwrap();
/// let q: Point<BigRational> = Point::from_ints(&[1, 1]).unwrap();
/// assert_eq!((&q - &p).to_string(), "(1/2, 4)");
/// assert_eq!(p[0], BigRational::new(1.into(), 2.into()));
/// assert_eq!(p.to_string().parse::<Point<BigRational>>().unwrap(), p);
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Point<T> {
    pub(crate) coords: SmallVec<[T; INLINE_COORDS]>,
}

impl<T> Point<T> {
    /// A point from coordinates already known to be valid (taken from validated points).
    pub(crate) fn from_valid(coords: impl IntoIterator<Item = T>) -> Self {
        let coords: SmallVec<_> = coords.into_iter().collect();
        debug_assert!(!coords.is_empty());
        Point { coords }
    }

    /// A point from the first `dim` (1 to 4) of `coords`, already known to be valid: kept
    /// inline as they are, with no iterator to collect.
    #[inline]
    pub(crate) fn from_inline_prefix(coords: [T; INLINE_COORDS], dim: usize) -> Self {
        debug_assert!((1..=INLINE_COORDS).contains(&dim));
        Point {
            coords: SmallVec::from_buf_and_len(coords, dim),
        }
    }

    /// The number of coordinates.
    pub fn dim(&self) -> usize {
        self.coords.len()
    }

    /// The coordinates.
    pub fn coords(&self) -> &[T] {
        &self.coords
    }

    /// The coordinates, by value.
    pub fn into_coords(self) -> Vec<T> {
        self.coords.into_vec()
    }
}

/// A point with `N` coordinates of type `T`, stored inline; `Copy` when `T` is.
///
/// ```
/// use casteljau::{Point2, PointN};
/// let a = Point2::new(1.0, 2.0);
/// let b: Point2<f64> = [4.0, 6.0].into();
/// assert_eq!(b - a, Point2::new(3.0, 4.0));
/// assert_eq!((b - a) * 0.5 + a, Point2::new(2.5, 4.0));
/// assert_eq!(a[1], 2.0);
/// assert_eq!(a.to_string().parse::<Point2<f64>>().unwrap(), a);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PointN<T, const N: usize>(pub [T; N]);
