//! Library objects in proofs for every value: their definitions, and lemmas that stand in for
//! them.
//!
//! The objects of a symbolic polygon `b` are library code: the de Casteljau evaluation `b(g)`,
//! the points `b(i, r, g)` of its scheme (9), the derivatives `b'(g)`, `b''(g)`, … and the
//! forward differences `delta(b, k, j)`. A proof for every n reads them as the texts define
//! them, and replaces one by a formula only through a **lemma**: a claim the proof cites
//! (`uses`), proved for every value, whose left side is the object applied to its variables
//! (`b(i, r, t) = sum(j, 0, r, b[i+j]*B(j, r, t))`). Each place a lemma is applied must lie in
//! the lemma's ranges: that is an [`Obligation`], shown by the prover over the claim's domain
//! (with the bounds of the sums around the place), never assumed.
//!
//! What the engine takes as the objects' definitions, from text 000:
//! - `b(g)` is `b(0, n, g)`, the last point of the scheme (9), `n` the polygon's degree;
//! - `b'(g)`, `b''(g)`, … are the derivatives of `b(x)` at `x = g`;
//! - `b(i, r, g)`: `b(i, 0, g) = b[i]`, `b(i, r, g) = (1 − g) b(i, r−1, g) + g b(i+1, r−1, g)` (9),
//!   for `0 ≤ r ≤ n`, `0 ≤ i ≤ n − r`;
//! - `delta(b, k, j)`: `Δ⁰b_j = b[j]`, `Δᵏb_j = Δᵏ⁻¹b_{j+1} − Δᵏ⁻¹b_j`, for `0 ≤ k ≤ n`,
//!   `0 ≤ j ≤ n − k`.
//!
//! The two recursions are unfolded only by an induction ([`unfold`]); the evaluation and the
//! derivatives are read through the scheme, so a formula for any of them comes from a lemma.

use super::claims::{Claim, Decls, Identity, Sides};
use super::context::Ctx;
use super::kernel::certificate::Symbolic;
use super::kernel::expr::Expr;
use super::rewrite::{all_names, derive, map_children, substitute};
use crate::error::{Error, Result};

/// How deep objects may be read through other objects and lemmas (a lemma whose formula
/// uses the object it stands for would never end).
const MAX_REWRITES: usize = 16;

/// A library object of the symbolic polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Object {
    /// `b(i, r, g)`: a point of the de Casteljau scheme (9).
    Scheme,
    /// `b(g)`: the de Casteljau evaluation.
    Evaluation,
    /// `b'(g)`, `b''(g)`, …: the derivative of that order.
    Derivative(usize),
    /// `delta(b, k, j)`: the forward difference Δᵏb_j.
    Differences,
}

impl Object {
    /// The object `e` applies, with its arguments (the polygon's name aside), when `e` is an
    /// object of the polygon `polygon`.
    fn of(e: &Expr, polygon: &str) -> Option<(Object, Vec<Expr>)> {
        let Expr::Call(name, args) = e else { return None };
        if name == "delta" {
            return match args.as_slice() {
                [Expr::Var(p), k, j] if p == polygon => Some((Object::Differences, vec![k.clone(), j.clone()])),
                _ => None,
            };
        }
        let primes = name.len() - name.trim_end_matches('\'').len();
        if &name[..name.len() - primes] != polygon {
            return None;
        }
        match (primes, args.len()) {
            (0, 3) => Some((Object::Scheme, args.clone())),
            (0, 1) => Some((Object::Evaluation, args.clone())),
            (k, 1) if k > 0 => Some((Object::Derivative(k), args.clone())),
            _ => None,
        }
    }

    /// The object applied to `args` on the polygon `polygon`.
    fn apply(self, polygon: &str, args: Vec<Expr>) -> Expr {
        match self {
            Object::Differences => {
                let mut all = vec![Expr::Var(polygon.into())];
                all.extend(args);
                Expr::Call("delta".into(), all)
            }
            Object::Derivative(k) => Expr::Call(format!("{polygon}{}", "'".repeat(k)), args),
            Object::Scheme | Object::Evaluation => Expr::Call(polygon.into(), args),
        }
    }

    /// The argument a recursive definition recurses on (`r` of `b(i, r, g)`, `k` of
    /// `delta(b, k, j)`).
    fn recursion_argument(self) -> Option<usize> {
        match self {
            Object::Scheme => Some(1),
            Object::Differences => Some(0),
            Object::Evaluation | Object::Derivative(_) => None,
        }
    }

    /// Where the object is defined, each condition `≥ 0`, for the polygon of degree `degree`.
    fn defined(self, args: &[Expr], degree: &Expr) -> Vec<Expr> {
        match self {
            // 0 ≤ r ≤ n, 0 ≤ i ≤ n − r (scheme: args i, r, g); 0 ≤ k ≤ n, 0 ≤ j ≤ n − k.
            Object::Scheme | Object::Differences => {
                let (step, at) = if self == Object::Scheme {
                    (&args[1], &args[0])
                } else {
                    (&args[0], &args[1])
                };
                vec![
                    step.clone(),
                    Expr::sub(degree.clone(), step.clone()),
                    at.clone(),
                    Expr::sub(Expr::sub(degree.clone(), step.clone()), at.clone()),
                ]
            }
            Object::Evaluation | Object::Derivative(_) => vec![degree.clone()],
        }
    }

    /// How the report names the object.
    fn phrase(self) -> &'static str {
        match self {
            Object::Scheme => "the scheme point",
            Object::Evaluation => "the de Casteljau evaluation",
            Object::Derivative(_) => "the derivative",
            Object::Differences => "the forward difference",
        }
    }
}

/// One argument of a lemma's object: a variable it binds, or (for an induction hypothesis)
/// exactly one expression.
#[derive(Clone, Debug)]
enum Pattern {
    Bind(String),
    Exactly(String, Expr),
}

/// A proved claim `object(x, …) = formula`, as it stands in for the object.
#[derive(Clone, Debug)]
pub(crate) struct Lemma {
    /// The claim's id.
    pub id: String,
    object: Object,
    pattern: Vec<Pattern>,
    /// The lemma's polygon name and degree variable.
    polygon: String,
    degree: String,
    formula: Expr,
    /// Where it holds: its ranges, each condition `≥ 0`.
    conditions: Vec<Expr>,
    /// The claim's goal as its own certificate states it, when it has one (set by the caller
    /// from the claim's proof): a proof citing the lemma lists it, and `check` compares it with
    /// the lemma's file.
    pub statement: Option<Box<Symbolic>>,
}

/// A condition `≥ 0` that must hold wherever a lemma or a definition was applied: the sums
/// around the place bound their variables (`lo ≤ v ≤ hi`).
#[derive(Clone, Debug)]
pub(crate) struct Obligation {
    pub condition: Expr,
    pub sums: Vec<(String, Expr, Expr)>,
    /// What was applied where (for the error).
    pub what: String,
}

/// Claim sides with the objects replaced, and what that rests on.
#[derive(Debug, Default)]
pub(crate) struct Rewritten {
    pub sides: Vec<Expr>,
    pub obligations: Vec<Obligation>,
    /// The ids of the lemmas applied, in first-use order.
    pub lemmas: Vec<String>,
    /// The definitions read (`b(t) = b(0, n, t)`), in first-use order.
    pub definitions: Vec<String>,
    /// Conditions `≥ 0` the proof may assume beyond the ranges (an induction's base: its
    /// first value is in range).
    pub assumptions: Vec<Expr>,
}

impl Rewritten {
    fn read(&mut self, definition: String) {
        if !self.definitions.contains(&definition) {
            self.definitions.push(definition);
        }
    }
}

impl Lemma {
    /// The lemma a proved claim states: an identity whose left side (first member) is an object
    /// of its polygon applied to distinct variables, each a range variable or a parameter; every
    /// range variable is one of them or the polygon's degree.
    /// `ctx` is the claim's elaborated context.
    pub(crate) fn from_claim(claim: &Claim, ctx: &Ctx<'_>) -> Result<Lemma> {
        let Some(identity) = claim.kind.identity() else {
            return Err(Error::Domain(format!(
                "claim {} cannot serve as a lemma: it is not an identity",
                claim.id
            )));
        };
        Lemma::from_parts(ctx, &identity)
    }

    /// The lemma of an identity in the context of its claim (see [`Lemma::from_claim`]).
    pub(crate) fn from_parts(ctx: &Ctx<'_>, identity: &Identity) -> Result<Lemma> {
        let (id, decls) = (ctx.id, &*ctx.decls);
        let not_a_lemma = |why: &str| Error::Domain(format!("claim {id} cannot serve as a lemma: {why}"));
        let Some(polygon) = &decls.polygon else {
            return Err(not_a_lemma("it declares no polygon"));
        };
        let members = match &identity.sides {
            Sides::Pair(l, r) => vec![l.clone(), r.clone()],
            Sides::Chain(c) => vec![c[0].clone(), c[c.len() - 1].clone()],
        };
        let lhs = ctx.expr(&members[0])?;
        let formula = ctx.expr(&members[1])?;
        let Some((object, args)) = Object::of(&lhs, &polygon.name) else {
            return Err(not_a_lemma("its left side is not an object of its polygon"));
        };
        let degree = polygon.degree.trim().to_string();
        let mut pattern = Vec::new();
        for a in &args {
            match a {
                Expr::Var(v) if !pattern.iter().any(|p| matches!(p, Pattern::Bind(w) if w == v)) && *v != degree => {
                    pattern.push(Pattern::Bind(v.clone()))
                }
                _ => return Err(not_a_lemma("the object's arguments must be distinct variables")),
            }
        }
        let bound = |v: &str| v == degree || pattern.iter().any(|p| matches!(p, Pattern::Bind(w) if w == v));
        let mut conditions = Vec::new();
        for r in &decls.ranges {
            if !bound(&r.var) {
                return Err(not_a_lemma(&format!(
                    "its range variable {} is not an argument of the object",
                    r.var
                )));
            }
            let v = Expr::Var(r.var.clone());
            conditions.push(Expr::sub(v.clone(), ctx.expr(&r.from)?));
            if let Some(to) = &r.to {
                conditions.push(Expr::sub(ctx.expr(to)?, v));
            }
        }
        if !decls.ranges.iter().any(|r| r.var == degree) {
            return Err(not_a_lemma("its polygon's degree must be one of its range variables"));
        }
        if let Some(v) = formula
            .free_vars()
            .into_iter()
            .find(|v| !bound(v) && *v != polygon.name)
        {
            return Err(not_a_lemma(&format!(
                "its formula uses {v}, which is not an argument of the object"
            )));
        }
        Ok(Lemma {
            id: id.to_string(),
            object,
            pattern,
            polygon: polygon.name.clone(),
            degree,
            formula,
            conditions,
            statement: None,
        })
    }

    /// The induction hypothesis of this claim (as a lemma) for the step from `var` to `var + 1`:
    /// it applies only where the object's argument bound to `var` is exactly `var`.
    pub(crate) fn hypothesis(&self, var: &str) -> Result<Lemma> {
        let mut found = false;
        let pattern = self
            .pattern
            .iter()
            .map(|p| match p {
                Pattern::Bind(v) if v == var => {
                    found = true;
                    Pattern::Exactly(v.clone(), Expr::Var(var.into()))
                }
                other => other.clone(),
            })
            .collect();
        if !found {
            return Err(Error::Domain(format!(
                "claim {}: the induction variable {var} must be an argument of the object on the left side",
                self.id
            )));
        }
        Ok(Lemma {
            id: format!("{} (induction hypothesis at {var})", self.id),
            pattern,
            ..self.clone()
        })
    }

    /// The formula at `args` on the polygon `polygon` of degree `degree`, with the conditions
    /// there; `None` when the arguments do not match an `Exactly` pattern.
    fn at(&self, args: &[Expr], polygon: &str, degree: &Expr, avoid: &[String]) -> Option<(Expr, Vec<Expr>)> {
        let mut params = vec![self.degree.clone()];
        let mut values = vec![degree.clone()];
        for (p, a) in self.pattern.iter().zip(args) {
            match p {
                Pattern::Bind(v) => {
                    params.push(v.clone());
                    values.push(a.clone());
                }
                Pattern::Exactly(v, x) => {
                    if a != x {
                        return None;
                    }
                    params.push(v.clone());
                    values.push(a.clone());
                }
            }
        }
        let formula = fresh_binders(&rename_polygon(&self.formula, &self.polygon, polygon), avoid);
        let formula = substitute(&formula, &params, &values);
        let conditions = self
            .conditions
            .iter()
            .map(|c| substitute(c, &params, &values))
            .collect();
        Some((formula, conditions))
    }
}

/// `e` with every summation variable renamed to a name not in `avoid` (nor used in `e`), so a
/// formula placed inside other sums never shadows or captures their variables.
fn fresh_binders(e: &Expr, avoid: &[String]) -> Expr {
    let mut used: Vec<String> = avoid.to_vec();
    all_names(e, &mut used);
    rename_binders(e, &mut used)
}

fn rename_binders(e: &Expr, used: &mut Vec<String>) -> Expr {
    match e {
        Expr::Sum(v, a, b, body) => {
            let fresh = (1..)
                .map(|k| format!("{v}{k}"))
                .find(|n| !used.contains(n))
                .expect("a fresh name");
            used.push(fresh.clone());
            let body = substitute(body, std::slice::from_ref(v), &[Expr::Var(fresh.clone())]);
            Expr::Sum(
                fresh,
                Box::new(rename_binders(a, used)),
                Box::new(rename_binders(b, used)),
                Box::new(rename_binders(&body, used)),
            )
        }
        _ => map_children(e, &mut |x| Ok(rename_binders(x, used))).expect("renaming cannot fail"),
    }
}

/// `e` with the polygon `from` (its points and objects) renamed `to`.
fn rename_polygon(e: &Expr, from: &str, to: &str) -> Expr {
    if from == to {
        return e.clone();
    }
    let renamed = |n: &String| -> String {
        let primes = n.len() - n.trim_end_matches('\'').len();
        if &n[..n.len() - primes] == from {
            format!("{to}{}", &n[n.len() - primes..])
        } else {
            n.clone()
        }
    };
    match e {
        Expr::Index(n, args) => Expr::Index(renamed(n), args.iter().map(|a| rename_polygon(a, from, to)).collect()),
        Expr::Call(n, args) => Expr::Call(renamed(n), args.iter().map(|a| rename_polygon(a, from, to)).collect()),
        Expr::Var(v) if v == from => Expr::Var(to.into()),
        _ => map_children(e, &mut |x| Ok(rename_polygon(x, from, to))).expect("renaming cannot fail"),
    }
}

/// Replaces the library objects of the polygon in `sides` by lemmas (and the evaluation and
/// derivatives by their definitions through the scheme); objects no lemma covers are left as
/// they are (the prover then says it cannot read them).
pub(crate) fn apply(sides: &[Expr], decls: &Decls, lemmas: &[Lemma]) -> Result<Rewritten> {
    let mut out = Rewritten::default();
    let degree = match &decls.polygon {
        Some(p) => Some(super::parse::parse(&p.degree, &[])?),
        None => None,
    };
    let net = match &decls.net {
        Some(net) => Some((
            net.name.as_str(),
            super::parse::parse(&net.degree[0], &[])?,
            super::parse::parse(&net.degree[1], &[])?,
        )),
        None => None,
    };
    let mut avoid = Vec::new();
    for s in sides {
        all_names(s, &mut avoid);
    }
    avoid.extend(decls.ranges.iter().map(|r| r.var.clone()));
    let mut rw = Rewriter {
        polygon: decls.polygon.as_ref().map(|p| p.name.as_str()).zip(degree.as_ref()),
        net: net.as_ref().map(|(name, m, n)| (*name, m, n)),
        lemmas,
        avoid,
        out: &mut out,
    };
    let mut done = Vec::new();
    for s in sides {
        done.push(rw.expr(s, &mut Vec::new(), 0)?);
    }
    out.sides = done;
    Ok(out)
}

struct Rewriter<'a> {
    /// The polygon's name and degree.
    polygon: Option<(&'a str, &'a Expr)>,
    /// The net's name and degrees.
    net: Option<(&'a str, &'a Expr, &'a Expr)>,
    lemmas: &'a [Lemma],
    avoid: Vec<String>,
    out: &'a mut Rewritten,
}

impl Rewriter<'_> {
    fn expr(&mut self, e: &Expr, sums: &mut Vec<(String, Expr, Expr)>, depth: usize) -> Result<Expr> {
        if depth > MAX_REWRITES {
            return Err(Error::Domain(format!(
                "objects read through more than {MAX_REWRITES} lemmas and definitions (a lemma whose formula uses its own object?)"
            )));
        }
        if let Expr::Sum(v, a, b, body) = e {
            let (a, b) = (self.expr(a, sums, depth)?, self.expr(b, sums, depth)?);
            sums.push((v.clone(), a.clone(), b.clone()));
            let body = self.expr(body, sums, depth);
            sums.pop();
            return Ok(Expr::Sum(v.clone(), Box::new(a), Box::new(b), Box::new(body?)));
        }
        let inner = map_children(e, &mut |x| self.expr(x, sums, depth))?;
        if let Some(surface) = self.surface(&inner)? {
            return Ok(surface);
        }
        let Some((polygon, degree)) = self.polygon else {
            return Ok(inner);
        };
        let Some((object, args)) = Object::of(&inner, polygon) else {
            return Ok(inner);
        };
        if let Some(found) = self.by_lemma(object, &args, sums)? {
            return self.expr(&found, sums, depth + 1);
        }
        match object {
            Object::Evaluation => {
                self.definition(format!(
                    "{p}(g) = {p}(0, n, g), the last point of the scheme (9)",
                    p = polygon
                ));
                let top = Object::Scheme.apply(polygon, vec![Expr::int(0), degree.clone(), args[0].clone()]);
                self.expr(&top, sums, depth + 1)
            }
            Object::Derivative(k) => {
                // The k-th derivative of b(x) at x = g: the formula of b(x), differentiated.
                let x = self.fresh("x");
                let curve = Object::Evaluation.apply(polygon, vec![Expr::Var(x.clone())]);
                let formula = self.expr(&curve, sums, depth + 1)?;
                if Object::of(&formula, polygon).is_some() {
                    return Ok(inner);
                }
                self.definition(format!(
                    "{p}{primes}(g) = d{k}/dx{k} {p}(x) at x = g",
                    p = polygon,
                    primes = "'".repeat(k),
                    k = if k == 1 { String::new() } else { format!("^{k}") }
                ));
                let mut d = formula;
                for _ in 0..k {
                    d = derive(&d, &x)?;
                }
                Ok(substitute(&d, &[x], &[args[0].clone()]))
            }
            Object::Scheme | Object::Differences => Ok(inner),
        }
    }

    fn definition(&mut self, text: String) {
        self.out.read(text);
    }

    /// A name used nowhere yet.
    fn fresh(&mut self, stem: &str) -> String {
        let name = (1..)
            .map(|m| format!("{stem}{m}"))
            .find(|n| !self.avoid.contains(n))
            .expect("a fresh name");
        self.avoid.push(name.clone());
        name
    }

    /// The net's surface `b(g, h)` or a partial `b_uv(g, h)` by text 003's definition of the
    /// tensor-product surface, `b(u, v) = Σ_i Σ_j b[i, j] B(i, m, u) B(j, n, v)`, differentiated
    /// (`None` for any other expression).
    fn surface(&mut self, e: &Expr) -> Result<Option<Expr>> {
        let (Some((net, m, n)), Expr::Call(name, args)) = (self.net, e) else {
            return Ok(None);
        };
        let (ku, kv) = match super::kernel::expr::split_partial(name) {
            Some((base, ku, kv)) if base == net => (ku, kv),
            _ if name == net => (0, 0),
            _ => return Ok(None),
        };
        if args.len() != 2 {
            return Ok(None);
        }
        let (x, y, i, j) = (self.fresh("x"), self.fresh("y"), self.fresh("i"), self.fresh("j"));
        let var = |v: &String| Expr::Var(v.clone());
        let term = Expr::mul(
            Expr::mul(
                Expr::Index(net.into(), vec![var(&i), var(&j)]),
                Expr::Call("B".into(), vec![var(&i), m.clone(), var(&x)]),
            ),
            Expr::Call("B".into(), vec![var(&j), n.clone(), var(&y)]),
        );
        let inner = Expr::Sum(j.clone(), Box::new(Expr::int(0)), Box::new(n.clone()), Box::new(term));
        let mut d = Expr::Sum(i, Box::new(Expr::int(0)), Box::new(m.clone()), Box::new(inner));
        for _ in 0..ku {
            d = derive(&d, &x)?;
        }
        for _ in 0..kv {
            d = derive(&d, &y)?;
        }
        self.definition(format!(
            "{net}(u, v) = Σ_i Σ_j {net}[i, j] B_i^m(u) B_j^n(v), the tensor-product surface as text 003 defines it{}",
            if ku + kv > 0 {
                " (its partials by differentiating)"
            } else {
                ""
            }
        ));
        Ok(Some(substitute(&d, &[x, y], &[args[0].clone(), args[1].clone()])))
    }

    /// The first lemma for `object` that matches `args`: its formula, with its conditions
    /// recorded as obligations.
    fn by_lemma(&mut self, object: Object, args: &[Expr], sums: &[(String, Expr, Expr)]) -> Result<Option<Expr>> {
        let Some((polygon, degree)) = self.polygon else {
            return Ok(None);
        };
        for lemma in self.lemmas.iter().filter(|l| l.object == object) {
            let Some((formula, conditions)) = lemma.at(args, polygon, degree, &self.avoid) else {
                continue;
            };
            all_names(&formula, &mut self.avoid);
            let site = object.apply(polygon, args.to_vec());
            for condition in conditions {
                self.out.obligations.push(Obligation {
                    condition,
                    sums: sums.to_vec(),
                    what: format!("lemma {} at {site}", lemma.id),
                });
            }
            if !self.out.lemmas.contains(&lemma.id) {
                self.out.lemmas.push(lemma.id.clone());
            }
            return Ok(Some(formula));
        }
        Ok(None)
    }
}

/// Which end of an induction to unfold the recursive objects at.
pub(crate) enum Unfold<'a> {
    /// The objects whose recursion argument is exactly `lo`, by their definition there: the
    /// base case at `lo = 0`, else the recursion unfolded `lo` times down to it.
    Base(&'a Expr),
    /// The objects whose recursion argument is exactly `var + 1`, by one step of the recursion
    /// (down to `var`).
    Step(&'a str),
}

/// `e` with the recursive objects of the polygon unfolded once by their definitions (see the
/// module documentation), where `how` says; the definitions' own ranges become obligations.
pub(crate) fn unfold(e: &Expr, decls: &Decls, how: &Unfold<'_>, out: &mut Rewritten) -> Result<Expr> {
    let Some(polygon) = &decls.polygon else {
        return Ok(e.clone());
    };
    let degree = super::parse::parse(&polygon.degree, &[])?;
    unfold_in(e, &polygon.name, &degree, how, &mut Vec::new(), out)
}

fn unfold_in(
    e: &Expr,
    p: &str,
    degree: &Expr,
    how: &Unfold<'_>,
    sums: &mut Vec<(String, Expr, Expr)>,
    out: &mut Rewritten,
) -> Result<Expr> {
    if let Expr::Sum(v, a, b, body) = e {
        let (a, b) = (
            unfold_in(a, p, degree, how, sums, out)?,
            unfold_in(b, p, degree, how, sums, out)?,
        );
        sums.push((v.clone(), a.clone(), b.clone()));
        let body = unfold_in(body, p, degree, how, sums, out);
        sums.pop();
        return Ok(Expr::Sum(v.clone(), Box::new(a), Box::new(b), Box::new(body?)));
    }
    let inner = map_children(e, &mut |x| unfold_in(x, p, degree, how, sums, out))?;
    let Some((object, args)) = Object::of(&inner, p) else {
        return Ok(inner);
    };
    let Some(k) = object.recursion_argument() else {
        return Ok(inner);
    };
    let step_of = |var: &str| Expr::add(Expr::Var(var.into()), Expr::int(1));
    let unfolded = match how {
        Unfold::Base(lo) if args[k] == **lo => {
            let steps = base_steps(lo)?;
            let at = if object == Object::Scheme { &args[0] } else { &args[1] };
            if steps == 0 {
                out.read(format!(
                    "{} at {lo}: {p}[…] (the base of its recursion)",
                    object.phrase()
                ));
                Expr::Index(p.into(), vec![at.clone()])
            } else {
                out.read(format!(
                    "{} at {lo}: its recursion unfolded {lo} times down to its base {p}[…]",
                    object.phrase()
                ));
                unfolded_from_base(object, p, at, args.get(2), steps)
            }
        }
        Unfold::Step(var) if args[k] == step_of(var) => {
            let v = Expr::Var((*var).into());
            let next = |a: &Expr| Expr::add(a.clone(), Expr::int(1));
            let text = match object {
                Object::Scheme => {
                    let (i, g) = (&args[0], &args[2]);
                    let here = Object::Scheme.apply(p, vec![i.clone(), v.clone(), g.clone()]);
                    let right = Object::Scheme.apply(p, vec![next(i), v, g.clone()]);
                    Expr::add(
                        Expr::mul(Expr::sub(Expr::int(1), g.clone()), here),
                        Expr::mul(g.clone(), right),
                    )
                }
                _ => {
                    let j = &args[1];
                    let here = Object::Differences.apply(p, vec![v.clone(), j.clone()]);
                    let right = Object::Differences.apply(p, vec![v, next(j)]);
                    Expr::sub(right, here)
                }
            };
            out.read(format!(
                "{} at {} by one step of its recursion",
                object.phrase(),
                args[k]
            ));
            text
        }
        _ => return Ok(inner),
    };
    for condition in object.defined(&args, degree) {
        out.obligations.push(Obligation {
            condition,
            sums: sums.clone(),
            what: format!("the definition of {inner}"),
        });
    }
    Ok(unfolded)
}

/// Most steps of a recursion unfolded to read an object at an induction's first value (the
/// coefficients, at most 3^steps, stay within an `i64`).
const MAX_BASE_STEPS: i64 = 32;

/// The number of recursion steps from the definition's base (0) to the first value `lo` of an
/// induction, or an error when `lo` is not an integer literal from 0 to [`MAX_BASE_STEPS`]: the
/// base case is read from the definition at `lo`, never assumed.
fn base_steps(lo: &Expr) -> Result<usize> {
    let steps = match lo {
        Expr::Num(q) if q.is_integer() => i64::try_from(q.to_integer()).ok(),
        _ => None,
    };
    match steps {
        Some(s) if (0..=MAX_BASE_STEPS).contains(&s) => Ok(s as usize),
        _ => Err(Error::Domain(format!(
            "induction from {lo}: the base case unfolds the recursion from its base at 0, so the first value must be an integer from 0 to MAX_BASE_STEPS = {MAX_BASE_STEPS}"
        ))),
    }
}

/// The object at recursion argument `steps`, written by its recursion unfolded `steps` times
/// down to the control points: `Σ_m c_m · p[at + m]`, each `c_m` a polynomial in the scheme's
/// parameter `g` (integers for the differences), computed exactly from the recursion:
/// `b(i, r+1, g) = (1 − g)·b(i, r, g) + g·b(i+1, r, g)` and `Δ^{r+1}b_j = Δ^r b_{j+1} − Δ^r b_j`.
fn unfolded_from_base(object: Object, p: &str, at: &Expr, g: Option<&Expr>, steps: usize) -> Expr {
    // c[m][e]: the coefficient of g^e in c_m.
    let mut c: Vec<Vec<i64>> = vec![vec![1]];
    for _ in 0..steps {
        let mut next = vec![vec![0i64; c[0].len() + 1]; c.len() + 1];
        for (m, cm) in c.iter().enumerate() {
            for (e, &x) in cm.iter().enumerate() {
                if object == Object::Scheme {
                    // (1 − g)·c_m at m, g·c_m at m + 1.
                    next[m][e] += x;
                    next[m][e + 1] -= x;
                    next[m + 1][e + 1] += x;
                } else {
                    // −c_m at m, c_m at m + 1.
                    next[m][e] -= x;
                    next[m + 1][e] += x;
                }
            }
        }
        c = next;
    }
    let mut total: Option<Expr> = None;
    for (m, cm) in c.iter().enumerate() {
        let point = Expr::Index(p.into(), vec![Expr::add(at.clone(), Expr::int(m as i64))]);
        for (e, &x) in cm.iter().enumerate().filter(|(_, &x)| x != 0) {
            let mut term = Expr::mul(Expr::int(x.abs()), point.clone());
            if let (Some(g), true) = (g, e > 0) {
                term = Expr::mul(Expr::pow(g.clone(), Expr::int(e as i64)), term);
            }
            total = Some(match (total, x < 0) {
                (None, false) => term,
                (None, true) => Expr::Neg(Box::new(term)),
                (Some(t), false) => Expr::add(t, term),
                (Some(t), true) => Expr::sub(t, term),
            });
        }
    }
    total.unwrap_or_else(|| Expr::int(0))
}

#[cfg(test)]
#[path = "lemma_tests.rs"]
mod tests;
