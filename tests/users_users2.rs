//! Issue 46, users' own claims: identities from the books a user checks (Farin, *Curves and
//! Surfaces for CAGD*; Prautzsch–Boehm–Paluszny, *Bézier and B-Spline Techniques*), proved for
//! every n within 2 s of CPU each, and false variants of them that never end `proved`.
//! A section per class of the issue: 5 (integrals) and 9 (speed).

#[path = "support/cpu.rs"]
mod cpu;

use casteljau::verify::claims::parse_file;
use casteljau::verify::{check_claim, Verdict};
use cpu::thread_cpu;
use std::path::Path;
use std::time::Duration;

/// The most CPU one claim of this file may take.
const CLAIM_CPU: Duration = Duration::from_secs(2);

/// The verdict (or the error) of the identity `lhs = rhs` over `ranges`, asserting that it took
/// at most [`CLAIM_CPU`] of the thread's CPU.
fn verdict(lhs: &str, rhs: &str, ranges: &[&str]) -> Result<Verdict, String> {
    let ranges: Vec<String> = ranges.iter().map(|r| format!("\"{r}\"")).collect();
    let text = format!(
        "[[claim]]\nid = \"u\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nfor = [{}]\nlhs = \"{lhs}\"\nrhs = \"{rhs}\"\n",
        ranges.join(", ")
    );
    let file = parse_file(&text, Path::new("users2.toml")).unwrap();
    let start = thread_cpu();
    let out = check_claim(&file.claim[0], false);
    let cpu = thread_cpu() - start;
    assert!(cpu <= CLAIM_CPU, "{lhs} = {rhs}: {cpu:?} of CPU");
    match out {
        Ok(c) if c.range().is_some() => Err(format!("proved only in range: {}", c.certificate)),
        Ok(c) => Ok(c.verdict()),
        Err(e) => Err(e.to_string()),
    }
}

fn assert_proved(lhs: &str, rhs: &str, ranges: &[&str]) {
    let v = verdict(lhs, rhs, ranges);
    assert!(v == Ok(Verdict::Proved), "{lhs} = {rhs}: {v:?}");
}

/// A false claim: `fails` or an error, never `proved`.
fn assert_not_proved(lhs: &str, rhs: &str, ranges: &[&str]) {
    let v = verdict(lhs, rhs, ranges);
    assert!(matches!(v, Ok(Verdict::Fails) | Err(_)), "{lhs} = {rhs}: {v:?}");
}

/// The verdict `fails` (a counterexample within the refutation window).
fn assert_fails(lhs: &str, rhs: &str, ranges: &[&str]) {
    let v = verdict(lhs, rhs, ranges);
    assert!(v == Ok(Verdict::Fails), "{lhs} = {rhs}: {v:?}");
}

// ---- class 9: speed ----------------------------------------------------------------------

const CUBIC: &str = "n*(n-1)*(n-2)*t^3 + 3*n*(n-1)*t^2 + n*t";

#[test]
fn class9_moments_of_the_bernstein_basis_are_proved_quickly() {
    // The moments Σ_i i^k B_i^n(t) (Farin, ch. 5, degree elevation and the linear precision
    // Σ (i/n) B_i^n = t; PBP §2.3): creative telescoping of order 2 with cubic coefficients
    // took 10.8 s of CPU before the lifted linear solve.
    assert_proved("sum(i, 0, n, i^3*B(i, n, t))", CUBIC, &["n = 0.."]);
    assert_proved("sum(i, 0, n, i^2*B(i, n, t))", "n*(n-1)*t^2 + n*t", &["n = 0.."]);
    // The factorial moments Σ_i C(i, 3) B_i^n(t) = C(n, 3) t³ (PBP §2.3, derivatives at 0).
    assert_proved("sum(i, 0, n, C(i, 3)*B(i, n, t))", "C(n, 3)*t^3", &["n = 0.."]);
}

#[test]
fn class9_false_moments_end_quickly_and_are_never_proved() {
    // Wrong only from n = 50 on (past the 41 values of the refutation window): an error.
    assert_not_proved(
        "sum(i, 0, n, i^3*B(i, n, t))",
        &format!("{CUBIC} + C(n, 50)*t"),
        &["n = 0.."],
    );
    assert_not_proved(
        "sum(i, 0, n, i^3*B(i, n, t))",
        &format!("{CUBIC} + C(n, 45)*t^2"),
        &["n = 0.."],
    );
    // Wrong at n = 2 (a zero of n(n−1)(n−2)): fails.
    assert_fails(
        "sum(i, 0, n, i^3*B(i, n, t))",
        "n*(n-1)*t^3 + 3*n*(n-1)*t^2 + n*t",
        &["n = 0.."],
    );
    // Wrong coefficient: fails at the first n where it shows.
    assert_fails(
        "sum(i, 0, n, i^3*B(i, n, t))",
        "n*(n-1)*(n-2)*t^3 + 2*n*(n-1)*t^2 + n*t",
        &["n = 0.."],
    );
}

// ---- class 5: integrals ------------------------------------------------------------------

#[test]
fn class5_integrals_where_an_exponent_is_negative_only_where_its_coefficient_vanishes() {
    // ∫_0^1 (B_i^n)'(t) dt = B_i^n(1) − B_i^n(0) (Farin ch. 5, the derivative of a Bernstein
    // polynomial n(B_{i−1}^{n−1} − B_i^{n−1})): the term (n − i)·(1 − t)^(n−i−1) has the
    // exponent −1 only at i = n, where it is 0.
    assert_proved(
        "integral(diff(B(i, n, t), t), t, 0, 1)",
        "B(i, n, 1) - B(i, n, 0)",
        &["n = 1..", "i = 0..=n"],
    );
    // The same on the interior indices, where both ends vanish.
    assert_proved(
        "integral(diff(B(i, n, t), t), t, 0, 1)",
        "0",
        &["n = 2..", "i = 1..=n-1"],
    );
    // The second derivative's integral is the first derivative's change, (B_i^n)' =
    // n(B_{i−1}^{n−1} − B_i^{n−1}) (Farin ch. 5): the exponents −2 and −1 of 1 − t at i = n and
    // i = n − 1, where the coefficient (n − i)(n − i − 1) vanishes.
    assert_proved(
        "integral(diff(B(i, n, t), t, 2), t, 0, 1)",
        "n*(B(i-1, n-1, 1) - B(i, n-1, 1) - B(i-1, n-1, 0) + B(i, n-1, 0))",
        &["n = 2..", "i = 0..=n"],
    );
}

#[test]
fn class5_integrands_with_t_to_the_minus_one() {
    // ∫_0^1 B_i^n(t)/t dt = 1/i for i ≥ 1 and ∫_0^1 B_i^n(t)/(1 − t) dt = 1/(n − i) for i < n
    // (the Beta integral, PBP §2.2; the evaluation cross-check divides exactly).
    assert_proved("integral(t^(-1)*B(i, n, t), t, 0, 1)", "1/i", &["n = 1..", "i = 1..=n"]);
    assert_proved(
        "integral((1-t)^(-1)*B(i, n, t), t, 0, 1)",
        "1/(n-i)",
        &["n = 1..", "i = 0..=n-1"],
    );
}

#[test]
fn class5_false_integrals_are_never_proved() {
    // The derivative's integral is not 0 at the end indices.
    assert_fails("integral(diff(B(i, n, t), t), t, 0, 1)", "0", &["n = 1..", "i = 0..=n"]);
    // The wrong sign at the ends.
    assert_fails(
        "integral(diff(B(i, n, t), t), t, 0, 1)",
        "B(i, n, 0) - B(i, n, 1)",
        &["n = 1..", "i = 0..=n"],
    );
    // Off by one in the Beta value.
    assert_fails(
        "integral(t^(-1)*B(i, n, t), t, 0, 1)",
        "1/(i+1)",
        &["n = 1..", "i = 1..=n"],
    );
    // Divergent at i = 0: never proved.
    assert_not_proved("integral(t^(-1)*B(i, n, t), t, 0, 1)", "1/i", &["n = 1..", "i = 0..=n"]);
    assert_not_proved(
        "integral((1-t)^(-1)*B(i, n, t), t, 0, 1)",
        "1/(n-i)",
        &["n = 1..", "i = 0..=n"],
    );
    // Wrong only from n = 45 on.
    assert_not_proved(
        "integral(t^(-1)*B(i, n, t), t, 0, 1)",
        "1/i + C(n, 45)",
        &["n = 1..", "i = 1..=n"],
    );
}
