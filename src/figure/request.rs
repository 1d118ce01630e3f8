//! `casteljau figure <what> [input] [options]`: which figure, from command-line text.

use super::{AnyCurve, Figure};
use crate::error::{Error, Result};
use crate::input::{parse_count, parse_net, parse_number, parse_numbers, parse_point, parse_points};
use crate::rational::RationalBezierCurve;
use crate::surface::BezierSurface;
use crate::{BezierCurve, BigRational};
use std::str::FromStr;

/// The figures `casteljau figure` draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FigureKind {
    /// [`super::construction`]: the scheme (9) at `t`.
    Construction,
    /// [`super::subdivision`]: both halves at `t`.
    Subdivision,
    /// [`super::elevation`]: elevated polygons and their distances.
    Elevation,
    /// [`super::hodograph`]: `b′(t)` and the end tangents.
    Hodograph,
    /// [`super::hull`]: the hull, a point, its weights.
    Hull,
    /// [`super::conics`]: arcs for several middle weights.
    Conics,
    /// [`super::net`]: a tensor-product net with iso-curves.
    Net,
    /// [`super::enneper`]: Enneper's net (text 003 Ex. 5).
    Enneper,
    /// [`super::fit`]: text 004's cubic fit.
    Fit,
}

impl FigureKind {
    /// Every kind, in the order the help lists them.
    pub const ALL: [FigureKind; 9] = [
        FigureKind::Construction,
        FigureKind::Subdivision,
        FigureKind::Elevation,
        FigureKind::Hodograph,
        FigureKind::Hull,
        FigureKind::Conics,
        FigureKind::Net,
        FigureKind::Enneper,
        FigureKind::Fit,
    ];

    /// The command-line name.
    pub fn name(self) -> &'static str {
        match self {
            FigureKind::Construction => "construction",
            FigureKind::Subdivision => "subdivision",
            FigureKind::Elevation => "elevation",
            FigureKind::Hodograph => "hodograph",
            FigureKind::Hull => "hull",
            FigureKind::Conics => "conics",
            FigureKind::Net => "net",
            FigureKind::Enneper => "enneper",
            FigureKind::Fit => "fit",
        }
    }

    /// The options that apply to this kind.
    fn options(self) -> &'static [&'static str] {
        match self {
            FigureKind::Construction | FigureKind::Subdivision => &["--t"],
            FigureKind::Elevation => &["--steps"],
            FigureKind::Hodograph | FigureKind::Enneper => &[],
            FigureKind::Hull => &["--point"],
            FigureKind::Conics | FigureKind::Fit => &["--weights"],
            FigureKind::Net => &["--iso"],
        }
    }
}

impl FromStr for FigureKind {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        FigureKind::ALL.into_iter().find(|k| k.name() == s).ok_or_else(|| {
            Error::Parse(format!(
                "unknown figure '{s}' (one of: {})",
                FigureKind::ALL.map(|k| k.name()).join(", ")
            ))
        })
    }
}

/// Text 000's example 4), the curve most figures default to.
pub const DEFAULT_CURVE: &str = "0,0; 4/3,-4/3; 4/3,4/3; 0,0";
/// Text 001's polygon of Ex. 3 and Ex. 4.
pub const DEFAULT_CONIC_POLYGON: &str = "-1,1; 0,-1; 1,1";
/// Text 003's Ex. 2 net (a hyperbolic paraboloid).
pub const DEFAULT_NET: &str = "-1,-1,0; -1,0,2; -1,1,0 | 0,-1,-2; 0,0,0; 0,1,-2 | 1,-1,0; 1,0,2; 1,1,0";
/// The space curve (t, 1 + t², t⁴) as a quartic, our worked example of text 004.
pub const DEFAULT_FIT_CURVE: &str = "0,1,0; 1/4,1,0; 1/2,7/6,0; 3/4,3/2,0; 1,2,1";

/// One `casteljau figure` request: the kind, the input (control points or a net; the
/// texts' examples by default) and the options as typed.
#[derive(Clone, Debug)]
pub struct FigureRequest {
    /// What to draw.
    pub kind: FigureKind,
    /// Control points (`"0,0; 1,2; 3,0"`) or, for `net` and `enneper`, a net (rows by `|`).
    pub input: Option<String>,
    /// `--t`: the parameter (default 1/2).
    pub t: Option<String>,
    /// `--steps`: elevation steps, e.g. `"1, 2, 4, 8"` (default 1, 2, 4, 8, 16).
    pub steps: Option<String>,
    /// `--point`: the point of the hull figure (default b(1/3)).
    pub point: Option<String>,
    /// `--weights`: the middle weights of `conics` (default 1/2, 1, 2), all weights of a
    /// rational curve for `fit`.
    pub weights: Option<String>,
    /// `--iso`: iso-curves per direction of `net` (default 4).
    pub iso: Option<String>,
}

impl FigureRequest {
    /// A request with no input and no options (the defaults).
    pub fn new(kind: FigureKind) -> Self {
        FigureRequest {
            kind,
            input: None,
            t: None,
            steps: None,
            point: None,
            weights: None,
            iso: None,
        }
    }

    /// Computes the figure; bad input or an option that does not apply is a clear error.
    pub fn figure(&self) -> Result<Figure> {
        let given = [
            ("--t", self.t.is_some()),
            ("--steps", self.steps.is_some()),
            ("--point", self.point.is_some()),
            ("--weights", self.weights.is_some()),
            ("--iso", self.iso.is_some()),
        ];
        if let Some((flag, _)) = given
            .iter()
            .find(|(flag, set)| *set && !self.kind.options().contains(flag))
        {
            return Err(Error::Domain(format!(
                "{flag} does not apply to `figure {}`",
                self.kind.name()
            )));
        }
        let t = || -> Result<BigRational> {
            self.t
                .as_deref()
                .map(|t| parse_number(t).map_err(|e| ctx("--t", e)))
                .unwrap_or_else(|| Ok(BigRational::new(1.into(), 2.into())))
        };
        match self.kind {
            FigureKind::Construction => super::construction(&self.curve()?, &t()?),
            FigureKind::Subdivision => super::subdivision(&self.curve()?, &t()?),
            FigureKind::Elevation => {
                let steps = match &self.steps {
                    None => vec![1, 2, 4, 8, 16],
                    Some(s) => s
                        .split(',')
                        .map(|r| parse_count(r.trim(), "--steps"))
                        .collect::<Result<Vec<_>>>()?,
                };
                super::elevation(&self.curve()?, &steps)
            }
            FigureKind::Hodograph => super::hodograph(&self.curve()?),
            FigureKind::Hull => {
                let curve = self.curve()?;
                let p = match &self.point {
                    Some(p) => parse_point(p).map_err(|e| ctx("--point", e))?,
                    None => curve.eval(&BigRational::new(1.into(), 3.into())),
                };
                super::hull(&curve, &p)
            }
            FigureKind::Conics => {
                let points = parse_points(self.input.as_deref().unwrap_or(DEFAULT_CONIC_POLYGON))
                    .map_err(|e| ctx("control points", e))?;
                let middles =
                    parse_numbers(self.weights.as_deref().unwrap_or("1/2, 1, 2")).map_err(|e| ctx("--weights", e))?;
                let one = BigRational::new(1.into(), 1.into());
                super::conics(&points, &one, &one, &middles)
            }
            FigureKind::Net => {
                let iso = match &self.iso {
                    Some(k) => parse_count(k, "--iso")?,
                    None => 4,
                };
                super::net(&self.net(DEFAULT_NET)?, iso, "A tensor-product Bézier net")
            }
            FigureKind::Enneper => match &self.input {
                None => super::enneper(&super::text003_example5::<BigRational>()?),
                Some(_) => super::enneper(&self.net("")?),
            },
            FigureKind::Fit => {
                let points = parse_points(self.input.as_deref().unwrap_or(DEFAULT_FIT_CURVE))
                    .map_err(|e| ctx("control points", e))?;
                let curve = match &self.weights {
                    None => AnyCurve::Polynomial(BezierCurve::new(points)?),
                    Some(w) => {
                        let w = parse_numbers(w).map_err(|e| ctx("--weights", e))?;
                        if w.len() != points.len() {
                            return Err(Error::Domain(format!(
                                "--weights: {} weights for {} control points",
                                w.len(),
                                points.len()
                            )));
                        }
                        AnyCurve::Rational(RationalBezierCurve::new(points, w)?)
                    }
                };
                super::fit(&curve)
            }
        }
    }

    fn curve(&self) -> Result<BezierCurve<BigRational>> {
        let points =
            parse_points(self.input.as_deref().unwrap_or(DEFAULT_CURVE)).map_err(|e| ctx("control points", e))?;
        BezierCurve::new(points).map_err(|e| ctx("control points", e))
    }

    fn net(&self, default: &str) -> Result<BezierSurface<BigRational>> {
        let net = parse_net(self.input.as_deref().unwrap_or(default)).map_err(|e| ctx("control net", e))?;
        BezierSurface::new(net).map_err(|e| ctx("control net", e))
    }
}

fn ctx(what: &str, e: Error) -> Error {
    crate::input::in_context(what, e)
}
