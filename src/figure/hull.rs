//! The convex hull of the control points, a point, and its certificate weights.

use super::svg::{indexed, Figure, Panel, Style, CURVE, POINT, POLYGON};
use super::{list, planar, planar_curve};
use crate::error::Result;
use crate::hull::{convex_weights, next_subset};
use crate::point::Point;
use crate::scalar::Scalar;
use crate::BezierCurve;

/// The curve, the convex hull of its control points (shaded), the point `p` and convex
/// weights `λ_i` (the certificate `p = Σ λ_i b_i`, `λ_i ≥ 0`, `Σ λ_i = 1`, found as
/// [`BezierCurve::hull_weights`] finds it but faster, by `certificate` in this file), each written
/// beside its control point; or the statement that `p` lies outside the hull.
pub fn hull<T: Scalar>(curve: &BezierCurve<T>, p: &Point<T>) -> Result<Figure> {
    super::check_figure_degree(curve.degree())?;
    let weights = certificate(curve.points(), p)?;
    let mut fig = Figure::new(match &weights {
        Some(_) => format!("The convex hull contains {p}: its certificate weights"),
        None => format!("{p} lies outside the convex hull of the control points"),
    });
    let mut panel = Panel::new("");
    let pts = curve.points();
    let drawn = pts.iter().map(planar).collect::<Result<Vec<_>>>()?;
    let hull = convex_hull(&drawn);
    panel.polyline(
        &hull,
        true,
        Style {
            fill: Some("#f4d03f"),
            ..Style::line("#b7950b", 1.2)
        },
        "hull",
        Some("the convex hull of the control points".into()),
    )?;
    panel.polyline(&drawn, false, Style::dashed(POLYGON, 1.2), "polygon", None)?;
    panel.curve(
        &planar_curve(curve)?,
        Style::line(CURVE, 2.5),
        "curve",
        Some(format!("b(t), control points {}", list(pts))),
    )?;
    let q = planar(p)?;
    for (i, (b, d)) in pts.iter().zip(&drawn).enumerate() {
        let name = indexed("b", &i.to_string(), None);
        let lambda = indexed("λ", &i.to_string(), None);
        let text = match &weights {
            Some(w) => {
                if !w[i].is_zero() {
                    panel.polyline(
                        &[q.clone(), d.clone()],
                        false,
                        Style::dashed(POINT, 1.0),
                        "weight",
                        None,
                    )?;
                }
                format!("{name}: {lambda} = {}", w[i])
            }
            None => name.clone(),
        };
        panel.dot(d, 3.5, POLYGON, format!("{name} = {b}"))?;
        panel.label(d, text, "#222222", 6.0, -7.0)?;
    }
    panel.dot(&q, 5.0, POINT, format!("p = {p}"))?;
    panel.label(&q, "p", POINT, 7.0, 15.0)?;
    fig.add_panel(panel);
    match weights {
        Some(w) => {
            let terms: Vec<String> = w
                .iter()
                .enumerate()
                .map(|(i, l)| format!("{} = {l}", indexed("λ", &i.to_string(), None)))
                .collect();
            fig.note(Some(POINT), format!("p = {p} = Σ λᵢ bᵢ with {}", terms.join(", ")));
            fig.note(
                None,
                "every λᵢ ≥ 0 and Σ λᵢ = 1, checked exactly: the certificate that p lies in the hull",
            );
        }
        None => fig.note(
            Some(POINT),
            format!("p = {p}: no convex weights exist (decided exactly)"),
        ),
    }
    Ok(fig)
}

/// Convex weights of `p` over `points`, exactly checked: the subsets of at most `dim + 1`
/// points are tried in [`crate::hull::convex_weights`]'s order, but a subset is solved
/// exactly only when its floating-point barycentric weights are not clearly negative (or
/// cannot be computed in floating point); the first exact solution is the certificate. The
/// exact solve of a subset is the library's own, over that subset alone. When no subset
/// passes, "outside the hull" is never a floating-point verdict: it is a separating plane
/// checked exactly ([`separated`]) or, failing that, the full exact search.
pub(crate) fn certificate<T: Scalar>(points: &[Point<T>], p: &Point<T>) -> Result<Option<Vec<T>>> {
    let dim = p.dim();
    if points.iter().any(|q| q.dim() != dim) {
        return convex_weights(points, p);
    }
    let mut distinct: Vec<usize> = Vec::new();
    for (i, q) in points.iter().enumerate() {
        if !distinct.iter().any(|&j| points[j] == *q) {
            distinct.push(i);
        }
    }
    let approx = |q: &Point<T>| q.coords().iter().map(|x| x.to_f64()).collect::<Vec<f64>>();
    let floats: Vec<Vec<f64>> = distinct.iter().map(|&i| approx(&points[i])).collect();
    let target = approx(p);
    let m = distinct.len();
    // beyond the library's work limit, its own search gives the refusal
    let subsets: u128 = (1..=(dim + 1).min(m))
        .map(|size| (0..size).fold(1u128, |c, i| c.saturating_mul((m - i) as u128) / (i as u128 + 1)))
        .fold(0, u128::saturating_add);
    if subsets > crate::hull::MAX_SUBSETS {
        return convex_weights(points, p);
    }
    for size in 1..=(dim + 1).min(m) {
        let mut subset: Vec<usize> = (0..size).collect();
        loop {
            if plausible(&floats, &subset, &target) {
                let chosen: Vec<Point<T>> = subset.iter().map(|&s| points[distinct[s]].clone()).collect();
                if let Some(w) = convex_weights(&chosen, p)? {
                    let mut full = vec![T::zero(); points.len()];
                    for (k, &s) in subset.iter().enumerate() {
                        full[distinct[s]] = w[k].clone();
                    }
                    return Ok(Some(full));
                }
            }
            if !next_subset(&mut subset, m) {
                break;
            }
        }
    }
    if separated(points, p, &floats, &target)? {
        return Ok(None);
    }
    convex_weights(points, p)
}

/// Whether a plane exactly separates `p` from every point: `n·b_i < n·p` checked in exact
/// arithmetic for a normal `n` found in floating point (`p` minus its nearest point of the
/// hull, by Gilbert's iteration). `false` only means that no certificate was found this way.
fn separated<T: Scalar>(points: &[Point<T>], p: &Point<T>, floats: &[Vec<f64>], target: &[f64]) -> Result<bool> {
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let Some(mut x) = floats.first().cloned() else {
        return Ok(false);
    };
    for _ in 0..1000 {
        let d: Vec<f64> = target.iter().zip(&x).map(|(t, x)| t - x).collect();
        // the hull's point furthest along d
        let Some(v) = floats.iter().max_by(|a, b| dot(a, &d).total_cmp(&dot(b, &d))) else {
            return Ok(false);
        };
        let e: Vec<f64> = v.iter().zip(&x).map(|(v, x)| v - x).collect();
        let (along, length) = (dot(&e, &d), dot(&e, &e));
        if !(along.is_finite() && length.is_finite()) || along <= 1e-12 * dot(&d, &d).sqrt() * length.sqrt() {
            break;
        }
        let s = (along / length).min(1.0);
        x = x.iter().zip(&e).map(|(x, e)| x + s * e).collect();
    }
    let normal = target
        .iter()
        .zip(&x)
        .map(|(t, x)| T::from_f64(t - x))
        .collect::<Result<Vec<T>>>();
    let Ok(normal) = normal else {
        return Ok(false);
    };
    let along = |q: &Point<T>| {
        q.coords()
            .iter()
            .zip(&normal)
            .fold(T::zero(), |s, (a, b)| s.add_ref(&a.mul_ref(b)))
    };
    let beyond = along(p);
    Ok(points.iter().all(|b| along(b) < beyond))
}

/// Whether `target` may be a convex combination of the subset's points, by a floating-point
/// solve of the barycentric system with partial pivoting: false only when the system is
/// clearly inconsistent or a weight clearly negative; anything not finite is plausible.
fn plausible(points: &[Vec<f64>], subset: &[usize], target: &[f64]) -> bool {
    let (rows, k) = (target.len() + 1, subset.len());
    // augmented matrix: each coordinate row, then Σ c = 1
    let mut a: Vec<Vec<f64>> = (0..rows)
        .map(|r| {
            let mut row: Vec<f64> = subset
                .iter()
                .map(|&s| if r < target.len() { points[s][r] } else { 1.0 })
                .collect();
            row.push(if r < target.len() { target[r] } else { 1.0 });
            row
        })
        .collect();
    let scale = a.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    if !scale.is_finite() || scale == 0.0 {
        return true;
    }
    let tol = 1e-9 * scale;
    // Gauss–Jordan: column `col` is pivoted into row `col` (or the subset is left to the
    // exact search)
    for col in 0..k {
        let best = (col..rows).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()));
        let Some(best) = best.filter(|&b| a[b][col].abs() > tol) else {
            // (nearly) dependent columns: the exact search treats a truly dependent subset as
            // covered by a smaller one; a near miss is left to it
            return true;
        };
        a.swap(col, best);
        let pivot = a[col].clone();
        for (r, row) in a.iter_mut().enumerate() {
            if r != col {
                let f = row[col] / pivot[col];
                for (x, y) in row.iter_mut().zip(&pivot).skip(col) {
                    *x -= f * y;
                }
            }
        }
    }
    // rows left over must read 0 = 0: otherwise the point is off the subset's affine hull
    if (k..rows).any(|r| a[r][k].abs() > 1e-6 * scale) {
        return false;
    }
    (0..k).all(|i| a[i][k] / a[i][i] > -1e-6)
}

/// The convex hull of planar points, counter-clockwise (Andrew's monotone chain, exact).
fn convex_hull<T: Scalar>(points: &[Point<T>]) -> Vec<Point<T>> {
    let mut pts: Vec<Point<T>> = points.to_vec();
    pts.sort_by(|a, b| {
        let (a, b) = (a.coords(), b.coords());
        a[0].partial_cmp(&b[0])
            .unwrap_or(std::cmp::Ordering::Equal)
            .then(a[1].partial_cmp(&b[1]).unwrap_or(std::cmp::Ordering::Equal))
    });
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let cross = |o: &Point<T>, a: &Point<T>, b: &Point<T>| -> T {
        let (o, a, b) = (o.coords(), a.coords(), b.coords());
        a[0].sub_ref(&o[0])
            .mul_ref(&b[1].sub_ref(&o[1]))
            .sub_ref(&a[1].sub_ref(&o[1]).mul_ref(&b[0].sub_ref(&o[0])))
    };
    let mut lower: Vec<Point<T>> = Vec::new();
    for p in &pts {
        while lower.len() >= 2 && cross(&lower[lower.len() - 2], &lower[lower.len() - 1], p) <= T::zero() {
            lower.pop();
        }
        lower.push(p.clone());
    }
    let mut upper: Vec<Point<T>> = Vec::new();
    for p in pts.iter().rev() {
        while upper.len() >= 2 && cross(&upper[upper.len() - 2], &upper[upper.len() - 1], p) <= T::zero() {
            upper.pop();
        }
        upper.push(p.clone());
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}
