//! The fast `f64` kernels give the bits of the straightforward ones: compensated
//! de Casteljau (products' errors by a prepared factor, redone by TwoProduct when a value
//! leaves the exact range) against the textbook loop with `f64::mul_add`, and
//! `tight_interval_de_casteljau` (two products per endpoint) against the interval operations on
//! every node, on random curves and on the edges: subnormals, values near 1e308, zeros of
//! both signs, t outside [0, 1] and at its ends.

use casteljau::float::{compensated_de_casteljau, next_down, next_up, two_product_fma, two_sum};
use casteljau::{tight_interval_de_casteljau, Interval};

#[path = "support/rng.rs"]
mod rng;
use rng::Rng;

/// Compensated de Casteljau as first written (Jiang, Li, Cheng, Su 2010), with the FMA form.
fn compensated_reference(b: &[f64], t: f64) -> f64 {
    let n = b.len() - 1;
    let (s, rho) = two_sum(1.0, -t);
    let mut hi = b.to_vec();
    let mut lo = vec![0.0; n + 1];
    for r in 1..=n {
        for i in 0..=n - r {
            let (p1, e1) = two_product_fma(s, hi[i]);
            let (p2, e2) = two_product_fma(t, hi[i + 1]);
            let (sum, e3) = two_sum(p1, p2);
            let w = e1 + e2 + e3 + rho * hi[i];
            lo[i] = w + s * lo[i] + t * lo[i + 1];
            hi[i] = sum;
        }
    }
    hi[0] + lo[0]
}

/// Interval de Casteljau by the interval operations, node by node.
fn interval_reference(b: &[f64], t: f64) -> Interval {
    let (s, rho) = two_sum(1.0, -t);
    let lo = if rho < 0.0 { next_down(s) } else { s };
    let hi = if rho > 0.0 { next_up(s) } else { s };
    let s = Interval::new(lo, hi).unwrap();
    let t = Interval::point(t).unwrap();
    let mut buf: Vec<Interval> = b.iter().map(|x| Interval::point(*x).unwrap()).collect();
    for len in (1..buf.len()).rev() {
        for i in 0..len {
            buf[i] = s * buf[i] + t * buf[i + 1];
        }
    }
    buf[0]
}

fn check(b: &[f64], t: f64) {
    let fast = compensated_de_casteljau(b, t).0;
    let reference = compensated_reference(b, t);
    assert!(
        fast.to_bits() == reference.to_bits() || (fast.is_nan() && reference.is_nan()),
        "compensated: {b:?} at {t}: {fast:e} against {reference:e}"
    );
    if b.iter().all(|x| x.is_finite()) && t.is_finite() {
        let fast = tight_interval_de_casteljau(b, t).unwrap();
        let reference = interval_reference(b, t);
        assert_eq!(
            (fast.lo().to_bits(), fast.hi().to_bits()),
            (reference.lo().to_bits(), reference.hi().to_bits()),
            "interval: {b:?} at {t}: {fast} against {reference}"
        );
    }
}

#[test]
fn fast_kernels_give_the_reference_bits() {
    let mut rng = Rng(2010);
    let specials = [
        0.0,
        -0.0,
        5e-324,
        -1e-310,
        f64::MIN_POSITIVE,
        1e-300,
        1e-290,
        1e300,
        1e308,
        -f64::MAX,
        f64::MAX,
        1.0,
        -0.5,
    ];
    let ts = [
        0.3,
        0.5,
        0.0,
        1.0,
        1e-310,
        0.9999999999999999,
        -0.25,
        1.5,
        1e-20,
        0.7500001,
    ];
    for case in 0..6_000 {
        let n = [1, 2, 3, 5, 10, 20, 40][case % 7];
        let scale = match case % 5 {
            0 => 1.0,
            1 => 1e-300,
            2 => 1e300,
            3 => 1e-310,
            _ => 2f64.powi((rng.next() % 2000) as i32 - 1000),
        };
        let b: Vec<f64> = (0..=n)
            .map(|_| {
                if rng.next() % 8 == 0 {
                    specials[(rng.next() % specials.len() as u64) as usize]
                } else {
                    (2.0 * rng.unit() - 1.0) * scale
                }
            })
            .collect();
        let t = if case % 3 == 0 {
            ts[(rng.next() % ts.len() as u64) as usize]
        } else {
            rng.unit()
        };
        check(&b, t);
    }
    // near a triple root, where the low parts matter
    for k in 0..200 {
        let t = 0.75 + (k as f64 - 100.0) * 1e-9;
        check(&[-0.421875, 0.140625, -0.046875, 0.015625], t);
    }
    check(&[f64::NAN, 1.0], 0.3);
    check(&[f64::INFINITY, 1.0, 2.0], 0.3);
}
