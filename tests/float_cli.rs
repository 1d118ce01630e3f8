//! `casteljau eval --f64` and the one-line stderr promise for usage errors and multi-line
//! messages, through the built binary.

use std::process::{Command, Output};

fn casteljau(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .args(args)
        .output()
        .unwrap()
}

const CUBE: &str = "-0.421875; 0.140625; -0.046875; 0.015625";

#[test]
fn eval_f64_judges_each_method() {
    for (method, needle) in [
        ("de-casteljau", "running_bound_ulps"),
        ("compensated", "method: compensated"),
        ("interval", "interval: [-3.902"),
    ] {
        let out = casteljau(&["eval", CUBE, "--t", "0.7500001", "--f64", "--method", method]);
        assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
        let text = String::from_utf8(out.stdout).unwrap();
        assert!(
            text.contains(needle) && text.contains("within_bound: true"),
            "{method}: {text}"
        );
    }
    // decimals are read as their nearest floats, as a float program would hold them
    let out = casteljau(&["eval", "0.1; 0.7", "--t", "0.5", "--f64", "--format", "json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["method"], "compensated");
    assert_eq!(v["ulps"], serde_json::json!([0]));
}

#[test]
fn usage_errors_are_one_line() {
    for args in [
        &["eval", "0,0", "--t", "1", "--bogus"][..],
        &["eval", "0,0", "--t", "1", "--method", "interval"],
        &["eval", "0,0"],
        &["frobnicate"],
        &["eval", "0,0; 1", "--t", "1/2"],
        &["eval", "0,0\n1,1", "--t", "x\ny"],
    ] {
        let out = casteljau(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("casteljau: "), "{err}");
    }
    let err = String::from_utf8(casteljau(&["eval", "0,0", "--t", "1", "--method", "interval"]).stderr).unwrap();
    assert!(err.contains("--f64"), "{err}");
}

#[test]
fn the_scheme_has_a_work_limit() {
    let points: Vec<String> = (0..=1000).map(|i| format!("{}", (i * 7919) % 1000)).collect();
    let out = casteljau(&["eval", &points.join(";"), "--t", "1/3", "--scheme"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("--scheme") && err.contains("estimated exact work"),
        "{err}"
    );
    assert!(out.stdout.is_empty());
}
