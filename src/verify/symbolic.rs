//! Claims for every value of an integer symbol: `for = ["n = 0.."]` (an open range) keeps `n`
//! symbolic, and the claim is proved for every integer point of its ranges, or it is an error.
//!
//! Both sides are translated into finite sums of hypergeometric terms ([`super::hyper`]):
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
//! checks, each as a finite identity by [`hyper::prove_zero`]:
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

use super::checked::Verdict;
use super::checked::{Checked, Method};
use super::claims::{Decls, Identity, IntRange};
use super::context::Ctx;
use super::eval::Alg;
use super::expr::{self, Expr, Op};
use super::hyper::{lin_mul, lin_neg, lin_subst, power_of, prove_zero, Aff, Domain, Lin, Symbols, Term, ZeroOutcome};
use super::identity::check_identity;
use super::poly::RatFunc;
use super::{parse, rewrite};
use crate::error::{Error, Result};
use num_traits::Zero;
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

/// How many values of each open range the evaluation cross-check covers.
pub const CROSS_CHECK: i64 = 3;

/// The name of the symbolic index of the unit control polygon.
const UNIT: &str = "__j";

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

/// The declarations with each open range closed after [`CROSS_CHECK`] values (for the
/// evaluation check).
pub fn closed_decls(decls: &Decls) -> Decls {
    closed_after(decls, CROSS_CHECK)
}

/// The declarations with each open range closed after `extra` values past its first.
fn closed_after(decls: &Decls, extra: i64) -> Decls {
    let ranges = decls
        .ranges
        .iter()
        .map(|r| IntRange {
            to: Some(r.to.clone().unwrap_or_else(|| format!("({}) + {extra}", r.from))),
            ..r.clone()
        })
        .collect();
    Decls {
        ranges,
        ..decls.clone()
    }
}

fn sum_vars(e: &Expr, out: &mut Vec<String>) {
    match e {
        Expr::Sum(v, a, b, body) => {
            if !out.contains(v) {
                out.push(v.clone());
            }
            sum_vars(a, out);
            sum_vars(b, out);
            sum_vars(body, out);
        }
        Expr::Neg(a) | Expr::Fact(a) => sum_vars(a, out),
        Expr::Bin(_, a, b) => {
            sum_vars(a, out);
            sum_vars(b, out);
        }
        Expr::Call(_, args) | Expr::Index(_, args) | Expr::Tuple(args) => {
            for a in args {
                sum_vars(a, out);
            }
        }
        Expr::Matrix(rows) => {
            for r in rows {
                for a in r {
                    sum_vars(a, out);
                }
            }
        }
        Expr::Num(_) | Expr::Var(_) => {}
    }
}

/// Translates expressions into sums of hypergeometric terms, evaluating symbolic sums by their
/// certificates.
pub struct Translator<'a> {
    sym: &'a Symbols,
    /// The symbolic polygon's name and degree.
    polygon: Option<(String, Aff)>,
    /// Whether control points are the unit polygon at [`UNIT`] (else the zero polygon).
    unit: bool,
    certs: &'a [Expr],
    next_cert: usize,
    /// The proof's log.
    pub log: Vec<String>,
    /// The certificates used, for the one-line summary.
    pub used: Vec<String>,
}

impl<'a> Translator<'a> {
    /// A translator for the zero polygon (or none), with the claim's certificates.
    fn new(sym: &'a Symbols, certs: &'a [Expr]) -> Self {
        Translator {
            sym,
            polygon: None,
            unit: false,
            certs,
            next_cert: 0,
            log: Vec::new(),
            used: Vec::new(),
        }
    }
}

fn is_scalar(t: &Term) -> bool {
    t.facts.is_empty()
        && t.pows.is_empty()
        && t.support.is_empty()
        && t.deltas.is_empty()
        && t.defined.is_empty()
        && t.nonzero.is_empty()
        && t.bdeg == 0
}

impl<'a> Translator<'a> {
    fn scalar_of(&self, l: &[Term], what: &Expr) -> Result<RatFunc> {
        let mut out = RatFunc::from_int(0);
        for t in l {
            if !is_scalar(t) {
                return Err(Error::Domain(format!(
                    "'{what}' must be a polynomial or rational function here (an index, exponent or argument)"
                )));
            }
            out = out.add(&t.coef);
        }
        Ok(out)
    }

    /// An integer expression affine in the integer symbols.
    fn aff(&mut self, e: &Expr) -> Result<Aff> {
        let l = self.lin(e, &Domain::default())?;
        let r = self.scalar_of(&l, e)?;
        self.sym.rf_to_aff(&r).ok_or_else(|| {
            Error::Domain(format!(
                "'{e}' is not affine in the integer symbols with integer coefficients"
            ))
        })
    }

    /// A polynomial in the continuous parameters only.
    fn cont_poly(&mut self, e: &Expr) -> Result<RatFunc> {
        let l = self.lin(e, &Domain::default())?;
        let r = self.scalar_of(&l, e)?;
        if self.sym.poly_has_ints(&r.num) || self.sym.poly_has_ints(&r.den) {
            return Err(Error::Domain(format!(
                "'{e}' involves an integer symbol where only the continuous parameters may occur"
            )));
        }
        Ok(r)
    }

    /// A polynomial (constant denominator folded in) in the continuous parameters only.
    fn cont_polynomial(&mut self, arg: &Expr, whole: &Expr) -> Result<RatFunc> {
        let g = self.cont_poly(arg)?;
        let Some(c) = g.den.as_constant() else {
            return Err(Error::Domain(format!("'{whole}': the argument must be a polynomial")));
        };
        RatFunc::poly(g.num.clone()).div(&RatFunc::from_rat(&c))
    }

    fn powers(&mut self, base: &Expr, e: &Aff) -> Result<Term> {
        let r = self.cont_poly(base)?;
        let mut t = Term::scalar(RatFunc::from_int(1));
        t.pows = power_of(self.sym, &r.num, e)?;
        if r.den.as_constant().is_none() {
            t.pows.extend(power_of(self.sym, &r.den, &e.scaled(-1))?);
        } else if let Some(c) = r.den.as_constant() {
            if c.is_zero() {
                return Err(Error::DivisionByZero(format!("'{base}'")));
            }
            let inv = super::hyper::Base::Const(num_rational::BigRational::from_integer(1.into()) / c);
            if inv != super::hyper::Base::Const(num_rational::BigRational::from_integer(1.into())) {
                t.pows.push((inv, e.clone()));
            }
        }
        Ok(t)
    }

    fn binom(&self, a: &Aff, b: &Aff) -> Term {
        let mut t = Term::scalar(RatFunc::from_int(1));
        // Zero outside 0 ≤ b ≤ a by the reciprocal factorials alone (1/m! = 0 for m < 0; then
        // a = b + (a − b) ≥ 0 wherever the term lives), so a certificate times it keeps the
        // boundary values of the shifted factorials rather than the support of C(a, b).
        t.facts = vec![(a.clone(), 1), (b.clone(), -1), (a.minus(b), -1)];
        t
    }

    /// The reciprocal of a divisor, as one term.
    fn recip(&mut self, e: &Expr, d: &Domain) -> Result<Term> {
        match e {
            Expr::Bin(Op::Mul, a, b) => self.recip(a, d)?.times(&self.recip(b, d)?),
            Expr::Bin(Op::Div, a, b) => {
                let r = self.recip(a, d)?;
                let l = self.lin(b, d)?;
                match l.as_slice() {
                    [t] => r.times(t),
                    _ => {
                        let s = self.scalar_of(&l, b)?;
                        r.times(&Term::scalar(s))
                    }
                }
            }
            Expr::Neg(a) => {
                let mut r = self.recip(a, d)?;
                r.coef = r.coef.neg();
                Ok(r)
            }
            _ => {
                let l = self.lin(e, d)?;
                if let [t] = l.as_slice() {
                    if !is_scalar(t) {
                        return t.recip(self.sym);
                    }
                }
                let s = self.scalar_of(&l, e)?;
                if s.num.is_zero() {
                    return Err(Error::DivisionByZero(format!("division by '{e}' = 0")));
                }
                let has_ints = self.sym.poly_has_ints(&s.num);
                let mut t = Term::scalar(RatFunc {
                    num: s.den.clone(),
                    den: s.num.clone(),
                });
                if has_ints {
                    let a = self
                        .sym
                        .rf_to_aff(&RatFunc::poly(s.num.clone()))
                        .filter(|_| !self.sym.poly_has_conts(&s.num))
                        .ok_or_else(|| {
                            Error::Domain(format!(
                                "the divisor '{e}' involves the integer symbols but is not affine in them (write it as a product)"
                            ))
                        })?;
                    t.nonzero.push(a);
                }
                Ok(t)
            }
        }
    }

    /// The expression as a finite sum of terms, on the domain `d` (which symbolic sums need).
    pub fn lin(&mut self, e: &Expr, d: &Domain) -> Result<Lin> {
        self.lin_hint(e, d, None)
    }

    fn lin_hint(&mut self, e: &Expr, d: &Domain, hint: Option<Lin>) -> Result<Lin> {
        let scalar = |r: RatFunc| vec![Term::scalar(r)];
        Ok(match e {
            Expr::Num(r) => scalar(RatFunc::from_rat(r)),
            Expr::Var(v) => {
                if self.sym.index(v).is_none() {
                    return Err(Error::Domain(format!("unknown name '{v}' in a symbolic claim")));
                }
                scalar(self.sym.var(v))
            }
            Expr::Neg(a) => lin_neg(&self.lin(a, d)?),
            Expr::Bin(Op::Add, a, b) => {
                let mut l = self.lin(a, d)?;
                l.extend(self.lin(b, d)?);
                l
            }
            Expr::Bin(Op::Sub, a, b) => {
                let mut l = self.lin(a, d)?;
                l.extend(lin_neg(&self.lin(b, d)?));
                l
            }
            Expr::Bin(Op::Mul, a, b) => lin_mul(&self.lin(a, d)?, &self.lin(b, d)?)?,
            Expr::Bin(Op::Div, a, b) => {
                let r = self.recip(b, d)?;
                lin_mul(&self.lin(a, d)?, &[r])?
            }
            Expr::Bin(Op::Pow, a, k) => {
                if let Ok(c) = expr::eval_int(k, &Default::default()) {
                    if !(-64..=64).contains(&c) {
                        let r = self.cont_poly(a)?;
                        return Ok(scalar(r.pow(c)?));
                    }
                    let unit = if c >= 0 {
                        self.lin(a, d)?
                    } else {
                        vec![self.recip(a, d)?]
                    };
                    let mut acc = scalar(RatFunc::from_int(1));
                    for _ in 0..c.abs() {
                        acc = lin_mul(&acc, &unit)?;
                    }
                    acc
                } else {
                    let ex = self.aff(k)?;
                    vec![self.powers(a, &ex)?]
                }
            }
            Expr::Fact(a) => {
                let mut t = Term::scalar(RatFunc::from_int(1));
                let a = self.aff(a)?;
                t.defined.push(a.clone());
                t.facts.push((a, 1));
                vec![t]
            }
            Expr::Call(name, args) => self.call(e, name, args, d)?,
            Expr::Sum(v, a, b, body) => self.sum(v, a, b, body, d, hint)?,
            Expr::Index(name, args) => {
                let Some((pname, deg)) = self.polygon.clone() else {
                    return Err(Error::Domain(format!("'{e}': no symbolic polygon named {name}")));
                };
                if *name != pname || args.len() != 1 {
                    return Err(Error::Domain(format!(
                        "'{e}' is not a control point of the polygon {pname}"
                    )));
                }
                if !self.unit {
                    return Ok(Vec::new());
                }
                let at = self.aff(&args[0])?;
                let mut t = Term::scalar(RatFunc::from_int(1));
                t.deltas.push(at.minus(&Aff::var(UNIT)));
                t.support = vec![at.clone(), deg.minus(&at)];
                t.bdeg = 1;
                vec![t]
            }
            _ => {
                return Err(Error::Domain(format!(
                    "'{e}' is not supported for symbolic integers (vectors, matrices)"
                )))
            }
        })
    }

    fn call(&mut self, e: &Expr, name: &str, args: &[Expr], d: &Domain) -> Result<Lin> {
        let one = || RatFunc::from_int(1);
        match (name, args.len()) {
            ("B", 3) => {
                let (i, n) = (self.aff(&args[0])?, self.aff(&args[1])?);
                let g = self.cont_polynomial(&args[2], e)?;
                let mut t = self.binom(&n, &i);
                t.pows = power_of(self.sym, &g.num, &i)?;
                t.pows.extend(power_of(self.sym, &one().sub(&g).num, &n.minus(&i))?);
                Ok(vec![t])
            }
            ("C" | "binom", 2) => {
                let (a, b) = (self.aff(&args[0])?, self.aff(&args[1])?);
                Ok(vec![self.binom(&a, &b)])
            }
            ("__dB", 4) if expr::eval_int(&args[3], &Default::default()) == Ok(1) => {
                // d/dg [C(n,i) g^i (1−g)^(n−i)] = C(n,i) (i g^(i−1) (1−g)^(n−i) − (n−i) g^i (1−g)^(n−i−1)),
                // the product rule for rational functions (integer exponents).
                let (i, n) = (self.aff(&args[0])?, self.aff(&args[1])?);
                let g = self.cont_polynomial(&args[2], e)?;
                let h = one().sub(&g);
                let mk = |s: &Self, ei: &Aff, eh: &Aff, c: RatFunc| -> Result<Term> {
                    let mut t = s.binom(&n, &i);
                    t.coef = c;
                    t.pows = power_of(s.sym, &g.num, ei)?;
                    t.pows.extend(power_of(s.sym, &h.num, eh)?);
                    Ok(t)
                };
                let a = mk(self, &i.shifted(-1), &n.minus(&i), i.to_rf(self.sym))?;
                let b = mk(self, &i, &n.minus(&i).shifted(-1), n.minus(&i).to_rf(self.sym).neg())?;
                Ok(vec![a, b])
            }
            ("__dpow", 3) if expr::eval_int(&args[2], &Default::default()) == Ok(1) => {
                // d/dg g^e = e g^(e−1).
                let ex = self.aff(&args[1])?;
                let mut t = if ex.is_const() {
                    let p = Expr::pow(args[0].clone(), Expr::int(ex.c - 1));
                    return lin_mul(&self.lin(&p, d)?, &[Term::scalar(RatFunc::from_int(ex.c))]);
                } else {
                    self.powers(&args[0], &ex.shifted(-1))?
                };
                t.coef = ex.to_rf(self.sym);
                Ok(vec![t])
            }
            _ => Err(Error::Domain(format!(
                "'{e}' is not supported for symbolic integers (only B, C, sums, powers, factorials, diff and control points b[j])"
            ))),
        }
    }

    fn sum(&mut self, v: &str, a: &Expr, b: &Expr, body: &Expr, d: &Domain, hint: Option<Lin>) -> Result<Lin> {
        if d.cons.iter().any(|c| c.coef(v) != 0) {
            return Err(Error::Domain(format!("the summation variable {v} is already in use")));
        }
        let (av, bv) = (self.aff(a)?, self.aff(b)?);
        let dk = d.with(Aff::var(v).minus(&av)).with(bv.minus(&Aff::var(v)));
        let body = self.lin(body, &dk)?;
        let mut resolved = Vec::new();
        let mut rest = Vec::new();
        for mut t in body {
            if let Some(pos) = t.deltas.iter().position(|x| x.coef(v).abs() == 1) {
                let delta = t.deltas.remove(pos);
                let k = delta.coef(v);
                let mut other = delta.clone();
                other.v.remove(v);
                let at = other.scaled(-k);
                let mut s = t.subst(self.sym, v, &at);
                s.support.push(at.minus(&av));
                s.support.push(bv.minus(&at));
                resolved.push(s);
            } else {
                rest.push(t);
            }
        }
        if rest.is_empty() {
            return Ok(resolved);
        }
        let width = bv.minus(&av);
        if width.is_const() {
            if width.c > 10_000 {
                return Err(Error::TooLarge {
                    what: "terms of a sum with constant bounds",
                    value: width.c.to_string(),
                    limit: "10000".into(),
                });
            }
            for m in 0..=width.c {
                resolved.extend(lin_subst(self.sym, &rest, v, &av.shifted(m)));
            }
            return Ok(resolved);
        }
        let hint = hint.map(|h| {
            let mut h = h;
            h.extend(lin_neg(&resolved));
            h
        });
        let closed = self.wz(v, &av, &bv, rest, d, hint)?;
        resolved.extend(closed);
        Ok(resolved)
    }

    /// Evaluates `Σ_{k=a}^{b} F` by a WZ certificate (see the module documentation); returns
    /// its value (`hint` when given, else the value at the least `n`).
    fn wz(&mut self, k: &str, a: &Aff, b: &Aff, f: Lin, d: &Domain, hint: Option<Lin>) -> Result<Lin> {
        let sym = self.sym;
        let what = format!("Σ_{{{k}={a}}}^{{{b}}}");
        // The induction variable: coefficient 1 in the upper bound, bounded below only.
        let n = b
            .v
            .iter()
            .filter(|(x, c)| **c == 1 && a.coef(x) == 0)
            .map(|(x, _)| x.clone())
            .find(|x| {
                d.cons.iter().all(|c| c.coef(x) >= 0)
                    && d.cons.iter().filter(|c| c.coef(x) != 0).count() == 1
                    && d.cons.iter().any(|c| c.coef(x) == 1)
            })
            .ok_or_else(|| {
                Error::Domain(format!(
                    "{what}: the upper bound must be m + c for an integer symbol m with only a lower bound (an open range), and the lower bound must not depend on it"
                ))
            })?;
        let low = d.cons.iter().find(|c| c.coef(&n) == 1).expect("found above");
        let n0 = low.minus(&Aff::var(&n)).scaled(-1);
        let rest = Domain {
            cons: d.cons.iter().filter(|c| c.coef(&n) == 0).cloned().collect(),
        };
        if !d.implies_ge(&b.minus(a).shifted(1)) {
            return Err(Error::Domain(format!("{what}: cannot show b − a ≥ −1 on {}", d.show())));
        }
        // Normalise by a one-term value depending on n. Where that term's coefficient
        // vanishes the quotient means nothing: those values of n are checked directly, and the
        // induction starts past them.
        let mut n0 = n0;
        let mut d_ind = d.clone();
        let mut direct = String::new();
        let (f, rhs, value) = match hint {
            Some(h) if h.len() == 1 && h[0].mentions(sym, &n) => {
                let start = induction_start(sym, &h[0], &n, &n0, &what)?;
                for m in 0..start.minus(&n0).c {
                    let at = n0.shifted(m);
                    let mut case = base_case_terms(sym, &f, (k, a, b), (&n, &at), &what)?;
                    case.extend(lin_neg(&lin_subst(sym, &h, &n, &at)));
                    self.expect_zero(
                        &case,
                        &rest,
                        &format!("{what}: the case {n} = {at}, where the closed form's coefficient vanishes (checked directly)"),
                    )?;
                }
                if start != n0 {
                    direct = format!("; {n} = {n0}..={} checked directly", start.shifted(-1));
                    d_ind = rest.with(Aff::var(&n).minus(&start));
                    n0 = start;
                }
                let r = h[0].recip(sym)?;
                (lin_mul(&f, &[r])?, vec![Term::scalar(RatFunc::from_int(1))], Some(h))
            }
            Some(h) => (f, h.clone(), Some(h)),
            None => {
                let base = base_case_terms(sym, &f, (k, a, b), (&n, &n0), &what)?;
                (f, base, None)
            }
        };
        let (cert, found) = match self.certs.get(self.next_cert).cloned() {
            Some(c) => {
                self.next_cert += 1;
                (c, false)
            }
            None => match f.as_slice() {
                [single] => (
                    super::ansatz::find(sym, single, &n, k).map_err(|e| Error::Domain(format!("{what}: {e}")))?,
                    true,
                ),
                _ => {
                    return Err(Error::Domain(format!(
                        "{what}: a sum with a symbolic bound needs a WZ certificate R (certificate = [\"R\"], one per such sum, innermost first); none is searched for a summand of {} terms",
                        f.len()
                    )))
                }
            },
        };
        let cert_note = if found {
            " (found by the ansatz search, then checked)"
        } else {
            ""
        };
        let g = self.times_certificate(&cert, &f)?;
        self.used.push(format!(
            "{what} (induction on {n} ≥ {n0}{direct}): R = {cert}{cert_note}"
        ));
        self.log.push(format!(
            "{what} by induction on {n} ≥ {n0}: F = {}; certificate R = {cert}, G = R·F = {}",
            show(&f),
            show(&g)
        ));
        let n1 = Aff::var(&n).shifted(1);
        let k1 = Aff::var(k).shifted(1);
        // 1. The WZ equation on a ≤ k ≤ b.
        let mut wzeq = lin_subst(sym, &f, &n, &n1);
        wzeq.extend(lin_neg(&f));
        wzeq.extend(lin_neg(&lin_subst(sym, &g, k, &k1)));
        wzeq.extend(g.iter().cloned());
        let dk = d_ind.with(Aff::var(k).minus(a)).with(b.minus(&Aff::var(k)));
        self.expect_zero(
            &wzeq,
            &dk,
            &format!("{what}: F({n}+1, {k}) − F({n}, {k}) = G({n}, {k}+1) − G({n}, {k})"),
        )?;
        // 2. The ends.
        let mut ends = lin_subst(sym, &g, k, &b.shifted(1));
        ends.extend(lin_neg(&lin_subst(sym, &g, k, a)));
        // F(n+1, b(n)+1): shift n first, then put k = b(n) + 1 (which is written in the old n).
        ends.extend(lin_subst(sym, &lin_subst(sym, &f, &n, &n1), k, &b.shifted(1)));
        ends.extend(lin_neg(&lin_subst(sym, &rhs, &n, &n1)));
        ends.extend(rhs.iter().cloned());
        self.expect_zero(
            &ends,
            &d_ind,
            &format!("{what}: G({n}, {b}+1) − G({n}, {a}) + F({n}+1, {b}+1) = rhs({n}+1) − rhs({n})"),
        )?;
        // 3. The base case.
        if value.is_some() {
            let mut base = base_case_terms(sym, &f, (k, a, b), (&n, &n0), &what)?;
            base.extend(lin_neg(&lin_subst(sym, &rhs, &n, &n0)));
            self.expect_zero(&base, &rest, &format!("{what}: the base case {n} = {n0}"))?;
        } else {
            self.log
                .push(format!("{what}: its value is its value at {n} = {n0}: {}", show(&rhs)));
        }
        Ok(value.unwrap_or(rhs))
    }

    fn expect_zero(&mut self, lin: &[Term], d: &Domain, what: &str) -> Result<()> {
        let mut log = Vec::new();
        match prove_zero(self.sym, lin, d, &mut log)? {
            ZeroOutcome::Zero(pieces) => {
                self.log.push(format!(
                    "{what}: proved on {} ({pieces} piece{})",
                    d.show(),
                    if pieces == 1 { "" } else { "s" }
                ));
                self.log.extend(log.into_iter().map(|l| format!("  {l}")));
                Ok(())
            }
            ZeroOutcome::NonZero { region, residue } => Err(Error::Domain(format!(
                "{what} does not hold as an identity on {region}: {residue}"
            ))),
        }
    }

    /// `G = R · F`, the factors of `R` affine in the integers cancelled against factorials.
    fn times_certificate(&mut self, r: &Expr, f: &[Term]) -> Result<Lin> {
        let mut factors = Vec::new();
        flatten(r, true, &mut factors)?;
        let mut out: Lin = f.to_vec();
        for (fac, up) in factors {
            let l = self.lin(&fac, &Domain::default())?;
            let s = self.scalar_of(&l, &fac)?;
            let aff = self
                .sym
                .rf_to_aff(&s)
                .filter(|a| !a.is_const() && !self.sym.poly_has_conts(&s.num));
            for t in &mut out {
                match &aff {
                    Some(a) => cancel(t, a, up, self.sym),
                    None if up => t.coef = t.coef.mul(&s),
                    None => {
                        if self.sym.poly_has_ints(&s.num) {
                            return Err(Error::Domain(format!(
                                "the certificate's divisor '{fac}' involves the integers but is not affine in them"
                            )));
                        }
                        t.coef = t.coef.div(&s)?;
                    }
                }
            }
        }
        Ok(out)
    }
}

fn flatten(e: &Expr, up: bool, out: &mut Vec<(Expr, bool)>) -> Result<()> {
    match e {
        Expr::Bin(Op::Mul, a, b) => {
            flatten(a, up, out)?;
            flatten(b, up, out)
        }
        Expr::Bin(Op::Div, a, b) => {
            flatten(a, up, out)?;
            flatten(b, !up, out)
        }
        Expr::Neg(a) => {
            out.push((Expr::int(-1), up));
            flatten(a, up, out)
        }
        Expr::Bin(Op::Pow, a, k) if expr::eval_int(k, &Default::default()).is_ok_and(|c| c.abs() <= 64) => {
            let c = expr::eval_int(k, &Default::default())?;
            for _ in 0..c.abs() {
                flatten(a, up == (c > 0), out)?;
            }
            Ok(())
        }
        _ => {
            out.push((e.clone(), up));
            Ok(())
        }
    }
}

/// Multiplies (`up`) or divides the term by the affine factor `a`, cancelling against a
/// factorial when one fits: `a / a! = 1/(a−1)!`, `a · (a−1)! = a!`, `1/(a · (a−1)!) = 1/a!`,
/// `a!/a = (a−1)!`.
fn cancel(t: &mut Term, a: &Aff, up: bool, sym: &Symbols) {
    let find = |t: &Term, arg: &Aff, e: i8| t.facts.iter().position(|(x, s)| x == arg && *s == e);
    if up {
        if let Some(p) = find(t, a, -1) {
            t.facts[p].0 = a.shifted(-1);
        } else if let Some(p) = find(t, &a.shifted(-1), 1) {
            t.facts[p].0 = a.clone();
        } else {
            t.coef = t.coef.mul(&a.to_rf(sym));
        }
    } else if let Some(p) = find(t, &a.shifted(-1), -1) {
        t.facts[p].0 = a.clone();
    } else if let Some(p) = find(t, a, 1) {
        t.facts[p].0 = a.shifted(-1);
    } else {
        t.coef = RatFunc {
            num: t.coef.num.clone(),
            den: t.coef.den.mul(&a.to_rf(sym).num),
        };
        t.nonzero.push(a.clone());
    }
}

fn show(l: &[Term]) -> String {
    if l.is_empty() {
        return "0".into();
    }
    l.iter().map(Term::show).collect::<Vec<_>>().join(" + ")
}

/// The certificates, the symbol list (integers: ranges, summation variables, the unit index)
/// and the continuous parameters of a claim with open ranges.
fn prepare(certificates: &[String], ctx: &Ctx<'_>, sides: &[Expr]) -> Result<(Vec<Expr>, Symbols, Vec<String>)> {
    let rs = &ctx.decls.ranges;
    let certs: Vec<Expr> = certificates
        .iter()
        .map(|c| parse::parse(c, &ctx.known).and_then(|e| rewrite::expand(&e, &ctx.defs)))
        .collect::<Result<_>>()?;
    let refs: Vec<&Expr> = sides.iter().chain(&certs).collect();
    let mut ints: Vec<String> = rs.iter().map(|r| r.var.clone()).collect();
    for e in &refs {
        let mut found = Vec::new();
        sum_vars(e, &mut found);
        for v in found {
            if ints.contains(&v) {
                if rs.iter().any(|r| r.var == v) {
                    return Err(Error::Domain(format!(
                        "the summation variable {v} shadows a range variable"
                    )));
                }
            } else {
                ints.push(v);
            }
        }
    }
    if ctx.decls.polygon.is_some() {
        ints.push(UNIT.into());
    }
    let conts: Vec<String> = ctx
        .params(&refs[..sides.len()])
        .into_iter()
        .filter(|v| !ints.contains(v))
        .collect();
    let sym = Symbols::new(&ints, &conts);
    Ok((certs, sym, conts))
}

impl Translator<'_> {
    /// The domain of the ranges (and records the polygon).
    fn domain(&mut self, decls: &Decls, rs: &[IntRange]) -> Result<Domain> {
        let mut dom = Domain::default();
        for r in rs {
            let v = Aff::var(&r.var);
            let from = self.aff(&parse::parse(&r.from, &[])?)?;
            dom = dom.with(v.minus(&from));
            if let Some(to) = &r.to {
                let to = self.aff(&parse::parse(to, &[])?)?;
                dom = dom.with(to.minus(&v));
            }
        }
        if let Some(p) = &decls.polygon {
            let deg = self.aff(&parse::parse(&p.degree, &[])?)?;
            self.polygon = Some((p.name.clone(), deg));
        }
        Ok(dom)
    }
}

/// `p ≥ 0` for every integer point of the open ranges and every `t` in `[a, b]`: on each
/// piece of the domain every live term is a product of nonnegative factors — a positive
/// constant or a polynomial in `t` with nonnegative Bernstein coefficients on `[a, b]`,
/// factorials of arguments ≥ 0, powers of positive constants, and powers with exponent ≥ 0 of
/// polynomials ≥ 0 on `[a, b]` (or any exponent of one > 0 there). `nonneg(q, strict)` decides a
/// polynomial in the parameter on `[a, b]`. The evaluation check is the caller's.
pub fn nonneg_for_every(
    decls: &Decls,
    ctx: &Ctx<'_>,
    p: &Expr,
    nonneg: &dyn Fn(&RatFunc, bool) -> Result<bool>,
    detail: bool,
) -> Result<Checked> {
    let rs = &decls.ranges;
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
    let mut check = |live: &[&Term], d: &Domain, place: &str, log: &mut Vec<String>| -> Result<Option<String>> {
        for t in live {
            if sym.poly_has_ints(&t.coef.num) || sym.poly_has_ints(&t.coef.den) {
                // An affine coefficient in the integers (n, i + 1, …) shown ≥ 0 on the piece, or
                // a polynomial with coefficients ≥ 0 in variables ≥ 0 (n t, with n ≥ 0, t ∈ [0, 1]).
                let affine = sym.rf_to_aff(&t.coef).is_some_and(|a| d.implies_ge(&a));
                let positive_den = t
                    .coef
                    .den
                    .as_constant()
                    .is_some_and(|c| c > num_rational::BigRational::from_integer(0.into()));
                let mut monomials = positive_den;
                for (e, c) in t.coef.num.terms_list() {
                    monomials &= c > num_rational::BigRational::from_integer(0.into());
                    for (k, &x) in e.iter().enumerate() {
                        if x == 0 || !monomials {
                            continue;
                        }
                        let name = &sym.names[k];
                        monomials &= if k < sym.ints {
                            d.implies_ge(&Aff::var(name))
                        } else {
                            nonneg(&sym.var(name), false)?
                        };
                    }
                }
                if !affine && !monomials {
                    return Ok(Some(format!("the coefficient of {} is not shown ≥ 0", t.show())));
                }
            } else if t.coef.den.as_constant().is_none() || !nonneg(&t.coef, false)? {
                return Ok(Some(format!("the coefficient of {} is not shown ≥ 0", t.show())));
            }
            for (b, e) in &t.pows {
                let ok = match b {
                    super::hyper::Base::Const(c) => c > &num_rational::BigRational::from_integer(0.into()),
                    super::hyper::Base::Poly(q) => {
                        let q = RatFunc::poly(q.clone());
                        nonneg(&q, true)? || (d.implies_ge(e) && nonneg(&q, false)?)
                    }
                };
                if !ok {
                    return Ok(Some(format!("the factor {b}^({e}) of {} is not shown ≥ 0", t.show())));
                }
            }
        }
        log.push(format!(
            "on {place}: {} live terms, each a product of factors ≥ 0",
            live.len()
        ));
        Ok(None)
    };
    let out = super::hyper::prove_pieces(&sym, &lin, &dom, &mut log, &mut check)?;
    match out {
        ZeroOutcome::Zero(pieces) => {
            let open = scope(rs);
            let mut out = Checked::new(
                Verdict::Proved,
                format!(
                    "for {}: the left side minus the right is a sum of hypergeometric terms; on each piece of the domain ({pieces} in all) every live term is a product of factors ≥ 0 on the interval (positive constants and factorials, powers with exponent ≥ 0 of polynomials with Bernstein coefficients ≥ 0)",
                    open
                ),
            );
            out.method = Method::ForEvery;
            if detail {
                out.steps = log;
            }
            Ok(out)
        }
        ZeroOutcome::NonZero { region, residue } => Err(Error::Domain(format!(
            "cannot show the inequality on {region}: {residue} (a product-of-nonnegative-factors argument only)"
        ))),
    }
}

/// The first `n ≥ n0` past every integer zero (in `n`) of the coefficient of the closed-form
/// term `h`, so that dividing by `h` is defined for the whole induction; at most
/// [`MAX_DIRECT_CASES`] values past `n0`.
fn induction_start(sym: &Symbols, h: &Term, n: &str, n0: &Aff, what: &str) -> Result<Aff> {
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
        if z.c % c != 0 {
            continue;
        }
        let root = -z.c / c;
        if root >= start.c {
            start = Aff::constant(root + 1);
        }
    }
    if start.minus(n0).c > MAX_DIRECT_CASES {
        return Err(Error::Domain(format!(
            "{what}: the closed form's coefficient vanishes at {n} = {}, more than {MAX_DIRECT_CASES} values past {n0}",
            start.c - 1
        )));
    }
    Ok(start)
}

/// How many values of the induction variable may be checked directly before an induction.
const MAX_DIRECT_CASES: i64 = 64;

/// The terms of `Σ_{k=a}^{b} F` at the base case `n = n0`, where the sum must have a fixed
/// number of terms (at most 10 001).
fn base_case_terms(
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
    let mut base = Vec::new();
    for m in 0..=width.c {
        base.extend(lin_subst(sym, &at0, k, &a.shifted(m)));
    }
    Ok(base)
}

/// Checks an identity claim with open ranges for every value (see the module documentation).
/// When no proof is found, the first values of the open ranges are searched for an exact
/// counterexample (in widening windows, within [`REFUTATION_COMBINATIONS`] and
/// [`REFUTATION_TIME`], up to the first window that cannot be evaluated); without one the claim
/// is an error with the reason and the extent of the search.
pub fn check(id: &str, decls: &Decls, identity: &Identity, detail: bool) -> Result<Checked> {
    prove_for_every(id, decls, identity, detail).or_else(|reason| refute_in_search(id, decls, identity, reason))
}

fn refute_in_search(id: &str, decls: &Decls, identity: &Identity, reason: Error) -> Result<Checked> {
    let open: Vec<&str> = decls
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
        let closed = closed_after(decls, extra);
        match check_identity(id, &closed, &members, false) {
            Ok(mut out) if out.verdict == Verdict::Fails => {
                out.range = None;
                return Ok(out);
            }
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

fn prove_for_every(id: &str, decls: &Decls, identity: &Identity, detail: bool) -> Result<Checked> {
    let closed = closed_decls(decls);
    let evaluated = check_identity(id, &closed, &identity.sides.members(), false)?;
    if evaluated.verdict == Verdict::Fails {
        let mut out = evaluated;
        out.range = None;
        return Ok(out);
    }
    let (cert, log) = prove_symbolic(id, decls, identity, &closed)?;
    let mut out = Checked::new(
        Verdict::Proved,
        format!(
            "{cert}; also evaluated exactly for the first {} values of each open range ({})",
            CROSS_CHECK + 1,
            evaluated.verdict.as_str()
        ),
    );
    out.method = Method::ForEvery;
    if detail {
        out.steps = log;
    }
    Ok(out)
}

/// Tries the symbolic proof alone (no evaluation cross-check, no counterexample search) of an
/// identity with open ranges: `Ok` with the certificate when it goes through, else the reason.
/// No verdict comes from here: the caller only reports the outcome.
pub(crate) fn attempt_for_every(id: &str, decls: &Decls, identity: &Identity) -> Result<String> {
    let closed = closed_decls(decls);
    prove_symbolic(id, decls, identity, &closed).map(|(cert, _)| cert)
}

/// The symbolic proof of `identity` over the open ranges of `decls`, parsed in the context of
/// `closed` (the same declarations over finite ranges): the certificate and the proof's log.
fn prove_symbolic(id: &str, decls: &Decls, identity: &Identity, closed: &Decls) -> Result<(String, Vec<String>)> {
    let rs = &decls.ranges;
    let ctx = Ctx::new(id, closed, Vec::new())?;
    let sides: Vec<Expr> = identity
        .sides
        .members()
        .iter()
        .map(|s| ctx.expr(s))
        .collect::<Result<_>>()?;
    let (certs, sym, conts) = prepare(&identity.certificates, &ctx, &sides)?;
    let mut tr = Translator::new(&sym, &certs);
    let dom = tr.domain(decls, rs)?;
    let modes: Vec<bool> = if decls.polygon.is_some() {
        vec![false, true]
    } else {
        vec![false]
    };
    for pair in sides.windows(2) {
        for &unit in &modes {
            tr.unit = unit;
            tr.next_cert = 0;
            tr.used.clear();
            let mut d = dom.clone();
            if unit {
                let (_, deg) = tr.polygon.clone().expect("polygon");
                d = d.with(Aff::var(UNIT)).with(deg.minus(&Aff::var(UNIT)));
                tr.log.push(format!(
                    "the unit polygon b[{UNIT}] = 1 (others 0), for every 0 ≤ {UNIT} ≤ {deg}:"
                ));
            } else if decls.polygon.is_some() {
                tr.log.push("the zero polygon:".into());
            }
            let (l, r) = match (&pair[0], &pair[1]) {
                (Expr::Sum(..), other) if !matches!(other, Expr::Sum(..)) => {
                    let r = tr.lin(other, &d)?;
                    (tr.lin_hint(&pair[0], &d, Some(r.clone()))?, r)
                }
                (other, Expr::Sum(..)) => {
                    let l = tr.lin(other, &d)?;
                    (l.clone(), tr.lin_hint(&pair[1], &d, Some(l))?)
                }
                _ => (tr.lin(&pair[0], &d)?, tr.lin(&pair[1], &d)?),
            };
            let mut diff = l;
            diff.extend(lin_neg(&r));
            tr.expect_zero(&diff, &d, &format!("{} = {}", pair[0], pair[1]))?;
        }
    }
    let open = scope(rs);
    let mut cert = format!(
        "for {}: both sides are sums of hypergeometric terms; dividing by one term leaves rational identities in the integer symbols and {}, proved exactly on every piece of the domain (the pieces where a term vanishes or a boundary convention applies are split off and proved separately)",
        open,
        if conts.is_empty() { "no parameters".to_string() } else { conts.join(", ") }
    );
    if decls.polygon.is_some() {
        cert.push_str("; affine in the control polygon: the zero polygon and the unit polygon at a symbolic index");
    }
    if !tr.used.is_empty() {
        cert.push_str(&format!("; WZ certificates: {}", tr.used.join("; ")));
    }
    Ok((cert, tr.log))
}
