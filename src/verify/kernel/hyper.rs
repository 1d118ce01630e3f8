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
//! [`super::pieces::prove_zero`] decides `Σ_j T_j = 0` on every integer point of a domain `{x : A x + c ≥ 0}`:
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
use std::collections::BTreeMap;
use std::fmt;
use std::rc::Rc;

/// Most pieces one proof may split its domain into.
pub const MAX_REGIONS: usize = 20_000;

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
    /// The claim's work budget, shared by every search of the proof (clones share it).
    pub budget: Rc<super::budget::Budget>,
}

impl Symbols {
    /// Builds the list (and makes it the one rational constants are built over).
    pub fn new(ints: &[String], conts: &[String]) -> Symbols {
        let names: Vec<String> = ints.iter().chain(conts).cloned().collect();
        let names: Rc<[String]> = Rc::from(names);
        Symbols {
            names,
            ints: ints.len(),
            budget: Rc::default(),
        }
    }
    /// The index of a name.
    pub fn index(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n == name)
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
        p.terms_in(self.names.len())
            .iter()
            .any(|(e, _)| e[..self.ints].iter().any(|&x| x > 0))
    }
    /// Whether a polynomial mentions a continuous parameter.
    pub fn poly_has_conts(&self, p: &Poly) -> bool {
        p.terms_in(self.names.len())
            .iter()
            .any(|(e, _)| e[self.ints..].iter().any(|&x| x > 0))
    }
    /// A polynomial of degree ≤ 1 in the integer symbols with integer coefficients and no
    /// continuous parameter, as an affine form.
    pub fn poly_to_aff(&self, p: &Poly) -> Option<Aff> {
        let mut out = Aff::constant(0);
        for (e, c) in p.terms_in(self.names.len()) {
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
        for (mut e, c) in p.terms_in(self.names.len()) {
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
        let l = p
            .terms_in(self.names.len())
            .iter()
            .fold(BigInt::one(), |l, (_, c)| l.lcm(c.denom()));
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
                .filter(|&k| c.terms_in(self.names.len()).iter().any(|(e, _)| e[k] > 0))
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
            let (_, c0) = ic
                .terms_in(self.names.len())
                .into_iter()
                .find(|(e, _)| e.iter().all(|&x| x == 0))?;
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
        let terms = p.terms_in(self.names.len());
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
    pub(crate) fn to_rf(&self) -> RatFunc {
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
    let terms = p.terms_in(sym.names.len());
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
        let in_poly = |p: &Poly| k.is_some_and(|k| p.terms_in(sym.names.len()).iter().any(|(e, _)| e[k] > 0));
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
