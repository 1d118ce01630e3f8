//! `casteljau prove --identity "lhs = rhs"`: one identity from the command line, read as a
//! claim file's `lhs`/`rhs`/`for`/`vars` and given the same verdicts, JSON, `--explain` and
//! exit status (0 proved, 1 fails, 2 bad input or undecidable).

use serde_json::Value;
use std::process::{Command, Output};

fn casteljau(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .args(args)
        .output()
        .unwrap()
}

fn text(out: &Output) -> (i32, String, String) {
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout.clone()).unwrap(),
        String::from_utf8(out.stderr.clone()).unwrap(),
    )
}

#[test]
fn the_binomial_sum_is_proved_for_every_n_and_a_false_one_fails() {
    let (code, out, err) = text(&casteljau(&[
        "prove",
        "--identity",
        "sum(k, 0, n, C(n, k)) = 2^n",
        "--for",
        "n = 0..",
    ]));
    assert_eq!((code, err.as_str()), (0, ""), "{out}");
    assert!(out.starts_with("[proved] identity\n"), "{out}");
    assert!(out.contains("certificate: for every n ≥ 0:"), "{out}");
    let (code, out, _) = text(&casteljau(&[
        "prove",
        "--identity",
        "sum(k, 0, n, C(n, k)) = 3^n",
        "--for",
        "n = 0..",
    ]));
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("[fails] identity\n"), "{out}");
    assert!(
        out.contains("counterexample: at n = 1: left side = 2, right side = 3"),
        "{out}"
    );
    // a finite range is proved in range, with the same verdict as a claim file's
    let (code, out, _) = text(&casteljau(&[
        "prove",
        "--identity",
        "sum(k, 0, n, C(n, k)) = 2^n",
        "--for",
        "n = 0..=5",
    ]));
    assert_eq!(code, 0);
    assert!(out.starts_with("[proved for n = 0..=5] identity\n"), "{out}");
}

#[test]
fn several_ranges_vars_chains_and_json() {
    let out = casteljau(&[
        "prove",
        "--identity",
        "B(i, n, t) = B(n - i, n, 1 - t)",
        "--for",
        "n = 0..",
        "--for",
        "i = 0..=n",
        "--vars",
        "t",
        "--format",
        "json",
    ]);
    let (code, out, _) = text(&out);
    assert_eq!(code, 0, "{out}");
    let v: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["claims"][0]["verdict"], "proved");
    assert_eq!(v["claims"][0]["id"], "identity");
    assert!(v["claims"][0]["range"].is_null());
    // a chain: each step separately; the false step fails
    let (code, out, _) = text(&casteljau(&[
        "prove",
        "--identity",
        "t^2 - t = t(t - 1) = t^2",
        "--format",
        "json",
    ]));
    assert_eq!(code, 1, "{out}");
    let v: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["claims"][0]["verdict"], "fails");
    // --vars is checked as in a claim file: an undeclared name is an error, never a constant
    let (code, out, _) = text(&casteljau(&["prove", "--identity", "x = x", "--vars", "t"]));
    assert_eq!(code, 2, "{out}");
    assert!(out.contains("unknown name 'x'"), "{out}");
}

#[test]
fn explain_needs_no_id_with_an_identity() {
    let (code, out, _) = text(&casteljau(&[
        "prove",
        "--identity",
        "B(1, 2, t) = 2t(1 - t)",
        "--explain",
    ]));
    assert_eq!(code, 0);
    assert!(out.starts_with("claim identity (command line)\n"), "{out}");
    assert!(out.contains("verdict: proved\n"), "{out}");
    let (code, _, err) = text(&casteljau(&["prove", "--explain"]));
    assert_eq!(code, 2);
    assert!(err.contains("--explain needs a claim id"), "{err}");
}

#[test]
fn bad_identities_are_one_line_errors_with_the_expected_form() {
    for (args, says) in [
        (vec!["--identity", "t^2"], "no '=' between two sides"),
        (vec!["--identity", "t <= 2"], "only '=' is an identity's relation"),
        (vec!["--identity", "t == t"], "only '=' is an identity's relation"),
        (vec!["--identity", " = t"], "a side is empty"),
        (
            vec!["--identity", "1 = 1", "--for", "n = 0..10"],
            "a range is written 'n = 0..=10'",
        ),
    ] {
        let mut all = vec!["prove"];
        all.extend(&args);
        let (code, out, err) = text(&casteljau(&all));
        assert_eq!((code, out.as_str()), (2, ""), "{args:?}: {err}");
        assert!(err.contains(says) && err.contains("expected"), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    // --for and --vars belong to --identity, and claim files do not mix with it
    let (code, _, err) = text(&casteljau(&["prove", "--for", "n = 0.."]));
    assert_eq!(code, 2, "{err}");
    let (code, _, err) = text(&casteljau(&["prove", "proofs", "--identity", "1 = 1"]));
    assert_eq!(code, 2, "{err}");
}
