//! Interactive figures: `casteljau figure KIND --interactive` and the report's
//! `interactive/` pages. Each is one self-contained HTML file (inline CSS, SVG and the script
//! `interactive.js`; nothing from the network, no build step) in which a reader drags control
//! points and slides `t` (and `r`, `w`, `n`) through the de Casteljau construction,
//! subdivision, degree elevation, the hodograph, a rational conic arc and the Bernstein basis.
//!
//! Values stay exact: points snap to a grid of `1/grid`, `t` moves over the rationals with
//! denominators at most [`T_DENOMINATORS`], and the page computes with BigInt fractions. The
//! page is written with the values at its starting state computed here by the engine (so it
//! reads right without the script, and `tests/interactive.rs` checks them against the
//! oracle); the script recomputes them on load and says on the page whether the two agree.
//! Every value sits in an element with a stable id and a `data-exact` attribute holding the
//! oracle's JSON for it (`scripts/browser_test.sh` compares the two byte for byte).

use crate::error::{Error, Result};
use crate::figure::svg::esc;
use crate::figure::{FigureKind, FigureRequest, DEFAULT_CONIC_POLYGON, DEFAULT_CURVE};
use crate::input::{parse_count, parse_number, parse_points};
use crate::point::Point;
use crate::rational::RationalBezierCurve;
use crate::{classify_conic, implicit_conic, BezierCurve, BigRational, ConicKind};
use num_integer::Integer;
use num_traits::{One, Zero};
use std::fmt::Write as _;
use std::path::Path;

type Q = BigRational;

/// The figures that have an interactive version, in the order the report lists them.
pub const INTERACTIVE_KINDS: [FigureKind; 6] = [
    FigureKind::Construction,
    FigureKind::Subdivision,
    FigureKind::Elevation,
    FigureKind::Hodograph,
    FigureKind::Conics,
    FigureKind::Bernstein,
];

/// At most this many control points (degree 9): the page recomputes every value on each
/// pointer move, and a scheme of more levels is no longer readable.
pub const MAX_INTERACTIVE_POINTS: usize = 10;
/// Starting coordinates, `t` and `w` have numerators and denominators of at most this many bits.
pub const MAX_INTERACTIVE_BITS: u64 = 64;
/// The elevation slider's range is `r = 1..=MAX_INTERACTIVE_ELEVATION`.
pub const MAX_INTERACTIVE_ELEVATION: usize = 16;
/// The Bernstein basis slider's range is `n = 1..=MAX_INTERACTIVE_DEGREE`.
pub const MAX_INTERACTIVE_DEGREE: usize = 10;
/// `t` moves over the fractions `p/q` in `[0, 1]` with `q` at most this (the Farey sequence).
pub const T_DENOMINATORS: i64 = 12;
/// The middle weights the conic's slider offers (`w_0 = w_2 = 1`).
pub const WEIGHTS: [&str; 23] = [
    "1/8", "1/6", "1/5", "1/4", "1/3", "2/5", "1/2", "3/5", "2/3", "3/4", "4/5", "1", "5/4", "4/3", "3/2", "5/3", "2",
    "5/2", "3", "4", "5", "6", "8",
];

/// The file an interactive figure is written to in the report's `interactive/` folder.
pub fn interactive_file(kind: FigureKind) -> String {
    format!("{}.html", kind.name())
}

/// The paragraph linking a report page's illustration to its interactive version, if it has
/// one (hidden in print).
pub fn link(kind: FigureKind) -> Option<String> {
    if !INTERACTIVE_KINDS.contains(&kind) {
        return None;
    }
    Some(format!(
        "<p class=\"interactive\"><a href=\"interactive/{}\">Interactive version</a> (drag the points, slide t; \
         exact values)</p>\n",
        interactive_file(kind)
    ))
}

/// Writes the interactive pages into `dir/interactive/`: pages with a script, kept apart
/// from the report's static, printable pages that link to them.
pub fn write_pages(dir: &Path) -> Result<()> {
    let folder = dir.join("interactive");
    std::fs::create_dir_all(&folder).map_err(|e| Error::Domain(format!("cannot create {}: {e}", folder.display())))?;
    for (name, html) in interactive_pages()? {
        let path = folder.join(name);
        std::fs::write(&path, html).map_err(|e| Error::Domain(format!("cannot write {}: {e}", path.display())))?;
    }
    Ok(())
}

/// The report's interactive pages, `(file name, HTML)`, each at the texts' example.
pub fn interactive_pages() -> Result<Vec<(String, String)>> {
    INTERACTIVE_KINDS
        .iter()
        .map(|&k| Ok((interactive_file(k), interactive_page(&FigureRequest::new(k))?)))
        .collect()
}

/// The starting state of a page.
struct State {
    kind: FigureKind,
    points: Vec<Point<Q>>,
    t: Option<Q>,
    r: usize,
    w: Q,
    n: usize,
    grid: i64,
}

fn q(s: &str) -> Q {
    parse_number(s).expect("a constant fraction")
}

fn domain(msg: String) -> Error {
    Error::Domain(msg)
}

fn check_bits(what: &str, x: &Q) -> Result<()> {
    if x.numer().bits() > MAX_INTERACTIVE_BITS || x.denom().bits() > MAX_INTERACTIVE_BITS {
        return Err(Error::TooLarge {
            what: "a number in an interactive figure",
            value: format!("{what} = {x}"),
            limit: format!("{MAX_INTERACTIVE_BITS} bits in a numerator or denominator"),
        });
    }
    Ok(())
}

impl State {
    fn from_request(req: &FigureRequest) -> Result<State> {
        let kind = req.kind;
        let name = kind.name();
        if !INTERACTIVE_KINDS.contains(&kind) {
            return Err(domain(format!(
                "`figure {name}` has no interactive version (interactive: {})",
                INTERACTIVE_KINDS.map(|k| k.name()).join(", ")
            )));
        }
        let allowed: &[&str] = match kind {
            FigureKind::Elevation => &["--steps"],
            FigureKind::Conics => &["--t", "--weights"],
            FigureKind::Bernstein => &["--t", "--degree"],
            _ => &["--t"],
        };
        for (flag, given) in [
            ("--t", req.t.is_some()),
            ("--steps", req.steps.is_some()),
            ("--point", req.point.is_some()),
            ("--weights", req.weights.is_some()),
            ("--iso", req.iso.is_some()),
            ("--degree", req.degree.is_some()),
        ] {
            if given && !allowed.contains(&flag) {
                return Err(domain(format!(
                    "{flag} does not apply to `figure {name} --interactive`"
                )));
            }
        }
        let points = match (kind, &req.input) {
            (FigureKind::Bernstein, Some(_)) => {
                return Err(domain("`figure bernstein` takes no control points".into()));
            }
            (FigureKind::Bernstein, None) => Vec::new(),
            (FigureKind::Conics, input) => parse_points(input.as_deref().unwrap_or(DEFAULT_CONIC_POLYGON))?,
            (_, input) => parse_points(input.as_deref().unwrap_or(DEFAULT_CURVE))?,
        };
        if kind != FigureKind::Bernstein {
            if kind == FigureKind::Conics && points.len() != 3 {
                return Err(domain(format!(
                    "a conic arc has three control points, not {}",
                    points.len()
                )));
            }
            if !(2..=MAX_INTERACTIVE_POINTS).contains(&points.len()) {
                return Err(domain(format!(
                    "an interactive figure takes 2 to {MAX_INTERACTIVE_POINTS} control points, not {}",
                    points.len()
                )));
            }
            if let Some(p) = points.iter().find(|p| p.dim() != 2) {
                return Err(domain(format!(
                    "interactive figures are planar: a point has {} coordinates, not 2",
                    p.dim()
                )));
            }
            for x in points.iter().flat_map(|p| p.coords()) {
                check_bits("a coordinate", x)?;
            }
        }
        let t = match kind {
            FigureKind::Elevation => None,
            _ => {
                let default = if kind == FigureKind::Bernstein { "1/3" } else { "1/2" };
                let t = parse_number(req.t.as_deref().unwrap_or(default))?;
                check_bits("--t", &t)?;
                if t < Q::zero() || t > Q::one() {
                    return Err(domain(format!("--t = {t} is outside [0, 1], where the slider moves")));
                }
                Some(t)
            }
        };
        let in_range = |text: &Option<String>, what: &str, default: usize, max: usize| -> Result<usize> {
            let v = match text {
                Some(s) => parse_count(s.trim(), what)?,
                None => default,
            };
            if !(1..=max).contains(&v) {
                return Err(domain(format!("{what} = {v} is outside 1..={max}, the slider's range")));
            }
            Ok(v)
        };
        let r = in_range(&req.steps, "--steps", 1, MAX_INTERACTIVE_ELEVATION)?;
        let n = in_range(&req.degree, "--degree", 3, MAX_INTERACTIVE_DEGREE)?;
        let w = parse_number(req.weights.as_deref().unwrap_or("1/2"))?;
        check_bits("--weights", &w)?;
        if w <= Q::zero() {
            return Err(domain(format!("the middle weight {w} must be positive")));
        }
        // the finest grid on which the starting points lie, if it is a fine enough to drag on
        let grid = points
            .iter()
            .flat_map(|p| p.coords())
            .fold(num_bigint::BigInt::from(6), |g, x| g.lcm(x.denom()));
        let grid = i64::try_from(&grid).ok().filter(|g| *g <= 24).unwrap_or(6);
        Ok(State {
            kind,
            points,
            t,
            r,
            w,
            n,
            grid,
        })
    }

    /// The starting state as the JSON the script reads.
    /// The values `t` moves over: the Farey fractions and the starting `t` (none for elevation).
    fn ts(&self) -> Vec<Q> {
        match &self.t {
            None => Vec::new(),
            Some(t) => with(farey(), t),
        }
    }

    /// The values the middle weight moves over.
    fn ws(&self) -> Vec<Q> {
        with(WEIGHTS.iter().map(|w| q(w)).collect(), &self.w)
    }

    fn json(&self) -> String {
        let (ts, ws) = (self.ts(), self.ws());
        format!(
            "{{\"kind\":\"{}\",\"points\":[{}],\"t\":\"{}\",\"ts\":{},\"r\":{},\"w\":\"{}\",\"ws\":{},\"n\":{},\"grid\":{}}}",
            self.kind.name(),
            self.points.iter().map(point_json).collect::<Vec<_>>().join(","),
            self.t.as_ref().map(|t| t.to_string()).unwrap_or_default(),
            strings_json(&ts),
            self.r,
            self.w,
            strings_json(&ws),
            self.n,
            self.grid
        )
    }
}

/// `values` with `x` in order, added if missing.
fn with(mut values: Vec<Q>, x: &Q) -> Vec<Q> {
    if !values.contains(x) {
        values.push(x.clone());
        values.sort();
    }
    values
}

/// The fractions `p/q` in `[0, 1]` with `q ≤ T_DENOMINATORS`, in increasing order.
fn farey() -> Vec<Q> {
    let mut v: Vec<Q> = (1..=T_DENOMINATORS)
        .flat_map(|d| (0..=d).map(move |p| Q::new(p.into(), d.into())))
        .collect();
    v.sort();
    v.dedup();
    v
}

/// A JSON array of the values as strings (`["1/2","3"]`): how the page reads exact numbers.
fn strings_json<T: std::fmt::Display>(values: &[T]) -> String {
    format!(
        "[{}]",
        values.iter().map(|x| format!("\"{x}\"")).collect::<Vec<_>>().join(",")
    )
}

fn point_json(p: &Point<Q>) -> String {
    strings_json(p.coords())
}

fn list_json(ps: &[Point<Q>]) -> String {
    format!("[{}]", ps.iter().map(point_json).collect::<Vec<_>>().join(","))
}

fn point_text(p: &Point<Q>) -> String {
    format!(
        "({})",
        p.coords().iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", ")
    )
}

fn list_text(ps: &[Point<Q>]) -> String {
    ps.iter().map(point_text).collect::<Vec<_>>().join("; ")
}

fn digits(k: usize, set: &[char; 10]) -> String {
    k.to_string().bytes().map(|b| set[(b - b'0') as usize]).collect()
}
const SUB: [char; 10] = ['₀', '₁', '₂', '₃', '₄', '₅', '₆', '₇', '₈', '₉'];
const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];

/// `A x² + B xy + … = 0` with zero terms left out (the script writes the same).
fn equation(k: &[String]) -> String {
    let terms = ["x²", "xy", "y²", "x", "y", ""];
    let mut s = String::new();
    for (c, term) in k.iter().zip(terms) {
        if c == "0" {
            continue;
        }
        let (neg, a) = match c.strip_prefix('-') {
            Some(a) => (true, a),
            None => (false, c.as_str()),
        };
        let coef = if a == "1" && !term.is_empty() { "" } else { a };
        let sign = match (s.is_empty(), neg) {
            (true, true) => "−",
            (true, false) => "",
            (false, true) => " − ",
            (false, false) => " + ",
        };
        let _ = write!(s, "{sign}{coef}{term}");
    }
    if s.is_empty() {
        s.push('0');
    }
    s + " = 0"
}

/// The values the page shows at its start, computed by the engine: `(id, data-exact, text)`,
/// in the order the script lists them.
fn values(s: &State) -> Result<Vec<(String, String, String)>> {
    let mut out = Vec::new();
    if let Some(t) = &s.t {
        out.push(("t-value".into(), format!("\"{t}\""), t.to_string()));
    }
    for (i, p) in s.points.iter().enumerate() {
        out.push((
            format!("p-{i}"),
            point_json(p),
            format!("b{} = {}", digits(i, &SUB), point_text(p)),
        ));
    }
    let curve = || BezierCurve::new(s.points.clone());
    let t = s.t.clone().unwrap_or_else(Q::zero);
    match s.kind {
        FigureKind::Construction => {
            // b_i^r(t) is the point at t of the curve of b_i, …, b_{i+r}
            for r in 0..s.points.len() {
                for i in 0..s.points.len() - r {
                    let p = BezierCurve::new(s.points[i..=i + r].to_vec())?.eval(&t);
                    out.push((
                        format!("b-{r}-{i}"),
                        point_json(&p),
                        format!("b{}{}(t) = {}", digits(i, &SUB), digits(r, &SUP), point_text(&p)),
                    ));
                }
            }
        }
        FigureKind::Subdivision => {
            let (left, right) = curve()?.split_at(&t);
            out.push(("left".into(), list_json(left.points()), list_text(left.points())));
            out.push(("right".into(), list_json(right.points()), list_text(right.points())));
        }
        FigureKind::Elevation => {
            let e = curve()?.elevate_by(s.r)?;
            out.push(("r-value".into(), format!("\"{}\"", s.r), s.r.to_string()));
            out.push(("elevated".into(), list_json(e.points()), list_text(e.points())));
        }
        FigureKind::Hodograph => {
            let c = curve()?;
            let b = c.eval(&t);
            let h = c.derivative(1)?;
            let v = c.derivative_at(1, &t)?;
            out.push(("point".into(), point_json(&b), point_text(&b)));
            out.push(("hodograph".into(), list_json(h.points()), list_text(h.points())));
            out.push(("vector".into(), point_json(&v), point_text(&v)));
        }
        FigureKind::Conics => {
            let arc = RationalBezierCurve::new(s.points.clone(), vec![Q::one(), s.w.clone(), Q::one()])?;
            let x = arc.eval(&t)?;
            let kind = classify_conic(&arc)?;
            let (implicit, text) = if kind == ConicKind::DegenerateCollinear {
                ("null".to_string(), "none (collinear control points)".to_string())
            } else {
                let k: Vec<String> = implicit_conic(&arc)?
                    .to_primitive_integers()
                    .iter()
                    .map(|c| c.to_string())
                    .collect();
                (strings_json(&k), equation(&k))
            };
            out.push(("w-value".into(), format!("\"{}\"", s.w), s.w.to_string()));
            out.push(("point".into(), point_json(&x), point_text(&x)));
            out.push(("type".into(), format!("\"{}\"", kind.as_str()), kind.as_str().into()));
            out.push(("implicit".into(), implicit, text));
        }
        FigureKind::Bernstein => {
            // the basis at t is the point at t of the curve whose control points are the unit
            // vectors e_0, …, e_n
            let unit = (0..=s.n)
                .map(|i| Point::new((0..=s.n).map(|j| if i == j { Q::one() } else { Q::zero() }).collect()))
                .collect::<Result<Vec<_>>>()?;
            let b = BezierCurve::new(unit)?.eval(&t);
            let strings: Vec<String> = b.coords().iter().map(|x| x.to_string()).collect();
            let text: Vec<String> = strings
                .iter()
                .enumerate()
                .map(|(i, v)| format!("B{}{} = {v}", digits(i, &SUB), digits(s.n, &SUP)))
                .collect();
            out.push(("n-value".into(), format!("\"{}\"", s.n), s.n.to_string()));
            out.push(("basis".into(), strings_json(&strings), text.join(", ")));
        }
        _ => unreachable!("checked in State::from_request"),
    }
    Ok(out)
}

/// What each page is about (HTML), and what its colours mean.
fn intro(kind: FigureKind) -> (&'static str, &'static str, &'static str) {
    match kind {
        FigureKind::Construction => (
            "De Casteljau's construction",
            "Drag the control points b<sub>0</sub>, …, b<sub>n</sub> and slide t. Each level is \
             b<sub>i</sub><sup>r</sup>(t) = (1 − t) b<sub>i</sub><sup>r−1</sup>(t) + t b<sub>i+1</sub><sup>r−1</sup>(t); \
             the last, b<sub>0</sub><sup>n</sup>(t), is the curve's point b(t).",
            "grey: the control polygon; blue, green, purple, brown: the levels r = 1, 2, 3, …; red: b(t).",
        ),
        FigureKind::Subdivision => (
            "Subdivision at t",
            "The first points b<sub>0</sub><sup>r</sup>(t) of the levels are the control points of the curve on \
             [0, t], the last points b<sub>n−r</sub><sup>r</sup>(t) those of the curve on [t, 1]. Drag the points, slide t.",
            "blue: the left half's polygon; orange: the right half's; red: b(t), where they meet.",
        ),
        FigureKind::Elevation => (
            "Degree elevation",
            "The same curve written with degree n + r: b<sub>i</sub><sup>(1)</sup> = i/(n+1) b<sub>i−1</sub> + \
             (1 − i/(n+1)) b<sub>i</sub>, repeated r times. Step r = 1, …, 16: the polygons approach the curve.",
            "grey: the control polygon; blue: the elevated polygon.",
        ),
        FigureKind::Hodograph => (
            "The hodograph",
            "The derivative b′(t) is the Bézier curve of degree n − 1 with control points n (b<sub>i+1</sub> − b<sub>i</sub>) \
             (the second panel, around the origin). Drawn at b(t), b′(t)/n is the last segment of the construction.",
            "left: the curve, red: b(t) and b′(t)/n; right: the hodograph's polygon and curve, red: b′(t).",
        ),
        FigureKind::Conics => (
            "A rational conic arc",
            "Weights 1, w, 1: the arc lies on an ellipse when w &lt; 1, a parabola when w = 1, a hyperbola when \
             w &gt; 1. The point is x(t) = (b<sub>0</sub>B<sub>0</sub> + w b<sub>1</sub>B<sub>1</sub> + b<sub>2</sub>B<sub>2</sub>) / \
             (B<sub>0</sub> + w B<sub>1</sub> + B<sub>2</sub>), the equation that of the whole conic.",
            "black: the arc for 0 ≤ t ≤ 1; dashed: the rest of the conic (the arc with weight −w); red: x(t).",
        ),
        FigureKind::Bernstein => (
            "The Bernstein basis",
            "B<sub>i</sub><sup>n</sup>(t) = C(n, i) t<sup>i</sup> (1 − t)<sup>n−i</sup> on [0, 1]. Slide t (or drag the \
             handle on the axis) and step the degree n: the values at t are positive and add up to 1.",
            "each curve is one B<sub>i</sub><sup>n</sup>; red: the values at t.",
        ),
        _ => ("", "", ""),
    }
}

const STYLE: &str = "
body { font-family: system-ui, sans-serif; margin: 0 auto; max-width: 1200px; padding: 0.8rem; color: #1b1b1b; }
.layout { display: grid; grid-template-columns: minmax(0, 1fr); gap: 0.8rem 1.5rem; }
@media (min-width: 900px) { .layout { grid-template-columns: minmax(0, 3fr) minmax(0, 2fr); } }
.legend { font-size: 0.9rem; color: #444; margin: 0.3rem 0; }
.label { font-size: 18px; fill: #1b1b1b; paint-order: stroke; stroke: #fff; stroke-width: 3px; }
output.now { min-width: 3.2em; font-variant-numeric: tabular-nums; }
h1 { font-size: 1.35rem; margin: 0.2rem 0 0.4rem; }
p { line-height: 1.4; }
svg { display: block; width: 100%; height: auto; max-height: 75vh; border: 1px solid #ccc; touch-action: none; background: #fff; }
#hodo { max-width: 320px; }
.panels { display: grid; grid-template-columns: minmax(0, 1fr); gap: 0.5rem; align-items: start; }
@media (min-width: 600px) { .panels.two { grid-template-columns: minmax(0, 3fr) minmax(0, 2fr); } #hodo { max-width: none; } }
.controls { display: flex; flex-wrap: wrap; gap: 0.4rem 1.2rem; margin: 0.6rem 0; }
.controls label { display: flex; align-items: center; gap: 0.4rem; }
input[type=range] { width: 12rem; max-width: 60vw; }
dl { display: grid; grid-template-columns: max-content minmax(0, 1fr); gap: 0.2rem 0.8rem; font-variant-numeric: tabular-nums; }
dt { font-weight: 600; }
dd { margin: 0; overflow-wrap: anywhere; }
#engine-check { font-size: 0.9rem; color: #2e6b2e; }
#engine-check[data-agree=false] { color: #b00020; font-weight: 600; }
.polygon { fill: none; stroke: #888; stroke-width: 1.2; }
.curve { fill: none; stroke: #1b1b1b; stroke-width: 2.2; }
.rest { fill: none; stroke: #999; stroke-width: 1.2; stroke-dasharray: 5 4; }
.level, .elevated, .left, .right, .tangent, .basis { fill: none; stroke-width: 1.6; }
.level0 { stroke: #1f77b4; } .level1 { stroke: #2ca02c; } .level2 { stroke: #9467bd; } .level3 { stroke: #8c564b; }
.basis { stroke-width: 2; }
.elevated { stroke: #1f77b4; } .left { stroke: #1f77b4; stroke-width: 2.4; } .right { stroke: #ff7f0e; stroke-width: 2.4; }
.tangent { stroke: #d62728; stroke-width: 2; }
.axes { fill: none; stroke: #444; }
.inner { fill: #555; } .at { fill: #d62728; }
.handle { fill: #1f77b4; fill-opacity: 0.35; stroke: #1f77b4; stroke-width: 2; cursor: grab; }
";

/// A slider; `now` is the value it stands at, shown beside it.
fn range(id: &str, label: &str, max: usize, value: usize, now: &str) -> String {
    format!(
        "<label>{label} <input type=\"range\" id=\"{id}\" min=\"{}\" max=\"{max}\" step=\"1\" value=\"{value}\"> \
         <output class=\"now\" data-of=\"{}\">{now}</output></label>\n",
        if id == "t-slider" || id == "w-slider" { 0 } else { 1 },
        &id[..1]
    )
}

/// The page of an interactive figure (see the module's documentation); bad input or an
/// option that does not apply is a clear error.
pub fn interactive_page(req: &FigureRequest) -> Result<String> {
    let state = State::from_request(req)?;
    let values = values(&state)?;
    let (title, what, legend) = intro(state.kind);
    let grid = match state.kind {
        FigureKind::Bernstein => String::new(),
        _ => format!(": points snap to a grid of 1/{}", state.grid),
    };
    let moves = match (&state.t, state.kind) {
        (None, _) => String::new(),
        (Some(_), FigureKind::Bernstein) => {
            format!(": t moves over the fractions with denominators up to {T_DENOMINATORS}")
        }
        (Some(_), _) => format!(", t over the fractions with denominators up to {T_DENOMINATORS}"),
    };
    let mut s = String::new();
    let _ = write!(
        s,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{title} — casteljau (interactive)</title>\n<style>{STYLE}</style>\n</head>\n<body>\n\
         <h1>{title}</h1>\n<p>{what} Every value shown is an exact fraction{grid}{moves}.</p>\n<div class=\"layout\">\n<div class=\"figure\">\n"
    );
    s.push_str("<div class=\"controls\">\n");
    if let Some(t) = &state.t {
        let ts = state.ts();
        let index = ts.iter().position(|x| x == t).unwrap_or(0);
        s.push_str(&range("t-slider", "t", ts.len() - 1, index, &t.to_string()));
    }
    match state.kind {
        FigureKind::Elevation => s.push_str(&range(
            "r-slider",
            "r",
            MAX_INTERACTIVE_ELEVATION,
            state.r,
            &state.r.to_string(),
        )),
        FigureKind::Bernstein => s.push_str(&range(
            "n-slider",
            "n",
            MAX_INTERACTIVE_DEGREE,
            state.n,
            &state.n.to_string(),
        )),
        FigureKind::Conics => {
            let ws = state.ws();
            let index = ws.iter().position(|x| *x == state.w).unwrap_or(0);
            s.push_str(&range("w-slider", "w", ws.len() - 1, index, &state.w.to_string()));
        }
        _ => {}
    }
    let two = state.kind == FigureKind::Hodograph;
    let _ = writeln!(
        s,
        "</div>\n<div class=\"panels{}\">\n<svg id=\"canvas\" viewBox=\"0 0 600 400\" role=\"img\" aria-label=\"the figure\"></svg>",
        if two { " two" } else { "" }
    );
    if two {
        s.push_str("<svg id=\"hodo\" viewBox=\"0 0 300 300\" role=\"img\" aria-label=\"the hodograph\"></svg>\n");
    }
    s.push_str("</div>\n");
    let _ = writeln!(s, "<p class=\"legend\">{legend}</p>\n</div>\n<div class=\"values\">");
    s.push_str("<p id=\"engine-check\">(The page's script did not run: the values below are the engine's, at the start.)</p>\n<dl id=\"values\">\n");
    for (id, exact, text) in &values {
        let label = match id.as_str() {
            "t-value" => "t".to_string(),
            "r-value" => "r".into(),
            "w-value" => "w₁".into(),
            "n-value" => "n".into(),
            "left" => "left half".into(),
            "right" => "right half".into(),
            "elevated" => "elevated polygon".into(),
            "hodograph" => "hodograph n Δbᵢ".into(),
            "vector" => "b′(t)".into(),
            "point" if state.kind == FigureKind::Conics => "x(t)".into(),
            "point" => "b(t)".into(),
            "basis" => "Bᵢⁿ(t)".into(),
            "type" => "conic".into(),
            "implicit" => "equation".into(),
            other if other.starts_with("p-") => "control point".into(),
            other => format!("level {}", other.split('-').nth(1).unwrap_or("")),
        };
        let _ = writeln!(
            s,
            "<dt>{}</dt><dd id=\"{id}\" data-exact=\"{}\">{}</dd>",
            esc(&label),
            esc(exact),
            esc(text)
        );
    }
    let _ = write!(
        s,
        "</dl>\n</div>\n</div>\n<script type=\"application/json\" id=\"state\">{}</script>\n<script>\n{}</script>\n</body>\n</html>\n",
        state.json(),
        include_str!("interactive.js")
    );
    Ok(s)
}
