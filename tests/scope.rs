//! The range-bound note: why a claim proved over finite ranges stays bound to them, or that
//! its open-range version is proved too — never a change of the verdict itself.

use casteljau::verify::check_claim;
use casteljau::verify::claims::parse_file;
use casteljau::verify::{explain, prove_paths, ExplainStyle, Verdict};
use casteljau::verify::{range_bound, PROVABLE};
use std::path::{Path, PathBuf};

/// The verdict of the one claim in `toml` and its range-bound note.
fn note(toml: &str) -> (Verdict, Option<String>) {
    let file = parse_file(toml, Path::new("x.toml")).expect("claim file");
    let c = &file.claim[0];
    let verdict = check_claim(c, false).expect("a verdict").verdict();
    (verdict, range_bound(c, verdict))
}

fn identity(ranges: &str, lhs: &str, rhs: &str, extra: &str) -> String {
    format!(
        "[[claim]]\nid = \"x\"\nsource = \"x\"\nstatement = \"x\"\nkind = \"identity\"\nfor = [{ranges}]\nlhs = \"{lhs}\"\nrhs = \"{rhs}\"\n{extra}"
    )
}

#[test]
fn a_claim_on_library_objects_carries_its_reason() {
    let (v, r) = note(&identity(
        "\"n = 1..=6\"",
        "b(t)",
        "(1 - t)*b(0, n-1, t) + t*b(1, n-1, t)",
        "polygon = { name = \"b\", degree = \"n\" }\nvars = [\"t\"]\n",
    ));
    assert_eq!(v, Verdict::ProvedInRange);
    let r = r.expect("a reason");
    assert!(
        r.contains("`b(t)`") && r.contains("`b(i, r, t)`") && r.contains("per degree"),
        "{r}"
    );
    assert!(!r.starts_with(PROVABLE));
}

#[test]
fn a_claim_whose_open_range_is_proved_says_so_and_keeps_its_verdict() {
    let (v, r) = note(&identity(
        "\"n = 0..=6\"",
        "sum(i, 0, n, B(i, n, t))",
        "1",
        "vars = [\"t\"]\n",
    ));
    // The claim file claims n ≤ 6: the verdict stays in range.
    assert_eq!(v, Verdict::ProvedInRange);
    assert_eq!(r.as_deref(), Some(format!("{PROVABLE} `n = 0..`").as_str()));
    // A dependent bound is kept; the constant one is opened.
    let (v, r) = note(&identity(
        "\"n = 1..=5\", \"i = 0..=n\"",
        "B(i, n, t)",
        "(1 - t)*B(i, n-1, t) + t*B(i-1, n-1, t)",
        "vars = [\"t\"]\n",
    ));
    assert_eq!(v, Verdict::ProvedInRange);
    assert_eq!(
        r.as_deref(),
        Some(format!("{PROVABLE} `n = 1..`, `i = 0..=n`").as_str())
    );
}

#[test]
fn a_claim_true_in_its_range_but_false_beyond_is_never_called_provable() {
    // Σ B_i^n = 1 + C(n, 11) holds for n ≤ 10 and fails from n = 11 on.
    let (v, r) = note(&identity(
        "\"n = 0..=6\"",
        "sum(i, 0, n, B(i, n, t))",
        "1 + C(n, 11)",
        "vars = [\"t\"]\n",
    ));
    assert_eq!(v, Verdict::ProvedInRange);
    let r = r.expect("a reason");
    assert!(!r.starts_with(PROVABLE), "{r}");
    assert!(r.contains("does not go through"), "{r}");
}

#[test]
fn a_false_claim_fails_and_has_no_note() {
    let (v, r) = note(&identity(
        "\"n = 0..=4\"",
        "sum(i, 0, n, B(i, n, t))",
        "2",
        "vars = [\"t\"]\n",
    ));
    assert_eq!(v, Verdict::Fails);
    assert_eq!(r, None);
    // A proved claim without ranges has none either.
    let (v, r) = note("[[claim]]\nid = \"x\"\nsource = \"x\"\nstatement = \"x\"\nkind = \"identity\"\nlhs = \"B(0, 1, t)\"\nrhs = \"1 - t\"\n");
    assert_eq!(v, Verdict::Proved);
    assert_eq!(r, None);
}

#[test]
fn theorem_claims_get_the_reason_of_their_code() {
    let (v, r) = note("[[claim]]\nid = \"x\"\nsource = \"x\"\nstatement = \"x\"\nkind = \"theorem\"\ntheorem = \"endpoint_tangent\"\ndegrees = \"1..=4\"\n");
    assert_eq!(v, Verdict::ProvedInRange);
    let r = r.expect("a reason");
    assert!(
        r.starts_with("a theorem claim (`endpoint_tangent`)") && r.contains("`deriv`"),
        "{r}"
    );
}

#[test]
fn every_report_of_the_texts_shows_the_note() {
    let report = prove_paths(&[PathBuf::from("proofs")], &mut |_, _, _| {}).expect("proofs");
    let mut bound = 0;
    for o in &report.outcomes {
        // Exactly the claims proved in range carry a note, and none of them is called
        // provable for every n (those are written with open ranges).
        assert_eq!(o.range_bound.is_some(), o.verdict == Verdict::ProvedInRange, "{}", o.id);
        if let Some(r) = &o.range_bound {
            bound += 1;
            assert!(!r.starts_with(PROVABLE), "{}: {r}", o.id);
        }
    }
    assert!(bound > 0);
    let text = report.to_text();
    assert!(
        text.contains("    range-bound: uses the isoparametric curve `isov`"),
        "{text}"
    );
    let json = report.to_json();
    let object = json["claims"]
        .as_array()
        .expect("claims")
        .iter()
        .find(|c| c["id"] == "003-iso-library")
        .expect("003-iso-library");
    assert!(object["range_bound"].as_str().expect("a field").contains("`isov`"));
    let proved = json["claims"]
        .as_array()
        .expect("claims")
        .iter()
        .find(|c| c["id"] == "000-7")
        .expect("000-7");
    assert!(proved.get("range_bound").is_none());
    let explained = explain(&[PathBuf::from("proofs")], "003-iso-library", ExplainStyle::Short).expect("explain");
    assert!(
        explained
            .contains("\nverdict: proved for m = 0..=3, n = 0..=3; range-bound: uses the isoparametric curve `isov`"),
        "{explained}"
    );
}
