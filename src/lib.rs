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
//! Everything for curves, surfaces and their numbers is at the crate root, whatever file
//! it lives in: the number trait [`Scalar`] and exact parsing ([`parse_exact`],
//! [`parse_points`]); the point trait [`VectorSpace`] with fixed-dimension points
//! ([`Point2`], [`PointN`]) and run-time-dimension [`Point`]s; Bézier curves of any degree
//! ([`Bezier`], [`BezierCurve`]) and of a fixed one ([`Cubic`], [`BezierN`]), with the
//! traits over curve kinds ([`ParamCurve`]); the Bernstein basis ([`bernstein`],
//! [`power_to_bernstein`]); exact convex-hull membership ([`convex_weights`]); rational
//! curves and conics ([`RationalBezierCurve`], [`classify_conic`]); surfaces
//! ([`BezierSurface`]); cubic fitting ([`fit_cubic`], [`fit_least_squares`]); and the float
//! judges that need no module of their own ([`Interval`], [`Shadow`]).
//!
//! Modules are public where their names need a namespace: [`float`] (certified floating
//! point), [`exact`] (the integer kernels behind exact evaluation), [`linalg`] (exact
//! elimination: `solve`, `inverse`, `determinant`), [`figure`] (SVG figures), and, behind
//! their Cargo features, `verify` and `html` (`prove`: the texts' claims and their report),
//! `oracle` (`oracle`: the JSON-lines oracle) and `strategies` (`strategies`: proptest
//! strategies for exact inputs).
//!
//! ## Layers
//!
//! No import circle: each core file (every file of `src/` but `verify/`, `html`, `figure/`,
//! `oracle/` and `main.rs`; a folder's `mod.rs` by the folder's name) imports only files named
//! before it in this list, bottom up (`tests/layers.rs` reads the list and checks it):
//!
//! - storage and errors, and the folders' `mod.rs` (declarations and re-exports only):
//!   `coords` (the point types' storage), `error`, `exact`, `float`;
//! - kernels on numbers: `exact/gcd`, `exact/hensel`, `exact/splitting`, `exact/long_pair`,
//!   `exact/elevation_words`,
//!   `exact/fraction_free/int`, `exact/fraction_free/horner`,
//!   `exact/fraction_free/horner_long`, `exact/fraction_free/split`,
//!   `exact/fraction_free/choice` (which of them runs, by size),
//!   `float/scratch`, `float/ulp`, `float/eft`, `float/casteljau`, `float/compensated_pairs`,
//!   `float/compensated`, `float/methods`, `float/ops`;
//! - `scalar/ring`, `scalar/ops`, and the exact kernels on points: `exact/fraction_free`,
//!   `exact/fit_numbers`, `exact/power_basis`;
//! - the number trait with its kernel choice: `scalar`; the other numbers:
//!   `exact/small_rational`, `quadratic`, `shadow`, `judge`, `linalg`, `bernstein`,
//!   `exact/basis_table`;
//! - points: `space`, `point`, `hull`, `input`;
//! - curves: `kernel`, `param`, `curve/scheme`, `curve`, `curve/exact`, `fixed`, `many`,
//!   `float/dyadic`, `strategies`;
//! - rational curves, surfaces, fitting: `rational`, `conic`, `any_curve`, `surface`, `fit`,
//!   `least_squares`, `work`;
//! - intervals: `interval`, `float/dispatch` (the sign-split kernel of `eval`),
//!   `interval/number` (`Interval` as a number, choosing that kernel).
//!
//! The generic algorithms choose a type's own kernel (the fraction-free kernels of
//! [`exact`] for `BigRational`, the sign-split enclosure for [`Interval`]) by methods of
//! [`Scalar`] and [`VectorSpace`] that the type overrides, not by type identity: the
//! kernels take slices of points and import only numbers and points.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod any_curve;
mod bernstein;
mod conic;
mod coords;
mod curve;
mod error;
pub mod exact;
pub mod figure;
mod fit;
mod fixed;
pub mod float;
#[cfg(feature = "prove")]
pub mod html;
mod hull;
mod input;
mod interval;
pub mod judge;
mod kernel;
mod least_squares;
pub mod linalg;
mod many;
#[cfg(feature = "oracle")]
pub mod oracle;
mod param;
mod point;
mod quadratic;
mod rational;
mod scalar;
mod shadow;
mod space;
#[cfg(feature = "strategies")]
pub mod strategies;
mod surface;
#[cfg(feature = "prove")]
pub mod verify;
// The figures estimate a part of their work with the oracle's model; the oracle uses all of it.
#[cfg_attr(not(feature = "oracle"), allow(dead_code))]
mod work;

pub use any_curve::AnyCurve;
pub use bernstein::{
    bernstein, bernstein_to_power, binomial, binomial_signed, eval_power, power_to_bernstein, reparametrize,
};
pub use curve::{Bezier, BezierCurve, DeCasteljauScheme, ElevationDistance};
pub use error::{Error, Result, MAX_DEGREE, MAX_DIMENSION};
pub use fixed::{BezierN, Cubic, Line, Quad};
pub use hull::{convex_weights, hull_contains, MAX_SUBSETS};
pub use input::{format_points, parse_count, parse_net, parse_number, parse_numbers, parse_point, parse_points};
pub use many::LANES;
pub use num_bigint::BigInt;
pub use num_rational::BigRational;
pub use param::{ParamCurve, ParamCurveDeriv};
pub use point::{barycentric, linear_combination, AffineMap, Point, Vector};
pub use scalar::{format_exact, parse_exact, RefOps, Ring, Scalar, MAX_DECIMAL_EXPONENT, MAX_NUMBER_LEN};
pub use space::{Point2, Point3, PointN, VectorSpace};

// --- rational curves, conics, quadratic irrationals
pub use conic::{
    classify_conic, conic_arc_passes_infinity, conic_shape_factor, implicit_conic, ConicKind, ImplicitConic,
};
pub use quadratic::{QuadraticIrrational, MAX_RADICAND};
pub use rational::{ExactSqrt, RationalBezierCurve};

// --- surfaces
pub use surface::{enneper_net, enneper_power, BezierSurface, EnneperMatch};

// --- fitting
pub use fit::{
    cubic_with_tangent_lengths, delta_squared, delta_squared_gradient, fit_cubic, fit_cubic_closed_form, fit_cubic_to,
    CubicFit, CubicFitData, CubicFitSource,
};
pub use least_squares::{
    centripetal_params, chord_length_params, chord_length_params_via_f64, fit_least_squares, least_squares_gradient,
    least_squares_residual, uniform_params, FitConstraints, LeastSquaresFit, MAX_FIT_DEGREE,
};

// --- judging floats: interval enclosures, filtered predicates, a float with its exact shadow
pub use interval::{
    filter_stats, filtered_conic_kind, filtered_hull_contains, filtered_orientation, interval_de_casteljau,
    tight_interval_de_casteljau, FilterStats, Interval,
};
pub use shadow::Shadow;

// --- verification
#[cfg(feature = "prove")]
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
