//! The ops that answer control points (`split`, `elevate`, `derivative`, `to_bezier`) with
//! the caller's float answer (`approx`, shaped as the exact answer) judged per coordinate
//! against the a priori bound of the float algorithm it names (`method`): [`Op::Judged`]
//! and [`Answer::Judged`]. The bounds are `crate::float`'s (see `docs/float-bounds.md`);
//! each coordinate is judged by [`judge_coords`], the one judge of every op.

use super::judge::{float_coords, float_json, judge_coords, ulps_json, Judgement};
use super::values::describe;
use super::{Answer, Op};
use crate::error::{Error, Result};
use crate::float::{derivative_bounds, elevate_bounds, exact_f64, split_bounds, to_bezier_bounds, OpBound, SplitForm};
use crate::input::in_context;
use crate::point::Point;
use num_rational::BigRational;
use serde_json::{json, Map, Value};

/// The float algorithm a caller names for an op that answers control points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointsMethod {
    /// `split`: de Casteljau's triangle in the convex form `fl(fl(s·a) + fl(t·b))`.
    DeCasteljau,
    /// `split`: de Casteljau's triangle in the lerp form `fl(a + fl(t·fl(b − a)))`.
    Lerp,
    /// `elevate`: one step at a time, `c_i = (i/(m+1))·b_{i−1} + (1 − i/(m+1))·b_i` with
    /// both quotients rounded (or the integer weights summed, then divided by `m + 1`);
    /// `to_bezier`: `b_i = Σ_j fl(C(i,j)/C(n,j))·a_j`.
    Formula,
    /// `derivative`: `order` rounds of `d_i ← (m − l + 1)·(d_{i+1} − d_i)`.
    Differences,
}

impl PointsMethod {
    /// The method's name in requests.
    pub fn as_str(self) -> &'static str {
        match self {
            PointsMethod::DeCasteljau => "de_casteljau",
            PointsMethod::Lerp => "lerp",
            PointsMethod::Formula => "formula",
            PointsMethod::Differences => "differences",
        }
    }

    /// The methods of `op` (the first is its default).
    pub fn of(op: &str) -> &'static [PointsMethod] {
        match op {
            "split" => &[PointsMethod::DeCasteljau, PointsMethod::Lerp],
            "elevate" | "to_bezier" => &[PointsMethod::Formula],
            "derivative" => &[PointsMethod::Differences],
            _ => &[],
        }
    }

    /// Reads `op`'s field `method` (its default when absent).
    pub fn parse(op: &str, v: Option<&Value>) -> Result<PointsMethod> {
        let known = Self::of(op);
        let names = || known.iter().map(|m| m.as_str()).collect::<Vec<_>>().join(", ");
        match v {
            None => Ok(known[0]),
            Some(Value::String(s)) => known.iter().copied().find(|m| m.as_str() == s).ok_or_else(|| {
                Error::Parse(format!(
                    "field 'method': unknown method {:?} for op '{op}' (one of {})",
                    super::values::truncate(s),
                    names()
                ))
            }),
            Some(other) => Err(Error::Parse(format!(
                "field 'method' must be a string naming the caller's algorithm ({}), got {}",
                names(),
                describe(other)
            ))),
        }
    }
}

/// The caller's float answer, in the shape of the exact one.
#[derive(Clone, Debug, PartialEq)]
pub enum Approx {
    /// control points (`elevate`, `derivative`, `to_bezier`)
    Points(Vec<Vec<f64>>),
    /// the two halves of a subdivision
    Split {
        /// `left`
        left: Vec<Vec<f64>>,
        /// `right`
        right: Vec<Vec<f64>>,
    },
}

impl Approx {
    /// Reads `approx` for an op whose exact answer has `count` points of `dim` coordinates
    /// (in each half for `split`): JSON numbers, or `"inf"`, `"-inf"`, `"nan"`.
    pub fn from_json(v: &Value, split: bool, count: usize, dim: usize) -> Result<Approx> {
        let points = |v: &Value, what: &str| -> Result<Vec<Vec<f64>>> {
            let items = v.as_array().filter(|a| a.len() == count).ok_or_else(|| {
                Error::Parse(format!(
                    "{what}: expected {count} points (as many as the exact answer has), got {}",
                    describe(v)
                ))
            })?;
            items
                .iter()
                .enumerate()
                .map(|(k, p)| {
                    let p = super::judge::floats_from_json(p, true)
                        .map_err(|e| in_context(&format!("{what}: point {k}"), e))?;
                    if p.len() != dim {
                        return Err(Error::DimensionMismatch {
                            expected: dim,
                            found: p.len(),
                            context: format!("{what}: point {k}"),
                        });
                    }
                    Ok(p)
                })
                .collect()
        };
        if !split {
            return Ok(Approx::Points(points(v, "field 'approx'")?));
        }
        let obj = v
            .as_object()
            .filter(|o| o.len() == 2 && o.contains_key("left") && o.contains_key("right"));
        let obj = obj.ok_or_else(|| {
            Error::Parse(format!(
                "field 'approx': a split's approximation is {{\"left\": [points], \"right\": [points]}}, got {}",
                describe(v)
            ))
        })?;
        Ok(Approx::Split {
            left: points(&obj["left"], "field 'approx': 'left'")?,
            right: points(&obj["right"], "field 'approx': 'right'")?,
        })
    }

    /// How many coordinates it holds.
    pub fn coordinates(&self) -> usize {
        let count = |p: &Vec<Vec<f64>>| p.iter().map(Vec::len).sum::<usize>();
        match self {
            Approx::Points(p) => count(p),
            Approx::Split { left, right } => count(left) + count(right),
        }
    }
}

/// An [`Answer::Points`] or [`Answer::Split`] with each point judged.
#[derive(Clone, Debug, PartialEq)]
pub struct JudgedAnswer {
    /// the exact answer
    pub exact: Answer,
    /// the algorithm judged
    pub method: PointsMethod,
    /// per group (`points`, or `left` and `right`), per point
    pub groups: Vec<(&'static str, Vec<Judgement>)>,
}

/// Runs `op` exactly and judges `approx` (when given) with `method`'s bounds.
pub(super) fn run(op: &Op, approx: Option<&Approx>, method: PointsMethod) -> Result<Answer> {
    let exact = op.run_checked()?;
    let bounds = bounds_of(op, method);
    let groups = match (&exact, approx) {
        (Answer::Split { left, right }, a) => {
            let (al, ar) = match a {
                Some(Approx::Split { left, right }) => (Some(left), Some(right)),
                None => (None, None),
                Some(_) => return Err(Error::Parse("field 'approx': a split's shape is left and right".into())),
            };
            let (bl, br) = match bounds {
                Some(mut b) if b.len() == 2 => {
                    let r = b.pop();
                    (b.pop(), r)
                }
                _ => (None, None),
            };
            vec![
                ("left", judge_group(left, al, bl.as_deref())?),
                ("right", judge_group(right, ar, br.as_deref())?),
            ]
        }
        (Answer::Points(points), a) => {
            let a = match a {
                Some(Approx::Points(p)) => Some(p),
                None => None,
                Some(_) => return Err(Error::Parse("field 'approx': expected a list of points".into())),
            };
            let b = bounds.and_then(|mut b| b.pop());
            vec![("points", judge_group(points, a, b.as_deref())?)]
        }
        _ => unreachable!("judged ops answer control points"),
    };
    Ok(Answer::Judged(Box::new(JudgedAnswer { exact, method, groups })))
}

fn judge_group(
    exact: &[Point<BigRational>],
    approx: Option<&Vec<Vec<f64>>>,
    bounds: Option<&[Vec<OpBound>]>,
) -> Result<Vec<Judgement>> {
    exact
        .iter()
        .enumerate()
        .map(|(i, x)| judge_coords(approx.map(|a| a[i].as_slice()), x, bounds.map(|b| b[i].as_slice())))
        .collect()
}

/// Per group, per point, per coordinate: the bounds of `method` for the request's inputs;
/// `None` when an input is not a float exactly (the float algorithm would not see it).
fn bounds_of(op: &Op, method: PointsMethod) -> Option<Vec<Vec<Vec<OpBound>>>> {
    // per coordinate lists of per point bounds, transposed to per point
    let transpose = |per_coord: Vec<Vec<OpBound>>| -> Vec<Vec<OpBound>> {
        let points = per_coord.first().map_or(0, Vec::len);
        (0..points).map(|i| per_coord.iter().map(|c| c[i]).collect()).collect()
    };
    match op {
        Op::Split { curve, t } => {
            let t = exact_f64(t)?;
            let (coords, exact) = float_coords(curve.points());
            let form = if method == PointsMethod::Lerp {
                SplitForm::Lerp
            } else {
                SplitForm::Convex
            };
            if !exact {
                return None;
            }
            let halves: Vec<(Vec<OpBound>, Vec<OpBound>)> = coords.iter().map(|b| split_bounds(b, t, form)).collect();
            let (l, r): (Vec<_>, Vec<_>) = halves.into_iter().unzip();
            Some(vec![transpose(l), transpose(r)])
        }
        Op::Elevate { curve, by } => {
            let (coords, exact) = float_coords(curve.points());
            exact.then(|| vec![transpose(coords.iter().map(|b| elevate_bounds(b, *by)).collect())])
        }
        Op::Derivative { curve, order, at: None } => {
            let (coords, exact) = float_coords(curve.points());
            exact.then(|| vec![transpose(coords.iter().map(|b| derivative_bounds(b, *order)).collect())])
        }
        Op::ToBezier { power } => {
            let coords: Vec<Vec<f64>> = power
                .iter()
                .map(|c| c.iter().map(exact_f64).collect::<Option<_>>())
                .collect::<Option<_>>()?;
            Some(vec![transpose(to_bezier_bounds(&coords))])
        }
        _ => None,
    }
}

/// How many float operations the bounds of `op` take (for its work estimate).
pub(super) fn float_work(op: &Op) -> f64 {
    match op {
        Op::Split { curve, .. } => {
            let n = curve.points().len() as f64;
            n * n * curve.dim() as f64
        }
        Op::Elevate { curve, by } => {
            let n = curve.points().len() as f64;
            *by as f64 * (n + *by as f64) * curve.dim() as f64
        }
        Op::Derivative { curve, order, .. } => curve.points().len() as f64 * (*order as f64 + 1.0) * curve.dim() as f64,
        Op::ToBezier { power } => {
            let n = power.first().map_or(0, Vec::len) as f64;
            // binomials of every row as big integers, then the weighted sums
            n * n * (n / 8.0 + power.len() as f64)
        }
        _ => 0.0,
    }
}

/// How many coordinates `op`'s exact answer has.
pub(super) fn output_coordinates(op: &Op) -> f64 {
    match op {
        Op::Split { curve, .. } => 2.0 * curve.points().len() as f64 * curve.dim() as f64,
        Op::Elevate { curve, by } => (curve.points().len() + by) as f64 * curve.dim() as f64,
        Op::Derivative { curve, order, .. } => curve.points().len().saturating_sub(*order) as f64 * curve.dim() as f64,
        Op::ToBezier { power } => power.first().map_or(0, Vec::len) as f64 * power.len() as f64,
        _ => 0.0,
    }
}

/// `op` (read from `obj`, limits checked) judged, when the request has `approx` or `method`.
pub(super) fn from_json(op: Op, name: &str, obj: &Map<String, Value>) -> Result<Op> {
    if !obj.contains_key("approx") && !obj.contains_key("method") {
        return Ok(op);
    }
    let method = PointsMethod::parse(name, obj.get("method"))?;
    let shape = match &op {
        Op::Split { curve, .. } => Some((true, curve.points().len(), curve.dim())),
        Op::Elevate { curve, by } => Some((false, curve.points().len() + by, curve.dim())),
        Op::Derivative { at: Some(_), .. } => {
            return Err(Error::Parse(
                "fields 'approx' and 'method' judge the derivative's control points: leave out 't'".into(),
            ))
        }
        // an order above the degree is the exact op's error, when it runs
        Op::Derivative { curve, order, .. } => {
            (*order < curve.points().len()).then(|| (false, curve.points().len() - order, curve.dim()))
        }
        Op::ToBezier { power } => Some((false, power[0].len(), power.len())),
        _ => unreachable!("only ops answering control points are judged"),
    };
    let approx = match (obj.get("approx"), shape) {
        (Some(v), Some((split, count, dim))) => Some(Approx::from_json(v, split, count, dim)?),
        _ => None,
    };
    Ok(Op::Judged {
        op: Box::new(op),
        approx,
        method,
    })
}

/// A list of a point's coordinates' values as JSON, when it has them.
fn per(xs: Option<Vec<Value>>) -> Option<Value> {
    xs.map(Value::Array)
}

/// One judged field of one point, when it has it.
type Field = dyn Fn(&Judgement) -> Option<Value>;

impl JudgedAnswer {
    /// The response fields: the exact answer's, then per coordinate in its shape `ulps`,
    /// `error_ulps`, `nearest` (with `approx`), `bound`, `within_bound` (with `approx`),
    /// `condition` (when the inputs are floats) and `verdict` (when a float is not finite).
    pub fn to_json(&self) -> Map<String, Value> {
        let mut m = self.exact.to_json();
        m.insert("method".into(), json!(self.method.as_str()));
        let field = |get: &Field| -> Option<Value> {
            let mut shaped = Vec::new();
            for (name, points) in &self.groups {
                let values: Option<Vec<Value>> = points.iter().map(get).collect();
                shaped.push((*name, Value::Array(values?)));
            }
            Some(if shaped.len() == 1 {
                shaped.pop().expect("one group").1
            } else {
                Value::Object(shaped.into_iter().map(|(k, v)| (k.to_string(), v)).collect())
            })
        };
        let fields: [(&str, &Field); 6] = [
            ("ulps", &|j| {
                per(j.errors.as_ref().map(|e| e.iter().map(|e| ulps_json(e.ulps)).collect()))
            }),
            ("error_ulps", &|j| {
                per(j
                    .errors
                    .as_ref()
                    .map(|e| e.iter().map(|e| float_json(e.error_ulps)).collect()))
            }),
            ("nearest", &|j| {
                per(j
                    .errors
                    .as_ref()
                    .map(|e| e.iter().map(|e| float_json(e.nearest)).collect()))
            }),
            ("bound", &|j| {
                per(j
                    .bound
                    .as_ref()
                    .map(|b| b.iter().map(|c| float_json(c.bound_ulps)).collect()))
            }),
            ("within_bound", &|j| {
                j.errors.as_ref()?;
                per(j.bound.as_ref().map(|b| b.iter().map(|c| json!(c.within)).collect()))
            }),
            ("condition", &|j| {
                per(j.condition.as_ref().map(|c| c.iter().map(|x| float_json(*x)).collect()))
            }),
        ];
        for (name, get) in fields {
            if let Some(v) = field(get) {
                m.insert(name.into(), v);
            }
        }
        let any_verdict = self
            .groups
            .iter()
            .flat_map(|g| &g.1)
            .flat_map(|j| &j.verdicts)
            .any(Option::is_some);
        if any_verdict {
            if let Some(v) = field(&|j| Some(j.verdicts.iter().map(|v| json!(v)).collect())) {
                m.insert("verdict".into(), v);
            }
        }
        m
    }
}
