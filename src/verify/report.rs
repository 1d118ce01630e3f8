//! The reports of a `prove` run: readable text, JSON, and the step-by-step `explain`.

use super::claims::{Claim, ClaimFile};
use super::engine::{Checked, CurveObj};
use super::{ClaimOutcome, Report, Verdict};
use num_rational::BigRational;
use serde::Serialize;
use std::fmt::Write as _;

/// The counts for one text.
#[derive(Clone, Debug, Default, Serialize, PartialEq, Eq)]
pub struct TextSummary {
    /// The text file.
    pub text: String,
    /// Claims checked.
    pub claims: usize,
    /// Verdict `proved` (for every value of every variable).
    pub proved: usize,
    /// Verdict `proved_in_range` (every case of finite ranges).
    pub proved_in_range: usize,
    /// Verdict `verified`.
    pub verified: usize,
    /// Verdict `fails`.
    pub fails: usize,
    /// Verdicts equal to the claim file's `expect`.
    pub as_expected: usize,
    /// Verdicts different from `expect`.
    pub mismatches: usize,
    /// Ids of the claims that fail (misprints, when expected).
    pub failing: Vec<String>,
}

/// A verdict with its scope, as the text reports show it: `proved`, `proved for n = 0..=10`,
/// `verified`, `fails`.
pub(super) fn verdict_text(v: Verdict, range: Option<&str>) -> String {
    match (v, range) {
        (Verdict::ProvedInRange, Some(r)) => format!("proved for {r}"),
        (Verdict::ProvedInRange, None) => "proved in range".into(),
        _ => v.as_str().into(),
    }
}

pub(super) fn summaries(outcomes: &[ClaimOutcome]) -> Vec<TextSummary> {
    let mut out: Vec<TextSummary> = Vec::new();
    for o in outcomes {
        let idx = match out.iter().position(|s| s.text == o.text) {
            Some(i) => i,
            None => {
                out.push(TextSummary {
                    text: o.text.clone(),
                    ..Default::default()
                });
                out.len() - 1
            }
        };
        let s = &mut out[idx];
        s.claims += 1;
        match o.verdict {
            Verdict::Proved => s.proved += 1,
            Verdict::ProvedInRange => s.proved_in_range += 1,
            Verdict::Verified => s.verified += 1,
            Verdict::Fails => {
                s.fails += 1;
                s.failing.push(o.id.clone());
            }
        }
        if o.verdict == o.expect {
            s.as_expected += 1;
        } else {
            s.mismatches += 1;
        }
    }
    out
}

fn total(sums: &[TextSummary]) -> TextSummary {
    let mut t = TextSummary {
        text: "total".into(),
        ..Default::default()
    };
    for s in sums {
        t.claims += s.claims;
        t.proved += s.proved;
        t.proved_in_range += s.proved_in_range;
        t.verified += s.verified;
        t.fails += s.fails;
        t.as_expected += s.as_expected;
        t.mismatches += s.mismatches;
        t.failing.extend(s.failing.iter().cloned());
    }
    t
}

pub(super) fn to_text(r: &Report) -> String {
    let mut s = String::new();
    let sums = summaries(&r.outcomes);
    let _ = writeln!(
        s,
        "casteljau prove: {} claims from {} texts, every verdict decided in exact arithmetic\n",
        r.outcomes.len(),
        sums.len()
    );
    for sum in &sums {
        let _ = writeln!(s, "=== {} ===", sum.text);
        for o in r.outcomes.iter().filter(|o| o.text == sum.text) {
            let flag = if o.verdict == o.expect {
                match o.verdict {
                    Verdict::Fails => "  (expected: a misprint)".to_string(),
                    _ => String::new(),
                }
            } else {
                format!("  !! MISMATCH: expected {}", o.expect.as_str())
            };
            let _ = writeln!(s, "[{}] {}{flag}", o.verdict_text(), o.id);
            let _ = writeln!(s, "    source:      {}", o.source);
            let _ = writeln!(s, "    statement:   {}", o.statement);
            if let Some(c) = &o.corrects {
                let _ = writeln!(s, "    corrects:    {c}");
            }
            if let Some(n) = &o.note {
                let _ = writeln!(s, "    note:        {n}");
            }
            let label = if o.verdict == Verdict::Fails {
                "counterexample"
            } else {
                "certificate"
            };
            let _ = writeln!(s, "    {label}: {}", o.certificate);
        }
        let _ = writeln!(s, "--- {}: {}\n", sum.text, counts(sum));
    }
    let _ = writeln!(s, "=== summary ===");
    let _ = writeln!(
        s,
        "{:<28} {:>6} {:>7} {:>15} {:>9} {:>6} {:>12}",
        "text", "claims", "proved", "proved in range", "verified", "fails", "as expected"
    );
    let t = total(&sums);
    for sum in sums.iter().chain(std::iter::once(&t)) {
        let _ = writeln!(
            s,
            "{:<28} {:>6} {:>7} {:>15} {:>9} {:>6} {:>12}",
            sum.text,
            sum.claims,
            sum.proved,
            sum.proved_in_range,
            sum.verified,
            sum.fails,
            format!("{}/{}", sum.as_expected, sum.claims)
        );
    }
    if !t.failing.is_empty() {
        let _ = writeln!(s, "\nclaims that fail: {}", t.failing.join(", "));
    }
    if t.proved_in_range > 0 {
        let _ = writeln!(
            s,
            "proved in range: proved for every case of the stated finite ranges, not for values outside them"
        );
    }
    if t.mismatches == 0 {
        let _ = writeln!(s, "every verdict is as the claim files expect");
    } else {
        let bad: Vec<&str> = r
            .outcomes
            .iter()
            .filter(|o| o.verdict != o.expect)
            .map(|o| o.id.as_str())
            .collect();
        let _ = writeln!(
            s,
            "{} verdicts differ from the claim files: {}",
            t.mismatches,
            bad.join(", ")
        );
    }
    s
}

fn counts(sum: &TextSummary) -> String {
    let exp = if sum.mismatches == 0 {
        "all as expected".to_string()
    } else {
        format!("{} NOT as expected", sum.mismatches)
    };
    format!(
        "{} claims: {} proved, {} proved in range, {} verified, {} fail; {exp}",
        sum.claims, sum.proved, sum.proved_in_range, sum.verified, sum.fails
    )
}

pub(super) fn to_json(r: &Report) -> serde_json::Value {
    let sums = summaries(&r.outcomes);
    let t = total(&sums);
    serde_json::json!({
        "claims": r.outcomes,
        "summary": {
            "claims": t.claims,
            "proved": t.proved,
            "proved_in_range": t.proved_in_range,
            "verified": t.verified,
            "fails": t.fails,
            "as_expected": t.as_expected,
            "mismatches": t.mismatches,
            "failing": t.failing,
            "texts": sums,
        }
    })
}

pub(super) fn explain_text(f: &ClaimFile, c: &Claim, checked: &Checked) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "claim {} ({})", c.id, f.path.display());
    let _ = writeln!(s, "source:    {}", c.source);
    let _ = writeln!(s, "statement: {}", c.statement);
    let _ = writeln!(s, "kind:      {}", c.kind);
    for (k, v) in [
        ("lhs", &c.lhs),
        ("rhs", &c.rhs),
        ("on", &c.on),
        ("equation", &c.equation),
        ("premise", &c.premise),
        ("factor", &c.factor),
        ("power", &c.power),
    ] {
        if let Some(v) = v {
            let _ = writeln!(s, "{k:<10} {v}");
        }
    }
    if let Some(ch) = &c.chain {
        let _ = writeln!(s, "chain:     {}", ch.join("\n         = "));
    }
    if let Some(d) = &c.defs {
        let _ = writeln!(s, "where:     {}", d.join("\n           "));
    }
    if let Some(r) = &c.ranges {
        let _ = writeln!(s, "for:       {}", r.join(", "));
    }
    let _ = writeln!(
        s,
        "\nverdict: {}",
        verdict_text(checked.verdict, checked.range.as_deref())
    );
    let _ = writeln!(
        s,
        "{}: {}\n",
        if checked.verdict == Verdict::Fails {
            "counterexample"
        } else {
            "certificate"
        },
        checked.certificate
    );
    if !checked.steps.is_empty() {
        let _ = writeln!(s, "steps:");
        for line in &checked.steps {
            let _ = writeln!(s, "  {line}");
        }
    }
    // The de Casteljau scheme (9) of every polynomial curve of the claim, at the first
    // parameters the proof used.
    if let Some(curves) = &c.curves {
        let ts: Vec<BigRational> = if checked.params.is_empty() {
            vec![BigRational::new(1.into(), 2.into())]
        } else {
            checked.params.iter().take(3).cloned().collect()
        };
        for (name, spec) in curves {
            if let Ok(CurveObj::Polynomial(curve)) = CurveObj::<BigRational>::from_spec(spec) {
                for t in &ts {
                    let _ = writeln!(s, "\ncurve {name}: {}", curve.scheme(t));
                }
            }
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn outcome(id: &str, verdict: Verdict, range: Option<&str>, expect: Verdict) -> ClaimOutcome {
        ClaimOutcome {
            id: id.into(),
            source: "s".into(),
            statement: "s".into(),
            verdict,
            range: range.map(String::from),
            certificate: "c".into(),
            expect,
            file: "f.toml".into(),
            text: "t.txt".into(),
            corrects: None,
            note: None,
        }
    }

    #[test]
    fn every_report_shows_the_scope() {
        let r = Report {
            outcomes: vec![
                outcome("a", Verdict::Proved, None, Verdict::Proved),
                outcome("b", Verdict::ProvedInRange, Some("n = 0..=10"), Verdict::ProvedInRange),
                outcome("c", Verdict::ProvedInRange, Some("n = 0..=3"), Verdict::Proved),
                outcome("d", Verdict::Fails, None, Verdict::Fails),
            ],
        };
        let text = r.to_text();
        assert!(text.contains("[proved] a\n"), "{text}");
        assert!(text.contains("[proved for n = 0..=10] b\n"), "{text}");
        assert!(
            text.contains("[proved for n = 0..=3] c  !! MISMATCH: expected proved"),
            "{text}"
        );
        assert!(
            text.contains("1 proved, 2 proved in range, 0 verified, 1 fail"),
            "{text}"
        );
        let s = &r.summaries()[0];
        assert_eq!((s.proved, s.proved_in_range, s.fails, s.mismatches), (1, 2, 1, 1));
        let json = r.to_json();
        assert_eq!(json["claims"][1]["verdict"], "proved_in_range");
        assert_eq!(json["claims"][1]["range"], "n = 0..=10");
        assert!(json["claims"][0].get("range").is_none());
        assert_eq!(json["summary"]["proved_in_range"], 2);
    }
}
