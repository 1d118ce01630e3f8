//! `eval` judged for the caller's own algorithm (`"method"`), float answers that overflowed
//! (`"inf"`, `"-inf"`, `"nan"` in `approx`), and batches: one curve at many parameters
//! (`"t": [..]`) for `eval` and `float_eval`, the work limit counting the whole batch.
//!
//! Each is read into typed ops ([`Op::EvalJudged`], [`Op::Batch`]) answered as single
//! requests are ([`Op::run`]); the curve, its limits and its errors are read by the general
//! path ([`Op::from_json`]), which calls this module for these requests.

use super::judge::{floats_from_json, FloatMethod};
use super::values::too_large;
use super::values::{describe, number_from_json};
use super::{Op, MAX_REQUEST_WORK};
use crate::error::{Error, Result};
use crate::input::in_context;
use num_rational::BigRational;
use serde_json::{Map, Value};

/// Most parameters in one batch.
pub const MAX_BATCH: usize = 4096;

/// Whether `approx` holds a string (`"inf"`, `"-inf"`, `"nan"`): only [`Op::EvalJudged`] reads them.
pub(super) fn has_string(v: Option<&Value>) -> bool {
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
pub(super) const BATCH_WEIGHT: f64 = 16.0;

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
                    Op::Eval { t: slot, .. } | Op::FloatEval { t: slot, .. } | Op::Split { t: slot, .. } => {
                        *slot = t.clone()
                    }
                    Op::Judged { op, .. } => match op.as_mut() {
                        Op::Split { t: slot, .. } => *slot = t.clone(),
                        _ => unreachable!("batches of judged ops are splits"),
                    },
                    _ => unreachable!("batches are of eval, float_eval and split"),
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

/// `eval` with `method`, with a string in `approx`, or at many parameters: one
/// [`Op::EvalJudged`] per parameter (a batch of them for `"t": [..]`), the curve, its limits
/// and its errors read by the general path.
pub(super) fn eval_judged(obj: &Map<String, Value>) -> Result<Op> {
    let batch = obj.get("t").is_some_and(Value::is_array);
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
    let mut approx: Option<Vec<Vec<f64>>> = match obj.get("approx") {
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
    let curve = std::sync::Arc::new(curve);
    let mut ops: Vec<Op> = ts
        .into_iter()
        .enumerate()
        .map(|(k, t)| Op::EvalJudged {
            curve: curve.clone(),
            t,
            approx: approx.as_mut().map(|a| std::mem::take(&mut a[k])),
            method,
        })
        .collect();
    if batch {
        Ok(Op::Batch { ops })
    } else {
        Ok(ops.pop().expect("one parameter"))
    }
}

/// `float_eval` at many parameters: the [`Op::Batch`] of one [`Op::FloatEval`] per
/// parameter. The first is read by the general path; the others are checked to be floats
/// when the batch reaches them ([`Op::run`]), as the general path checks the first.
pub(super) fn float_eval_batch(obj: &Map<String, Value>) -> Result<Op> {
    let ts = parameters(obj)?;
    let mut op = Op::from_json(&base_request(obj, &[], &obj["t"][0]))?;
    check_batch_work(&mut op, &ts)?;
    let Op::FloatEval { curve, method, .. } = op else {
        unreachable!("a float_eval request reads as Op::FloatEval")
    };
    let ops = ts
        .into_iter()
        .map(|t| Op::FloatEval {
            curve: curve.clone(),
            t,
            method,
        })
        .collect();
    Ok(Op::Batch { ops })
}

/// `split` at many parameters (`"t": [..]`, `approx` then one per parameter): the typed
/// [`Op::Batch`] of one split per parameter, read by the general path and its work limit
/// checked before any op is built.
pub(super) fn split_batch(obj: &Map<String, Value>) -> Result<Op> {
    let ts = parameters(obj)?;
    let approx = match obj.get("approx") {
        None => None,
        Some(v) => Some(v.as_array().filter(|a| a.len() == ts.len()).ok_or_else(|| {
            Error::Parse(format!(
                "field 'approx': a batch needs one approximation per parameter ({}), got {}",
                ts.len(),
                describe(v)
            ))
        })?),
    };
    let mut first = base_request(obj, &["approx"], &obj["t"][0]);
    if let Some(a) = approx {
        first["approx"] = a[0].clone();
    }
    let mut op = Op::from_json(&first).map_err(|e| in_context("parameter 0", e))?;
    check_batch_work(&mut op, &ts)?;
    let mut ops = Vec::with_capacity(ts.len());
    for (k, t) in ts.iter().enumerate() {
        let mut one = op.clone();
        match &mut one {
            Op::Split { t: slot, .. } => *slot = t.clone(),
            Op::Judged {
                op: inner,
                approx: slot,
                ..
            } => {
                let Op::Split { curve, t: at } = inner.as_mut() else {
                    unreachable!("a split request reads as a split")
                };
                *at = t.clone();
                if let Some(a) = approx {
                    let read = super::judged::Approx::from_json(&a[k], true, curve.points().len(), curve.dim());
                    *slot = Some(read.map_err(|e| in_context(&format!("parameter {k}"), e))?);
                }
            }
            _ => unreachable!("a split request reads as a split"),
        }
        ops.push(one);
    }
    Ok(Op::Batch { ops })
}
