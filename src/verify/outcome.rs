//! What checking a claim produces, as the reports read it: the verdict (a proof's, or one of
//! the verdicts that need none), the certificate and, for `explain`, the steps. A [`Checked`]
//! is `proved` only by holding a [`Proof`], which only the kernel makes.

use super::kernel::certificate::{Data, Refutation};
use super::kernel::checked::{Evaluation, Method, Step, StepKind, Verdict};
use super::kernel::expr::Expr;
use super::kernel::{Proof, Trusted};
use crate::fit::CubicFitData;
use crate::quadratic::QuadraticIrrational;
use num_rational::BigRational;

impl Method {
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
    /// For a proof by a library computation: its inputs and results, for a certificate.
    pub computed: Vec<Computed>,
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

/// A library computation a `computation` proof accepted by name, with its inputs and its
/// result, so that a checker can compute it again (`docs/certificates.md`).
#[derive(Clone, Debug, PartialEq)]
pub enum Computed {
    /// `ImplicitConic::kind` of the conic `lhs = rhs` in x, y: its coefficients `A, …, F` of
    /// `A x² + B xy + C y² + D x + E y + F` (of `lhs − rhs`) and its family.
    ConicKind {
        lhs: Expr,
        rhs: Expr,
        coefficients: Vec<BigRational>,
        kind: &'static str,
    },
    /// `classify_conic` of the rational quadratic with these control points and weights (exact
    /// rationals or `a + b√d`).
    WeightType {
        points: Vec<Vec<QuadraticIrrational>>,
        weights: Vec<QuadraticIrrational>,
        kind: &'static str,
    },
    /// `fit_cubic` (text 004's method) on the curve with these control points (and weights, a
    /// rational curve): its data `x(0), x(1), x(1/2), ẋ(0), ẋ(1)`, the solution `k, l` of the
    /// normal equations (11) and `δ²` there.
    CubicFit {
        points: Vec<Vec<BigRational>>,
        weights: Option<Vec<BigRational>>,
        data: Box<CubicFitData<BigRational>>,
        k: BigRational,
        l: BigRational,
        delta2: BigRational,
    },
    /// The convex hull property for degrees `lo..=hi`, from the cited lemmas (their claim
    /// ids) `B_i^n(t) ≥ 0` on `[0, 1]` and `Σ_i B_i^n(t) = 1`.
    ConvexHull {
        lo: i64,
        hi: i64,
        nonnegative: &'static str,
        sum_one: &'static str,
    },
    /// Affine invariance in the plane for degrees `lo..=hi`, from the cited lemma (its claim
    /// id) `Σ_i B_i^n(t) = 1` and the library's `transform` on the basis maps and polygons.
    AffineInvariance { lo: i64, hi: i64, sum_one: &'static str },
    /// Not a proof's computation: the bounded evidence of Theorem 1.2 (`verified`), each
    /// curve's control points and its exact max-norm distances for `r = 0..=steps`.
    Convergence {
        steps: usize,
        curves: Vec<(String, Vec<Vec<BigRational>>, Vec<BigRational>)>,
    },
}

impl Checked {
    fn other(verdict: Verdict, certificate: String) -> Self {
        Checked {
            computed: Vec::new(),
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
            computed: Vec::new(),
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

    /// The verdict's data, taken out (see [`Checked::data`]).
    pub fn into_data(self) -> Data {
        match self.outcome {
            Outcome::Proved(p) => p.into_data(),
            Outcome::Other(..) => self.data,
        }
    }

    /// The proof, taken out, when the claim is proved.
    pub fn into_proof(self) -> Option<Proof> {
        match self.outcome {
            Outcome::Proved(p) => Some(p),
            Outcome::Other(..) => None,
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

impl Evaluation {
    /// The value of `name` at this point.
    pub fn value_of(&self, name: &str) -> Option<&BigRational> {
        self.values.iter().find(|(k, _)| k == name).map(|(_, v)| v)
    }
}

/// The report lines a log's steps are read as (the kernel writes only text, pieces that
/// vanish and nesting).
impl Step {
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
