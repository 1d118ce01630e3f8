//! Figures for teaching, computed from exact data: the de Casteljau construction, subdivision,
//! degree elevation, the hodograph, the convex hull, conic arcs, control nets, Enneper's net,
//! text 004's fit, the Bernstein basis and text 001's projection of a parabola to a conic,
//! each written as a standalone SVG. Labels are placed clear of lines, points and each other
//! (the private `place` module).
//!
//! Every figure is computed in exact arithmetic with the library's own operations (`scheme`,
//! `split_at`, `elevate_by`, `derivative`, `convex_weights`, `classify_conic`, `iso_u`/`iso_v`,
//! `enneper_net`, `fit_cubic_to`); values become `f64` pixel coordinates only when the SVG is
//! written ([`svg`]). Each drawn point carries its exact value as a `<title>` tooltip, and
//! the figure's notes print the exact numbers the figure is about, so a printed copy keeps
//! them. Space curves and surfaces are drawn in one fixed projection ([`projection`]).
//!
//! What a figure only draws (the curve between its control points, iso-curves, arcs) is
//! sampled in `f64` from the exact control data rounded once (the private `sample` module):
//! pixels need no more, and exact samples would cost a whole scheme each.
//!
//! # Limits
//!
//! Every `casteljau figure` request is bounded before any work, and refused with a one-line
//! error naming the limit: degrees (of a curve, or of a net either way) at most
//! [`MAX_FIGURE_DEGREE`]; every number (coordinates, `--t`, `--point`, `--weights`) at most
//! [`MAX_FIGURE_NUMBER_BITS`] bits in its numerator and in its denominator; at most
//! [`MAX_FIGURE_STEPS`] elevation steps, each at most [`MAX_FIGURE_ELEVATION`]; at most
//! [`MAX_FIGURE_ARCS`] conic arcs and [`MAX_ISO`] iso-curves per direction; the Bernstein
//! basis's degree times the bits of `--t` at most [`MAX_BERNSTEIN_BITS`]; the hull search at
//! most [`crate::hull::MAX_SUBSETS`] subsets. The exact computations a figure prints (the
//! scheme, the pieces, elevated polygons and their distances, hull weights, the fit, the
//! Enneper match) are given a work estimate in the oracle's units (the oracle's `Op::work`)
//! which must stay below [`MAX_FIGURE_WORK`]. The list with
//! examples is in `docs/limits.md`.
//!
//! ```
//! use casteljau::{figure, BezierCurve, BigRational, Scalar};
//! let c: BezierCurve<BigRational> = BezierCurve::from_ints(&[&[0, 0], &[1, 2], &[3, 2], &[4, 0]]).unwrap();
//! let fig = figure::construction(&c, &BigRational::from_ratio(1, 2).unwrap()).unwrap();
//! let svg = fig.to_svg().unwrap();
//! assert!(svg.contains("b₀³(1/2) = (2, 3/2)"));
//! ```

mod bernstein;
mod conics;
mod construction;
mod elevation;
mod enneper;
mod fit;
mod hodograph;
mod homogeneous;
mod hull;
mod net;
mod place;
mod request;
mod sample;
mod subdivision;
pub mod svg;

pub use bernstein::bernstein_basis;
pub use conics::conics;
pub use construction::construction;
pub use elevation::{elevation, MAX_FIGURE_ELEVATION};
pub use enneper::{enneper, text003_example5};
pub use fit::fit;
pub use hodograph::hodograph;
pub use homogeneous::conic_projection;
pub use hull::hull;
pub use net::{net, MAX_ISO};
pub use request::{
    FigureKind, FigureRequest, DEFAULT_CONIC_POLYGON, DEFAULT_CURVE, DEFAULT_FIT_CURVE, DEFAULT_NET, DEFAULT_PARABOLA,
    MAX_BERNSTEIN_BITS, MAX_FIGURE_ARCS, MAX_FIGURE_NUMBER_BITS, MAX_FIGURE_STEPS, MAX_FIGURE_WORK,
};
pub use subdivision::subdivision;
pub use svg::{Figure, Layout, Panel, PanelMap};

use crate::error::{Error, Result};
use crate::point::{AffineMap, Point};
use crate::scalar::Scalar;
use crate::BezierCurve;

/// The largest degree (of a curve, or of a net in either direction) a figure draws: the
/// construction alone draws `(n + 1)(n + 2)/2` labelled points, and beyond this no figure is
/// readable.
pub const MAX_FIGURE_DEGREE: usize = 64;

/// [`MAX_FIGURE_DEGREE`] as an error.
pub(crate) fn check_figure_degree(degree: usize) -> Result<()> {
    if degree > MAX_FIGURE_DEGREE {
        return Err(Error::TooLarge {
            what: "degree in a figure",
            value: degree.to_string(),
            limit: MAX_FIGURE_DEGREE.to_string(),
        });
    }
    Ok(())
}

/// The fixed projection of space figures: the oblique (cabinet-like) view of textbooks, with
/// the x axis towards the reader drawn down-left at a third of its length:
/// `X = y − x/3`, `Y = z − x/3`. The map is exact, so projected curves and nets are exactly
/// the projections of the exact ones.
pub fn projection<T: Scalar>() -> Result<AffineMap<T>> {
    let third = T::from_ratio(-1, 3)?;
    AffineMap::new(
        vec![
            vec![third.clone(), T::one(), T::zero()],
            vec![third, T::zero(), T::one()],
        ],
        vec![T::zero(), T::zero()],
    )
}

/// The heading of panels drawn in the [`projection`].
pub(crate) const PROJECTION_HEADING: &str = "oblique view, x towards the reader: X = y − x/3, Y = z − x/3";

/// The point as drawn: planar points as they are, space points projected.
pub fn planar<T: Scalar>(p: &Point<T>) -> Result<Point<T>> {
    match p.dim() {
        2 => Ok(p.clone()),
        3 => projection()?.apply(p),
        d => Err(Error::Domain(format!(
            "a figure draws planar or space points (2 or 3 coordinates), not {d}"
        ))),
    }
}

/// A curve as drawn (see [`planar`]).
pub fn planar_curve<T: Scalar>(c: &BezierCurve<T>) -> Result<BezierCurve<T>> {
    BezierCurve::new(c.points().iter().map(planar).collect::<Result<Vec<_>>>()?)
}

pub use crate::AnyCurve;

impl<T: Scalar> AnyCurve<T> {
    /// `k/n` samples for drawing, projected: the exact control data rounded to `f64` once,
    /// then evaluated in `f64` ([`sample`]).
    pub(crate) fn drawn_samples(&self, n: usize) -> Result<Vec<[f64; 2]>> {
        let drawn = self
            .points()
            .iter()
            .map(|p| svg::xy(&planar(p)?))
            .collect::<Result<Vec<_>>>()?;
        Ok(match self {
            AnyCurve::Polynomial(_) => sample::polynomial(&drawn, n),
            AnyCurve::Rational(c) => {
                // only the weights' ratios matter: scaled by the largest, they stay in range
                let largest = c.weights().iter().map(|w| w.to_f64().abs()).fold(0.0, f64::max);
                let weights: Vec<f64> = c.weights().iter().map(|w| w.to_f64() / largest).collect();
                sample::rational(&drawn, &weights, n)
            }
        })
    }
}

/// `(p0; p1; …)` for tooltips and notes.
pub(crate) fn list<T: std::fmt::Display>(points: &[Point<T>]) -> String {
    crate::point::PointList(points).to_string()
}
