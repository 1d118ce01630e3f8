//! The a priori bounds of `split`, `elevate`, `derivative` and `to_bezier` (with `approx`
//! and `method`) on the 10,000 edge cases of `tests/float_edges.rs` (subnormal coefficients,
//! tiny t, coefficients near 1e308, near-cancellation, mixed scales): a plain f64
//! implementation of each named algorithm, written here, is always within its bound, and
//! answers moved past twice the bound are caught (`within_bound` false). Everything goes
//! through the oracle's request lines.

#[path = "support/float_edges.rs"]
mod edges;
#[path = "support/rng.rs"]
mod rng;

use casteljau::float::{binomials, nearest_f64, next_down, next_up, ulp};
use casteljau::oracle::handle_line;
use casteljau::BigRational;
use num_traits::{Signed, Zero};
use serde_json::Value;

/// A float as the oracle reads it: a JSON number, or `"inf"`, `"-inf"`, `"nan"`.
fn fj(x: f64) -> String {
    if x.is_finite() {
        serde_json::to_string(&x).unwrap()
    } else if x.is_nan() {
        "\"nan\"".into()
    } else if x > 0.0 {
        "\"inf\"".into()
    } else {
        "\"-inf\"".into()
    }
}

/// One-coordinate points as JSON.
fn points(p: &[f64]) -> String {
    format!(
        "[{}]",
        p.iter().map(|x| format!("[{}]", fj(*x))).collect::<Vec<_>>().join(",")
    )
}

// ---- the algorithms, plainly ----

fn split_convex(b: &[f64], t: f64) -> (Vec<f64>, Vec<f64>) {
    split_with(b, |a, c| (1.0 - t) * a + t * c)
}

fn split_lerp(b: &[f64], t: f64) -> (Vec<f64>, Vec<f64>) {
    split_with(b, |a, c| a + t * (c - a))
}

fn split_with(b: &[f64], node: impl Fn(f64, f64) -> f64) -> (Vec<f64>, Vec<f64>) {
    let n = b.len() - 1;
    let mut level = b.to_vec();
    let mut left = vec![b[0]];
    let mut right = vec![b[n]];
    for _ in 0..n {
        level = level.windows(2).map(|w| node(w[0], w[1])).collect();
        left.push(level[0]);
        right.push(level[level.len() - 1]);
    }
    right.reverse();
    (left, right)
}

/// Elevation by one, `by` times: quotients rounded (`weights`) or integer weights then one
/// division (the `bezier` package's form).
fn elevate(b: &[f64], by: usize, integer_weights: bool) -> Vec<f64> {
    let mut b = b.to_vec();
    for _ in 0..by {
        let m = b.len() - 1;
        let mut c = vec![b[0]];
        for i in 1..=m {
            let (i_f, j_f, d) = (i as f64, (m + 1 - i) as f64, (m + 1) as f64);
            c.push(if integer_weights {
                (i_f * b[i - 1] + j_f * b[i]) / d
            } else {
                (i_f / d) * b[i - 1] + (j_f / d) * b[i]
            });
        }
        c.push(b[m]);
        b = c;
    }
    b
}

fn derivative(b: &[f64], order: usize) -> Vec<f64> {
    let mut d = b.to_vec();
    for l in 1..=order {
        let m = (b.len() - l) as f64;
        d = d.windows(2).map(|w| m * (w[1] - w[0])).collect();
    }
    d
}

fn to_bezier(a: &[f64]) -> Vec<f64> {
    let n = a.len() - 1;
    let cn = binomials(n);
    (0..=n)
        .map(|i| {
            let ci = binomials(i);
            (0..=i).fold(0.0, |s, j| s + (ci[j] / cn[j]) * a[j])
        })
        .collect()
}

// ---- judging ----

#[derive(Default, Debug)]
struct Tally {
    judged: usize,
    outside: usize,
    overflowed: usize,
    moved: usize,
    moved_caught: usize,
    unbounded: usize,
    seconds: f64,
    failures: Vec<String>,
}

impl Tally {
    fn fail(&mut self, s: String) {
        if self.failures.len() < 5 {
            self.failures.push(s);
        }
    }
}

/// A float beyond `bound_ulps` ulps of `x`, on the far side of `toward`'s sign: twice the
/// bound away, then stepped outward until it is past the bound (decided exactly). `None`
/// when that leaves the f64 range.
fn moved_past(x: &BigRational, bound_ulps: f64, up: bool) -> Option<f64> {
    let reach = BigRational::from_float(bound_ulps)? * ulp(x);
    let twice = &reach + &reach;
    let target = if up { x + twice } else { x - twice };
    let mut a = nearest_f64(&target);
    while a.is_finite() && (BigRational::from_float(a)? - x).abs() <= reach {
        a = if up { next_up(a) } else { next_down(a) };
    }
    a.is_finite().then_some(a)
}

/// The values of `field` in the response, flattened in order (left then right for a split).
fn flat<'a>(r: &'a Value, field: &str) -> Vec<&'a Value> {
    let v = &r[field];
    let groups: Vec<&Value> = match v {
        Value::Object(m) => vec![&m["left"], &m["right"]],
        other => vec![other],
    };
    groups
        .into_iter()
        .flat_map(|g| g.as_array().unwrap().iter().flat_map(|p| p.as_array().unwrap().iter()))
        .collect()
}

/// Asks `request(approx)` with the reference answer, then with every finite coordinate moved
/// past twice its bound; tallies both.
fn judge(tally: &mut Tally, ours: &[f64], request: &dyn Fn(&[f64]) -> String, what: &str, move_too: bool) {
    let start = std::time::Instant::now();
    judge_timed(tally, ours, request, what, move_too);
    tally.seconds += start.elapsed().as_secs_f64();
}

fn judge_timed(tally: &mut Tally, ours: &[f64], request: &dyn Fn(&[f64]) -> String, what: &str, move_too: bool) {
    let line = request(ours);
    let r: Value = serde_json::from_str(&handle_line(&line)).unwrap();
    if r["ok"] != true {
        tally.outside += 1;
        tally.fail(format!("{what}: {r} for {line}"));
        return;
    }
    let within = flat(&r, "within_bound");
    let bounds = flat(&r, "bound");
    assert_eq!(within.len(), ours.len(), "{r}");
    // the exact values, read only to move the answers (reading them is most of the time)
    let exact: Vec<BigRational> = if !move_too {
        Vec::new()
    } else {
        ["points", "left", "right"]
            .iter()
            .filter_map(|k| r.get(*k))
            .flat_map(|g| {
                g.as_array()
                    .unwrap()
                    .iter()
                    .map(|p| p[0].as_str().unwrap().parse::<BigRational>().unwrap())
            })
            .collect()
    };
    let mut moved = ours.to_vec();
    for (k, a) in ours.iter().enumerate() {
        if !a.is_finite() {
            tally.overflowed += 1;
            continue;
        }
        tally.judged += 1;
        if within[k] != true {
            tally.outside += 1;
            tally.fail(format!("{what}: coordinate {k} outside its bound: {line} -> {r}"));
        }
        if !move_too {
            continue;
        }
        match bounds[k].as_f64() {
            Some(b) => {
                // away from the exact value, on the side of the answer
                let up = BigRational::from_float(*a).unwrap() >= exact[k];
                if let Some(m) = moved_past(&exact[k], b, up) {
                    moved[k] = m;
                    continue;
                }
            }
            None => tally.unbounded += 1,
        }
        moved[k] = f64::NAN; // left out below
    }
    if !move_too {
        return;
    }
    let line = request(
        &moved
            .iter()
            .map(|x| if x.is_nan() { 0.0 } else { *x })
            .collect::<Vec<_>>(),
    );
    let r: Value = serde_json::from_str(&handle_line(&line)).unwrap();
    let within = flat(&r, "within_bound");
    for (k, m) in moved.iter().enumerate() {
        if !m.is_finite() || !ours[k].is_finite() {
            continue;
        }
        tally.moved += 1;
        if within[k] == false {
            tally.moved_caught += 1;
        } else {
            tally.fail(format!(
                "{what}: coordinate {k} moved past twice its bound is within: {line} -> {r}"
            ));
        }
    }
}

fn split_request<'a>(b: &'a [f64], t: f64, method: &str) -> impl Fn(&[f64]) -> String + 'a {
    let n = b.len();
    let method = method.to_string();
    move |a: &[f64]| {
        format!(
            r#"{{"op":"split","points":{},"t":{},"method":"{method}","approx":{{"left":{},"right":{}}}}}"#,
            points(b),
            fj(t),
            points(&a[..n]),
            points(&a[n..])
        )
    }
}

#[test]
fn every_ops_bound_holds_on_the_edge_cases_and_catches_answers_moved_past_it() {
    let mut rng = rng::Rng(0x5EED_F10A7);
    let names = ["split de_casteljau", "split lerp", "elevate", "derivative", "to_bezier"];
    let mut tallies: Vec<Tally> = names.iter().map(|_| Tally::default()).collect();
    let cases: usize = std::env::var("FLOAT_OPS_CASES").map_or(10_000, |v| v.parse().unwrap());
    for i in 0..cases {
        let (_family, b, t) = edges::case(&mut rng, i);
        // every case judged; every fourth, whose families cycle with period 6, also moved
        let move_too = i % 4 == 0;
        let n = b.len() - 1;
        for (k, method) in ["de_casteljau", "lerp"].iter().enumerate() {
            let (l, r) = if k == 0 { split_convex(&b, t) } else { split_lerp(&b, t) };
            let ours: Vec<f64> = l.into_iter().chain(r).collect();
            judge(
                &mut tallies[k],
                &ours,
                &split_request(&b, t, method),
                names[k],
                move_too,
            );
        }
        let by = 1 + i % 3;
        let ours = elevate(&b, by, i % 2 == 1);
        let request = |a: &[f64]| {
            format!(
                r#"{{"op":"elevate","points":{},"by":{by},"approx":{}}}"#,
                points(&b),
                points(a)
            )
        };
        judge(&mut tallies[2], &ours, &request, names[2], move_too);
        let order = (1 + i % 3).min(n);
        let ours = derivative(&b, order);
        let request = |a: &[f64]| {
            format!(
                r#"{{"op":"derivative","points":{},"order":{order},"method":"differences","approx":{}}}"#,
                points(&b),
                points(a)
            )
        };
        judge(&mut tallies[3], &ours, &request, names[3], move_too);
        let ours = to_bezier(&b);
        let power = format!("[[{}]]", b.iter().map(|x| fj(*x)).collect::<Vec<_>>().join(","));
        let request = |a: &[f64]| format!(r#"{{"op":"to_bezier","power":{power},"approx":{}}}"#, points(a));
        judge(&mut tallies[4], &ours, &request, names[4], move_too);
    }
    let mut report = String::new();
    for (name, t) in names.iter().zip(&tallies) {
        report.push_str(&format!(
            "{name}: {} judged, {} outside, {} overflowed, {} moved, {} caught, {} unbounded, {:.1} s\n",
            t.judged, t.outside, t.overflowed, t.moved, t.moved_caught, t.unbounded, t.seconds
        ));
        for f in &t.failures {
            report.push_str(&format!("  {f}\n"));
        }
    }
    println!("{report}");
    for t in &tallies {
        assert_eq!(t.outside, 0, "{report}");
        assert_eq!(t.moved, t.moved_caught, "{report}");
        // the cases reach the ops: tens of thousands of coordinates each, a fourth moved
        assert!(
            cases < 10_000 || (t.judged > 30_000 && t.moved * 5 > t.judged),
            "{report}"
        );
    }
}

#[test]
fn the_shapes_and_errors_of_judged_answers() {
    let ask = |line: &str| -> Value { serde_json::from_str(&handle_line(line)).unwrap() };
    // without approx or method: the exact answer, byte for byte as before
    let plain = r#"{"op":"split","points":[[0],[1],[3]],"t":"1/2"}"#;
    assert_eq!(
        handle_line(plain),
        r#"{"left":[["0"],["1/2"],["5/4"]],"ok":true,"right":[["5/4"],["2"],["3"]]}"#
    );
    // method alone: the bounds and condition, no verdict
    let r = ask(r#"{"op":"elevate","points":[[0.1,1],[0.7,2]],"by":2,"method":"formula"}"#);
    assert_eq!(r["bound"].as_array().unwrap().len(), 4, "{r}");
    assert_eq!(r["bound"][0], serde_json::json!([0.0, 0.0]), "{r}");
    assert!(r.get("within_bound").is_none() && r.get("ulps").is_none(), "{r}");
    assert!(r["condition"][1][0].as_f64().unwrap() >= 1.0, "{r}");
    // inputs that are no floats: ulps, no bound
    let r = ask(r#"{"op":"derivative","points":[["1/3"],[1]],"order":1,"approx":[[0.6666666666666667]]}"#);
    assert_eq!(r["ulps"], serde_json::json!([[1]]), "{r}");
    assert!(r.get("bound").is_none(), "{r}");
    for (line, needle) in [
        (
            r#"{"op":"split","points":[[0],[1]],"t":0.5,"approx":[[0],[1]]}"#,
            "\"left\"",
        ),
        (
            r#"{"op":"split","points":[[0],[1]],"t":0.5,"approx":{"left":[[0],[0.5]],"right":[[0.5]]}}"#,
            "expected 2 points",
        ),
        (
            r#"{"op":"elevate","points":[[0],[1]],"by":1,"approx":[[0],[0.5],[1, 2]]}"#,
            "dimension mismatch",
        ),
        (
            r#"{"op":"elevate","points":[[0],[1]],"by":1,"approx":[[0],["x"],[1]]}"#,
            "point 1",
        ),
        (
            r#"{"op":"derivative","points":[[0],[1]],"order":1,"method":"forward"}"#,
            "unknown method",
        ),
        (r#"{"op":"to_bezier","power":[[0,1]],"method":3}"#, "must be a string"),
        (
            r#"{"op":"derivative","points":[[0],[1]],"order":1,"t":0,"approx":[[1]]}"#,
            "leave out 't'",
        ),
    ] {
        let r = ask(line);
        assert_eq!(r["ok"], false, "{line}");
        assert!(r["error"].as_str().unwrap().contains(needle), "{line}: {r}");
    }
    // an overflowed float answer is judged as such
    let r = ask(r#"{"op":"derivative","points":[[-1e308],[1e308]],"order":1,"approx":[["inf"]]}"#);
    assert_eq!(r["within_bound"], serde_json::json!([[true]]), "{r}");
    assert!(
        r["verdict"][0][0].as_str().unwrap().starts_with("correctly rounded"),
        "{r}"
    );
    let r = ask(r#"{"op":"split","points":[[1],[2]],"t":0.5,"approx":{"left":[[1],["nan"]],"right":[[1.5],[2]]}}"#);
    assert_eq!(r["within_bound"]["left"], serde_json::json!([[true], [false]]), "{r}");
    assert!(r["verdict"]["right"][0][0].is_null(), "{r}");
    // the work estimate counts the judging: a judged split costs more than the plain one
    let req = |s: &str| {
        casteljau::oracle::Op::from_json(&serde_json::from_str(s).unwrap())
            .unwrap()
            .work()
    };
    let plain = req(r#"{"op":"split","points":[[0.1],[0.7],[0.3]],"t":0.3}"#);
    let judged = req(r#"{"op":"split","points":[[0.1],[0.7],[0.3]],"t":0.3,"method":"lerp"}"#);
    assert!(judged > 2.0 * plain, "{plain} {judged}");
    let _ = BigRational::zero();
}
