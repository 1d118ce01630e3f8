//! The fraction-free kernels ([`crate::exact::fraction_free`]) as methods of a curve of
//! exact rationals, each equal to the generic method it names (which runs it).

use super::{BezierCurve, DeCasteljauScheme};
use crate::error::Result;
use crate::exact::fraction_free;
use crate::point::Point;
use num_rational::BigRational;

impl BezierCurve<BigRational> {
    /// `b(t)` exactly by the nested (Horner) Bernstein sum over integers: the same value as
    /// [`BezierCurve::eval`], in `n` steps on machine words while they fit (see
    /// [`crate::exact::fraction_free`]).
    ///
    /// ```
    /// use casteljau::{BezierCurve, BigRational, Scalar};
    /// let c: BezierCurve<BigRational> = BezierCurve::from_ints(&[&[0, 0], &[1, 2], &[3, 2], &[4, 0]]).unwrap();
    /// let t = BigRational::from_ratio(-1, 3).unwrap();
    /// assert_eq!(c.eval_nested(&t), c.eval(&t));
    /// ```
    pub fn eval_nested(&self, t: &BigRational) -> Point<BigRational> {
        fraction_free::eval(self.points(), t)
    }

    /// The `k`-th derivative vector at `t` (zero when `k` exceeds the degree), by forward
    /// differences and the nested sum over integers; equals [`BezierCurve::derivative_at`].
    pub fn derivative_at_nested(&self, k: usize, t: &BigRational) -> Point<BigRational> {
        if k > self.degree() {
            return Point::origin(self.dim());
        }
        fraction_free::derivative_at(self.points(), k, t)
    }

    /// The `k`-th derivative curve over integers; equals [`BezierCurve::derivative`] (and
    /// `k > n` is the same error).
    pub fn derivative_fraction_free(&self, k: usize) -> Result<Self> {
        BezierCurve::new(fraction_free::derivative(self.points(), k)?)
    }

    /// The de Casteljau triangle (9) at `t` over integers; equals [`BezierCurve::scheme`].
    pub fn scheme_fraction_free(&self, t: &BigRational) -> DeCasteljauScheme<BigRational> {
        DeCasteljauScheme {
            t: t.clone(),
            columns: fraction_free::scheme(self.points(), t),
        }
    }

    /// Subdivision at `t0` over integers (long denominators at a low degree pair by pair
    /// on reduced fractions, which costs less than their lcm); equals
    /// [`BezierCurve::split_at`].
    pub fn split_fraction_free(&self, t0: &BigRational) -> (Self, Self) {
        let (left, right) = fraction_free::split(self.points(), t0);
        let valid = "the points of a valid curve's scheme";
        (
            BezierCurve::new(left).expect(valid),
            BezierCurve::new(right).expect(valid),
        )
    }

    /// One degree elevation step (7) over integers; equals [`BezierCurve::elevate`].
    pub fn elevate_fraction_free(&self) -> Result<Self> {
        BezierCurve::new(fraction_free::elevate(self.points())?)
    }

    /// `r` elevation steps by the closed form (8) over integers; equals
    /// [`BezierCurve::elevate_by`] (one step combines neighbouring points pairwise, see
    /// [`crate::exact::fraction_free`]).
    pub fn elevate_by_fraction_free(&self, r: usize) -> Result<Self> {
        BezierCurve::new(fraction_free::elevate_by(self.points(), r)?)
    }
}
