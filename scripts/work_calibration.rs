//! Calibrates the oracle's work estimate: for each JSON request line on stdin, prints the
//! estimate (`Op::work`), the real time of `Op::run`, and their ratio in units per second.
//! The estimate is meant to bound real time: `MAX_REQUEST_WORK` units should take a few seconds.
//!
//! `cargo run --release --example work_calibration < requests.jsonl`

use casteljau::oracle::{Op, MAX_REQUEST_WORK};
use std::io::BufRead;
use std::time::Instant;

fn main() {
    for line in std::io::stdin().lock().lines() {
        let line = line.expect("readable input");
        let request: serde_json::Value = serde_json::from_str(&line).expect("a JSON request");
        let op = match Op::from_json(&request) {
            Ok(op) => op,
            Err(e) => {
                println!("refused: {}", e);
                continue;
            }
        };
        let work = op.work();
        let start = Instant::now();
        let ok = op.run().is_ok();
        let secs = start.elapsed().as_secs_f64();
        println!(
            "{} work {work:.3e} ({:.3} of MAX_REQUEST_WORK), {secs:.3} s, {:.2e} units/s, ok {ok}",
            request["op"],
            work / MAX_REQUEST_WORK,
            work / secs
        );
    }
}
