//! Labels as a reader sees them: in every figure `casteljau figure` draws and every figure of
//! the HTML report, no label's box crosses a drawn line or curve, covers a point marker or
//! overlaps another label — at the SVG's font size, and for the report's figures also at the
//! larger size its print stylesheet sets, which must print at 9 pt or more on A4.
//!
//! The SVG is read back as text (roxmltree) and checked with its own geometry: a label's box
//! from its character count at 0.6 em per character (DejaVu Sans's digits and capitals are
//! 0.6–0.7 em wide, so this is no larger than the glyphs), ascent 0.75 em, descent 0.2 em;
//! paths from their `d` data, curves flattened.

use casteljau::figure::{FigureKind, FigureRequest};
use casteljau::html::render_pages;
use casteljau::verify::claims::load_paths;
use casteljau::verify::prove_paths;
use std::path::PathBuf;

type Box2 = [f64; 4];
/// A point marker: centre and radius.
type Dot = ([f64; 2], f64);

#[derive(Debug)]
struct Label {
    text: String,
    bounds: Box2,
}

/// The drawn segments, dots and labels of one `<svg>` element, its labels at `font` pixels
/// (default: the SVG's own font size).
fn read_svg(svg: roxmltree::Node, font: Option<f64>) -> (Vec<Box2>, Vec<Dot>, Vec<Label>) {
    let font: f64 = font.unwrap_or_else(|| svg.attribute("font-size").unwrap_or("13").parse().unwrap());
    let (mut segments, mut dots, mut labels) = (Vec::new(), Vec::new(), Vec::new());
    for n in svg.descendants().filter(|n| n.is_element()) {
        // arrowheads are drawn in <defs> in their own coordinates
        if n.ancestors().any(|a| a.has_tag_name("defs")) {
            continue;
        }
        match n.tag_name().name() {
            "path" => segments.extend(path_segments(n.attribute("d").unwrap())),
            "circle" => {
                let f = |a: &str| n.attribute(a).unwrap().parse::<f64>().unwrap();
                dots.push(([f("cx"), f("cy")], f("r")));
            }
            "text" if n.attribute("class") == Some("label") => {
                let text: String = n.text().unwrap_or("").to_string();
                let f = |a: &str| n.attribute(a).unwrap().parse::<f64>().unwrap();
                let w = text.chars().count() as f64 * 0.6 * font;
                let (x, y) = (f("x"), f("y"));
                let left = match n.attribute("text-anchor").unwrap_or("start") {
                    "start" => x,
                    "middle" => x - w / 2.0,
                    "end" => x - w,
                    a => panic!("text-anchor {a}"),
                };
                labels.push(Label {
                    text,
                    bounds: [left, y - 0.75 * font, left + w, y + 0.2 * font],
                });
            }
            _ => {}
        }
    }
    (segments, dots, labels)
}

/// The straight pieces of a path (`M`, `L`, `Q`, `C`, `Z`; curves as 64 chords).
fn path_segments(d: &str) -> Vec<Box2> {
    let tokens: Vec<&str> = d.split_whitespace().collect();
    let (mut out, mut pos, mut start) = (Vec::new(), [0.0, 0.0], [0.0, 0.0]);
    let mut k = 0;
    let num = |k: usize| tokens[k].parse::<f64>().unwrap();
    while k < tokens.len() {
        let cmd = tokens[k];
        k += 1;
        match cmd {
            "M" => {
                pos = [num(k), num(k + 1)];
                start = pos;
                k += 2;
            }
            "L" => {
                let to = [num(k), num(k + 1)];
                out.push([pos[0], pos[1], to[0], to[1]]);
                pos = to;
                k += 2;
            }
            "Q" | "C" => {
                let count = if cmd == "Q" { 2 } else { 3 };
                let mut ctrl = vec![pos];
                for i in 0..count {
                    ctrl.push([num(k + 2 * i), num(k + 2 * i + 1)]);
                }
                k += 2 * count;
                let mut prev = pos;
                for s in 1..=64 {
                    let t = s as f64 / 64.0;
                    let mut p = ctrl.clone();
                    for r in 1..p.len() {
                        for i in 0..p.len() - r {
                            p[i] = [
                                (1.0 - t) * p[i][0] + t * p[i + 1][0],
                                (1.0 - t) * p[i][1] + t * p[i + 1][1],
                            ];
                        }
                    }
                    out.push([prev[0], prev[1], p[0][0], p[0][1]]);
                    prev = p[0];
                }
                pos = prev;
            }
            "Z" => out.push([pos[0], pos[1], start[0], start[1]]),
            other => panic!("path command {other} in {d}"),
        }
    }
    out
}

fn crosses(s: Box2, b: Box2) -> bool {
    // sampled densely enough for boxes a few pixels high
    let steps = (((s[2] - s[0]).abs() + (s[3] - s[1]).abs()) / 0.5).ceil().max(1.0) as usize;
    (0..=steps).any(|i| {
        let t = i as f64 / steps as f64;
        let (x, y) = (s[0] + t * (s[2] - s[0]), s[1] + t * (s[3] - s[1]));
        x > b[0] && x < b[2] && y > b[1] && y < b[3]
    })
}

/// Every overlap in one figure with its labels at `font` pixels, described.
fn overlaps(svg: roxmltree::Node, font: Option<f64>) -> Vec<String> {
    let (segments, dots, labels) = read_svg(svg, font);
    let mut found = Vec::new();
    for (i, l) in labels.iter().enumerate() {
        let b = l.bounds;
        if segments.iter().any(|&s| crosses(s, b)) {
            found.push(format!("'{}' crosses a line", l.text));
        }
        for (c, r) in &dots {
            let dx = c[0] - c[0].clamp(b[0], b[2]);
            let dy = c[1] - c[1].clamp(b[1], b[3]);
            if dx * dx + dy * dy < r * r {
                found.push(format!("'{}' covers the point at {c:?}", l.text));
            }
        }
        for m in &labels[i + 1..] {
            let o = m.bounds;
            if b[0] < o[2] && o[0] < b[2] && b[1] < o[3] && o[1] < b[3] {
                found.push(format!("'{}' overlaps '{}'", l.text, m.text));
            }
        }
    }
    found
}

#[test]
fn the_checker_sees_an_overlap() {
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" font-size="13"><path d="M 0 10 L 200 10"/>
        <text class="label" x="20" y="14">w₁ = 1/2</text><text class="label" x="40" y="40">a</text>
        <text class="label" x="38" y="42">b</text><circle cx="100" cy="80" r="3"/>
        <text class="label" x="96" y="84">c</text></svg>"#;
    let doc = roxmltree::Document::parse(svg).unwrap();
    let found = overlaps(doc.root_element(), None);
    assert_eq!(
        found,
        [
            "'w₁ = 1/2' crosses a line",
            "'a' overlaps 'b'",
            "'c' covers the point at [100.0, 80.0]"
        ]
    );
}

#[test]
fn no_label_overlaps_a_line_a_point_or_a_label_in_any_figure() {
    let svgs: Vec<(String, String)> = FigureKind::ALL
        .into_iter()
        .map(|k| {
            let svg = FigureRequest::new(k).figure().unwrap().to_svg().unwrap();
            (format!("figure {}", k.name()), svg)
        })
        .collect();
    let proofs = vec![PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("proofs")];
    let report = prove_paths(&proofs, &mut |_, _, _| {}).unwrap();
    let pages = render_pages(&report, &load_paths(&proofs).unwrap()).unwrap();
    let print_font = print_figure_font(&pages[0].1);
    let mut report_svgs = Vec::new();
    for (name, html) in &pages {
        let opts = roxmltree::ParsingOptions {
            allow_dtd: true,
            ..Default::default()
        };
        let doc = roxmltree::Document::parse_with_options(html, opts).unwrap();
        for svg in doc.descendants().filter(|n| n.has_tag_name("svg")) {
            let id = svg.attribute("id").unwrap_or("?");
            report_svgs.push((format!("{name}#{id}"), html[svg.range()].to_string()));
        }
    }
    assert!(
        report_svgs.len() >= 15,
        "only {} figures in the report",
        report_svgs.len()
    );
    let mut bad = Vec::new();
    for (name, svg) in &svgs {
        let doc = roxmltree::Document::parse(svg).unwrap();
        bad.extend(
            overlaps(doc.root_element(), None)
                .into_iter()
                .map(|o| format!("{name}: {o}")),
        );
    }
    for (name, svg) in &report_svgs {
        let doc = roxmltree::Document::parse(svg).unwrap();
        let root = doc.root_element();
        bad.extend(overlaps(root, None).into_iter().map(|o| format!("{name}: {o}")));
        bad.extend(
            overlaps(root, Some(print_font))
                .into_iter()
                .map(|o| format!("{name} (printed): {o}")),
        );
        let printed_pt = print_font * print_scale(root) * 0.75;
        if printed_pt < 9.0 {
            bad.push(format!("{name}: its text prints at {printed_pt:.1} pt"));
        }
    }
    assert!(
        bad.is_empty(),
        "{} SVGs checked ({} of the report also as printed):\n{}",
        svgs.len() + report_svgs.len(),
        report_svgs.len(),
        bad.join("\n")
    );
    eprintln!(
        "{} figures of `casteljau figure` and {} of the report checked, no overlaps (the report's also at the print size, {print_font} px)",
        svgs.len(),
        report_svgs.len()
    );
}

/// The font size the print stylesheet gives figures (`figure svg { … font-size: 16px … }`
/// inside `@media print`), in pixels.
fn print_figure_font(page: &str) -> f64 {
    let print = &page[page.find("@media print").expect("a print stylesheet")..];
    let rule = &print[print.find("figure svg {").expect("a print rule for figures")..];
    let rule = &rule[..rule.find('}').unwrap()];
    let size = rule.split("font-size:").nth(1).expect("a print font size for figures");
    size.trim().split("px").next().unwrap().parse().unwrap()
}

/// How much a figure is scaled when printed on A4: to the width between the page margins,
/// 190 mm = 718 px, less the claim box's padding and border (693 px, as measured in
/// Chromium's PDF), and to the print stylesheet's `max-height: 145mm` (548 px).
fn print_scale(svg: roxmltree::Node) -> f64 {
    let (w, h) = view_size(svg);
    (693.0 / w).min(548.0 / h).min(1.0)
}

/// The width and height of an SVG's `viewBox` (its drawing's own size; it has no fixed width).
fn view_size(svg: roxmltree::Node) -> (f64, f64) {
    let v: Vec<f64> = svg
        .attribute("viewBox")
        .expect("a viewBox")
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect();
    (v[2], v[3])
}

/// The text of every `<title>` in an SVG.
fn titles(svg: &str) -> Vec<String> {
    let doc = roxmltree::Document::parse(svg).unwrap();
    doc.descendants()
        .filter(|n| n.has_tag_name("title"))
        .map(|n| n.text().unwrap_or("").to_string())
        .collect()
}

#[test]
fn the_interactive_construction_starts_with_the_static_figure_s_labels_and_values() {
    // the page's starting values (`bᵢʳ(t) = …`, written by the engine before any script runs)
    // are the exact points the static figure labels `bᵢʳ(1/2) = …`, every level of the scheme
    let page = casteljau::html::interactive::interactive_page(&FigureRequest::new(FigureKind::Construction)).unwrap();
    let shown: Vec<String> = page
        .split("<dd id=\"b-")
        .skip(1)
        .map(|p| p.split_once('>').unwrap().1.split_once("</dd>").unwrap().0.to_string())
        .collect();
    let svg = FigureRequest::new(FigureKind::Construction)
        .figure()
        .unwrap()
        .to_svg()
        .unwrap();
    let drawn = titles(&svg);
    // degree 3: 4 + 3 + 2 + 1 points of the scheme
    assert_eq!(shown.len(), 10, "{shown:?}");
    for s in &shown {
        let at_half = s.replacen("(t) = ", "(1/2) = ", 1);
        // level 0 is drawn as the control points `bᵢ = …`
        let control = s.replacen("⁰(t) = ", " = ", 1);
        assert!(
            drawn.contains(&at_half) || drawn.contains(&control),
            "the page starts with {s}; the figure's points: {drawn:?}"
        );
    }
    // and a false value is not among them
    assert!(!drawn.contains(&"b₀³(1/2) = (1, 1)".to_string()));
}

#[test]
fn every_interactive_page_starts_with_values_equal_to_the_engine_s() {
    use casteljau::html::interactive::{interactive_page, INTERACTIVE_KINDS};
    use casteljau::{BezierCurve, BigRational, Scalar};
    let half = BigRational::from_ratio(1, 2).unwrap();
    let curve: BezierCurve<BigRational> = BezierCurve::from_ints(&[&[0, 0], &[1, 2], &[3, 2], &[4, 0]]).unwrap();
    let list = |c: &BezierCurve<BigRational>| c.points().iter().map(|p| p.to_string()).collect::<Vec<_>>().join("; ");
    for kind in INTERACTIVE_KINDS {
        let input =
            (kind != FigureKind::Bernstein && kind != FigureKind::Conics).then(|| "0,0; 1,2; 3,2; 4,0".to_string());
        let mut req = FigureRequest::new(kind);
        req.input = input;
        let page = interactive_page(&req).unwrap();
        let text = |id: &str| -> String {
            let at = page
                .find(&format!("<dd id=\"{id}\""))
                .unwrap_or_else(|| panic!("{id} on {}", kind.name()));
            page[at..]
                .split_once('>')
                .unwrap()
                .1
                .split_once("</dd>")
                .unwrap()
                .0
                .to_string()
        };
        match kind {
            FigureKind::Subdivision => {
                let (l, r) = curve.split_at(&half);
                assert_eq!(text("left"), list(&l));
                assert_eq!(text("right"), list(&r));
            }
            FigureKind::Elevation => assert_eq!(text("elevated"), list(&curve.elevate_by(1).unwrap())),
            FigureKind::Hodograph => {
                assert_eq!(text("point"), curve.eval(&half).to_string());
                assert_eq!(text("vector"), curve.derivative_at(1, &half).unwrap().to_string());
            }
            FigureKind::Construction => assert_eq!(text("b-3-0"), format!("b₀³(t) = {}", curve.eval(&half))),
            _ => {}
        }
    }
}

#[test]
fn the_projection_s_labels_are_each_nearest_their_own_point() {
    let svg = FigureRequest::new(FigureKind::Projection)
        .figure()
        .unwrap()
        .to_svg()
        .unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let (_, _, labels) = read_svg(doc.root_element(), None);
    // each point's name is its tooltip up to " = "
    let mut points: Vec<(String, [f64; 2])> = Vec::new();
    for n in doc.descendants().filter(|n| n.has_tag_name("circle")) {
        let f = |a: &str| n.attribute(a).unwrap().parse::<f64>().unwrap();
        let title = n
            .children()
            .find(|c| c.has_tag_name("title"))
            .and_then(|t| t.text())
            .unwrap_or("");
        points.push((title.split(" = ").next().unwrap().to_string(), [f("cx"), f("cy")]));
    }
    let distance = |c: [f64; 2], b: Box2| (c[0] - c[0].clamp(b[0], b[2])).hypot(c[1] - c[1].clamp(b[1], b[3]));
    let mut checked = 0;
    for l in &labels {
        let Some((_, own)) = points.iter().find(|(name, _)| *name == l.text) else {
            continue;
        };
        let own_d = distance(*own, l.bounds);
        for (name, at) in &points {
            if at != own {
                assert!(
                    // clearly nearer: half-way between two points, a label reads as either's
                    distance(*at, l.bounds) > 1.5 * own_d,
                    "'{}' is {own_d:.1} px from its point but {:.1} px from {name}'s",
                    l.text,
                    distance(*at, l.bounds)
                );
            }
        }
        checked += 1;
    }
    assert!(labels.iter().any(|l| l.text == "x(1/2)") && checked >= 3, "{labels:?}");
    for (i, a) in labels.iter().enumerate() {
        for b in &labels[i + 1..] {
            let (p, q) = (a.bounds, b.bounds);
            assert!(
                !(p[0] < q[2] && q[0] < p[2] && p[1] < q[3] && q[1] < p[3]),
                "'{}' overlaps '{}'",
                a.text,
                b.text
            );
        }
    }
}
