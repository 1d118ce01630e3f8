//! Tests of the recurrence checks (a file of their own: `recurrence.rs` stays within the
//! size the guide sets).

use super::super::hyper::Base;
use super::*;
use num_rational::BigRational;

fn sym() -> Symbols {
    Symbols::new(&["n".into(), "k".into()], &[])
}

fn aff(n: i64, k: i64, c: i64) -> Aff {
    Aff::var("n").scaled(n).plus(&Aff::var("k").scaled(k)).shifted(c)
}

/// `coef · n! / ((k − s)! (n − k + s)!) · base^(n + e)`: `C(n, k − s)` times a power.
fn binomial(coef: RatFunc, s: i64, base: i64, e: i64) -> Term {
    let mut t = Term::scalar(coef);
    t.facts = vec![(aff(1, 0, 0), 1), (aff(0, 1, -s), -1), (aff(1, -1, s), -1)];
    if base != 1 {
        let b = BigRational::new(1.into(), base.into());
        t.pows = vec![(Base::Const(b), aff(1, 0, e))];
    }
    t
}

fn q(a: i64, b: i64) -> RatFunc {
    RatFunc::from_rat(&BigRational::new(a.into(), b.into()))
}

/// `Σ_{k=0}^{n} C(n, k) / 2^n = 1` for `n ≥ 0` with the certificate `G`.
fn wz(g: &[Term]) -> Result<Discharged> {
    let sym = sym();
    let (zero, n) = (Aff::constant(0), Aff::var("n"));
    let bounds = Bounds {
        k: "k",
        a: &zero,
        b: &n,
        n: "n",
    };
    let d = Domain { cons: vec![n.clone()] };
    let f = vec![binomial(RatFunc::from_int(1), 0, 2, 0)];
    let hint = Some(vec![Term::scalar(RatFunc::from_int(1))]);
    let mut log = Vec::new();
    let at = |m: &Aff| d.subst("n", m);
    let goal = wz_goal(&sym, f, hint, &bounds, &zero, &d, &at, "S", &mut log)?;
    check_wz(&sym, &goal, g, &bounds, &d, &at(&zero), "S", &mut log)
}

#[test]
fn check_wz_refuses_a_wrong_certificate() {
    // G(n, k) = −C(n, k − 1) / 2^(n+1).
    assert!(wz(&[binomial(q(-1, 1), 1, 2, 1)]).is_ok());
    // Right but for its coefficient, for its shift, or G = F, or no G at all.
    assert!(wz(&[binomial(q(-1, 3), 1, 2, 1)]).is_err());
    assert!(wz(&[binomial(q(-1, 1), 1, 2, 0)]).is_err());
    assert!(wz(&[binomial(q(-1, 1), 2, 2, 1)]).is_err());
    assert!(wz(&[binomial(q(1, 1), 0, 2, 0)]).is_err());
    assert!(wz(&[]).is_err());
    // The right G split in two terms, one of them with a wrong coefficient.
    assert!(wz(&[binomial(q(-1, 2), 1, 2, 1), binomial(q(-1, 2), 1, 2, 1)]).is_ok());
    assert!(wz(&[binomial(q(-1, 2), 1, 2, 1), binomial(q(-1, 3), 1, 2, 1)]).is_err());
}

/// The sum over `0 ≤ k ≤ n` for every `n ≥ 0` (`zero` the constant 0, `n` the variable).
fn from_zero_to_n<'a>(zero: &'a Aff, n: &'a Aff, rest: &'a Domain) -> SumShape<'a> {
    SumShape {
        k: "k",
        a: zero,
        b: n,
        n: "n",
        n0: zero,
        rest,
    }
}

/// `Σ_{k=0}^{n} C(n, k) = c^n` for `n ≥ 0` by the recurrence `p` and certificate `G`.
fn telescoper(p: &[i64], g: Term, c: i64) -> Result<(Discharged, String)> {
    let sym = sym();
    let (zero, n) = (Aff::constant(0), Aff::var("n"));
    let rest = Domain::default();
    let shape = from_zero_to_n(&zero, &n, &rest);
    let t = Telescoper {
        p: p.iter().map(|&x| RatFunc::from_int(x)).collect(),
        g,
        r: String::new(),
    };
    let mut rhs = Term::scalar(RatFunc::from_int(1));
    rhs.pows = vec![(Base::Const(BigRational::from_integer(c.into())), n.clone())];
    let f = binomial(RatFunc::from_int(1), 0, 1, 0);
    check_telescoper(&sym, &f, &t, &shape, (&[rhs], None), "S", &mut Vec::new())
}

#[test]
fn check_telescoper_refuses_a_wrong_recurrence() {
    // S(n+1) − 2 S(n) = 0 with G(n, k) = −C(n, k − 1).
    let g = |c: i64, s: i64| binomial(RatFunc::from_int(c), s, 1, 0);
    assert!(telescoper(&[-2, 1], g(-1, 1), 2).is_ok());
    assert!(telescoper(&[-3, 1], g(-1, 1), 2).is_err());
    assert!(telescoper(&[-2, 1], g(-2, 1), 2).is_err());
    assert!(telescoper(&[-2, 1], g(-1, 0), 2).is_err());
    assert!(telescoper(&[-2, 1], g(-1, 1), 3).is_err());
    // A true recurrence of the sum that 3^n does not satisfy: refused at the ends.
    assert!(telescoper(&[-3, 1], g(-1, 1), 3).is_err());
}

/// `Σ_{k=0}^{n} C(n, k) = Σ_{k=1}^{n+1} C(n, k − s2)` for `n ≥ 0` by `S(n+1) − 2 S(n)` for
/// the left sum (`G = −C(n, k − 1)`) and `p2`, `G2 = c2·C(n, k − 2)` for the right one.
fn two_forms(p2: &[i64], c2: i64, s2: i64) -> Result<(Discharged, String)> {
    let sym = sym();
    let (zero, one, n) = (Aff::constant(0), Aff::constant(1), Aff::var("n"));
    let rest = Domain::default();
    let shape = from_zero_to_n(&zero, &n, &rest);
    let tel = |p: &[i64], g: Term| Telescoper {
        p: p.iter().map(|&x| RatFunc::from_int(x)).collect(),
        g,
        r: String::new(),
    };
    let t1 = tel(&[-2, 1], binomial(RatFunc::from_int(-1), 1, 1, 0));
    let t2 = tel(p2, binomial(RatFunc::from_int(c2), 2, 1, 0));
    let (f1, f2) = (
        binomial(RatFunc::from_int(1), 0, 1, 0),
        binomial(RatFunc::from_int(1), s2, 1, 0),
    );
    let b2 = n.shifted(1);
    let other: Other<'_> = (&f2, &t2, &one, &b2);
    check_telescoper(&sym, &f1, &t1, &shape, (&[], Some(&other)), "S", &mut Vec::new())
}

#[test]
fn two_forms_need_one_recurrence_both_certificates_and_the_initial_values() {
    assert!(two_forms(&[-2, 1], -1, 1).is_ok());
    // Another recurrence for the right sum, a wrong certificate of it, or the right sum
    // of another sequence (Σ_{k=1}^{n+1} C(n, k − 2) = 2^n − 1).
    assert!(two_forms(&[-3, 1], -1, 1).is_err());
    assert!(two_forms(&[-2, 1], -2, 1).is_err());
    assert!(two_forms(&[-2, 1], -1, 2).is_err());
}
