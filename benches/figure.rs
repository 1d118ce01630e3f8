//! `casteljau figure` on a degree-20 curve (and a degree-20 net) of small integers, planar
//! and in space: every kind from the command's request to its SVG text, and in the same group the peer it
//! replaced, 200 exact samples of the curve (what drawing the curve cost when every sample
//! was an exact de Casteljau scheme), so the ratio comes from one run.
//!
//! `cargo bench --bench figure -- --warm-up-time 1 --measurement-time 2`

use casteljau::figure::{FigureKind, FigureRequest};
use casteljau::{BezierCurve, BigRational};
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;

/// Small integer coordinates (−11..=11), deterministic and unstructured.
fn digit(k: usize) -> i64 {
    ((k * k * k + 7 * k + 3) % 23) as i64 - 11
}

fn points(n: usize, dim: usize, offset: usize) -> String {
    (0..=n)
        .map(|i| {
            (0..dim)
                .map(|j| digit(offset + i * dim + j).to_string())
                .collect::<Vec<_>>()
                .join(",")
        })
        .collect::<Vec<_>>()
        .join("; ")
}

fn request(kind: FigureKind, n: usize) -> FigureRequest {
    let mut r = FigureRequest::new(kind);
    match kind {
        FigureKind::Bernstein => {
            r.degree = Some(n.to_string());
            return r;
        }
        FigureKind::Projection => {
            r.input = Some("3,-2,1; 1,0,3; 3,2,1".into());
            return r;
        }
        _ => {}
    }
    r.input = Some(match kind {
        FigureKind::Net | FigureKind::Enneper => (0..=n).map(|i| points(n, 3, i * 97)).collect::<Vec<_>>().join(" | "),
        FigureKind::Conics => "-1,1; 0,-1; 1,1".into(),
        FigureKind::Fit => points(n, 3, 0),
        _ => points(n, 2, 0),
    });
    r
}

fn degree_20(c: &mut Criterion) {
    let mut group = c.benchmark_group("figure_degree20");
    group.sample_size(20).measurement_time(Duration::from_secs(2));
    for kind in FigureKind::ALL {
        let r = request(kind, 20);
        group.bench_function(BenchmarkId::new("figure", kind.name()), |b| {
            b.iter(|| black_box(r.figure().and_then(|f| f.to_svg()).unwrap()))
        });
    }
    // the kinds that also draw space curves, in space
    for kind in [
        FigureKind::Construction,
        FigureKind::Elevation,
        FigureKind::Hodograph,
        FigureKind::Hull,
    ] {
        let mut r = FigureRequest::new(kind);
        r.input = Some(points(20, 3, 0));
        group.bench_function(BenchmarkId::new("figure_3d", kind.name()), |b| {
            b.iter(|| black_box(r.figure().and_then(|f| f.to_svg()).unwrap()))
        });
    }
    let mut r = FigureRequest::new(FigureKind::Hull);
    r.input = Some(points(20, 3, 0));
    r.point = Some("100,100,100".into());
    group.bench_function(BenchmarkId::new("figure_3d", "hull_outside"), |b| {
        b.iter(|| black_box(r.figure().and_then(|f| f.to_svg()).unwrap()))
    });
    let curve: BezierCurve<BigRational> =
        BezierCurve::new(casteljau::parse_points(&points(20, 2, 0)).unwrap()).unwrap();
    let params: Vec<BigRational> = (0..=200).map(|k| BigRational::new(k.into(), 200.into())).collect();
    group.bench_function(BenchmarkId::new("peer", "exact_samples_200"), |b| {
        b.iter(|| black_box(params.iter().map(|t| curve.eval(t)).collect::<Vec<_>>()))
    });
    group.finish();
}

criterion_group!(benches, degree_20);
criterion_main!(benches);
