//! Certificates as data: what a check verified, kept typed so that it can be written out and
//! re-checked later by the kernel alone, with no claim and no search (`docs/certificates.md`).
//!
//! The checks record it ([`sample::check_pair`] for each equality it proves or refutes); the
//! re-checks ([`recheck_sampled`], [`recheck_refutation`]) take the goal's expressions (parsed
//! outside, from the file's text) and the recorded data, and run the same kernel code on them:
//! the degree bounds derived again, the points checked distinct and numerous enough, both sides
//! evaluated again at every point and compared with the file's values.

use super::alg::Alg;
use super::eval::{Deg, Env, Evaluator, Value, VarEnv};
use super::expr::Expr;
use super::sample::{self, Pair, Points};
use super::Proof;
use crate::error::Result;
use num_rational::BigRational;
use num_traits::Zero;
use std::collections::BTreeMap;

/// Most grid points a re-checked file may list (all its equalities together).
pub const MAX_RECHECK_POINTS: usize = 10_000;

/// One real parameter of a sampled equality.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Param {
    /// Its name.
    pub name: String,
    /// The degree bound of the cleared difference of both sides in it.
    pub degree: u64,
    /// The bounds of each side, `num` or `num/den`.
    pub lhs_degree: String,
    /// See `lhs_degree`.
    pub rhs_degree: String,
    /// The values it was evaluated at.
    pub points: Vec<BigRational>,
}

/// One grid point where both sides were evaluated and found equal.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Row {
    /// The parameters' values, in the order of the params.
    pub at: Vec<BigRational>,
    /// The basis polygon: 0 the zero polygon, `k + 1` the unit polygon of control point `k`.
    pub basis: usize,
    /// The common value of both sides, entry by entry (printed exactly).
    pub value: Vec<String>,
}

/// One equality as the kernel checked it: `lhs = rhs` at the integer values `ints`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Equality {
    /// The integer symbols' values.
    pub ints: BTreeMap<String, i64>,
    /// The left side (a certificate prints it; the printer's text parses back to it).
    pub lhs: Expr,
    /// The right side.
    pub rhs: Expr,
    /// The real parameters (empty for an exact evaluation).
    pub params: Vec<Param>,
    /// Every grid point, the last parameter fastest.
    pub rows: Vec<Row>,
    /// How many basis polygons the sides were evaluated on (1: no symbolic control points).
    pub polygons: usize,
    /// The symbolic control points, in the order of the unit polygons.
    pub control_points: Vec<(String, Vec<i64>)>,
}

/// A counterexample: the equality, where it fails and both sides' values there.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refutation {
    /// The failing equality (no params, no rows).
    pub equality: Equality,
    /// The real parameters' values.
    pub at: Vec<(String, BigRational)>,
    /// The left side's value, entry by entry.
    pub lhs: Vec<String>,
    /// The right side's value.
    pub rhs: Vec<String>,
    /// The basis polygon of the equality's control points the sides were evaluated on (0: the
    /// zero polygon, or no control points).
    pub basis: usize,
    /// For an implication, its premise (written like the sides) and its value there (zero):
    /// the claim is the equality wherever the premise is zero.
    pub premise: Option<(String, Vec<String>)>,
}

/// What a verdict's data is.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub enum Data {
    /// No data a checker could re-derive the verdict from (not done for this method).
    #[default]
    None,
    /// Equalities proved by exact evaluation at enough points.
    Sampled(Vec<Equality>),
    /// A counterexample.
    Refuted(Box<Refutation>),
    /// Equalities proved by symbolic expansion, each as expanded.
    Expanded(Vec<super::expand::Expansion>),
    /// A for-every proof on the pieces of a domain, by the goal it was built from.
    Symbolic(Box<Symbolic>),
    /// A for-every inequality on the pieces of a domain: its goal and each live term's
    /// nonnegativity obligation.
    Nonneg(Box<super::nonneg::Nonneg>),
}

/// The goal of a for-every proof as its translation into hypergeometric terms read it
/// (written by the caller, printed so that it parses back): a re-check translates it again
/// and runs the same kernel checks on what it gets.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Symbolic {
    /// The real parameters.
    pub reals: Vec<String>,
    /// The integer ranges: variable, least value, largest value (`None`: open).
    pub for_all: Vec<(String, String, Option<String>)>,
    /// The symbolic control polygon: name, degree.
    pub polygon: Option<(String, String)>,
    /// The symbolic control net: name, degrees.
    pub net: Option<(String, [String; 2])>,
    /// The chain's members.
    pub members: Vec<String>,
    /// The WZ certificates `R` of the symbolic sums, as the claim gives them.
    pub certificates: Vec<String>,
    /// The lemmas the proof assumes: each claim's id and goal (its own `certificates`,
    /// `lemmas` and `induction` empty), checked against the lemma's own file by the caller.
    pub lemmas: Vec<(String, Symbolic)>,
    /// Proved by induction on this range symbol (base and step derived again from the goal).
    pub induction: Option<String>,
}

impl Data {
    /// The data of several parts checked together: kept only when every part was sampled.
    pub(super) fn join(self, other: Data) -> Data {
        match (self, other) {
            (Data::Sampled(mut a), Data::Sampled(b)) => {
                a.extend(b);
                Data::Sampled(a)
            }
            (Data::Expanded(mut a), Data::Expanded(b)) => {
                a.extend(b);
                Data::Expanded(a)
            }
            _ => Data::None,
        }
    }
}

/// The data of one equality proved by [`sample::check_pair`]; `written`: both sides without
/// the claim's objects, when the environment could write them so (their degree bounds, derived
/// again, are the ones recorded).
pub(super) fn equality(
    bounds: &sample::Bounds<'_>,
    points: &[Vec<BigRational>],
    rows: Vec<Row>,
    (polygons, control_points): (usize, Vec<(String, Vec<i64>)>),
    written: Option<(Expr, Expr)>,
) -> Equality {
    let names = bounds.params().to_vec();
    let degrees = Degrees::of(&names, &control_points);
    // Sides written out unchanged keep the bounds derived from them.
    let again = written
        .as_ref()
        .filter(|(l, r)| l != bounds.lhs() || r != bounds.rhs())
        .and_then(|(l, r)| sample::bounds(l, r, bounds.ints(), names.clone(), &degrees).ok());
    let used = again.as_ref().unwrap_or(bounds);
    let params = used
        .params()
        .iter()
        .zip(used.needs())
        .zip(points)
        .map(|((name, &degree), points)| {
            let (lhs_degree, rhs_degree) = used.describe(name);
            Param {
                name: name.clone(),
                degree,
                lhs_degree,
                rhs_degree,
                points: points.clone(),
            }
        })
        .collect();
    let rewritten = again.is_some();
    drop(again);
    let (lhs, rhs) = match written {
        Some((l, r)) if rewritten => (l, r),
        _ => (bounds.lhs().clone(), bounds.rhs().clone()),
    };
    Equality {
        ints: bounds.ints().clone(),
        lhs,
        rhs,
        params,
        rows,
        polygons,
        control_points,
    }
}

/// A recorded row: the point, the basis polygon, the left side's and the right side's values
/// (in the algebra the goal is evaluated in: the rationals, or `Q(√d)` for a goal with `sqrt(d)`).
pub type RowValues<A> = (Vec<BigRational>, usize, Vec<A>, Vec<A>);

/// One recorded equality to re-check, its sides parsed from the file's text.
pub struct Claimed<'a, A> {
    /// The left side.
    pub lhs: &'a Expr,
    /// The right side.
    pub rhs: &'a Expr,
    /// The integer symbols' values.
    pub ints: BTreeMap<String, i64>,
    /// The parameters with their recorded bounds and points.
    pub params: Vec<Param>,
    /// Every row: where, on which basis polygon, the left side's and the right side's values.
    pub rows: Vec<RowValues<A>>,
    /// The goal's symbols at each point and basis polygon, read from the file (elaboration,
    /// like the claim's objects in `prove`; the kernel checks the basis complete).
    pub env: Box<dyn Points<A> + 'a>,
}

/// The degree bounds of parameters and of control points (degree 1 in the polygon).
pub struct Degrees<'a>(pub VarEnv<Deg>, pub &'a [(String, Vec<i64>)]);

impl Degrees<'_> {
    fn of<'a>(names: &[String], points: &'a [(String, Vec<i64>)]) -> Degrees<'a> {
        Degrees(
            VarEnv(names.iter().map(|v| (v.clone(), Value::S(Deg::var(v)))).collect()),
            points,
        )
    }
}

impl Env<Deg> for Degrees<'_> {
    fn var(&self, name: &str) -> Option<Value<Deg>> {
        self.0.var(name)
    }
    fn call(&self, _: &str, _: &[Expr], _: &mut Evaluator<'_, Deg>) -> Result<Option<Value<Deg>>> {
        Ok(None)
    }
    fn index(&self, name: &str, _: &[i64]) -> Result<Option<Value<Deg>>> {
        Ok(self
            .1
            .iter()
            .any(|(n, _)| n == name)
            .then(|| Value::S(Deg::control_point())))
    }
}

fn list<T: std::fmt::Display>(v: &[T]) -> String {
    v.iter().map(ToString::to_string).collect::<Vec<_>>().join(", ")
}

/// The obligations of the `i`-th recorded equality that evaluate nothing: the degree bounds
/// derived again are the recorded ones, and there is one row per grid point. Its bounds and
/// grid's points.
fn recorded<'c, A: Alg>(
    i: usize,
    c: &Claimed<'c, A>,
) -> std::result::Result<(sample::Bounds<'c>, Vec<Vec<BigRational>>), String> {
    let at = |m: String| format!("equality {i}: {m}");
    let names: Vec<String> = c.params.iter().map(|p| p.name.clone()).collect();
    let control = c.env.control_points();
    let degrees = Degrees::of(&names, &control);
    let bounds = sample::bounds(c.lhs, c.rhs, &c.ints, names, &degrees).map_err(|e| at(e.to_string()))?;
    for (p, &need) in c.params.iter().zip(bounds.needs()) {
        let (l, r) = bounds.describe(&p.name);
        if (p.degree, &p.lhs_degree, &p.rhs_degree) != (need, &l, &r) {
            return Err(at(format!(
                "degree bound of {}: the file says {} (sides {}, {}), the kernel derives {need} (sides {l}, {r})",
                p.name, p.degree, p.lhs_degree, p.rhs_degree
            )));
        }
    }
    let points: Vec<Vec<BigRational>> = c.params.iter().map(|p| p.points.clone()).collect();
    let grid = points.iter().try_fold(1usize, |acc, p| acc.checked_mul(p.len()));
    let (rows, polygons) = (c.rows.len(), c.env.polygons());
    if grid.and_then(|g| g.checked_mul(polygons)) != Some(rows) {
        return Err(at(format!(
            "{rows} value rows for a grid of {} points on {polygons} basis polygons",
            grid.map_or("too many".into(), |g| g.to_string()),
        )));
    }
    Ok((bounds, points))
}

/// Re-checks recorded equalities: for each, the kernel derives the degree bounds again (they
/// must be the recorded ones), checks the points distinct and more than the bound, evaluates
/// both sides at every grid point (the recorded rows, in grid order, must list exactly those
/// points and both sides' values). The error names the first failing obligation. `A` is the
/// rationals, or `Q(√d)` ([`crate::quadratic::QuadraticIrrational`], the prover's) for a goal
/// with `sqrt(d)`: values of another field, or mixing two, compare unequal.
pub fn recheck_sampled<A: Alg + PartialEq>(claimed: &mut [Claimed<'_, A>]) -> std::result::Result<Proof, String> {
    let total: usize = claimed.iter().map(|c| c.rows.len()).sum();
    if total > MAX_RECHECK_POINTS {
        return Err(format!(
            "{total} grid points: more than the limit of {MAX_RECHECK_POINTS} per file"
        ));
    }
    let mut cases = Vec::with_capacity(claimed.len());
    for (i, c) in claimed.iter_mut().enumerate() {
        let at = |m: String| format!("equality {i}: {m}");
        let (bounds, points) = recorded(i, c)?;
        let mut k = 0;
        let mut mismatch: Option<String> = None;
        let rows = &c.rows;
        let mut observe = |values: &[BigRational], b: usize, l: &Value<A>| {
            if mismatch.is_some() {
                return;
            }
            let (row_at, row_b, row_l, row_r) = &rows[k];
            k += 1;
            let got: Vec<A> = l.entries().into_iter().cloned().collect();
            if row_at.as_slice() != values || *row_b != b {
                mismatch = Some(format!(
                    "row {}: at ({}) on polygon {row_b}, the grid's point is ({}) on polygon {b}",
                    k - 1,
                    list(row_at),
                    list(values)
                ));
            } else if *row_l != got {
                mismatch = Some(format!(
                    "at ({}): the left side is ({}), the file says ({})",
                    list(values),
                    list(&got),
                    list(row_l)
                ));
            } else if *row_r != got {
                mismatch = Some(format!(
                    "at ({}): the right side is ({}), the file says ({})",
                    list(values),
                    list(&got),
                    list(row_r)
                ));
            }
        };
        let outcome = sample::check_pair(&bounds, &mut *c.env, &points, &mut observe).map_err(|e| at(e.to_string()))?;
        if let Some(m) = mismatch {
            return Err(at(m));
        }
        match outcome {
            Pair::Equal(case) => cases.push(case),
            Pair::Differs { at: p, lhs, rhs, .. } => {
                return Err(at(format!("at ({}): the sides differ, {lhs} and {rhs}", list(&p))))
            }
            Pair::Vanishes { index, error } => {
                return Err(at(format!("a denominator vanishes at grid point {index:?} ({error})")))
            }
        }
    }
    super::check_sampled(cases)
}

/// A counterexample to re-check, its expressions parsed from the file's text.
pub struct Counterexample<'a> {
    /// The left side.
    pub lhs: &'a Expr,
    /// The right side.
    pub rhs: &'a Expr,
    /// For an implication: its premise and the recorded value (it must be zero).
    pub premise: Option<(&'a Expr, Vec<BigRational>)>,
    /// The integer symbols' values.
    pub ints: BTreeMap<String, i64>,
    /// The real symbols' values.
    pub at: Vec<(String, BigRational)>,
    /// The basis polygon of the control points (0 without them).
    pub basis: usize,
    /// The goal's symbols at the point and basis polygon, read from the file.
    pub env: Box<dyn Points<BigRational> + 'a>,
}

/// Re-checks a counterexample: both sides of `lhs = rhs` evaluated at `ints`, `at` and the
/// basis polygon must be the recorded values, and differ; an implication's premise evaluated
/// there must be the recorded value, and zero (so the premise holds and the equality fails).
pub fn recheck_refutation(
    c: &mut Counterexample<'_>,
    recorded: (&[BigRational], &[BigRational]),
) -> std::result::Result<(), String> {
    let polygons = c.env.polygons();
    if c.basis >= polygons {
        return Err(format!("basis polygon {}: there are {polygons}", c.basis));
    }
    let (names, values): (Vec<String>, Vec<BigRational>) = c.at.iter().cloned().unzip();
    let env = c.env.at(c.basis, &names, &values).map_err(|e| e.to_string())?;
    let ints = &c.ints;
    let side = |e: &Expr, which: &str, want: &[BigRational]| -> std::result::Result<Value<BigRational>, String> {
        let v = super::eval::Evaluator::new(env, ints.clone())
            .eval(e)
            .map_err(|err| format!("the {which}: {err}"))?;
        let got: Vec<BigRational> = v.entries().into_iter().cloned().collect();
        if got != want {
            return Err(format!(
                "the {which} is ({}), the file says ({})",
                list(&got),
                list(want)
            ));
        }
        Ok(v)
    };
    if let Some((p, want)) = &c.premise {
        let v = side(p, "premise", want)?;
        if v.entries().iter().any(|x| !x.is_zero()) {
            return Err(format!("the premise is ({}), not zero: it does not hold there", v));
        }
    }
    let l = side(c.lhs, "left side", recorded.0)?;
    let r = side(c.rhs, "right side", recorded.1)?;
    match l.equals(&r) {
        Some(false) => Ok(()),
        Some(true) => Err(format!("both sides are ({}): no counterexample", l)),
        None => Err("the sides cannot be compared".into()),
    }
}

/// Re-checks bounded evidence of a limit (Theorem 1.2's, `verified`): the distances `listed`
/// in a file must be the ones `computed` again, never increase with `r`, and each be at most
/// its `bound`. Evidence only: nothing here makes a [`Proof`].
pub fn recheck_bounded(
    listed: &[BigRational],
    computed: &[BigRational],
    bounds: &[BigRational],
) -> std::result::Result<(), String> {
    if listed.len() != computed.len() || computed.len() != bounds.len() {
        return Err(format!(
            "{} distances listed for r = 0..={}",
            listed.len(),
            computed.len().saturating_sub(1)
        ));
    }
    for (r, ((l, c), b)) in listed.iter().zip(computed).zip(bounds).enumerate() {
        if l != c {
            return Err(format!("at r = {r} the distance is {c}, the file says {l}"));
        }
        if c > b {
            return Err(format!("at r = {r} the distance {c} exceeds the bound {b}"));
        }
    }
    if let Some(r) = computed.windows(2).position(|w| w[1] > w[0]) {
        return Err(format!("the distance grows from r = {r} to r = {}", r + 1));
    }
    Ok(())
}

/// The printed entries of a value.
pub(super) fn entries<A: Alg>(v: &Value<A>) -> Vec<String> {
    v.entries().into_iter().map(ToString::to_string).collect()
}
