//! The fixed-degree curves ([`casteljau::BezierN`]: `Line`, `Quad`, `Cubic`, …) against the
//! any-degree [`casteljau::Bezier`] on the same random control points: eval, split,
//! subsegment, elevation and derivative agree with `==` on exact rationals (run-time and
//! fixed-dimension points) and bit for bit on `f64`.
//!
//! "Bit for bit" is `==` together with equal `Debug` output, which for `f64` is the shortest
//! text that reads back to the same bits (so `0.0` and `-0.0` differ).

use casteljau::strategies::{exact_curve, f64_curve, wide_parameter, wide_parameter_f64};
use casteljau::{Bezier, BezierCurve, BezierN, ParamCurve, Point2, RefOps, Scalar, VectorSpace};
use proptest::prelude::*;
use proptest::test_runner::Config;
use std::fmt::Debug;

/// Equal, and equal to the bit.
fn same<X: PartialEq + Debug>(a: &X, b: &X) -> bool {
    a == b && format!("{a:?}") == format!("{b:?}")
}

/// The planar curve of a run-time-dimension curve of dimension 2.
fn planar<T: Scalar>(c: &BezierCurve<T>) -> Bezier<Point2<T>>
where
    for<'a> &'a T: RefOps<T>,
{
    Bezier::from_points(c.points().iter().map(|p| Point2::new(p[0].clone(), p[1].clone()))).unwrap()
}

/// What holds for every `N`: conversion both ways, eval, split and subsegment agree.
fn agrees<T, P, const N: usize>(c: &Bezier<P>, t: &T, u: &T) -> Result<(), TestCaseError>
where
    T: Scalar,
    for<'a> &'a T: RefOps<T>,
    P: VectorSpace<Scalar = T>,
{
    let f = BezierN::<P, N>::try_from(c).unwrap();
    prop_assert!(same(&Bezier::from(f.clone()), c));
    prop_assert_eq!(f.degree(), c.degree());
    prop_assert!(same(&f.eval(t), &c.eval(t)));
    let (fl, fr) = f.split_at(t);
    let (cl, cr) = c.split_at(t);
    prop_assert!(same(&Bezier::from(fl), &cl));
    prop_assert!(same(&Bezier::from(fr), &cr));
    match (ParamCurve::subsegment(&f, t, u), ParamCurve::subsegment(c, t, u)) {
        (Ok(fs), Ok(cs)) => prop_assert!(same(&Bezier::from(fs), &cs)),
        (fs, cs) => prop_assert_eq!(fs.err(), cs.err()),
    }
    Ok(())
}

macro_rules! fixed_agrees {
    ($($name:ident: $n:literal),* $(,)?) => {$(
        mod $name {
            use super::*;
            use casteljau::ParamCurveDeriv;

            const DEGREE: usize = $n - 1;

            fn elevate_and_deriv<T, P>(c: &Bezier<P>) -> Result<(), TestCaseError>
            where
                T: Scalar,
                for<'a> &'a T: RefOps<T>,
                P: VectorSpace<Scalar = T>,
            {
                let f = BezierN::<P, $n>::try_from(c).unwrap();
                prop_assert!(same(&Bezier::from(f.elevate()), &c.elevate().unwrap()));
                prop_assert!(same(&Bezier::from(f.deriv()), &c.deriv().unwrap()));
                prop_assert!(same(&Bezier::from(ParamCurveDeriv::deriv(&f).unwrap()), &c.deriv().unwrap()));
                Ok(())
            }

            proptest! {
                #![proptest_config(Config::with_cases(48))]

                #[test]
                fn exact_runtime_points(c in exact_curve(DEGREE..=DEGREE, 1..=3), t in wide_parameter(), u in wide_parameter()) {
                    agrees::<_, _, $n>(&c, &t, &u)?;
                    elevate_and_deriv(&c)?;
                    // The elevated curve is the same curve, exactly.
                    let f = BezierN::<_, $n>::try_from(&c).unwrap();
                    prop_assert_eq!(f.elevate().eval(&t), f.eval(&t));
                }

                #[test]
                fn exact_planar_points(c in exact_curve(DEGREE..=DEGREE, 2..=2), t in wide_parameter(), u in wide_parameter()) {
                    let c = planar(&c);
                    agrees::<_, _, $n>(&c, &t, &u)?;
                    elevate_and_deriv(&c)?;
                }

                #[test]
                fn f64_runtime_points(c in f64_curve(DEGREE..=DEGREE, 1..=3, 100.0), t in wide_parameter_f64(), u in wide_parameter_f64()) {
                    agrees::<_, _, $n>(&c, &t, &u)?;
                    elevate_and_deriv(&c)?;
                }

                #[test]
                fn f64_planar_points(c in f64_curve(DEGREE..=DEGREE, 2..=2, 100.0), t in wide_parameter_f64(), u in wide_parameter_f64()) {
                    let c = planar(&c);
                    agrees::<_, _, $n>(&c, &t, &u)?;
                    elevate_and_deriv(&c)?;
                }
            }
        }
    )*};
}

fixed_agrees!(constant: 1, line: 2, quad: 3, cubic: 4, quartic: 5, degree_7: 8);

/// One step of (7) written out on the coordinates, `b'_i = b_i + (i · 1/(n+1)) (b_{i-1} − b_i)`
/// with the first and last points kept: the operations of the generic loop, in its order.
fn elevated_by_hand(points: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let n = points.len() - 1;
    let step = 1.0 / (n + 1) as f64;
    (0..n + 2)
        .map(|i| match i {
            0 => points[0].clone(),
            i if i > n => points[n].clone(),
            i => {
                let w = i as f64 * step;
                points[i]
                    .iter()
                    .zip(&points[i - 1])
                    .map(|(a, b)| a + w * (b - a))
                    .collect()
            }
        })
        .collect()
}

proptest! {
    #![proptest_config(Config::with_cases(256))]

    /// The any-degree elevation takes the fixed-degree kernel for a quadratic and a cubic and
    /// a loop for the other degrees: all of them are (7) by hand, bit for bit, for run-time
    /// and fixed-dimension points.
    #[test]
    fn f64_elevation_is_formula_7_bit_for_bit(c in f64_curve(0..=7, 1..=3, 100.0)) {
        let coords = |points: Vec<Vec<f64>>| points.into_iter().map(|p| p.into_iter().map(f64::to_bits).collect::<Vec<_>>()).collect::<Vec<_>>();
        let expected = coords(elevated_by_hand(&c.points().iter().map(|p| p.coords().to_vec()).collect::<Vec<_>>()));
        let runtime = c.elevate().unwrap();
        prop_assert_eq!(&coords(runtime.points().iter().map(|p| p.coords().to_vec()).collect()), &expected);
        if c.dim() == 2 {
            let planar = planar(&c).elevate().unwrap();
            prop_assert_eq!(&coords(planar.points().iter().map(|p| p.0.to_vec()).collect()), &expected);
        }
    }
}

#[test]
fn a_curve_of_another_degree_is_refused() {
    let c: BezierCurve<f64> = BezierCurve::from_ints(&[&[0, 0], &[1, 2], &[3, 2], &[4, 0]]).unwrap();
    assert!(casteljau::Quad::try_from(&c).is_err());
    assert!(BezierN::<_, 5>::try_from(&c).is_err());
    assert!(casteljau::Cubic::try_from(&c).is_ok());
}
