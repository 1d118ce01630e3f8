//! The certificate-search reproducers of issue 27: binomial identities in five integer
//! symbols with open ranges (a 361-byte one once ran 233 s and took 1.77 GB). Each must end
//! with a verdict or one line saying what stopped it (a limit, named, or why the symbolic
//! proof does not go through) — never `fails` (they are true) — and within seconds. The CPU bound here is generous (20 s of the thread's CPU, for a loaded machine
//! and a debug build); `/usr/bin/time` figures are in docs/limits.md.

use casteljau::verify::claims::parse_file;
use casteljau::verify::{check_claim, Verdict};
use std::path::Path;
use std::time::Duration;

#[path = "support/cpu.rs"]
mod cpu;
use cpu::thread_cpu;

const FIVE: &str = "for = [\"a = 0..\", \"b = 0..\", \"c = 0..\", \"m = 0..\", \"n = 0..\"]\n";

/// The verdict, or the error, of an identity claim `lhs = rhs` over the five open ranges.
fn check(lhs: &str, rhs: &str) -> Result<Verdict, String> {
    let text = format!(
        "[[claim]]\nid = \"r\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\n{FIVE}lhs = \"{lhs}\"\nrhs = \"{rhs}\"\n"
    );
    let file = parse_file(&text, Path::new("reproducer.toml")).unwrap();
    let start = thread_cpu();
    let out = check_claim(&file.claim[0], false);
    let cpu = thread_cpu() - start;
    assert!(cpu < Duration::from_secs(20), "{lhs} = {rhs}: {cpu:?} of CPU");
    match out {
        Ok(c) => Ok(c.verdict()),
        Err(e) => {
            let e = e.to_string();
            assert!(!e.contains('\n'), "one line: {e}");
            Err(e)
        }
    }
}

fn assert_true_claim_ends(lhs: &str, rhs: &str) {
    match check(lhs, rhs) {
        Ok(v) => assert_eq!(v, Verdict::Proved, "{lhs} = {rhs}"),
        // A limit reached, or a reason the symbolic proof does not go through (a term
        // undefined on part of the domain): one line, checked in `check`.
        Err(e) => assert!(!e.is_empty(), "{lhs} = {rhs}"),
    }
}

#[test]
fn vandermonde_with_five_symbols_in_its_arguments_is_proved() {
    assert_true_claim_ends("sum(k, 0, n, C(a+c, k)*C(b+m, n-k))", "C(a+b+c+m, n)");
}

#[test]
fn a_sum_with_a_third_binomial_ends_with_a_verdict_or_a_named_limit() {
    assert_true_claim_ends(
        "sum(k, 0, n, C(a, k)*C(b, n-k)*C(c+k, m))",
        "sum(k, 0, n, C(b, n-k)*C(a, k)*C(c+k, m))",
    );
}

#[test]
fn vandermonde_times_a_free_binomial_ends() {
    assert_true_claim_ends("sum(k, 0, n, C(a, k)*C(b, n-k))*C(c, m)", "C(a+b, n)*C(c, m)");
}

#[test]
fn two_splittings_of_one_vandermonde_sum_end() {
    assert_true_claim_ends(
        "sum(k, 0, n, C(a+b, k)*C(c+m, n-k))",
        "sum(k, 0, n, C(a+c, k)*C(b+m, n-k))",
    );
}

#[test]
fn a_sum_against_a_sum_over_another_variable_ends() {
    assert_true_claim_ends(
        "sum(k, 0, n, C(n, k)*C(a+k, m)*C(b, c))",
        "sum(j, 0, m, C(n, j)*C(a, m-j)*2^(n-j))*C(b, c)",
    );
}

#[test]
fn a_summand_with_a_shifted_upper_argument_ends() {
    assert_true_claim_ends("sum(k, 0, n, C(a, k)*C(b, n-k)*C(a+b-n, c))", "C(a+b, n)*C(a+b-n, c)");
}

#[test]
fn a_partial_vandermonde_with_a_vanishing_factor_ends() {
    // For n < m both sides are 0 through C(c, n − m); the prover may say so or name what
    // stopped it.
    assert_true_claim_ends("sum(k, 0, n, C(a, k)*C(b, m-k)*C(c, n-m))", "C(a+b, m)*C(c, n-m)");
}

/// The verdict or error of `lhs = rhs` for every n ≥ 0 in the parameters `vars`, and the
/// thread's CPU time it took.
fn check_in(vars: &str, lhs: &str, rhs: &str) -> (Result<Verdict, String>, Duration) {
    let text = format!(
        "[[claim]]\nid = \"r\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nfor = [\"n = 0..\"]\nvars = [{vars}]\nlhs = \"{lhs}\"\nrhs = \"{rhs}\"\n"
    );
    let file = parse_file(&text, Path::new("reproducer.toml")).unwrap();
    let start = thread_cpu();
    let out = check_claim(&file.claim[0], false);
    (
        out.map(|c| c.verdict()).map_err(|e| e.to_string()),
        thread_cpu() - start,
    )
}

/// Binomial theorems in five and six parameters (issue 41): the WZ ansatz built its equations
/// as products of rational functions with every common factor kept, 4.6 s to 39.6 s and up to
/// 1.45 GB each. Each must end within 5 s of CPU (a release build; ten times that in a debug
/// build), with `proved` or a one-line error, never `fails`.
#[test]
fn binomial_theorems_in_five_and_six_parameters_end_within_seconds() {
    let limit = Duration::from_secs(if cfg!(debug_assertions) { 50 } else { 5 });
    let five = r#""s", "t", "u", "v", "w""#;
    let six = r#""s", "t", "u", "v", "w", "x""#;
    let cases = [
        (five, "s*t + t*u + u*v + v*w + w*s + 3", "s*t*u*v*w + s*t*u + 2"),
        (
            five,
            "s*t + t*u + u*v + v*w + w*s + s*u + t*v + 3",
            "s*t*u*v*w + s*t*u + u*v*w + 2",
        ),
        (five, "(s + t + u + v + w + 1)^3", "(s*t*u*v*w + 2)^2"),
        (
            six,
            "s*t + t*u + u*v + v*w + w*x + x*s + 3",
            "s*t*u*v*w*x + s*t*u + v*w*x + 2",
        ),
    ];
    for (vars, x, y) in cases {
        let lhs = format!("sum(k, 0, n, C(n, k)*({x})^k*({y})^(n-k))");
        let rhs = format!("({x} + {y})^n");
        let (out, cpu) = check_in(vars, &lhs, &rhs);
        assert!(cpu < limit, "{lhs} = {rhs}: {cpu:?} of CPU");
        match out {
            Ok(v) => assert_eq!(v, Verdict::Proved, "{lhs} = {rhs}"),
            Err(e) => assert!(!e.is_empty() && !e.contains('\n'), "{lhs} = {rhs}: {e}"),
        }
    }
    // The one found within the limits is proved.
    let (out, _) = check_in(five, "sum(k, 0, n, C(n, k)*(s*t)^k*(u*v*w)^(n-k))", "(s*t + u*v*w)^n");
    assert_eq!(out, Ok(Verdict::Proved));
}
