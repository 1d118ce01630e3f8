//! The JSON-lines oracle: exact answers for other programs (`casteljau oracle`).
//!
//! A program that computes Bézier geometry in floating point writes one JSON request per
//! line and reads back one JSON response per line with the exact answer, so it can measure
//! its own error. The loop ([`serve`]) never stops on a bad request: every line gets exactly
//! one response line, in order, flushed before the loop waits for more input; only end of
//! input ends it.
//!
//! ```
//! use casteljau::oracle::handle_line;
//! let out = handle_line(r#"{"id": 7, "op": "eval", "points": [[0, 0], [1, 2], [2, 0]], "t": "1/3"}"#);
//! assert_eq!(out, r#"{"id":7,"ok":true,"point":["2/3","8/9"]}"#);
//! let bad = handle_line(r#"{"op": "eval", "points": [], "t": 0}"#);
//! assert!(bad.starts_with(r#"{"error":"#) && bad.contains(r#""ok":false"#));
//! ```
//!
//! # Protocol
//!
//! Requests are JSON objects with an `"op"` and the op's fields; an `"id"` (any JSON value)
//! is echoed in the response. Numbers follow [`number_from_json`]: strings (`"1/3"`, `"0.25"`,
//! `"1e-3"`) are exact, JSON numbers are exactly the `f64` they parse to. Exact results are
//! strings in lowest terms. Every response has `"ok"`; failures carry `"error"`. Unknown
//! fields are errors (a misspelt optional field would otherwise be silently ignored), and so
//! is a field given twice (JSON leaves open which copy counts).
//!
//! | op           | fields                                   | answer                     |
//! |--------------|------------------------------------------|----------------------------|
//! | `eval`       | `points`, `t`, optional `approx`, `method` | `point` (+ `ulps`, `error_ulps`, `nearest`, `bound`, `within_bound`; with `method` also `condition`) |
//! | `elevate`    | `points`, `by`, optional `approx`, `method` | `points` (+ judged fields per point) |
//! | `split`      | `points`, `t`, optional `approx`, `method` | `left`, `right` (+ judged fields per half and point) |
//! | `derivative` | `points`, `order`, optional `t`; without `t` optional `approx`, `method` | `points`, or `vector` with `t` |
//! | `to_bezier`  | `power` (one array per coordinate, `t^0..t^n`), optional `approx`, `method` | `points` |
//! | `rational_eval` | `points`, `weights`, `t`, optional `approx` | `point` (+ ulps)      |
//! | `conic`      | `points` (three 2D points), `weights` (three) | `type`, `implicit`    |
//! | `surface_eval` | `net` (rows `i = 0..m` of points `j = 0..n`), `u`, `v`, optional `approx` | `point` (+ ulps) |
//! | `fit_cubic`  | `x0`, `x1`, `xh` = x(1/2), `d0` = ẋ(0), `d1` = ẋ(1) | `k`, `l`, `points`, `delta2`, `warnings` |
//! | `float_eval` | `points`, `t` (floats), optional `method` (`de_casteljau`, `lerp`, `horner`, `bernstein`, `compensated`, `interval`) | `value`, `point`, ulps, `bound`, `within_bound`, `condition` (+ `running_bound`, or `interval`, `encloses`) |
//!
//! `eval`'s `method` names the caller's float algorithm, whose own a priori bound judges
//! `approx` (see [`crate::float`] and `docs/float-bounds.md`); a float answer that overflowed
//! is sent as `"inf"`, `"-inf"` or `"nan"` and judged, with a `verdict`. For `eval` and
//! `float_eval`, `"t": [..]` (at most [`MAX_BATCH`]) asks at many parameters in one request,
//! answered as `results`, one object per parameter; the work limit counts the whole batch.
//!
//! `split`, `elevate`, `derivative` and `to_bezier` judge `approx` (shaped as the exact
//! answer) against the a priori bound of the caller's `method` ([`PointsMethod`]), per point
//! and coordinate, through [`Op::Judged`] and [`Answer::Judged`].
//!
//! `conic`'s `type` is `"ellipse"`, `"parabola"`, `"hyperbola"` or `"degenerate (…)"`;
//! `implicit` is `[A, B, C, D, E, F]` of `A x² + B xy + C y² + D x + E y + F = 0` scaled to
//! coprime integers with the first non-zero one positive (`null` when the control points
//! are collinear: no unique conic carries the arc). `surface_eval` is
//! `Σ_i Σ_j b_ij B_i^m(u) B_j^n(v)` with `net[i][j] = b_ij`.
//!
//! # `ulps`
//!
//! For `eval` with `approx` (the caller's float result, one JSON number per coordinate),
//! per coordinate, with `x` the exact value and `a` the approximation:
//! - `nearest`: the `f64` nearest to `x` (ties to even), i.e. the correctly rounded result;
//! - `ulps`: how many `f64` steps `a` is from `nearest` — `0` exactly when `a` is correctly
//!   rounded (an integer; `+0` and `-0` count as the same);
//! - `error_ulps`: `|a − x| / ulp(x)` computed exactly, then rounded to a JSON number, where
//!   `ulp(x) = 2^(e−52)` for `2^e ≤ |x| < 2^(e+1)` and `e ≥ −1022`, and `ulp(x) = 2^−1074`
//!   for `|x| < 2^−1022` (subnormal range, exact 0 included). A correctly rounded `a` has
//!   `error_ulps ≤ 0.5`;
//! - `bound` (when the parameters are floats): the a priori bound of f64 de Casteljau for
//!   the request's float inputs, in ulps of `x` rounded up, and `within_bound`: whether
//!   `|a − x|` is at most that bound, decided exactly (see [`crate::float`]).
//!
//! Encodings: `ulps` is a JSON integer up to 2^53, a decimal string beyond; `error_ulps` and
//! `bound` are JSON numbers, or `"inf"` beyond the largest f64 (never `null`). The `id` is
//! echoed as the JSON value it is; an id holding a number that is not a 64-bit integer is
//! echoed verbatim, as its own text, first in the response.
//!
//! # Limits
//!
//! No request can exhaust memory or time: lines are read at most [`MAX_LINE_BYTES`] at a
//! time, not counting the `\r` of a `\r\n` line end (a longer line is answered with an
//! error as soon as the limit is crossed, then skipped without being stored). That answer
//! carries the request's `id` when the line starts with it (`{"id": 7, "op": …`, the id
//! within the limit); an id anywhere else cannot be read without the whole line, so the
//! answer has none: a client that pipelines large requests puts the id first. Curves
//! have at most [`MAX_POINTS`] points, degrees stay at most [`MAX_DEGREE`] (after elevation
//! too), points at most [`MAX_REQUEST_DIMENSION`] coordinates; numbers at most
//! [`crate::scalar::MAX_NUMBER_LEN`] characters and decimal exponents within
//! ±[`crate::scalar::MAX_DECIMAL_EXPONENT`]. Exact arithmetic grows numbers, so each request
//! is also given a work estimate ([`Op::work`], roughly Σ bits² over its rational
//! operations) which must stay below [`MAX_REQUEST_WORK`]; beyond it the request is refused before
//! any computation.

mod batch;
mod cost;
mod fast;
mod io;
mod json;
mod judge;
mod judged;
mod protocol;
mod text;
mod values;

pub use crate::float::{nearest_f64, ulp, ulp_distance, ulp_error, UlpError};
pub use batch::MAX_BATCH;
pub use cost::check_scheme_work;
pub use io::{read_line_bounded, serve, skip_line, Line, READ_CHUNK_BYTES};
pub use judge::{judge_coords, judge_float, BoundCheck, FloatEvalAnswer, FloatMethod, Judgement};
pub use judged::{Approx, JudgedAnswer, PointsMethod};
pub use protocol::{check_weight_count, Answer, Op, OPS};
pub use text::conic_polynomial;
pub use values::{
    net_from_json, number_from_json, number_to_json, point_from_json, point_to_json, points_from_json, points_to_json,
};

use serde_json::{json, Map, Value};

/// Longest request line, in bytes (1 MiB).
pub const MAX_LINE_BYTES: usize = 1 << 20;

/// Most control points in one curve (or one row or column of a net).
pub const MAX_POINTS: usize = 4097;

/// Highest degree of any input or result (after elevation too).
pub use crate::error::MAX_DEGREE;

/// Most coordinates per point of a request (points built by the library itself may have up
/// to [`crate::MAX_DIMENSION`]).
pub const MAX_REQUEST_DIMENSION: usize = 64;

/// Largest work estimate ([`Op::work`]) a request may have.
///
/// The unit is one bit² of gcd-reduced rational arithmetic in each op's model of its kernel,
/// calibrated per op and per kind of input numbers (integers, floats, decimals, other
/// fractions) so that the largest request any op admits takes about a quarter of a second of
/// CPU on one core of a busy 2-core machine, its answer written out included
/// (`tests/calibration.rs` runs it for every op and eight kinds of numbers, and fails above
/// two seconds). For scale: `split` of a planar curve of three-digit integers is admitted up
/// to degree 1259 at `t = 1/3` and 226 at `t = 0.1`, `eval` up to the degree limit at 1/3
/// and to degree 1118 at 0.1.
pub const MAX_REQUEST_WORK: f64 = crate::work::HALF_SECOND;

/// Answers one request line with one response line (no newline).
///
/// Never panics on any input: a panic inside a handler would be a bug, and is caught and
/// answered with `"internal error"` so that the loop goes on.
pub fn handle_line(line: &str) -> String {
    let outcome = std::panic::catch_unwind(|| respond(line));
    match outcome {
        Ok(v) => v,
        Err(_) => {
            json!({"ok": false, "error": "internal error (a bug in casteljau: please report the request)"}).to_string()
        }
    }
}

fn respond(line: &str) -> String {
    if let Some((op, id)) = fast::eval_request(line) {
        return answer_line(op.run_checked(), id.as_ref(), line);
    }
    respond_in_general(line)
}

/// [`respond`] without the fast path: what the fast path's answers are tested against.
fn respond_in_general(line: &str) -> String {
    let request: Value = match serde_json::from_str(line) {
        Ok(v) => v,
        Err(e) => {
            let msg = if line.trim().is_empty() {
                "empty line: expected one JSON request object per line".to_string()
            } else {
                format!("not valid JSON: {e}")
            };
            return json!({"ok": false, "error": msg}).to_string();
        }
    };
    if let Err(e) = json::check_unique_fields(line) {
        return answer_line(Err(e), request.get("id"), line);
    }
    let answer = Op::from_json(&request).and_then(|op| op.run_checked());
    answer_line(answer, request.get("id"), line)
}

/// The response fields with `ok` (and `error` for a failure).
fn with_ok(fields: crate::Result<Map<String, Value>>) -> Map<String, Value> {
    match fields {
        Ok(mut m) => {
            m.insert("ok".into(), Value::Bool(true));
            m
        }
        Err(e) => {
            let mut m = Map::new();
            m.insert("ok".into(), Value::Bool(false));
            m.insert("error".into(), Value::String(e.to_string()));
            m
        }
    }
}

/// The response line to `line`, whose request was parsed into `answer` and `id`.
fn answer_line(answer: crate::Result<Answer>, id: Option<&Value>, line: &str) -> String {
    if let Ok(Answer::Point { point, ulps, bound }) = &answer {
        if !id.is_some_and(has_inexact_number) {
            return point_response(point, ulps.as_deref(), bound.as_deref(), id);
        }
    }
    finish_line(with_ok(answer.map(|a| a.to_json())), id, line)
}

/// The response line with the fields `out` and the request's `id` echoed.
fn finish_line(mut out: Map<String, Value>, id: Option<&Value>, line: &str) -> String {
    match id {
        None => Value::Object(out).to_string(),
        Some(id) if !has_inexact_number(id) => {
            out.insert("id".into(), id.clone());
            Value::Object(out).to_string()
        }
        Some(id) => {
            // A number that is not a 64-bit integer would be re-printed from its f64
            // (1e+29 for a 30-digit id): echo the id's own text instead, verbatim.
            #[derive(serde::Deserialize)]
            struct RawId<'a> {
                #[serde(borrow)]
                id: &'a serde_json::value::RawValue,
            }
            let raw = serde_json::from_str::<RawId>(line).map(|r| r.id.get().to_string());
            let rest = Value::Object(out.clone()).to_string();
            match raw {
                Ok(raw) => format!("{{\"id\":{raw},{}", &rest[1..]),
                Err(_) => {
                    out.insert("id".into(), id.clone());
                    Value::Object(out).to_string()
                }
            }
        }
    }
}

/// The response to a request answered with a point, written directly: byte for byte what
/// the answer's [`Answer::to_json`] map with `ok` and `id` prints (keys in sorted order, as
/// serde_json's map keeps them), without building the map.
fn point_response(
    point: &crate::point::Point<num_rational::BigRational>,
    ulps: Option<&[UlpError]>,
    bound: Option<&[BoundCheck]>,
    id: Option<&Value>,
) -> String {
    fn key(out: &mut Vec<u8>, name: &str) {
        if out.len() > 1 {
            out.push(b',');
        }
        out.push(b'"');
        out.extend_from_slice(name.as_bytes());
        out.extend_from_slice(b"\":");
    }
    fn list<T>(out: &mut Vec<u8>, items: impl Iterator<Item = T>, write: impl Fn(&mut Vec<u8>, T)) {
        out.push(b'[');
        for (k, item) in items.enumerate() {
            if k > 0 {
                out.push(b',');
            }
            write(out, item);
        }
        out.push(b']');
    }
    fn array<T: serde::Serialize>(out: &mut Vec<u8>, items: impl Iterator<Item = T>) {
        list(out, items, |out, item| {
            serde_json::to_writer(out, &item).expect("writing JSON to memory")
        });
    }
    let mut out = Vec::with_capacity(512);
    out.push(b'{');
    if let Some(b) = bound {
        key(&mut out, "bound");
        array(&mut out, b.iter().map(|c| judge::float_json(c.bound_ulps)));
    }
    if let Some(u) = ulps {
        key(&mut out, "error_ulps");
        array(&mut out, u.iter().map(|e| judge::float_json(e.error_ulps)));
    }
    if let Some(id) = id {
        key(&mut out, "id");
        serde_json::to_writer(&mut out, id).expect("writing JSON to memory");
    }
    if let Some(u) = ulps {
        key(&mut out, "nearest");
        array(&mut out, u.iter().map(|e| judge::float_json(e.nearest)));
    }
    key(&mut out, "ok");
    out.extend_from_slice(b"true");
    key(&mut out, "point");
    list(&mut out, point.coords().iter(), |out, c| {
        // digits, '-' and '/': a JSON string with nothing to escape
        out.push(b'"');
        out.extend_from_slice(crate::scalar::format_exact(c).as_bytes());
        out.push(b'"');
    });
    if let Some(u) = ulps {
        key(&mut out, "ulps");
        array(&mut out, u.iter().map(|e| judge::ulps_json(e.ulps)));
    }
    if let Some(b) = bound {
        key(&mut out, "within_bound");
        array(&mut out, b.iter().map(|c| c.within));
    }
    out.push(b'}');
    String::from_utf8(out).expect("serde_json writes UTF-8")
}

/// Whether a JSON value holds a number that serde_json keeps only as an `f64`.
fn has_inexact_number(v: &Value) -> bool {
    match v {
        Value::Number(n) => !(n.is_i64() || n.is_u64()),
        Value::Array(items) => items.iter().any(has_inexact_number),
        Value::Object(m) => m.values().any(has_inexact_number),
        _ => false,
    }
}

#[cfg(test)]
mod tests;
