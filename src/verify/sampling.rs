//! The identity prover: degree bounds derived from the expressions, exact checks at enough
//! points, on a basis of control polygons; the work of a claim estimated before it runs.

use super::context::Ctx;
use super::inline::inline;
use super::kernel::certificate::Refutation;
use super::kernel::check_sampled;
use super::kernel::checked::{Evaluation, Method, Step};
use super::kernel::eval::{Deg, Env, Value};
use super::kernel::expr::{self, check_index, Expr};
use super::kernel::sample::{self, Bounds, Pair, Points};
use super::objects::{DegEnv, Exact, NumEnv};
use super::outcome::Checked;
use super::parse::parse;
use crate::error::{Error, Result};
use num_rational::BigRational;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;

/// Largest number of exact evaluations one identity may take (per side and instance).
pub const MAX_EVALUATIONS: usize = 2_000_000;

// ---------------------------------------------------------------------------------------
// Choosing parameters

/// Distinct rationals: first `k/d` for `k = 0..=d`, then `p/q` in lowest terms for growing `q`.
pub struct Candidates {
    seen: BTreeSet<BigRational>,
    queue: Vec<BigRational>,
    q: i64,
}

impl Candidates {
    /// Candidates for a polynomial of degree `d`.
    pub fn new(d: usize) -> Self {
        let d = d.max(1) as i64;
        let queue: Vec<BigRational> = (0..=d).rev().map(|k| BigRational::new(k.into(), d.into())).collect();
        Candidates {
            seen: BTreeSet::new(),
            queue,
            q: 1,
        }
    }
}

impl Iterator for Candidates {
    type Item = BigRational;
    fn next(&mut self) -> Option<BigRational> {
        loop {
            if let Some(x) = self.queue.pop() {
                if self.seen.insert(x.clone()) {
                    return Some(x);
                }
                continue;
            }
            self.q += 1;
            let q = self.q;
            // Also step outside [0, 1]: a denominator may vanish on a whole interval's rationals
            // only if it is zero, but values beyond 1 make the search shorter for e.g. 1/(t - p/q).
            self.queue = (0..=2 * q)
                .rev()
                .map(|p| BigRational::new(p.into(), q.into()))
                .collect();
        }
    }
}

// ---------------------------------------------------------------------------------------
// The identity prover

/// One polygon of the basis on which an affine identity is checked.
#[derive(Clone, Debug)]
enum Basis {
    None,
    Zero,
    Unit(usize),
    NetUnit(usize, usize),
}

impl Basis {
    fn describe(&self, ctx: &Ctx<'_>) -> String {
        let p = ctx.decls.polygon.as_ref().map(|p| p.name.as_str());
        let n = ctx.decls.net.as_ref().map(|p| p.name.as_str());
        match self {
            Basis::None => String::new(),
            Basis::Zero => {
                let names: Vec<&str> = p.into_iter().chain(n).collect();
                format!("{} = 0 (all control points zero)", names.join(" = "))
            }
            Basis::Unit(k) => format!("{0}[{k}] = 1, other {0}[j] = 0", p.unwrap_or("b")),
            Basis::NetUnit(i, j) => format!("{0}[{i}, {j}] = 1, other {0}[k, l] = 0", n.unwrap_or("b")),
        }
    }
}

/// What one checked equality established.
#[derive(Clone, Debug, Default)]
pub struct PairProof {
    /// Per parameter: (name, degree needed, lhs bound, rhs bound, rational?).
    pub degrees: Vec<(String, u64, Deg, Deg)>,
    /// The parameter values checked, per parameter.
    pub points: Vec<Vec<BigRational>>,
    /// How many basis polygons.
    pub polygons: usize,
    /// Exact evaluations done (both sides).
    pub evaluations: usize,
    /// Candidate parameters skipped because a denominator vanished.
    pub skipped: usize,
    /// Detailed lines (for explain).
    pub lines: Vec<Step>,
    /// The kernel's evidence that the pair was checked on its grid.
    pub case: Option<sample::Case>,
}

/// The outcome of one equality check.
pub enum PairResult {
    /// Proved, with what was checked.
    Proved(PairProof),
    /// Fails: the counterexample, and as data when the kernel recorded it.
    Fails(String, Option<Box<Refutation>>),
}

/// The claim's objects for one case, set to one basis polygon and parameter point.
struct Grid<T> {
    num: NumEnv<T>,
    basis: Vec<Basis>,
    /// Whether the sides are written out for a certificate ([`Ctx::certify`]).
    certify: bool,
}

impl<T: Exact> Points<T> for Grid<T> {
    fn polygons(&self) -> usize {
        self.basis.len()
    }
    fn at(&mut self, basis: usize, params: &[String], values: &[BigRational]) -> Result<&dyn Env<T>> {
        set_basis(&mut self.num, &self.basis[basis]);
        for (v, x) in params.iter().zip(values) {
            self.num.vars.insert(v.clone(), Value::S(T::from_rational(x)?));
        }
        Ok(&self.num)
    }
    fn control_points(&self) -> Vec<(String, Vec<i64>)> {
        let mut out = Vec::new();
        if let Some((name, c)) = &self.num.polygon {
            out.extend((0..c.len() as i64).map(|j| (name.clone(), vec![j])));
        }
        if let Some((name, n)) = &self.num.net {
            for (i, row) in n.iter().enumerate() {
                out.extend((0..row.len() as i64).map(|j| (name.clone(), vec![i as i64, j])));
            }
        }
        out
    }
    fn written_out(&self, side: &Expr, ints: &BTreeMap<String, i64>) -> Option<Expr> {
        // Only a certificate file reads them; writing the library's operations out costs
        // more than evaluating many claims.
        if !self.certify {
            return None;
        }
        inline(side, &self.num, ints)
    }
}

fn prove_prepared<T: Exact>(
    ctx: &Ctx<'_>,
    ints: &BTreeMap<String, i64>,
    detail: bool,
    prepared: Prepared<'_, T>,
) -> Result<PairResult> {
    let Prepared {
        bounds,
        mut grid,
        needs,
        mut proof,
        ..
    } = prepared;
    let params = bounds.params().to_vec();

    // Propose the parameter sets; the kernel checks both sides on the grid. A point where
    // some denominator vanishes is replaced by the next candidate of its (last) parameter.
    let mut gens: Vec<Candidates> = needs.iter().map(|&d| Candidates::new(d)).collect();
    let mut sets: Vec<Vec<BigRational>> = gens
        .iter_mut()
        .zip(&needs)
        .map(|(g, &d)| g.take(d + 1).collect())
        .collect();
    let limit_skips = 64 + needs.iter().sum::<usize>() * 4;
    let basis = grid.basis.clone();
    loop {
        let mut lines = Vec::new();
        // Described only when it is printed: formatting every point costs more than
        // evaluating a small claim.
        let mut observe = |values: &[BigRational], b: usize, l: &Value<T>| {
            if detail {
                lines.push(Step::evaluation(Evaluation {
                    at: describe_point(&params, values, ints, &basis[b], ctx),
                    values: ints
                        .iter()
                        .map(|(k, v)| (k.clone(), BigRational::from_integer((*v).into())))
                        .chain(params.iter().cloned().zip(values.iter().cloned()))
                        .collect(),
                    unit: match basis[b] {
                        Basis::Unit(k) => Some(k),
                        _ => None,
                    },
                    value: l.to_string(),
                }));
            }
        };
        match sample::check_pair(&bounds, &mut grid, &sets, &mut observe)? {
            Pair::Equal(case) => {
                proof.evaluations = 2 * basis.len() * sets.iter().map(Vec::len).product::<usize>();
                proof.points = sets;
                proof.lines.extend(lines);
                proof.case = Some(case);
                return Ok(PairResult::Proved(proof));
            }
            Pair::Differs {
                at,
                basis: b,
                lhs: l,
                rhs: r,
                equal,
                refutation,
            } => {
                let at = describe_point(&params, &at, ints, &basis[b], ctx);
                if equal == Some(false) {
                    return Ok(PairResult::Fails(
                        format!("at {at}: left side = {l}, right side = {r}"),
                        refutation,
                    ));
                }
                return Err(Error::Domain(format!(
                    "at {at} the sides are {l} and {r}: the claim mixes square roots of different fields \
                     (exact arithmetic here is in one Q(√d) per claim), so it cannot be decided"
                )));
            }
            Pair::Vanishes { index, error: e } => {
                // Replace the offending value of the last parameter and start again.
                proof.skipped += 1;
                if params.is_empty() || proof.skipped > limit_skips {
                    return Err(Error::Domain(format!(
                        "no parameter values found where every denominator is non-zero ({e}); \
                         is a denominator the zero polynomial?"
                    )));
                }
                let k = params.len() - 1;
                let fresh = gens[k].next().expect("candidates are infinite");
                sets[k][index[k]] = fresh;
            }
        }
    }
}

/// A pair of sides ready to be checked at one integer instance.
struct Prepared<'a, T> {
    bounds: Bounds<'a>,
    grid: Grid<T>,
    needs: Vec<usize>,
    proof: PairProof,
    /// The estimated work, in units of [`MAX_WORK`].
    work: u128,
}

/// Largest estimated work of one claim, in units of one exact evaluation of an expression of
/// degree `d` counted as `(1 + d)²` (d: the identity's degree plus the degree of the symbolic
/// polygon or net), times `w²` where `w = max(1, (1 + d)·L/64)` words for literals of `L` bits,
/// summed over every case, pair of sides, basis polygon and sample point.
pub const MAX_WORK: u128 = 50_000_000;

/// The largest size in bits (numerator and denominator) of a number written in `e`.
fn literal_bits(e: &Expr) -> u64 {
    let mut bits = 0;
    e.visit(&mut |x| {
        if let Expr::Num(r) = x {
            bits = bits.max(r.numer().bits() + r.denom().bits());
        }
    });
    bits
}

/// The work of checking `lhs = rhs` at one instance, estimated before computing.
pub fn estimate_work<T: Exact>(ctx: &Ctx<'_>, lhs: &Expr, rhs: &Expr, ints: &BTreeMap<String, i64>) -> Result<u128> {
    Ok(prepare::<T>(ctx, lhs, rhs, ints, false)?.work)
}

fn prepare<'a, T: Exact>(
    ctx: &Ctx<'_>,
    lhs: &'a Expr,
    rhs: &'a Expr,
    ints: &BTreeMap<String, i64>,
    detail: bool,
) -> Result<Prepared<'a, T>> {
    let params = ctx.params(&[lhs, rhs]);
    let mut num: NumEnv<T> = NumEnv::new(&ctx.decls)?;
    // Shape the symbolic polygon/net for this instance. Both sides are affine in all their
    // control points together, so one basis covers every declared polygon and net at once:
    // all zero, then each single control point of each object set to 1.
    let mut basis = vec![Basis::Zero];
    if let Some(p) = &ctx.decls.polygon {
        let n = expr::eval_int(&parse(&p.degree, &[])?, ints)?;
        check_index(n)?;
        if n < 0 {
            return Err(Error::Domain(format!("polygon {} of negative degree {n}", p.name)));
        }
        num.polygon = Some((p.name.clone(), vec![T::zero(); n as usize + 1]));
        basis.extend((0..=n as usize).map(Basis::Unit));
    }
    if let Some(p) = &ctx.decls.net {
        let m = expr::eval_int(&parse(&p.degree[0], &[])?, ints)?;
        let n = expr::eval_int(&parse(&p.degree[1], &[])?, ints)?;
        check_index(m)?;
        check_index(n)?;
        if m < 0 || n < 0 {
            return Err(Error::Domain(format!("net {} of negative degree", p.name)));
        }
        num.net = Some((p.name.clone(), vec![vec![T::zero(); n as usize + 1]; m as usize + 1]));
        basis.extend((0..=m as usize).flat_map(|i| (0..=n as usize).map(move |j| Basis::NetUnit(i, j))));
    }

    // Degree bounds, derived by the kernel in the algebra of degree bounds.
    let degenv = DegEnv::new(&num, &params);
    let bounds = sample::bounds(lhs, rhs, ints, params, &degenv)?;
    if !bounds.uses_polygon() {
        basis = vec![Basis::None];
    }
    let mut proof = PairProof {
        polygons: basis.len(),
        ..Default::default()
    };
    let mut needs = Vec::new();
    let (first_l, first_r) = bounds.first();
    for (v, &need) in bounds.params().iter().zip(bounds.needs()) {
        if need > 100_000 {
            return Err(Error::TooLarge {
                what: "degree of the identity",
                value: need.to_string(),
                limit: "100000".into(),
            });
        }
        needs.push(need as usize);
        proof.degrees.push((v.clone(), need, first_l.clone(), first_r.clone()));
        if detail {
            let (l, r) = bounds.describe(v);
            proof.lines.push(Step::text(format!(
                "degree in {v}: left side {l}, right side {r} (num/den bounds from the expression) ⇒ the cleared difference has degree ≤ {need}, so {} points suffice",
                need + 1
            )));
        }
    }
    let object_degree = num.polygon.as_ref().map_or(0, |p| p.1.len() - 1)
        + num.net.as_ref().map_or(0, |n| n.1.len() + n.1[0].len() - 2);
    let total: usize = needs
        .iter()
        .map(|d| d + 1)
        .product::<usize>()
        .saturating_mul(basis.len());
    if total.saturating_mul(2) > MAX_EVALUATIONS {
        return Err(Error::TooLarge {
            what: "number of exact evaluations",
            value: total.to_string(),
            limit: MAX_EVALUATIONS.to_string(),
        });
    }
    let size = 1 + needs.iter().copied().max().unwrap_or(0) as u128 + object_degree as u128;
    // Numbers grow with the degree: a literal of L bits raised to degree d has d·L bits, and
    // one product of such numbers costs about (d·L/64)² word operations.
    // The sample points k/d (d: the largest degree needed) have about 2·log2(d + 1) bits, as
    // much a number size as the literals: a value of degree `size` at them has `size` times
    // as many bits.
    let largest_need = needs.iter().copied().max().unwrap_or(0) as u64;
    let point_bits = if needs.is_empty() {
        0
    } else {
        2 * u64::from(u64::BITS - (largest_need + 1).leading_zeros())
    };
    let bits = literal_bits(lhs).max(literal_bits(rhs)).max(point_bits);
    let words = (size * u128::from(bits) / 64).max(1);
    let work = (total as u128)
        .saturating_mul(2)
        .saturating_mul(size * size)
        .saturating_mul(words.saturating_mul(words));
    Ok(Prepared {
        bounds,
        grid: Grid {
            num,
            basis,
            certify: ctx.certify,
        },
        needs,
        proof,
        work,
    })
}

fn set_basis<T: Exact>(num: &mut NumEnv<T>, b: &Basis) {
    if let Some((_, c)) = &mut num.polygon {
        c.iter_mut().for_each(|x| *x = T::zero());
        if let Basis::Unit(k) = b {
            c[*k] = T::one();
        }
    }
    if let Some((_, n)) = &mut num.net {
        n.iter_mut().flatten().for_each(|x| *x = T::zero());
        if let Basis::NetUnit(i, j) = b {
            n[*i][*j] = T::one();
        }
    }
}

fn describe_point(
    params: &[String],
    values: &[BigRational],
    ints: &BTreeMap<String, i64>,
    b: &Basis,
    ctx: &Ctx<'_>,
) -> String {
    let mut parts: Vec<String> = ints.iter().map(|(k, v)| format!("{k} = {v}")).collect();
    parts.extend(params.iter().zip(values).map(|(p, v)| format!("{p} = {v}")));
    let bd = b.describe(ctx);
    if !bd.is_empty() {
        parts.push(bd);
    }
    if parts.is_empty() {
        "the constant case".into()
    } else {
        parts.join(", ")
    }
}

pub(crate) fn list(v: &[BigRational]) -> String {
    v.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", ")
}

/// A one-line summary of a pair proof.
pub fn pair_summary(p: &PairProof) -> String {
    let mut s = String::new();
    if p.degrees.is_empty() {
        s.push_str("no parameters: checked exactly");
    } else {
        let parts: Vec<String> = p
            .degrees
            .iter()
            .zip(&p.points)
            .map(|((v, need, _, _), pts)| {
                if pts.len() <= 8 {
                    format!(
                        "degree ≤ {need} in {v}, equal at {v} = {} ({} points)",
                        list(pts),
                        pts.len()
                    )
                } else {
                    format!("degree ≤ {need} in {v}, equal at {} values of {v}", pts.len())
                }
            })
            .collect();
        s.push_str(&parts.join("; "));
        if p.degrees.len() > 1 {
            let _ = write!(
                s,
                " (a {} grid)",
                p.points
                    .iter()
                    .map(|x| x.len().to_string())
                    .collect::<Vec<_>>()
                    .join("×")
            );
        }
    }
    if p.polygons > 1 {
        let _ = write!(
            s,
            ", on {} basis polygons (zero and unit; both sides affine in the control points)",
            p.polygons
        );
    }
    if p.skipped > 0 {
        let _ = write!(
            s,
            ", {} candidate values skipped where a denominator vanishes",
            p.skipped
        );
    }
    s
}

/// The estimated work of checking the chain `sides` for every instance of the claim's
/// ranges, added to `before` (the work of earlier parts of the same claim); an error naming
/// [`MAX_WORK`] as soon as the sum exceeds it, before anything is evaluated.
pub fn chain_work<T: Exact>(ctx: &Ctx<'_>, sides: &[Expr], before: u128) -> Result<u128> {
    let mut work = before;
    for inst in &ctx.instances()? {
        for pair in sides.windows(2) {
            work = work.saturating_add(estimate_work::<T>(ctx, &pair[0], &pair[1], inst)?);
            if work > MAX_WORK {
                return Err(too_much_work(work));
            }
        }
    }
    Ok(work)
}

fn too_much_work(work: u128) -> Error {
    Error::TooLarge {
        what: "estimated work of the claim",
        value: format!("more than {work} units"),
        limit: format!("MAX_WORK = {MAX_WORK} units: exact evaluations × (1 + degree)² × (words of the numbers)²"),
    }
}

/// Checks a chain `e0 = e1 = …` for every instance of the integer ranges.
pub fn check_chain<T: Exact>(ctx: &Ctx<'_>, sides: &[Expr], detail: bool) -> Result<Checked> {
    if sides.len() < 2 {
        return Err(Error::Parse(format!("claim {}: an identity needs two sides", ctx.id)));
    }
    let instances = ctx.instances()?;
    // Bounded work: every pair of every case is prepared (degrees derived, basis chosen) and
    // the whole claim's work estimated before anything is evaluated.
    let mut plans = Vec::with_capacity(instances.len() * (sides.len() - 1));
    let mut work: u128 = 0;
    for inst in &instances {
        for pair in sides.windows(2) {
            let plan = prepare::<T>(ctx, &pair[0], &pair[1], inst, detail)?;
            work = work.saturating_add(plan.work);
            if work > MAX_WORK {
                return Err(too_much_work(work));
            }
            plans.push(plan);
        }
    }
    let mut plans = plans.into_iter();
    let mut steps = Vec::new();
    let mut max_need: BTreeMap<String, u64> = BTreeMap::new();
    let mut evaluations = 0;
    let mut last: Option<PairProof> = None;
    let mut first_params: Vec<BigRational> = Vec::new();
    // The kernel's evidence for each case and pair.
    let mut sampled_cases: Vec<sample::Case> = Vec::new();
    let mut rational = false;
    let mut polygons = (usize::MAX, 0usize);
    // The explanation argues from the derived degrees when any pair has parameters.
    let (mut sampled, mut basis) = (false, false);
    let method = |sampled: bool, basis: bool, degree: u64| {
        if sampled {
            Method::Sampling { basis, degree }
        } else {
            Method::Evaluation
        }
    };
    for inst in &instances {
        for (k, pair) in sides.windows(2).enumerate() {
            let plan = plans.next().expect("one plan per case and pair");
            match prove_prepared::<T>(ctx, inst, detail, plan)? {
                PairResult::Fails(cx, refutation) => {
                    let which = if sides.len() > 2 {
                        format!("step {} ('{}' = '{}') ", k + 1, pair[0], pair[1])
                    } else {
                        String::new()
                    };
                    let degree = max_need.values().copied().max().unwrap_or(0);
                    let mut c = Checked::fails(format!("{which}{cx}"))
                        .found_by(method(sampled, basis, degree))
                        .refuted(refutation);
                    c.steps = steps;
                    c.steps.push(Step::text(format!("FAILS {which}{cx}")));
                    return Ok(c);
                }
                PairResult::Proved(mut p) => {
                    for (v, need, l, r) in &p.degrees {
                        let e = max_need.entry(v.clone()).or_insert(0);
                        *e = (*e).max(*need);
                        rational |= !l.is_polynomial() || !r.is_polynomial();
                    }
                    polygons = (polygons.0.min(p.polygons), polygons.1.max(p.polygons));
                    sampled |= !p.degrees.is_empty();
                    basis |= p.polygons > 1;
                    evaluations += p.evaluations;
                    if detail {
                        steps.push(Step::instance(
                            inst.iter().map(|(k, v)| (k.clone(), *v)).collect(),
                            format!("'{}' = '{}': {}", pair[0], pair[1], pair_summary(&p)),
                        ));
                        steps.extend(p.lines.iter().cloned().map(|l| l.nested(2)));
                    }
                    if first_params.is_empty() {
                        first_params = p.points.first().cloned().unwrap_or_default();
                    }
                    // moved, not copied: a case holds both sides written out
                    sampled_cases.extend(p.case.take());
                    last = Some(p);
                }
            }
        }
    }
    let what = if sides.len() > 2 {
        format!("all {} equalities of the chain", sides.len() - 1)
    } else {
        "identity".into()
    };
    let cert = if instances.len() == 1 {
        let p = last.expect("one instance checked");
        let rat = if rational {
            " (rational functions: the cleared numerators P1·Q2 − P2·Q1 are compared, at points where no denominator vanishes)"
        } else {
            ""
        };
        format!(
            "{what}: {}{rat}; {evaluations} exact evaluations: proof",
            pair_summary(&p)
        )
    } else {
        let degs: Vec<String> = max_need.iter().map(|(v, d)| format!("{v} ≤ {d}")).collect();
        let poly = if polygons.1 > 1 {
            format!(
                "; each case on its {}–{} basis polygons (zero and unit control polygons; both sides affine in them)",
                polygons.0, polygons.1
            )
        } else {
            String::new()
        };
        let degs = if degs.is_empty() {
            "no continuous parameters".to_string()
        } else {
            format!(
                "degrees (from the expressions) up to {}, each case at d+1 points per parameter",
                degs.join(", ")
            )
        };
        format!(
            "{what} for every {} ({} cases): {degs}{poly}; {evaluations} exact evaluations: proof",
            ctx.range_text(),
            instances.len()
        )
    };
    let proof =
        check_sampled(sampled_cases).map_err(|e| Error::Domain(format!("the kernel refuses the evaluations: {e}")))?;
    let mut c = Checked::proved(proof, cert);
    c.steps = steps;
    c.params = first_params;
    Ok(c)
}

#[cfg(test)]
mod tests {
    use super::super::claims::test_claim as claim;
    use super::*;

    #[test]
    fn the_work_estimate_grows_with_degree_and_basis() {
        let c = claim("polygon = { name = \"b\", degree = \"3\" }");
        let ctx = Ctx::new(&c.id, std::borrow::Cow::Borrowed(&c.decls), Vec::new()).unwrap();
        let (l, r) = (ctx.expr("b(t)").unwrap(), ctx.expr("bsum(b, t)").unwrap());
        let ints = BTreeMap::new();
        let w = estimate_work::<BigRational>(&ctx, &l, &r, &ints).unwrap();
        // 4 points × 5 basis polygons × 2 sides × (1 + 3 + 3)²
        assert_eq!(w, 4 * 5 * 2 * 49);
        let big = ctx.expr("(1 + t)^4096").unwrap();
        let w = estimate_work::<BigRational>(&ctx, &big, &big, &ints).unwrap();
        assert!(w > MAX_WORK, "{w}");
    }
}
