//! The Rust half of the conformance survey (docs/peers.md): runs kurbo's and lyon_geom's
//! f64 operations on the cases `scripts/survey.py` sends, and prints their answers for the
//! oracle to judge.
//!
//! Reads JSON lines `{"id", "lib": "kurbo"|"lyon", "op", "points": [[x, y], …], "t"}` on
//! stdin (degree 1–3, planar; `t` absent for `elevate` and `derivative`) and writes one
//! line per case: `{"id", "points": <the points as read>, "approx": <the library's answer>}`,
//! the answer in the shape of the oracle's exact answer (`split`: `{"left", "right"}`).
//! The points are echoed so that the caller can check they were read as the floats it sent.
//!
//! `python3 scripts/survey.py` runs it (`cargo run --release --example peers_survey`).

use std::io::{self, BufRead, BufWriter, Write};

use kurbo::{CubicBez, Line, ParamCurve, ParamCurveDeriv, Point, QuadBez};
use lyon_geom::{point, CubicBezierSegment, LineSegment, QuadraticBezierSegment};
use serde_json::{json, Value};

type P = [f64; 2];

fn kp(p: P) -> Point {
    Point::new(p[0], p[1])
}

fn from_k(p: Point) -> P {
    [p.x, p.y]
}

fn lp(p: P) -> lyon_geom::Point<f64> {
    point(p[0], p[1])
}

fn from_l(p: lyon_geom::Point<f64>) -> P {
    [p.x, p.y]
}

fn split_answer(left: Vec<P>, right: Vec<P>) -> Value {
    json!({ "left": left, "right": right })
}

/// kurbo: `eval`, `subdivide` (at 1/2), `subsegment` (`split` at t: 0..t and t..1),
/// `QuadBez::raise` (`elevate`), `deriv` (`derivative`, control points).
fn kurbo(op: &str, b: &[P], t: f64) -> Result<Value, String> {
    macro_rules! on_curve {
        ($c:expr, $pts:expr) => {{
            let c = $c;
            match op {
                "eval" => Ok(json!(from_k(c.eval(t)))),
                "subdivide" => {
                    let (l, r) = c.subdivide();
                    Ok(split_answer($pts(&l), $pts(&r)))
                }
                "split" => Ok(split_answer($pts(&c.subsegment(0.0..t)), $pts(&c.subsegment(t..1.0)))),
                _ => Err(format!("kurbo has no {op} here")),
            }
        }};
    }
    match (b.len(), op) {
        (3, "elevate") => {
            let c = QuadBez::new(kp(b[0]), kp(b[1]), kp(b[2])).raise();
            Ok(json!([c.p0, c.p1, c.p2, c.p3].map(from_k)))
        }
        (3, "derivative") => {
            let d = QuadBez::new(kp(b[0]), kp(b[1]), kp(b[2])).deriv();
            Ok(json!([d.p0, d.p1].map(from_k)))
        }
        (4, "derivative") => {
            let d = CubicBez::new(kp(b[0]), kp(b[1]), kp(b[2]), kp(b[3])).deriv();
            Ok(json!([d.p0, d.p1, d.p2].map(from_k)))
        }
        (2, _) => on_curve!(Line::new(kp(b[0]), kp(b[1])), |l: &Line| vec![
            from_k(l.p0),
            from_k(l.p1)
        ]),
        (3, _) => on_curve!(QuadBez::new(kp(b[0]), kp(b[1]), kp(b[2])), |q: &QuadBez| vec![
            from_k(q.p0),
            from_k(q.p1),
            from_k(q.p2)
        ]),
        (4, _) => on_curve!(
            CubicBez::new(kp(b[0]), kp(b[1]), kp(b[2]), kp(b[3])),
            |c: &CubicBez| vec![from_k(c.p0), from_k(c.p1), from_k(c.p2), from_k(c.p3)]
        ),
        (n, _) => Err(format!("kurbo has no curve of {n} points")),
    }
}

/// lyon_geom: `sample` (`eval`), `split` at t, `QuadraticBezierSegment::to_cubic`
/// (`elevate`), `derivative(t)` (`derivative_at`, the vector at t).
fn lyon(op: &str, b: &[P], t: f64) -> Result<Value, String> {
    match b.len() {
        2 => {
            let c = LineSegment {
                from: lp(b[0]),
                to: lp(b[1]),
            };
            match op {
                "eval" => Ok(json!(from_l(c.sample(t)))),
                "split" => {
                    let (l, r) = c.split(t);
                    Ok(split_answer(
                        vec![from_l(l.from), from_l(l.to)],
                        vec![from_l(r.from), from_l(r.to)],
                    ))
                }
                _ => Err(format!("lyon has no line {op} here")),
            }
        }
        3 => {
            let c = QuadraticBezierSegment {
                from: lp(b[0]),
                ctrl: lp(b[1]),
                to: lp(b[2]),
            };
            let pts = |q: &QuadraticBezierSegment<f64>| vec![from_l(q.from), from_l(q.ctrl), from_l(q.to)];
            match op {
                "eval" => Ok(json!(from_l(c.sample(t)))),
                "split" => {
                    let (l, r) = c.split(t);
                    Ok(split_answer(pts(&l), pts(&r)))
                }
                "elevate" => {
                    let e = c.to_cubic();
                    Ok(json!([e.from, e.ctrl1, e.ctrl2, e.to].map(from_l)))
                }
                "derivative_at" => {
                    let v = c.derivative(t);
                    Ok(json!([v.x, v.y]))
                }
                _ => Err(format!("lyon has no quadratic {op}")),
            }
        }
        4 => {
            let c = CubicBezierSegment {
                from: lp(b[0]),
                ctrl1: lp(b[1]),
                ctrl2: lp(b[2]),
                to: lp(b[3]),
            };
            let pts =
                |q: &CubicBezierSegment<f64>| vec![from_l(q.from), from_l(q.ctrl1), from_l(q.ctrl2), from_l(q.to)];
            match op {
                "eval" => Ok(json!(from_l(c.sample(t)))),
                "split" => {
                    let (l, r) = c.split(t);
                    Ok(split_answer(pts(&l), pts(&r)))
                }
                "derivative_at" => {
                    let v = c.derivative(t);
                    Ok(json!([v.x, v.y]))
                }
                _ => Err(format!("lyon has no cubic {op}")),
            }
        }
        n => Err(format!("lyon has no curve of {n} points")),
    }
}

fn answer(case: &Value) -> Result<Value, String> {
    let field = |k: &str| case.get(k).ok_or_else(|| format!("no field {k}"));
    let points: Vec<P> = serde_json::from_value(field("points")?.clone()).map_err(|e| e.to_string())?;
    let t = case.get("t").and_then(Value::as_f64).unwrap_or(f64::NAN);
    let op = field("op")?.as_str().ok_or("op is a string")?;
    let approx = match field("lib")?.as_str() {
        Some("kurbo") => kurbo(op, &points, t)?,
        Some("lyon") => lyon(op, &points, t)?,
        other => return Err(format!("unknown lib {other:?}")),
    };
    Ok(json!({ "id": field("id")?, "points": points, "approx": approx }))
}

fn main() -> io::Result<()> {
    let stdin = io::stdin();
    let mut out = BufWriter::new(io::stdout().lock());
    for line in stdin.lock().lines() {
        let line = line?;
        let reply = match serde_json::from_str::<Value>(&line) {
            Ok(case) => answer(&case).unwrap_or_else(|e| json!({ "id": case.get("id"), "error": e })),
            Err(e) => json!({ "error": e.to_string() }),
        };
        writeln!(out, "{reply}")?;
    }
    out.flush()
}
