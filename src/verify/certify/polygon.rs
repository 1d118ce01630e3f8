//! Goals with symbolic control points (`docs/certificates.md`, "Control points"): the
//! equality's control points read from the file, and the environment that sets them to the
//! zero polygon and to each unit polygon at the grid's points (elaboration, like the claim's
//! objects in `prove`; the kernel checks the basis complete and the sides affine in them).

use super::{array, field, Res};
use crate::error::Result;
use crate::verify::kernel::alg::Alg;
use crate::verify::kernel::eval::{Env, Evaluator, Value, VarEnv};
use crate::verify::kernel::expr::Expr;
use crate::verify::kernel::sample::Points;
use num_rational::BigRational;
use serde_json::{json, Value as Json};

/// The sort of a control polygon or net's name in the goal's symbols.
pub(super) const SORT: &str = "control_points";

/// The control points of an equality as JSON, `[{"name": "b", "index": [0]}, …]`.
pub(super) fn points_json(points: &[(String, Vec<i64>)]) -> Json {
    Json::Array(points.iter().map(|(n, idx)| json!({"name": n, "index": idx})).collect())
}

/// An equality's `control_points` (none when the field is absent); each name must be one of
/// `names` (the goal's symbols of sort `control_points`).
pub(super) fn read_points(eq: &Json, at: &str, names: &[String]) -> Res<Vec<(String, Vec<i64>)>> {
    if eq.get("control_points").is_none() {
        return Ok(Vec::new());
    }
    let mut out = Vec::new();
    for (k, p) in array(eq, "control_points", at)?.iter().enumerate() {
        let at = format!("{at}.control_points[{k}]");
        let name = field(p, "name", &at)?
            .as_str()
            .ok_or_else(|| format!("{at}.name: not a string"))?;
        if !names.iter().any(|n| n == name) {
            return Err(format!("{at}: '{name}' is not a symbol of sort {SORT}"));
        }
        let index = array(p, "index", &at)?
            .iter()
            .map(|i| i.as_i64().ok_or_else(|| format!("{at}.index: not a list of integers")))
            .collect::<Res<Vec<i64>>>()?;
        let point = (name.to_string(), index);
        if out.contains(&point) {
            return Err(format!("{at}: listed twice"));
        }
        out.push(point);
    }
    Ok(out)
}

/// The basis polygon of a value row: its `polygon` field, absent (0) without control points.
pub(super) fn read_basis(row: &Json, at: &str, points: usize) -> Res<usize> {
    match row.get("polygon") {
        None if points == 0 => Ok(0),
        None => Err(format!("{at}: no field 'polygon'")),
        Some(p) => p
            .as_u64()
            .and_then(|p| usize::try_from(p).ok())
            .filter(|&p| points > 0 && p <= points)
            .ok_or_else(|| format!("{at}.polygon: not a basis polygon 0..={points}")),
    }
}

/// The goal's real symbols set at a grid point, its control points at one basis polygon:
/// polygon 0 is the zero polygon, polygon `k + 1` sets the `k`-th listed point to 1. A control
/// point not listed is 0 (the claims' convention: `b[-1] = b[n + 1] = 0`). `A`: the exact
/// numbers the sides are evaluated in (machine-word rationals while the values fit, for speed;
/// `Q(√d)` for a goal with `sqrt(d)`).
pub(super) struct FileEnv<A> {
    vars: VarEnv<A>,
    points: Vec<(String, Vec<i64>)>,
    basis: usize,
}

impl<A> FileEnv<A> {
    pub(super) fn new(points: Vec<(String, Vec<i64>)>) -> FileEnv<A> {
        FileEnv {
            vars: VarEnv(Default::default()),
            points,
            basis: 0,
        }
    }
}

impl<A: Alg> Env<A> for FileEnv<A> {
    fn var(&self, name: &str) -> Option<Value<A>> {
        self.vars.var(name)
    }
    fn call(&self, _: &str, _: &[Expr], _: &mut Evaluator<'_, A>) -> Result<Option<Value<A>>> {
        Ok(None)
    }
    fn index(&self, name: &str, idx: &[i64]) -> Result<Option<Value<A>>> {
        if !self.points.iter().any(|(n, _)| n == name) {
            return Ok(None);
        }
        let unit = self.basis.checked_sub(1).and_then(|k| self.points.get(k));
        let one = unit.is_some_and(|(n, i)| n == name && i.as_slice() == idx);
        Ok(Some(Value::S(A::from_int(i64::from(one)))))
    }
}

impl<A: Alg> Points<A> for FileEnv<A> {
    fn polygons(&self) -> usize {
        self.points.len() + 1
    }
    fn at(&mut self, basis: usize, params: &[String], values: &[BigRational]) -> Result<&dyn Env<A>> {
        self.basis = basis;
        for (p, v) in params.iter().zip(values) {
            self.vars.0.insert(p.clone(), Value::S(A::from_rat(v)));
        }
        Ok(self)
    }
    fn control_points(&self) -> Vec<(String, Vec<i64>)> {
        self.points.clone()
    }
}
