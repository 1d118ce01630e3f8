//! A claim's concrete curves and surfaces written out with the built-in `B` (and `__dB` for
//! derivatives), so that a certificate's goal needs no claim object (`docs/certificates.md`).
//! Only the printed goal changes; proofs evaluate the objects as before.

use super::kernel::expr::{eval_int, split_partial, Expr};
use super::objects::{Exact, NumEnv};
use crate::any_curve::AnyCurve;
use crate::point::Point;
use crate::quadratic::QuadraticIrrational;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::collections::BTreeMap;
use std::str::FromStr;

mod library;
mod routines;

/// `e` with every call of a concrete curve or surface of `env`, and of the symbolic polygon
/// or net as a curve or surface, written out; `None` when a call cannot be (a rational
/// curve's derivative, a coordinate that is not rational). The library's operations whose
/// result is a curve or point with rational coefficients in the control points are written
/// as what the library computes (`library`); the others stay calls.
pub fn inline<T: Exact>(e: &Expr, env: &NumEnv<T>, ints: &BTreeMap<String, i64>) -> Option<Expr> {
    let go = |x: &Expr| inline(x, env, ints);
    let all = |xs: &[Expr]| xs.iter().map(go).collect::<Option<Vec<_>>>();
    Some(match e {
        Expr::Num(_) | Expr::Var(_) => e.clone(),
        Expr::Neg(a) => Expr::Neg(Box::new(go(a)?)),
        Expr::Fact(a) => Expr::Fact(Box::new(go(a)?)),
        Expr::Bin(op, a, b) => Expr::Bin(*op, Box::new(go(a)?), Box::new(go(b)?)),
        Expr::Index(name, args) => {
            let args = all(args)?;
            point(name, &args, env, ints).unwrap_or(Expr::Index(name.clone(), args))
        }
        Expr::Tuple(xs) => Expr::Tuple(all(xs)?),
        Expr::Matrix(rows) => Expr::Matrix(rows.iter().map(|r| all(r)).collect::<Option<_>>()?),
        Expr::Sum(v, a, b, body) => Expr::Sum(v.clone(), Box::new(go(a)?), Box::new(go(b)?), Box::new(go(body)?)),
        Expr::Call(name, args) => {
            let args = all(args)?;
            object(name, &args, env)
                .or_else(|| symbolic(name, &args, env))
                .or_else(|| library::written(name, &args, env, ints))
                .unwrap_or(Expr::Call(name.clone(), args))
        }
    })
}

/// A coordinate or weight as a constant: a rational, or `a + b·sqrt(d)` for a number of
/// `Q(√d)` (read from its exact printed form; the certificate's goal is then in `Q(√d)`).
fn rat<T: Exact>(x: &T) -> Option<Expr> {
    let text = x.to_string();
    if let Ok(r) = BigRational::from_str(&text) {
        return Some(Expr::Num(r));
    }
    let q = QuadraticIrrational::parse(&text).ok()?;
    let (a, b, d) = q.parts().ok()?;
    let root = Expr::Call("sqrt".into(), vec![Expr::int(d?)]);
    let irrational = if b.is_one() {
        root
    } else {
        Expr::mul(Expr::Num(b.clone()), root)
    };
    Some(if a.is_zero() {
        irrational
    } else {
        Expr::add(Expr::Num(a.clone()), irrational)
    })
}

fn tuple<T: Exact>(p: &Point<T>) -> Option<Expr> {
    Some(Expr::Tuple(p.coords().iter().map(rat).collect::<Option<_>>()?))
}

/// `B(i, n, x)`, or its `k`-th derivative `__dB(i, n, x, k)`.
fn basis(i: usize, n: usize, x: &Expr, k: usize) -> Expr {
    let (i, n) = (Expr::int(i as i64), Expr::int(n as i64));
    if k == 0 {
        Expr::Call("B".into(), vec![i, n, x.clone()])
    } else {
        Expr::Call("__dB".into(), vec![i, n, x.clone(), Expr::int(k as i64)])
    }
}

/// A control point `c[i]` of a concrete polynomial curve or `x[i, j]` of a concrete surface,
/// written as its coordinates (0 outside the polygon or net, as `prove` reads it); `None`:
/// not one, or an index that is not a constant integer here.
fn point<T: Exact>(name: &str, args: &[Expr], env: &NumEnv<T>, ints: &BTreeMap<String, i64>) -> Option<Expr> {
    let idx = args
        .iter()
        .map(|a| eval_int(a, ints).ok())
        .collect::<Option<Vec<i64>>>()?;
    let at = |i: i64| usize::try_from(i).ok();
    let zeros = |dim: usize| Some(Expr::Tuple(vec![Expr::int(0); dim]));
    if let (Some(AnyCurve::Polynomial(c)), [i]) = (env.curves.get(name), idx.as_slice()) {
        return match at(*i).and_then(|i| c.points().get(i)) {
            Some(p) => tuple(p),
            None => zeros(c.dim()),
        };
    }
    let net = env.surfaces.get(name)?;
    let [i, j] = idx.as_slice() else {
        return None;
    };
    match at(*i)
        .and_then(|i| net.get(i))
        .and_then(|r| at(*j).and_then(|j| r.get(j)))
    {
        Some(p) => tuple(p),
        None => zeros(net.first()?.first()?.dim()),
    }
}

fn sum(terms: impl Iterator<Item = Expr>) -> Option<Expr> {
    terms.reduce(Expr::add)
}

/// The call `name(args)` of a curve or surface of `env`, written out (`None`: not one, or
/// not written out).
fn object<T: Exact>(name: &str, args: &[Expr], env: &NumEnv<T>) -> Option<Expr> {
    let base = name.trim_end_matches('\'');
    let order = name.len() - base.len();
    if let (Some(c), [t]) = (env.curves.get(base), args) {
        return match c {
            AnyCurve::Polynomial(c) => {
                let n = c.degree();
                sum(c
                    .points()
                    .iter()
                    .enumerate()
                    .map(|(i, p)| Some(Expr::mul(tuple(p)?, basis(i, n, t, order))))
                    .collect::<Option<Vec<_>>>()?
                    .into_iter())
            }
            AnyCurve::Rational(c) if order == 0 => {
                let n = c.degree();
                let terms = |with_point: bool| -> Option<Expr> {
                    sum(c
                        .points()
                        .iter()
                        .zip(c.weights())
                        .enumerate()
                        .map(|(i, (p, w))| {
                            let wb = Expr::mul(rat(w)?, basis(i, n, t, 0));
                            Some(if with_point { Expr::mul(tuple(p)?, wb) } else { wb })
                        })
                        .collect::<Option<Vec<_>>>()?
                        .into_iter())
                };
                Some(Expr::div(terms(true)?, terms(false)?))
            }
            AnyCurve::Rational(_) => None,
        };
    }
    let (base, ku, kv) = if env.surfaces.contains_key(name) {
        (name, 0, 0)
    } else {
        split_partial(name)?
    };
    let (net, [u, v]) = (env.surfaces.get(base)?, args) else {
        return None;
    };
    let (m, n) = (net.len().checked_sub(1)?, net.first()?.len().checked_sub(1)?);
    let mut terms = Vec::new();
    for (i, row) in net.iter().enumerate() {
        for (j, p) in row.iter().enumerate() {
            terms.push(Expr::mul(Expr::mul(tuple(p)?, basis(i, m, u, ku)), basis(j, n, v, kv)));
        }
    }
    sum(terms.into_iter())
}

fn sum_over(v: &str, hi: Expr, body: Expr) -> Expr {
    Expr::Sum(v.into(), Box::new(Expr::int(0)), Box::new(hi), Box::new(body))
}

/// A call of the symbolic polygon `b` (`b(t)`, `b'(t)`, the de Casteljau point `b(i, r, t)`)
/// or net (`b(u, v)` and its partials `b_u(u, v)`, …) written with its control points:
/// `Σ_j b[j] B(j, n, t)`, `Σ_j b[i + j] B(j, r, t)`, `Σ_i Σ_j b[i, j] B(i, m, u) B(j, n, v)`.
fn symbolic<T: Exact>(name: &str, args: &[Expr], env: &NumEnv<T>) -> Option<Expr> {
    let var = |v: &str| Expr::Var(v.into());
    if let Some((pname, coeffs)) = &env.polygon {
        let base = name.trim_end_matches('\'');
        let order = name.len() - base.len();
        let n = coeffs.len() as i64 - 1;
        if base == pname {
            let at = |i: Expr| Expr::Index(pname.clone(), vec![i]);
            return match args {
                [t] => Some(sum_over(
                    "_j",
                    Expr::int(n),
                    Expr::mul(at(var("_j")), basis_at(var("_j"), Expr::int(n), t, order)),
                )),
                [i, r, t] if order == 0 => {
                    let b = basis_at(var("_j"), r.clone(), t, 0);
                    Some(sum_over(
                        "_j",
                        r.clone(),
                        Expr::mul(at(Expr::add(i.clone(), var("_j"))), b),
                    ))
                }
                _ => None,
            };
        }
    }
    let (nname, net) = env.net.as_ref()?;
    let (ku, kv) = if name == nname {
        (0, 0)
    } else {
        match split_partial(name)? {
            (b, ku, kv) if b == nname => (ku, kv),
            _ => return None,
        }
    };
    let [u, v] = args else {
        return None;
    };
    let (m, n) = (net.len() as i64 - 1, net.first()?.len() as i64 - 1);
    let at = Expr::Index(nname.clone(), vec![var("_i"), var("_j")]);
    let (m, n) = (Expr::int(m), Expr::int(n));
    let term = Expr::mul(
        Expr::mul(at, basis_at(var("_i"), m.clone(), u, ku)),
        basis_at(var("_j"), n.clone(), v, kv),
    );
    Some(sum_over("_i", m, sum_over("_j", n, term)))
}

/// `B(i, n, x)`, or its `k`-th derivative, for an index expression `i`.
fn basis_at(i: Expr, n: Expr, x: &Expr, k: usize) -> Expr {
    if k == 0 {
        Expr::Call("B".into(), vec![i, n, x.clone()])
    } else {
        Expr::Call("__dB".into(), vec![i, n, x.clone(), Expr::int(k as i64)])
    }
}
