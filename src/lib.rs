//! # casteljau — Bézier geometry, checked exactly
//!
//! One set of algorithms, generic over a [`Scalar`], runs on exact rationals
//! ([`BigRational`]) to verify identities and textbook claims with `==`, and on `f64` for
//! speed. The exact path doubles as a regression oracle for float code.
//!
//! ```
//! use casteljau::{BezierCurve, BigRational, Ring, Scalar};
//! let curve: BezierCurve<BigRational> = BezierCurve::from_ints(&[&[0, 0], &[1, 2], &[3, 2], &[4, 0]]).unwrap();
//! let half = BigRational::from_ratio(1, 2).unwrap();
//! let (left, right) = curve.split_at(&half);
//! // Lemma 1.3: the left half at t is the curve at t/2, exactly.
//! let t = BigRational::from_ratio(1, 3).unwrap();
//! assert_eq!(left.eval(&t), curve.eval(&(&half * &t)));
//! assert_eq!(right.eval(&BigRational::from_i64(0)), curve.eval(&half));
//! ```
//!
//! Modules, one concept each: [`scalar`] (the number trait, exact parsing), [`space`] (the
//! point trait the algorithms are generic over, fixed-dimension points), [`point`]
//! (run-time-dimension points, barycentric combinations, affine maps), [`kernel`] (the one
//! de Casteljau kernel), [`bernstein`] (binomials, the Bernstein basis, power ↔ Bernstein),
//! [`curve`] (Bézier curves), [`fixed`] (curves of a fixed degree), [`param`] (traits over curve kinds), [`hull`] (exact
//! convex-hull membership), [`linalg`] (exact elimination).

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bernstein;
pub mod curve;
pub mod error;
pub mod exact;
pub mod figure;
pub mod fit;
pub mod fixed;
pub mod float;
pub mod html;
pub mod hull;
pub mod input;
pub mod interval;
pub mod kernel;
pub mod linalg;
pub mod oracle;
pub mod param;
pub mod point;
pub mod quadratic;
pub mod rational;
pub mod scalar;
pub mod shadow;
pub mod space;
#[cfg(feature = "strategies")]
pub mod strategies;
pub mod surface;
pub mod verify;

pub use curve::{Bezier, BezierCurve, DeCasteljauScheme, ElevationDistance};
pub use error::{Error, Result, MAX_DEGREE, MAX_DIMENSION};
pub use fixed::{BezierN, Cubic, Line, Quad};
pub use num_bigint::BigInt;
pub use num_rational::BigRational;
pub use param::{ParamCurve, ParamCurveDeriv};
pub use point::{AffineMap, Point, Vector};
pub use scalar::{RefOps, Ring, Scalar};
pub use space::{Point2, Point3, PointN, VectorSpace};

// --- rational curves, conics, quadratic irrationals
pub use quadratic::QuadraticIrrational;
pub use rational::{
    classify_conic, conic_arc_passes_infinity, conic_shape_factor, implicit_conic, ConicKind, ExactSqrt, ImplicitConic,
    RationalBezierCurve,
};

// --- surfaces
pub use surface::{enneper_net, BezierSurface, EnneperMatch};

// --- fitting
pub use fit::{
    fit_cubic, fit_cubic_closed_form, fit_cubic_to, fit_least_squares, CubicFit, CubicFitData, CubicFitSource,
    FitConstraints, LeastSquaresFit,
};

// --- verification
pub use verify::{explain, explain_files, prove_files, prove_paths, ClaimOutcome, Report, Verdict};

// --- exact arithmetic for the hot loops: a machine-word rational, shared Bernstein rows
pub use exact::{BernsteinTable, SmallRational};

// --- end of re-exports

/// The README's Rust examples, compiled and run as doctests so that they stay true.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// The library guide's Rust examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../docs/library.md")]
pub struct LibraryGuideDoctests;
