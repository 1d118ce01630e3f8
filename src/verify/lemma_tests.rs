// Induction from a first value other than 0: the base read from the definition there.
use super::super::claims::parse_file;
use super::super::context::Ctx;
use super::super::symbolic::{attempt_for_every, prove_symbolic};
use super::super::{Method, Verdict};
use std::borrow::Cow;
use std::path::Path;

/// Claims by induction from a first value other than 0 (the scheme and the differences
/// from 1), and a false one whose base at 1 only a wrong reading of `b(i, 1, t)` passes.
const FROM_ONE: &str = r#"
[[claim]]
id = "scheme-from-1"
source = "s"
statement = "s"
kind = "identity"
polygon = { name = "b", degree = "n" }
vars = ["t"]
for = ["n = 1..", "r = 1..=n", "i = 0..=n-r"]
induction = "r"
lhs = "b(i, r, t)"
rhs = "sum(j, 0, r, b[i+j]*B(j, r, t))"

[[claim]]
id = "delta-from-1"
source = "s"
statement = "s"
kind = "identity"
polygon = { name = "b", degree = "n" }
vars = []
for = ["n = 1..", "k = 1..=n", "j = 0..=n-k"]
induction = "k"
lhs = "delta(b, k, j)"
rhs = "sum(i, 0, k, (-1)^(k-i)*C(k, i)*b[j+i])"

[[claim]]
id = "scheme-offset-false"
source = "s"
statement = "s"
kind = "identity"
polygon = { name = "b", degree = "n" }
vars = ["t"]
for = ["n = 1..", "r = 1..=n", "i = 0..=n-r"]
induction = "r"
lhs = "b(i, r, t)"
rhs = "sum(j, 0, r-1, b[i+j]*B(j, r-1, t))"

[[claim]]
id = "delta-from-2"
source = "s"
statement = "s"
kind = "identity"
polygon = { name = "b", degree = "n" }
vars = []
for = ["n = 2..", "k = 2..=n", "j = 0..=n-k"]
induction = "k"
lhs = "delta(b, k, j)"
rhs = "sum(i, 0, k, (-1)^(k-i)*C(k, i)*b[j+i])"

[[claim]]
id = "delta-from-2-false"
source = "s"
statement = "s"
kind = "identity"
polygon = { name = "b", degree = "n" }
vars = []
for = ["n = 2..", "k = 2..=n", "j = 0..=n-k"]
induction = "k"
lhs = "delta(b, k, j)"
rhs = "sum(i, 0, k-1, (-1)^(k-1-i)*C(k-1, i)*b[j+i])"

[[claim]]
id = "delta-late-false"
source = "s"
statement = "s"
kind = "identity"
polygon = { name = "b", degree = "n" }
vars = []
for = ["n = 1..", "k = 1..=n", "j = 0..=n-k"]
induction = "k"
lhs = "delta(b, k, j)"
rhs = "sum(i, 0, k, (-1)^(k-i)*C(k, i)*b[j+i]) + (k-1)*(k-2)*b[j]"

[[claim]]
id = "scheme-late-false"
source = "s"
statement = "s"
kind = "identity"
polygon = { name = "b", degree = "n" }
vars = ["t"]
for = ["n = 1..", "r = 1..=n", "i = 0..=n-r"]
induction = "r"
lhs = "b(i, r, t)"
rhs = "sum(j, 0, r, b[i+j]*B(j, r, t)) + (r-1)*(r-2)*t*b[i]"
"#;

/// The symbolic proof alone (no evaluation cross-check, no counterexample search).
fn induction_alone(id: &str) -> Result<String, String> {
    let file = parse_file(FROM_ONE, Path::new("from_one.toml")).unwrap();
    let claim = file.claim.iter().find(|c| c.id == id).unwrap();
    let identity = claim.kind.identity().unwrap();
    let ctx = Ctx::new(&claim.id, Cow::Borrowed(&claim.decls), Vec::new()).unwrap();
    attempt_for_every(&ctx, &identity).map_err(|e| e.to_string())
}

#[test]
fn the_base_is_the_definition_at_the_first_value() {
    for id in ["scheme-from-1", "delta-from-1", "delta-from-2"] {
        let cert = induction_alone(id).unwrap_or_else(|e| panic!("{id}: {e}"));
        assert!(cert.starts_with("by induction on"), "{id}: {cert}");
    }
    // Wrong only at the first value, and right there but wrong from r = 3 (the step fails).
    for id in [
        "scheme-offset-false",
        "delta-from-2-false",
        "delta-late-false",
        "scheme-late-false",
    ] {
        let err = induction_alone(id).expect_err(id);
        assert!(!err.is_empty(), "{id}");
    }
}

/// The claims of `../shared/repro/induction_base_not_zero.toml` (w2a, w2b true; w2c false,
/// passing base and step only under a reading of `b(i, 1, t)` as `b[i]`), as `FROM_ONE` writes
/// them: the kernel's induction check alone, without the evaluation cross-check, proves the
/// true ones and refuses the false one.
#[test]
fn the_kernel_checks_the_induction_without_the_cross_check() {
    let file = parse_file(FROM_ONE, Path::new("from_one.toml")).unwrap();
    let kernel_alone = |id: &str| {
        let claim = file.claim.iter().find(|c| c.id == id).unwrap();
        let identity = claim.kind.identity().unwrap();
        let ctx = Ctx::new(&claim.id, Cow::Borrowed(&claim.decls), Vec::new()).unwrap();
        let closed = ctx.closed_after(super::super::symbolic::CROSS_CHECK).unwrap();
        prove_symbolic(&ctx, &identity, &closed, &[]).map(|(_, _, proof)| proof)
    };
    for id in ["scheme-from-1", "delta-from-1"] {
        let proof = kernel_alone(id).unwrap_or_else(|e| panic!("{id}: {e}"));
        assert!(proof.verdict() == Verdict::Proved, "{id}");
        assert_eq!(proof.method(), Method::Induction, "{id}");
        assert!(proof.rests_on().is_empty(), "{id}");
    }
    let err = kernel_alone("scheme-offset-false").expect_err("the false claim");
    assert!(err.to_string().contains("does not hold"), "{err}");
}
