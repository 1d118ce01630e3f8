//! The float oracle at the edges of the f64 range: random and adversarial cases (subnormal
//! coefficients, tiny t, coefficients near 1e308, near-cancellation, mixed scales), each
//! judged with every method (convex and lerp de Casteljau, Horner, Bernstein sum,
//! compensated). Prints how many answers fell outside their bound (decided exactly) or
//! outside the bound's derived formula (in rationals), how many intervals missed the exact
//! value, and how many filtered orientations disagreed with the exact predicate.
//!
//! `cargo run --release --example float_edges [cases] [every]` (default 10,000 cases, the
//! formulas checked in rationals on every 10th); exits 1 on any failure.

#[path = "../tests/support/float_edges.rs"]
mod edges;
#[path = "../tests/support/rng.rs"]
mod rng;

fn main() {
    let cases = std::env::args()
        .nth(1)
        .map(|s| s.parse().expect("the number of cases"))
        .unwrap_or(10_000);
    let every = std::env::args()
        .nth(2)
        .map(|s| s.parse().expect("how often to check the formulas"))
        .unwrap_or(10);
    let counts = edges::run(0x5EED_F10A7, cases, every);
    print!("{}", counts.report());
    if !counts.ok() {
        std::process::exit(1);
    }
}
