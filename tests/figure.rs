//! Figures as a reader sees them: every SVG parses, every coordinate is a finite number, the
//! exact values written on a figure are the library's, and the rasterised curve lies where the
//! exact curve is.

use casteljau::enneper_net;
use casteljau::figure::{self, svg::CURVE, AnyCurve, FigureKind, FigureRequest};
use casteljau::fit_cubic_to;
use casteljau::{AffineMap, BezierCurve, BigRational, Point, Scalar};
use std::process::Command;

fn q(p: i64, d: i64) -> BigRational {
    BigRational::from_ratio(p, d).unwrap()
}

fn curve(points: &[&[i64]]) -> BezierCurve<BigRational> {
    BezierCurve::from_ints(points).unwrap()
}

/// Parses an SVG, checks its numbers, and returns every `<title>` and note text.
fn check_svg(svg: &str) -> (Vec<String>, Vec<String>) {
    let doc = roxmltree::Document::parse(svg).unwrap_or_else(|e| panic!("not well-formed XML: {e}\n{svg}"));
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    let mut titles = Vec::new();
    let mut notes = Vec::new();
    let mut shapes = 0;
    for n in doc.descendants().filter(|n| n.is_element()) {
        for a in n.attributes() {
            let numeric = matches!(
                a.name(),
                "x" | "y" | "cx" | "cy" | "r" | "width" | "height" | "stroke-width"
            );
            if numeric {
                let v: f64 = a
                    .value()
                    .parse()
                    .unwrap_or_else(|_| panic!("{}=\"{}\" is not a number", a.name(), a.value()));
                assert!(v.is_finite(), "{}={v}", a.name());
            }
            if a.name() == "d" {
                assert!(!a.value().trim().is_empty(), "an empty path");
                for tok in a.value().split_whitespace() {
                    if tok.chars().all(|c| c.is_ascii_alphabetic()) {
                        continue;
                    }
                    let v: f64 = tok.parse().unwrap_or_else(|_| panic!("path token '{tok}'"));
                    assert!(v.is_finite());
                }
            }
        }
        match n.tag_name().name() {
            "title" => titles.push(n.text().unwrap_or("").to_string()),
            "text" if n.attribute("class") == Some("note") => notes.push(n.text().unwrap_or("").to_string()),
            "path" | "circle" => shapes += 1,
            _ => {}
        }
    }
    assert!(shapes > 0, "a figure with nothing drawn");
    assert!(!svg.contains("NaN"), "NaN in the SVG");
    (titles, notes)
}

/// The title that starts with `prefix`, without it.
fn titled<'a>(titles: &'a [String], prefix: &str) -> &'a str {
    titles
        .iter()
        .find_map(|t| t.strip_prefix(prefix))
        .unwrap_or_else(|| panic!("no title '{prefix}…' among {titles:#?}"))
}

#[test]
fn every_kind_draws_a_well_formed_figure_with_its_defaults() {
    for kind in FigureKind::ALL {
        let fig = FigureRequest::new(kind)
            .figure()
            .unwrap_or_else(|e| panic!("{}: {e}", kind.name()));
        let svg = fig.to_svg().unwrap();
        let (titles, notes) = check_svg(&svg);
        assert!(!titles.is_empty() && !notes.is_empty(), "{}", kind.name());
        assert_eq!(titles[0], fig.title());
    }
}

#[test]
fn construction_labels_are_the_scheme() {
    let c = curve(&[&[0, 0], &[1, 3], &[4, 3], &[6, -1], &[7, 2]]);
    let t = q(2, 7);
    let (titles, notes) = check_svg(&figure::construction(&c, &t).unwrap().to_svg().unwrap());
    let scheme = c.scheme(&t);
    let sub = ['₀', '₁', '₂', '₃', '₄'];
    let sup = ['⁰', '¹', '²', '³', '⁴'];
    for (r, sup) in sup.iter().enumerate().skip(1) {
        for (i, sub) in sub.iter().enumerate().take(5 - r) {
            let shown = titled(&titles, &format!("b{sub}{sup}(2/7) = "));
            assert_eq!(shown, scheme.get(r, i).unwrap().to_string());
        }
    }
    assert_eq!(titled(&titles, "b₀ = "), "(0, 0)");
    // the notes print the same values, for a printed copy
    let level4 = notes.iter().find(|n| n.starts_with("r = 4:")).unwrap();
    assert!(level4.ends_with(&c.eval(&t).to_string()), "{level4}");
}

#[test]
fn subdivision_polygons_are_split_at() {
    let c = curve(&[&[0, 0], &[2, 4], &[5, 4], &[6, 0]]);
    let t = q(1, 3);
    let (left, right) = c.split_at(&t);
    let (titles, _) = check_svg(&figure::subdivision(&c, &t).unwrap().to_svg().unwrap());
    assert_eq!(titled(&titles, "b₀¹(1/3) = "), left.points()[1].to_string());
    assert_eq!(titled(&titles, "b₀²(1/3) = "), left.points()[2].to_string());
    assert_eq!(titled(&titles, "b₁²(1/3) = "), right.points()[1].to_string());
    assert_eq!(titled(&titles, "b₂¹(1/3) = "), right.points()[2].to_string());
    assert_eq!(titled(&titles, "b(1/3) = "), c.eval(&t).to_string());
    assert_eq!(
        titled(&titles, "the left piece: control points "),
        casteljau::format_points(left.points())
    );
}

#[test]
fn elevation_notes_carry_the_exact_distances() {
    let c = curve(&[&[0, 0], &[1, 3], &[3, -2], &[4, 4], &[6, 1], &[7, -3]]);
    let steps = [1, 3, 10];
    let (_, notes) = check_svg(&figure::elevation(&c, &steps).unwrap().to_svg().unwrap());
    let all = notes.join(" ");
    for r in steps {
        let d = c.elevation_distance(r).unwrap();
        let b_ir = figure::svg::indexed("b", "ᵢ", Some(&format!("({r})")));
        let line = format!("r = {r}: maxᵢ |{b_ir} − b(i/{})|∞ = {},", 5 + r, d.max_norm);
        assert!(all.contains(&line), "missing {line} in {all}");
    }
    assert!(figure::elevation(&c, &[100_000]).is_err());
}

#[test]
fn hull_weights_are_the_certificate() {
    let c = curve(&[&[0, 0], &[4, 0], &[4, 4], &[0, 4]]);
    let p = Point::new(vec![q(1, 1), q(3, 1)]).unwrap();
    let w = c.hull_weights(&p).unwrap().unwrap();
    let (_, notes) = check_svg(&figure::hull(&c, &p).unwrap().to_svg().unwrap());
    // the legend wraps long lines at spaces: joined again, it is the one sentence
    let all = notes.join(" ");
    let line = &all[all.find("p = (1, 3) = Σ λᵢ bᵢ with").expect(&all)..];
    for (i, l) in w.iter().enumerate() {
        let sub = ['₀', '₁', '₂', '₃'][i];
        assert!(line.contains(&format!("λ{sub} = {l}")), "{line}");
    }
    let outside = Point::new(vec![q(5, 1), q(5, 1)]).unwrap();
    let (_, notes) = check_svg(&figure::hull(&c, &outside).unwrap().to_svg().unwrap());
    assert!(notes.iter().any(|n| n.contains("no convex weights exist")));
}

#[test]
fn conic_arcs_are_classified_by_the_library() {
    let pts = vec![
        Point::new(vec![q(-1, 1), q(1, 1)]).unwrap(),
        Point::new(vec![q(0, 1), q(-1, 1)]).unwrap(),
        Point::new(vec![q(1, 1), q(1, 1)]).unwrap(),
    ];
    let one = q(1, 1);
    let (titles, _) = check_svg(
        &figure::conics(&pts, &one, &one, &[q(1, 2), q(1, 1), q(2, 1)])
            .unwrap()
            .to_svg()
            .unwrap(),
    );
    assert_eq!(titled(&titles, "w₁ = 1/2: "), "ellipse (w₁²/(w₀w₂) = 1/4)");
    assert_eq!(titled(&titles, "w₁ = 1: "), "parabola (w₁²/(w₀w₂) = 1)");
    assert_eq!(titled(&titles, "w₁ = 2: "), "hyperbola (w₁²/(w₀w₂) = 4)");
    // x(1/2) for w1 = 2: (w0 b0 + 2 w1 b1 + w2 b2)/(w0 + 2 w1 + w2) = (0, -2/6)
    assert_eq!(titled(&titles, "x(1/2) = "), "(0, 1/3) for w₁ = 1/2");
    // a negative middle weight sends the arc through infinity: refused, not drawn
    assert!(figure::conics(&pts, &one, &one, &[q(-2, 1)]).is_err());
}

#[test]
fn enneper_net_points_are_the_library_net() {
    let e = figure::text003_example5::<BigRational>().unwrap();
    let expected = enneper_net(&q(2, 1))
        .unwrap()
        .transform(&AffineMap::scaling(3, &q(3, 1)))
        .unwrap();
    assert_eq!(e, expected);
    let (titles, notes) = check_svg(&figure::enneper(&e).unwrap().to_svg().unwrap());
    for i in 0..4 {
        for j in 0..4 {
            assert_eq!(
                titled(&titles, &format!("b_{{{i},{j}}} = ")),
                e.get(i, j).unwrap().to_string()
            );
        }
    }
    assert_eq!(titled(&titles, "b_{1,1} = "), "(-22/3, -22/3, 0)");
    assert!(notes.iter().any(|n| n.contains("text 003")), "{notes:?}");
    assert!(notes
        .iter()
        .any(|n| n.starts_with("library match: x(s, t) = 3 · E(4s − 2, 4t − 2)")));
}

#[test]
fn fit_figure_states_k_l_and_delta() {
    let x = BezierCurve::new(casteljau::parse_points(figure::DEFAULT_FIT_CURVE).unwrap()).unwrap();
    let fit = fit_cubic_to(&x).unwrap();
    assert_eq!((fit.k.clone(), fit.delta2.clone()), (q(3, 10), q(1, 1280)));
    let fig = figure::fit(&AnyCurve::Polynomial(x)).unwrap();
    assert_eq!(fig.title(), "Text 004's cubic fit: k = 3/10, l = 3/10, δ² = 1/1280");
    let (titles, _) = check_svg(&fig.to_svg().unwrap());
    assert_eq!(titled(&titles, "a(1/2) − x(1/2) = "), fit.residual.to_string());
}

#[test]
fn hodograph_end_tangents_are_n_times_the_first_legs() {
    let c = curve(&[&[0, 0], &[1, 2], &[3, 3], &[4, 0]]);
    let (titles, _) = check_svg(&figure::hodograph(&c).unwrap().to_svg().unwrap());
    assert_eq!(titled(&titles, "b′(0) = 3(b₁ − b₀) = "), "(3, 6)");
    assert_eq!(titled(&titles, "b′(1) = 3(b₃ − b₂) = "), "(3, -9)");
    assert!(figure::hodograph(&curve(&[&[1, 1]])).is_err());
}

#[test]
fn bad_requests_are_clear_errors() {
    assert!("circle"
        .parse::<FigureKind>()
        .unwrap_err()
        .to_string()
        .contains("construction"));
    let mut r = FigureRequest::new(FigureKind::Hull);
    r.t = Some("1/2".into());
    assert!(r.figure().unwrap_err().to_string().contains("--t does not apply"));
    let mut r = FigureRequest::new(FigureKind::Construction);
    r.input = Some("0,0; 1".into());
    assert!(r.figure().is_err());
    // a point of four coordinates cannot be drawn
    r.input = Some("0,0,0,0; 1,1,1,1".into());
    assert!(r.figure().is_err());
    let mut r = FigureRequest::new(FigureKind::Net);
    r.iso = Some("1000".into());
    assert!(r.figure().is_err());
    // bounded work: a degree beyond the figure limit is refused before anything is computed
    let mut r = FigureRequest::new(FigureKind::Construction);
    r.input = Some(vec!["0,0"; figure::MAX_FIGURE_DEGREE + 2].join("; "));
    let e = r.figure().unwrap_err().to_string();
    assert!(e.contains("degree in a figure") && e.contains("limit 64"), "{e}");
}

#[test]
fn hostile_numbers_and_options_are_refused_at_once_naming_the_limit() {
    let fraction = format!("{}/{}", "7".repeat(5000), "3".repeat(4999));
    let start = std::time::Instant::now();
    for t in ["1e-4096", "-1e4096", fraction.as_str()] {
        let mut r = FigureRequest::new(FigureKind::Construction);
        r.t = Some(t.into());
        let e = r.figure().unwrap_err().to_string();
        assert!(e.contains("--t") && e.contains("limit 1000 bits"), "{e}");
    }
    let mut r = FigureRequest::new(FigureKind::Subdivision);
    r.input = Some(format!("0,0; 1,{}; 2,0", "9".repeat(400)));
    let e = r.figure().unwrap_err().to_string();
    assert!(e.contains("control point") && e.contains("limit 1000 bits"), "{e}");
    let mut r = FigureRequest::new(FigureKind::Elevation);
    r.steps = Some(vec!["1"; figure::MAX_FIGURE_STEPS + 1].join(","));
    assert!(r.figure().unwrap_err().to_string().contains("--steps"));
    let mut r = FigureRequest::new(FigureKind::Conics);
    r.weights = Some(vec!["2"; figure::MAX_FIGURE_ARCS + 1].join(","));
    assert!(r.figure().unwrap_err().to_string().contains("arcs"));
    // a degree-64 curve of 50-digit fractions: the exact scheme is past the work limit
    let digits = |k: usize| format!("{}{}", k % 9 + 1, "3".repeat(49));
    let curve: Vec<String> = (0..=64)
        .map(|k| format!("{}/{},{}/{}", digits(k), digits(k + 1), digits(k + 2), digits(k + 5)))
        .collect();
    for kind in [FigureKind::Construction, FigureKind::Elevation, FigureKind::Hull] {
        let mut r = FigureRequest::new(kind);
        r.input = Some(curve.join("; "));
        let e = r.figure().unwrap_err().to_string();
        assert!(e.contains("estimated exact work") && e.contains("limit"), "{e}");
    }
    assert!(start.elapsed().as_secs_f64() < 2.0, "refusals must come at once");
}

#[test]
fn elevation_distances_are_the_library_s() {
    // the figure sums Bernstein terms itself; the notes must be elevation_distance's values
    let c = curve(&[&[0, 0], &[1, 5], &[6, 4], &[7, -1], &[4, -2]]);
    let fig = figure::elevation(&c, &[1, 3, 7]).unwrap();
    // a long note is wrapped onto an indented next line
    let notes = fig.notes().join("\n").replace("\n    ", " ");
    for r in [0, 1, 3, 7] {
        let d = c.elevation_distance(r).unwrap();
        let b_ir = figure::svg::indexed("b", "ᵢ", Some(&format!("({r})")));
        let needle = format!("maxᵢ |{b_ir} − b(i/{})|∞ = {}", 4 + r, d.max_norm);
        let needle0 = format!("maxᵢ |bᵢ − b(i/4)|∞ = {}", d.max_norm);
        assert!(
            notes.contains(&needle) || (r == 0 && notes.contains(&needle0)),
            "r = {r}: {notes}"
        );
        if r > 0 {
            assert!(notes.contains(&format!("|·|₂² = {}", d.max_squared)), "{notes}");
        }
    }
}

/// Rasterises the figure and checks that the pixels of the curve's colour are exactly where
/// the exact curve is: every sample of b(t) has such a pixel within 2 px, and every such
/// pixel is within 3 px of the exact curve.
#[test]
fn rasterised_curve_lies_on_the_exact_curve() {
    let c = curve(&[&[0, 0], &[1, 5], &[6, 4], &[7, -1], &[4, -2]]); // degree 4: drawn through samples
    let c3 = curve(&[&[0, 0], &[2, 6], &[5, -3], &[8, 2]]); // degree 3: drawn as an SVG cubic
    for c in [c, c3] {
        let fig = figure::construction(&c, &q(1, 3)).unwrap();
        let svg = fig.to_svg().unwrap();
        let layout = fig.layout();
        let map = layout.panels[0];
        let tree = resvg::usvg::Tree::from_str(&svg, &resvg::usvg::Options::default()).unwrap();
        let (w, h) = (layout.width as u32, layout.height as u32);
        let mut pixmap = resvg::tiny_skia::Pixmap::new(w, h).unwrap();
        resvg::render(&tree, resvg::tiny_skia::Transform::default(), &mut pixmap.as_mut());

        let hex = |k: usize| u8::from_str_radix(&CURVE[k..k + 2], 16).unwrap() as i32;
        let want = [hex(1), hex(3), hex(5)];
        let is_curve = |x: i64, y: i64| -> bool {
            if x < 0 || y < 0 || x >= w as i64 || y >= h as i64 {
                return false;
            }
            let p = pixmap.pixel(x as u32, y as u32).unwrap();
            let d: i32 = [p.red() as i32, p.green() as i32, p.blue() as i32]
                .iter()
                .zip(want)
                .map(|(a, b)| (a - b).abs())
                .sum();
            d < 40
        };
        // the exact curve, densely, in pixels
        let exact: Vec<(f64, f64)> = (0..=2000)
            .map(|k| {
                let p = c.eval(&q(k, 2000)).to_f64();
                map.to_screen(p[0], p[1])
            })
            .collect();
        // dots and labels are drawn over the curve in a few places (b₀, bₙ, b(t)): allow
        // a few samples to be hidden, never a whole stretch
        let samples: Vec<_> = exact.iter().step_by(20).collect();
        let hidden: Vec<_> = samples
            .iter()
            .filter(|(x, y)| {
                !(-2..=2).any(|dx| (-2..=2).any(|dy| is_curve(x.round() as i64 + dx, y.round() as i64 + dy)))
            })
            .collect();
        assert!(hidden.len() * 10 <= samples.len(), "no curve pixels near {hidden:?}");
        let bottom = exact.iter().map(|p| p.1).fold(0.0, f64::max) + 4.0; // below: the notes' swatches
        let mut count = 0;
        for y in 0..(bottom as u32).min(h) {
            for x in 0..w {
                if is_curve(x as i64, y as i64) {
                    count += 1;
                    let (fx, fy) = (x as f64 + 0.5, y as f64 + 0.5);
                    let near = exact.iter().any(|(ex, ey)| (ex - fx).hypot(ey - fy) <= 3.0);
                    assert!(near, "a curve-coloured pixel at ({x}, {y}) is off the exact curve");
                }
            }
        }
        assert!(count > 200, "only {count} curve pixels");
    }
}

#[test]
fn the_command_writes_the_svg() {
    let dir = std::env::temp_dir().join(format!("casteljau-figure-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("c.svg");
    let run = Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .args(["figure", "construction", "0,0; 1,2; 3,2; 4,0", "--t", "1/4", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    let svg = std::fs::read_to_string(&out).unwrap();
    let (titles, _) = check_svg(&svg);
    assert_eq!(titled(&titles, "b₀³(1/4) = "), "(29/32, 9/8)");
    let bad = Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .args(["figure", "spiral"])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("unknown figure 'spiral'"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn committed_figures_are_what_the_command_draws() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/figures");
    for kind in FigureKind::ALL {
        let path = dir.join(format!("{}.svg", kind.name()));
        let committed = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let drawn = FigureRequest::new(kind).figure().unwrap().to_svg().unwrap();
        assert!(
            committed == drawn,
            "{} is stale: run `casteljau figure {} -o {}`",
            path.display(),
            kind.name(),
            path.display()
        );
    }
}

/// `B_i^n(a/b) = C(n, i) a^i (b − a)^(n−i) / b^n`, in integers.
fn bernstein_by_hand(i: usize, n: usize, t: &BigRational) -> BigRational {
    use casteljau::BigInt;
    let (a, b) = (t.numer().clone(), t.denom().clone());
    let mut c = BigInt::from(1);
    for k in 0..i {
        c = c * BigInt::from(n - k) / BigInt::from(k + 1);
    }
    let num = c * num_pow(&a, i) * num_pow(&(&b - &a), n - i);
    BigRational::new(num, num_pow(&b, n))
}

fn num_pow(x: &casteljau::BigInt, k: usize) -> casteljau::BigInt {
    (0..k).fold(casteljau::BigInt::from(1), |p, _| p * x)
}

#[test]
fn bernstein_values_are_the_exact_basis_and_are_plotted_there() {
    for (n, t) in [(3, q(1, 3)), (7, q(2, 5)), (1, q(1, 1))] {
        let fig = figure::bernstein_basis(n, &t).unwrap();
        let svg = fig.to_svg().unwrap();
        let (titles, notes) = check_svg(&svg);
        let map = fig.layout().panels[0];
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let mut sum = q(0, 1);
        for i in 0..=n {
            let exact = bernstein_by_hand(i, n, &t);
            sum += exact.clone();
            let name = figure::svg::indexed("B", &i.to_string(), Some(&n.to_string()));
            let prefix = format!("{name}({t}) = ");
            assert_eq!(titled(&titles, &prefix), exact.to_string());
            assert!(notes.contains(&format!("{prefix}{exact}")), "{notes:?}");
            // the dot is drawn at (t, B_i^n(t))
            let dot = doc
                .descendants()
                .find(|d| {
                    d.has_tag_name("circle")
                        && d.first_child().and_then(|c| c.text()) == Some(&format!("{prefix}{exact}"))
                })
                .unwrap();
            let (x, y) = map.to_screen(t.to_f64(), exact.to_f64());
            let at = |a: &str| dot.attribute(a).unwrap().parse::<f64>().unwrap();
            assert!((at("cx") - x).abs() < 0.01 && (at("cy") - y).abs() < 0.01, "{name}");
        }
        assert_eq!(sum, q(1, 1));
    }
    // the request: defaults, limits, bad input
    let fig = FigureRequest::new(FigureKind::Bernstein).figure().unwrap();
    assert!(
        fig.title().contains("at t = 1/3") && fig.notes()[0] == "B₀³(1/3) = 8/27",
        "{:?}",
        fig.notes()
    );
    let mut r = FigureRequest::new(FigureKind::Bernstein);
    r.t = Some("3/2".into());
    assert!(r.figure().unwrap_err().to_string().contains("[0, 1]"));
    r.t = Some(format!("1/{}", "7".repeat(300)));
    r.degree = Some("64".into());
    let e = r.figure().unwrap_err().to_string();
    assert!(e.contains("degree × bits of --t") && e.contains("limit 4096"), "{e}");
    r.degree = Some("65".into());
    assert!(r.figure().unwrap_err().to_string().contains("limit 64"));
    let mut r = FigureRequest::new(FigureKind::Bernstein);
    r.input = Some("0,0; 1,1".into());
    assert!(r.figure().unwrap_err().to_string().contains("no control points"));
}

#[test]
fn projection_points_are_the_parabola_divided_by_its_height() {
    for input in [figure::DEFAULT_PARABOLA, "3,-2,1; 1,0,3; 3,2,1"] {
        let mut r = FigureRequest::new(FigureKind::Projection);
        r.input = Some(input.into());
        let (titles, notes) = check_svg(&r.figure().unwrap().to_svg().unwrap());
        let p: Vec<Vec<BigRational>> = casteljau::parse_points(input)
            .unwrap()
            .iter()
            .map(|p| p.coords().to_vec())
            .collect();
        let divided = |v: &[BigRational]| format!("({}, {})", &v[0] / &v[2], &v[1] / &v[2]);
        for (i, v) in p.iter().enumerate() {
            let b = format!("{}, weight {}", divided(v), v[2]);
            assert_eq!(titled(&titles, &format!("b{} = ", ['₀', '₁', '₂'][i])), b);
        }
        // p(1/2) = (p0 + 2 p1 + p2)/4 and its projection
        let half: Vec<BigRational> = (0..3)
            .map(|k| (&p[0][k] + &(&p[1][k] * q(2, 1)) + &p[2][k]) * q(1, 4))
            .collect();
        let line = format!(
            "p(1/2) = ({}, {}, {}) projects to x(1/2) = {}",
            half[0],
            half[1],
            half[2],
            divided(&half)
        );
        assert!(notes.contains(&line), "{line} not in {notes:?}");
    }
    let mut r = FigureRequest::new(FigureKind::Projection);
    r.input = Some("1,0,1; 1,1,0; 0,2,2".into());
    assert!(r.figure().unwrap_err().to_string().contains("z > 0"));
    r.input = Some("1,0; 1,1; 0,2".into());
    assert!(r.figure().unwrap_err().to_string().contains("quadratic in space"));
}

/// The hull figure's weights, read back from its legend: index → λ.
fn legend_weights(notes: &[String]) -> Option<Vec<(usize, BigRational)>> {
    let all = notes.join("\n").replace("\n    ", " ");
    let line = all.lines().find(|l| l.contains("= Σ λᵢ bᵢ with "))?;
    let terms = &line[line.find(" with ").unwrap() + 6..];
    Some(
        terms
            .split(", ")
            .map(|term| {
                let (name, value) = term.split_once(" = ").unwrap();
                let index: String = name
                    .trim_start_matches('λ')
                    .chars()
                    .map(|c| char::from_digit(c as u32 - '₀' as u32, 10).unwrap())
                    .collect();
                (index.parse().unwrap(), value.parse().unwrap())
            })
            .collect(),
    )
}

#[test]
fn hull_certificates_in_space_are_exact_and_outside_agrees_with_the_library() {
    let c = BezierCurve::new(
        casteljau::parse_points("0,0,0; 5,-2,1; -3,4,2; 2,2,-4; 6,1,3; -1,-3,0; 4,4,4; 1,0,-2").unwrap(),
    )
    .unwrap();
    let mut points: Vec<Point<BigRational>> = (0..=9).map(|k| c.eval(&q(k, 9))).collect();
    points.extend(c.points().iter().cloned());
    points.push(Point::new(vec![q(1, 2), q(1, 3), q(1, 5)]).unwrap());
    points.push(Point::new(vec![q(9, 1), q(9, 1), q(9, 1)]).unwrap());
    points.push(Point::new(vec![q(7, 1), q(-3, 1), q(0, 1)]).unwrap());
    // just beyond a control point, and on an edge between two
    points.push(Point::new(vec![q(6001, 1000), q(1, 1), q(3, 1)]).unwrap());
    points.push(Point::new(vec![q(-3, 1), q(4, 1), q(2001, 1000)]).unwrap());
    points.push(Point::new(vec![q(5, 2), q(-1, 1), q(1, 2)]).unwrap());
    let (mut inside, mut outside) = (0, 0);
    for p in &points {
        let (_, notes) = check_svg(&figure::hull(&c, p).unwrap().to_svg().unwrap());
        match legend_weights(&notes) {
            Some(w) => {
                inside += 1;
                let mut sum = q(0, 1);
                let mut combination = vec![q(0, 1); 3];
                for (i, l) in &w {
                    assert!(*l >= q(0, 1), "λ{i} = {l} < 0 for {p}");
                    sum += l.clone();
                    for (k, x) in combination.iter_mut().enumerate() {
                        *x += l.clone() * c.points()[*i].coords()[k].clone();
                    }
                }
                assert_eq!(sum, q(1, 1), "{p}");
                assert_eq!(combination, p.coords(), "{p}");
                assert!(c.hull_weights(p).unwrap().is_some());
            }
            None => {
                outside += 1;
                assert!(notes.iter().any(|n| n.contains("no convex weights exist")));
                assert!(c.hull_weights(p).unwrap().is_none(), "{p}");
            }
        }
    }
    assert!(inside >= 10 && outside >= 1, "{inside} inside, {outside} outside");
}

#[test]
fn coinciding_points_draw() {
    // issue 41: "coordinate (5, 5) is beyond the range of f64" after 390 MB
    let dir = std::env::temp_dir().join(format!("casteljau-figure-coinciding-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (kind, points) in [
        ("construction", "5,5"),
        ("hull", "0,0; 0,0"),
        ("construction", "1e-200,0; 1e-200,0"),
        ("subdivision", "3,-7; 3,-7; 3,-7"),
    ] {
        let out = dir.join(format!("{kind}.svg"));
        let run = Command::new(env!("CARGO_BIN_EXE_casteljau"))
            .args(["figure", kind, points, "-o"])
            .arg(&out)
            .output()
            .unwrap();
        assert!(
            run.status.success(),
            "{kind} {points}: {}",
            String::from_utf8_lossy(&run.stderr)
        );
        check_svg(&std::fs::read_to_string(&out).unwrap());
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
