//! Surface evaluation: tensor de Casteljau (u first, v first) and the Bernstein sum, on a
//! bicubic and a 6×6 net, in `f64` and exact rationals.

use casteljau::{BezierSurface, BigRational, Point, Scalar};
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;

/// A deterministic 3D net of degrees `(m, n)` with small rational coordinates.
fn net(m: usize, n: usize) -> BezierSurface<BigRational> {
    let rows = (0..=m)
        .map(|i| {
            (0..=n)
                .map(|j| {
                    let (i, j) = (i as i64, j as i64);
                    Point::new(vec![
                        BigRational::from_ratio(3 * i + j, 2).unwrap(),
                        BigRational::from_ratio(i - 2 * j, 3).unwrap(),
                        BigRational::from_ratio((i * j) % 7 - 3, 5).unwrap(),
                    ])
                    .unwrap()
                })
                .collect()
        })
        .collect();
    BezierSurface::new(rows).unwrap()
}

fn bench_eval(c: &mut Criterion) {
    let mut group = c.benchmark_group("surface_eval");
    group
        .sample_size(20)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500));
    for (m, n) in [(3usize, 3usize), (6, 6)] {
        let exact = net(m, n);
        let float = exact.try_map(|x| Ok(x.to_f64())).unwrap();
        let label = format!("{m}x{n}");
        let (u, v) = (0.3f64, 0.7f64);
        group.bench_function(BenchmarkId::new("f64_u_first", &label), |b| {
            b.iter(|| float.eval(black_box(&u), black_box(&v)))
        });
        group.bench_function(BenchmarkId::new("f64_v_first", &label), |b| {
            b.iter(|| float.eval_v_first(black_box(&u), black_box(&v)))
        });
        group.bench_function(BenchmarkId::new("f64_bernstein", &label), |b| {
            b.iter(|| float.eval_bernstein(black_box(&u), black_box(&v)))
        });
        let (uq, vq) = (
            BigRational::from_ratio(3, 10).unwrap(),
            BigRational::from_ratio(7, 10).unwrap(),
        );
        group.bench_function(BenchmarkId::new("exact_u_first", &label), |b| {
            b.iter(|| exact.eval(black_box(&uq), black_box(&vq)))
        });
        group.bench_function(BenchmarkId::new("exact_bernstein", &label), |b| {
            b.iter(|| exact.eval_bernstein(black_box(&uq), black_box(&vq)))
        });
    }
    group.finish();
}

criterion_group!(benches, bench_eval);
criterion_main!(benches);
