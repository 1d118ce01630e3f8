//! The oracle as judge: a priori bounds for the request's float inputs, and casteljau's own
//! float evaluators (`float_eval`) measured against the exact value.

use crate::curve::BezierCurve;
use crate::error::{Error, Result};
use crate::float::{
    a_priori_bound, abs_bernstein_sum, bernstein_bound, bernstein_sum, compensated_a_priori_bound,
    compensated_de_casteljau, compensated_de_casteljau_by, condition_number, de_casteljau, de_casteljau_running,
    error_at_most, eval_dyadic, exact_f64, horner, horner_bound, lerp_bound, lerp_de_casteljau, nearest_f64,
    power_coefficients, rational_a_priori_bound, scale_pow2_up, surface_a_priori_bound, ulp_exponent, OpBound,
    UlpError, UNIT_ROUNDOFF,
};
use crate::interval::{tight_interval_de_casteljau, Interval};
use crate::point::Point;
use crate::rational::RationalBezierCurve;
use crate::scalar::Scalar;
use crate::surface::BezierSurface;
use num_rational::BigRational;
use serde_json::{json, Value};

/// A float result judged against an error bound, for one coordinate.
#[derive(Clone, Debug, PartialEq)]
pub struct BoundCheck {
    /// The bound in ulps of the exact value, rounded up (`+∞` when there is none).
    pub bound_ulps: f64,
    /// Whether the error is at most the bound (decided exactly).
    pub within: bool,
}

impl BoundCheck {
    /// Judges `approx` against the exact `x` with the absolute bound `bound`.
    ///
    /// A bound that came out NaN (`∞ · 0` in a bound's float arithmetic, on inputs near the
    /// largest float) bounds nothing: it is `+∞`. An answer with no error is within every
    /// bound, and so is `±∞` where the exact value is beyond the largest float on that side
    /// (the correctly rounded answer).
    pub fn new(approx: f64, x: &BigRational, bound: f64) -> Self {
        let bound = no_nan(bound);
        let correctly_rounded_overflow = approx.is_infinite() && nearest_f64(x) == approx;
        BoundCheck {
            bound_ulps: no_nan(scale_pow2_up(bound, -ulp_exponent(x))),
            within: correctly_rounded_overflow || error_at_most(approx, x, bound),
        }
    }
}

/// A bound, `+∞` for NaN: a bound is a number or `+∞` (no bound), never NaN.
pub(super) fn no_nan(bound: f64) -> f64 {
    if bound.is_nan() {
        f64::INFINITY
    } else {
        bound
    }
}

/// One point's coordinates judged: errors when an approximation was sent, the bound and the
/// condition when the inputs are floats.
#[derive(Clone, Debug, PartialEq)]
pub struct Judgement {
    /// per coordinate, the caller's error (with `approx`)
    pub errors: Option<Vec<UlpError>>,
    /// per coordinate, a sentence when the caller's float is `±∞` or NaN
    pub verdicts: Vec<Option<&'static str>>,
    /// per coordinate, the algorithm's bound in ulps, and whether the answer is within it
    /// (`within` is false without `approx`)
    pub bound: Option<Vec<BoundCheck>>,
    /// per coordinate, `S / |x|`: `S` the sum of absolute values the bound is `γ_k` times
    pub condition: Option<Vec<f64>>,
}

/// Judges one point's float answer (`approx`, when sent) against the exact point `x`, and
/// with `bounds` (per coordinate, an absolute bound of the caller's algorithm and the sum it
/// is `γ_k` times) gives the bound in ulps, the verdict and the condition.
pub fn judge_coords(approx: Option<&[f64]>, x: &Point<BigRational>, bounds: Option<&[OpBound]>) -> Result<Judgement> {
    let (errors, verdicts) = match approx {
        Some(a) => {
            if a.len() != x.dim() {
                return Err(Error::DimensionMismatch {
                    expected: x.dim(),
                    found: a.len(),
                    context: "field 'approx'".into(),
                });
            }
            let (e, v): (Vec<_>, Vec<_>) = a
                .iter()
                .zip(x.coords())
                .map(|(a, x)| judge_float(*a, x))
                .collect::<Result<Vec<_>>>()?
                .into_iter()
                .unzip();
            (Some(e), v)
        }
        None => (None, vec![None; x.dim()]),
    };
    let bound = bounds.map(|b| {
        b.iter()
            .zip(x.coords())
            .enumerate()
            .map(|(k, (b, x))| match approx {
                Some(a) => BoundCheck::new(a[k], x, b.bound),
                None => BoundCheck {
                    bound_ulps: no_nan(scale_pow2_up(no_nan(b.bound), -ulp_exponent(x))),
                    within: false,
                },
            })
            .collect()
    });
    let condition = bounds.map(|b| {
        b.iter()
            .zip(x.coords())
            .map(|(b, x)| {
                let p = nearest_f64(x);
                if p == 0.0 {
                    if b.sum == 0.0 {
                        0.0
                    } else {
                        f64::INFINITY
                    }
                } else {
                    no_nan(crate::float::next_up(b.sum / p.abs()))
                }
            })
            .collect()
    });
    Ok(Judgement {
        errors,
        verdicts,
        bound,
        condition,
    })
}

/// `b(t)` and the caller's float answer (`approx`, when sent) judged by [`judge_coords`]
/// against the a priori bound of `method` (plain de Casteljau when `None`) at a float
/// parameter; the condition comes with a named method or with the bound alone (without a
/// method an approximation is answered as plain `eval` answers it).
pub(super) fn eval_judgement(
    curve: &BezierCurve<BigRational>,
    t: &BigRational,
    approx: Option<&[f64]>,
    method: Option<FloatMethod>,
) -> Result<(Point<BigRational>, Judgement)> {
    let point = eval_dyadic(curve, t).unwrap_or_else(|| curve.eval_nested(t));
    let bounds: Option<Vec<OpBound>> = exact_f64(t).map(|tf| {
        let algorithm = method.unwrap_or(FloatMethod::DeCasteljau);
        let (coords, exact) = float_coords(curve.points());
        coords
            .iter()
            .zip(point.coords())
            .map(|(b, x)| OpBound {
                bound: rounded_inputs(algorithm.bound(b, tf, nearest_f64(x)), b, tf, exact),
                sum: abs_bernstein_sum(b, tf),
            })
            .collect()
    });
    let mut judgement = judge_coords(approx, &point, bounds.as_deref())?;
    if method.is_none() && approx.is_some() {
        judgement.condition = None;
    }
    Ok((point, judgement))
}

/// A float evaluation algorithm: one of casteljau's evaluators (`float_eval`), or the one
/// a caller used (`eval` with `method`), each with its own a priori bound.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FloatMethod {
    /// Plain de Casteljau in the convex form `fl(fl(s·a) + fl(t·b))`, `s = fl(1 − t)`, with
    /// its a priori and running bounds.
    DeCasteljau,
    /// De Casteljau in the lerp form `a + t·(b − a)`.
    Lerp,
    /// Horner's rule on the correctly rounded power-basis coefficients.
    Horner,
    /// The Bernstein sum `Σ b_i C(n, i) t^i (1 − t)^{n−i}`.
    Bernstein,
    /// Compensated de Casteljau, with its bound.
    Compensated,
    /// The generic de Casteljau on [`Interval`]s: an enclosure (`float_eval` only).
    Interval,
}

/// The method names, for error messages.
const METHODS: &str = "de_casteljau, lerp, horner, bernstein, compensated, interval";

impl FloatMethod {
    /// The method's name in requests.
    pub fn as_str(self) -> &'static str {
        match self {
            FloatMethod::DeCasteljau => "de_casteljau",
            FloatMethod::Lerp => "lerp",
            FloatMethod::Horner => "horner",
            FloatMethod::Bernstein => "bernstein",
            FloatMethod::Compensated => "compensated",
            FloatMethod::Interval => "interval",
        }
    }

    /// Parses a method name.
    pub fn parse(name: &str) -> Result<Self> {
        Ok(match name {
            "de_casteljau" => FloatMethod::DeCasteljau,
            "lerp" => FloatMethod::Lerp,
            "horner" => FloatMethod::Horner,
            "bernstein" => FloatMethod::Bernstein,
            "compensated" => FloatMethod::Compensated,
            "interval" => FloatMethod::Interval,
            other => {
                return Err(Error::Parse(format!(
                    "unknown method {:?} (one of {METHODS})",
                    super::values::truncate(other)
                )))
            }
        })
    }

    /// Runs the method on one coordinate's coefficients (`Interval`, which has no float
    /// answer, gives the compensated value).
    pub fn run(self, b: &[f64], t: f64) -> f64 {
        match self {
            FloatMethod::DeCasteljau => de_casteljau(b, t),
            FloatMethod::Lerp => lerp_de_casteljau(b, t),
            FloatMethod::Horner => horner(&power_coefficients(b), t),
            FloatMethod::Bernstein => bernstein_sum(b, t),
            FloatMethod::Compensated | FloatMethod::Interval => compensated_de_casteljau(b, t).0,
        }
    }

    /// The method's a priori bound on one coordinate, `p` a float near the exact value (the
    /// compensated bound is relative to it); `+∞` for `Interval`, which has no float answer.
    pub fn bound(self, b: &[f64], t: f64, p: f64) -> f64 {
        match self {
            FloatMethod::DeCasteljau => a_priori_bound(b, t),
            FloatMethod::Lerp => lerp_bound(b, t),
            FloatMethod::Horner => horner_bound(&power_coefficients(b), t),
            FloatMethod::Bernstein => bernstein_bound(b, t),
            FloatMethod::Compensated => compensated_a_priori_bound(b, t, p),
            FloatMethod::Interval => f64::INFINITY,
        }
    }
}

/// A float answer's error when it may be `±∞` or NaN: `(error, verdict)`, the verdict a
/// sentence when the float is not finite. An infinity is one step past `±f64::MAX`, so its
/// `ulps` count from the nearest float; its `error_ulps` is `+∞`. A NaN has `ulps` `u64::MAX`
/// and `error_ulps` NaN (written `"nan"`).
pub fn judge_float(approx: f64, exact: &BigRational) -> Result<(UlpError, Option<&'static str>)> {
    crate::judge::float_error(approx, exact)
}

/// What `float_eval` answers: the float results with their exact errors and bounds.
#[derive(Clone, Debug, PartialEq)]
pub struct FloatEvalAnswer {
    /// the evaluator
    pub method: FloatMethod,
    /// the exact point
    pub point: Point<BigRational>,
    /// the float result per coordinate (the interval's midpoint for `interval`)
    pub values: Vec<f64>,
    /// the float result's error per coordinate
    pub errors: Vec<UlpError>,
    /// the method's bound per coordinate (for `interval`, the distance to the farther end)
    pub bound: Vec<BoundCheck>,
    /// `de_casteljau` only: the running (a posteriori) bound
    pub running: Option<Vec<BoundCheck>>,
    /// `interval` only: per coordinate `lo`, `hi` and whether they enclose the exact value
    pub enclosure: Option<Vec<(f64, f64, bool)>>,
    /// per coordinate, the condition number `Σ|b_i||B_i(t)| / |b(t)|` (estimated)
    pub condition: Vec<f64>,
    /// per coordinate, a sentence when the float result is `±∞` or NaN
    pub verdicts: Vec<Option<&'static str>>,
}

/// The curve's coordinates as floats, coordinate-major, and whether every one was exact.
pub(super) fn float_coords(points: &[Point<BigRational>]) -> (Vec<Vec<f64>>, bool) {
    let dim = points[0].dim();
    let mut exact = true;
    let coords = (0..dim)
        .map(|k| {
            points
                .iter()
                .map(|p| {
                    let x = &p.coords()[k];
                    exact_f64(x).unwrap_or_else(|| {
                        exact = false;
                        nearest_f64(x)
                    })
                })
                .collect()
        })
        .collect();
    (coords, exact)
}

/// Adds `u Σ|b_i||B_i|` to a bound when the inputs were rounded to floats first.
pub(super) fn rounded_inputs(bound: f64, b: &[f64], t: f64, exact_inputs: bool) -> f64 {
    if exact_inputs {
        bound
    } else {
        crate::float::next_up(bound + UNIT_ROUNDOFF * abs_bernstein_sum(b, t) * (1.0 + 1e-15))
    }
}

/// `approx` judged against the a priori de Casteljau bound for the request's float inputs;
/// `None` when the parameter is not a float (the float algorithm would not see it).
pub fn curve_bounds(
    curve: &BezierCurve<BigRational>,
    t: &BigRational,
    approx: &[f64],
    point: &Point<BigRational>,
) -> Option<Vec<BoundCheck>> {
    let t = exact_f64(t)?;
    let (coords, exact) = float_coords(curve.points());
    Some(
        coords
            .iter()
            .zip(approx)
            .zip(point.coords())
            .map(|((b, a), x)| BoundCheck::new(*a, x, rounded_inputs(a_priori_bound(b, t), b, t, exact)))
            .collect(),
    )
}

/// As [`curve_bounds`] for a rational curve (see [`rational_a_priori_bound`]).
pub fn rational_bounds(
    curve: &RationalBezierCurve<BigRational>,
    t: &BigRational,
    approx: &[f64],
    point: &Point<BigRational>,
) -> Option<Vec<BoundCheck>> {
    let t = exact_f64(t)?;
    let weights: Vec<f64> = curve.weights().iter().map(exact_f64).collect::<Option<_>>()?;
    let (coords, exact) = float_coords(curve.points());
    if !exact {
        return None;
    }
    let nearest: Vec<f64> = point.coords().iter().map(nearest_f64).collect();
    let bounds = rational_a_priori_bound(&coords, &weights, t, &nearest);
    Some(
        bounds
            .iter()
            .zip(approx)
            .zip(point.coords())
            .map(|((bound, a), x)| BoundCheck::new(*a, x, *bound))
            .collect(),
    )
}

/// As [`curve_bounds`] for a surface (see [`surface_a_priori_bound`]).
pub fn surface_bounds(
    surface: &BezierSurface<BigRational>,
    u: &BigRational,
    v: &BigRational,
    approx: &[f64],
    point: &Point<BigRational>,
) -> Option<Vec<BoundCheck>> {
    let (u, v) = (exact_f64(u)?, exact_f64(v)?);
    let net = surface.net();
    (0..surface.dim())
        .map(|k| {
            let rows: Vec<Vec<f64>> = net
                .iter()
                .map(|row| row.iter().map(|p| exact_f64(&p.coords()[k])).collect::<Option<_>>())
                .collect::<Option<_>>()?;
            let x = &point.coords()[k];
            Some(BoundCheck::new(approx[k], x, surface_a_priori_bound(&rows, u, v)))
        })
        .collect()
}

/// Runs `method` on the curve's floats at `t` and judges it against the exact `point`.
/// The inputs must be floats exactly (checked when the request is read).
pub fn float_eval(
    curve: &BezierCurve<BigRational>,
    t: &BigRational,
    method: FloatMethod,
    point: Point<BigRational>,
) -> Result<FloatEvalAnswer> {
    let tf = exact_f64(t).ok_or_else(|| not_a_float("t", t))?;
    let (coords, exact) = float_coords(curve.points());
    if !exact {
        return Err(Error::Parse(
            "float_eval runs in f64: every control point coordinate must be a float exactly".into(),
        ));
    }
    let mut values = Vec::new();
    let mut bound = Vec::new();
    let mut running = Vec::new();
    let mut enclosure = Vec::new();
    // De Casteljau's convex form in interval arithmetic: for t in [0, 1] its widths add up
    // level by level like the a priori bound, where the generic lerp form `a + t·(b − a)`
    // grows them with the degree (3.3e44 ulps at degree 100). Both enclose the value, so
    // their intersection does, and it is the narrower at every degree.
    let intervals = if method == FloatMethod::Interval {
        let c = curve.try_map(Interval::from_rational)?;
        let generic = c.eval_reference(&Interval::from_rational(t)?);
        Some(
            coords
                .iter()
                .zip(generic.coords())
                .map(|(b, g)| {
                    let convex = unbounded_for_nan(tight_interval_de_casteljau(b, tf)?);
                    let g = unbounded_for_nan(*g);
                    Ok(Interval::new(convex.lo().max(g.lo()), convex.hi().min(g.hi())).unwrap_or(convex))
                })
                .collect::<Result<Vec<_>>>()?,
        )
    } else {
        None
    };
    let mut condition = Vec::new();
    for (k, b) in coords.iter().enumerate() {
        let x = &point.coords()[k];
        condition.push(condition_number(b, tf, nearest_f64(x)));
        match method {
            FloatMethod::Lerp | FloatMethod::Horner | FloatMethod::Bernstein => {
                let value = method.run(b, tf);
                values.push(value);
                bound.push(BoundCheck::new(value, x, method.bound(b, tf, nearest_f64(x))));
            }
            FloatMethod::DeCasteljau => {
                let value = de_casteljau(b, tf);
                let (_, run) = de_casteljau_running(b, tf);
                values.push(value);
                bound.push(BoundCheck::new(value, x, a_priori_bound(b, tf)));
                running.push(BoundCheck::new(value, x, run));
            }
            FloatMethod::Compensated => {
                // Dekker's product on every CPU: the same value as the run-time choice, and
                // a bound that does not depend on the machine answering (tests/golden).
                let (value, e) = compensated_de_casteljau_by(b, tf, false);
                values.push(value);
                bound.push(BoundCheck::new(value, x, e));
            }
            FloatMethod::Interval => {
                let iv = intervals.as_ref().expect("computed above")[k];
                // the midpoint: an infinite end where there is one, NaN for [−∞, ∞] (no value)
                let mid = iv.to_f64();
                let reach = no_nan(crate::float::next_up((iv.hi() - mid).max(mid - iv.lo())));
                values.push(mid);
                bound.push(BoundCheck::new(mid, x, reach));
                enclosure.push((iv.lo(), iv.hi(), iv.contains(x)));
            }
        }
    }
    let judged = values
        .iter()
        .zip(point.coords())
        .map(|(v, x)| judge_float(*v, x))
        .collect::<Result<Vec<_>>>()?;
    let (errors, verdicts) = judged.into_iter().unzip();
    Ok(FloatEvalAnswer {
        condition,
        verdicts,
        method,
        point,
        values,
        errors,
        bound,
        running: (method == FloatMethod::DeCasteljau).then_some(running),
        enclosure: (method == FloatMethod::Interval).then_some(enclosure),
    })
}

/// An enclosure with a NaN endpoint (`∞ − ∞` where the values overflowed) widened to the
/// infinity on that side: `[−∞, ∞]` encloses every value.
fn unbounded_for_nan(iv: Interval) -> Interval {
    let lo = if iv.lo().is_nan() { f64::NEG_INFINITY } else { iv.lo() };
    let hi = if iv.hi().is_nan() { f64::INFINITY } else { iv.hi() };
    Interval::new(lo, hi).unwrap_or_else(|_| Interval::new(f64::NEG_INFINITY, f64::INFINITY).expect("an interval"))
}

/// The error for an input that `float_eval` needs as a float.
pub fn not_a_float(what: &str, x: &BigRational) -> Error {
    Error::Parse(format!(
        "float_eval runs in f64: '{what}' must be a float exactly (a JSON number, or a string naming a float), got {x}"
    ))
}

/// `ulps` as JSON: a number up to 2^53 (exact in every JSON client), a decimal string beyond;
/// `"nan"` for the count of a NaN ([`judge_float`]).
pub fn ulps_json(ulps: u64) -> Value {
    if ulps == u64::MAX {
        json!("nan")
    } else if ulps <= 1 << 53 {
        json!(ulps)
    } else {
        json!(ulps.to_string())
    }
}

/// A float as JSON: a number, or the string `"inf"`, `"-inf"` or `"nan"` (JSON has no
/// infinity; `null` would read as "missing").
pub fn float_json(x: f64) -> Value {
    if x.is_finite() {
        json!(x)
    } else if x.is_nan() {
        json!("nan")
    } else if x > 0.0 {
        json!("inf")
    } else {
        json!("-inf")
    }
}

/// A float from JSON: a number, or one of the strings `"inf"`, `"+inf"`, `"-inf"`, `"nan"`
/// (how a float answer that overflowed is sent); `None` for anything else.
pub fn float_from_json(v: &Value) -> Option<f64> {
    match v {
        Value::Number(n) => n.as_f64(),
        Value::String(s) => match s.as_str() {
            "inf" | "+inf" => Some(f64::INFINITY),
            "-inf" => Some(f64::NEG_INFINITY),
            "nan" => Some(f64::NAN),
            _ => None,
        },
        _ => None,
    }
}

/// A caller's float answer, one per coordinate: JSON numbers, and with `overflow` also the
/// strings of [`float_from_json`]. Both of `eval`'s paths read `approx` here, so that they
/// answer alike.
pub(super) fn floats_from_json(v: &Value, overflow: bool) -> Result<Vec<f64>> {
    let items = v.as_array().ok_or_else(|| {
        Error::Parse(format!(
            "expected an array of JSON numbers (one per coordinate), got {}",
            super::values::describe(v)
        ))
    })?;
    if items.len() > super::MAX_REQUEST_DIMENSION {
        return Err(super::values::too_large(
            "dimension",
            items.len(),
            super::MAX_REQUEST_DIMENSION,
        ));
    }
    let what = if overflow {
        "a float answer must be a JSON number or one of \"inf\", \"-inf\", \"nan\""
    } else {
        "the approximation must be a JSON number (a float)"
    };
    items
        .iter()
        .enumerate()
        .map(|(k, x)| {
            let float = if overflow { float_from_json(x) } else { x.as_f64() };
            float.ok_or_else(|| Error::Parse(format!("coordinate {k}: {what}, got {}", super::values::describe(x))))
        })
        .collect()
}
