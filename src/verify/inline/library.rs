//! The library's operations on the symbolic polygon or net written out as what the library
//! computes: each result is linear in the control points, so running the library on the zero
//! polygon and on each unit polygon gives its coefficients, and the call is written as the
//! resulting curve (`Σ_i (c_i0 + Σ_j c_ij b[j]) B(i, d, t)`) or point. The operations act on
//! each coordinate alike, so one run on the polygon whose control point `j` is the unit vector
//! `e_j` gives every unit polygon's result at once ([`Basis`]). Operations whose result
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
use crate::exact::SmallRational;
use crate::point::Point;
use crate::scalar::Ring as _;
use crate::surface::BezierSurface;
use num_rational::BigRational;
use num_traits::Zero;
use std::collections::BTreeMap;

/// The library runs on `SmallRational` here: the same exact values as on `BigRational`
/// (machine words while they fit, `BigRational` beyond), at a fraction of num-bigint's cost
/// (the basis polygons' values are small).
pub(super) type Q = SmallRational;

/// A library result on one basis polygon, as a row of [`differences`]: a curve (its control
/// points) or a point.
enum Result1<'a> {
    Curve(&'a [BigRational]),
    Point(BigRational),
}

/// The polygons the library runs on to write a call out: the zero polygon (one coordinate),
/// and all the unit polygons at once, as the polygon whose control point `j` is the unit
/// vector `e_j` (its operations act on each coordinate alike, so coordinate `k` of a result
/// there is the result on the unit polygon of point `k`).
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Basis {
    Zero,
    Units,
}

impl Basis {
    /// Control point `j` of `len` on this basis.
    fn point(self, len: usize, j: usize) -> Option<Point<Q>> {
        let coords = match self {
            Basis::Zero => vec![Q::zero()],
            Basis::Units => (0..len).map(|k| if k == j { Q::one() } else { Q::zero() }).collect(),
        };
        Point::new(coords).ok()
    }

    /// The polygon of `len` control points on this basis.
    pub(super) fn polygon(self, len: usize) -> Option<BezierCurve<Q>> {
        let points = (0..len).map(|j| self.point(len, j)).collect::<Option<Vec<_>>>()?;
        BezierCurve::new(points).ok()
    }

    /// The `rows × cols` net on this basis (its points numbered row by row).
    pub(super) fn net(self, rows: usize, cols: usize) -> Option<BezierSurface<Q>> {
        let net = (0..rows)
            .map(|i| (0..cols).map(|j| self.point(rows * cols, i * cols + j)).collect())
            .collect::<Option<Vec<Vec<_>>>>()?;
        BezierSurface::new(net).ok()
    }
}

/// The values of one result on every basis polygon, from its runs on the zero polygon and on
/// the unit vectors (`len` of them): the zero polygon's row, then unit polygon `k`'s, each a
/// list of one value per point of the result.
pub(super) fn by_basis(zero: &[Point<Q>], units: &[Point<Q>], len: usize) -> Option<Vec<Vec<Q>>> {
    if zero.len() != units.len() || units.iter().any(|p| p.coords().len() != len) {
        return None;
    }
    let zero_row = zero.iter().map(|p| p.coords()[0].clone()).collect();
    let unit_rows = (0..len).map(|k| units.iter().map(|p| p.coords()[k].clone()).collect());
    Some(std::iter::once(zero_row).chain(unit_rows).collect())
}

/// [`by_basis`] as exact rationals.
fn big(rows: Vec<Vec<Q>>) -> Vec<Vec<BigRational>> {
    rows.iter().map(|r| r.iter().map(Q::to_big).collect()).collect()
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
            let on = |b: Basis| -> Option<Vec<Point<Q>>> {
                let c = b.polygon(n)?;
                let zero = || Some(vec![Point::new(vec![Q::zero(); c.dim()]).ok()?]);
                Some(match of {
                    PolygonMethod::Elev => c.elevate_by(r).ok()?.points().to_vec(),
                    PolygonMethod::Steps => c.elevate_steps(r).ok()?.points().to_vec(),
                    // a derivative of order ≥ the polygon's length is the zero curve
                    _ if r >= n => zero()?,
                    _ => match c.derivative(r) {
                        Ok(d) => d.points().to_vec(),
                        Err(_) => zero()?,
                    },
                })
            };
            // The curves on each basis polygon, computed once per run: every case over polygons
            // of one length writes the same call, and a point of the result is picked from them.
            let table = tables(Key::Results(of, n, r), || {
                differences(big(by_basis(&on(Basis::Zero)?, &on(Basis::Units)?, n)?))
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
                            .map_or_else(<BigRational as Zero>::zero, Clone::clone),
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
    let on = |b: Basis| -> Option<Vec<Vec<Point<Q>>>> {
        let s = b.net(rows, cols)?;
        Some(match m {
            NetMethod::Bnd => s.boundary().iter().map(|c| c.points().to_vec()).collect(),
            NetMethod::Corner => s.corners().iter().map(|c| vec![c.clone()]).collect(),
            _ => return None,
        })
    };
    let bases = rows * cols + 1;
    let table = tables(Key::NetResults(m, rows, cols), || {
        let (zero, units) = (on(Basis::Zero)?, on(Basis::Units)?);
        let mut table = Vec::with_capacity(4 * bases);
        for (z, u) in zero.iter().zip(&units) {
            table.extend(differences(big(by_basis(z, u, rows * cols)?))?);
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
