//! Float evaluators side by side: plain de Casteljau, with its running bound, compensated
//! (FMA chosen at run time, and with Dekker's product forced),
//! the generic algorithm on `f64`, the public `BezierCurve<Interval>::eval` (`interval`: at a
//! point of `[0, 1]` it takes the kernel of `interval_de_casteljau`), that kernel, and kurbo's
//! cubic, one coordinate of a curve of degree 3, 10, 20 at t = 0.3. `plain` is the floor they
//! are measured against: the obvious hand loop of de Casteljau (convex form) on a stack array.
//!
//! CPU time of the bench thread (`support/cpu_time.rs`): the figures come from a shared
//! machine. `cargo bench --bench float`.

use casteljau::float::{compensated_de_casteljau, compensated_de_casteljau_by, de_casteljau, de_casteljau_running};
use casteljau::{interval_de_casteljau, tight_interval_de_casteljau, Interval};
use casteljau::{BezierCurve, Scalar};
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use kurbo::{CubicBez, ParamCurve};

#[path = "support/cpu_time.rs"]
mod cpu_time;
use cpu_time::{cpu_time_of, long_samples};

fn coefficients(n: usize) -> Vec<f64> {
    (0..=n).map(|i| ((i * 7919) % 13) as f64 / 6.5 - 1.0).collect()
}

/// de Casteljau by hand, `b_i ← (1 − t) b_i + t b_{i+1}` in place on a copy on the stack.
fn plain<const N: usize>(points: &[f64; N], t: f64) -> f64 {
    let mut b = *points;
    let s = 1.0 - t;
    for len in (1..N).rev() {
        for i in 0..len {
            b[i] = s * b[i] + t * b[i + 1];
        }
    }
    b[0]
}

fn bench_plain<const N: usize>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    b: &[f64],
    t: f64,
) {
    let array: [f64; N] = b.try_into().expect("N coefficients");
    group.bench_function(BenchmarkId::new("plain", N - 1), |bch| {
        bch.iter_custom(|iters| cpu_time_of(iters, || plain(black_box(&array), black_box(t))))
    });
}

fn evaluators(c: &mut Criterion) {
    let t = 0.3;
    let mut group = c.benchmark_group("float_eval");
    long_samples(&mut group);
    for n in [3usize, 10, 20] {
        let b = coefficients(n);
        let generic: BezierCurve<f64> = BezierCurve::from_coords(b.iter().map(|x| vec![*x]).collect()).unwrap();
        let interval: BezierCurve<Interval> =
            BezierCurve::from_coords(b.iter().map(|x| vec![Interval::from_f64(*x).unwrap()]).collect()).unwrap();
        let ti = Interval::from_f64(t).unwrap();
        match n {
            3 => bench_plain::<4>(&mut group, &b, t),
            10 => bench_plain::<11>(&mut group, &b, t),
            _ => bench_plain::<21>(&mut group, &b, t),
        }
        group.bench_with_input(BenchmarkId::new("de_casteljau", n), &b, |bch, b| {
            bch.iter_custom(|iters| cpu_time_of(iters, || de_casteljau(black_box(b), black_box(t))))
        });
        group.bench_with_input(BenchmarkId::new("running_bound", n), &b, |bch, b| {
            bch.iter_custom(|iters| cpu_time_of(iters, || de_casteljau_running(black_box(b), black_box(t))))
        });
        group.bench_with_input(BenchmarkId::new("compensated", n), &b, |bch, b| {
            bch.iter_custom(|iters| cpu_time_of(iters, || compensated_de_casteljau(black_box(b), black_box(t))))
        });
        // the same triangle with Dekker's product forced: what the default target ran before
        // FMA was chosen at run time
        group.bench_with_input(BenchmarkId::new("compensated_dekker", n), &b, |bch, b| {
            bch.iter_custom(|iters| {
                cpu_time_of(iters, || compensated_de_casteljau_by(black_box(b), black_box(t), false))
            })
        });
        group.bench_with_input(BenchmarkId::new("generic_f64", n), &generic, |bch, c| {
            bch.iter_custom(|iters| cpu_time_of(iters, || c.eval(black_box(&t))))
        });
        group.bench_with_input(BenchmarkId::new("interval", n), &interval, |bch, c| {
            bch.iter_custom(|iters| cpu_time_of(iters, || c.eval(black_box(&ti))))
        });
        group.bench_with_input(BenchmarkId::new("interval_de_casteljau", n), &b, |bch, b| {
            bch.iter_custom(|iters| cpu_time_of(iters, || interval_de_casteljau(black_box(b), black_box(t))))
        });
        group.bench_with_input(BenchmarkId::new("tight_interval_de_casteljau", n), &b, |bch, b| {
            bch.iter_custom(|iters| cpu_time_of(iters, || tight_interval_de_casteljau(black_box(b), black_box(t))))
        });
        if n == 3 {
            let p = |x: f64| kurbo::Point::new(x, 0.0);
            let k = CubicBez::new(p(b[0]), p(b[1]), p(b[2]), p(b[3]));
            group.bench_function(BenchmarkId::new("kurbo", n), |bch| {
                bch.iter_custom(|iters| cpu_time_of(iters, || black_box(k).eval(black_box(t))))
            });
        }
    }
    group.finish();
}

criterion_group!(benches, evaluators);
criterion_main!(benches);
