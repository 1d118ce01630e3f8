// The expression parser and evaluator: round trips, agreement with the library, bad input.

use super::kernel::eval::{Evaluator, Value, VarEnv};
use super::kernel::expr::Expr;
use super::parse::parse;
use crate::{bernstein, eval_power};
use crate::{BigRational, Ring, Scalar};
use proptest::prelude::*;
use std::collections::BTreeMap;

type Q = BigRational;

fn eval_t(e: &Expr, t: &Q) -> crate::Result<Q> {
    let mut vars = BTreeMap::new();
    vars.insert("t".to_string(), Value::S(t.clone()));
    vars.insert("s".to_string(), Value::S(Q::from_ratio(2, 7).unwrap()));
    let env = VarEnv(vars);
    Evaluator::new(&env, BTreeMap::new()).scalar(e)
}

fn arb_expr() -> impl Strategy<Value = Expr> {
    let leaf = prop_oneof![
        (0i64..20).prop_map(Expr::int),
        Just(Expr::Var("t".into())),
        Just(Expr::Var("s".into())),
    ];
    leaf.prop_recursive(4, 32, 3, |inner| operations(inner.boxed()))
}

/// Negation, the four operations, integer powers and `B(i, n, ·)` of expressions of `inner`.
fn operations(inner: BoxedStrategy<Expr>) -> impl Strategy<Value = Expr> {
    prop_oneof![
        inner.clone().prop_map(|a| Expr::Neg(Box::new(a))),
        (inner.clone(), inner.clone()).prop_map(|(a, b)| Expr::add(a, b)),
        (inner.clone(), inner.clone()).prop_map(|(a, b)| Expr::sub(a, b)),
        (inner.clone(), inner.clone()).prop_map(|(a, b)| Expr::mul(a, b)),
        (inner.clone(), inner.clone()).prop_map(|(a, b)| Expr::div(a, b)),
        (inner.clone(), 0i64..4).prop_map(|(a, k)| Expr::pow(a, Expr::int(k))),
        (0i64..4, 0i64..5, inner).prop_map(|(i, n, g)| Expr::Call("B".into(), vec![Expr::int(i), Expr::int(n), g])),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn print_parse_round_trip(e in arb_expr()) {
        let printed = e.to_string();
        let back = parse(&printed, &[]).unwrap();
        prop_assert_eq!(&back, &e, "printed as {}", printed);
    }

    #[test]
    fn bernstein_agrees_with_library(i in 0usize..8, n in 0usize..8, p in -9i64..10, q in 1i64..9) {
        let t = Q::from_ratio(p, q).unwrap();
        let e = parse(&format!("B({i}, {n}, t)"), &[]).unwrap();
        prop_assert_eq!(eval_t(&e, &t).unwrap(), bernstein(i, n, &t).unwrap());
    }

    #[test]
    fn polynomials_agree_with_eval_power(coeffs in prop::collection::vec(-20i64..20, 1..7), p in -9i64..10, q in 1i64..9) {
        let t = Q::from_ratio(p, q).unwrap();
        let text: Vec<String> = coeffs.iter().enumerate().map(|(k, c)| format!("({c})t^{k}")).collect();
        let e = parse(&text.join(" + "), &[]).unwrap();
        let a: Vec<Q> = coeffs.iter().map(|&c| Q::from_i64(c)).collect();
        prop_assert_eq!(eval_t(&e, &t).unwrap(), eval_power(&a, &t));
    }
}

#[test]
fn book_notation() {
    let q = |p, d| Q::from_ratio(p, d).unwrap();
    let e = parse("(2t-1)/(t^2-t+1)", &[]).unwrap();
    assert_eq!(eval_t(&e, &q(1, 2)).unwrap(), q(0, 1));
    let e = parse("4x^2+3y^2-10y+3", &[]).unwrap();
    assert_eq!(e.to_string(), "4*x^2 + 3*y^2 - 10*y + 3");
    let e = parse("C(5, 2) + binom(4, 4) + sum(r, 0, 3, r)", &[]).unwrap();
    assert_eq!(eval_t(&e, &q(0, 1)).unwrap(), q(17, 1));
}

#[test]
fn bad_inputs_have_clear_errors() {
    let msg = |s: &str| match parse(s, &[]) {
        Err(e) => e.to_string(),
        Ok(e) => match eval_t(&e, &Q::from_ratio(1, 3).unwrap()) {
            Err(e) => e.to_string(),
            Ok(v) => panic!("{s} evaluated to {v}"),
        },
    };
    assert!(msg("(1 + t").contains("expected ')'"));
    assert!(msg("1 + t)").contains("unexpected ')'"));
    assert!(msg("foo(t)").contains("unknown function"));
    assert!(msg("1/0").contains("division by zero"));
    assert!(msg("1/(3t - 1)").contains("division by zero"));
    assert!(msg("t^99999999").contains("too large"));
    assert!(msg("sqrt(-4)").contains("negative"));
    assert!(msg("sqrt(2)").contains("irrational"));
    assert!(msg("sqrt(t)").contains("constant"));
    assert!(msg("t^(1/2)").contains("exponent"));
    assert!(msg("B(1, 2)").contains("B needs 3 arguments"));
    assert!(msg("").contains("empty"));
}

/// Expressions as a certificate's goal is built (`inline`): negative and fractional
/// constants, vectors, sums, factorials, Bernstein polynomials and their derivatives, control
/// points.
fn arb_written() -> impl Strategy<Value = Expr> {
    let num = (-30i64..30, 1i64..7).prop_map(|(p, q)| Expr::Num(Q::from_ratio(p, q).unwrap()));
    let leaf = prop_oneof![num, Just(Expr::Var("t".into())), Just(Expr::Var("s".into()))];
    leaf.prop_recursive(4, 40, 3, |inner| {
        prop_oneof![
            7 => operations(inner.clone().boxed()),
            1 => (0i64..5).prop_map(|k| Expr::Fact(Box::new(Expr::int(k)))),
            1 => (0i64..4, 0i64..5, inner.clone(), 0i64..3)
                .prop_map(|(i, n, g, k)| Expr::Call("__dB".into(), vec![Expr::int(i), Expr::int(n), g, Expr::int(k)])),
            1 => (0i64..3, inner.clone()).prop_map(|(top, body)| Expr::Sum(
                "k".into(),
                Box::new(Expr::int(0)),
                Box::new(Expr::int(top)),
                Box::new(Expr::mul(Expr::Var("k".into()), body))
            )),
            1 => (0i64..4).prop_map(|j| Expr::Index("b".into(), vec![Expr::int(j)])),
        ]
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    // A certificate writes a goal as the printer prints it, without parsing it back: the text
    // must be canonical (it prints back to itself) and mean what the expression means.
    #[test]
    fn written_goals_print_back_and_mean_the_same(e in arb_written(), pair in any::<bool>()) {
        let e = if pair { Expr::Tuple(vec![e.clone(), Expr::Neg(Box::new(e))]) } else { e };
        let known = ["t".to_string(), "s".to_string()];
        let printed = e.to_string();
        let back = parse(&printed, &known).unwrap();
        prop_assert_eq!(back.to_string(), printed.clone());
        let mut vars = BTreeMap::new();
        vars.insert("t".to_string(), Value::S(Q::from_ratio(3, 7).unwrap()));
        vars.insert("s".to_string(), Value::S(Q::from_ratio(-2, 5).unwrap()));
        let env = VarEnv(vars);
        let value = |x: &Expr| Evaluator::new(&env, BTreeMap::new()).eval(x).map_err(|e| e.to_string());
        match (value(&e), value(&back)) {
            (Ok(a), Ok(b)) => prop_assert_eq!(a.equals(&b), Some(true), "printed as {}", printed),
            (Err(_), Err(_)) => {}
            (a, b) => prop_assert!(false, "{} evaluates to {:?} printed, {:?} as built", printed, b, a),
        }
    }
}
