//! The context a claim's expressions are parsed in: its declarations, definitions (expanded,
//! `diff` applied) and integer ranges.

use super::claims::Decls;
use super::kernel::expr::{self, check_index, Expr};
use super::methods::{NetMethod, PolygonMethod};
use super::parse::parse;
use super::parse::{closed_range, ClosedRange};
use super::rewrite;
use super::rewrite::{parse_definition, Definition};
use crate::error::{Error, Result};
use std::collections::BTreeMap;

// ---------------------------------------------------------------------------------------
// Claim context: parsed definitions, ranges, objects.

/// A claim prepared for checking.
pub struct Ctx<'c> {
    /// The claim's id (for messages).
    pub id: &'c str,
    /// What the expressions may use.
    pub decls: &'c Decls,
    /// Names the kind itself binds (an implicit claim's coordinates, a power form's parameter).
    bound_by_kind: Vec<String>,
    /// Names kept whole by the parser.
    pub known: Vec<String>,
    /// Definitions, already expanded and differentiated.
    pub defs: Vec<Definition>,
    /// Integer ranges.
    pub ranges: Vec<ClosedRange>,
}

impl<'c> Ctx<'c> {
    /// The context of a claim's declarations; `bound_by_kind` are names the claim's kind binds.
    pub fn new(id: &'c str, decls: &'c Decls, bound_by_kind: Vec<String>) -> Result<Self> {
        let mut known = decls.known_names();
        known.extend(PolygonMethod::ALL.iter().map(|m| m.name().to_string()));
        known.extend(NetMethod::ALL.iter().map(|m| m.name().to_string()));
        let parsed = decls
            .defs
            .iter()
            .map(|d| parse_definition(d, &known))
            .collect::<Result<Vec<_>>>()?;
        let ranges = decls.ranges.iter().map(closed_range).collect::<Result<Vec<_>>>()?;
        let mut ctx = Ctx {
            id,
            decls,
            bound_by_kind,
            known,
            defs: Vec::new(),
            ranges,
        };
        // In dependency order, each body expanded with the definitions it uses (so `diff`
        // sees the whole expression, never an undefined name).
        for mut def in rewrite::dependency_order(parsed)? {
            let expanded = rewrite::expand(&def.body, &ctx.defs)?;
            ctx.check_names(&expanded, &def.params)?;
            def.body = rewrite::expand_diffs(&expanded, &ctx.int_names())?;
            ctx.defs.push(def);
        }
        Ok(ctx)
    }

    /// Parses an expression of the claim, with definitions and `diff` expanded.
    pub fn expr(&self, text: &str) -> Result<Expr> {
        let e = parse(text, &self.known)?;
        let e = rewrite::expand(&e, &self.defs)?;
        self.check_names(&e, &[])?;
        rewrite::expand_diffs(&e, &self.int_names())
    }

    /// The claim's integer names (its range variables), which `diff` may not take.
    fn int_names(&self) -> Vec<String> {
        self.ranges.iter().map(|r| r.var.clone()).collect()
    }

    /// When the claim lists its parameters (`vars`), every free name must be declared: an
    /// unknown name is an error, never silently a constant (whose derivative would be 0).
    fn check_names(&self, e: &Expr, local: &[String]) -> Result<()> {
        let Some(vars) = &self.decls.vars else {
            return Ok(());
        };
        for v in e.free_vars() {
            let known = vars.contains(&v)
                || local.contains(&v)
                || self.is_bound(&v)
                || self.bound_by_kind.contains(&v)
                || self.defs.iter().any(|d| d.name == v);
            if !known {
                return Err(Error::Domain(format!(
                    "unknown name '{v}' in '{e}' (declare it: vars, symbols, for, let, …)"
                )));
            }
        }
        Ok(())
    }

    /// Parses `A = B` into `(A, B)`, or `A` into `(A, 0)`.
    pub fn equation(&self, text: &str) -> Result<(Expr, Expr)> {
        match text.split_once('=') {
            Some((a, b)) => Ok((self.expr(a)?, self.expr(b)?)),
            None => Ok((self.expr(text)?, Expr::int(0))),
        }
    }

    /// Every assignment of the integer range variables (a single empty one without ranges).
    pub fn instances(&self) -> Result<Vec<BTreeMap<String, i64>>> {
        let mut out = vec![BTreeMap::new()];
        for r in &self.ranges {
            let mut next = Vec::new();
            for inst in &out {
                let (a, b) = (expr::eval_int(&r.from, inst)?, expr::eval_int(&r.to, inst)?);
                check_index(a)?;
                check_index(b)?;
                if b < a {
                    let at: Vec<String> = inst.iter().map(|(k, v)| format!("{k} = {v}")).collect();
                    return Err(Error::Domain(format!(
                        "the range {} = {a}..={b} is empty{}: a claim over an empty range says nothing",
                        r.var,
                        if at.is_empty() {
                            String::new()
                        } else {
                            format!(" (at {})", at.join(", "))
                        }
                    )));
                }
                for k in a..=b {
                    let mut i = inst.clone();
                    i.insert(r.var.clone(), k);
                    next.push(i);
                }
            }
            out = next;
            if out.len() > 100_000 {
                return Err(Error::TooLarge {
                    what: "number of range instances",
                    value: out.len().to_string(),
                    limit: "100000".into(),
                });
            }
        }
        Ok(out)
    }

    /// Describes the ranges, e.g. `n = 0..=10, j = 0..=n`.
    pub fn range_text(&self) -> String {
        self.decls
            .ranges
            .iter()
            .map(|r| r.to_string())
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// Whether `name` is declared (a range variable, symbol, vector, curve, surface, polygon or net).
    pub fn is_bound(&self, name: &str) -> bool {
        self.ranges.iter().any(|r| r.var == name)
            || self.decls.symbols.iter().flatten().any(|s| s == name)
            || self.decls.vectors.iter().any(|v| v.contains_key(name))
            || self.decls.curves.iter().any(|c| c.contains_key(name))
            || self.decls.surfaces.iter().any(|c| c.contains_key(name))
            || self.decls.polygon.as_ref().is_some_and(|p| p.name == name)
            || self.decls.net.as_ref().is_some_and(|p| p.name == name)
    }

    /// The continuous parameters of some expressions: the `vars` field, or every free name not
    /// bound otherwise.
    pub fn params(&self, exprs: &[&Expr]) -> Vec<String> {
        if let Some(v) = &self.decls.vars {
            return v.clone();
        }
        let mut out: Vec<String> = Vec::new();
        for e in exprs {
            for v in e.free_vars() {
                if !self.is_bound(&v) && !out.contains(&v) {
                    out.push(v);
                }
            }
        }
        out
    }

    /// Whether the claim is decided by symbolic expansion (it declares symbols or vectors).
    pub fn symbolic(&self) -> bool {
        self.decls.symbolic()
    }
}

#[cfg(test)]
mod tests {
    use super::super::claims::test_claim as claim;
    use super::*;

    #[test]
    fn ranges_enumerate_every_case_and_refuse_empty_ones() {
        let c = claim("for = [\"n = 0..=2\", \"j = 0..=n\"]");
        let ctx = Ctx::new(&c.id, &c.decls, Vec::new()).unwrap();
        assert_eq!(ctx.instances().unwrap().len(), 6);
        assert_eq!(ctx.range_text(), "n = 0..=2, j = 0..=n");
        let c = claim("for = [\"n = 0..=2\", \"j = 1..=n\"]");
        let err = Ctx::new(&c.id, &c.decls, Vec::new())
            .unwrap()
            .instances()
            .unwrap_err()
            .to_string();
        assert!(err.contains("j = 1..=0 is empty (at n = 0)"), "{err}");
    }

    #[test]
    fn unknown_names_are_errors_when_the_parameters_are_listed() {
        let c = claim("vars = [\"t\"]\nsymbols = [\"k\"]");
        let ctx = Ctx::new(&c.id, &c.decls, Vec::new()).unwrap();
        assert!(ctx.expr("t + k").is_ok());
        assert!(ctx.expr("sum(j, 0, 2, j t)").is_ok());
        let err = ctx.expr("t + q").unwrap_err().to_string();
        assert!(err.contains("unknown name 'q'"), "{err}");
        // Without `vars`, free names are the parameters (documented).
        let c = claim("");
        assert!(Ctx::new(&c.id, &c.decls, Vec::new()).unwrap().expr("t + q").is_ok());
    }
}
