//! A tensor-product control net with iso-curves and boundary curves (text 003).

use super::svg::{Figure, Panel, Style, CURVE, POINT, POLYGON};
use super::{planar, planar_curve, projection};
use crate::error::{Error, Result};
use crate::point::Point;
use crate::scalar::Scalar;
use crate::surface::BezierSurface;

/// The largest number of iso-curves per direction a net figure draws.
pub const MAX_ISO: usize = 64;

/// The net `b_{i,j}` (rows `i` and columns `j` joined), `iso` iso-curves `x(u_k, v)` and
/// `x(u, v_k)` at `u_k, v_k = k/(iso+1)` ([`BezierSurface::iso_u`], [`BezierSurface::iso_v`]),
/// the four boundary curves ([`BezierSurface::boundary`]) and the corners. Space nets are
/// drawn in the fixed [`projection`], with a small axis tripod.
pub fn net<T: Scalar>(surface: &BezierSurface<T>, iso: usize, title: &str) -> Result<Figure> {
    draw_net(surface, iso, title, false)
}

/// Iso-curve colours from far to near: in space, depth is `x` (towards the reader).
const DEPTH_SHADES: [&str; 4] = ["#c9daf0", "#9dbbe3", "#6b93cc", "#2f5ea8"];

/// [`net`]; `shaded`: a space net's iso-curves shaded by depth (darker is nearer), the
/// control net drawn light and only its corners named, for a surface that folds over itself.
pub(crate) fn draw_net<T: Scalar>(surface: &BezierSurface<T>, iso: usize, title: &str, shaded: bool) -> Result<Figure> {
    let shaded = shaded && surface.dim() == 3;
    if iso > MAX_ISO {
        return Err(Error::TooLarge {
            what: "iso-curves per direction",
            value: iso.to_string(),
            limit: MAX_ISO.to_string(),
        });
    }
    super::check_figure_degree(surface.degrees().0.max(surface.degrees().1))?;
    let (m, n) = surface.degrees();
    let mut fig = Figure::new(format!("{title} (degree ({m}, {n}))"));
    let mut panel = Panel::new(if surface.dim() == 3 {
        super::PROJECTION_HEADING
    } else {
        ""
    });
    let net = surface.net();
    let drawn: Vec<Vec<Point<T>>> = net
        .iter()
        .map(|row| row.iter().map(planar).collect::<Result<Vec<_>>>())
        .collect::<Result<_>>()?;
    let net_style = if shaded {
        Style::dashed("#b0b0b0", 0.8)
    } else {
        Style::line(POLYGON, 1.0)
    };
    for row in &drawn {
        panel.polyline(row, false, net_style, "net", None)?;
    }
    for j in 0..=n {
        let column: Vec<Point<T>> = drawn.iter().map(|row| row[j].clone()).collect();
        panel.polyline(&column, false, net_style, "net", None)?;
    }
    // the depth of every control point, as a second drawn net (x, 0) reduced alongside
    let depth: Vec<Vec<[f64; 2]>> = net
        .iter()
        .map(|row| row.iter().map(|p| [p.coords()[0].to_f64(), 0.0]).collect())
        .collect();
    let (near, far) = depth
        .iter()
        .flatten()
        .fold((f64::MIN, f64::MAX), |(a, b), d| (a.max(d[0]), b.min(d[0])));
    // iso-curves only place pixels: reduced in f64 from the drawn net (see `sample`)
    let drawn_f64: Vec<Vec<[f64; 2]>> = drawn
        .iter()
        .map(|row| row.iter().map(super::svg::xy).collect::<Result<Vec<_>>>())
        .collect::<Result<_>>()?;
    for k in 1..=iso {
        let s = T::from_ratio(k as i64, iso as i64 + 1)?;
        let at = k as f64 / (iso + 1) as f64;
        for (along_rows, title) in [
            (false, format!("iso-curve u = {s}: x({s}, v)")),
            (true, format!("iso-curve v = {s}: x(u, {s})")),
        ] {
            let control = super::sample::iso(&drawn_f64, at, along_rows);
            if !shaded {
                panel.curve_f64(control, Style::line("#7fa7d9", 1.1), "iso", Some(title));
                continue;
            }
            let pts = super::sample::polynomial(&control, 96);
            let depths = super::sample::polynomial(&super::sample::iso(&depth, at, along_rows), 96);
            let shade = |d: f64| {
                let k = ((d - far) / (near - far).max(f64::MIN_POSITIVE) * 4.0).floor();
                k.clamp(0.0, 3.0) as usize
            };
            // runs of one shade, each drawn with the next run's first point so they join
            let mut start = 0;
            for i in 1..=pts.len() {
                let level = shade(depths[start][0]);
                if i == pts.len() || shade(depths[i][0]) != level {
                    let end = i.min(pts.len() - 1);
                    let style = Style::line(DEPTH_SHADES[level], 0.9 + 0.5 * level as f64);
                    panel.polyline_f64(pts[start..=end].to_vec(), style, "iso", Some(title.clone()));
                    start = i;
                }
            }
        }
    }
    let names = ["x(u, 0)", "x(1, v)", "x(u, 1)", "x(0, v)"];
    for (b, name) in surface.boundary().iter().zip(names) {
        panel.curve(
            &planar_curve(b)?,
            Style::line(CURVE, 2.4),
            "curve",
            Some(format!("boundary {name}: control points {}", super::list(b.points()))),
        )?;
    }
    for (i, row) in net.iter().enumerate() {
        for (j, p) in row.iter().enumerate() {
            let corner = (i == 0 || i == m) && (j == 0 || j == n);
            let name = format!("b{}{}", sub(i), sub(j));
            panel.dot(
                &drawn[i][j],
                if corner { 4.0 } else { 2.8 },
                if corner { POINT } else { POLYGON },
                format!("b_{{{i},{j}}} = {p}"),
            )?;
            if (m + n <= 6 && !shaded) || corner {
                panel.label(&drawn[i][j], name, "#222222", 6.0, -6.0)?;
            }
        }
    }
    fig.add_panel(panel);
    if surface.dim() == 3 {
        fig.add_panel(tripod::<T>()?);
    }
    fig.note(
        Some(CURVE),
        "boundary curves: the Bézier curves of the net's boundary rows and columns (property c)",
    );
    if shaded {
        fig.note(
            Some(DEPTH_SHADES[2]),
            format!(
                "iso-curves at u, v = k/{} for k = 1..{iso}, shaded by depth: darker and wider is nearer (larger x)",
                iso + 1
            ),
        );
    } else {
        fig.note(
            Some("#7fa7d9"),
            format!("iso-curves at u, v = k/{} for k = 1..{iso}", iso + 1),
        );
    }
    let corners = surface.corners();
    fig.note(
        Some(POINT),
        format!("corners x(0,0), x(1,0), x(0,1), x(1,1): {}", super::list(&corners)),
    );
    Ok(fig)
}

fn sub(k: usize) -> String {
    super::svg::indexed("", &k.to_string(), None)
}

/// The unit axes in the projection, so a reader can tell x, y and z apart.
fn tripod<T: Scalar>() -> Result<Panel> {
    let map = projection::<T>()?;
    let mut panel = Panel::new("").with_max_size(90.0, 90.0);
    let o = map.apply(&Point::origin(3))?;
    // label offsets: x points down-left, y right, z up
    for (k, (name, dx, dy)) in [("x", -8.0, 12.0), ("y", 6.0, -4.0), ("z", 6.0, 4.0)]
        .into_iter()
        .enumerate()
    {
        let mut e = vec![T::zero(); 3];
        e[k] = T::one();
        let tip = map.apply(&Point::new(e)?)?;
        panel.arrow(
            &o,
            &tip,
            Style::line("#333333", 1.4),
            "axis",
            Some(format!("the {name} axis")),
        )?;
        panel.label(&tip, name, "#333333", dx, dy)?;
    }
    Ok(panel)
}
