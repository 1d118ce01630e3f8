//! Bézier-curve benchmarks: the same generic code on `f64` and on exact `BigRational`
//! (eval, split, elevate, derivative at degrees 3, 10, 20), and our `f64` cubic against
//! kurbo's `CubicBez` in one group, so the ratios come from a single run.
//!
//! `cargo bench --bench curves` (add `-- --quick` for a fast look).

use casteljau::{BezierCurve, BigRational, Scalar};
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use kurbo::{CubicBez, ParamCurve};
use std::time::Duration;

/// A planar curve of degree `n` with small-denominator rational control points
/// (`p/7`, as typed by a person), and the same curve rounded to `f64`.
fn curves(n: usize) -> (BezierCurve<BigRational>, BezierCurve<f64>) {
    let coords: Vec<Vec<BigRational>> = (0..=n as i64)
        .map(|i| {
            vec![
                BigRational::from_ratio(3 * i, 7).unwrap(),
                BigRational::from_ratio((i * i) % 11 - 5, 7).unwrap(),
            ]
        })
        .collect();
    let exact = BezierCurve::from_coords(coords).unwrap();
    let float = exact.try_map(f64::from_rational).unwrap();
    (exact, float)
}

fn generic_ops(c: &mut Criterion) {
    let t_exact = BigRational::from_ratio(1, 3).unwrap();
    let t = 1.0 / 3.0;
    for (name, degree_list) in [
        ("eval", [3usize, 10, 20]),
        ("split", [3, 10, 20]),
        ("elevate", [3, 10, 20]),
        ("derivative", [3, 10, 20]),
    ] {
        let mut group = c.benchmark_group(name);
        group
            .sample_size(20)
            .measurement_time(Duration::from_secs(2))
            .warm_up_time(Duration::from_millis(500));
        for n in degree_list {
            let (exact, float) = curves(n);
            match name {
                "eval" => {
                    group.bench_with_input(BenchmarkId::new("f64", n), &float, |b, c| {
                        b.iter(|| c.eval(black_box(&t)))
                    });
                    group.bench_with_input(BenchmarkId::new("f64_eval_array", n), &float, |b, c| {
                        b.iter(|| c.eval_array::<2>(black_box(t)).unwrap())
                    });
                    group.bench_with_input(BenchmarkId::new("rational", n), &exact, |b, c| {
                        b.iter(|| c.eval(black_box(&t_exact)))
                    });
                    group.bench_with_input(BenchmarkId::new("rational_reference", n), &exact, |b, c| {
                        b.iter(|| c.eval_reference(black_box(&t_exact)))
                    });
                }
                "split" => {
                    group.bench_with_input(BenchmarkId::new("f64", n), &float, |b, c| {
                        b.iter(|| c.split_at(black_box(&t)))
                    });
                    group.bench_with_input(BenchmarkId::new("rational", n), &exact, |b, c| {
                        b.iter(|| c.split_at(black_box(&t_exact)))
                    });
                }
                "elevate" => {
                    group.bench_with_input(BenchmarkId::new("f64", n), &float, |b, c| {
                        b.iter(|| c.elevate().unwrap())
                    });
                    group.bench_with_input(BenchmarkId::new("rational", n), &exact, |b, c| {
                        b.iter(|| c.elevate().unwrap())
                    });
                }
                _ => {
                    group.bench_with_input(BenchmarkId::new("f64", n), &float, |b, c| {
                        b.iter(|| c.derivative(black_box(1)).unwrap())
                    });
                    group.bench_with_input(BenchmarkId::new("rational", n), &exact, |b, c| {
                        b.iter(|| c.derivative(black_box(1)).unwrap())
                    });
                }
            }
        }
        group.finish();
    }
}

/// Our f64 cubic against kurbo's, same control points, same parameter.
fn versus_kurbo(c: &mut Criterion) {
    let (_, ours) = curves(3);
    let p: Vec<(f64, f64)> = ours.points().iter().map(|p| (p.coords()[0], p.coords()[1])).collect();
    let theirs = CubicBez::new(p[0], p[1], p[2], p[3]);
    let t = 1.0 / 3.0;
    let mut group = c.benchmark_group("cubic_vs_kurbo");
    group
        .sample_size(20)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500));
    group.bench_function("eval/casteljau_f64", |b| b.iter(|| ours.eval(black_box(&t))));
    group.bench_function("eval/casteljau_eval_array", |b| {
        b.iter(|| ours.eval_array::<2>(black_box(t)).unwrap())
    });
    group.bench_function("eval/kurbo", |b| b.iter(|| theirs.eval(black_box(t))));
    group.bench_function("split_half/casteljau_f64", |b| {
        b.iter(|| ours.split_at(black_box(&0.5)))
    });
    group.bench_function("split_half/kurbo_subdivide", |b| {
        b.iter(|| black_box(&theirs).subdivide())
    });
    group.bench_function("split_at/kurbo_subsegment", |b| {
        b.iter(|| black_box(&theirs).subsegment(black_box(t)..1.0))
    });
    group.bench_function("split_at/casteljau_f64", |b| b.iter(|| ours.split_at(black_box(&t))));
    group.finish();
}

/// Many elevation steps at once by (8): dominated by the exact binomial rows.
fn elevate_many(c: &mut Criterion) {
    let (exact, float) = curves(3);
    let mut group = c.benchmark_group("elevate_by_1000");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500));
    group.bench_function("f64", |b| b.iter(|| float.elevate_by(black_box(1000)).unwrap()));
    group.bench_function("rational", |b| b.iter(|| exact.elevate_by(black_box(1000)).unwrap()));
    group.finish();
}

/// Exact evaluation, naive (a reduced fraction at every step) against the nested integer
/// sum that `eval` runs, at degrees where the difference shows.
fn exact_eval_naive_vs_nested(c: &mut Criterion) {
    let t = BigRational::from_ratio(2, 7).unwrap();
    let mut group = c.benchmark_group("curve_exact_eval");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(300));
    for n in [10usize, 50, 200] {
        let (exact, _) = curves(n);
        group.bench_with_input(BenchmarkId::new("naive", n), &exact, |b, c| {
            b.iter(|| c.eval_reference(black_box(&t)))
        });
        group.bench_with_input(BenchmarkId::new("nested", n), &exact, |b, c| {
            b.iter(|| c.eval(black_box(&t)))
        });
    }
    group.finish();
}

criterion_group!(
    benches,
    versus_kurbo,
    generic_ops,
    elevate_many,
    exact_eval_naive_vs_nested
);
criterion_main!(benches);
