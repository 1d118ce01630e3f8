//! A verdict in words: its CSS class, its label and what it covers, in one place.

use crate::verify::{ClaimOutcome, Verdict};

/// How a verdict reads in the report: a CSS class, its word, and what it covers.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VerdictText {
    /// `proved`, `verified` or `fails` (a CSS class).
    pub class: &'static str,
    /// The word shown.
    pub label: &'static str,
    /// What the verdict covers, in one sentence.
    pub scope: String,
}

/// The one place that turns a verdict into words.
pub fn verdict_text(outcome: &ClaimOutcome) -> VerdictText {
    verdict_words(outcome.verdict, outcome.range.as_deref())
}

/// The words for a verdict; `range` is the finite range a `proved_in_range` covers.
pub(super) fn verdict_words(verdict: Verdict, range: Option<&str>) -> VerdictText {
    match verdict {
        Verdict::Proved => VerdictText {
            class: "proved",
            label: "proved",
            scope: "for every value of every variable of the statement; the certificate says why the finite check is a proof"
                .into(),
        },
        Verdict::ProvedInRange => VerdictText {
            class: "proved-in-range",
            label: "proved in range",
            scope: match range {
                Some(r) => format!("every case of {r} proved; not a proof beyond that range"),
                None => "every case of the stated finite ranges proved; not a proof beyond them".into(),
            },
        },
        Verdict::Verified => VerdictText {
            class: "verified",
            label: "verified",
            scope: "bounded evidence, not a proof: the certificate says exactly what was checked".into(),
        },
        Verdict::Fails => VerdictText {
            class: "fails",
            label: "fails",
            scope: "false as stated: the certificate is an exact counterexample".into(),
        },
        Verdict::Error => VerdictText {
            class: "error",
            label: "error",
            scope: "not decided: the reason says which limit or form stopped the check".into(),
        },
    }
}
