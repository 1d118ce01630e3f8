//! Lemmas (`uses`) and induction (`induction = "r"`): library objects proved for every n
//! through their definitions, and false variants of every new form never proved.

use casteljau::verify::claims::parse_file;
use casteljau::verify::{prove_files, Verdict};
use std::path::Path;

/// One claim's TOML table over the polygon `b` of degree `n`, in the parameter `t`.
fn claim(id: &str, ranges: &str, lhs: &str, rhs: &str, extra: &str) -> String {
    format!(
        "[[claim]]\nid = \"{id}\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\n{extra}\npolygon = {{ name = \"b\", degree = \"n\" }}\nfor = [{ranges}]\nvars = [\"t\"]\nlhs = \"{lhs}\"\nrhs = \"{rhs}\"\n"
    )
}

/// One claim over the polygon `b` of degree `n` for every n, in `t0` and `t`, citing the scheme;
/// `body` holds its sides (`lhs`/`rhs` or a `chain`) and any other fields.
fn subdivision_claim(id: &str, body: &str) -> String {
    format!(
        "[[claim]]\nid = \"{id}\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\npolygon = {{ name = \"b\", degree = \"n\" }}\nfor = [\"n = 0..\"]\nuses = [\"scheme\"]\nvars = [\"t0\", \"t\"]\n{body}\n"
    )
}

const SCHEME_RANGES: &str = r#""n = 0..", "r = 0..=n", "i = 0..=n-r""#;
const STEP_RANGES: &str = r#""n = 1..", "r = 1..=n", "i = 0..=n-r""#;

/// The closed form of the scheme (9), by induction on r.
fn scheme() -> String {
    claim(
        "scheme",
        SCHEME_RANGES,
        "b(i, r, t)",
        "sum(j, 0, r, b[i+j]*B(j, r, t))",
        "induction = \"r\"",
    )
}

/// Every claim's verdict and certificate (or error), by id.
fn verdicts(claims: &[String]) -> Vec<(String, Verdict, String)> {
    let file = parse_file(&claims.join("\n"), Path::new("lemmas.toml")).expect("claims parse");
    let report = prove_files(&[file], &mut |_, _, _| {}).expect("files are checked");
    report
        .outcomes
        .into_iter()
        .map(|o| (o.id, o.verdict, o.certificate))
        .collect()
}

/// Each of `false_claims`, checked beside the scheme (their lemma), fails or is an error.
fn assert_all_refuted_beside_the_scheme(false_claims: &[String]) {
    let mut all = vec![scheme()];
    all.extend(false_claims.iter().cloned());
    for (id, v, c) in verdicts(&all).into_iter().skip(1) {
        assert!(matches!(v, Verdict::Fails | Verdict::Error), "{id}: {v:?} {c}");
    }
}

fn verdict_of(claims: &[String], id: &str) -> (Verdict, String) {
    verdicts(claims)
        .into_iter()
        .find(|(i, _, _)| i == id)
        .map(|(_, v, c)| (v, c))
        .expect("the claim is reported")
}

#[test]
fn the_scheme_is_proved_by_induction_and_its_lemma_proves_the_recursion() {
    let rec = claim(
        "rec",
        STEP_RANGES,
        "b(i, r, t)",
        "(1 - t)*b(i, r-1, t) + t*b(i+1, r-1, t)",
        "uses = [\"scheme\"]",
    );
    let out = verdicts(&[scheme(), rec]);
    assert_eq!(out[0].1, Verdict::Proved, "{}", out[0].2);
    assert!(out[0].2.starts_with("by induction on r from 0"), "{}", out[0].2);
    assert!(out[0].2.contains("the claim at r its only hypothesis"), "{}", out[0].2);
    assert_eq!(out[1].1, Verdict::Proved, "{}", out[1].2);
    assert!(out[1]
        .2
        .contains("lemmas (proved for every value, each applied within its ranges): scheme"));
}

#[test]
fn the_evaluation_and_its_derivative_are_read_through_the_scheme() {
    let derivative = claim(
        "derivative",
        r#""n = 1..""#,
        "diff(b(t), t)",
        "n*sum(j, 0, n-1, (b[j+1] - b[j])*B(j, n-1, t))",
        "uses = [\"scheme\"]",
    );
    let second = claim(
        "second",
        r#""n = 2..""#,
        "b''(t)",
        "n*(n-1)*sum(j, 0, n-2, (b[j+2] - 2*b[j+1] + b[j])*B(j, n-2, t))",
        "uses = [\"scheme\"]",
    );
    for id in ["derivative", "second"] {
        let (v, c) = verdict_of(&[scheme(), derivative.clone(), second.clone()], id);
        assert_eq!(v, Verdict::Proved, "{id}: {c}");
        assert!(c.contains("b(g) = b(0, n, g), the last point of the scheme (9)"), "{c}");
    }
}

#[test]
fn false_variants_are_never_proved() {
    let false_claims = [
        // An index shifted by one, in the lemma or in a claim using it.
        claim(
            "shift",
            SCHEME_RANGES,
            "b(i, r, t)",
            "sum(j, 0, r, b[i+j+1]*B(j, r, t))",
            "induction = \"r\"",
        ),
        claim(
            "wrong-index",
            STEP_RANGES,
            "b(i, r, t)",
            "(1 - t)*b(i, r-1, t) + t*b(i, r-1, t)",
            "uses = [\"scheme\"]",
        ),
        // A wrong range end of a sum.
        claim(
            "sum-end",
            SCHEME_RANGES,
            "b(i, r, t)",
            "sum(j, 0, r-1, b[i+j]*B(j, r, t))",
            "induction = \"r\"",
        ),
        // A false derivative (the factor n missing).
        claim(
            "no-factor",
            r#""n = 1..""#,
            "diff(b(t), t)",
            "sum(j, 0, n-1, (b[j+1] - b[j])*B(j, n-1, t))",
            "uses = [\"scheme\"]",
        ),
        // An induction whose hypothesis would be needed at r + 1.
        claim(
            "next",
            r#""n = 1..", "r = 0..=n-1", "i = 0..=n-r-1""#,
            "b(i, r, t)",
            "b(i, r+1, t)",
            "induction = \"r\"",
        ),
    ];
    assert_all_refuted_beside_the_scheme(&false_claims);
}

#[test]
fn induction_from_one_reads_the_base_from_the_definition() {
    // At r = 1 the scheme point is (1 − t)·b[i] + t·b[i+1], not b[i]; Δ¹b_j = b[j+1] − b[j].
    let scheme_from_1 = claim(
        "s1",
        STEP_RANGES,
        "b(i, r, t)",
        "sum(j, 0, r, b[i+j]*B(j, r, t))",
        "induction = \"r\"",
    );
    let delta_from_1 = claim(
        "d1",
        r#""n = 1..", "k = 1..=n", "j = 0..=n-k""#,
        "delta(b, k, j)",
        "sum(i, 0, k, (-1)^(k-i)*C(k, i)*b[j+i])",
        "induction = \"k\"",
    );
    // The scheme one level lower: its base at r = 1 is false.
    let offset = claim(
        "off",
        STEP_RANGES,
        "b(i, r, t)",
        "sum(j, 0, r-1, b[i+j]*B(j, r-1, t))",
        "induction = \"r\"",
    );
    let out = verdicts(&[scheme_from_1, delta_from_1, offset]);
    for (id, v, c) in &out[..2] {
        assert_eq!(*v, Verdict::Proved, "{id}: {c}");
        assert!(c.contains("from 1"), "{id}: {c}");
    }
    assert!(matches!(out[2].1, Verdict::Fails | Verdict::Error), "{:?}", out[2]);
}

#[test]
fn a_lemma_only_proved_in_a_range_proves_nothing_for_every_n() {
    let in_range = claim(
        "in-range",
        r#""n = 0..=5", "r = 0..=n", "i = 0..=n-r""#,
        "b(i, r, t)",
        "sum(j, 0, r, b[i+j]*B(j, r, t))",
        "",
    );
    let rec = claim(
        "rec",
        STEP_RANGES,
        "b(i, r, t)",
        "(1 - t)*b(i, r-1, t) + t*b(i+1, r-1, t)",
        "uses = [\"in-range\"]",
    );
    let (v, c) = verdict_of(&[in_range, rec], "rec");
    assert_eq!(v, Verdict::Error, "{c}");
    assert!(c.contains("it cites in-range, which is proved_in_range"), "{c}");
}

#[test]
fn cyclic_and_unknown_citations_are_errors_and_hide_no_other_verdict() {
    let a = claim(
        "a",
        SCHEME_RANGES,
        "b(i, r, t)",
        "sum(j, 0, r, b[i+j]*B(j, r, t))",
        "uses = [\"b\"]",
    );
    let b = claim(
        "b",
        SCHEME_RANGES,
        "b(i, r, t)",
        "sum(j, 0, r, b[i+j]*B(j, r, t))",
        "uses = [\"a\"]",
    );
    let c = claim(
        "c",
        SCHEME_RANGES,
        "b(i, r, t)",
        "sum(j, 0, r, b[i+j]*B(j, r, t))",
        "uses = [\"nowhere\"]",
    );
    let out = verdicts(&[a, b, c, scheme()]);
    assert_eq!(out[0].1, Verdict::Error);
    assert!(
        out[0].2.contains("the citations form a cycle: a → b → a"),
        "{}",
        out[0].2
    );
    assert_eq!(out[1].1, Verdict::Error);
    assert!(
        out[2].2.contains("it cites nowhere, which is not a claim"),
        "{}",
        out[2].2
    );
    assert_eq!(out[3].1, Verdict::Proved);
}

#[test]
fn a_lemma_applies_only_within_its_ranges() {
    // True, but proved only for r < n: the recursion at r = n may not use it.
    let narrow = claim(
        "narrow",
        r#""n = 1..", "r = 0..=n-1", "i = 0..=n-r""#,
        "b(i, r, t)",
        "sum(j, 0, r, b[i+j]*B(j, r, t))",
        "induction = \"r\"",
    );
    let top = claim(
        "top",
        r#""n = 1..""#,
        "b(0, n, t)",
        "sum(j, 0, n, b[j]*B(j, n, t))",
        "uses = [\"narrow\"]",
    );
    let out = verdicts(&[narrow, top]);
    assert_eq!(out[0].1, Verdict::Proved, "{}", out[0].2);
    assert_eq!(out[1].1, Verdict::Error, "{}", out[1].2);
    assert!(
        out[1].2.contains("lemma narrow at b(0, n, t): cannot show"),
        "{}",
        out[1].2
    );
}

#[test]
fn induction_on_the_polygons_degree_is_refused() {
    let on_n = claim(
        "on-n",
        SCHEME_RANGES,
        "b(i, r, t)",
        "sum(j, 0, r, b[i+j]*B(j, r, t))",
        "induction = \"n\"",
    );
    let (v, c) = verdict_of(&[on_n], "on-n");
    assert_eq!(v, Verdict::Error);
    assert!(c.contains("induction on n: it is the polygon's degree"), "{c}");
}

/// One claim's TOML table over the net `b` of degrees `m`, `n`.
fn net_claim(id: &str, ranges: &str, lhs: &str, rhs: &str) -> String {
    format!(
        "[[claim]]\nid = \"{id}\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nnet = {{ name = \"b\", degree = [\"m\", \"n\"] }}\nfor = [{ranges}]\nvars = [\"u\", \"v\"]\nlhs = \"{lhs}\"\nrhs = \"{rhs}\"\n"
    )
}

#[test]
fn surfaces_and_their_partials_are_proved_for_every_degree_on_the_unit_net() {
    let claims = [
        net_claim(
            "twist",
            r#""m = 1..", "n = 1..""#,
            "b_uv(u, v)",
            "m*n*sum(i, 0, m-1, sum(j, 0, n-1, (b[i+1,j+1] - b[i+1,j] - b[i,j+1] + b[i,j])*B(i, m-1, u)*B(j, n-1, v)))",
        ),
        net_claim(
            "corners",
            r#""m = 0..", "n = 0..""#,
            "(b(0, 0), b(1, 0), b(0, 1), b(1, 1))",
            "(b[0,0], b[m,0], b[0,n], b[m,n])",
        ),
        net_claim(
            "corner-twist",
            r#""m = 1..", "n = 1..""#,
            "b_uv(1, 0)",
            "m*n*(b[m,1] - b[m,0] - b[m-1,1] + b[m-1,0])",
        ),
    ];
    for (id, v, c) in verdicts(&claims) {
        assert_eq!(v, Verdict::Proved, "{id}: {c}");
        assert!(c.contains("the zero net and the unit net"), "{c}");
    }
}

#[test]
fn false_surface_claims_are_never_proved() {
    let claims = [
        // The twist with a wrong sign, a missing factor, a shifted index, a wrong corner.
        net_claim(
            "sign",
            r#""m = 1..", "n = 1..""#,
            "b_uv(u, v)",
            "m*n*sum(i, 0, m-1, sum(j, 0, n-1, (b[i+1,j+1] - b[i+1,j] + b[i,j+1] - b[i,j])*B(i, m-1, u)*B(j, n-1, v)))",
        ),
        net_claim(
            "factor",
            r#""m = 1..", "n = 1..""#,
            "b_uv(u, v)",
            "m*sum(i, 0, m-1, sum(j, 0, n-1, (b[i+1,j+1] - b[i+1,j] - b[i,j+1] + b[i,j])*B(i, m-1, u)*B(j, n-1, v)))",
        ),
        net_claim("corner", r#""m = 0..", "n = 0..""#, "b(1, 0)", "b[0,m]"),
        net_claim(
            "corner-shift",
            r#""m = 1..", "n = 1..""#,
            "b_u(0, 0)",
            "m*(b[1,1] - b[0,0])",
        ),
    ];
    for (id, v, c) in verdicts(&claims) {
        assert!(matches!(v, Verdict::Fails | Verdict::Error), "{id}: {v:?} {c}");
    }
}

#[test]
fn the_end_values_of_derivatives_are_read_without_powers_of_zero() {
    let ends = claim(
        "ends",
        r#""n = 1..""#,
        "(b'(0), b'(1))",
        "(n*(b[1] - b[0]), n*(b[n] - b[n-1]))",
        "uses = [\"scheme\"]",
    );
    let wrong = claim(
        "wrong-end",
        r#""n = 1..""#,
        "b'(1)",
        "n*(b[n] - b[n-2])",
        "uses = [\"scheme\"]",
    );
    let out = verdicts(&[scheme(), ends, wrong]);
    assert_eq!(out[1].1, Verdict::Proved, "{}", out[1].2);
    assert!(matches!(out[2].1, Verdict::Fails | Verdict::Error), "{:?}", out[2]);
}

/// Lemma 1.3's proof (the chain of sums over `b[j]` and `r`) and the second half `c_2`.
const CHAIN_1_3: [&str; 8] = [
    "b(t0*t)",
    "sum(j, 0, n, b[j]*B(j, n, t0*t))",
    "sum(j, 0, n, b[j]*sum(r, j, n, B(j, r, t0)*B(r, n, t)))",
    "sum(j, 0, n, b[j]*sum(r, 0, n, B(j, r, t0)*B(r, n, t)))",
    "sum(j, 0, n, sum(r, 0, n, b[j]*B(j, r, t0)*B(r, n, t)))",
    "sum(r, 0, n, sum(j, 0, n, b[j]*B(j, r, t0))*B(r, n, t))",
    "sum(r, 0, n, sum(j, 0, r, b[j]*B(j, r, t0))*B(r, n, t))",
    "sum(r, 0, n, b(0, r, t0)*B(r, n, t))",
];

fn chain(members: &[&str]) -> String {
    let quoted: Vec<String> = members.iter().map(|m| format!("\"{m}\"")).collect();
    format!("chain = [{}]", quoted.join(", "))
}

#[test]
fn subdivision_is_proved_for_every_n_through_sums_over_the_unit_point() {
    let c2 = "lhs = \"b(t0 + (1 - t0)*t)\"\nrhs = \"sum(r, 0, n, b(r, n - r, t0)*B(r, n, t))\"";
    let out = verdicts(&[
        scheme(),
        subdivision_claim("proof", &chain(&CHAIN_1_3)),
        subdivision_claim("c2", c2),
    ]);
    for (id, v, c) in &out[1..] {
        assert_eq!(*v, Verdict::Proved, "{id}: {c}");
    }
    // c2's sum over r ≤ ĵ: induction on the unit index, bounded above by n.
    assert!(out[2].2.contains("(induction on __j ≥ 0)"), "{}", out[2].2);
}

#[test]
fn false_subdivision_variants_are_never_proved() {
    let mut shifted = CHAIN_1_3;
    shifted[2] = "sum(j, 0, n, b[j]*sum(r, j+1, n, B(j, r, t0)*B(r, n, t)))";
    let mut late = CHAIN_1_3;
    late[6] = "sum(r, 0, n, sum(j, 1, r, b[j]*B(j, r, t0))*B(r, n, t))";
    let false_claims = [
        // Not affine in the polygon: refused before any sum over the unit point collapses.
        subdivision_claim("square", "lhs = \"sum(j, 0, n, b[j]*b[j])\"\nrhs = \"sum(j, 0, n, b[j])\""),
        subdivision_claim("shifted-range", &chain(&shifted)),
        subdivision_claim("late-start", &chain(&late)),
        // The points of c2 with the wrong basis index.
        subdivision_claim(
            "c2-shift",
            "lhs = \"b(t0 + (1 - t0)*t)\"\nrhs = \"sum(r, 0, n, b(r, n - r, t0)*B(n - r, n, t))\"",
        ),
        // A wrong certificate is rejected, not trusted.
        subdivision_claim(
            "c2-wrong-certificate",
            "certificate = [\"r*t0*(1 - t)/((__j - r + 1)*(t0 + t - t0*t))\"]\nlhs = \"b(t0 + (1 - t0)*t)\"\nrhs = \"sum(r, 0, n, b(r, n - r, t0)*B(r, n, t))\"",
        ),
    ];
    assert_all_refuted_beside_the_scheme(&false_claims);
}
