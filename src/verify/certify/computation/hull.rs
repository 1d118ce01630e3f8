//! The convex hull and the affine invariance of text 000 as `computation` facts resting on
//! cited lemmas (`docs/certificates.md`, "Method `computation`"): the file lists each lemma by
//! claim id with the goal it assumes (`lemmas`, resolved among the files checked together as
//! for any proof citing lemmas), and the kernel accepts the fact only when those goals are,
//! exactly, `B(i, n, t) ≥ 0` on `[0, 1]` and `Σ_{i=0}^{n} B(i, n, t) = 1` for every `n ≥ 0`.
//! For the affine invariance the library's `transform` is also run again on the basis maps
//! and polygons (each control point must be mapped by `Φ`).

use super::super::hyper;
use super::super::nonneg;
use super::super::{field, string, Res};
use crate::curve::BezierCurve;
use crate::point::{AffineMap, Point};
use crate::verify::kernel::certificate::Symbolic;
use crate::verify::kernel::nonneg::{
    basis_nonneg_goal, check_affine_invariance, check_convex_combination, Unity, UNITY_MEMBERS,
};
use crate::verify::kernel::Trusted;
use crate::verify::outcome::Computed;
use num_rational::BigRational;
use num_traits::{One, Zero};
use serde_json::{json, Value as Json};

/// The kernel's argument for each kind of fact, as `check` reports it.
const CONVEX: &str = "B_i^n ≥ 0 on [0, 1] and Σ B_i^n = 1 make b(t) = Σ B_i^n(t) b_i a convex combination";
const AFFINE: &str = "Φ(Σ b_i B_i^n) = Σ Φ(b_i) B_i^n by linearity and Σ B_i^n = 1, transform run again on the 6 basis maps and the zero and unit polygons";

/// Largest degree a re-check runs `transform` for (the texts use 8).
const MAX_DEGREE: i64 = 64;

/// The dimension of the affine invariance's maps (the claim is in the plane).
const DIM: usize = 2;

/// The goal `Σ_{i=0}^{n} B(i, n, t) = 1` for every `n ≥ 0`, as its own file states it.
fn unity_goal() -> Symbolic {
    Symbolic {
        reals: vec!["t".into()],
        for_all: vec![("n".into(), "0".into(), None)],
        polygon: None,
        net: None,
        members: UNITY_MEMBERS.iter().map(|m| m.to_string()).collect(),
        certificates: Vec::new(),
        lemmas: Vec::new(),
        induction: None,
    }
}

fn degrees(lo: i64, hi: i64) -> Json {
    json!({"from": lo.to_string(), "to": hi.to_string()})
}

/// The fact and the cited lemmas (`{"id", "goal"}`) of a theorem resting on lemmas; `None`
/// for another computation.
pub(super) fn fact(c: &Computed) -> Option<(Json, Vec<Json>)> {
    let unity = |id: &str| json!({"id": id, "goal": hyper::goal_json(&unity_goal())});
    match c {
        Computed::ConvexHull {
            lo,
            hi,
            nonnegative,
            sum_one,
        } => Some((
            json!({"computation": "convex_combination", "degrees": degrees(*lo, *hi),
                   "nonnegative": nonnegative, "sum_one": sum_one}),
            vec![
                json!({"id": nonnegative, "goal": nonneg::goal_json(&basis_nonneg_goal())}),
                unity(sum_one),
            ],
        )),
        Computed::AffineInvariance { lo, hi, sum_one } => Some((
            json!({"computation": "affine_invariance", "degrees": degrees(*lo, *hi), "sum_one": sum_one}),
            vec![unity(sum_one)],
        )),
        _ => None,
    }
}

/// The goal the file lists for the cited lemma named by the fact's `key`.
fn cited<'a>(fact: &Json, key: &str, at: &str, lemmas: &[(String, &'a Json)]) -> Res<&'a Json> {
    let id = string(fact, key, at)?;
    lemmas
        .iter()
        .find(|(l, _)| l == id)
        .map(|(_, g)| *g)
        .ok_or_else(|| format!("{at}.{key}: lemma {id} is not among the file's lemmas"))
}

fn range(fact: &Json, at: &str) -> Res<(i64, i64)> {
    let d = field(fact, "degrees", at)?;
    let end = |k: &str| -> Res<i64> {
        string(d, k, &format!("{at}.degrees"))?
            .parse()
            .map_err(|_| format!("{at}.degrees.{k}: not an integer"))
    };
    let (lo, hi) = (end("from")?, end("to")?);
    if !(0..=hi).contains(&lo) || hi > MAX_DEGREE {
        return Err(format!("{at}.degrees: not 0 ≤ from ≤ to ≤ {MAX_DEGREE}"));
    }
    Ok((lo, hi))
}

/// Whether the library's `transform` maps every control point by the map, for the 4 matrix
/// units (no translation) and the 2 unit translations, on the zero polygon and every unit
/// polygon of each degree `lo..=hi` (the maps and polygons span all of them: the result is
/// affine in each, as the proof assumes).
fn transform_maps_points(lo: i64, hi: i64) -> Res<bool> {
    let e = |e: crate::error::Error| e.to_string();
    let q = |x: bool| if x { BigRational::one() } else { BigRational::zero() };
    let mut maps = Vec::new();
    for r in 0..DIM {
        for s in 0..DIM {
            let m = (0..DIM)
                .map(|a| (0..DIM).map(|b| q(a == r && b == s)).collect())
                .collect();
            maps.push(AffineMap::new(m, vec![BigRational::zero(); DIM]).map_err(e)?);
        }
        let c = (0..DIM).map(|a| q(a == r)).collect();
        maps.push(AffineMap::new(vec![vec![BigRational::zero(); DIM]; DIM], c).map_err(e)?);
    }
    for n in lo as usize..=hi as usize {
        let mut polygons = vec![None];
        polygons.extend((0..=n).flat_map(|k| (0..DIM).map(move |c| Some((k, c)))));
        for unit in polygons {
            let points = (0..=n)
                .map(|i| Point::new((0..DIM).map(|c| q(unit == Some((i, c)))).collect()))
                .collect::<crate::error::Result<Vec<_>>>()
                .map_err(e)?;
            let curve = BezierCurve::new(points).map_err(e)?;
            for map in &maps {
                let moved = curve.transform(map).map_err(e)?;
                if moved.points().len() != curve.points().len() {
                    return Ok(false);
                }
                for (m, p) in moved.points().iter().zip(curve.points()) {
                    if *m != map.apply(p).map_err(e)? {
                        return Ok(false);
                    }
                }
            }
        }
    }
    Ok(true)
}

/// Re-checks a fact resting on cited lemmas: the computations the kernel's proof rests on;
/// `None` for another computation; with the argument, as `check` reports it.
pub(super) fn recheck(fact: &Json, at: &str, lemmas: &[(String, &Json)]) -> Res<Option<(Vec<Trusted>, &'static str)>> {
    let kind = string(fact, "computation", at)?;
    if !matches!(kind, "convex_combination" | "affine_invariance") {
        return Ok(None);
    }
    let (lo, hi) = range(fact, at)?;
    let unity_goal = hyper::read_goal(cited(fact, "sum_one", at, lemmas)?, &format!("{at}: lemma sum_one"))?;
    let unity = Unity {
        members: &unity_goal.members,
        reals: &unity_goal.reals,
        for_all: &unity_goal.for_all,
    };
    if unity_goal.polygon.is_some() || unity_goal.net.is_some() {
        return Err(format!("{at}.sum_one: the lemma's goal has a polygon"));
    }
    let proof = if kind == "convex_combination" {
        let g = nonneg::read_goal(
            cited(fact, "nonnegative", at, lemmas)?,
            &format!("{at}: lemma nonnegative"),
        )?;
        check_convex_combination(lo, hi, &g, &unity).ok_or_else(|| {
            format!("{at}: the kernel refuses: the lemmas' goals are not B(i, n, t) ≥ 0 on [0, 1] and Σ B(i, n, t) = 1 for every n ≥ 0")
        })?
    } else {
        let transformed = transform_maps_points(lo, hi)?;
        check_affine_invariance(lo, hi, &unity, transformed).ok_or_else(|| {
            format!(
                "{at}: the kernel refuses: {}",
                if transformed {
                    "the lemma's goal is not Σ B(i, n, t) = 1 for every n ≥ 0"
                } else {
                    "the library's transform does not map each control point by the map"
                }
            )
        })?
    };
    let argument = if kind == "convex_combination" { CONVEX } else { AFFINE };
    Ok(Some((proof.rests_on().to_vec(), argument)))
}
