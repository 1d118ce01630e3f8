//! The library's operations on the symbolic polygon or net written out as what the library
//! computes: each result is linear in the control points, so running the library on the zero
//! polygon and on each unit polygon gives its coefficients, and the call is written as the
//! resulting curve (`Σ_i (c_i0 + Σ_j c_ij b[j]) B(i, d, t)`) or point. Operations whose result
//! depends on a parameter other than the curve's (`left(b, t0, t)`, `isou(b, u0, v)`, the
//! evaluation routines `bsum`, `vfirst`, `sbsum`) are interpolated in it (`routines`).
//!
//! The certificate's values are the ones the proof computed with the library; re-reading the
//! written goal re-evaluates it on the same grid and basis polygons, so an expression written
//! here that differs from the library's result is not kept (`certify::certificate`).

use super::super::kernel::expr::{eval_int, Expr};
use super::super::methods::{NetMethod, PolygonMethod};
use super::super::objects::{Exact, NumEnv};
use super::routines::{tables, Key};
use crate::curve::BezierCurve;
use crate::point::Point;
use crate::surface::BezierSurface;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::collections::BTreeMap;

/// A library result on one basis polygon, as a row of [`differences`]: a curve (its control
/// points) or a point.
enum Result1<'a> {
    Curve(&'a [BigRational]),
    Point(BigRational),
}

pub(super) fn coord(p: &Point<BigRational>) -> BigRational {
    p.coords()[0].clone()
}

fn curve_points(c: &BezierCurve<BigRational>) -> Vec<BigRational> {
    c.points().iter().map(coord).collect()
}

/// `c0 + Σ_k d_k · point_k` with the zero terms left out: `d_k` is point k's coefficient, its
/// unit polygon's value less the zero polygon's (a row of [`differences`]).
pub(super) fn affine<'a>(c0: &BigRational, coeffs: impl Iterator<Item = (&'a Expr, &'a BigRational)>) -> Expr {
    let mut terms: Vec<Expr> = Vec::new();
    if !c0.is_zero() {
        terms.push(Expr::Num(c0.clone()));
    }
    for (point, d) in coeffs {
        if !d.is_zero() {
            terms.push(Expr::mul(Expr::Num(d.clone()), point.clone()));
        }
    }
    terms.into_iter().reduce(Expr::add).unwrap_or_else(|| Expr::int(0))
}

/// Values on the zero polygon and on each unit polygon (`rows[0]`, `rows[k + 1]`) as the
/// coefficients of their affine form: the zero polygon's row, then each unit polygon's less it
/// (`None` when the rows' lengths differ). Kept in the tables so that each call written from
/// them only copies.
pub(super) fn differences(rows: Vec<Vec<BigRational>>) -> Option<Vec<Vec<BigRational>>> {
    let mut rows = rows.into_iter();
    let zero = rows.next()?;
    let units = rows
        .map(|r| (r.len() == zero.len()).then(|| r.iter().zip(&zero).map(|(a, z)| a - z).collect()))
        .collect::<Option<Vec<Vec<BigRational>>>>()?;
    Some(std::iter::once(zero).chain(units).collect())
}

/// The call written from the results on the basis polygons as [`differences`] (`results[0]`
/// the zero polygon's, `results[k + 1]` the coefficients of `points[k]`); `t` the curve's
/// parameter for a curve result.
fn write(points: &[Expr], results: &[Result1], t: Option<&Expr>) -> Option<Expr> {
    let (zero, units) = results.split_first()?;
    match zero {
        Result1::Point(z) => {
            let coeffs = units
                .iter()
                .map(|r| match r {
                    Result1::Point(x) => Some(x),
                    Result1::Curve(_) => None,
                })
                .collect::<Option<Vec<_>>>()?;
            Some(affine(z, points.iter().zip(coeffs)))
        }
        Result1::Curve(z) => {
            let d = z.len().checked_sub(1)?;
            let units = units
                .iter()
                .map(|r| match r {
                    Result1::Curve(c) if c.len() == z.len() => Some(c),
                    _ => None,
                })
                .collect::<Option<Vec<_>>>()?;
            let mut terms = Vec::new();
            for (i, zi) in z.iter().enumerate() {
                let b = Expr::Call("B".into(), vec![Expr::int(i as i64), Expr::int(d as i64), t?.clone()]);
                terms.push(Expr::mul(affine(zi, points.iter().zip(units.iter().map(|c| &c[i]))), b));
            }
            terms.into_iter().reduce(Expr::add)
        }
    }
}

pub(super) fn unit(len: usize, one: Option<usize>) -> Vec<BigRational> {
    (0..len)
        .map(|j| {
            if Some(j) == one {
                BigRational::one()
            } else {
                BigRational::zero()
            }
        })
        .collect()
}

/// The `rows × cols` net of one coordinate that is 1 at control point `one` (row by row) and 0
/// elsewhere (`None`: the zero net).
pub(super) fn unit_net(rows: usize, cols: usize, one: Option<usize>) -> Option<BezierSurface<BigRational>> {
    let net = unit(rows * cols, one)
        .chunks(cols)
        .map(|row| {
            row.iter()
                .map(|x| Point::new(vec![x.clone()]).ok())
                .collect::<Option<Vec<_>>>()
        })
        .collect::<Option<Vec<_>>>()?;
    BezierSurface::new(net).ok()
}

/// A library operation on the polygon or net of `env` written out (`None`: not one, or one
/// that is not written out).
pub(super) fn written<T: Exact>(
    name: &str,
    args: &[Expr],
    env: &NumEnv<T>,
    ints: &BTreeMap<String, i64>,
) -> Option<Expr> {
    let int = |k: usize| eval_int(args.get(k)?, ints).ok();
    if let Some((pname, coeffs)) = &env.polygon {
        if let Some(m) = PolygonMethod::of_call(name, args, pname).ok().flatten() {
            let n = coeffs.len();
            let points: Vec<Expr> = (0..n)
                .map(|j| Expr::Index(pname.clone(), vec![Expr::int(j as i64)]))
                .collect();
            if let Some(e) = super::routines::polygon(m, &points, args, int(2)) {
                return Some(e);
            }
            let r = usize::try_from(int(1)?).ok()?;
            // The operation whose curves give the result (a point is one of them).
            let of = match m {
                PolygonMethod::Elev | PolygonMethod::Elevp => PolygonMethod::Elev,
                PolygonMethod::Steps => PolygonMethod::Steps,
                PolygonMethod::Deriv | PolygonMethod::Derivp => PolygonMethod::Deriv,
                _ => return None,
            };
            let on = |one: Option<usize>| -> Option<Vec<BigRational>> {
                let pts = unit(n, one)
                    .into_iter()
                    .map(|x| Point::new(vec![x]).ok())
                    .collect::<Option<Vec<_>>>()?;
                let c = BezierCurve::new(pts).ok()?;
                Some(match of {
                    PolygonMethod::Elev => curve_points(&c.elevate_by(r).ok()?),
                    PolygonMethod::Steps => curve_points(&c.elevate_steps(r).ok()?),
                    // a derivative of order ≥ the polygon's length is the zero curve
                    _ if r >= n => vec![BigRational::zero()],
                    _ => c
                        .derivative(r)
                        .ok()
                        .map_or(vec![BigRational::zero()], |d| curve_points(&d)),
                })
            };
            // The curves on each basis polygon, computed once per run: every case over polygons
            // of one length writes the same call, and a point of the result is picked from them.
            let table = tables(Key::Results(of, n, r), || {
                differences(
                    std::iter::once(None)
                        .chain((0..n).map(Some))
                        .map(on)
                        .collect::<Option<_>>()?,
                )
            })?;
            let point = match m {
                PolygonMethod::Elevp => Some(int(2)?),
                PolygonMethod::Derivp => Some(int(2).unwrap_or(-1)),
                _ => None,
            };
            let results: Vec<Result1> = table
                .iter()
                .map(|c| match point {
                    // control point i of the curve, 0 when there is none
                    Some(i) => Result1::Point(
                        usize::try_from(i)
                            .ok()
                            .and_then(|i| c.get(i))
                            .map_or_else(BigRational::zero, Clone::clone),
                    ),
                    None => Result1::Curve(c),
                })
                .collect();
            return write(&points, &results, args.get(2));
        }
    }
    let (nname, net) = env.net.as_ref()?;
    let m = NetMethod::of_call(name, args, nname).ok().flatten()?;
    let (rows, cols) = (net.len(), net.first()?.len());
    let points: Vec<Expr> = (0..rows * cols)
        .map(|k| {
            Expr::Index(
                nname.clone(),
                vec![Expr::int((k / cols) as i64), Expr::int((k % cols) as i64)],
            )
        })
        .collect();
    if let Some(e) = super::routines::net(m, &points, (rows, cols), args) {
        return Some(e);
    }
    let k = usize::try_from(int(1)?).ok().filter(|&k| k < 4)?;
    // All four boundaries (or corners) of the basis nets, one table per operation and size:
    // row `k·bases + b` is side `k` on basis net `b`; a corner is listed as a one-point curve.
    let on = |one: Option<usize>| -> Option<Vec<Vec<BigRational>>> {
        let s = unit_net(rows, cols, one)?;
        Some(match m {
            NetMethod::Bnd => s.boundary().iter().map(curve_points).collect(),
            NetMethod::Corner => s.corners().iter().map(|c| vec![coord(c)]).collect(),
            _ => return None,
        })
    };
    let bases = rows * cols + 1;
    let table = tables(Key::NetResults(m, rows, cols), || {
        let per_basis = std::iter::once(None)
            .chain((0..rows * cols).map(Some))
            .map(on)
            .collect::<Option<Vec<_>>>()?;
        let mut table = Vec::with_capacity(4 * bases);
        for side in 0..4 {
            table.extend(differences(per_basis.iter().map(|s| s[side].clone()).collect())?);
        }
        Some(table)
    })?;
    let sides = table.get(k * bases..(k + 1) * bases)?;
    let results: Vec<Result1> = match m {
        NetMethod::Corner => sides
            .iter()
            .map(|c| c.first().cloned().map(Result1::Point))
            .collect::<Option<_>>()?,
        _ => sides.iter().map(|c| Result1::Curve(c)).collect(),
    };
    write(&points, &results, args.get(2))
}
