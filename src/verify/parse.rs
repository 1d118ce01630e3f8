//! The parser of expressions written as in a book.
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
//! first argument, `v` by the second; see [`super::kernel::expr::split_partial`]).

use super::claims::IntRange;
use super::kernel::expr::*;
use crate::error::{Error, Result};
use crate::scalar::parse_exact;
use num_rational::BigRational;

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
    check_tree_depth(e.depth())?;
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
        let mut depth = acc.depth();
        loop {
            // A chain grows the tree by one level per term, without nesting the parser: its
            // depth is checked as it grows, so no longer chain is ever built.
            let op: fn(Expr, Expr) -> Expr = if self.peek_sym('+') {
                Expr::add
            } else if self.peek_sym('-') {
                Expr::sub
            } else {
                return Ok(acc);
            };
            self.pos += 1;
            let rhs = self.term()?;
            depth = chain_depth(depth, &rhs)?;
            acc = op(acc, rhs);
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
        let mut depth = acc.depth();
        loop {
            let (op, rhs): (fn(Expr, Expr) -> Expr, Expr) = if self.peek_sym('*') {
                self.pos += 1;
                (Expr::mul, self.unary()?)
            } else if self.peek_sym('/') {
                self.pos += 1;
                (Expr::div, self.unary()?)
            } else if self.starts_primary() {
                // implicit multiplication: 2t, 4x^2, (1-t)(1+t)
                (Expr::mul, self.power()?)
            } else {
                return Ok(acc);
            };
            depth = chain_depth(depth, &rhs)?;
            acc = op(acc, rhs);
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
        let mut depth = e.depth();
        while self.peek_sym('!') {
            self.pos += 1;
            depth += 1;
            check_tree_depth(depth)?;
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

/// The depth of a chain `acc op rhs`, given the depth of `acc`; an error past
/// [`MAX_TREE_DEPTH`].
fn chain_depth(acc: usize, rhs: &Expr) -> Result<usize> {
    let depth = 1 + acc.max(rhs.depth());
    check_tree_depth(depth)?;
    Ok(depth)
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
