//! Evaluation of expressions in any "algebra": exact numbers (to check a claim at a point),
//! degree bounds (to know how many points make a proof), and symbolic polynomials.
//!
//! One evaluator, generic over [`Alg`], walks the tree; what a claim object (`b(t)`, `b[j]`,
//! `x(u, v)`) means is supplied by an [`Env`]. Because the degree bounds are computed by the
//! very same walk as the values, every construct that has a value also has a bound, and the
//! bound describes the formal numerator/denominator the walk builds (see [`Deg`]).

pub use super::alg::{Alg, Deg};
use super::expr::{check_index, eval_int, Expr, Op, MAX_SUM_TERMS};
use crate::bernstein::binomial_signed;
use crate::error::{Error, Result};
use crate::linalg::{self, dot};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::collections::BTreeMap;
use std::fmt;

/// A value: a scalar, a vector (tuple, point) or a matrix.
#[derive(Clone, Debug)]
pub enum Value<A> {
    /// A number.
    S(A),
    /// A vector.
    V(Vec<A>),
    /// A matrix, by rows.
    M(Vec<Vec<A>>),
}

impl<A: Alg> fmt::Display for Value<A> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let list = |v: &[A]| v.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", ");
        match self {
            Value::S(a) => write!(f, "{a}"),
            Value::V(v) => write!(f, "({})", list(v)),
            Value::M(m) => write!(f, "[{}]", m.iter().map(|r| list(r)).collect::<Vec<_>>().join("; ")),
        }
    }
}

impl<A: Alg> Value<A> {
    /// The entries, flattened.
    pub fn entries(&self) -> Vec<&A> {
        match self {
            Value::S(a) => vec![a],
            Value::V(v) => v.iter().collect(),
            Value::M(m) => m.iter().flatten().collect(),
        }
    }
    /// The entries of two sides of an equation, paired; sides of different sizes (a number
    /// against a vector, vectors of different lengths) are an error.
    pub fn paired_entries<'v>(&'v self, other: &'v Value<A>) -> Result<Vec<(&'v A, &'v A)>> {
        let (l, r) = (self.entries(), other.entries());
        if l.len() != r.len() {
            return Err(Error::Domain(format!(
                "the two sides have different shapes ({} and {})",
                self.shape(),
                other.shape()
            )));
        }
        Ok(l.into_iter().zip(r).collect())
    }
    /// A description of the shape, for error messages.
    pub fn shape(&self) -> String {
        match self {
            Value::S(_) => "a number".into(),
            Value::V(v) => format!("a vector of {}", v.len()),
            Value::M(m) => format!("a {}×{} matrix", m.len(), m.first().map_or(0, Vec::len)),
        }
    }
    /// The scalar, or an error naming `what`.
    pub fn scalar(self, what: &str) -> Result<A> {
        match self {
            Value::S(a) => Ok(a),
            other => Err(Error::Domain(format!("{what} must be a number, not {}", other.shape()))),
        }
    }
    fn same_shape(&self, o: &Value<A>) -> bool {
        match (self, o) {
            (Value::S(_), Value::S(_)) => true,
            (Value::V(a), Value::V(b)) => a.len() == b.len(),
            (Value::M(a), Value::M(b)) => a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.len() == y.len()),
            _ => false,
        }
    }
    fn map(&self, f: impl Fn(&A) -> A) -> Value<A> {
        match self {
            Value::S(a) => Value::S(f(a)),
            Value::V(v) => Value::V(v.iter().map(f).collect()),
            Value::M(m) => Value::M(m.iter().map(|r| r.iter().map(&f).collect()).collect()),
        }
    }
    fn zip(&self, o: &Value<A>, what: &str, f: impl Fn(&A, &A) -> A) -> Result<Value<A>> {
        if !self.same_shape(o) {
            return Err(Error::Domain(format!(
                "cannot {what} {} and {}",
                self.shape(),
                o.shape()
            )));
        }
        Ok(match (self, o) {
            (Value::S(a), Value::S(b)) => Value::S(f(a, b)),
            (Value::V(a), Value::V(b)) => Value::V(a.iter().zip(b).map(|(x, y)| f(x, y)).collect()),
            (Value::M(a), Value::M(b)) => Value::M(
                a.iter()
                    .zip(b)
                    .map(|(r, s)| r.iter().zip(s).map(|(x, y)| f(x, y)).collect())
                    .collect(),
            ),
            _ => unreachable!("shapes checked above"),
        })
    }
    /// `self + o`
    pub fn add(&self, o: &Value<A>) -> Result<Value<A>> {
        self.zip(o, "add", A::add_ref)
    }
    /// `self - o`
    pub fn sub(&self, o: &Value<A>) -> Result<Value<A>> {
        self.zip(o, "subtract", A::sub_ref)
    }
    /// `-self`
    pub fn neg(&self) -> Value<A> {
        self.map(A::neg_ref)
    }
    /// Products: scalar × anything, matrix × vector, matrix × matrix.
    pub fn mul(&self, o: &Value<A>) -> Result<Value<A>> {
        Ok(match (self, o) {
            (Value::S(a), x) => x.map(|y| a.mul_ref(y)),
            (x, Value::S(b)) => x.map(|y| y.mul_ref(b)),
            (Value::M(m), Value::V(v)) => {
                if m.first().map_or(0, Vec::len) != v.len() {
                    return Err(Error::Domain(format!(
                        "cannot multiply {} by {}",
                        self.shape(),
                        o.shape()
                    )));
                }
                Value::V(m.iter().map(|r| dot(r, v)).collect())
            }
            (Value::M(a), Value::M(b)) => {
                let inner = a.first().map_or(0, Vec::len);
                if inner != b.len() {
                    return Err(Error::Domain(format!(
                        "cannot multiply {} by {}",
                        self.shape(),
                        o.shape()
                    )));
                }
                let cols = b.first().map_or(0, Vec::len);
                Value::M(
                    a.iter()
                        .map(|r| {
                            (0..cols)
                                .map(|j| dot(r, &b.iter().map(|row| row[j].clone()).collect::<Vec<_>>()))
                                .collect()
                        })
                        .collect(),
                )
            }
            _ => {
                return Err(Error::Domain(format!(
                    "cannot multiply {} by {} (use dot(a, b) for the dot product)",
                    self.shape(),
                    o.shape()
                )))
            }
        })
    }
    /// `self / s` for a scalar `s`.
    pub fn div(&self, o: &Value<A>) -> Result<Value<A>> {
        let Value::S(s) = o else {
            return Err(Error::Domain(format!("cannot divide by {}", o.shape())));
        };
        Ok(match self {
            Value::S(a) => Value::S(a.div(s)?),
            Value::V(v) => Value::V(v.iter().map(|x| x.div(s)).collect::<Result<_>>()?),
            Value::M(m) => Value::M(
                m.iter()
                    .map(|r| r.iter().map(|x| x.div(s)).collect::<Result<Vec<_>>>())
                    .collect::<Result<_>>()?,
            ),
        })
    }
    /// Exact equality, entry by entry (`None` when the algebra has none).
    pub fn equals(&self, o: &Value<A>) -> Option<bool> {
        if !self.same_shape(o) {
            return Some(false);
        }
        let mut all = true;
        for (a, b) in self.entries().into_iter().zip(o.entries()) {
            all &= a.equals(b)?;
        }
        Some(all)
    }
}

/// Largest matrix `det` and `inv` accept: Berkowitz's algorithm takes O(n⁴) products, so a
/// 16 × 16 matrix costs about 65,000 per evaluation.
pub const MAX_MATRIX: usize = 16;

/// What the names of a claim mean in one algebra.
pub trait Env<A: Alg> {
    /// A variable's value (`None`: unknown).
    fn var(&self, name: &str) -> Option<Value<A>>;
    /// A call of a claim object, `b(t)`, `b(i, r, t)`, `b'(t)`, `x(u, v)`; `None`: unknown name.
    fn call(&self, name: &str, args: &[Expr], ev: &mut Evaluator<'_, A>) -> Result<Option<Value<A>>>;
    /// A control point `b[j]` (`None`: unknown name). Out-of-range indices are zero.
    fn index(&self, name: &str, idx: &[i64]) -> Result<Option<Value<A>>>;
}

/// An environment with plain variables only.
pub struct VarEnv<A>(pub BTreeMap<String, Value<A>>);

impl<A: Alg> Env<A> for VarEnv<A> {
    fn var(&self, name: &str) -> Option<Value<A>> {
        self.0.get(name).cloned()
    }
    fn call(&self, _: &str, _: &[Expr], _: &mut Evaluator<'_, A>) -> Result<Option<Value<A>>> {
        Ok(None)
    }
    fn index(&self, _: &str, _: &[i64]) -> Result<Option<Value<A>>> {
        Ok(None)
    }
}

/// Walks an expression in one algebra.
pub struct Evaluator<'e, A: Alg> {
    /// Bound integer variables (ranges of the claim, summation variables).
    pub ints: BTreeMap<String, i64>,
    env: &'e dyn Env<A>,
    terms: i64,
}

impl<'e, A: Alg> Evaluator<'e, A> {
    /// An evaluator over `env` with the integer variables `ints`.
    pub fn new(env: &'e dyn Env<A>, ints: BTreeMap<String, i64>) -> Self {
        Evaluator { ints, env, terms: 0 }
    }

    /// An integer sub-expression (index, exponent, range bound).
    pub fn int(&self, e: &Expr) -> Result<i64> {
        eval_int(e, &self.ints)
    }

    /// A scalar sub-expression.
    pub fn scalar(&mut self, e: &Expr) -> Result<A> {
        match self.eval(e)? {
            Value::S(a) => Ok(a),
            // The message names the expression; formatting it only here keeps it off the
            // hot path (a scalar is asked for at every call argument of every evaluation).
            other => other.scalar(&format!("'{e}'")),
        }
    }

    /// Evaluates `e`.
    pub fn eval(&mut self, e: &Expr) -> Result<Value<A>> {
        Ok(match e {
            Expr::Num(r) => Value::S(A::from_rat(r)),
            Expr::Var(v) => {
                if let Some(&n) = self.ints.get(v) {
                    Value::S(A::from_int(n))
                } else if let Some(x) = self.env.var(v) {
                    x
                } else {
                    return Err(Error::Domain(format!("unknown variable '{v}'")));
                }
            }
            Expr::Neg(a) => self.eval(a)?.neg(),
            Expr::Bin(Op::Pow, a, k) => {
                let k = self.int(k).map_err(|err| {
                    Error::Domain(format!("in '{e}': the exponent must be an integer expression ({err})"))
                })?;
                Value::S(self.scalar(a)?.pow(k)?)
            }
            Expr::Bin(op, a, b) => {
                let (x, y) = (self.eval(a)?, self.eval(b)?);
                match op {
                    Op::Add => x.add(&y)?,
                    Op::Sub => x.sub(&y)?,
                    Op::Mul => x.mul(&y)?,
                    Op::Div => x.div(&y).map_err(|err| match err {
                        Error::DivisionByZero(_) => Error::DivisionByZero(format!("'{e}'")),
                        other => other,
                    })?,
                    Op::Pow => unreachable!("handled above"),
                }
            }
            Expr::Fact(_) => Value::S(A::from_int(self.int(e)?)),
            Expr::Tuple(items) => Value::V(items.iter().map(|x| self.scalar(x)).collect::<Result<_>>()?),
            Expr::Matrix(rows) => Value::M(
                rows.iter()
                    .map(|r| r.iter().map(|x| self.scalar(x)).collect::<Result<Vec<_>>>())
                    .collect::<Result<_>>()?,
            ),
            Expr::Sum(v, from, to, body) => {
                let (a, b) = (self.int(from)?, self.int(to)?);
                let mut acc: Option<Value<A>> = None;
                let saved = self.ints.get(v).copied();
                if b >= a {
                    self.terms = self.terms.saturating_add(b.saturating_sub(a).saturating_add(1));
                    if self.terms > MAX_SUM_TERMS {
                        return Err(Error::TooLarge {
                            what: "number of summed terms",
                            value: self.terms.to_string(),
                            limit: MAX_SUM_TERMS.to_string(),
                        });
                    }
                }
                let mut r = a;
                while r <= b {
                    // Rebinding in place: no new key (a String) per term.
                    match self.ints.get_mut(v) {
                        Some(slot) => *slot = r,
                        None => {
                            self.ints.insert(v.clone(), r);
                        }
                    }
                    let term = self.eval(body);
                    let term = match term {
                        Ok(t) => t,
                        Err(err) => {
                            restore(&mut self.ints, v, saved);
                            return Err(err);
                        }
                    };
                    acc = Some(match acc {
                        None => term,
                        Some(s) => s.add(&term)?,
                    });
                    r += 1;
                }
                restore(&mut self.ints, v, saved);
                // An empty sum is the number 0 (there is no term to take a shape from).
                acc.unwrap_or(Value::S(A::from_int(0)))
            }
            Expr::Index(name, args) => {
                let idx = args.iter().map(|a| self.int(a)).collect::<Result<Vec<_>>>()?;
                self.env
                    .index(name, &idx)?
                    .ok_or_else(|| Error::Domain(format!("'{name}' is not a control polygon or net")))?
            }
            Expr::Call(name, args) => self.call(e, name, args)?,
        })
    }

    fn call(&mut self, e: &Expr, name: &str, args: &[Expr]) -> Result<Value<A>> {
        Ok(match name {
            "B" => {
                let (i, n) = (self.int(&args[0])?, self.int(&args[1])?);
                check_index(n)?;
                check_index(i)?;
                let g = self.scalar(&args[2])?;
                Value::S(bernstein(i, n, &g)?)
            }
            "__dB" => {
                let (i, n, k) = (self.int(&args[0])?, self.int(&args[1])?, self.int(&args[3])?);
                check_index(n)?;
                check_index(i)?;
                check_index(k)?;
                let g = self.scalar(&args[2])?;
                Value::S(bernstein_derivative(i, n, &g, k)?)
            }
            "__dpow" => {
                let (e, k) = (self.int(&args[1])?, self.int(&args[2])?);
                check_index(e)?;
                check_index(k)?;
                let g = self.scalar(&args[0])?;
                Value::S(power_derivative(&g, e, k)?)
            }
            "C" | "binom" => Value::S(A::from_int(self.int(e)?)),
            "sqrt" => {
                // The argument must be a constant: evaluate it exactly, with no variables.
                let env = VarEnv::<BigRational>(BTreeMap::new());
                let mut ev = Evaluator::new(&env, self.ints.clone());
                let r = ev.scalar(&args[0]).map_err(|err| {
                    Error::Domain(format!("sqrt needs a constant rational argument in '{e}' ({err})"))
                })?;
                Value::S(A::sqrt_rat(&r)?)
            }
            "dot" => {
                let (a, b) = (self.eval(&args[0])?, self.eval(&args[1])?);
                match (&a, &b) {
                    (Value::V(x), Value::V(y)) if x.len() == y.len() => Value::S(dot(x, y)),
                    (Value::S(x), Value::S(y)) => Value::S(x.mul_ref(y)),
                    _ => return Err(Error::Domain(format!("dot of {} and {}", a.shape(), b.shape()))),
                }
            }
            "rows" | "cols" => {
                let vs = args
                    .iter()
                    .map(|a| match self.eval(a)? {
                        Value::V(v) => Ok(v),
                        Value::S(s) => Ok(vec![s]),
                        other => Err(Error::Domain(format!("{name} takes vectors, not {}", other.shape()))),
                    })
                    .collect::<Result<Vec<_>>>()?;
                if vs.iter().any(|v| v.len() != vs[0].len()) {
                    return Err(Error::Domain(format!("{name} of vectors of different lengths")));
                }
                let m = Value::M(vs);
                if name == "cols" {
                    transpose(m)?
                } else {
                    m
                }
            }
            "transpose" => transpose(self.eval(&args[0])?)?,
            "comp" => {
                let k = self.int(&args[1])?;
                let v = self.eval(&args[0])?;
                let entries = v.entries();
                let x = usize::try_from(k - 1)
                    .ok()
                    .and_then(|i| entries.get(i))
                    .ok_or_else(|| Error::Domain(format!("'{e}': {} has no coordinate {k}", v.shape())))?;
                Value::S((*x).clone())
            }
            "integral" => Value::S(integral(self, e, args)?),
            "det" | "inv" => {
                let m = match self.eval(&args[0])? {
                    Value::M(m) if m.len() == m[0].len() && m.len() <= MAX_MATRIX => m,
                    other => {
                        return Err(Error::Domain(format!(
                            "{name} needs a square matrix of size at most {MAX_MATRIX}, not {}",
                            other.shape()
                        )))
                    }
                };
                let d = linalg::determinant_division_free(&m);
                if name == "det" {
                    Value::S(d)
                } else {
                    inverse(&m, &d).map_err(|err| match err {
                        Error::DivisionByZero(_) => Error::Singular(format!("'{e}' is not invertible")),
                        other => other,
                    })?
                }
            }
            "delta" => {
                let Expr::Var(poly) = &args[0] else {
                    return Err(Error::Domain(format!("delta needs a polygon name first, in '{e}'")));
                };
                let (k, j) = (self.int(&args[1])?, self.int(&args[2])?);
                check_index(k)?;
                if k < 0 {
                    return Err(Error::Domain(format!("negative difference order in '{e}'")));
                }
                // Δ^k b_j = Σ_i (-1)^(k-i) C(k,i) b_(j+i)
                let mut acc: Option<Value<A>> = None;
                for i in 0..=k {
                    let p = self
                        .env
                        .index(poly, &[j + i])?
                        .ok_or_else(|| Error::Domain(format!("'{poly}' is not a control polygon")))?;
                    let mut c = binomial_signed(k, i);
                    if (k - i) % 2 == 1 {
                        c = -c;
                    }
                    let term = Value::S(A::from_bigint(&c)).mul(&p)?;
                    acc = Some(match acc {
                        None => term,
                        Some(s) => s.add(&term)?,
                    });
                }
                acc.expect("k >= 0 gives at least one term")
            }
            "diff" => {
                return Err(Error::Domain(format!(
                    "'{e}': diff must be expanded before evaluation (internal)"
                )))
            }
            _ => {
                let env = self.env;
                env.call(name, args, self)?.ok_or_else(|| unknown_call(name))?
            }
        })
    }
}

/// The error for a call nothing answers; a derivative (`f'`, `f_u`, as `diff` writes them)
/// of something that is not a claim object says so.
fn unknown_call(name: &str) -> Error {
    let primed = name.trim_end_matches('\'');
    let base = if primed.len() < name.len() {
        Some(primed)
    } else {
        super::expr::split_partial(name).map(|(b, _, _)| b)
    };
    match base {
        Some(b) => Error::Domain(format!(
            "cannot differentiate {b}(…): '{name}' is a derivative, and only claim objects have them (a curve's b'(t), a surface's x_u(u, v)); {b} is not a curve or surface of the claim"
        )),
        None => Error::Domain(format!("unknown function or object '{name}'")),
    }
}

fn restore(ints: &mut BTreeMap<String, i64>, v: &str, saved: Option<i64>) {
    match saved {
        Some(x) => ints.insert(v.to_string(), x),
        None => ints.remove(v),
    };
}

/// The `k`-th derivative of `g^e` with respect to `g`: `e(e-1)…(e-k+1) g^(e-k)`, zero when
/// the falling factorial is (so `d/dg g^0 = 0` even at `g = 0`).
fn power_derivative<A: Alg>(g: &A, e: i64, k: i64) -> Result<A> {
    let mut ff = BigInt::from(1);
    for m in 0..k {
        ff *= e - m;
    }
    if ff.is_zero() {
        return Ok(A::from_int(0));
    }
    Ok(A::from_bigint(&ff).mul_ref(&g.pow(e - k)?))
}

/// The `k`-th derivative of `B_i^n(g) = C(n,i) g^i (1-g)^(n-i)` with respect to `g`, by
/// Leibniz's rule on the two powers (independent of the difference formulas it is used to check).
fn bernstein_derivative<A: Alg>(i: i64, n: i64, g: &A, k: i64) -> Result<A> {
    if i < 0 || i > n {
        return Ok(A::from_int(0));
    }
    let s = A::from_int(1).sub_ref(g);
    let mut acc = A::from_int(0);
    // Powers differentiated past their exponent vanish: skipped, so that the degree bound
    // is n − k (a zero factor would keep the other factor's degree in `Deg`).
    for m in (k - (n - i)).max(0)..=k.min(i) {
        let left = power_derivative(g, i, m)?;
        let mut right = power_derivative(&s, n - i, k - m)?;
        if (k - m) % 2 == 1 {
            right = right.neg_ref(); // d/dg (1-g) = -1
        }
        acc = acc.add_ref(&A::from_bigint(&binomial_signed(k, m)).mul_ref(&left).mul_ref(&right));
    }
    Ok(A::from_bigint(&binomial_signed(n, i)).mul_ref(&acc))
}

/// `B_i^n(g) = C(n,i) g^i (1-g)^(n-i)`, zero outside `0 ≤ i ≤ n`.
pub fn bernstein<A: Alg>(i: i64, n: i64, g: &A) -> Result<A> {
    g.bernstein(i, n)
}

/// `∫_a^b e dt` for an integrand that is a polynomial in `t` alone (and the integer ranges),
/// or a quotient that divides exactly to one: expanded exactly, integrated term by term, its antiderivative evaluated at `b` and `a` in
/// the evaluator's algebra (so the bounds may be parameters, and degree bounds compose).
fn integral<A: Alg>(ev: &mut Evaluator<'_, A>, e: &Expr, args: &[Expr]) -> Result<A> {
    use super::poly::{Poly, RatFunc};
    let Expr::Var(t) = &args[1] else {
        return Err(Error::Domain(format!(
            "'{e}': the variable of integration must be a name"
        )));
    };
    let names: std::rc::Rc<[String]> = std::rc::Rc::from(vec![t.clone()]);
    let degrees = std::iter::once((t.clone(), Value::S(Deg::var(t)))).collect();
    check_symbolic_degrees(degrees, &ev.ints, &[&args[0]])?;
    let mut vars = BTreeMap::new();
    vars.insert(t.clone(), Value::S(RatFunc::poly(Poly::var(&names, 0))));
    let env = VarEnv(vars);
    let expanded = Evaluator::new(&env, ev.ints.clone()).scalar(&args[0]);
    let f = expanded.map_err(|err| {
        Error::Domain(format!(
            "'{e}': the integrand must be a polynomial in {t} (and the integer ranges) only: {err}"
        ))
    })?;
    let not_polynomial = || Error::Domain(format!("'{e}': the integrand must be a polynomial in {t}"));
    let (f, den) = match f.den.as_constant() {
        Some(d) if d.is_zero() => return Err(not_polynomial()),
        Some(d) => (f, d),
        // A quotient that is a polynomial (t^(−1)·B_i^n(t) with i ≥ 1): the exact quotient,
        // equal to the integrand except at the finitely many zeros of the denominator.
        None => {
            let q = f.num.exact_div(&f.den).ok_or_else(not_polynomial)?;
            (RatFunc::poly(q), BigRational::one())
        }
    };
    let (a, b) = (ev.scalar(&args[2])?, ev.scalar(&args[3])?);
    // F(x) = Σ c_k x^(k+1) / (k+1), by Horner on the coefficients of F.
    let mut coeffs: Vec<BigRational> = Vec::new();
    for (exp, c) in f.num.terms_in(1) {
        let k = exp[0] as usize;
        if coeffs.len() <= k + 1 {
            coeffs.resize(k + 2, <BigRational as Zero>::zero());
        }
        coeffs[k + 1] = c / (&den * BigRational::from_integer(BigInt::from(k + 1)));
    }
    let at = |x: &A| {
        coeffs
            .iter()
            .rev()
            .fold(A::from_int(0), |acc, c| acc.mul_ref(x).add_ref(&A::from_rat(c)))
    };
    Ok(at(&b).sub_ref(&at(&a)))
}

/// The transpose of a matrix value.
fn transpose<A: Alg>(v: Value<A>) -> Result<Value<A>> {
    match v {
        // `cols()` of no vectors: the empty matrix is its own transpose.
        Value::M(m) if m.is_empty() => Ok(Value::M(m)),
        Value::M(m) => linalg::transpose(&m).map(Value::M),
        other => Err(Error::Domain(format!("transpose of {}", other.shape()))),
    }
}

/// `M⁻¹ = adj(M) / det M`, entry by entry (a zero `d` is the first division's error).
fn inverse<A: Alg>(m: &[Vec<A>], d: &A) -> Result<Value<A>> {
    let inverse = linalg::adjugate(m)
        .into_iter()
        .map(|row| row.iter().map(|x| x.div(d)).collect::<Result<Vec<_>>>())
        .collect::<Result<_>>()?;
    Ok(Value::M(inverse))
}

/// Largest degree, in any one variable, of the numerators and denominators a symbolic
/// expansion may build (checked on the derived bounds before expanding).
pub const MAX_SYMBOLIC_DEGREE: u64 = 4_096;

/// Checks, before expanding, that `exprs` expand to degrees at most [`MAX_SYMBOLIC_DEGREE`]
/// in each of the variables `vars` (scalars and vector coordinates, as degree bounds).
pub fn check_symbolic_degrees(
    vars: BTreeMap<String, Value<Deg>>,
    ints: &BTreeMap<String, i64>,
    exprs: &[&Expr],
) -> Result<()> {
    let env = VarEnv(vars);
    for e in exprs {
        let d = Evaluator::new(&env, ints.clone()).eval(e)?;
        for x in d.entries() {
            for (v, (num, den)) in x.vars() {
                if num.max(den) > MAX_SYMBOLIC_DEGREE {
                    return Err(Error::TooLarge {
                        what: "degree of a symbolic expansion",
                        value: format!("{} in {v}", num.max(den)),
                        limit: format!("MAX_SYMBOLIC_DEGREE = {MAX_SYMBOLIC_DEGREE} per variable"),
                    });
                }
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::super::parse::parse;
    use super::*;
    use crate::scalar::Ring;

    fn q(p: i64, d: i64) -> BigRational {
        BigRational::new(p.into(), d.into())
    }

    fn eval_at(s: &str, t: BigRational) -> Result<Value<BigRational>> {
        let mut vars = BTreeMap::new();
        vars.insert("t".to_string(), Value::S(t));
        let env = VarEnv(vars);
        Evaluator::new(&env, BTreeMap::new()).eval(&parse(s, &[])?)
    }

    fn deg(s: &str) -> Deg {
        let mut vars = BTreeMap::new();
        vars.insert("t".to_string(), Value::S(Deg::var("t")));
        let env = VarEnv(vars);
        Evaluator::new(&env, BTreeMap::new())
            .scalar(&parse(s, &[]).unwrap())
            .unwrap()
    }

    #[test]
    fn evaluates_exactly() {
        let v = eval_at("(2t - 1)/(t^2 - t + 1)", q(1, 3)).unwrap().scalar("").unwrap();
        assert_eq!(v, q(-1, 3) / q(7, 9));
        let b = eval_at("4/3 B(1, 3, t) + 4/3 B(2, 3, t)", q(1, 2))
            .unwrap()
            .scalar("")
            .unwrap();
        assert_eq!(b, q(1, 1));
        assert!(matches!(eval_at("1/(t - 1/3)", q(1, 3)), Err(Error::DivisionByZero(_))));
        assert!(eval_at("sqrt(2)", q(0, 1)).is_err());
        assert_eq!(eval_at("sqrt(9/4)", q(0, 1)).unwrap().scalar("").unwrap(), q(3, 2));
        assert!(eval_at("sqrt(-4)", q(0, 1))
            .unwrap_err()
            .to_string()
            .contains("negative"));
        assert!(eval_at("t^99999999", q(1, 2)).is_err());
        assert_eq!(
            eval_at("sum(r, 0, 3, B(r, 3, t))", q(2, 7))
                .unwrap()
                .scalar("")
                .unwrap(),
            q(1, 1)
        );
    }

    #[test]
    fn composed_bounds_keep_the_control_point_degree() {
        let cp = Deg::control_point();
        // A polynomial of degree 3 at a value of degree 1 in the control points: degree 3.
        assert_eq!(cp.compose(3).poly, 3);
        assert_eq!(cp.compose(3).times_control_point().poly, 4);
        assert_eq!(Deg::var("t").compose(3).poly, 0);
        assert_eq!(Deg::var("t").compose(3).times_control_point().poly, 1);
        // Composition multiplies the inner bounds; it never resets them.
        let g = Deg::var("t").mul_ref(&cp);
        let c = g.compose(2);
        assert_eq!((c.get("t"), c.poly), ((2, 0), 2));
        assert!(
            Deg::var("t").div(&cp).is_err(),
            "dividing by control points is not affine"
        );
        assert_eq!(cp.pow(3).unwrap().poly, 3);
    }

    #[test]
    fn degree_bounds() {
        assert_eq!(deg("(2t-1)^3 + 2t").get("t"), (3, 0));
        assert_eq!(deg("B(2, 5, t)").get("t"), (5, 0));
        assert_eq!(deg("(2t - 1)/(t^2 - t + 1)").get("t"), (1, 2));
        assert_eq!(deg("1/(1+t) + t").get("t"), (2, 1));
        assert_eq!(deg("t^-2").get("t"), (0, 2));
    }
}
