//! The casteljau side of `scripts/exact_grid.py`: reads one case a line from stdin, runs the
//! public exact operation on it and prints its CPU time per run and its result.
//!
//! A line is `op <TAB> t <TAB> data`: `op` one of `eval`, `split`, `elevate`, `derivative`,
//! `to_power`, `rational_eval`, `surface_eval`; `t` an exact number (`u = v = t` for the
//! surface; unused by `elevate`, `derivative`, `to_power`); `data` the points in
//! [`casteljau::parse_points`]'s syntax, `points # weights` for `rational_eval`, a net in
//! [`casteljau::parse_net`]'s for `surface_eval`. The answer line is
//! `median_ns <TAB> min_ns <TAB> max_ns <TAB> runs <TAB> result`, the result every output
//! coordinate in order (point by point; `split` left piece then right), separated by spaces.
//!
//! CPU time is the thread's (its CPU clock, to the nanosecond): the median, min and max of
//! five batches' means, each batch repeating the operation for about `BATCH_NS`, after one
//! run that gives the result (the only run, timed by itself, when it took more than ten
//! batches' time).
//!
//! With `--wall REPS`, each batch is instead `REPS` runs timed by the wall clock, nine
//! batches of a number of runs chosen by hand, for comparing two builds on one case side by
//! side on a quiet machine (`exact_grid.py --cases` prints the lines).
//!
//! ```sh
//! cargo run --release --example exact_grid < cases.tsv
//! python3 scripts/exact_grid.py --ops derivative --digits 35 --degrees 50 --cases > case.tsv
//! target/release/examples/exact_grid --wall 1000 < case.tsv | cut -f1-3
//! ```

use casteljau::{format_exact, parse_exact, parse_net, parse_numbers, parse_points};
use casteljau::{BezierCurve, BezierSurface, BigRational, Point, RationalBezierCurve, Result};
use std::io::{BufRead, Write};

const BATCH_NS: u64 = 50_000_000;
const BATCHES: usize = 5;
/// Batches of `--wall`.
const WALL_BATCHES: u64 = 9;

#[path = "../tests/support/cpu.rs"]
mod cpu;

/// The thread's CPU clock, in nanoseconds.
fn cpu_ns() -> u64 {
    cpu::thread_cpu().as_nanos() as u64
}

/// The output coordinates, moved out of the points (a copy would be timed with the operation).
fn coords(points: Vec<Point<BigRational>>) -> Vec<BigRational> {
    points.into_iter().flat_map(Point::into_coords).collect()
}

/// The operation, ready to run: its result as the list of output coordinates.
fn operation(op: &str, t: BigRational, data: &str) -> Result<Box<dyn Fn() -> Vec<BigRational>>> {
    Ok(match op {
        "rational_eval" => {
            let (points, weights) = data.split_once('#').expect("points # weights");
            let c = RationalBezierCurve::new(parse_points(points)?, parse_numbers(weights)?)?;
            Box::new(move || c.eval(&t).expect("a positive weight").into_coords())
        }
        "surface_eval" => {
            let s = BezierSurface::new(parse_net(data)?)?;
            Box::new(move || s.eval(&t, &t).into_coords())
        }
        _ => {
            let c = BezierCurve::new(parse_points(data)?)?;
            match op {
                "eval" => Box::new(move || c.eval(&t).into_coords()),
                "split" => Box::new(move || {
                    let (l, r) = c.split_at(&t);
                    let mut out = coords(l.into_points());
                    out.extend(coords(r.into_points()));
                    out
                }),
                "elevate" => Box::new(move || coords(c.elevate().expect("below the degree limit").into_points())),
                "derivative" => Box::new(move || coords(c.derivative(1).expect("degree ≥ 1").into_points())),
                "to_power" => Box::new(move || coords(c.to_power().expect("below the degree limit"))),
                other => panic!("unknown op {other}"),
            }
        }
    })
}

/// The means of `BATCHES` batches of about `BATCH_NS` each by the thread's CPU time, sorted,
/// and the number of runs (one run of `once` ns alone when that took ten batches' time).
fn cpu_means(run: &dyn Fn() -> Vec<BigRational>, once: u64) -> (Vec<u64>, u64) {
    // The repetitions of a batch are counted by doubling until a tenth of a batch has passed.
    let batches = if once > 10 * BATCH_NS { 0 } else { BATCHES };
    let mut reps = 1u64;
    if batches > 0 {
        loop {
            let start = cpu_ns();
            for _ in 0..reps {
                std::hint::black_box(run());
            }
            let spent = cpu_ns() - start;
            if spent >= BATCH_NS / 10 {
                reps = (reps * BATCH_NS / spent).max(1);
                break;
            }
            reps *= 2;
        }
    }
    let mut means: Vec<u64> = (0..batches)
        .map(|_| {
            let start = cpu_ns();
            for _ in 0..reps {
                std::hint::black_box(run());
            }
            (cpu_ns() - start) / reps
        })
        .collect();
    if means.is_empty() {
        means.push(once);
    }
    means.sort_unstable();
    (means, if batches == 0 { 1 } else { reps * batches as u64 })
}

/// `reps` runs a batch, nine batches by the wall clock: the means, sorted.
fn wall_means(run: &dyn Fn() -> Vec<BigRational>, reps: u64) -> Vec<u64> {
    let mut means: Vec<u64> = (0..WALL_BATCHES)
        .map(|_| {
            let start = std::time::Instant::now();
            for _ in 0..reps {
                std::hint::black_box(run());
            }
            (start.elapsed().as_nanos() / u128::from(reps)) as u64
        })
        .collect();
    means.sort_unstable();
    means
}

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let wall: Option<u64> = match args.get(1).map(String::as_str) {
        Some("--wall") => Some(
            args.get(2)
                .and_then(|r| r.parse().ok())
                .filter(|&r| r > 0)
                .expect("--wall REPS"),
        ),
        _ => None,
    };
    let stdin = std::io::stdin();
    let mut out = std::io::stdout().lock();
    for line in stdin.lock().lines() {
        let line = line.expect("stdin");
        let mut fields = line.splitn(3, '\t');
        let (op, t, data) = (
            fields.next().unwrap_or(""),
            fields.next().unwrap_or(""),
            fields.next().unwrap_or(""),
        );
        let run = operation(op, parse_exact(t)?, data)?;
        let start = cpu_ns();
        let result = std::hint::black_box(run());
        let once = cpu_ns() - start;
        let (means, runs) = match wall {
            Some(reps) => (wall_means(&run, reps), reps * WALL_BATCHES),
            None => cpu_means(&run, once),
        };
        let text: Vec<String> = result.iter().map(format_exact).collect();
        writeln!(
            out,
            "{}\t{}\t{}\t{}\t{}",
            means[means.len() / 2],
            means[0],
            means[means.len() - 1],
            runs,
            text.join(" ")
        )
        .expect("stdout");
        out.flush().expect("stdout");
    }
    Ok(())
}
