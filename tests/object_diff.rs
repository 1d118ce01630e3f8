//! `diff` of claim objects: partials of surfaces and nets (`x_u(u, v)`, `diff(x(u, v), u)`),
//! derivatives of curve objects (`diff(b(t), t)` = `b'(t)`); false variants fail with exact
//! values, and misuse is a one-line error.

use casteljau::verify::claims::parse_file;
use casteljau::verify::kinds::check_claim;
use casteljau::verify::Verdict;
use std::path::Path;

fn check(body: &str) -> casteljau::Result<(Verdict, String)> {
    let f = parse_file(
        &format!("[[claim]]\nid = \"x\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\n{body}"),
        Path::new("test.toml"),
    )?;
    let out = check_claim(&f.claim[0], false)?;
    Ok((out.verdict, out.certificate))
}

fn verdict(body: &str) -> Verdict {
    let (v, c) = check(body).unwrap_or_else(|e| panic!("{body}: {e}"));
    println!("{c}");
    v
}

fn fails(body: &str) -> String {
    let (v, c) = check(body).unwrap_or_else(|e| panic!("{body}: {e}"));
    assert_eq!(v, Verdict::Fails, "{body}: {c}");
    c
}

fn error(body: &str) -> String {
    let err = check(body).expect_err(body).to_string();
    assert!(!err.contains('\n'), "one line: {err}");
    err
}

/// The bilinear example of text 003: x(u, v) = (u, v, uv).
const PARABOLOID: &str =
    "surfaces = { x = { net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]] } }\nvars = [\"u\", \"v\"]\n";

/// Text 003, example 1 (m = n = 2): x(u, v) = (2v, 2u, 2u(1 - u) + 2v(1 - v)).
const EX1: &str = "surfaces = { x = { net = [[[0, 0, 0], [1, 0, 1], [2, 0, 0]], [[0, 1, 1], [1, 1, 2], [2, 1, 1]], [[0, 2, 0], [1, 2, 1], [2, 2, 0]]] } }\nvars = [\"u\", \"v\"]\n";

#[test]
fn surface_partials_by_name_and_by_diff() {
    for (lhs, rhs) in [
        ("x_u(u, v)", "(1, 0, v)"),
        ("x_v(u, v)", "(0, 1, u)"),
        ("x_uv(u, v)", "(0, 0, 1)"),
        ("x_vu(u, v)", "(0, 0, 1)"),
        ("x_uu(u, v)", "(0, 0, 0)"),
        ("diff(x(u, v), u)", "(1, 0, v)"),
        ("diff(diff(x(u, v), u), v)", "x_uv(u, v)"),
        ("diff(x(u, v), v, 2)", "(0, 0, 0)"),
    ] {
        let body = format!("{PARABOLOID}lhs = \"{lhs}\"\nrhs = \"{rhs}\"");
        assert_eq!(verdict(&body), Verdict::Proved, "{lhs} = {rhs}");
    }
    for (lhs, rhs) in [
        ("x_u(u, v)", "(0, 2, 2 - 4u)"),
        ("x_vv(u, v)", "(0, 0, -4)"),
        ("x_uuv(u, v)", "(0, 0, 0)"),
        ("diff(x(u, v), v)", "(2, 0, 2 - 4v)"),
    ] {
        let body = format!("{EX1}lhs = \"{lhs}\"\nrhs = \"{rhs}\"");
        assert_eq!(verdict(&body), Verdict::Proved, "{lhs} = {rhs}");
    }
}

#[test]
fn the_chain_rule_through_the_arguments() {
    // d/dt x(t, t^2) = x_u + 2t x_v, and d/dt x(s, 1 - s) with s a constant is 0.
    let body =
        format!("{PARABOLOID}vars = [\"t\"]\nlhs = \"diff(x(t, t^2), t)\"\nrhs = \"x_u(t, t^2) + 2t x_v(t, t^2)\"");
    let body = body.replacen("vars = [\"u\", \"v\"]\n", "", 1);
    assert_eq!(verdict(&body), Verdict::Proved);
    let body = format!("{EX1}lhs = \"diff(x(2u, 3v), u, 2)\"\nrhs = \"4 x_uu(2u, 3v)\"");
    assert_eq!(verdict(&body), Verdict::Proved);
}

#[test]
fn false_partials_fail_with_exact_values() {
    let c = fails(&format!("{PARABOLOID}lhs = \"x_u(u, v)\"\nrhs = \"(1, 0, u)\""));
    assert!(c.contains("left side") && c.contains("right side"), "{c}");
    fails(&format!("{PARABOLOID}lhs = \"diff(x(u, v), v)\"\nrhs = \"(0, 1, v)\""));
    fails(&format!("{EX1}lhs = \"x_uv(u, v)\"\nrhs = \"(0, 0, 1)\""));
}
