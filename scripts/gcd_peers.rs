//! The Rust side of `scripts/gcd_peers.py`: the CPU time of one gcd of big naturals by
//! casteljau's `exact::gcd::gcd`, dashu-int's `gcd` (on numbers already in its type, so no
//! copies counted) and num-bigint's, on the pairs read from stdin.
//!
//! Input: one group a line, `label <TAB> a,b a,b ...` (decimal). Output: one line per group,
//! `label <TAB> casteljau_ns <TAB> dashu_ns <TAB> num_bigint_ns`, each the median over five
//! interleaved batches of the mean time per gcd, thread CPU time; every gcd is first checked
//! equal to num-bigint's.
//!
//! ```sh
//! python3 scripts/gcd_peers.py
//! ```

use num_bigint::BigUint;
use num_integer::Integer;
use std::hint::black_box;
use std::io::{BufRead, Write};

#[path = "../tests/support/cpu.rs"]
mod cpu;

/// The thread's CPU clock, in nanoseconds.
fn cpu_ns() -> u64 {
    cpu::thread_cpu().as_nanos() as u64
}

/// Mean CPU ns per call of `f` over `reps` calls.
fn mean_ns(reps: u64, pairs: usize, f: &dyn Fn()) -> f64 {
    let start = cpu_ns();
    for _ in 0..reps {
        f();
    }
    (cpu_ns() - start) as f64 / (reps as f64 * pairs as f64)
}

fn main() {
    let mut out = std::io::stdout().lock();
    for line in std::io::stdin().lock().lines() {
        let line = line.expect("stdin");
        let (label, data) = line.split_once('\t').expect("label <TAB> pairs");
        let pairs: Vec<(BigUint, BigUint)> = data
            .split_whitespace()
            .map(|p| {
                let (a, b) = p.split_once(',').expect("a,b");
                (a.parse().expect("a natural"), b.parse().expect("a natural"))
            })
            .collect();
        let dashu: Vec<(dashu_int::UBig, dashu_int::UBig)> = pairs
            .iter()
            .map(|(a, b)| (a.to_string().parse().expect("a"), b.to_string().parse().expect("b")))
            .collect();
        for (a, b) in &pairs {
            assert_eq!(casteljau::exact::gcd::gcd(a, b), a.gcd(b), "{a} {b}");
        }
        let ours = || {
            for (a, b) in &pairs {
                black_box(casteljau::exact::gcd::gcd(black_box(a), black_box(b)));
            }
        };
        let theirs = || {
            for (a, b) in &dashu {
                black_box(dashu_int::ops::Gcd::gcd(black_box(a), black_box(b)));
            }
        };
        let num = || {
            for (a, b) in &pairs {
                black_box(black_box(a).gcd(black_box(b)));
            }
        };
        // Repetitions for about 20 ms of our gcd per batch, counted by doubling.
        let mut reps = 1u64;
        loop {
            let spent = mean_ns(reps, 1, &ours) * reps as f64;
            if spent >= 4e6 {
                reps = ((reps as f64 * 20e6 / spent) as u64).max(1);
                break;
            }
            reps *= 2;
        }
        let mut times: [Vec<f64>; 3] = Default::default();
        for _ in 0..5 {
            for (k, f) in [&ours as &dyn Fn(), &theirs, &num].into_iter().enumerate() {
                times[k].push(mean_ns(reps, pairs.len(), f));
            }
        }
        let median = |v: &mut Vec<f64>| {
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        };
        let [mut a, mut b, mut c] = times;
        writeln!(
            out,
            "{label}\t{:.1}\t{:.1}\t{:.1}",
            median(&mut a),
            median(&mut b),
            median(&mut c)
        )
        .expect("stdout");
        out.flush().expect("stdout");
    }
}
