//! Regression references recorded from the program: the texts' verdicts and certificates
//! (`prove --format json`), every claim's explanation (`prove --explain`), and the oracle's
//! answers to a recorded request file (`tests/golden/make_oracle_requests.py`). A change to
//! any of them is a change of behaviour: deliberate ones re-record the file in the same commit.

use std::io::Write;
use std::process::{Command, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_casteljau");

fn golden(name: &str) -> String {
    let path = format!("{}/tests/golden/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// Equal texts, or a panic naming the first line that differs.
fn assert_same(what: &str, got: &str, want: &str) {
    if got == want {
        return;
    }
    let (g, w): (Vec<&str>, Vec<&str>) = (got.lines().collect(), want.lines().collect());
    let at = g
        .iter()
        .zip(&w)
        .position(|(a, b)| a != b)
        .unwrap_or(g.len().min(w.len()));
    panic!(
        "{what} changed at line {}:\n  now:    {}\n  before: {}",
        at + 1,
        g.get(at).unwrap_or(&"<end>"),
        w.get(at).unwrap_or(&"<end>")
    );
}

fn run(args: &[&str], stdin: &[u8]) -> (String, i32) {
    let mut child = Command::new(BIN)
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child.stdin.take().unwrap().write_all(stdin).unwrap();
    let out = child.wait_with_output().unwrap();
    let mut text = String::from_utf8(out.stdout).unwrap();
    text.push_str(&String::from_utf8(out.stderr).unwrap());
    (text, out.status.code().unwrap_or(-1))
}

#[test]
fn the_texts_verdicts_and_certificates_are_unchanged() {
    let (got, code) = run(&["prove", "--format", "json"], b"");
    assert_eq!(code, 0);
    assert_same("prove --format json", &got, &golden("prove.json"));
}

#[test]
fn every_explanation_is_unchanged() {
    let want = golden("explain.txt");
    let ids: Vec<&str> = want
        .lines()
        .filter_map(|l| l.strip_prefix("==== "))
        .map(|l| l.split(' ').next().unwrap())
        .collect();
    assert_eq!(ids.len(), 155);
    let mut got = String::new();
    for id in ids {
        let (text, code) = run(&["prove", "--explain", id], b"");
        got.push_str(&format!("==== {id} (exit {code})\n{text}"));
    }
    assert_same("prove --explain", &got, &want);
}

#[test]
fn the_oracle_answers_a_recorded_session_as_before() {
    let requests = golden("oracle_requests.jsonl");
    let (got, code) = run(&["oracle"], requests.as_bytes());
    assert_eq!(code, 0);
    assert_eq!(got.lines().count(), requests.lines().count());
    assert_same("oracle answers", &got, &golden("oracle_answers.jsonl"));
}
