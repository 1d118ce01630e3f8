//! The claim kinds: each turns a claim into identities (or other exact checks) and a verdict.
//!
//! | kind            | decides                                                             |
//! |-----------------|---------------------------------------------------------------------|
//! | `identity`      | `lhs = rhs` or every step of `chain`, for all parameters and ranges   |
//! | `implicit`      | the curve `on` satisfies `equation` for every parameter               |
//! | `bezier_points` | the Bézier points of a power-basis curve on `[a, b]` are `points`     |
//! | `conic_type`    | the conic `equation` (degree 2 in x, y) is the printed `conic`        |
//! | `implies`       | `equation` follows from `premise`: their difference is `factor · premise` |
//! | `theorem`       | a general theorem of the texts for every degree in `degrees`          |
//! | `convergence`   | Theorem 1.2 (bounded evidence: `verified`)                            |
//! | `fit`           | text 004's cubic fit of a concrete curve: (11) = (13), ∇δ² = 0, printed k, l, δ² |
//! | `inequality`    | `lhs ≥ rhs` (or `>`) on an interval, by a Bernstein certificate or an exact point |

use super::claims::{BezierPoints, Claim, ConicType, CurveSpec, Decls, Fit, Implicit, Kind, Number, WeightType};
use super::context::Ctx;
use super::expansion::check_implies;
use super::identity::{chain_in_field, check_identity, uses_sqrt};
use super::kernel::eval::{Alg, Deg, Evaluator, Value};
use super::kernel::expr::Expr;
use super::kernel::poly::{Poly, RatFunc};
use super::kernel::{check_computed, Trusted};
use super::lemma::Lemma;
use super::objects::{curve_from_spec, points};
use super::outcome::{Checked, Computed};
use super::rewrite::substitute;
use super::sampling::check_chain;
use super::theorems;
use crate::conic::{classify_conic, ConicKind, ImplicitConic};
use crate::curve::BezierCurve;
use crate::error::{Error, Result};
use crate::point::Point;
use crate::quadratic::QuadraticIrrational;
use crate::rational::RationalBezierCurve;
use crate::surface::BezierSurface;
use num_rational::BigRational;
use num_traits::Zero;
use std::borrow::Cow;
use std::collections::BTreeMap;
use std::rc::Rc;

/// Checks one claim; `detail` also records the steps for `explain`.
///
/// A `proved` over finite ranges (`for`, a theorem's `degrees`) is reported as
/// `proved_in_range` with the ranges: the scope is decided here, once, for every kind.
///
/// A claim that cites lemmas (`uses`) is checked with its claim files ([`super::prove_files`]),
/// which decide the lemmas first; here it is an error.
pub fn check_claim(claim: &Claim, detail: bool) -> Result<Checked> {
    if !claim.uses.is_empty() {
        return Err(Error::Domain(format!(
            "claim {} cites lemmas ({}): check it with the claim files that hold them",
            claim.id,
            claim.uses.join(", ")
        )));
    }
    check_citing(claim, &Ok(Vec::new()), detail, true).map(|(out, _)| out)
}

/// Checks one claim with the lemmas it cites, or the reason they cannot serve (a cited claim
/// not proved for every value): a claim with open ranges then is that error, one over finite
/// ranges is checked case by case as without them. The claim is elaborated once, here; its
/// context is returned with the outcome (the note on its scope and its lemma read it).
/// `certify`: also keep what only a certificate file needs ([`Ctx::certify`]); the verdict
/// and the evidence the kernel checks for it are the same either way.
pub(crate) fn check_citing<'c>(
    claim: &'c Claim,
    lemmas: &Result<Vec<Lemma>>,
    detail: bool,
    certify: bool,
) -> Result<(Checked, Ctx<'c>)> {
    let elaborate = |claim: &'c Claim| {
        elaborate(claim).map(|mut ctx| {
            ctx.certify = certify;
            ctx
        })
    };
    super::names::check_declarations(claim)?;
    if claim.for_every() {
        if let (Some(identity), false) = (claim.kind.identity(), claim.decls.symbolic()) {
            let lemmas = lemmas.as_ref().map_err(|e| Error::Domain(e.to_string()))?;
            let ctx = elaborate(claim)?;
            let out = super::symbolic::check(&ctx, &identity, lemmas, detail)?;
            return Ok((out, ctx));
        }
        return match &claim.kind {
            Kind::Inequality(ineq) => {
                let ctx = elaborate(claim)?;
                let out = super::inequality::check_for_every(&ctx, ineq, detail)?;
                Ok((out, ctx))
            }
            _ => Err(Error::Parse(format!(
                "claim {}: open ranges (n = 0..) are for identity (without symbols or vectors) and inequality claims",
                claim.id
            ))),
        };
    }
    if matches!(&claim.kind, Kind::Identity(i) if i.induction.is_some()) {
        return Err(Error::Parse(format!(
            "claim {}: induction belongs to a claim with an open range (r = 0..)",
            claim.id
        )));
    }
    if matches!(&claim.kind, Kind::Identity(i) if !i.certificates.is_empty()) {
        return Err(Error::Parse(format!(
            "claim {}: a certificate belongs to a claim with an open range (n = 0..)",
            claim.id
        )));
    }
    let ctx = elaborate(claim)?;
    let out = check_kind(&ctx, &claim.kind, detail)?;
    if out.proof().is_none() {
        return Ok((out, ctx));
    }
    let out = library_operations(&ctx, &claim.kind)
        .into_iter()
        .fold(out, Checked::resting_on);
    let scope = match &claim.kind {
        Kind::Theorem(t) => Some(theorems::scope(t)?),
        _ if claim.has_ranges() => Some(ctx.range_text()),
        _ => None,
    };
    let out = match scope {
        Some(range) => out.in_range(range),
        None => out,
    };
    Ok((out, ctx))
}

/// The claim elaborated: its declarations, with the objects its kind lowers it to (a power
/// form's curve with the printed points, Enneper's surface as a definition) and the names
/// the kind binds.
pub(crate) fn elaborate(claim: &Claim) -> Result<Ctx<'_>> {
    let decls = &claim.decls;
    let (decls, bound_by_kind) = match &claim.kind {
        Kind::Implicit(i) => (Cow::Borrowed(decls), i.coordinates()),
        Kind::BezierPoints(b) => (
            Cow::Owned(Decls {
                curves: Some(BTreeMap::from([(
                    "P".to_string(),
                    CurveSpec {
                        points: b.points.clone(),
                        weights: None,
                    },
                )])),
                vars: Some(vec![power_form_var(b).to_string()]),
                ..decls.clone()
            }),
            vec![b.parameter()],
        ),
        Kind::Enneper => (
            Cow::Owned(Decls {
                vars: Some(vec!["s".into(), "t".into()]),
                defs: vec![ENNEPER.into()],
                ..decls.clone()
            }),
            Vec::new(),
        ),
        _ => (Cow::Borrowed(decls), Vec::new()),
    };
    Ctx::new(&claim.id, decls, bound_by_kind)
}

/// Enneper's surface, the definition an `enneper` claim is lowered with.
const ENNEPER: &str = "E(u, v) = (u - u^3/3 + u*v^2, v - v^3/3 + v*u^2, u^2 - v^2)";

/// The parameter of the curve with a power form's printed points (not the power form's).
fn power_form_var(b: &BezierPoints) -> &'static str {
    if b.parameter() == "t" {
        "s"
    } else {
        "t"
    }
}

/// The library operations on a polygon or net (`bsum`, `elev`, `isou`, …) that the claim's
/// expressions call: their values are the library's, accepted by name.
fn library_operations(ctx: &Ctx<'_>, kind: &Kind) -> Vec<Trusted> {
    let Some(identity) = kind.identity() else {
        return Vec::new();
    };
    let exprs: Vec<Expr> = identity
        .sides
        .members()
        .iter()
        .filter_map(|m| ctx.expr(m).ok())
        .collect();
    super::methods::operations_called(&exprs)
}

fn check_kind(ctx: &Ctx<'_>, kind: &Kind, detail: bool) -> Result<Checked> {
    match kind {
        Kind::Identity(identity) => check_identity(ctx, &identity.sides.members(), detail),
        Kind::Implicit(implicit) => check_implicit(ctx, implicit, detail),
        Kind::BezierPoints(b) => check_bezier_points(ctx, b, detail),
        Kind::ConicType(c) => check_conic_type(ctx, c),
        Kind::Implies(i) => check_implies(ctx, i, detail),
        Kind::Theorem(t) => theorems::check_theorem(ctx, t, detail),
        Kind::Enneper => check_enneper(ctx, detail),
        Kind::WeightType(w) => check_weight_type(ctx, w),
        Kind::Convergence(c) => theorems::check_convergence(ctx, c, detail),
        Kind::Fit(f) => check_fit(ctx, f),
        Kind::Inequality(i) => super::inequality::check_inequality(ctx, i, detail),
        Kind::Vanishes(v) => check_identity(ctx, &v.identity().sides.members(), detail),
    }
}

/// Substitutes the coordinates of the curve `on` for the coordinate names in an equation.
fn on_curve(coords: &[String], e: &Expr, on: &Expr) -> Expr {
    let args: Vec<Expr> = (1..=coords.len())
        .map(|k| match on {
            Expr::Tuple(items) if k <= items.len() => items[k - 1].clone(),
            _ => Expr::Call("comp".into(), vec![on.clone(), Expr::int(k as i64)]),
        })
        .collect();
    substitute(e, coords, &args)
}

fn check_implicit(ctx: &Ctx<'_>, implicit: &Implicit, detail: bool) -> Result<Checked> {
    let on = ctx.expr(&implicit.on)?;
    let (a, b) = ctx.equation(&implicit.equation)?;
    let coords = implicit.coordinates();
    let sides = vec![on_curve(&coords, &a, &on), on_curve(&coords, &b, &on)];
    let mut out = chain_in_field(ctx, &sides, detail)?;
    out.certificate = format!("substituting the curve into the equation: {}", out.certificate);
    Ok(out)
}

/// Lowered to the identity `P(t) = power(a + (b − a) t)` over the curve `P` with the printed
/// points (declared by the claim's elaboration), then compared with the library's conversion.
fn check_bezier_points(ctx: &Ctx<'_>, claim: &BezierPoints, detail: bool) -> Result<Checked> {
    let param = claim.parameter();
    let t = power_form_var(claim);
    let [a, b] = &claim.interval;
    let pts = &claim.points;
    let power = ctx.expr(&claim.power)?;
    let (ea, eb) = (ctx.expr(&a.text()?)?, ctx.expr(&b.text()?)?);
    // u = a + (b - a) t
    let u = Expr::add(ea, Expr::mul(Expr::sub(eb, ctx.expr(&a.text()?)?), Expr::Var(t.into())));
    let lhs = Expr::Call("P".into(), vec![Expr::Var(t.into())]);
    let rhs = substitute(&power, std::slice::from_ref(&param), &[u]);
    let out = check_chain::<BigRational>(ctx, &[lhs, rhs], detail)?;
    if out.proof().is_none() {
        return Ok(out);
    }
    // The library's conversion must give the same points; the verdict then accepts it.
    let lib = library_power_on(&power, &param, a, b)?;
    let printed: Vec<Point<BigRational>> = points(pts)?;
    if lib.points() != printed.as_slice() {
        return Ok(Checked::fails(format!(
            "BezierCurve::from_power_on gives {lib}, not the printed points"
        )));
    }
    let mut out = out.resting_on(Trusted::FromPowerOn);
    out.certificate = format!(
        "the curve with the printed points equals the power form at {param} = a + (b − a){t}: {}; BezierCurve::from_power_on gives the same points",
        out.certificate
    );
    Ok(out)
}

fn library_power_on(power: &Expr, param: &str, a: &Number, b: &Number) -> Result<BezierCurve<BigRational>> {
    let names: Rc<[String]> = Rc::from(vec![param.to_string()]);
    let degrees = std::iter::once((param.to_string(), Value::S(Deg::var(param)))).collect();
    super::kernel::eval::check_symbolic_degrees(degrees, &BTreeMap::new(), &[power])?;
    let mut vars = BTreeMap::new();
    vars.insert(param.to_string(), Value::S(RatFunc::poly(Poly::var(&names, 0))));
    let env = super::kernel::eval::VarEnv(vars);
    let v = Evaluator::new(&env, BTreeMap::new()).eval(power)?;
    let comps: Vec<Vec<BigRational>> = v.entries().iter().map(|r| poly_coeffs_1d(r)).collect::<Result<_>>()?;
    let n = comps.iter().map(Vec::len).max().unwrap_or(1);
    let coeffs: Vec<Point<BigRational>> = (0..n)
        .map(|k| {
            Point::new(
                comps
                    .iter()
                    .map(|c| c.get(k).cloned().unwrap_or_else(BigRational::zero))
                    .collect(),
            )
        })
        .collect::<Result<_>>()?;
    BezierCurve::from_power_on(
        &coeffs,
        &super::objects::constant(&a.text()?)?,
        &super::objects::constant(&b.text()?)?,
    )
}

fn poly_coeffs_1d(r: &RatFunc) -> Result<Vec<BigRational>> {
    let den = r
        .den
        .as_constant()
        .ok_or_else(|| Error::Domain("the power form must be a polynomial".into()))?;
    let mut out = Vec::new();
    for (e, c) in r.num.terms_in(1) {
        let k = e[0] as usize;
        if out.len() <= k {
            out.resize(k + 1, BigRational::zero());
        }
        out[k] = &c / &den;
    }
    if out.is_empty() {
        out.push(BigRational::zero());
    }
    Ok(out)
}

/// The coefficients `A, …, F` of `lhs − rhs = A x² + B xy + C y² + D x + E y + F`, expanded
/// exactly in x and y; an error unless it is a polynomial of degree ≤ 2.
pub(crate) fn conic_coefficients(l: &Expr, r: &Expr) -> Result<[BigRational; 6]> {
    let names: Rc<[String]> = Rc::from(vec!["x".to_string(), "y".to_string()]);
    let degrees = ["x", "y"]
        .iter()
        .map(|v| (v.to_string(), Value::S(Deg::var(v))))
        .collect();
    super::kernel::eval::check_symbolic_degrees(degrees, &BTreeMap::new(), &[l, r])?;
    let mut vars = BTreeMap::new();
    vars.insert("x".into(), Value::S(RatFunc::poly(Poly::var(&names, 0))));
    vars.insert("y".into(), Value::S(RatFunc::poly(Poly::var(&names, 1))));
    let env = super::kernel::eval::VarEnv(vars);
    let lv = Evaluator::new(&env, BTreeMap::new()).scalar(l)?;
    let rv = Evaluator::new(&env, BTreeMap::new()).scalar(r)?;
    let diff = lv.sub(&rv);
    let den = diff
        .den
        .as_constant()
        .ok_or_else(|| Error::Domain("the conic's equation must be a polynomial in x, y".into()))?;
    let mut coef: [BigRational; 6] = Default::default();
    for (e, k) in diff.num.terms_in(2) {
        let slot = match (e[0], e[1]) {
            (2, 0) => 0,
            (1, 1) => 1,
            (0, 2) => 2,
            (1, 0) => 3,
            (0, 1) => 4,
            (0, 0) => 5,
            _ => return Err(Error::Domain(format!("'{}' has degree above 2: not a conic", diff))),
        };
        coef[slot] = &k / &den;
    }
    Ok(coef)
}

fn check_conic_type(ctx: &Ctx<'_>, claim: &ConicType) -> Result<Checked> {
    let (l, r) = ctx.equation(&claim.equation)?;
    let printed = claim.conic.as_str();
    let coef = conic_coefficients(&l, &r)?;
    let kind = ImplicitConic::from_coefficients(coef.clone()).kind();
    let [a, b, cc, d, e, f] = &coef;
    let disc = b * b - BigRational::from_integer(4.into()) * a * cc;
    let cert = format!(
        "A x² + B xy + C y² + D x + E y + F with (A, B, C, D, E, F) = ({a}, {b}, {cc}, {d}, {e}, {f}): \
         B² − 4AC = {disc}, the 3×3 matrix of the conic is {}singular ⇒ {}",
        if kind == ConicKind::DegenerateSingular {
            ""
        } else {
            "non-"
        },
        kind.family()
    );
    match check_computed(&[kind.family() == printed], &[Trusted::ConicKind]) {
        Some(proof) => {
            let mut c = Checked::proved(proof, format!("{cert}: proof"));
            let (lhs, rhs, coefficients, kind) = (l, r, coef.to_vec(), kind.family());
            c.computed = vec![Computed::ConicKind {
                lhs,
                rhs,
                coefficients,
                kind,
            }];
            Ok(c)
        }
        None => Ok(Checked::fails(format!("{cert}, not {printed}"))),
    }
}

/// `weight_type`: the type of the conic of a quadratic rational curve (`curves`, one curve
/// with weights), by the library's [`classify_conic`] (`w1² / (w0 w2)` against 1), compared
/// with the printed `conic`.
/// Text 004's method on one concrete curve, decided exactly: the library solves the normal
/// equations (11); the closed form (13) must give the same `(k, l)`; the gradient of `δ²` must
/// vanish there (δ² is a convex quadratic in `k, l` with the Gram matrix as Hessian, so a zero
/// gradient is the global minimum when the tangents are independent); the printed `k`, `l`,
/// `δ²` (when given) must be equal to the computed ones. A plane curve must give `δ² = 0`.
fn check_fit(ctx: &Ctx<'_>, c: &Fit) -> Result<Checked> {
    use crate::fit::{delta_squared, delta_squared_gradient, fit_cubic, fit_cubic_closed_form, CubicFitSource};
    let (name, spec) = ctx
        .decls
        .curves
        .as_ref()
        .filter(|m| m.len() == 1)
        .and_then(|m| m.iter().next())
        .ok_or_else(|| Error::Parse(format!("claim {}: fit needs exactly one curve", ctx.id)))?;
    let coords = |ps: &[Point<BigRational>]| ps.iter().map(|p| p.coords().to_vec()).collect::<Vec<_>>();
    let (data, points, weights) = match curve_from_spec::<BigRational>(spec)? {
        crate::AnyCurve::Polynomial(curve) => (curve.cubic_fit_data()?, coords(curve.points()), None),
        crate::AnyCurve::Rational(curve) => (
            curve.cubic_fit_data()?,
            coords(curve.points()),
            Some(curve.weights().to_vec()),
        ),
    };
    let fit = fit_cubic(&data)?;
    let (k13, l13) = fit_cubic_closed_form(&data)?;
    let (gk, gl) = delta_squared_gradient(&data, &fit.k, &fit.l)?;
    let d2 = delta_squared(&data, &fit.k, &fit.l)?;
    let computed = format!("{name}: k = {}, l = {}, δ² = {}", fit.k, fit.l, fit.delta2);
    let mut wrong: Vec<String> = Vec::new();
    if (&k13, &l13) != (&fit.k, &fit.l) {
        wrong.push(format!(
            "(13) gives k = {k13}, l = {l13} but (11) gives k = {}, l = {}",
            fit.k, fit.l
        ));
    }
    if !gk.is_zero() || !gl.is_zero() {
        wrong.push(format!("∇δ² = ({gk}, {gl}) ≠ 0 at the solution"));
    }
    if d2 != fit.delta2 {
        wrong.push(format!("δ² by its definition is {d2}, not {}", fit.delta2));
    }
    if data.x0.dim() == 2 && !fit.delta2.is_zero() {
        wrong.push(format!("a plane curve, yet δ² = {} ≠ 0", fit.delta2));
    }
    for (label, printed, value) in [("k", &c.k, &fit.k), ("l", &c.l, &fit.l), ("δ²", &c.delta2, &fit.delta2)] {
        if let Some(p) = printed {
            let p: BigRational = super::objects::constant(&p.text()?)?;
            if &p != value {
                wrong.push(format!("printed {label} = {p}, computed {label} = {value}"));
            }
        }
    }
    for w in &fit.warnings {
        wrong.push(format!("warning: {w}"));
    }
    let failures = wrong.iter().filter(|w| !w.starts_with("warning")).count();
    let Some(proof) = check_computed(&[failures == 0], &[Trusted::CubicFit]) else {
        return Ok(Checked::fails(format!("{computed}; {}", wrong.join("; "))));
    };
    let notes = if wrong.is_empty() {
        String::new()
    } else {
        format!(" ({})", wrong.join("; "))
    };
    let mut out = Checked::proved(
        proof,
        format!(
            "{computed}, exactly: the normal equations (11) solved by exact elimination agree with the closed form (13), \
             ∇δ² = (0, 0) there and the Gram matrix is non-singular (det {}), so this is the unique minimum{notes}: proof",
            fit.gram_determinant
        ),
    );
    out.computed = vec![Computed::CubicFit {
        points,
        weights,
        data: Box::new(data),
        k: fit.k,
        l: fit.l,
        delta2: fit.delta2,
    }];
    Ok(out)
}

fn check_weight_type(ctx: &Ctx<'_>, claim: &WeightType) -> Result<Checked> {
    let printed = claim.conic.as_str();
    let (name, spec) = ctx
        .decls
        .curves
        .as_ref()
        .and_then(|m| m.iter().next())
        .ok_or_else(|| Error::Parse(format!("claim {}: weight_type needs one curve with weights", ctx.id)))?;
    let w = spec
        .weights
        .as_ref()
        .ok_or_else(|| Error::Parse(format!("claim {}: the curve {name} needs weights", ctx.id)))?;
    let verdict = |kind: &str, detail: String| match check_computed(&[kind == printed], &[Trusted::ClassifyConic]) {
        Some(proof) => Checked::proved(proof, format!("{detail} ⇒ {kind}: proof")),
        None => Checked::fails(format!("{detail} ⇒ {kind}, not {printed}")),
    };
    if uses_sqrt(&ctx.decls, &[]) {
        let pts = points::<QuadraticIrrational>(&spec.points)?;
        let ws = w
            .iter()
            .map(|x| super::objects::constant(&x.text()?))
            .collect::<Result<Vec<QuadraticIrrational>>>()?;
        let curve = RationalBezierCurve::new(pts.clone(), ws.clone())?;
        let kind = classify_conic(&curve)?;
        let mut c = verdict(kind.as_str(), format!("weights {}, {}, {}", ws[0], ws[1], ws[2]));
        if c.proof().is_some() {
            c.computed = vec![Computed::WeightType {
                points: pts.iter().map(|p| p.coords().to_vec()).collect(),
                weights: ws,
                kind: kind.as_str(),
            }];
        }
        return Ok(c);
    }
    let pts = points::<BigRational>(&spec.points)?;
    let ws = w
        .iter()
        .map(|x| super::objects::constant(&x.text()?))
        .collect::<Result<Vec<BigRational>>>()?;
    let curve = RationalBezierCurve::new(pts.clone(), ws.clone())?;
    let kind = classify_conic(&curve)?;
    let computed = Computed::WeightType {
        points: pts
            .iter()
            .map(|p| p.coords().iter().cloned().map(QuadraticIrrational::rational).collect())
            .collect(),
        weights: ws.iter().cloned().map(QuadraticIrrational::rational).collect(),
        kind: kind.as_str(),
    };
    let ratio = if ws.len() == 3 && !ws[0].is_zero() && !ws[2].is_zero() {
        format!(", w1²/(w0 w2) = {}", &ws[1] * &ws[1] / (&ws[0] * &ws[2]))
    } else {
        String::new()
    };
    let mut c = verdict(
        kind.as_str(),
        format!(
            "classify_conic: weights ({}){ratio}",
            ws.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", ")
        ),
    );
    if c.proof().is_some() {
        c.computed = vec![computed];
    }
    Ok(c)
}

/// `enneper`: the surface (`surfaces`, one) is Enneper's surface
/// `E(u, v) = (u − u³/3 + uv², v − v³/3 + vu², u² − v²)` up to an affine change of parameters
/// and a scale. The library's power-form match ([`BezierSurface::enneper_matches`]) finds the
/// parameters; the identity `x(s, t) = λ E(αs + β, γt + δ)` is then proved independently on a
/// 4×4 grid (bicubic: degree ≤ 3 in each parameter).
fn check_enneper(ctx: &Ctx<'_>, detail: bool) -> Result<Checked> {
    let (name, spec) = ctx
        .decls
        .surfaces
        .as_ref()
        .and_then(|m| m.iter().next())
        .ok_or_else(|| Error::Parse(format!("claim {}: enneper needs one surface", ctx.id)))?;
    let net = super::objects::net_from_spec::<BigRational>(spec)?;
    let surface = BezierSurface::new(net)?;
    let found = surface.enneper_matches()?;
    let Some(m) = found.first() else {
        let power = surface.to_power()?;
        return Ok(Checked::fails(
            format!(
                "the power form of {name} (coefficients of s^k t^l, e.g. s³: {}, t³: {}) is not λ E(αs+β, γt+δ) for any α, β, γ, δ, λ, nor with s and t exchanged (the parameters are forced by a few coefficients, then every coefficient is compared exactly)",
                power.get(3).and_then(|r| r.first()).map(|p| p.to_string()).unwrap_or_default(),
                power.first().and_then(|r| r.get(3)).map(|p| p.to_string()).unwrap_or_default()
            ),
        ));
    };
    let (u, v) = if m.swapped {
        (
            format!("({})*t + ({})", m.gamma, m.delta),
            format!("({})*s + ({})", m.alpha, m.beta),
        )
    } else {
        (
            format!("({})*s + ({})", m.alpha, m.beta),
            format!("({})*t + ({})", m.gamma, m.delta),
        )
    };
    // The claim is elaborated with Enneper's surface as the definition `E` (see `elaborate`).
    let lhs = ctx.expr(&format!("{name}(s, t)"))?;
    let rhs = ctx.expr(&format!("({})*E({u}, {v})", m.lambda))?;
    let out = check_chain::<BigRational>(ctx, &[lhs, rhs], detail)?;
    // The library's match only proposes the parameters; the proof is the identity's.
    let Some(proof) = out.proof().cloned() else {
        return Ok(Checked::fails(format!(
            "the library's match does not hold: {}",
            out.certificate
        )));
    };
    let mut res = Checked::proved(
        proof,
        format!(
            "power-form match: {name}(s, t) = {} · E({u}, {v}){}; verified independently: {}",
            m.lambda,
            if m.swapped { " (parameters exchanged)" } else { "" },
            out.certificate
        ),
    );
    res.steps = out.steps;
    Ok(res)
}
