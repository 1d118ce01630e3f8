//! Hypergeometric terms in symbolic integers, and exact proofs that a finite sum of them is
//! zero for every integer point of a polyhedral domain.
//!
//! A [`Term`] is `coef · Π (a_m)!^{±1} · Π base_l^{e_l}`, with `coef` a rational function of the
//! integer symbols and the continuous parameters, `a_m` and `e_l` affine in the integer symbols,
//! and `base_l` a polynomial in the continuous parameters only. Its value at an integer point:
//! zero when a *support* condition (`a ≥ 0`, from the conventions `B(i, n, t) = 0` outside
//! `0 ≤ i ≤ n`, `C(n, k) = 0` outside `0 ≤ k ≤ n`, `b[j] = 0` outside the polygon), a Kronecker
//! delta (`[a = 0]`, from a unit control polygon) or a reciprocal factorial (`1/a! = 0` for
//! `a < 0`) says so; otherwise the formula, which must then be defined (numerator factorials of
//! integers ≥ 0, denominators ≠ 0).
//!
//! [`prove_zero`] decides `Σ_j T_j = 0` on every integer point of a domain `{x : A x + c ≥ 0}`:
//! the domain is split (exactly, by affine conditions) until in each piece every condition of
//! every term holds throughout or fails throughout — which is decided by Fourier–Motzkin
//! elimination over the rationals with integer tightening, a sound emptiness test for integer
//! points. In a piece, the dead terms are dropped and the rest are divided by the first live term
//! `T_0`: every `T_j / T_0` is then a rational function (factorials with the same linear part
//! pair into products of affine factors, which are positive because every factorial argument is
//! ≥ 0 there; powers of the same base with exponents differing by a constant give a power), and
//! `Σ_j T_j = 0` ⟺ `Σ_j T_j / T_0 = 0`, an identity of rational functions in all the symbols,
//! checked exactly. An equality piece (`a = 0`) is handled by substituting one variable.

use super::eval::Alg;
use super::poly::{Poly, RatFunc};
use crate::error::{Error, Result};
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt;
use std::rc::Rc;

/// Most pieces one proof may split its domain into.
pub const MAX_REGIONS: usize = 20_000;
/// Most constraints Fourier–Motzkin may hold while eliminating one variable (beyond it the
/// test answers "maybe feasible", which only costs splits, never soundness).
const MAX_FM: usize = 4_000;

/// An affine form `c + Σ a_v v` in integer symbols, integer coefficients.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Aff {
    /// The constant.
    pub c: i64,
    /// The coefficients (never zero).
    pub v: BTreeMap<String, i64>,
}

impl Aff {
    /// The constant `c`.
    pub fn constant(c: i64) -> Aff {
        Aff { c, v: BTreeMap::new() }
    }
    /// The variable `name`.
    pub fn var(name: &str) -> Aff {
        let mut v = BTreeMap::new();
        v.insert(name.to_string(), 1);
        Aff { c: 0, v }
    }
    /// The coefficient of `name`.
    pub fn coef(&self, name: &str) -> i64 {
        self.v.get(name).copied().unwrap_or(0)
    }
    /// Whether the form is a constant.
    pub fn is_const(&self) -> bool {
        self.v.is_empty()
    }
    /// `self + k·o`.
    pub fn add_scaled(&self, o: &Aff, k: i64) -> Aff {
        let mut out = self.clone();
        out.c = affine_op(k.checked_mul(o.c).and_then(|x| out.c.checked_add(x)));
        for (name, a) in &o.v {
            let e = out.v.entry(name.clone()).or_insert(0);
            *e = affine_op(k.checked_mul(*a).and_then(|x| e.checked_add(x)));
            if *e == 0 {
                out.v.remove(name);
            }
        }
        out
    }
    /// `self + o`.
    pub fn plus(&self, o: &Aff) -> Aff {
        self.add_scaled(o, 1)
    }
    /// `self − o`.
    pub fn minus(&self, o: &Aff) -> Aff {
        self.add_scaled(o, -1)
    }
    /// `k · self`.
    pub fn scaled(&self, k: i64) -> Aff {
        Aff::constant(0).add_scaled(self, k)
    }
    /// `self + k`.
    pub fn shifted(&self, k: i64) -> Aff {
        let mut out = self.clone();
        out.c = affine_op(out.c.checked_add(k));
        out
    }
    /// `self` with `name` replaced by `by`.
    pub fn subst(&self, name: &str, by: &Aff) -> Aff {
        let a = self.coef(name);
        if a == 0 {
            return self.clone();
        }
        let mut out = self.clone();
        out.v.remove(name);
        out.add_scaled(by, a)
    }
    /// The linear part (the constant dropped).
    pub fn linear(&self) -> BTreeMap<String, i64> {
        self.v.clone()
    }
    /// As a rational function over the symbol list.
    pub fn to_rf(&self, sym: &Symbols) -> RatFunc {
        let mut out = RatFunc::from_int(self.c);
        for (name, a) in &self.v {
            out = out.add(&RatFunc::from_int(*a).mul(&sym.var(name)));
        }
        out
    }
}

/// Largest integer coefficient an index expression may hold (`n + 100`, `2k − 1`): affine
/// forms built from such inputs by the few substitutions of a proof stay far inside 64 bits.
pub const MAX_AFFINE_COEFFICIENT: i64 = 1 << 32;

/// The result of an affine-form operation. Overflow would silently change which terms a proof
/// keeps, so it stops the claim instead (the command reports it as an error); inputs are held
/// to [`MAX_AFFINE_COEFFICIENT`], so this is a backstop, not an expected path.
fn affine_op(value: Option<i64>) -> i64 {
    value.expect("an index expression's integer coefficient overflowed 64 bits")
}

impl fmt::Display for Aff {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut first = true;
        for (name, a) in &self.v {
            let sign = if *a < 0 { "-" } else { "+" };
            let mag = a.abs();
            let coef = if mag == 1 { String::new() } else { mag.to_string() };
            if first {
                write!(f, "{}{coef}{name}", if *a < 0 { "-" } else { "" })?;
            } else {
                write!(f, " {sign} {coef}{name}")?;
            }
            first = false;
        }
        if first {
            write!(f, "{}", self.c)
        } else if self.c != 0 {
            write!(f, " {} {}", if self.c < 0 { "-" } else { "+" }, self.c.abs())
        } else {
            Ok(())
        }
    }
}

/// The variable list every polynomial of one proof is built over: integer symbols, then
/// continuous parameters.
#[derive(Clone, Debug)]
pub struct Symbols {
    /// All names, integer symbols first.
    pub names: Rc<[String]>,
    /// How many of them are integer symbols.
    pub ints: usize,
}

impl Symbols {
    /// Builds the list (and makes it the one rational constants are built over).
    pub fn new(ints: &[String], conts: &[String]) -> Symbols {
        let names: Vec<String> = ints.iter().chain(conts).cloned().collect();
        let names: Rc<[String]> = Rc::from(names);
        super::poly::set_names(&names);
        Symbols {
            names,
            ints: ints.len(),
        }
    }
    /// The index of a name.
    pub fn index(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n == name)
    }
    /// Whether `name` is an integer symbol.
    pub fn is_int(&self, name: &str) -> bool {
        self.index(name).is_some_and(|k| k < self.ints)
    }
    /// Whether `name` is a continuous parameter.
    pub fn is_cont(&self, name: &str) -> bool {
        self.index(name).is_some_and(|k| k >= self.ints)
    }
    /// The variable `name` as a rational function (0 if unknown: callers check names first).
    pub fn var(&self, name: &str) -> RatFunc {
        match self.index(name) {
            Some(k) => RatFunc::poly(Poly::var(&self.names, k)),
            None => RatFunc::from_int(0),
        }
    }
    fn poly_from_terms(&self, terms: &[(Vec<u16>, BigRational)]) -> Poly {
        let mut out = RatFunc::from_int(0);
        for (e, c) in terms {
            let mut m = RatFunc::from_rat(c);
            for (k, &x) in e.iter().enumerate() {
                for _ in 0..x {
                    m = m.mul(&RatFunc::poly(Poly::var(&self.names, k)));
                }
            }
            out = out.add(&m);
        }
        out.num
    }
    /// Whether a polynomial mentions an integer symbol.
    pub fn poly_has_ints(&self, p: &Poly) -> bool {
        p.terms_list()
            .iter()
            .any(|(e, _)| e[..self.ints].iter().any(|&x| x > 0))
    }
    /// Whether a polynomial mentions a continuous parameter.
    pub fn poly_has_conts(&self, p: &Poly) -> bool {
        p.terms_list()
            .iter()
            .any(|(e, _)| e[self.ints..].iter().any(|&x| x > 0))
    }
    /// A polynomial of degree ≤ 1 in the integer symbols with integer coefficients and no
    /// continuous parameter, as an affine form.
    pub fn poly_to_aff(&self, p: &Poly) -> Option<Aff> {
        let mut out = Aff::constant(0);
        for (e, c) in p.terms_list() {
            if !c.is_integer() {
                return None;
            }
            let c = c.to_integer().to_i64().filter(|c| c.abs() <= MAX_AFFINE_COEFFICIENT)?;
            let deg: u32 = e.iter().map(|&x| u32::from(x)).sum();
            match deg {
                0 => out.c = affine_op(out.c.checked_add(c)),
                1 => {
                    let k = e.iter().position(|&x| x == 1)?;
                    if k >= self.ints {
                        return None;
                    }
                    out.v.insert(self.names[k].clone(), c);
                }
                _ => return None,
            }
        }
        Some(out)
    }
    /// A rational function that is affine in the integer symbols (constant denominator).
    pub fn rf_to_aff(&self, r: &RatFunc) -> Option<Aff> {
        let d = r.den.as_constant()?;
        if !d.is_one() {
            let scaled = RatFunc::poly(r.num.clone()).div(&RatFunc::from_rat(&d)).ok()?;
            return self.poly_to_aff(&scaled.num);
        }
        self.poly_to_aff(&r.num)
    }
    /// Affine forms in the integer symbols such that `p` is a nonzero polynomial in the
    /// continuous parameters wherever each of them is ≠ 0 (the integer points where `p`
    /// vanishes identically are on their zero sets). An error when `p` is zero, or when those
    /// points are not found to lie on such hyperplanes (then a division by `p` is refused).
    pub fn integer_zeros(&self, p: &Poly) -> Result<Vec<Aff>> {
        if p.is_zero() {
            return Err(Error::DivisionByZero("division by zero".into()));
        }
        // p = Σ_α c_α(ints) x^α: p ≢ 0 wherever one c_α ≠ 0; take the simplest c_α.
        let mut groups: BTreeMap<Vec<u16>, Vec<(Vec<u16>, BigRational)>> = BTreeMap::new();
        for (mut e, c) in p.terms_list() {
            let cont = e[self.ints..].to_vec();
            e[self.ints..].iter_mut().for_each(|x| *x = 0);
            groups.entry(cont).or_default().push((e, c));
        }
        let simplest = groups
            .values()
            .min_by_key(|t| (t.len(), t.iter().map(|(e, _)| e.iter().sum::<u16>()).max()))
            .expect("p is not zero");
        self.affine_factors(self.poly_from_terms(simplest)).ok_or_else(|| {
            Error::Domain(format!(
                "cannot divide by ({p}): the integer points where it vanishes are not known to lie on hyperplanes"
            ))
        })
    }

    /// `p` scaled to integer coefficients (by the lcm of their denominators).
    fn integral(&self, p: &Poly) -> Poly {
        let l = p.terms_list().iter().fold(BigInt::one(), |l, (_, c)| l.lcm(c.denom()));
        p.mul(&Poly::constant(&self.names, &BigRational::from_integer(l)))
    }

    /// Affine forms whose nonvanishing makes the polynomial `c` in the integer symbols nonzero
    /// at integer points: its affine factors, the integer roots of a one-symbol factor.
    fn affine_factors(&self, mut c: Poly) -> Option<Vec<Aff>> {
        let mut out: Vec<Aff> = Vec::new();
        'factor: loop {
            if c.as_constant().is_some() {
                return Some(out);
            }
            if let Some(a) = self.poly_to_aff(&self.integral(&c)) {
                // Zero at some integer point only when the gcd of the coefficients divides
                // the constant (2n − 1 never is).
                let g = a.v.values().fold(0i64, |g, &x| g.gcd(&x));
                if g != 0 && a.c % g == 0 {
                    out.push(a);
                }
                return Some(out);
            }
            let used: Vec<usize> = (0..self.ints)
                .filter(|&k| c.terms_list().iter().any(|(e, _)| e[k] > 0))
                .collect();
            for &k in &used {
                if let Some(q) = c.exact_div(&Poly::var(&self.names, k)) {
                    let a = Aff::var(&self.names[k]);
                    if !out.contains(&a) {
                        out.push(a);
                    }
                    c = q;
                    continue 'factor;
                }
            }
            let [k] = used[..] else {
                return None;
            };
            // One symbol s, c(0) ≠ 0: an integer root divides the constant of integral(c).
            let ic = self.integral(&c);
            let (_, c0) = ic.terms_list().into_iter().find(|(e, _)| e.iter().all(|&x| x == 0))?;
            let c0 = c0.to_integer().abs();
            if c0 > BigInt::from(MAX_ROOT_SEARCH) {
                return None;
            }
            let c0 = c0.to_i64()?;
            let mut point = vec![BigRational::zero(); self.names.len()];
            for d in (1..=c0).filter(|d| c0 % d == 0) {
                for r in [d, -d] {
                    point[k] = BigRational::from_integer(r.into());
                    if ic.eval(&point).is_zero() {
                        out.push(Aff::var(&self.names[k]).shifted(-r));
                    }
                }
            }
            return Some(out);
        }
    }

    /// `p` with the integer symbol `name` replaced by `by`.
    pub fn subst_poly(&self, p: &Poly, name: &str, by: &Aff) -> Poly {
        let Some(k) = self.index(name) else {
            return p.clone();
        };
        let terms = p.terms_list();
        if terms.iter().all(|(e, _)| e[k] == 0) {
            return p.clone();
        }
        let by = by.to_rf(self);
        let mut out = RatFunc::from_int(0);
        for (mut e, c) in terms {
            let x = e[k];
            e[k] = 0;
            let mut m = RatFunc::poly(self.poly_from_terms(&[(e, c)]));
            for _ in 0..x {
                m = m.mul(&by);
            }
            out = out.add(&m);
        }
        out.num
    }
    /// `r` with `name` replaced by `by`.
    pub fn subst_rf(&self, r: &RatFunc, name: &str, by: &Aff) -> RatFunc {
        RatFunc {
            num: self.subst_poly(&r.num, name, by),
            den: self.subst_poly(&r.den, name, by),
        }
    }
}

/// Up to this constant term, a one-symbol divisor's integer roots are searched (its divisors).
const MAX_ROOT_SEARCH: i64 = 1_000_000;

/// The base of a power with a symbolic exponent: a rational constant or a normalised
/// non-constant polynomial in the continuous parameters (first coefficient 1).
#[derive(Clone, Debug, PartialEq)]
pub enum Base {
    /// A nonzero rational constant.
    Const(BigRational),
    /// A non-constant polynomial with first coefficient 1.
    Poly(Poly),
}

impl Base {
    fn to_rf(&self) -> RatFunc {
        match self {
            Base::Const(c) => RatFunc::from_rat(c),
            Base::Poly(p) => RatFunc::poly(p.clone()),
        }
    }
}

impl fmt::Display for Base {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Base::Const(c) => write!(f, "{c}"),
            Base::Poly(p) => write!(f, "({p})"),
        }
    }
}

/// Splits a nonzero polynomial in the continuous parameters into `c · Π x^α · q` and returns
/// the powers `base^(k·e)` of `p^e`.
pub fn power_of(sym: &Symbols, p: &Poly, e: &Aff) -> Result<Vec<(Base, Aff)>> {
    let terms = p.terms_list();
    if terms.is_empty() {
        return Err(Error::Domain(format!(
            "the base of the power with symbolic exponent {e} is zero"
        )));
    }
    if sym.poly_has_ints(p) {
        return Err(Error::Domain(format!(
            "the base ({p}) of a power with symbolic exponent {e} involves an integer symbol: not a hypergeometric term"
        )));
    }
    let c = terms[0].1.clone();
    let width = terms[0].0.len();
    let alpha: Vec<u16> = (0..width)
        .map(|k| terms.iter().map(|(x, _)| x[k]).min().unwrap_or(0))
        .collect();
    let q: Vec<(Vec<u16>, BigRational)> = terms
        .iter()
        .map(|(x, a)| (x.iter().zip(&alpha).map(|(u, v)| u - v).collect(), a / &c))
        .collect();
    let mut out = Vec::new();
    if !c.is_one() {
        out.push((Base::Const(c), e.clone()));
    }
    for (k, &a) in alpha.iter().enumerate() {
        if a > 0 {
            out.push((Base::Poly(Poly::var(&sym.names, k)), e.scaled(i64::from(a))));
        }
    }
    let qp = sym.poly_from_terms(&q);
    if qp.as_constant().is_none() {
        out.push((Base::Poly(qp), e.clone()));
    }
    Ok(out)
}

/// One hypergeometric term (see the module documentation for its value).
#[derive(Clone, Debug)]
pub struct Term {
    /// The rational coefficient.
    pub coef: RatFunc,
    /// Factorials `(arg)!^{+1}` (numerator) or `^{-1}` (denominator).
    pub facts: Vec<(Aff, i8)>,
    /// Powers with affine exponents.
    pub pows: Vec<(Base, Aff)>,
    /// The term is zero unless each is ≥ 0.
    pub support: Vec<Aff>,
    /// The term is zero unless each is 0.
    pub deltas: Vec<Aff>,
    /// Each must be ≥ 0 for the term to be defined (a divisor that may vanish otherwise).
    pub defined: Vec<Aff>,
    /// Each must be ≠ 0 (an affine divisor).
    pub nonzero: Vec<Aff>,
    /// The degree in the symbolic control polygon (0 or 1).
    pub bdeg: u8,
}

impl Term {
    /// The term `coef`.
    pub fn scalar(coef: RatFunc) -> Term {
        Term {
            coef,
            facts: Vec::new(),
            pows: Vec::new(),
            support: Vec::new(),
            deltas: Vec::new(),
            defined: Vec::new(),
            nonzero: Vec::new(),
            bdeg: 0,
        }
    }
    /// The product of two terms.
    pub fn times(&self, o: &Term) -> Result<Term> {
        if self.bdeg + o.bdeg > 1 {
            return Err(Error::Domain(
                "a product of symbolic control points: the claim is not affine in the control polygon".into(),
            ));
        }
        let mut out = self.clone();
        out.coef = out.coef.mul(&o.coef);
        out.facts.extend(o.facts.iter().cloned());
        out.pows.extend(o.pows.iter().cloned());
        out.support.extend(o.support.iter().cloned());
        out.deltas.extend(o.deltas.iter().cloned());
        out.defined.extend(o.defined.iter().cloned());
        out.nonzero.extend(o.nonzero.iter().cloned());
        out.bdeg += o.bdeg;
        Ok(out)
    }
    /// The term with `name` replaced by `by`.
    pub fn subst(&self, sym: &Symbols, name: &str, by: &Aff) -> Term {
        let s = |v: &Vec<Aff>| v.iter().map(|a| a.subst(name, by)).collect();
        Term {
            coef: sym.subst_rf(&self.coef, name, by),
            facts: self.facts.iter().map(|(a, e)| (a.subst(name, by), *e)).collect(),
            pows: self.pows.iter().map(|(b, a)| (b.clone(), a.subst(name, by))).collect(),
            support: s(&self.support),
            deltas: s(&self.deltas),
            defined: s(&self.defined),
            nonzero: s(&self.nonzero),
            bdeg: self.bdeg,
        }
    }
    /// Whether any part mentions the integer symbol `name`.
    pub fn mentions(&self, sym: &Symbols, name: &str) -> bool {
        let in_aff = |v: &[Aff]| v.iter().any(|a| a.coef(name) != 0);
        let k = sym.index(name);
        let in_poly = |p: &Poly| k.is_some_and(|k| p.terms_list().iter().any(|(e, _)| e[k] > 0));
        in_poly(&self.coef.num)
            || in_poly(&self.coef.den)
            || self.facts.iter().any(|(a, _)| a.coef(name) != 0)
            || self.pows.iter().any(|(_, a)| a.coef(name) != 0)
            || in_aff(&self.support)
            || in_aff(&self.deltas)
            || in_aff(&self.defined)
            || in_aff(&self.nonzero)
    }
    /// `1 / self`, defined only where `self` is nonzero: its zero conditions become
    /// conditions of definedness.
    /// The integer zeros of the coefficient become `nonzero` conditions (split off as pieces).
    pub fn recip(&self, sym: &Symbols) -> Result<Term> {
        if !self.deltas.is_empty() || self.bdeg > 0 {
            return Err(Error::Domain("division by a control point".into()));
        }
        let mut nonzero = self.nonzero.clone();
        for a in sym.integer_zeros(&self.coef.num)? {
            if !nonzero.contains(&a) {
                nonzero.push(a);
            }
        }
        let mut defined = self.support.clone();
        defined.extend(self.defined.iter().cloned());
        defined.extend(self.facts.iter().map(|(a, _)| a.clone()));
        Ok(Term {
            coef: RatFunc {
                num: self.coef.den.clone(),
                den: self.coef.num.clone(),
            },
            facts: self.facts.iter().map(|(a, e)| (a.clone(), -e)).collect(),
            pows: self.pows.iter().map(|(b, a)| (b.clone(), a.scaled(-1))).collect(),
            support: Vec::new(),
            deltas: Vec::new(),
            defined,
            nonzero,
            bdeg: 0,
        })
    }
    /// A short readable form.
    pub fn show(&self) -> String {
        let coef = self.coef.to_string();
        let mut parts = vec![if coef.contains(' ') { format!("({coef})") } else { coef }];
        for (a, e) in &self.facts {
            parts.push(if *e > 0 { format!("({a})!") } else { format!("1/({a})!") });
        }
        for (b, a) in &self.pows {
            parts.push(format!("{b}^({a})"));
        }
        for d in &self.deltas {
            parts.push(format!("[{d} = 0]"));
        }
        for s in &self.support {
            parts.push(format!("[{s} ≥ 0]"));
        }
        parts.join("·")
    }
}

/// A finite sum of terms.
pub type Lin = Vec<Term>;

/// `a · b` for sums of terms.
pub fn lin_mul(a: &[Term], b: &[Term]) -> Result<Lin> {
    let mut out = Vec::with_capacity(a.len() * b.len());
    for x in a {
        for y in b {
            out.push(x.times(y)?);
        }
    }
    if out.len() > 10_000 {
        return Err(Error::TooLarge {
            what: "symbolic expansion (terms)",
            value: out.len().to_string(),
            limit: "10000".into(),
        });
    }
    Ok(out)
}

/// `−a`.
pub fn lin_neg(a: &[Term]) -> Lin {
    a.iter()
        .map(|t| {
            let mut t = t.clone();
            t.coef = t.coef.neg();
            t
        })
        .collect()
}

/// `a` with `name` replaced by `by`.
pub fn lin_subst(sym: &Symbols, a: &[Term], name: &str, by: &Aff) -> Lin {
    a.iter().map(|t| t.subst(sym, name, by)).collect()
}

// ---------------------------------------------------------------------------------------
// Domains: integer points of {x : a(x) ≥ 0 for every constraint}.

/// A domain: the integer points where every constraint is ≥ 0.
#[derive(Clone, Debug, Default)]
pub struct Domain {
    /// The constraints `a ≥ 0`.
    pub cons: Vec<Aff>,
}

impl Domain {
    /// The domain with one more constraint.
    pub fn with(&self, c: Aff) -> Domain {
        let mut d = self.clone();
        d.cons.push(c);
        d
    }
    /// The domain with `name` replaced by `by`.
    pub fn subst(&self, name: &str, by: &Aff) -> Domain {
        Domain {
            cons: self.cons.iter().map(|c| c.subst(name, by)).collect(),
        }
    }
    /// Whether the domain may have an integer point (false: it certainly has none).
    pub fn feasible(&self) -> bool {
        feasible(&self.cons)
    }
    /// Whether `a ≥ 0` at every integer point of the domain (a proof when true).
    pub fn implies_ge(&self, a: &Aff) -> bool {
        !self.with(a.scaled(-1).shifted(-1)).feasible()
    }
    /// Readable form.
    pub fn show(&self) -> String {
        if self.cons.is_empty() {
            return "every integer point".into();
        }
        self.cons
            .iter()
            .map(|c| format!("{c} ≥ 0"))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

fn gcd(a: i128, b: i128) -> i128 {
    let (mut a, mut b) = (a.abs(), b.abs());
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// Normalises `a·x + c ≥ 0` over the integers: divides by the gcd of `a`, rounding `c` down.
fn tighten(mut a: Vec<i128>, c: i128) -> (Vec<i128>, i128) {
    let g = a.iter().fold(0, |g, &x| gcd(g, x));
    if g > 1 {
        for x in &mut a {
            *x /= g;
        }
        return (a, c.div_euclid(g));
    }
    (a, c)
}

/// Fourier–Motzkin: false only when the constraints have no rational (so no integer) solution.
fn feasible(cons: &[Aff]) -> bool {
    let vars: Vec<String> = cons
        .iter()
        .flat_map(|c| c.v.keys().cloned())
        .collect::<BTreeSet<_>>()
        .into_iter()
        .collect();
    let mut rows: BTreeSet<(Vec<i128>, i128)> = cons
        .iter()
        .map(|c| {
            let a: Vec<i128> = vars.iter().map(|v| i128::from(c.coef(v))).collect();
            tighten(a, i128::from(c.c))
        })
        .collect();
    for k in 0..vars.len() {
        let (mut pos, mut neg, mut keep) = (Vec::new(), Vec::new(), BTreeSet::new());
        for r in rows {
            match r.0[k].signum() {
                1 => pos.push(r),
                -1 => neg.push(r),
                _ => {
                    keep.insert(r);
                }
            }
        }
        if pos.len() * neg.len() + keep.len() > MAX_FM {
            return true;
        }
        for (pa, pc) in &pos {
            for (na, nc) in &neg {
                let (x, y) = (pa[k], -na[k]);
                // y·p + x·q, checked: on overflow the test answers "maybe feasible", which
                // only costs splits, never soundness.
                let combine = |p: i128, q: i128| y.checked_mul(p)?.checked_add(x.checked_mul(q)?);
                let a: Option<Vec<i128>> = pa.iter().zip(na).map(|(p, q)| combine(*p, *q)).collect();
                let (Some(a), Some(c)) = (a, combine(*pc, *nc)) else {
                    return true;
                };
                if a.iter().chain(std::iter::once(&c)).any(|v| v.abs() > (1i128 << 100)) {
                    return true;
                }
                keep.insert(tighten(a, c));
            }
        }
        rows = keep;
    }
    rows.iter().all(|(_, c)| *c >= 0)
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Class {
    Always,
    Never,
    Mixed,
}

/// Whether the term `t`, which is defined only where `a ≥ 0`, is defined on all of `d`: an
/// error where it never is, a split where it is on part of `d`, `None` where it always is.
fn defined_split(d: &Domain, t: &Term, a: &Aff) -> Result<Option<Split>> {
    match class_ge(d, a) {
        Class::Never => Err(Error::Domain(format!(
            "the term {} is undefined where {a} < 0 (on {})",
            t.show(),
            d.show()
        ))),
        Class::Mixed => Ok(Some(Split::Ge(a.clone()))),
        Class::Always => Ok(None),
    }
}

fn class_ge(d: &Domain, a: &Aff) -> Class {
    if d.implies_ge(a) {
        Class::Always
    } else if !d.with(a.clone()).feasible() {
        Class::Never
    } else {
        Class::Mixed
    }
}

fn class_eq(d: &Domain, a: &Aff) -> Class {
    if a.is_const() {
        return if a.c == 0 { Class::Always } else { Class::Never };
    }
    if !d.with(a.clone()).with(a.scaled(-1)).feasible() {
        Class::Never
    } else if d.implies_ge(a) && d.implies_ge(&a.scaled(-1)) {
        Class::Always
    } else {
        Class::Mixed
    }
}

/// How `a = 0` is substituted: a variable with coefficient ±1 and its value.
fn solve_for(a: &Aff) -> Result<(String, Aff)> {
    let (name, k) =
        a.v.iter()
            .find(|(_, k)| k.abs() == 1)
            .map(|(n, k)| (n.clone(), *k))
            .ok_or_else(|| {
                Error::Domain(format!(
                    "cannot split the domain on {a} = 0: no variable has coefficient ±1"
                ))
            })?;
    let mut rest = a.clone();
    rest.v.remove(&name);
    // k·x + rest = 0 ⇒ x = −rest / k, with k = ±1.
    Ok((name, rest.scaled(-k)))
}

/// What [`prove_zero`] found.
#[derive(Clone, Debug)]
pub enum ZeroOutcome {
    /// Zero at every integer point of the domain; the number of pieces checked.
    Zero(usize),
    /// In this piece the quotient by the first live term is a nonzero rational function.
    NonZero {
        /// The piece.
        region: String,
        /// The nonzero numerator.
        residue: String,
    },
}

enum Split {
    Ge(Aff),
    Eq(Aff),
}

fn pick_split(lin: &[Term], d: &Domain, alive: &mut [bool]) -> Result<Option<Split>> {
    // What every term needs to be defined at all (a divisor that must not vanish).
    for t in lin {
        for a in &t.defined {
            if let Some(split) = defined_split(d, t, a)? {
                return Ok(Some(split));
            }
        }
    }
    // First the conditions that make a term vanish.
    for (t, live) in lin.iter().zip(alive.iter_mut()) {
        let zeroing = t
            .support
            .iter()
            .chain(t.facts.iter().filter(|(_, e)| *e < 0).map(|(a, _)| a));
        for a in zeroing {
            match class_ge(d, a) {
                Class::Never => *live = false,
                Class::Mixed => return Ok(Some(Split::Ge(a.clone()))),
                Class::Always => {}
            }
            if !*live {
                break;
            }
        }
        if !*live {
            continue;
        }
        for a in &t.deltas {
            match class_eq(d, a) {
                Class::Never => {
                    *live = false;
                    break;
                }
                Class::Mixed => return Ok(Some(Split::Eq(a.clone()))),
                Class::Always => {}
            }
        }
    }
    // Then, for the live terms, that their numerator factorials are defined.
    for (t, live) in lin.iter().zip(alive.iter()) {
        if !*live {
            continue;
        }
        for a in t.facts.iter().filter(|(_, e)| *e > 0).map(|(a, _)| a) {
            if let Some(split) = defined_split(d, t, a)? {
                return Ok(Some(split));
            }
        }
    }
    for t in lin {
        for a in &t.nonzero {
            match class_eq(d, a) {
                Class::Never => {}
                Class::Always => {
                    return Err(Error::DivisionByZero(format!(
                        "a division by {a}, which is 0 on {}",
                        d.show()
                    )))
                }
                Class::Mixed => return Ok(Some(Split::Eq(a.clone()))),
            }
        }
    }
    Ok(None)
}

/// Proves `Σ lin = 0` at every integer point of `d` (see the module documentation), logging
/// each piece to `log`.
pub fn prove_zero(sym: &Symbols, lin: &[Term], d: &Domain, log: &mut Vec<String>) -> Result<ZeroOutcome> {
    let mut check =
        |live: &[&Term], _: &Domain, place: &str, log: &mut Vec<String>| classes_cancel(sym, live, place, log);
    prove_pieces(sym, lin, d, log, &mut check)
}

/// What a piece must satisfy: given its live terms (every condition decided, every factorial
/// argument ≥ 0), the piece and its description, `None` when it does, else the reason.
pub type PieceCheck<'a> = dyn FnMut(&[&Term], &Domain, &str, &mut Vec<String>) -> Result<Option<String>> + 'a;

/// Splits `d` into pieces on which every term of `lin` is decided, and runs `check` on each.
pub fn prove_pieces(
    sym: &Symbols,
    lin: &[Term],
    d: &Domain,
    log: &mut Vec<String>,
    check: &mut PieceCheck<'_>,
) -> Result<ZeroOutcome> {
    let mut count = 0usize;
    let out = prove_rec(sym, lin.to_vec(), d.clone(), Vec::new(), log, &mut count, check)?;
    Ok(match out {
        None => ZeroOutcome::Zero(count),
        Some((region, residue)) => ZeroOutcome::NonZero { region, residue },
    })
}

type Found = Option<(String, String)>;

fn prove_rec(
    sym: &Symbols,
    lin: Lin,
    d: Domain,
    path: Vec<String>,
    log: &mut Vec<String>,
    count: &mut usize,
    check: &mut PieceCheck<'_>,
) -> Result<Found> {
    if !d.feasible() {
        return Ok(None);
    }
    *count += 1;
    if *count > MAX_REGIONS {
        return Err(Error::TooLarge {
            what: "domain pieces of a symbolic proof",
            value: count.to_string(),
            limit: MAX_REGIONS.to_string(),
        });
    }
    let mut alive = vec![true; lin.len()];
    match pick_split(&lin, &d, &mut alive)? {
        Some(Split::Ge(a)) => {
            for piece in [a.clone(), a.scaled(-1).shifted(-1)] {
                let mut p = path.clone();
                p.push(format!("{piece} ≥ 0"));
                if let Some(found) = prove_rec(sym, lin.clone(), d.with(piece), p, log, count, check)? {
                    return Ok(Some(found));
                }
            }
            Ok(None)
        }
        Some(Split::Eq(a)) => {
            for piece in [a.shifted(-1), a.scaled(-1).shifted(-1)] {
                let mut p = path.clone();
                p.push(format!("{piece} ≥ 0"));
                if let Some(found) = prove_rec(sym, lin.clone(), d.with(piece), p, log, count, check)? {
                    return Ok(Some(found));
                }
            }
            let (x, by) = solve_for(&a)?;
            let mut p = path;
            p.push(format!("{x} = {by}"));
            let sub = lin_subst(sym, &lin, &x, &by);
            prove_rec(sym, sub, d.subst(&x, &by), p, log, count, check)
        }
        None => {
            // A piece that is thinner than it looks (i ≥ 0 and −i ≥ 0): substitute the
            // equality, so the rational identity is asked only where it must hold.
            let flat = d
                .cons
                .iter()
                .find(|c| !c.is_const() && d.implies_ge(&c.scaled(-1)) && c.v.values().any(|k| k.abs() == 1));
            if let Some(c) = flat {
                let (x, by) = solve_for(c)?;
                let mut p = path;
                p.push(format!("{x} = {by}"));
                let sub = lin_subst(sym, &lin, &x, &by);
                return prove_rec(sym, sub, d.subst(&x, &by), p, log, count, check);
            }
            if let Some(t) = lin.iter().zip(&alive).find(|(t, a)| **a && t.coef.den.is_zero()) {
                return Err(Error::DivisionByZero(format!(
                    "the term {} has the denominator 0 on {}",
                    t.0.show(),
                    d.show()
                )));
            }
            let live: Vec<&Term> = lin
                .iter()
                .zip(&alive)
                .filter(|(t, a)| **a && !t.coef.num.is_zero())
                .map(|(t, _)| t)
                .collect();
            let place = if path.is_empty() {
                d.show()
            } else {
                format!("{} (piece {})", d.show(), path.join(", "))
            };
            if live.is_empty() {
                log.push(format!("on {place}: every term vanishes"));
                return Ok(None);
            }
            Ok(check(&live, &d, &place, log)?.map(|why| (place, why)))
        }
    }
}

/// The live terms of a piece sum to zero: each class of similar terms (rational quotients)
/// cancels on its own (enough for the sum to vanish; a class that does not cancel is
/// reported, never taken as a disproof).
fn classes_cancel(sym: &Symbols, live: &[&Term], place: &str, log: &mut Vec<String>) -> Result<Option<String>> {
    let mut classes: Vec<(&Term, RatFunc, usize)> = Vec::new();
    for t in live {
        let mut placed = false;
        for (first, total, size) in classes.iter_mut() {
            if let Some(r) = ratio(sym, t, first)? {
                *total = total.add(&t.coef.mul(&r));
                *size += 1;
                placed = true;
                break;
            }
        }
        if !placed {
            classes.push((t, t.coef.clone(), 1));
        }
    }
    for (first, total, size) in &classes {
        if !total.num.is_zero() {
            return Ok(Some(format!(
                "the quotient's numerator is {} (the {size} terms similar to {})",
                total.num,
                first.show()
            )));
        }
    }
    log.push(format!(
        "on {place}: {} live term{} in {} class{} of similar terms, each Σ T_j / T_0 = 0 identically",
        live.len(),
        if live.len() == 1 { "" } else { "s" },
        classes.len(),
        if classes.len() == 1 { "" } else { "es" },
    ));
    Ok(None)
}

/// The factorials of `H_t / H_0` grouped by linear part: for each, the constants of the
/// factorials upstairs (from `t`) and downstairs (from `first`).
type FactorialGroups = BTreeMap<BTreeMap<String, i64>, (Vec<i64>, Vec<i64>)>;

fn factorial_groups(t: &Term, first: &Term) -> FactorialGroups {
    let mut groups = FactorialGroups::new();
    let both = t
        .facts
        .iter()
        .map(|(a, e)| (a, *e))
        .chain(first.facts.iter().map(|(a, e)| (a, -*e)));
    for (a, e) in both {
        let g = groups.entry(a.linear()).or_default();
        if e > 0 {
            g.0.push(a.c);
        } else {
            g.1.push(a.c);
        }
    }
    groups
}

/// `H_t / H_0` (the factorial and power parts; the coefficients are not included), a rational
/// function valid where every factorial argument is ≥ 0; `None` when the terms are not similar.
pub fn ratio(sym: &Symbols, t: &Term, first: &Term) -> Result<Option<RatFunc>> {
    let mut out = RatFunc::from_int(1);
    let groups = factorial_groups(t, first);
    for (lin, (mut up, mut down)) in groups {
        if lin.is_empty() {
            for c in up {
                out = out.mul(&factorial(c)?);
            }
            for c in down {
                out = out.div(&factorial(c)?)?;
            }
            continue;
        }
        if up.len() != down.len() {
            // The factorials of this linear part do not pair: not a rational quotient.
            return Ok(None);
        }
        up.sort_unstable();
        down.sort_unstable();
        let l = Aff { c: 0, v: lin };
        for (p, q) in up.into_iter().zip(down) {
            // (L+p)! / (L+q)!
            let (lo, hi, inv) = if p >= q { (q, p, false) } else { (p, q, true) };
            let mut prod = RatFunc::from_int(1);
            for m in lo + 1..=hi {
                prod = prod.mul(&l.shifted(m).to_rf(sym));
            }
            out = if inv { out.div(&prod)? } else { out.mul(&prod) };
        }
    }
    // Powers: exponents per base must differ by constants.
    let mut bases: Vec<(Base, Aff)> = Vec::new();
    let mut add = |b: &Base, e: Aff| {
        if let Some(slot) = bases.iter_mut().find(|(x, _)| x == b) {
            slot.1 = slot.1.plus(&e);
        } else {
            bases.push((b.clone(), e));
        }
    };
    for (b, e) in &t.pows {
        add(b, e.clone());
    }
    for (b, e) in &first.pows {
        add(b, e.scaled(-1));
    }
    for (b, e) in bases {
        if !e.is_const() {
            return Ok(None);
        }
        out = out.mul(&b.to_rf().pow(e.c)?);
    }
    Ok(Some(out))
}

/// The factors of the denominator of `H_t / H_0`: affine forms (from factorials) and
/// polynomials in the parameters (from powers with negative exponent differences).
pub fn ratio_denominator(t: &Term, first: &Term) -> (Vec<Aff>, Vec<Poly>) {
    let groups = factorial_groups(t, first);
    let mut affs = Vec::new();
    for (lin, (mut up, mut down)) in groups {
        if lin.is_empty() || up.len() != down.len() {
            continue;
        }
        up.sort_unstable();
        down.sort_unstable();
        let l = Aff { c: 0, v: lin };
        for (p, q) in up.into_iter().zip(down) {
            for m in p + 1..=q {
                affs.push(l.shifted(m));
            }
        }
    }
    let mut polys = Vec::new();
    let mut bases: Vec<(Base, Aff)> = Vec::new();
    for (b, e) in t
        .pows
        .iter()
        .map(|(b, e)| (b, e.clone()))
        .chain(first.pows.iter().map(|(b, e)| (b, e.scaled(-1))))
    {
        if let Some(slot) = bases.iter_mut().find(|(x, _)| x == b) {
            slot.1 = slot.1.plus(&e);
        } else {
            bases.push((b.clone(), e));
        }
    }
    for (b, e) in bases {
        if let (Base::Poly(q), true) = (&b, e.is_const() && e.c < 0) {
            for _ in 0..e.c.unsigned_abs() {
                polys.push(q.clone());
            }
        }
    }
    (affs, polys)
}

fn factorial(c: i64) -> Result<RatFunc> {
    if !(0..=super::expr::MAX_FACTORIAL).contains(&c) {
        return Err(Error::Domain(format!("factorial of {c}")));
    }
    let mut f = num_bigint::BigInt::one();
    for k in 2..=c {
        f *= k;
    }
    Ok(RatFunc::from_bigint(&f))
}

/// Whether a rational constant is ≥ 0 (for callers that classify coefficients).
pub fn nonneg(r: &BigRational) -> bool {
    !r.is_negative()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fourier_motzkin_decides_simple_domains() {
        let n = Aff::var("n");
        let i = Aff::var("i");
        // 0 ≤ i ≤ n and i ≥ n + 1: empty.
        let d = Domain {
            cons: vec![i.clone(), n.minus(&i), i.minus(&n).shifted(-1)],
        };
        assert!(!d.feasible());
        let d = Domain {
            cons: vec![i.clone(), n.minus(&i)],
        };
        assert!(d.feasible());
        assert!(d.implies_ge(&n));
        assert!(!d.implies_ge(&n.shifted(-1)));
        // 2i = 1 has no integer solution: 2i − 1 ≥ 0 and 1 − 2i ≥ 0 tighten to i ≥ 1, i ≤ 0.
        let d = Domain {
            cons: vec![i.scaled(2).shifted(-1), i.scaled(-2).shifted(1)],
        };
        assert!(!d.feasible());
    }

    #[test]
    fn a_divisor_registers_its_integer_zeros() {
        let sym = Symbols::new(&["n".into(), "m".into()], &["t".into()]);
        let v = |x: &str| sym.var(x);
        let c = |k: i64| RatFunc::from_int(k);
        let zeros = |r: RatFunc| {
            sym.integer_zeros(&r.num)
                .map(|z| z.iter().map(|a| a.to_string()).collect::<Vec<_>>())
        };
        // n (n − 1) t + n (n − 1): zero polynomial in t exactly at n = 0 and n = 1.
        let p = v("n").mul(&v("n").sub(&c(1))).mul(&v("t").add(&c(1)));
        assert_eq!(zeros(p).unwrap(), ["n", "n - 1"]);
        // (2n − 4) t: at n = 2; (n² + 1) t and (2n − 1) t: at no integer.
        assert_eq!(zeros(v("n").mul(&c(2)).sub(&c(4)).mul(&v("t"))).unwrap(), ["2n - 4"]);
        assert!(zeros(v("n").mul(&v("n")).add(&c(1)).mul(&v("t"))).unwrap().is_empty());
        assert!(zeros(v("n").mul(&c(2)).sub(&c(1)).mul(&v("t"))).unwrap().is_empty());
        // n t + m: zero only where n = m = 0 — one of its coefficients is constant-free, the
        // other (m) is affine: m ≠ 0 suffices.
        assert_eq!(zeros(v("n").mul(&v("t")).add(&v("m"))).unwrap(), ["m"]);
        // n m + 1 has no affine description that this finds: refused, never ignored.
        assert!(zeros(v("n").mul(&v("m")).add(&c(1)).mul(&v("t"))).is_err());
        assert!(zeros(c(0)).is_err());
    }
}
