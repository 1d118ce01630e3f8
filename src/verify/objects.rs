//! A claim's objects in exact numbers and as degree bounds: constants, concrete curves and
//! surfaces, the symbolic polygon and net, and the environments the evaluator reads them from.

use super::claims::{CurveSpec, Decls, Number, SurfaceSpec};
use super::kernel::eval::{Alg, Deg, Env, Evaluator, Value, VarEnv};
use super::kernel::expr::Expr;
use super::methods::{NetMethod, PolygonMethod};
use super::parse::parse;
use crate::any_curve::AnyCurve;
use crate::curve::BezierCurve;
use crate::error::{Error, Result};
use crate::param::ParamCurve;
use crate::point::Point;
use crate::scalar::Scalar;
use crate::surface::BezierSurface;
use std::collections::{BTreeMap, BTreeSet};

// ---------------------------------------------------------------------------------------
// Numbers in claim files and objects.

/// An exact number type the identity prover can evaluate in.
pub trait Exact: Scalar + Alg {}
impl<T: Scalar + Alg> Exact for T {}

/// Evaluates a constant expression (a coordinate in a claim file).
pub fn constant<T: Exact>(text: &str) -> Result<T> {
    let e = parse(text, &[])?;
    let env = VarEnv::<T>(BTreeMap::new());
    Evaluator::new(&env, BTreeMap::new()).scalar(&e)
}

fn point<T: Exact>(coords: &[Number]) -> Result<Point<T>> {
    Point::new(coords.iter().map(|c| constant(&c.text()?)).collect::<Result<_>>()?)
}

/// Control points from a claim file.
pub fn points<T: Exact>(list: &[Vec<Number>]) -> Result<Vec<Point<T>>> {
    list.iter().map(|p| point(p)).collect()
}

/// A concrete curve of a claim, from its specification.
pub fn curve_from_spec<T: Exact>(spec: &CurveSpec) -> Result<AnyCurve<T>> {
    let pts = points::<T>(&spec.points)?;
    Ok(match &spec.weights {
        None => AnyCurve::Polynomial(BezierCurve::new(pts)?),
        Some(w) => {
            let w = w.iter().map(|x| constant(&x.text()?)).collect::<Result<Vec<T>>>()?;
            AnyCurve::Rational(crate::rational::RationalBezierCurve::new(pts, w)?)
        }
    })
}

/// A concrete surface of a claim: `net[i][j] = b_{i,j}`.
pub fn net_from_spec<T: Exact>(spec: &SurfaceSpec) -> Result<Vec<Vec<Point<T>>>> {
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

/// `∂^{ku+kv} x / ∂u^{ku} ∂v^{kv}` at `(u, v)` by the library: the surface of the derivative
/// net (`m!/(m-ku)! n!/(n-kv)! Δ_u^{ku} Δ_v^{kv} b_{i,j}`), evaluated
/// ([`BezierSurface::partial_at`]; zero beyond the degrees).
pub fn partial_net<T: Exact>(net: &[Vec<Point<T>>], ku: usize, kv: usize, u: &T, v: &T) -> Result<Point<T>> {
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
        super::kernel::expr::split_partial(name).filter(|(base, _, _)| is_surface(base))
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
        if let Some((curve, _, _)) = super::kernel::expr::split_partial(name).filter(|(b, _, _)| is_curve(b)) {
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
    pub curves: BTreeMap<String, AnyCurve<T>>,
    /// Concrete surfaces.
    pub surfaces: BTreeMap<String, Vec<Vec<Point<T>>>>,
    /// The symbolic polygon (name, one-dimensional instance).
    pub polygon: Option<(String, Vec<T>)>,
    /// The symbolic net (name, instance).
    pub net: Option<(String, Vec<Vec<T>>)>,
}

impl<T: Exact> NumEnv<T> {
    /// The objects declared.
    pub fn new(decls: &Decls) -> Result<Self> {
        let mut curves = BTreeMap::new();
        for (k, spec) in decls.curves.iter().flatten() {
            curves.insert(k.clone(), curve_from_spec(spec)?);
        }
        let mut surfaces = BTreeMap::new();
        for (k, spec) in decls.surfaces.iter().flatten() {
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

impl<T: Exact> Env<T> for NumEnv<T> {
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
                let c = AnyCurve::Polynomial(BezierCurve::new(pts)?);
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
            let AnyCurve::Polynomial(c) = c else {
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
    c: &AnyCurve<T>,
    name: &str,
    order: usize,
    args: &[Expr],
    ev: &mut Evaluator<'_, T>,
) -> Result<Value<T>> {
    match (args.len(), c) {
        (1, _) if order == 0 => Ok(Value::V(c.eval(&ev.scalar(&args[0])?)?.into_coords())),
        (1, AnyCurve::Polynomial(curve)) => {
            let t = ev.scalar(&args[0])?;
            Ok(Value::V(curve.derivative_at(order, &t)?.into_coords()))
        }
        (1, AnyCurve::Rational(curve)) => {
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
        (3, AnyCurve::Polynomial(curve)) if order == 0 => {
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
    pub fn new<T: Exact>(num: &NumEnv<T>, params: &[String]) -> Self {
        DegEnv {
            params: params.iter().cloned().collect(),
            curves: num
                .curves
                .iter()
                .map(|(k, c)| {
                    (
                        k.clone(),
                        (c.degree() as u64, c.dim(), matches!(c, AnyCurve::Rational(_))),
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
