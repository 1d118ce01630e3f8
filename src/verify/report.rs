//! The reports of a `prove` run: readable text, JSON, and the step-by-step `explain`.

use super::checked::{Checked, Method};
use super::claims::{Claim, ClaimFile, Identity, Kind, Sides};
use super::objects::CurveObj;
use super::{ClaimOutcome, Report, Verdict};
use crate::bernstein::bernstein_all;
use crate::curve::{BezierCurve, DeCasteljauScheme};
use crate::point::Point;
use num_rational::BigRational;
use num_traits::Zero;
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
            let label = match o.verdict {
                Verdict::Fails => "counterexample",
                Verdict::Error => "error",
                _ => "certificate",
            };
            let _ = writeln!(s, "    {label}: {}", o.certificate);
            if let Some(r) = &o.range_bound {
                let _ = writeln!(s, "    range-bound: {r}");
            }
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
    if !t.undecided.is_empty() {
        let _ = writeln!(
            s,
            "claims not decided (error, each with its reason): {}",
            t.undecided.join(", ")
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

/// One case of the log: its header line and the lines under it.
pub(super) struct Case<'a> {
    pub(super) header: &'a str,
    pub(super) lines: Vec<&'a str>,
}

pub(super) fn cases(steps: &[String]) -> Vec<Case<'_>> {
    let mut out: Vec<Case<'_>> = Vec::new();
    for line in steps {
        match out.last_mut() {
            Some(case) if line.starts_with(' ') => case.lines.push(line.trim()),
            // a label such as "the zero polygon:" heads the equality checked under it
            Some(case) if case.lines.is_empty() && case.header.ends_with(':') => case.lines.push(line.trim()),
            _ => out.push(Case {
                header: line.trim(),
                lines: Vec::new(),
            }),
        }
    }
    out
}

/// The case worked out by default: the last one of degree 3 (the chain's final equality, for a
/// chain), else the first of those showing the most (the zero polygon of a symbolic proof only
/// says that every term vanishes), else the first.
pub(super) fn worked_case<'a>(all: &'a [Case<'a>]) -> Option<&'a Case<'a>> {
    all.iter()
        .rev()
        .find(|c| c.header.starts_with('[') && c.header.split(']').next().is_some_and(|h| h.ends_with("n = 3")))
        .or_else(|| {
            // the first case with the most to show (a piece where every term vanishes shows little)
            let shown = |c: &Case<'_>| c.lines.iter().filter(|l| !l.ends_with("every term vanishes")).count();
            all.iter().rev().filter(|c| shown(c) > 0).max_by_key(|c| shown(c))
        })
        .or_else(|| all.first())
}

/// The worked case of a claim whose check leaves no log (a classification, a fit, a vector
/// identity, a theorem checked by its own code): the certificate's computation, one step a line.
pub(super) fn certificate_case(checked: &Checked) -> (&'static str, Vec<&str>) {
    let header = if checked.verdict == Verdict::Fails {
        "the counterexample, computed exactly:"
    } else {
        "the claim's own data, computed exactly:"
    };
    // a counterexample reads "at <point>: <what happens there>": one line each
    let lines = checked
        .certificate
        .split("; ")
        .flat_map(|part| match part.strip_prefix("at ").and_then(|p| p.split_once(": ")) {
            Some((point, rest)) if checked.verdict == Verdict::Fails => vec![&part[..point.len() + 3], rest],
            _ => vec![part],
        })
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect();
    (header, lines)
}

/// Says that an expected failure is a misprint of the text and names its correction (or, for a
/// correction, the misprint it corrects).
pub(super) fn misprint_lines(f: &ClaimFile, c: &Claim) -> Vec<String> {
    let mut out = Vec::new();
    if c.expected() == Verdict::Fails {
        out.push("expected:  fails, as printed: a misprint of the text (kept, never corrected in place)".into());
        if let Some(note) = &c.note {
            out.push(format!("note:      {note}"));
        }
        let fixes: Vec<&str> = f
            .claim
            .iter()
            .filter(|d| d.corrects.as_deref() == Some(c.id.as_str()))
            .map(|d| d.id.as_str())
            .collect();
        if fixes.is_empty() {
            out.push("correction: none in this claim file".into());
        }
        for id in fixes {
            out.push(format!("correction: {id} (see --explain {id})"));
        }
    }
    if let Some(target) = &c.corrects {
        out.push(format!(
            "corrects:  {target}, the misprint as printed (see --explain {target})"
        ));
    }
    out
}

/// Up to `k` evaluations of a case, preferring those whose value is a proper fraction.
pub(super) fn sample_evaluations<'a>(case: &Case<'a>, k: usize) -> Vec<&'a str> {
    let evals: Vec<&str> = case
        .lines
        .iter()
        .copied()
        .filter(|l| l.contains("both sides"))
        .collect();
    let mut pick: Vec<&str> = evals
        .iter()
        .copied()
        .filter(|l| l.rsplit('=').next().is_some_and(|v| v.contains('/')))
        .take(k)
        .collect();
    if pick.is_empty() {
        pick = evals.into_iter().take(k).collect();
    }
    pick
}

/// The argument: what was checked and why it suffices.
pub(super) fn argument(c: &Claim, checked: &Checked) -> Vec<String> {
    let mut a = Vec::new();
    if matches!(c.kind, Kind::Inequality(_)) {
        a.extend(super::inequality::ARGUMENT.iter().map(|l| l.to_string()));
        if checked.method == Method::ForEvery {
            a.extend(super::inequality::ARGUMENT_FOR_EVERY.iter().map(|l| l.to_string()));
        }
    } else if checked.method == Method::ForEvery && checked.range.is_none() {
        a.extend(super::symbolic::ARGUMENT.iter().map(|l| l.to_string()));
    } else if let Method::Sampling { basis } = checked.method {
        let vars = c
            .decls
            .vars
            .as_ref()
            .map(|v| v.join(", "))
            .unwrap_or_else(|| "the parameters".into());
        a.push(format!(
            "Each equality, cleared of denominators, is a polynomial identity in {vars}; its degree d in each"
        ));
        a.push(
            "variable is bounded from the expressions. A nonzero polynomial of degree ≤ d in one variable has at"
                .into(),
        );
        a.push(
            "most d roots, so the identity holds for all values iff it holds at d+1 distinct points per variable"
                .into(),
        );
        if basis {
            a.push(
                "(a grid, by induction on the variables). Both sides are affine in the control points, so checking"
                    .into(),
            );
            a.push("the zero polygon and each unit polygon covers every control polygon. All checks are exact.".into());
        } else {
            a.push("(a grid, by induction on the variables). All checks are in exact rational arithmetic.".into());
        }
    } else {
        a.extend(kind_argument(&c.kind).iter().map(|l| l.to_string()));
    }
    a
}

/// Why the check of a claim without a points-per-degree log suffices, by kind.
fn kind_argument(kind: &Kind) -> &'static [&'static str] {
    match kind {
        Kind::ConicType(_) => &[
            "The conic A x² + B xy + C y² + D x + E y + F = 0 is degenerate when its symmetric 3×3 matrix is",
            "singular; otherwise it is an ellipse (with real points when (A + C)·det < 0), a parabola or a",
            "hyperbola as B² − 4AC < 0, = 0 or > 0. Every quantity is computed exactly from the coefficients,",
            "so each sign is decided, not estimated.",
        ],
        Kind::WeightType(_) => &[
            "A rational quadratic with positive weights w0, w1, w2 (as in the texts) is an arc of an ellipse, a parabola or a",
            "hyperbola as w1²/(w0 w2) < 1, = 1 or > 1 (the ratio is unchanged by reparametrisation); it is",
            "computed exactly from the weights.",
        ],
        Kind::Implies(_) => &[
            "The equation, moved to one side, is compared with the factor times the premise by exact symbolic",
            "expansion in every symbol and vector coordinate: if the two are identical, the premise being zero",
            "forces the equation. A failure is an exact point where the premise holds and the equation does not.",
        ],
        Kind::Fit(_) => &[
            "δ²(k, l) is a quadratic in the tangent lengths k and l. The normal equations (11) are solved by exact",
            "elimination and compared with the closed form (13); a zero gradient there with a non-singular Gram",
            "matrix makes that point the unique minimum, so the printed k, l and δ² are the method's values.",
        ],
        Kind::Theorem(_) => &[
            "A general theorem, checked for each degree n of its range by the library's own code. For each n",
            "the check is a proof: both sides are polynomials of bounded degree in the parameters and linear",
            "in the data, so the finitely many cases of the certificate (basis polygons, matrix units,",
            "parameters) cover every input of that degree. Degrees outside the range are not covered.",
        ],
        Kind::Convergence(_) => &[
            "A statement about a limit cannot be decided by finitely many exact evaluations: the certificate is",
            "bounded evidence, the exact distances for the elevations checked and the explicit bound they meet.",
        ],
        _ => &["Decided in exact arithmetic; the certificate above says what was established and how."],
    }
}

/// The claim and its verdict; the range-bound note shares the verdict's line (the short
/// explanation fits one screen).
fn header(s: &mut String, f: &ClaimFile, c: &Claim, checked: &Checked, range_bound: Option<&str>) {
    let _ = writeln!(s, "claim {} ({})", c.id, f.path.display());
    let _ = writeln!(s, "source:    {}", c.source);
    let _ = writeln!(s, "statement: {}", c.statement);
    let _ = writeln!(s, "kind:      {}", c.kind.name());
    for (k, v) in c.kind.shown_fields() {
        let _ = writeln!(s, "{k:<10} {v}");
    }
    if let Kind::Identity(Identity {
        sides: Sides::Chain(ch),
        ..
    }) = &c.kind
    {
        let _ = writeln!(s, "chain:     {}", ch.join("\n         = "));
    }
    if !c.decls.defs.is_empty() {
        let _ = writeln!(s, "where:     {}", c.decls.defs.join("\n           "));
    }
    if !c.decls.ranges.is_empty() {
        let ranges: Vec<String> = c.decls.ranges.iter().map(|r| r.to_string()).collect();
        let _ = writeln!(s, "for:       {}", ranges.join(", "));
    }
    let _ = writeln!(
        s,
        "\nverdict: {}{}",
        verdict_text(checked.verdict, checked.range.as_deref()),
        range_bound.map(|r| format!("; range-bound: {r}")).unwrap_or_default()
    );
    let _ = writeln!(
        s,
        "{}: {}",
        if checked.verdict == Verdict::Fails {
            "counterexample"
        } else {
            "certificate"
        },
        checked.certificate
    );
    for line in misprint_lines(f, c) {
        let _ = writeln!(s, "{line}");
    }
}

/// The value of `name` in an evaluation line such as `n = 3, t0 = 1/2, t = 1/3, b[1] = 1, …`.
fn value_in(line: &str, name: &str) -> Option<BigRational> {
    let head = line.split(':').next()?;
    head.split(", ").find_map(|part| {
        let (k, v) = part.split_once(" = ")?;
        if k.trim() == name {
            v.trim().parse().ok()
        } else {
            None
        }
    })
}

/// The members of an identity claim's chain (none for another kind).
fn identity_members(c: &Claim) -> Vec<String> {
    match &c.kind {
        Kind::Identity(i) => i.sides.members(),
        _ => Vec::new(),
    }
}

/// The scheme (9) that goes with the worked case: for a claim about a symbolic polygon whose
/// expressions use its scheme (`b(i, r, t0)`), the scheme of the case's unit polygon at the case's
/// first parameter; else the first polynomial curve of the claim at its first nonzero checked
/// parameter.
pub(super) fn worked_scheme(
    c: &Claim,
    checked: &Checked,
    eval: Option<&str>,
) -> Option<DeCasteljauScheme<BigRational>> {
    if let (Some(poly), Some(line), Some(var)) = (&c.decls.polygon, eval, c.decls.vars.as_ref().and_then(|v| v.first()))
    {
        let uses_scheme = identity_members(c)
            .iter()
            .any(|e| e.contains(&format!("{}(0, ", poly.name)));
        let n: usize = value_in(line, &poly.degree).and_then(|v| v.to_integer().try_into().ok())?;
        let t = value_in(line, var)?;
        let unit = line.split(", ").find_map(|p| {
            let rest = p.strip_prefix(&format!("{}[", poly.name))?;
            let (k, v) = rest.split_once("] = ")?;
            (v.trim() == "1").then(|| k.parse::<usize>().ok()).flatten()
        })?;
        if uses_scheme && n <= 6 {
            let points = (0..=n)
                .map(|j| Point::from_ints(&[i64::from(j == unit)]))
                .collect::<crate::error::Result<Vec<_>>>()
                .ok()?;
            return Some(BezierCurve::new(points).ok()?.scheme(&t));
        }
        return None;
    }
    let t = checked
        .params
        .iter()
        .find(|t| !t.is_zero())
        .cloned()
        .unwrap_or_else(|| BigRational::new(1.into(), 2.into()));
    c.decls
        .curves
        .as_ref()?
        .values()
        .find_map(|spec| match CurveObj::<BigRational>::from_spec(spec) {
            Ok(CurveObj::Polynomial(curve)) => Some(curve.scheme(&t)),
            _ => None,
        })
}

/// For a claim whose expressions contain `Σ_r b_0^r(t0) B_r^n(t)` (`b(0, r, t0)*B(r, n, t)`):
/// that sum written out at the worked evaluation, from the scheme's upper edge, and its value.
pub(super) fn worked_sum(c: &Claim, scheme: &DeCasteljauScheme<BigRational>, eval: &str) -> Option<String> {
    let poly = c.decls.polygon.as_ref()?;
    let vars = c.decls.vars.as_ref()?;
    let (v0, v1) = (vars.first()?, vars.get(1)?);
    let pattern = format!("{}(0, r, {v0})*B(r, {}, {v1})", poly.name, poly.degree);
    if !identity_members(c).iter().any(|e| e.contains(&pattern)) {
        return None;
    }
    let t = value_in(eval, v1)?;
    let n = scheme.degree();
    let bern = bernstein_all(n, &t);
    let mut terms = Vec::new();
    let mut total = BigRational::zero();
    for (r, b) in bern.iter().enumerate() {
        let edge = scheme.get(r, 0)?.coords().first()?.clone();
        terms.push(format!("{edge}·{b}"));
        total += &edge * b;
    }
    Some(format!(
        "Σ_r {}_0^r({v0}) B_r^{n}({v1}) at {v0} = {}, {v1} = {t}: {} = {total} (the first evaluation)",
        poly.name,
        scheme.t,
        terms.join(" + ")
    ))
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
        let _ = writeln!(s, "  {line}");
    }
    let all = cases(&checked.steps);
    let case = worked_case(&all);
    let evals = case.map(|c| sample_evaluations(c, 4)).unwrap_or_default();
    if let Some(case) = case {
        let _ = writeln!(s, "\nworked case: {}", case.header);
        for l in case.lines.iter().filter(|l| !l.contains("both sides")).take(4) {
            let _ = writeln!(s, "  {l}");
        }
        for l in &evals {
            let _ = writeln!(s, "  {l}");
        }
    } else {
        let (header, lines) = certificate_case(checked);
        let _ = writeln!(s, "\nworked case: {header}");
        for l in lines {
            let _ = writeln!(s, "  {l}");
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
                let _ = writeln!(s, "  {line}");
            }
        }
    } else if lines > 0 {
        let shown = case
            .map(|c| c.lines.iter().filter(|l| l.contains("both sides")).count())
            .unwrap_or(0);
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
            range_bound: None,
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

    #[test]
    fn the_worked_case_is_the_last_of_degree_3_with_fractions_first() {
        let steps: Vec<String> = [
            "[n = 2] 'a' = 'b': …",
            "    n = 2, t = 1/2: both sides = 1/4",
            "[n = 3] 'a' = 'b': …",
            "    degree in t: … so 4 points suffice",
            "    n = 3, t = 0: both sides = 0",
            "[n = 3] 'b' = 'c': …",
            "    n = 3, t = 0: both sides = 0",
            "    n = 3, t = 1/3, b[1] = 1, other b[j] = 0: both sides = 4/9",
            "[n = 13] 'b' = 'c': …",
        ]
        .map(String::from)
        .to_vec();
        let all = cases(&steps);
        assert_eq!(all.len(), 4);
        let case = worked_case(&all).unwrap();
        assert_eq!(case.header, "[n = 3] 'b' = 'c': …");
        let evals = sample_evaluations(case, 4);
        assert_eq!(evals, ["n = 3, t = 1/3, b[1] = 1, other b[j] = 0: both sides = 4/9"]);
        assert_eq!(value_in(evals[0], "t"), Some(BigRational::new(1.into(), 3.into())));
        assert_eq!(value_in(evals[0], "n"), Some(BigRational::from_integer(3.into())));
        assert_eq!(value_in(evals[0], "u"), None);
    }
}
