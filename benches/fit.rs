//! Benchmarks of the fits: text 004's cubic fit and the least-squares fit, in f64 and exact.

use casteljau::{fit_cubic, fit_cubic_closed_form, fit_least_squares, CubicFitData, FitConstraints};
use casteljau::{BigRational, Point, Scalar};
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use std::time::Duration;

type Q = BigRational;

fn cubic_data<T: Scalar>() -> CubicFitData<T>
where
    for<'a> &'a T: casteljau::RefOps<T>,
{
    // x(t) = (t, 1 + t², t⁴): the worked example of tests/fit.rs.
    let coeffs: Vec<Point<T>> = [[0, 1, 0], [1, 0, 0], [0, 1, 0], [0, 0, 0], [0, 0, 1]]
        .iter()
        .map(|c| Point::from_ints(c).unwrap())
        .collect();
    CubicFitData::from_power(&coeffs).unwrap()
}

/// 40 samples of a space curve with rational coordinates, at parameters j/39.
fn samples<T: Scalar>() -> (Vec<Point<T>>, Vec<T>)
where
    for<'a> &'a T: casteljau::RefOps<T>,
{
    let m = 40;
    let t: Vec<T> = (0..m).map(|j| T::from_ratio(j, m - 1).unwrap()).collect();
    let y = t
        .iter()
        .enumerate()
        .map(|(j, t)| {
            let wobble = T::from_ratio((j as i64 * 7) % 5 - 2, 100).unwrap();
            let x = t.clone();
            let y = &(t * t) + &wobble;
            let z = &(&(t * t) * t) - &wobble;
            Point::new(vec![x, y, z]).unwrap()
        })
        .collect();
    (y, t)
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("fit");
    g.sample_size(20)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500));

    let (df, dq) = (cubic_data::<f64>(), cubic_data::<Q>());
    g.bench_function("cubic (11) f64", |b| b.iter(|| fit_cubic(black_box(&df)).unwrap()));
    g.bench_function("cubic (11) exact", |b| b.iter(|| fit_cubic(black_box(&dq)).unwrap()));
    g.bench_function("cubic closed form (13) f64", |b| {
        b.iter(|| fit_cubic_closed_form(black_box(&df)).unwrap())
    });
    g.bench_function("cubic closed form (13) exact", |b| {
        b.iter(|| fit_cubic_closed_form(black_box(&dq)).unwrap())
    });

    let (yf, tf) = samples::<f64>();
    let (yq, tq) = samples::<Q>();
    let free = FitConstraints::none();
    g.bench_function("least squares deg 5, 40 pts, 3D f64", |b| {
        b.iter(|| fit_least_squares(black_box(&yf), &tf, 5, &free).unwrap())
    });
    g.bench_function("least squares deg 5, 40 pts, 3D exact", |b| {
        b.iter(|| fit_least_squares(black_box(&yq), &tq, 5, &FitConstraints::none()).unwrap())
    });
    let last = yf.len() - 1;
    let cons_f = FitConstraints::endpoints_and_directions(
        yf[0].clone(),
        yf[last].clone(),
        Point::new(vec![1.0, 0.0, 0.0]).unwrap(),
        Point::new(vec![1.0, 2.0, 3.0]).unwrap(),
    );
    let cons_q = FitConstraints::endpoints_and_directions(
        yq[0].clone(),
        yq[last].clone(),
        Point::from_ints(&[1, 0, 0]).unwrap(),
        Point::from_ints(&[1, 2, 3]).unwrap(),
    );
    g.bench_function("least squares deg 5 + ends + directions f64", |b| {
        b.iter(|| fit_least_squares(black_box(&yf), &tf, 5, &cons_f).unwrap())
    });
    g.bench_function("least squares deg 5 + ends + directions exact", |b| {
        b.iter(|| fit_least_squares(black_box(&yq), &tq, 5, &cons_q).unwrap())
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
