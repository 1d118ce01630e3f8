//! Identities by exact symbolic expansion: every scalar symbol and every vector coordinate an
//! independent variable, both sides evaluated as rational functions in them, and the cleared
//! difference of each pair of entries compared with the zero polynomial.

use super::eval::{check_symbolic_degrees, Deg, Env, Evaluator, Value};
use super::expr::Expr;
use super::poly::{Poly, RatFunc};
use crate::error::{Error, Result};
use num_rational::BigRational;
use std::collections::{BTreeMap, BTreeSet};
use std::rc::Rc;

/// The symbolic environment: each symbol of a layout its own variable (a vector `v` of `dim`
/// coordinates the variables `v_1, …, v_dim`).
pub struct SymEnv {
    vars: BTreeMap<String, Value<RatFunc>>,
}

impl Env<RatFunc> for SymEnv {
    fn var(&self, name: &str) -> Option<Value<RatFunc>> {
        self.vars.get(name).cloned()
    }
    fn call(&self, _: &str, _: &[Expr], _: &mut Evaluator<'_, RatFunc>) -> Result<Option<Value<RatFunc>>> {
        Ok(None)
    }
    fn index(&self, _: &str, _: &[i64]) -> Result<Option<Value<RatFunc>>> {
        Ok(None)
    }
}

/// The variables of `layout` (symbols with their dimension, 0 for a scalar), in order, and the
/// environment giving each symbol its own; an error when a name occurs twice.
pub fn sym_env(layout: &[(String, usize)]) -> Result<(Rc<[String]>, SymEnv)> {
    let mut names: Vec<String> = Vec::new();
    for (v, dim) in layout {
        if *dim == 0 {
            names.push(v.clone());
        } else {
            names.extend((1..=*dim).map(|k| format!("{v}_{k}")));
        }
    }
    let distinct: BTreeSet<&String> = names.iter().chain(layout.iter().map(|(v, _)| v)).collect();
    let scalars = layout.iter().filter(|(_, d)| *d == 0).count();
    if distinct.len() != names.len() + layout.len() - scalars {
        return Err(Error::Domain("a symbol of the expansion is named twice".into()));
    }
    let names: Rc<[String]> = Rc::from(names);
    let mut vars = BTreeMap::new();
    let mut k = 0;
    for (v, dim) in layout {
        if *dim == 0 {
            vars.insert(v.clone(), Value::S(RatFunc::poly(Poly::var(&names, k))));
            k += 1;
        } else {
            let comps = (0..*dim).map(|i| RatFunc::poly(Poly::var(&names, k + i))).collect();
            vars.insert(v.clone(), Value::V(comps));
            k += dim;
        }
    }
    Ok((names, SymEnv { vars }))
}

fn layout_degrees(layout: &[(String, usize)]) -> BTreeMap<String, Value<Deg>> {
    layout
        .iter()
        .map(|(v, dim)| {
            let d = if *dim == 0 {
                Value::S(Deg::var(v))
            } else {
                Value::V((1..=*dim).map(|k| Deg::var(&format!("{v}_{k}"))).collect())
            };
            (v.clone(), d)
        })
        .collect()
}

/// A polynomial's terms: exponents (one per variable) and coefficient.
pub type Terms = Vec<(Vec<u16>, BigRational)>;

/// What [`expand`] expanded, as a certificate's data: the variables, the integers' values,
/// both sides, and per pair of entries (up to the first that differ) the terms of the left
/// side's numerator and denominator, then the right side's.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Expansion {
    pub layout: Vec<(String, usize)>,
    pub ints: BTreeMap<String, i64>,
    pub sides: (Expr, Expr),
    pub entries: Vec<[Terms; 4]>,
}

/// `lhs = rhs` expanded here (made only by [`expand`]): the first cleared difference that is
/// not the zero polynomial, if any.
#[derive(Clone, Debug)]
pub struct Expanded {
    difference: Option<Poly>,
    terms: usize,
    /// What was expanded.
    pub record: Expansion,
}

impl Expanded {
    /// The cleared difference of the first pair of entries that differ (`None`: the sides are
    /// equal as rational functions).
    pub fn difference(&self) -> Option<&Poly> {
        self.difference.as_ref()
    }
    /// The number of terms of both sides' numerators, over every entry.
    pub fn terms(&self) -> usize {
        self.terms
    }
}

/// Both sides expanded in the variables of `layout` (the integers `ints` bound), within
/// [`super::eval::MAX_SYMBOLIC_DEGREE`], and compared entry by entry.
pub fn expand(layout: &[(String, usize)], lhs: &Expr, rhs: &Expr, ints: &BTreeMap<String, i64>) -> Result<Expanded> {
    check_symbolic_degrees(layout_degrees(layout), ints, &[lhs, rhs])?;
    let (names, env) = sym_env(layout)?;
    let l = Evaluator::new(&env, ints.clone()).eval(lhs)?;
    let r = Evaluator::new(&env, ints.clone()).eval(rhs)?;
    let (mut entries, mut terms, mut difference) = (Vec::new(), 0, None);
    for (a, b) in l.paired_entries(&r)? {
        entries.push([&a.num, &a.den, &b.num, &b.den].map(|p| p.terms_in(names.len())));
        let d = a.cleared_difference(b);
        if !d.is_zero() {
            difference = Some(d);
            break;
        }
        terms += a.num.len() + b.num.len();
    }
    let record = Expansion {
        layout: layout.to_vec(),
        ints: ints.clone(),
        sides: (lhs.clone(), rhs.clone()),
        entries,
    };
    Ok(Expanded {
        difference,
        terms,
        record,
    })
}

#[cfg(test)]
mod tests {
    use super::super::check_expanded;
    use super::*;

    fn var(v: &str) -> Expr {
        Expr::Var(v.into())
    }

    #[test]
    fn check_expanded_expands_itself() {
        let layout = vec![("x".to_string(), 0), ("y".to_string(), 0)];
        let none = BTreeMap::new();
        let (x, y) = (var("x"), var("y"));
        let square = |e: Expr| Expr::mul(e.clone(), e);
        // (x + y)² = x² + 2xy + y², but not x² + y².
        let lhs = square(Expr::add(x.clone(), y.clone()));
        let cross = Expr::mul(Expr::int(2), Expr::mul(x.clone(), y.clone()));
        let rhs = Expr::add(Expr::add(square(x.clone()), cross), square(y.clone()));
        let good = expand(&layout, &lhs, &rhs, &none).unwrap();
        let bad = expand(&layout, &lhs, &Expr::add(square(x.clone()), square(y.clone())), &none).unwrap();
        assert!(good.difference().is_none() && bad.difference().is_some());
        assert!(check_expanded(std::slice::from_ref(&good)).is_some());
        assert!(check_expanded(&[good.clone(), bad]).is_none());
        assert!(check_expanded(&[]).is_none());
        // x and y read as one variable would make x − y = 0: a name twice is refused.
        let twice = vec![("x".to_string(), 0), ("x".to_string(), 0)];
        assert!(expand(&twice, &x, &y, &none).is_err());
        let clash = vec![("v_1".to_string(), 0), ("v".to_string(), 2)];
        assert!(sym_env(&clash).is_err());
    }
}
