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
}

impl Method {
    /// The method of several parts checked together: sampling when any part sampled.
    pub fn join(self, other: Method) -> Method {
        match (self, other) {
            (Method::Sampling { basis: a }, Method::Sampling { basis: b }) => Method::Sampling { basis: a || b },
            (s @ Method::Sampling { .. }, _) | (_, s @ Method::Sampling { .. }) => s,
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
    pub steps: Vec<String>,
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
