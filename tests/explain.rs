//! `--explain` for every claim of the texts: a reason and a worked case that are never empty,
//! the scope of the argument matching the verdict, and misprints named with their corrections.

use casteljau::verify::claims::{builtin_files, load_paths, ClaimFile};
use casteljau::verify::{explain_files, ExplainStyle, Verdict};
use rayon::prelude::*;
use std::path::PathBuf;

fn texts() -> Vec<ClaimFile> {
    load_paths(&[PathBuf::from("proofs")]).unwrap()
}

/// The indented lines under `heading` (up to the next blank line).
fn section<'a>(text: &'a str, heading: &str) -> (&'a str, Vec<&'a str>) {
    let start = text
        .find(&format!("\n{heading}"))
        .unwrap_or_else(|| panic!("no '{heading}' in\n{text}"));
    let mut lines = text[start + 1..].lines();
    let head = lines.next().unwrap();
    (head, lines.take_while(|l| l.starts_with("  ")).collect())
}

#[test]
fn every_claim_has_a_reason_and_a_worked_case() {
    let files = texts();
    let claims: Vec<(&ClaimFile, String)> = files
        .iter()
        .flat_map(|f| f.claim.iter().map(move |c| (f, c.id.clone())))
        .collect();
    assert_eq!(claims.len(), 155);
    claims.par_iter().for_each(|(_, id)| {
        let text = explain_files(&files, id, ExplainStyle::Short).unwrap();
        let (_, why) = section(&text, "why this suffices:");
        assert!(
            !why.is_empty() && why.iter().all(|l| l.trim().len() > 10),
            "{id}: empty reason\n{text}"
        );
        let (head, lines) = section(&text, "worked case: ");
        let head = head.trim_start_matches("worked case: ").trim();
        assert!(!head.is_empty(), "{id}: worked case without a header\n{text}");
        assert!(
            head.len() > 30 || !lines.is_empty(),
            "{id}: the worked case shows nothing\n{text}"
        );
        assert!(
            !lines.iter().any(|l| l.ends_with("every term vanishes")) || lines.len() > 2,
            "{id}: the worked case is only the zero polygon\n{text}"
        );
        // the symbolic argument (every n) only for a verdict without a range
        let verdict = text.lines().find(|l| l.starts_with("verdict: ")).unwrap();
        if verdict.starts_with("verdict: proved for ") {
            assert!(
                !text.contains("The integers stay symbolic"),
                "{id}: a range verdict with the every-n argument\n{text}"
            );
        }
    });
}

#[test]
fn misprints_say_so_and_name_their_correction() {
    let files = texts();
    let mut misprints = Vec::new();
    for f in &files {
        for c in &f.claim {
            if c.expected() != Verdict::Fails {
                continue;
            }
            let text = explain_files(&files, &c.id, ExplainStyle::Short).unwrap();
            assert!(text.contains("\nverdict: fails\n"), "{}\n{text}", c.id);
            assert!(text.contains("a misprint of the text"), "{}\n{text}", c.id);
            let fixes: Vec<&str> = f
                .claim
                .iter()
                .filter(|d| d.corrects.as_deref() == Some(c.id.as_str()))
                .map(|d| d.id.as_str())
                .collect();
            assert!(!fixes.is_empty(), "{} has no correction in its file", c.id);
            for fix in &fixes {
                assert!(text.contains(&format!("correction: {fix} ")), "{}\n{text}", c.id);
                let fixed = explain_files(&files, fix, ExplainStyle::Short).unwrap();
                assert!(fixed.contains("\nverdict: proved"), "{fix}\n{fixed}");
                assert!(fixed.contains(&format!("corrects:  {}, ", c.id)), "{fix}\n{fixed}");
            }
            misprints.push(c.id.clone());
        }
    }
    assert_eq!(misprints, ["000-ex4-y", "003-two-stage", "004-8", "004-10"]);
    // a claim that is not a misprint does not say it is one
    let proved = explain_files(&files, "000-7", ExplainStyle::Short).unwrap();
    assert!(
        !proved.contains("misprint") && !proved.contains("correction:"),
        "{proved}"
    );
}

/// The claims built into the library are the files of `proofs/`, parsed the same way.
#[test]
fn the_builtin_claims_are_the_proofs_directory() {
    let (disk, builtin) = (texts(), builtin_files().unwrap());
    assert_eq!(disk.len(), builtin.len());
    for (d, b) in disk.iter().zip(&builtin) {
        assert_eq!(d.path, b.path);
        assert!(b.builtin && !d.builtin);
        // every claim, every field as parsed
        assert_eq!(format!("{:?}", d.claim), format!("{:?}", b.claim));
        assert_eq!(format!("{:?}", d.text), format!("{:?}", b.text));
        // an explanation says where its claim comes from: the file read, or the program
        assert_eq!(d.origin(), d.path.display().to_string());
        assert!(b.origin().starts_with("built into casteljau: 0"), "{}", b.origin());
    }
    let e = explain_files(&builtin, "004-8", ExplainStyle::Short).unwrap();
    assert!(
        e.starts_with("claim 004-8 (built into casteljau: 004_658c519a4aef48a5.toml)\n"),
        "{e}"
    );
    // an unknown id gets the nearest ones
    let err = explain_files(&builtin, "004-08", ExplainStyle::Short)
        .unwrap_err()
        .to_string();
    assert!(err.ends_with("(did you mean 004-8?)"), "{err}");
    let err = explain_files(&builtin, "no-such-claim-at-all", ExplainStyle::Short)
        .unwrap_err()
        .to_string();
    assert!(!err.contains("did you mean"), "{err}");
}
