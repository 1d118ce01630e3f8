//! Bézier curves whose number of control points is part of the type, in the spirit of
//! kurbo's `QuadBez` and `CubicBez`: [`BezierN<P, N>`] stores `[P; N]`, with [`Line`],
//! [`Quad`] and [`Cubic`] for degrees 1 to 3.

use crate::curve::Bezier;
use crate::error::{Error, Result, MAX_DEGREE};
use crate::kernel::{de_casteljau, elevate_points, eval_cubic, split_points};
use crate::param::{ParamCurve, ParamCurveDeriv};
use crate::scalar::Scalar;
use crate::space::{common_dim, PointN, VectorSpace};

/// A Bézier curve with exactly `N` control points (degree `N - 1`), stored as an array;
/// `Copy` when `P` is. `N = 0` and degrees above [`MAX_DEGREE`] do not compile.
///
/// In the spirit of kurbo's `QuadBez` and `CubicBez` ([`Line`], [`Quad`] and [`Cubic`] are
/// degrees 1 to 3), it runs the algorithms of [`crate::Bezier`] (the same kernel, the same
/// results: bit for bit on floats, `==` on exact scalars) without its length word, its
/// inline/heap test or its `Result` where nothing can fail: [`BezierN::elevate`] and [`BezierN::deriv`] change the
/// type's degree and are infallible. Generic over the point type like [`crate::Bezier`], so
/// `Cubic<Point2<f64>>` (which is `Copy`) and `Cubic<Point2<BigRational>>` share one code.
///
/// ```
/// use casteljau::{Bezier, Cubic, Point2, Quad};
/// let quad = Quad::new([Point2::new(0.0, 0.0), Point2::new(1.0, 2.0), Point2::new(3.0, 0.5)]);
/// let cubic: Cubic<_> = quad.elevate();
/// assert_eq!(cubic.eval(&0.5), quad.eval(&0.5));
/// let any: Bezier<_> = cubic.into();
/// assert_eq!(Cubic::try_from(&any).unwrap(), cubic);
/// assert!(Quad::try_from(&any).is_err());
/// ```
///
/// ```
/// use casteljau::{Cubic, Point2};
/// let c = Cubic::new([Point2::new(0.0, 0.0), Point2::new(1.0, 2.0), Point2::new(3.0, 2.0), Point2::new(4.0, 0.0)]);
/// assert_eq!(c.eval(&0.5), Point2::new(2.0, 1.5));
/// let (left, right) = c.split_at(&0.5);
/// assert_eq!(left.points()[3], right.points()[0]);
/// assert_eq!(c.deriv().degree(), 2);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BezierN<P, const N: usize> {
    points: [P; N],
}

/// A segment: two control points.
pub type Line<P> = BezierN<P, 2>;
/// A quadratic Bézier curve: three control points.
pub type Quad<P> = BezierN<P, 3>;
/// A cubic Bézier curve: four control points.
pub type Cubic<P> = BezierN<P, 4>;

impl<P, const N: usize> BezierN<P, N> {
    /// Refuses, at compile time, the point counts no curve has.
    const VALID: () = assert!(
        N >= 1 && N <= MAX_DEGREE + 1,
        "a Bézier curve has 1 to MAX_DEGREE + 1 points"
    );

    /// The control points.
    #[inline]
    pub const fn points(&self) -> &[P; N] {
        &self.points
    }

    /// The control points, by value.
    #[inline]
    pub fn into_points(self) -> [P; N] {
        self.points
    }

    /// The degree, `N - 1`.
    #[inline]
    pub const fn degree(&self) -> usize {
        N - 1
    }
}

impl<T, const D: usize, const N: usize> BezierN<PointN<T, D>, N> {
    /// The curve of these control points: points of a fixed dimension share it, so nothing
    /// can be wrong.
    #[inline]
    pub const fn new(points: [PointN<T, D>; N]) -> Self {
        let () = Self::VALID;
        BezierN { points }
    }
}

impl<T, const D: usize, const N: usize> From<[PointN<T, D>; N]> for BezierN<PointN<T, D>, N> {
    #[inline]
    fn from(points: [PointN<T, D>; N]) -> Self {
        Self::new(points)
    }
}

impl<T: Scalar, P: VectorSpace<Scalar = T>, const N: usize> BezierN<P, N> {
    /// The curve of these control points of any point type; points of different dimensions
    /// (possible for [`crate::Point`]) are an error.
    pub fn from_points(points: [P; N]) -> Result<Self> {
        let () = Self::VALID;
        common_dim(&points, "a Bézier curve")?;
        Ok(BezierN { points })
    }

    /// The dimension of the control points.
    pub fn dim(&self) -> usize {
        self.points[0].dim()
    }

    /// `b(t)`, as [`Bezier::eval`] computes it: de Casteljau's algorithm (1), a float cubic
    /// by its nested Bernstein sum (`((t b₃ + 3s b₂) t + 3s² b₁) t + s³ b₀` with `s = 1 − t`).
    #[inline]
    pub fn eval(&self, t: &T) -> P {
        eval_points(&self.points, t)
    }

    /// Subdivision at `t0` (Lemma 1.3), as [`Bezier::split_at`]: the pieces `b(t0 t)` and
    /// `b(t0 + (1 − t0) t)`, sharing the point `b_0^n(t0)` of the scheme (9) (on floats, not
    /// always `self.eval(t0)` to the last bit: see [`Bezier::split_at`]).
    #[inline]
    pub fn split_at(&self, t0: &T) -> (Self, Self) {
        let (left, right) = split_points(&self.points, t0);
        (BezierN { points: left }, BezierN { points: right })
    }
}

/// `b(t)` of the curve with control points `points`, as [`Bezier::eval`] computes it.
#[inline(always)]
pub(crate) fn eval_points<T: Scalar, P: VectorSpace<Scalar = T>, const N: usize>(points: &[P; N], t: &T) -> P {
    if let Ok(cubic) = <&[P; 4]>::try_from(&points[..]) {
        return eval_cubic(cubic, t);
    }
    let mut column = points.clone();
    de_casteljau(&mut column, t, |_| {});
    let Some(first) = column.into_iter().next() else {
        unreachable!("a curve has at least one point")
    };
    first
}

/// The hodograph's control points `(N − 1) (b_{j+1} − b_j)`, as [`Bezier::derivative`]
/// computes them; `M = N − 1`.
#[inline(always)]
fn hodograph_points<T: Scalar, P: VectorSpace<Scalar = T>, const N: usize, const M: usize>(points: &[P; N]) -> [P; M] {
    debug_assert_eq!(M + 1, N);
    let n = T::from_usize(M);
    std::array::from_fn(|j| {
        let mut d = points[j + 1].minus(&points[j]);
        d.scale_assign(&n);
        d
    })
}

impl<T: Scalar, P: VectorSpace<Scalar = T>, const N: usize> ParamCurve for BezierN<P, N> {
    type Scalar = T;
    type Point = P;

    fn eval(&self, t: &T) -> Result<P> {
        Ok(Self::eval(self, t))
    }
    fn split_at(&self, t0: &T) -> Result<(Self, Self)> {
        Ok(Self::split_at(self, t0))
    }
    fn degree(&self) -> usize {
        N - 1
    }
}

/// Degree elevation and the derivative, which change `N` by one: written per degree, as
/// stable Rust has no `N + 1` in a type.
macro_rules! elevate_and_deriv {
    ($($n:literal => $m:literal),* $(,)?) => {$(
        impl<T: Scalar, P: VectorSpace<Scalar = T>> BezierN<P, $n> {
            #[doc = concat!("One step of degree elevation (7), to ", stringify!($m), " points: the same curve.")]
            #[inline]
            pub fn elevate(&self) -> BezierN<P, $m> {
                BezierN { points: elevate_points(&self.points) }
            }
        }

        impl<T: Scalar, P: VectorSpace<Scalar = T>> BezierN<P, $m> {
            #[doc = concat!("The hodograph, of ", stringify!($n), " points: `b'(t)`.")]
            #[inline]
            pub fn deriv(&self) -> BezierN<P, $n> {
                BezierN { points: hodograph_points(&self.points) }
            }
        }

        impl<T: Scalar, P: VectorSpace<Scalar = T>> ParamCurveDeriv for BezierN<P, $m> {
            type Deriv = BezierN<P, $n>;

            fn deriv(&self) -> Result<Self::Deriv> {
                Ok(Self::deriv(self))
            }
        }
    )*};
}

elevate_and_deriv!(
    1 => 2, 2 => 3, 3 => 4, 4 => 5, 5 => 6, 6 => 7, 7 => 8, 8 => 9,
    9 => 10, 10 => 11, 11 => 12, 12 => 13, 13 => 14, 14 => 15, 15 => 16, 16 => 17,
);

impl<T: Scalar, P: VectorSpace<Scalar = T>> BezierN<P, 1> {
    /// The derivative of a constant curve: the constant zero.
    #[inline]
    pub fn deriv(&self) -> Self {
        BezierN {
            points: [self.points[0].zero_like()],
        }
    }
}

/// A constant curve's derivative is the constant zero curve, as for [`Bezier`].
impl<T: Scalar, P: VectorSpace<Scalar = T>> ParamCurveDeriv for BezierN<P, 1> {
    type Deriv = Self;

    fn deriv(&self) -> Result<Self> {
        Ok(Self::deriv(self))
    }
}

impl<T: Scalar, P: VectorSpace<Scalar = T>, const N: usize> From<BezierN<P, N>> for Bezier<P> {
    /// The same curve of any degree (no heap allocation up to a cubic).
    fn from(c: BezierN<P, N>) -> Self {
        Bezier::from_valid(c.points)
    }
}

impl<T: Scalar, P: VectorSpace<Scalar = T>, const N: usize> TryFrom<&Bezier<P>> for BezierN<P, N> {
    type Error = Error;

    /// The same curve, when it has exactly `N` control points; [`Error::WrongCount`] if not.
    fn try_from(c: &Bezier<P>) -> Result<Self> {
        let () = Self::VALID;
        let points = <&[P; N]>::try_from(c.points()).map_err(|_| Error::WrongCount {
            what: "a curve of this fixed degree",
            needed: N,
            got: c.points().len(),
        })?;
        Ok(BezierN { points: points.clone() })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{BezierCurve, BigRational, Point, Point2};

    type Q = BigRational;

    fn q(p: i64, d: i64) -> Q {
        Q::from_ratio(p, d).unwrap()
    }

    #[test]
    fn runtime_points_of_mixed_dimensions_are_refused() {
        let p = |c: &[i64]| Point::<Q>::from_ints(c).unwrap();
        assert!(BezierN::from_points([p(&[0, 0]), p(&[1, 2, 3])]).is_err());
        let c = BezierN::from_points([p(&[0, 0]), p(&[1, 2]), p(&[4, 0])]).unwrap();
        assert_eq!(c.dim(), 2);
        let any: BezierCurve<Q> = c.clone().into();
        assert_eq!(any.eval(&q(1, 3)), c.eval(&q(1, 3)));
    }

    #[test]
    fn wrong_count_is_an_error() {
        let c: BezierCurve<Q> = BezierCurve::from_ints(&[&[0, 0], &[1, 2], &[3, 2]]).unwrap();
        let err = Cubic::try_from(&c).unwrap_err();
        assert_eq!(
            err,
            Error::WrongCount {
                what: "a curve of this fixed degree",
                needed: 4,
                got: 3
            }
        );
        assert!(Quad::try_from(&c).is_ok());
    }

    #[test]
    fn float_halves_share_de_casteljaus_point() {
        // A float cubic's halves meet at the last level of the scheme, the same bits in both,
        // whether it is split as a `Cubic` or as an any-degree `Bezier`; eval's nested sum
        // may differ from that point in the last bits, which the test does not ask.
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 200.0 - 100.0
        };
        for _ in 0..2000 {
            let c = Cubic::new(std::array::from_fn(|_| Point2::new(next(), next())));
            let t = next() / 100.0;
            let (left, right) = c.split_at(&t);
            let mut column = *c.points();
            de_casteljau(&mut column, &t, |_| {});
            assert_eq!(left.points()[3].0.map(f64::to_bits), column[0].0.map(f64::to_bits));
            assert_eq!(right.points()[0].0.map(f64::to_bits), column[0].0.map(f64::to_bits));
            let (any_left, any_right) = Bezier::from(c).split_at(&t);
            assert_eq!((any_left, any_right), (left.into(), right.into()));
        }
    }

    #[test]
    fn constant_and_line() {
        let point = BezierN::new([Point2::new(q(1, 2), q(3, 1))]);
        assert_eq!(point.eval(&q(7, 3)), Point2::new(q(1, 2), q(3, 1)));
        assert_eq!(point.deriv().points()[0], Point2::new(q(0, 1), q(0, 1)));
        let line = point.elevate();
        assert_eq!(line.points()[0], line.points()[1]);
        let seg: Line<_> = Line::new([Point2::new(0.0, 0.0), Point2::new(2.0, 4.0)]);
        assert_eq!(seg.eval(&0.25), Point2::new(0.5, 1.0));
        assert_eq!(seg.deriv().points(), &[Point2::new(2.0, 4.0)]);
        assert_eq!(ParamCurve::degree(&seg), 1);
    }
}
