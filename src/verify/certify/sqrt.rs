//! Goals in a real quadratic field `Q(√d)` (`docs/certificates.md`, "Square roots"): a goal's
//! `sqrt(d)`, one square-free integer `d ≥ 2` per goal, and the numbers `a + b√d` of its values
//! and of the computations' facts, written `{"rational": a, "irrational": b, "radicand": d}`.
//! The arithmetic is the prover's ([`QuadraticIrrational`]); nothing here computes.

use super::{rational, string, Res};
use crate::quadratic::QuadraticIrrational;
use crate::verify::kernel::expr::Expr;
use num_traits::{ToPrimitive, Zero};
use serde_json::{json, Value as Json};

/// A number `a + b√d` as JSON: `"p/q"` when rational, else `{"rational": a, "irrational": b,
/// "radicand": d}` (d square-free, not 0 or 1: √d is irrational).
pub(super) fn number_json(q: &QuadraticIrrational) -> Json {
    match q.to_rational() {
        Some(r) => json!(r.to_string()),
        None => json!({"rational": q.rational_part().to_string(), "irrational": q.irrational_part().to_string(),
                       "radicand": q.radicand().map(|d| d.to_string())}),
    }
}

/// A number written by [`number_json`]; an irrational one with `b ≠ 0` only.
pub(super) fn number(v: &Json, at: &str) -> Res<QuadraticIrrational> {
    if let Some(s) = v.as_str() {
        return rational(s)
            .map(QuadraticIrrational::rational)
            .map_err(|e| format!("{at}: {e}"));
    }
    let part = |k: &str| rational(string(v, k, at)?).map_err(|e| format!("{at}.{k}: {e}"));
    let (a, b) = (part("rational")?, part("irrational")?);
    let d: i64 = string(v, "radicand", at)?
        .parse()
        .map_err(|_| format!("{at}.radicand: not an integer"))?;
    if b.is_zero() {
        return Err(format!("{at}: a rational number is written as \"p/q\""));
    }
    QuadraticIrrational::new(a, b, d).map_err(|e| format!("{at}: {e}"))
}

/// The radicand `d` of the `sqrt(d)` calls of `exprs` (`None`: there is none). Each call's
/// argument must be an integer literal `d ≥ 2`, square-free (so `√d` is real, irrational and
/// written one way), and all calls the same `d`: the goal is in one field `Q(√d)`.
pub(super) fn radicand<'e>(exprs: impl IntoIterator<Item = &'e Expr>) -> Res<Option<i64>> {
    let mut found: Res<Option<i64>> = Ok(None);
    for e in exprs {
        e.visit(&mut |x| {
            let Expr::Call(name, args) = x else { return };
            if name != "sqrt" || found.is_err() {
                return;
            }
            let d = match args.as_slice() {
                [Expr::Num(r)] if r.is_integer() => r.to_integer().to_i64().filter(|&d| d >= 2),
                _ => None,
            };
            let checked = match d {
                None => Err(format!(
                    "'{x}': sqrt's argument is not an integer d ≥ 2 (a real irrational √d)"
                )),
                Some(d) => QuadraticIrrational::new(Zero::zero(), num_traits::One::one(), d)
                    .map(|_| d)
                    .map_err(|e| format!("'{x}': {e}")),
            };
            found = match (checked, &found) {
                (Err(e), _) => Err(e),
                (Ok(d), Ok(e)) => same_field(*e, Some(d)),
                (Ok(_), Err(e)) => Err(e.clone()),
            };
        });
    }
    found
}

/// The field of a goal whose parts are in `Q(√a)` and `Q(√b)` (`None`: the rationals): one
/// radicand at most.
pub(super) fn same_field(a: Option<i64>, b: Option<i64>) -> Res<Option<i64>> {
    match (a, b) {
        (Some(e), Some(d)) if e != d => Err(format!(
            "the goal mixes sqrt({e}) and sqrt({d}): it must be in one field Q(√d)"
        )),
        _ => Ok(a.or(b)),
    }
}

/// A value entry as the kernel printed it (exactly: a rational, or `a + b*sqrt(d)`) as a
/// number of the goal's field `Q(√d)` (`radicand`; `None`: the rationals).
pub(super) fn value_json(text: &str, radicand: Option<i64>) -> Res<Json> {
    // `rational` accepts only a rational written as it prints (lowest terms): the text itself
    if rational(text).is_ok() {
        return Ok(Json::String(text.to_string()));
    }
    let q =
        QuadraticIrrational::parse(text).map_err(|e| format!("the value '{text}' is not a number a + b√d ({e})"))?;
    match (q.radicand(), radicand) {
        (Some(d), Some(e)) if d == e => Ok(number_json(&q)),
        _ => Err(format!("the value '{text}' is not in the goal's field")),
    }
}

/// A listed value read with [`number`], in the goal's field: a rational, or `a + b√d` with the
/// goal's radicand `d`.
pub(super) fn value(v: &Json, at: &str, radicand: Option<i64>) -> Res<QuadraticIrrational> {
    let q = number(v, at)?;
    match (q.radicand(), radicand) {
        (None, _) => Ok(q),
        (Some(d), Some(e)) if d == e => Ok(q),
        (Some(d), Some(e)) => Err(format!("{at}: a number of Q(√{d}), the goal is in Q(√{e})")),
        (Some(d), None) => Err(format!(
            "{at}: a number of Q(√{d}), the goal has no sqrt (its values are rational)"
        )),
    }
}
