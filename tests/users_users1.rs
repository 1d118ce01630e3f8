//! Users' own claims (issue 46), classes 1, 4, 6 and 7: true identities from the books proved
//! for every n, and false variants of them (wrong only at a late n, only at a zero of the
//! closed form, only on one piece of a split domain) that fail or are errors, never proved.

#[path = "support/identity.rs"]
mod identity;

use casteljau::verify::Verdict;
use identity::check_scoped;

/// The claim `lhs = rhs` on the ranges `ranges`, with the proof's steps recorded.
fn claim_on(ranges: &[&str], lhs: &str, rhs: &str) -> casteljau::Result<(Verdict, Option<String>, String)> {
    let ranges: Vec<String> = ranges.iter().map(|r| format!("\"{r}\"")).collect();
    check_scoped(&format!(
        "for = [{}]\nlhs = \"{lhs}\"\nrhs = \"{rhs}\"",
        ranges.join(", ")
    ))
}

/// Proved for every n (no range): the certificate.
fn proved(lhs: &str, rhs: &str) -> String {
    proved_on(&["n = 0.."], lhs, rhs)
}

/// Proved for every point of the open ranges (no range in the verdict): the certificate.
fn proved_on(ranges: &[&str], lhs: &str, rhs: &str) -> String {
    let out = claim_on(ranges, lhs, rhs);
    let Ok((v, range, c)) = out else {
        panic!("{lhs} = {rhs}: {out:?}");
    };
    assert!(
        v == Verdict::Proved && range.is_none(),
        "{lhs} = {rhs}: {v:?} {range:?} {c}"
    );
    c
}

/// A false claim: `fails`, or an error; never proved.
fn not_proved(lhs: &str, rhs: &str) -> Option<String> {
    not_proved_on(&["n = 0.."], lhs, rhs)
}

/// A false claim on the ranges `ranges`: `fails`, or an error; never proved.
fn not_proved_on(ranges: &[&str], lhs: &str, rhs: &str) -> Option<String> {
    match claim_on(ranges, lhs, rhs) {
        Ok((v, _, c)) => {
            assert!(v == Verdict::Fails, "{lhs} = {rhs}: {v:?} {c}");
            Some(c)
        }
        Err(_) => None,
    }
}

// Class 1: a closed form that vanishes for some n. Its zeros are checked directly and the
// induction starts past them.

#[test]
fn factorial_moments_of_the_binomial_row() {
    // Petkovšek–Wilf–Zeilberger, "A = B", §1 and ch. 5 examples: the falling factorial
    // moments Σ_k k(k−1)…(k−r+1) C(n,k) = n(n−1)…(n−r+1) 2^(n−r), zero for n < r.
    let c = proved("sum(k, 0, n, k*(k-1)*C(n, k))", "n*(n-1)*2^(n-2)");
    assert!(c.contains("n = 0..=1 checked directly"), "{c}");
    let c = proved("sum(k, 0, n, k*(k-1)*(k-2)*C(n, k))", "n*(n-1)*(n-2)*2^(n-3)");
    assert!(c.contains("n = 0..=2 checked directly"), "{c}");
    // A factor (n − 50) on both sides: n = 0..=50 checked directly.
    let c = proved("sum(k, 0, n, (n-50)*C(n, k))", "(n-50)*2^n");
    assert!(c.contains("n = 0..=50 checked directly"), "{c}");
}

#[test]
fn bernstein_moments_vanishing_for_small_degree() {
    // Farin, "Curves and Surfaces for CAGD", §5 (degree elevation and the second moment of
    // the Bernstein polynomials); Prautzsch–Boehm–Paluszny, §2.3: Σ_i i(i−1) B_i^n(t) =
    // n(n−1) t², zero for n = 0, 1.
    let c = proved("sum(i, 0, n, i*(i-1)*B(i, n, t))", "n*(n-1)*t^2");
    assert!(c.contains("n = 0..=1 checked directly"), "{c}");
}

#[test]
fn false_closed_forms_wrong_only_at_a_zero_or_late_are_never_proved() {
    // Wrong only at n = 2, a zero of n(n−1)(n−2): C(2, n)·C(n, 2) is 1 there and 0 elsewhere.
    let c = not_proved(
        "sum(k, 0, n, k*(k-1)*(k-2)*C(n, k))",
        "n*(n-1)*(n-2)*2^(n-3) + C(2, n)*C(n, 2)",
    );
    assert!(c.is_some_and(|c| c.contains("at n = 2")));
    // Wrong only at n = 50, the zero of the factor (n − 50), past the refutation window.
    not_proved("sum(k, 0, n, (n-50)*C(n, k))", "(n-50)*2^n + C(0, n-50)");
    // Wrong only from n = 45 on.
    not_proved(
        "sum(k, 0, n, k*(k-1)*(k-2)*C(n, k))",
        "n*(n-1)*(n-2)*2^(n-3) + C(n, 45)",
    );
    // The zeros shifted: wrong everywhere but where both vanish.
    not_proved("sum(k, 0, n, k*(k-1)*C(n, k))", "n*(n-2)*2^(n-2)");
}

// Class 4: sums of several terms, gathered into one hypergeometric term (the kernel proves
// the gathered summand equal to the written one).

#[test]
fn sums_of_several_terms() {
    // "A = B", §1.2: Σ_k (k + 1) C(n, k) = (n + 2) 2^(n−1).
    proved("sum(k, 0, n, (k+1)*C(n, k))", "(n+2)*2^(n-1)");
    // "A = B": the symmetric sum Σ_k (2k − n) C(n, k)² vanishes.
    proved("sum(k, 0, n, (2*k - n)*C(n, k)^2)", "0");
    // Prautzsch–Boehm–Paluszny, §2.3 (linear precision and the variance of the Bernstein
    // weights): Σ_i (i − nt) B_i^n(t) = 0 and Σ_i (i − nt)² B_i^n(t) = n t (1 − t).
    proved("sum(i, 0, n, (i - n*t)*B(i, n, t))", "0");
    proved("sum(i, 0, n, (i - n*t)^2*B(i, n, t))", "n*t*(1-t)");
}

#[test]
fn derivatives_of_sums_whose_summand_has_several_terms() {
    // Farin, §5.3 (derivatives of a Bézier curve, here the control points b_i = i): the
    // derivative's summand is i·C(n,i)(i t^(i−1)(1−t)^(n−i) − (n−i) t^i (1−t)^(n−i−1)), two
    // terms with exponents one apart.
    proved("diff(sum(i, 0, n, i*B(i, n, t)), t)", "n");
    // Prautzsch–Boehm–Paluszny, §2.4: the basis sums to 1, so its derivative vanishes.
    proved("diff(sum(i, 0, n, B(i, n, t)), t)", "0");
}

#[test]
fn false_sums_of_several_terms_are_never_proved() {
    // Wrong from n = 60 on only.
    not_proved("sum(k, 0, n, (k+1)*C(n, k))", "(n+2)*2^(n-1) + C(n, 60)");
    // Wrong from n = 45 on only, in t.
    not_proved("diff(sum(i, 0, n, i*B(i, n, t)), t)", "n + C(n, 45)*t");
    // Wrong only at n = 0.
    let c = not_proved("diff(sum(i, 0, n, i*B(i, n, t)), t)", "n + C(0, n)*(1-t)");
    assert!(c.is_some_and(|c| c.contains("at n = 0")));
    // The variance with a wrong sign.
    not_proved("sum(i, 0, n, (i - n*t)^2*B(i, n, t))", "n*t*(t-1)");
}

// Class 6: powers with symbolic exponents and constant factors, written one way by the
// kernel (`(−1)^e` by the parity of `e`, constants by their prime factors).

#[test]
fn powers_with_constant_factors() {
    // "A = B", §1.1 (the binomial theorem at x = −2 and at x = 2²):
    // Σ_k C(n,k) (−2)^k = (−1)^n and Σ_k C(n,k) 2^(2k) = 5^n.
    proved("sum(k, 0, n, C(n, k)*(-2)^k)", "(-1)^n");
    proved("sum(k, 0, n, C(n, k)*2^(2*k))", "5^n");
    // Prautzsch–Boehm–Paluszny, §2.1, and Farin, §5.1 (Bernstein and power form):
    // B_0^n(t) = (1 − t)^n = (−1)^n (t − 1)^n.
    proved("B(0, n, t)", "(-1)^n*(t-1)^n");
    // The forms.
    proved("(1-t)^n*(t-1)^(-n)", "(-1)^n");
    proved("(-1)^(2*n)", "1");
    proved("(-2*t)^n", "(-1)^n*2^n*t^n");
    proved("4^n", "2^(2*n)");
    proved("6^n*(1/3)^n", "2^n");
}

#[test]
fn false_powers_are_never_proved() {
    let c = not_proved("(-1)^(2*n+1)", "1");
    assert!(c.is_some_and(|c| c.contains("at n = 0")));
    let c = not_proved("(1-t)^n*(t-1)^(-n)", "1");
    assert!(c.is_some_and(|c| c.contains("n = 1")));
    not_proved("(-2*t)^n", "2^n*t^n");
    // Wrong from n = 45 or n = 50 on only.
    not_proved("4^n", "2^(2*n) + C(n, 45)");
    not_proved("sum(k, 0, n, C(n, k)*(-2)^k)", "(-1)^n + C(n, 50)");
}

// Class 7: a symbol with two lower bounds neither implying the other (`n ≥ 0` and
// `n ≥ j − 1` on `0 ≤ j ≤ n + 1`): the domain split by which one is larger, the values of
// `j` that constants bound on a piece written out one by one.

#[test]
fn two_lower_bounds() {
    let on = ["n = 0..", "j = 0..=n+1"];
    // "A = B", ch. 1 (the upper summation, "hockey stick", identity), for degree n + 1:
    // Σ_{i=j}^{n+1} C(i, j) = C(n+2, j+1).
    proved_on(&on, "sum(i, j, n+1, C(i, j))", "C(n+2, j+1)");
    // "A = B", ch. 1 (trinomial revision summed), as in the subdivision of a Bézier curve
    // of degree n + 1 (Prautzsch–Boehm–Paluszny, §2.5):
    // Σ_i C(n+1, i) C(i, j) = C(n+1, j) 2^(n+1−j).
    proved_on(&on, "sum(i, 0, n+1, C(n+1, i)*C(i, j))", "C(n+1, j)*2^(n+1-j)");
}

#[test]
fn false_claims_with_two_lower_bounds_are_never_proved() {
    let on = ["n = 0..", "j = 0..=n+1"];
    // Wrong only at j = 0 (a piece of its own).
    let c = not_proved_on(&on, "sum(i, j, n+1, C(i, j))", "C(n+2, j+1) + C(0, j)");
    assert!(c.is_some_and(|c| c.contains("j = 0")));
    // Wrong only at j = 0 or only at j = 1, and only from n = 45 on.
    not_proved_on(&on, "sum(i, j, n+1, C(i, j))", "C(n+2, j+1) + C(0, j)*C(n, 45)");
    not_proved_on(&on, "sum(i, j, n+1, C(i, j))", "C(n+2, j+1) + C(0, j-1)*C(n, 45)");
    // Wrong only from n = 45 on, for every j.
    not_proved_on(&on, "sum(i, j, n+1, C(i, j))", "C(n+2, j+1) + C(n, 45)");
    not_proved_on(
        &on,
        "sum(i, 0, n+1, C(n+1, i)*C(i, j))",
        "C(n+1, j)*2^(n+1-j) + C(0, j)*C(n, 50)",
    );
}
