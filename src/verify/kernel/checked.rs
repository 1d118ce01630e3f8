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

impl Step {
    /// A line of text that heads a case.
    pub fn text(text: impl Into<String>) -> Step {
        Step {
            depth: 0,
            kind: StepKind::Text(text.into()),
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
}
