//! Exact symbolic expansion: identities in scalar and vector unknowns, and `implies`.

use super::claims::Implies;
use super::context::Ctx;
use super::kernel::certificate::{Equality, Refutation};
use super::kernel::check_expanded;
use super::kernel::checked::Step;
use super::kernel::eval::{Evaluator, Value, VarEnv};
use super::kernel::expand::{expand, sym_env, Expanded};
use super::kernel::expr::Expr;
use super::kernel::poly::{Poly, RatFunc};
use super::outcome::Checked;
use super::rewrite::substitute;
use super::sampling::{list, PairProof};
use crate::error::{Error, Result};
use crate::scalar::{Ring, Scalar};
use num_rational::BigRational;
use std::collections::BTreeMap;
use std::rc::Rc;

// ---------------------------------------------------------------------------------------
// Symbolic expansion

fn sym_names(ctx: &Ctx<'_>, extra: &[String]) -> (Rc<[String]>, Vec<(String, usize)>) {
    let mut names: Vec<String> = Vec::new();
    let mut layout = Vec::new();
    for s in ctx.decls.symbols.iter().flatten().chain(extra) {
        if !names.contains(s) {
            layout.push((s.clone(), 0));
            names.push(s.clone());
        }
    }
    for (v, &dim) in ctx.decls.vectors.iter().flatten() {
        layout.push((v.clone(), dim));
        for k in 1..=dim {
            names.push(format!("{v}_{k}"));
        }
    }
    (Rc::from(names), layout)
}

/// The variables of a layout in the kernel's order: a scalar its name, a vector `v` its
/// coordinates `v_1, …, v_d`.
pub(crate) fn variables(layout: &[(String, usize)]) -> Vec<String> {
    let mut out = Vec::new();
    for (v, dim) in layout {
        if *dim == 0 {
            out.push(v.clone());
        } else {
            out.extend((1..=*dim).map(|k| format!("{v}_{k}")));
        }
    }
    out
}

/// `e` with every vector of the layout written as the tuple of its coordinates.
pub(crate) fn in_coordinates(e: &Expr, layout: &[(String, usize)]) -> Expr {
    let (names, tuples): (Vec<String>, Vec<Expr>) = layout
        .iter()
        .filter(|(_, dim)| *dim > 0)
        .map(|(v, dim)| {
            let coords = (1..=*dim).map(|k| Expr::Var(format!("{v}_{k}"))).collect();
            (v.clone(), Expr::Tuple(coords))
        })
        .unzip();
    substitute(e, &names, &tuples)
}

/// The counterexample of an implication as data: the equation and the premise written in
/// coordinates (a vector `v` as `(v_1, …, v_d)`), the point, and the values there.
fn implies_refutation(
    layout: &[(String, usize)],
    vars: &BTreeMap<String, Value<BigRational>>,
    (prem, a, b): (&Expr, &Expr, &Expr),
    (pv, av, bv): (&Value<BigRational>, &Value<BigRational>, &Value<BigRational>),
) -> Box<Refutation> {
    let mut at = Vec::new();
    for (v, dim) in layout {
        match vars.get(v) {
            Some(Value::S(x)) if *dim == 0 => at.push((v.clone(), x.clone())),
            Some(Value::V(xs)) => at.extend(
                xs.iter()
                    .enumerate()
                    .map(|(k, x)| (format!("{v}_{}", k + 1), x.clone())),
            ),
            _ => {}
        }
    }
    let written = |e: &Expr| in_coordinates(e, layout).to_string();
    let entries = |v: &Value<BigRational>| v.entries().into_iter().map(ToString::to_string).collect();
    Box::new(Refutation {
        equality: Equality {
            ints: BTreeMap::new(),
            lhs: in_coordinates(a, layout),
            rhs: in_coordinates(b, layout),
            params: Vec::new(),
            rows: Vec::new(),
            polygons: 1,
            control_points: Vec::new(),
        },
        at,
        lhs: entries(av),
        rhs: entries(bv),
        basis: 0,
        premise: Some((written(prem), entries(pv))),
    })
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

/// What the expansion of one equality found.
pub enum PairResult {
    /// Equal as rational functions: the log, and the kernel's expansion.
    Proved(PairProof, Box<Expanded>),
    /// Not equal: a point where the sides differ.
    Fails(String),
}

/// Proves or refutes `lhs = rhs` by exact symbolic expansion in the claim's symbols.
pub fn symbolic_equal(ctx: &Ctx<'_>, lhs: &Expr, rhs: &Expr, ints: &BTreeMap<String, i64>) -> Result<PairResult> {
    let extra = ctx.params(&[lhs, rhs]);
    let extra: Vec<String> = extra.into_iter().filter(|v| !ctx.is_bound(v)).collect();
    let (names, layout) = sym_names(ctx, &extra);
    let expanded = expand(&layout, lhs, rhs, ints)?;
    if let Some(d) = expanded.difference() {
        let point = nonzero_point(d, names.len());
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
    let terms = expanded.terms();
    let mut proof = PairProof::default();
    proof.lines.push(Step::text(format!(
        "expanded exactly in {} variables ({}); both sides agree term by term after clearing denominators ({terms} terms)",
        names.len(),
        names.join(", ")
    )));
    Ok(PairResult::Proved(proof, Box::new(expanded)))
}

/// Checks a chain by symbolic expansion.
pub fn check_chain_symbolic(ctx: &Ctx<'_>, sides: &[Expr], detail: bool) -> Result<Checked> {
    let instances = ctx.instances()?;
    let mut steps = Vec::new();
    let mut expanded = Vec::new();
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
                    let mut c = Checked::fails(format!("{which}{cx}"));
                    c.steps = steps;
                    return Ok(c);
                }
                PairResult::Proved(p, e) => {
                    expanded.push(*e);
                    if detail {
                        steps.push(Step::text(format!("'{}' = '{}':", pair[0], pair[1])));
                        steps.extend(p.lines.iter().cloned().map(|l| l.nested(2)));
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
    // Every pair expanded to a zero difference: a `Fails` returned above otherwise.
    let proof = check_expanded(&expanded).ok_or_else(|| Error::Domain("the kernel refuses the expansion".into()))?;
    let mut c = Checked::proved(
        proof,
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
    let (_, layout) = sym_names(ctx, &extra);
    let (_, env) = sym_env(&layout)?;
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
fn refute_at_poles(ctx: &Ctx<'_>, imp: &Implies, prem: &Expr, (a, b): (&Expr, &Expr)) -> Result<Option<Checked>> {
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
                            return Ok(Some(Checked::fails(
                                format!(
                                    "at {shown}: the premise '{}' holds (the factor has a pole there), but the equation '{}' gives left side = {av}, right side = {bv}",
                                    imp.premise.as_str(),
                                    imp.equation.as_str()
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
pub fn check_implies(ctx: &Ctx<'_>, imp: &Implies, detail: bool) -> Result<Checked> {
    let (a, b) = ctx.equation(&imp.equation)?;
    let (p, q) = ctx.equation(&imp.premise)?;
    let factor = ctx.expr(&imp.factor)?;
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
        PairResult::Proved(pp, expanded) => {
            if let Some(reason) = factor_pole(ctx, &concl, &factor, &prem)? {
                if let Some(found) = refute_at_poles(ctx, imp, &prem, (&a, &b))? {
                    return Ok(found);
                }
                return Err(Error::Domain(format!(
                    "the equation is factor × premise identically, but {reason}: where it vanishes and the premise holds, \
                     nothing follows, so the implication is not proved (refused; no counterexample among the first {POLE_SEARCH} small rational points)"
                )));
            }
            // The difference expanded to zero (`PairResult::Proved`) and the factor has no pole
            // where the premise holds.
            let proof = check_expanded(std::slice::from_ref(&*expanded))
                .ok_or_else(|| Error::Domain("the kernel refuses the expansion".into()))?;
            let mut out = Checked::proved(
                proof,
                format!(
                    "[{}] = ({}) · [{}] identically, as rational functions of the symbols and vector coordinates \
                     (exact symbolic expansion), so '{} = 0' implies the equation: proof",
                    imp.equation.as_str(),
                    imp.factor.as_str(),
                    imp.premise.as_str(),
                    imp.premise.as_str()
                ),
            );
            if detail {
                out.steps = pp.lines;
            }
            Ok(out)
        }
        PairResult::Fails(..) => {
            // A concrete counterexample: data where the premise holds (solved for the first
            // symbol, which it contains linearly) but the equation does not.
            let unknown = ctx
                .decls
                .symbols
                .as_ref()
                .and_then(|s| s.first().cloned())
                .ok_or_else(|| Error::Parse(format!("claim {}: implies needs symbols (the unknowns)", ctx.id)))?;
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
                for s in ctx.decls.symbols.iter().flatten() {
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
                    let refutation = implies_refutation(&layout, &vars, (&prem, &a, &b), (&pv, &av, &bv));
                    return Ok(Checked::fails(format!(
                        "at {}: the premise '{}' = 0 holds, but the equation '{}' gives left side = {av}, right side = {bv}",
                        shown.join(", "),
                        imp.premise.as_str(),
                        imp.equation.as_str()
                    ))
                    .refuted(Some(refutation)));
                }
            }
            Err(Error::Domain(format!(
                "claim {}: the equation is not factor × premise, and no counterexample was found",
                ctx.id
            )))
        }
    }
}
