//! Proof by exact evaluation at enough points: the degree bounds of both sides derived in the
//! algebra of degree bounds, the proposed points checked distinct and numerous enough, and both
//! sides evaluated exactly at every point of the grid on every basis polygon.
//!
//! The planner (`verify::sampling`) proposes the points and the environment; the environment
//! (the claim's objects shaped for one case, set to one basis polygon) is trusted elaboration.

use super::alg::Alg;
use super::certificate::{self, Refutation, Row};
use super::eval::{Deg, Env, Evaluator, Value};
use super::expr::Expr;
use crate::error::{Error, Result};
use num_rational::BigRational;
use std::collections::{BTreeMap, BTreeSet};

/// The claim's objects at one basis polygon and one parameter point (trusted elaboration).
pub trait Points<A: Alg> {
    /// How many basis polygons the sides are evaluated on: the zero polygon and each unit
    /// control point (1: the sides use no symbolic control points).
    fn polygons(&self) -> usize;
    /// The environment with basis polygon `basis` and the parameters `params` set to `values`.
    fn at(&mut self, basis: usize, params: &[String], values: &[BigRational]) -> Result<&dyn Env<A>>;
    /// The symbolic control points, by name and index (`b[j]`, `p[i, j]`), in the order of
    /// the unit polygons: basis polygon `k + 1` sets the `k`-th to 1.
    fn control_points(&self) -> Vec<(String, Vec<i64>)>;
    /// A side written without the claim's objects, for a certificate (`None`: it cannot be).
    fn written_out(&self, _side: &Expr, _ints: &BTreeMap<String, i64>) -> Option<Expr> {
        None
    }
}

/// Checks that `env`'s basis is complete for sides affine in its control points: basis
/// polygon 0 is the zero polygon and polygon `k + 1` the unit polygon of the `k`-th control
/// point (1 there, 0 at every other), one for each control point. An affine function that
/// vanishes on all of them is zero.
fn check_basis<A: Alg>(
    env: &mut dyn Points<A>,
    params: &[String],
    values: &[BigRational],
) -> std::result::Result<(), String> {
    let points = env.control_points();
    let polygons = env.polygons();
    if points.is_empty() || polygons != points.len() + 1 {
        return Err(format!(
            "{polygons} basis polygons for {} control points (the zero polygon and one unit polygon each)",
            points.len()
        ));
    }
    let (zero, one) = (A::from_int(0), A::from_int(1));
    for b in 0..polygons {
        let e = env.at(b, params, values).map_err(|e| e.to_string())?;
        for (k, (name, idx)) in points.iter().enumerate() {
            let want = if b == k + 1 { &one } else { &zero };
            let holds = match e.index(name, idx) {
                Ok(Some(Value::S(x))) => x.equals(want) == Some(true),
                _ => false,
            };
            if !holds {
                return Err(format!(
                    "basis polygon {b} is not the {} polygon at {name}{idx:?}",
                    if b == 0 { "zero" } else { "unit" }
                ));
            }
        }
    }
    Ok(())
}

/// The degree bounds of an equality `lhs = rhs` at one integer case, derived by the kernel.
pub struct Bounds<'a> {
    lhs: &'a Expr,
    rhs: &'a Expr,
    ints: BTreeMap<String, i64>,
    params: Vec<String>,
    dl: Value<Deg>,
    dr: Value<Deg>,
    needs: Vec<u64>,
}

/// The degree bounds of `lhs` and `rhs` in each of `params`, evaluated over `degrees` (the
/// claim's objects in the algebra of degree bounds); an error if a side is not affine in the
/// symbolic control points.
pub fn bounds<'a>(
    lhs: &'a Expr,
    rhs: &'a Expr,
    ints: &BTreeMap<String, i64>,
    params: Vec<String>,
    degrees: &dyn Env<Deg>,
) -> Result<Bounds<'a>> {
    let dl = Evaluator::new(degrees, ints.clone()).eval(lhs)?;
    let dr = Evaluator::new(degrees, ints.clone()).eval(rhs)?;
    for (side, d) in [("left", &dl), ("right", &dr)] {
        if d.entries().iter().any(|x| x.poly > 1) {
            return Err(Error::Domain(format!(
                "the {side} side is not affine in the symbolic control points (it multiplies two of them)"
            )));
        }
    }
    let needs = params
        .iter()
        .map(|v| needed_degree(&dl, &dr, v))
        .collect::<Result<_>>()?;
    Ok(Bounds {
        lhs,
        rhs,
        ints: ints.clone(),
        params,
        dl,
        dr,
        needs,
    })
}

impl Bounds<'_> {
    /// The parameters, in the order of [`Bounds::needs`].
    pub fn params(&self) -> &[String] {
        &self.params
    }
    /// The degree bound of the cleared difference in each parameter.
    pub fn needs(&self) -> &[u64] {
        &self.needs
    }
    /// The integer values of the case.
    pub fn ints(&self) -> &BTreeMap<String, i64> {
        &self.ints
    }
    /// The left side.
    pub fn lhs(&self) -> &Expr {
        self.lhs
    }
    /// The right side.
    pub fn rhs(&self) -> &Expr {
        self.rhs
    }
    /// Whether a side uses the symbolic control points.
    pub fn uses_polygon(&self) -> bool {
        self.dl
            .entries()
            .iter()
            .chain(self.dr.entries().iter())
            .any(|x| x.poly > 0)
    }
    /// The first entry's bound of each side.
    pub fn first(&self) -> (Deg, Deg) {
        let f = |d: &Value<Deg>| d.entries().first().map(|x| (*x).clone()).unwrap_or_default();
        (f(&self.dl), f(&self.dr))
    }
    /// Both sides' bounds in `v`, as `num` or `num/den`.
    pub fn describe(&self, v: &str) -> (String, String) {
        (describe_deg(&self.dl, v), describe_deg(&self.dr, v))
    }
}

fn describe_deg(d: &Value<Deg>, v: &str) -> String {
    let ds: Vec<(u64, u64)> = d.entries().iter().map(|x| x.get(v)).collect();
    let n = ds.iter().map(|x| x.0).max().unwrap_or(0);
    let m = ds.iter().map(|x| x.1).max().unwrap_or(0);
    if m == 0 {
        format!("{n}")
    } else {
        format!("{n}/{m}")
    }
}

/// The degree in `v` of the cleared difference `P1·Q2 − P2·Q1` of two sides.
fn needed_degree(l: &Value<Deg>, r: &Value<Deg>, v: &str) -> Result<u64> {
    let mut need = 0;
    for (a, b) in l.paired_entries(r)? {
        let (na, da) = a.get(v);
        let (nb, db) = b.get(v);
        let d = if da == 0 && db == 0 {
            na.max(nb)
        } else {
            (na + db).max(nb + da)
        };
        need = need.max(d);
    }
    Ok(need)
}

/// One equality at one case checked on its whole grid: the evidence [`super::check_sampled`]
/// assembles a proof from (made only here).
#[derive(Clone, Debug)]
pub struct Case {
    pub(super) degrees: Vec<u64>,
    pub(super) polygons: usize,
    pub(super) data: Box<certificate::Equality>,
}

/// What sees each point where both sides agree: its grid values, basis polygon, the value.
pub type Observe<'o, A> = dyn FnMut(&[BigRational], usize, &Value<A>) + 'o;

/// The outcome of checking one equality at the proposed points.
pub enum Pair<A> {
    /// Equal at every point of the grid on every basis polygon.
    Equal(Case),
    /// The sides differ (or cannot be compared: `equal` is `None`) at the grid point `at` on
    /// basis polygon `basis`.
    Differs {
        at: Vec<BigRational>,
        basis: usize,
        lhs: Value<A>,
        rhs: Value<A>,
        equal: Option<bool>,
        /// The counterexample as data, when the sides are unequal.
        refutation: Option<Box<Refutation>>,
    },
    /// A denominator vanishes at the grid point with these indices into the proposed points.
    Vanishes { index: Vec<usize>, error: Error },
}

fn written<A: Alg>(env: &dyn Points<A>, bounds: &Bounds<'_>) -> Option<(Expr, Expr)> {
    Some((
        env.written_out(bounds.lhs, &bounds.ints)?,
        env.written_out(bounds.rhs, &bounds.ints)?,
    ))
}

/// Checks that each parameter, of degree bound `needs`, has more distinct `points` than its bound.
fn enough_points(needs: &[u64], points: &[Vec<BigRational>]) -> std::result::Result<(), String> {
    if points.len() != needs.len() {
        return Err(format!("{} point sets for {} parameters", points.len(), needs.len()));
    }
    for (d, values) in needs.iter().zip(points) {
        let distinct: BTreeSet<&BigRational> = values.iter().collect();
        if distinct.len() != values.len() || (distinct.len() as u64) <= *d {
            return Err(format!(
                "a parameter of degree ≤ {d} proposed at {} values, {} distinct",
                values.len(),
                distinct.len()
            ));
        }
    }
    Ok(())
}

/// Checks `bounds`' equality at the grid `points` (the proposed values of each parameter):
/// each parameter needs more distinct values than its degree bound; both sides are evaluated
/// exactly at every grid point on every basis polygon of `env`. `observe` sees each point
/// where they agree (grid values, basis polygon, the common value).
pub fn check_pair<A: Alg>(
    bounds: &Bounds<'_>,
    env: &mut dyn Points<A>,
    points: &[Vec<BigRational>],
    observe: &mut Observe<'_, A>,
) -> Result<Pair<A>> {
    let refuse = |m: String| Err(Error::Domain(format!("the kernel refuses the evaluations: {m}")));
    if let Err(m) = enough_points(&bounds.needs, points) {
        return refuse(m);
    }
    let polygons = env.polygons();
    if polygons == 0 {
        return refuse("no basis polygon".into());
    }
    if bounds.uses_polygon() {
        let first: Vec<BigRational> = points.iter().filter_map(|s| s.first().cloned()).collect();
        if first.len() != points.len() {
            return refuse("a parameter without values".into());
        }
        if let Err(m) = check_basis(env, &bounds.params, &first) {
            return refuse(m);
        }
    }
    let mut idx = vec![0usize; points.len()];
    // The certificate's rows: every grid point on every basis polygon.
    let mut rows = Vec::new();
    loop {
        let values: Vec<BigRational> = idx.iter().zip(points).map(|(&i, s)| s[i].clone()).collect();
        for b in 0..polygons {
            let e = env.at(b, &bounds.params, &values)?;
            let l = Evaluator::new(e, bounds.ints.clone()).eval(bounds.lhs);
            let r = Evaluator::new(e, bounds.ints.clone()).eval(bounds.rhs);
            let (l, r) = match (l, r) {
                (Ok(l), Ok(r)) => (l, r),
                (Err(error @ (Error::DivisionByZero(_) | Error::Singular(_))), _)
                | (_, Err(error @ (Error::DivisionByZero(_) | Error::Singular(_)))) => {
                    return Ok(Pair::Vanishes { index: idx, error });
                }
                (Err(e), _) | (_, Err(e)) => return Err(e),
            };
            match l.equals(&r) {
                Some(true) => {
                    observe(&values, b, &l);
                    rows.push(Row {
                        at: values.clone(),
                        basis: b,
                        value: certificate::entries(&l),
                    });
                }
                equal => {
                    let refutation = (equal == Some(false)).then(|| {
                        let points = if polygons > 1 { env.control_points() } else { Vec::new() };
                        let equality =
                            certificate::equality(bounds, &[], Vec::new(), (polygons, points), written(&*env, bounds));
                        Box::new(Refutation {
                            equality,
                            at: bounds.params.iter().cloned().zip(values.iter().cloned()).collect(),
                            lhs: certificate::entries(&l),
                            rhs: certificate::entries(&r),
                            basis: b,
                            premise: None,
                        })
                    });
                    return Ok(Pair::Differs {
                        at: values,
                        basis: b,
                        lhs: l,
                        rhs: r,
                        equal,
                        refutation,
                    });
                }
            }
        }
        // The next grid point, the last parameter fastest.
        let mut k = points.len();
        loop {
            if k == 0 {
                return Ok(Pair::Equal(Case {
                    degrees: bounds.needs.clone(),
                    polygons,
                    data: Box::new(certificate::equality(
                        bounds,
                        points,
                        rows,
                        (polygons, if polygons > 1 { env.control_points() } else { Vec::new() }),
                        written(&*env, bounds),
                    )),
                }));
            }
            k -= 1;
            idx[k] += 1;
            if idx[k] < points[k].len() {
                break;
            }
            idx[k] = 0;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::checked::{Method, Verdict};
    use super::super::eval::VarEnv;
    use super::super::expr::Op;
    use super::*;

    fn q(n: i64) -> BigRational {
        BigRational::from_integer(n.into())
    }
    fn num(n: i64) -> Expr {
        Expr::Num(q(n))
    }
    fn bin(op: Op, a: Expr, b: Expr) -> Expr {
        Expr::Bin(op, Box::new(a), Box::new(b))
    }
    fn t() -> Expr {
        Expr::Var("t".into())
    }

    /// Plain variables, no control polygon.
    struct Plain(VarEnv<BigRational>);
    impl Points<BigRational> for Plain {
        fn polygons(&self) -> usize {
            1
        }
        fn at(&mut self, _: usize, params: &[String], values: &[BigRational]) -> Result<&dyn Env<BigRational>> {
            for (p, v) in params.iter().zip(values) {
                self.0 .0.insert(p.clone(), Value::S(v.clone()));
            }
            Ok(&self.0)
        }
        fn control_points(&self) -> Vec<(String, Vec<i64>)> {
            Vec::new()
        }
    }

    /// A control polygon `b[0], b[1]` whose basis polygons are `basis` (their values).
    struct Polygon {
        basis: Vec<[i64; 2]>,
        at: usize,
    }
    impl Env<BigRational> for Polygon {
        fn var(&self, _: &str) -> Option<Value<BigRational>> {
            None
        }
        fn call(&self, _: &str, _: &[Expr], _: &mut Evaluator<'_, BigRational>) -> Result<Option<Value<BigRational>>> {
            Ok(None)
        }
        fn index(&self, name: &str, idx: &[i64]) -> Result<Option<Value<BigRational>>> {
            let j = usize::try_from(idx[0]).ok().filter(|&j| name == "b" && j < 2);
            Ok(j.map(|j| Value::S(q(self.basis[self.at][j]))))
        }
    }
    impl Points<BigRational> for Polygon {
        fn polygons(&self) -> usize {
            self.basis.len()
        }
        fn at(&mut self, basis: usize, _: &[String], _: &[BigRational]) -> Result<&dyn Env<BigRational>> {
            self.at = basis;
            Ok(self)
        }
        fn control_points(&self) -> Vec<(String, Vec<i64>)> {
            vec![("b".into(), vec![0]), ("b".into(), vec![1])]
        }
    }
    struct PolygonDegrees;
    impl Env<Deg> for PolygonDegrees {
        fn var(&self, _: &str) -> Option<Value<Deg>> {
            None
        }
        fn call(&self, _: &str, _: &[Expr], _: &mut Evaluator<'_, Deg>) -> Result<Option<Value<Deg>>> {
            Ok(None)
        }
        fn index(&self, _: &str, _: &[i64]) -> Result<Option<Value<Deg>>> {
            Ok(Some(Value::S(Deg::control_point())))
        }
    }

    #[test]
    fn an_incomplete_basis_is_refused() {
        // b[0] + b[1] = b[0] + 2·b[1] holds on the zero polygon and the unit polygon of b[0].
        let b = |j: i64| Expr::Index("b".into(), vec![num(j)]);
        let lhs = bin(Op::Add, b(0), b(1));
        let rhs = bin(Op::Add, b(0), bin(Op::Mul, num(2), b(1)));
        let ints = BTreeMap::new();
        let bd = bounds(&lhs, &rhs, &ints, Vec::new(), &PolygonDegrees).unwrap();
        assert!(bd.uses_polygon());
        let check = |basis: Vec<[i64; 2]>| check_pair(&bd, &mut Polygon { basis, at: 0 }, &[], &mut |_, _, _| {});
        for basis in [
            vec![[0, 0], [1, 0]],
            vec![[0, 0], [1, 0], [1, 0]],
            vec![[0, 0], [1, 0], [0, 2]],
            vec![[0, 1], [1, 0], [0, 1]],
            vec![[0, 0], [1, 1], [0, 1]],
            vec![[0, 0], [1, 0], [0, 1], [0, 0]],
        ] {
            assert!(check(basis.clone()).is_err(), "{basis:?}");
        }
        let complete = check(vec![[0, 0], [1, 0], [0, 1]]).unwrap();
        assert!(matches!(complete, Pair::Differs { basis: 2, .. }));
        let same = bounds(&lhs, &lhs, &ints, Vec::new(), &PolygonDegrees).unwrap();
        let equal = check_pair(
            &same,
            &mut Polygon {
                basis: vec![[0, 0], [1, 0], [0, 1]],
                at: 0,
            },
            &[],
            &mut |_, _, _| {},
        );
        assert!(matches!(equal.unwrap(), Pair::Equal(Case { polygons: 3, .. })));
    }

    #[test]
    fn wrong_proposals_are_refused() {
        // (t + 1)^2 = t·t + 2·t + 1, and a right side off by t·(t − 1): equal at 0 and 1 only.
        let lhs = bin(Op::Pow, bin(Op::Add, t(), num(1)), num(2));
        let square = bin(
            Op::Add,
            bin(Op::Add, bin(Op::Mul, t(), t()), bin(Op::Mul, num(2), t())),
            num(1),
        );
        let off = bin(Op::Add, square.clone(), bin(Op::Mul, t(), bin(Op::Sub, t(), num(1))));
        let degrees = VarEnv(BTreeMap::from([("t".to_string(), Value::S(Deg::var("t")))]));
        let ints = BTreeMap::new();
        let good = bounds(&lhs, &square, &ints, vec!["t".into()], &degrees).unwrap();
        assert_eq!(good.needs(), &[2]);
        let mut env = Plain(VarEnv(BTreeMap::new()));
        let mut check = |b: &Bounds<'_>, pts: Vec<BigRational>| check_pair(b, &mut env, &[pts], &mut |_, _, _| {});
        let case = match check(&good, vec![q(0), q(1), q(2)]).unwrap() {
            Pair::Equal(c) => c,
            _ => panic!("(t + 1)^2 = t^2 + 2t + 1 at 0, 1, 2"),
        };
        let p = super::super::check_sampled(vec![case]).unwrap();
        assert_eq!(p.verdict(), Verdict::Proved);
        assert_eq!(
            p.method(),
            Method::Sampling {
                basis: false,
                degree: 2
            }
        );
        // Too few points, a repeated point, points for no parameter.
        assert!(check(&good, vec![q(0), q(1)]).is_err());
        assert!(check(&good, vec![q(0), q(1), q(1)]).is_err());
        assert!(check_pair(&good, &mut Plain(VarEnv(BTreeMap::new())), &[], &mut |_, _, _| {}).is_err());
        // A side that differs at one point of the grid is a counterexample there.
        let wrong = bounds(&lhs, &off, &ints, vec!["t".into()], &degrees).unwrap();
        assert!(check(&wrong, vec![q(0), q(1)]).is_err());
        match check(&wrong, vec![q(0), q(1), q(2)]).unwrap() {
            Pair::Differs {
                at, lhs, rhs, equal, ..
            } => {
                assert_eq!((at, equal), (vec![q(2)], Some(false)));
                assert_eq!((lhs.to_string(), rhs.to_string()), ("9".to_string(), "11".to_string()));
            }
            _ => panic!("t·(t − 1) is 2 at t = 2"),
        }
        // A vanishing denominator is reported at its grid point, not passed over.
        let pole = bin(Op::Div, num(1), t());
        let b = bounds(&pole, &pole, &ints, vec!["t".into()], &degrees).unwrap();
        assert!(matches!(check(&b, vec![q(1), q(0), q(2)]).unwrap(), Pair::Vanishes { index, .. } if index == [1]));
        assert!(super::super::check_sampled(Vec::new()).is_err());
    }
}
