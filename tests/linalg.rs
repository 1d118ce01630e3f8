//! Exact linear algebra: Bareiss against cofactor expansion, solve/inverse round trips,
//! singular systems as errors.

use casteljau::linalg::{
    determinant, determinant_cofactor, identity, inverse, mat_mul, mat_vec, rank, solve, solve_many,
};
use casteljau::{BigRational, Error, Ring, Scalar};
use proptest::prelude::*;

type Q = BigRational;

fn rat() -> impl Strategy<Value = Q> {
    // Many zeros, so that zero pivots and row swaps are exercised.
    prop_oneof![
        Just(Q::from_i64(0)),
        (-9i64..=9, 1i64..=5).prop_map(|(p, q)| Q::from_ratio(p, q).unwrap()),
    ]
}

fn square(n: usize) -> impl Strategy<Value = Vec<Vec<Q>>> {
    prop::collection::vec(prop::collection::vec(rat(), n), n)
}

fn sized() -> impl Strategy<Value = Vec<Vec<Q>>> {
    (1usize..=5).prop_flat_map(square)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn bareiss_equals_cofactor_expansion(a in sized()) {
        prop_assert_eq!(determinant(&a).unwrap(), determinant_cofactor(&a).unwrap());
    }

    #[test]
    fn determinant_is_multiplicative(a in square(3), b in square(3)) {
        let ab = mat_mul(&a, &b).unwrap();
        prop_assert_eq!(determinant(&ab).unwrap(), &determinant(&a).unwrap() * &determinant(&b).unwrap());
    }

    /// solve(A, A x) = x when det A ≠ 0; otherwise solve and inverse report Singular and the
    /// rank is below n.
    #[test]
    fn solve_round_trip_or_singular(a in sized(), x in prop::collection::vec(rat(), 5)) {
        let n = a.len();
        let x = x[..n].to_vec();
        let b = mat_vec(&a, &x).unwrap();
        if determinant(&a).unwrap().is_zero() {
            prop_assert!(rank(&a).unwrap() < n);
            prop_assert!(matches!(solve(&a, &b), Err(Error::Singular(_))));
            prop_assert!(matches!(inverse(&a), Err(Error::Singular(_))));
        } else {
            prop_assert_eq!(rank(&a).unwrap(), n);
            prop_assert_eq!(solve(&a, &b).unwrap(), x.clone());
            let inv = inverse(&a).unwrap();
            prop_assert_eq!(mat_mul(&a, &inv).unwrap(), identity(n));
            prop_assert_eq!(mat_vec(&inv, &b).unwrap(), x.clone());
            let many = solve_many(&a, &b.iter().map(|v| vec![v.clone(), -v]).collect::<Vec<_>>()).unwrap();
            prop_assert_eq!(many.iter().map(|r| r[0].clone()).collect::<Vec<_>>(), x);
        }
    }

    /// A matrix with a row that is a combination of two others is singular: det 0, error.
    #[test]
    fn dependent_rows_are_singular(a in square(4), c1 in rat(), c2 in rat()) {
        let mut a = a;
        a[3] = a[0].iter().zip(&a[1]).map(|(x, y)| &(&c1 * x) + &(&c2 * y)).collect();
        prop_assert!(determinant(&a).unwrap().is_zero());
        prop_assert!(matches!(solve(&a, &[Q::from_i64(1), Q::from_i64(2), Q::from_i64(3), Q::from_i64(4)]), Err(Error::Singular(_))));
    }

    /// f64 runs the same Bareiss code: it agrees with the exact determinant to 1e-9 relative
    /// to the product of the row norms (Hadamard's bound).
    #[test]
    fn float_determinant_agrees(a in sized()) {
        let exact = determinant(&a).unwrap().to_f64();
        let af: Vec<Vec<f64>> = a.iter().map(|r| r.iter().map(Scalar::to_f64).collect()).collect();
        let float = determinant(&af).unwrap();
        let hadamard: f64 = af.iter().map(|r| r.iter().map(|x| x * x).sum::<f64>().sqrt().max(1.0)).product();
        prop_assert!((float - exact).abs() <= 1e-9 * hadamard, "{} vs {}", float, exact);
    }
}

#[test]
fn bad_shapes_are_errors() {
    let q = Q::from_i64;
    assert!(determinant::<Q>(&[]).is_err());
    assert!(determinant(&[vec![q(1), q(2)], vec![q(3)]]).is_err());
    assert!(inverse(&[vec![q(1), q(2), q(3)], vec![q(4), q(5), q(6)]]).is_err());
    assert!(mat_mul(&[vec![q(1), q(2)]], &[vec![q(1), q(2)]]).is_err());
    assert!(mat_vec(&[vec![q(1), q(2)]], &[q(1)]).is_err());
    let big = vec![vec![q(1); 9]; 9];
    assert!(matches!(determinant_cofactor(&big), Err(Error::TooLarge { .. })));
    assert_eq!(determinant(&big).unwrap(), q(0));
    // Under-determined: 1 equation, 2 unknowns.
    assert!(solve(&[vec![q(1), q(1)]], &[q(2)]).is_err());
}

#[test]
fn float_overflow_is_an_error_not_infinity() {
    let a = vec![vec![1e200, 0.0], vec![0.0, 1e200]];
    assert!(matches!(determinant(&a), Err(Error::NotFinite(_))));
}
