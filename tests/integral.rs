//! `integral(e, t, a, b)`: exact integrals of polynomial integrands, hygienic in `let`, and
//! false values fail.

#[path = "support/identity.rs"]
mod identity;

use casteljau::verify::Verdict;
use identity::check;

#[test]
fn integrals_of_the_basis() {
    let (v, c) =
        check("for = [\"n = 0..=8\", \"i = 0..=n\"]\nlhs = \"integral(B(i, n, t), t, 0, 1)\"\nrhs = \"1/(n+1)\"")
            .unwrap();
    assert_eq!(v, Verdict::ProvedInRange, "{c}");
    let (v, c) =
        check("for = [\"n = 0..=8\", \"i = 0..=n\"]\nlhs = \"integral(B(i, n, t), t, 0, 1)\"\nrhs = \"1/(n+2)\"")
            .unwrap();
    assert_eq!(v, Verdict::Fails, "{c}");
    assert!(c.contains("left side = 1, right side = 1/2"), "{c}");
}

#[test]
fn bounds_may_be_parameters_and_the_variable_is_bound() {
    let (v, c) = check("vars = [\"s\"]\nlhs = \"integral(3t^2 + 1, t, 0, s)\"\nrhs = \"s^3 + s\"").unwrap();
    assert_eq!(v, Verdict::Proved, "{c}");
    let (v, _) = check("vars = [\"s\"]\nlhs = \"integral(3t^2 + 1, t, 0, s)\"\nrhs = \"s^3\"").unwrap();
    assert_eq!(v, Verdict::Fails);
    // f(t) = ∫_0^1 t·x dx: the argument t is not captured by the variable of integration (which
    // would give ∫_0^1 t·t dt = 1/3); the integrand then has another parameter: refused.
    let captured = check("vars = [\"t\"]\nlet = [\"f(u) = integral(u*t, t, 0, 1)\"]\nlhs = \"f(t)\"\nrhs = \"1/3\"");
    assert!(captured.is_err(), "{captured:?}");
    // An integrand with another parameter, or a rational one, is refused.
    assert!(check("vars = [\"s\"]\nlhs = \"integral(s*t, t, 0, 1)\"\nrhs = \"s/2\"").is_err());
    assert!(check("vars = [\"s\"]\nlhs = \"integral(1/(1+t), t, 0, s)\"\nrhs = \"s\"").is_err());
}
