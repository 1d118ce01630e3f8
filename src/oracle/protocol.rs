//! The oracle's requests ([`Op`]) and answers ([`Answer`]): limits checked, exact work run.

use super::judge::{
    curve_bounds, eval_judgement, float_eval, float_json, not_a_float, rational_bounds, surface_bounds, ulps_json,
    BoundCheck, FloatEvalAnswer, FloatMethod, Judgement,
};
use super::judged::{Approx, JudgedAnswer, PointsMethod};
use super::values::too_large;
use super::values::{number_to_json, point_to_json, points_to_json};
use super::{MAX_DEGREE, MAX_POINTS, MAX_REQUEST_DIMENSION, MAX_REQUEST_WORK};
use crate::conic::{classify_conic, implicit_conic, ConicKind};
use crate::curve::BezierCurve;
use crate::error::{Error, Result};
use crate::fit::{fit_cubic, CubicFit, CubicFitData};
use crate::float::{eval_dyadic, exact_f64, ulp_error, UlpError};
use crate::input::in_context;
use crate::point::Point;
use crate::rational::RationalBezierCurve;
use crate::surface::BezierSurface;
use num_bigint::BigInt;
use num_rational::BigRational;
use serde_json::{json, Map, Value};

/// One request, parsed and checked: exact inputs, sizes within the limits.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Op {
    /// `b(t)`; with `approx`, also the caller's rounding error.
    Eval {
        /// the curve
        curve: BezierCurve<BigRational>,
        /// the parameter
        t: BigRational,
        /// the caller's float result, one per coordinate
        approx: Option<Vec<f64>>,
    },
    /// Degree elevation by `by` steps.
    Elevate {
        /// the curve
        curve: BezierCurve<BigRational>,
        /// number of steps `r`
        by: usize,
    },
    /// Subdivision at `t`.
    Split {
        /// the curve
        curve: BezierCurve<BigRational>,
        /// the parameter
        t: BigRational,
    },
    /// The control points of the `order`-th derivative curve, or with `at` its value there.
    Derivative {
        /// the curve
        curve: BezierCurve<BigRational>,
        /// the order `k`
        order: usize,
        /// evaluate the derivative vector at this parameter instead
        at: Option<BigRational>,
    },
    /// The Bézier points of a polynomial curve given in the power basis on `[0, 1]`.
    ToBezier {
        /// `power[k][i]`: coordinate `k`'s coefficient of `t^i`
        power: Vec<Vec<BigRational>>,
    },
    /// `x(t)` of a rational Bézier curve; with `approx`, also the caller's rounding error.
    RationalEval {
        /// the curve
        curve: RationalBezierCurve<BigRational>,
        /// the parameter
        t: BigRational,
        /// the caller's float result, one per coordinate
        approx: Option<Vec<f64>>,
    },
    /// The type and implicit equation of the conic carrying a rational quadratic arc.
    Conic {
        /// the arc: three planar points and their weights
        curve: RationalBezierCurve<BigRational>,
    },
    /// `b(u, v)` of a tensor-product surface; with `approx`, also the caller's error.
    SurfaceEval {
        /// the surface
        surface: BezierSurface<BigRational>,
        /// the first parameter (the direction of the net's rows index `i`)
        u: BigRational,
        /// the second parameter
        v: BigRational,
        /// the caller's float result, one per coordinate
        approx: Option<Vec<f64>>,
    },
    /// Text 004's cubic fit.
    FitCubic {
        /// `x(0), x(1), x(1/2), ẋ(0), ẋ(1)`
        data: CubicFitData<BigRational>,
    },
    /// casteljau's own float evaluation of `b(t)` by `method`, judged exactly (float inputs).
    FloatEval {
        /// the curve (every coordinate a float exactly)
        curve: BezierCurve<BigRational>,
        /// the parameter (a float exactly)
        t: BigRational,
        /// the evaluator
        method: FloatMethod,
    },
    /// `b(t)` with the caller's float answer judged against the a priori bound of `method`,
    /// the caller's algorithm (plain de Casteljau when `None`): `eval` with `"method"`, with
    /// `"inf"`, `"-inf"` or `"nan"` in `approx`, or in a batch. Without `approx`, the bound
    /// and the condition alone.
    EvalJudged {
        /// the curve (shared by a batch's parameters)
        curve: std::sync::Arc<BezierCurve<BigRational>>,
        /// the parameter
        t: BigRational,
        /// the caller's float result, one per coordinate (`±∞` and NaN allowed)
        approx: Option<Vec<f64>>,
        /// the caller's algorithm, when named
        method: Option<FloatMethod>,
    },
    /// An op answering control points (`split`, `elevate`, `derivative` without `t`,
    /// `to_bezier`) with the caller's float answer judged against the a priori bound of
    /// `method`, the caller's algorithm.
    Judged {
        /// the op
        op: Box<Op>,
        /// the caller's float answer, shaped as the exact one (without it, the bounds alone)
        approx: Option<Approx>,
        /// the caller's algorithm
        method: PointsMethod,
    },
    /// One request at many parameters (`eval`, `float_eval` and `split` with `"t": [..]`):
    /// one op per parameter, each answered as the single request would be,
    /// answered as `results`, the work limit counting them all.
    Batch {
        /// the requests, one per parameter
        ops: Vec<Op>,
    },
}

/// The exact result of an [`Op`].
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Answer {
    /// A point of a curve, with the caller's error when it sent an approximation.
    Point {
        /// the exact point
        point: Point<BigRational>,
        /// per coordinate, when `approx` was given
        ulps: Option<Vec<UlpError>>,
        /// per coordinate, the caller's result judged against the a priori de Casteljau
        /// bound (when `approx` was given and the parameters are floats)
        bound: Option<Vec<BoundCheck>>,
    },
    /// A point of a curve with the caller's float answer judged ([`Op::EvalJudged`]).
    JudgedPoint {
        /// the exact point
        point: Point<BigRational>,
        /// the caller's algorithm, when named
        method: Option<FloatMethod>,
        /// per coordinate: errors, verdicts, bound and condition
        judgement: Judgement,
    },
    /// casteljau's own float evaluation, judged exactly.
    FloatEval(Box<FloatEvalAnswer>),
    /// Control points.
    Points(Vec<Point<BigRational>>),
    /// A vector (a derivative at a parameter).
    Vector(Point<BigRational>),
    /// The two halves of a subdivision.
    Split {
        /// `b(t0 t)`
        left: Vec<Point<BigRational>>,
        /// `b(t0 + (1 - t0) t)`
        right: Vec<Point<BigRational>>,
    },
    /// The conic carrying a rational quadratic arc.
    Conic {
        /// its affine type
        kind: ConicKind,
        /// `[A, B, C, D, E, F]` as coprime integers, first non-zero positive; `None` when
        /// the control points are collinear
        implicit: Option<[BigInt; 6]>,
    },
    /// Text 004's cubic fit.
    Fit(Box<CubicFit<BigRational>>),
    /// Control points (or a split's halves) with the caller's float answer judged.
    Judged(Box<JudgedAnswer>),
    /// A batch's answers, one per parameter.
    Results(Vec<Answer>),
}

impl Answer {
    /// The response fields (without `ok` and `id`).
    pub fn to_json(&self) -> Map<String, Value> {
        let mut m = Map::new();
        match self {
            Answer::Point { point, ulps, bound } => {
                m.insert("point".into(), point_to_json(point));
                if let Some(u) = ulps {
                    insert_errors(&mut m, u);
                }
                if let Some(b) = bound {
                    insert_bound(&mut m, "bound", "within_bound", b);
                }
            }
            Answer::JudgedPoint {
                point,
                method,
                judgement: j,
            } => {
                m.insert("point".into(), point_to_json(point));
                if let Some(name) = method {
                    m.insert("method".into(), json!(name.as_str()));
                }
                if let Some(e) = &j.errors {
                    insert_errors(&mut m, e);
                }
                insert_verdicts(&mut m, &j.verdicts);
                match &j.bound {
                    Some(b) if j.errors.is_some() => insert_bound(&mut m, "bound", "within_bound", b),
                    // without an approximation there is no verdict, only the bound
                    Some(b) => {
                        m.insert("bound".into(), b.iter().map(|c| float_json(c.bound_ulps)).collect());
                    }
                    None => {}
                }
                if let Some(c) = &j.condition {
                    m.insert("condition".into(), c.iter().map(|c| float_json(*c)).collect());
                }
            }
            Answer::FloatEval(f) => {
                m.insert("method".into(), json!(f.method.as_str()));
                m.insert("point".into(), point_to_json(&f.point));
                m.insert("value".into(), f.values.iter().map(|v| float_json(*v)).collect());
                m.insert("condition".into(), f.condition.iter().map(|c| float_json(*c)).collect());
                insert_errors(&mut m, &f.errors);
                insert_verdicts(&mut m, &f.verdicts);
                insert_bound(&mut m, "bound", "within_bound", &f.bound);
                if let Some(r) = &f.running {
                    insert_bound(&mut m, "running_bound", "within_running_bound", r);
                }
                if let Some(e) = &f.enclosure {
                    m.insert(
                        "interval".into(),
                        e.iter()
                            .map(|(lo, hi, _)| json!([float_json(*lo), float_json(*hi)]))
                            .collect(),
                    );
                    m.insert("encloses".into(), e.iter().map(|(_, _, ok)| json!(ok)).collect());
                }
            }
            Answer::Points(p) => {
                m.insert("points".into(), points_to_json(p));
            }
            Answer::Vector(v) => {
                m.insert("vector".into(), point_to_json(v));
            }
            Answer::Split { left, right } => {
                m.insert("left".into(), points_to_json(left));
                m.insert("right".into(), points_to_json(right));
            }
            Answer::Conic { kind, implicit } => {
                m.insert("type".into(), json!(kind.as_str()));
                let implicit = implicit
                    .as_ref()
                    .map_or(Value::Null, |k| k.iter().map(|c| json!(c.to_string())).collect());
                m.insert("implicit".into(), implicit);
            }
            Answer::Fit(fit) => {
                m.insert("k".into(), number_to_json(&fit.k));
                m.insert("l".into(), number_to_json(&fit.l));
                m.insert("points".into(), points_to_json(fit.curve.points()));
                m.insert("delta2".into(), number_to_json(&fit.delta2));
                m.insert("warnings".into(), json!(fit.warnings));
            }
            Answer::Judged(j) => m = j.to_json(),
            Answer::Results(r) => {
                m.insert("results".into(), r.iter().map(|a| Value::Object(a.to_json())).collect());
            }
        }
        m
    }
}

/// `ulps`, `error_ulps` and `nearest`, one entry per coordinate.
pub(super) fn insert_errors(m: &mut Map<String, Value>, errors: &[UlpError]) {
    m.insert("ulps".into(), errors.iter().map(|e| ulps_json(e.ulps)).collect());
    m.insert(
        "error_ulps".into(),
        errors.iter().map(|e| float_json(e.error_ulps)).collect(),
    );
    m.insert("nearest".into(), errors.iter().map(|e| float_json(e.nearest)).collect());
}

/// `verdict` when some float answer is `±∞` or NaN: per coordinate a sentence, or `null`.
pub(super) fn insert_verdicts(m: &mut Map<String, Value>, verdicts: &[Option<&'static str>]) {
    if verdicts.iter().any(Option::is_some) {
        m.insert("verdict".into(), verdicts.iter().map(|v| json!(v)).collect());
    }
}

/// A bound in ulps and the verdicts, one entry per coordinate.
pub(super) fn insert_bound(m: &mut Map<String, Value>, bound: &str, within: &str, checks: &[BoundCheck]) {
    m.insert(bound.into(), checks.iter().map(|c| float_json(c.bound_ulps)).collect());
    m.insert(within.into(), checks.iter().map(|c| json!(c.within)).collect());
}

impl Op {
    /// Checks the size limits and the work estimate.
    pub fn check_limits(&self) -> Result<()> {
        let degree = |c: &BezierCurve<BigRational>| -> Result<()> {
            if c.points().len() > MAX_POINTS {
                return Err(too_large("number of points", c.points().len(), MAX_POINTS));
            }
            if c.dim() > MAX_REQUEST_DIMENSION {
                return Err(too_large("dimension", c.dim(), MAX_REQUEST_DIMENSION));
            }
            Ok(())
        };
        match self {
            Op::EvalJudged { curve, .. } => degree(curve)?,
            Op::Eval { curve, .. }
            | Op::FloatEval { curve, .. }
            | Op::Split { curve, .. }
            | Op::Derivative { curve, .. } => degree(curve)?,
            Op::Elevate { curve, by } => {
                degree(curve)?;
                let total = curve.degree() as u128 + *by as u128;
                if total > MAX_DEGREE as u128 {
                    return Err(Error::TooLarge {
                        what: "degree after elevation",
                        value: total.to_string(),
                        limit: MAX_DEGREE.to_string(),
                    });
                }
            }
            Op::RationalEval { curve, .. } | Op::Conic { curve } => {
                if curve.points().len() > MAX_POINTS {
                    return Err(too_large("number of points", curve.points().len(), MAX_POINTS));
                }
                if curve.dim() > MAX_REQUEST_DIMENSION {
                    return Err(too_large("dimension", curve.dim(), MAX_REQUEST_DIMENSION));
                }
            }
            Op::SurfaceEval { surface, .. } => {
                let (m, n) = surface.degrees();
                if m.max(n) >= MAX_POINTS {
                    return Err(too_large(
                        "number of points in a net row or column",
                        m.max(n) + 1,
                        MAX_POINTS,
                    ));
                }
                if surface.dim() > MAX_REQUEST_DIMENSION {
                    return Err(too_large("dimension", surface.dim(), MAX_REQUEST_DIMENSION));
                }
            }
            Op::Judged { op, .. } => op.check_limits()?,
            Op::Batch { ops } => {
                if ops.is_empty() || ops.len() > super::MAX_BATCH {
                    return Err(too_large(
                        "number of parameters in a batch",
                        ops.len(),
                        super::MAX_BATCH,
                    ));
                }
                for op in ops {
                    op.check_limits()?;
                }
            }
            Op::FitCubic { data } => {
                if data.x0.dim() > MAX_REQUEST_DIMENSION {
                    return Err(too_large("dimension", data.x0.dim(), MAX_REQUEST_DIMENSION));
                }
            }
            Op::ToBezier { power } => {
                if power.is_empty() {
                    return Err(Error::Empty("a power-basis curve (no coordinates)"));
                }
                if power.len() > MAX_REQUEST_DIMENSION {
                    return Err(too_large("dimension", power.len(), MAX_REQUEST_DIMENSION));
                }
                let len = power[0].len();
                if len == 0 {
                    return Err(Error::Empty("a power-basis curve (no coefficients)"));
                }
                if len > MAX_POINTS {
                    return Err(too_large("number of coefficients", len, MAX_POINTS));
                }
                if let Some((k, c)) = power.iter().enumerate().find(|(_, c)| c.len() != len) {
                    return Err(Error::Parse(format!(
                        "ragged power coefficients: coordinate 0 has {len} coefficients but coordinate {k} has {}",
                        c.len()
                    )));
                }
            }
        }
        check_work(self.work())
    }

    /// Computes the exact answer (after [`Op::check_limits`]).
    pub fn run(&self) -> Result<Answer> {
        self.check_limits()?;
        self.run_checked()
    }

    /// [`Op::run`] without the limits: for measuring the work estimate against the clock
    /// (`tests/calibration.rs`), never for a request from outside.
    #[doc(hidden)]
    pub fn run_without_limits(&self) -> Result<Answer> {
        self.run_checked()
    }

    /// [`Op::run`] for an op whose limits were already checked ([`Op::from_json`] does).
    pub(super) fn run_checked(&self) -> Result<Answer> {
        Ok(match self {
            Op::Eval { curve, t, approx } => {
                // Same value as `curve.eval(t)` (property tests pin both), without a gcd per step;
                // float inputs need no gcd at all.
                let point = eval_dyadic(curve, t).unwrap_or_else(|| curve.eval_nested(t));
                let ulps = ulps_of(approx.as_deref(), &point)?;
                let bound = approx.as_deref().and_then(|a| curve_bounds(curve, t, a, &point));
                Answer::Point { point, ulps, bound }
            }
            Op::EvalJudged {
                curve,
                t,
                approx,
                method,
            } => {
                let (point, judgement) = eval_judgement(curve, t, approx.as_deref(), *method)?;
                Answer::JudgedPoint {
                    point,
                    method: *method,
                    judgement,
                }
            }
            Op::FloatEval { curve, t, method } => {
                let point = eval_dyadic(curve, t).unwrap_or_else(|| curve.eval_nested(t));
                Answer::FloatEval(Box::new(float_eval(curve, t, *method, point)?))
            }
            Op::Elevate { curve, by } => Answer::Points(curve.elevate_by(*by)?.into_points()),
            Op::Split { curve, t } => {
                let (l, r) = curve.split_at(t);
                Answer::Split {
                    left: l.into_points(),
                    right: r.into_points(),
                }
            }
            Op::Derivative { curve, order, at: None } => Answer::Points(curve.derivative(*order)?.into_points()),
            Op::Derivative {
                curve,
                order,
                at: Some(t),
            } => Answer::Vector(curve.derivative_at(*order, t)?),
            Op::RationalEval { curve, t, approx } => {
                let point = curve.eval_nested(t)?;
                let ulps = ulps_of(approx.as_deref(), &point)?;
                let bound = approx.as_deref().and_then(|a| rational_bounds(curve, t, a, &point));
                Answer::Point { point, ulps, bound }
            }
            Op::Conic { curve } => {
                if curve.points().len() != 3 {
                    return Err(Error::WrongCount {
                        what: "a conic arc",
                        needed: 3,
                        got: curve.points().len(),
                    });
                }
                if curve.dim() != 2 {
                    return Err(Error::DimensionMismatch {
                        expected: 2,
                        found: curve.dim(),
                        context: "the control points of a conic arc (planar)".into(),
                    });
                }
                let kind = classify_conic(curve)?;
                let implicit = if kind == ConicKind::DegenerateCollinear {
                    None
                } else {
                    Some(implicit_conic(curve)?.to_primitive_integers())
                };
                Answer::Conic { kind, implicit }
            }
            Op::SurfaceEval { surface, u, v, approx } => {
                let point = surface.eval_nested(u, v);
                let ulps = ulps_of(approx.as_deref(), &point)?;
                let bound = approx.as_deref().and_then(|a| surface_bounds(surface, u, v, a, &point));
                Answer::Point { point, ulps, bound }
            }
            Op::FitCubic { data } => Answer::Fit(Box::new(fit_cubic(data)?)),
            Op::Judged { op, approx, method } => super::judged::run(op, approx.as_ref(), *method)?,
            Op::Batch { ops } => Answer::Results(
                ops.iter()
                    .enumerate()
                    .map(|(k, op)| match op {
                        // float_eval's parameters after the first are checked in turn, as
                        // they are reached, and named by their place in the batch
                        Op::FloatEval { t, .. } if exact_f64(t).is_none() => {
                            Err(in_context(&format!("parameter {k}"), not_a_float("t", t)))
                        }
                        _ => op.run_checked(),
                    })
                    .collect::<Result<_>>()?,
            ),
            Op::ToBezier { power } => {
                let coeffs = (0..power[0].len())
                    .map(|i| Point::new(power.iter().map(|c| c[i].clone()).collect()))
                    .collect::<Result<Vec<_>>>()?;
                Answer::Points(BezierCurve::from_power(&coeffs)?.into_points())
            }
        })
    }
}

/// A work estimate within [`MAX_REQUEST_WORK`], or the error naming the limit.
pub(super) fn check_work(work: f64) -> Result<()> {
    // NaN cannot arise (finite sums of squares), but would be refused too
    if work.is_nan() || work > MAX_REQUEST_WORK {
        return Err(Error::TooLarge {
            what: "request (estimated exact work)",
            value: format!("{work:.2e}"),
            limit: format!("{MAX_REQUEST_WORK:.0e}; use fewer points, a lower degree or shorter numbers"),
        });
    }
    Ok(())
}

/// One weight per control point, said in those words.
pub fn check_weight_count(points: usize, weights: usize) -> Result<()> {
    if points != weights {
        return Err(Error::Parse(format!(
            "{weights} weights for {points} control points (give one weight per control point)"
        )));
    }
    Ok(())
}

/// Per coordinate errors of the caller's approximation, when it sent one.
fn ulps_of(approx: Option<&[f64]>, point: &Point<BigRational>) -> Result<Option<Vec<UlpError>>> {
    let Some(a) = approx else { return Ok(None) };
    if a.len() != point.dim() {
        return Err(Error::DimensionMismatch {
            expected: point.dim(),
            found: a.len(),
            context: "field 'approx'".into(),
        });
    }
    Ok(Some(
        a.iter()
            .zip(point.coords())
            .map(|(a, x)| ulp_error(*a, x))
            .collect::<Result<_>>()?,
    ))
}

/// The names of the ops, for error messages.
pub const OPS: &[&str] = &[
    "eval",
    "elevate",
    "split",
    "derivative",
    "to_bezier",
    "rational_eval",
    "conic",
    "surface_eval",
    "fit_cubic",
    "float_eval",
];
