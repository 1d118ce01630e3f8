//! `casteljau figure <what> [input] [options]`: which figure, from command-line text.

use super::{AnyCurve, Figure};
use crate::error::{Error, Result};
use crate::input::{parse_count, parse_net, parse_number, parse_numbers, parse_point, parse_points};
use crate::rational::RationalBezierCurve;
use crate::surface::BezierSurface;
use crate::work::{elevate_work, eval_work, split_work, to_bezier_work};
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
    /// [`super::bernstein_basis`]: `B_i^n` on `[0, 1]` and the values at `t`.
    Bernstein,
    /// [`super::conic_projection`]: text 001's parabola in space projected to `z = 1`.
    Projection,
}

impl FigureKind {
    /// Every kind, in the order the help lists them.
    pub const ALL: [FigureKind; 11] = [
        FigureKind::Construction,
        FigureKind::Subdivision,
        FigureKind::Elevation,
        FigureKind::Hodograph,
        FigureKind::Hull,
        FigureKind::Conics,
        FigureKind::Net,
        FigureKind::Enneper,
        FigureKind::Fit,
        FigureKind::Bernstein,
        FigureKind::Projection,
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
            FigureKind::Bernstein => "bernstein",
            FigureKind::Projection => "projection",
        }
    }

    /// The options that apply to this kind.
    fn options(self) -> &'static [&'static str] {
        match self {
            FigureKind::Construction | FigureKind::Subdivision => &["--t"],
            FigureKind::Elevation => &["--steps"],
            FigureKind::Hodograph | FigureKind::Enneper | FigureKind::Projection => &[],
            FigureKind::Bernstein => &["--t", "--degree"],
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
/// Text 001's parabola in space whose projection is the quarter circle (its Ex. 1 of (10)).
pub const DEFAULT_PARABOLA: &str = "1,0,1; 1,1,1; 0,2,2";
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
    /// `--degree`: the degree of the Bernstein basis (default 3).
    pub degree: Option<String>,
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
            degree: None,
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
            ("--degree", self.degree.is_some()),
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
            let t = self
                .t
                .as_deref()
                .map(|t| parse_number(t).map_err(|e| ctx("--t", e)))
                .unwrap_or_else(|| {
                    let third = self.kind == FigureKind::Bernstein;
                    Ok(BigRational::new(1.into(), if third { 3 } else { 2 }.into()))
                })?;
            check_bits("a number of --t in a figure", [&t])?;
            Ok(t)
        };
        match self.kind {
            FigureKind::Construction | FigureKind::Subdivision => {
                let (curve, t) = (self.curve()?, t()?);
                check_work(split_work(&curve, &t))?;
                if self.kind == FigureKind::Construction {
                    super::construction(&curve, &t)
                } else {
                    super::subdivision(&curve, &t)
                }
            }
            FigureKind::Elevation => {
                let steps = match &self.steps {
                    None => vec![1, 2, 4, 8, 16],
                    Some(s) => s
                        .split(',')
                        .map(|r| parse_count(r.trim(), "--steps"))
                        .collect::<Result<Vec<_>>>()?,
                };
                if steps.len() > MAX_FIGURE_STEPS {
                    return Err(Error::TooLarge {
                        what: "number of --steps in a figure",
                        value: steps.len().to_string(),
                        limit: MAX_FIGURE_STEPS.to_string(),
                    });
                }
                let curve = self.curve()?;
                if let Some(r) = steps.iter().find(|&&r| r > super::MAX_FIGURE_ELEVATION) {
                    return Err(Error::TooLarge {
                        what: "elevation steps in a figure",
                        value: r.to_string(),
                        limit: super::MAX_FIGURE_ELEVATION.to_string(),
                    });
                }
                check_work(steps.iter().map(|&r| elevation_work(&curve, r)).sum())?;
                super::elevation(&curve, &steps)
            }
            FigureKind::Hodograph => {
                let curve = self.curve()?;
                // the derivative, and b′ at 0 and 1: de Casteljau schemes at those parameters
                let zero = BigRational::from_integer(0.into());
                check_work(2.0 * split_work(&curve, &zero))?;
                super::hodograph(&curve)
            }
            FigureKind::Hull => {
                let curve = self.curve()?;
                let p = match &self.point {
                    Some(p) => {
                        let p = parse_point(p).map_err(|e| ctx("--point", e))?;
                        check_bits("a coordinate of --point in a figure", p.coords())?;
                        p
                    }
                    None => {
                        let third = BigRational::new(1.into(), 3.into());
                        check_work(hull_work(&curve) + eval_work(&curve, &third))?;
                        curve.eval_nested(&third)
                    }
                };
                check_work(hull_work(&curve))?;
                super::hull(&curve, &p)
            }
            FigureKind::Conics => {
                let points = parse_points(self.input.as_deref().unwrap_or(DEFAULT_CONIC_POLYGON))
                    .map_err(|e| ctx("control points", e))?;
                check_bits(
                    "a control point coordinate in a figure",
                    points.iter().flat_map(|p| p.coords()),
                )?;
                let middles =
                    parse_numbers(self.weights.as_deref().unwrap_or("1/2, 1, 2")).map_err(|e| ctx("--weights", e))?;
                if middles.len() > MAX_FIGURE_ARCS {
                    return Err(Error::TooLarge {
                        what: "number of middle weights (arcs) in a figure",
                        value: middles.len().to_string(),
                        limit: MAX_FIGURE_ARCS.to_string(),
                    });
                }
                check_bits("a number of --weights in a figure", &middles)?;
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
                Some(_) => {
                    let surface = self.net("")?;
                    check_work(enneper_work(&surface))?;
                    super::enneper(&surface)
                }
            },
            FigureKind::Bernstein => {
                if self.input.is_some() {
                    return Err(Error::Domain(
                        "`figure bernstein` takes no control points (use --degree and --t)".into(),
                    ));
                }
                let n = match &self.degree {
                    Some(d) => parse_count(d, "--degree")?,
                    None => 3,
                };
                super::check_figure_degree(n)?;
                let t = t()?;
                let bits = n as u64 * t.numer().bits().max(t.denom().bits());
                if bits > MAX_BERNSTEIN_BITS {
                    return Err(Error::TooLarge {
                        what: "Bernstein figure (degree × bits of --t)",
                        value: bits.to_string(),
                        limit: format!("{MAX_BERNSTEIN_BITS}; use a lower degree or a shorter t"),
                    });
                }
                super::bernstein_basis(n, &t)
            }
            FigureKind::Projection => {
                let points = parse_points(self.input.as_deref().unwrap_or(DEFAULT_PARABOLA))
                    .map_err(|e| ctx("control points", e))?;
                check_bits(
                    "a control point coordinate in a figure",
                    points.iter().flat_map(|p| p.coords()),
                )?;
                super::conic_projection(&BezierCurve::new(points).map_err(|e| ctx("control points", e))?)
            }
            FigureKind::Fit => {
                let points = parse_points(self.input.as_deref().unwrap_or(DEFAULT_FIT_CURVE))
                    .map_err(|e| ctx("control points", e))?;
                check_bits(
                    "a control point coordinate in a figure",
                    points.iter().flat_map(|p| p.coords()),
                )?;
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
                        check_bits("a number of --weights in a figure", &w)?;
                        AnyCurve::Rational(RationalBezierCurve::new(points, w)?)
                    }
                };
                super::check_figure_degree(curve.points().len() - 1)?;
                check_work(fit_work(&curve)?)?;
                super::fit(&curve)
            }
        }
    }

    fn curve(&self) -> Result<BezierCurve<BigRational>> {
        let points =
            parse_points(self.input.as_deref().unwrap_or(DEFAULT_CURVE)).map_err(|e| ctx("control points", e))?;
        check_bits(
            "a control point coordinate in a figure",
            points.iter().flat_map(|p| p.coords()),
        )?;
        let curve = BezierCurve::new(points).map_err(|e| ctx("control points", e))?;
        super::check_figure_degree(curve.degree())?;
        Ok(curve)
    }

    fn net(&self, default: &str) -> Result<BezierSurface<BigRational>> {
        let net = parse_net(self.input.as_deref().unwrap_or(default)).map_err(|e| ctx("control net", e))?;
        check_bits(
            "a control net coordinate in a figure",
            net.iter().flatten().flat_map(|p| p.coords()),
        )?;
        let surface = BezierSurface::new(net).map_err(|e| ctx("control net", e))?;
        let (m, n) = surface.degrees();
        super::check_figure_degree(m.max(n))?;
        Ok(surface)
    }
}

/// The most bits in the numerator or the denominator of any number a figure is given
/// (coordinates, `--t`, `--point`, `--weights`): about 301 decimal digits. A figure is drawn
/// in `f64`, whose range ends near 2^1024, and the exact values it prints grow from these.
pub const MAX_FIGURE_NUMBER_BITS: u64 = 1000;

/// The largest degree of the Bernstein figure times the bits in the numerator or denominator of
/// its `--t`: the printed values `B_i^n(t)` have up to that many bits.
pub const MAX_BERNSTEIN_BITS: u64 = 4096;

/// The most elevation steps (`--steps`) one figure draws.
pub const MAX_FIGURE_STEPS: usize = 16;

/// The most arcs (`--weights` of `conics`) one figure draws.
pub const MAX_FIGURE_ARCS: usize = 16;

/// The largest work estimate of a figure's exact computations, in the oracle's units (a
/// quarter of the largest request, `oracle::MAX_REQUEST_WORK`): a fraction of a second of CPU. Everything a figure only
/// draws is sampled in `f64` and costs nothing on this scale.
pub const MAX_FIGURE_WORK: f64 = crate::work::HALF_SECOND / 4.0;

fn check_bits<'a>(what: &'static str, numbers: impl IntoIterator<Item = &'a BigRational>) -> Result<()> {
    let most = numbers
        .into_iter()
        .map(|x| x.numer().bits().max(x.denom().bits()))
        .max()
        .unwrap_or(0);
    if most > MAX_FIGURE_NUMBER_BITS {
        return Err(Error::TooLarge {
            what,
            value: format!("{most} bits"),
            limit: format!("{MAX_FIGURE_NUMBER_BITS} bits in a numerator or denominator, about 301 decimal digits"),
        });
    }
    Ok(())
}

fn check_work(work: f64) -> Result<()> {
    if work.is_nan() || work > MAX_FIGURE_WORK {
        return Err(Error::TooLarge {
            what: "figure (estimated exact work)",
            value: format!("{work:.2e}"),
            limit: format!("{MAX_FIGURE_WORK:.1e}; use a lower degree, shorter numbers or fewer steps"),
        });
    }
    Ok(())
}

/// One elevated polygon and its distance to the curve: the elevation (the oracle's
/// `elevate`), then `b(i/N)`, `N = n + r`, at each of the `N + 1` points as a sum of `n + 1`
/// products of a coordinate with an integer `C(n,j) i^j (N − i)^(n−j)` of up to `n log2 N`
/// bits.
fn elevation_work(curve: &BezierCurve<BigRational>, r: usize) -> f64 {
    let (n, total) = (curve.degree(), curve.degree() + r);
    let elevate = elevate_work(curve, r);
    let weight_bits = n as f64 * (total.max(2) as f64).log2();
    let b = coordinate_bits(curve.points()) + weight_bits + 64.0;
    let products = ((total + 1) * (n + 1) * curve.dim()) as f64;
    elevate + 25.0 * products * b * b
}

/// The largest numerator plus denominator bits of the coordinates.
fn coordinate_bits(points: &[crate::point::Point<BigRational>]) -> f64 {
    points
        .iter()
        .flat_map(|p| p.coords())
        .map(|x| (x.numer().bits() + x.denom().bits()) as f64)
        .fold(0.0, f64::max)
}

/// Matching a net against Enneper's surface converts it to the power basis twice (as it is
/// and transposed): the oracle's `to_bezier` work, on every row and every column.
fn enneper_work(surface: &BezierSurface<BigRational>) -> f64 {
    let (m, n) = surface.degrees();
    // every row and column as long as the net's and with its largest number throughout
    let largest = surface
        .net()
        .iter()
        .flatten()
        .flat_map(|p| p.coords())
        .max_by_key(|x| x.numer().bits() + x.denom().bits())
        .cloned()
        .unwrap_or_default();
    let line = |len: usize| to_bezier_work(&vec![vec![largest.clone(); len]; surface.dim()]);
    2.0 * ((m + 1) as f64 * line(n + 1) + (n + 1) as f64 * line(m + 1))
}

/// The hull certificate tries every subset of up to `dim + 1` control points, solving a
/// small exact linear system for each.
fn hull_work(curve: &BezierCurve<BigRational>) -> f64 {
    let (m, k) = (curve.points().len() as f64, (curve.dim() + 1) as f64);
    let subsets: f64 = (1..=curve.dim() + 1)
        .map(|size| (0..size).fold(1.0, |c, i| c * (m - i as f64) / (i + 1) as f64))
        .sum();
    let bits = coordinate_bits(curve.points());
    let b = k * bits + 64.0;
    // measured: each subset's solve costs about twelve of these units per k³ b²
    12.0 * subsets * k * k * k * b * b
}

/// Text 004's fit reads x(0), x(1), x(1/2) and the end derivatives off the curve (schemes at
/// 0, 1/2 and 1; a rational curve's in homogeneous coordinates, one more), then solves a 2×2
/// system on those few numbers.
fn fit_work(curve: &AnyCurve<BigRational>) -> Result<f64> {
    let polygon = BezierCurve::new(curve.points().to_vec())?;
    let half = BigRational::new(1.into(), 2.into());
    let dim = curve.dim() as f64;
    Ok(match curve {
        AnyCurve::Polynomial(_) => 3.0 * split_work(&polygon, &half),
        AnyCurve::Rational(c) => {
            // the weights multiply into every coordinate: their bits add to the numbers'
            let weight_bits = c
                .weights()
                .iter()
                .map(|w| w.numer().bits() + w.denom().bits())
                .max()
                .unwrap_or(0);
            let factor = (1.0 + weight_bits as f64 / 64.0).powi(2);
            3.0 * split_work(&polygon, &half) * (dim + 1.0) / dim * factor
        }
    })
}

fn ctx(what: &str, e: Error) -> Error {
    crate::input::in_context(what, e)
}
