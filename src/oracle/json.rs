//! Reading requests: JSON fields into exact inputs, with errors that name the field.

use super::judge::{floats_from_json, not_a_float, FloatMethod};
use super::values::{
    count_from_json, describe, net_from_json, number_from_json, numbers_from_json, point_from_json, points_from_json,
};
use super::values::{too_large, truncate};
use super::{check_weight_count, Op, MAX_POINTS, MAX_REQUEST_DIMENSION, OPS};
use crate::curve::BezierCurve;
use crate::error::{Error, Result};
use crate::fit::CubicFitData;
use crate::float::exact_f64;
use crate::input::in_context;
use crate::rational::RationalBezierCurve;
use crate::surface::BezierSurface;
use num_rational::BigRational;
use serde_json::{Map, Value};

impl Op {
    /// Parses a request object (its `op` and fields; `id` is allowed and ignored).
    pub fn from_json(request: &Value) -> Result<Op> {
        let obj = request
            .as_object()
            .ok_or_else(|| Error::Parse(format!("a request must be a JSON object, got {}", describe(request))))?;
        let op = match obj.get("op") {
            Some(Value::String(s)) => s.as_str(),
            Some(other) => {
                return Err(Error::Parse(format!(
                    "field 'op' must be a string, got {}",
                    describe(other)
                )))
            }
            None => return Err(Error::Parse(format!("missing field 'op' (one of {})", OPS.join(", ")))),
        };
        let batch = obj.get("t").is_some_and(Value::is_array);
        match op {
            "eval" if batch || obj.contains_key("method") || super::batch::has_string(obj.get("approx")) => {
                return super::batch::eval_judged(obj)
            }
            "float_eval" if batch => return super::batch::float_eval_batch(obj),
            _ => {}
        }
        let fields: &[&str] = match op {
            "eval" => &["points", "t", "approx"],
            "elevate" => &["points", "by", "approx", "method"],
            "split" => &["points", "t", "approx", "method"],
            "derivative" => &["points", "order", "t", "approx", "method"],
            "to_bezier" => &["power", "approx", "method"],
            "rational_eval" => &["points", "weights", "t", "approx"],
            "conic" => &["points", "weights"],
            "surface_eval" => &["net", "u", "v", "approx"],
            "fit_cubic" => &["x0", "x1", "xh", "d0", "d1"],
            "float_eval" => &["points", "t", "method"],
            other => {
                return Err(Error::Parse(format!(
                    "unknown op {:?} (known ops: {})",
                    truncate(other),
                    OPS.join(", ")
                )))
            }
        };
        if let Some(k) = obj
            .keys()
            .find(|k| *k != "op" && *k != "id" && !fields.contains(&k.as_str()))
        {
            return Err(Error::Parse(format!(
                "unknown field {:?} for op '{op}' (its fields: {})",
                truncate(k),
                fields.join(", ")
            )));
        }
        if op == "split" && batch {
            return super::batch::split_batch(obj);
        }
        let req = Fields { obj, op };
        let name = op;
        let op = match op {
            "eval" => Op::Eval {
                curve: req.curve("points")?,
                t: req.number("t")?,
                approx: req.approx(true)?,
            },
            "elevate" => Op::Elevate {
                curve: req.curve("points")?,
                by: req.in_field("by", count_from_json(req.get("by")?, "by"))?,
            },
            "split" => Op::Split {
                curve: req.curve("points")?,
                t: req.number("t")?,
            },
            "derivative" => Op::Derivative {
                curve: req.curve("points")?,
                order: req.in_field("order", count_from_json(req.get("order")?, "order"))?,
                at: match obj.get("t") {
                    None => None,
                    Some(v) => Some(req.in_field("t", number_from_json(v))?),
                },
            },
            "to_bezier" => {
                let v = req.get("power")?;
                let coords = v.as_array().ok_or_else(|| {
                    Error::Parse(format!(
                        "field 'power': expected an array with one array of coefficients per coordinate, got {}",
                        describe(v)
                    ))
                })?;
                if coords.len() > MAX_REQUEST_DIMENSION {
                    return Err(too_large("dimension", coords.len(), MAX_REQUEST_DIMENSION));
                }
                Op::ToBezier {
                    power: coords
                        .iter()
                        .enumerate()
                        .map(|(k, c)| {
                            numbers_from_json(c, MAX_POINTS)
                                .map_err(|e| in_context(&format!("field 'power': coordinate {k}"), e))
                        })
                        .collect::<Result<_>>()?,
                }
            }
            "rational_eval" => Op::RationalEval {
                curve: req.rational_curve()?,
                t: req.number("t")?,
                approx: req.approx(false)?,
            },
            "conic" => Op::Conic {
                curve: req.rational_curve()?,
            },
            "surface_eval" => {
                let net = req.in_field("net", net_from_json(req.get("net")?, MAX_POINTS))?;
                if net[0][0].dim() > MAX_REQUEST_DIMENSION {
                    return Err(too_large("dimension", net[0][0].dim(), MAX_REQUEST_DIMENSION));
                }
                Op::SurfaceEval {
                    surface: req.in_field("net", BezierSurface::new(net))?,
                    u: req.number("u")?,
                    v: req.number("v")?,
                    approx: req.approx(false)?,
                }
            }
            "fit_cubic" => {
                let point = |name: &str| req.in_field(name, point_from_json(req.get(name)?));
                Op::FitCubic {
                    data: CubicFitData::new(point("x0")?, point("x1")?, point("xh")?, point("d0")?, point("d1")?)?,
                }
            }
            "float_eval" => {
                let curve = req.curve("points")?;
                let t = req.number("t")?;
                if exact_f64(&t).is_none() {
                    return Err(not_a_float("t", &t));
                }
                if let Some(x) = curve
                    .points()
                    .iter()
                    .flat_map(|p| p.coords())
                    .find(|x| exact_f64(x).is_none())
                {
                    return Err(not_a_float("points", x));
                }
                let method = match obj.get("method") {
                    None => FloatMethod::Compensated,
                    Some(Value::String(s)) => req.in_field("method", FloatMethod::parse(s))?,
                    Some(other) => {
                        return Err(Error::Parse(format!(
                            "field 'method' must be a string (de_casteljau, lerp, horner, bernstein, compensated or interval), got {}",
                            describe(other)
                        )))
                    }
                };
                Op::FloatEval { curve, t, method }
            }
            _ => unreachable!("op names were matched above"),
        };
        op.check_limits()?;
        if matches!(name, "split" | "elevate" | "derivative" | "to_bezier") {
            let judged = super::judged::from_json(op, name, obj)?;
            if matches!(judged, Op::Judged { .. }) {
                judged.check_limits()?;
            }
            return Ok(judged);
        }
        Ok(op)
    }
}

struct Fields<'a> {
    obj: &'a Map<String, Value>,
    op: &'a str,
}

impl Fields<'_> {
    fn get(&self, name: &str) -> Result<&Value> {
        self.obj
            .get(name)
            .ok_or_else(|| Error::Parse(format!("op '{}' needs the field '{name}'", self.op)))
    }

    fn in_field<T>(&self, name: &str, r: Result<T>) -> Result<T> {
        r.map_err(|e| in_context(&format!("field '{name}'"), e))
    }

    fn number(&self, name: &str) -> Result<BigRational> {
        self.in_field(name, number_from_json(self.get(name)?))
    }

    /// `approx`: JSON numbers, and for `eval` (`overflow`) also `"inf"`, `"-inf"`, `"nan"`.
    fn approx(&self, overflow: bool) -> Result<Option<Vec<f64>>> {
        match self.obj.get("approx") {
            None => Ok(None),
            Some(v) => Ok(Some(self.in_field("approx", floats_from_json(v, overflow))?)),
        }
    }

    fn rational_curve(&self) -> Result<RationalBezierCurve<BigRational>> {
        let points = self.in_field("points", points_from_json(self.get("points")?, MAX_POINTS))?;
        if points[0].dim() > MAX_REQUEST_DIMENSION {
            return Err(too_large("dimension", points[0].dim(), MAX_REQUEST_DIMENSION));
        }
        let weights = self.in_field("weights", numbers_from_json(self.get("weights")?, MAX_POINTS))?;
        check_weight_count(points.len(), weights.len())?;
        RationalBezierCurve::new(points, weights)
    }

    fn curve(&self, name: &str) -> Result<BezierCurve<BigRational>> {
        let points = self.in_field(name, points_from_json(self.get(name)?, MAX_POINTS))?;
        if points[0].dim() > MAX_REQUEST_DIMENSION {
            return Err(too_large("dimension", points[0].dim(), MAX_REQUEST_DIMENSION));
        }
        self.in_field(name, BezierCurve::new(points))
    }
}

/// Refuses a request object that gives a field twice: JSON parsers disagree on which copy
/// counts (serde_json keeps the last), so the oracle takes neither. Only the request's own
/// fields are checked; a line that is not an object is left to the parser's error.
pub(super) fn check_unique_fields(line: &str) -> Result<()> {
    struct UniqueKeys;
    impl<'de> serde::de::Visitor<'de> for UniqueKeys {
        type Value = Option<String>;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("a request object")
        }
        fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> std::result::Result<Self::Value, A::Error> {
            let mut seen = std::collections::HashSet::new();
            let mut repeated = None;
            while let Some(key) = map.next_key::<std::borrow::Cow<'de, str>>()? {
                map.next_value::<serde::de::IgnoredAny>()?;
                if repeated.is_none() && !seen.insert(key.clone().into_owned()) {
                    repeated = Some(key.into_owned());
                }
            }
            Ok(repeated)
        }
    }
    struct Keys(Option<String>);
    impl<'de> serde::Deserialize<'de> for Keys {
        fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
            d.deserialize_map(UniqueKeys).map(Keys)
        }
    }
    match serde_json::from_str::<Keys>(line) {
        Ok(Keys(Some(key))) => Err(Error::Parse(format!(
            "field {:?} given twice (give each field once)",
            truncate(&key)
        ))),
        _ => Ok(()),
    }
}
