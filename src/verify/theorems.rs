//! The general theorems of the texts, checked on the library's own code for every degree in
//! a range.
//!
//! Most theorems are identities that are affine in the control points; they are written as
//! identity claims over a symbolic polygon `b` (so the prover checks them on the zero and unit
//! polygons, at enough parameters for the degree it derives) and call the library through
//! `elev`, `left`, `deriv`, … (see [`super::methods::PolygonMethod`]). The others (affine
//! invariance, the convex hull property, Theorem 1.2) have their own exact checks here.

use super::claims::{Convergence, Decls, IntRange, PolygonSpec, Theorem};
use super::context::Ctx;
use super::kernel::checked::{Method, Step};
use super::kernel::{check_all, check_computed, Trusted};
use super::outcome::{Checked, Computed};
use super::sampling::{chain_work, check_chain, MAX_WORK};
use crate::curve::BezierCurve;
use crate::error::{Error, Result};
use crate::exact::SmallRational;
use crate::point::{AffineMap, Point};
use crate::scalar::{Ring, Scalar};

/// The exact numbers of these checks: machine words while values fit (most do), big
/// integers beyond, so the same verdicts at a fraction of the cost of `BigRational`.
type Q = SmallRational;

/// The theorems known to `kind = "theorem"`, with what each checks.
pub const THEOREMS: &[(&str, &str)] = &[
    (
        "de_casteljau_bernstein",
        "de Casteljau (1) = eval_bernstein = Σ b_i B_i^n(t)",
    ),
    ("partition_of_unity", "Σ_i B_i^n(t) = 1"),
    ("elevation_7", "elevate() gives the points (7) and the same curve"),
    (
        "elevation_8",
        "elevate_by(r) gives the points (8) = r steps of (7), and the same curve",
    ),
    (
        "subdivision",
        "Lemma 1.3: split_at(t0) gives b(t0 t) and b(t0 + (1-t0) t), with the scheme's boundary as points",
    ),
    ("identity_4", "(4): B_j^n(st) = Σ_{r=j}^n B_j^r(s) B_r^n(t)"),
    (
        "derivative",
        "d/dt b(t) = n Σ Δb_j B_j^{n-1}(t) (library derivative and the formula)",
    ),
    ("derivative_k", "d^k/dt^k b(t) = n!/(n-k)! Σ Δ^k b_j B_j^{n-k}(t)"),
    ("endpoint_tangent", "b'(0) = n(b_1 - b_0), b'(1) = n(b_n - b_{n-1})"),
    ("tangent_at_t0", "b'(t0) = n (b_1^{n-1}(t0) - b_0^{n-1}(t0))"),
    ("affine_invariance", "transform(Φ) then evaluate = evaluate then Φ"),
    (
        "convex_hull",
        "b(t) lies in the convex hull of the control points for 0 ≤ t ≤ 1",
    ),
];

/// Largest degree a theorem is checked for.
pub const MAX_THEOREM_DEGREE: i64 = 64;

/// The number of elevation steps `r = 0..=R` that `elevation_8` checks for each degree.
const ELEVATION_STEPS: i64 = 4;

/// The degree range `lo..=hi` of a theorem claim: non-empty, from 0, at most
/// [`MAX_THEOREM_DEGREE`].
fn degrees(theorem: &Theorem) -> Result<(i64, i64)> {
    let text = theorem.degrees.as_deref().unwrap_or("0..=10");
    let r = super::parse::closed_range(&IntRange::parse(&format!("n = {text}"))?)?;
    let empty = Default::default();
    let (lo, hi) = (
        super::kernel::expr::eval_int(&r.from, &empty)?,
        super::kernel::expr::eval_int(&r.to, &empty)?,
    );
    if lo < 0 || hi < lo {
        return Err(Error::Domain(format!(
            "the degree range {lo}..={hi} is {}: write degrees = \"a..=b\" with 0 ≤ a ≤ b",
            if lo < 0 { "negative" } else { "empty" }
        )));
    }
    if hi > MAX_THEOREM_DEGREE {
        return Err(Error::TooLarge {
            what: "theorem degree",
            value: format!("{lo}..={hi}"),
            limit: format!("degrees up to {MAX_THEOREM_DEGREE}"),
        });
    }
    Ok((lo, hi))
}

/// The finite ranges a theorem claim is checked over, e.g. `n = 0..=10` (and the elevation
/// steps of `elevation_8`): the scope of its `proved_in_range`.
pub fn scope(theorem: &Theorem) -> Result<String> {
    let (lo, hi) = degrees(theorem)?;
    let mut s = format!("n = {lo}..={hi}");
    match theorem.theorem.as_str() {
        "elevation_8" => s.push_str(&format!(", r = 0..={ELEVATION_STEPS}")),
        "derivative_k" => s.push_str(", k = 1..=n"),
        "affine_invariance" => s.push_str(", in the plane"),
        _ => {}
    }
    Ok(s)
}

/// One identity over the symbolic polygon `b` of degree `n`.
struct Part {
    label: &'static str,
    ranges: Vec<String>,
    chain: Vec<String>,
    vars: Vec<&'static str>,
}

fn part(label: &'static str, min_n: i64, extra: &[&str], vars: &[&'static str], chain: &[&str]) -> (i64, Part) {
    (
        min_n,
        Part {
            label,
            ranges: extra.iter().map(|s| s.to_string()).collect(),
            chain: chain.iter().map(|s| s.to_string()).collect(),
            vars: vars.to_vec(),
        },
    )
}

/// One identity a theorem checks over the symbolic polygon `b` of degree `n`: its least `n`,
/// its own ranges, the chain, the continuous parameters.
pub(crate) type Identity = (i64, Vec<String>, Vec<String>, Vec<&'static str>);

/// The identities theorem `name` checks (the k-th derivative for k ≤ 2), or `None` for a
/// theorem with an exact check of its own (affine invariance, the convex hull).
pub(crate) fn identities(name: &str) -> Option<Vec<Identity>> {
    let parts = parts_of(name, 2)?;
    Some(parts.into_iter().map(|(n, p)| (n, p.ranges, p.chain, p.vars)).collect())
}

fn parts_of(name: &str, kmax: i64) -> Option<Vec<(i64, Part)>> {
    Some(match name {
        "de_casteljau_bernstein" => vec![part(
            "b(t) = bsum = Σ b_i B_i^n",
            0,
            &[],
            &["t"],
            &["b(t)", "bsum(b, t)", "sum(i, 0, n, b[i]*B(i, n, t))"],
        )],
        "partition_of_unity" => vec![part("Σ B_i^n = 1", 0, &[], &["t"], &["sum(i, 0, n, B(i, n, t))", "1"])],
        "elevation_7" => vec![
            part(
                "points (7)",
                0,
                &["i = 0..=n+1"],
                &[],
                &["elevp(b, 1, i)", "i/(n+1)*b[i-1] + (1 - i/(n+1))*b[i]"],
            ),
            part("same curve", 0, &[], &["t"], &["elev(b, 1, t)", "b(t)"]),
        ],
        "elevation_8" => vec![
            part(
                "points (8)",
                0,
                &["r = 0..=4", "i = 0..=n+r"],
                &[],
                &["elevp(b, r, i)", "sum(j, i-r, i, C(n, j)*C(r, i-j)/C(n+r, i)*b[j])"],
            ),
            part(
                "same curve, = r steps of (7)",
                0,
                &["r = 0..=4"],
                &["t"],
                &["elev(b, r, t)", "steps(b, r, t)", "b(t)"],
            ),
        ],
        "subdivision" => vec![
            part("c1(t) = b(t0 t)", 0, &[], &["t0", "t"], &["left(b, t0, t)", "b(t0*t)"]),
            part(
                "c2(t) = b(t0 + (1-t0) t)",
                0,
                &[],
                &["t0", "t"],
                &["right(b, t0, t)", "b(t0 + (1 - t0)*t)"],
            ),
            part(
                "points of c1: b_0^r(t0)",
                0,
                &["r = 0..=n"],
                &["t0"],
                &["leftp(b, t0, r)", "b(0, r, t0)"],
            ),
            part(
                "points of c2: b_r^{n-r}(t0)",
                0,
                &["r = 0..=n"],
                &["t0"],
                &["rightp(b, t0, r)", "b(r, n - r, t0)"],
            ),
        ],
        "identity_4" => vec![part(
            "(4)",
            0,
            &["j = 0..=n"],
            &["s", "t"],
            &["B(j, n, s*t)", "sum(r, j, n, B(j, r, s)*B(r, n, t))"],
        )],
        "derivative" => vec![part(
            "first derivative",
            1,
            &[],
            &["t"],
            &[
                "deriv(b, 1, t)",
                "b'(t)",
                "diff(sum(j, 0, n, b[j]*B(j, n, t)), t)",
                "n*sum(j, 0, n - 1, delta(b, 1, j)*B(j, n - 1, t))",
            ],
        )],
        "derivative_k" => {
            // One part per order k (diff needs a literal order). The order is also the
            // part's integer symbol `k` (a range of one value), so that each case's equality
            // names it: a certificate's goal then covers the claim's `k = 1..=n`.
            let mut v = Vec::new();
            for k in 1..=kmax {
                let d = format!("diff(sum(j, 0, n, b[j]*B(j, n, t)), t, {k})");
                let f = "n!/(n - k)!*sum(j, 0, n - k, delta(b, k, j)*B(j, n - k, t))".to_string();
                let l = "deriv(b, k, t)".to_string();
                v.push((
                    k,
                    Part {
                        label: "k-th derivative",
                        ranges: vec![format!("k = {k}..={k}")],
                        chain: vec![l, d, f],
                        vars: vec!["t"],
                    },
                ));
            }
            v
        }
        "endpoint_tangent" => vec![
            part("b'(0)", 1, &[], &[], &["deriv(b, 1, 0)", "n*(b[1] - b[0])"]),
            part("b'(1)", 1, &[], &[], &["deriv(b, 1, 1)", "n*(b[n] - b[n - 1])"]),
        ],
        "tangent_at_t0" => vec![part(
            "b'(t0)",
            1,
            &[],
            &["t0"],
            &["deriv(b, 1, t0)", "n*(b(1, n - 1, t0) - b(0, n - 1, t0))"],
        )],
        _ => return None,
    })
}

/// A part of a theorem lowered to the declarations of an identity over the symbolic polygon
/// `b` of degree `n`: `n` in `n_range`, then the part's own ranges, its parameters.
pub(crate) fn part_decls(n_range: String, ranges: &[String], vars: &[&str]) -> Result<Decls> {
    let ranges = std::iter::once(n_range.as_str())
        .chain(ranges.iter().map(String::as_str))
        .map(IntRange::parse)
        .collect::<Result<Vec<_>>>()?;
    Ok(Decls {
        polygon: Some(PolygonSpec {
            name: "b".into(),
            degree: "n".into(),
        }),
        ranges,
        vars: Some(vars.iter().map(|s| s.to_string()).collect()),
        ..Decls::default()
    })
}

fn sub_sides(sub: &Ctx<'_>, chain: &[String]) -> Result<Vec<super::kernel::expr::Expr>> {
    chain.iter().map(|s| sub.expr(s)).collect()
}

/// `kind = "theorem"`.
pub fn check_theorem(ctx: &Ctx<'_>, theorem: &Theorem, detail: bool) -> Result<Checked> {
    let id = ctx.id;
    let name = theorem.theorem.as_str();
    let (lo, hi) = degrees(theorem)?;
    match name {
        "affine_invariance" => return affine_invariance(lo, hi),
        "convex_hull" => return convex_hull(lo, hi, detail),
        _ => {}
    }
    let parts = parts_of(name, hi).ok_or_else(|| {
        Error::Parse(format!(
            "claim {id}: unknown theorem '{name}' (known: {})",
            THEOREMS.iter().map(|t| t.0).collect::<Vec<_>>().join(", ")
        ))
    })?;
    // Every part as an identity claim over the symbolic polygon `b` of degree `n`; the work
    // of all parts is estimated before any is checked.
    let mut prepared = Vec::new();
    let mut work = 0;
    for (min_n, p) in parts {
        let from = lo.max(min_n);
        if from > hi {
            continue;
        }
        // The theorem claim declares nothing: each part's context is its declarations.
        let sub = ctx.with_declarations(part_decls(format!("n = {from}..={hi}"), &p.ranges, &p.vars)?)?;
        let sides = sub_sides(&sub, &p.chain)?;
        prepared.push((p, sub, sides));
    }
    for (_, sub, sides) in &prepared {
        work = chain_work::<Q>(sub, sides, work).map_err(|e| lower_degrees(e, name))?;
    }
    let mut certs = Vec::new();
    let mut steps = Vec::new();
    let mut method = Method::Evaluation;
    let mut proofs = Vec::new();
    let mut operations = Vec::new();
    for (p, sub, sides) in &prepared {
        let mut out = check_chain::<Q>(sub, sides, detail)?;
        operations.extend(super::methods::operations_called(sides));
        if let Some(m) = out.method() {
            method = method.join(m);
        }
        if detail {
            steps.push(Step::text(format!("{}: {}", p.label, p.chain.join(" = "))));
            steps.extend(out.steps.iter().cloned().map(|s| s.nested(1)));
        }
        let text = std::mem::take(&mut out.certificate);
        let Some(proof) = out.into_proof() else {
            let mut f = Checked::fails(format!("{} ({}): {text}", p.label, p.chain.join(" = "))).found_by(method);
            f.steps = steps;
            return Ok(f);
        };
        proofs.push(proof);
        certs.push(format!("[{}] {text}", p.label));
    }
    let Some(proof) = check_all(proofs) else {
        return Err(Error::Domain(format!(
            "claim {id}: the degree range {lo}..={hi} is empty for {name}"
        )));
    };
    let mut out = operations
        .into_iter()
        .fold(Checked::proved(proof, certs.join("; ")), Checked::resting_on);
    out.steps = steps;
    Ok(out)
}

/// The machine words of a value of degree `n` at the parameters `k/n`: `(n+1)·2·log2(n+1)`
/// bits, at least one word (as `sampling` counts the sample points).
fn sample_words(n: i64) -> u128 {
    let k = n.max(0) as u128 + 1;
    let bits = 2 * u128::from(u128::BITS - k.leading_zeros());
    (k * bits / 64).max(1)
}

/// A work limit's error, saying how to lower the work of a theorem claim.
fn lower_degrees(e: Error, name: &str) -> Error {
    match e {
        Error::TooLarge { what, value, limit } => Error::TooLarge {
            what,
            value,
            limit: format!(
                "{limit}; lower the top of `degrees` (docs/limits.md lists the degrees admitted for `{name}`)"
            ),
        },
        e => e,
    }
}

/// The sum of the estimated work of each degree, or an error naming [`MAX_WORK`].
fn within_work_limit(per_degree: impl Iterator<Item = u128>) -> Result<()> {
    let work = per_degree.fold(0u128, u128::saturating_add);
    if work > MAX_WORK {
        return Err(Error::TooLarge {
            what: "estimated work of the claim",
            value: format!("{work} units"),
            limit: format!(
                "MAX_WORK = {MAX_WORK} units; lower the top of `degrees` (docs/limits.md lists the degrees admitted)"
            ),
        });
    }
    Ok(())
}

fn unit_polygon(n: usize, dim: usize, k: usize, coord: usize) -> Result<BezierCurve<Q>> {
    let pts = (0..=n)
        .map(|i| {
            let mut c = vec![Q::zero(); dim];
            if i == k {
                c[coord] = Q::one();
            }
            Point::new(c)
        })
        .collect::<Result<_>>()?;
    BezierCurve::new(pts)
}

fn params(d: usize) -> Result<Vec<Q>> {
    (0..=d).map(|k| Q::from_ratio(k as i64, d.max(1) as i64)).collect()
}

/// Affine invariance: `transform(Φ)(t) = Φ(b(t))` for every affine `Φ(p) = A p + c` (in the
/// plane). Both sides are `Σ_i B_i(t) (A b_i) + c·(…)`: bilinear in `(A, polygon)` plus linear
/// in `c`, so it suffices to check matrix units `A = E_rs` with `c = 0` on the unit polygons,
/// and `A = 0` with translations `c = e_r` (on the zero polygon), each at `n + 1` parameters.
fn affine_invariance(lo: i64, hi: i64) -> Result<Checked> {
    // 4 matrix units × 2(n+1) unit polygons and 2 translations, at n+1 parameters, 2 sides,
    // each evaluation (n+1)² operations on numbers of (n+1)·2·log2(n+1) bits (t = k/n); the
    // factor 8 is measured (a transform and a map besides each evaluation).
    within_work_limit((lo..=hi).map(|n| {
        let k = n as u128 + 1;
        let words = sample_words(n);
        8 * (8 * k * k + 2 * k) * 2 * k * k * words * words
    }))?;
    let mut evaluations = 0;
    let dim = 2;
    for n in lo.max(0) as usize..=hi as usize {
        let ts = params(n)?;
        let mut maps: Vec<(AffineMap<Q>, bool)> = Vec::new();
        for r in 0..dim {
            for s in 0..dim {
                let mut m = vec![vec![Q::zero(); dim]; dim];
                m[r][s] = Q::one();
                maps.push((AffineMap::new(m, vec![Q::zero(); dim])?, false));
            }
            let mut c = vec![Q::zero(); dim];
            c[r] = Q::one();
            maps.push((AffineMap::new(vec![vec![Q::zero(); dim]; dim], c)?, true));
        }
        for (map, translation) in &maps {
            let polygons: Vec<BezierCurve<Q>> = if *translation {
                vec![BezierCurve::new(vec![Point::origin(dim); n + 1])?]
            } else {
                let mut v = Vec::new();
                for k in 0..=n {
                    for coord in 0..dim {
                        v.push(unit_polygon(n, dim, k, coord)?);
                    }
                }
                v
            };
            for p in &polygons {
                let moved = p.transform(map)?;
                for t in &ts {
                    evaluations += 2;
                    let (l, r) = (moved.eval(t), map.apply(&p.eval(t))?);
                    if l != r {
                        return Ok(Checked::fails(format!("counterexample at n = {n}, t = {t}, polygon {p}, map {map:?}: transform then eval = {l}, eval then map = {r}"),
                        ));
                    }
                }
            }
        }
    }
    let proof = check_computed(&[], &[Trusted::Transform]).expect("no fact failed");
    let mut out = Checked::proved(
        proof,
        format!(
            "for every n = {lo}..={hi}: both sides are bilinear in (A, control points) plus linear in c, degree ≤ n in t; \
             checked on the 4 matrix units × 2(n+1) unit polygons and the 2 translations, at t = k/n (n+1 points); \
             {evaluations} exact evaluations: proof"
        ),
    );
    out.computed = vec![Computed::AffineInvariance {
        lo,
        hi,
        sum_one: PARTITION_OF_UNITY,
    }];
    Ok(out)
}

/// The convex hull property: `B_i^n(t) = C(n,i) t^i (1-t)^(n-i) ≥ 0` on `[0, 1]` (a product of
/// non-negative factors) and `Σ_i B_i^n(t) = 1` (an identity of degree ≤ n, proved at n + 1
/// points), so `b(t) = Σ B_i^n(t) b_i` is a convex combination; and the library's exact hull
/// test finds convex weights for sample curve points.
fn convex_hull(lo: i64, hi: i64, detail: bool) -> Result<Checked> {
    // The exact hull tests dominate: about 20 (n+1)⁴ units each (measured: degrees 0..=34
    // took 2.3 s at 4 (n+1)⁴).
    within_work_limit((lo..=hi).map(|n| 20 * (n as u128 + 1).pow(4)))?;
    let mut steps = Vec::new();
    let mut hull_checks = 0;
    for n in lo.max(0) as usize..=hi as usize {
        let ts = params(n)?;
        for t in &ts {
            let basis: Vec<Q> = crate::bernstein::bernstein_all(n, t);
            let sum = basis.iter().fold(Q::zero(), |a, b| a + b);
            if sum != Q::one() {
                return Ok(Checked::fails(format!("Σ B_i^{n}({t}) = {sum} ≠ 1")));
            }
            if basis.iter().any(|b| *b < Q::zero()) {
                return Ok(Checked::fails(format!(
                    "a Bernstein polynomial of degree {n} is negative at t = {t}"
                )));
            }
        }
        // A sample curve of degree n in the plane (a zig-zag), its points at t = k/8 in the hull.
        let pts: Vec<Point<Q>> = (0..=n)
            .map(|i| Point::new(vec![Q::from_usize(i), Q::from_i64(((i * 7) % 5) as i64 - 2)]))
            .collect::<Result<_>>()?;
        let curve = BezierCurve::new(pts)?;
        for k in 0..=8 {
            let t = Q::from_ratio(k, 8)?;
            let p = curve.eval(&t);
            match curve.hull_weights(&p)? {
                Some(w) => {
                    hull_checks += 1;
                    if detail && n == hi as usize {
                        steps.push(Step::text(format!(
                            "n = {n}, t = {t}: b(t) = {p} = Σ w_i b_i with w = {:?}",
                            w.iter().map(|x| x.to_string()).collect::<Vec<_>>()
                        )));
                    }
                }
                None => {
                    return Ok(Checked::fails(format!(
                        "the point b({t}) = {p} of the curve {curve} is outside the convex hull of its control points"
                    )))
                }
            }
        }
    }
    let proof = check_computed(&[], &[Trusted::BernsteinAll, Trusted::HullWeights]).expect("no fact failed");
    let mut out = Checked::proved(
        proof,
        format!(
            "for every n = {lo}..={hi}: B_i^n(t) = C(n,i) t^i (1−t)^(n−i) is a product of factors ≥ 0 on [0, 1], \
             and Σ_i B_i^n(t) = 1 (degree ≤ n, exact at t = k/n, n+1 points) ⇒ b(t) is a convex combination of the b_i: proof; \
             also the exact hull test found convex weights for {hull_checks} sample curve points"
        ),
    );
    out.steps = steps;
    out.computed = vec![Computed::ConvexHull {
        lo,
        hi,
        nonnegative: BASIS_NONNEG,
        sum_one: PARTITION_OF_UNITY,
    }];
    Ok(out)
}

/// The claims of text 000 whose goals a certificate of the convex hull and of the affine
/// invariance cites as lemmas (`docs/certificates.md`): `B_i^n(t) ≥ 0` on `[0, 1]` and
/// `Σ_i B_i^n(t) = 1`, each for every `n ≥ 0`. A `check` without their files leaves the two
/// "not re-checked".
const BASIS_NONNEG: &str = "000-basis-nonneg";
const PARTITION_OF_UNITY: &str = "000-partition-of-unity";

/// The bound used for Theorem 1.2: `max_i |b_i^(r) − b(i/(n+r))|_∞ ≤ n(n−1)/(2(n+r)) · max_j |Δ²b_j|_∞`.
///
/// Why it holds: `b_i^(r) = E f(J)` for `J` hypergeometric and `b(i/(n+r)) = E f(K)` for `K`
/// binomial with the same mean (`f(j) = b_j`, per coordinate); `J` is smaller than `K` in the
/// convex order (Hoeffding 1963), so `|E f(K) − E f(J)| ≤ M/2 (Var K − Var J)` with
/// `M = max|Δ²f|`, and `Var K − Var J = n(n−1) i(N−i) / (N²(N−1)) ≤ n(n−1)/(4(N−1))`,
/// `N = n + r`. That is at most half the bound stated here (`N ≥ 2`; for `n ≤ 1` both are 0).
pub fn elevation_bound<T: Scalar>(curve: &BezierCurve<T>, r: usize) -> Result<T> {
    let n = curve.degree();
    if n < 2 {
        return Ok(T::zero());
    }
    let d2 = curve.forward_differences(2)?;
    let m = d2
        .iter()
        .flat_map(|p| p.coords().iter().map(Scalar::abs))
        .fold(T::zero(), |a, b| if b > a { b } else { a });
    let factor = T::from_ratio((n * (n - 1)) as i64, (2 * (n + r)) as i64)?;
    Ok(factor * m)
}

/// `kind = "convergence"`: Theorem 1.2, bounded evidence on the claim's curves.
pub fn check_convergence(ctx: &Ctx<'_>, c: &Convergence, detail: bool) -> Result<Checked> {
    let steps_max = c.steps.unwrap_or(64);
    if steps_max > 512 {
        return Err(Error::TooLarge {
            what: "elevation steps",
            value: steps_max.to_string(),
            limit: "512".into(),
        });
    }
    let curves = ctx
        .decls
        .curves
        .as_ref()
        .filter(|m| !m.is_empty())
        .ok_or_else(|| Error::Parse(format!("claim {}: convergence needs curves", ctx.id)))?;
    let mut lines = Vec::new();
    let mut summary = Vec::new();
    let mut recorded = Vec::new();
    for (name, spec) in curves {
        let curve: BezierCurve<Q> = BezierCurve::new(super::objects::points(&spec.points)?)?;
        let d = curve.elevation_distances(steps_max)?;
        recorded.push((
            name.clone(),
            curve
                .points()
                .iter()
                .map(|p| p.coords().iter().map(Q::to_big).collect())
                .collect(),
            d.iter().map(|e| e.max_norm.to_big()).collect(),
        ));
        for w in d.windows(2) {
            if w[1].max_norm > w[0].max_norm {
                return Ok(Checked::fails(format!(
                    "{name}: the distance grows from r = {} ({}) to r = {} ({})",
                    w[0].r, w[0].max_norm, w[1].r, w[1].max_norm
                )));
            }
        }
        for e in &d {
            let bound = elevation_bound(&curve, e.r)?;
            if e.max_norm > bound {
                return Ok(Checked::fails(format!(
                    "{name}: at r = {} the distance {} exceeds the bound {bound}",
                    e.r, e.max_norm
                )));
            }
            if detail {
                lines.push(Step::text(format!(
                    "{name}, r = {}: max_i |b_i^(r) − b(i/(n+r))|_∞ = {} ≤ {bound}",
                    e.r, e.max_norm
                )));
            }
        }
        let last = d.last().expect("r = 0 is always there");
        summary.push(format!(
            "{name} (degree {}): distance {} at r = 0 down to {} ≈ {:.3e} at r = {}",
            curve.degree(),
            d[0].max_norm,
            last.max_norm,
            Scalar::to_f64(&last.max_norm),
            last.r
        ));
    }
    let mut out = Checked::verified(format!(
        "bounded evidence, not a proof of the limit: for r = 0..={steps_max} the exact max-norm distances between the \
             r-times elevated polygon and the curve at i/(n+r) never increase and satisfy the O(1/r) bound \
             n(n−1)/(2(n+r))·max_j|Δ²b_j|_∞ (which tends to 0); {}",
        summary.join("; ")
    ));
    out.steps = lines;
    out.computed = vec![super::outcome::Computed::Convergence {
        steps: steps_max,
        curves: recorded,
    }];
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::super::claims::parse_file;
    use super::*;
    use std::path::Path;

    fn theorem(degrees: &str, theorem: &str) -> Theorem {
        let claim = parse_file(
            &format!(
                "[[claim]]\nid = \"x\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"theorem\"\ntheorem = \"{theorem}\"\ndegrees = \"{degrees}\""
            ),
            Path::new("t.toml"),
        )
        .unwrap()
        .claim
        .remove(0);
        match claim.kind {
            super::super::claims::Kind::Theorem(t) => t,
            _ => unreachable!("a theorem claim"),
        }
    }

    #[test]
    fn the_scope_names_every_range_checked() {
        let c = theorem("0..=6", "elevation_8");
        assert_eq!(scope(&c).unwrap(), "n = 0..=6, r = 0..=4");
        let c = theorem("2..=5", "derivative");
        assert_eq!(scope(&c).unwrap(), "n = 2..=5");
    }

    #[test]
    fn degree_ranges_are_checked() {
        for (bad, want) in [
            ("5..=3", "empty"),
            ("-2..=3", "negative"),
            ("0..=-1", "empty"),
            ("0..=65", "64"),
        ] {
            let c = theorem(bad, "convex_hull");
            let err = degrees(&c).unwrap_err().to_string();
            assert!(err.contains(want), "{bad}: {err}");
        }
    }

    #[test]
    fn work_beyond_the_limit_is_refused_before_computing() {
        assert!(within_work_limit([MAX_WORK].into_iter()).is_ok());
        let err = within_work_limit([MAX_WORK, 1].into_iter()).unwrap_err().to_string();
        assert!(err.contains("MAX_WORK"), "{err}");
    }
}
