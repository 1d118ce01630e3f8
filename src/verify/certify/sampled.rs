//! The re-check of a sampled certificate (`sampling`, `evaluation`) and of a counterexample
//! (`fails`): the goal's equalities read back, each value in the goal's field, and the kernel's
//! `recheck_sampled` / `recheck_refutation` on them.

use super::kernel;
use super::kernel::alg::Alg;
use super::kernel::certificate::{self, Claimed, Param};
use super::kernel::expr::Expr;
use super::{array, field, method_name, polygon, rational, rationals, sqrt, string, Res};
use crate::exact::SmallRational;
use crate::quadratic::QuadraticIrrational;
use crate::verify::parse::parse;
use serde_json::Value as Json;
use std::collections::BTreeMap;

/// One goal equality: the integer values, both sides, the symbolic control points.
pub(super) type GoalEq = (BTreeMap<String, i64>, Expr, Expr, Vec<(String, Vec<i64>)>);

/// The goal: its real symbols and equalities, and each equality's premise (the equality is
/// claimed where the premise is zero; only a counterexample reads one in this version).
pub(super) struct Goal {
    pub(super) reals: Vec<String>,
    pub(super) equalities: Vec<GoalEq>,
    pub(super) premises: Vec<Option<Expr>>,
    /// The `d` of the goal's `sqrt(d)`: its values are in `Q(√d)` (`None`: rational).
    radicand: Option<i64>,
}

pub(super) fn read_goal(cert: &Json) -> Res<Goal> {
    let g = field(cert, "goal", "certificate")?;
    if string(g, "relation", "goal")? != "=" {
        return Err("goal.relation: only '=' is defined".into());
    }
    let (mut reals, mut integers, mut polygons) = (Vec::new(), Vec::new(), Vec::new());
    for (i, s) in array(g, "symbols", "goal")?.iter().enumerate() {
        let at = format!("goal.symbols[{i}]");
        let name = string(s, "name", &at)?.to_string();
        if reals.contains(&name) || integers.contains(&name) || polygons.contains(&name) {
            return Err(format!("{at}: '{name}' is declared twice"));
        }
        match string(s, "sort", &at)? {
            "real" => reals.push(name),
            "integer" => integers.push(name),
            polygon::SORT => polygons.push(name),
            other => {
                return Err(format!(
                    "{at}.sort: '{other}' is not real, integer or {}",
                    polygon::SORT
                ))
            }
        }
    }
    let known: Vec<String> = reals.iter().chain(&integers).chain(&polygons).cloned().collect();
    let (mut equalities, mut premises) = (Vec::new(), Vec::new());
    for (i, eq) in array(g, "equalities", "goal")?.iter().enumerate() {
        let at = format!("goal.equalities[{i}]");
        let obj = field(eq, "ints", &at)?
            .as_object()
            .ok_or_else(|| format!("{at}.ints: not an object"))?;
        let mut ints = BTreeMap::new();
        for (k, v) in obj {
            if !integers.contains(k) {
                return Err(format!("{at}.ints: '{k}' is not an integer symbol"));
            }
            let v = v
                .as_str()
                .and_then(|s| s.parse::<i64>().ok())
                .ok_or_else(|| format!("{at}.ints.{k}: not an integer"))?;
            ints.insert(k.clone(), v);
        }
        let side =
            |key: &str| -> Res<Expr> { parse(string(eq, key, &at)?, &known).map_err(|e| format!("{at}.{key}: {e}")) };
        let points = polygon::read_points(eq, &at, &polygons)?;
        premises.push(match eq.get("premise") {
            None => None,
            Some(_) => Some(side("premise")?),
        });
        equalities.push((ints, side("lhs")?, side("rhs")?, points));
    }
    if equalities.is_empty() {
        return Err("goal.equalities: none".into());
    }
    let exprs = equalities.iter().flat_map(|(_, l, r, _)| [l, r]);
    let radicand = sqrt::radicand(exprs.chain(premises.iter().flatten())).map_err(|e| format!("goal: {e}"))?;
    Ok(Goal {
        reals,
        equalities,
        premises,
        radicand,
    })
}

fn read_params(eq: &Json, at: &str, reals: &[String]) -> Res<Vec<Param>> {
    let mut params = Vec::new();
    for (j, p) in array(eq, "params", at)?.iter().enumerate() {
        let at = format!("{at}.params[{j}]");
        let name = string(p, "name", &at)?.to_string();
        if !reals.contains(&name) {
            return Err(format!("{at}: '{name}' is not a real symbol of the goal"));
        }
        let degree = field(p, "degree", &at)?
            .as_u64()
            .ok_or_else(|| format!("{at}.degree: not a non-negative integer"))?;
        params.push(Param {
            name,
            degree,
            lhs_degree: string(p, "lhs_degree", &at)?.to_string(),
            rhs_degree: string(p, "rhs_degree", &at)?.to_string(),
            points: rationals(field(p, "points", &at)?, &format!("{at}.points"))?,
        });
    }
    Ok(params)
}

type Rows = Vec<certificate::RowValues<QuadraticIrrational>>;

/// The value rows; each value a number of the goal's field `Q(√radicand)` (or rational).
fn read_rows(eq: &Json, at: &str, points: usize, radicand: Option<i64>) -> Res<Rows> {
    let values = array(eq, "values", at)?;
    if values.len() > certificate::MAX_RECHECK_POINTS {
        return Err(format!(
            "{at}.values: {} rows, more than the limit of {}",
            values.len(),
            certificate::MAX_RECHECK_POINTS
        ));
    }
    values
        .iter()
        .enumerate()
        .map(|(k, row)| {
            let at = format!("{at}.values[{k}]");
            let get = |key: &str| -> Res<Vec<QuadraticIrrational>> {
                let list = array(row, key, &at)?;
                let at = format!("{at}.{key}");
                list.iter()
                    .enumerate()
                    .map(|(i, x)| sqrt::value(x, &format!("{at}[{i}]"), radicand))
                    .collect()
            };
            Ok((
                rationals(field(row, "at", &at)?, &format!("{at}.at"))?,
                polygon::read_basis(row, &at, points)?,
                get("lhs")?,
                get("rhs")?,
            ))
        })
        .collect()
}

pub(super) fn recheck_proof(cert: &Json, goal: &Goal, method: &str) -> Res<String> {
    let s = field(cert, "sampling", "certificate")?;
    let eqs = array(s, "equalities", "sampling")?;
    if eqs.len() != goal.equalities.len() {
        return Err(format!(
            "sampling.equalities: {} entries for {} goal equalities",
            eqs.len(),
            goal.equalities.len()
        ));
    }
    let mut read = Vec::with_capacity(eqs.len());
    for (i, (eq, (_, _, _, points))) in eqs.iter().zip(&goal.equalities).enumerate() {
        let at = format!("sampling.equalities[{i}]");
        let rows = read_rows(eq, &at, points.len(), goal.radicand)?;
        read.push((read_params(eq, &at, &goal.reals)?, rows));
    }
    // A goal without sqrt is evaluated in the rationals (its values were read as rationals),
    // as `SmallRational`s: the same exact values on machine words while they fit, so the
    // re-check does not pay a big gcd per operation.
    let (proof, points) = match goal.radicand {
        Some(_) => recheck_in(goal, read, Some)?,
        None => recheck_in(goal, read, |q: QuadraticIrrational| {
            q.to_rational().map(SmallRational::from)
        })?,
    };
    let derived = method_name(proof.method());
    if derived != method {
        return Err(format!("method: the file says {method}, the data is {derived}"));
    }
    let field = goal.radicand.map_or(String::new(), |d| format!(" in Q(√{d})"));
    Ok(format!(
        "{} equalities, {}, {points} grid points re-evaluated{field}",
        goal.equalities.len(),
        proof.method().text()
    ))
}

/// The kernel's re-check of the read equalities, evaluated in `A` (each value converted by
/// `into`, which cannot fail for a value of the goal's field): the proof and the grid points.
fn recheck_in<A: Alg + PartialEq>(
    goal: &Goal,
    read: Vec<(Vec<Param>, Rows)>,
    into: impl Fn(QuadraticIrrational) -> Option<A>,
) -> Res<(kernel::Proof, usize)> {
    let conv = |v: Vec<QuadraticIrrational>| -> Res<Vec<A>> {
        v.into_iter()
            .map(|q| into(q).ok_or_else(|| "a value outside the goal's field".to_string()))
            .collect()
    };
    let mut claimed = Vec::with_capacity(read.len());
    for ((params, rows), (ints, lhs, rhs, points)) in read.into_iter().zip(&goal.equalities) {
        let rows = rows
            .into_iter()
            .map(|(at, b, l, r)| Ok((at, b, conv(l)?, conv(r)?)))
            .collect::<Res<Vec<_>>>()?;
        claimed.push(Claimed {
            lhs,
            rhs,
            ints: ints.clone(),
            params,
            rows,
            env: Box::new(polygon::FileEnv::<A>::new(points.clone())),
        });
    }
    let proof = certificate::recheck_sampled(&mut claimed)?;
    Ok((proof, claimed.iter().map(|c| c.rows.len()).sum()))
}

pub(super) fn recheck_fails(cert: &Json, goal: &Goal) -> Res<String> {
    let f = field(cert, "fails", "certificate")?;
    let k = field(f, "equality", "fails")?
        .as_u64()
        .ok_or_else(|| "fails.equality: not an index".to_string())?;
    let k = usize::try_from(k)
        .ok()
        .filter(|&k| k < goal.equalities.len())
        .ok_or_else(|| format!("fails.equality: no equality {k} in the goal"))?;
    let (ints, lhs, rhs, points) = &goal.equalities[k];
    let basis = polygon::read_basis(f, "fails", points.len())?;
    let obj = field(f, "at", "fails")?
        .as_object()
        .ok_or_else(|| "fails.at: not an object".to_string())?;
    let mut at = Vec::new();
    for (name, v) in obj {
        if !goal.reals.contains(name) {
            return Err(format!("fails.at: '{name}' is not a real symbol of the goal"));
        }
        let v = v.as_str().ok_or_else(|| format!("fails.at.{name}: not a string"))?;
        at.push((name.clone(), rational(v).map_err(|e| format!("fails.at.{name}: {e}"))?));
    }
    let l = rationals(field(f, "lhs", "fails")?, "fails.lhs")?;
    let r = rationals(field(f, "rhs", "fails")?, "fails.rhs")?;
    let premise = match (&goal.premises[k], f.get("premise")) {
        (None, None) => None,
        (Some(p), Some(v)) => Some((p, rationals(v, "fails.premise")?)),
        (Some(_), None) => return Err("fails: the goal has a premise, the counterexample no value of it".into()),
        (None, Some(_)) => return Err("fails.premise: the goal's equality has no premise".into()),
    };
    let mut c = certificate::Counterexample {
        lhs,
        rhs,
        premise,
        ints: ints.clone(),
        at,
        basis,
        env: Box::new(polygon::FileEnv::new(points.clone())),
    };
    certificate::recheck_refutation(&mut c, (&l, &r)).map_err(|e| format!("the counterexample: {e}"))?;
    Ok(match (basis, &goal.premises[k]) {
        (0, None) => "the counterexample re-evaluated: the sides differ".into(),
        (_, None) => format!("the counterexample re-evaluated on basis polygon {basis}: the sides differ"),
        (_, Some(_)) => "the counterexample re-evaluated: the premise is zero, the sides differ".into(),
    })
}
