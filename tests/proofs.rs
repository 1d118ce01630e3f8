//! The report over proofs/ matches every `expect`; the failing claims are pinned.

use casteljau::verify::{prove_paths, Verdict};
use std::path::PathBuf;

#[test]
fn every_verdict_is_as_expected() {
    let report = prove_paths(&[PathBuf::from("proofs")], &mut |_, _, _| {}).unwrap();
    let bad: Vec<String> = report
        .outcomes
        .iter()
        .filter(|o| o.verdict != o.expect)
        .map(|o| format!("{}: {} (expected {}): {}", o.id, o.verdict.as_str(), o.expect.as_str(), o.certificate))
        .collect();
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    assert_eq!(report.mismatches(), 0);
    let fails: Vec<&str> = report
        .outcomes
        .iter()
        .filter(|o| o.verdict == Verdict::Fails)
        .map(|o| o.id.as_str())
        .collect();
    assert_eq!(fails, ["000-ex4-y"]);
}

/// `cargo test --release --test proofs -- --ignored --nocapture` prints the report and the time.
#[test]
#[ignore]
fn print_report() {
    let start = std::time::Instant::now();
    let mut last = std::time::Instant::now();
    let paths: Vec<PathBuf> = match std::env::var("PROOFS") {
        Ok(p) => vec![PathBuf::from(p)],
        Err(_) => vec![PathBuf::from("proofs")],
    };
    let report = prove_paths(&paths, &mut |_, _, id| {
        eprintln!("{:>8.3}s {id}", last.elapsed().as_secs_f64());
        last = std::time::Instant::now();
    })
    .unwrap();
    println!("{}", report.to_text());
    println!("prove over proofs/ took {:?}", start.elapsed());
}
