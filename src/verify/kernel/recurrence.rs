//! The for-every obligations of sums with a symbolic bound, built and checked here from what
//! the searches outside the kernel propose (a WZ certificate, a recurrence with its
//! certificate): whatever they propose, a `proved` needs every identity below to hold on every
//! piece of its domain ([`prove_zero`]).
//!
//! - WZ (`Σ_{k=a}^{b(n)} F(n, k) = rhs(n)` by induction on `n ≥ n₀`, `G` proposed):
//!   `F(n+1, k) − F(n, k) = G(n, k+1) − G(n, k)` for `a ≤ k ≤ b`; the ends
//!   `G(n, b+1) − G(n, a) + F(n+1, b+1) = rhs(n+1) − rhs(n)`; the base case at `n₀`, a finite
//!   sum; and, when dividing by a closed form's one term, the values of `n` where its
//!   coefficient vanishes, checked directly ([`wz_goal`], [`check_wz`]).
//! - Creative telescoping (`p_0, …, p_J` and `G` proposed):
//!   1. the telescoping equation for every `a ≤ k ≤ b(n)` and every `n ≥ n₁`;
//!   2. `Σ_j p_j(n) rhs(n+j) = G(n, b(n)+1) − G(n, a) + Σ_j p_j(n) Σ_{m=1}^{j} F(n+j, b(n)+m)`
//!      for every `n ≥ n₁` — summing 1 over `k` shows the same of `S`, so `Δ = S − rhs`
//!      satisfies `Σ_j p_j(n) Δ(n+j) = 0` there;
//!   3. `S(n) = rhs(n)` for `n = n₀, …, n₁ + J − 1`, finite sums,
//!
//!   where `n₁ ≥ n₀` is past every integer zero of the leading coefficient `p_J` (which is then
//!   a nonzero polynomial in the parameters for every `n ≥ n₁`, whatever the other integers).
//!   Induction on `n`: `Δ(n+J) = −Σ_{j<J} p_j(n) Δ(n+j) / p_J(n)`, so `Δ = 0` for every
//!   `n ≥ n₀` ([`check_telescoper`]).
//!
//!   With a second sum `S₂` on the right (two forms of one sequence, [`Other`]), its certificate
//!   must be of the same recurrence: its telescoping equation is proved too, its telescoped ends
//!   join the identity of 2. (so `Δ = S − rhs − S₂` satisfies the recurrence), and 3. compares
//!   `S` with `rhs + S₂`.
//! - A recurrence the claim states: each of its sums is the first one's summand shifted in `n`
//!   ([`stated_sums`]), the coefficients are the claim's, and the telescoping equation and the
//!   telescoped ends with the claim's other terms cancel ([`check_stated_recurrence`]). When
//!   no certificate has those ends, the sums are one sum of `h = Σ_j q_j F(n+j, k)` (proved on
//!   `a ≤ k ≤ b`) plus the terms past `b(n)`, and that sum's closed form is proved by `h`'s own
//!   recurrence for every `n ≥ n₀` ([`check_inhomogeneous`]).

use super::checked::{Method, Step};
use super::eval::Alg;
use super::hyper::{lin_mul, lin_neg, lin_subst, Aff, Lin, Symbols, Term};
use super::pieces::{prove_zero, Domain, ZeroOutcome};
use super::poly::RatFunc;
use super::Discharged;
use crate::error::{Error, Result};

/// `Σ lin = 0` at every integer point of `d`, proved piece by piece; the proof's steps go to
/// `log`.
pub fn check_zero(sym: &Symbols, lin: &[Term], d: &Domain, what: &str, log: &mut Vec<Step>) -> Result<Discharged> {
    let mut inner = Vec::new();
    match prove_zero(sym, lin, d, &mut inner)? {
        ZeroOutcome::Zero(pieces) => {
            log.push(Step::text(format!(
                "{what}: proved on {} ({pieces} piece{})",
                d.show(),
                if pieces == 1 { "" } else { "s" }
            )));
            log.extend(inner.into_iter().map(|l| l.nested(1)));
            Ok(Discharged::new(Method::Pieces))
        }
        ZeroOutcome::NonZero { region, residue } => Err(Error::Domain(format!(
            "{what} does not hold as an identity on {region}: {residue}"
        ))),
    }
}

/// Every obligation proved by [`check_zero`], in order; the first that fails is the error.
fn discharge(sym: &Symbols, obligations: &[Obligation], log: &mut Vec<Step>) -> Result<()> {
    for o in obligations {
        check_zero(sym, &o.lin, &o.domain, &o.what, log)?;
    }
    Ok(())
}

/// Most values of `n` checked directly before an induction (initial values, and the zeros of
/// a leading coefficient or of a closed form's coefficient).
pub const MAX_DIRECT_CASES: i64 = 64;

/// A recurrence with its certificate: `Σ_j p[j](n) F(n+j, k) = G(n, k+1) − G(n, k)`.
pub struct Telescoper {
    /// `p_0, …, p_J`, polynomials in every symbol but `k` (or as given).
    pub p: Vec<RatFunc>,
    /// `G = R·F`, a term.
    pub g: Term,
    /// `R`, readable.
    pub r: String,
}

impl Telescoper {
    /// The order `J`.
    pub fn order(&self) -> usize {
        self.p.len() - 1
    }
    /// The recurrence as text: `(p_J)·S(n+J) + … + (p_0)·S(n)`.
    pub fn show(&self, s: &str, n: &str) -> String {
        let mut parts = Vec::new();
        for (j, p) in self.p.iter().enumerate().rev() {
            if p.num.is_zero() {
                continue;
            }
            let at = if j == 0 { n.to_string() } else { format!("{n}+{j}") };
            parts.push(format!("({p})·{s}({at})"));
        }
        parts.join(" + ")
    }
}

/// One identity a proof rests on: `Σ lin = 0` at every integer point of `domain`.
pub struct Obligation {
    /// The terms.
    pub lin: Lin,
    /// Where.
    pub domain: Domain,
    /// What it says, for the log and the error.
    pub what: String,
}

/// A sum `Σ_{k=a}^{b(n)} F(n, k)` over the induction variable `n ≥ n₀`, the other integers on
/// `rest`.
pub struct SumShape<'a> {
    /// The summation variable.
    pub k: &'a str,
    /// The lower bound (free of `n`).
    pub a: &'a Aff,
    /// The upper bound `n + c`.
    pub b: &'a Aff,
    /// The induction variable.
    pub n: &'a str,
    /// Its least value.
    pub n0: &'a Aff,
    /// The domain of the other integers.
    pub rest: &'a Domain,
}

/// `p · lin` for a scalar `p`.
fn scaled(p: &RatFunc, lin: &[Term]) -> Result<Lin> {
    lin_mul(&[Term::scalar(p.clone())], lin)
}

/// The terms of `Σ_{k=a}^{b} F` at `n = n0`, where the sum must have a fixed number of terms
/// (at most 10 001).
pub fn finite_sum(
    sym: &Symbols,
    f: &[Term],
    (k, a, b): (&str, &Aff, &Aff),
    (n, n0): (&str, &Aff),
    what: &str,
) -> Result<Lin> {
    let width = b.subst(n, n0).minus(a);
    if !width.is_const() || width.c < -1 || width.c > 10_000 {
        return Err(Error::Domain(format!(
            "{what}: at {n} = {n0} the sum does not have a fixed number of terms"
        )));
    }
    let at0 = lin_subst(sym, f, n, n0);
    let mut out = Vec::new();
    for m in 0..=width.c {
        out.extend(lin_subst(sym, &at0, k, &a.shifted(m)));
    }
    Ok(out)
}

/// The first `n ≥ n0` past every integer zero (in `n`) of the coefficient of the closed-form
/// term `h`, so that dividing by `h` is defined for the whole induction; at most
/// [`MAX_DIRECT_CASES`] values past `n0`.
pub(crate) fn induction_start(sym: &Symbols, h: &Term, n: &str, n0: &Aff, what: &str) -> Result<Aff> {
    let mut start = n0.clone();
    for z in sym.integer_zeros(&h.coef.num)? {
        let c = z.coef(n);
        if c == 0 {
            continue;
        }
        let moving = z.v.keys().any(|x| x != n);
        if moving || !n0.is_const() {
            return Err(Error::Domain(format!(
                "{what}: the closed form's coefficient vanishes where {z} = 0, which moves with the other symbols: the induction cannot start past it"
            )));
        }
        start = past_root(start, &z, c);
    }
    if start.minus(n0).c > MAX_DIRECT_CASES {
        return Err(Error::Domain(format!(
            "{what}: the closed form's coefficient vanishes at {n} = {}, more than {MAX_DIRECT_CASES} values past {n0}",
            start.c - 1
        )));
    }
    Ok(start)
}

/// `Σ_j p_j(n) F(n+j, k) − G(n, k+1) + G(n, k)`, the telescoping equation as one sum.
pub fn telescoping_equation(sym: &Symbols, f: &Term, t: &Telescoper, n: &str, k: &str) -> Result<Lin> {
    let mut out = Vec::new();
    for (j, p) in t.p.iter().enumerate() {
        let fj = f.subst(sym, n, &Aff::var(n).shifted(j as i64));
        out.extend(scaled(p, &[fj])?);
    }
    out.extend(lin_neg(&[t.g.subst(sym, k, &Aff::var(k).shifted(1))]));
    out.push(t.g.clone());
    Ok(out)
}

/// `Σ_j p_j(n) S(n+j)` for `S(n) = Σ_{k=a}^{b(n)} F(n, k)`, by the telescoped ends:
/// `G(n, b+1) − G(n, a) + Σ_j p_j Σ_{m=1}^{j} F(n+j, b+m)`.
pub fn telescoped_sum(sym: &Symbols, f: &Term, t: &Telescoper, (n, k, a, b): (&str, &str, &Aff, &Aff)) -> Result<Lin> {
    let mut out = vec![t.g.subst(sym, k, &b.shifted(1))];
    out.extend(lin_neg(&[t.g.subst(sym, k, a)]));
    for (j, p) in t.p.iter().enumerate() {
        // Shift n first, then put k = b(n) + m (written in the old n).
        let fj = f.subst(sym, n, &Aff::var(n).shifted(j as i64));
        for m in 1..=j as i64 {
            out.extend(scaled(p, &[fj.subst(sym, k, &b.shifted(m))])?);
        }
    }
    Ok(out)
}

/// The first `n ≥ n₀` past every integer zero in `n` of the leading coefficient `p_J`; an
/// error when it may vanish at a point that moves with the other integers.
/// The first value of an induction moved past the integer root of `z = 0` in the induction
/// variable (whose coefficient in `z` is `c ≠ 0`), if it has one at or after `start`.
fn past_root(start: Aff, z: &Aff, c: i64) -> Aff {
    if z.c % c != 0 || -z.c / c < start.c {
        return start;
    }
    Aff::constant(-z.c / c + 1)
}

fn past_leading_zeros(sym: &Symbols, lead: &RatFunc, s: &SumShape<'_>, what: &str) -> Result<Aff> {
    let mut start = s.n0.clone();
    for z in sym.integer_zeros(&lead.num)? {
        let c = z.coef(s.n);
        if c == 0 {
            // Free of n: harmless only where the domain rules z = 0 out.
            if s.rest.with(z.clone()).with(z.scaled(-1)).feasible() {
                return Err(Error::Domain(format!(
                    "{what}: the recurrence's leading coefficient {lead} vanishes where {z} = 0, for every {}",
                    s.n
                )));
            }
            continue;
        }
        if z.v.len() > 1 || !s.n0.is_const() {
            return Err(Error::Domain(format!(
                "{what}: the recurrence's leading coefficient {lead} vanishes where {z} = 0, which moves with the other symbols"
            )));
        }
        start = past_root(start, &z, c);
    }
    Ok(start)
}

/// A second sum `Σ_{k=a}^{b(n)} F(n, k)` added to the right side (two forms of one sequence):
/// its summand `F`, its certificate of the left sum's recurrence, `a` (free of `n`) and `b`.
pub type Other<'a> = (&'a Term, &'a Telescoper, &'a Aff, &'a Aff);

/// Whether two recurrences have the same coefficients.
fn same_coefficients(p: &[RatFunc], q: &[RatFunc]) -> bool {
    let at = |p: &[RatFunc], j: usize| p.get(j).cloned().unwrap_or_else(|| RatFunc::from_int(0));
    (0..p.len().max(q.len())).all(|j| at(p, j).add(&at(q, j).neg()).num.is_zero())
}

/// The identities proving `Σ_{k=a}^{b(n)} F(n, k) = rhs(n) (+ the sum `other`)` for every
/// `n ≥ n₀` by the recurrence `t` (see the module documentation), and the text of the
/// certificate.
pub fn closed_form(
    sym: &Symbols,
    f: &Term,
    t: &Telescoper,
    s: &SumShape<'_>,
    (rhs, other): (&[Term], Option<&Other<'_>>),
    what: &str,
) -> Result<(Vec<Obligation>, String)> {
    let n = s.n;
    let order = t.order();
    let lead = &t.p[order];
    let d_n0 = s.rest.with(Aff::var(n).minus(s.n0));
    // Each S(n + j) is its sum to b(n) and the terms past it only where b ≥ a − 1.
    for (a, b) in [(s.a, s.b)].into_iter().chain(other.map(|o| (o.2, o.3))) {
        Bounds { k: s.k, a, b, n }.check(what)?;
        if !d_n0.implies_ge(&b.minus(a).shifted(1)) {
            let why = format!("{what}: cannot show b ≥ a − 1 on {}", d_n0.show());
            return Err(Error::Domain(why));
        }
    }
    if other.is_some_and(|o| !same_coefficients(&t.p, &o.1.p)) {
        return Err(Error::Domain(format!("{what}: the two sums' recurrences differ")));
    }
    let n1 = past_leading_zeros(sym, lead, s, what)?;
    let span = n1.minus(s.n0);
    if !span.is_const() || span.c + order as i64 > MAX_DIRECT_CASES {
        return Err(Error::Domain(format!(
            "{what}: the recurrence needs the values n = {}..{n1}+{order} directly, more than MAX_DIRECT_CASES = {MAX_DIRECT_CASES}",
            s.n0
        )));
    }
    let d_rec = s.rest.with(Aff::var(n).minus(&n1));
    let d_k = d_rec.with(Aff::var(s.k).minus(s.a)).with(s.b.minus(&Aff::var(s.k)));
    let mut out = vec![Obligation {
        lin: telescoping_equation(sym, f, t, n, s.k)?,
        domain: d_k,
        what: format!(
            "{what}: Σ_j p_j({n}) F({n}+j, {k}) = G({n}, {k}+1) − G({n}, {k})",
            k = s.k
        ),
    }];
    let mut ends = Vec::new();
    for (j, p) in t.p.iter().enumerate() {
        ends.extend(scaled(p, &lin_subst(sym, rhs, n, &Aff::var(n).shifted(j as i64)))?);
    }
    ends.extend(lin_neg(&telescoped_sum(sym, f, t, (n, s.k, s.a, s.b))?));
    if let Some((f2, t2, a2, b2)) = other {
        out.push(Obligation {
            lin: telescoping_equation(sym, f2, t2, n, s.k)?,
            domain: d_rec.with(Aff::var(s.k).minus(a2)).with(b2.minus(&Aff::var(s.k))),
            what: format!("{what}: the right sum's telescoping equation"),
        });
        ends.extend(telescoped_sum(sym, f2, t2, (n, s.k, a2, b2))?);
    }
    out.push(Obligation {
        lin: ends,
        domain: d_rec.clone(),
        what: format!(
            "{what}: the closed form satisfies the recurrence (Σ_j p_j({n}) rhs({n}+j) = the telescoped ends)"
        ),
    });
    let cases = span.c + order as i64;
    for m in 0..cases {
        let at = s.n0.shifted(m);
        let mut case = finite_sum(sym, std::slice::from_ref(f), (s.k, s.a, s.b), (n, &at), what)?;
        case.extend(lin_neg(&lin_subst(sym, rhs, n, &at)));
        if let Some((f2, _, a2, b2)) = other {
            let right = finite_sum(sym, std::slice::from_ref(f2), (s.k, a2, b2), (n, &at), what)?;
            case.extend(lin_neg(&right));
        }
        out.push(Obligation {
            lin: case,
            domain: s.rest.clone(),
            what: format!("{what}: the initial value {n} = {at}"),
        });
    }
    let last = s.n0.shifted(cases - 1);
    let text = format!(
        "{what}: {} = the telescoped ends, R = {}; leading coefficient ≠ 0 for {n} ≥ {n1}; {n} = {}..={last} checked directly",
        t.show("S", n),
        t.r,
        s.n0
    );
    Ok((out, text))
}

/// `Σ_{k=a}^{b(n)}` with the induction variable `n`: `b` must be `n + c` and `a` free of `n`
/// (so the sum at `n + 1` is the sum at `n` with one more term).
pub struct Bounds<'a> {
    /// The summation variable.
    pub k: &'a str,
    /// The lower bound.
    pub a: &'a Aff,
    /// The upper bound.
    pub b: &'a Aff,
    /// The induction variable.
    pub n: &'a str,
}

impl Bounds<'_> {
    fn check(&self, what: &str) -> Result<()> {
        if self.b.coef(self.n) != 1 || self.a.coef(self.n) != 0 || self.a.coef(self.k) != 0 {
            return Err(Error::Domain(format!(
                "{what}: the upper bound must be {n} + c and the lower bound free of {n} and {k}",
                n = self.n,
                k = self.k
            )));
        }
        Ok(())
    }
}

/// What a WZ certificate must prove: `Σ_k f = rhs` for every `n ≥ n0` on `d_ind` (before the
/// caller's upper bounds on `n` are added); `value` is the sum's closed form when one was
/// given, else `rhs` is the sum's value at `n0`.
pub struct WzGoal {
    /// The summand, divided by the closed form's one term when there is one.
    pub f: Lin,
    /// The right side: 1 after that division, the given closed form, or the value at `n0`.
    pub rhs: Lin,
    /// The closed form given (`None`: the sum is its value at `n0`).
    pub value: Option<Lin>,
    /// The first value of the induction.
    pub n0: Aff,
    /// The induction's domain.
    pub d_ind: Domain,
    /// The values checked directly, for the certificate's text (empty or `; n = …`).
    pub direct: String,
}

/// The goal of a WZ proof of `Σ_{k=a}^{b} f` for every `n ≥ n0` on `d` (`hint`: its closed
/// form, if given). A closed form of one term depending on `n` divides both sides (with
/// `numbers`, control points' factors read as 1 on the unit polygon); the values of `n` where
/// its coefficient vanishes are checked here directly (each on `at_value(n)`) and the induction
/// starts past them.
#[allow(clippy::too_many_arguments)]
pub fn wz_goal(
    sym: &Symbols,
    f: Lin,
    hint: Option<Lin>,
    s: &Bounds<'_>,
    n0: &Aff,
    d: &Domain,
    at_value: &dyn Fn(&Aff) -> Domain,
    what: &str,
    log: &mut Vec<Step>,
) -> Result<WzGoal> {
    s.check(what)?;
    let (k, a, b, n) = (s.k, s.a, s.b, s.n);
    let mut n0 = n0.clone();
    let mut d_ind = d.clone();
    let mut direct = String::new();
    let (f, rhs, value) = match hint {
        Some(h) if h.len() == 1 && h[0].mentions(sym, n) => {
            // On the unit polygon a control point's factor is 1 once its delta is resolved:
            // the sum and its one-term value, of the same degree in the control points, are
            // divided as numbers.
            let same_degree =
                h[0].deltas.is_empty() && h[0].bdeg > 0 && f.iter().all(|t| t.deltas.is_empty() && t.bdeg == h[0].bdeg);
            let numbers = |l: &[Term]| -> Lin { l.iter().map(|t| Term { bdeg: 0, ..t.clone() }).collect() };
            let (f, hn) = if same_degree {
                (numbers(&f), numbers(&h))
            } else {
                (f, h.clone())
            };
            let start = induction_start(sym, &hn[0], n, &n0, what)?;
            for m in 0..start.minus(&n0).c {
                let at = n0.shifted(m);
                let mut case = finite_sum(sym, &f, (k, a, b), (n, &at), what)?;
                case.extend(lin_neg(&lin_subst(sym, &hn, n, &at)));
                check_zero(
                    sym,
                    &case,
                    &at_value(&at),
                    &format!(
                        "{what}: the case {n} = {at}, where the closed form's coefficient vanishes (checked directly)"
                    ),
                    log,
                )?;
            }
            if start != n0 {
                direct = format!("; {n} = {n0}..={} checked directly", start.shifted(-1));
                d_ind = Domain {
                    cons: d.cons.iter().filter(|c| c.coef(n) <= 0).cloned().collect(),
                }
                .with(Aff::var(n).minus(&start));
                n0 = start;
            }
            let r = hn[0].recip(sym)?;
            (lin_mul(&f, &[r])?, vec![Term::scalar(RatFunc::from_int(1))], Some(h))
        }
        Some(h) => (f, h.clone(), Some(h)),
        None => {
            let base = finite_sum(sym, &f, (k, a, b), (n, &n0), what)?;
            (f, base, None)
        }
    };
    Ok(WzGoal {
        f,
        rhs,
        value,
        n0,
        d_ind,
        direct,
    })
}

/// The WZ proof of `goal` with `G` proposed by the caller, on the induction domain `d_ind`
/// (the goal's, with the caller's upper bounds on `n`), the base case on `at_n0`: the WZ
/// equation, the ends, and the base case when the closed form was given.
#[allow(clippy::too_many_arguments)]
pub fn check_wz(
    sym: &Symbols,
    goal: &WzGoal,
    g: &[Term],
    s: &Bounds<'_>,
    d_ind: &Domain,
    at_n0: &Domain,
    what: &str,
    log: &mut Vec<Step>,
) -> Result<Discharged> {
    s.check(what)?;
    let (k, a, b, n) = (s.k, s.a, s.b, s.n);
    let (f, rhs, n0) = (&goal.f, &goal.rhs, &goal.n0);
    if !d_ind.implies_ge(&Aff::var(n).minus(n0)) {
        return Err(Error::Domain(format!(
            "{what}: the induction's domain does not imply {n} ≥ {n0}"
        )));
    }
    let n1 = Aff::var(n).shifted(1);
    let k1 = Aff::var(k).shifted(1);
    // 1. The WZ equation on a ≤ k ≤ b.
    let mut wzeq = lin_subst(sym, f, n, &n1);
    wzeq.extend(lin_neg(f));
    wzeq.extend(lin_neg(&lin_subst(sym, g, k, &k1)));
    wzeq.extend(g.iter().cloned());
    // 2. The ends.
    let mut ends = lin_subst(sym, g, k, &b.shifted(1));
    ends.extend(lin_neg(&lin_subst(sym, g, k, a)));
    // F(n+1, b(n)+1): shift n first, then put k = b(n) + 1 (which is written in the old n).
    ends.extend(lin_subst(sym, &lin_subst(sym, f, n, &n1), k, &b.shifted(1)));
    ends.extend(lin_neg(&lin_subst(sym, rhs, n, &n1)));
    ends.extend(rhs.iter().cloned());
    let mut obligations = vec![
        Obligation {
            lin: wzeq,
            domain: d_ind.with(Aff::var(k).minus(a)).with(b.minus(&Aff::var(k))),
            what: format!("{what}: F({n}+1, {k}) − F({n}, {k}) = G({n}, {k}+1) − G({n}, {k})"),
        },
        Obligation {
            lin: ends,
            domain: d_ind.clone(),
            what: format!("{what}: G({n}, {b}+1) − G({n}, {a}) + F({n}+1, {b}+1) = rhs({n}+1) − rhs({n})"),
        },
    ];
    // 3. The base case (without a closed form, rhs is the sum at n0 by construction).
    if goal.value.is_some() {
        let mut base = finite_sum(sym, f, (k, a, b), (n, n0), what)?;
        base.extend(lin_neg(&lin_subst(sym, rhs, n, n0)));
        obligations.push(Obligation {
            lin: base,
            domain: at_n0.clone(),
            what: format!("{what}: the base case {n} = {n0}"),
        });
    }
    discharge(sym, &obligations, log)?;
    if goal.value.is_none() {
        log.push(Step::text(format!(
            "{what}: its value is its value at {n} = {n0}: {}",
            show(rhs)
        )));
    }
    Ok(Discharged::new(Method::Wz))
}

/// The proof of `Σ_{k=a}^{b(n)} f = rhs` for every `n ≥ n₀` by the recurrence `t` proposed by
/// a search (see the module documentation): every obligation built and checked, the steps in
/// `log` (none left there on failure), and the certificate's text.
pub fn check_telescoper(
    sym: &Symbols,
    f: &Term,
    t: &Telescoper,
    s: &SumShape<'_>,
    rhs: (&[Term], Option<&Other<'_>>),
    what: &str,
    log: &mut Vec<Step>,
) -> Result<(Discharged, String)> {
    let (obligations, text) = closed_form(sym, f, t, s, rhs, what)?;
    let mark = log.len();
    log.push(Step::text(format!(
        "{what}: F = {}; G = R·F = {}",
        f.show(),
        t.g.show()
    )));
    if let Err(e) = discharge(sym, &obligations, log) {
        log.truncate(mark);
        return Err(e);
    }
    Ok((Discharged::new(Method::Telescoping), text))
}

/// The sums of a recurrence a claim states, each `coef · Σ_{k=a}^{b_s} summand`: shown to be
/// `F(n + j_s, k)` for the first one's summand `F` with `b_s = b + j_s`; their coefficients
/// make the recurrence's `p_j`.
pub struct StatedSums {
    p: Vec<RatFunc>,
}

impl StatedSums {
    /// The coefficients `p_0, …, p_J` the claim states.
    pub fn coefficients(&self) -> &[RatFunc] {
        &self.p
    }
}

/// Checks that each of `sums` (coefficient, upper bound, summand) is `f` shifted by its upper
/// bound's distance `j` from `b` on `a ≤ k ≤ b_s` of `d`; `None` when one is not.
pub fn stated_sums(
    sym: &Symbols,
    sums: &[(RatFunc, Aff, Term)],
    f: &Term,
    s: &Bounds<'_>,
    d: &Domain,
    what: &str,
    log: &mut Vec<Step>,
) -> Result<Option<StatedSums>> {
    s.check(what)?;
    let (k, a, b, n) = (s.k, s.a, s.b, s.n);
    let mark = log.len();
    let mut p: Vec<RatFunc> = Vec::new();
    for (coef, bs, summand) in sums {
        let shift = bs.minus(b);
        if !shift.is_const() || shift.c < 0 {
            return Ok(None);
        }
        let j = shift.c as usize;
        if p.len() <= j {
            p.resize(j + 1, RatFunc::from_int(0));
        }
        p[j] = p[j].add(coef);
        // The summand is F at n + j.
        let fj = f.subst(sym, n, &Aff::var(n).shifted(j as i64));
        let dk = d.with(Aff::var(k).minus(a)).with(bs.minus(&Aff::var(k)));
        let check = vec![summand.clone(), lin_neg(&[fj])[0].clone()];
        if check_zero(
            sym,
            &check,
            &dk,
            &format!("{what}: the summand of Σ^{{{bs}}} is F({n}+{j}, {k})"),
            log,
        )
        .is_err()
        {
            log.truncate(mark);
            return Ok(None);
        }
    }
    Ok(Some(StatedSums { p }))
}

/// The proof that the claim's recurrence (`stated`, with its other terms `rest`) holds on `d`,
/// by `t`'s certificate `G`: `t`'s coefficients must be the stated ones, the telescoping
/// equation holds on `a ≤ k ≤ b`, and the telescoped ends and `rest` cancel.
#[allow(clippy::too_many_arguments)]
pub fn check_stated_recurrence(
    sym: &Symbols,
    stated: &StatedSums,
    f: &Term,
    t: &Telescoper,
    s: &Bounds<'_>,
    rest: Lin,
    d: &Domain,
    what: &str,
    log: &mut Vec<Step>,
) -> Result<Discharged> {
    s.check(what)?;
    let (k, a, b, n) = (s.k, s.a, s.b, s.n);
    if !same_coefficients(&t.p, &stated.p) {
        return Err(Error::Domain(format!(
            "{what}: the recurrence's coefficients are not the claim's"
        )));
    }
    if !d.implies_ge(&b.minus(a).shifted(1)) {
        return Err(Error::Domain(format!("{what}: cannot show b − a ≥ −1 on {}", d.show())));
    }
    log.push(Step::text(format!(
        "{what} by creative telescoping: F = {}; G = R·F = {}",
        f.show(),
        t.g.show()
    )));
    let mut ends = telescoped_sum(sym, f, t, (n, k, a, b))?;
    ends.extend(rest);
    let obligations = [
        Obligation {
            lin: telescoping_equation(sym, f, t, n, k)?,
            domain: d.with(Aff::var(k).minus(a)).with(b.minus(&Aff::var(k))),
            what: format!("{what}: Σ_j p_j({n}) F({n}+j, {k}) = G({n}, {k}+1) − G({n}, {k})"),
        },
        Obligation {
            lin: ends,
            domain: d.clone(),
            what: format!("{what}: the telescoped ends and the other terms of the claim cancel"),
        },
    ];
    discharge(sym, &obligations, log)?;
    Ok(Discharged::new(Method::StatedRecurrence))
}

/// The proof of a stated recurrence `Σ_j q_j S(n+j) + rest(n) = 0` on `d` (`q` = `stated`)
/// whose other terms are no telescoped ends: its sums are one sum of `h = Σ_j q_j F(n+j, k)`
/// (checked on `a ≤ k ≤ b`) and the terms of each `S(n+j)` past `b(n)`, so the claim is the
/// closed form `Σ_{k=a}^{b(n)} h = −rest − those terms`, proved for every `n ≥ n₀` by `h`'s
/// own recurrence `t` ([`check_telescoper`], which shows `b ≥ a − 1`).
#[allow(clippy::too_many_arguments)]
pub fn check_inhomogeneous(
    sym: &Symbols,
    (stated, f, h): (&StatedSums, &Term, &Term),
    t: &Telescoper,
    s: &SumShape<'_>,
    rest: &[Term],
    d: &Domain,
    what: &str,
    log: &mut Vec<Step>,
) -> Result<(Discharged, String)> {
    // d within n ≥ n₀ and the other integers' domain, so the induction covers the claim.
    let on = s.rest.with(Aff::var(s.n).minus(s.n0));
    if !on.cons.iter().all(|c| d.implies_ge(c)) {
        let why = format!("{what}: the induction is not on all of {}", d.show());
        return Err(Error::Domain(why));
    }
    // A certificate 0: the equation is Σ_j q_j F(n+j, k), the ends the terms past b(n).
    let (p, g) = (stated.p.clone(), Term::scalar(RatFunc::from_int(0)));
    let q = Telescoper { p, g, r: String::new() };
    let mut comb = telescoping_equation(sym, f, &q, s.n, s.k)?;
    comb.extend(lin_neg(std::slice::from_ref(h)));
    let d_k = d.with(Aff::var(s.k).minus(s.a)).with(s.b.minus(&Aff::var(s.k)));
    let eq = format!("{what}: h = Σ_j q_j F(n+j, k) on a ≤ k ≤ b");
    check_zero(sym, &comb, &d_k, &eq, log)?;
    let mut rhs = lin_neg(rest);
    rhs.extend(lin_neg(&telescoped_sum(sym, f, &q, (s.n, s.k, s.a, s.b))?));
    check_telescoper(sym, h, t, s, (&rhs, None), what, log)
}

fn show(l: &[Term]) -> String {
    if l.is_empty() {
        return "0".into();
    }
    l.iter().map(Term::show).collect::<Vec<_>>().join(" + ")
}

#[cfg(test)]
mod tests;
