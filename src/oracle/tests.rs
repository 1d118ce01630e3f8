use super::values::number_to_json;
use super::*;
use crate::curve::BezierCurve;
use crate::scalar::parse_exact;
use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::prelude::*;
use std::io;

fn ask(line: &str) -> Value {
    serde_json::from_str(&handle_line(line)).unwrap()
}

fn q(s: &str) -> BigRational {
    parse_exact(s).unwrap()
}

#[test]
fn ulps_of_a_value_beyond_the_f64_range_is_a_clear_error() {
    let r = ask(r#"{"id":3,"op":"eval","points":[["1e400"]],"t":0,"approx":[1e308]}"#);
    assert_eq!(r["ok"], json!(false), "{r}");
    assert!(r["error"].as_str().unwrap().contains("beyond the largest f64"), "{r}");
    // Just inside the range it is measured.
    let r = ask(r#"{"op":"eval","points":[["1e308"]],"t":0,"approx":[1e308]}"#);
    assert_eq!(r["ulps"], json!([0]), "{r}");
}

#[test]
fn eval_judges_the_callers_float_against_the_a_priori_bound() {
    // fl(fl(0.5·0.1) + fl(0.5·0.7)) = 0.39999999999999997 vs exact 0.4 + tiny: within
    let r = ask(r#"{"op":"eval","points":[[0.1],[0.7]],"t":0.5,"approx":[0.39999999999999997]}"#);
    assert_eq!(r["within_bound"], json!([true]), "{r}");
    let b = r["bound"][0].as_f64().unwrap();
    assert!(b > 0.0 && b < 3.0, "{r}");
    // 5 ulps off is beyond the bound of a degree-1 evaluation
    let r = ask(r#"{"op":"eval","points":[[0.1],[0.7]],"t":0.5,"approx":[0.4000000000000002]}"#);
    assert_eq!(r["within_bound"], json!([false]), "{r}");
    // a parameter that is no float: no bound
    let r = ask(r#"{"op":"eval","points":[[0.1],[0.7]],"t":"1/3","approx":[0.3]}"#);
    assert!(r.get("bound").is_none() && r["ok"] == json!(true), "{r}");
    let r = ask(r#"{"op":"rational_eval","points":[[1,0],[1,1],[0,1]],"weights":[1,1,2],"t":0.5,"approx":[0.6,0.8]}"#);
    assert_eq!(r["within_bound"], json!([true, true]), "{r}");
    let r = ask(
        r#"{"op":"surface_eval","net":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]],"u":0.1,"v":0.7,"approx":[0.1,0.7,0.07]}"#,
    );
    assert_eq!(r["within_bound"], json!([true, true, true]), "{r}");
}

#[test]
fn float_eval_runs_each_method_and_judges_it() {
    let pts = r#"[[-0.421875],[0.140625],[-0.046875],[0.015625]]"#;
    for method in ["de_casteljau", "compensated", "interval"] {
        let r = ask(&format!(
            r#"{{"op":"float_eval","points":{pts},"t":0.7500001,"method":"{method}"}}"#
        ));
        assert_eq!(r["ok"], json!(true), "{r}");
        assert_eq!(r["within_bound"], json!([true]), "{method}: {r}");
        if method == "compensated" {
            assert!(r["error_ulps"][0].as_f64().unwrap() < 1000.0, "{r}");
        }
        if method == "de_casteljau" {
            assert!(r["error_ulps"][0].as_f64().unwrap() > 1000.0, "{r}");
            assert_eq!(r["within_running_bound"], json!([true]), "{r}");
        }
        if method == "interval" {
            assert_eq!(r["encloses"], json!([true]), "{r}");
        }
    }
    let r = ask(r#"{"op":"float_eval","points":[[0],[1]],"t":"1/3"}"#);
    assert!(r["error"].as_str().unwrap().contains("must be a float"), "{r}");
    let r = ask(r#"{"op":"float_eval","points":[[0],["0.1"]],"t":0.5}"#);
    assert!(r["error"].as_str().unwrap().contains("must be a float"), "{r}");
    let r = ask(r#"{"op":"float_eval","points":[[0],[1]],"t":0.5,"method":"bogus"}"#);
    assert!(r["error"].as_str().unwrap().contains("unknown method"), "{r}");
}

#[test]
fn encodings_never_lose_information() {
    // an error beyond the f64 range of ulps is the string "inf", never null
    let r = ask(r#"{"op":"eval","points":[[0]],"t":0,"approx":[1e-15]}"#);
    assert_eq!(r["error_ulps"], json!(["inf"]), "{r}");
    assert_eq!(r["ulps"], json!([1e-15f64.to_bits().to_string()]), "{r}");
    assert_eq!(r["bound"], json!([0.0]), "{r}");
    // ids are echoed verbatim, big integers included
    let line = r#"{"id":123456789012345678901234567890,"op":"eval","points":[[1]],"t":0}"#;
    assert_eq!(
        handle_line(line),
        r#"{"id":123456789012345678901234567890,"ok":true,"point":["1"]}"#
    );
    let line = r#"{"id":[0.1, 1e400],"op":"eval","points":[[1]],"t":0}"#;
    assert!(handle_line(line).contains("not valid JSON"));
    let line = r#"{"id":[0.10, 2],"op":"eval","points":[[1]],"t":0}"#;
    assert_eq!(handle_line(line), r#"{"id":[0.10, 2],"ok":true,"point":["1"]}"#);
}

#[test]
fn point_responses_are_written_as_the_map_prints_them() {
    for line in [
        r#"{"id":0,"op":"eval","points":[[0.1,-0.2],[0.7,0.3],[-0.5,1e-300]],"t":0.3,"approx":[0.3,0.1]}"#,
        r#"{"op":"eval","points":[[0.1],[0.7]],"t":"1/3","approx":[0.3]}"#,
        r#"{"id":{"b":[1,"x"],"a":null},"op":"eval","points":[[0,0],[1,2],[2,0]],"t":"1/3"}"#,
        r#"{"id":"q\"\u00e9","op":"eval","points":[[0]],"t":0,"approx":[1e-15]}"#,
        r#"{"id":-5,"op":"eval","points":[["1/3"],[0.7]],"t":0.5,"approx":[-1e300]}"#,
        r#"{"op":"rational_eval","points":[[1,0],[1,1],[0,1]],"weights":[1,1,2],"t":0.5,"approx":[0.6,0.8]}"#,
        r#"{"id":true,"op":"surface_eval","net":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]],"u":0.1,"v":0.7,"approx":[0.1,0.7,0.07]}"#,
    ] {
        let request: Value = serde_json::from_str(line).unwrap();
        let mut m = Op::from_json(&request).unwrap().run().unwrap().to_json();
        m.insert("ok".into(), Value::Bool(true));
        if let Some(id) = request.get("id") {
            m.insert("id".into(), id.clone());
        }
        assert_eq!(handle_line(line), Value::Object(m).to_string(), "{line}");
    }
}

#[test]
fn an_over_long_line_is_answered_before_its_end_arrives() {
    // a reader that fails after the limit + 1 bytes: the answer must already be out
    struct Failing(usize);
    impl io::Read for Failing {
        fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
            if self.0 == 0 {
                return Err(io::Error::other("the rest of the line never comes"));
            }
            let n = buf.len().min(self.0);
            buf[..n].fill(b'x');
            self.0 -= n;
            Ok(n)
        }
    }
    let mut out = Vec::new();
    let result = serve(io::BufReader::new(Failing(MAX_LINE_BYTES + 1)), &mut out);
    assert!(result.is_err());
    assert!(String::from_utf8(out).unwrap().contains("longer than"));
}

/// A client that sends its requests one at a time, each read returning the next line
/// only: every answer must have been flushed to it before the server asks for the next
/// request, or the two would wait on each other forever.
#[test]
fn an_interactive_client_gets_each_answer_before_its_next_request() {
    use std::cell::RefCell;
    use std::rc::Rc;
    struct Client {
        requests: Vec<&'static [u8]>,
        sent: usize,
        delivered: Rc<RefCell<usize>>,
    }
    impl io::Read for Client {
        fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
            assert_eq!(
                *self.delivered.borrow(),
                self.sent,
                "read before the answer was flushed"
            );
            let Some(line) = self.requests.get(self.sent) else {
                return Ok(0);
            };
            buf[..line.len()].copy_from_slice(line);
            self.sent += 1;
            Ok(line.len())
        }
    }
    /// Counts the lines that reach the client: only flushed bytes do.
    struct Screen {
        pending: Vec<u8>,
        delivered: Rc<RefCell<usize>>,
    }
    impl io::Write for Screen {
        fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
            self.pending.extend_from_slice(buf);
            Ok(buf.len())
        }
        fn flush(&mut self) -> io::Result<()> {
            *self.delivered.borrow_mut() += self.pending.iter().filter(|&&b| b == b'\n').count();
            self.pending.clear();
            Ok(())
        }
    }
    let delivered = Rc::new(RefCell::new(0));
    let eval: &[u8] = b"{\"op\":\"eval\",\"points\":[[0],[2]],\"t\":\"1/4\"}\n";
    let client = Client {
        requests: vec![eval, b"nope\n", eval],
        sent: 0,
        delivered: delivered.clone(),
    };
    let screen = Screen {
        pending: Vec::new(),
        delivered: delivered.clone(),
    };
    serve(client, screen).unwrap();
    assert_eq!(*delivered.borrow(), 3);
}

/// A burst already in the buffer is answered without a flush per line, and nothing is
/// left unflushed at the end of input.
#[test]
fn a_piped_burst_is_answered_in_one_flush() {
    struct Flushes(Vec<u8>, usize);
    impl io::Write for Flushes {
        fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
            self.0.extend_from_slice(buf);
            Ok(buf.len())
        }
        fn flush(&mut self) -> io::Result<()> {
            self.1 += 1;
            Ok(())
        }
    }
    let input = "{\"op\":\"eval\",\"points\":[[0],[2]],\"t\":\"1/4\"}\n".repeat(100);
    let mut out = Flushes(Vec::new(), 0);
    serve(input.as_bytes(), &mut out).unwrap();
    assert_eq!(out.0.iter().filter(|&&b| b == b'\n').count(), 100);
    assert!(out.1 <= 2, "{} flushes for one buffered burst", out.1);
}

#[test]
fn eval_is_exact_and_echoes_the_id() {
    let r = ask(r#"{"id":"a","op":"eval","points":[[0,0],["4/3","-4/3"],["4/3","4/3"],[0,0]],"t":"1/2"}"#);
    assert_eq!(r, json!({"id": "a", "ok": true, "point": ["1", "0"]}));
    let r = ask(r#"{"id":[1,{"x":2}],"op":"eval","points":[[1]],"t":5}"#);
    assert_eq!(r, json!({"id": [1, {"x": 2}], "ok": true, "point": ["1"]}));
}

#[test]
fn every_op_answers() {
    let r = ask(r#"{"op":"elevate","points":[[0,0],[1,2],[2,0]],"by":1}"#);
    assert_eq!(
        r["points"],
        json!([["0", "0"], ["2/3", "4/3"], ["4/3", "4/3"], ["2", "0"]])
    );
    let r = ask(r#"{"op":"split","points":[[0],[1],[3]],"t":"1/2"}"#);
    assert_eq!(r["left"], json!([["0"], ["1/2"], ["5/4"]]));
    assert_eq!(r["right"], json!([["5/4"], ["2"], ["3"]]));
    let r = ask(r#"{"op":"derivative","points":[[0],[1],[3]],"order":1}"#);
    assert_eq!(r["points"], json!([["2"], ["4"]]));
    let r = ask(r#"{"op":"derivative","points":[[0],[1],[3]],"order":2}"#);
    assert_eq!(r["points"], json!([["2"]]));
    let r = ask(r#"{"op":"derivative","points":[[0],[1],[3]],"order":1,"t":"1/2"}"#);
    assert_eq!(r, json!({"ok": true, "vector": ["3"]}));
    let r = ask(r#"{"op":"derivative","points":[[0],[1],[3]],"order":5,"t":"1/2"}"#);
    assert_eq!(r, json!({"ok": true, "vector": ["0"]}));
    // 4t - 4t² as a quadratic: Bézier points 0, 2, 0
    let r = ask(r#"{"op":"to_bezier","power":[[0,4,-4],[1,0,0]]}"#);
    assert_eq!(r["points"], json!([["0", "1"], ["2", "1"], ["0", "1"]]));
}

#[test]
fn rational_conic_surface_fit_answer() {
    // text 001, Example 3: the arc (-1,1), (0,-1), (1,1) with weights 1, 1/2, 1
    let r = ask(r#"{"op":"conic","points":[[-1,1],[0,-1],[1,1]],"weights":[1,"1/2",1]}"#);
    assert_eq!(
        r,
        json!({"ok": true, "type": "ellipse", "implicit": ["4", "0", "3", "0", "-10", "3"]})
    );
    let r = ask(r#"{"op":"conic","points":[[-1,1],[0,-1],[1,1]],"weights":[1,2,1]}"#);
    assert_eq!(r["type"], json!("hyperbola"));
    let r = ask(r#"{"op":"conic","points":[[0,0],[1,1],[2,2]],"weights":[1,1,1]}"#);
    assert_eq!(r["implicit"], Value::Null);
    assert!(r["type"].as_str().unwrap().starts_with("degenerate"));
    // the quarter circle: x(1/2) = (3/5, 4/5), and 0.6, 0.8 are its correctly rounded floats
    let r =
        ask(r#"{"op":"rational_eval","points":[[1,0],[1,1],[0,1]],"weights":[1,1,2],"t":"1/2","approx":[0.6,0.8]}"#);
    assert_eq!(r["point"], json!(["3/5", "4/5"]));
    assert_eq!(r["ulps"], json!([0, 0]));
    let r = ask(r#"{"op":"rational_eval","points":[[1,0],[1,1],[0,1]],"weights":[1,-1,1],"t":"1/2"}"#);
    assert!(r["error"].as_str().unwrap().contains("vanishes"), "{r}");
    // text 003: the bilinear patch z = xy
    let r = ask(r#"{"op":"surface_eval","net":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]],"u":"1/3","v":"3/4"}"#);
    assert_eq!(r["point"], json!(["1/3", "3/4", "1/4"]));
    // text 004: a cubic is its own fit, k = l = 1/3, δ² = 0
    let r = ask(r#"{"op":"fit_cubic","x0":[0,0,0],"x1":[4,0,5],"xh":[2,"3/2",1],"d0":[3,6,0],"d1":[3,-6,12]}"#);
    assert_eq!(
        r,
        json!({"ok": true, "k": "1/3", "l": "1/3", "delta2": "0", "warnings": [],
               "points": [["0", "0", "0"], ["1", "2", "0"], ["3", "2", "1"], ["4", "0", "5"]]})
    );
    let r = ask(r#"{"op":"fit_cubic","x0":[0,0],"x1":[1,0],"xh":[0,1],"d0":[1,0],"d1":[2,0]}"#);
    assert!(r["error"].as_str().unwrap().contains("parallel"), "{r}");
    for (line, needle) in [
        (
            r#"{"op":"conic","points":[[-1,1],[0,-1]],"weights":[1,1]}"#,
            "needs 3 points",
        ),
        (
            r#"{"op":"conic","points":[[-1,1,0],[0,-1,0],[1,1,0]],"weights":[1,1,1]}"#,
            "planar",
        ),
        (
            r#"{"op":"rational_eval","points":[[1,0],[1,1]],"weights":[1],"t":0}"#,
            "1 weights for 2",
        ),
        (
            r#"{"op":"rational_eval","points":[[1,0],[1,1]],"weights":[0,0],"t":0}"#,
            "all weights",
        ),
        (
            r#"{"op":"surface_eval","net":[[[0,0]],[[0,1],[1,1]]],"u":0,"v":0}"#,
            "ragged",
        ),
        (r#"{"op":"surface_eval","net":[],"u":0,"v":0}"#, "empty"),
        (
            r#"{"op":"fit_cubic","x0":[0,0],"x1":[1,0],"xh":[0,1],"d0":[1,0]}"#,
            "'d1'",
        ),
        (
            r#"{"op":"fit_cubic","x0":[0,0],"x1":[1,0,0],"xh":[0,1],"d0":[1,0],"d1":[0,1]}"#,
            "dimension",
        ),
    ] {
        let r = ask(line);
        assert_eq!(r["ok"], json!(false), "{line}");
        assert!(r["error"].as_str().unwrap().contains(needle), "{line}: {r}");
    }
}

#[test]
fn conic_equations_read_like_the_text() {
    let k = |c: [i64; 6]| conic_polynomial(&c.map(BigInt::from));
    assert_eq!(k([4, 0, 3, 0, -10, 3]), "4x^2 + 3y^2 - 10y + 3");
    assert_eq!(k([-1, 1, 0, 0, 0, 0]), "-x^2 + xy");
    assert_eq!(k([0, 0, 0, 0, 0, -1]), "-1");
    assert_eq!(k([0, 0, 0, 0, 0, 0]), "0");
}

#[test]
fn bad_requests_get_clear_errors() {
    let cases: &[(&str, &str)] = &[
        ("not json", "not valid JSON"),
        ("", "empty line"),
        ("[1,2]", "must be a JSON object"),
        (r#"{"points":[[0]]}"#, "missing field 'op'"),
        (r#"{"op":"frobnicate"}"#, "unknown op"),
        (r#"{"op":7}"#, "'op' must be a string"),
        (r#"{"op":"eval","points":[[0]]}"#, "needs the field 't'"),
        (
            r#"{"op":"eval","points":[[0]],"t":0,"aprox":[0.5]}"#,
            "unknown field \"aprox\"",
        ),
        (r#"{"op":"eval","points":[],"t":0}"#, "empty"),
        (r#"{"op":"eval","points":[[0,0],[1]],"t":0}"#, "dimension mismatch"),
        (r#"{"op":"eval","points":[[0]],"t":"1/0"}"#, "zero denominator"),
        (r#"{"op":"eval","points":[[0]],"t":"abc"}"#, "not a number"),
        (r#"{"op":"eval","points":[[0]],"t":"NaN"}"#, "not a number"),
        (r#"{"op":"eval","points":[[0]],"t":"1e999999999"}"#, "too large"),
        (r#"{"op":"eval","points":[[0]],"t":null}"#, "field 't'"),
        (r#"{"op":"eval","points":"0,0","t":0}"#, "field 'points'"),
        (
            r#"{"op":"eval","points":[[0]],"t":0,"approx":[1,2]}"#,
            "dimension mismatch",
        ),
        (
            r#"{"op":"eval","points":[[0]],"t":0,"approx":["0.5"]}"#,
            "must be a JSON number",
        ),
        (
            r#"{"op":"elevate","points":[[0]],"by":1000000000000}"#,
            "degree after elevation is too large",
        ),
        (r#"{"op":"elevate","points":[[0]],"by":-1}"#, "non-negative integer"),
        (r#"{"op":"elevate","points":[[0]],"by":"x"}"#, "non-negative integer"),
        (r#"{"op":"derivative","points":[[0],[1]],"order":2}"#, "order 2"),
        (r#"{"op":"to_bezier","power":[[0,1],[1]]}"#, "ragged"),
        (r#"{"op":"to_bezier","power":[]}"#, "empty"),
        (r#"{"op":"eval","points":[[1e400]],"t":0}"#, "not valid JSON"),
    ];
    for (line, needle) in cases {
        let r = ask(line);
        assert_eq!(r["ok"], json!(false), "{line} -> {r}");
        let msg = r["error"].as_str().unwrap();
        assert!(msg.contains(needle), "{line}: {msg:?} should mention {needle:?}");
    }
}

#[test]
fn huge_requests_are_refused_quickly() {
    let many: Vec<Value> = (0..5000).map(|i| json!([i])).collect();
    let r = ask(&json!({"op": "eval", "points": many, "t": "1/3"}).to_string());
    assert!(
        r["error"].as_str().unwrap().contains("number of points is too large"),
        "{r}"
    );
    let wide: Vec<Value> = (0..65).map(|i| json!(i)).collect();
    let r = ask(&json!({"op": "eval", "points": [wide], "t": 0}).to_string());
    assert!(r["error"].as_str().unwrap().contains("dimension is too large"), "{r}");
    // degree 4000 at a parameter with 1000-digit numerator: far beyond the work limit
    let pts: Vec<Value> = (0..4000).map(|i| json!([i])).collect();
    let t = format!("1/{}", "7".repeat(1000));
    let r = ask(&json!({"op": "eval", "points": pts, "t": t}).to_string());
    assert!(r["error"].as_str().unwrap().contains("estimated exact work"), "{r}");
}

#[test]
fn work_limit_matches_its_documentation() {
    let request = |op: &str, n: i64, t: Value| {
        let points: Vec<Value> = (0..n).map(|i| json!([(i * 7919) % 1000, (i * 104729) % 997])).collect();
        Op::from_json(&json!({"op": op, "points": points, "t": t}))
    };
    let planar = |n: i64, t: Value| request("split", n, t);
    assert!(planar(1201, json!("1/3")).is_ok());
    assert!(planar(1401, json!("1/3"))
        .unwrap_err()
        .to_string()
        .contains("estimated exact work"));
    // integers at a float parameter are calibrated as floats (the dyadic kernels)
    assert!(planar(201, json!(0.1)).is_ok());
    assert!(planar(261, json!(0.1)).is_err());
    assert!(request("eval", 4097, json!("1/3")).is_ok());
    assert!(request("eval", 1001, json!(0.1)).is_ok());
    assert!(request("eval", 2001, json!(0.1)).is_err());
    // calibrated per op and kind of number (tests/calibration.rs): 64-D floats of degree
    // 89 at 0.1 (about 0.8 s with the answer written) are admitted, of degree 100 refused;
    // 64-D fits of these distinct 151-digit fractions admitted (0.13 s), of 201 refused
    let wide = |n: usize| -> Vec<Value> {
        (0..n)
            .map(|i| {
                (0..64)
                    .map(|k| json!(((i * 64 + k) as f64 * 0.618).fract() - 0.5))
                    .collect()
            })
            .collect()
    };
    let split = |n: usize| Op::from_json(&json!({"op": "split", "points": wide(n), "t": 0.1}));
    assert!(split(101).unwrap_err().to_string().contains("estimated exact work"));
    assert!(split(90).is_ok());
    // (10^k + j)/(10^k + j' + 10): k + 1 digits, distinct denominators
    let fraction =
        |k: usize, j: usize| format!("1{}{}/1{}1{}", "0".repeat(k - 1), j % 10, "0".repeat(k - 2), j % 9 + 1);
    let point = |k: usize, o: usize| json!((0..64).map(|j| fraction(k, o + j)).collect::<Vec<_>>());
    let fit = |k: usize| {
        Op::from_json(
            &json!({"op": "fit_cubic", "x0": point(k, 0), "x1": point(k, 1), "xh": point(k, 2), "d0": point(k, 3), "d1": point(k, 5)}),
        )
    };
    assert!(fit(200).is_err());
    assert!(fit(150).is_ok());
    let cubic = json!([[0, 0], [1, 2], [3, 2], [4, 0]]);
    assert!(Op::from_json(&json!({"op": "elevate", "points": cubic, "by": 1718})).is_ok());
    assert!(Op::from_json(&json!({"op": "elevate", "points": cubic, "by": 4093})).is_ok());
    // the everyday case (degree 20 at a float) is well below the limit
    let op = planar(21, json!(0.1)).unwrap();
    assert!(op.work() < MAX_REQUEST_WORK / 30.0, "{}", op.work());
}

#[test]
fn bounded_reader_skips_long_lines() {
    let input = format!("{}\nshort\n{}", "x".repeat(100), "y".repeat(5));
    let mut r = io::BufReader::with_capacity(7, input.as_bytes());
    assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::TooLong);
    skip_line(&mut r).unwrap();
    assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::Text(b"short".to_vec()));
    assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::Text(b"yyyyy".to_vec()));
    assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::Eof);
    let mut r = io::BufReader::new(&b"\n\n"[..]);
    assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::Text(vec![]));
    assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::Text(vec![]));
    assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::Eof);
    // exactly the limit is fine; one more byte is too long, even without a newline
    let mut r = io::BufReader::new(&b"0123456789\n0123456789a"[..]);
    assert_eq!(
        read_line_bounded(&mut r, 10).unwrap(),
        Line::Text(b"0123456789".to_vec())
    );
    assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::TooLong);
    skip_line(&mut r).unwrap();
    assert_eq!(read_line_bounded(&mut r, 10).unwrap(), Line::Eof);
}

#[test]
fn serve_answers_every_line_in_order() {
    let input = "{\"id\":1,\"op\":\"eval\",\"points\":[[0],[2]],\"t\":\"1/4\"}\nnope\r\n\n\u{FFFD}\n{\"id\":2,\"op\":\"eval\",\"points\":[[0],[2]],\"t\":0.5}";
    let mut out = Vec::new();
    serve(input.as_bytes(), &mut out).unwrap();
    let lines: Vec<Value> = String::from_utf8(out)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines.len(), 5);
    assert_eq!(lines[0], json!({"id": 1, "ok": true, "point": ["1/2"]}));
    assert_eq!(lines[1]["ok"], json!(false));
    assert_eq!(lines[2]["ok"], json!(false));
    assert_eq!(lines[3]["ok"], json!(false));
    assert_eq!(lines[4], json!({"id": 2, "ok": true, "point": ["1"]}));
    let mut out = Vec::new();
    serve(&[b'{', 0xff, b'}', b'\n'][..], &mut out).unwrap();
    assert!(String::from_utf8(out).unwrap().contains("not valid UTF-8"));
}

/// JSON text of one number-like value, valid or not for a coordinate.
fn json_number_text() -> impl Strategy<Value = String> {
    prop_oneof![
        40 => (-1e3f64..1e3).prop_map(|x| format!("{x:?}")),
        10 => (-50i64..50).prop_map(|i| i.to_string()),
        1 => Just("18446744073709551615".to_string()),
        1 => Just("1e-310".to_string()),
        1 => Just("\"1/3\"".to_string()),
        1 => Just("null".to_string()),
        1 => Just("1e400".to_string()),
    ]
}

/// An `eval` request as text, mostly well formed, with the faults the fast path must
/// leave to the general one: repeated, unknown or null fields, other ops, string
/// numbers, mismatched dimensions, fields in any order.
fn eval_line() -> impl Strategy<Value = String> {
    let list = |len: std::ops::Range<usize>| {
        prop::collection::vec(json_number_text(), len).prop_map(|c| format!("[{}]", c.join(",")))
    };
    let points = (1usize..4).prop_flat_map(move |dim| {
        let point = prop_oneof![20 => list(dim..dim + 1), 1 => list(1..4)];
        prop::collection::vec(point, 0..6).prop_map(|p| format!("[{}]", p.join(",")))
    });
    let approx = prop_oneof![6 => list(0..4), 1 => Just("null".to_string())];
    let id = prop_oneof![
        Just("7".to_string()),
        Just("\"a\"".to_string()),
        Just("null".to_string()),
        Just("1.5".to_string()),
        Just("[1, {\"b\": 2}]".to_string()),
    ];
    let op = prop_oneof![
        10 => Just("\"eval\"".to_string()),
        1 => Just("\"split\"".to_string()),
        1 => Just("\"ev\\u0061l\"".to_string())
    ];
    (
        op,
        points,
        json_number_text(),
        prop::option::of(approx),
        prop::option::of(id),
        prop::option::weighted(0.1, prop_oneof![Just("\"t\": 0.5"), Just("\"extra\": 1")]),
        any::<prop::sample::Index>(),
    )
        .prop_map(|(op, points, t, approx, id, more, order)| {
            let mut fields = vec![
                format!("\"op\":{op}"),
                format!("\"points\":{points}"),
                format!("\"t\": {t}"),
            ];
            fields.extend(approx.map(|a| format!("\"approx\":{a}")));
            fields.extend(id.map(|i| format!("\"id\": {i}")));
            fields.extend(more.map(str::to_string));
            let k = order.index(fields.len());
            fields.rotate_left(k);
            format!("{{{}}}", fields.join(","))
        })
}

/// The fast path for `eval` answers every line byte for byte as the general path does,
/// and the lines drawn exercise both.
#[test]
fn the_eval_fast_path_answers_as_the_general_path() {
    use proptest::test_runner::TestRunner;
    let mut runner = TestRunner::new(ProptestConfig::with_cases(1024));
    let taken = std::cell::Cell::new(0usize);
    runner
        .run(&eval_line(), |line| {
            taken.set(taken.get() + usize::from(fast::eval_request(&line).is_some()));
            prop_assert_eq!(handle_line(&line), respond_in_general(&line), "{}", line);
            Ok(())
        })
        .unwrap();
    assert!(
        (100..900).contains(&taken.get()),
        "fast path taken {} times in 1024",
        taken.get()
    );
}

#[test]
fn the_eval_fast_path_takes_the_common_requests() {
    let line = r#"{"id":3,"op":"eval","points":[[0.5,1],[2,-0.25]],"t":0.75,"approx":[1.625,0.0625]}"#;
    assert!(fast::eval_request(line).is_some());
    assert_eq!(handle_line(line), respond_in_general(line));
    for other in [
        r#"{"op":"eval","points":[[0.5,1],[2,-0.25]],"t":"3/4"}"#,
        r#"{"op":"eval","points":[[0.5,1],[2,-0.25]],"t":0.75,"approx":null}"#,
        r#"{"op":"eval","points":[[0.5,1],[2,-0.25]],"t":0.75,"t":0.5}"#,
        r#"{"op":"eval","points":[[0.5,1],[2]],"t":0.75}"#,
    ] {
        assert!(fast::eval_request(other).is_none(), "{other}");
    }
}

fn small_rational() -> impl Strategy<Value = BigRational> {
    (-1000i64..1000, 1i64..100).prop_map(|(p, d)| BigRational::new(p.into(), d.into()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn oracle_eval_equals_library_eval(
        coords in prop::collection::vec(prop::collection::vec(small_rational(), 2), 1..8),
        t in small_rational(),
    ) {
        let curve = BezierCurve::from_coords(coords.clone()).unwrap();
        let exact = curve.eval(&t);
        let points: Vec<Value> = coords.iter().map(|p| p.iter().map(number_to_json).collect()).collect();
        let approx: Vec<f64> = exact.coords().iter().map(nearest_f64).collect();
        let r = ask(&json!({"op": "eval", "points": points, "t": number_to_json(&t), "approx": approx}).to_string());
        prop_assert_eq!(&r["ok"], &json!(true));
        let got: Vec<BigRational> = r["point"].as_array().unwrap().iter().map(|c| q(c.as_str().unwrap())).collect();
        prop_assert_eq!(got.as_slice(), exact.coords());
        prop_assert_eq!(&r["ulps"], &json!([0, 0]));
        for e in r["error_ulps"].as_array().unwrap() {
            prop_assert!(e.as_f64().unwrap() <= 0.5);
        }
    }
}
