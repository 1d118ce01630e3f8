//! Common mistakes in a claim file, each answered with the line and the expected syntax of
//! the field (not serde's bare "invalid type: map, expected a sequence").

use casteljau::verify::claims::parse_file;
use std::path::Path;

const HEAD: &str = "[[claim]]\nid = \"x\"\nsource = \"s\"\nstatement = \"s\"\n";

/// The error for a claim of `kind` (with `body`, lines 6 on), which must be refused.
fn error(kind: &str, body: &str) -> String {
    let text = format!("{HEAD}kind = \"{kind}\"\n{body}\n");
    match parse_file(&text, Path::new("my.toml")) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn ten_common_mistakes_each_get_the_expected_syntax() {
    let identity = "lhs = \"sum(k, 0, n, C(n, k))\"\nrhs = \"2^n\"";
    let cases: [(&str, String, &str, &str); 12] = [
        // a map for the list of ranges (the issue's example)
        (
            "identity",
            format!("{identity}\nfor = {{ n = \"0..\" }}"),
            "my.toml:8:",
            r#"for = ["n = 0..=10", "j = 0..=n"] or, for every n, for = ["n = 0.."]"#,
        ),
        // one range not in a list
        (
            "identity",
            format!("{identity}\nfor = \"n = 0..\""),
            "my.toml:8:",
            r#"for = ["n = 0..=10""#,
        ),
        // a Rust-style half-open range
        (
            "identity",
            format!("{identity}\nfor = [\"n = 0..10\"]"),
            "my.toml:8:",
            "a range is written 'n = 0..=10' or 'n = 0..'",
        ),
        // one parameter not in a list
        (
            "identity",
            "lhs = \"t\"\nrhs = \"t\"\nvars = \"t\"".into(),
            "my.toml:8:",
            r#"vars = ["t"]"#,
        ),
        // a polygon's degree as a number
        (
            "identity",
            "lhs = \"1\"\nrhs = \"1\"\npolygon = { name = \"b\", degree = 3 }".into(),
            "my.toml:8:",
            r#"polygon = { name = "b", degree = "n" }"#,
        ),
        // a net's two degrees in one string
        (
            "identity",
            "lhs = \"1\"\nrhs = \"1\"\nnet = { name = \"b\", degree = \"m, n\" }".into(),
            "my.toml:8:",
            r#"net = { name = "b", degree = ["m", "n"] }"#,
        ),
        // a curve given as its bare points
        (
            "identity",
            "lhs = \"1\"\nrhs = \"1\"\ncurves = { b = [[0, 0], [1, 1]] }".into(),
            "my.toml:8:",
            r#"curves = { b = { points = [[0, 0]"#,
        ),
        // a definition not in a list
        (
            "implies",
            "premise = \"k\"\nequation = \"k = 0\"\nfactor = \"1\"\nsymbols = [\"k\"]\nlet = \"X = 1\"".into(),
            "my.toml:10:",
            r#"let = ["X = x0 + x1 - 2xh""#,
        ),
        // vectors as a list of names, without their dimensions
        (
            "implies",
            "premise = \"k\"\nequation = \"k = 0\"\nfactor = \"1\"\nvectors = [\"x0\"]".into(),
            "my.toml:9:",
            "vectors = { x0 = 3, d0 = 3 }",
        ),
        // a misspelt verdict
        (
            "identity",
            "lhs = \"1\"\nrhs = \"1\"\nexpect = \"proven\"".into(),
            "my.toml:8:",
            r#"one of "proved", "proved_in_range", "verified", "fails""#,
        ),
        // a misspelt kind
        (
            "identiy",
            "lhs = \"1\"\nrhs = \"1\"".into(),
            "my.toml:5:",
            "identity, implicit, bezier_points",
        ),
        // only one side of an identity
        (
            "identity",
            "lhs = \"1\"".into(),
            "the claim at line 1",
            r#"lhs = "(1 - t)^2" and rhs = "B(0, 2, t)""#,
        ),
    ];
    for (kind, body, line, syntax) in cases {
        let err = error(kind, &body);
        assert!(err.contains(line), "{body}\n=> {err}\n(expected the line {line})");
        assert!(err.contains(syntax), "{body}\n=> {err}\n(expected the syntax {syntax})");
        assert!(err.contains("expected"), "{err}");
    }
}

#[test]
fn a_single_table_for_an_array_of_claims_and_a_missing_field() {
    let text =
        "[claim]\nid = \"x\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nlhs = \"1\"\nrhs = \"1\"\n";
    let err = parse_file(text, Path::new("my.toml")).unwrap_err().to_string();
    assert!(
        err.contains("my.toml:1: [claim] is a single table") && err.contains("[[claim]]"),
        "{err}"
    );
    let text = "[[claim]]\nid = \"x\"\nstatement = \"s\"\nkind = \"identity\"\nlhs = \"1\"\nrhs = \"1\"\n";
    let err = parse_file(text, Path::new("my.toml")).unwrap_err().to_string();
    assert!(err.contains("missing field `source`; expected: source = \""), "{err}");
    // the line is the field's own, in the second claim of a file
    let two = format!("{HEAD}kind = \"identity\"\nlhs = \"1\"\nrhs = \"1\"\n\n{}kind = \"identity\"\nlhs = \"1\"\nrhs = \"1\"\nuses = \"x\"\n", HEAD.replace("\"x\"", "\"y\""));
    let err = parse_file(&two, Path::new("my.toml")).unwrap_err().to_string();
    assert!(
        err.contains("my.toml:16: claim y: ") && err.contains(r#"uses = ["000-9-intermediate"]"#),
        "{err}"
    );
    // a correct file still reads
    let ok = format!("{HEAD}kind = \"identity\"\nlhs = \"1\"\nrhs = \"1\"\nfor = [\"n = 0..\"]\n");
    assert!(parse_file(&ok, Path::new("my.toml")).is_ok());
}
