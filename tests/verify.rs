//! The engine: false claims are caught with exact counterexamples, true ones proved, the
//! convergence bound is true, reports and explain say what was checked.

use casteljau::verify::check_claim;
use casteljau::verify::claims::parse_file;
use casteljau::verify::elevation_bound;
use casteljau::verify::{explain, prove_paths, ExplainStyle, Verdict};
use casteljau::{BezierCurve, BigRational, Point, Ring, Scalar};
use proptest::prelude::*;
use std::path::{Path, PathBuf};

fn check(toml: &str) -> casteljau::Result<(Verdict, String)> {
    let f = parse_file(toml, Path::new("test.toml"))?;
    let out = check_claim(&f.claim[0], false)?;
    Ok((out.verdict(), out.certificate))
}

fn identity(lhs: &str, rhs: &str, extra: &str) -> casteljau::Result<(Verdict, String)> {
    check(&format!(
        "[[claim]]\nid = \"x\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nlhs = \"{lhs}\"\nrhs = \"{rhs}\"\n{extra}"
    ))
}

#[test]
fn a_wrong_coefficient_fails_with_a_counterexample() {
    let (v, c) = identity("-(2t-1)^2 + 1", "4/3 B(1,3,t) + 5/3 B(2,3,t)", "").unwrap();
    assert_eq!(v, Verdict::Fails);
    assert!(
        c.contains("t = ") && c.contains("left side = ") && c.contains("right side = "),
        "{c}"
    );
    let (v, _) = identity("-(2t-1)^2 + 1", "4/3 B(1,3,t) + 4/3 B(2,3,t)", "").unwrap();
    assert_eq!(v, Verdict::Proved);
}

#[test]
fn agreeing_at_a_few_points_is_not_a_proof() {
    // t³ = t at t = 0, 1, −1: the derived degree 3 needs four points.
    let (v, c) = identity("t^3", "t", "").unwrap();
    assert_eq!(v, Verdict::Fails, "{c}");
    // (t − 0)(t − 1/2)(t − 1)… vanishes at the first candidates; degree 4 needs five points.
    let (v, _) = identity("t(t - 1/4)(t - 1/2)(t - 3/4)", "0", "").unwrap();
    assert_eq!(v, Verdict::Fails);
}

#[test]
fn rational_functions_skip_poles_and_zero_denominators_are_errors() {
    let (v, c) = identity("(t^2 - 1)/(t - 1)", "t + 1", "").unwrap();
    assert_eq!(v, Verdict::Proved, "{c}");
    assert!(c.contains("denominator"), "{c}");
    let err = identity("1/(t - t)", "1", "").unwrap_err().to_string();
    assert!(err.contains("zero polynomial") || err.contains("denominator"), "{err}");
}

#[test]
fn ranges_and_polygons() {
    let (v, c) = identity(
        "sum(i, 0, n, b[i]*B(i, n, t))",
        "sum(i, 0, n+1, (i/(n+1)*b[i-1] + (1 - i/(n+1))*b[i])*B(i, n+1, t))",
        "polygon = { name = \"b\", degree = \"n\" }\nfor = [\"n = 0..=5\"]",
    )
    .unwrap();
    assert_eq!(v, Verdict::ProvedInRange, "{c}");
    assert!(c.contains("n = 0..=5") && c.contains("basis polygons"), "{c}");
    // a wrong elevation weight is caught on some unit polygon
    let (v, c) = identity(
        "sum(i, 0, n, b[i]*B(i, n, t))",
        "sum(i, 0, n+1, (i/(n+2)*b[i-1] + (1 - i/(n+2))*b[i])*B(i, n+1, t))",
        "polygon = { name = \"b\", degree = \"n\" }\nfor = [\"n = 0..=5\"]",
    )
    .unwrap();
    assert_eq!(v, Verdict::Fails);
    assert!(c.contains("b[") && c.contains("n = "), "{c}");
    // a product of control points is refused, not mis-proved
    let err = identity("b[0]*b[1]", "0", "polygon = { name = \"b\", degree = \"2\" }").unwrap_err();
    assert!(err.to_string().contains("affine"), "{err}");
}

#[test]
fn symbolic_claims() {
    let (v, _) = identity(
        "dot(a + b, a + b)",
        "dot(a, a) + 2 dot(a, b) + dot(b, b)",
        "vectors = { a = 3, b = 3 }",
    )
    .unwrap();
    assert_eq!(v, Verdict::Proved);
    let (v, c) = identity(
        "dot(a + b, a + b)",
        "dot(a, a) + dot(b, b)",
        "vectors = { a = 3, b = 3 }",
    )
    .unwrap();
    assert_eq!(v, Verdict::Fails);
    assert!(c.contains("left side"), "{c}");
}

#[test]
fn conic_types_and_misnamed_conics() {
    let conic = |eq: &str, kind: &str| {
        check(&format!(
            "[[claim]]\nid = \"x\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"conic_type\"\nequation = \"{eq}\"\nconic = \"{kind}\""
        ))
        .unwrap()
        .0
    };
    assert_eq!(conic("4x^2 + 3y^2 - 10y + 3 = 0", "ellipse"), Verdict::Proved);
    assert_eq!(conic("4x^2 + 3y^2 - 10y + 3 = 0", "hyperbola"), Verdict::Fails);
    assert_eq!(conic("y = x^2", "parabola"), Verdict::Proved);
    // one classifier for claims and the library: no real points, no quadratic terms, a line pair
    let imaginary = "imaginary ellipse (no real points)";
    assert_eq!(conic("x^2 + y^2 + 1 = 0", imaginary), Verdict::Proved);
    assert_eq!(conic("x^2 + y^2 + 1 = 0", "ellipse"), Verdict::Fails);
    assert_eq!(conic("x^2 + y^2 - 1 = 0", "ellipse"), Verdict::Proved);
    assert_eq!(
        conic("2x + y + 1 = 0", "not a conic (no quadratic terms)"),
        Verdict::Proved
    );
    assert_eq!(conic("x^2 - y^2 = 0", "degenerate"), Verdict::Proved);
    let kind = |k: [i64; 6]| casteljau::ImplicitConic::<BigRational>::from_ints(k).kind();
    assert_eq!(kind([1, 0, 1, 0, 0, 1]), casteljau::ConicKind::ImaginaryEllipse);
    assert_eq!(kind([-1, 0, -1, 0, 0, -1]), casteljau::ConicKind::ImaginaryEllipse);
    assert_eq!(kind([1, 0, 1, 0, 0, -1]), casteljau::ConicKind::Ellipse);
    assert_eq!(kind([-1, 0, -1, 0, 0, 1]), casteljau::ConicKind::Ellipse);
    assert_eq!(kind([0, 0, 0, 2, 1, 1]), casteljau::ConicKind::NoQuadraticTerms);
    assert_eq!(kind([1, 0, -1, 0, 0, 0]), casteljau::ConicKind::DegenerateSingular);
}

#[test]
fn bad_claim_files_are_clear_errors() {
    let err = parse_file("[[claim]]\nid = \"x\"\n", Path::new("t.toml"))
        .unwrap_err()
        .to_string();
    assert!(err.contains("missing field"), "{err}");
    let err = identity("t", "t", "colour = 1").unwrap_err().to_string();
    assert!(err.contains("unknown field"), "{err}");
    let err = identity("t", "t", "expect = \"maybe\"").unwrap_err().to_string();
    assert!(err.contains("expect"), "{err}");
    let err = check("[[claim]]\nid = \"x\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"magic\"").unwrap_err();
    assert!(err.to_string().contains("unknown kind"));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// The O(1/r) bound used for Theorem 1.2 holds for random exact curves.
    #[test]
    fn elevation_bound_is_true(coords in prop::collection::vec((-20i64..20, -20i64..20), 1..7), r in 0usize..12) {
        let pts: Vec<Point<BigRational>> = coords.iter().map(|&(x, y)| Point::from_ints(&[x, y]).unwrap()).collect();
        let curve = BezierCurve::new(pts).unwrap();
        let d = curve.elevation_distance(r).unwrap();
        let bound = elevation_bound(&curve, r).unwrap();
        prop_assert!(d.max_norm <= bound, "r = {}: {} > {}", r, d.max_norm, bound);
    }
}

#[test]
fn report_and_explain() {
    let report = prove_paths(&[PathBuf::from("proofs/000_ef6a3958c7d702f5.toml")], &mut |_, _, _| {}).unwrap();
    let text = report.to_text();
    assert!(text.contains("000-ex4-y") && text.contains("counterexample") && text.contains("summary"));
    let json = report.to_json();
    assert_eq!(json["summary"]["texts"][0]["text"], "000_ef6a3958c7d702f5.txt");
    assert!(json["claims"][0]["certificate"].is_string());
    let ex = explain(&[PathBuf::from("proofs")], "000-ex4-curve", ExplainStyle::Verbose).unwrap();
    assert!(
        ex.contains("de Casteljau scheme (9)") && ex.contains("both sides ="),
        "{ex}"
    );
    assert!(explain(&[PathBuf::from("proofs")], "no-such-id", ExplainStyle::Short).is_err());
    let one = BigRational::from_i64(1);
    assert_eq!(Scalar::to_f64(&one), 1.0);
}

#[test]
fn fit_claims_check_the_printed_numbers_exactly() {
    let claim = |extra: &str| {
        check(&format!(
            "[[claim]]\nid = \"f\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"fit\"\n\
             curves = {{ x = {{ points = [[0, 1, 0], [\"1/4\", 1, 0], [\"1/2\", \"7/6\", 0], [\"3/4\", \"3/2\", 0], [1, 2, 1]] }} }}\n{extra}"
        ))
    };
    // x(t) = (t, 1 + t², t⁴): k = l = 3/10, δ² = 1/1280.
    let (v, c) = claim("k = \"3/10\"\nl = \"3/10\"\ndelta2 = \"1/1280\"").unwrap();
    assert_eq!(v, Verdict::Proved, "{c}");
    let (v, c) = claim("delta2 = \"1/1281\"").unwrap();
    assert_eq!(v, Verdict::Fails, "{c}");
    assert!(c.contains("printed δ² = 1/1281, computed δ² = 1/1280"), "{c}");
    // Parallel end tangents: the normal equations are singular, a clear error, not a verdict.
    let err = check(
        "[[claim]]\nid = \"f\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"fit\"\n\
         curves = { x = { points = [[0, 0, 0], [1, 0, 0], [2, 1, 0], [3, 1, 0]] } }",
    )
    .unwrap_err()
    .to_string();
    assert!(err.contains("singular") || err.contains("parallel"), "{err}");
}

/// `--explain` by default: the argument and one worked case on one screen, the worked case's
/// numbers being the library's (the scheme (9) from `BezierCurve::scheme`, the sum from it).
#[test]
fn explain_fits_one_screen_with_a_case_worked_exactly() {
    let proofs = [PathBuf::from("tests/support/subdivision_in_range.toml")];
    let id = "lemma-1.3-proof-in-range";
    let short = explain(&proofs, id, ExplainStyle::Short).unwrap();
    // the proof on one screen; its certificate file read back follows (tests/certificate_view.rs)
    let (proof, _) = short.split_once("\n\ncertificate file ").expect(&short);
    let lines: Vec<&str> = proof.lines().collect();
    assert!(lines.len() <= 40, "{} lines:\n{short}", lines.len());
    assert!(
        short.contains("why this suffices:") && short.contains("d+1 distinct points"),
        "{short}"
    );
    assert!(!short.contains("\nsteps:"), "{short}");
    assert!(short.contains(&format!("--explain {id} --verbose")), "{short}");

    // the first shown evaluation of the worked case, n = 3: `… t0 = a, t = s, b[k] = 1 …: both sides = v`
    let eval = lines
        .iter()
        .find(|l| l.trim_start().starts_with("n = 3, t0 = "))
        .expect(&short);
    let field = |name: &str| -> BigRational {
        let head = eval.split(':').next().unwrap();
        let part = head
            .split(", ")
            .find(|p| p.trim().starts_with(&format!("{name} = ")))
            .unwrap();
        part.split(" = ").nth(1).unwrap().trim().parse().unwrap()
    };
    let (t0, t) = (field("t0"), field("t"));
    let unit: usize = eval
        .split("b[")
        .nth(1)
        .unwrap()
        .split(']')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    let value: BigRational = eval.rsplit("both sides = ").next().unwrap().trim().parse().unwrap();

    // the printed scheme is the library's scheme of that unit polygon at t0, byte for byte
    let polygon: Vec<Point<BigRational>> = (0..=3)
        .map(|j| Point::from_ints(&[i64::from(j == unit)]).unwrap())
        .collect();
    let scheme = BezierCurve::new(polygon).unwrap().scheme(&t0);
    assert!(short.contains(&scheme.to_string()), "{short}\nexpected:\n{scheme}");

    // the written-out sum Σ_r b_0^r(t0) B_r^3(t) is the library's and equals both sides
    let sum = (0..=3).fold(BigRational::from_i64(0), |acc, r| {
        let edge = scheme.get(r, 0).unwrap().coords()[0].clone();
        acc + edge * casteljau::bernstein(r, 3, &t).unwrap()
    });
    assert_eq!(sum, value);
    let sum_line = lines
        .iter()
        .find(|l| l.trim_start().starts_with("Σ_r b_0^r(t0)"))
        .expect(&short);
    assert!(
        sum_line.contains(&format!("= {value} (the first evaluation)")),
        "{sum_line}"
    );

    // --verbose keeps the whole log; LaTeX has the same scheme as an array
    let verbose = explain(&proofs, id, ExplainStyle::Verbose).unwrap();
    assert!(verbose.starts_with(short.split("\nthe full log").next().unwrap()));
    assert!(verbose.contains("\nsteps:") && verbose.lines().count() > 1000);
    let latex = explain(&proofs, id, ExplainStyle::Latex).unwrap();
    assert!(
        latex.contains(&scheme.to_latex()) && latex.contains("\\begin{array}{llll}"),
        "{latex}"
    );
    assert!(!latex.contains('Σ') && !latex.contains('≤'), "{latex}");

    // other long logs fit on a screen too
    for id in [
        "003-tensor",
        "000-4-proof-ratio",
        "000-derivative-proof",
        "000-ex4-curve",
        "000-lemma-1.3-proof",
    ] {
        let text = explain(&[PathBuf::from("proofs")], id, ExplainStyle::Short).unwrap();
        let (text, _) = text.split_once("\n\ncertificate file ").expect(&text);
        assert!(
            text.lines().count() <= 40,
            "{id}: {} lines\n{text}",
            text.lines().count()
        );
    }
}

#[test]
fn det_and_inv_beyond_four_by_four() {
    // det(tI + P) for the cyclic shift P of size 5 is t^5 + 1 (Berkowitz beyond 4 × 4).
    let m = "[t, 1, 0, 0, 0; 0, t, 1, 0, 0; 0, 0, t, 1, 0; 0, 0, 0, t, 1; 1, 0, 0, 0, t]";
    let vars = "vars = [\"t\"]";
    assert_eq!(
        identity(&format!("det({m})"), "t^5 + 1", vars).unwrap().0,
        Verdict::Proved
    );
    let (v, c) = identity(&format!("det({m})"), "t^5 - 1", vars).unwrap();
    assert_eq!(v, Verdict::Fails);
    assert!(c.contains("t = 0") && c.contains("left side = 1"), "{c}");
    // inv of a 6 × 6 matrix (Cayley–Hamilton with Berkowitz's coefficients).
    let a =
        "[2, 0, 0, 0, 0, 0; 0, 1, 0, 0, 0, 0; 0, 0, 1, 0, 0, 0; 0, 0, 0, 1, 0, 0; 0, 0, 0, 0, 1, t; 0, 0, 0, 0, 0, 1]";
    let a_inv = "[1/2, 0, 0, 0, 0, 0; 0, 1, 0, 0, 0, 0; 0, 0, 1, 0, 0, 0; 0, 0, 0, 1, 0, 0; 0, 0, 0, 0, 1, -t; 0, 0, 0, 0, 0, 1]";
    assert_eq!(identity(&format!("inv({a})"), a_inv, vars).unwrap().0, Verdict::Proved);
    let wrong = a_inv.replace("-t", "t");
    assert_eq!(identity(&format!("inv({a})"), &wrong, vars).unwrap().0, Verdict::Fails);
    // Past the documented size: a clear error.
    let big = format!("[{}]", vec![vec!["1"; 17].join(", "); 17].join("; "));
    let e = identity(&format!("det({big})"), "0", "").unwrap_err().to_string();
    assert!(e.contains("at most 16"), "{e}");
}

#[test]
fn derivatives_of_rational_curve_objects() {
    // The quarter circle of text 001 Ex. 1 as a rational quadratic: b' and b'' are the
    // derivatives of ((1 − t²)/(1 + t²), 2t/(1 + t²)), computed by the library's rational
    // derivative; a wrong denominator fails with a counterexample.
    let curve = "vars = [\"t\"]\ncurves = { b = { points = [[1, 0], [1, 1], [0, 1]], weights = [1, 1, 2] } }";
    let d1 = "(-4t/(1+t^2)^2, 2(1-t^2)/(1+t^2)^2)";
    assert_eq!(identity("b'(t)", d1, curve).unwrap().0, Verdict::Proved);
    assert_eq!(identity("diff(b(t), t)", d1, curve).unwrap().0, Verdict::Proved);
    assert_eq!(
        identity("b''(t)", &format!("diff({d1}, t)"), curve).unwrap().0,
        Verdict::Proved
    );
    let (v, c) = identity("b'(t)", "(-4t/(1+t^2)^2, 2(1-t^2)/(1+t^2))", curve).unwrap();
    assert_eq!(v, Verdict::Fails, "{c}");
    let e = identity("b''''(t)", "b''''(t)", curve).unwrap_err().to_string();
    assert!(e.contains("at most 3 times"), "{e}");
}

#[test]
fn vanishes_is_the_identity_it_states() {
    let v = |body: &str| {
        check(&format!(
            "[[claim]]\nid = \"x\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"vanishes\"\n{body}"
        ))
    };
    // for every value, for a range, and for every n (the alternating binomial sum, n ≥ 1)
    assert_eq!(
        v("vars = [\"t\"]\nexpr = \"B(0, 2, t) + B(1, 2, t) + B(2, 2, t) - 1\"")
            .unwrap()
            .0,
        Verdict::Proved
    );
    assert_eq!(
        v("for = [\"n = 1..=6\"]\nexpr = \"sum(k, 0, n, (-1)^k*C(n, k))\"")
            .unwrap()
            .0,
        Verdict::ProvedInRange
    );
    let pascal = |rhs: &str| {
        v(&format!(
            "for = [\"n = 0..\", \"k = 1..=n+1\"]\nexpr = \"C(n+2, k) - {rhs}\""
        ))
    };
    let (verdict, cert) = pascal("C(n+1, k) - C(n+1, k-1)").unwrap();
    assert_eq!(verdict, Verdict::Proved, "{cert}");
    // false: n = 0 gives 1, a shifted index for every n, a wrong sign, a nonzero polynomial
    assert_eq!(
        v("for = [\"n = 0..=6\"]\nexpr = \"sum(k, 0, n, (-1)^k*C(n, k))\"")
            .unwrap()
            .0,
        Verdict::Fails
    );
    assert_eq!(pascal("C(n+1, k) - C(n+1, k+1)").unwrap().0, Verdict::Fails);
    assert_eq!(
        v("vars = [\"t\"]\nexpr = \"B(0, 2, t) - B(1, 2, t) + B(2, 2, t) - 1\"")
            .unwrap()
            .0,
        Verdict::Fails
    );
    assert_eq!(v("vars = [\"t\"]\nexpr = \"t^5 - t^4\"").unwrap().0, Verdict::Fails);
    let err = v("expr = \"0\"\nlhs = \"1\"").unwrap_err().to_string();
    assert!(err.contains("unknown field `lhs`"), "{err}");
}
