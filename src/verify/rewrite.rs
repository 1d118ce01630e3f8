//! Rewrites of the expression tree: definitions (`let`) expanded hygienically, substitution
//! that renames a binder instead of capturing, and symbolic differentiation by a real
//! parameter (an integer position depending on it is an error).

use super::kernel::expr::*;
use super::parse::parse;
use crate::error::{Error, Result};
use num_rational::BigRational;
use num_traits::Signed;

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
///
/// The result is at most [`MAX_TREE_DEPTH`] levels deep (a body put in place deepens the tree
/// at that place): the expansion stops with that error as soon as it would go deeper.
pub fn expand(e: &Expr, defs: &[Definition]) -> Result<Expr> {
    expand_depth(e, defs, 0, 1)
}

/// `depth`: definitions expanded around `e`; `level`: the level of `e` in the result.
fn expand_depth(e: &Expr, defs: &[Definition], depth: usize, level: usize) -> Result<Expr> {
    if depth > 64 {
        return Err(Error::Domain(
            "definitions nest more than 64 deep (a recursive definition?)".into(),
        ));
    }
    check_tree_depth(level)?;
    let rec = |x: &Expr| expand_depth(x, defs, depth, level + 1);
    Ok(match e {
        Expr::Var(v) => match defs.iter().find(|d| &d.name == v && d.params.is_empty()) {
            Some(d) => expand_depth(&d.body, defs, depth + 1, level)?,
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
                    expand_depth(&body, defs, depth + 1, level)?
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
pub(crate) fn all_names(e: &Expr, out: &mut Vec<String>) {
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

/// `e` with each child replaced by `f` of it (the first error stops).
pub(crate) fn map_children(e: &Expr, f: &mut dyn FnMut(&Expr) -> Result<Expr>) -> Result<Expr> {
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
    let out = expand_diffs_in(e, &mut scope)?;
    check_tree_depth(out.depth())?;
    Ok(out)
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
                // the product rule copies each factor's siblings: a derivative is at most
                // about size × depth nodes, bounded before it is built
                let work = d.size().saturating_mul(d.depth());
                if work > MAX_DIFF_WORK {
                    return Err(Error::TooLarge {
                        what: "derivative",
                        value: format!("{work} (nodes × depth of the expression differentiated)"),
                        limit: format!("{MAX_DIFF_WORK}, MAX_DIFF_WORK"),
                    });
                }
                d = derive(&d, &var)?;
                // each derivative is taken of the last one: its depth is bounded before
                check_tree_depth(d.depth())?;
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

/// The name of the partial `∂^{ku+kv} x / ∂u^{ku} ∂v^{kv}`: `x_uuv` (`x` itself for 0, 0).
pub fn partial_name(base: &str, ku: usize, kv: usize) -> String {
    if ku + kv == 0 {
        return base.to_string();
    }
    format!("{base}_{}{}", "u".repeat(ku), "v".repeat(kv))
}

#[cfg(test)]
mod tests {
    use super::super::claims::IntRange;
    use super::super::kernel::expr::*;
    use super::super::parse::parse;
    use super::*;
    use std::collections::BTreeMap;

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
        let r = super::super::parse::closed_range(&IntRange::parse("j = 0..=n").unwrap()).unwrap();
        assert_eq!(r.var, "j");
    }
}
