//! The symbol table of a claim with open ranges (its integers: ranges, summation variables,
//! the unit indices) and the domain of its ranges.

use super::super::claims::{Decls, IntRange};
use super::super::context::Ctx;
use super::super::kernel::expr::Expr;
use super::super::kernel::hyper::{Aff, Symbols};
use super::super::kernel::pieces::Domain;
use super::super::{parse, rewrite};
use super::{Translator, UNIT, UNIT2};
use crate::error::{Error, Result};

fn sum_vars(e: &Expr, out: &mut Vec<String>) {
    match e {
        Expr::Sum(v, a, b, body) => {
            if !out.contains(v) {
                out.push(v.clone());
            }
            sum_vars(a, out);
            sum_vars(b, out);
            sum_vars(body, out);
        }
        Expr::Neg(a) | Expr::Fact(a) => sum_vars(a, out),
        Expr::Bin(_, a, b) => {
            sum_vars(a, out);
            sum_vars(b, out);
        }
        Expr::Call(_, args) | Expr::Index(_, args) | Expr::Tuple(args) => {
            for a in args {
                sum_vars(a, out);
            }
        }
        Expr::Matrix(rows) => {
            for r in rows {
                for a in r {
                    sum_vars(a, out);
                }
            }
        }
        Expr::Num(_) | Expr::Var(_) => {}
    }
}

/// The certificates, the symbol list (integers: ranges, summation variables, the unit index)
/// and the continuous parameters of a claim with open ranges.
pub(crate) fn prepare(
    certificates: &[String],
    ctx: &Ctx<'_>,
    sides: &[Expr],
) -> Result<(Vec<Expr>, Symbols, Vec<String>)> {
    let rs = &ctx.decls.ranges;
    let certs: Vec<Expr> = certificates
        .iter()
        .map(|c| parse::parse(c, &ctx.known).and_then(|e| rewrite::expand(&e, &ctx.defs)))
        .collect::<Result<_>>()?;
    let refs: Vec<&Expr> = sides.iter().chain(&certs).collect();
    let mut ints: Vec<String> = rs.iter().map(|r| r.var.clone()).collect();
    for e in &refs {
        let mut found = Vec::new();
        sum_vars(e, &mut found);
        for v in found {
            if ints.contains(&v) {
                if rs.iter().any(|r| r.var == v) {
                    return Err(Error::Domain(format!(
                        "the summation variable {v} shadows a range variable"
                    )));
                }
            } else {
                ints.push(v);
            }
        }
    }
    if ctx.decls.polygon.is_some() || ctx.decls.net.is_some() {
        ints.push(UNIT.into());
    }
    if ctx.decls.net.is_some() {
        ints.push(UNIT2.into());
    }
    let conts: Vec<String> = ctx
        .params(&refs[..sides.len()])
        .into_iter()
        .filter(|v| !ints.contains(v))
        .collect();
    // The variables of integration are parameters of the integrands only.
    let mut all = conts.clone();
    for e in &refs {
        super::super::kernel::beta::integral_vars(e, &mut all);
    }
    let all: Vec<String> = all.into_iter().filter(|v| !ints.contains(v)).collect();
    let sym = Symbols::new(&ints, &all);
    Ok((certs, sym, conts))
}

impl Translator<'_> {
    /// The domain of the ranges (and records the polygon).
    pub(crate) fn domain(&mut self, decls: &Decls, rs: &[IntRange]) -> Result<Domain> {
        let mut dom = Domain::default();
        for r in rs {
            let v = Aff::var(&r.var);
            let from = self.aff(&parse::parse(&r.from, &[])?)?;
            dom = dom.with(v.minus(&from));
            if let Some(to) = &r.to {
                let to = self.aff(&parse::parse(to, &[])?)?;
                dom = dom.with(to.minus(&v));
            }
        }
        if let Some(p) = &decls.polygon {
            let deg = self.aff(&parse::parse(&p.degree, &[])?)?;
            self.polygon = Some((p.name.clone(), deg));
        }
        if let Some(net) = &decls.net {
            let m = self.aff(&parse::parse(&net.degree[0], &[])?)?;
            let n = self.aff(&parse::parse(&net.degree[1], &[])?)?;
            self.net = Some((net.name.clone(), m, n));
        }
        Ok(dom)
    }
}
