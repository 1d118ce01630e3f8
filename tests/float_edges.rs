//! The float oracle at the edges of the f64 range: 10,000 random and adversarial cases
//! (subnormal coefficients, tiny t, coefficients near 1e308, near-cancellation, mixed
//! scales), each judged with every method. No float answer may fall outside its bound
//! (decided exactly) or outside its derived formula (in rationals), no interval may miss the
//! exact value, and every filtered orientation must be the exact one. The same run with a
//! printed table: `cargo run --release --example float_edges`.

#[path = "support/float_edges.rs"]
mod edges;
#[path = "support/rng.rs"]
mod rng;

use casteljau::float::{a_priori_bound, compensated_de_casteljau, de_casteljau, error_at_most, eval_dyadic};
use casteljau::oracle::handle_line;
use casteljau::{filtered_hull_contains, filtered_orientation, Interval};
use casteljau::{BezierCurve, BigRational, Scalar};
use serde_json::Value;
use std::cmp::Ordering;

#[test]
fn ten_thousand_edge_cases_hold_every_bound() {
    let counts = edges::run(0x5EED_F10A7, 10_000, 100);
    println!("{}", counts.report());
    assert!(counts.ok(), "{}", counts.report());
    assert_eq!(counts.cases, 10_000);
    // the families do reach the edges: some lerp and Horner answers overflow near 1e308
    assert!(counts.judged.iter().all(|&j| j > 8_000), "{}", counts.report());
    assert!(
        counts.overflowed[1] > 0 && counts.overflowed[2] > 0,
        "{}",
        counts.report()
    );
}

fn ask(line: &str) -> Value {
    serde_json::from_str(&handle_line(line)).unwrap()
}

#[test]
fn the_issues_reproducers_give_correct_answers() {
    // subnormal coefficients: the bound includes underflow
    let b = [3e-323, 2e-323, 3.5e-323];
    let exact = eval_dyadic(
        &BezierCurve::from_coords(b.iter().map(|x| vec![BigRational::from_f64(*x).unwrap()]).collect()).unwrap(),
        &BigRational::from_f64(0.3).unwrap(),
    )
    .unwrap()
    .coords()[0]
        .clone();
    assert!(error_at_most(de_casteljau(&b, 0.3), &exact, a_priori_bound(&b, 0.3)));
    let (c, e) = compensated_de_casteljau(&b, 0.3);
    assert!(error_at_most(c, &exact, e));
    // a product that underflows: the interval still encloses
    let r = ask(r#"{"op":"float_eval","method":"interval","points":[[5e-324],[0]],"t":0.5}"#);
    assert_eq!(r["encloses"], serde_json::json!([true]), "{r}");
    assert_eq!(
        filtered_orientation([0.0, 0.0], [1e-200, 0.0], [0.0, 1e-200]).unwrap(),
        Ordering::Greater
    );
    assert_eq!(
        filtered_orientation([0.0, 0.0], [0.0, 1e-200], [1e-200, 0.0]).unwrap(),
        Ordering::Less
    );
    let tiny = Interval::from_f64(1e-200).unwrap();
    let sq = tiny * tiny;
    assert!(sq.lo() == 0.0 && sq.hi() > 0.0, "{sq}");
    // large finite inputs with every method
    for method in ["de_casteljau", "lerp", "horner", "bernstein", "compensated", "interval"] {
        let r = ask(&format!(
            r#"{{"op":"float_eval","points":[[1e308],[-1e308]],"t":0.3,"method":"{method}"}}"#
        ));
        assert_eq!(r["ok"], true, "{method}: {r}");
        if method == "lerp" || method == "horner" {
            // lerp's b − a and Horner's power coefficients overflow: the answer is judged
            assert!(
                r["verdict"][0].as_str().unwrap().starts_with("overflow"),
                "{method}: {r}"
            );
        } else {
            assert_eq!(r["within_bound"], serde_json::json!([true]), "{method}: {r}");
        }
    }
    // an overflowed answer is judged as such
    let r = ask(r#"{"op":"eval","points":[[7e307],[7e307],[7e307],[7e307],[7e307],[7e307]],"t":0.5,"approx":["inf"]}"#);
    assert_eq!(r["within_bound"], serde_json::json!([false]), "{r}");
    assert!(r["verdict"][0].as_str().unwrap().starts_with("overflow"), "{r}");
    let r = ask(r#"{"op":"eval","points":[["1e400"]],"t":0,"approx":["inf"]}"#);
    assert_eq!(r["ulps"], serde_json::json!([0]), "{r}");
    let r = ask(r#"{"op":"eval","points":[[1]],"t":0,"approx":["nan"]}"#);
    assert!(r["verdict"][0].as_str().unwrap().starts_with("nan"), "{r}");
}

#[test]
fn filtered_predicates_are_exact_at_the_edges() {
    let square = [[0.0, 0.0], [1e-300, 0.0], [1e-300, 1e-300], [0.0, 1e-300]];
    assert!(filtered_hull_contains(&square, [5e-301, 5e-301]).unwrap());
    assert!(!filtered_hull_contains(&square, [2e-300, 5e-301]).unwrap());
    let sub = [[0.0, 0.0], [4e-323, 0.0], [0.0, 4e-323]];
    assert!(filtered_hull_contains(&sub, [1e-323, 1e-323]).unwrap());
    assert!(!filtered_hull_contains(&sub, [3e-323, 3e-323]).unwrap());
    let big = [[-1e308, -1e308], [1e308, -1e308], [0.0, 1e308]];
    assert!(filtered_hull_contains(&big, [0.0, 0.0]).unwrap());
    assert!(!filtered_hull_contains(&big, [1e308, 1e308]).unwrap());
    // quotients that underflow are rounded outward too
    let q = Interval::from_f64(1e-300)
        .unwrap()
        .checked_div(&Interval::from_f64(1e100).unwrap())
        .unwrap();
    assert!(q.contains(&(BigRational::from_f64(1e-300).unwrap() / BigRational::from_f64(1e100).unwrap())));
    assert!(q.lo() < q.hi(), "{q}");
}

#[test]
fn batches_and_methods_answer_per_parameter() {
    let r = ask(
        r#"{"op":"eval","points":[[0.1],[0.7],[0.3]],"t":[0.25,0.5,"1/3"],"method":"lerp","approx":[[0.3375],[0.45],[0.4]]}"#,
    );
    let results = r["results"].as_array().unwrap();
    assert_eq!(results.len(), 3);
    assert_eq!(results[0]["within_bound"], serde_json::json!([true]), "{r}");
    assert_eq!(results[0]["method"], "lerp");
    assert!(results[0]["condition"][0].as_f64().unwrap() >= 1.0);
    // no float parameter, no bound
    assert!(results[2].get("bound").is_none(), "{r}");
    let r = ask(r#"{"op":"float_eval","points":[[0.1],[0.7]],"t":[0.25,"1/3"]}"#);
    assert!(r["error"].as_str().unwrap().contains("parameter 1"), "{r}");
    let many: Vec<String> = (0..5000).map(|i| format!("{}", i as f64 / 5000.0)).collect();
    let r = ask(&format!(
        r#"{{"op":"eval","points":[[0],[1]],"t":[{}]}}"#,
        many.join(",")
    ));
    assert!(r["error"].as_str().unwrap().contains("4096"), "{r}");
    // the work limit counts the whole batch
    let pts: Vec<String> = (0..=300).map(|i| format!("[{}]", (i * 7919) % 1000)).collect();
    // at a float parameter the integers run the dyadic kernel, the costlier one
    let one = format!(r#"{{"op":"eval","points":[{}],"t":0.1}}"#, pts.join(","));
    let work = casteljau::oracle::Op::from_json(&serde_json::from_str(&one).unwrap())
        .unwrap()
        .work();
    let fits = (casteljau::oracle::MAX_REQUEST_WORK / work) as usize;
    assert!((1..4000).contains(&fits), "{work}");
    let batch = |count: usize| {
        let ts = vec!["0.1"; count];
        ask(&format!(
            r#"{{"op":"eval","points":[{}],"t":[{}]}}"#,
            pts.join(","),
            ts.join(",")
        ))
    };
    let r = batch(fits + 1);
    assert!(r["error"].as_str().unwrap().contains("batch"), "{r}");
    assert_eq!(batch(1)["ok"], true);
    let r = ask(r#"{"op":"eval","points":[[0.1],[0.7]],"t":0.5,"method":"bogus"}"#);
    assert!(r["error"].as_str().unwrap().contains("unknown method"), "{r}");
}

#[test]
fn each_method_bound_is_the_bound_of_that_method() {
    // a caller's lerp answer near t = 1 errs more than de Casteljau's convex form allows
    // somewhere; the lerp bound always covers it (counted over the edge run above), and
    // the bounds differ: lerp's weights are larger
    let b = [1.0, -1.0, 1.0, -1.0];
    let t = 0.9;
    let de = casteljau::oracle::FloatMethod::DeCasteljau.bound(&b, t, 0.0);
    let lerp = casteljau::oracle::FloatMethod::Lerp.bound(&b, t, 0.0);
    assert!(lerp > de, "{lerp} {de}");
    assert!(Scalar::to_f64(&BigRational::from_f64(lerp).unwrap()) > 0.0);
}

#[test]
fn predicates_refuse_points_that_are_not_finite() {
    for bad in [f64::INFINITY, f64::NEG_INFINITY, f64::NAN] {
        assert!(filtered_orientation([0.0, 0.0], [bad, 0.0], [0.0, 1.0]).is_err());
        assert!(filtered_hull_contains(&[[0.0, 0.0], [1.0, 0.0], [0.0, bad]], [0.1, 0.1]).is_err());
        assert!(filtered_hull_contains(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], [bad, 0.1]).is_err());
    }
}
