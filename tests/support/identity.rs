//! One `identity` claim checked from the body of its TOML table: the verdict and the
//! certificate (or counterexample). Shared by the claim-language tests.

#![allow(dead_code)]

use casteljau::verify::check_claim;
use casteljau::verify::claims::parse_file;
use casteljau::verify::Verdict;
use std::path::Path;

/// The verdict, its range and the certificate of the one claim whose fields after `statement`
/// are `body`; `detail` also records the proof's steps (as `--explain`).
pub fn check_table(body: &str, detail: bool) -> casteljau::Result<(Verdict, Option<String>, String)> {
    let f = parse_file(
        &format!("[[claim]]\nid = \"x\"\nsource = \"s\"\nstatement = \"s\"\n{body}"),
        Path::new("test.toml"),
    )?;
    let out = check_claim(&f.claim[0], detail)?;
    Ok((out.verdict(), out.range().map(str::to_string), out.certificate))
}

/// The verdict and the certificate of an `identity` claim.
pub fn check(body: &str) -> casteljau::Result<(Verdict, String)> {
    check_table(&format!("kind = \"identity\"\n{body}"), false).map(|(v, _, c)| (v, c))
}

/// The verdict, its range and the certificate of an `identity` claim, with the proof's steps
/// recorded (as `--explain`).
pub fn check_scoped(body: &str) -> casteljau::Result<(Verdict, Option<String>, String)> {
    check_table(&format!("kind = \"identity\"\n{body}"), true)
}

/// The certificate of a claim `proved` for every n; a panic naming what came instead.
pub fn assert_proved(body: &str) -> String {
    match check_scoped(body) {
        Ok((Verdict::Proved, None, c)) => c,
        other => panic!("{body}: expected proved for every n, got {other:?}"),
    }
}
