//! The library's operations at a symbolic parameter (the evaluation routines `bsum`,
//! `vfirst`, `sbsum`; the split `left`, `right`, `leftp`, `rightp` at `t0`; the iso-curves
//! `isou`, `isov` at `u0`, `v0`) written out as what the library computes.
//!
//! Each value is affine in the control points and, by the degree bound `prove` uses for the
//! operation (`methods::PolygonMethod::degree`, `NetMethod::degree`), a polynomial of degree
//! ≤ d in each of its parameters. So the library's values on the zero polygon and on each unit
//! polygon, at d + 1 points per parameter, determine it: they are interpolated into
//! coefficients in the tensor Bernstein basis, and the call is written as
//! `Σ (c_0 + Σ_k c_k·point_k)·B(i, d1, x1)·B(j, d2, x2)` of its argument expressions. This
//! trusts the library's degree bound exactly as the sampling proof does (it evaluates the call
//! at d + 1 points); the certificate then states the identity about that polynomial.

use super::super::methods::{NetMethod, PolygonMethod};
use super::library::{affine, by_basis, differences, Basis, Q};
use crate::curve::BezierCurve;
use crate::point::Point;
use crate::surface::BezierSurface;
use num_rational::BigRational;
use num_traits::Zero;
use std::cell::RefCell;
use std::collections::HashMap;
use std::hash::Hash;
use std::sync::{Arc, Mutex, OnceLock};

use super::super::kernel::expr::Expr;

/// The points `i/d`, `i = 0..=d` (just 0 for d = 0).
fn nodes(d: usize) -> Vec<BigRational> {
    if d == 0 {
        return vec![BigRational::zero()];
    }
    (0..=d)
        .map(|i| BigRational::new((i as i64).into(), (d as i64).into()))
        .collect()
}

/// The inverse of the matrix `B_j^d(i/d)` (rows i, columns j): values at the nodes to
/// Bernstein coefficients. The matrix is invertible (distinct nodes, a basis of degree ≤ d).
/// Eliminated on `SmallRational` (the same exact values, machine words while they fit).
fn to_bernstein(d: usize) -> Option<Vec<Vec<BigRational>>> {
    use crate::scalar::{Ring as _, Scalar as _};
    let size = d + 1;
    let powers = |x: &Q| -> Vec<Q> {
        std::iter::successors(Some(Q::from(1)), |p| Some(p.mul_ref(x)))
            .take(size)
            .collect()
    };
    let mut m: Vec<Vec<Q>> = nodes(d)
        .iter()
        .map(|x| {
            let x = Q::from(x);
            let (xs, ys) = (powers(&x), powers(&Q::from(1).sub_ref(&x)));
            (0..size)
                .map(|j| {
                    let c = Q::from_bigint(&crate::bernstein::binomial_signed(d as i64, j as i64)).ok()?;
                    Some(c.mul_ref(&xs[j]).mul_ref(&ys[d - j]))
                })
                .collect::<Option<Vec<Q>>>()
        })
        .collect::<Option<_>>()?;
    let mut inv: Vec<Vec<Q>> = (0..size)
        .map(|i| (0..size).map(|j| Q::from(i64::from(i == j))).collect())
        .collect();
    // Gauss–Jordan elimination, exact.
    for col in 0..size {
        let pivot = (col..size).find(|&r| !m[r][col].is_zero())?;
        m.swap(col, pivot);
        inv.swap(col, pivot);
        let p = m[col][col].clone();
        for x in m[col].iter_mut().chain(inv[col].iter_mut()) {
            *x = x.checked_div(&p).ok()?;
        }
        let (prow, pinv) = (m[col].clone(), inv[col].clone());
        for (r, (row, irow)) in m.iter_mut().zip(inv.iter_mut()).enumerate() {
            let f = row[col].clone();
            if r == col || f.is_zero() {
                continue;
            }
            row.iter_mut()
                .zip(&prow)
                .for_each(|(x, a)| *x = x.sub_ref(&a.mul_ref(&f)));
            irow.iter_mut()
                .zip(&pinv)
                .for_each(|(x, a)| *x = x.sub_ref(&a.mul_ref(&f)));
        }
    }
    Some(inv.iter().map(|row| row.iter().map(Q::to_big).collect()).collect())
}

/// [`to_bernstein`] of `d`, computed once per run (every table of degree `d` uses it).
fn inverse(d: usize) -> Option<Arc<Matrix>> {
    static INVERSES: Memo<usize> = OnceLock::new();
    memo(&INVERSES, d, || to_bernstein(d))
}

/// A square or rectangular table of exact numbers, shared once computed.
type Matrix = Vec<Vec<BigRational>>;
type Memo<K> = OnceLock<Mutex<HashMap<K, Arc<Matrix>>>>;

/// `make()`, or what it gave for `key` before in this run (at most `MAX_TABLES` kept).
fn memo<K: Hash + Eq>(cache: &'static Memo<K>, key: K, make: impl FnOnce() -> Option<Matrix>) -> Option<Arc<Matrix>> {
    let cache = cache.get_or_init(Default::default);
    if let Some(t) = cache.lock().ok()?.get(&key) {
        return Some(Arc::clone(t));
    }
    let table = Arc::new(make()?);
    let mut map = cache.lock().ok()?;
    if map.len() < MAX_TABLES {
        map.insert(key, Arc::clone(&table));
    }
    Some(table)
}

/// The tensor Bernstein coefficients of the values on a grid (the last axis fastest), by each
/// axis' inverse matrix ([`to_bernstein`] on `SmallRational`: the same exact values, most
/// entries machine words).
fn coefficients(values: &[Q], degrees: &[usize], inverses: &[Vec<Vec<Q>>]) -> Vec<BigRational> {
    use crate::scalar::Ring as _;
    let mut c: Vec<Q> = values.to_vec();
    let sizes: Vec<usize> = degrees.iter().map(|d| d + 1).collect();
    for (axis, inv) in inverses.iter().enumerate() {
        let stride: usize = sizes[axis + 1..].iter().product();
        let len = sizes[axis];
        let mut next = c.clone();
        for (start, _) in c.iter().enumerate().filter(|(k, _)| (k / stride) % len == 0) {
            for (i, row) in inv.iter().enumerate() {
                next[start + i * stride] = row
                    .iter()
                    .enumerate()
                    .map(|(j, m)| m.mul_ref(&c[start + j * stride]))
                    .fold(Q::from(0), |a, b| a.add_ref(&b));
            }
        }
        c = next;
    }
    c.iter().map(Q::to_big).collect()
}

/// An inverse matrix on `SmallRational`, for [`coefficients`].
fn small(m: &Matrix) -> Vec<Vec<Q>> {
    m.iter().map(|row| row.iter().map(Q::from).collect()).collect()
}

/// Which library operation a table of coefficients is of: everything `value` depends on in
/// [`polygon`] and [`net`] (the control points enter only as unit polygons).
#[derive(Clone, PartialEq, Eq, Hash)]
pub(super) enum Key {
    Polygon(PolygonMethod, usize, Option<i64>),
    Net(NetMethod, usize, usize),
    /// The library's curves on each basis polygon (`library::written`): the operation, the
    /// polygon's length, its order (of elevation or derivative).
    Results(PolygonMethod, usize, usize),
    /// The same on each basis net, all four boundaries or corners: the operation, its rows
    /// and columns.
    NetResults(NetMethod, usize, usize),
}

/// Most tables kept: a claim's cases use a few degrees, so the texts need a few dozen.
const MAX_TABLES: usize = 512;

/// The coefficients of `key`'s operation, computed once per run: `prove` writes the same
/// call at the same degree in every equality of a case, and in every claim over that polygon.
pub(super) fn tables(key: Key, make: impl FnOnce() -> Option<Matrix>) -> Option<Arc<Matrix>> {
    static TABLES: Memo<Key> = OnceLock::new();
    memo(&TABLES, key, make)
}

/// The tensor Bernstein coefficients of `value` on the zero polygon and on each of the
/// `points` unit polygons, from its values at `d + 1` nodes of each axis, as [`differences`]:
/// `value(basis, at)` is the library's point there (one coordinate on [`Basis::Zero`], one per
/// unit polygon on [`Basis::Units`]).
fn per_basis(
    points: usize,
    degrees: &[usize],
    value: impl Fn(Basis, &[BigRational]) -> Option<Point<Q>>,
) -> Option<Vec<Vec<BigRational>>> {
    let inverses = degrees
        .iter()
        .map(|&d| Some(small(&*inverse(d)?)))
        .collect::<Option<Vec<_>>>()?;
    let grid: Vec<Vec<BigRational>> = degrees.iter().fold(vec![Vec::new()], |acc, &d| {
        acc.iter()
            .flat_map(|p| {
                nodes(d).into_iter().map(move |x| {
                    let mut q = p.clone();
                    q.push(x);
                    q
                })
            })
            .collect()
    });
    let on = |b: Basis| grid.iter().map(|at| value(b, at)).collect::<Option<Vec<_>>>();
    let values = by_basis(&on(Basis::Zero)?, &on(Basis::Units)?, points)?;
    differences(values.iter().map(|v| coefficients(v, degrees, &inverses)).collect())
}

/// The call written from `value(basis polygon, parameter values)`: `points` the control
/// points (basis polygon `Some(k)` sets the k-th to 1), `axes` each parameter's degree bound
/// and argument expression.
fn interpolated(
    key: Key,
    points: &[Expr],
    axes: &[(usize, Expr)],
    value: impl Fn(Basis, &[BigRational]) -> Option<Point<Q>>,
) -> Option<Expr> {
    let degrees: Vec<usize> = axes.iter().map(|a| a.0).collect();
    let per_basis = tables(key, || per_basis(points.len(), &degrees, value))?;
    let (zero, units) = per_basis.split_first()?;
    let sizes: Vec<usize> = degrees.iter().map(|d| d + 1).collect();
    let mut terms = Vec::new();
    for (k, z) in zero.iter().enumerate() {
        let a = affine(z, points.iter().zip(units.iter().map(|u| &u[k])));
        if matches!(&a, Expr::Num(x) if x.is_zero()) {
            continue;
        }
        // The multi-index of coefficient k, the last axis fastest.
        let mut rest = k;
        let mut index = vec![0; sizes.len()];
        for axis in (0..sizes.len()).rev() {
            index[axis] = rest % sizes[axis];
            rest /= sizes[axis];
        }
        let term = axes.iter().zip(&index).fold(a, |acc, ((d, x), &i)| {
            Expr::mul(
                acc,
                Expr::Call("B".into(), vec![Expr::int(i as i64), Expr::int(*d as i64), x.clone()]),
            )
        });
        terms.push(term);
    }
    Some(terms.into_iter().reduce(Expr::add).unwrap_or_else(|| Expr::int(0)))
}

/// Control point `i` of a curve (the origin when there is none, as `prove` reads it).
fn pick(c: &BezierCurve<Q>, i: i64) -> Option<Point<Q>> {
    match usize::try_from(i).ok().and_then(|i| c.points().get(i)) {
        Some(p) => Some(p.clone()),
        None => Point::new(vec![Q::from(0); c.dim()]).ok(),
    }
}

/// A polygon operation at a symbolic parameter, written out (`None`: another operation).
/// `points` the polygon's control points `b[0..=n]`, `args` the call's (inlined) arguments,
/// `r` the index argument of `leftp`/`rightp`.
pub(super) fn polygon(m: PolygonMethod, points: &[Expr], args: &[Expr], r: Option<i64>) -> Option<Expr> {
    let len = points.len();
    let n = len.checked_sub(1)?;
    let on = |b: Basis| b.polygon(len);
    match m {
        PolygonMethod::Bsum => interpolated(
            Key::Polygon(m, len, None),
            points,
            &[(n, args.get(1)?.clone())],
            |b, at| Some(on(b)?.eval_bernstein(&Q::from(&at[0]))),
        ),
        PolygonMethod::Left | PolygonMethod::Right => {
            let left = m == PolygonMethod::Left;
            // The parts' degree, read off the library on the zero polygon, as `prove` does.
            let deg = on(Basis::Zero)?.split_at(&Q::from(0)).0.degree();
            let axes = [(n, args.get(1)?.clone()), (deg, args.get(2)?.clone())];
            // The grid's last axis runs fastest: one split serves a whole row of `t` values.
            let last = RefCell::new(None);
            interpolated(Key::Polygon(m, len, None), points, &axes, |b, at| {
                let mut last = last.borrow_mut();
                let fresh = !matches!(&*last, Some((lb, lt, _)) if *lb == b && *lt == at[0]);
                if fresh {
                    let (l, r) = on(b)?.split_at(&Q::from(&at[0]));
                    *last = Some((b, at[0].clone(), if left { l } else { r }));
                }
                let (_, _, part) = last.as_ref()?;
                Some(part.eval(&Q::from(&at[1])))
            })
        }
        PolygonMethod::Leftp | PolygonMethod::Rightp => {
            let (left, r) = (m == PolygonMethod::Leftp, r?);
            interpolated(
                Key::Polygon(m, len, Some(r)),
                points,
                &[(n, args.get(1)?.clone())],
                |b, at| {
                    let (lc, rc) = on(b)?.split_at(&Q::from(&at[0]));
                    pick(if left { &lc } else { &rc }, r)
                },
            )
        }
        _ => None,
    }
}

/// The basis net, the parameter and the iso-curve a row of the grid shares.
type IsoRow = (Basis, BigRational, BezierSurface<Q>, Option<BezierCurve<Q>>);

/// A net operation at symbolic parameters, written out (`None`: another operation).
/// `points` the net's control points row by row (`rows × cols`).
pub(super) fn net(m: NetMethod, points: &[Expr], (rows, cols): (usize, usize), args: &[Expr]) -> Option<Expr> {
    let (dm, dn) = (rows.checked_sub(1)?, cols.checked_sub(1)?);
    let on = |b: Basis| b.net(rows, cols);
    let (x1, x2) = (args.get(1)?.clone(), args.get(2)?.clone());
    let axes = match m {
        NetMethod::Vfirst | NetMethod::Sbsum | NetMethod::Isou => [(dm, x1), (dn, x2)],
        NetMethod::Isov => [(dn, x1), (dm, x2)],
        _ => return None,
    };
    // The grid's last axis runs fastest: one net and one iso-curve serve a whole row.
    let last: RefCell<Option<IsoRow>> = RefCell::new(None);
    interpolated(Key::Net(m, rows, cols), points, &axes, |b, at| {
        let mut last = last.borrow_mut();
        let fresh = !matches!(&*last, Some((lb, lx, ..)) if *lb == b && *lx == at[0]);
        if fresh {
            let s = on(b)?;
            let x = Q::from(&at[0]);
            let iso = match m {
                NetMethod::Isou => Some(s.iso_u(&x)),
                NetMethod::Isov => Some(s.iso_v(&x)),
                _ => None,
            };
            *last = Some((b, at[0].clone(), s, iso));
        }
        let (_, _, s, iso) = last.as_ref()?;
        let (x, y) = (Q::from(&at[0]), Q::from(&at[1]));
        Some(match (m, iso) {
            (NetMethod::Vfirst, _) => s.eval_v_first(&x, &y),
            (NetMethod::Sbsum, _) => s.eval_bernstein(&x, &y),
            (_, Some(c)) => c.eval(&y),
            _ => return None,
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::One;

    fn pow(x: &BigRational, k: usize) -> BigRational {
        (0..k).fold(BigRational::one(), |acc, _| acc * x)
    }

    fn points(n: usize) -> Vec<Expr> {
        (0..=n)
            .map(|j| Expr::Index("b".into(), vec![Expr::int(j as i64)]))
            .collect()
    }

    fn var(v: &str) -> Expr {
        Expr::Var(v.into())
    }

    #[test]
    fn the_interpolation_inverts_the_bernstein_matrix() {
        for d in 0..6 {
            let inv = to_bernstein(d).unwrap();
            // The values of B_j^d at the nodes, mapped back, are the unit coefficients.
            for j in 0..=d {
                let values: Vec<Q> = nodes(d)
                    .iter()
                    .map(|x| {
                        BigRational::from_integer(crate::bernstein::binomial_signed(d as i64, j as i64))
                            * pow(x, j)
                            * pow(&(BigRational::one() - x), d - j)
                    })
                    .map(Q::from)
                    .collect();
                let c = coefficients(&values, &[d], &[small(&inv)]);
                let unit: Vec<BigRational> = (0..=d)
                    .map(|k| BigRational::from_integer(i64::from(k == j).into()))
                    .collect();
                assert_eq!(c, unit, "d = {d}, j = {j}");
            }
        }
    }

    #[test]
    fn bsum_is_written_as_the_bernstein_sum_of_its_points() {
        let e = polygon(PolygonMethod::Bsum, &points(2), &[var("b"), var("t")], None).unwrap();
        assert_eq!(
            e.to_string(),
            "1*b[0]*B(0, 2, t) + 1*b[1]*B(1, 2, t) + 1*b[2]*B(2, 2, t)"
        );
    }

    #[test]
    fn the_split_points_are_de_casteljau_points_of_t0() {
        // leftp(b, t0, 1) = b_0^1(t0) = (1 - t0) b[0] + t0 b[1], of degree n = 2 in t0.
        let e = polygon(
            PolygonMethod::Leftp,
            &points(2),
            &[var("b"), var("t0"), Expr::int(1)],
            Some(1),
        )
        .unwrap();
        assert_eq!(
            e.to_string(),
            "1*b[0]*B(0, 2, t0) + (1/2*b[0] + 1/2*b[1])*B(1, 2, t0) + 1*b[1]*B(2, 2, t0)"
        );
        // A point index outside the part is 0, as the library's `pick` reads it.
        let z = polygon(
            PolygonMethod::Rightp,
            &points(1),
            &[var("b"), var("t0"), Expr::int(5)],
            Some(5),
        )
        .unwrap();
        assert_eq!(z.to_string(), "0");
    }

    #[test]
    fn an_iso_curve_has_the_degrees_of_its_parameters() {
        // A 1×3 net (m = 0, n = 2): isov(b, v0, u) has degree n = 2 in v0 and m = 0 in u.
        let pts: Vec<Expr> = (0..3)
            .map(|j| Expr::Index("b".into(), vec![Expr::int(0), Expr::int(j)]))
            .collect();
        let e = net(NetMethod::Isov, &pts, (1, 3), &[var("b"), var("v0"), var("u")]).unwrap();
        assert_eq!(
            e.to_string(),
            "1*b[0, 0]*B(0, 2, v0)*B(0, 0, u) + 1*b[0, 1]*B(1, 2, v0)*B(0, 0, u) + 1*b[0, 2]*B(2, 2, v0)*B(0, 0, u)"
        );
    }
}
