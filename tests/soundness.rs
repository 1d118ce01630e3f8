//! Soundness at the edges of the engine: each case here was once a wrong verdict or a
//! needless refusal.
//! - Differentiation is by a real parameter only: a factorial, a sum bound, a binomial or an
//!   index that depends on the variable, directly or through a definition, and a derivative by
//!   an integer range variable, are one-line errors — never `proved`.
//! - The refutation search after a failed every-n proof has one budget per claim.
//! - An `implies` whose factor has a pole is refuted at the pole when the premise holds there.
//! - A divisor's integer zeros are split off: sums whose closed form vanishes at n = 0 are
//!   proved for every n, and a zero reached by a shift is never a silent comparison.
//! - Work is bounded before it starts: the size of the numbers counts, and the certificate
//!   search stops at its budget, saying which degree it reached.

#[path = "support/identity.rs"]
mod identity;
use casteljau::verify::claims::parse_file;
use casteljau::verify::Verdict;
use std::path::Path;
use std::time::Instant;

fn check(body: &str) -> casteljau::Result<(Verdict, String)> {
    identity::check_table(body, false).map(|(v, _, c)| (v, c))
}

fn assert_error(body: &str, needle: &str) {
    match check(body) {
        Err(e) => {
            let msg = e.to_string();
            assert_eq!(msg.lines().count(), 1, "{body}: {msg}");
            assert!(msg.contains(needle), "{body}: {msg:?} should mention {needle:?}");
        }
        Ok(other) => panic!("{body}: expected an error, got {other:?}"),
    }
}

fn assert_verdict(body: &str, want: Verdict) {
    match check(body) {
        Ok((v, _)) if v == want => {}
        other => panic!("{body}: expected {want:?}, got {other:?}"),
    }
}

#[test]
fn a_sum_bound_is_not_a_constant_of_diff() {
    assert_error(
        "kind = \"identity\"\nfor = [\"n = 0..\"]\nlhs = \"diff(sum(k, 0, n, k), n)\"\nrhs = \"0\"",
        "cannot differentiate by n: it is an integer",
    );
    // The same with a real parameter in the bound, and through a definition.
    assert_error(
        "kind = \"identity\"\nvars = [\"t\"]\nlhs = \"diff(sum(k, 0, t, k), t)\"\nrhs = \"0\"",
        "the bounds of a sum are integers",
    );
    assert_error(
        "kind = \"identity\"\nvars = [\"t\"]\nlet = [\"S(m) = sum(k, 0, m, k^2)\"]\nlhs = \"diff(S(t), t)\"\nrhs = \"0\"",
        "the bounds of a sum are integers",
    );
    // A lower bound, a bound inside a definition that is itself differentiated, a nested sum.
    assert_error(
        "kind = \"identity\"\nvars = [\"t\"]\nlhs = \"diff(sum(k, t, 3, k), t)\"\nrhs = \"0\"",
        "the bounds of a sum are integers",
    );
    assert_error(
        "kind = \"identity\"\nvars = [\"t\"]\nlet = [\"D(m) = diff(sum(k, 0, m, k), m)\"]\nlhs = \"D(t)\"\nrhs = \"0\"",
        "the bounds of a sum are integers",
    );
    assert_error(
        "kind = \"identity\"\nvars = [\"t\"]\nlhs = \"diff(sum(j, 0, 2, sum(k, 0, t, j*k)), t)\"\nrhs = \"0\"",
        "the bounds of a sum are integers",
    );
}

#[test]
fn a_factorial_is_not_a_constant_of_diff() {
    assert_error(
        "kind = \"identity\"\nvars = [\"t\"]\nlhs = \"diff((t+2)!, t)\"\nrhs = \"0\"",
        "a factorial takes an integer",
    );
    assert_error(
        "kind = \"identity\"\nvars = [\"t\"]\nlhs = \"diff(((t)!)!, t)\"\nrhs = \"0\"",
        "a factorial takes an integer",
    );
    assert_error(
        "kind = \"identity\"\nvars = [\"t\"]\nlet = [\"F(m) = (m+1)!\"]\nlhs = \"diff(t*F(t), t)\"\nrhs = \"0\"",
        "a factorial takes an integer",
    );
    assert_error(
        "kind = \"inequality\"\nfor = [\"n = 0..\"]\nvars = [\"t\"]\ninterval = [0, 1]\nlhs = \"diff(n!, n) + t^2\"",
        "cannot differentiate by n: it is an integer",
    );
}

#[test]
fn other_integer_positions_and_integer_variables_are_refused() {
    assert_error(
        "kind = \"identity\"\nvars = [\"t\"]\nlhs = \"diff(C(t, 2), t)\"\nrhs = \"0\"",
        "cannot differentiate",
    );
    // A summation index is an integer inside its sum.
    assert_error(
        "kind = \"identity\"\nvars = [\"t\"]\nlhs = \"sum(k, 0, 3, diff(k^2, k))\"\nrhs = \"12\"",
        "cannot differentiate by k: it is an integer",
    );
    // A polynomial in a range variable: the derivative is refused too (n is an integer).
    assert_error(
        "kind = \"identity\"\nfor = [\"n = 0..=5\"]\nlhs = \"diff(n*(n+1)/2, n)\"\nrhs = \"n + 1/2\"",
        "cannot differentiate by n: it is an integer",
    );
}

#[test]
fn the_consistent_claims_keep_their_verdicts() {
    assert_verdict(
        "kind = \"identity\"\nfor = [\"n = 0..\"]\nlhs = \"sum(k, 0, n, k)\"\nrhs = \"n*(n+1)/2\"",
        Verdict::Proved,
    );
    assert_verdict(
        "kind = \"identity\"\nvars = [\"n\"]\nlhs = \"diff(n*(n+1)/2, n)\"\nrhs = \"n + 1/2\"",
        Verdict::Proved,
    );
    // Integer names stay constants where they are not differentiated.
    assert_verdict(
        "kind = \"identity\"\nfor = [\"n = 1..=4\"]\nvars = [\"t\"]\nlhs = \"diff(t^n + sum(k, 0, n, k*t), t)\"\nrhs = \"n*t^(n-1) + n*(n+1)/2\"",
        Verdict::ProvedInRange,
    );
    // ... and a false variant of it is not proved.
    assert_verdict(
        "kind = \"identity\"\nfor = [\"n = 1..=4\"]\nvars = [\"t\"]\nlhs = \"diff(t^n + sum(k, 0, n, k*t), t)\"\nrhs = \"n*t^(n-1) + n*(n-1)/2\"",
        Verdict::Fails,
    );
}

fn assert_fails_with(body: &str, needle: &str) {
    match check(body) {
        Ok((Verdict::Fails, c)) => assert!(c.contains(needle), "{body}: {c:?} should mention {needle:?}"),
        other => panic!("{body}: expected fails, got {other:?}"),
    }
}

const TWO_OPEN: &str = "kind = \"identity\"\nfor = [\"m = 0..\", \"n = 0..\"]\nvars = [\"u\", \"v\"]\n";

#[test]
fn the_refutation_search_has_one_budget_across_open_ranges() {
    // True, but the given certificates are for another sum: no proof, no counterexample, and
    // the search ends within its budget (it once tried 41 × 41 values: 82 s).
    let start = Instant::now();
    assert_error(
        &format!(
            "{TWO_OPEN}lhs = \"sum(i, 0, m, sum(j, 0, n, B(m-i, m, u)*B(j, n, v)))\"\nrhs = \"1\"\ncertificate = [\"-(1 - v)*j/(n + 1 - j)\", \"-(1 - u)*i/(m + 1 - i)\"]"
        ),
        "no counterexample in the first 12 values of m, n (the search budget: at most 200 combinations",
    );
    assert!(start.elapsed().as_secs() < 10, "{:?}", start.elapsed());
    // A false variant is still refuted inside the budget, also past the first window.
    assert_fails_with(
        &format!(
            "{TWO_OPEN}lhs = \"sum(i, 0, m, sum(j, 0, n, B(i, m, u)*B(j, n, v)))\"\nrhs = \"1 + C(m, 5)*C(n, 4)\"\ncertificate = [\"-(1 - v)*j/(n + 1 - j)\", \"-(1 - u)*i/(m + 1 - i)\"]"
        ),
        "m = 5",
    );
}

#[test]
fn an_implies_with_a_pole_is_refuted_at_the_pole() {
    assert_fails_with(
        "kind = \"implies\"\nsymbols = [\"k\", \"l\"]\npremise = \"k*l = 0\"\nequation = \"l = 0\"\nfactor = \"1/k\"",
        "at k = 0, l = 1",
    );
    // The pole set of a shifted factor, and a vector unknown.
    assert_fails_with(
        "kind = \"implies\"\nsymbols = [\"k\", \"l\"]\npremise = \"(k - 2)*l = 0\"\nequation = \"l = 0\"\nfactor = \"1/(k - 2)\"",
        "at k = 2, l = 1",
    );
    assert_fails_with(
        "kind = \"implies\"\nsymbols = [\"k\"]\nvectors = { p = 2 }\npremise = \"k*p\"\nequation = \"p = 0*p\"\nfactor = \"1/k\"",
        "k = 0",
    );
}

const EVERY_N: &str = "kind = \"identity\"\nfor = [\"n = 0..\"]\n";

#[test]
fn a_closed_form_that_vanishes_at_n_0_is_proved_with_that_case_apart() {
    for (lhs, rhs) in [
        ("sum(i, 0, n, i*B(i, n, t))", "n*t"),
        ("sum(k, 0, n, k*C(n, k))", "n*2^(n-1)"),
    ] {
        match check(&format!("{EVERY_N}lhs = \"{lhs}\"\nrhs = \"{rhs}\"")) {
            Ok((Verdict::Proved, c)) => assert!(c.contains("n = 0..=0 checked directly"), "{c}"),
            other => panic!("{lhs} = {rhs}: {other:?}"),
        }
    }
}

#[test]
fn false_claims_at_a_vanishing_coefficient_are_never_proved() {
    for (lhs, rhs, at) in [
        ("sum(i, 0, n, i*B(i, n, t))", "(n-1)*t", "n = 0"),
        ("sum(k, 0, n, k*C(n, k))", "(n+1)*2^(n-1)", "n = 0"),
        // Wrong only at n = 2, where the closed form's coefficient vanishes.
        (
            "sum(k, 0, n, (n-2)*k*C(n, k)) + C(2, n)*C(n, 2)",
            "(n-2)*n*2^(n-1)",
            "n = 2",
        ),
    ] {
        match check(&format!("{EVERY_N}lhs = \"{lhs}\"\nrhs = \"{rhs}\"")) {
            Ok((Verdict::Fails, c)) => assert!(c.contains(at), "{lhs} = {rhs}: {c}"),
            Ok((v, c)) => panic!("{lhs} = {rhs}: {v:?} {c}"),
            Err(_) => {}
        }
    }
}

#[test]
fn big_numbers_count_in_the_work_estimate() {
    let x = "7".repeat(4000);
    let y = "3".repeat(3999) + "1";
    let claim = |e: u32| {
        format!("kind = \"identity\"\nvars = [\"t\"]\nlhs = \"({x}/{y} + t)^{e}\"\nrhs = \"({x}/{y} + t)^{e}\"")
    };
    assert_verdict(&claim(2), Verdict::Proved);
    // Once 38 s of CPU; now refused before any evaluation.
    let start = Instant::now();
    assert_error(&claim(16), "MAX_WORK");
    assert!(start.elapsed().as_secs() < 2, "{:?}", start.elapsed());
}

#[test]
fn the_certificate_search_stops_at_its_budget_and_says_where() {
    // Σ_k C(n,k)² = C(2n, n) with spectator symbols: found (degree 4) with five of them ...
    let spectators = |extra: &str, sum: &str| {
        format!(
            "kind = \"identity\"\nfor = [\"a = 0..\", \"b = 0..\", \"c = 0..\", \"d = 0..\", {extra}\"n = 0..\"]\nlhs = \"sum(k, 0, n, C(n, k)^2*C({sum}, a)*C(c + d, c))\"\nrhs = \"C(2*n, n)*C({sum}, a)*C(c + d, c)\""
        )
    };
    assert_verdict(&spectators("", "a + b"), Verdict::Proved);
    // ... and with seven, degree 4 has more unknowns than the search takes: the error names
    // the degree reached and the limit (it once claimed "degree ≤ 6" after stopping at 4).
    let start = Instant::now();
    assert_error(
        &spectators("\"e = 0..\", \"f = 0..\", ", "a + b + e + f"),
        "no R = P/D with P of total degree ≤ 3 solves the WZ equation (D from the factorials of F that grow with n); the search stopped at degree 4: 495 unknowns, more than MAX_UNKNOWNS = 400",
    );
    assert!(start.elapsed().as_secs() < 10, "{:?}", start.elapsed());
}

#[test]
fn an_undecided_claim_does_not_hide_the_others() {
    use casteljau::verify::prove_files;
    let file = parse_file(
        "[[claim]]\nid = \"a\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nfor = [\"n = 0..\"]\nlhs = \"sum(k, 0, n, k)\"\nrhs = \"n*(n+1)/2\"\n\n\
         [[claim]]\nid = \"b\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nfor = [\"n = 0..\"]\nlhs = \"diff(sum(k, 0, n, k), n)\"\nrhs = \"0\"\n\n\
         [[claim]]\nid = \"c\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nvars = [\"t\"]\nlhs = \"(1 - t) + t\"\nrhs = \"2\"\nexpect = \"fails\"\n",
        Path::new("mixed.toml"),
    )
    .unwrap();
    let report = prove_files(&[file], &mut |_, _, _| {}).unwrap();
    let verdicts: Vec<Verdict> = report.outcomes.iter().map(|o| o.verdict).collect();
    assert_eq!(verdicts, [Verdict::Proved, Verdict::Error, Verdict::Fails]);
    assert!(report.outcomes[1].certificate.contains("cannot differentiate by n"));
    let text = report.to_text();
    assert!(text.contains("[error] b"), "{text}");
    assert!(
        text.contains("claims not decided (error, each with its reason): b"),
        "{text}"
    );
    assert_eq!(report.to_json()["summary"]["undecided"][0], "b");
}
