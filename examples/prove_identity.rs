//! Prove your own identity from Rust: the same claim and verdict as
//! `casteljau prove --identity "sum(k, 0, n, C(n, k)) = 2^n" --for "n = 0.."`.
//!
//! `cargo run --example prove_identity`

use casteljau::verify::{identity_file, prove_files, Verdict};

/// The verdict and its certificate (or counterexample) for `lhs = rhs` over `ranges`.
fn check(identity: &str, ranges: &[&str]) -> (Verdict, String) {
    let ranges: Vec<String> = ranges.iter().map(|r| r.to_string()).collect();
    let file = identity_file(identity, &ranges, None).expect("a well-formed identity");
    let report = prove_files(&[file], &mut |_, _, _| {}).expect("decided");
    let outcome = &report.outcomes[0];
    (outcome.verdict, outcome.certificate.clone())
}

fn main() {
    for (identity, ranges) in [
        ("sum(k, 0, n, C(n, k)) = 2^n", &["n = 0.."][..]),
        ("B(1, 2, t) = 2t(1 - t)", &[][..]),
        ("sum(k, 0, n, C(n, k)) = 3^n", &["n = 0.."][..]),
    ] {
        let (verdict, why) = check(identity, ranges);
        println!("{identity}: {}\n    {why}", verdict.as_str());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_true_identity_is_proved_for_every_n_and_a_false_one_fails() {
        let (v, why) = check("sum(k, 0, n, C(n, k)) = 2^n", &["n = 0.."]);
        assert_eq!(v, Verdict::Proved);
        assert!(why.starts_with("for every n ≥ 0"), "{why}");
        let (v, why) = check("sum(k, 0, n, C(n, k)) = 3^n", &["n = 0.."]);
        assert_eq!(v, Verdict::Fails);
        assert_eq!(why, "at n = 1: left side = 2, right side = 3");
        assert_eq!(check("B(1, 2, t) = 2t(1 - t)", &[]).0, Verdict::Proved);
    }
}
