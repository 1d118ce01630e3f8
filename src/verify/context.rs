//! The context a claim's expressions are parsed in: its declarations, definitions (expanded,
//! `diff` applied) and integer ranges.
//!
//! A claim is elaborated once ([`Ctx::new`]): its definitions are parsed, put in dependency
//! order, expanded and differentiated there and nowhere else. The contexts of the claim's
//! cases are made from that one by typed changes that parse no definition again: other
//! ranges ([`Ctx::with_ranges`], e.g. the open ranges closed after a few values, an induction's
//! base and step) or, for a claim without definitions, declarations written by its kind
//! ([`Ctx::with_declarations`], a theorem's parts).

use super::claims::{close_ranges, Decls, IntRange};
use super::kernel::expr::{self, check_index, Expr};
use super::methods::{NetMethod, PolygonMethod};
use super::parse::parse;
use super::rewrite;
use super::rewrite::{parse_definition, Definition};
use crate::error::{Error, Result};
use std::borrow::Cow;
use std::collections::BTreeMap;
use std::rc::Rc;

// ---------------------------------------------------------------------------------------
// Claim context: parsed definitions, ranges, objects.

/// A claim prepared for checking.
#[derive(Clone)]
pub struct Ctx<'c> {
    /// The claim's id (for messages).
    pub id: &'c str,
    /// What the expressions may use (the claim's own, or those of a case of it).
    pub decls: Cow<'c, Decls>,
    /// Names the kind itself binds (an implicit claim's coordinates, a power form's parameter).
    bound_by_kind: Vec<String>,
    /// Names kept whole by the parser.
    pub known: Vec<String>,
    /// Definitions, already expanded and differentiated (shared by the cases of the claim).
    pub defs: Rc<[Definition]>,
    /// Each definition's body expanded before `diff`, with its parameters: the names a case
    /// with fewer range variables checks again.
    expanded: Rc<[(Expr, Vec<String>)]>,
    /// Integer ranges, their bounds parsed (`to` is `None` for an open range).
    ranges: Vec<Bounds>,
    /// Whether the checks keep what only a certificate file needs (the sampled sides written
    /// out without the claim's objects): `prove` without `--certificates` skips that work.
    pub(crate) certify: bool,
}

/// An integer range with its bounds parsed.
#[derive(Clone)]
struct Bounds {
    var: String,
    from: Expr,
    to: Option<Expr>,
}

fn bounds(ranges: &[IntRange]) -> Result<Vec<Bounds>> {
    ranges
        .iter()
        .map(|r| {
            Ok(Bounds {
                var: r.var.clone(),
                from: parse(&r.from, &[])?,
                to: r.to.as_deref().map(|to| parse(to, &[])).transpose()?,
            })
        })
        .collect()
}

/// The names the parser keeps whole for `decls`.
fn known_names(decls: &Decls) -> Vec<String> {
    let mut known = decls.known_names();
    known.extend(PolygonMethod::ALL.iter().map(|m| m.name().to_string()));
    known.extend(NetMethod::ALL.iter().map(|m| m.name().to_string()));
    known
}

impl<'c> Ctx<'c> {
    /// Elaborates a claim's declarations: its own, or those its kind lowers it to (its own
    /// and the kind's objects, e.g. the curve with a power form's printed points);
    /// `bound_by_kind` are names the claim's kind binds.
    pub fn new(id: &'c str, decls: Cow<'c, Decls>, bound_by_kind: Vec<String>) -> Result<Self> {
        count_elaboration();
        let known = known_names(&decls);
        let parsed = decls
            .defs
            .iter()
            .map(|d| parse_definition(d, &known))
            .collect::<Result<Vec<_>>>()?;
        let ranges = bounds(&decls.ranges)?;
        let mut ctx = Ctx {
            id,
            decls,
            bound_by_kind,
            known,
            defs: Rc::from(Vec::new()),
            expanded: Rc::from(Vec::new()),
            ranges,
            certify: true,
        };
        // In dependency order, each body expanded with the definitions it uses (so `diff`
        // sees the whole expression, never an undefined name).
        let mut defs: Vec<Definition> = Vec::new();
        let mut expanded = Vec::new();
        for mut def in rewrite::dependency_order(parsed)? {
            let body = rewrite::expand(&def.body, &defs)?;
            ctx.check_names(&body, &def.params, &defs)?;
            def.body = rewrite::expand_diffs(&body, &ctx.int_names())?;
            expanded.push((body, def.params.clone()));
            defs.push(def);
        }
        ctx.defs = Rc::from(defs);
        ctx.expanded = Rc::from(expanded);
        Ok(ctx)
    }

    /// The context of a case of the claim over other integer ranges: the definitions are not
    /// parsed again; their names are checked against the new range variables as elaborating
    /// the case anew would (`diff` by a range variable was refused by the claim's own).
    pub fn with_ranges(&self, ranges: Vec<IntRange>) -> Result<Ctx<'c>> {
        let parsed = bounds(&ranges)?;
        let decls = Decls {
            ranges,
            ..Decls::clone(&self.decls)
        };
        let ctx = Ctx {
            id: self.id,
            decls: Cow::Owned(decls),
            bound_by_kind: self.bound_by_kind.clone(),
            known: self.known.clone(),
            defs: Rc::clone(&self.defs),
            expanded: Rc::clone(&self.expanded),
            ranges: parsed,
            certify: self.certify,
        };
        for (k, (body, params)) in ctx.expanded.iter().enumerate() {
            ctx.check_names(body, params, &ctx.defs[..k])?;
        }
        Ok(ctx)
    }

    /// The context with each open range closed after `extra` values past its first.
    pub fn closed_after(&self, extra: i64) -> Result<Ctx<'c>> {
        self.with_ranges(close_ranges(&self.decls.ranges, extra))
    }

    /// The context of declarations a claim's kind writes for it (a theorem's parts, each a
    /// claim over a symbolic polygon): only for a claim without definitions, and declarations
    /// without definitions, so that nothing is parsed but range bounds.
    pub fn with_declarations(&self, decls: Decls) -> Result<Ctx<'c>> {
        if !self.defs.is_empty() || !decls.defs.is_empty() {
            return Err(Error::Domain(format!(
                "claim {}: declarations written by the kind take no definitions",
                self.id
            )));
        }
        Ok(Ctx {
            id: self.id,
            known: known_names(&decls),
            ranges: bounds(&decls.ranges)?,
            decls: Cow::Owned(decls),
            bound_by_kind: self.bound_by_kind.clone(),
            defs: Rc::clone(&self.defs),
            expanded: Rc::clone(&self.expanded),
            certify: self.certify,
        })
    }

    /// Parses an expression of the claim, with definitions and `diff` expanded.
    pub fn expr(&self, text: &str) -> Result<Expr> {
        let e = parse(text, &self.known)?;
        let e = rewrite::expand(&e, &self.defs)?;
        self.check_names(&e, &[], &self.defs)?;
        rewrite::expand_diffs(&e, &self.int_names())
    }

    /// The claim's integer names (its range variables), which `diff` may not take.
    fn int_names(&self) -> Vec<String> {
        self.ranges.iter().map(|r| r.var.clone()).collect()
    }

    /// When the claim lists its parameters (`vars`), every free name must be declared: an
    /// unknown name is an error, never silently a constant (whose derivative would be 0).
    /// `defs` are the definitions the name may be (those before it, in a definition).
    fn check_names(&self, e: &Expr, local: &[String], defs: &[Definition]) -> Result<()> {
        let Some(vars) = &self.decls.vars else {
            return Ok(());
        };
        for v in e.free_vars() {
            let known = vars.contains(&v)
                || local.contains(&v)
                || self.is_bound(&v)
                || self.bound_by_kind.contains(&v)
                || defs.iter().any(|d| d.name == v);
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
        for (r, written) in self.ranges.iter().zip(&self.decls.ranges) {
            let to = r
                .to
                .as_ref()
                .ok_or_else(|| Error::Parse(format!("the range '{written}' is open: it has no cases to enumerate")))?;
            let mut next = Vec::new();
            for inst in &out {
                let (a, b) = (expr::eval_int(&r.from, inst)?, expr::eval_int(to, inst)?);
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

/// Counts an elaboration: nothing outside tests.
#[cfg(not(test))]
fn count_elaboration() {}

// (after the code: `tests/layers.rs` reads a file's imports up to its first test item)
#[cfg(test)]
thread_local! {
    /// How many claims were elaborated ([`Ctx::new`]) on this thread: tests count them per claim.
    static ELABORATIONS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

#[cfg(test)]
fn count_elaboration() {
    ELABORATIONS.with(|n| n.set(n.get() + 1));
}

/// How many times [`Ctx::new`] ran on this thread.
#[cfg(test)]
pub(crate) fn elaborations() -> usize {
    ELABORATIONS.with(std::cell::Cell::get)
}

#[cfg(test)]
mod tests {
    use super::super::claims::test_claim as claim;
    use super::*;

    #[test]
    fn ranges_enumerate_every_case_and_refuse_empty_ones() {
        let c = claim("for = [\"n = 0..=2\", \"j = 0..=n\"]");
        let ctx = Ctx::new(&c.id, Cow::Borrowed(&c.decls), Vec::new()).unwrap();
        assert_eq!(ctx.instances().unwrap().len(), 6);
        assert_eq!(ctx.range_text(), "n = 0..=2, j = 0..=n");
        let c = claim("for = [\"n = 0..=2\", \"j = 1..=n\"]");
        let err = Ctx::new(&c.id, Cow::Borrowed(&c.decls), Vec::new())
            .unwrap()
            .instances()
            .unwrap_err()
            .to_string();
        assert!(err.contains("j = 1..=0 is empty (at n = 0)"), "{err}");
    }

    #[test]
    fn a_case_of_a_claim_reads_as_the_case_elaborated_anew() {
        let c = claim("vars = [\"t\"]\nfor = [\"n = 1..\", \"j = 0..=n\"]\nlet = [\"f(x) = x^n + diff(x^2 t, t)\"]");
        let ctx = Ctx::new(&c.id, Cow::Borrowed(&c.decls), Vec::new()).unwrap();
        let err = ctx.instances().unwrap_err().to_string();
        assert!(err.contains("the range 'n = 1..' is open"), "{err}");
        let closed = ctx.closed_after(2).unwrap();
        let decls = Decls {
            ranges: close_ranges(&c.decls.ranges, 2),
            ..c.decls.clone()
        };
        let fresh = Ctx::new(&c.id, Cow::Borrowed(&decls), Vec::new()).unwrap();
        for text in ["f(t) + j", "sum(k, 0, n, f(k t))"] {
            assert_eq!(closed.expr(text).unwrap(), fresh.expr(text).unwrap(), "{text}");
        }
        assert_eq!(
            closed.expr("f(2)").unwrap().to_string(),
            fresh.expr("f(2)").unwrap().to_string()
        );
        // n = 1..=3, j = 0..=n: 2 + 3 + 4 cases.
        assert_eq!(closed.instances().unwrap().len(), 9);
        assert_eq!(closed.instances().unwrap(), fresh.instances().unwrap());
        assert_eq!(closed.range_text(), "n = 1..=(1) + 2, j = 0..=n");
        assert_eq!(closed.range_text(), fresh.range_text());
        // Without the range n the definition's `n` is unknown: the case is refused with the
        // error a fresh elaboration gives.
        let without_n = vec![IntRange::parse("j = 0..=3").unwrap()];
        let decls = Decls {
            ranges: without_n.clone(),
            ..c.decls.clone()
        };
        let (Err(derived), Err(anew)) = (
            ctx.with_ranges(without_n),
            Ctx::new(&c.id, Cow::Borrowed(&decls), Vec::new()),
        ) else {
            panic!("a case without n elaborated");
        };
        assert_eq!(derived.to_string(), anew.to_string());
        assert!(derived.to_string().contains("unknown name 'n'"), "{derived}");
        // A kind's own declarations are for claims without definitions only.
        assert!(ctx.with_declarations(Decls::default()).is_err());
    }

    #[test]
    fn unknown_names_are_errors_when_the_parameters_are_listed() {
        let c = claim("vars = [\"t\"]\nsymbols = [\"k\"]");
        let ctx = Ctx::new(&c.id, Cow::Borrowed(&c.decls), Vec::new()).unwrap();
        assert!(ctx.expr("t + k").is_ok());
        assert!(ctx.expr("sum(j, 0, 2, j t)").is_ok());
        let err = ctx.expr("t + q").unwrap_err().to_string();
        assert!(err.contains("unknown name 'q'"), "{err}");
        // Without `vars`, free names are the parameters (documented).
        let c = claim("");
        assert!(Ctx::new(&c.id, Cow::Borrowed(&c.decls), Vec::new())
            .unwrap()
            .expr("t + q")
            .is_ok());
    }
}
