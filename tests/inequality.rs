//! The `inequality` kind: Bernstein certificates on an interval, exact refutations, and `B ≥ 0`
//! for every n; false inequalities are never proved.

#[path = "support/identity.rs"]
mod identity;
use casteljau::verify::Verdict;

fn check(body: &str) -> casteljau::Result<(Verdict, Option<String>, String)> {
    identity::check_table(&format!("kind = \"inequality\"\nvars = [\"t\"]\n{body}"), true)
}

#[test]
fn bernstein_certificates_prove() {
    let (v, _, c) = check("lhs = \"(2t - 1)^2\"\ninterval = [0, 1]").unwrap();
    assert_eq!(v, Verdict::Proved, "{c}");
    assert!(c.contains("2 subintervals"), "{c}");
    let (v, _, c) = check("lhs = \"t^2 - t + 26/100\"\nrelation = \">\"\ninterval = [0, 1]").unwrap();
    assert_eq!(v, Verdict::Proved, "{c}");
    // A rational function with a denominator > 0 on the interval.
    let (v, _, _) = check("lhs = \"t/(1 + t^2)\"\nrhs = \"t/2\"\ninterval = [0, 1]").unwrap();
    assert_eq!(v, Verdict::Proved);
    // Over a finite range: proved in range.
    let (v, r, _) =
        check("for = [\"n = 0..=5\", \"i = 0..=n\"]\nlhs = \"1\"\nrhs = \"B(i, n, t)\"\ninterval = [0, 1]").unwrap();
    assert_eq!(
        (v, r.as_deref()),
        (Verdict::ProvedInRange, Some("n = 0..=5, i = 0..=n"))
    );
}

#[test]
fn false_inequalities_fail_at_an_exact_point() {
    // ≥ 0 at both ends, −1/20 at t = 1/2.
    let (v, _, c) = check("lhs = \"t^2 - t + 1/5\"\ninterval = [0, 1]").unwrap();
    assert_eq!(v, Verdict::Fails);
    assert!(c.contains("at t = 1/2: left side − right side = -1/20"), "{c}");
    // Not strict: the value 0 at t = 1/2.
    let (v, _, c) = check("lhs = \"(2t - 1)^2\"\nrelation = \">\"\ninterval = [0, 1]").unwrap();
    assert_eq!(v, Verdict::Fails, "{c}");
    assert!(c.contains("= 0"), "{c}");
    // B ≥ 0 off [0, 1].
    let (v, _, c) = check("for = [\"n = 1..\", \"i = 0..=n\"]\nlhs = \"B(i, n, t)\"\ninterval = [0, 2]").unwrap();
    assert_eq!(v, Verdict::Fails, "{c}");
}

#[test]
fn basis_nonnegative_for_every_n() {
    let (v, r, c) = check("for = [\"n = 0..\", \"i = 0..=n\"]\nlhs = \"B(i, n, t)\"\ninterval = [0, 1]").unwrap();
    assert_eq!((v, r), (Verdict::Proved, None), "{c}");
    assert!(c.starts_with("for every n ≥ 0"), "{c}");
    // A product of nonnegative factors with a shifted index.
    let (v, _, c) =
        check("for = [\"n = 1..\", \"i = 0..=n\"]\nlhs = \"n*t*B(i-1, n-1, t)\"\ninterval = [0, 1]").unwrap();
    assert_eq!(v, Verdict::Proved, "{c}");
}

#[test]
fn what_cannot_be_shown_is_an_error_never_proved() {
    // True (0 ≤ B ≤ 1) but not a product of nonnegative factors: refused, with the reason.
    let err = check("for = [\"n = 0..\", \"i = 0..=n\"]\nlhs = \"1 - B(i, n, t)\"\ninterval = [0, 1]").unwrap_err();
    assert!(err.to_string().contains("cannot show"), "{err}");
    // False from n = 5 on only (evaluated n ≤ 3 pass): never proved.
    let err =
        check("for = [\"n = 0..\", \"i = 0..=n\"]\nlhs = \"B(i, n, t) - n*(n-1)*(n-2)*(n-3)*t\"\ninterval = [0, 1]")
            .unwrap_err();
    assert!(err.to_string().contains("cannot show"), "{err}");
    // A double root at 1/3 is not decided within the halving limit.
    assert!(check("lhs = \"(t - 1/3)^2\"\ninterval = [0, 1]").is_err());
    // A bad relation.
    assert!(check("lhs = \"t\"\nrelation = \"<=\"\ninterval = [0, 1]").is_err());
}
