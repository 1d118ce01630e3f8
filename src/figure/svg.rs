//! A small SVG writer for figures: panels in equal-aspect world coordinates, items that carry
//! their exact values as `<title>` tooltips, notes below the drawing.
//!
//! Items are added with exact points; their coordinates become `f64` only here, the one place
//! where a figure stops being exact. Polynomial curves of degree ≤ 3 are written as SVG path
//! segments (`L`, `Q`, `C`) from their control points, so the renderer draws the curve itself;
//! other curves are written through exact samples.

use super::place::{Anchor, Obstacles, Placed, Wanted};
use crate::error::{Error, Result};
use crate::point::Point;
use crate::scalar::Scalar;
use crate::BezierCurve;
use std::fmt::Write as _;

/// How a line or shape is painted.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Style {
    /// Stroke colour (`#rrggbb`).
    pub stroke: &'static str,
    /// Stroke width in pixels.
    pub width: f64,
    /// Dash pattern, e.g. `"5 4"`.
    pub dash: Option<&'static str>,
    /// Fill colour of closed shapes.
    pub fill: Option<&'static str>,
}

impl Style {
    /// A solid line.
    pub const fn line(stroke: &'static str, width: f64) -> Self {
        Style {
            stroke,
            width,
            dash: None,
            fill: None,
        }
    }

    /// A dashed line.
    pub const fn dashed(stroke: &'static str, width: f64) -> Self {
        Style {
            stroke,
            width,
            dash: Some("5 4"),
            fill: None,
        }
    }
}

/// The colour of the curve itself in every figure (unique, so tests can find its pixels).
pub const CURVE: &str = "#1f3a93";
/// Control polygons.
pub const POLYGON: &str = "#6b6b6b";
/// The point the figure is about (b(t), the split point, the hull point).
pub const POINT: &str = "#c0392b";
/// Colours for successive levels, pieces or family members.
pub const PALETTE: [&str; 6] = ["#d95f02", "#1b9e77", "#7570b3", "#e7298a", "#66a61e", "#a6761d"];

#[derive(Clone, Debug)]
enum Shape {
    /// A polyline (open or closed).
    Path { pts: Vec<[f64; 2]>, closed: bool },
    /// One Bézier segment of degree 1..=3 (an SVG `L`, `Q` or `C`).
    Bezier { pts: Vec<[f64; 2]> },
    /// A dot of the given radius.
    Dot { at: [f64; 2], radius: f64 },
    /// An arrow from the first point to the second.
    Arrow { from: [f64; 2], to: [f64; 2] },
    /// A text label, offset in pixels from its anchor.
    Label {
        at: [f64; 2],
        text: String,
        dx: f64,
        dy: f64,
    },
}

#[derive(Clone, Debug)]
struct Item {
    shape: Shape,
    style: Style,
    class: &'static str,
    title: Option<String>,
}

/// One drawing area with its own equal-aspect scale.
#[derive(Clone, Debug)]
pub struct Panel {
    heading: String,
    items: Vec<Item>,
    max_size: (f64, f64),
}

/// A line of text under the drawing, with an optional colour swatch.
#[derive(Clone, Debug)]
struct Note {
    swatch: Option<&'static str>,
    text: String,
}

/// A figure: a title, panels side by side, notes below.
#[derive(Clone, Debug)]
pub struct Figure {
    title: String,
    panels: Vec<Panel>,
    notes: Vec<Note>,
}

/// Where a panel's world coordinates land in the SVG (pixels, y downwards).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PanelMap {
    /// Smallest world x drawn.
    pub xmin: f64,
    /// Largest world y drawn.
    pub ymax: f64,
    /// Pixels per world unit (the same in x and y).
    pub scale: f64,
    /// Left edge of the drawing area.
    pub left: f64,
    /// Top edge of the drawing area.
    pub top: f64,
}

impl PanelMap {
    /// The pixel position of the world point `(x, y)`.
    pub fn to_screen(&self, x: f64, y: f64) -> (f64, f64) {
        (
            self.left + (x - self.xmin) * self.scale,
            self.top + (self.ymax - y) * self.scale,
        )
    }
}

/// The figure's size and the map of each panel.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// Width in pixels.
    pub width: f64,
    /// Height in pixels.
    pub height: f64,
    /// One map per panel, in order.
    pub panels: Vec<PanelMap>,
}

const MARGIN: f64 = 30.0;
/// Room left and right of a drawing for labels.
const SIDE: f64 = 64.0;
const TITLE_H: f64 = 34.0;
const HEADING_H: f64 = 20.0;
const NOTE_H: f64 = 18.0;
/// Longest legend line, in characters: short enough that a line still fits the figure's
/// width when the print stylesheet sets the legends at 16 px instead of 13.
const NOTE_CHARS: usize = 88;
/// Smallest figure width, in pixels: room for a legend line.
const MIN_WIDTH: f64 = 766.0;

/// Converts a 2D exact point for drawing; any other dimension is an error.
pub(crate) fn xy<T: Scalar>(p: &Point<T>) -> Result<[f64; 2]> {
    match p.coords() {
        [x, y] => Ok([x.to_f64(), y.to_f64()]),
        c => Err(Error::DimensionMismatch {
            expected: 2,
            found: c.len(),
            context: "a point drawn in a figure (project it first)".into(),
        }),
    }
}

impl Panel {
    /// An empty panel with a heading (may be empty), at most 460 × 420 pixels of drawing.
    pub fn new(heading: impl Into<String>) -> Self {
        Panel {
            heading: heading.into(),
            items: Vec::new(),
            max_size: (460.0, 420.0),
        }
    }

    /// Sets the largest drawing size in pixels.
    pub fn with_max_size(mut self, width: f64, height: f64) -> Self {
        self.max_size = (width, height);
        self
    }

    fn push(&mut self, shape: Shape, style: Style, class: &'static str, title: Option<String>) {
        self.items.push(Item {
            shape,
            style,
            class,
            title,
        });
    }

    /// A polyline through `pts` (closed: a polygon, filled when the style has a fill).
    pub fn polyline<T: Scalar>(
        &mut self,
        pts: &[Point<T>],
        closed: bool,
        style: Style,
        class: &'static str,
        title: Option<String>,
    ) -> Result<()> {
        let pts = pts.iter().map(xy).collect::<Result<Vec<_>>>()?;
        self.push(Shape::Path { pts, closed }, style, class, title);
        Ok(())
    }

    /// A polyline through points already in drawing coordinates ([`super::sample`]).
    pub(crate) fn polyline_f64(
        &mut self,
        pts: Vec<[f64; 2]>,
        style: Style,
        class: &'static str,
        title: Option<String>,
    ) {
        self.push(Shape::Path { pts, closed: false }, style, class, title);
    }

    /// A planar polynomial curve: written exactly as one SVG segment for degree ≤ 3, through
    /// 200 samples above (evaluated in `f64` from the rounded control points: they only
    /// place pixels, see the `sample` module).
    pub fn curve<T: Scalar>(
        &mut self,
        curve: &BezierCurve<T>,
        style: Style,
        class: &'static str,
        title: Option<String>,
    ) -> Result<()> {
        let pts = curve.points().iter().map(xy).collect::<Result<Vec<_>>>()?;
        self.curve_f64(pts, style, class, title);
        Ok(())
    }

    /// [`Panel::curve`] from control points already in drawing coordinates.
    pub(crate) fn curve_f64(&mut self, pts: Vec<[f64; 2]>, style: Style, class: &'static str, title: Option<String>) {
        if (2..=4).contains(&pts.len()) {
            self.push(Shape::Bezier { pts }, style, class, title);
        } else {
            self.polyline_f64(super::sample::polynomial(&pts, 200), style, class, title);
        }
    }

    /// A dot at `p` with its exact value as the tooltip.
    pub fn dot<T: Scalar>(&mut self, p: &Point<T>, radius: f64, color: &'static str, title: String) -> Result<()> {
        let at = xy(p)?;
        self.push(Shape::Dot { at, radius }, Style::line(color, 1.0), "point", Some(title));
        Ok(())
    }

    /// An arrow from `from` to `to`.
    pub fn arrow<T: Scalar>(
        &mut self,
        from: &Point<T>,
        to: &Point<T>,
        style: Style,
        class: &'static str,
        title: Option<String>,
    ) -> Result<()> {
        let (from, to) = (xy(from)?, xy(to)?);
        self.push(Shape::Arrow { from, to }, style, class, title);
        Ok(())
    }

    /// A text label at `p`, offset by `(dx, dy)` pixels (y downwards).
    pub fn label<T: Scalar>(
        &mut self,
        p: &Point<T>,
        text: impl Into<String>,
        color: &'static str,
        dx: f64,
        dy: f64,
    ) -> Result<()> {
        let at = xy(p)?;
        let text = text.into();
        // labels of coincident points (b₀ = b₃ of a closed polygon) are written once, joined
        for it in &mut self.items {
            if let Shape::Label {
                at: a,
                text: t,
                dx: x,
                dy: y,
            } = &mut it.shape
            {
                if *a == at && *x == dx && *y == dy {
                    t.push_str(if t.contains('=') || text.contains('=') {
                        "; "
                    } else {
                        " = "
                    });
                    t.push_str(&text);
                    return Ok(());
                }
            }
        }
        self.push(
            Shape::Label { at, text, dx, dy },
            Style::line(color, 1.0),
            "label",
            None,
        );
        Ok(())
    }

    /// Where each label goes (in item order), clear of this panel's lines, points, heading
    /// and other labels ([`super::place`]).
    fn place_labels(&self, map: &PanelMap, frame: [f64; 4]) -> Vec<Placed> {
        let mut obstacles = Obstacles::new(frame);
        let screen = |q: &[f64; 2]| {
            let (x, y) = map.to_screen(q[0], q[1]);
            [x, y]
        };
        if !self.heading.is_empty() {
            let (x, y) = (map.left - SIDE + 16.0, map.top - MARGIN - 4.0);
            obstacles.boxed(super::place::label_box(&self.heading, x, y, Anchor::Start));
        }
        let mut wanted = Vec::new();
        for it in &self.items {
            match &it.shape {
                Shape::Path { pts, closed } => {
                    let pts: Vec<[f64; 2]> = pts.iter().map(screen).collect();
                    for w in pts.windows(2) {
                        obstacles.segment(w[0], w[1]);
                    }
                    if *closed && pts.len() > 2 {
                        obstacles.segment(pts[pts.len() - 1], pts[0]);
                    }
                }
                Shape::Bezier { pts } => {
                    let flat = super::sample::polynomial(pts, 32);
                    for w in flat.windows(2) {
                        obstacles.segment(screen(&w[0]), screen(&w[1]));
                    }
                }
                Shape::Arrow { from, to } => obstacles.segment(screen(from), screen(to)),
                Shape::Dot { at, radius } => obstacles.dot(screen(at), radius + 1.0),
                Shape::Label { at, text, dx, dy } => wanted.push(Wanted {
                    at: screen(at),
                    dx: *dx,
                    dy: *dy,
                    text,
                }),
            }
        }
        obstacles.place(&wanted)
    }

    fn bounds(&self) -> Option<[f64; 4]> {
        let mut b: Option<[f64; 4]> = None;
        let mut add = |p: &[f64; 2]| {
            let e = b.get_or_insert([p[0], p[1], p[0], p[1]]);
            e[0] = e[0].min(p[0]);
            e[1] = e[1].min(p[1]);
            e[2] = e[2].max(p[0]);
            e[3] = e[3].max(p[1]);
        };
        for it in &self.items {
            match &it.shape {
                Shape::Path { pts, .. } | Shape::Bezier { pts } => pts.iter().for_each(&mut add),
                Shape::Dot { at, .. } | Shape::Label { at, .. } => add(at),
                Shape::Arrow { from, to } => {
                    add(from);
                    add(to);
                }
            }
        }
        b
    }

    fn map(&self, left: f64, top: f64) -> (PanelMap, f64, f64) {
        let [x0, y0, x1, y1] = self.bounds().unwrap_or([0.0, 0.0, 1.0, 1.0]);
        let (mut dx, mut dy) = (x1 - x0, y1 - y0);
        // coinciding points (a box of size 0, or of rounding size next to the coordinates)
        // get a frame as large as the coordinates (1 at the origin); the floor keeps the scale
        // finite for subnormal drawings
        let magnitude = x0.abs().max(x1.abs()).max(y0.abs()).max(y1.abs());
        let mut span = dx.max(dy);
        if span.is_nan() || span <= magnitude * 1e-12 {
            span = if magnitude > 0.0 { magnitude } else { 1.0 };
        }
        let span = span.max(1e-290);
        // a flat drawing (a segment, a point) still gets a square-ish frame
        if dx < span * 1e-9 {
            dx = span;
        }
        if dy < span * 1e-9 {
            dy = span;
        }
        let (cx, cy) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
        let scale = (self.max_size.0 / dx).min(self.max_size.1 / dy);
        let map = PanelMap {
            xmin: cx - dx / 2.0,
            ymax: cy + dy / 2.0,
            scale,
            left: left + SIDE,
            top: top + HEADING_H + MARGIN,
        };
        (map, dx * scale + 2.0 * SIDE, dy * scale + 2.0 * MARGIN + HEADING_H)
    }
}

impl Figure {
    /// An empty figure.
    pub fn new(title: impl Into<String>) -> Self {
        Figure {
            title: title.into(),
            panels: Vec::new(),
            notes: Vec::new(),
        }
    }

    /// The title.
    pub fn title(&self) -> &str {
        &self.title
    }

    /// Adds a panel (drawn left to right in order).
    pub fn add_panel(&mut self, panel: Panel) {
        self.panels.push(panel);
    }

    /// Adds a note line (long notes are wrapped) with an optional colour swatch.
    pub fn note(&mut self, swatch: Option<&'static str>, text: impl Into<String>) {
        let text = text.into();
        let mut first = true;
        for line in wrap(&text, NOTE_CHARS) {
            self.notes.push(Note {
                swatch: if first { swatch } else { None },
                text: if first { line } else { format!("    {line}") },
            });
            first = false;
        }
    }

    /// The notes' text, one entry per line.
    pub fn notes(&self) -> Vec<&str> {
        self.notes.iter().map(|n| n.text.as_str()).collect()
    }

    /// Where everything goes.
    pub fn layout(&self) -> Layout {
        let mut left = 0.0;
        let mut panels = Vec::new();
        let mut height: f64 = 0.0;
        for p in &self.panels {
            let (map, w, h) = p.map(left, TITLE_H);
            panels.push(map);
            left += w;
            height = height.max(h);
        }
        let width = left.max(MIN_WIDTH);
        // panels are centred in the figure's width
        let shift = ((width - left) / 2.0).floor();
        for map in &mut panels {
            map.left += shift;
        }
        Layout {
            width: width.ceil(),
            height: (TITLE_H + height + self.notes.len() as f64 * NOTE_H + 12.0).ceil(),
            panels,
        }
    }

    /// The SVG document. Fails if a coordinate is not a finite `f64` (an exact value too
    /// large for floating point).
    pub fn to_svg(&self) -> Result<String> {
        let layout = self.layout();
        let mut s = String::new();
        let (w, h) = (layout.width, layout.height);
        let _ = writeln!(
            s,
            r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {w} {h}" role="img" aria-label="{}" font-family="DejaVu Sans, Noto Sans, Arial, sans-serif" font-size="13">"#,
            esc(&self.title)
        );
        let _ = writeln!(s, "<title>{}</title>", esc(&self.title));
        let _ = writeln!(s, r##"<rect width="{w}" height="{h}" fill="#ffffff"/>"##);
        // one arrowhead per arrow colour (`context-stroke` is not supported everywhere)
        let mut colors: Vec<&str> = Vec::new();
        for it in self.panels.iter().flat_map(|p| &p.items) {
            if matches!(it.shape, Shape::Arrow { .. }) && !colors.contains(&it.style.stroke) {
                colors.push(it.style.stroke);
            }
        }
        if !colors.is_empty() {
            s.push_str("<defs>");
            for c in colors {
                let _ = write!(
                    s,
                    r#"<marker id="arrow-{}" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" orient="auto"><path d="M 0 0 L 10 5 L 0 10 z" fill="{c}"/></marker>"#,
                    c.trim_start_matches('#')
                );
            }
            s.push_str("</defs>\n");
        }
        let _ = writeln!(
            s,
            r##"<text x="16" y="23" font-size="16" font-weight="bold" fill="#222222">{}</text>"##,
            esc(&self.title)
        );
        let mut y = TITLE_H + layout.panels.iter().fold(0.0f64, |m, p| m.max(p.top - TITLE_H)) + 6.0;
        y = y.max(h - self.notes.len() as f64 * NOTE_H - 12.0);
        for (panel, map) in self.panels.iter().zip(&layout.panels) {
            let mut placed = panel.place_labels(map, [2.0, TITLE_H, w - 2.0, y + 4.0]).into_iter();
            let _ = writeln!(s, r#"<g class="panel">"#);
            if !panel.heading.is_empty() {
                let _ = writeln!(
                    s,
                    r##"<text x="{}" y="{}" font-size="13" font-style="italic" fill="#444444">{}</text>"##,
                    num(map.left - SIDE + 16.0),
                    num(map.top - MARGIN - 4.0),
                    esc(&panel.heading)
                );
            }
            for it in &panel.items {
                let at = if matches!(it.shape, Shape::Label { .. }) {
                    placed.next()
                } else {
                    None
                };
                write_item(&mut s, it, map, at)?;
            }
            let _ = writeln!(s, "</g>");
        }
        for n in &self.notes {
            y += NOTE_H;
            if let Some(c) = n.swatch {
                let _ = writeln!(
                    s,
                    r#"<rect x="16" y="{}" width="14" height="4" fill="{c}"/>"#,
                    num(y - 7.0)
                );
            }
            let _ = writeln!(
                s,
                r##"<text class="note" x="38" y="{}" fill="#222222">{}</text>"##,
                num(y - 2.0),
                esc(&n.text)
            );
        }
        s.push_str("</svg>\n");
        Ok(s)
    }
}

fn write_item(s: &mut String, it: &Item, map: &PanelMap, placed: Option<Placed>) -> Result<()> {
    let screen = |q: &[f64; 2]| -> Result<(f64, f64)> {
        let (x, y) = map.to_screen(q[0], q[1]);
        if !x.is_finite() || !y.is_finite() {
            return Err(Error::NotFinite(format!(
                "a figure coordinate ({}, {}) is beyond the range of f64",
                q[0], q[1]
            )));
        }
        Ok((x, y))
    };
    let p = |q: &[f64; 2]| -> Result<String> {
        let (x, y) = screen(q)?;
        Ok(format!("{} {}", num(x), num(y)))
    };
    let st = &it.style;
    let mut paint = format!(
        r#" stroke="{}" stroke-width="{}" stroke-linejoin="round" stroke-linecap="round""#,
        st.stroke,
        num(st.width)
    );
    if let Some(d) = st.dash {
        let _ = write!(paint, r#" stroke-dasharray="{d}""#);
    }
    let _ = write!(paint, r#" fill="{}""#, st.fill.unwrap_or("none"));
    if st.fill.is_some() {
        paint.push_str(r#" fill-opacity="0.35""#);
    }
    let title = it
        .title
        .as_ref()
        .map(|t| format!("<title>{}</title>", esc(t)))
        .unwrap_or_default();
    let class = it.class;
    match &it.shape {
        Shape::Path { pts, closed } => {
            let mut d = String::new();
            for (k, q) in pts.iter().enumerate() {
                let _ = write!(d, "{}{} ", if k == 0 { "M " } else { "L " }, p(q)?);
            }
            if *closed {
                d.push('Z');
            }
            let _ = writeln!(s, r#"<path class="{class}" d="{}"{paint}>{title}</path>"#, d.trim_end());
        }
        Shape::Bezier { pts } => {
            let cmd = ["", "L", "Q", "C"][pts.len() - 1];
            let rest = pts[1..].iter().map(p).collect::<Result<Vec<_>>>()?.join(" ");
            let _ = writeln!(
                s,
                r#"<path class="{class}" d="M {} {cmd} {rest}"{paint}>{title}</path>"#,
                p(&pts[0])?
            );
        }
        Shape::Dot { at, radius } => {
            let (x, y) = screen(at)?;
            let _ = writeln!(
                s,
                r##"<circle class="{class}" cx="{}" cy="{}" r="{}" fill="{}" stroke="#ffffff" stroke-width="1">{title}</circle>"##,
                num(x),
                num(y),
                num(*radius),
                st.stroke
            );
        }
        Shape::Arrow { from, to } => {
            let _ = writeln!(
                s,
                r#"<path class="{class}" d="M {} L {}"{paint} marker-end="url(#arrow-{})">{title}</path>"#,
                p(from)?,
                p(to)?,
                st.stroke.trim_start_matches('#'),
            );
        }
        Shape::Label { at, text, dx, dy } => {
            let (x, y) = screen(at)?;
            let (x, y, anchor) = match placed {
                Some(p) => (p.x, p.y, p.anchor.svg()),
                None => (x + dx, y + dy, if *dx < 0.0 { "end" } else { "start" }),
            };
            let _ = writeln!(
                s,
                r##"<text class="{class}" x="{}" y="{}" text-anchor="{anchor}" fill="{}" stroke="#ffffff" stroke-width="3" paint-order="stroke">{}</text>"##,
                num(x),
                num(y),
                st.stroke,
                esc(text)
            );
        }
    }
    Ok(())
}

/// A pixel coordinate with two decimals (trailing zeros dropped).
fn num(x: f64) -> String {
    let s = format!("{x:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.to_string()
    }
}

/// Escapes text for XML content and attribute values.
pub fn esc(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

/// Splits `text` at spaces into lines of at most `width` characters (longer words stay whole).
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    lines.push(line);
    lines
}

/// `b` with subscript `i` and superscript `r` in Unicode (`b₁²`); `r = None` for no superscript.
pub fn indexed(base: &str, sub: &str, sup: Option<&str>) -> String {
    const SUB: [char; 10] = ['₀', '₁', '₂', '₃', '₄', '₅', '₆', '₇', '₈', '₉'];
    const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let conv = |s: &str, table: &[char; 10]| -> String {
        s.chars()
            .map(|c| match c.to_digit(10) {
                Some(d) => table[d as usize],
                None => match (c, table[0]) {
                    (',', _) => ',',
                    ('(', '⁰') => '⁽',
                    (')', '⁰') => '⁾',
                    ('r', '⁰') => 'ʳ',
                    ('n', '⁰') => 'ⁿ',
                    _ => c,
                },
            })
            .collect()
    };
    let mut out = format!("{base}{}", conv(sub, &SUB));
    if let Some(r) = sup {
        out.push_str(&conv(r, &SUP));
    }
    out
}
