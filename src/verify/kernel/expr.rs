//! Expressions written as in a book: the syntax tree, its printing, and integer evaluation
//! of ranges and indices. The grammar is in `verify::parse`; definitions and `diff` are
//! rewrites of the tree (`verify::rewrite`).
//!
//! Limits: exponents and Bernstein/binomial indices at most [`MAX_EXPONENT`]; at most
//! [`MAX_SUM_TERMS`] terms summed per evaluation; factorials of at most [`MAX_FACTORIAL`];
//! expressions at most [`MAX_EXPR_LEN`] characters, [`MAX_DEPTH`] levels of nesting and
//! [`MAX_TREE_DEPTH`] levels of tree.

use crate::error::{Error, Result};
use num_rational::BigRational;
use num_traits::Signed;
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
/// Deepest tree accepted, after parsing and after definitions and `diff` are expanded. A
/// chain `a + b + … + z` of N terms is a tree N levels deep, and every pass over a tree
/// (rewriting, evaluation, degree bounds, printing) recurses once per level: this bounds the
/// stack those passes use, whatever the parentheses are.
pub const MAX_TREE_DEPTH: usize = 512;

/// Largest nodes × depth of an expression `diff` differentiates (a bound of the derivative's size).
pub const MAX_DIFF_WORK: usize = 1_000_000;

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
#[derive(Clone, Debug, PartialEq, Eq)]
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

    /// The number of levels of the tree (a leaf is 1), counted without recursion so that any
    /// tree can be measured.
    pub fn depth(&self) -> usize {
        let mut deepest = 0;
        let mut stack = vec![(self, 1)];
        while let Some((e, d)) = stack.pop() {
            deepest = deepest.max(d);
            match e {
                Expr::Num(_) | Expr::Var(_) => {}
                Expr::Neg(a) | Expr::Fact(a) => stack.push((a, d + 1)),
                Expr::Bin(_, a, b) => stack.extend([(a.as_ref(), d + 1), (b.as_ref(), d + 1)]),
                Expr::Call(_, args) | Expr::Index(_, args) | Expr::Tuple(args) => {
                    stack.extend(args.iter().map(|a| (a, d + 1)))
                }
                Expr::Sum(_, a, b, body) => {
                    stack.extend([(a.as_ref(), d + 1), (b.as_ref(), d + 1), (body.as_ref(), d + 1)])
                }
                Expr::Matrix(rows) => stack.extend(rows.iter().flatten().map(|a| (a, d + 1))),
            }
        }
        deepest
    }

    /// The number of nodes of the tree.
    pub fn size(&self) -> usize {
        let mut n = 0;
        self.visit(&mut |_| n += 1);
        n
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
        // -p parses as a negation, -p/q as (-p)/q: printed where those would be.
        Expr::Num(r) if r.is_integer() && r.is_negative() => 3,
        Expr::Num(r) if !r.is_integer() => 2,
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
                // a - (b + c) and a / (b * c) keep their parentheses; -x (a negation or a
                // negative integer) after any operator too.
                let negative = match b.as_ref() {
                    Expr::Neg(_) => true,
                    Expr::Num(r) => r.is_integer() && r.is_negative(),
                    _ => false,
                };
                let rb = if negative && *op != Op::Pow { 4 } else { rb };
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

/// `integral(e, t, a, b)` as the binder `sum(t, a, b, e)`, for scoping only.
pub(crate) fn as_binder(args: &[Expr]) -> Expr {
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

/// Checks a tree's depth against [`MAX_TREE_DEPTH`] (`depth`: measured, or a lower bound of it).
pub fn check_tree_depth(depth: usize) -> Result<()> {
    if depth > MAX_TREE_DEPTH {
        return Err(Error::TooLarge {
            what: "expression tree",
            value: format!(
                "more than {MAX_TREE_DEPTH} levels deep (a chain a + b + … of N terms is N levels; write a long sum as sum(…))"
            ),
            limit: format!("{MAX_TREE_DEPTH} levels, MAX_TREE_DEPTH"),
        });
    }
    Ok(())
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

/// The partial-derivative notation of a surface: `x_u`, `x_vv`, `x_uuv`, … is
/// `(x, ku, kv)`, `ku` the count of `u` (the first argument) and `kv` of `v` (the second)
/// after the last `_`; `None` for any other name (`x_uvu` is `(x, 2, 1)`, `x_w` is `None`).
pub fn split_partial(name: &str) -> Option<(&str, usize, usize)> {
    let (base, suffix) = name.rsplit_once('_')?;
    if base.is_empty() || suffix.is_empty() || !suffix.chars().all(|c| c == 'u' || c == 'v') {
        return None;
    }
    let ku = suffix.chars().filter(|&c| c == 'u').count();
    Some((base, ku, suffix.len() - ku))
}
