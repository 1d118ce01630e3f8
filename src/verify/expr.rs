//! Expressions written as in a book: the parser, the syntax tree, printing, and symbolic
//! differentiation of the tree.
//!
//! Grammar (loosest binding first):
//!
//! ```text
//! expr    := sum ("," sum)*                     -- a comma list inside ( ) is a tuple (vector)
//! sum     := term (("+" | "-") term)*
//! term    := unary (("*" | "/" | implicit) unary)*    -- `2t`, `4x^2`, `(1-t)(1+t)`, `2 sqrt(2)`
//! unary   := "-" unary | power
//! power   := postfix ("^" unary)?               -- right associative: -t^2 = -(t^2), t^-1
//! postfix := primary "!"*                       -- factorial of an integer: n!
//! primary := number | name | name "(" args ")" | name "[" args "]" | "(" expr ")" | "[" rows "]"
//! ```
//!
//! Implicit multiplication binds like `*`, so `3k/8` is `(3k)/8` and `1/2t` is `(1/2)t`.
//! A run of letters that is not a known name is a product of one-letter variables
//! (`st` = `s t`, `xy^2` = `x y^2`), unless it is directly followed by `(` (a call);
//! names with digits (`t0`, `x1`) are single names.
//!
//! Functions: `B(i, n, t)` (Bernstein, zero for `i < 0` or `i > n`), `C(n, k)` / `binom(n, k)`
//! (zero outside `0 ≤ k ≤ n`), `sum(r, a, b, body)` (`a ≤ r ≤ b`, empty when `a > b`),
//! `sqrt(d)` (exact), `diff(e, t)` / `diff(e, t, k)`, `dot(a, b)`, `det(M)`, `inv(M)`,
//! `rows(v1, v2, …)`, `cols(v1, v2, …)`, `transpose(M)`, `comp(v, k)` (the `k`-th coordinate,
//! from 1), `integral(e, t, a, b)` (exact, for a polynomial integrand in `t`), `delta(b, k, j)` (forward difference
//! `Δ^k b_j` of a control polygon). Claim objects are called by name: `b(t)` (a curve),
//! `b(i, r, t)` (the de Casteljau point `b_i^r(t)`), `b'(t)` (derivative), `b[j]` (a control
//! point), `x(u, v)` (a surface), `x_u(u, v)`, `x_uv(u, v)`, … (its partials: `u` by the
//! first argument, `v` by the second; see [`split_partial`]).
//!
//! Limits: exponents and Bernstein/binomial indices at most [`MAX_EXPONENT`]; at most
//! [`MAX_SUM_TERMS`] terms summed per evaluation; factorials of at most [`MAX_FACTORIAL`];
//! expressions at most [`MAX_EXPR_LEN`] characters and [`MAX_DEPTH`] levels deep.

use super::claims::IntRange;
use crate::error::{Error, Result};
use crate::scalar::parse_exact;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::collections::BTreeMap;
use std::fmt;

/// Largest absolute exponent, Bernstein degree or binomial argument accepted.
pub const MAX_EXPONENT: i64 = 4_096;
/// Largest number of terms a `sum(…)` may add up in one evaluation.
pub const MAX_SUM_TERMS: i64 = 100_000;
/// Largest integer whose factorial may be taken.
pub const MAX_FACTORIAL: i64 = 1_000;
/// Longest expression text accepted.
pub const MAX_EXPR_LEN: usize = 20_000;
/// Deepest nesting accepted (parentheses, powers, calls).
pub const MAX_DEPTH: usize = 200;

/// Built-in function names (they are never split into one-letter variables).
pub const FUNCTIONS: &[&str] = &[
    "B",
    "C",
    "binom",
    "sum",
    "sqrt",
    "diff",
    "dot",
    "det",
    "inv",
    "rows",
    "cols",
    "transpose",
    "delta",
    "comp",
    "integral",
];

/// A binary operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// `a + b`
    Add,
    /// `a - b`
    Sub,
    /// `a * b`
    Mul,
    /// `a / b`
    Div,
    /// `a ^ b` (integer exponent)
    Pow,
}

/// The syntax tree of an expression.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    /// An exact number (the parser produces non-negative ones; `-3` is `Neg(3)`).
    Num(BigRational),
    /// A variable or a nullary name.
    Var(String),
    /// `-a`
    Neg(Box<Expr>),
    /// `a op b`
    Bin(Op, Box<Expr>, Box<Expr>),
    /// `a!`
    Fact(Box<Expr>),
    /// `name(args)`: a built-in function or a claim object.
    Call(String, Vec<Expr>),
    /// `name[args]`: a control point `b[j]` or `b[i, j]`.
    Index(String, Vec<Expr>),
    /// `sum(var, from, to, body)`.
    Sum(String, Box<Expr>, Box<Expr>, Box<Expr>),
    /// `(a, b, …)`: a vector.
    Tuple(Vec<Expr>),
    /// `[a, b; c, d]`: a matrix given by rows.
    Matrix(Vec<Vec<Expr>>),
}

// Constructors named after the operation they build (not arithmetic on values).
#[allow(clippy::should_implement_trait)]
impl Expr {
    fn bin(op: Op, a: Expr, b: Expr) -> Expr {
        Expr::Bin(op, Box::new(a), Box::new(b))
    }
    /// `a + b`
    pub fn add(a: Expr, b: Expr) -> Expr {
        Expr::bin(Op::Add, a, b)
    }
    /// `a - b`
    pub fn sub(a: Expr, b: Expr) -> Expr {
        Expr::bin(Op::Sub, a, b)
    }
    /// `a * b`
    pub fn mul(a: Expr, b: Expr) -> Expr {
        Expr::bin(Op::Mul, a, b)
    }
    /// `a / b`
    pub fn div(a: Expr, b: Expr) -> Expr {
        Expr::bin(Op::Div, a, b)
    }
    /// `a ^ b`
    pub fn pow(a: Expr, b: Expr) -> Expr {
        Expr::bin(Op::Pow, a, b)
    }
    /// The integer `n`.
    pub fn int(n: i64) -> Expr {
        Expr::Num(BigRational::from_integer(n.into()))
    }

    /// Every name used as a variable (not bound by a `sum`), in first-use order.
    pub fn free_vars(&self) -> Vec<String> {
        let mut out = Vec::new();
        self.collect_vars(&mut Vec::new(), &mut out);
        out
    }

    fn collect_vars(&self, bound: &mut Vec<String>, out: &mut Vec<String>) {
        match self {
            Expr::Num(_) => {}
            Expr::Var(v) => {
                if !bound.contains(v) && !out.contains(v) {
                    out.push(v.clone());
                }
            }
            Expr::Neg(a) | Expr::Fact(a) => a.collect_vars(bound, out),
            Expr::Bin(_, a, b) => {
                a.collect_vars(bound, out);
                b.collect_vars(bound, out);
            }
            Expr::Call(name, args) if name == "integral" && args.len() == 4 && matches!(args[1], Expr::Var(_)) => {
                // The variable of integration is bound in the integrand, as a sum's is.
                as_binder(args).collect_vars(bound, out);
            }
            Expr::Call(_, args) | Expr::Index(_, args) | Expr::Tuple(args) => {
                for a in args {
                    a.collect_vars(bound, out);
                }
            }
            Expr::Sum(v, a, b, body) => {
                a.collect_vars(bound, out);
                b.collect_vars(bound, out);
                bound.push(v.clone());
                body.collect_vars(bound, out);
                bound.pop();
            }
            Expr::Matrix(rows) => {
                for r in rows {
                    for a in r {
                        a.collect_vars(bound, out);
                    }
                }
            }
        }
    }

    /// Whether the expression mentions `name` as a free variable.
    pub fn mentions(&self, name: &str) -> bool {
        self.free_vars().iter().any(|v| v == name)
    }

    /// Every name called or indexed (`b(t)`, `b[j]`), with the call's name as written.
    pub fn called_names(&self) -> Vec<String> {
        let mut out = Vec::new();
        self.visit(&mut |e| match e {
            Expr::Call(n, _) | Expr::Index(n, _) if !out.contains(n) => out.push(n.clone()),
            _ => {}
        });
        out
    }

    /// Calls `f` on every node of the tree, this one first.
    pub fn visit(&self, f: &mut dyn FnMut(&Expr)) {
        f(self);
        match self {
            Expr::Num(_) | Expr::Var(_) => {}
            Expr::Neg(a) | Expr::Fact(a) => a.visit(f),
            Expr::Bin(_, a, b) => {
                a.visit(f);
                b.visit(f);
            }
            Expr::Call(_, args) | Expr::Index(_, args) | Expr::Tuple(args) => args.iter().for_each(|a| a.visit(f)),
            Expr::Sum(_, a, b, body) => {
                a.visit(f);
                b.visit(f);
                body.visit(f);
            }
            Expr::Matrix(rows) => rows.iter().flatten().for_each(|a| a.visit(f)),
        }
    }
}

// ---------------------------------------------------------------------------------------
// Printing: parenthesised enough to parse back to the same tree.

fn prec(e: &Expr) -> u8 {
    match e {
        Expr::Tuple(_) => 0,
        Expr::Bin(Op::Add | Op::Sub, ..) => 1,
        Expr::Bin(Op::Mul | Op::Div, ..) => 2,
        Expr::Neg(_) => 3,
        Expr::Bin(Op::Pow, ..) => 4,
        Expr::Fact(_) => 5,
        Expr::Num(r) if !r.is_integer() || r.is_negative() => 2,
        _ => 6,
    }
}

fn write_wrapped(f: &mut fmt::Formatter<'_>, e: &Expr, min: u8) -> fmt::Result {
    if prec(e) < min {
        write!(f, "({e})")
    } else {
        write!(f, "{e}")
    }
}

impl fmt::Display for Expr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Expr::Num(r) => write!(f, "{r}"),
            Expr::Var(v) => write!(f, "{v}"),
            Expr::Neg(a) => {
                write!(f, "-")?;
                write_wrapped(f, a, 4)
            }
            Expr::Bin(op, a, b) => {
                let (sym, la, rb) = match op {
                    Op::Add => (" + ", 1, 2),
                    Op::Sub => (" - ", 1, 2),
                    Op::Mul => ("*", 2, 3),
                    Op::Div => ("/", 2, 3),
                    Op::Pow => ("^", 5, 3),
                };
                write_wrapped(f, a, la)?;
                write!(f, "{sym}")?;
                // a - (b + c) and a / (b * c) keep their parentheses; -x in a product too.
                let rb = if matches!(b.as_ref(), Expr::Neg(_)) && *op != Op::Pow {
                    4
                } else {
                    rb
                };
                write_wrapped(f, b, rb)
            }
            Expr::Fact(a) => {
                write_wrapped(f, a, 6)?;
                write!(f, "!")
            }
            Expr::Call(name, args) => {
                write!(f, "{name}(")?;
                write_list(f, args)?;
                write!(f, ")")
            }
            Expr::Index(name, args) => {
                write!(f, "{name}[")?;
                write_list(f, args)?;
                write!(f, "]")
            }
            Expr::Sum(v, a, b, body) => write!(f, "sum({v}, {a}, {b}, {body})"),
            Expr::Tuple(items) => {
                write!(f, "(")?;
                write_list(f, items)?;
                if items.len() == 1 {
                    write!(f, ",")?;
                }
                write!(f, ")")
            }
            Expr::Matrix(rows) => {
                write!(f, "[")?;
                for (i, r) in rows.iter().enumerate() {
                    if i > 0 {
                        write!(f, "; ")?;
                    }
                    write_list(f, r)?;
                }
                write!(f, "]")
            }
        }
    }
}

fn write_list(f: &mut fmt::Formatter<'_>, items: &[Expr]) -> fmt::Result {
    for (i, a) in items.iter().enumerate() {
        if i > 0 {
            write!(f, ", ")?;
        }
        // Items of a list are full expressions; a nested tuple keeps its own parentheses.
        write!(f, "{a}")?;
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------
// Lexer

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Num(BigRational),
    Ident(String),
    Sym(char),
}

fn lex(text: &str, known: &[String]) -> Result<Vec<Tok>> {
    if text.len() > MAX_EXPR_LEN {
        return Err(Error::TooLarge {
            what: "expression",
            value: format!("{} characters", text.len()),
            limit: format!("{MAX_EXPR_LEN} characters"),
        });
    }
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_digit() || (c == '.' && chars.get(i + 1).is_some_and(|d| d.is_ascii_digit())) {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                i += 1;
            }
            let lit: String = chars[start..i].iter().collect();
            out.push(Tok::Num(
                parse_exact(&lit).map_err(|_| Error::Parse(format!("bad number '{lit}'")))?,
            ));
        } else if c.is_alphabetic() || c == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_' || chars[i] == '\'') {
                i += 1;
            }
            let word: String = chars[start..i].iter().collect();
            // A word directly followed by '(' is a call (an unknown one is reported by name).
            let called = chars.get(i) == Some(&'(');
            let is_known = called || known.iter().any(|k| k == &word) || FUNCTIONS.contains(&word.as_str());
            if is_known || word.chars().count() == 1 || !word.chars().all(char::is_alphabetic) {
                out.push(Tok::Ident(word));
            } else {
                // `st`, `xy`: a product of one-letter variables.
                for ch in word.chars() {
                    out.push(Tok::Ident(ch.to_string()));
                }
            }
        } else if "+-*/^()[],;!".contains(c) {
            out.push(Tok::Sym(c));
            i += 1;
        } else if c == '·' || c == '×' {
            out.push(Tok::Sym('*'));
            i += 1;
        } else if c == '−' {
            out.push(Tok::Sym('-'));
            i += 1;
        } else {
            return Err(Error::Parse(format!("unexpected character '{c}' in '{text}'")));
        }
    }
    Ok(out)
}

// ---------------------------------------------------------------------------------------
// Parser

struct Parser<'a> {
    known: &'a [String],
    toks: Vec<Tok>,
    pos: usize,
    text: &'a str,
    depth: usize,
}

/// Parses an expression; `known` lists the multi-letter names of the claim (objects,
/// symbols, definitions) so that they are not split into one-letter variables.
///
/// ```
/// use casteljau::verify::expr::parse;
/// let e = parse("4x^2 + 3y^2 - 10y + 3", &[]).unwrap();
/// assert_eq!(e.to_string(), "4*x^2 + 3*y^2 - 10*y + 3");
/// assert!(parse("(1 + t", &[]).is_err());
/// ```
pub fn parse(text: &str, known: &[String]) -> Result<Expr> {
    let toks = lex(text, known)?;
    if toks.is_empty() {
        return Err(Error::Parse("empty expression".into()));
    }
    let mut p = Parser {
        known,
        toks,
        pos: 0,
        text,
        depth: 0,
    };
    let e = p.expr_list()?;
    if p.pos < p.toks.len() {
        return Err(p.err(&format!("unexpected '{}'", show(&p.toks[p.pos]))));
    }
    Ok(e)
}

fn show(t: &Tok) -> String {
    match t {
        Tok::Num(r) => r.to_string(),
        Tok::Ident(s) => s.clone(),
        Tok::Sym(c) => c.to_string(),
    }
}

impl Parser<'_> {
    fn err(&self, msg: &str) -> Error {
        Error::Parse(format!("{msg} in '{}'", self.text))
    }
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.pos)
    }
    fn peek_sym(&self, c: char) -> bool {
        self.peek() == Some(&Tok::Sym(c))
    }
    fn expect(&mut self, c: char) -> Result<()> {
        if self.peek_sym(c) {
            self.pos += 1;
            Ok(())
        } else {
            let found = self.peek().map(show).unwrap_or_else(|| "end of input".into());
            Err(self.err(&format!("expected '{c}', found {found} (unbalanced parentheses?)")))
        }
    }
    fn enter(&mut self) -> Result<()> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(Error::TooLarge {
                what: "expression nesting",
                value: format!("more than {MAX_DEPTH} levels"),
                limit: MAX_DEPTH.to_string(),
            });
        }
        Ok(())
    }

    /// A comma list: a single item is itself, several make a tuple.
    fn expr_list(&mut self) -> Result<Expr> {
        let first = self.sum()?;
        if !self.peek_sym(',') {
            return Ok(first);
        }
        let mut items = vec![first];
        while self.peek_sym(',') {
            self.pos += 1;
            if self.peek_sym(')') {
                break; // `(a,)`: a one-element tuple
            }
            items.push(self.sum()?);
        }
        Ok(Expr::Tuple(items))
    }

    fn sum(&mut self) -> Result<Expr> {
        let mut acc = self.term()?;
        loop {
            if self.peek_sym('+') {
                self.pos += 1;
                acc = Expr::add(acc, self.term()?);
            } else if self.peek_sym('-') {
                self.pos += 1;
                acc = Expr::sub(acc, self.term()?);
            } else {
                return Ok(acc);
            }
        }
    }

    fn starts_primary(&self) -> bool {
        matches!(
            self.peek(),
            Some(Tok::Num(_) | Tok::Ident(_) | Tok::Sym('(') | Tok::Sym('['))
        )
    }

    fn term(&mut self) -> Result<Expr> {
        let mut acc = self.unary()?;
        loop {
            if self.peek_sym('*') {
                self.pos += 1;
                acc = Expr::mul(acc, self.unary()?);
            } else if self.peek_sym('/') {
                self.pos += 1;
                acc = Expr::div(acc, self.unary()?);
            } else if self.starts_primary() {
                // implicit multiplication: 2t, 4x^2, (1-t)(1+t)
                acc = Expr::mul(acc, self.power()?);
            } else {
                return Ok(acc);
            }
        }
    }

    fn unary(&mut self) -> Result<Expr> {
        if self.peek_sym('-') {
            self.pos += 1;
            self.enter()?;
            let e = Expr::Neg(Box::new(self.unary()?));
            self.depth -= 1;
            return Ok(e);
        }
        if self.peek_sym('+') {
            self.pos += 1;
            return self.unary();
        }
        self.power()
    }

    fn power(&mut self) -> Result<Expr> {
        let base = self.postfix()?;
        if self.peek_sym('^') {
            self.pos += 1;
            self.enter()?;
            let exp = self.unary()?;
            self.depth -= 1;
            return Ok(Expr::pow(base, exp));
        }
        Ok(base)
    }

    fn postfix(&mut self) -> Result<Expr> {
        let mut e = self.primary()?;
        while self.peek_sym('!') {
            self.pos += 1;
            e = Expr::Fact(Box::new(e));
        }
        Ok(e)
    }

    fn args(&mut self, close: char) -> Result<Vec<Expr>> {
        let mut args = Vec::new();
        if self.peek_sym(close) {
            self.pos += 1;
            return Ok(args);
        }
        loop {
            args.push(self.sum()?);
            if self.peek_sym(',') {
                self.pos += 1;
            } else {
                self.expect(close)?;
                return Ok(args);
            }
        }
    }

    fn primary(&mut self) -> Result<Expr> {
        self.enter()?;
        let e = self.primary_inner();
        self.depth -= 1;
        e
    }

    fn primary_inner(&mut self) -> Result<Expr> {
        let tok = self
            .peek()
            .cloned()
            .ok_or_else(|| self.err("unexpected end of expression"))?;
        self.pos += 1;
        match tok {
            Tok::Num(r) => Ok(Expr::Num(r)),
            Tok::Sym('(') => {
                let e = self.expr_list()?;
                self.expect(')')?;
                Ok(e)
            }
            Tok::Sym('[') => {
                let mut rows = vec![Vec::new()];
                if self.peek_sym(']') {
                    return Err(self.err("empty matrix"));
                }
                loop {
                    rows.last_mut().expect("rows is never empty").push(self.sum()?);
                    if self.peek_sym(',') {
                        self.pos += 1;
                    } else if self.peek_sym(';') {
                        self.pos += 1;
                        rows.push(Vec::new());
                    } else {
                        self.expect(']')?;
                        break;
                    }
                }
                if rows.iter().any(|r| r.len() != rows[0].len()) {
                    return Err(self.err("matrix rows of different lengths"));
                }
                Ok(Expr::Matrix(rows))
            }
            Tok::Ident(name) => {
                // `t(1 - t)` is a product; `b(t)`, `B(…)`, `foo(…)` are calls.
                let one_letter_var = name.chars().count() == 1
                    && !FUNCTIONS.contains(&name.as_str())
                    && !self.known.iter().any(|k| k == &name);
                if self.peek_sym('(') && !one_letter_var {
                    self.pos += 1;
                    let args = self.args(')')?;
                    if name == "sum" {
                        return self.make_sum(args);
                    }
                    check_arity(&name, args.len()).map_err(|m| self.err(&m))?;
                    return Ok(Expr::Call(name, args));
                }
                if self.peek_sym('[') {
                    self.pos += 1;
                    let args = self.args(']')?;
                    if args.is_empty() {
                        return Err(self.err(&format!("{name}[] needs an index")));
                    }
                    return Ok(Expr::Index(name, args));
                }
                if FUNCTIONS.contains(&name.as_str()) {
                    return Err(self.err(&format!("function {name} needs arguments in parentheses")));
                }
                Ok(Expr::Var(name))
            }
            Tok::Sym(c) => Err(self.err(&format!("unexpected '{c}'"))),
        }
    }

    fn make_sum(&mut self, mut args: Vec<Expr>) -> Result<Expr> {
        if args.len() != 4 {
            return Err(self.err("sum needs 4 arguments: sum(var, from, to, body)"));
        }
        let body = args.pop().expect("4 args");
        let to = args.pop().expect("4 args");
        let from = args.pop().expect("4 args");
        match args.pop().expect("4 args") {
            Expr::Var(v) => Ok(Expr::Sum(v, Box::new(from), Box::new(to), Box::new(body))),
            other => Err(self.err(&format!("the first argument of sum must be a variable, not '{other}'"))),
        }
    }
}

fn check_arity(name: &str, n: usize) -> std::result::Result<(), String> {
    let ok = match name {
        "B" => n == 3,
        "C" | "binom" | "dot" | "comp" => n == 2,
        "sqrt" | "det" | "inv" | "transpose" => n == 1,
        "diff" => n == 2 || n == 3,
        "delta" => n == 3,
        "integral" => n == 4,
        "rows" | "cols" => n >= 1,
        _ => true,
    };
    if ok {
        Ok(())
    } else {
        let want = match name {
            "B" => "3 arguments: B(i, n, t)",
            "C" | "binom" => "2 arguments: C(n, k)",
            "dot" => "2 arguments: dot(a, b)",
            "comp" => "2 arguments: comp(v, k), the k-th coordinate (from 1)",
            "diff" => "2 or 3 arguments: diff(e, t) or diff(e, t, k)",
            "delta" => "3 arguments: delta(b, k, j)",
            "integral" => "4 arguments: integral(e, t, a, b)",
            "rows" | "cols" => "at least one argument",
            _ => "1 argument",
        };
        Err(format!("{name} needs {want}, got {n}"))
    }
}

// ---------------------------------------------------------------------------------------
// Definitions (`let`) and symbolic differentiation, both rewrites of the tree.

/// A claim-local definition `name(p1, p2) = body` (or `name = body`).
#[derive(Clone, Debug, PartialEq)]
pub struct Definition {
    /// The defined name.
    pub name: String,
    /// The parameter names.
    pub params: Vec<String>,
    /// The body.
    pub body: Expr,
}

/// Parses `name(p, q) = body` or `name = body`.
pub fn parse_definition(text: &str, known: &[String]) -> Result<Definition> {
    let (head, body) = text
        .split_once('=')
        .ok_or_else(|| Error::Parse(format!("a definition needs 'name = expression': '{text}'")))?;
    let head = head.trim();
    let (name, params) = match head.split_once('(') {
        Some((n, rest)) => {
            let inner = rest
                .strip_suffix(')')
                .ok_or_else(|| Error::Parse(format!("bad definition head '{head}'")))?;
            (
                n.trim(),
                inner.split(',').map(|p| p.trim().to_string()).collect::<Vec<_>>(),
            )
        }
        None => (head, Vec::new()),
    };
    let valid = |s: &str| !s.is_empty() && s.chars().all(|c| c.is_alphanumeric() || c == '_');
    if !valid(name) || !params.iter().all(|p| valid(p)) {
        return Err(Error::Parse(format!("bad definition head '{head}'")));
    }
    Ok(Definition {
        name: name.to_string(),
        params,
        body: parse(body, known)?,
    })
}

/// Replaces every use of a definition by its body, with the arguments substituted.
///
/// Hygienic: a `sum` variable of `e` that a definition's body (or an argument) uses freely is
/// renamed first, so no substitution is ever captured by a binder.
pub fn expand(e: &Expr, defs: &[Definition]) -> Result<Expr> {
    expand_depth(e, defs, 0)
}

fn expand_depth(e: &Expr, defs: &[Definition], depth: usize) -> Result<Expr> {
    if depth > 64 {
        return Err(Error::Domain(
            "definitions nest more than 64 deep (a recursive definition?)".into(),
        ));
    }
    let rec = |x: &Expr| expand_depth(x, defs, depth);
    Ok(match e {
        Expr::Var(v) => match defs.iter().find(|d| &d.name == v && d.params.is_empty()) {
            Some(d) => expand_depth(&d.body, defs, depth + 1)?,
            None => e.clone(),
        },
        Expr::Call(name, args) => {
            let args = args.iter().map(rec).collect::<Result<Vec<_>>>()?;
            match defs.iter().find(|d| &d.name == name) {
                Some(d) => {
                    if d.params.len() != args.len() {
                        return Err(Error::Domain(format!(
                            "{name} is defined with {} parameters, called with {}",
                            d.params.len(),
                            args.len()
                        )));
                    }
                    let body = substitute(&d.body, &d.params, &args);
                    expand_depth(&body, defs, depth + 1)?
                }
                None => Expr::Call(name.clone(), args),
            }
        }
        Expr::Sum(v, a, b, body) => {
            // A definition used in the body refers to the claim's `v`, not to this binder:
            // rename the binder when some definition mentions (or is named) `v`.
            let clash = defs
                .iter()
                .any(|d| d.name == *v || (!d.params.contains(v) && d.body.mentions(v)));
            let (v, body) = if clash {
                let fresh = fresh_name(v, &[body.as_ref()], defs);
                let renamed = substitute(body, std::slice::from_ref(v), &[Expr::Var(fresh.clone())]);
                (fresh, renamed)
            } else {
                (v.clone(), (**body).clone())
            };
            Expr::Sum(v, Box::new(rec(a)?), Box::new(rec(b)?), Box::new(rec(&body)?))
        }
        _ => map_children(e, &mut |x| rec(x))?,
    })
}

/// Every name that occurs in `e` (free or bound, variables and calls).
fn all_names(e: &Expr, out: &mut Vec<String>) {
    e.visit(&mut |x| match x {
        Expr::Var(v) | Expr::Call(v, _) | Expr::Index(v, _) | Expr::Sum(v, ..) if !out.contains(v) => {
            out.push(v.clone())
        }
        _ => {}
    });
}

/// A name `v_1`, `v_2`, … that occurs nowhere in `exprs` nor in the definitions.
fn fresh_name(v: &str, exprs: &[&Expr], defs: &[Definition]) -> String {
    let mut used = Vec::new();
    for e in exprs {
        all_names(e, &mut used);
    }
    for d in defs {
        used.push(d.name.clone());
        used.extend(d.params.iter().cloned());
        all_names(&d.body, &mut used);
    }
    (1..)
        .map(|k| format!("{v}_{k}"))
        .find(|n| !used.contains(n))
        .expect("a fresh name exists")
}

/// Substitutes `args[k]` for the free variable `params[k]`, capture-avoiding: a `sum` whose
/// variable occurs free in an argument substituted into its body is renamed first.
pub fn substitute(e: &Expr, params: &[String], args: &[Expr]) -> Expr {
    match e {
        Expr::Var(v) => match params.iter().position(|p| p == v) {
            Some(k) => args[k].clone(),
            None => e.clone(),
        },
        Expr::Sum(v, a, b, body) => {
            // The summation variable shadows a parameter of the same name.
            let (p2, a2): (Vec<String>, Vec<Expr>) = params
                .iter()
                .zip(args)
                .filter(|(p, _)| *p != v && body.mentions(p))
                .map(|(p, a)| (p.clone(), a.clone()))
                .unzip();
            let (v, body) = if a2.iter().any(|x| x.mentions(v)) {
                let mut exprs: Vec<&Expr> = vec![body.as_ref()];
                exprs.extend(a2.iter());
                let fresh = fresh_name(v, &exprs, &[]);
                let renamed = substitute(body, std::slice::from_ref(v), &[Expr::Var(fresh.clone())]);
                (fresh, renamed)
            } else {
                (v.clone(), (**body).clone())
            };
            Expr::Sum(
                v,
                Box::new(substitute(a, params, args)),
                Box::new(substitute(b, params, args)),
                Box::new(substitute(&body, &p2, &a2)),
            )
        }
        Expr::Call(name, cargs) if name == "integral" && cargs.len() == 4 && matches!(cargs[1], Expr::Var(_)) => {
            // Hygienic like a sum: the variable of integration is renamed rather than capture.
            match substitute(&as_binder(cargs), params, args) {
                Expr::Sum(v, a, b, body) => Expr::Call(name.clone(), vec![*body, Expr::Var(v), *a, *b]),
                other => other,
            }
        }
        _ => map_children(e, &mut |x| Ok(substitute(x, params, args))).expect("substitution cannot fail"),
    }
}

/// `integral(e, t, a, b)` as the binder `sum(t, a, b, e)`, for scoping only.
fn as_binder(args: &[Expr]) -> Expr {
    let Expr::Var(v) = &args[1] else {
        unreachable!("checked by the callers")
    };
    Expr::Sum(
        v.clone(),
        Box::new(args[2].clone()),
        Box::new(args[3].clone()),
        Box::new(args[0].clone()),
    )
}

/// Orders definitions so that each comes after the definitions it uses (any order may be
/// written); a definition that uses itself, directly or through others, is an error.
pub fn dependency_order(defs: Vec<Definition>) -> Result<Vec<Definition>> {
    let uses = |d: &Definition, other: &Definition| {
        let mut names = Vec::new();
        all_names(&d.body, &mut names);
        names.contains(&other.name) && !d.params.contains(&other.name)
    };
    let mut done: Vec<Definition> = Vec::new();
    let mut left = defs;
    while !left.is_empty() {
        let ready = left
            .iter()
            .position(|d| left.iter().all(|o| !uses(d, o)))
            .ok_or_else(|| {
                let names: Vec<&str> = left.iter().map(|d| d.name.as_str()).collect();
                Error::Domain(format!(
                    "the definitions of {} are circular (each uses another)",
                    names.join(", ")
                ))
            })?;
        done.push(left.remove(ready));
    }
    Ok(done)
}

fn map_children(e: &Expr, f: &mut dyn FnMut(&Expr) -> Result<Expr>) -> Result<Expr> {
    Ok(match e {
        Expr::Num(_) | Expr::Var(_) => e.clone(),
        Expr::Neg(a) => Expr::Neg(Box::new(f(a)?)),
        Expr::Fact(a) => Expr::Fact(Box::new(f(a)?)),
        Expr::Bin(op, a, b) => Expr::Bin(*op, Box::new(f(a)?), Box::new(f(b)?)),
        Expr::Call(n, args) => Expr::Call(n.clone(), args.iter().map(&mut *f).collect::<Result<_>>()?),
        Expr::Index(n, args) => Expr::Index(n.clone(), args.iter().map(&mut *f).collect::<Result<_>>()?),
        Expr::Tuple(args) => Expr::Tuple(args.iter().map(&mut *f).collect::<Result<_>>()?),
        Expr::Sum(v, a, b, body) => Expr::Sum(v.clone(), Box::new(f(a)?), Box::new(f(b)?), Box::new(f(body)?)),
        Expr::Matrix(rows) => Expr::Matrix(
            rows.iter()
                .map(|r| r.iter().map(&mut *f).collect::<Result<Vec<_>>>())
                .collect::<Result<_>>()?,
        ),
    })
}

/// Rewrites every `diff(e, t)` / `diff(e, t, k)` into its derivative, by the rules of
/// calculus applied to the tree (sum, product, quotient and power rules; `B(i, n, g)` by
/// the product rule on `C(n,i) g^i (1-g)^(n-i)`; a claim object `b(g)` becomes `b'(g) g'`).
///
/// Differentiation is by a real parameter only: `ints` are the claim's integer names (its
/// range variables); a summation index in scope is one too. Differentiating by one of them is
/// an error, and so is any integer position (a factorial, a sum bound, a binomial, an index,
/// an exponent) that depends on the variable: `d/dn Σ_{k=0}^n k` has no meaning as a
/// derivative of the sum, and reading `n` as a constant there would prove false claims.
pub fn expand_diffs(e: &Expr, ints: &[String]) -> Result<Expr> {
    let mut scope = ints.to_vec();
    expand_diffs_in(e, &mut scope)
}

fn expand_diffs_in(e: &Expr, ints: &mut Vec<String>) -> Result<Expr> {
    if let Expr::Sum(v, a, b, body) = e {
        let (a, b) = (expand_diffs_in(a, ints)?, expand_diffs_in(b, ints)?);
        ints.push(v.clone());
        let body = expand_diffs_in(body, ints);
        ints.pop();
        return Ok(Expr::Sum(v.clone(), Box::new(a), Box::new(b), Box::new(body?)));
    }
    let inner = map_children(e, &mut |c| expand_diffs_in(c, ints))?;
    if let Expr::Call(name, args) = &inner {
        if name == "diff" {
            let var = match &args[1] {
                Expr::Var(v) => v.clone(),
                other => return Err(Error::Domain(format!("diff needs a variable, not '{other}'"))),
            };
            if ints.contains(&var) {
                return Err(Error::Domain(format!(
                    "cannot differentiate by {var}: it is an integer (a range or summation variable); diff takes a real parameter"
                )));
            }
            let k = match args.get(2) {
                None => 1,
                Some(Expr::Num(r)) if r.is_integer() && !r.is_negative() && *r.numer() <= 16.into() => {
                    r.to_integer().try_into().expect("at most 16")
                }
                Some(other) => {
                    return Err(Error::Domain(format!(
                        "the order of diff must be an integer from 0 to 16, not '{other}'"
                    )))
                }
            };
            let mut d = args[0].clone();
            for _ in 0..k {
                d = derive(&d, &var)?;
            }
            return Ok(d);
        }
    }
    Ok(inner)
}

fn is_lit(e: &Expr, v: i64) -> bool {
    matches!(e, Expr::Num(r) if *r == BigRational::from_integer(v.into()))
}

/// `a + b`, dropping literal zeros (keeps derivative trees from doubling at every order).
fn sadd(a: Expr, b: Expr) -> Expr {
    if is_lit(&a, 0) {
        b
    } else if is_lit(&b, 0) {
        a
    } else {
        Expr::add(a, b)
    }
}

fn ssub(a: Expr, b: Expr) -> Expr {
    if is_lit(&b, 0) {
        a
    } else if is_lit(&a, 0) {
        Expr::Neg(Box::new(b))
    } else {
        Expr::sub(a, b)
    }
}

/// `a * b`, with `0 * x = 0` and `1 * x = x` for literals.
fn smul(a: Expr, b: Expr) -> Expr {
    if is_lit(&a, 0) || is_lit(&b, 0) {
        Expr::int(0)
    } else if is_lit(&a, 1) {
        b
    } else if is_lit(&b, 1) {
        a
    } else {
        Expr::mul(a, b)
    }
}

/// The derivative of `e` with respect to `var`.
pub fn derive(e: &Expr, var: &str) -> Result<Expr> {
    let zero = || Expr::int(0);
    if !e.mentions(var) && e.called_names().is_empty() {
        return Ok(zero());
    }
    Ok(match e {
        Expr::Num(_) => zero(),
        Expr::Var(v) => Expr::int(i64::from(v == var)),
        Expr::Neg(a) => {
            let d = derive(a, var)?;
            if is_lit(&d, 0) {
                d
            } else {
                Expr::Neg(Box::new(d))
            }
        }
        Expr::Bin(Op::Add, a, b) => sadd(derive(a, var)?, derive(b, var)?),
        Expr::Bin(Op::Sub, a, b) => ssub(derive(a, var)?, derive(b, var)?),
        Expr::Bin(Op::Mul, a, b) => sadd(
            smul(derive(a, var)?, (**b).clone()),
            smul((**a).clone(), derive(b, var)?),
        ),
        Expr::Bin(Op::Div, a, b) => {
            let (da, db) = (derive(a, var)?, derive(b, var)?);
            if is_lit(&db, 0) {
                if is_lit(&da, 0) {
                    zero()
                } else {
                    Expr::div(da, (**b).clone())
                }
            } else {
                Expr::div(
                    ssub(smul(da, (**b).clone()), smul((**a).clone(), db)),
                    Expr::pow((**b).clone(), Expr::int(2)),
                )
            }
        }
        Expr::Bin(Op::Pow, a, k) => {
            if k.mentions(var) {
                return Err(Error::Domain(format!(
                    "cannot differentiate '{e}': the exponent depends on {var}"
                )));
            }
            // d/dx a^k = (k-th power rule, written so that k = 0 gives 0 even where a = 0)
            smul(
                Expr::Call("__dpow".into(), vec![(**a).clone(), (**k).clone(), Expr::int(1)]),
                derive(a, var)?,
            )
        }
        Expr::Fact(a) => {
            if a.mentions(var) {
                return Err(integer_position(e, var, "a factorial takes an integer"));
            }
            zero()
        }
        Expr::Sum(v, a, b, body) => {
            if v == var {
                return Err(Error::Domain(format!(
                    "cannot differentiate by the summation variable {var}"
                )));
            }
            if a.mentions(var) || b.mentions(var) {
                return Err(integer_position(e, var, "the bounds of a sum are integers"));
            }
            let d = derive(body, var)?;
            if is_lit(&d, 0) {
                d
            } else {
                Expr::Sum(v.clone(), a.clone(), b.clone(), Box::new(d))
            }
        }
        Expr::Tuple(items) => Expr::Tuple(items.iter().map(|x| derive(x, var)).collect::<Result<_>>()?),
        Expr::Matrix(rows) => Expr::Matrix(
            rows.iter()
                .map(|r| r.iter().map(|x| derive(x, var)).collect::<Result<Vec<_>>>())
                .collect::<Result<_>>()?,
        ),
        Expr::Index(_, args) => {
            if args.iter().any(|a| a.mentions(var)) {
                return Err(integer_position(e, var, "an index is an integer"));
            }
            zero()
        }
        Expr::Call(name, args) => derive_call(e, name, args, var)?,
    })
}

/// The error for a derivative by `var` of `e`, where `var` stands in an integer position.
fn integer_position(e: &Expr, var: &str, why: &str) -> Error {
    Error::Domain(format!(
        "cannot differentiate '{e}' by {var}: {why}, so it does not depend smoothly on {var}"
    ))
}

fn bump_order(name: &str, args: &[Expr], var: &str, e: &Expr) -> Result<Expr> {
    // __dB(i, n, g, k) / __dpow(g, e, k): the k-th derivative with respect to g; one more
    // derivative raises k by one and multiplies by g' (chain rule).
    let (g, fixed) = if name == "__dB" {
        (&args[2], &args[..2])
    } else {
        (&args[0], &args[1..2])
    };
    if fixed.iter().any(|a| a.mentions(var)) {
        return Err(Error::Domain(format!("cannot differentiate '{e}' by {var}")));
    }
    let mut next = args.to_vec();
    let k = next.last().cloned().expect("order argument");
    *next.last_mut().expect("order argument") = Expr::add(k, Expr::int(1));
    Ok(smul(Expr::Call(name.into(), next), derive(g, var)?))
}

fn derive_call(e: &Expr, name: &str, args: &[Expr], var: &str) -> Result<Expr> {
    let zero = Expr::int(0);
    let unsupported = || Error::Domain(format!("cannot differentiate '{e}' by {var}"));
    match name {
        "B" => {
            if args[0].mentions(var) || args[1].mentions(var) {
                return Err(unsupported());
            }
            let mut a = args.to_vec();
            a.push(Expr::int(1));
            Ok(smul(Expr::Call("__dB".into(), a), derive(&args[2], var)?))
        }
        "__dB" | "__dpow" => bump_order(name, args, var, e),
        "C" | "binom" | "delta" | "sqrt" | "integral" => {
            if args.iter().any(|a| a.mentions(var)) {
                return Err(unsupported());
            }
            Ok(zero)
        }
        "comp" => Ok(Expr::Call("comp".into(), vec![derive(&args[0], var)?, args[1].clone()])),
        "dot" => Ok(sadd(
            Expr::Call("dot".into(), vec![derive(&args[0], var)?, args[1].clone()]),
            Expr::Call("dot".into(), vec![args[0].clone(), derive(&args[1], var)?]),
        )),
        "det" | "inv" | "rows" | "cols" | "transpose" => {
            if args.iter().any(|a| a.mentions(var)) {
                return Err(unsupported());
            }
            Ok(zero)
        }
        _ if args.len() == 2 => {
            // A surface (or net) x(g, h) → x_u(g, h) g' + x_v(g, h) h' (chain rule; `_u` is
            // the partial by the first argument, whatever it is called). Partials of a
            // polynomial surface commute, so the suffix is kept sorted: x_uv = x_vu.
            if !args.iter().any(|a| a.mentions(var)) {
                return Ok(zero);
            }
            let (base, ku, kv) = split_partial(name).unwrap_or((name, 0, 0));
            let du = derive(&args[0], var)?;
            let dv = derive(&args[1], var)?;
            Ok(sadd(
                smul(Expr::Call(partial_name(base, ku + 1, kv), args.to_vec()), du),
                smul(Expr::Call(partial_name(base, ku, kv + 1), args.to_vec()), dv),
            ))
        }
        _ => {
            // A claim object: b(g) → b'(g) g' (a curve of one parameter).
            if args.len() != 1 {
                if args.iter().any(|a| a.mentions(var)) {
                    return Err(unsupported());
                }
                return Ok(zero);
            }
            if !args[0].mentions(var) {
                return Ok(zero);
            }
            Ok(smul(
                Expr::Call(format!("{name}'"), args.to_vec()),
                derive(&args[0], var)?,
            ))
        }
    }
}

/// The partial-derivative notation of a surface: `x_u`, `x_vv`, `x_uuv`, … is
/// `(x, ku, kv)`, `ku` the count of `u` (the first argument) and `kv` of `v` (the second)
/// after the last `_`; `None` for any other name.
///
/// ```
/// use casteljau::verify::expr::split_partial;
/// assert_eq!(split_partial("x_uvu"), Some(("x", 2, 1)));
/// assert_eq!(split_partial("x"), None);
/// assert_eq!(split_partial("x_w"), None);
/// ```
pub fn split_partial(name: &str) -> Option<(&str, usize, usize)> {
    let (base, suffix) = name.rsplit_once('_')?;
    if base.is_empty() || suffix.is_empty() || !suffix.chars().all(|c| c == 'u' || c == 'v') {
        return None;
    }
    let ku = suffix.chars().filter(|&c| c == 'u').count();
    Some((base, ku, suffix.len() - ku))
}

/// The name of the partial `∂^{ku+kv} x / ∂u^{ku} ∂v^{kv}`: `x_uuv` (`x` itself for 0, 0).
pub fn partial_name(base: &str, ku: usize, kv: usize) -> String {
    if ku + kv == 0 {
        return base.to_string();
    }
    format!("{base}_{}{}", "u".repeat(ku), "v".repeat(kv))
}

/// A finite integer range `var = from..=to` with its bounds parsed (later bounds may use
/// earlier variables).
#[derive(Clone, Debug, PartialEq)]
pub struct ClosedRange {
    /// The variable.
    pub var: String,
    /// The first value (an integer expression).
    pub from: Expr,
    /// The last value, inclusive.
    pub to: Expr,
}

/// The bounds of a finite range, parsed; an open range (`n = 0..`) is an error here.
pub fn closed_range(r: &IntRange) -> Result<ClosedRange> {
    let to =
        r.to.as_deref()
            .ok_or_else(|| Error::Parse(format!("the range '{r}' is open: it has no cases to enumerate")))?;
    Ok(ClosedRange {
        var: r.var.clone(),
        from: parse(&r.from, &[])?,
        to: parse(to, &[])?,
    })
}

/// Evaluates an integer expression: literals, integer variables, `+ - * ^ !`, exact `/`,
/// and `C(n, k)`.
pub fn eval_int(e: &Expr, ints: &BTreeMap<String, i64>) -> Result<i64> {
    let over = || Error::TooLarge {
        what: "integer",
        value: format!("'{e}'"),
        limit: "64-bit".into(),
    };
    Ok(match e {
        Expr::Num(r) => {
            if !r.is_integer() {
                return Err(Error::Domain(format!("{r} is not an integer")));
            }
            i64::try_from(r.numer()).map_err(|_| over())?
        }
        Expr::Var(v) => *ints
            .get(v)
            .ok_or_else(|| Error::Domain(format!("'{v}' is not an integer here (needed as an index or exponent)")))?,
        Expr::Neg(a) => eval_int(a, ints)?.checked_neg().ok_or_else(over)?,
        Expr::Bin(op, a, b) => {
            let (x, y) = (eval_int(a, ints)?, eval_int(b, ints)?);
            match op {
                Op::Add => x.checked_add(y).ok_or_else(over)?,
                Op::Sub => x.checked_sub(y).ok_or_else(over)?,
                Op::Mul => x.checked_mul(y).ok_or_else(over)?,
                Op::Div => {
                    if y == 0 {
                        return Err(Error::DivisionByZero(format!("'{e}'")));
                    }
                    if x % y != 0 {
                        return Err(Error::Domain(format!("'{e}' = {x}/{y} is not an integer")));
                    }
                    x / y
                }
                Op::Pow => {
                    if !(0..=64).contains(&y) {
                        return Err(Error::Domain(format!("integer power '{e}' needs an exponent 0..=64")));
                    }
                    x.checked_pow(y as u32).ok_or_else(over)?
                }
            }
        }
        Expr::Fact(a) => {
            let n = eval_int(a, ints)?;
            if n < 0 {
                return Err(Error::Domain(format!("factorial of a negative number in '{e}'")));
            }
            (1..=n).try_fold(1i64, |acc, k| acc.checked_mul(k)).ok_or_else(over)?
        }
        Expr::Call(name, args) if (name == "C" || name == "binom") => {
            let (n, k) = (eval_int(&args[0], ints)?, eval_int(&args[1], ints)?);
            check_index(n)?;
            i64::try_from(crate::bernstein::binomial_signed(n, k)).map_err(|_| over())?
        }
        _ => return Err(Error::Domain(format!("'{e}' is not an integer expression"))),
    })
}

/// Checks an index or exponent against [`MAX_EXPONENT`].
pub fn check_index(n: i64) -> Result<()> {
    if n.abs() > MAX_EXPONENT {
        return Err(Error::TooLarge {
            what: "exponent or index",
            value: n.to_string(),
            limit: MAX_EXPONENT.to_string(),
        });
    }
    Ok(())
}

/// `1` as a rational (used by printing code elsewhere).
pub fn one() -> BigRational {
    BigRational::one()
}

/// `0` as a rational.
pub fn zero() -> BigRational {
    BigRational::zero()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(s: &str) -> Expr {
        parse(s, &[]).unwrap()
    }

    #[test]
    fn precedence_and_implicit_multiplication() {
        assert_eq!(p("2t").to_string(), "2*t");
        assert_eq!(p("-t^2").to_string(), "-t^2");
        assert_eq!(
            p("3k/8"),
            Expr::div(Expr::mul(Expr::int(3), Expr::Var("k".into())), Expr::int(8))
        );
        assert_eq!(p("(1-t)(1+t)").to_string(), "(1 - t)*(1 + t)");
        assert_eq!(p("xy^2").to_string(), "x*y^2");
        assert_eq!(
            p("2^3^2"),
            Expr::pow(Expr::int(2), Expr::pow(Expr::int(3), Expr::int(2)))
        );
        assert_eq!(p("t^-1").to_string(), "t^-1");
        assert_eq!(p("n!/(n-k)!").to_string(), "n!/(n - k)!");
        assert_eq!(p("(a, b)").to_string(), "(a, b)");
        assert_eq!(p("[1, 2; 3, 4]").to_string(), "[1, 2; 3, 4]");
        assert_eq!(p("sum(r, j, n, B(j, r, s))").to_string(), "sum(r, j, n, B(j, r, s))");
        assert_eq!(p("b'(t)").to_string(), "b'(t)");
    }

    #[test]
    fn clear_errors() {
        for (bad, want) in [
            ("(1 + t", "expected ')'"),
            ("1 + ", "unexpected end"),
            ("B(1, 2)", "B needs 3 arguments"),
            ("sqrt", "needs arguments"),
            ("t $ 2", "unexpected character"),
            ("sum(1, 0, 3, t)", "must be a variable"),
            ("1 2)", "unexpected ')'"),
        ] {
            let msg = parse(bad, &[]).unwrap_err().to_string();
            assert!(msg.contains(want), "{bad}: {msg}");
        }
        let deep = "(".repeat(1000) + "t" + &")".repeat(1000);
        assert!(parse(&deep, &[]).is_err());
    }

    #[test]
    fn definitions_and_derivatives() {
        let d = parse_definition("e(i) = i/(n+1)*b[i-1]", &[]).unwrap();
        // `e` is declared (as claims declare their definitions); undeclared, `e(2)` is `e·2`.
        assert_eq!(p("e(2)").to_string(), "e*2");
        let e = expand(&parse("e(2) + e(j)", &["e".to_string()]).unwrap(), &[d]).unwrap();
        assert_eq!(e.to_string(), "2/(n + 1)*b[2 - 1] + j/(n + 1)*b[j - 1]");
        let dd = expand_diffs(&p("diff(t^3, t)"), &[]).unwrap();
        assert!(dd.to_string().contains("__dpow(t, 3, 1)"), "{dd}");
    }

    #[test]
    fn substitution_renames_a_binder_instead_of_capturing() {
        // e(x) = sum(j, 0, 1, x) applied to j: the inner j must not capture the argument.
        let body = p("sum(j, 0, 1, x)");
        let out = substitute(&body, &["x".to_string()], &[p("j")]);
        assert_eq!(out.to_string(), "sum(j_1, 0, 1, j)");
        // A binder the argument does not mention is kept; a shadowed parameter is not replaced.
        assert_eq!(
            substitute(&body, &["x".to_string()], &[p("k")]).to_string(),
            "sum(j, 0, 1, k)"
        );
        assert_eq!(
            substitute(&p("sum(x, 0, 1, x)"), &["x".to_string()], &[p("j")]).to_string(),
            "sum(x, 0, 1, x)"
        );
        // The fresh name avoids every name in sight.
        let out = substitute(&p("sum(j, 0, j_1, x + j_1)"), &["x".to_string()], &[p("j")]);
        assert_eq!(out.to_string(), "sum(j_2, 0, j_1, j + j_1)");
    }

    #[test]
    fn expansion_renames_a_binder_a_definition_uses() {
        let known = ["D".to_string()];
        let d = parse_definition("D = t + 1", &known).unwrap();
        let e = expand(&parse("sum(t, 0, 1, D)", &known).unwrap(), &[d]).unwrap();
        assert_eq!(e.to_string(), "sum(t_1, 0, 1, t + 1)");
    }

    #[test]
    fn definitions_are_ordered_by_dependency() {
        let known: Vec<String> = ["D", "F", "G"].iter().map(|s| s.to_string()).collect();
        let defs = vec![
            parse_definition("D = diff(F, t)", &known).unwrap(),
            parse_definition("F = G^2", &known).unwrap(),
            parse_definition("G = t + 1", &known).unwrap(),
        ];
        let names: Vec<String> = dependency_order(defs).unwrap().into_iter().map(|d| d.name).collect();
        assert_eq!(names, ["G", "F", "D"]);
        let cyclic = vec![
            parse_definition("F = G", &known).unwrap(),
            parse_definition("G = F + 1", &known).unwrap(),
        ];
        assert!(dependency_order(cyclic).unwrap_err().to_string().contains("circular"));
        let selfref = vec![parse_definition("F = F + 1", &known).unwrap()];
        assert!(dependency_order(selfref).is_err());
        // A parameter named like another definition is the parameter.
        let defs = vec![
            parse_definition("e(F) = F + 1", &known).unwrap(),
            parse_definition("F = e(2)", &known).unwrap(),
        ];
        assert!(dependency_order(defs).is_ok());
    }

    #[test]
    fn integer_evaluation() {
        let mut ints = BTreeMap::new();
        ints.insert("n".to_string(), 5);
        assert_eq!(eval_int(&p("n!/(n-2)!"), &ints).unwrap(), 20);
        assert_eq!(eval_int(&p("C(n, 2)"), &ints).unwrap(), 10);
        assert!(eval_int(&p("n/2"), &ints).is_err());
        assert!(eval_int(&p("t"), &ints).is_err());
        assert!(eval_int(&p("30!"), &ints).is_err());
        let r = closed_range(&IntRange::parse("j = 0..=n").unwrap()).unwrap();
        assert_eq!(r.var, "j");
    }
}
