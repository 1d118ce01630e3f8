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
        .map(|o| {
            format!(
                "{}: {} (expected {}): {}",
                o.id,
                o.verdict.as_str(),
                o.expect.as_str(),
                o.certificate
            )
        })
        .collect();
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    assert_eq!(report.mismatches(), 0);
    let fails: Vec<&str> = report
        .outcomes
        .iter()
        .filter(|o| o.verdict == Verdict::Fails)
        .map(|o| o.id.as_str())
        .collect();
    // The misprints of the texts, each with its proved correction beside it.
    assert_eq!(fails, ["000-ex4-y", "003-two-stage", "004-8", "004-10"]);
    for id in &fails {
        let fixed = report.outcomes.iter().find(|o| o.corrects.as_deref() == Some(*id));
        assert!(
            fixed.is_some_and(|o| o.verdict == Verdict::Proved),
            "{id} has no proved correction"
        );
    }
    let counts: Vec<(String, usize, usize, usize, usize)> = report
        .summaries()
        .iter()
        .map(|s| (s.text.clone(), s.proved, s.proved_in_range, s.verified, s.fails))
        .collect();
    assert_eq!(
        counts,
        [
            ("000_ef6a3958c7d702f5.txt".to_string(), 33, 11, 1, 1),
            ("001_d6775559ddbdd5b2.txt".to_string(), 32, 0, 0, 0),
            ("003_bd67d8bed055bcf9.txt".to_string(), 52, 6, 0, 1),
            ("004_658c519a4aef48a5.txt".to_string(), 16, 0, 0, 2),
        ]
    );
    // Exactly the claims over finite ranges (`for`, a theorem's `degrees`) are proved in
    // range, each with its range; nothing over a range is called `proved`.
    for o in &report.outcomes {
        let over_range = o.range.is_some();
        match o.verdict {
            Verdict::ProvedInRange => assert!(over_range, "{}: proved_in_range without a range", o.id),
            _ => assert!(!over_range, "{}: a range on a {} verdict", o.id, o.verdict.as_str()),
        }
    }
    let in_range = report
        .outcomes
        .iter()
        .filter(|o| o.verdict == Verdict::ProvedInRange)
        .count();
    assert_eq!(in_range, 17);
    let theorem = report.outcomes.iter().find(|o| o.id == "000-7-library").unwrap();
    assert_eq!(theorem.verdict_text(), "proved for n = 0..=10");
    // Proved for every n (open ranges): no range, a certificate saying so.
    for id in [
        "000-7",
        "000-4",
        "000-partition-of-unity",
        "000-basis-recursion",
        "000-derivative-basis",
        "003-a-partition",
        "000-basis-nonneg",
    ] {
        let o = report.outcomes.iter().find(|o| o.id == id).unwrap();
        assert_eq!(o.verdict_text(), "proved", "{id}");
        assert!(o.certificate.starts_with("for every"), "{id}: {}", o.certificate);
    }
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

/// Claims run in parallel; the progress callback still counts 1, 2, …, total once per claim,
/// and the report keeps file order whatever order the claims finish in.
#[test]
fn progress_counts_every_claim_once() {
    let mut calls: Vec<(usize, usize, String)> = Vec::new();
    let report = prove_paths(&[PathBuf::from("proofs")], &mut |done, total, id| {
        calls.push((done, total, id.to_string()));
    })
    .unwrap();
    let total = report.outcomes.len();
    let counts: Vec<usize> = calls.iter().map(|c| c.0).collect();
    assert_eq!(counts, (1..=total).collect::<Vec<_>>());
    assert!(calls.iter().all(|c| c.1 == total));
    let mut seen: Vec<String> = calls.into_iter().map(|c| c.2).collect();
    let mut ids: Vec<String> = report.outcomes.iter().map(|o| o.id.clone()).collect();
    let files: Vec<String> = report.outcomes.iter().map(|o| o.file.clone()).collect();
    assert!(files.windows(2).all(|w| w[0] <= w[1]), "report out of file order");
    seen.sort();
    ids.sort();
    assert_eq!(seen, ids);
}
