//! The library's operations on a claim's symbolic polygon or net (`elev(b, r, t)`,
//! `vfirst(b, u, v)`, …): one enum each, whose value (computed by the library) and degree
//! bound (for the prover) live in one `impl`, matched exhaustively, so the two cannot drift
//! apart: a new operation without a bound does not compile.

use super::kernel::eval::{Alg, Deg, Evaluator};
use super::kernel::expr::Expr;
use super::kernel::Trusted;
use crate::curve::BezierCurve;
use crate::error::{Error, Result};
use crate::point::Point;
use crate::scalar::{Ring, Scalar};
use crate::surface::BezierSurface;
use num_rational::BigRational;
use num_traits::Zero;

/// An operation on the symbolic polygon `b` of degree `n`, called as `name(b, …)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PolygonMethod {
    /// `bsum(b, t)`: `eval_bernstein`.
    Bsum,
    /// `elev(b, r, t)`: `elevate_by(r)`, evaluated at `t`.
    Elev,
    /// `steps(b, r, t)`: `elevate_steps(r)`, evaluated at `t`.
    Steps,
    /// `elevp(b, r, i)`: the i-th point of `elevate_by(r)`.
    Elevp,
    /// `left(b, t0, t)`: the left part of `split_at(t0)`, at `t`.
    Left,
    /// `right(b, t0, t)`: the right part of `split_at(t0)`, at `t`.
    Right,
    /// `leftp(b, t0, r)`: the r-th point of the left part.
    Leftp,
    /// `rightp(b, t0, r)`: the r-th point of the right part.
    Rightp,
    /// `deriv(b, k, t)`: `derivative(k)` at `t`.
    Deriv,
    /// `derivp(b, k, j)`: the j-th point of `derivative(k)`.
    Derivp,
}

/// An operation on the symbolic net `b` of degree `(m, n)`, called as `name(b, …)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum NetMethod {
    /// `vfirst(b, u, v)`: `eval_v_first`.
    Vfirst,
    /// `sbsum(b, u, v)`: `eval_bernstein`.
    Sbsum,
    /// `isou(b, u0, v)`: `iso_u(u0)` at `v`.
    Isou,
    /// `isov(b, v0, u)`: `iso_v(v0)` at `u`.
    Isov,
    /// `bnd(b, k, s)`: boundary curve `k = 0..3` at `s`.
    Bnd,
    /// `corner(b, k, 0)`: corner `k = 0..3`.
    Corner,
}

impl PolygonMethod {
    /// Every operation.
    pub const ALL: [PolygonMethod; 10] = [
        Self::Bsum,
        Self::Elev,
        Self::Steps,
        Self::Elevp,
        Self::Left,
        Self::Right,
        Self::Leftp,
        Self::Rightp,
        Self::Deriv,
        Self::Derivp,
    ];

    /// Its name in expressions.
    pub fn name(self) -> &'static str {
        match self {
            Self::Bsum => "bsum",
            Self::Elev => "elev",
            Self::Steps => "steps",
            Self::Elevp => "elevp",
            Self::Left => "left",
            Self::Right => "right",
            Self::Leftp => "leftp",
            Self::Rightp => "rightp",
            Self::Deriv => "deriv",
            Self::Derivp => "derivp",
        }
    }

    /// The operation called `name`.
    pub fn parse(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == name)
    }

    /// The operation of a call `name(args)` on the polygon `pname` (its first argument), with
    /// the number of arguments checked.
    pub fn of_call(name: &str, args: &[Expr], pname: &str) -> Result<Option<Self>> {
        let Some(m) = Self::parse(name) else {
            return Ok(None);
        };
        if !matches!(args.first(), Some(Expr::Var(v)) if v == pname) {
            return Ok(None);
        }
        let want = if m == Self::Bsum { 2 } else { 3 };
        if args.len() != want {
            return Err(Error::Domain(format!(
                "{name} takes {want} arguments, got {}",
                args.len()
            )));
        }
        Ok(Some(m))
    }

    /// The value, computed by the library on the polygon `coeffs` (one coordinate).
    pub fn value<T: Scalar + Alg>(self, coeffs: &[T], args: &[Expr], ev: &mut Evaluator<'_, T>) -> Result<T> {
        let pts = coeffs
            .iter()
            .map(|c| Point::new(vec![c.clone()]))
            .collect::<Result<_>>()?;
        let c = BezierCurve::new(pts)?;
        let pick = |curve: &BezierCurve<T>, i: i64| -> T {
            usize::try_from(i)
                .ok()
                .and_then(|i| curve.points().get(i))
                .map_or_else(T::zero, |p| p.coords()[0].clone())
        };
        let at = |curve: &BezierCurve<T>, ev: &mut Evaluator<'_, T>| -> Result<T> {
            Ok(curve.eval(&ev.scalar(&args[2])?).coords()[0].clone())
        };
        let order = |ev: &mut Evaluator<'_, T>| -> Result<usize> {
            let k = ev.int(&args[1])?;
            usize::try_from(k).map_err(|_| Error::Domain(format!("{}: negative order {k}", self.name())))
        };
        Ok(match self {
            Self::Bsum => c.eval_bernstein(&ev.scalar(&args[1])?).coords()[0].clone(),
            Self::Elev => at(&c.elevate_by(order(ev)?)?, ev)?,
            Self::Steps => at(&c.elevate_steps(order(ev)?)?, ev)?,
            Self::Elevp => {
                let e = c.elevate_by(order(ev)?)?;
                pick(&e, ev.int(&args[2])?)
            }
            Self::Left | Self::Right | Self::Leftp | Self::Rightp => {
                let (l, r) = c.split_at(&ev.scalar(&args[1])?);
                let part = if matches!(self, Self::Left | Self::Leftp) { l } else { r };
                if matches!(self, Self::Leftp | Self::Rightp) {
                    pick(&part, ev.int(&args[2])?)
                } else {
                    at(&part, ev)?
                }
            }
            Self::Deriv | Self::Derivp => {
                let k = order(ev)?;
                if k > c.degree() {
                    T::zero()
                } else {
                    let d = c.derivative(k)?;
                    if self == Self::Derivp {
                        pick(&d, ev.int(&args[2])?)
                    } else {
                        at(&d, ev)?
                    }
                }
            }
        })
    }

    /// The degree bound of the value for a polygon of degree `n`: the library's results are
    /// Bézier curves whose degree is read off the library itself (on the zero polygon),
    /// evaluated by de Casteljau (degree ≤ that degree in `t`); split points are de Casteljau
    /// points of `t0` (degree ≤ n in `t0`); every value is linear in the control points.
    pub fn degree(self, n: u64, args: &[Expr], ev: &mut Evaluator<'_, Deg>) -> Result<Deg> {
        let zero: BezierCurve<BigRational> = BezierCurve::new(vec![Point::origin(1); n as usize + 1])?;
        let order = |ev: &mut Evaluator<'_, Deg>| -> Result<usize> { Ok(ev.int(&args[1])?.max(0) as usize) };
        let d = match self {
            Self::Bsum => ev.scalar(&args[1])?.compose(n),
            Self::Elev => {
                let deg = zero.elevate_by(order(ev)?)?.degree() as u64;
                ev.scalar(&args[2])?.compose(deg)
            }
            Self::Steps => {
                let deg = zero.elevate_steps(order(ev)?)?.degree() as u64;
                ev.scalar(&args[2])?.compose(deg)
            }
            Self::Elevp | Self::Derivp => Deg::default(),
            Self::Left | Self::Right => {
                let t0 = ev.scalar(&args[1])?.compose(n);
                let deg = zero.split_at(&<BigRational as Zero>::zero()).0.degree() as u64;
                t0.mul_ref(&ev.scalar(&args[2])?.compose(deg))
            }
            Self::Leftp | Self::Rightp => ev.scalar(&args[1])?.compose(n),
            Self::Deriv => {
                let k = order(ev)?;
                if k as u64 > n {
                    Deg::default()
                } else {
                    let deg = zero.derivative(k)?.degree() as u64;
                    ev.scalar(&args[2])?.compose(deg)
                }
            }
        };
        Ok(d.times_control_point())
    }
}

impl NetMethod {
    /// Every operation.
    pub const ALL: [NetMethod; 6] = [
        Self::Vfirst,
        Self::Sbsum,
        Self::Isou,
        Self::Isov,
        Self::Bnd,
        Self::Corner,
    ];

    /// Its name in expressions.
    pub fn name(self) -> &'static str {
        match self {
            Self::Vfirst => "vfirst",
            Self::Sbsum => "sbsum",
            Self::Isou => "isou",
            Self::Isov => "isov",
            Self::Bnd => "bnd",
            Self::Corner => "corner",
        }
    }

    /// The operation called `name`.
    pub fn parse(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == name)
    }

    /// The operation of a call `name(args)` on the net `nname` (its first argument), with the
    /// number of arguments checked.
    pub fn of_call(name: &str, args: &[Expr], nname: &str) -> Result<Option<Self>> {
        let Some(m) = Self::parse(name) else {
            return Ok(None);
        };
        if !matches!(args.first(), Some(Expr::Var(v)) if v == nname) {
            return Ok(None);
        }
        if args.len() != 3 {
            return Err(Error::Domain(format!("{name} takes 3 arguments, got {}", args.len())));
        }
        Ok(Some(m))
    }

    fn corner_index(self, k: i64) -> Result<usize> {
        usize::try_from(k)
            .ok()
            .filter(|k| *k < 4)
            .ok_or_else(|| Error::Domain(format!("{}: k must be 0, 1, 2 or 3", self.name())))
    }

    /// The value, computed by the library on the net (one coordinate).
    pub fn value<T: Scalar + Alg>(self, net: &[Vec<T>], args: &[Expr], ev: &mut Evaluator<'_, T>) -> Result<T> {
        let pts: Vec<Vec<Point<T>>> = net
            .iter()
            .map(|r| r.iter().map(|c| Point::new(vec![c.clone()])).collect::<Result<_>>())
            .collect::<Result<_>>()?;
        let s = BezierSurface::new(pts)?;
        let p = match self {
            Self::Vfirst => s.eval_v_first(&ev.scalar(&args[1])?, &ev.scalar(&args[2])?),
            Self::Sbsum => s.eval_bernstein(&ev.scalar(&args[1])?, &ev.scalar(&args[2])?),
            Self::Isou => s.iso_u(&ev.scalar(&args[1])?).eval(&ev.scalar(&args[2])?),
            Self::Isov => s.iso_v(&ev.scalar(&args[1])?).eval(&ev.scalar(&args[2])?),
            Self::Bnd => {
                let k = self.corner_index(ev.int(&args[1])?)?;
                s.boundary()[k].eval(&ev.scalar(&args[2])?)
            }
            Self::Corner => s.corners()[self.corner_index(ev.int(&args[1])?)?].clone(),
        };
        Ok(p.coords()[0].clone())
    }

    /// The degree bound of the value for a net of degree `(m, n)` (linear in the control points).
    pub fn degree(self, m: u64, n: u64, args: &[Expr], ev: &mut Evaluator<'_, Deg>) -> Result<Deg> {
        let d = match self {
            Self::Vfirst | Self::Sbsum | Self::Isou => {
                let (u, v) = (ev.scalar(&args[1])?, ev.scalar(&args[2])?);
                u.compose(m).mul_ref(&v.compose(n))
            }
            Self::Isov => {
                let (v0, u) = (ev.scalar(&args[1])?, ev.scalar(&args[2])?);
                v0.compose(n).mul_ref(&u.compose(m))
            }
            Self::Bnd => ev.scalar(&args[2])?.compose(m.max(n)),
            Self::Corner => Deg::default(),
        };
        Ok(d.times_control_point())
    }
}

/// The library operations on a polygon or net (`bsum`, `elev`, `isou`, …) that `exprs` call:
/// a verdict over them accepts the library's values by name.
pub fn operations_called(exprs: &[Expr]) -> Vec<Trusted> {
    let mut out = Vec::new();
    for e in exprs {
        for name in e.called_names() {
            let op = PolygonMethod::parse(&name)
                .map(PolygonMethod::name)
                .or_else(|| NetMethod::parse(&name).map(NetMethod::name));
            if let Some(op) = op {
                out.push(Trusted::Operation(op));
            }
        }
    }
    out
}
