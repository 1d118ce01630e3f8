//! Exact arithmetic at integer speed: evaluation of a planar curve with small integer control
//! points at t = 1/3, naive (generic de Casteljau on `BigRational`, a gcd per step) against
//! the fraction-free de Casteljau of `eval_fraction_free`, the nested integer sum of
//! `eval_nested`, and generic de Casteljau on `SmallRational`; and the proof engine's hot
//! spot, Bernstein values at sample points, rebuilt per use against cached tables.
//!
//! `cargo bench --bench exact` (add `-- --quick` for a fast look).

use casteljau::exact::{BernsteinTable, SmallRational};
use casteljau::{BezierCurve, BigRational, Scalar};
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;

/// A planar curve of degree `n` with small integer control points.
fn curve(n: usize) -> BezierCurve<BigRational> {
    let points: Vec<Vec<i64>> = (0..=n as i64).map(|i| vec![3 * i, (i * i) % 11 - 5]).collect();
    let refs: Vec<&[i64]> = points.iter().map(Vec::as_slice).collect();
    BezierCurve::from_ints(&refs).expect("valid curve")
}

fn exact_eval(c: &mut Criterion) {
    let t = BigRational::from_ratio(1, 3).expect("nonzero");
    let t_small = SmallRational::from(&t);
    let mut group = c.benchmark_group("exact_eval");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(300));
    for n in [3usize, 10, 20, 50, 200] {
        let exact = curve(n);
        let small = exact.try_map(SmallRational::from_rational).expect("exact");
        // The naive path at degree 200 takes about half a second per call: skip it there.
        if n <= 50 {
            group.bench_with_input(BenchmarkId::new("naive", n), &exact, |b, c| {
                b.iter(|| c.eval(black_box(&t)))
            });
        }
        group.bench_with_input(BenchmarkId::new("fraction_free", n), &exact, |b, c| {
            b.iter(|| c.eval_fraction_free(black_box(&t)))
        });
        group.bench_with_input(BenchmarkId::new("nested", n), &exact, |b, c| {
            b.iter(|| c.eval_nested(black_box(&t)))
        });
        group.bench_with_input(BenchmarkId::new("small_rational", n), &small, |b, c| {
            b.iter(|| c.eval(black_box(&t_small)))
        });
    }
    group.finish();
}

/// One claim of degree `n` checked at `n + 1` points needs `B_j^n` at each: rebuilt as
/// `BigRational`s at `k/n` for every use, or computed once by a table (at the integers `k`,
/// or at `k/n`, also as `SmallRational`s, what the engine reads) and handed out.
fn prove_hot(c: &mut Criterion) {
    let mut group = c.benchmark_group("prove_hot");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(300));
    for n in [3usize, 10, 20] {
        let d = n as i64;
        let points: Vec<BigRational> = (0..=d).map(|k| BigRational::from_ratio(k, d).expect("d ≥ 1")).collect();
        group.bench_with_input(BenchmarkId::new("rebuilt_rational", n), &n, |b, &n| {
            b.iter(|| {
                for t in &points {
                    for j in 0..=n {
                        black_box(casteljau::bernstein::bernstein(j, n, t).expect("exact"));
                    }
                }
            })
        });
        let table = BernsteinTable::new();
        group.bench_with_input(BenchmarkId::new("cached_rational", n), &n, |b, &n| {
            b.iter(|| {
                for t in &points {
                    let row = table.at_rational(n, t).expect("degree within limit");
                    for j in 0..=n {
                        black_box(row.value(j));
                    }
                }
            })
        });
        // The engine evaluates in SmallRational: the same rows, as machine words.
        let small_points: Vec<SmallRational> = points.iter().map(SmallRational::from).collect();
        group.bench_with_input(BenchmarkId::new("cached_small", n), &n, |b, &n| {
            b.iter(|| {
                for t in &small_points {
                    let row = table.at_small(n, t).expect("degree within limit");
                    for j in 0..=n {
                        black_box(&row[j]);
                    }
                }
            })
        });
        group.bench_with_input(BenchmarkId::new("cached_integer", n), &n, |b, &n| {
            b.iter(|| {
                for k in 0..=d {
                    let row = table.at_integer(n, k).expect("degree within limit");
                    for j in 0..=n {
                        black_box(&row[j]);
                    }
                }
            })
        });
        group.bench_with_input(BenchmarkId::new("fresh_table_integer", n), &n, |b, &n| {
            b.iter(|| {
                let table = BernsteinTable::new();
                for k in 0..=d {
                    black_box(table.at_integer(n, k).expect("degree within limit"));
                }
            })
        });
    }
    group.finish();
}

criterion_group!(benches, exact_eval, prove_hot);
criterion_main!(benches);
