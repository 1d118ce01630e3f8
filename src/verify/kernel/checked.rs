//! What checking a claim produces: the verdict, what it rests on (a typed [`Method`]), the
//! certificate and, for `explain`, the steps.

use super::certificate::{Data, Refutation};
use super::{Proof, Trusted};
use num_rational::BigRational;
use serde::Serialize;

/// How strong a verdict is, and so what it covers (its scope).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// A proof for every value of every variable of the statement (e.g. a polynomial identity
    /// of degree ≤ d checked exactly at d+1 points).
    Proved,
    /// Every case of the stated finite integer ranges is proved (each case for every value of
    /// its continuous parameters); the ranges are in [`super::ClaimOutcome::range`]. Not a proof for
    /// values outside them.
    ProvedInRange,
    /// Bounded evidence (e.g. a limit checked up to some r), saying exactly what was checked.
    Verified,
    /// The claim is false; the certificate holds an exact counterexample.
    Fails,
    /// Not a verdict: the claim could not be decided (a limit reached, a form the engine does
    /// not handle); the certificate holds the one-line reason. The other claims are still
    /// checked, and `prove` exits with status 2.
    Error,
}

impl Verdict {
    /// The lowercase name used in reports and JSON.
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Proved => "proved",
            Verdict::ProvedInRange => "proved_in_range",
            Verdict::Verified => "verified",
            Verdict::Fails => "fails",
            Verdict::Error => "error",
        }
    }

    /// The verdict named `name` (as [`Verdict::as_str`] writes it), e.g. a claim's `expect`.
    pub fn from_name(name: &str) -> Option<Verdict> {
        [
            Verdict::Proved,
            Verdict::ProvedInRange,
            Verdict::Verified,
            Verdict::Fails,
            Verdict::Error,
        ]
        .into_iter()
        .find(|v| v.as_str() == name)
    }

    /// The strongest verdict a claim can get: `proved_in_range` for a claim bound to finite
    /// ranges, `proved` otherwise.
    pub fn strongest(in_range: bool) -> Verdict {
        if in_range {
            Verdict::ProvedInRange
        } else {
            Verdict::Proved
        }
    }

    /// The verdicts a report explains, strongest first.
    pub const SHOWN: [Verdict; 4] = [
        Verdict::Proved,
        Verdict::ProvedInRange,
        Verdict::Verified,
        Verdict::Fails,
    ];
}

/// The kind of argument a verdict rests on: the explanation argues from it (never from the
/// certificate's or the steps' text). One variant per kind of argument, so a new one is
/// carried by the compiler into every report that explains it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// Exact evaluation at d + 1 distinct points per parameter, for degree bounds d derived
    /// from the expressions (`degree`: the largest); with `basis`, on the zero and unit
    /// control polygons (both sides affine in them).
    Sampling {
        /// Whether the cases ran over basis polygons.
        basis: bool,
        /// The largest degree bound of a parameter.
        degree: u64,
    },
    /// Both sides evaluated exactly, with no free parameter.
    Evaluation,
    /// Exact symbolic expansion as rational functions.
    Expansion,
    /// Hypergeometric terms: rational identities (or products of factors ≥ 0) on every piece
    /// of the domain (Fourier–Motzkin).
    Pieces,
    /// WZ certificates of sums.
    Wz,
    /// A recurrence of a sum found by creative telescoping, with its closed form.
    Telescoping,
    /// A recurrence of sums stated by the claim, checked by creative telescoping.
    StatedRecurrence,
    /// Induction on a range variable: its base and its step, each proved for every value of
    /// the others.
    Induction,
    /// Bernstein coefficients ≥ 0 of a numerator on subintervals.
    Bernstein,
    /// Euler's Beta integral over [0, 1].
    Beta,
    /// A library computation accepted by name (see the proof's `rests_on`).
    Computation,
}

impl Method {
    /// The method of several parts checked together: sampling when any part sampled.
    pub fn join(self, other: Method) -> Method {
        match (self, other) {
            (Method::Sampling { basis: a, degree: d }, Method::Sampling { basis: b, degree: e }) => Method::Sampling {
                basis: a || b,
                degree: d.max(e),
            },
            (s @ Method::Sampling { .. }, _) | (_, s @ Method::Sampling { .. }) => s,
            (Method::Evaluation, m) => m,
            (m, _) => m,
        }
    }

    /// Whether the method proves a claim for every value of open ranges.
    pub fn is_for_every(self) -> bool {
        matches!(
            self,
            Method::Pieces
                | Method::Wz
                | Method::Telescoping
                | Method::StatedRecurrence
                | Method::Induction
                | Method::Beta
        )
    }

    /// The method in one line, as the reports show it.
    pub fn text(self) -> String {
        match self {
            Method::Sampling { basis, degree } => format!(
                "exact evaluation at d + 1 points per parameter (degree bounds up to {degree}){}",
                if basis { ", on the basis polygons" } else { "" }
            ),
            Method::Evaluation => "exact evaluation (no free parameter)".into(),
            Method::Expansion => "exact symbolic expansion".into(),
            Method::Pieces => "hypergeometric terms on the pieces of the domain".into(),
            Method::Wz => "WZ certificates".into(),
            Method::Telescoping => "creative telescoping".into(),
            Method::StatedRecurrence => "the stated recurrence, by creative telescoping".into(),
            Method::Induction => "induction (base and step)".into(),
            Method::Bernstein => "Bernstein coefficients ≥ 0".into(),
            Method::Beta => "Euler's Beta integral".into(),
            Method::Computation => "a library computation accepted by name".into(),
        }
    }
}

/// What a check ended in.
#[derive(Clone, Debug)]
enum Outcome {
    /// A proof: the verdict is the proof's.
    Proved(Proof),
    /// Any other verdict (the constructors below make only `verified`, `fails`, `error`), and
    /// the method of the check that reached it.
    Other(Verdict, Option<Method>),
}

/// The result of checking one claim. It is `proved` (or `proved_in_range`) only by holding a
/// [`Proof`], which only the kernel makes:
///
/// ```compile_fail
/// use casteljau::verify::{Checked, Verdict};
/// let c = Checked { verdict: Verdict::Proved, certificate: String::new(), steps: Vec::new(), params: Vec::new() };
/// ```
/// ```compile_fail
/// fn promote(c: &mut casteljau::verify::Checked) {
///     c.verdict = casteljau::verify::Verdict::Proved;
/// }
/// ```
#[derive(Clone, Debug)]
pub struct Checked {
    outcome: Outcome,
    /// The certificate (one line).
    pub certificate: String,
    /// The step-by-step account (filled when asked for).
    pub steps: Vec<Step>,
    /// The values of the first parameter that the proof checked (for `explain`).
    pub params: Vec<BigRational>,
    /// A verdict other than a proof: its data (a counterexample's).
    data: Data,
}

impl Checked {
    fn other(verdict: Verdict, certificate: String) -> Self {
        Checked {
            outcome: Outcome::Other(verdict, None),
            certificate,
            steps: Vec::new(),
            params: Vec::new(),
            data: Data::None,
        }
    }

    /// A proved claim.
    pub(crate) fn proved(proof: Proof, certificate: String) -> Self {
        Checked {
            outcome: Outcome::Proved(proof),
            certificate,
            steps: Vec::new(),
            params: Vec::new(),
            data: Data::None,
        }
    }

    /// A false claim; the certificate holds the exact counterexample.
    pub(crate) fn fails(certificate: String) -> Self {
        Checked::other(Verdict::Fails, certificate)
    }

    /// Bounded evidence, saying exactly what was checked.
    pub(crate) fn verified(certificate: String) -> Self {
        Checked::other(Verdict::Verified, certificate)
    }

    /// Not decided; the certificate holds the reason.
    pub(crate) fn error(certificate: String) -> Self {
        Checked::other(Verdict::Error, certificate)
    }

    /// A verdict other than a proof, with the method of the check that reached it (a proof's
    /// method is its own and stays).
    pub(crate) fn found_by(mut self, method: Method) -> Self {
        if let Outcome::Other(_, m) = &mut self.outcome {
            *m = Some(method);
        }
        self
    }

    /// A proof read as covering only the cases of `range` (other verdicts stay).
    pub(crate) fn in_range(mut self, range: String) -> Self {
        if let Outcome::Proved(p) = self.outcome {
            self.outcome = Outcome::Proved(p.in_range(range));
        }
        self
    }

    /// A proof that also accepts `trusted` (other verdicts stay).
    pub(crate) fn resting_on(mut self, trusted: Trusted) -> Self {
        if let Outcome::Proved(p) = self.outcome {
            self.outcome = Outcome::Proved(p.resting_on(trusted));
        }
        self
    }

    /// A `fails` verdict with its counterexample as data (other verdicts stay).
    pub(crate) fn refuted(mut self, refutation: Option<Box<Refutation>>) -> Self {
        if let (Some(r), Verdict::Fails) = (refutation, self.verdict()) {
            self.data = Data::Refuted(r);
        }
        self
    }

    /// What the verdict's data is: the proof's, or a counterexample (`docs/certificates.md`).
    pub fn data(&self) -> &Data {
        match &self.outcome {
            Outcome::Proved(p) => p.data(),
            Outcome::Other(..) => &self.data,
        }
    }

    /// The verdict.
    pub fn verdict(&self) -> Verdict {
        match &self.outcome {
            Outcome::Proved(p) => p.verdict(),
            Outcome::Other(v, _) => *v,
        }
    }

    /// The proof, when the claim is proved.
    pub fn proof(&self) -> Option<&Proof> {
        match &self.outcome {
            Outcome::Proved(p) => Some(p),
            Outcome::Other(..) => None,
        }
    }

    /// What the verdict rests on: a proof's method, or the method of the check that found a
    /// counterexample.
    pub fn method(&self) -> Option<Method> {
        match &self.outcome {
            Outcome::Proved(p) => Some(p.method()),
            Outcome::Other(_, m) => *m,
        }
    }

    /// The finite ranges a [`Verdict::ProvedInRange`] covers.
    pub fn range(&self) -> Option<&str> {
        self.proof().and_then(Proof::range)
    }
}

/// One line of a proof's log. What the reports pick out of a log (the cases, the exact
/// evaluations, the pieces where every term vanishes) is a kind, never found in the text.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// Nesting, in two-space indents: 0 heads a case, deeper lines belong to the case above.
    pub depth: usize,
    /// What the line says.
    pub kind: StepKind,
}

/// What one line of a proof's log says.
#[derive(Clone, Debug, PartialEq)]
pub enum StepKind {
    /// A line of the log.
    Text(String),
    /// A label that heads the one equality checked under it (`the zero polygon:`).
    Label(String),
    /// Both sides evaluated exactly at one point and found equal.
    Evaluation(Evaluation),
    /// The header of one case of a finite range: the integer values, then what was checked.
    Instance {
        /// The integer values of the case, in the order shown.
        ints: Vec<(String, i64)>,
        /// What was checked for them.
        text: String,
    },
    /// A piece of a domain on which every term of the identity vanishes.
    Vanishes {
        /// The piece.
        on: String,
    },
}

/// One exact evaluation of both sides of an equality.
#[derive(Clone, Debug, PartialEq)]
pub struct Evaluation {
    /// The point, as shown.
    pub at: String,
    /// The integer values and parameters of the point, by name.
    pub values: Vec<(String, BigRational)>,
    /// The index of the unit control point, when the point is a unit polygon.
    pub unit: Option<usize>,
    /// The common value of both sides.
    pub value: String,
}

impl Evaluation {
    /// The value of `name` at this point.
    pub fn value_of(&self, name: &str) -> Option<&BigRational> {
        self.values.iter().find(|(k, _)| k == name).map(|(_, v)| v)
    }
}

impl Step {
    /// A line of text that heads a case.
    pub fn text(text: impl Into<String>) -> Step {
        Step {
            depth: 0,
            kind: StepKind::Text(text.into()),
        }
    }
    /// A label heading the equality checked under it.
    pub fn label(text: impl Into<String>) -> Step {
        Step {
            depth: 0,
            kind: StepKind::Label(text.into()),
        }
    }
    /// An exact evaluation where both sides agree.
    pub fn evaluation(e: Evaluation) -> Step {
        Step {
            depth: 0,
            kind: StepKind::Evaluation(e),
        }
    }
    /// The header of a case of a finite range.
    pub fn instance(ints: Vec<(String, i64)>, text: String) -> Step {
        Step {
            depth: 0,
            kind: StepKind::Instance { ints, text },
        }
    }
    /// A piece on which every term vanishes.
    pub fn vanishes(on: impl Into<String>) -> Step {
        Step {
            depth: 0,
            kind: StepKind::Vanishes { on: on.into() },
        }
    }
    /// The same line `by` levels deeper.
    pub fn nested(self, by: usize) -> Step {
        Step {
            depth: self.depth + by,
            kind: self.kind,
        }
    }
    /// The line without its indent.
    pub fn line(&self) -> String {
        match &self.kind {
            StepKind::Text(t) | StepKind::Label(t) => t.clone(),
            StepKind::Evaluation(e) => e.to_string(),
            StepKind::Instance { ints, text } if ints.is_empty() => text.clone(),
            StepKind::Instance { ints, text } => {
                let ints: Vec<String> = ints.iter().map(|(k, v)| format!("{k} = {v}")).collect();
                format!("[{}] {text}", ints.join(", "))
            }
            StepKind::Vanishes { on } => format!("on {on}: every term vanishes"),
        }
    }
}

impl std::fmt::Display for Evaluation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: both sides = {}", self.at, self.value)
    }
}

impl std::fmt::Display for Step {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{:width$}{}", "", self.line(), width = 2 * self.depth)
    }
}
