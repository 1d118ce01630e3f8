//! Rational Bézier evaluation: f64 against exact BigRational and QuadraticIrrational, at
//! degree 2 (a conic arc) and degree 6, plus the exact implicit equation of a conic.

use casteljau::{implicit_conic, BigRational, Point, QuadraticIrrational, RationalBezierCurve, Ring, Scalar};
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;

/// A degree-`n` planar curve with small integer control points, weights in 1..=3 and one
/// y-coordinate scaled by `root` (√2 for the quadratic type, so it does real work).
fn curve<T: Scalar>(n: usize, root: &T) -> RationalBezierCurve<T>
where
    for<'a> &'a T: casteljau::RefOps<T>,
{
    let points = (0..=n)
        .map(|i| {
            let x = T::from_i64(i as i64);
            let y = &T::from_i64(((i * 7) % 5) as i64 - 2) * root;
            Point::new(vec![x, y]).expect("two coordinates")
        })
        .collect();
    let weights = (0..=n).map(|i| T::from_i64(1 + (i % 3) as i64)).collect();
    RationalBezierCurve::new(points, weights).expect("valid curve")
}

fn bench_eval(c: &mut Criterion) {
    let mut group = c.benchmark_group("rational_eval");
    group
        .sample_size(20)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500));
    for n in [2usize, 6] {
        let f = curve::<f64>(n, &2f64.sqrt());
        let tf = 0.375f64;
        group.bench_with_input(BenchmarkId::new("f64", n), &n, |b, _| b.iter(|| f.eval(black_box(&tf))));

        let q = curve::<BigRational>(n, &BigRational::from_ratio(99, 70).expect("nonzero"));
        let tq = BigRational::from_ratio(3, 8).expect("nonzero");
        group.bench_with_input(BenchmarkId::new("rational", n), &n, |b, _| {
            b.iter(|| q.eval(black_box(&tq)))
        });

        let r = curve::<QuadraticIrrational>(n, &QuadraticIrrational::sqrt(2).expect("√2"));
        let tr = QuadraticIrrational::from_ratio(3, 8).expect("nonzero");
        group.bench_with_input(BenchmarkId::new("quadratic", n), &n, |b, _| {
            b.iter(|| r.eval(black_box(&tr)))
        });
    }
    group.finish();
}

fn bench_implicit(c: &mut Criterion) {
    let mut group = c.benchmark_group("implicit_conic");
    group
        .sample_size(20)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500));
    let f = curve::<f64>(2, &1.0);
    group.bench_function("f64", |b| b.iter(|| implicit_conic(black_box(&f))));
    let q = curve::<BigRational>(2, &BigRational::from_i64(1));
    group.bench_function("rational", |b| b.iter(|| implicit_conic(black_box(&q))));
    let r = curve::<QuadraticIrrational>(2, &QuadraticIrrational::sqrt(2).expect("√2"));
    group.bench_function("quadratic", |b| b.iter(|| implicit_conic(black_box(&r))));
    group.finish();
}

criterion_group!(benches, bench_eval, bench_implicit);
criterion_main!(benches);
