//! The reports of a `prove` run: readable text, JSON, and the step-by-step `explain`.

use super::argue::{
    argument, cases, certificate_case, misprint_lines, sample_evaluations, verdict_text, worked_case, worked_scheme,
    worked_sum,
};
use super::claims::{Claim, ClaimFile, Identity, Kind, Sides};
use super::kernel::checked::Method;
use super::kernel::checked::Verdict;
use super::kernel::Trusted;
use super::outcome::Checked;
use serde::Serialize;
use std::borrow::Cow;
use std::fmt::Write as _;

/// A string as the text reports show it: control characters (newlines, `\r`, terminal
/// escapes) and the invisible marks that reorder or break lines (bidirectional overrides, line
/// separators) written as `\u{1b}`, so that no field of a claim file can draw, move or erase a
/// report line.
pub fn printable(s: &str) -> Cow<'_, str> {
    let hidden = |c: char| {
        c.is_control()
            || matches!(c, '\u{200e}' | '\u{200f}' | '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}' | '\u{2028}' | '\u{2029}')
    };
    if !s.chars().any(hidden) {
        return Cow::Borrowed(s);
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        if hidden(c) {
            let _ = write!(out, "{}", c.escape_unicode());
        } else {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

/// The outcome of checking one claim.
#[derive(Clone, Debug, Serialize)]
pub struct ClaimOutcome {
    /// The claim's id, unique within its file.
    pub id: String,
    /// The text file and printed label, e.g. `001_d6775559ddbdd5b2.txt 例3`.
    pub source: String,
    /// The statement as printed.
    pub statement: String,
    /// The verdict, decided in exact arithmetic.
    pub verdict: Verdict,
    /// The finite ranges a `proved_in_range` verdict covers, e.g. `n = 0..=10, j = 0..=n`
    /// (absent for every other verdict).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub range: Option<String>,
    /// For a proof: the kind of argument it rests on.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub method: Option<Method>,
    /// For a proof: the library computations it accepts by name (empty when none).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rests_on: Option<Vec<Trusted>>,
    /// What was checked: the proof's certificate or the exact counterexample.
    pub certificate: String,
    /// The verdict the claim file expects.
    pub expect: Verdict,
    /// The claim file it came from.
    pub file: String,
    /// The text file the claim is about (from the file's `[text]` table, or the file name).
    pub text: String,
    /// The id of the misprinted claim this one corrects.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub corrects: Option<String>,
    /// The claim file's note, if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
    /// For a `proved_in_range` verdict: why the claim stays bound to its ranges, or that it is
    /// also provable for every n and which ranges to write ([`super::scope::range_bound`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub range_bound: Option<String>,
    /// What the kernel checked, as data (`docs/certificates.md`; not in the JSON report).
    #[serde(skip)]
    pub data: super::kernel::certificate::Data,
    /// A `computation` proof's library computations, as data (not in the JSON report).
    #[serde(skip)]
    pub computed: Vec<super::outcome::Computed>,
}

impl ClaimOutcome {
    /// The verdict with its scope, as the text report shows it: `proved`,
    /// `proved for n = 0..=10`, `verified`, `fails`.
    pub fn verdict_text(&self) -> String {
        verdict_text(self.verdict, self.range.as_deref())
    }

    /// For a proof, its method and the library computations it accepts, in one line:
    /// `exact symbolic expansion`, `a library computation accepted by name; rests on
    /// classify_conic`.
    pub fn method_text(&self) -> Option<String> {
        let method = self.method?;
        let rests: Vec<&str> = self.rests_on.iter().flatten().map(|t| t.name()).collect();
        Some(if rests.is_empty() {
            method.text()
        } else {
            format!("{}; rests on {}", method.text(), rests.join(", "))
        })
    }
}

/// The outcomes of a whole run.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Report {
    /// One outcome per claim, in file order.
    pub outcomes: Vec<ClaimOutcome>,
}

impl Report {
    /// How many claims got a verdict other than the expected one.
    pub fn mismatches(&self) -> usize {
        self.outcomes.iter().filter(|o| o.verdict != o.expect).count()
    }

    /// Per text: counts of proved / verified / fails and of verdicts as expected.
    pub fn summaries(&self) -> Vec<TextSummary> {
        summaries(&self.outcomes)
    }

    /// The human-readable report: per claim its source, statement, verdict and certificate,
    /// then a summary per text.
    pub fn to_text(&self) -> String {
        to_text(self)
    }

    /// Each claim's block alone, without the texts' headers and the summary (the one-line
    /// `prove --identity` check, whose claim has no file to compare with).
    pub fn claims_text(&self) -> String {
        let mut s = String::new();
        for o in &self.outcomes {
            outcome_text(&mut s, o, "");
        }
        s
    }

    /// The JSON report `{"claims": [...], "summary": {...}}` with a summary per text.
    pub fn to_json(&self) -> serde_json::Value {
        to_json(self)
    }
}

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
    /// Claims that could not be decided (`error`).
    #[serde(skip_serializing_if = "is_zero")]
    pub errors: usize,
    /// Their ids.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub undecided: Vec<String>,
}

fn is_zero(n: &usize) -> bool {
    *n == 0
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
            Verdict::Error => {
                s.errors += 1;
                s.undecided.push(o.id.clone());
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
        t.errors += s.errors;
        t.undecided.extend(s.undecided.iter().cloned());
    }
    t
}

/// One claim's block of the report: verdict, source, statement, notes, certificate.
fn outcome_text(s: &mut String, o: &ClaimOutcome, flag: &str) {
    let _ = writeln!(s, "[{}] {}{flag}", o.verdict_text(), printable(&o.id));
    let _ = writeln!(s, "    source:      {}", printable(&o.source));
    let _ = writeln!(s, "    statement:   {}", printable(&o.statement));
    if let Some(c) = &o.corrects {
        let _ = writeln!(s, "    corrects:    {}", printable(c));
    }
    if let Some(n) = &o.note {
        let _ = writeln!(s, "    note:        {}", printable(n));
    }
    let label = match o.verdict {
        Verdict::Fails => "counterexample",
        Verdict::Error => "error",
        _ => "certificate",
    };
    let _ = writeln!(s, "    {label}: {}", printable(&o.certificate));
    if let Some(m) = o.method_text() {
        let _ = writeln!(s, "    method:      {m}");
    }
    if let Some(r) = &o.range_bound {
        let _ = writeln!(s, "    range-bound: {}", printable(r));
    }
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
        let _ = writeln!(s, "=== {} ===", printable(&sum.text));
        for o in r.outcomes.iter().filter(|o| o.text == sum.text) {
            let flag = if o.verdict == o.expect {
                match o.verdict {
                    Verdict::Fails => "  (expected: a misprint)".to_string(),
                    _ => String::new(),
                }
            } else {
                format!("  !! MISMATCH: expected {}", o.expect.as_str())
            };
            outcome_text(&mut s, o, &flag);
        }
        let _ = writeln!(s, "--- {}: {}\n", printable(&sum.text), counts(sum));
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
            printable(&sum.text),
            sum.claims,
            sum.proved,
            sum.proved_in_range,
            sum.verified,
            sum.fails,
            format!("{}/{}", sum.as_expected, sum.claims)
        );
    }
    if !t.failing.is_empty() {
        let _ = writeln!(s, "\nclaims that fail: {}", printable(&t.failing.join(", ")));
    }
    if !t.undecided.is_empty() {
        let _ = writeln!(
            s,
            "claims not decided (error, each with its reason): {}",
            printable(&t.undecided.join(", "))
        );
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
            printable(&bad.join(", "))
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
            "errors": t.errors,
            "undecided": t.undecided,
            "texts": sums,
        }
    })
}

/// How `explain` prints a proof.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ExplainStyle {
    /// The argument in a few lines and one worked case in exact fractions (one screen).
    Short,
    /// The short form, then the full log of every checked case.
    Verbose,
    /// The short form as a LaTeX fragment (the scheme as an `array`).
    Latex,
}

/// The claim and its verdict; the range-bound note shares the verdict's line (the short
/// explanation fits one screen).
fn header(s: &mut String, f: &ClaimFile, c: &Claim, checked: &Checked, range_bound: Option<&str>) {
    let _ = writeln!(s, "claim {} ({})", printable(&c.id), printable(&f.origin()));
    let _ = writeln!(s, "source:    {}", printable(&c.source));
    let _ = writeln!(s, "statement: {}", printable(&c.statement));
    let _ = writeln!(s, "kind:      {}", c.kind.name());
    for (k, v) in c.kind.shown_fields() {
        let _ = writeln!(s, "{k:<10} {}", printable(v));
    }
    if let Kind::Identity(Identity {
        sides: Sides::Chain(ch),
        ..
    }) = &c.kind
    {
        let ch: Vec<Cow<'_, str>> = ch.iter().map(|e| printable(e)).collect();
        let _ = writeln!(s, "chain:     {}", ch.join("\n         = "));
    }
    if !c.decls.defs.is_empty() {
        let defs: Vec<Cow<'_, str>> = c.decls.defs.iter().map(|d| printable(d)).collect();
        let _ = writeln!(s, "where:     {}", defs.join("\n           "));
    }
    if !c.decls.ranges.is_empty() {
        let ranges: Vec<String> = c.decls.ranges.iter().map(|r| r.to_string()).collect();
        let _ = writeln!(s, "for:       {}", printable(&ranges.join(", ")));
    }
    let _ = writeln!(
        s,
        "\nverdict: {}{}",
        verdict_text(checked.verdict(), checked.range()),
        range_bound
            .map(|r| format!("; range-bound: {}", printable(r)))
            .unwrap_or_default()
    );
    let _ = writeln!(
        s,
        "{}: {}",
        if checked.verdict() == Verdict::Fails {
            "counterexample"
        } else {
            "certificate"
        },
        printable(&checked.certificate)
    );
    for line in misprint_lines(f, c) {
        let _ = writeln!(s, "{}", printable(&line));
    }
}

/// The proof of one claim: the argument, one worked case, and (`Verbose`) the whole log.
pub(super) fn explain_text(
    f: &ClaimFile,
    c: &Claim,
    checked: &Checked,
    range_bound: Option<&str>,
    style: ExplainStyle,
) -> String {
    if style == ExplainStyle::Latex {
        return super::latex::explain(f, c, checked, range_bound);
    }
    let mut s = String::new();
    header(&mut s, f, c, checked, range_bound);
    let _ = writeln!(s, "\nwhy this suffices:");
    for line in argument(c, checked) {
        let _ = writeln!(s, "  {}", printable(&line));
    }
    let all = cases(&checked.steps);
    let case = worked_case(&all);
    let evals = case.map(|c| sample_evaluations(c, 4)).unwrap_or_default();
    if let Some(case) = case {
        let _ = writeln!(s, "\nworked case: {}", printable(&case.header.line()));
        for l in case.other_lines().take(4) {
            let _ = writeln!(s, "  {}", printable(&l.line()));
        }
        for l in &evals {
            let _ = writeln!(s, "  {}", printable(&l.to_string()));
        }
    } else {
        let (header, lines) = certificate_case(checked);
        let _ = writeln!(s, "\nworked case: {}", printable(header));
        for l in lines {
            let _ = writeln!(s, "  {}", printable(l));
        }
    }
    if let Some(scheme) = worked_scheme(c, checked, evals.first().copied()) {
        let _ = write!(s, "\n{scheme}");
        if let Some(sum) = evals.first().and_then(|e| worked_sum(c, &scheme, e)) {
            let _ = writeln!(s, "  {sum}");
        }
    }
    let lines = checked.steps.len();
    if style == ExplainStyle::Verbose {
        if lines > 0 {
            let _ = writeln!(s, "\nsteps:");
            for line in &checked.steps {
                let _ = writeln!(s, "  {}", printable(&line.to_string()));
            }
        }
    } else if lines > 0 {
        let shown = case.map(|c| c.evaluations().count()).unwrap_or(0);
        let _ = writeln!(
            s,
            "\nthe full log ({lines} lines, {} case{}; {shown} evaluations in the worked case): --explain {} --verbose",
            all.len(),
            if all.len() == 1 { "" } else { "s" },
            c.id
        );
    }
    s
}

/// The worked case for a reader of the texts (the handout): the exact evaluations of the
/// worked case and its scheme (9), or, with no evaluation, the counterexample or the claim's own
/// data. The symbolic pieces of a proof for every n are left out: they say how the proof
/// went, not what the statement gives.
pub(super) fn worked_lines(c: &Claim, checked: &Checked) -> Vec<String> {
    let mut out = Vec::new();
    let all = cases(&checked.steps);
    let case = worked_case(&all);
    let evals = case.map(|c| sample_evaluations(c, 3)).unwrap_or_default();
    for e in &evals {
        out.push(e.to_string());
    }
    if evals.is_empty() {
        match case {
            Some(case) if checked.verdict() != Verdict::Fails => {
                // a case header in the prover's own terms (quoted expressions, pieces of a
                // domain, generated names) is not for the handout
                let line = case.header.line();
                if !["'", "__", "piece", "≥ 0", "expanded", "terms"]
                    .iter()
                    .any(|w| line.contains(w))
                {
                    out.push(line);
                }
            }
            _ => out.extend(certificate_case(checked).1.into_iter().map(str::to_string)),
        }
    }
    if let Some(scheme) = worked_scheme(c, checked, evals.first().copied()) {
        out.extend(scheme.to_string().lines().map(str::to_string));
        if let Some(sum) = evals.first().and_then(|e| worked_sum(c, &scheme, e)) {
            out.push(sum);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    // Verdicts as data (a report reads them; only the kernel's proofs make them).
    const PROVED: Verdict = Verdict::SHOWN[0];
    const IN_RANGE: Verdict = Verdict::SHOWN[1];

    fn outcome(id: &str, verdict: Verdict, range: Option<&str>, expect: Verdict) -> ClaimOutcome {
        ClaimOutcome {
            id: id.into(),
            source: "s".into(),
            statement: "s".into(),
            verdict,
            range: range.map(String::from),
            method: None,
            rests_on: None,
            certificate: "c".into(),
            expect,
            file: "f.toml".into(),
            text: "t.txt".into(),
            corrects: None,
            note: None,
            range_bound: None,
            data: Default::default(),
            computed: Vec::new(),
        }
    }

    #[test]
    fn every_report_shows_the_scope() {
        let r = Report {
            outcomes: vec![
                outcome("a", PROVED, None, PROVED),
                outcome("b", IN_RANGE, Some("n = 0..=10"), IN_RANGE),
                outcome("c", IN_RANGE, Some("n = 0..=3"), PROVED),
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

    #[test]
    fn the_worked_case_is_the_last_of_degree_3_with_fractions_first() {
        use super::super::kernel::checked::{Evaluation, Step};
        let q = |s: &str| s.parse::<BigRational>().unwrap();
        let eval = |n: i64, t: &str, unit: Option<usize>, value: &str| {
            let basis = unit
                .map(|k| format!(", b[{k}] = 1, other b[j] = 0"))
                .unwrap_or_default();
            Step::evaluation(Evaluation {
                at: format!("n = {n}, t = {t}{basis}"),
                values: vec![("n".into(), q(&n.to_string())), ("t".into(), q(t))],
                unit,
                value: value.into(),
            })
            .nested(2)
        };
        let case = |n: i64, text: &str| Step::instance(vec![("n".into(), n)], text.into());
        let steps = vec![
            case(2, "'a' = 'b': …"),
            eval(2, "1/2", None, "1/4"),
            case(3, "'a' = 'b': …"),
            Step::text("degree in t: … so 4 points suffice").nested(2),
            eval(3, "0", None, "0"),
            case(3, "'b' = 'c': …"),
            eval(3, "0", None, "0"),
            eval(3, "1/3", Some(1), "4/9"),
            case(13, "'b' = 'c': …"),
        ];
        assert_eq!(steps[1].to_string(), "    n = 2, t = 1/2: both sides = 1/4");
        let all = cases(&steps);
        assert_eq!(all.len(), 4);
        let case = worked_case(&all).unwrap();
        assert_eq!(case.header.line(), "[n = 3] 'b' = 'c': …");
        let evals = sample_evaluations(case, 4);
        assert_eq!(evals.len(), 1);
        assert_eq!(
            evals[0].to_string(),
            "n = 3, t = 1/3, b[1] = 1, other b[j] = 0: both sides = 4/9"
        );
        assert_eq!(evals[0].value_of("t"), Some(&q("1/3")));
        assert_eq!(evals[0].value_of("n"), Some(&q("3")));
        assert_eq!(evals[0].value_of("u"), None);
        assert_eq!(evals[0].unit, Some(1));
    }
}
