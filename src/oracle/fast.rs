//! The oracle's most common request, `eval` with every number a JSON number, read straight
//! into its fields instead of through a `serde_json::Value` tree (which costs a small request
//! more than its exact evaluation does).
//!
//! It only ever accepts: any other op, a string number, a missing, unknown, repeated or
//! mistyped field, or an input past a limit returns `None`, and the request goes the general
//! way ([`Op::from_json`]). So every answer and every error is the general path's, and tests
//! compare the two on the same lines.

use super::values::json_number;
use super::{Op, MAX_POINTS, MAX_REQUEST_DIMENSION};
use crate::curve::BezierCurve;
use crate::point::Point;
use serde::{Deserialize, Deserializer};
use serde_json::{Number, Value};

/// A field that may be absent, told apart from one given as `null`: with `#[serde(default)]`
/// an absent field is `None`, while `null` must parse as the field's type (and so fails, as
/// the general path refuses it) instead of reading as absent.
fn present<'de, D: Deserializer<'de>, T: Deserialize<'de>>(d: D) -> Result<Option<T>, D::Error> {
    T::deserialize(d).map(Some)
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct EvalRequest<'a> {
    #[serde(borrow)]
    op: &'a str,
    points: Vec<Vec<Number>>,
    t: Number,
    #[serde(default, deserialize_with = "present")]
    approx: Option<Vec<f64>>,
    #[serde(default, deserialize_with = "present")]
    id: Option<Value>,
}

/// The request on `line` and its `id` when it is a well-formed `eval` with JSON numbers
/// only and within every limit; `None` otherwise (the general path then answers it).
pub fn eval_request(line: &str) -> Option<(Op, Option<Value>)> {
    let request: EvalRequest = serde_json::from_str(line).ok()?;
    if request.op != "eval" || request.points.is_empty() || request.points.len() > MAX_POINTS {
        return None;
    }
    let dim = request.points[0].len();
    if dim > MAX_REQUEST_DIMENSION || request.points.iter().any(|p| p.len() != dim) {
        return None;
    }
    let points = request
        .points
        .iter()
        .map(|p| Point::new(p.iter().map(json_number).collect::<crate::Result<_>>()?))
        .collect::<crate::Result<Vec<_>>>()
        .ok()?;
    let approx = request.approx;
    if approx.as_ref().is_some_and(|a| a.len() > MAX_REQUEST_DIMENSION) {
        return None;
    }
    let op = Op::Eval {
        curve: BezierCurve::new(points).ok()?,
        t: json_number(&request.t).ok()?,
        approx,
    };
    op.check_limits().ok()?;
    Some((op, request.id))
}
