//! Capability traits over curve kinds, in the spirit of kurbo's `ParamCurve`: generic code
//! (the cubic fit, a user's checks) takes any curve that can be evaluated, split and, for
//! [`ParamCurveDeriv`], differentiated — polynomial curves ([`crate::Bezier`], including the
//! iso-curves of surfaces) and rational ones ([`crate::RationalBezierCurve`]).

use crate::error::Result;
use crate::scalar::{Ring, Scalar};

/// A parametric curve `t ↦ x(t)`.
pub trait ParamCurve: Sized {
    /// The parameter and coordinate type.
    type Scalar: Clone;
    /// What the curve evaluates to.
    type Point;

    /// `x(t)`; an error where the curve has no point (a rational curve whose weight vanishes).
    fn eval(&self, t: &Self::Scalar) -> Result<Self::Point>;
    /// The pieces `x(t0 t)` and `x(t0 + (1 − t0) t)`.
    fn split_at(&self, t0: &Self::Scalar) -> Result<(Self, Self)>;
    /// The polynomial degree (of the numerator and denominator for a rational curve).
    fn degree(&self) -> usize;

    /// The piece `x(t0 + (t1 − t0) t)`, `0 ≤ t ≤ 1`: the curve between the parameters `t0` and
    /// `t1` (reversed when `t1 < t0`). Only `t0 = 1, t1 = 0` is refused (a division by zero).
    fn subsegment(&self, t0: &Self::Scalar, t1: &Self::Scalar) -> Result<Self>
    where
        Self::Scalar: Scalar,
    {
        let one = Self::Scalar::one();
        if *t0 != one {
            let (_, right) = self.split_at(t0)?;
            let s = t1.sub_ref(t0).checked_div(&one.sub_ref(t0))?;
            Ok(right.split_at(&s)?.0)
        } else {
            let (left, _) = self.split_at(t1)?;
            let s = t0.checked_div(t1)?;
            Ok(left.split_at(&s)?.1)
        }
    }
}

/// A curve with a derivative curve.
pub trait ParamCurveDeriv: ParamCurve {
    /// The derivative's kind: a polynomial curve of one degree less, or a rational curve.
    type Deriv: ParamCurve<Scalar = Self::Scalar, Point = Self::Point>;

    /// The derivative curve `ẋ`.
    fn deriv(&self) -> Result<Self::Deriv>;

    /// `ẋ(t)`, without building the derivative curve where a kind can do better.
    fn deriv_at(&self, t: &Self::Scalar) -> Result<Self::Point> {
        self.deriv()?.eval(t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{BezierCurve, BigRational, Point, Point2, RationalBezierCurve};

    type Q = BigRational;

    fn q(p: i64, d: i64) -> Q {
        Q::from_ratio(p, d).unwrap()
    }

    #[test]
    fn rational_derivative_curve_matches_the_quotient_rule() {
        // a quarter circle and a cubic with mixed weights
        let arc: RationalBezierCurve<Q> =
            RationalBezierCurve::from_ints(&[&[1, 0], &[1, 1], &[0, 1]], &[1, 1, 2]).unwrap();
        let cubic: RationalBezierCurve<Q> =
            RationalBezierCurve::from_ints(&[&[0, 0], &[1, 3], &[4, -1], &[5, 2]], &[2, 1, 3, 1]).unwrap();
        for c in [arc, cubic] {
            let d = c.deriv().unwrap();
            assert_eq!(ParamCurve::degree(&d), 2 * c.degree());
            for t in [q(0, 1), q(1, 3), q(1, 2), q(1, 1), q(-2, 5)] {
                assert_eq!(
                    ParamCurve::eval(&d, &t).unwrap(),
                    c.derivative_at(&t).unwrap(),
                    "t = {t}"
                );
            }
        }
        let point: RationalBezierCurve<Q> = RationalBezierCurve::from_ints(&[&[3, 4]], &[5]).unwrap();
        assert_eq!(
            point.deriv().unwrap().eval(&q(1, 2)).unwrap(),
            Point::from_ints(&[0, 0]).unwrap()
        );
    }

    #[test]
    fn polynomial_deriv_is_the_hodograph() {
        let c: BezierCurve<Q> = BezierCurve::from_ints(&[&[0, 0], &[1, 2], &[3, 2], &[4, 0]]).unwrap();
        assert_eq!(c.deriv().unwrap(), c.hodograph().unwrap());
        assert_eq!(c.deriv_at(&q(1, 3)).unwrap(), c.derivative_at(1, &q(1, 3)).unwrap());
        let constant: BezierCurve<Q> = BezierCurve::from_ints(&[&[7, 1]]).unwrap();
        assert_eq!(
            constant.deriv().unwrap().points(),
            &[Point::from_ints(&[0, 0]).unwrap()]
        );
    }

    #[test]
    fn subsegment_is_the_reparametrised_curve() {
        let c: BezierCurve<Q> = BezierCurve::from_ints(&[&[0, 0], &[1, 2], &[3, 2], &[4, 0]]).unwrap();
        for (t0, t1) in [
            (q(1, 4), q(2, 3)),
            (q(2, 3), q(1, 4)),
            (q(1, 1), q(1, 2)),
            (q(0, 1), q(1, 1)),
        ] {
            let s = c.subsegment(&t0, &t1).unwrap();
            for u in [q(0, 1), q(1, 5), q(1, 1)] {
                let t = &t0 + &(&(&t1 - &t0) * &u);
                assert_eq!(s.eval(&u), c.eval(&t));
            }
        }
        assert!(c.subsegment(&q(1, 1), &q(0, 1)).is_err());
        let r: RationalBezierCurve<Q> =
            RationalBezierCurve::from_ints(&[&[1, 0], &[1, 1], &[0, 1]], &[1, 1, 2]).unwrap();
        let s = r.subsegment(&q(1, 3), &q(3, 4)).unwrap();
        assert_eq!(
            ParamCurve::eval(&s, &q(1, 2)).unwrap(),
            r.eval(&(&q(1, 3) + &(&q(5, 12) * &q(1, 2)))).unwrap()
        );
    }

    #[test]
    fn fixed_and_runtime_points_agree_bit_for_bit() {
        let coords = [[0.1, 0.7], [1.3, 2.9], [3.7, 2.1], [4.3, 0.2], [5.5, -1.25]];
        let fixed = crate::Bezier::from_points(coords.map(Point2::from)).unwrap();
        let runtime: BezierCurve<f64> = BezierCurve::from_coords(coords.iter().map(|c| c.to_vec()).collect()).unwrap();
        for t in [0.3, -0.4, 1.7] {
            assert_eq!(&fixed.eval(&t).0[..], runtime.eval(&t).coords());
            let (fl, fr) = fixed.split_at(&t);
            let (rl, rr) = runtime.split_at(&t);
            for (a, b) in fl
                .points()
                .iter()
                .zip(rl.points())
                .chain(fr.points().iter().zip(rr.points()))
            {
                assert_eq!(&a.0[..], b.coords());
            }
        }
        let e = fixed.elevate().unwrap();
        for (a, b) in e.points().iter().zip(runtime.elevate().unwrap().points()) {
            assert_eq!(&a.0[..], b.coords());
        }
    }
}
