//! The one operator macro and the `Ring` methods it forwards to: for every number type of
//! the crate, each form of each operator (values, references, mixed, compound assignment)
//! gives what the type's `Ring` method gives, and that is the exact `BigRational` result
//! (for `Shadow`, its exact part; for `Interval`, an enclosure of it). Random inputs include
//! values beyond the machine-word fast paths and false identities that must stay false.

use casteljau::exact::SmallRational;
use casteljau::strategies::{large_rational, small_rational};
use casteljau::{BigRational, Interval, QuadraticIrrational, Ring, Scalar, Shadow};
use proptest::prelude::*;

#[derive(Clone, Copy, Debug)]
enum Op {
    Add,
    Sub,
    Mul,
}

const OPS: [Op; 3] = [Op::Add, Op::Sub, Op::Mul];

fn exact(op: Op, a: &BigRational, b: &BigRational) -> BigRational {
    match op {
        Op::Add => a + b,
        Op::Sub => a - b,
        Op::Mul => a * b,
    }
}

/// Every operator form of `op` on `a` and `b`, and the `Ring` method; all must be equal.
fn all_forms<T: Scalar>(op: Op, a: &T, b: &T) -> Vec<T> {
    let method = match op {
        Op::Add => a.add_ref(b),
        Op::Sub => a.sub_ref(b),
        Op::Mul => a.mul_ref(b),
    };
    let (owned_a, owned_b) = (a.clone(), b.clone());
    let by_value = match op {
        Op::Add => owned_a.clone() + owned_b.clone(),
        Op::Sub => owned_a.clone() - owned_b.clone(),
        Op::Mul => owned_a.clone() * owned_b.clone(),
    };
    let value_by_ref = match op {
        Op::Add => owned_a.clone() + b,
        Op::Sub => owned_a.clone() - b,
        Op::Mul => owned_a.clone() * b,
    };
    let mut assigned = owned_a.clone();
    match op {
        Op::Add => assigned += b,
        Op::Sub => assigned -= b,
        Op::Mul => assigned *= b,
    }
    vec![method, by_value, value_by_ref, assigned]
}

/// The forms only the crate's own types have (references on the left, owned on the right).
fn ref_forms<T>(op: Op, a: &T, b: &T) -> Vec<T>
where
    T: Clone,
    for<'a> &'a T: std::ops::Add<&'a T, Output = T>
        + std::ops::Sub<&'a T, Output = T>
        + std::ops::Mul<&'a T, Output = T>
        + std::ops::Add<T, Output = T>
        + std::ops::Sub<T, Output = T>
        + std::ops::Mul<T, Output = T>,
    T: std::ops::AddAssign<T> + std::ops::SubAssign<T> + std::ops::MulAssign<T>,
{
    let mut assigned = a.clone();
    let forms = match op {
        Op::Add => {
            assigned += b.clone();
            [a + b, a + b.clone()]
        }
        Op::Sub => {
            assigned -= b.clone();
            [a - b, a - b.clone()]
        }
        Op::Mul => {
            assigned *= b.clone();
            [a * b, a * b.clone()]
        }
    };
    let mut out = forms.to_vec();
    out.push(assigned);
    out
}

fn rational() -> BoxedStrategy<BigRational> {
    prop_oneof![3 => small_rational(), 1 => large_rational()].boxed()
}

proptest! {
    #[test]
    fn small_rational_operators_are_the_ring_methods_and_exact(a in rational(), b in rational()) {
        let (x, y) = (SmallRational::from(&a), SmallRational::from(&b));
        for op in OPS {
            let want = SmallRational::from(&exact(op, &a, &b));
            for got in all_forms(op, &x, &y).into_iter().chain(ref_forms(op, &x, &y)) {
                prop_assert_eq!(&got, &want, "{:?}", op);
            }
        }
        prop_assert_eq!(-&x, SmallRational::from(&-&a));
        prop_assert_eq!(-x.clone(), x.neg_ref());
        // A false identity stays false: a + b = a + b + 1.
        prop_assert_ne!(x.add_ref(&y), x.add_ref(&y).add_ref(&SmallRational::one()));
    }

    #[test]
    fn quadratic_operators_are_the_ring_methods_and_exact(a in rational(), b in rational(), c in rational(), d in rational()) {
        // x = a + b√2, y = c + d√2: (x·y) = (ac + 2bd) + (ad + bc)√2.
        let x = QuadraticIrrational::new(a.clone(), b.clone(), 2).unwrap();
        let y = QuadraticIrrational::new(c.clone(), d.clone(), 2).unwrap();
        let two = BigRational::from_i64(2);
        let expected = |op: Op| match op {
            Op::Add => QuadraticIrrational::new(&a + &c, &b + &d, 2).unwrap(),
            Op::Sub => QuadraticIrrational::new(&a - &c, &b - &d, 2).unwrap(),
            Op::Mul => QuadraticIrrational::new(&a * &c + &two * &b * &d, &a * &d + &b * &c, 2).unwrap(),
        };
        for op in OPS {
            let want = expected(op);
            for got in all_forms(op, &x, &y).into_iter().chain(ref_forms(op, &x, &y)) {
                prop_assert_eq!(&got, &want, "{:?}", op);
            }
        }
        prop_assert_eq!(-&x, QuadraticIrrational::new(-&a, -&b, 2).unwrap());
        prop_assert_ne!(x.mul_ref(&y), x.mul_ref(&y).add_ref(&QuadraticIrrational::sqrt(2).unwrap()));
    }

    #[test]
    fn shadow_operators_carry_the_exact_value(a in -1e6f64..1e6, b in -1e6f64..1e6) {
        let (x, y) = (Shadow::from_f64(a).unwrap(), Shadow::from_f64(b).unwrap());
        let (ea, eb) = (BigRational::from_f64(a).unwrap(), BigRational::from_f64(b).unwrap());
        for op in OPS {
            let want = exact(op, &ea, &eb);
            let float = match op {
                Op::Add => a + b,
                Op::Sub => a - b,
                Op::Mul => a * b,
            };
            for got in all_forms(op, &x, &y).into_iter().chain(ref_forms(op, &x, &y)) {
                prop_assert_eq!(got.exact(), &want, "{:?}", op);
                prop_assert_eq!(got.value(), float, "{:?}", op);
            }
        }
        let negated = -&x;
        prop_assert_eq!(negated.exact(), &-&ea);
    }

    #[test]
    fn interval_operators_enclose_the_exact_value(a in rational(), b in rational()) {
        let (x, y) = (Interval::from_rational(&a).unwrap(), Interval::from_rational(&b).unwrap());
        for op in OPS {
            let want = exact(op, &a, &b);
            let forms = all_forms(op, &x, &y);
            for got in forms.iter().chain(&ref_forms(op, &x, &y)) {
                prop_assert!(got.contains(&want), "{:?}: {} does not contain {}", op, got, want);
                prop_assert_eq!(got, &forms[0], "{:?}", op);
            }
        }
        prop_assert!((-&x).contains(&-&a));
    }

    #[test]
    fn f64_and_rational_ring_methods_are_their_operators(a in -1e6f64..1e6, b in -1e6f64..1e6, p in rational(), q in rational()) {
        prop_assert_eq!(a.add_ref(&b), a + b);
        prop_assert_eq!(a.sub_ref(&b), a - b);
        prop_assert_eq!(a.mul_ref(&b), a * b);
        prop_assert_eq!(a.neg_ref(), -a);
        prop_assert_eq!(p.add_ref(&q), &p + &q);
        prop_assert_eq!(p.sub_ref(&q), &p - &q);
        prop_assert_eq!(p.mul_ref(&q), &p * &q);
        prop_assert_eq!(p.neg_ref(), -&p);
    }
}

#[test]
fn ring_constants_are_the_integers() {
    for n in [-7i64, -1, 0, 1, 2, 1 << 40, i64::MAX, i64::MIN] {
        let q = BigRational::from_i64(n);
        assert_eq!(BigRational::from(SmallRational::from_i64(n)), q);
        assert_eq!(
            QuadraticIrrational::from_i64(n),
            QuadraticIrrational::rational(q.clone())
        );
        assert_eq!(Shadow::from_i64(n).exact(), &q);
        assert!(Interval::from_i64(n).contains(&q));
        assert_eq!(f64::from_i64(n), n as f64);
    }
    assert_eq!(
        SmallRational::zero().add_ref(&SmallRational::one()),
        SmallRational::one()
    );
    assert_ne!(SmallRational::zero(), SmallRational::one());
    assert_eq!(<BigRational as Ring>::one().neg_ref(), BigRational::from_i64(-1));
}
