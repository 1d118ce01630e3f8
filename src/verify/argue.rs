//! The parts of an explanation that the text and the LaTeX forms share: the verdict's text,
//! the argument (from the typed [`Method`]), the cases of the log and the worked case, the
//! misprint lines and the de Casteljau scheme that goes with a case.

use super::claims::{Claim, ClaimFile, Kind};
use super::kernel::checked::{Evaluation, Method, Step, StepKind, Verdict};
use super::objects::curve_from_spec;
use super::outcome::Checked;
use crate::bernstein::bernstein_all;
use crate::curve::{BezierCurve, DeCasteljauScheme};
use crate::point::Point;
use num_rational::BigRational;
use num_traits::Zero;

/// A verdict with its scope, as the text reports show it: `proved`, `proved for n = 0..=10`,
/// `verified`, `fails`.
pub(crate) fn verdict_text(v: Verdict, range: Option<&str>) -> String {
    match (v, range) {
        (Verdict::ProvedInRange, Some(r)) => format!("proved for {r}"),
        (Verdict::ProvedInRange, None) => "proved in range".into(),
        _ => v.as_str().into(),
    }
}

/// One case of the log: its header and the lines under it.
pub(crate) struct Case<'a> {
    pub(crate) header: &'a Step,
    pub(crate) lines: Vec<&'a Step>,
}

impl Case<'_> {
    /// The lines that are not exact evaluations.
    pub(crate) fn other_lines(&self) -> impl Iterator<Item = &Step> {
        self.lines
            .iter()
            .copied()
            .filter(|l| !matches!(l.kind, StepKind::Evaluation(_)))
    }
    /// The exact evaluations.
    pub(crate) fn evaluations(&self) -> impl Iterator<Item = &Evaluation> {
        self.lines.iter().filter_map(|l| match &l.kind {
            StepKind::Evaluation(e) => Some(e),
            _ => None,
        })
    }
}

pub(crate) fn cases(steps: &[Step]) -> Vec<Case<'_>> {
    let mut out: Vec<Case<'_>> = Vec::new();
    for step in steps {
        match out.last_mut() {
            Some(case) if step.depth > 0 => case.lines.push(step),
            // a label such as "the zero polygon:" heads the equality checked under it
            Some(case) if case.lines.is_empty() && matches!(case.header.kind, StepKind::Label(_)) => {
                case.lines.push(step)
            }
            _ => out.push(Case {
                header: step,
                lines: Vec::new(),
            }),
        }
    }
    out
}

/// The case worked out by default: the last one of degree 3 (the chain's final equality, for a
/// chain), else the first of those showing the most (the zero polygon of a symbolic proof only
/// says that every term vanishes), else the first.
pub(crate) fn worked_case<'a>(all: &'a [Case<'a>]) -> Option<&'a Case<'a>> {
    let degree_3 = |c: &&Case<'_>| match &c.header.kind {
        StepKind::Instance { ints, .. } => ints.last().is_some_and(|(k, v)| k.ends_with('n') && *v == 3),
        _ => false,
    };
    all.iter()
        .rev()
        .find(degree_3)
        .or_else(|| {
            // the first case with the most to show (a piece where every term vanishes shows little)
            let shown = |c: &Case<'_>| {
                let live = c.lines.iter().filter(|l| !matches!(l.kind, StepKind::Vanishes { .. }));
                // under a label, its equality's own line shows nothing yet
                let own = usize::from(matches!(c.header.kind, StepKind::Label(_)));
                live.count().saturating_sub(own)
            };
            all.iter().rev().filter(|c| shown(c) > 0).max_by_key(|c| shown(c))
        })
        .or_else(|| all.first())
}

/// The worked case of a claim whose check leaves no log (a classification, a fit, a vector
/// identity, a theorem checked by its own code): the certificate's computation, one step a line.
pub(crate) fn certificate_case(checked: &Checked) -> (&'static str, Vec<&str>) {
    let header = if checked.verdict() == Verdict::Fails {
        "the counterexample, computed exactly:"
    } else {
        "the claim's own data, computed exactly:"
    };
    // a counterexample reads "at <point>: <what happens there>": one line each
    let lines = checked
        .certificate
        .split("; ")
        .flat_map(|part| match part.strip_prefix("at ").and_then(|p| p.split_once(": ")) {
            Some((point, rest)) if checked.verdict() == Verdict::Fails => vec![&part[..point.len() + 3], rest],
            _ => vec![part],
        })
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect();
    (header, lines)
}

/// Says that an expected failure is a misprint of the text and names its correction (or, for a
/// correction, the misprint it corrects).
pub(crate) fn misprint_lines(f: &ClaimFile, c: &Claim) -> Vec<String> {
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
pub(crate) fn sample_evaluations<'a>(case: &Case<'a>, k: usize) -> Vec<&'a Evaluation> {
    let evals: Vec<&Evaluation> = case
        .lines
        .iter()
        .filter_map(|l| match &l.kind {
            StepKind::Evaluation(e) => Some(e),
            _ => None,
        })
        .collect();
    let mut pick: Vec<&Evaluation> = evals
        .iter()
        .copied()
        .filter(|e| e.value.contains('/'))
        .take(k)
        .collect();
    if pick.is_empty() {
        pick = evals.into_iter().take(k).collect();
    }
    pick
}

/// The argument: what was checked and why it suffices. Every method has its arm, so a new one
/// is placed here by the compiler.
pub(crate) fn argument(c: &Claim, checked: &Checked) -> Vec<String> {
    let mut a = Vec::new();
    let own_failure = matches!(c.kind, Kind::Inequality(_) | Kind::Implies(_));
    if checked.verdict() == Verdict::Fails && !own_failure {
        a.push("One counterexample disproves a claim: the counterexample above is computed in exact rational".into());
        a.push("arithmetic, so the statement is false there, and nothing more needs checking.".into());
        return a;
    }
    match checked.method() {
        _ if matches!(c.kind, Kind::Inequality(_)) => {
            a.extend(super::inequality::ARGUMENT.iter().map(|l| l.to_string()));
            if checked.method() == Some(Method::Pieces) {
                a.extend(super::inequality::ARGUMENT_FOR_EVERY.iter().map(|l| l.to_string()));
            }
        }
        Some(Method::Induction) => {
            a.extend(super::symbolic::INDUCTION_ARGUMENT.iter().map(|l| l.to_string()));
            a.extend(super::symbolic::ARGUMENT.iter().map(|l| l.to_string()));
        }
        Some(Method::Pieces | Method::Wz | Method::Telescoping | Method::StatedRecurrence | Method::Beta)
            if checked.range().is_none() =>
        {
            a.extend(super::symbolic::ARGUMENT.iter().map(|l| l.to_string()));
        }
        Some(Method::Sampling { basis, .. }) => {
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
                a.push(
                    "the zero polygon and each unit polygon covers every control polygon. All checks are exact.".into(),
                );
            } else {
                a.push("(a grid, by induction on the variables). All checks are in exact rational arithmetic.".into());
            }
        }
        Some(
            Method::Pieces
            | Method::Wz
            | Method::Telescoping
            | Method::StatedRecurrence
            | Method::Beta
            | Method::Evaluation
            | Method::Expansion
            | Method::Bernstein
            | Method::Computation,
        )
        | None => a.extend(kind_argument(&c.kind).iter().map(|l| l.to_string())),
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
pub(crate) fn worked_scheme(
    c: &Claim,
    checked: &Checked,
    eval: Option<&Evaluation>,
) -> Option<DeCasteljauScheme<BigRational>> {
    if let (Some(poly), Some(line), Some(var)) = (&c.decls.polygon, eval, c.decls.vars.as_ref().and_then(|v| v.first()))
    {
        let uses_scheme = identity_members(c)
            .iter()
            .any(|e| e.contains(&format!("{}(0, ", poly.name)));
        let n: usize = line
            .value_of(&poly.degree)
            .and_then(|v| v.to_integer().try_into().ok())?;
        let t = line.value_of(var)?;
        let unit = line.unit?;
        if uses_scheme && n <= 6 {
            let points = (0..=n)
                .map(|j| Point::from_ints(&[i64::from(j == unit)]))
                .collect::<crate::error::Result<Vec<_>>>()
                .ok()?;
            return Some(BezierCurve::new(points).ok()?.scheme(t));
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
        .find_map(|spec| match curve_from_spec::<BigRational>(spec) {
            Ok(crate::AnyCurve::Polynomial(curve)) => Some(curve.scheme(&t)),
            _ => None,
        })
}

/// For a claim whose expressions contain `Σ_r b_0^r(t0) B_r^n(t)` (`b(0, r, t0)*B(r, n, t)`):
/// that sum written out at the worked evaluation, from the scheme's upper edge, and its value.
pub(crate) fn worked_sum(c: &Claim, scheme: &DeCasteljauScheme<BigRational>, eval: &Evaluation) -> Option<String> {
    let poly = c.decls.polygon.as_ref()?;
    let vars = c.decls.vars.as_ref()?;
    let (v0, v1) = (vars.first()?, vars.get(1)?);
    let pattern = format!("{}(0, r, {v0})*B(r, {}, {v1})", poly.name, poly.degree);
    if !identity_members(c).iter().any(|e| e.contains(&pattern)) {
        return None;
    }
    let t = eval.value_of(v1)?.clone();
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
