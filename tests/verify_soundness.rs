//! A wrong `proved` is the worst bug: false and unproved claims written outside the texts get
//! `fails` with an exact counterexample or a one-line error, never `proved`; a finite range is
//! `proved_in_range` with its range; random false claims are never proved.

#[path = "support/identity.rs"]
mod identity;
use casteljau::verify::Verdict;
use proptest::prelude::*;

/// The verdict, range and certificate of the single claim in `body` (a claim's fields
/// without id/source/statement).
fn check(body: &str) -> casteljau::Result<(Verdict, Option<String>, String)> {
    identity::check_table(body, false)
}

/// The claim fails with an exact counterexample.
fn assert_fails(body: &str) -> String {
    match check(body) {
        Ok((Verdict::Fails, _, c)) => {
            assert!(c.contains("left side") || c.contains("at "), "{body}: {c}");
            c
        }
        other => panic!("{body}: expected fails, got {other:?}"),
    }
}

/// The claim is refused with a one-line error mentioning `needle`.
fn assert_error(body: &str, needle: &str) -> String {
    match check(body) {
        Err(e) => {
            let msg = e.to_string();
            assert_eq!(msg.lines().count(), 1, "{body}: {msg}");
            assert!(msg.contains(needle), "{body}: {msg:?} should mention {needle:?}");
            msg
        }
        Ok(other) => panic!("{body}: expected an error, got {other:?}"),
    }
}

/// Fails or is refused; never proved.
fn assert_not_proved(body: &str) {
    if let Ok((v, _, c)) = check(body) {
        assert!(
            !matches!(v, Verdict::Proved | Verdict::ProvedInRange),
            "{body}: {v:?}: {c}"
        );
    }
}

const IDENTITY: &str = "kind = \"identity\"\n";

#[test]
fn bug1_a_control_point_inside_an_evaluation_is_tracked() {
    // b(b[1]) = b0 (1 - b1) + b1 b1: not affine in the control points.
    let body = format!(
        "{IDENTITY}polygon = {{ name = \"b\", degree = \"1\" }}\nvars = []\nlhs = \"b(b[1])\"\nrhs = \"b[0] + b[1]\""
    );
    assert_error(&body, "affine");
    // Through a library operation too.
    let body = format!(
        "{IDENTITY}polygon = {{ name = \"b\", degree = \"2\" }}\nvars = []\nlhs = \"bsum(b, b[1])\"\nrhs = \"b[0]\""
    );
    assert_error(&body, "affine");
}

#[test]
fn bug2_a_polygon_and_a_net_share_one_basis() {
    let body = format!(
        "{IDENTITY}polygon = {{ name = \"b\", degree = \"1\" }}\nnet = {{ name = \"c\", degree = [\"0\", \"0\"] }}\nvars = []\nlhs = \"b[0]\"\nrhs = \"0\""
    );
    let c = assert_fails(&body);
    assert!(c.contains("b[0] = 1"), "{c}");
    let body = format!(
        "{IDENTITY}polygon = {{ name = \"b\", degree = \"1\" }}\nnet = {{ name = \"c\", degree = [\"0\", \"0\"] }}\nvars = []\nlhs = \"c[0, 0] + b[1]\"\nrhs = \"b[1]\""
    );
    let c = assert_fails(&body);
    assert!(c.contains("c[0, 0] = 1"), "{c}");
    // A true identity over both is proved.
    let body = format!(
        "{IDENTITY}polygon = {{ name = \"b\", degree = \"1\" }}\nnet = {{ name = \"c\", degree = [\"1\", \"0\"] }}\nlhs = \"b(t) + c(t, 0)\"\nrhs = \"(1-t)(b[0] + c[0, 0]) + t(b[1] + c[1, 0])\""
    );
    assert_eq!(check(&body).unwrap().0, Verdict::Proved);
}

#[test]
fn bug3_an_implies_factor_with_a_pole_on_the_premise_is_refuted_or_refused() {
    // False, argued with 1/k: refuted at the pole.
    let body =
        "kind = \"implies\"\nsymbols = [\"k\", \"l\"]\npremise = \"k*l\"\nequation = \"l = 0\"\nfactor = \"1/k\"";
    let c = assert_fails(body);
    assert!(c.contains("at k = 0, l = 1: the premise 'k*l' holds"), "{c}");
    // True, but the argument divides by k where the premise holds: no counterexample at the
    // pole, so refused with the reason.
    let body =
        "kind = \"implies\"\nsymbols = [\"k\", \"l\"]\npremise = \"k^2*l\"\nequation = \"k*l = 0\"\nfactor = \"1/k\"";
    assert_error(body, "no counterexample among the first 2401 small rational points");
    // A polynomial factor is a proof.
    let body =
        "kind = \"implies\"\nsymbols = [\"k\", \"l\"]\npremise = \"k - l\"\nequation = \"2k = 2l\"\nfactor = \"2\"";
    assert_eq!(check(body).unwrap().0, Verdict::Proved);
    // A denominator that is a denominator of the equation itself is fine: the equation is
    // only claimed where it is defined.
    let body =
        "kind = \"implies\"\nsymbols = [\"k\", \"l\"]\npremise = \"k*l - 1\"\nequation = \"l = 1/k\"\nfactor = \"1/k\"";
    assert_eq!(check(body).unwrap().0, Verdict::Proved);
}

#[test]
fn bug4_let_substitution_does_not_capture() {
    let body = format!("{IDENTITY}let = [\"e(x) = sum(j, 0, 1, x)\"]\nlhs = \"sum(j, 0, 2, e(j))\"\nrhs = \"3\"");
    let c = assert_fails(&body);
    assert!(c.contains("left side = 6"), "{c}");
    let body = format!("{IDENTITY}let = [\"e(x) = sum(j, 0, 1, x)\"]\nlhs = \"sum(j, 0, 2, e(j))\"\nrhs = \"6\"");
    assert_eq!(check(&body).unwrap().0, Verdict::Proved);
    // A definition's free name is not captured by a sum at the use site either.
    let body = format!("{IDENTITY}vars = [\"t\"]\nlet = [\"D = t + 1\"]\nlhs = \"sum(t, 0, 1, D)\"\nrhs = \"2t + 2\"");
    assert_eq!(check(&body).unwrap().0, Verdict::Proved);
}

#[test]
fn bug5_definitions_in_dependency_order_and_unknown_names() {
    let body = format!("{IDENTITY}vars = [\"t\"]\nlet = [\"D = diff(F, t)\", \"F = t^2\"]\nlhs = \"D\"\nrhs = \"0\"");
    let c = assert_fails(&body);
    assert!(c.contains("left side = 2"), "{c}");
    let body = format!("{IDENTITY}vars = [\"t\"]\nlet = [\"D = diff(F, t)\", \"F = t^2\"]\nlhs = \"D\"\nrhs = \"2t\"");
    assert_eq!(check(&body).unwrap().0, Verdict::Proved);
    let body = format!("{IDENTITY}vars = [\"t\"]\nlet = [\"D = diff(F, t)\"]\nlhs = \"D\"\nrhs = \"0\"");
    assert_error(&body, "unknown name 'F'");
    let body = format!("{IDENTITY}let = [\"F = G + 1\", \"G = F\"]\nlhs = \"F\"\nrhs = \"0\"");
    assert_error(&body, "circular");
}

#[test]
fn bug6_exponents_are_checked() {
    let body = format!("{IDENTITY}symbols = [\"k\"]\nlhs = \"(k^4096)^16\"\nrhs = \"k*(k^4096)^16\"");
    assert_error(&body, "limit");
}

#[test]
fn bug7_empty_and_inverted_ranges_are_errors() {
    assert_error(
        &format!("{IDENTITY}for = [\"n = 1..=0\"]\nlhs = \"1\"\nrhs = \"2\""),
        "empty",
    );
    assert_error(
        &format!("{IDENTITY}for = [\"n = 0..=3\", \"j = n..=2\"]\nlhs = \"1\"\nrhs = \"1\""),
        "empty",
    );
    assert_error(
        "kind = \"theorem\"\ntheorem = \"derivative\"\ndegrees = \"5..=3\"",
        "empty",
    );
    assert_error(
        "kind = \"theorem\"\ntheorem = \"convex_hull\"\ndegrees = \"0..=-1\"",
        "empty",
    );
}

#[test]
fn bug8_a_finite_range_is_proved_in_range_not_proved() {
    let body = format!("{IDENTITY}for = [\"n = 0..=10\"]\nlhs = \"sum(i, 0, n, B(i, n, t))\"\nrhs = \"1 + C(n, 11)\"");
    let (v, range, _) = check(&body).unwrap();
    assert_eq!(v, Verdict::ProvedInRange);
    assert_eq!(range.as_deref(), Some("n = 0..=10"));
    // ... and it is false just outside the range.
    let body = format!("{IDENTITY}for = [\"n = 0..=11\"]\nlhs = \"sum(i, 0, n, B(i, n, t))\"\nrhs = \"1 + C(n, 11)\"");
    assert_fails(&body);
    let (v, range, _) = check("kind = \"theorem\"\ntheorem = \"partition_of_unity\"\ndegrees = \"0..=5\"").unwrap();
    assert_eq!((v, range.as_deref()), (Verdict::ProvedInRange, Some("n = 0..=5")));
}

#[test]
fn mixing_square_roots_is_an_error_not_a_counterexample() {
    assert_error(
        &format!("{IDENTITY}lhs = \"sqrt(2)*sqrt(3)\"\nrhs = \"sqrt(6)\""),
        "sqrt",
    );
    assert_eq!(
        check(&format!("{IDENTITY}lhs = \"(1 + sqrt(2))^2\"\nrhs = \"3 + 2 sqrt(2)\""))
            .unwrap()
            .0,
        Verdict::Proved
    );
}

#[test]
fn claims_cannot_shadow_built_ins() {
    assert_error(
        &format!("{IDENTITY}let = [\"B(i, n, t) = 1\"]\nlhs = \"B(0, 1, t)\"\nrhs = \"1\""),
        "shadow",
    );
    assert_error(
        "kind = \"theorem\"\ntheorem = \"derivative\"\nlet = [\"b(t) = 0\"]",
        "does not belong",
    );
}

#[test]
fn work_is_bounded() {
    let start = std::time::Instant::now();
    assert_error(
        &format!("{IDENTITY}lhs = \"((1+t)^4096)^24\"\nrhs = \"((1+t)^4096)^24\""),
        "limit",
    );
    assert_error(
        "kind = \"theorem\"\ntheorem = \"elevation_8\"\ndegrees = \"0..=62\"",
        "limit",
    );
    assert_error(
        "kind = \"theorem\"\ntheorem = \"elevation_8\"\ndegrees = \"62..=62\"",
        "limit",
    );
    assert!(
        start.elapsed().as_secs() < 5,
        "refusals must be fast: {:?}",
        start.elapsed()
    );
}

#[test]
fn a_vector_side_against_a_number_is_an_error() {
    assert_error(&format!("{IDENTITY}lhs = \"(t, 1)\"\nrhs = \"t\""), "shape");
}

/// The engine computes on machine words while values fit; past 64 bits a value moves to big
/// integers exactly, so a difference far below the leading bits is still a counterexample.
#[test]
fn values_beyond_machine_words_stay_exact() {
    let square = "(2^40*t + 3)^2";
    let expanded = "2^80*t^2 + 6*2^40*t + 9";
    let true_claim = format!("{IDENTITY}lhs = \"{square}\"\nrhs = \"{expanded}\"");
    assert_eq!(check(&true_claim).unwrap().0, Verdict::Proved);
    for wrong in [
        format!("{expanded} + t/2^70"),
        format!("{expanded} + 1"),
        "(2^80 + 1)*t^2 + 6*2^40*t + 9".to_string(),
        format!("{expanded} + (2^63 - 1)*t*(t - 1)*(t - 1/2)/2^63"),
    ] {
        assert_fails(&format!("{IDENTITY}lhs = \"{square}\"\nrhs = \"{wrong}\""));
    }
    // Near the edges of i64: (2^63 - 1) t + 1 and its neighbours.
    let edge = format!("{IDENTITY}lhs = \"(2^63 - 1)*t + 1 - 2^63*t\"\nrhs = \"1 - t\"");
    assert_eq!(check(&edge).unwrap().0, Verdict::Proved);
    assert_fails(&format!(
        "{IDENTITY}lhs = \"(2^63 - 1)*t + 1 - 2^63*t\"\nrhs = \"1 - t + t/(2^63 - 1)\""
    ));
}

/// A true identity: `Σ_k c_k B(k, n, t) = Σ_k c_k C(n, k) t^k (1 - t)^(n - k)` written in the
/// power basis, with one coefficient of the right side changed.
fn perturbed_identity(coeffs: &[i64], which: usize, delta: (i64, i64)) -> String {
    let n = coeffs.len() - 1;
    let lhs: Vec<String> = coeffs
        .iter()
        .enumerate()
        .map(|(k, c)| format!("({c})*B({k}, {n}, t)"))
        .collect();
    let rhs: Vec<String> = coeffs
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let c = if k == which {
                format!("({c} + {}/{})", delta.0, delta.1)
            } else {
                c.to_string()
            };
            format!("({c})*C({n}, {k})*t^{k}*(1 - t)^({n} - {k})")
        })
        .collect();
    format!("{IDENTITY}lhs = \"{}\"\nrhs = \"{}\"", lhs.join(" + "), rhs.join(" + "))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// A true identity with one coefficient perturbed by a non-zero rational is never proved.
    #[test]
    fn perturbed_identities_are_never_proved(
        coeffs in prop::collection::vec(-9i64..10, 1..9),
        which in 0usize..8,
        num in prop_oneof![-20i64..-1, 1i64..20],
        den in 1i64..12,
    ) {
        let which = which % coeffs.len();
        let true_claim = perturbed_identity(&coeffs, which, (0, 1));
        prop_assert_eq!(check(&true_claim).unwrap().0, Verdict::Proved);
        let body = perturbed_identity(&coeffs, which, (num, den));
        let (v, _, c) = check(&body).unwrap();
        prop_assert_eq!(v, Verdict::Fails, "{}", c);
    }

    /// The same over a range of degrees: the perturbed sum identity fails in some case.
    #[test]
    fn perturbed_range_identities_are_never_proved(num in prop_oneof![-20i64..-1, 1i64..20], den in 1i64..12, hi in 0i64..6) {
        let body = format!(
            "{IDENTITY}for = [\"n = 0..={hi}\"]\nlhs = \"sum(i, 0, n, B(i, n, t))\"\nrhs = \"1 + {num}/{den} * C(n, {hi})\""
        );
        let (v, _, c) = check(&body).unwrap();
        prop_assert_eq!(v, Verdict::Fails, "{}", c);
        assert_not_proved(&body);
    }
}
