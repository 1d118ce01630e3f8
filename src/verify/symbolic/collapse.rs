//! Control points resolved before translation. On the zero polygon every product with a
//! control point is 0 (so no sum inside it is evaluated). On the unit polygon
//! (`b[ĵ] = 1`, others 0) `Σ_{j=a}^{c} b[j + e] · X(j)` is `X(ĵ − e)` wherever the domain shows
//! `a ≤ ĵ − e ≤ c`; a sum inside `X` then meets the other side of its equality as a closed form
//! (the WZ hint) instead of being evaluated on its own. A sum around such a sum
//! (`Σ_j Σ_r b[j] …`, bounds free of each other) is interchanged first. Only exact rewrites of
//! finite sums are made; where the domain does not show the range condition the sum is kept.

use super::super::kernel::expr::{eval_int, Expr, Op};
use super::super::kernel::hyper::Aff;
use super::super::kernel::pieces::Domain;
use super::super::rewrite::{map_children, substitute};
use super::super::translate::{Translator, UNIT};
use crate::error::Result;
use num_traits::Zero;

/// `e` on the zero polygon (`unit` false) or the unit polygon: see the module documentation.
pub(in crate::verify) fn collapse(
    tr: &mut Translator<'_>,
    e: &Expr,
    polygon: &str,
    unit: bool,
    d: &Domain,
) -> Result<Expr> {
    if unit {
        collapse_unit(tr, e, polygon, d)
    } else {
        Ok(zero_polygon(e, polygon))
    }
}

/// `e` with every product that has a factor `polygon[…]` replaced by 0, and the products and
/// sums of such zeros.
fn zero_polygon(e: &Expr, polygon: &str) -> Expr {
    let is_zero = |f: &Expr| matches!(f, Expr::Num(x) if x.is_zero());
    let mapped = map_children(e, &mut |c| Ok(zero_polygon(c, polygon))).expect("the rewrite cannot fail");
    let mut factors = Vec::new();
    flatten_product(&mapped, &mut factors);
    let zero = factors
        .iter()
        .any(|f| is_zero(f) || matches!(f, Expr::Index(name, _) if name == polygon))
        || matches!(&mapped, Expr::Sum(_, _, _, body) | Expr::Neg(body) if is_zero(body));
    match mapped {
        _ if zero => Expr::int(0),
        Expr::Bin(Op::Add, a, b) if is_zero(&a) => *b,
        Expr::Bin(Op::Add | Op::Sub, a, b) if is_zero(&b) => *a,
        Expr::Bin(Op::Sub, a, b) if is_zero(&a) => Expr::Neg(b),
        Expr::Bin(Op::Div, a, _) if is_zero(&a) => Expr::int(0),
        other => other,
    }
}

/// `e` with every sum over the unit point of `polygon` collapsed where `d` (and the bounds of
/// the sums around it) shows that the unit index is in the sum's range.
fn collapse_unit(tr: &mut Translator<'_>, e: &Expr, polygon: &str, d: &Domain) -> Result<Expr> {
    match e {
        Expr::Sum(v, a, b, body) => {
            let Some(dv) = with_bounds(tr, d, v, a, b) else {
                return Ok(e.clone());
            };
            let body = collapse_unit(tr, body, polygon, &dv)?;
            if let Some(x) = at_unit(tr, v, a, b, &body, polygon, d) {
                return Ok(x);
            }
            // Σ_v Σ_w X = Σ_w Σ_v X when neither range mentions the other variable.
            if let Expr::Sum(w, a2, b2, inner) = &body {
                let free = |x: &Expr, y: &str| !x.mentions(y);
                if w != v && free(a2, v) && free(b2, v) && free(a, w) && free(b, w) {
                    if let Some(dw) = with_bounds(tr, d, w, a2, b2) {
                        if let Some(x) = at_unit(tr, v, a, b, inner, polygon, &dw) {
                            return Ok(Expr::Sum(w.clone(), a2.clone(), b2.clone(), Box::new(x)));
                        }
                    }
                }
            }
            Ok(Expr::Sum(v.clone(), a.clone(), b.clone(), Box::new(body)))
        }
        _ => map_children(e, &mut |c| collapse_unit(tr, c, polygon, d)),
    }
}

/// `d` with `a ≤ v ≤ b`, if both bounds are affine.
fn with_bounds(tr: &mut Translator<'_>, d: &Domain, v: &str, a: &Expr, b: &Expr) -> Option<Domain> {
    let var = Aff::var(v);
    let (lo, hi) = (tr.affine(a).ok()?, tr.affine(b).ok()?);
    Some(d.with(var.minus(&lo)).with(hi.minus(&var)))
}

/// `Σ_{v=a}^{b} body` as its one term on the unit polygon: `body` a product with the factor
/// `polygon[v + e]` (`e` free of `v`) and `a ≤ ĵ − e ≤ b` on `d`; `None` otherwise.
fn at_unit(
    tr: &mut Translator<'_>,
    v: &str,
    a: &Expr,
    b: &Expr,
    body: &Expr,
    polygon: &str,
    d: &Domain,
) -> Option<Expr> {
    let mut factors = Vec::new();
    flatten_product(body, &mut factors);
    let k = factors.iter().position(|f| match f {
        Expr::Index(name, args) if name == polygon && args.len() == 1 => {
            tr.affine(&args[0]).is_ok_and(|idx| idx.coef(v) == 1)
        }
        _ => false,
    })?;
    let Expr::Index(_, args) = factors[k] else {
        unreachable!("found above")
    };
    let offset = substitute(&args[0], &[v.to_string()], &[Expr::int(0)]);
    let unit = Expr::Var(UNIT.to_string());
    let at = match eval_int(&offset, &Default::default()) {
        Ok(0) => unit,
        Ok(c) if c < 0 => Expr::add(unit, Expr::int(-c)),
        Ok(c) => Expr::sub(unit, Expr::int(c)),
        Err(_) => Expr::sub(unit, offset),
    };
    let at_aff = tr.affine(&at).ok()?;
    if at_aff.coef(v) != 0
        || !d.implies_ge(&at_aff.minus(&tr.affine(a).ok()?))
        || !d.implies_ge(&tr.affine(b).ok()?.minus(&at_aff))
    {
        return None;
    }
    let rest = factors
        .iter()
        .enumerate()
        .filter(|(j, _)| *j != k)
        .map(|(_, f)| (*f).clone())
        .reduce(Expr::mul)
        .unwrap_or_else(|| Expr::int(1));
    Some(substitute(&rest, &[v.to_string()], &[at]))
}

fn flatten_product<'e>(e: &'e Expr, out: &mut Vec<&'e Expr>) {
    match e {
        Expr::Bin(Op::Mul, a, b) => {
            flatten_product(a, out);
            flatten_product(b, out);
        }
        _ => out.push(e),
    }
}
