//! Bounded work of `prove`: random true claims of growing size — polynomial degree, terms of
//! a sum, digits of the literals, closed and open ranges, integer symbols — and every theorem
//! at growing degrees. Each must end with its verdict (`proved`, `proved_in_range`) or with
//! one line naming the limit that refused it, and nothing may run past the stated budget:
//! the test allows [`CPU_BOUND`] = 5 s of the thread's own CPU time per claim (the largest
//! seen is 1.3 s; the margin is for a loaded 2-core machine, whose shared caches slow a
//! thread's CPU time too).
//!
//! Run with `--nocapture` to see the table of sizes, outcomes and times.

#[path = "support/rng.rs"]
#[allow(dead_code)]
mod rng;

use casteljau::verify::claims::parse_file;
use casteljau::verify::{check_claim, Verdict};
use rng::Rng;
use std::path::Path;
use std::time::Duration;

#[path = "support/cpu.rs"]
mod cpu;
use cpu::thread_cpu;

const CPU_BOUND: Duration = Duration::from_secs(5);

#[derive(Debug, PartialEq)]
enum Outcome {
    Verdict(Verdict),
    Refused(String),
}

/// Checks one claim (the TOML body of a `[[claim]]` without id and source) and returns its
/// outcome and CPU time, asserting the bounds every claim must keep.
fn run(label: &str, body: &str) -> (Outcome, Duration) {
    let text = format!("[[claim]]\nid = \"c\"\nsource = \"s\"\nstatement = \"s\"\n{body}");
    let file = parse_file(&text, Path::new("calibration.toml")).unwrap_or_else(|e| panic!("{label}: {e}\n{text}"));
    let start = thread_cpu();
    let result = check_claim(&file.claim[0], false);
    let cpu = thread_cpu() - start;
    let outcome = match result {
        Ok(c) => Outcome::Verdict(c.verdict()),
        Err(e) => Outcome::Refused(e.to_string()),
    };
    println!("{label:<48} {:>7.2} s  {}", cpu.as_secs_f64(), short(&outcome));
    match &outcome {
        Outcome::Verdict(v) => assert!(
            matches!(v, Verdict::Proved | Verdict::ProvedInRange),
            "{label}: a true claim got {v:?}\n{text}"
        ),
        Outcome::Refused(e) => {
            assert!(!e.contains('\n'), "{label}: the error is one line: {e}");
            assert!(e.contains("limit"), "{label}: the error names its limit: {e}");
        }
    }
    assert!(
        cpu <= CPU_BOUND,
        "{label}: {:.2} s of CPU, past the bound {CPU_BOUND:?} ({outcome:?})\n{text}",
        cpu.as_secs_f64()
    );
    (outcome, cpu)
}

fn short(o: &Outcome) -> String {
    match o {
        Outcome::Verdict(v) => format!("{v:?}"),
        Outcome::Refused(e) => format!("refused: {}", e.chars().take(90).collect::<String>()),
    }
}

/// A random rational `p/q`, `p` of `digits` digits and `q` of one more (ending in 7, so never
/// 1): literals with distinct denominators.
fn rational(rng: &mut Rng, digits: usize) -> String {
    let mut number = || -> String {
        (0..digits)
            .map(|k| {
                let d = (rng.next() % 10) as u8;
                char::from(b'0' + if k == 0 { d % 9 + 1 } else { d })
            })
            .collect()
    };
    let p = number();
    let q = number();
    format!("({p}/{q}7)")
}

/// Every theorem of `kind = "theorem"` (proofs/README.md).
const THEOREMS: [&str; 12] = [
    "de_casteljau_bernstein",
    "partition_of_unity",
    "elevation_7",
    "elevation_8",
    "subdivision",
    "identity_4",
    "derivative",
    "derivative_k",
    "endpoint_tangent",
    "tangent_at_t0",
    "affine_invariance",
    "convex_hull",
];

#[test]
fn random_identities_of_growing_size_end_within_the_budget() {
    let mut rng = Rng(0x5eed_c1a1_b0a7_0001);
    // Polynomial degree, terms of a sum and digits of the literals: the binomial theorem (the
    // evaluator's 64-bit binomials refuse C(100, k) and beyond).
    for degree in [0, 1, 3, 10, 20, 25, 30, 35, 40, 50, 60, 100, 1000] {
        for digits in [1, 5, 10, 20, 30] {
            let (a, b) = (rational(&mut rng, digits), rational(&mut rng, digits));
            run(
                &format!("binomial, degree {degree}, {digits}-digit literals"),
                &format!(
                    "kind = \"identity\"\nlhs = \"({a}*t + {b})^{degree}\"\nrhs = \"sum(k, 0, {degree}, C({degree}, k)*{a}^k*{b}^({degree}-k)*t^k)\"\n"
                ),
            );
        }
    }
    // Closed ranges of growing length, with and without big literals.
    for top in [5, 10, 15, 20, 30, 40, 50, 60, 80, 160] {
        run(
            &format!("Σ B_i^n = 1, n = 0..={top}"),
            &format!(
                "kind = \"identity\"\nfor = [\"n = 0..={top}\"]\nlhs = \"sum(i, 0, n, B(i, n, t))\"\nrhs = \"1\"\n"
            ),
        );
        let a = rational(&mut rng, 30);
        run(
            &format!("Σ C(n,k) a^k t^k, n = 0..={top}, 30 digits"),
            &format!(
                "kind = \"identity\"\nfor = [\"n = 0..={top}\"]\nlhs = \"sum(k, 0, n, C(n, k)*{a}^k*t^k)\"\nrhs = \"(1 + {a}*t)^n\"\n"
            ),
        );
    }
    // Open ranges starting later and later: the base cases and pieces grow with the start.
    for start in [0, 10, 20, 24, 28, 30, 35, 40, 45, 60] {
        run(
            &format!("Σ B_i^n = 1, n = {start}.."),
            &format!(
                "kind = \"identity\"\nfor = [\"n = {start}..\"]\nlhs = \"sum(i, 0, n, B(i, n, t))\"\nrhs = \"1\"\n"
            ),
        );
    }
}

#[test]
fn identities_in_more_and_more_integer_symbols_end_within_the_budget() {
    let names = ["a", "b", "c", "d", "e"];
    for symbols in 2..=5 {
        let ranges: Vec<String> = names[..symbols - 1]
            .iter()
            .chain(std::iter::once(&"n"))
            .map(|v| format!("\"{v} = 0..\""))
            .collect();
        // Vandermonde with the upper arguments split among the symbols: Σ_k C(x, k) C(y, n−k) =
        // C(x + y, n) with x + y the sum of the other symbols.
        let (x, y) = names[..symbols - 1].split_at((symbols - 1).div_ceil(2));
        let (x, y) = (x.join("+"), if y.is_empty() { "0".to_string() } else { y.join("+") });
        run(
            &format!("Vandermonde in {symbols} integer symbols"),
            &format!(
                "kind = \"identity\"\nfor = [{}]\nlhs = \"sum(k, 0, n, C({x}, k)*C({y}, n-k))\"\nrhs = \"C({x}+{y}, n)\"\n",
                ranges.join(", ")
            ),
        );
    }
}

#[test]
fn theorems_at_growing_degrees_end_within_the_budget() {
    // Every degree up to the first refused (the estimate grows with the top degree, so none
    // above is admitted either).
    for theorem in THEOREMS {
        for top in 1..=64 {
            let (outcome, _) = run(
                &format!("{theorem}, degrees up to {top}"),
                &format!("kind = \"theorem\"\ntheorem = \"{theorem}\"\ndegrees = \"1..={top}\"\n"),
            );
            if matches!(outcome, Outcome::Refused(_)) {
                break;
            }
        }
    }
}
