//! The oracle against hostile inputs (issue 41): no `null` and no NaN bound in any answer, an
//! exact answer within every bound, one answer shape and one wording per request whichever
//! path reads it, enclosures that enclose and are as narrow as de Casteljau's own bound, and
//! work estimates that neither fall when a cheaper kind of number joins nor run long before
//! refusing a batch.

use casteljau::oracle::{handle_line, nearest_f64};
use casteljau::{parse_exact, BigRational};
use proptest::prelude::*;
use serde_json::{json, Value};
use std::time::{Duration, Instant};

fn ask(line: &str) -> Value {
    serde_json::from_str(&handle_line(line)).unwrap()
}

const MAX: f64 = f64::MAX;

/// Every `null` in an answer, and every `"nan"` under a bound's key, by path.
fn faults(v: &Value, path: &str, out: &mut Vec<String>) {
    match v {
        Value::Null => out.push(format!("{path}: null")),
        Value::Array(items) => {
            for (k, x) in items.iter().enumerate() {
                faults(x, &format!("{path}[{k}]"), out);
            }
        }
        Value::Object(m) => {
            for (k, x) in m {
                if k.ends_with("bound") && x.to_string().contains("\"nan\"") {
                    out.push(format!("{path}.{k}: {x}"));
                }
                if k == "interval" && x.to_string().contains("\"nan\"") {
                    out.push(format!("{path}.{k}: {x}"));
                }
                faults(x, &format!("{path}.{k}"), out);
            }
        }
        _ => {}
    }
}

fn endpoint(v: &Value) -> Option<BigRational> {
    match v {
        Value::Number(n) => BigRational::from_float(n.as_f64().unwrap()),
        _ => None,
    }
}

/// Checks one answer object (a request's, or one of a batch's `results`).
fn check_answer(r: &Value, request: &str) {
    let mut found = Vec::new();
    faults(r, "", &mut found);
    assert!(found.is_empty(), "{request}\n -> {r}\n{found:?}");
    let Some(point) = r["point"].as_array() else { return };
    let exact: Vec<BigRational> = point
        .iter()
        .map(|c| parse_exact(c.as_str().unwrap()).unwrap())
        .collect();
    // an answer without error is within every bound
    for (key, within) in [("bound", "within_bound"), ("running_bound", "within_running_bound")] {
        if let (Some(e), Some(w)) = (r["error_ulps"].as_array(), r[within].as_array()) {
            for (k, e) in e.iter().enumerate() {
                if e.as_f64() == Some(0.0) {
                    assert_eq!(w[k], json!(true), "{request}\n -> {r}: {key}");
                }
            }
        }
    }
    if let Some(iv) = r["interval"].as_array() {
        for (k, pair) in iv.iter().enumerate() {
            let (lo, hi) = (&pair[0], &pair[1]);
            let above = lo == &json!("-inf") || endpoint(lo).is_some_and(|l| l <= exact[k]);
            let below = hi == &json!("inf") || endpoint(hi).is_some_and(|h| exact[k] <= h);
            assert_eq!(r["encloses"][k], json!(above && below), "{request}\n -> {r}");
            assert!(above && below, "not an enclosure: {request}\n -> {r}");
        }
    }
}

fn check(request: &Value) {
    let line = request.to_string();
    let r = ask(&line);
    if let Some(results) = r["results"].as_array() {
        results.iter().for_each(|x| check_answer(x, &line));
    } else {
        check_answer(&r, &line);
    }
}

const METHODS: &[&str] = &["de_casteljau", "lerp", "horner", "bernstein", "compensated"];

#[test]
fn interval_at_huge_parameters_names_its_infinities() {
    let r = ask(r#"{"op":"float_eval","points":[[0.1],[0.2],[0.7]],"t":1e308,"method":"interval"}"#);
    assert_eq!(r["ok"], json!(true), "{r}");
    assert_eq!(r["interval"], json!([[MAX, "inf"]]), "{r}");
    assert_eq!(r["value"], json!(["inf"]), "{r}");
    assert_eq!(r["within_bound"], json!([true]), "{r}");
    assert_eq!(r["encloses"], json!([true]));
    assert_eq!(r["bound"], json!(["inf"]));
    assert!(!r.to_string().contains("null"), "{r}");
}

#[test]
fn exact_answers_are_within_their_bounds_near_the_largest_float() {
    let points = json!([[0.5], [MAX], [MAX]]);
    for m in METHODS {
        let r = ask(&json!({"op": "eval", "points": points, "t": 0, "approx": [0.5], "method": m}).to_string());
        assert_eq!(r["error_ulps"], json!([0.0]), "{m}: {r}");
        assert_eq!(r["within_bound"], json!([true]), "{m}: {r}");
        assert_ne!(r["bound"], json!(["nan"]), "{m}: {r}");
        let r = ask(
            &json!({"op": "eval", "points": points, "t": [0, 0], "approx": [[0.5], [0.5]], "method": m}).to_string(),
        );
        for x in r["results"].as_array().unwrap() {
            assert_eq!(x["within_bound"], json!([true]), "{m}: {r}");
        }
        let mut all = vec!["interval"];
        all.extend_from_slice(METHODS);
        for m in &all {
            check(&json!({"op": "float_eval", "points": points, "t": 0, "method": m}));
        }
    }
}

/// Hostile floats: the largest, subnormals, zeros of both signs, and ordinary ones.
fn hostile() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => -1.0f64..1.0,
        1 => Just(MAX),
        1 => Just(-MAX),
        1 => Just(1e308),
        1 => Just(-1e308),
        1 => Just(5e-324),
        1 => Just(-1e-310),
        1 => Just(0.0),
        1 => Just(-0.0),
        1 => Just(2.0),
        1 => Just(1e200),
        1 => -1e300f64..1e300,
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// No `null`, no NaN bound, no exact answer outside its bound, and every interval an
    /// enclosure of the exact value, for every method at hostile points and parameters.
    #[test]
    fn hostile_floats_get_sane_answers(
        points in prop::collection::vec(hostile(), 1..6),
        t in hostile(),
        method in prop::sample::select(vec!["interval", "de_casteljau", "lerp", "horner", "bernstein", "compensated"]),
    ) {
        let points: Vec<Value> = points.iter().map(|x| json!([x])).collect();
        check(&json!({"op": "float_eval", "points": points, "t": t, "method": method}));
        check(&json!({"op": "float_eval", "points": points, "t": [t, 0.5], "method": method}));
        if method != "interval" {
            check(&json!({"op": "eval", "points": points, "t": t, "method": method}));
        }
    }
}

#[test]
fn eval_answers_one_shape_and_one_wording() {
    // the same request with a number and with a string in `approx`: the same fields
    let number = ask(r#"{"op":"eval","points":[[0.1],[0.2]],"t":0.5,"approx":[0.15]}"#);
    let string = ask(r#"{"op":"eval","points":[[0.1],[0.2]],"t":0.5,"approx":["inf"]}"#);
    let keys = |v: &Value| {
        let mut k: Vec<String> = v
            .as_object()
            .unwrap()
            .keys()
            .filter(|k| *k != "verdict")
            .cloned()
            .collect();
        k.sort();
        k
    };
    assert_eq!(keys(&number), keys(&string), "{number}\n{string}");
    // the same fault read by either path: the same words
    let general = ask(r#"{"op":"eval","points":[[0.1,1],[0.2,1]],"t":0.5,"approx":[null,1]}"#);
    let judged = ask(r#"{"op":"eval","points":[[0.1,1],[0.2,1]],"t":0.5,"approx":[null,"inf"]}"#);
    assert_eq!(general["error"], judged["error"], "{general}\n{judged}");
    // `inf` where the exact value is beyond the largest float is correctly rounded: within
    let r = ask(r#"{"op":"eval","points":[[0],[1.7976931348623157e308]],"t":2,"approx":["inf"]}"#);
    assert_eq!(r["ulps"], json!([0]), "{r}");
    assert_eq!(r["within_bound"], json!([true]), "{r}");
}

fn refused_quickly(line: &str, limit: Duration) -> Value {
    let start = Instant::now();
    let r = ask(line);
    let took = start.elapsed();
    assert!(
        took < limit,
        "took {took:?}: {}",
        &r.to_string()[..200.min(r.to_string().len())]
    );
    r
}

/// 40-digit integers, 64-D, `n + 1` points; `decimal` puts one `"0.1"` among them.
fn wide_integers(n: usize, decimal: bool) -> Vec<Vec<String>> {
    let mut x: u64 = 1;
    let mut digits = || {
        (0..40)
            .map(|_| {
                x = x.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                char::from(b'1' + ((x >> 33) % 9) as u8)
            })
            .collect::<String>()
    };
    let mut pts: Vec<Vec<String>> = (0..=n).map(|_| (0..64).map(|_| digits()).collect()).collect();
    if decimal {
        pts[0][0] = "0.1".into();
    }
    pts
}

#[test]
fn a_cheaper_kind_of_number_does_not_make_a_request_cheap() {
    // issue 41's N2b: admitted with the decimals' calibration, > 18 s of CPU
    for decimal in [false, true] {
        let line = json!({"op": "elevate", "points": wide_integers(100, decimal), "by": 3996}).to_string();
        let r = refused_quickly(&line, Duration::from_secs(1));
        assert_eq!(r["ok"], json!(false), "{decimal}");
        assert!(r["error"].as_str().unwrap().contains("estimated exact work"), "{r}");
    }
    // fractions with an integer among them are charged as the integers
    let pts: Vec<Vec<String>> = wide_integers(100, false)
        .into_iter()
        .enumerate()
        .map(|(i, p)| {
            p.into_iter()
                .map(|c| if i == 0 { "1/3".to_string() } else { c })
                .collect()
        })
        .collect();
    let r = refused_quickly(
        &json!({"op": "elevate", "points": pts, "by": 3996}).to_string(),
        Duration::from_secs(1),
    );
    assert_eq!(r["ok"], json!(false), "{r}");
}

#[test]
fn a_batch_beyond_the_limit_is_refused_at_once() {
    // issue 41's N15: 4,097 64-D points at 4,096 parameters 0, refused after > 54 s
    let pts: Vec<Vec<u32>> = (0..4097).map(|i| (0..64).map(|k| (i * 7 + k) % 10).collect()).collect();
    let line = json!({"op": "eval", "points": pts, "t": vec![0; 4096]}).to_string();
    let r = refused_quickly(&line, Duration::from_secs(1));
    assert!(r["error"].as_str().unwrap().contains("batch"), "{r}");
    // distinct parameters: the sum is compared as it grows
    let ts: Vec<f64> = (0..4096).map(|k| k as f64 / 4096.0).collect();
    let line = json!({"op": "eval", "points": pts, "t": ts}).to_string();
    let r = refused_quickly(&line, Duration::from_secs(1));
    assert!(r["error"].as_str().unwrap().contains("batch"), "{r}");
}

#[test]
fn a_batch_is_charged_for_its_answers() {
    // issue 41's N16: 301 planar one-digit points at 4,096 parameters 1/3 were admitted and
    // took 0.6–1.1 s of CPU
    let pts: Vec<Vec<u32>> = (0..301).map(|i| vec![(i * 7) % 10, (i * 3) % 10]).collect();
    let line = json!({"op": "eval", "points": pts, "t": vec!["1/3"; 4096]}).to_string();
    let r = refused_quickly(&line, Duration::from_secs(1));
    assert_eq!(r["ok"], json!(false), "{}", &r.to_string()[..200]);
}

/// Random floats in [-1, 1], from a seed.
fn coefficients(seed: u64, n: usize) -> Vec<f64> {
    let mut x = seed;
    (0..=n)
        .map(|_| {
            x = x.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((x >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        })
        .collect()
}

#[test]
fn interval_enclosures_are_as_narrow_as_de_casteljaus_bound() {
    // issue 41: 9.3e8 ulps wide at degree 20, t = 0.9, and 3.3e44 at degree 100
    for (seed, n) in (0..40).map(|s| (s, [3, 20, 50, 100][s as usize % 4])) {
        for t in [0.1, 0.5, 0.9, 0.3333333333333333, 0.999] {
            let b = coefficients(seed, n);
            let points: Vec<Value> = b.iter().map(|x| json!([x])).collect();
            let req = json!({"op": "float_eval", "points": points, "t": t, "method": "interval"});
            let r = ask(&req.to_string());
            check_answer(&r, &req.to_string());
            let dc = ask(&json!({"op": "float_eval", "points": points, "t": t, "method": "de_casteljau"}).to_string());
            let (reach, a_priori) = (r["bound"][0].as_f64().unwrap(), dc["bound"][0].as_f64().unwrap());
            assert!(
                reach <= 100.0 * a_priori,
                "degree {n}, t = {t}: the enclosure reaches {reach} ulps, de Casteljau's bound is {a_priori}"
            );
        }
    }
}

/// The answer of a single request without `ok` and `id`: what a batch lists per parameter.
fn fields_of(line: &str) -> Value {
    let mut v = ask(line);
    assert_eq!(v["ok"], json!(true), "{line} -> {v}");
    let m = v.as_object_mut().unwrap();
    m.remove("ok");
    m.remove("id");
    v
}

/// A batch is its single requests, one per parameter: each of its `results` is byte for
/// byte the answer to the request at that parameter alone (with that parameter's `approx`),
/// for every op and method that takes `"t": [..]`.
#[test]
fn a_batch_answers_as_its_single_requests_one_by_one() {
    let points = json!([[0.1, -2.5], [0.7, 1e-3], [-0.3, 4.0], [1.0, 0.25]]);
    // floats, an end point, a non-float fraction (no bound), a parameter outside [0, 1]
    let ts = [json!(0.1), json!(0), json!(0.75), json!("1/3"), json!(1.5)];
    let floats_only = &ts[..3];
    let point_approx = |t: &Value| -> Value {
        let r = ask(&json!({"op": "eval", "points": points, "t": t}).to_string());
        let p: Vec<f64> = r["point"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| nearest_f64(&parse_exact(c.as_str().unwrap()).unwrap()) * (1.0 + 3e-16))
            .collect();
        json!(p)
    };
    let split_approx = |t: &Value| -> Value {
        let r = ask(&json!({"op": "split", "points": points, "t": t}).to_string());
        let moved = |side: &Value| -> Value {
            side.as_array()
                .unwrap()
                .iter()
                .map(|p| {
                    p.as_array()
                        .unwrap()
                        .iter()
                        .map(|c| json!(nearest_f64(&parse_exact(c.as_str().unwrap()).unwrap()) * (1.0 - 5e-16)))
                        .collect::<Value>()
                })
                .collect()
        };
        json!({"left": moved(&r["left"]), "right": moved(&r["right"])})
    };
    let mut checked = 0;
    let mut check = |base: Value, ts: &[Value], approx: Option<&dyn Fn(&Value) -> Value>| {
        let mut batch = base.clone();
        batch["t"] = json!(ts);
        if let Some(a) = approx {
            batch["approx"] = ts.iter().map(a).collect();
        }
        let batch = batch.to_string();
        let r = ask(&batch);
        assert_eq!(r["ok"], json!(true), "{batch} -> {r}");
        let results = r["results"].as_array().unwrap();
        assert_eq!(results.len(), ts.len(), "{batch}");
        for (k, t) in ts.iter().enumerate() {
            let mut single = base.clone();
            single["t"] = t.clone();
            if let Some(a) = approx {
                single["approx"] = a(t);
            }
            let single = single.to_string();
            assert_eq!(
                serde_json::to_string(&results[k]).unwrap(),
                serde_json::to_string(&fields_of(&single)).unwrap(),
                "parameter {k} of {batch} vs {single}"
            );
            checked += 1;
        }
    };
    for method in ["de_casteljau", "lerp", "horner", "bernstein", "compensated"] {
        let base = json!({"op": "eval", "points": points, "method": method});
        check(base.clone(), &ts, None);
        check(base, &ts, Some(&point_approx));
    }
    // without a method: with an approximation as plain `eval` answers it
    check(json!({"op": "eval", "points": points}), &ts, Some(&point_approx));
    for method in ["de_casteljau", "lerp", "horner", "bernstein", "compensated", "interval"] {
        check(
            json!({"op": "float_eval", "points": points, "method": method}),
            floats_only,
            None,
        );
    }
    check(json!({"op": "float_eval", "points": points}), floats_only, None);
    check(json!({"op": "split", "points": points}), &ts, None);
    for method in ["de_casteljau", "lerp"] {
        let base = json!({"op": "split", "points": points, "method": method});
        check(base.clone(), &ts, None);
        check(base, &ts, Some(&split_approx));
    }
    check(json!({"op": "split", "points": points}), &ts, Some(&split_approx));
    assert_eq!(checked, 11 * 5 + 7 * 3 + 6 * 5);
    // an `eval` batch without approximations gives the bound and condition of plain de
    // Casteljau: the single request naming it, without the method's name
    let batch = ask(&json!({"op": "eval", "points": points, "t": ts}).to_string());
    for (k, t) in ts.iter().enumerate() {
        let mut single =
            fields_of(&json!({"op": "eval", "points": points, "t": t, "method": "de_casteljau"}).to_string());
        single.as_object_mut().unwrap().remove("method");
        assert_eq!(batch["results"][k], single, "parameter {k}");
        assert_eq!(batch["results"][k].get("bound").is_some(), k != 3, "parameter {k}");
    }
}
