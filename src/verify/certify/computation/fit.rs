//! The data of text 004's cubic fit (`fit_cubic`, `docs/certificates.md` "Method
//! computation"): the curve, its data `x(0), x(1), x(1/2), ẋ(0), ẋ(1)`, the normal equations
//! (11) as a matrix and a right side for the unknowns `(−k, l)`, their solution and `δ²`.
//!
//! The re-check derives the data from the curve and the equations from the data again (the
//! library's `cubic_fit_data` and `normal_equations`, on which the proof rests), then checks
//! the listed solution exactly: `M·(−k, l) = r` and `det M ≠ 0`, so `(k, l)` is the only
//! solution, the unique minimum of the convex quadratic `δ²`; and `δ²` there is the listed one.

use super::super::{array, field, rational, string};
use super::{rationals, strings, Res};
use crate::curve::BezierCurve;
use crate::fit::{delta_squared, CubicFitData, CubicFitSource};
use crate::point::Point;
use crate::rational::RationalBezierCurve;
use crate::verify::kernel::Trusted;
use crate::verify::outcome::Computed;
use crate::AnyCurve;
use num_rational::BigRational;
use num_traits::Zero;
use serde_json::{json, Value as Json};

/// The data's five vectors, by their names in the file.
const DATA: [&str; 5] = ["x0", "x1", "xh", "d0", "d1"];

fn vectors(data: &CubicFitData<BigRational>) -> [&[BigRational]; 5] {
    [
        data.x0.coords(),
        data.x1.coords(),
        data.xh.coords(),
        data.d0.coords(),
        data.d1.coords(),
    ]
}

/// The fact of a [`Computed::CubicFit`].
pub(super) fn fact(c: &Computed) -> Res<Json> {
    let Computed::CubicFit {
        points,
        weights,
        data,
        k,
        l,
        delta2,
    } = c
    else {
        return Err("not a cubic fit".into());
    };
    let (matrix, rhs) = data.normal_equations();
    let listed: serde_json::Map<String, Json> = DATA
        .iter()
        .zip(vectors(data))
        .map(|(n, v)| (n.to_string(), json!(strings(v))))
        .collect();
    let points: Vec<Vec<String>> = points.iter().map(|p| strings(p)).collect();
    let matrix: Vec<Vec<String>> = matrix.iter().map(|r| strings(r)).collect();
    Ok(json!({
        "computation": Trusted::CubicFit.name(),
        "points": points,
        "weights": weights.as_deref().map(strings),
        "data": listed,
        "normal_equations": {"matrix": matrix, "rhs": strings(&rhs)},
        "k": k.to_string(),
        "l": l.to_string(),
        "delta2": delta2.to_string(),
    }))
}

fn one(fact: &Json, key: &str, at: &str) -> Res<BigRational> {
    rational(string(fact, key, at)?).map_err(|e| format!("{at}.{key}: {e}"))
}

/// The curve of the fact: its control points, and weights unless `null` (a polynomial curve).
fn curve(fact: &Json, at: &str) -> Res<AnyCurve<BigRational>> {
    let mut points = Vec::new();
    for (i, p) in array(fact, "points", at)?.iter().enumerate() {
        let coords = rationals(p, &format!("{at}.points[{i}]"))?;
        points.push(Point::new(coords).map_err(|e| format!("{at}.points[{i}]: {e}"))?);
    }
    let w = field(fact, "weights", at)?;
    Ok(if w.is_null() {
        AnyCurve::Polynomial(BezierCurve::new(points).map_err(|e| format!("{at}: {e}"))?)
    } else {
        let weights = rationals(w, &format!("{at}.weights"))?;
        AnyCurve::Rational(RationalBezierCurve::new(points, weights).map_err(|e| format!("{at}: {e}"))?)
    })
}

fn differs(at: &str, what: &str, listed: &[BigRational], derived: &[BigRational]) -> Res<()> {
    if listed == derived {
        return Ok(());
    }
    Err(format!(
        "{at}.{what}: ({}), derived ({})",
        strings(listed).join(", "),
        strings(derived).join(", ")
    ))
}

/// Re-checks a `fit_cubic` fact (see the module's comment); an error names the first failing
/// obligation.
pub(super) fn recheck(fact: &Json, at: &str) -> Res<()> {
    let data = curve(fact, at)?.cubic_fit_data().map_err(|e| format!("{at}: {e}"))?;
    let listed = field(fact, "data", at)?;
    for (name, derived) in DATA.iter().zip(vectors(&data)) {
        let v = rationals(
            field(listed, name, &format!("{at}.data"))?,
            &format!("{at}.data.{name}"),
        )?;
        differs(at, &format!("data.{name}"), &v, derived)?;
    }
    let (matrix, rhs) = data.normal_equations();
    let eqs = field(fact, "normal_equations", at)?;
    let rows = array(eqs, "matrix", &format!("{at}.normal_equations"))?;
    if rows.len() != matrix.len() {
        return Err(format!("{at}.normal_equations.matrix: not 2 rows"));
    }
    for (i, (row, derived)) in rows.iter().zip(&matrix).enumerate() {
        let m = format!("normal_equations.matrix[{i}]");
        differs(at, &m, &rationals(row, &format!("{at}.{m}"))?, derived)?;
    }
    let r = rationals(field(eqs, "rhs", at)?, &format!("{at}.normal_equations.rhs"))?;
    differs(at, "normal_equations.rhs", &r, &rhs)?;
    let (k, l) = (one(fact, "k", at)?, one(fact, "l", at)?);
    // The unknowns of (11) are (−k, l).
    let x = [-k.clone(), l.clone()];
    for (i, (row, want)) in matrix.iter().zip(&rhs).enumerate() {
        let got: BigRational = row.iter().zip(&x).map(|(m, x)| m * x).sum();
        if &got != want {
            return Err(format!(
                "{at}: row {i} of the normal equations at k = {k}, l = {l} is {got}, not {want}"
            ));
        }
    }
    let det = &matrix[0][0] * &matrix[1][1] - &matrix[0][1] * &matrix[1][0];
    if det.is_zero() {
        return Err(format!(
            "{at}: the normal equations are singular: (k, l) is not the unique minimum"
        ));
    }
    let d2 = delta_squared(&data, &k, &l).map_err(|e| format!("{at}: {e}"))?;
    let said = one(fact, "delta2", at)?;
    if d2 != said {
        return Err(format!("{at}.delta2: {said}, δ² at (k, l) is {d2}"));
    }
    Ok(())
}
