//! Deciding claims: the identity prover (degree bounds derived from the expressions, exact
//! checks at enough points, on a basis of control polygons), symbolic expansion, and the
//! claim kinds built on them. Every verdict comes with a certificate saying what was checked.

use super::claims::{Claim, CurveSpec, Number, SurfaceSpec};
use super::eval::{Alg, Deg, Env, Evaluator, Value, VarEnv};
use super::expr::{self, check_index, parse, parse_definition, parse_range, Definition, Expr, IntRange};
use super::methods::{NetMethod, PolygonMethod};
use super::poly::{set_names, Poly, RatFunc};
use super::Verdict;
use crate::curve::BezierCurve;
use crate::error::{Error, Result};
use crate::point::Point;
use crate::scalar::{RefOps, Ring, Scalar};
use crate::surface::BezierSurface;
use num_rational::BigRational;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::rc::Rc;

/// The result of checking one claim.
#[derive(Clone, Debug)]
pub struct Checked {
    /// The verdict.
    pub verdict: Verdict,
    /// The finite ranges a [`Verdict::ProvedInRange`] covers.
    pub range: Option<String>,
    /// The certificate (one line).
    pub certificate: String,
    /// The step-by-step account (filled when asked for).
    pub steps: Vec<String>,
    /// The values of the first parameter that the proof checked (for `explain`).
    pub params: Vec<BigRational>,
}

impl Checked {
    pub(crate) fn new(verdict: Verdict, certificate: String) -> Self {
        Checked {
            verdict,
            range: None,
            certificate,
            steps: Vec::new(),
            params: Vec::new(),
        }
    }
}

/// Largest number of exact evaluations one identity may take (per side and instance).
pub const MAX_EVALUATIONS: usize = 2_000_000;

// ---------------------------------------------------------------------------------------
// Claim context: parsed definitions, ranges, objects.

/// A claim prepared for checking.
pub struct Ctx<'c> {
    /// The claim.
    pub claim: &'c Claim,
    /// Names kept whole by the parser.
    pub known: Vec<String>,
    /// Definitions, already expanded and differentiated.
    pub defs: Vec<Definition>,
    /// Integer ranges.
    pub ranges: Vec<IntRange>,
}

impl<'c> Ctx<'c> {
    /// Parses the claim's shared fields.
    pub fn new(claim: &'c Claim) -> Result<Self> {
        let mut known = claim.known_names();
        known.extend(PolygonMethod::ALL.iter().map(|m| m.name().to_string()));
        known.extend(NetMethod::ALL.iter().map(|m| m.name().to_string()));
        let parsed = claim
            .defs
            .iter()
            .flatten()
            .map(|d| parse_definition(d, &known))
            .collect::<Result<Vec<_>>>()?;
        let ranges = claim
            .ranges
            .iter()
            .flatten()
            .map(|r| parse_range(r))
            .collect::<Result<Vec<_>>>()?;
        let mut ctx = Ctx {
            claim,
            known,
            defs: Vec::new(),
            ranges,
        };
        // In dependency order, each body expanded with the definitions it uses (so `diff`
        // sees the whole expression, never an undefined name).
        for mut def in expr::dependency_order(parsed)? {
            let expanded = expr::expand(&def.body, &ctx.defs)?;
            ctx.check_names(&expanded, &def.params)?;
            def.body = expr::expand_diffs(&expanded, &ctx.int_names())?;
            ctx.defs.push(def);
        }
        Ok(ctx)
    }

    /// Parses an expression of the claim, with definitions and `diff` expanded.
    pub fn expr(&self, text: &str) -> Result<Expr> {
        let e = parse(text, &self.known)?;
        let e = expr::expand(&e, &self.defs)?;
        self.check_names(&e, &[])?;
        expr::expand_diffs(&e, &self.int_names())
    }

    /// The claim's integer names (its range variables), which `diff` may not take.
    fn int_names(&self) -> Vec<String> {
        self.ranges.iter().map(|r| r.var.clone()).collect()
    }

    /// When the claim lists its parameters (`vars`), every free name must be declared: an
    /// unknown name is an error, never silently a constant (whose derivative would be 0).
    fn check_names(&self, e: &Expr, local: &[String]) -> Result<()> {
        let Some(vars) = &self.claim.vars else {
            return Ok(());
        };
        let coords = self
            .claim
            .coords
            .clone()
            .unwrap_or_else(|| vec!["x".into(), "y".into(), "z".into()]);
        for v in e.free_vars() {
            let known = vars.contains(&v)
                || local.contains(&v)
                || self.is_bound(&v)
                || (self.claim.kind == "implicit" && coords.contains(&v))
                || (self.claim.kind == "bezier_points" && v == self.claim.param.as_deref().unwrap_or("u"))
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
        self.claim
            .ranges
            .iter()
            .flatten()
            .cloned()
            .collect::<Vec<_>>()
            .join(", ")
    }

    fn is_bound(&self, name: &str) -> bool {
        self.ranges.iter().any(|r| r.var == name)
            || self.claim.symbols.iter().flatten().any(|s| s == name)
            || self.claim.vectors.iter().any(|v| v.contains_key(name))
            || self.claim.curves.iter().any(|c| c.contains_key(name))
            || self.claim.surfaces.iter().any(|c| c.contains_key(name))
            || self.claim.polygon.as_ref().is_some_and(|p| p.name == name)
            || self.claim.net.as_ref().is_some_and(|p| p.name == name)
    }

    /// The continuous parameters of some expressions: the `vars` field, or every free name not
    /// bound otherwise.
    pub fn params(&self, exprs: &[&Expr]) -> Vec<String> {
        if let Some(v) = &self.claim.vars {
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
        self.claim.symbols.is_some() || self.claim.vectors.is_some()
    }
}

// ---------------------------------------------------------------------------------------
// Numbers in claim files and objects.

/// An exact number type the identity prover can evaluate in.
pub trait Exact: Scalar + Alg
where
    for<'a> &'a Self: RefOps<Self>,
{
}
impl<T: Scalar + Alg> Exact for T where for<'a> &'a T: RefOps<T> {}

/// Evaluates a constant expression (a coordinate in a claim file).
pub fn constant<T: Exact>(text: &str) -> Result<T>
where
    for<'a> &'a T: RefOps<T>,
{
    let e = parse(text, &[])?;
    let env = VarEnv::<T>(BTreeMap::new());
    Evaluator::new(&env, BTreeMap::new()).scalar(&e)
}

fn point<T: Exact>(coords: &[Number]) -> Result<Point<T>>
where
    for<'a> &'a T: RefOps<T>,
{
    Point::new(coords.iter().map(|c| constant(&c.text()?)).collect::<Result<_>>()?)
}

/// Control points from a claim file.
pub fn points<T: Exact>(list: &[Vec<Number>]) -> Result<Vec<Point<T>>>
where
    for<'a> &'a T: RefOps<T>,
{
    list.iter().map(|p| point(p)).collect()
}

/// A concrete curve of a claim.
#[derive(Clone, Debug)]
pub enum CurveObj<T> {
    /// `Σ b_i B_i^n(t)`.
    Polynomial(BezierCurve<T>),
    /// `Σ w_i b_i B_i^n(t) / Σ w_i B_i^n(t)` (the library's rational curve).
    Rational(crate::rational::RationalBezierCurve<T>),
}

impl<T: Exact> CurveObj<T>
where
    for<'a> &'a T: RefOps<T>,
{
    /// Builds the object from its specification.
    pub fn from_spec(spec: &CurveSpec) -> Result<Self> {
        let pts = points::<T>(&spec.points)?;
        match &spec.weights {
            None => Ok(CurveObj::Polynomial(BezierCurve::new(pts)?)),
            Some(w) => {
                let w = w.iter().map(|x| constant(&x.text()?)).collect::<Result<Vec<T>>>()?;
                Ok(CurveObj::Rational(crate::rational::RationalBezierCurve::new(pts, w)?))
            }
        }
    }
    fn degree(&self) -> usize {
        match self {
            CurveObj::Polynomial(c) => c.degree(),
            CurveObj::Rational(c) => c.degree(),
        }
    }
    fn dim(&self) -> usize {
        match self {
            CurveObj::Polynomial(c) => c.dim(),
            CurveObj::Rational(c) => c.dim(),
        }
    }
    /// The point at `t` (the projection of the lift for a rational curve).
    pub fn eval(&self, t: &T) -> Result<Vec<T>> {
        match self {
            CurveObj::Polynomial(c) => Ok(c.eval(t).into_coords()),
            CurveObj::Rational(c) => Ok(c.eval(t)?.into_coords()),
        }
    }
}

/// A concrete surface of a claim: `net[i][j] = b_{i,j}`.
pub fn net_from_spec<T: Exact>(spec: &SurfaceSpec) -> Result<Vec<Vec<Point<T>>>>
where
    for<'a> &'a T: RefOps<T>,
{
    let net: Vec<Vec<Point<T>>> = spec.net.iter().map(|r| points(r)).collect::<Result<_>>()?;
    let cols = net.first().map_or(0, Vec::len);
    if net.is_empty() || cols == 0 || net.iter().any(|r| r.len() != cols) {
        return Err(Error::Domain(
            "a control net needs rows of equal, non-zero length".into(),
        ));
    }
    crate::point::common_dimension(&net.concat(), "a control net")?;
    Ok(net)
}

/// `Σ_i Σ_j b_ij B_i^m(u) B_j^n(v)` by the library ([`BezierSurface::eval`], u first).
pub fn eval_net<T: Exact>(net: &[Vec<Point<T>>], u: &T, v: &T) -> Result<Point<T>>
where
    for<'a> &'a T: RefOps<T>,
{
    Ok(BezierSurface::new(net.to_vec())?.eval(u, v))
}

/// `∂^{ku+kv} x / ∂u^{ku} ∂v^{kv}` at `(u, v)` by the library: the surface of the derivative
/// net (`m!/(m-ku)! n!/(n-kv)! Δ_u^{ku} Δ_v^{kv} b_{i,j}`), evaluated
/// ([`BezierSurface::partial_at`]; zero beyond the degrees).
pub fn partial_net<T: Exact>(net: &[Vec<Point<T>>], ku: usize, kv: usize, u: &T, v: &T) -> Result<Point<T>>
where
    for<'a> &'a T: RefOps<T>,
{
    let s = BezierSurface::new(net.to_vec())?;
    if ku + kv == 0 {
        return Ok(s.eval(u, v));
    }
    s.partial_at(ku, kv, u, v)
}

/// Highest total order of a partial derivative of a surface or net a claim may take
/// (`x_uuv` has order 3); the same bound as `diff(e, t, k)`.
pub const MAX_SURFACE_PARTIAL: usize = 16;

/// `name` as a surface or its partial: `x` → `(x, 0, 0)`, `x_uv` → `(x, 1, 1)`, when
/// `is_surface` holds for the base; `None` for other names. Primes on a surface, partials
/// of a curve and orders above [`MAX_SURFACE_PARTIAL`] are errors, as is any call other
/// than with two arguments.
fn surface_ref<'n>(
    name: &'n str,
    args: &[Expr],
    is_surface: &dyn Fn(&str) -> bool,
    is_curve: &dyn Fn(&str) -> bool,
    what: &str,
) -> Result<Option<(&'n str, usize, usize)>> {
    let found = if is_surface(name) {
        Some((name, 0, 0))
    } else {
        expr::split_partial(name).filter(|(base, _, _)| is_surface(base))
    };
    let Some((base, ku, kv)) = found else {
        let (primed, order) = split_primes(name);
        if order > 0 && is_surface(primed) {
            return Err(Error::Domain(format!(
                "{name}: the {what} {primed} has partials {primed}_u(u, v), {primed}_v(u, v), {primed}_uv(u, v), … (or diff({primed}(u, v), u)), not primes"
            )));
        }
        if let Some((surface, suffix)) = name.rsplit_once('_').filter(|(b, _)| is_surface(b)) {
            return Err(Error::Domain(format!(
                "{name}: a partial of the {what} {surface} is written with u (by the first argument) and v (by the second), e.g. {surface}_u, {surface}_uv, not '{suffix}'"
            )));
        }
        if let Some((curve, _, _)) = expr::split_partial(name).filter(|(b, _, _)| is_curve(b)) {
            return Err(Error::Domain(format!(
                "{name}: {curve} is a curve; its derivatives are {curve}'(t), {curve}''(t), … (or diff({curve}(t), t))"
            )));
        }
        return Ok(None);
    };
    if ku + kv > MAX_SURFACE_PARTIAL {
        return Err(Error::Domain(format!(
            "{name}: a {what} is differentiated at most {MAX_SURFACE_PARTIAL} times in all (this is order {})",
            ku + kv
        )));
    }
    if args.len() != 2 {
        return Err(Error::Domain(format!(
            "the {what} {base} is called as {name}(u, v), with two arguments, not {}",
            args.len()
        )));
    }
    Ok(Some((base, ku, kv)))
}

// ---------------------------------------------------------------------------------------
// Environments

/// The objects of a claim, in exact numbers.
pub struct NumEnv<T> {
    /// Parameter and data values.
    pub vars: BTreeMap<String, Value<T>>,
    /// Concrete curves.
    pub curves: BTreeMap<String, CurveObj<T>>,
    /// Concrete surfaces.
    pub surfaces: BTreeMap<String, Vec<Vec<Point<T>>>>,
    /// The symbolic polygon (name, one-dimensional instance).
    pub polygon: Option<(String, Vec<T>)>,
    /// The symbolic net (name, instance).
    pub net: Option<(String, Vec<Vec<T>>)>,
}

impl<T: Exact> NumEnv<T>
where
    for<'a> &'a T: RefOps<T>,
{
    /// The objects of `claim`.
    pub fn new(claim: &Claim) -> Result<Self> {
        let mut curves = BTreeMap::new();
        for (k, spec) in claim.curves.iter().flatten() {
            curves.insert(k.clone(), CurveObj::from_spec(spec)?);
        }
        let mut surfaces = BTreeMap::new();
        for (k, spec) in claim.surfaces.iter().flatten() {
            surfaces.insert(k.clone(), net_from_spec(spec)?);
        }
        Ok(NumEnv {
            vars: BTreeMap::new(),
            curves,
            surfaces,
            polygon: None,
            net: None,
        })
    }
}

fn split_primes(name: &str) -> (&str, usize) {
    let base = name.trim_end_matches('\'');
    (base, name.len() - base.len())
}

impl<T: Exact> Env<T> for NumEnv<T>
where
    for<'a> &'a T: RefOps<T>,
{
    fn var(&self, name: &str) -> Option<Value<T>> {
        self.vars.get(name).cloned()
    }

    fn call(&self, name: &str, args: &[Expr], ev: &mut Evaluator<'_, T>) -> Result<Option<Value<T>>> {
        let (base, order) = split_primes(name);
        if let Some(c) = self.curves.get(base) {
            return Ok(Some(curve_call(c, base, order, args, ev)?));
        }
        let is_curve = |n: &str| self.curves.contains_key(n) || self.polygon.as_ref().is_some_and(|p| p.0 == n);
        let is_surface = |n: &str| self.surfaces.contains_key(n);
        if let Some((s, ku, kv)) = surface_ref(name, args, &is_surface, &is_curve, "surface")? {
            let (u, v) = (ev.scalar(&args[0])?, ev.scalar(&args[1])?);
            return Ok(Some(Value::V(
                partial_net(&self.surfaces[s], ku, kv, &u, &v)?.into_coords(),
            )));
        }
        if let Some((pname, coeffs)) = &self.polygon {
            if let Some(m) = PolygonMethod::of_call(name, args, pname)? {
                return Ok(Some(Value::S(m.value(coeffs, args, ev)?)));
            }
            if pname == base {
                let pts = coeffs
                    .iter()
                    .map(|c| Point::new(vec![c.clone()]))
                    .collect::<Result<_>>()?;
                let c = CurveObj::Polynomial(BezierCurve::new(pts)?);
                return Ok(Some(Value::S(
                    curve_call(&c, base, order, args, ev)?.entries()[0].clone(),
                )));
            }
        }
        if let Some((nname, net)) = &self.net {
            if let Some(m) = NetMethod::of_call(name, args, nname)? {
                return Ok(Some(Value::S(m.value(net, args, ev)?)));
            }
            if let Some((_, ku, kv)) = surface_ref(name, args, &|n| n == nname, &is_curve, "net")? {
                let (u, v) = (ev.scalar(&args[0])?, ev.scalar(&args[1])?);
                let pts: Vec<Vec<Point<T>>> = net
                    .iter()
                    .map(|r| r.iter().map(|c| Point::new(vec![c.clone()])).collect::<Result<_>>())
                    .collect::<Result<_>>()?;
                return Ok(Some(Value::S(partial_net(&pts, ku, kv, &u, &v)?.coords()[0].clone())));
            }
        }
        Ok(None)
    }

    fn index(&self, name: &str, idx: &[i64]) -> Result<Option<Value<T>>> {
        let get = |v: &[T], i: i64| -> T {
            usize::try_from(i)
                .ok()
                .and_then(|i| v.get(i).cloned())
                .unwrap_or_else(T::zero)
        };
        if let Some((pname, coeffs)) = &self.polygon {
            if pname == name {
                one_index(name, idx)?;
                return Ok(Some(Value::S(get(coeffs, idx[0]))));
            }
        }
        if let Some((nname, net)) = &self.net {
            if nname == name {
                if idx.len() != 2 {
                    return Err(Error::Domain(format!("the net {name} is indexed as {name}[i, j]")));
                }
                let row = usize::try_from(idx[0]).ok().and_then(|i| net.get(i));
                return Ok(Some(Value::S(row.map_or_else(T::zero, |r| get(r, idx[1])))));
            }
        }
        if let Some(c) = self.curves.get(name) {
            one_index(name, idx)?;
            let CurveObj::Polynomial(c) = c else {
                return Err(Error::Domain(format!(
                    "{name} is rational: index its control points by hand"
                )));
            };
            let p = usize::try_from(idx[0]).ok().and_then(|i| c.points().get(i));
            return Ok(Some(Value::V(
                p.map_or_else(|| vec![T::zero(); c.dim()], |p| p.coords().to_vec()),
            )));
        }
        if let Some(net) = self.surfaces.get(name) {
            if idx.len() != 2 {
                return Err(Error::Domain(format!("the net {name} is indexed as {name}[i, j]")));
            }
            let dim = net[0][0].dim();
            let p = usize::try_from(idx[0])
                .ok()
                .and_then(|i| net.get(i))
                .and_then(|r| usize::try_from(idx[1]).ok().and_then(|j| r.get(j)));
            return Ok(Some(Value::V(
                p.map_or_else(|| vec![T::zero(); dim], |p| p.coords().to_vec()),
            )));
        }
        Ok(None)
    }
}

fn one_index(name: &str, idx: &[i64]) -> Result<()> {
    if idx.len() != 1 {
        return Err(Error::Domain(format!("the polygon {name} is indexed as {name}[j]")));
    }
    Ok(())
}

fn curve_call<T: Exact>(
    c: &CurveObj<T>,
    name: &str,
    order: usize,
    args: &[Expr],
    ev: &mut Evaluator<'_, T>,
) -> Result<Value<T>>
where
    for<'a> &'a T: RefOps<T>,
{
    match (args.len(), c) {
        (1, _) if order == 0 => Ok(Value::V(c.eval(&ev.scalar(&args[0])?)?)),
        (1, CurveObj::Polynomial(curve)) => {
            let t = ev.scalar(&args[0])?;
            Ok(Value::V(curve.derivative_at(order, &t)?.into_coords()))
        }
        (1, CurveObj::Rational(curve)) => {
            check_rational_order(name, order)?;
            let t = ev.scalar(&args[0])?;
            if order == 1 {
                return Ok(Value::V(curve.derivative_at(&t)?.into_coords()));
            }
            // Each derivative of a rational curve is a rational curve of twice the degree.
            let mut d = curve.clone();
            for _ in 0..order {
                d = crate::param::ParamCurveDeriv::deriv(&d)?;
            }
            Ok(Value::V(d.eval(&t)?.into_coords()))
        }
        (3, CurveObj::Polynomial(curve)) if order == 0 => {
            let (i, r) = (ev.int(&args[0])?, ev.int(&args[1])?);
            let t = ev.scalar(&args[2])?;
            let n = curve.degree() as i64;
            if i < 0 || r < 0 || i + r > n {
                return Err(Error::Domain(format!(
                    "{name}({i}, {r}, t): the de Casteljau point b_i^r needs 0 ≤ i, 0 ≤ r, i + r ≤ {n}"
                )));
            }
            let s = curve.scheme(&t);
            Ok(Value::V(
                s.get(r as usize, i as usize)
                    .expect("indices checked")
                    .coords()
                    .to_vec(),
            ))
        }
        _ => Err(Error::Domain(format!(
            "{name}{}: call a curve as {name}(t), {name}'(t) or {name}(i, r, t) (polynomial curves)",
            "'".repeat(order)
        ))),
    }
}

/// Highest derivative of a rational curve a claim may take: the `k`-th derivative is a
/// rational curve of degree `2^k n`.
pub const MAX_RATIONAL_DERIVATIVE: usize = 3;

fn check_rational_order(name: &str, order: usize) -> Result<()> {
    if order > MAX_RATIONAL_DERIVATIVE {
        return Err(Error::Domain(format!(
            "{name}{}: a rational curve is differentiated at most {MAX_RATIONAL_DERIVATIVE} times",
            "'".repeat(order)
        )));
    }
    Ok(())
}

/// The objects of a claim, as degree bounds.
pub struct DegEnv {
    params: BTreeSet<String>,
    /// name → (degree, dimension, rational)
    curves: BTreeMap<String, (u64, usize, bool)>,
    /// name → (m, n, dimension)
    surfaces: BTreeMap<String, (u64, u64, usize)>,
    polygon: Option<(String, u64)>,
    net: Option<(String, u64, u64)>,
    vars: BTreeMap<String, Value<Deg>>,
}

impl DegEnv {
    /// Degree information of the claim's objects, for the parameters `params`.
    pub fn new<T: Exact>(num: &NumEnv<T>, params: &[String]) -> Self
    where
        for<'a> &'a T: RefOps<T>,
    {
        DegEnv {
            params: params.iter().cloned().collect(),
            curves: num
                .curves
                .iter()
                .map(|(k, c)| {
                    (
                        k.clone(),
                        (c.degree() as u64, c.dim(), matches!(c, CurveObj::Rational(_))),
                    )
                })
                .collect(),
            surfaces: num
                .surfaces
                .iter()
                .map(|(k, n)| {
                    (
                        k.clone(),
                        ((n.len() - 1) as u64, (n[0].len() - 1) as u64, n[0][0].dim()),
                    )
                })
                .collect(),
            polygon: num.polygon.as_ref().map(|(k, c)| (k.clone(), (c.len() - 1) as u64)),
            net: num
                .net
                .as_ref()
                .map(|(k, n)| (k.clone(), (n.len() - 1) as u64, (n[0].len() - 1) as u64)),
            vars: BTreeMap::new(),
        }
    }
}

impl Env<Deg> for DegEnv {
    fn var(&self, name: &str) -> Option<Value<Deg>> {
        if let Some(v) = self.vars.get(name) {
            return Some(v.clone());
        }
        self.params.contains(name).then(|| Value::S(Deg::var(name)))
    }

    fn call(&self, name: &str, args: &[Expr], ev: &mut Evaluator<'_, Deg>) -> Result<Option<Value<Deg>>> {
        let (base, order) = split_primes(name);
        let composed = |ev: &mut Evaluator<'_, Deg>, n: u64, rational: bool| -> Result<Deg> {
            let g = ev.scalar(
                args.last()
                    .ok_or_else(|| Error::Domain(format!("{name}() needs a parameter, e.g. {base}(t)")))?,
            )?;
            let c = g.compose(n);
            if rational {
                c.div(&c)
            } else {
                Ok(c)
            }
        };
        if let Some(&(n, dim, rational)) = self.curves.get(base) {
            let d = match args.len() {
                3 => {
                    let r = ev.int(&args[1])?;
                    composed(ev, r.max(0) as u64, rational)?
                }
                // The k-th derivative of a rational curve of degree n is a rational curve
                // of degree 2^k n; a polynomial curve's has degree n − k.
                _ if rational => {
                    check_rational_order(base, order)?;
                    composed(ev, n << order, true)?
                }
                _ => composed(ev, n.saturating_sub(order as u64), false)?,
            };
            return Ok(Some(Value::V(vec![d; dim])));
        }
        if let Some((pname, n)) = &self.polygon {
            if let Some(m) = PolygonMethod::of_call(name, args, pname)? {
                return Ok(Some(Value::S(m.degree(*n, args, ev)?)));
            }
            if pname == base {
                let d = match args.len() {
                    3 => {
                        let r = ev.int(&args[1])?;
                        composed(ev, r.max(0) as u64, false)?
                    }
                    _ => composed(ev, n.saturating_sub(order as u64), false)?,
                };
                return Ok(Some(Value::S(d.times_control_point())));
            }
        }
        // A partial ∂^{ku+kv}/∂u^{ku}∂v^{kv} lowers the degrees to (m − ku, n − kv).
        let surface = |ev: &mut Evaluator<'_, Deg>, m: u64, n: u64, ku: usize, kv: usize| -> Result<Deg> {
            let (u, v) = (ev.scalar(&args[0])?, ev.scalar(&args[1])?);
            Ok(u.compose(m.saturating_sub(ku as u64))
                .mul(&v.compose(n.saturating_sub(kv as u64))))
        };
        let is_curve = |n: &str| self.curves.contains_key(n) || self.polygon.as_ref().is_some_and(|p| p.0 == n);
        let is_surface = |n: &str| self.surfaces.contains_key(n);
        if let Some((s, ku, kv)) = surface_ref(name, args, &is_surface, &is_curve, "surface")? {
            let (m, n, dim) = self.surfaces[s];
            let d = surface(ev, m, n, ku, kv)?;
            return Ok(Some(Value::V(vec![d; dim])));
        }
        if let Some((nname, m, n)) = &self.net {
            if let Some(meth) = NetMethod::of_call(name, args, nname)? {
                return Ok(Some(Value::S(meth.degree(*m, *n, args, ev)?)));
            }
            if let Some((_, ku, kv)) = surface_ref(name, args, &|x| x == nname, &is_curve, "net")? {
                return Ok(Some(Value::S(surface(ev, *m, *n, ku, kv)?.times_control_point())));
            }
        }
        Ok(None)
    }

    fn index(&self, name: &str, _: &[i64]) -> Result<Option<Value<Deg>>> {
        if self.polygon.as_ref().is_some_and(|p| p.0 == name) || self.net.as_ref().is_some_and(|p| p.0 == name) {
            return Ok(Some(Value::S(Deg::control_point())));
        }
        if let Some(&(_, dim, _)) = self.curves.get(name) {
            return Ok(Some(Value::V(vec![Deg::default(); dim])));
        }
        if let Some(&(_, _, dim)) = self.surfaces.get(name) {
            return Ok(Some(Value::V(vec![Deg::default(); dim])));
        }
        Ok(None)
    }
}

// ---------------------------------------------------------------------------------------
// Choosing parameters

/// Distinct rationals: first `k/d` for `k = 0..=d`, then `p/q` in lowest terms for growing `q`.
pub struct Candidates {
    seen: BTreeSet<BigRational>,
    queue: Vec<BigRational>,
    q: i64,
}

impl Candidates {
    /// Candidates for a polynomial of degree `d`.
    pub fn new(d: usize) -> Self {
        let d = d.max(1) as i64;
        let queue: Vec<BigRational> = (0..=d).rev().map(|k| BigRational::new(k.into(), d.into())).collect();
        Candidates {
            seen: BTreeSet::new(),
            queue,
            q: 1,
        }
    }
}

impl Iterator for Candidates {
    type Item = BigRational;
    fn next(&mut self) -> Option<BigRational> {
        loop {
            if let Some(x) = self.queue.pop() {
                if self.seen.insert(x.clone()) {
                    return Some(x);
                }
                continue;
            }
            self.q += 1;
            let q = self.q;
            // Also step outside [0, 1]: a denominator may vanish on a whole interval's rationals
            // only if it is zero, but values beyond 1 make the search shorter for e.g. 1/(t - p/q).
            self.queue = (0..=2 * q)
                .rev()
                .map(|p| BigRational::new(p.into(), q.into()))
                .collect();
        }
    }
}

// ---------------------------------------------------------------------------------------
// The identity prover

/// One polygon of the basis on which an affine identity is checked.
#[derive(Clone, Debug)]
enum Basis {
    None,
    Zero,
    Unit(usize),
    NetUnit(usize, usize),
}

impl Basis {
    fn describe(&self, ctx: &Ctx<'_>) -> String {
        let p = ctx.claim.polygon.as_ref().map(|p| p.name.as_str());
        let n = ctx.claim.net.as_ref().map(|p| p.name.as_str());
        match self {
            Basis::None => String::new(),
            Basis::Zero => {
                let names: Vec<&str> = p.into_iter().chain(n).collect();
                format!("{} = 0 (all control points zero)", names.join(" = "))
            }
            Basis::Unit(k) => format!("{0}[{k}] = 1, other {0}[j] = 0", p.unwrap_or("b")),
            Basis::NetUnit(i, j) => format!("{0}[{i}, {j}] = 1, other {0}[k, l] = 0", n.unwrap_or("b")),
        }
    }
}

/// What one checked equality established.
#[derive(Clone, Debug, Default)]
pub struct PairProof {
    /// Per parameter: (name, degree needed, lhs bound, rhs bound, rational?).
    pub degrees: Vec<(String, u64, Deg, Deg)>,
    /// The parameter values checked, per parameter.
    pub points: Vec<Vec<BigRational>>,
    /// How many basis polygons.
    pub polygons: usize,
    /// Exact evaluations done (both sides).
    pub evaluations: usize,
    /// Candidate parameters skipped because a denominator vanished.
    pub skipped: usize,
    /// Detailed lines (for explain).
    pub lines: Vec<String>,
}

/// The outcome of one equality check.
pub enum PairResult {
    /// Proved, with what was checked.
    Proved(PairProof),
    /// Fails: the counterexample.
    Fails(String),
}

fn describe_deg(d: &Value<Deg>, v: &str) -> String {
    let ds: Vec<(u64, u64)> = d.entries().iter().map(|x| x.get(v)).collect();
    let n = ds.iter().map(|x| x.0).max().unwrap_or(0);
    let m = ds.iter().map(|x| x.1).max().unwrap_or(0);
    if m == 0 {
        format!("{n}")
    } else {
        format!("{n}/{m}")
    }
}

fn needed_degree(l: &Value<Deg>, r: &Value<Deg>, v: &str) -> Result<u64> {
    let mut need = 0;
    for (a, b) in l.paired_entries(r)? {
        let (na, da) = a.get(v);
        let (nb, db) = b.get(v);
        let d = if da == 0 && db == 0 {
            na.max(nb)
        } else {
            (na + db).max(nb + da)
        };
        need = need.max(d);
    }
    Ok(need)
}

/// Proves or refutes `lhs = rhs` for all parameter values, at one integer instance, exactly.
pub fn prove_equal<T: Exact>(
    ctx: &Ctx<'_>,
    lhs: &Expr,
    rhs: &Expr,
    ints: &BTreeMap<String, i64>,
    detail: bool,
) -> Result<PairResult>
where
    for<'a> &'a T: RefOps<T>,
{
    let prepared = prepare::<T>(ctx, lhs, rhs, ints, detail)?;
    prove_prepared(ctx, lhs, rhs, ints, detail, prepared)
}

fn prove_prepared<T: Exact>(
    ctx: &Ctx<'_>,
    lhs: &Expr,
    rhs: &Expr,
    ints: &BTreeMap<String, i64>,
    detail: bool,
    prepared: Prepared<T>,
) -> Result<PairResult>
where
    for<'a> &'a T: RefOps<T>,
{
    let Prepared {
        params,
        mut num,
        basis,
        needs,
        mut proof,
        ..
    } = prepared;

    // Choose the parameter sets and check on the grid; a point where some denominator
    // vanishes is replaced by the next candidate of its (last) parameter.
    let mut gens: Vec<Candidates> = needs.iter().map(|&d| Candidates::new(d)).collect();
    let mut sets: Vec<Vec<BigRational>> = gens
        .iter_mut()
        .zip(&needs)
        .map(|(g, &d)| g.take(d + 1).collect())
        .collect();
    let limit_skips = 64 + needs.iter().sum::<usize>() * 4;
    'retry: loop {
        let mut idx = vec![0usize; params.len()];
        let mut lines = Vec::new();
        let mut evaluations = 0;
        loop {
            let values: Vec<BigRational> = idx.iter().zip(&sets).map(|(&i, s)| s[i].clone()).collect();
            for b in &basis {
                set_basis(&mut num, b);
                for (v, x) in params.iter().zip(&values) {
                    num.vars.insert(v.clone(), Value::S(T::from_rational(x)?));
                }
                let l = Evaluator::new(&num, ints.clone()).eval(lhs);
                let r = Evaluator::new(&num, ints.clone()).eval(rhs);
                evaluations += 2;
                let (l, r) = match (l, r) {
                    (Ok(l), Ok(r)) => (l, r),
                    (Err(e @ (Error::DivisionByZero(_) | Error::Singular(_))), _)
                    | (_, Err(e @ (Error::DivisionByZero(_) | Error::Singular(_)))) => {
                        // Replace the offending value of the last parameter and start again.
                        proof.skipped += 1;
                        if params.is_empty() || proof.skipped > limit_skips {
                            return Err(Error::Domain(format!(
                                "no parameter values found where every denominator is non-zero ({e}); \
                                 is a denominator the zero polynomial?"
                            )));
                        }
                        let k = params.len() - 1;
                        let fresh = gens[k].next().expect("candidates are infinite");
                        sets[k][idx[k]] = fresh;
                        continue 'retry;
                    }
                    (Err(e), _) | (_, Err(e)) => return Err(e),
                };
                // Described only when it is printed: formatting every point costs more than
                // evaluating a small claim.
                let at = || describe_point(&params, &values, ints, b, ctx);
                match l.equals(&r) {
                    Some(true) => {
                        if detail {
                            lines.push(format!("{}: both sides = {l}", at()));
                        }
                    }
                    Some(false) => {
                        let at = at();
                        return Ok(PairResult::Fails(format!("at {at}: left side = {l}, right side = {r}")));
                    }
                    None => {
                        let at = at();
                        return Err(Error::Domain(format!(
                            "at {at} the sides are {l} and {r}: the claim mixes square roots of different fields \
                             (exact arithmetic here is in one Q(√d) per claim), so it cannot be decided"
                        )));
                    }
                }
            }
            // next grid point
            let mut k = params.len();
            loop {
                if k == 0 {
                    proof.points = sets;
                    proof.evaluations = evaluations;
                    proof.lines.extend(lines);
                    return Ok(PairResult::Proved(proof));
                }
                k -= 1;
                idx[k] += 1;
                if idx[k] < sets[k].len() {
                    break;
                }
                idx[k] = 0;
            }
        }
    }
}

/// A pair of sides ready to be checked at one integer instance.
struct Prepared<T> {
    params: Vec<String>,
    num: NumEnv<T>,
    basis: Vec<Basis>,
    needs: Vec<usize>,
    proof: PairProof,
    /// The estimated work, in units of [`MAX_WORK`].
    work: u128,
}

/// Largest estimated work of one claim, in units of one exact evaluation of an expression of
/// degree `d` counted as `(1 + d)²` (d: the identity's degree plus the degree of the symbolic
/// polygon or net), times `w²` where `w = max(1, (1 + d)·L/64)` words for literals of `L` bits,
/// summed over every case, pair of sides, basis polygon and sample point.
pub const MAX_WORK: u128 = 50_000_000;

/// The largest size in bits (numerator and denominator) of a number written in `e`.
fn literal_bits(e: &Expr) -> u64 {
    let mut bits = 0;
    e.visit(&mut |x| {
        if let Expr::Num(r) = x {
            bits = bits.max(r.numer().bits() + r.denom().bits());
        }
    });
    bits
}

/// The work of checking `lhs = rhs` at one instance, estimated before computing.
pub fn estimate_work<T: Exact>(ctx: &Ctx<'_>, lhs: &Expr, rhs: &Expr, ints: &BTreeMap<String, i64>) -> Result<u128>
where
    for<'a> &'a T: RefOps<T>,
{
    Ok(prepare::<T>(ctx, lhs, rhs, ints, false)?.work)
}

fn prepare<T: Exact>(
    ctx: &Ctx<'_>,
    lhs: &Expr,
    rhs: &Expr,
    ints: &BTreeMap<String, i64>,
    detail: bool,
) -> Result<Prepared<T>>
where
    for<'a> &'a T: RefOps<T>,
{
    let params = ctx.params(&[lhs, rhs]);
    let mut num: NumEnv<T> = NumEnv::new(ctx.claim)?;
    // Shape the symbolic polygon/net for this instance. Both sides are affine in all their
    // control points together, so one basis covers every declared polygon and net at once:
    // all zero, then each single control point of each object set to 1.
    let mut basis = vec![Basis::Zero];
    if let Some(p) = &ctx.claim.polygon {
        let n = expr::eval_int(&parse(&p.degree, &[])?, ints)?;
        check_index(n)?;
        if n < 0 {
            return Err(Error::Domain(format!("polygon {} of negative degree {n}", p.name)));
        }
        num.polygon = Some((p.name.clone(), vec![T::zero(); n as usize + 1]));
        basis.extend((0..=n as usize).map(Basis::Unit));
    }
    if let Some(p) = &ctx.claim.net {
        let m = expr::eval_int(&parse(&p.degree[0], &[])?, ints)?;
        let n = expr::eval_int(&parse(&p.degree[1], &[])?, ints)?;
        check_index(m)?;
        check_index(n)?;
        if m < 0 || n < 0 {
            return Err(Error::Domain(format!("net {} of negative degree", p.name)));
        }
        num.net = Some((p.name.clone(), vec![vec![T::zero(); n as usize + 1]; m as usize + 1]));
        basis.extend((0..=m as usize).flat_map(|i| (0..=n as usize).map(move |j| Basis::NetUnit(i, j))));
    }

    // Degree bounds, derived by evaluating both sides in the algebra of degree bounds.
    let degenv = DegEnv::new(&num, &params);
    let dl = Evaluator::new(&degenv, ints.clone()).eval(lhs)?;
    let dr = Evaluator::new(&degenv, ints.clone()).eval(rhs)?;
    for (side, d) in [("left", &dl), ("right", &dr)] {
        if d.entries().iter().any(|x| x.poly > 1) {
            return Err(Error::Domain(format!(
                "the {side} side is not affine in the symbolic control points (it multiplies two of them)"
            )));
        }
    }
    let uses_polygon = dl.entries().iter().chain(dr.entries().iter()).any(|x| x.poly > 0);
    if !uses_polygon {
        basis = vec![Basis::None];
    }
    let mut proof = PairProof {
        polygons: basis.len(),
        ..Default::default()
    };
    let mut needs = Vec::new();
    for v in &params {
        let need = needed_degree(&dl, &dr, v)?;
        if need > 100_000 {
            return Err(Error::TooLarge {
                what: "degree of the identity",
                value: need.to_string(),
                limit: "100000".into(),
            });
        }
        needs.push(need as usize);
        proof.degrees.push((
            v.clone(),
            need,
            dl.entries().first().map(|x| (*x).clone()).unwrap_or_default(),
            dr.entries().first().map(|x| (*x).clone()).unwrap_or_default(),
        ));
        if detail {
            proof.lines.push(format!(
                "degree in {v}: left side {}, right side {} (num/den bounds from the expression) ⇒ the cleared difference has degree ≤ {need}, so {} points suffice",
                describe_deg(&dl, v),
                describe_deg(&dr, v),
                need + 1
            ));
        }
    }
    let object_degree = num.polygon.as_ref().map_or(0, |p| p.1.len() - 1)
        + num.net.as_ref().map_or(0, |n| n.1.len() + n.1[0].len() - 2);
    let total: usize = needs
        .iter()
        .map(|d| d + 1)
        .product::<usize>()
        .saturating_mul(basis.len());
    if total.saturating_mul(2) > MAX_EVALUATIONS {
        return Err(Error::TooLarge {
            what: "number of exact evaluations",
            value: total.to_string(),
            limit: MAX_EVALUATIONS.to_string(),
        });
    }
    let size = 1 + needs.iter().copied().max().unwrap_or(0) as u128 + object_degree as u128;
    // Numbers grow with the degree: a literal of L bits raised to degree d has d·L bits, and
    // one product of such numbers costs about (d·L/64)² word operations.
    let words = (size * u128::from(literal_bits(lhs).max(literal_bits(rhs))) / 64).max(1);
    let work = (total as u128)
        .saturating_mul(2)
        .saturating_mul(size * size)
        .saturating_mul(words.saturating_mul(words));
    Ok(Prepared {
        params,
        num,
        basis,
        needs,
        proof,
        work,
    })
}

fn set_basis<T: Exact>(num: &mut NumEnv<T>, b: &Basis)
where
    for<'a> &'a T: RefOps<T>,
{
    if let Some((_, c)) = &mut num.polygon {
        c.iter_mut().for_each(|x| *x = T::zero());
        if let Basis::Unit(k) = b {
            c[*k] = T::one();
        }
    }
    if let Some((_, n)) = &mut num.net {
        n.iter_mut().flatten().for_each(|x| *x = T::zero());
        if let Basis::NetUnit(i, j) = b {
            n[*i][*j] = T::one();
        }
    }
}

fn describe_point(
    params: &[String],
    values: &[BigRational],
    ints: &BTreeMap<String, i64>,
    b: &Basis,
    ctx: &Ctx<'_>,
) -> String {
    let mut parts: Vec<String> = ints.iter().map(|(k, v)| format!("{k} = {v}")).collect();
    parts.extend(params.iter().zip(values).map(|(p, v)| format!("{p} = {v}")));
    let bd = b.describe(ctx);
    if !bd.is_empty() {
        parts.push(bd);
    }
    if parts.is_empty() {
        "the constant case".into()
    } else {
        parts.join(", ")
    }
}

fn list(v: &[BigRational]) -> String {
    v.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", ")
}

/// A one-line summary of a pair proof.
pub fn pair_summary(p: &PairProof) -> String {
    let mut s = String::new();
    if p.degrees.is_empty() {
        s.push_str("no parameters: checked exactly");
    } else {
        let parts: Vec<String> = p
            .degrees
            .iter()
            .zip(&p.points)
            .map(|((v, need, _, _), pts)| {
                if pts.len() <= 8 {
                    format!(
                        "degree ≤ {need} in {v}, equal at {v} = {} ({} points)",
                        list(pts),
                        pts.len()
                    )
                } else {
                    format!("degree ≤ {need} in {v}, equal at {} values of {v}", pts.len())
                }
            })
            .collect();
        s.push_str(&parts.join("; "));
        if p.degrees.len() > 1 {
            let _ = write!(
                s,
                " (a {} grid)",
                p.points
                    .iter()
                    .map(|x| x.len().to_string())
                    .collect::<Vec<_>>()
                    .join("×")
            );
        }
    }
    if p.polygons > 1 {
        let _ = write!(
            s,
            ", on {} basis polygons (zero and unit; both sides affine in the control points)",
            p.polygons
        );
    }
    if p.skipped > 0 {
        let _ = write!(
            s,
            ", {} candidate values skipped where a denominator vanishes",
            p.skipped
        );
    }
    s
}

/// The estimated work of checking the chain `sides` for every instance of the claim's
/// ranges, added to `before` (the work of earlier parts of the same claim); an error naming
/// [`MAX_WORK`] as soon as the sum exceeds it, before anything is evaluated.
pub fn chain_work<T: Exact>(ctx: &Ctx<'_>, sides: &[Expr], before: u128) -> Result<u128>
where
    for<'a> &'a T: RefOps<T>,
{
    let mut work = before;
    for inst in &ctx.instances()? {
        for pair in sides.windows(2) {
            work = work.saturating_add(estimate_work::<T>(ctx, &pair[0], &pair[1], inst)?);
            if work > MAX_WORK {
                return Err(too_much_work(work));
            }
        }
    }
    Ok(work)
}

fn too_much_work(work: u128) -> Error {
    Error::TooLarge {
        what: "estimated work of the claim",
        value: format!("more than {work} units"),
        limit: format!("MAX_WORK = {MAX_WORK} units: exact evaluations × (1 + degree)² × (words of the numbers)²"),
    }
}

/// Checks a chain `e0 = e1 = …` for every instance of the integer ranges.
pub fn check_chain<T: Exact>(ctx: &Ctx<'_>, sides: &[Expr], detail: bool) -> Result<Checked>
where
    for<'a> &'a T: RefOps<T>,
{
    if sides.len() < 2 {
        return Err(Error::Parse(format!(
            "claim {}: an identity needs two sides",
            ctx.claim.id
        )));
    }
    let instances = ctx.instances()?;
    // Bounded work: every pair of every case is prepared (degrees derived, basis chosen) and
    // the whole claim's work estimated before anything is evaluated.
    let mut plans = Vec::with_capacity(instances.len() * (sides.len() - 1));
    let mut work: u128 = 0;
    for inst in &instances {
        for pair in sides.windows(2) {
            let plan = prepare::<T>(ctx, &pair[0], &pair[1], inst, detail)?;
            work = work.saturating_add(plan.work);
            if work > MAX_WORK {
                return Err(too_much_work(work));
            }
            plans.push(plan);
        }
    }
    let mut plans = plans.into_iter();
    let mut steps = Vec::new();
    let mut max_need: BTreeMap<String, u64> = BTreeMap::new();
    let mut evaluations = 0;
    let mut last: Option<PairProof> = None;
    let mut first_params: Vec<BigRational> = Vec::new();
    let mut rational = false;
    let mut polygons = (usize::MAX, 0usize);
    for inst in &instances {
        for (k, pair) in sides.windows(2).enumerate() {
            let plan = plans.next().expect("one plan per case and pair");
            match prove_prepared::<T>(ctx, &pair[0], &pair[1], inst, detail, plan)? {
                PairResult::Fails(cx) => {
                    let which = if sides.len() > 2 {
                        format!("step {} ('{}' = '{}') ", k + 1, pair[0], pair[1])
                    } else {
                        String::new()
                    };
                    let mut c = Checked::new(Verdict::Fails, format!("{which}{cx}"));
                    c.steps = steps;
                    c.steps.push(format!("FAILS {which}{cx}"));
                    return Ok(c);
                }
                PairResult::Proved(p) => {
                    for (v, need, l, r) in &p.degrees {
                        let e = max_need.entry(v.clone()).or_insert(0);
                        *e = (*e).max(*need);
                        rational |= !l.is_polynomial() || !r.is_polynomial();
                    }
                    polygons = (polygons.0.min(p.polygons), polygons.1.max(p.polygons));
                    evaluations += p.evaluations;
                    if detail {
                        let head = if inst.is_empty() {
                            String::new()
                        } else {
                            format!(
                                "[{}] ",
                                inst.iter()
                                    .map(|(k, v)| format!("{k} = {v}"))
                                    .collect::<Vec<_>>()
                                    .join(", ")
                            )
                        };
                        steps.push(format!("{head}'{}' = '{}': {}", pair[0], pair[1], pair_summary(&p)));
                        steps.extend(p.lines.iter().map(|l| format!("    {l}")));
                    }
                    if first_params.is_empty() {
                        first_params = p.points.first().cloned().unwrap_or_default();
                    }
                    last = Some(p);
                }
            }
        }
    }
    let what = if sides.len() > 2 {
        format!("all {} equalities of the chain", sides.len() - 1)
    } else {
        "identity".into()
    };
    let cert = if instances.len() == 1 {
        let p = last.expect("one instance checked");
        let rat = if rational {
            " (rational functions: the cleared numerators P1·Q2 − P2·Q1 are compared, at points where no denominator vanishes)"
        } else {
            ""
        };
        format!(
            "{what}: {}{rat}; {evaluations} exact evaluations: proof",
            pair_summary(&p)
        )
    } else {
        let degs: Vec<String> = max_need.iter().map(|(v, d)| format!("{v} ≤ {d}")).collect();
        let poly = if polygons.1 > 1 {
            format!(
                "; each case on its {}–{} basis polygons (zero and unit control polygons; both sides affine in them)",
                polygons.0, polygons.1
            )
        } else {
            String::new()
        };
        let degs = if degs.is_empty() {
            "no continuous parameters".to_string()
        } else {
            format!(
                "degrees (from the expressions) up to {}, each case at d+1 points per parameter",
                degs.join(", ")
            )
        };
        format!(
            "{what} for every {} ({} cases): {degs}{poly}; {evaluations} exact evaluations: proof",
            ctx.range_text(),
            instances.len()
        )
    };
    let mut c = Checked::new(Verdict::Proved, cert);
    c.steps = steps;
    c.params = first_params;
    Ok(c)
}

// ---------------------------------------------------------------------------------------
// Symbolic expansion

/// The symbolic environment: every scalar symbol and every vector component is a variable.
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

fn sym_names(ctx: &Ctx<'_>, extra: &[String]) -> (Rc<[String]>, Vec<(String, usize)>) {
    let mut names: Vec<String> = Vec::new();
    let mut layout = Vec::new();
    for s in ctx.claim.symbols.iter().flatten().chain(extra) {
        if !names.contains(s) {
            layout.push((s.clone(), 0));
            names.push(s.clone());
        }
    }
    for (v, &dim) in ctx.claim.vectors.iter().flatten() {
        layout.push((v.clone(), dim));
        for k in 1..=dim {
            names.push(format!("{v}_{k}"));
        }
    }
    (Rc::from(names), layout)
}

fn sym_env(names: &Rc<[String]>, layout: &[(String, usize)]) -> SymEnv {
    set_names(names);
    let mut vars = BTreeMap::new();
    let mut k = 0;
    for (v, dim) in layout {
        if *dim == 0 {
            vars.insert(v.clone(), Value::S(RatFunc::poly(Poly::var(names, k))));
            k += 1;
        } else {
            let comps = (0..*dim).map(|i| RatFunc::poly(Poly::var(names, k + i))).collect();
            vars.insert(v.clone(), Value::V(comps));
            k += dim;
        }
    }
    SymEnv { vars }
}

/// A point where a nonzero polynomial does not vanish (small integers tried in turn).
fn nonzero_point(p: &Poly, n: usize) -> Vec<BigRational> {
    // Deterministic search: values 1..=K cycled with different strides per variable.
    for attempt in 0..10_000u64 {
        let point: Vec<BigRational> = (0..n)
            .map(|i| {
                let x = ((attempt + 1) * (i as u64 * 7 + 3) + i as u64 * attempt) % 11;
                BigRational::from_integer((x as i64 - 5).into())
            })
            .collect();
        if !p.eval(&point).is_zero() {
            return point;
        }
    }
    vec![BigRational::one(); n]
}

fn sym_assignment(
    names: &Rc<[String]>,
    layout: &[(String, usize)],
    point: &[BigRational],
) -> (String, BTreeMap<String, Value<BigRational>>) {
    let mut vars = BTreeMap::new();
    let mut parts = Vec::new();
    let mut k = 0;
    for (v, dim) in layout {
        if *dim == 0 {
            vars.insert(v.clone(), Value::S(point[k].clone()));
            parts.push(format!("{v} = {}", point[k]));
            k += 1;
        } else {
            let comps: Vec<BigRational> = point[k..k + dim].to_vec();
            parts.push(format!("{v} = ({})", list(&comps)));
            vars.insert(v.clone(), Value::V(comps));
            k += dim;
        }
    }
    let _ = names;
    (parts.join(", "), vars)
}

/// Largest degree, in any one variable, of the numerators and denominators a symbolic
/// expansion may build (checked on the derived bounds before expanding).
pub const MAX_SYMBOLIC_DEGREE: u64 = 4_096;

/// Checks, before expanding, that `exprs` expand to degrees at most [`MAX_SYMBOLIC_DEGREE`]
/// in each of the variables `vars` (scalars and vector coordinates, as degree bounds).
pub fn check_symbolic_degrees(
    vars: BTreeMap<String, Value<Deg>>,
    ints: &BTreeMap<String, i64>,
    exprs: &[&Expr],
) -> Result<()> {
    let env = VarEnv(vars);
    for e in exprs {
        let d = Evaluator::new(&env, ints.clone()).eval(e)?;
        for x in d.entries() {
            for (v, &(num, den)) in &x.vars {
                if num.max(den) > MAX_SYMBOLIC_DEGREE {
                    return Err(Error::TooLarge {
                        what: "degree of a symbolic expansion",
                        value: format!("{} in {v}", num.max(den)),
                        limit: format!("MAX_SYMBOLIC_DEGREE = {MAX_SYMBOLIC_DEGREE} per variable"),
                    });
                }
            }
        }
    }
    Ok(())
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

/// Proves or refutes `lhs = rhs` by exact symbolic expansion in the claim's symbols.
pub fn symbolic_equal(ctx: &Ctx<'_>, lhs: &Expr, rhs: &Expr, ints: &BTreeMap<String, i64>) -> Result<PairResult> {
    let extra = ctx.params(&[lhs, rhs]);
    let extra: Vec<String> = extra.into_iter().filter(|v| !ctx.is_bound(v)).collect();
    let (names, layout) = sym_names(ctx, &extra);
    check_symbolic_degrees(layout_degrees(&layout), ints, &[lhs, rhs])?;
    let env = sym_env(&names, &layout);
    let l = Evaluator::new(&env, ints.clone()).eval(lhs)?;
    let r = Evaluator::new(&env, ints.clone()).eval(rhs)?;
    let mut terms = 0;
    for (a, b) in l.paired_entries(&r)? {
        let d = a.cleared_difference(b);
        if !d.is_zero() {
            let point = nonzero_point(&d, names.len());
            let (at, vars) = sym_assignment(&names, &layout, &point);
            let env = VarEnv(vars);
            let lv = Evaluator::new(&env, ints.clone()).eval(lhs);
            let rv = Evaluator::new(&env, ints.clone()).eval(rhs);
            let shown = match (lv, rv) {
                (Ok(x), Ok(y)) => format!("left side = {x}, right side = {y}"),
                _ => "a denominator vanishes there".into(),
            };
            return Ok(PairResult::Fails(format!(
                "the difference of the two sides does not expand to 0 (it has {} terms); at {at}: {shown}",
                d.len()
            )));
        }
        terms += a.num.len() + b.num.len();
    }
    let mut proof = PairProof::default();
    proof.lines.push(format!(
        "expanded exactly in {} variables ({}); both sides agree term by term after clearing denominators ({terms} terms)",
        names.len(),
        names.join(", ")
    ));
    Ok(PairResult::Proved(proof))
}

/// Checks a chain by symbolic expansion.
pub fn check_chain_symbolic(ctx: &Ctx<'_>, sides: &[Expr], detail: bool) -> Result<Checked> {
    let instances = ctx.instances()?;
    let mut steps = Vec::new();
    let mut nvars = 0;
    for inst in &instances {
        for (k, pair) in sides.windows(2).enumerate() {
            match symbolic_equal(ctx, &pair[0], &pair[1], inst)? {
                PairResult::Fails(cx) => {
                    let which = if sides.len() > 2 {
                        format!("step {} ('{}' = '{}'): ", k + 1, pair[0], pair[1])
                    } else {
                        String::new()
                    };
                    let mut c = Checked::new(Verdict::Fails, format!("{which}{cx}"));
                    c.steps = steps;
                    return Ok(c);
                }
                PairResult::Proved(p) => {
                    if detail {
                        steps.push(format!("'{}' = '{}':", pair[0], pair[1]));
                        steps.extend(p.lines.iter().map(|l| format!("    {l}")));
                    }
                    nvars = sym_names(ctx, &[]).0.len();
                }
            }
        }
    }
    let what = if sides.len() > 2 {
        format!("all {} equalities of the chain", sides.len() - 1)
    } else {
        "identity".into()
    };
    let mut c = Checked::new(
        Verdict::Proved,
        format!(
            "{what} expanded exactly as rational functions of the {nvars} coordinates of {}: the cleared numerators agree: proof",
            sym_names(ctx, &[]).1.iter().map(|(v, _)| v.clone()).collect::<Vec<_>>().join(", ")
        ),
    );
    c.steps = steps;
    Ok(c)
}

/// Why `conclusion = factor · premise` (an identity of rational functions) may not make the
/// premise imply the conclusion, or `None` when it does: at a point where the premise holds
/// (its numerator `P_n` vanishes) and the conclusion is defined (its formal denominator
/// `D_c ≠ 0`), `D_c · conclusion = Σ_j (F_ij D_c / P_dj) · P_n,j`, which is 0 when every
/// `F_ij D_c / P_dj` is a polynomial. So the factor's denominator may only vanish where the
/// conclusion is undefined anyway (e.g. `inv(M)` on both sides); otherwise the claim is refused.
fn factor_pole(ctx: &Ctx<'_>, concl: &Expr, factor: &Expr, prem: &Expr) -> Result<Option<String>> {
    let extra: Vec<String> = ctx
        .params(&[concl, factor, prem])
        .into_iter()
        .filter(|v| !ctx.is_bound(v))
        .collect();
    let (names, layout) = sym_names(ctx, &extra);
    let env = sym_env(&names, &layout);
    let c = Evaluator::new(&env, BTreeMap::new()).eval(concl)?;
    let f = Evaluator::new(&env, BTreeMap::new()).eval(factor)?;
    let p = Evaluator::new(&env, BTreeMap::new()).eval(prem)?;
    let (cs, ps) = (c.entries(), p.entries());
    let entries: Vec<(usize, usize, &RatFunc)> = match &f {
        Value::S(x) => (0..cs.len()).map(|i| (i, i, x)).collect(),
        Value::M(m) => m
            .iter()
            .enumerate()
            .flat_map(|(i, r)| r.iter().enumerate().map(move |(j, x)| (i, j, x)))
            .collect(),
        Value::V(_) => {
            return Err(Error::Domain(
                "the factor of implies must be a number or a matrix".into(),
            ))
        }
    };
    for (i, j, fij) in entries {
        let (Some(ci), Some(pj)) = (cs.get(i), ps.get(j)) else {
            continue;
        };
        if fij.num.is_zero() {
            continue;
        }
        if fij.num.mul(&ci.den).exact_div(&fij.den.mul(&pj.den)).is_none() {
            return Ok(Some(format!(
                "the factor '{factor}' has the denominator {}, which may vanish where the equation is defined",
                fij.den
            )));
        }
    }
    Ok(None)
}

/// How many points the counterexample search of an `implies` with a pole in its factor tries.
pub const POLE_SEARCH: usize = 2_401;

/// Where `conclusion = factor · premise` holds identically, the premise can hold while the
/// conclusion fails only where the factor has a pole. Small rational points (coordinates from
/// 0, ±1, ±2, 1/2, 3, the smallest first) are tried for one where the premise is 0 and the
/// equation `a = b` is defined and false: an exact counterexample.
fn refute_at_poles(ctx: &Ctx<'_>, prem: &Expr, (a, b): (&Expr, &Expr)) -> Result<Option<Checked>> {
    let c = ctx.claim;
    let extra: Vec<String> = ctx
        .params(&[prem, a, b])
        .into_iter()
        .filter(|v| !ctx.is_bound(v))
        .collect();
    let (names, layout) = sym_names(ctx, &extra);
    let values: Vec<BigRational> = [(0, 1), (1, 1), (-1, 1), (2, 1), (-2, 1), (1, 2), (3, 1)]
        .iter()
        .map(|&(p, q)| BigRational::new(p.into(), q.into()))
        .collect();
    let inst = BTreeMap::new();
    let at = |vars: &BTreeMap<String, Value<BigRational>>, e: &Expr| {
        Evaluator::new(&VarEnv(vars.clone()), inst.clone()).eval(e)
    };
    let mut tried = 0;
    // Points whose largest coordinate rank is `top`, for `top` = 0, 1, …: smallest first.
    for top in 0..values.len() {
        let mut digits = vec![0usize; names.len()];
        loop {
            if digits.contains(&top) || (top == 0 && digits.is_empty()) {
                tried += 1;
                if tried > POLE_SEARCH {
                    return Ok(None);
                }
                let point: Vec<BigRational> = digits.iter().map(|&d| values[d].clone()).collect();
                let (shown, vars) = sym_assignment(&names, &layout, &point);
                let holds = at(&vars, prem).is_ok_and(|p| p.entries().iter().all(|x| x.is_zero()));
                if holds {
                    if let (Ok(av), Ok(bv)) = (at(&vars, a), at(&vars, b)) {
                        if av.equals(&bv) == Some(false) {
                            return Ok(Some(Checked::new(
                                Verdict::Fails,
                                format!(
                                    "at {shown}: the premise '{}' holds (the factor has a pole there), but the equation '{}' gives left side = {av}, right side = {bv}",
                                    c.premise.as_deref().unwrap_or_default(),
                                    c.equation.as_deref().unwrap_or_default()
                                ),
                            )));
                        }
                    }
                }
            }
            // The next point with every coordinate rank ≤ top.
            let Some(k) = digits.iter().rposition(|&d| d < top) else {
                break;
            };
            digits[k] += 1;
            digits[k + 1..].iter_mut().for_each(|d| *d = 0);
        }
    }
    Ok(None)
}

/// `implies`: `conclusion_lhs − conclusion_rhs = factor · (premise_lhs − premise_rhs)` identically,
/// so the premise implies the conclusion. When it is not an identity, an exact counterexample
/// is searched where the premise holds and the conclusion does not.
pub fn check_implies(ctx: &Ctx<'_>, detail: bool) -> Result<Checked> {
    let c = ctx.claim;
    let (a, b) = ctx.equation(c.need(&c.equation, "equation")?)?;
    let (p, q) = ctx.equation(c.need(&c.premise, "premise")?)?;
    let factor = ctx.expr(c.need(&c.factor, "factor")?)?;
    let is_zero = |e: &Expr| matches!(e, Expr::Num(r) if Scalar::is_zero(r));
    let concl = Expr::sub(a.clone(), b.clone());
    let prem = if is_zero(&q) {
        p.clone()
    } else {
        Expr::sub(p.clone(), q.clone())
    };
    let rhs = Expr::mul(factor.clone(), prem.clone());
    let inst = BTreeMap::new();
    match symbolic_equal(ctx, &concl, &rhs, &inst)? {
        PairResult::Proved(pp) => {
            if let Some(reason) = factor_pole(ctx, &concl, &factor, &prem)? {
                if let Some(found) = refute_at_poles(ctx, &prem, (&a, &b))? {
                    return Ok(found);
                }
                return Err(Error::Domain(format!(
                    "the equation is factor × premise identically, but {reason}: where it vanishes and the premise holds, \
                     nothing follows, so the implication is not proved (refused; no counterexample among the first {POLE_SEARCH} small rational points)"
                )));
            }
            let mut out = Checked::new(
                Verdict::Proved,
                format!(
                    "[{}] = ({}) · [{}] identically, as rational functions of the symbols and vector coordinates \
                     (exact symbolic expansion), so '{} = 0' implies the equation: proof",
                    c.equation.as_deref().unwrap_or_default(),
                    c.factor.as_deref().unwrap_or_default(),
                    c.premise.as_deref().unwrap_or_default(),
                    c.premise.as_deref().unwrap_or_default()
                ),
            );
            if detail {
                out.steps = pp.lines;
            }
            Ok(out)
        }
        PairResult::Fails(_) => {
            // A concrete counterexample: data where the premise holds (solved for the first
            // symbol, which it contains linearly) but the equation does not.
            let unknown = c
                .symbols
                .as_ref()
                .and_then(|s| s.first().cloned())
                .ok_or_else(|| Error::Parse(format!("claim {}: implies needs symbols (the unknowns)", c.id)))?;
            let (names, layout) = sym_names(ctx, &[]);
            for attempt in 0..200u64 {
                let point: Vec<BigRational> = (0..names.len())
                    .map(|i| {
                        BigRational::from_integer((((attempt + 2) * (i as u64 * 5 + 1) + attempt) % 7).into())
                            - BigRational::from_integer(3.into())
                    })
                    .collect();
                let (_, mut vars) = sym_assignment(&names, &layout, &point);
                // other symbols 0, the unknown solved from the (linear) premise
                for s in c.symbols.iter().flatten() {
                    vars.insert(s.clone(), Value::S(BigRational::zero()));
                }
                let eval_prem = |vars: &BTreeMap<String, Value<BigRational>>| -> Result<Value<BigRational>> {
                    let env = VarEnv(vars.clone());
                    Evaluator::new(&env, inst.clone()).eval(&prem)
                };
                let p0 = eval_prem(&vars)?;
                vars.insert(unknown.clone(), Value::S(BigRational::one()));
                let p1 = eval_prem(&vars)?;
                let (Value::S(p0), Value::S(p1)) = (p0, p1) else {
                    return Err(Error::Domain(
                        "implies with a vector premise needs a proof, not a search".into(),
                    ));
                };
                let slope = &p1 - &p0;
                if slope.is_zero() {
                    continue;
                }
                let k = -&p0 / &slope;
                vars.insert(unknown.clone(), Value::S(k));
                let env = VarEnv(vars.clone());
                let pv = Evaluator::new(&env, inst.clone()).eval(&prem)?;
                let av = Evaluator::new(&env, inst.clone()).eval(&a)?;
                let bv = Evaluator::new(&env, inst.clone()).eval(&b)?;
                if pv.equals(&Value::S(BigRational::zero())) == Some(true) && av.equals(&bv) == Some(false) {
                    let shown: Vec<String> = vars.iter().map(|(k, v)| format!("{k} = {v}")).collect();
                    return Ok(Checked::new(
                        Verdict::Fails,
                        format!(
                            "at {}: the premise '{}' = 0 holds, but the equation '{}' gives left side = {av}, right side = {bv}",
                            shown.join(", "),
                            c.premise.as_deref().unwrap_or_default(),
                            c.equation.as_deref().unwrap_or_default()
                        ),
                    ));
                }
            }
            Err(Error::Domain(format!(
                "claim {}: the equation is not factor × premise, and no counterexample was found",
                c.id
            )))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::claims::parse_file;
    use super::*;
    use std::path::Path;

    fn claim(body: &str) -> Claim {
        parse_file(
            &format!("[[claim]]\nid = \"x\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nlhs = \"1\"\nrhs = \"1\"\n{body}"),
            Path::new("t.toml"),
        )
        .unwrap()
        .claim[0]
            .clone()
    }

    #[test]
    fn ranges_enumerate_every_case_and_refuse_empty_ones() {
        let c = claim("for = [\"n = 0..=2\", \"j = 0..=n\"]");
        let ctx = Ctx::new(&c).unwrap();
        assert_eq!(ctx.instances().unwrap().len(), 6);
        assert_eq!(ctx.range_text(), "n = 0..=2, j = 0..=n");
        let c = claim("for = [\"n = 0..=2\", \"j = 1..=n\"]");
        let err = Ctx::new(&c).unwrap().instances().unwrap_err().to_string();
        assert!(err.contains("j = 1..=0 is empty (at n = 0)"), "{err}");
    }

    #[test]
    fn unknown_names_are_errors_when_the_parameters_are_listed() {
        let c = claim("vars = [\"t\"]\nsymbols = [\"k\"]");
        let ctx = Ctx::new(&c).unwrap();
        assert!(ctx.expr("t + k").is_ok());
        assert!(ctx.expr("sum(j, 0, 2, j t)").is_ok());
        let err = ctx.expr("t + q").unwrap_err().to_string();
        assert!(err.contains("unknown name 'q'"), "{err}");
        // Without `vars`, free names are the parameters (documented).
        let c = claim("");
        assert!(Ctx::new(&c).unwrap().expr("t + q").is_ok());
    }

    #[test]
    fn the_work_estimate_grows_with_degree_and_basis() {
        let c = claim("polygon = { name = \"b\", degree = \"3\" }");
        let ctx = Ctx::new(&c).unwrap();
        let (l, r) = (ctx.expr("b(t)").unwrap(), ctx.expr("bsum(b, t)").unwrap());
        let ints = BTreeMap::new();
        let w = estimate_work::<BigRational>(&ctx, &l, &r, &ints).unwrap();
        // 4 points × 5 basis polygons × 2 sides × (1 + 3 + 3)²
        assert_eq!(w, 4 * 5 * 2 * 49);
        let big = ctx.expr("(1 + t)^4096").unwrap();
        let w = estimate_work::<BigRational>(&ctx, &big, &big, &ints).unwrap();
        assert!(w > MAX_WORK, "{w}");
    }
}
