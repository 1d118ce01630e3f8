//! The JSON-lines oracle through the built binary: every line answered in order, ids
//! echoed, bad requests answered without ending the loop, answers flushed one at a time.

use casteljau::oracle::nearest_f64;
use casteljau::oracle::number_to_json;
use casteljau::{BezierCurve, BigRational};
use proptest::prelude::*;
use serde_json::{json, Value};
use std::io::{BufRead, BufReader, Write};
use std::process::{Command, Stdio};

/// Feeds `input` to `casteljau oracle` and returns the response lines.
fn session(input: &[u8]) -> Vec<Value> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .arg("oracle")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let input = input.to_vec();
    // write from another thread: a long input must not deadlock against unread output
    let writer = std::thread::spawn(move || {
        stdin.write_all(&input).unwrap();
    });
    let out = child.wait_with_output().unwrap();
    writer.join().unwrap();
    assert!(out.status.success(), "the oracle exits 0 at end of input");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "{stderr}");
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).expect("every response line is JSON"))
        .collect()
}

#[test]
fn every_line_is_answered_in_order_with_ids() {
    let lines = [
        r#"{"id":1,"op":"eval","points":[[0,0],["4/3","-4/3"],["4/3","4/3"],[0,0]],"t":"1/3"}"#,
        r#"this is not json"#,
        r#"{"id":"two","op":"frobnicate"}"#,
        r#"{"id":3,"op":"eval","points":[],"t":0}"#,
        r#"{"id":4,"op":"eval","points":[[0,0],[1]],"t":0}"#,
        r#"{"id":5,"op":"eval","points":[[0]],"t":"1/0"}"#,
        r#"{"id":6,"op":"eval","points":[[0]],"t":"abc"}"#,
        r#"{"id":7,"op":"eval","points":[[0]],"t":"1e999999999"}"#,
        r#"{"id":8,"op":"elevate","points":[[0],[1]],"by":1000000000000}"#,
        r#"{"id":9,"op":"elevate","points":[[0,0],[1,2],[2,0]],"by":1}"#,
        r#"{"id":10,"op":"split","points":[[0],[1],[3]],"t":0.5}"#,
        r#"{"id":11,"op":"derivative","points":[[0],[1],[3]],"order":1}"#,
        r#"{"id":12,"op":"to_bezier","power":[[0,4,-4],[1,0,0]]}"#,
        r#"{"id":{"nested":[1,2]},"op":"eval","points":[[1,2]],"t":0}"#,
        r#"{"id":14,"op":"eval","points":[[0]]}"#,
        r#""#,
        r#"{"id":16,"op":"eval","points":[[0],[1]],"t":0.1,"approx":[0.1]}"#,
        r#"{"id":17,"op":"conic","points":[[-1,1],[0,-1],[1,1]],"weights":[1,"1/2",1]}"#,
        r#"{"id":18,"op":"rational_eval","points":[[1,0],[1,1],[0,1]],"weights":[1,1,2],"t":"1/2"}"#,
        r#"{"id":19,"op":"surface_eval","net":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]],"u":"1/3","v":"3/4"}"#,
        r#"{"id":20,"op":"fit_cubic","x0":[0,0,0],"x1":[4,0,5],"xh":[2,"3/2",1],"d0":[3,6,0],"d1":[3,-6,12]}"#,
        r#"{"id":21,"op":"conic","points":[[-1,1],[0,-1],[1,1]],"weights":[1,"1/2"]}"#,
    ];
    let input = lines.join("\n") + "\n";
    let out = session(input.as_bytes());
    assert_eq!(out.len(), lines.len(), "{out:#?}");
    assert_eq!(out[0], json!({"id": 1, "ok": true, "point": ["8/9", "-8/27"]}));
    let expect_error = [
        (1, "not valid JSON"),
        (2, "unknown op"),
        (3, "empty"),
        (4, "dimension mismatch"),
        (5, "zero denominator"),
        (6, "not a number"),
        (7, "too large"),
        (8, "degree after elevation is too large"),
        (14, "needs the field 't'"),
        (15, "empty line"),
    ];
    for (i, needle) in expect_error {
        assert_eq!(out[i]["ok"], json!(false), "line {i}: {}", out[i]);
        let msg = out[i]["error"].as_str().unwrap();
        assert!(msg.contains(needle), "line {i}: {msg:?} should mention {needle:?}");
    }
    assert_eq!(out[1].get("id"), None, "no id can be read from a line that is not JSON");
    assert_eq!(out[2]["id"], json!("two"));
    for (i, r) in out.iter().enumerate().take(9).skip(3) {
        assert_eq!(r["id"], json!(i));
    }
    assert_eq!(
        out[9]["points"],
        json!([["0", "0"], ["2/3", "4/3"], ["4/3", "4/3"], ["2", "0"]])
    );
    assert_eq!(out[10]["left"], json!([["0"], ["1/2"], ["5/4"]]));
    assert_eq!(out[11]["points"], json!([["2"], ["4"]]));
    assert_eq!(out[12]["points"], json!([["0", "1"], ["2", "1"], ["0", "1"]]));
    assert_eq!(
        out[13],
        json!({"id": {"nested": [1, 2]}, "ok": true, "point": ["1", "2"]})
    );
    // 0.1 as a JSON number is the float 0.1, so b(t) = t is exactly that float
    assert_eq!(out[16]["point"], json!(["3602879701896397/36028797018963968"]));
    assert_eq!(out[16]["ulps"], json!([0]));
    assert_eq!(out[16]["error_ulps"], json!([0.0]));
    assert_eq!(out[17]["implicit"], json!(["4", "0", "3", "0", "-10", "3"]));
    assert_eq!(out[18]["point"], json!(["3/5", "4/5"]));
    assert_eq!(out[19]["point"], json!(["1/3", "3/4", "1/4"]));
    assert_eq!(
        (&out[20]["k"], &out[20]["l"], &out[20]["delta2"]),
        (&json!("1/3"), &json!("1/3"), &json!("0"))
    );
    assert_eq!((&out[21]["id"], &out[21]["ok"]), (&json!(21), &json!(false)));
}

#[test]
fn an_overlong_line_is_refused_without_ending_the_session() {
    let mut input = Vec::new();
    input.extend_from_slice(b"{\"id\":1,\"op\":\"eval\",\"points\":[[1]],\"t\":0}\n");
    input.extend(std::iter::repeat_n(b'x', 3 << 20));
    input.push(b'\n');
    input.extend_from_slice(&[b'{', 0xff, 0xfe, b'}', b'\n']);
    input.extend_from_slice(b"{\"id\":4,\"op\":\"eval\",\"points\":[[2]],\"t\":0}");
    let out = session(&input);
    assert_eq!(out.len(), 4, "{out:?}");
    assert_eq!(out[0], json!({"id": 1, "ok": true, "point": ["1"]}));
    assert!(out[1]["error"].as_str().unwrap().contains("longer than"), "{}", out[1]);
    assert!(out[2]["error"].as_str().unwrap().contains("UTF-8"), "{}", out[2]);
    assert_eq!(
        out[3],
        json!({"id": 4, "ok": true, "point": ["2"]}),
        "a last line without newline is served"
    );
}

/// A request line of exactly `len` bytes: an `eval` padded with spaces inside the object.
fn line_of(len: usize, id: &str) -> Vec<u8> {
    let head = format!("{{\"id\":{id},\"op\":\"eval\",\"points\":[[1]],\"t\":0");
    let mut line = head.into_bytes();
    line.extend(std::iter::repeat_n(b' ', len - line.len() - 1));
    line.push(b'}');
    line
}

#[test]
fn the_line_limit_counts_the_line_without_its_crlf() {
    const LIMIT: usize = casteljau::oracle::MAX_LINE_BYTES;
    let mut input = Vec::new();
    // exactly at the limit, with CRLF: served
    input.extend(line_of(LIMIT, "1"));
    input.extend_from_slice(b"\r\n");
    // one byte over, with CRLF or LF: refused, the leading id echoed
    input.extend(line_of(LIMIT + 1, "2"));
    input.extend_from_slice(b"\r\n");
    input.extend(line_of(LIMIT + 1, "12345678901234567890123456789"));
    input.push(b'\n');
    // far over, id first: refused with the id as soon as the limit is crossed
    input.extend(line_of(3 * LIMIT, "{\"k\": [1, \"x\"]}"));
    input.push(b'\n');
    // far over, id last: it cannot be read, the answer has none
    input.extend_from_slice(b"{\"op\":\"eval\",\"points\":[[1]],\"t\":0");
    input.extend(std::iter::repeat_n(b' ', 2 * LIMIT));
    input.extend_from_slice(b",\"id\":6}\n");
    input.extend_from_slice(b"{\"id\":7,\"op\":\"eval\",\"points\":[[2]],\"t\":0}\r\n");
    let out = session(&input);
    assert_eq!(out.len(), 6, "{out:?}");
    assert_eq!(out[0], json!({"id": 1, "ok": true, "point": ["1"]}));
    for (k, id) in [(1, json!(2)), (3, json!({"k": [1, "x"]}))] {
        assert_eq!(out[k]["ok"], false, "{}", out[k]);
        assert_eq!(out[k]["id"], id, "{}", out[k]);
        assert!(out[k]["error"].as_str().unwrap().contains("longer than"), "{}", out[k]);
    }
    assert!(out[2]["error"].as_str().unwrap().contains("longer than"), "{}", out[2]);
    assert!(out[4].get("id").is_none() && out[4]["ok"] == false, "{}", out[4]);
    assert_eq!(out[5], json!({"id": 7, "ok": true, "point": ["2"]}));
}

#[test]
fn a_long_integer_id_of_an_overlong_line_is_echoed_as_written() {
    let mut input = line_of(casteljau::oracle::MAX_LINE_BYTES + 10, "12345678901234567890123456789");
    input.push(b'\n');
    let mut child = Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .arg("oracle")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let writer = std::thread::spawn(move || stdin.write_all(&input).unwrap());
    let out = child.wait_with_output().unwrap();
    writer.join().unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("\"id\":12345678901234567890123456789,"), "{text}");
}

#[test]
fn a_field_given_twice_is_refused() {
    let out = session(
        b"{\"id\":1,\"op\":\"eval\",\"points\":[[1]],\"t\":0,\"t\":1}\n\
          {\"id\":2,\"op\":\"split\",\"points\":[[1],[2]],\"t\":\"1/2\",\"points\":[[3]]}\n\
          {\"id\":3,\"id\":3,\"op\":\"eval\",\"points\":[[1]],\"t\":0}\n\
          {\"id\":{\"a\":1},\"op\":\"eval\",\"points\":[[1]],\"t\":0}\n",
    );
    assert_eq!(out.len(), 4, "{out:?}");
    for (k, field) in [(0, "t"), (1, "points"), (2, "id")] {
        assert_eq!(out[k]["ok"], false, "{}", out[k]);
        let error = out[k]["error"].as_str().unwrap();
        assert!(error.contains(&format!("\"{field}\" given twice")), "{error}");
    }
    assert_eq!(out[3]["ok"], true, "{}", out[3]);
}

#[test]
fn absurd_requests_are_refused_quickly() {
    let start = std::time::Instant::now();
    let points: Vec<Value> = (0..4000).map(|i| json!([i, i])).collect();
    let wide: Vec<Value> = (0..201).map(|i| json!(vec![i as f64 * 0.618 - 0.25; 8])).collect();
    let lines = [
        json!({"op": "eval", "points": points, "t": format!("1/{}", "7".repeat(900))}),
        // (a line elevated to the documented degree 4096 is accepted: 0.1 s)
        json!({"op": "elevate", "points": wide, "by": 3895, "id": "deg"}),
        json!({"op": "eval", "points": [(0..100).collect::<Vec<_>>()], "t": 0}),
    ];
    let input: String = lines.iter().map(|l| l.to_string() + "\n").collect();
    let out = session(input.as_bytes());
    assert_eq!(out.len(), 3);
    for r in &out {
        assert_eq!(r["ok"], json!(false), "{r}");
        assert!(r["error"].as_str().unwrap().contains("too large"), "{r}");
    }
    // refused from the estimate, not after computing (the bound is generous for slow CI)
    assert!(start.elapsed().as_secs() < 20);
}

#[test]
fn answers_are_flushed_one_at_a_time() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .arg("oracle")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let mut stdout = BufReader::new(child.stdout.take().unwrap());
    for k in 1..=3 {
        // the next request is written only after the previous answer arrived
        writeln!(stdin, r#"{{"id":{k},"op":"eval","points":[[0],[{k}]],"t":"1/2"}}"#).unwrap();
        stdin.flush().unwrap();
        let mut line = String::new();
        stdout.read_line(&mut line).unwrap();
        let r: Value = serde_json::from_str(&line).unwrap();
        let half = casteljau::format_exact(&BigRational::new(k.into(), 2.into()));
        assert_eq!(r, json!({"id": k, "ok": true, "point": [half]}));
        writeln!(stdin, "garbage").unwrap();
        stdin.flush().unwrap();
        line.clear();
        stdout.read_line(&mut line).unwrap();
        assert!(line.contains("\"ok\":false"), "{line}");
    }
    drop(stdin);
    assert!(child.wait().unwrap().success());
}

fn rational() -> impl Strategy<Value = BigRational> {
    (-10_000i64..10_000, 1i64..1_000).prop_map(|(p, d)| BigRational::new(p.into(), d.into()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// Through the binary: the oracle's eval is the library's exact eval, and sending the
    /// correctly rounded value as `approx` gives 0 ulps.
    #[test]
    fn oracle_eval_matches_the_library(
        curves in prop::collection::vec(
            (prop::collection::vec(prop::collection::vec(rational(), 3), 1..10), rational()), 8),
    ) {
        let mut input = String::new();
        let mut expected = Vec::new();
        for (i, (coords, t)) in curves.iter().enumerate() {
            let exact = BezierCurve::from_coords(coords.clone()).unwrap().eval(t);
            let points: Vec<Value> = coords.iter().map(|p| p.iter().map(number_to_json).collect()).collect();
            let approx: Vec<f64> = exact.coords().iter().map(nearest_f64).collect();
            input += &json!({"id": i, "op": "eval", "points": points, "t": number_to_json(t), "approx": approx}).to_string();
            input.push('\n');
            expected.push(exact);
        }
        let out = session(input.as_bytes());
        prop_assert_eq!(out.len(), curves.len());
        for (i, (r, exact)) in out.iter().zip(&expected).enumerate() {
            prop_assert_eq!(&r["id"], &json!(i));
            let got: Vec<Value> = exact.coords().iter().map(number_to_json).collect();
            prop_assert_eq!(&r["point"], &Value::Array(got));
            prop_assert_eq!(&r["ulps"], &json!([0, 0, 0]));
        }
    }
}
