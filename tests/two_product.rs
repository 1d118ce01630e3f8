//! TwoProduct is exact on every target: the method this build uses
//! (`casteljau::float::TWO_PRODUCT_METHOD`), Dekker's product and the FMA form are compared
//! with the exact `a·b − p` computed in rationals, on random floats of every magnitude and
//! on the edges: subnormals, products near underflow, operands beyond Dekker's split limit
//! (2^995) and products near overflow, signed zeros, infinities and NaN. Compensated de
//! Casteljau, whose method is chosen at run time, gives the bits of both methods' formulas.

use casteljau::float::{
    compensated_de_casteljau, compensated_de_casteljau_by, nearest_f64, two_product, two_product_dekker,
    two_product_fma, TWO_PRODUCT_METHOD,
};
use casteljau::{BigRational, Scalar};

#[path = "support/rng.rs"]
mod rng;
use rng::Rng;

fn exact(x: f64) -> BigRational {
    BigRational::from_f64(x).unwrap()
}

/// Checks one pair: `p` is the rounded product, the error is `a·b − p` rounded to nearest
/// (exactly it when that is a float), and all three methods agree bit for bit.
fn check(a: f64, b: f64) {
    let (p, e) = two_product(a, b);
    let (pd, ed) = two_product_dekker(a, b);
    let (pf, ef) = two_product_fma(a, b);
    assert_eq!(p.to_bits(), (a * b).to_bits(), "{a:e} * {b:e}");
    assert_eq!((pd.to_bits(), pf.to_bits()), (p.to_bits(), p.to_bits()));
    if !p.is_finite() {
        // no exact error exists; both methods give what the FMA gives
        assert_eq!(ed.is_nan(), ef.is_nan(), "{a:e} * {b:e}");
        if !ef.is_nan() {
            assert_eq!(ed.to_bits(), ef.to_bits(), "{a:e} * {b:e}");
        }
        return;
    }
    let err = exact(a) * exact(b) - exact(p);
    let rounded = nearest_f64(&err);
    for (name, x) in [("chosen", e), ("dekker", ed), ("fma", ef)] {
        assert_eq!(
            x.to_bits(),
            // an exact zero error is +0 (a·b + (−p) with equal magnitudes); a tiny one
            // rounds to the zero of its sign
            if num_traits::Zero::is_zero(&err) {
                0.0f64.to_bits()
            } else {
                rounded.to_bits()
            },
            "{name}: {a:e} * {b:e} = {p:e} + {x:e}, exactly + {rounded:e}"
        );
    }
    // when the error is a float, p + e is the product exactly
    if exact(rounded) == err {
        assert_eq!(exact(p) + exact(e), exact(a) * exact(b));
    }
}

/// A float with random significand bits and an exponent in `lo..hi` (binary), random sign.
fn random_float(rng: &mut Rng, lo: i32, hi: i32) -> f64 {
    let m = 1.0 + rng.unit();
    let e = lo + ((rng.next() % (hi - lo) as u64) as i32);
    let x = m * 2f64.powi(e / 2) * 2f64.powi(e - e / 2);
    if rng.next() % 2 == 0 {
        -x
    } else {
        x
    }
}

#[test]
fn the_chosen_method_is_named() {
    let expected = if cfg!(target_feature = "fma") { "fma" } else { "dekker" };
    assert_eq!(TWO_PRODUCT_METHOD, expected);
}

#[test]
fn random_products_of_every_magnitude_are_exact() {
    let mut rng = Rng(24);
    for _ in 0..20_000 {
        let a = random_float(&mut rng, -1074, 1024);
        let b = random_float(&mut rng, -1074, 1024);
        check(a, b);
        // products near 1, where compensated algorithms live
        check(random_float(&mut rng, -60, 60), random_float(&mut rng, -60, 60));
        // random bit patterns: subnormals, zeros, infinities and NaN included
        check(f64::from_bits(rng.next()), f64::from_bits(rng.next()));
    }
}

#[test]
fn edge_products_are_exact() {
    let two = |e: i32| 2f64.powi(e / 2) * 2f64.powi(e - e / 2);
    let odd = 1.0 + f64::EPSILON; // every significand bit matters
    let mut values = vec![
        0.0,
        -0.0,
        f64::MIN_POSITIVE,
        5e-324,
        1e-310,
        -2.5e-320,
        f64::MAX,
        -f64::MAX,
        1e308,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        0.1,
        0.3,
        1.0 / 3.0,
        134_217_729.0,
    ];
    // around Dekker's limits: operands near 2^995 (the split overflows above 2^996),
    // products near 2^1023 and 2^−967, near 2^−1022 and the smallest subnormal
    for e in [
        995, 996, 997, 1000, 1023, 511, 512, 28, 27, -967, -968, -1022, -1000, -53, -100, -500,
    ] {
        values.extend([two(e), two(e) * odd, -two(e) * (2.0 - f64::EPSILON), two(e) * 1.5]);
    }
    for &a in &values {
        for &b in &values {
            check(a, b);
        }
    }
    // near overflow with full significands: the scaled path
    let mut rng = Rng(1024);
    for _ in 0..5_000 {
        let big = random_float(&mut rng, 960, 1024);
        let small = random_float(&mut rng, -10, 1023 - (big.abs().log2() as i32));
        check(big, small);
        check(small, big);
        let tiny = random_float(&mut rng, -1074, -900);
        check(tiny, random_float(&mut rng, -100, 100));
    }
}

/// Whether compensated de Casteljau takes the FMA formulas on this CPU: the build's target
/// has FMA, or the CPU has AVX and FMA (chosen at run time).
fn runtime_fma() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        cfg!(target_feature = "fma") || (is_x86_feature_detected!("avx") && is_x86_feature_detected!("fma"))
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        cfg!(target_feature = "fma")
    }
}

/// Compensated de Casteljau as called (FMA chosen at run time where the CPU has it, the
/// compile-time method else) against the FMA formulas and Dekker's, forced: the same bits
/// of the value by both, and of the bound by the method this CPU takes (the other method
/// may give another valid bound where its fast path declines a triangle of tiny values),
/// on random coefficients of every magnitude (subnormals, near Dekker's limits, huge,
/// zeros), at degrees 1 to 70 (past the unit-interval path's 63) and at parameters in and
/// out of [0, 1].
#[test]
fn compensated_runtime_choice_gives_the_bits_of_both_methods() {
    let chosen = runtime_fma();
    let mut rng = Rng(47);
    let mut checked = 0;
    for round in 0..6_000 {
        let degree = 1 + (rng.next() % if round % 10 == 0 { 70 } else { 8 }) as usize;
        let (lo, hi) = [(-60, 60), (-1074, -900), (900, 1000), (-1074, 1024)][(rng.next() % 4) as usize];
        let b: Vec<f64> = (0..=degree)
            .map(|_| {
                if rng.next() % 9 == 0 {
                    0.0
                } else {
                    random_float(&mut rng, lo, hi)
                }
            })
            .collect();
        let t = match rng.next() % 6 {
            0 => rng.unit() * 3.0 - 1.0,
            1 => [0.0, 1.0, 5e-324, 1.0 - f64::EPSILON / 2.0][(rng.next() % 4) as usize],
            _ => rng.unit(),
        };
        let runtime = compensated_de_casteljau(&b, t);
        let bits = |(x, e): (f64, f64)| (x.to_bits(), e.to_bits());
        for fma in [true, false] {
            let forced = compensated_de_casteljau_by(&b, t, fma);
            if runtime.0.is_nan() {
                assert!(forced.0.is_nan(), "fma {fma}: {b:?} at {t:e}");
                continue;
            }
            assert_eq!(forced.0.to_bits(), runtime.0.to_bits(), "fma {fma}: {b:?} at {t:e}");
            if fma == chosen {
                assert_eq!(bits(forced), bits(runtime), "fma {fma}: {b:?} at {t:e}");
            }
        }
        checked += 1;
    }
    assert!(checked > 5_000);
}

/// The FMA formulas take the error of each node's sum by FastTwoSum on the two products
/// ordered by magnitude, Dekker's by Knuth's TwoSum: both are the exact error, so the value
/// and the bound agree bit for bit, signed zeros included, on inputs built to exercise the
/// ordering: ties in magnitude, opposite signs that cancel, negative zeros, addends far apart.
#[test]
fn compensated_sum_error_is_the_same_by_either_two_sum() {
    let third = 1.0 / 3.0;
    let cases: Vec<Vec<f64>> = vec![
        vec![-0.0, -0.0, -0.0, -0.0],
        vec![0.0, -0.0, 0.0, -0.0],
        vec![-0.0, 0.0],
        vec![1.0, -1.0, 1.0, -1.0],
        vec![third, -third, third, -third, third],
        vec![1e300, -1e-300, 1e-300, -1e300],
        vec![1.0, 1e-30, -1.0, 1e30],
        vec![-2.5, 2.5, -2.5],
        vec![f64::MIN_POSITIVE, -f64::MIN_POSITIVE, 5e-324, -5e-324],
    ];
    for b in &cases {
        for t in [0.5, 0.3, third, 0.0, 1.0, 1e-20, 1.0 - f64::EPSILON / 2.0] {
            let (fma, dekker) = (
                compensated_de_casteljau_by(b, t, true),
                compensated_de_casteljau_by(b, t, false),
            );
            let runtime = compensated_de_casteljau(b, t);
            assert_eq!(fma.0.to_bits(), dekker.0.to_bits(), "{b:?} at {t:e}");
            assert_eq!(runtime.0.to_bits(), dekker.0.to_bits(), "{b:?} at {t:e}");
            if runtime_fma() {
                assert_eq!(runtime.1.to_bits(), fma.1.to_bits(), "{b:?} at {t:e}");
            }
        }
    }
}
