//! The figure each claim is about: its own curves or surfaces when it has them, otherwise an
//! illustration of its topic on a text's example.

use crate::error::Result;
use crate::figure::FigureKind;
use crate::figure::{self, AnyCurve, Figure};
use crate::point::Point;
use crate::quadratic::QuadraticIrrational;
use crate::rational::RationalBezierCurve;
use crate::scalar::{Ring, Scalar};
use crate::surface::BezierSurface;
use crate::verify::claims::{Claim, Kind, Number, SurfaceSpec};
use crate::BezierCurve;

/// The exact scalar of claim figures: claim files may write `2*sqrt(2)`.
type Q = QuadraticIrrational;

/// A figure for a claim, with a caption saying what it shows.
#[derive(Clone, Debug)]
pub struct ClaimFigure {
    /// The figure.
    pub figure: Figure,
    /// Whether it draws the claim's own data (`false`: an illustration on a text's example).
    pub own_data: bool,
    /// One line under the figure.
    pub caption: String,
}

fn number(n: &Number) -> Result<Q> {
    Q::parse(&n.text()?)
}

fn points(rows: &[Vec<Number>]) -> Result<Vec<Point<Q>>> {
    rows.iter()
        .map(|p| Point::new(p.iter().map(number).collect::<Result<Vec<_>>>()?))
        .collect()
}

fn surface_of(spec: &SurfaceSpec) -> Result<BezierSurface<Q>> {
    BezierSurface::new(spec.net.iter().map(|row| points(row)).collect::<Result<_>>()?)
}

fn q(p: i64, d: i64) -> Q {
    Q::from_ratio(p, d).expect("nonzero denominator")
}

/// Text 000's example 4), the curve the illustrations of general statements are drawn on.
fn example_curve() -> Result<BezierCurve<Q>> {
    BezierCurve::new(vec![
        Point::new(vec![q(0, 1), q(0, 1)])?,
        Point::new(vec![q(4, 3), q(-4, 3)])?,
        Point::new(vec![q(4, 3), q(4, 3)])?,
        Point::new(vec![q(0, 1), q(0, 1)])?,
    ])
}

const ON_EXAMPLE: &str = "illustration on text 000's example 4), b = (0, 0), (4/3, −4/3), (4/3, 4/3), (0, 0)";

/// Which illustration a general statement about curves gets: the claim's `figure`, or its
/// theorem's.
pub(super) fn topic(c: &Claim) -> Option<FigureKind> {
    if let Kind::Theorem(t) = &c.kind {
        return match t.theorem.as_str() {
            "de_casteljau_bernstein" => Some(FigureKind::Construction),
            "subdivision" => Some(FigureKind::Subdivision),
            "elevation_7" | "elevation_8" => Some(FigureKind::Elevation),
            "derivative" | "derivative_k" | "endpoint_tangent" | "tangent_at_t0" => Some(FigureKind::Hodograph),
            "convex_hull" => Some(FigureKind::Hull),
            _ => None,
        };
    }
    c.figure
}

fn illustrate(t: FigureKind) -> Result<Figure> {
    let c = example_curve()?;
    let half = q(1, 2);
    match t {
        FigureKind::Construction => figure::construction(&c, &half),
        FigureKind::Subdivision => figure::subdivision(&c, &q(1, 3)),
        FigureKind::Elevation => figure::elevation(&c, &[1, 2, 4, 8, 16]),
        FigureKind::Hodograph => figure::hodograph(&c),
        FigureKind::Hull => figure::hull(&c, &c.eval(&q(1, 3))),
        FigureKind::Conics => {
            let rows = crate::input::parse_points(figure::DEFAULT_CONIC_POLYGON)?;
            let pts = rows
                .iter()
                .map(|p| p.try_map(|x| Ok(Q::rational(x.clone()))))
                .collect::<Result<Vec<_>>>()?;
            figure::conics(&pts, &q(1, 1), &q(1, 1), &[q(1, 2), q(1, 1), q(2, 1)])
        }
        FigureKind::Projection => figure::conic_projection(&BezierCurve::new(
            crate::input::parse_points(figure::DEFAULT_PARABOLA)?
                .iter()
                .map(|p| p.try_map(|x| Ok(Q::rational(x.clone()))))
                .collect::<Result<_>>()?,
        )?),
        FigureKind::Fit => {
            let rows = crate::input::parse_points(figure::DEFAULT_FIT_CURVE)?;
            let pts = rows
                .iter()
                .map(|p| p.try_map(|x| Ok(Q::rational(x.clone()))))
                .collect::<Result<Vec<_>>>()?;
            figure::fit(&AnyCurve::Polynomial(BezierCurve::new(pts)?))
        }
        // the others on the figure command's own defaults (its texts' examples)
        FigureKind::Net | FigureKind::Enneper | FigureKind::Bernstein => figure::FigureRequest::new(t).figure(),
    }
}

/// The figure a claim is about: the claim's own curves or surfaces when it has them (a
/// conic arc family for a rational quadratic, the fit for a `fit` claim, the net with
/// iso-curves for a surface, Enneper's net, the elevation for Theorem 1.2, the construction
/// for a polynomial curve), otherwise an illustration of the statement's topic on a text's
/// example (by its theorem, or the claim file's `figure`). `None` for claims with no geometric
/// object (scalar identities, text 004's vector algebra).
pub fn claim_figure(c: &Claim) -> Result<Option<ClaimFigure>> {
    let own = |figure: Figure, caption: String| {
        Ok(Some(ClaimFigure {
            figure,
            own_data: true,
            caption,
        }))
    };
    if let Some(surfaces) = &c.decls.surfaces {
        if let Some((name, spec)) = surfaces.iter().next() {
            let surface = surface_of(spec)?;
            if matches!(c.kind, Kind::Enneper) {
                return own(
                    figure::enneper(&surface)?,
                    format!("the claim's net {name}, with iso-curves"),
                );
            }
            return own(
                figure::net(&surface, 4, &format!("The net of {name}"))?,
                format!("the claim's net {name}: iso-curves and boundary curves"),
            );
        }
    }
    if let Some(curves) = &c.decls.curves {
        let objs: Vec<(&String, AnyCurve<Q>)> = curves
            .iter()
            .map(|(n, spec)| Ok((n, crate::verify::curve_from_spec::<Q>(spec)?)))
            .collect::<Result<_>>()?;
        if matches!(c.kind, Kind::Fit(_)) {
            if let Some((name, x)) = objs.first() {
                return own(figure::fit(x)?, format!("text 004's fit of the claim's curve {name}"));
            }
        }
        if matches!(c.kind, Kind::Convergence(_)) {
            if let Some((name, AnyCurve::Polynomial(b))) =
                objs.iter().find(|(_, o)| matches!(o, AnyCurve::Polynomial(_)))
            {
                return own(
                    figure::elevation(b, &[1, 2, 4, 8, 16])?,
                    format!("the claim's curve {name} elevated r = 1, 2, 4, 8, 16 times"),
                );
            }
        }
        // a planar rational quadratic: the family of arcs of its polygon
        let conic = objs.iter().find_map(|(name, o)| match o {
            AnyCurve::Rational(r) if r.dim() == 2 && r.degree() == 2 => Some((name, r.clone())),
            _ => None,
        });
        // a homogeneous quadratic in space: the rational arc it projects to
        let conic = match conic {
            Some(found) => Some(found),
            None => objs.iter().find_map(|(name, o)| match o {
                AnyCurve::Polynomial(p) if p.dim() == 3 && p.degree() == 2 => {
                    RationalBezierCurve::from_homogeneous(p).ok().map(|r| (name, r))
                }
                _ => None,
            }),
        };
        if let Some((name, arc)) = conic {
            let w = arc.weights();
            let mut middles = vec![w[1].clone()];
            if w[0] == Q::one() && w[2] == Q::one() {
                for m in [q(1, 2), q(1, 1), q(2, 1)] {
                    if !middles.contains(&m) {
                        middles.push(m);
                    }
                }
            }
            middles.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
            return own(
                figure::conics(arc.points(), &w[0], &w[2], &middles)?,
                format!(
                    "the claim's arc {name} (w₁ = {}) among arcs of its control polygon",
                    w[1]
                ),
            );
        }
        if let Some((name, AnyCurve::Polynomial(b))) = objs.iter().find(|(_, o)| matches!(o, AnyCurve::Polynomial(_))) {
            return own(
                figure::construction(b, &q(1, 2))?,
                format!("the claim's curve {name}: de Casteljau's construction at t = 1/2"),
            );
        }
    }
    if let Kind::BezierPoints(claimed) = &c.kind {
        {
            let b = BezierCurve::new(points(&claimed.points)?)?;
            return own(
                figure::construction(&b, &q(1, 2))?,
                "the claimed Bézier points and their curve, constructed at t = 1/2".into(),
            );
        }
    }
    if let Some(t) = topic(c) {
        let caption = match t {
            FigureKind::Fit => "illustration of text 004's method on our worked example x(t) = (t, 1 + t², t⁴)",
            FigureKind::Conics => "illustration on the control polygon of text 001's Ex. 3 and Ex. 4, w₀ = w₂ = 1",
            FigureKind::Projection => "illustration on the parabola of text 001's Ex. 1 of the proof of (10)",
            FigureKind::Net => "illustration on text 003's Ex. 2 net (degree (2, 2))",
            FigureKind::Enneper => "illustration on Enneper's net of text 003's Ex. 5",
            FigureKind::Bernstein => "the Bernstein basis of degree 3, with its values at t = 1/3",
            _ => ON_EXAMPLE,
        };
        return Ok(Some(ClaimFigure {
            figure: illustrate(t)?,
            own_data: false,
            caption: caption.into(),
        }));
    }
    if let Some(net) = &c.decls.net {
        // a symbolic net: illustrated on text 003's nets
        let (spec, what) = if net.degree == ["1", "1"] {
            (
                "0,0,0; 0,1,0 | 1,0,0; 1,1,1",
                "illustration on text 003's bilinear patch (a hyperbolic paraboloid)",
            )
        } else {
            (
                figure::DEFAULT_NET,
                "illustration on text 003's Ex. 2 net (degree (2, 2))",
            )
        };
        let rows = crate::input::parse_net(spec)?;
        let surface: BezierSurface<Q> = BezierSurface::new(
            rows.iter()
                .map(|r| {
                    r.iter()
                        .map(|p| p.try_map(|x| Ok(Q::rational(x.clone()))))
                        .collect::<Result<Vec<_>>>()
                })
                .collect::<Result<_>>()?,
        )?;
        return Ok(Some(ClaimFigure {
            figure: figure::net(&surface, 4, "A tensor-product net")?,
            own_data: false,
            caption: what.into(),
        }));
    }
    Ok(None)
}
