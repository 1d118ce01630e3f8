//! `eval` judged for the caller's own algorithm (`"method"`), float answers that overflowed
//! (`"inf"`, `"-inf"`, `"nan"` in `approx`), and batches: one curve at many parameters
//! (`"t": [..]`) for `eval` and `float_eval`, the work limit counting the whole batch.
//!
//! The general path reads everything else; this one reads its requests through it too (the
//! curve, its limits and its errors are the general path's), then adds what it knows.

use super::judge::{
    float_coords, float_eval, float_json, floats_from_json, judge_float, no_nan, not_a_float, rounded_inputs,
    BoundCheck, FloatMethod,
};
use super::protocol::{insert_bound, insert_errors, insert_verdicts};
use super::values::too_large;
use super::values::{describe, number_from_json, point_to_json};
use super::{Answer, Op, MAX_REQUEST_WORK};
use crate::curve::BezierCurve;
use crate::error::{Error, Result};
use crate::float::{condition_number, eval_dyadic, exact_f64, nearest_f64, scale_pow2_up, ulp_exponent};
use crate::input::in_context;
use crate::point::Point;
use num_rational::BigRational;
use serde_json::{json, Map, Value};

/// Most parameters in one batch.
pub const MAX_BATCH: usize = 4096;

/// The answer's fields when the request is one for this module, `None` otherwise.
pub(super) fn respond(request: &Value) -> Option<Result<Map<String, Value>>> {
    let obj = request.as_object()?;
    let op = obj.get("op")?.as_str()?;
    let batch = obj.get("t").is_some_and(Value::is_array);
    match op {
        "eval" if batch || obj.contains_key("method") || has_string(obj.get("approx")) => Some(judged_eval(obj, batch)),
        "float_eval" if batch => Some(float_eval_batch(obj)),
        _ => None,
    }
}

fn has_string(v: Option<&Value>) -> bool {
    match v {
        Some(Value::String(_)) => true,
        Some(Value::Array(items)) => items.iter().any(|x| has_string(Some(x))),
        _ => false,
    }
}

/// The request without `drop`'s fields and with its first parameter as `t`: what the general
/// path reads (curve, limits, errors).
fn base_request(obj: &Map<String, Value>, drop: &[&str], t: &Value) -> Value {
    let mut base: Map<String, Value> = obj
        .iter()
        .filter(|(k, _)| !drop.contains(&k.as_str()))
        .map(|(k, v)| (k.clone(), v.clone()))
        .collect();
    base.insert("t".into(), t.clone());
    Value::Object(base)
}

/// The parameters: one, or a list of at most [`MAX_BATCH`].
fn parameters(obj: &Map<String, Value>) -> Result<Vec<BigRational>> {
    let t = obj
        .get("t")
        .ok_or_else(|| Error::Parse("this op needs the field 't'".into()))?;
    let Value::Array(items) = t else {
        return Ok(vec![number_from_json(t).map_err(|e| in_context("field 't'", e))?]);
    };
    if items.is_empty() {
        return Err(Error::Parse(
            "field 't': an empty list (a batch needs at least one parameter)".into(),
        ));
    }
    if items.len() > MAX_BATCH {
        return Err(too_large("number of parameters in a batch", items.len(), MAX_BATCH));
    }
    items
        .iter()
        .enumerate()
        .map(|(k, x)| number_from_json(x).map_err(|e| in_context(&format!("field 't': parameter {k}"), e)))
        .collect()
}

/// How much more a batch's further parameter costs than its work estimate says: the
/// estimates are calibrated at the largest single requests, where the kernel's work
/// dominates, and a batch is many small ones, each judged and written as its own object
/// (301 planar points at 4096 parameters `1/3`, 37% of the limit at weight 4, took 0.5–1.1 s
/// of CPU). The first parameter counts once: a batch of one is the request alone.
const BATCH_WEIGHT: f64 = 16.0;

/// Refuses a batch whose summed work estimate is beyond [`MAX_REQUEST_WORK`]; `op` is any one of its
/// requests, its parameter replaced in turn. The sum is compared with the limit as it grows,
/// and a parameter met before is not estimated again, so that a batch beyond the limit is
/// refused after a few estimates.
fn check_batch_work(op: &mut Op, ts: &[BigRational]) -> Result<()> {
    let mut work = 0.0;
    let mut seen: std::collections::HashMap<&BigRational, f64> = std::collections::HashMap::new();
    for (k, t) in ts.iter().enumerate() {
        let one = match seen.get(t) {
            Some(w) => *w,
            None => {
                match op {
                    Op::Eval { t: slot, .. } | Op::FloatEval { t: slot, .. } => *slot = t.clone(),
                    _ => unreachable!("batches are of eval and float_eval"),
                }
                let w = op.work();
                seen.insert(t, w);
                w
            }
        };
        work += if k == 0 { one } else { one * BATCH_WEIGHT };
        if work.is_nan() || work > MAX_REQUEST_WORK {
            return Err(Error::TooLarge {
                what: "batch (estimated exact work of all its parameters)",
                value: format!("{work:.2e} after {} of its {} parameters", k + 1, ts.len()),
                limit: format!("{MAX_REQUEST_WORK:.0e}; use fewer parameters, fewer points or a lower degree"),
            });
        }
    }
    Ok(())
}

/// One approximation: a list of floats (JSON numbers, or `"inf"`, `"-inf"`, `"nan"`), read
/// as the general path reads it.
fn approx_point(v: &Value, what: &str) -> Result<Vec<f64>> {
    floats_from_json(v, true).map_err(|e| in_context(what, e))
}

fn judged_eval(obj: &Map<String, Value>, batch: bool) -> Result<Map<String, Value>> {
    let method = match obj.get("method") {
        None => None,
        Some(Value::String(s)) => Some(FloatMethod::parse(s).map_err(|e| in_context("field 'method'", e))?),
        Some(other) => {
            return Err(Error::Parse(format!(
                "field 'method' must be a string naming the caller's algorithm, got {}",
                describe(other)
            )))
        }
    };
    if method == Some(FloatMethod::Interval) {
        return Err(Error::Parse(
            "field 'method': eval's method is the caller's float algorithm (de_casteljau, lerp, horner, bernstein, compensated); casteljau's own interval enclosure is float_eval's".into(),
        ));
    }
    let ts = parameters(obj)?;
    let first = obj.get("t").map(|t| if batch { t[0].clone() } else { t.clone() });
    let mut op = Op::from_json(&base_request(obj, &["method", "approx"], &first.unwrap_or(Value::Null)))?;
    check_batch_work(&mut op, &ts)?;
    let Op::Eval { curve, .. } = op else {
        unreachable!("an eval request reads as Op::Eval")
    };
    let approx: Option<Vec<Vec<f64>>> = match obj.get("approx") {
        None => None,
        Some(v) if batch => {
            let items = v.as_array().filter(|a| a.len() == ts.len()).ok_or_else(|| {
                Error::Parse(format!(
                    "field 'approx': a batch needs one approximation per parameter ({}), got {}",
                    ts.len(),
                    describe(v)
                ))
            })?;
            Some(
                items
                    .iter()
                    .enumerate()
                    .map(|(k, a)| approx_point(a, &format!("field 'approx': parameter {k}")))
                    .collect::<Result<_>>()?,
            )
        }
        Some(v) => Some(vec![approx_point(v, "field 'approx'")?]),
    };
    let mut results = Vec::with_capacity(ts.len());
    for (k, t) in ts.iter().enumerate() {
        let a = approx.as_ref().map(|a| a[k].as_slice());
        results.push(judge_point(&curve, t, a, method)?);
    }
    if batch {
        let mut m = Map::new();
        m.insert("results".into(), results.into_iter().map(Value::Object).collect());
        Ok(m)
    } else {
        Ok(results.pop().expect("one parameter"))
    }
}

/// One parameter's fields: the exact point; with `approx` the errors (and verdicts); at a
/// float parameter the bound of `method` (convex de Casteljau by default) and the condition.
fn judge_point(
    curve: &BezierCurve<BigRational>,
    t: &BigRational,
    approx: Option<&[f64]>,
    method: Option<FloatMethod>,
) -> Result<Map<String, Value>> {
    let point = eval_dyadic(curve, t).unwrap_or_else(|| curve.eval_nested(t));
    let mut m = Map::new();
    m.insert("point".into(), point_to_json(&point));
    if let Some(name) = method {
        m.insert("method".into(), json!(name.as_str()));
    }
    if let Some(a) = approx {
        if a.len() != point.dim() {
            return Err(Error::DimensionMismatch {
                expected: point.dim(),
                found: a.len(),
                context: "field 'approx'".into(),
            });
        }
        let (errors, verdicts): (Vec<_>, Vec<_>) = a
            .iter()
            .zip(point.coords())
            .map(|(a, x)| judge_float(*a, x))
            .collect::<Result<Vec<_>>>()?
            .into_iter()
            .unzip();
        insert_errors(&mut m, &errors);
        insert_verdicts(&mut m, &verdicts);
    }
    if let Some(tf) = exact_f64(t) {
        let method_named = method.is_some();
        let method = method.unwrap_or(FloatMethod::DeCasteljau);
        let (coords, exact) = float_coords(curve.points());
        let near: Vec<f64> = point.coords().iter().map(nearest_f64).collect();
        let bounds: Vec<f64> = coords
            .iter()
            .zip(&near)
            .map(|(b, p)| rounded_inputs(method.bound(b, tf, *p), b, tf, exact))
            .collect();
        match approx {
            Some(a) => {
                let checks: Vec<BoundCheck> = a
                    .iter()
                    .zip(point.coords())
                    .zip(&bounds)
                    .map(|((a, x), bound)| BoundCheck::new(*a, x, *bound))
                    .collect();
                insert_bound(&mut m, "bound", "within_bound", &checks);
            }
            None => {
                let ulps = bounds
                    .iter()
                    .zip(point.coords())
                    .map(|(b, x)| float_json(no_nan(scale_pow2_up(no_nan(*b), -ulp_exponent(x)))));
                m.insert("bound".into(), ulps.collect());
            }
        }
        // the condition comes with a method, or with the bound alone: an approximation without
        // a method is answered as the general path answers it, whatever its numbers' encoding
        if method_named || approx.is_none() {
            let condition = coords
                .iter()
                .zip(&near)
                .map(|(b, p)| float_json(condition_number(b, tf, *p)));
            m.insert("condition".into(), condition.collect());
        }
    }
    Ok(m)
}

fn float_eval_batch(obj: &Map<String, Value>) -> Result<Map<String, Value>> {
    let ts = parameters(obj)?;
    let mut op = Op::from_json(&base_request(obj, &[], &obj["t"][0]))?;
    check_batch_work(&mut op, &ts)?;
    let Op::FloatEval { curve, method, .. } = op else {
        unreachable!("a float_eval request reads as Op::FloatEval")
    };
    let mut results = Vec::with_capacity(ts.len());
    for (k, t) in ts.iter().enumerate() {
        if exact_f64(t).is_none() {
            return Err(in_context(&format!("parameter {k}"), not_a_float("t", t)));
        }
        let point: Point<BigRational> = eval_dyadic(&curve, t).unwrap_or_else(|| curve.eval_nested(t));
        let answer = Answer::FloatEval(Box::new(float_eval(&curve, t, method, point)?));
        results.push(Value::Object(answer.to_json()));
    }
    let mut m = Map::new();
    m.insert("results".into(), Value::Array(results));
    Ok(m)
}
