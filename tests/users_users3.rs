//! Issue 46, users' own claims, classes 2 and 3: identities from Petkovšek–Wilf–Zeilberger's
//! *A = B* and Graham–Knuth–Patashnik's *Concrete Mathematics* whose both sides are sums (two
//! forms of one sequence), and stated recurrences whose right side is no telescoped end
//! (inhomogeneous), proved for every n within 2 s of CPU each by creative telescoping checked
//! in the kernel, and false variants of them that never end `proved`.

#[path = "support/cpu.rs"]
mod cpu;

use casteljau::verify::claims::parse_file;
use casteljau::verify::{check_claim, Verdict};
use cpu::thread_cpu;
use std::path::Path;
use std::time::Duration;

/// The most CPU one claim of this file may take.
const CLAIM_CPU: Duration = Duration::from_secs(2);

/// The verdict and certificate (or the error) of the identity `lhs = rhs` for every `n ≥ 0`,
/// asserting that it took at most [`CLAIM_CPU`] of the thread's CPU.
fn verdict(lhs: &str, rhs: &str) -> Result<(Verdict, String), String> {
    let text = format!(
        "[[claim]]\nid = \"u\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nfor = [\"n = 0..\"]\nlhs = \"{lhs}\"\nrhs = \"{rhs}\"\n"
    );
    let file = parse_file(&text, Path::new("users3.toml")).unwrap();
    let start = thread_cpu();
    let out = check_claim(&file.claim[0], false);
    let cpu = thread_cpu() - start;
    assert!(cpu <= CLAIM_CPU, "{lhs} = {rhs}: {cpu:?} of CPU");
    match out {
        Ok(c) if c.range().is_some() => Err(format!("proved only in range: {}", c.certificate)),
        Ok(c) => Ok((c.verdict(), c.certificate.clone())),
        Err(e) => Err(e.to_string()),
    }
}

/// Proved for every n, by the route whose certificate names `route`.
fn assert_proved(lhs: &str, rhs: &str, route: &str) {
    let v = verdict(lhs, rhs);
    assert!(
        matches!(&v, Ok((Verdict::Proved, c)) if c.contains(route)),
        "{lhs} = {rhs}: {v:?}"
    );
}

/// A false claim: `fails` or an error, never `proved`.
fn assert_not_proved(lhs: &str, rhs: &str) {
    let v = verdict(lhs, rhs);
    assert!(matches!(v, Ok((Verdict::Fails, _)) | Err(_)), "{lhs} = {rhs}: {v:?}");
}

const TWO: &str = "two forms of one sequence";
const INHOMOGENEOUS: &str = "inhomogeneous";

// ---- class 2: sums on both sides with different summands ---------------------------------

/// The central Delannoy numbers D(n) = P_n(3) in their two forms (A = B, §6.3 and exercise 6.1;
/// Concrete Mathematics (5.27)-style sums): Σ_k C(n, k) C(n+k, k) = Σ_k C(n, k)² 2^k.
const DELANNOY: (&str, &str) = ("sum(k, 0, n, C(n, k)*C(n+k, k))", "sum(k, 0, n, C(n, k)^2*2^k)");

#[test]
fn class2_two_forms_of_one_sequence_are_proved() {
    // Order 2: (n+2) D(n+2) − 3(2n+3) D(n+1) + (n+1) D(n) = 0 for both sums.
    assert_proved(DELANNOY.0, DELANNOY.1, TWO);
    // 3^n two ways (the binomial theorem read from both ends, Concrete Mathematics (5.12)).
    assert_proved("sum(k, 0, n, C(n, k)*2^k)", "sum(k, 0, n, C(n, k)*2^(n-k))", TWO);
    // With constant factors on both sides.
    assert_proved(
        "2*sum(k, 0, n, C(n, k)*C(n+k, k))",
        "sum(k, 0, n, 2*C(n, k)^2*2^k)",
        TWO,
    );
    // The Legendre polynomials P_n(2x + 1) in their two forms (A = B, §6.3; Concrete
    // Mathematics §5.2): Σ_k C(n, k) C(n+k, k) x^k = Σ_k C(n, k)² x^k (1+x)^(n−k), a
    // continuous parameter in the coefficients.
    assert_proved(
        "sum(k, 0, n, C(n, k)*C(n+k, k)*x^k)",
        "sum(k, 0, n, C(n, k)^2*x^k*(1+x)^(n-k))",
        TWO,
    );
}

#[test]
fn class2_false_two_forms_are_never_proved() {
    let (l, r) = DELANNOY;
    // Wrong only from n = 50 on (past the refutation window): the ends do not cancel.
    assert_not_proved(l, &format!("{r} + C(n, 50)"));
    assert_not_proved(
        "sum(k, 0, n, C(n, k)*2^k)",
        "sum(k, 0, n, C(n, k)*2^(n-k)) + C(n, 45)*3^n",
    );
    // Wrong only at the first value: the right sum misses its k = 0 term, 1 at n = 0 only.
    assert_not_proved(l, &r.replace("sum(k, 0,", "sum(k, 1,"));
    // Wrong only at n = 1, the last initial value of the order-2 recurrence (C(n, 1) C(1, n)
    // is 1 there, else 0), and only at n = 2, the first value the recurrence fixes.
    assert_not_proved(l, &format!("{r} + C(n, 1)*C(1, n)"));
    assert_not_proved(l, &format!("{r} + C(n, 2)*C(2, n)"));
    // The Legendre form wrong by x^50 C(n, 50) (past the window) and at the first value.
    let (pl, pr) = (
        "sum(k, 0, n, C(n, k)*C(n+k, k)*x^k)",
        "sum(k, 0, n, C(n, k)^2*x^k*(1+x)^(n-k))",
    );
    assert_not_proved(pl, &format!("{pr} + C(n, 50)*x^50"));
    assert_not_proved(pl, &pr.replace("sum(k, 0,", "sum(k, 1,"));
    // Two sums of different sequences (3^n and 2^n).
    assert_not_proved("sum(k, 0, n, C(n, k)*2^k)", "sum(k, 0, n, C(n, k))");
}

// ---- class 3: inhomogeneous stated recurrences --------------------------------------------

/// f(n) = Σ_k k C(n, k) = n 2^(n−1) (Concrete Mathematics (5.53) with m = 1).
const F1: (&str, &str) = ("sum(k, 0, n+1, k*C(n+1, k))", "sum(k, 0, n, k*C(n, k))");

#[test]
fn class3_inhomogeneous_stated_recurrences_are_proved() {
    let (next, now) = F1;
    // f(n+1) − 2 f(n) = 2^n: Σ_k (k C(n+1, k) − 2k C(n, k)) is no hypergeometric term's
    // difference in k, so no certificate has these ends.
    assert_proved(&format!("{next} - 2*{now}"), "2^n", INHOMOGENEOUS);
    // f(n) = Σ_k k² C(n, k) = n(n+1) 2^(n−2): f(n+1) − 2 f(n) = (n+1) 2^n.
    assert_proved(
        "sum(k, 0, n+1, k^2*C(n+1, k)) - 2*sum(k, 0, n, k^2*C(n, k))",
        "(n+1)*2^n",
        INHOMOGENEOUS,
    );
    // The same recurrence written as f(n+1) = 2 f(n) + 2^n, and with a polynomial factor.
    assert_proved(next, &format!("2*{now} + 2^n"), INHOMOGENEOUS);
    assert_proved(&format!("(n-3)*{next} - 2*(n-3)*{now}"), "(n-3)*2^n", INHOMOGENEOUS);
}

#[test]
fn class3_false_inhomogeneous_recurrences_are_never_proved() {
    let (next, now) = F1;
    let lhs = format!("{next} - 2*{now}");
    // Wrong only from n = 50 on (past the refutation window).
    assert_not_proved(&lhs, "2^n + C(n, 50)");
    // Wrong only at the first value, and only at n = 2.
    assert_not_proved(&lhs, "2^n + C(0, n)");
    assert_not_proved(&lhs, "2^n + C(n, 2)*C(2, n)");
    // Wrong only at n = 3, the zero of the stated coefficients n − 3 (there 0 = 1).
    assert_not_proved(&format!("(n-3)*{next} - 2*(n-3)*{now}"), "(n-3)*2^n + C(n, 3)*C(3, n)");
    // Wrong inhomogeneous part: n 2^n instead of (n+1) 2^n.
    assert_not_proved("sum(k, 0, n+1, k^2*C(n+1, k)) - 2*sum(k, 0, n, k^2*C(n, k))", "n*2^n");
}
