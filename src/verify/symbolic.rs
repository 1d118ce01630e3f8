//! Claims for every value of an integer symbol: `for = ["n = 0.."]` (an open range) keeps `n`
//! symbolic, and the claim is proved for every integer point of its ranges, or it is an error.
//!
//! Both sides are translated into finite sums of hypergeometric terms ([`super::kernel::hyper`]):
//! `B(i, n, g)` is `n!/(i!(n−i)!) g^i (1−g)^(n−i)` with its support `0 ≤ i ≤ n`, `C(a, b)` likewise,
//! powers with affine exponents of polynomials in the continuous parameters, factorials, and the
//! derivatives `diff` produces. A symbolic control polygon `b` (the claim must be affine in it)
//! is checked on the zero polygon and on the unit polygon `b[ĵ] = 1` for a *symbolic* index
//! `ĵ` (`b[e]` becomes the Kronecker delta `[e = ĵ]`), so a sum `Σ_i b[i] …` collapses to its
//! one surviving term.
//!
//! A sum `Σ_{k=a}^{b(n)} F(n, k)` with symbolic bounds is evaluated by a WZ certificate `R` (from
//! the claim's `certificate = ["R"]`, one per such sum, innermost first): with `G = R·F` (the
//! factors of `R` that are affine in the integers cancel against the factorials of `F`, so `G`
//! is itself a hypergeometric term — any `G` would do, the checks below are about `G` itself) it
//! checks, each as a finite identity by [`super::kernel::pieces::prove_zero`]:
//!
//! 1. `F(n+1, k) − F(n, k) = G(n, k+1) − G(n, k)` for every `a ≤ k ≤ b(n)`;
//! 2. `G(n, b(n)+1) − G(n, a) + F(n+1, b(n)+1) = rhs(n+1) − rhs(n)` (the telescoped ends, with
//!    `b(n+1) = b(n) + 1`, `a` independent of `n`, and `b(n) ≥ a − 1` shown on the domain);
//! 3. the base case `Σ_{k=a}^{b(n₀)} F(n₀, k) = rhs(n₀)` at the least `n`, a finite sum.
//!
//! Together: `S(n+1) − S(n) = rhs(n+1) − rhs(n)` for `n ≥ n₀` and `S(n₀) = rhs(n₀)`, so
//! `S(n) = rhs(n)` for every `n ≥ n₀`. When the other side is one term depending on `n`, `F` is
//! first divided by it (the certificate is then for `Σ F/rhs = 1`); a sum inside another is
//! evaluated to its value at `n₀`, step 2 showing it does not depend on `n`.
//!
//! Independently of the proof, the claim is also checked by evaluation for the first few values
//! of each open range (the ordinary engine): a counterexample there is a `fails` verdict with
//! exact values; a symbolic check that does not go through is an error, never a verdict.

use super::claims::{Decls, Identity, IntRange};
use super::context::Ctx;
use super::identity::check_identity;
use super::kernel::bernstein::check_nonneg_pieces;
use super::kernel::checked::Verdict;
use super::kernel::checked::{Method, Step};
use super::kernel::expr::Expr;
use super::kernel::hyper::{lin_mul, lin_neg, Aff, Lin};
use super::kernel::nonneg::{check_record, Nonneg, NonnegGoal};
use super::kernel::pieces::Domain;
use super::kernel::{check_discharged, check_induction, Discharged, Proof};
use super::lemma::{self, Lemma, Obligation, Rewritten};
use super::outcome::Checked;

mod collapse;
mod induction;
pub(crate) mod written;
use super::recurrence::{self, coefficient_times_sum, has_sum};
use super::translate::{prepare, Translator, UNIT, UNIT2};
use crate::error::{Error, Result};
use num_rational::BigRational;
use std::time::{Duration, Instant};

/// Why a symbolic proof suffices, as `--explain` prints it.
pub const ARGUMENT: &[&str] = &[
    "The integers stay symbolic. Each side is a finite sum of hypergeometric terms (factorials of affine",
    "forms, powers with affine exponents); the domain is split until every term is zero or given by its",
    "formula throughout a piece, and there the quotient of similar terms is a rational function, so each",
    "class of similar terms cancelling is an exact identity of rational functions in all the symbols.",
    "A sum with a symbolic bound is evaluated by its WZ certificate R (G = R·F): the WZ equation, the",
    "telescoped ends and the base case are such identities, and induction on n gives the sum for every n.",
];

/// Why an induction suffices, as `--explain` prints it (before [`ARGUMENT`], which proves its
/// base and its step).
pub const INDUCTION_ARGUMENT: &[&str] = &[
    "Induction on the variable named: the base is the claim at its first value, the library objects there",
    "read by the base of their defining recursion; the step is the claim at r + 1 for every r in range,",
    "the objects at r + 1 unfolded by one step of their recursion and those at r replaced by the claim at r",
    "(the hypothesis, used only at r and only within the claim's ranges). Base and step are each proved",
    "for every value of the other symbols as below, so the claim holds for every r.",
];

/// The evaluation cross-check covers `n₀..=n₀ + CROSS_CHECK` of each open range (the proof is
/// the symbolic one; three values keep `prove` over the texts under a second of CPU).
pub const CROSS_CHECK: i64 = 2;

/// One range of a claim: `v = lo..=hi` or the open `v = lo..`.
/// The ranges as a certificate states them: `n = 0..=3`, `every n ≥ 0`, joined by commas.
fn scope(rs: &[IntRange]) -> String {
    rs.iter()
        .map(|r| match &r.to {
            Some(to) => format!("{} = {}..={to}", r.var, r.from),
            None => format!("every {} ≥ {}", r.var, r.from),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// How many values past the first of each open range are searched for a counterexample when
/// the symbolic proof does not go through: a false claim then gets `fails` with exact values,
/// not only the reason the proof failed.
pub const REFUTATION_SEARCH: i64 = 40;

/// The refutation search's budget per claim: value combinations of the open ranges, over all
/// its windows (one open range: 73, up to 41 values; two: 189, up to 12 values each).
pub const REFUTATION_COMBINATIONS: i64 = 200;

/// The refutation search starts no new window after this long.
pub const REFUTATION_TIME: Duration = Duration::from_secs(4);

/// `p ≥ 0` for every integer point of the open ranges and every `t` in `[a, b]`: on each
/// piece of the domain every live term is a product of nonnegative factors — a positive
/// constant or a polynomial in `t` with nonnegative Bernstein coefficients on `[a, b]`,
/// factorials of arguments ≥ 0, powers of positive constants, and powers with exponent ≥ 0 of
/// polynomials ≥ 0 on `[a, b]` (or any exponent of one > 0 there), checked by the kernel
/// ([`check_nonneg_pieces`]). The evaluation check is the caller's. The proof's data is the
/// goal `lhs ≥ rhs` with every piece's live terms and the reason each factor is ≥ 0
/// (`docs/certificates.md`), kept when every factor's Bernstein coefficients on the whole
/// interval show its reason.
pub fn nonneg_for_every(
    decls: &Decls,
    ctx: &Ctx<'_>,
    (lhs, rhs): (&Expr, &Expr),
    interval: (&BigRational, &BigRational),
    detail: bool,
) -> Result<Checked> {
    let rs = &decls.ranges;
    let p = &Expr::sub(lhs.clone(), rhs.clone());
    let sides = [p.clone()];
    let (certs, sym, conts) = prepare(&[], ctx, &sides)?;
    if conts.len() > 1 {
        return Err(Error::Domain(format!(
            "an inequality in one parameter, not {}",
            conts.join(", ")
        )));
    }
    let mut tr = Translator::new(&sym, &certs);
    let dom = tr.domain(decls, rs)?;
    let lin = tr.lin(p, &dom)?;
    let mut log = Vec::new();
    let (discharged, pieces, record) = check_nonneg_pieces(&sym, &lin, &dom, interval, &mut log)?;
    let mut proof = check_discharged(Method::Pieces, &[discharged])
        .ok_or_else(|| Error::Domain("the kernel refuses a for-every proof by Pieces".into()))?;
    if let ([real], true) = (&conts[..], check_record(&record)) {
        let goal = NonnegGoal {
            real: real.clone(),
            for_all: rs
                .iter()
                .map(|r| (r.var.clone(), r.from.clone(), r.to.clone()))
                .collect(),
            lhs: lhs.to_string(),
            rhs: rhs.to_string(),
            interval: (interval.0.clone(), interval.1.clone()),
        };
        proof = proof.with_nonneg(Nonneg { goal, pieces: record });
    }
    let open = scope(rs);
    let mut out = Checked::proved(
        proof,
        format!(
            "for {}: the left side minus the right is a sum of hypergeometric terms; on each piece of the domain ({pieces} in all) every live term is a product of factors ≥ 0 on the interval (positive constants and factorials, powers with exponent ≥ 0 of polynomials with Bernstein coefficients ≥ 0)",
            open
        ),
    );
    if detail {
        out.steps = log;
    }
    Ok(out)
}
/// Checks an identity claim with open ranges for every value (see the module documentation).
/// When no proof is found, the first values of the open ranges are searched for an exact
/// counterexample (in widening windows, within [`REFUTATION_COMBINATIONS`] and
/// [`REFUTATION_TIME`], up to the first window that cannot be evaluated); without one the claim
/// is an error with the reason and the extent of the search.
/// `ctx` is the claim's context, over its open ranges.
pub(crate) fn check(ctx: &Ctx<'_>, identity: &Identity, lemmas: &[Lemma], detail: bool) -> Result<Checked> {
    prove_for_every(ctx, identity, lemmas, detail).or_else(|reason| refute_in_search(ctx, identity, reason))
}

fn refute_in_search(ctx: &Ctx<'_>, identity: &Identity, reason: Error) -> Result<Checked> {
    let open: Vec<&str> = ctx
        .decls
        .ranges
        .iter()
        .filter(|r| r.is_open())
        .map(|r| r.var.as_str())
        .collect();
    let windows = refutation_windows(open.len() as u32);
    let start = Instant::now();
    let mut tried = 0;
    let mut stop = "the search budget";
    let members = identity.sides.members();
    // Widening windows: the values of a later window may be past what the ordinary engine
    // evaluates (a binomial beyond 64 bits), which must not hide a counterexample before them.
    for &extra in &windows {
        if start.elapsed() > REFUTATION_TIME {
            stop = "the search time";
            break;
        }
        match ctx
            .closed_after(extra)
            .and_then(|closed| check_identity(&closed, &members, false))
        {
            Ok(out) if out.verdict() == Verdict::Fails => return Ok(out),
            Ok(_) => tried = extra + 1,
            Err(_) if tried == 0 => return Err(reason),
            Err(_) => {
                stop = "the values the evaluator reaches";
                break;
            }
        }
    }
    Err(Error::Domain(format!(
        "{reason}; no counterexample in the first {tried} values of {} ({stop}: at most {REFUTATION_COMBINATIONS} combinations and {} s per claim)",
        open.join(", "),
        REFUTATION_TIME.as_secs()
    )))
}

/// The windows of the refutation search for `open` open ranges: each `extra` closes every
/// open range after `extra + 1` values, and all windows together try at most
/// [`REFUTATION_COMBINATIONS`] combinations (so two open ranges do not multiply the work of one).
fn refutation_windows(open: u32) -> Vec<i64> {
    let cost = |e: i64| -> i64 { [e / 4, e / 2, e].iter().map(|w| (w + 1).saturating_pow(open)).sum() };
    let widest = (0..=REFUTATION_SEARCH)
        .rev()
        .find(|&e| cost(e) <= REFUTATION_COMBINATIONS)
        .unwrap_or(0);
    let mut w = vec![widest / 4, widest / 2, widest];
    w.dedup();
    w
}

fn prove_for_every(ctx: &Ctx<'_>, identity: &Identity, lemmas: &[Lemma], detail: bool) -> Result<Checked> {
    let closed = ctx.closed_after(CROSS_CHECK)?;
    let evaluated = check_identity(&closed, &identity.sides.members(), false)?;
    if evaluated.verdict() == Verdict::Fails {
        return Ok(evaluated);
    }
    let (cert, log, proof) = prove_symbolic(ctx, identity, &closed, lemmas)?;
    let mut out = Checked::proved(
        proof,
        format!(
            "{cert}; also evaluated exactly for the first {} values of each open range ({})",
            CROSS_CHECK + 1,
            evaluated.verdict().as_str()
        ),
    );
    if detail {
        out.steps = log;
    }
    Ok(out)
}

/// Tries the symbolic proof alone (no evaluation cross-check, no counterexample search) of an
/// identity with open ranges: `Ok` with the certificate when it goes through, else the reason.
/// No verdict comes from here: the caller only reports the outcome.
pub(crate) fn attempt_for_every(ctx: &Ctx<'_>, identity: &Identity) -> Result<String> {
    let closed = ctx.closed_after(CROSS_CHECK)?;
    prove_symbolic(ctx, identity, &closed, &[]).map(|(cert, ..)| cert)
}

/// The symbolic proof of `identity` over the open ranges of `ctx`, parsed in `closed` (the
/// same declarations over finite ranges), the library objects read through `lemmas`: the
/// certificate, the proof's log, and the kernel's proof from the obligations it checked (no
/// evaluation cross-check here).
pub(crate) fn prove_symbolic(
    ctx: &Ctx<'_>,
    identity: &Identity,
    closed: &Ctx<'_>,
    lemmas: &[Lemma],
) -> Result<(String, Vec<Step>, Proof)> {
    let refused = |method: Method| Error::Domain(format!("the kernel refuses a for-every proof by {method:?}"));
    let sides = parsed_sides(closed, identity)?;
    let with_goal = |proof: Proof, goal: Option<_>| match goal {
        Some(g) => proof.with_goal(g),
        None => proof,
    };
    if let Some(var) = &identity.induction {
        let goal = written::written(ctx, &sides, identity, lemmas);
        let (cert, log, base, step) = induction::prove(ctx, identity, var, lemmas)?;
        let proof = check_induction(&base, &step).ok_or_else(|| refused(Method::Induction))?;
        return Ok((cert, log, with_goal(proof, goal)));
    }
    let rewritten = lemma::apply(&sides, &ctx.decls, lemmas)?;
    // Without lemmas the goal is the sides as the objects' definitions read them (a checker
    // needs no definition of an object), and only when reading them left no obligation; with
    // lemmas it is the claim's sides, which `check` reads through the lemmas' goals again.
    let goal = if !lemmas.is_empty() {
        written::written(ctx, &sides, identity, lemmas)
    } else if rewritten.obligations.is_empty() && rewritten.assumptions.is_empty() {
        written::written(ctx, &rewritten.sides, identity, lemmas)
    } else {
        None
    };
    let (cert, log, method, evidence) = prove_sides(&ctx.decls, closed, rewritten, &identity.certificates)?;
    let proof = check_discharged(method, &evidence).ok_or_else(|| refused(method))?;
    Ok((cert, log, with_goal(proof, goal)))
}

/// The members of an identity, parsed in `ctx`.
fn parsed_sides(ctx: &Ctx<'_>, identity: &Identity) -> Result<Vec<Expr>> {
    identity.sides.members().iter().map(|s| ctx.expr(s)).collect()
}

/// Each condition of `obligations` shown on `dom` (with the bounds of the sums around it).
fn check_obligations(tr: &mut Translator<'_>, dom: &Domain, obligations: &[Obligation]) -> Result<()> {
    for o in obligations {
        let mut d = dom.clone();
        for (v, lo, hi) in &o.sums {
            let var = Aff::var(v);
            d = d.with(var.minus(&tr.affine(lo)?)).with(tr.affine(hi)?.minus(&var));
        }
        let holds = tr.affine(&o.condition).is_ok_and(|c| d.implies_ge(&c));
        if !holds {
            return Err(Error::Domain(format!(
                "{}: cannot show {} ≥ 0 there (a lemma or definition applies only in its ranges)",
                o.what, o.condition
            )));
        }
    }
    Ok(())
}

/// The equalities of consecutive members, vectors component by component.
fn component_pairs(sides: &[Expr]) -> Result<Vec<[Expr; 2]>> {
    fn split(a: &Expr, b: &Expr, out: &mut Vec<[Expr; 2]>) -> Result<()> {
        match (a, b) {
            (Expr::Tuple(x), Expr::Tuple(y)) if x.len() == y.len() => {
                x.iter().zip(y).try_for_each(|(p, q)| split(p, q, out))
            }
            (Expr::Tuple(_), _) | (_, Expr::Tuple(_)) => Err(Error::Domain(format!(
                "'{a} = {b}': a vector equals only a vector of as many components"
            ))),
            _ => {
                out.push([a.clone(), b.clone()]);
                Ok(())
            }
        }
    }
    let mut out = Vec::new();
    for pair in sides.windows(2) {
        split(&pair[0], &pair[1], &mut out)?;
    }
    Ok(out)
}

/// One equality proved on `d`; a sum against a side that is not one is evaluated with that
/// side as its closed form (the WZ hint).
fn equal(tr: &mut Translator<'_>, pair: &[Expr; 2], d: &Domain) -> Result<()> {
    let (l, r) = match (&pair[0], &pair[1]) {
        (x, y) if !matches!(x, Expr::Sum(..)) && !matches!(y, Expr::Sum(..)) && (has_sum(x) != has_sum(y)) => {
            let (with_sum, other) = if has_sum(x) { (x, y) } else { (y, x) };
            let (s, o) = match scaled_sum(tr, with_sum, other, d)? {
                Some(lin) => lin,
                None => (tr.lin(with_sum, d)?, tr.lin(other, d)?),
            };
            if has_sum(x) {
                (s, o)
            } else {
                (o, s)
            }
        }
        (Expr::Sum(..), other) if !matches!(other, Expr::Sum(..)) => {
            let r = tr.lin(other, d)?;
            (tr.lin_hint(&pair[0], d, Some(r.clone()))?, r)
        }
        (other, Expr::Sum(..)) => {
            let l = tr.lin(other, d)?;
            (l.clone(), tr.lin_hint(&pair[1], d, Some(l))?)
        }
        _ => (tr.lin(&pair[0], d)?, tr.lin(&pair[1], d)?),
    };
    let mut diff = l;
    diff.extend(lin_neg(&r));
    tr.expect_zero(&diff, d, &format!("{} = {}", pair[0], pair[1]))
}

/// `c · Σ` against `other` (a side without sums), both translated: the sum with the closed
/// form `other / c` as its hint (`c` one term); `None` for another shape.
fn scaled_sum(tr: &mut Translator<'_>, with_sum: &Expr, other: &Expr, d: &Domain) -> Result<Option<(Lin, Lin)>> {
    let Some((c, sum)) = coefficient_times_sum(with_sum) else {
        return Ok(None);
    };
    let Ok(inverse) = tr.recip(&c, d) else {
        return Ok(None);
    };
    let o = tr.lin(other, d)?;
    let hint = lin_mul(&o, &[inverse])?;
    let s = tr.lin_hint(&sum, d, Some(hint))?;
    Ok(Some((lin_mul(&tr.lin(&c, d)?, &s)?, o)))
}

/// The symbolic proof of the parsed `rewritten` sides over the open ranges of `decls`.
fn prove_sides(
    decls: &Decls,
    ctx: &Ctx<'_>,
    rewritten: Rewritten,
    certificates: &[String],
) -> Result<(String, Vec<Step>, Method, Vec<Discharged>)> {
    let rs = &decls.ranges;
    let sides = rewritten.sides;
    let (certs, sym, conts) = prepare(certificates, ctx, &sides)?;
    let mut tr = Translator::new(&sym, &certs);
    let mut dom = tr.domain(decls, rs)?;
    for a in &rewritten.assumptions {
        dom = dom.with(tr.affine(a)?);
    }
    check_obligations(&mut tr, &dom, &rewritten.obligations)?;
    let modes: Vec<bool> = if decls.polygon.is_some() || decls.net.is_some() {
        vec![false, true]
    } else {
        vec![false]
    };
    // In a chain of scalars, the latest member without sums, per mode: every member up to the
    // current one is proved equal to it, so an equality that does not go through on its own
    // may be proved as its right side against it (the sum's closed form, a hint).
    let chain = !sides.iter().any(|s| matches!(s, Expr::Tuple(_)));
    let mut anchors: Vec<Option<Expr>> = vec![None; modes.len()];
    // The kinds of argument the equalities took, for the proof's method.
    let mut argued: Vec<Method> = Vec::new();
    for pair in &component_pairs(&sides)? {
        for (m, &unit) in modes.iter().enumerate() {
            tr.unit = unit;
            tr.next_cert = 0;
            tr.used.clear();
            tr.recurrences.clear();
            tr.integrals = 0;
            let mut d = dom.clone();
            if let (true, Some((name, m, n))) = (unit, tr.net.clone()) {
                let (i, j) = (Aff::var(UNIT), Aff::var(UNIT2));
                d = d.with(i.clone()).with(m.minus(&i)).with(j.clone()).with(n.minus(&j));
                tr.log.push(Step::label(format!(
                    "the unit net {name}[{UNIT}, {UNIT2}] = 1 (others 0), for every 0 ≤ {UNIT} ≤ {m}, 0 ≤ {UNIT2} ≤ {n}:"
                )));
            } else if unit {
                let (_, deg) = tr.polygon.clone().expect("polygon");
                d = d.with(Aff::var(UNIT)).with(deg.minus(&Aff::var(UNIT)));
                tr.log.push(Step::label(format!(
                    "the unit polygon b[{UNIT}] = 1 (others 0), for every 0 ≤ {UNIT} ≤ {deg}:"
                )));
            } else if decls.net.is_some() {
                tr.log.push(Step::label("the zero net:"));
            } else if decls.polygon.is_some() {
                tr.log.push(Step::label("the zero polygon:"));
            }
            let pair = match (&tr.polygon, tr.net.is_none()) {
                (Some((name, _)), true) => {
                    let name = name.clone();
                    [
                        collapse::collapse(&mut tr, &pair[0], &name, unit, &d)?,
                        collapse::collapse(&mut tr, &pair[1], &name, unit, &d)?,
                    ]
                }
                _ => pair.clone(),
            };
            let pair = &pair;
            let anchor = anchors[m].clone().filter(|_| chain);
            if !has_sum(&pair[0]) {
                anchors[m] = Some(pair[0].clone());
            }
            let marks = (tr.log.len(), tr.used.len(), tr.next_cert, tr.integrals);
            let reset = |tr: &mut Translator<'_>| {
                tr.log.truncate(marks.0);
                tr.used.truncate(marks.1);
                tr.next_cert = marks.2;
                tr.integrals = marks.3;
            };
            // Sums on both sides: first the right side against the chain's anchor (every member
            // so far equals it), which gives its sums a closed form; then the direct route; then
            // a claim stating a recurrence of sums, by creative telescoping; else the direct
            // route's reason stands.
            let by_anchor = match anchor.filter(|_| has_sum(&pair[0]) && has_sum(&pair[1])) {
                Some(a) => {
                    let through = equal(&mut tr, &[a, pair[1].clone()], &d).is_ok();
                    if !through {
                        reset(&mut tr);
                    }
                    through
                }
                None => false,
            };
            if !by_anchor {
                if let Err(reason) = equal(&mut tr, pair, &d) {
                    reset(&mut tr);
                    if recurrence::prove(&mut tr, &pair[0], &pair[1], &d)?.is_none() {
                        return Err(reason);
                    }
                }
            }
            if !has_sum(&pair[1]) {
                anchors[m] = Some(pair[1].clone());
            }
            argued.extend(tr.recurrences.iter().map(|r| r.0));
            if !tr.used.is_empty() {
                argued.push(Method::Wz);
            }
            if tr.integrals > 0 {
                argued.push(Method::Beta);
            }
        }
    }
    // The deepest argument names the proof; rational identities on pieces alone otherwise.
    let method = [Method::StatedRecurrence, Method::Telescoping, Method::Wz, Method::Beta]
        .into_iter()
        .find(|m| argued.contains(m))
        .unwrap_or(Method::Pieces);
    let open = scope(rs);
    let mut cert = format!(
        "for {}: both sides are sums of hypergeometric terms; dividing by one term leaves rational identities in the integer symbols and {}, proved exactly on every piece of the domain (the pieces where a term vanishes or a boundary convention applies are split off and proved separately)",
        open,
        if conts.is_empty() { "no parameters".to_string() } else { conts.join(", ") }
    );
    if decls.polygon.is_some() {
        cert.push_str("; affine in the control polygon: the zero polygon and the unit polygon at a symbolic index");
    }
    if decls.net.is_some() {
        cert.push_str("; affine in the control net: the zero net and the unit net at a symbolic pair of indices");
    }
    if !tr.used.is_empty() {
        cert.push_str(&format!("; WZ certificates: {}", tr.used.join("; ")));
    }
    if !tr.recurrences.is_empty() {
        let texts: Vec<&str> = tr.recurrences.iter().map(|r| r.1.as_str()).collect();
        cert.push_str(&format!("; {}", texts.join("; ")));
    }
    if !rewritten.definitions.is_empty() {
        cert.push_str(&format!(
            "; objects read by their definitions: {}",
            rewritten.definitions.join("; ")
        ));
    }
    if !rewritten.lemmas.is_empty() {
        cert.push_str(&format!(
            "; lemmas (proved for every value, each applied within its ranges): {}",
            rewritten.lemmas.join(", ")
        ));
    }
    Ok((cert, tr.log, method, tr.evidence))
}
