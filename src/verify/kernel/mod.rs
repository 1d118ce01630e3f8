//! The trusted core: what a verdict is, and the one door through which a `proved` passes.
//!
//! A [`Proof`] has private fields and is made only by the `check_*` functions of this module;
//! [`Proof::verdict`] is the only expression of the crate that yields [`Verdict::Proved`] or
//! [`Verdict::ProvedInRange`], and a `Checked` (`verify::outcome`) is `proved` only by holding a `Proof`. Every
//! proof names its kind of argument ([`Method`]) and the library computations it accepts by
//! name ([`Trusted`], as Lean's `#print axioms` names compiled code it trusts).
//!
//! What the entries check themselves, and what they still take from their callers, is listed
//! in `docs/trust.md`. The for-every obligations of sums (WZ, creative telescoping, stated
//! recurrences) are built and proved here from what the searches propose (`recurrence`), on
//! the hypergeometric terms and domain pieces of this folder; so are identities by exact
//! evaluation at enough points (`sample`), identities by symbolic expansion (`expand`), and
//! inequalities by Bernstein coefficients, on an interval or on the pieces of a domain
//! (`bernstein`).
//!
//! This module imports nothing of `verify` outside `kernel/` (checked by `tests/layers.rs`).

pub(crate) mod alg;
pub(crate) mod bernstein;
pub(crate) mod beta;
pub(crate) mod budget;
pub(crate) mod certificate;
pub mod checked;
pub(crate) mod eval;
pub(crate) mod expand;
pub(crate) mod expr;
pub(crate) mod hyper;
pub(crate) mod nonneg;
pub(crate) mod pieces;
pub(crate) mod poly;
pub(crate) mod powers;
pub(crate) mod recurrence;
pub(crate) mod sample;

use checked::{Method, Verdict};
use num_rational::BigRational;
use serde::Serialize;
use std::collections::BTreeSet;

/// A library computation whose result a verdict accepts without re-deriving it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Trusted {
    /// `conic::classify_conic`: the type of a rational quadratic's conic from its weights.
    ClassifyConic,
    /// `ImplicitConic::kind`: the type of an implicit conic from its six coefficients.
    ConicKind,
    /// `BezierCurve::from_power_on`: the Bézier points of a power form on an interval.
    FromPowerOn,
    /// `fit::fit_cubic`, `fit_cubic_closed_form`, `delta_squared`, `delta_squared_gradient`.
    CubicFit,
    /// `BezierCurve::transform` and `eval`, run over a theorem's degree range.
    Transform,
    /// `bernstein::bernstein_all`, run over a theorem's degree range.
    BernsteinAll,
    /// `BezierCurve::hull_weights`, the exact convex-hull test.
    HullWeights,
    /// A library operation on a polygon or net called in the claim's expressions, by its name
    /// there (`bsum`, `elev`, `isou`, …).
    Operation(&'static str),
}

impl Trusted {
    /// The library function's name, as reports show it.
    pub fn name(self) -> &'static str {
        match self {
            Trusted::ClassifyConic => "classify_conic",
            Trusted::ConicKind => "ImplicitConic::kind",
            Trusted::FromPowerOn => "BezierCurve::from_power_on",
            Trusted::CubicFit => "fit_cubic",
            Trusted::Transform => "BezierCurve::transform",
            Trusted::BernsteinAll => "bernstein_all",
            Trusted::HullWeights => "BezierCurve::hull_weights",
            Trusted::Operation(name) => name,
        }
    }
}

impl Serialize for Trusted {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

/// What a proof covers.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Scope {
    /// Every value of every variable.
    Every,
    /// Every case of these finite ranges.
    InRange(String),
}

/// A proof: made only by this module's `check_*` functions.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Proof {
    scope: Scope,
    method: Method,
    rests_on: Vec<Trusted>,
    data: certificate::Data,
}

impl Proof {
    fn new(method: Method, rests_on: &[Trusted]) -> Proof {
        let rests_on: BTreeSet<Trusted> = rests_on.iter().copied().collect();
        Proof {
            scope: Scope::Every,
            method,
            rests_on: rests_on.into_iter().collect(),
            data: certificate::Data::None,
        }
    }

    /// The verdict this proof earns: the only way to a `proved` or `proved_in_range`.
    pub fn verdict(&self) -> Verdict {
        match self.scope {
            Scope::Every => Verdict::Proved,
            Scope::InRange(_) => Verdict::ProvedInRange,
        }
    }

    /// The kind of argument.
    pub fn method(&self) -> Method {
        self.method
    }

    /// The library computations the proof accepts by name (empty when it accepts none).
    pub fn rests_on(&self) -> &[Trusted] {
        &self.rests_on
    }

    /// What the kernel checked, as data a checker can re-check (`docs/certificates.md`).
    pub fn data(&self) -> &certificate::Data {
        &self.data
    }

    /// What the kernel checked, taken out of the proof (for a report that keeps it).
    pub fn into_data(self) -> certificate::Data {
        self.data
    }

    /// The same proof with the goal its for-every obligations were built from, as its data.
    pub fn with_goal(mut self, goal: certificate::Symbolic) -> Proof {
        if self.method.is_for_every() {
            self.data = certificate::Data::Symbolic(Box::new(goal));
        }
        self
    }

    /// The same proof with the for-every inequality's goal and the obligations its pieces
    /// discharged, as its data (a proof by [`Method::Pieces`] only).
    pub fn with_nonneg(mut self, record: nonneg::Nonneg) -> Proof {
        if self.method == Method::Pieces {
            self.data = certificate::Data::Nonneg(Box::new(record));
        }
        self
    }

    /// The finite ranges a `proved_in_range` covers.
    pub fn range(&self) -> Option<&str> {
        match &self.scope {
            Scope::Every => None,
            Scope::InRange(r) => Some(r),
        }
    }

    /// The same proof read as covering only the cases of `range` (a weakening: a claim
    /// checked case by case over finite ranges is proved in them, never for every value).
    pub fn in_range(mut self, range: String) -> Proof {
        self.scope = Scope::InRange(range);
        self
    }

    /// The same proof, also accepting `trusted` (a weakening).
    pub fn resting_on(mut self, trusted: Trusted) -> Proof {
        if !self.rests_on.contains(&trusted) {
            self.rests_on.push(trusted);
            self.rests_on.sort();
        }
        self
    }
}

/// A proof from exact evaluation: every equality of every case checked by
/// [`sample::check_pair`] on its whole grid, each parameter at more distinct values than its
/// degree bound d (a nonzero polynomial of degree ≤ d has at most d roots). Parameter-free
/// cases are exact evaluations of both sides.
pub fn check_sampled(cases: Vec<sample::Case>) -> Result<Proof, String> {
    if cases.is_empty() {
        return Err("no case was evaluated".into());
    }
    let basis = cases.iter().any(|c| c.polygons > 1);
    let mut proof = Proof::new(sampled_method(cases.iter().flat_map(|c| &c.degrees), basis), &[]);
    proof.data = certificate::Data::Sampled(cases.into_iter().map(|c| *c.data).collect());
    Ok(proof)
}

/// The method of exact evaluation at grids with these degree bounds (one per parameter of
/// each case; `basis`: some case on basis polygons): with no parameter, exact evaluation.
fn sampled_method<'a>(degrees: impl IntoIterator<Item = &'a u64>, basis: bool) -> Method {
    match degrees.into_iter().max() {
        Some(&degree) => Method::Sampling { basis, degree },
        None => Method::Evaluation,
    }
}

/// A proof by exact symbolic expansion from pairs of sides expanded by [`expand::expand`]:
/// at least one, and in each the cleared difference of every pair of entries is the zero
/// polynomial.
pub fn check_expanded(pairs: &[expand::Expanded]) -> Option<Proof> {
    (!pairs.is_empty() && pairs.iter().all(|p| p.difference().is_none())).then(|| Proof {
        data: certificate::Data::Expanded(pairs.iter().map(|p| p.record.clone()).collect()),
        ..Proof::new(Method::Expansion, &[])
    })
}

/// A proof accepting library computations by name: every fact the computation reported
/// (e.g. its classification equal to the printed one) must hold.
pub fn check_computed(facts: &[bool], rests_on: &[Trusted]) -> Option<Proof> {
    facts
        .iter()
        .all(|&f| f)
        .then(|| Proof::new(Method::Computation, rests_on))
}

/// A proof that `lhs − rhs ≥ 0` (`> 0` when `strict`) on `[a, b]` from its values, one
/// rational function of the parameter per case: for each, the kernel computes the Bernstein
/// coefficients of the denominator and the numerator on the subintervals of its own halving
/// ([`bernstein::nonnegative`]); none may be negative, and the denominator keeps one sign.
pub fn check_bernstein(values: &[poly::RatFunc], a: &BigRational, b: &BigRational, strict: bool) -> Option<Proof> {
    (a < b && !values.is_empty() && values.iter().all(|v| bernstein::nonnegative(v, a, b, strict)))
        .then(|| Proof::new(Method::Bernstein, &[]))
}

/// An obligation of a for-every proof checked by this module (made only here): the evidence
/// [`check_discharged`] assembles a proof from.
#[derive(Clone, Debug)]
pub struct Discharged {
    method: Method,
}

impl Discharged {
    fn new(method: Method) -> Discharged {
        Discharged { method }
    }
}

/// A proof for every value of the open ranges by `method` from the obligations this module
/// checked: at least one, and one of `method`'s own kind unless `method` is [`Method::Pieces`]
/// (rational identities on the pieces of a domain).
pub fn check_discharged(method: Method, evidence: &[Discharged]) -> Option<Proof> {
    let backed = method == Method::Pieces || evidence.iter().any(|d| d.method == method);
    (method.is_for_every() && !evidence.is_empty() && backed).then(|| Proof::new(method, &[]))
}

/// A proof by induction on an integer variable from its two parts, each proved for every value
/// by obligations this module checked: the base (the claim at the variable's first value, the
/// recursive objects there read from their definitions, unfolded from the recursion's base
/// whatever that first value is) and the step (the claim at `v + 1` from the claim at `v`, used
/// only as stated).
pub fn check_induction(base: &[Discharged], step: &[Discharged]) -> Option<Proof> {
    (!base.is_empty() && !step.is_empty()).then(|| Proof::new(Method::Induction, &[]))
}

/// The proof of several parts together: every part proved (`None` without parts).
pub fn check_all(parts: Vec<Proof>) -> Option<Proof> {
    let mut parts = parts.into_iter();
    let first = parts.next()?;
    Some(parts.fold(first, |acc, p| {
        let mut out = Proof::new(acc.method.join(p.method), &acc.rests_on);
        out.data = acc.data.join(p.data);
        for t in p.rests_on {
            out = out.resting_on(t);
        }
        out.scope = match (acc.scope, p.scope) {
            (Scope::Every, Scope::Every) => Scope::Every,
            (Scope::InRange(r), _) | (_, Scope::InRange(r)) => Scope::InRange(r),
        };
        out
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn for_every_proofs_need_obligations_the_kernel_checked() {
        let (pieces, wz) = (Discharged::new(Method::Pieces), Discharged::new(Method::Wz));
        assert!(check_discharged(Method::Pieces, &[]).is_none());
        assert!(check_discharged(Method::Wz, std::slice::from_ref(&pieces)).is_none());
        assert!(check_discharged(Method::Computation, std::slice::from_ref(&pieces)).is_none());
        let p = check_discharged(Method::Wz, &[pieces.clone(), wz]).unwrap();
        assert_eq!((p.verdict(), p.method()), (Verdict::Proved, Method::Wz));
        assert_eq!(
            check_discharged(Method::Pieces, std::slice::from_ref(&pieces)).map(|p| p.method()),
            Some(Method::Pieces)
        );
        assert!(check_induction(&[], std::slice::from_ref(&pieces)).is_none());
        assert!(check_induction(std::slice::from_ref(&pieces), &[]).is_none());
        let i = check_induction(std::slice::from_ref(&pieces), std::slice::from_ref(&pieces)).unwrap();
        assert_eq!((i.verdict(), i.method()), (Verdict::Proved, Method::Induction));
    }

    #[test]
    fn the_other_entries_refuse_what_does_not_hold() {
        assert!(check_computed(&[true, false], &[Trusted::CubicFit]).is_none());
        assert!(check_all(Vec::new()).is_none());
        let p = check_computed(&[true], &[Trusted::ClassifyConic, Trusted::ClassifyConic]).unwrap();
        assert_eq!(p.rests_on(), &[Trusted::ClassifyConic]);
        let r = p.in_range("n = 0..=3".into());
        assert_eq!(r.verdict(), Verdict::ProvedInRange);
        assert_eq!(r.range(), Some("n = 0..=3"));
    }
}
