//! What checking a claim produces: the verdict, what it rests on (a typed [`Method`]), the
//! certificate and, for `explain`, the steps.

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
}

/// What a verdict rests on: the explanation argues from it (never from the certificate's
/// or the steps' text).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Method {
    /// A check of the kind's own: a classification, an exact elimination, library code on a
    /// finite set of cases, bounded evidence or a counterexample.
    #[default]
    Direct,
    /// Exact evaluation at d + 1 points per parameter, for degree bounds d derived from the
    /// expressions; with `basis`, on the zero and unit control polygons (both sides affine in
    /// them).
    Sampling {
        /// Whether the cases ran over basis polygons.
        basis: bool,
    },
    /// For every value of the open ranges: hypergeometric terms, WZ certificates, Fourier–Motzkin
    /// pieces or Bernstein certificates of the factors.
    ForEvery,
    /// For every value by induction on a range variable: its base and its step, each proved
    /// for every value of the others.
    Induction,
}

impl Method {
    /// The method of several parts checked together: sampling when any part sampled.
    pub fn join(self, other: Method) -> Method {
        match (self, other) {
            (Method::Sampling { basis: a }, Method::Sampling { basis: b }) => Method::Sampling { basis: a || b },
            (s @ Method::Sampling { .. }, _) | (_, s @ Method::Sampling { .. }) => s,
            (Method::Induction, _) | (_, Method::Induction) => Method::Induction,
            (Method::ForEvery, _) | (_, Method::ForEvery) => Method::ForEvery,
            _ => Method::Direct,
        }
    }
}

/// The result of checking one claim.
#[derive(Clone, Debug)]
pub struct Checked {
    /// The verdict.
    pub verdict: Verdict,
    /// What the verdict rests on.
    pub method: Method,
    /// The finite ranges a [`Verdict::ProvedInRange`] covers.
    pub range: Option<String>,
    /// The certificate (one line).
    pub certificate: String,
    /// The step-by-step account (filled when asked for).
    pub steps: Vec<Step>,
    /// The values of the first parameter that the proof checked (for `explain`).
    pub params: Vec<BigRational>,
}

impl Checked {
    pub(crate) fn new(verdict: Verdict, certificate: String) -> Self {
        Checked {
            verdict,
            method: Method::Direct,
            range: None,
            certificate,
            steps: Vec::new(),
            params: Vec::new(),
        }
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
