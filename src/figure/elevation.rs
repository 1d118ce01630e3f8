//! Degree elevation converging to the curve (Theorem 1.2), with the exact distances.

use super::svg::{Figure, Panel, Style, CURVE, PALETTE, POLYGON};
use super::{planar, planar_curve};
use crate::curve::ElevationDistance;
use crate::error::{Error, Result};
use crate::point::Point;
use crate::scalar::Scalar;
use crate::BezierCurve;

/// The largest number of elevation steps a figure draws (each polygon is drawn and its
/// distance computed exactly; beyond this the polygons are indistinguishable from the curve).
pub const MAX_FIGURE_ELEVATION: usize = 1024;

/// The control polygons of the curve elevated `r` times for each `r` in `steps` (formula (8),
/// [`BezierCurve::elevate_by`]), over the curve, with the exact distance
/// `max_i |b_i^(r) − b(i/(n+r))|_∞` of each ([`BezierCurve::elevation_distance`]).
pub fn elevation<T: Scalar>(curve: &BezierCurve<T>, steps: &[usize]) -> Result<Figure> {
    if let Some(r) = steps.iter().find(|&&r| r > MAX_FIGURE_ELEVATION) {
        return Err(Error::TooLarge {
            what: "elevation steps in a figure",
            value: r.to_string(),
            limit: MAX_FIGURE_ELEVATION.to_string(),
        });
    }
    super::check_figure_degree(curve.degree())?;
    let n = curve.degree();
    let mut fig = Figure::new(format!(
        "Degree elevation r = {} converging to the curve (Theorem 1.2)",
        steps.iter().map(|r| r.to_string()).collect::<Vec<_>>().join(", ")
    ));
    let mut panel = Panel::new("");
    let original = curve.points().iter().map(planar).collect::<Result<Vec<_>>>()?;
    panel.polyline(&original, false, Style::line(POLYGON, 1.3), "polygon", None)?;
    for (i, p) in curve.points().iter().enumerate() {
        panel.dot(&original[i], 3.0, POLYGON, format!("b_{i} = {p}"))?;
    }
    let d0 = distance(curve, curve)?;
    fig.note(
        Some(POLYGON),
        format!("r = 0 (degree {n}): max_i |b_i − b(i/{n})|∞ = {}", d0.max_norm),
    );
    for (k, &r) in steps.iter().enumerate() {
        let color = PALETTE[k % PALETTE.len()];
        let elevated = curve.elevate_by(r)?;
        let drawn = elevated.points().iter().map(planar).collect::<Result<Vec<_>>>()?;
        let d = distance(curve, &elevated)?;
        let title = format!(
            "r = {r}: the {} Bézier points of degree {}; max_i |b_i^({r}) − b(i/{})|∞ = {}",
            elevated.points().len(),
            n + r,
            n + r,
            d.max_norm
        );
        panel.polyline(&drawn, false, Style::line(color, 1.2), "polygon", Some(title))?;
        if drawn.len() <= 40 {
            for (i, (p, q)) in elevated.points().iter().zip(&drawn).enumerate() {
                panel.dot(q, 2.0, color, format!("b_{i}^({r}) = {p}"))?;
            }
        }
        fig.note(
            Some(color),
            format!(
                "r = {r} (degree {}): max_i |b_i^({r}) − b(i/{})|∞ = {}, squared Euclidean {}",
                n + r,
                n + r,
                d.max_norm,
                d.max_squared
            ),
        );
    }
    panel.curve(
        &planar_curve(curve)?,
        Style::line(CURVE, 2.5),
        "curve",
        Some(format!("b(t), control points {}", super::list(curve.points()))),
    )?;
    fig.add_panel(panel);
    fig.note(
        Some(CURVE),
        "the curve b(t); the elevated polygons approach it as r grows",
    );
    Ok(fig)
}

/// [`BezierCurve::elevation_distance`] of `elevated` (the curve elevated `r` times), the same
/// exact numbers, with each `b(i/N)`, `N = n + r`, as one sum of integer multiples
/// `Σ_j C(n,j) i^j (N − i)^(n−j) b_j / N^n`: `n + 1` products per point instead of a whole
/// de Casteljau scheme, whose lerps at `i/N` reduce a fraction at every step.
fn distance<T: Scalar>(curve: &BezierCurve<T>, elevated: &BezierCurve<T>) -> Result<ElevationDistance<T>> {
    let (n, total) = (curve.degree(), elevated.degree());
    let binomials: Vec<T> = (0..=n)
        .scan(T::one(), |c, j| {
            let here = c.clone();
            *c = c
                .mul_ref(&T::from_usize(n - j))
                .checked_div(&T::from_usize(j + 1))
                .ok()?;
            Some(here)
        })
        .collect();
    let scale = T::one().checked_div(&integer_power(&T::from_usize(total), n))?;
    let (mut max_norm, mut max_squared) = (T::zero(), T::zero());
    for (i, p) in elevated.points().iter().enumerate() {
        let (a, b) = (T::from_usize(i), T::from_usize(total - i));
        let powers_of_a = powers(&a, n);
        let powers_of_b = powers(&b, n);
        let mut sum = vec![T::zero(); curve.dim()];
        for (j, q) in curve.points().iter().enumerate() {
            let weight = binomials[j].mul_ref(&powers_of_a[j]).mul_ref(&powers_of_b[n - j]);
            if weight.is_zero() {
                continue;
            }
            for (s, x) in sum.iter_mut().zip(q.coords()) {
                *s += &weight.mul_ref(x);
            }
        }
        let on_curve = Point::new(sum.iter().map(|s| s.mul_ref(&scale)).collect())?;
        let m = p.max_norm_distance(&on_curve);
        let sq = p.distance_squared(&on_curve);
        if m > max_norm {
            max_norm = m;
        }
        if sq > max_squared {
            max_squared = sq;
        }
    }
    Ok(ElevationDistance {
        r: total - n,
        max_norm,
        max_squared,
    })
}

/// `1, x, x², …, x^k`.
fn powers<T: Scalar>(x: &T, k: usize) -> Vec<T> {
    let mut out = vec![T::one()];
    for _ in 0..k {
        let next = (out.last().expect("starts with 1")).mul_ref(x);
        out.push(next);
    }
    out
}

fn integer_power<T: Scalar>(x: &T, k: usize) -> T {
    powers(x, k).pop().expect("starts with 1")
}
