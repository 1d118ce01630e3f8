//! Claims for every n (open ranges `n = 0..`): hypergeometric identities and WZ certificates are
//! proved for every value, false ones fail with an exact counterexample or are refused, and a
//! wrong certificate is rejected — never `proved`.

#[path = "support/identity.rs"]
mod identity;
use casteljau::verify::Verdict;
use identity::{assert_proved, check_scoped as check};

fn assert_error(body: &str, needle: &str) {
    match check(body) {
        Err(e) => {
            let msg = e.to_string();
            assert!(msg.contains(needle), "{body}: {msg:?} should mention {needle:?}");
        }
        Ok(other) => panic!("{body}: expected an error, got {other:?}"),
    }
}

const POU: &str = "for = [\"n = 0..\"]\nlhs = \"sum(i, 0, n, B(i, n, t))\"\n";

#[test]
fn finite_identities_between_terms_for_every_n() {
    // The recursion of the basis, with B_{-1}^{n-1} = B_n^{n-1} = 0 at the ends.
    let c = assert_proved(
        "for = [\"n = 1..\", \"i = 0..=n\"]\nlhs = \"B(i, n, t)\"\nrhs = \"(1 - t)*B(i, n-1, t) + t*B(i-1, n-1, t)\"",
    );
    assert!(c.contains("every n ≥ 1"), "{c}");
    // The derivative of the basis.
    assert_proved(
        "for = [\"n = 1..\", \"i = 0..=n\"]\nlhs = \"diff(B(i, n, t), t)\"\nrhs = \"n*(B(i-1, n-1, t) - B(i, n-1, t))\"",
    );
    // Outside the basis's support both sides are 0 (i = n + 1 included).
    assert_proved("for = [\"n = 0..\", \"i = 0..=n+1\"]\nlhs = \"C(n, i)*t^i*(1-t)^(n-i)\"\nrhs = \"B(i, n, t)\"");
    // Degree elevation (7) on the unit polygon at a symbolic index and the zero polygon.
    let c = assert_proved(
        "polygon = { name = \"b\", degree = \"n\" }\nfor = [\"n = 0..\"]\nlet = [\"e(i) = i/(n+1)*b[i-1] + (1 - i/(n+1))*b[i]\"]\nlhs = \"sum(i, 0, n, b[i]*B(i, n, t))\"\nrhs = \"sum(i, 0, n+1, e(i)*B(i, n+1, t))\"",
    );
    assert!(c.contains("unit polygon at a symbolic index"), "{c}");
}

#[test]
fn false_finite_identities_fail_or_are_refused() {
    // Wrong already for small n: an exact counterexample from the evaluation.
    let (v, _, c) = check(
        "for = [\"n = 1..\", \"i = 0..=n\"]\nlhs = \"B(i, n, t)\"\nrhs = \"(1 - t)*B(i, n-1, t) + t*B(i, n-1, t)\"",
    )
    .unwrap();
    assert_eq!(v, Verdict::Fails, "{c}");
    // Wrong only from n = 5 on (true for n = 1..=4, past the evaluated first values): never proved; the search
    // past the cross-check finds the counterexample.
    assert_fails_at(
        "for = [\"n = 1..\", \"i = 0..=n\"]\nlhs = \"B(i, n, t)\"\nrhs = \"B(i, n, t) + (n-1)*(n-2)*(n-3)*(n-4)*t\"",
        "n = 5",
    );
    // The wrong boundary convention at i = n: (1 - t)B(n, n-1, t) is 0, not t^n (1 - t).
    assert_fails_at(
        "for = [\"n = 4..\", \"i = 0..=n\"]\nlhs = \"B(i, n, t)\"\nrhs = \"(1 - t)*B(i, n-1, t) + t*B(i-1, n-1, t) + C(i, n)*(1 - t)*(n-4)*(n-5)*(n-6)*(n-7)*t^n\"",
        "n = 8",
    );
}

#[test]
fn sums_by_wz_certificates() {
    let c = assert_proved(&format!("{POU}rhs = \"1\"\ncertificate = \"-(1-t)*i/(n+1-i)\""));
    assert!(c.contains("R = -(1 - t)*i/(n + 1 - i)"), "{c}");
    assert_proved(
        "for = [\"n = 1..\"]\nlhs = \"sum(i, 0, n, i/n*B(i, n, t))\"\nrhs = \"t\"\ncertificate = \"-(1-t)*(i-1)/(n+1-i)\"",
    );
    // Identity (4), normalised by its right side.
    assert_proved(
        "for = [\"j = 0..\", \"n = j..\"]\nlhs = \"B(j, n, s*t)\"\nrhs = \"sum(r, j, n, B(j, r, s)*B(r, n, t))\"\ncertificate = \"-(1-t)*(r-j)/((1-s*t)*(n+1-r))\"",
    );
    // A double sum, innermost certificate first.
    assert_proved(
        "for = [\"m = 0..\", \"n = 0..\"]\nlhs = \"sum(i, 0, m, sum(j, 0, n, B(i, m, u)*B(j, n, v)))\"\nrhs = \"1\"\ncertificate = [\"-(1-v)*j/(n+1-j)\", \"-(1-u)*i/(m+1-i)\"]",
    );
}

#[test]
fn certificates_are_found_when_not_given() {
    let c = assert_proved(&format!("{POU}rhs = \"1\""));
    assert!(c.contains("found by the ansatz search, then checked"), "{c}");
    assert_proved(
        "for = [\"j = 0..\", \"n = j..\"]\nlhs = \"B(j, n, s*t)\"\nrhs = \"sum(r, j, n, B(j, r, s)*B(r, n, t))\"",
    );
    assert_proved(
        "for = [\"m = 0..\", \"n = 0..\"]\nlhs = \"sum(i, 0, m, sum(j, 0, n, B(i, m, u)*B(j, n, v)))\"\nrhs = \"1\"",
    );
    // A polynomial sum: G = 0 and the new term telescopes against the right side.
    assert_proved("for = [\"n = 0..\"]\nlhs = \"sum(i, 0, n, i^2)\"\nrhs = \"n*(n+1)*(2n+1)/6\"");
    // Classical sums whose certificates need a numerator of degree 4 to 6: Σ C(n, k)² = C(2n, n)
    // and Vandermonde's convolution, in two free integers.
    assert_proved("for = [\"n = 0..\"]\nlhs = \"sum(k, 0, n, C(n, k)^2)\"\nrhs = \"C(2n, n)\"");
    assert_proved(
        "for = [\"a = 0..\", \"n = 0..\"]\nlhs = \"sum(k, 0, n, C(a, k)*C(n, n - k))\"\nrhs = \"C(a + n, n)\"",
    );
    // Their false neighbours are not.
    assert_fails_at(
        "for = [\"n = 0..\"]\nlhs = \"sum(k, 0, n, C(n, k)^2)\"\nrhs = \"C(2n, n) + C(n, 5)\"",
        "n = 5",
    );
    // What the search finds is checked like a given certificate: a false claim is never
    // proved; the counterexample search past the cross-check finds where it fails.
    assert_fails_at(&format!("{POU}rhs = \"1 + C(n, 11)\""), "n = 11");
}

#[test]
fn a_wrong_certificate_or_claim_is_rejected() {
    // A wrong certificate: the WZ equation does not hold.
    assert_error(
        &format!("{POU}rhs = \"1\"\ncertificate = \"-(1-t)*i/(n+2-i)\""),
        "does not hold",
    );
    // The right one without the factor i: G(n, 0) ≠ 0, the ends do not telescope.
    assert_error(
        &format!("{POU}rhs = \"1\"\ncertificate = \"-(1-t)/(n+1-i)\""),
        "does not hold",
    );
    // A sum whose certificate the ansatz cannot find (Σ C(n, i)³ has none of this form) equal
    // to another sum (Strehl's identity, true): refused, with the reason.
    assert_error(
        "for = [\"n = 0..\"]\nlhs = \"sum(i, 0, n, C(n, i)^3)\"\nrhs = \"sum(j, 0, n, C(n, j)^2*C(2j, n))\"",
        "none found",
    );
    // The same sum with its variable renamed: one sum at the same n, proved (a recurrence
    // with coefficient 0, G = 0).
    assert_proved("for = [\"n = 0..\"]\nlhs = \"sum(i, 0, n, C(n, i)^3)\"\nrhs = \"sum(j, 0, n, C(n, j)^3)\"");
    // True for n ≤ 10 (and so for the evaluated n ≤ 3), false from n = 11 on: never proved,
    // and the search finds n = 11.
    assert_fails_at(
        &format!("{POU}rhs = \"1 + C(n, 11)\"\ncertificate = \"-(1-t)*i/(n+1-i)\""),
        "n = 11",
    );
    // False for small n: fails with an exact counterexample, whatever the certificate.
    let (v, _, _) = check(&format!(
        "{POU}rhs = \"1 + t*(1-t)\"\ncertificate = \"-(1-t)*i/(n+1-i)\""
    ))
    .unwrap();
    assert_eq!(v, Verdict::Fails);
    // A certificate belongs to a claim with an open range.
    assert_error(
        "for = [\"n = 0..=3\"]\nlhs = \"sum(i, 0, n, B(i, n, t))\"\nrhs = \"1\"\ncertificate = \"0\"",
        "open range",
    );
}

#[test]
fn what_is_not_supported_is_an_error() {
    // The library's de Casteljau evaluation is code, not a formula: not symbolic.
    assert_error(
        "polygon = { name = \"b\", degree = \"n\" }\nfor = [\"n = 0..\"]\nlhs = \"b(t)\"\nrhs = \"sum(i, 0, n, b[i]*B(i, n, t))\"",
        "not supported",
    );
    // A product of control points.
    assert_error(
        "polygon = { name = \"b\", degree = \"n\" }\nfor = [\"n = 0..\"]\nlhs = \"b[0]*b[0]\"\nrhs = \"b[0]\"",
        "affine",
    );
    // Division by an integer that may vanish on the domain.
    assert_error("for = [\"n = 0..\"]\nlhs = \"n/n\"\nrhs = \"1\"", "division");
}

#[test]
fn perturbed_identities_are_never_proved() {
    // True identities with a perturbation that vanishes for the evaluated n (or is small):
    // every variant must fail or be refused, none proved.
    let bases = [
        (
            "for = [\"n = 1..\", \"i = 0..=n\"]",
            "B(i, n, t)",
            "(1 - t)*B(i, n-1, t) + t*B(i-1, n-1, t)",
        ),
        (
            "for = [\"n = 1..\", \"i = 0..=n\"]",
            "diff(B(i, n, t), t)",
            "n*(B(i-1, n-1, t) - B(i, n-1, t))",
        ),
    ];
    let bumps = [
        "(n-1)*(n-2)*(n-3)*(n-4)*B(i, n, t)",
        "(n-1)*(n-2)*(n-3)*(n-4)*t^i",
        "(n-1)*(n-2)*(n-3)*(n-4)*C(n, i)",
        "(n-1)*(n-2)*(n-3)*(n-4)*B(i+1, n, t)",
        "C(i, 5)*t",
        "C(n, 5)*B(0, n, t)",
        "B(i, n-5, t)",
        "t*B(i-1, n-1, t) - t*B(i-1, n-1, t) + B(n+1, n, t) + C(n, 6)",
    ];
    for (range, lhs, rhs) in bases {
        for bump in bumps {
            let body = format!("{range}\nlhs = \"{lhs}\"\nrhs = \"{rhs} + {bump}\"");
            if let Ok((v, _, c)) = check(&body) {
                assert_ne!(v, Verdict::Proved, "{body}: {c}");
                assert_ne!(v, Verdict::ProvedInRange, "{body}: {c}");
            }
        }
    }
    // The partition of unity with a bump, and the right certificate.
    for bump in ["C(n, 4)", "C(n, 4)*t", "(n-1)*(n-2)*(n-3)*n*t^n", "B(4, n, t)"] {
        let body = format!("{POU}rhs = \"1 + {bump}\"\ncertificate = \"-(1-t)*i/(n+1-i)\"");
        if let Ok((v, _, c)) = check(&body) {
            assert_eq!(v, Verdict::Fails, "{body}: {c}");
        }
    }
}

/// A false claim: a verdict other than `proved`, or an error.
fn assert_not_proved(body: &str) {
    if let Ok((v, _, c)) = check(body) {
        assert_ne!(v, Verdict::Proved, "{body}: {c}");
    }
}

fn assert_fails_at(body: &str, at: &str) {
    match check(body) {
        Ok((Verdict::Fails, None, c)) => assert!(c.contains(at), "{body}: counterexample {c:?} should be {at:?}"),
        other => panic!("{body}: expected fails, got {other:?}"),
    }
}

#[test]
fn false_beyond_the_cross_check_still_fails_with_a_counterexample() {
    // Wrong only from n = 11, 12, 20 on: past the first values the proof's cross-check
    // evaluates, and no certificate can exist; the search finds the first wrong case.
    assert_fails_at(&format!("{POU}rhs = \"1 + C(n, 11)\""), "n = 11");
    assert_fails_at(
        "for = [\"n = 0..\"]\nlhs = \"sum(i, 0, n, i*B(i, n, t))\"\nrhs = \"n*t + C(n - 7, 5)*t^3*(1-t)^3\"",
        "n = 12",
    );
    assert_fails_at(
        "for = [\"n = 1..\"]\nlhs = \"B(2, n, t)\"\nrhs = \"(1 - t)*B(2, n - 1, t) + t*B(1, n - 1, t) + C(n, 20)*t - C(n, 20)\"",
        "n = 20",
    );
}

const ELEVATION_8: &str = "polygon = { name = \"b\", degree = \"n\" }\nfor = [\"n = 0..\", \"r = 0..\"]\nlhs = \"sum(i, 0, n, b[i]*B(i, n, t))\"\n";

#[test]
fn repeated_elevation_is_proved_by_induction_on_the_steps_and_its_false_variants_are_not() {
    // (8): the coefficient of the unit point b[ĵ] is Σ_{i=ĵ}^{ĵ+r}, by induction on r ≤ ….
    let c = assert_proved(&format!(
        "{ELEVATION_8}rhs = \"sum(i, 0, n+r, sum(j, i-r, i, C(n, j)*C(r, i-j)/C(n+r, i)*b[j])*B(i, n+r, t))\""
    ));
    assert!(c.contains("(induction on r ≥ 0)"), "{c}");
    for wrong in [
        // an index shift in the weights
        "sum(i, 0, n+r, sum(j, i-r, i, C(n, j)*C(r, i-j+1)/C(n+r, i)*b[j])*B(i, n+r, t))",
        // a wrong range end: one control point too few
        "sum(i, 0, n+r, sum(j, i-r+1, i, C(n, j)*C(r, i-j)/C(n+r, i)*b[j])*B(i, n+r, t))",
        // the outer sum one term short
        "sum(i, 0, n+r-1, sum(j, i-r, i, C(n, j)*C(r, i-j)/C(n+r, i)*b[j])*B(i, n+r, t))",
        // wrong only from r = 5 on, past the evaluated first values
        "sum(i, 0, n+r, sum(j, i-r, i, C(n, j)*C(r, i-j)/C(n+r, i)*b[j])*B(i, n+r, t)) + r*(r-1)*(r-2)*(r-3)*(r-4)*t*b[0]",
    ] {
        let body = format!("{ELEVATION_8}rhs = \"{wrong}\"");
        assert_not_proved(&body);
    }
}

#[test]
fn powers_written_as_products_are_recognized_and_false_ones_are_not_proved() {
    // ((1 − s)(1 − t))^n = (1 − s)^n (1 − t)^n: the base splits over the other bases.
    assert_proved(
        "for = [\"n = 0..\"]\nvars = [\"s\", \"t\"]\nlhs = \"(1 - s - t + s*t)^n\"\nrhs = \"(1 - s)^n*(1 - t)^n\"",
    );
    for wrong in ["(1 - s)^n*(1 + t)^n", "(1 - s)^n*(1 - t)^(n+1)", "(1 - s - t)^n"] {
        let body =
            format!("for = [\"n = 0..\"]\nvars = [\"s\", \"t\"]\nlhs = \"(1 - s - t + s*t)^n\"\nrhs = \"{wrong}\"");
        assert_not_proved(&body);
    }
}

#[test]
fn a_sum_starts_where_its_binomials_do_and_a_wrong_start_is_not_proved() {
    // B(j, r, t0) = 0 for r < j: Σ_{r=0}^{n} is Σ_{r=j}^{n}, identity (4) with the other side its hint.
    let four = "for = [\"n = 0..\", \"j = 0..=n\"]\nvars = [\"t0\", \"t\"]\nlhs = \"B(j, n, t0*t)\"\n";
    assert_proved(&format!("{four}rhs = \"sum(r, 0, n, B(j, r, t0)*B(r, n, t))\""));
    // the binomial theorem inside a product, by induction on n from j
    assert_proved(
        "for = [\"n = 0..\", \"j = 0..=n\"]\nvars = [\"s\", \"t\"]\nlhs = \"C(n, j)*(1 - s*t)^(n-j)*(s*t)^j\"\nrhs = \"C(n, j)*sum(i, 0, n-j, C(n-j, i)*(1-t)^(n-j-i)*t^i*(1-s)^i)*(s*t)^j\"",
    );
    for wrong in [
        "sum(r, 1, n, B(j, r, t0)*B(r, n, t))",
        "sum(r, 0, n-1, B(j, r, t0)*B(r, n, t))",
        "sum(r, 0, n, B(j, r, t0)*B(r+1, n, t))",
    ] {
        let body = format!("{four}rhs = \"{wrong}\"");
        assert_not_proved(&body);
    }
}
