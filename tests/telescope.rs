//! Creative telescoping and integrals symbolic in n: closed forms of sums that have no WZ
//! certificate, recurrences stated by a claim (Franel's), the Bernstein product formula and
//! `∫_0^1 B_i^n = 1/(n+1)` proved for every value — and their false variants never `proved`:
//! each fails with an exact counterexample or is an error.

#[path = "support/identity.rs"]
mod identity;
use casteljau::verify::Verdict;
use identity::{assert_proved, check_scoped as check};
use proptest::prelude::*;

fn assert_fails_at(body: &str, at: &str) {
    match check(body) {
        Ok((Verdict::Fails, None, c)) => assert!(c.contains(at), "{body}: counterexample {c:?} should be at {at:?}"),
        other => panic!("{body}: expected fails at {at}, got {other:?}"),
    }
}

fn assert_error(body: &str, needle: &str) {
    match check(body) {
        Err(e) => assert!(e.to_string().contains(needle), "{body}: {e} should mention {needle:?}"),
        Ok(other) => panic!("{body}: expected an error, got {other:?}"),
    }
}

const SECOND_MOMENT: &str = "for = [\"n = 0..\"]\nlhs = \"sum(i, 0, n, i^2*B(i, n, t))\"\n";
const PAIRS: &str = "for = [\"n = 0..\"]\nlhs = \"sum(k, 0, n, C(k, 2)*C(n, k))\"\n";
const FRANEL: &str = "for = [\"n = 0..\"]\nlet = [\"f(m) = sum(k, 0, m, C(m, k)^3)\"]\n";

#[test]
fn the_second_moment_of_the_basis_by_a_first_order_recurrence() {
    let c = assert_proved(&format!("{SECOND_MOMENT}rhs = \"n*t*(1-t) + n^2*t^2\""));
    // No WZ pair exists for this closed form; the recurrence found has coefficients
    // polynomial in n and t: n(1 − t + nt)·S(n+1) − (n+1)(1 + nt)·S(n) = the telescoped ends.
    assert!(c.contains("no WZ") || c.contains("creative telescoping"), "{c}");
    assert!(
        c.contains("creative telescoping: (n^2*t - n*t + n)·S(n+1) + (-n^2*t - n*t - n - 1)·S(n)"),
        "{c}"
    );
    // Its leading coefficient n(1 − t + nt) vanishes at n = 0: checked directly, with n = 1.
    assert!(
        c.contains("leading coefficient ≠ 0 for n ≥ 1; n = 0..=1 checked directly"),
        "{c}"
    );
}

#[test]
fn pairs_of_a_subset() {
    let c = assert_proved(&format!("{PAIRS}rhs = \"n*(n-1)*2^(n-2)/2\""));
    assert!(c.contains("(n - 1)·S(n+1) + (-2*n - 2)·S(n)"), "{c}");
    // The same sum as a single-term closed form (WZ would need no recurrence): also proved.
    assert_proved(&format!("{PAIRS}rhs = \"C(n, 2)*2^(n-2)\""));
}

#[test]
fn franels_recurrence_stated_as_a_claim() {
    let c = assert_proved(&format!(
        "{FRANEL}lhs = \"(n+2)^2*f(n+2) - (7n^2+21n+16)*f(n+1) - 8(n+1)^2*f(n)\"\nrhs = \"0\""
    ));
    assert!(
        c.contains("(n^2 + 4*n + 4)·S(n+2) + (-7*n^2 - 21*n - 16)·S(n+1) + (-8*n^2 - 16*n - 8)·S(n)"),
        "{c}"
    );
    // Written with the sums on both sides and in another order: the same recurrence.
    assert_proved(&format!(
        "{FRANEL}lhs = \"(n+2)^2*f(n+2)\"\nrhs = \"(7n^2+21n+16)*f(n+1) + 8(n+1)^2*f(n)\""
    ));
}

#[test]
fn the_bernstein_product_formula_for_every_degree_and_index() {
    let c = assert_proved(
        "for = [\"m = 0..\", \"n = 0..\", \"i = 0..=m\", \"j = 0..=n\"]\nlhs = \"B(i, m, t)*B(j, n, t)\"\nrhs = \"C(m, i)*C(n, j)/C(m+n, i+j)*B(i+j, m+n, t)\"",
    );
    assert!(c.contains("every m ≥ 0, every n ≥ 0, i = 0..=m, j = 0..=n"), "{c}");
}

#[test]
fn integrals_of_the_basis_for_every_n() {
    let c =
        assert_proved("for = [\"n = 0..\", \"i = 0..=n\"]\nlhs = \"integral(B(i, n, t), t, 0, 1)\"\nrhs = \"1/(n+1)\"");
    assert!(c.contains("every n ≥ 0, i = 0..=n"), "{c}");
    // A polynomial factor of t moves the exponent: ∫ t B_i^n = (i+1)/((n+1)(n+2)).
    assert_proved(
        "for = [\"n = 0..\", \"i = 0..=n\"]\nlhs = \"integral(t*B(i, n, t), t, 0, 1)\"\nrhs = \"(i+1)/((n+1)*(n+2))\"",
    );
    // ∫_0^1 t^(i−1) dt = 1/i needs i ≥ 1: with i = 0 the integral diverges — refused.
    assert_proved("for = [\"i = 1..\"]\nlhs = \"integral(t^(i-1), t, 0, 1)\"\nrhs = \"1/i\"");
    assert_error(
        "for = [\"i = 0..\"]\nlhs = \"integral(t^(i-1), t, 0, 1)\"\nrhs = \"1/i\"",
        "",
    );
    // Other intervals and integrands stay the bounded check's: errors here.
    assert_error(
        "for = [\"n = 0..\"]\nlhs = \"integral(t^n, t, 0, 1/2)\"\nrhs = \"(1/2)^(n+1)/(n+1)\"",
        "over [0, 1]",
    );
    assert_error(
        "for = [\"n = 0..\"]\nlhs = \"integral((1+t)^n, t, 0, 1)\"\nrhs = \"(2^(n+1) - 1)/(n+1)\"",
        "not t^e or (1 − t)^e",
    );
}

#[test]
fn false_sums_fail_with_a_counterexample() {
    // An index shift, a wrong range end, a wrong closed form from n = 7 on.
    assert_fails_at(
        "for = [\"n = 0..\"]\nlhs = \"sum(i, 0, n, (i+1)^2*B(i, n, t))\"\nrhs = \"n*t*(1-t) + n^2*t^2\"",
        "n = 0",
    );
    assert_fails_at(
        "for = [\"n = 0..\"]\nlhs = \"sum(i, 0, n-1, i^2*B(i, n, t))\"\nrhs = \"n*t*(1-t) + n^2*t^2\"",
        "n = 1",
    );
    assert_fails_at(
        &format!("{SECOND_MOMENT}rhs = \"n*t*(1-t) + n^2*t^2 + C(n, 7)\""),
        "n = 7",
    );
    assert_fails_at(
        &format!("{SECOND_MOMENT}rhs = \"n*t*(1-t) + n^2*t^2 + C(n, 9)*t^2\""),
        "n = 9",
    );
    assert_fails_at(&format!("{PAIRS}rhs = \"n*(n-1)*2^(n-2)/2 + C(n, 7)\""), "n = 7");
    assert_fails_at(
        "for = [\"n = 0..\"]\nlhs = \"sum(k, 0, n, C(k-1, 2)*C(n, k))\"\nrhs = \"n*(n-1)*2^(n-2)/2\"",
        "n = 2",
    );
}

#[test]
fn false_beyond_the_search_is_an_error_never_proved() {
    // Wrong only from n = 50 on: past every value evaluated; the symbolic proof must refuse it.
    assert_error(
        &format!("{SECOND_MOMENT}rhs = \"n*t*(1-t) + n^2*t^2 + C(n, 50)\""),
        "creative telescoping",
    );
    assert_error(
        &format!("{FRANEL}lhs = \"(n+2)^2*f(n+2) - (7n^2+21n+16)*f(n+1) - 8(n+1)^2*f(n)\"\nrhs = \"C(n, 50)\""),
        "",
    );
}

#[test]
fn a_search_past_its_budget_ends_and_the_claim_still_gets_its_verdict() {
    // Σ C(n, k)^5 has no recurrence within MAX_TELESCOPE_WORK; this closed form matches it
    // for n ≤ 3 (past the cross-check of n ≤ 2) and is wrong from n = 4: the bounded search gives up, and
    // the refutation search finds the counterexample.
    let start = std::time::Instant::now();
    assert_fails_at(
        "for = [\"n = 0..\"]\nlhs = \"sum(k, 0, n, C(n, k)^5)\"\nrhs = \"1 + n + 31*C(n, 2) + 391*C(n, 3)\"",
        "n = 4",
    );
    assert!(start.elapsed().as_secs() < 60, "{:?}", start.elapsed());
}

#[test]
fn wrong_recurrences_fail() {
    for (c2, c1, c0) in [
        ("(n+2)^2", "7n^2+21n+15", "8(n+1)^2"),
        ("(n+2)^2", "7n^2+21n+16", "9(n+1)^2"),
        ("(n+3)^2", "7n^2+21n+16", "8(n+1)^2"),
    ] {
        let body = format!("{FRANEL}lhs = \"{c2}*f(n+2) - ({c1})*f(n+1) - {c0}*f(n)\"\nrhs = \"0\"");
        assert!(
            matches!(check(&body), Ok((Verdict::Fails, None, _))),
            "{body}: {:?}",
            check(&body)
        );
    }
    // A coefficient wrong only from n = 5 on (right for every n the cross-check evaluates):
    // the stated recurrence has no certificate G; the counterexample search finds n = 5.
    assert_fails_at(
        &format!("{FRANEL}lhs = \"(n+2)^2*f(n+2) - (7n^2+21n+16 + n*(n-1)*(n-2)*(n-3)*(n-4))*f(n+1) - 8(n+1)^2*f(n)\"\nrhs = \"0\""),
        "n = 5",
    );
    // True for n ≤ 6, wrong from n = 7 on.
    assert_fails_at(
        &format!("{FRANEL}lhs = \"(n+2)^2*f(n+2) - (7n^2+21n+16)*f(n+1) - 8(n+1)^2*f(n)\"\nrhs = \"C(n, 7)\""),
        "n = 7",
    );
    // A shifted sum that is not the same summand: another recurrence, not telescoped.
    assert!(matches!(
        check(&format!(
            "{FRANEL}lhs = \"(n+2)^2*f(n+2) - (7n^2+21n+16)*f(n+1) - 8(n+1)^2*sum(k, 0, n, C(n, k)^2)\"\nrhs = \"0\""
        )),
        Ok((Verdict::Fails, None, _)) | Err(_)
    ));
}

#[test]
fn false_products_and_integrals_fail() {
    // C(m+n, i+j+1) = 0 at i = m, j = n: a division by zero, an error.
    assert_error(
        "for = [\"m = 0..\", \"n = 0..\", \"i = 0..=m\", \"j = 0..=n\"]\nlhs = \"B(i, m, t)*B(j, n, t)\"\nrhs = \"C(m, i)*C(n, j)/C(m+n, i+j+1)*B(i+j, m+n, t)\"",
        "division by zero",
    );
    // Where it is defined (j < n), the wrong binomial fails with exact values.
    assert_fails_at(
        "for = [\"m = 0..\", \"n = 1..\", \"i = 0..=m\", \"j = 0..=n-1\"]\nlhs = \"B(i, m, t)*B(j, n, t)\"\nrhs = \"C(m, i)*C(n, j)/C(m+n, i+j+1)*B(i+j, m+n, t)\"",
        "left side",
    );
    assert_fails_at(
        "for = [\"n = 0..\", \"i = 0..=n\"]\nlhs = \"integral(B(i, n, t), t, 0, 1)\"\nrhs = \"1/(n+2)\"",
        "n = 0",
    );
    assert_fails_at(
        "for = [\"n = 0..\", \"i = 0..=n\"]\nlhs = \"integral(B(i, n, t), t, 0, 1)\"\nrhs = \"1/(n+1) + C(n, 9)\"",
        "n = 9",
    );
}

/// The exact value of `Σ_{i=a}^{n+e} (i+s)^2 B_i^n(t)` minus `n t (1 − t) + n² t²` at `t = 1/3`,
/// by its definition (B_i^n = 0 outside 0 ≤ i ≤ n).
fn moment_gap(n: i64, (a, e, s): (i64, i64, i64)) -> num_rational::BigRational {
    use num_rational::BigRational as Q;
    use num_traits::{One, Zero};
    let t = Q::new(1.into(), 3.into());
    let binom = |n: i64, k: i64| -> Q {
        if k < 0 || k > n {
            return Q::zero();
        }
        (0..k).fold(Q::one(), |acc, j| {
            acc * Q::from_integer((n - j).into()) / Q::from_integer((j + 1).into())
        })
    };
    let pow = |x: &Q, k: i64| (0..k).fold(Q::one(), |acc, _| acc * x);
    let mut sum = Q::zero();
    for i in a..=n + e {
        let w = Q::from_integer((i + s).into());
        sum += &w * &w * binom(n, i) * pow(&t, i.max(0)) * pow(&(Q::one() - &t), (n - i).max(0));
    }
    let nq = Q::from_integer(n.into());
    sum - (&nq * &t * (Q::one() - &t) + &nq * &nq * &t * &t)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 8, ..ProptestConfig::default() })]

    /// Shifted variants of the second moment: `proved` only when the variant holds for every
    /// n evaluated exactly here; a variant that differs anywhere in n ≤ 12 is never proved.
    #[test]
    fn shifted_moments_are_proved_only_when_true(a in 0i64..=2, e in -1i64..=1, s in -1i64..=1) {
        let body = format!(
            "for = [\"n = 0..\"]\nlhs = \"sum(i, {a}, n + ({e}), (i + ({s}))^2*B(i, n, t))\"\nrhs = \"n*t*(1-t) + n^2*t^2\""
        );
        let wrong = (0..=12).any(|n| !num_traits::Zero::is_zero(&moment_gap(n, (a, e, s))));
        match check(&body) {
            Ok((Verdict::Proved, _, c)) => prop_assert!(!wrong, "{body}: proved but false: {c}"),
            Ok((Verdict::Fails, _, _)) => prop_assert!(wrong, "{body}: fails but true for n ≤ 12"),
            Ok(other) => prop_assert!(false, "{body}: {other:?}"),
            Err(_) => {}
        }
    }

    /// Franel's recurrence with one coefficient off by a small amount is never proved.
    #[test]
    fn perturbed_franel_is_never_proved(which in 0usize..3, by in prop::sample::select(vec![-2i64, -1, 1, 2])) {
        let mut c = [
            "(n+2)^2".to_string(),
            "(7n^2+21n+16)".to_string(),
            "8(n+1)^2".to_string(),
        ];
        c[which] = format!("({} + ({by}))", c[which]);
        let body = format!("{FRANEL}lhs = \"{}*f(n+2) - {}*f(n+1) - {}*f(n)\"\nrhs = \"0\"", c[0], c[1], c[2]);
        let out = check(&body);
        prop_assert!(!matches!(out, Ok((Verdict::Proved, ..))), "{body}: {out:?}");
    }
}
