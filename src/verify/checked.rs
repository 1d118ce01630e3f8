//! What checking a claim produces: the verdict, what it rests on (a typed [`Method`]), the
//! certificate and, for `explain`, the steps.

use super::Verdict;
use num_rational::BigRational;

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
