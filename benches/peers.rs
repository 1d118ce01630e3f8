//! casteljau's generic `f64` code beside the float libraries people use, in one group per
//! operation so the ratios come from a single run: kurbo, lyon_geom and, at degree 20, a
//! hand-written de Casteljau on `[[f64; 2]; 21]`. All planar, at t = 0.3.
//!
//! `casteljau` is the fixed-degree type a user reaches for with a cubic or a quadratic in
//! hand ([`casteljau::Cubic`], [`casteljau::Quad`]); `casteljau_any_degree` is the same
//! operation on the any-degree [`casteljau::Bezier`], measured beside it.
//!
//! Every function gets its inputs the same way: the curve through `black_box(&curve)` and
//! the parameter as an opaque value, `black_box(T)` (casteljau then borrows it, as a caller
//! with a `t` in hand does), never through a pointer only one side has to follow.
//!
//! CPU time of the bench thread (`support/cpu_time.rs`): the figures come from a shared
//! machine. `cargo bench --bench peers`

use casteljau::{Bezier, Cubic, Point2, Quad};
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use kurbo::{CubicBez, ParamCurve as _, QuadBez};
use lyon_geom::{point, CubicBezierSegment, QuadraticBezierSegment};

#[path = "support/cpu_time.rs"]
mod cpu_time;
use cpu_time::{cpu_time_of, long_samples};

const T: f64 = 0.3;
const CUBIC: [[f64; 2]; 4] = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]];
const QUAD: [[f64; 2]; 3] = [[0.0, 0.0], [1.0, 2.0], [3.0, 0.5]];

fn cubic() -> Cubic<Point2<f64>> {
    Cubic::new(CUBIC.map(Point2::from))
}

fn kurbo_cubic() -> CubicBez {
    let [a, b, c, d] = CUBIC.map(|[x, y]| (x, y));
    CubicBez::new(a, b, c, d)
}

fn lyon_cubic() -> CubicBezierSegment<f64> {
    let [a, b, c, d] = CUBIC.map(|[x, y]| point(x, y));
    CubicBezierSegment {
        from: a,
        ctrl1: b,
        ctrl2: c,
        to: d,
    }
}

fn degree_20() -> [[f64; 2]; 21] {
    std::array::from_fn(|i| [3.0 * i as f64 / 7.0, ((i * i) % 11) as f64 / 7.0 - 5.0 / 7.0])
}

/// de Casteljau by hand on a fixed array, each coordinate written out and updated in place
/// (no point copied per step): the floor for the generic code.
fn array_casteljau(points: &[[f64; 2]; 21], t: f64) -> [f64; 2] {
    let mut b = *points;
    for len in (1..21).rev() {
        for i in 0..len {
            b[i][0] += t * (b[i + 1][0] - b[i][0]);
            b[i][1] += t * (b[i + 1][1] - b[i][1]);
        }
    }
    b[0]
}

/// de Casteljau by hand, the plainest way: each point read, the new one written whole,
/// `a + t (b − a)` per coordinate (the steps `Bezier::eval` takes).
fn plain_casteljau(points: &[[f64; 2]; 21], t: f64) -> [f64; 2] {
    let mut b = *points;
    for len in (1..21).rev() {
        for i in 0..len {
            let (p, q) = (b[i], b[i + 1]);
            b[i] = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
        }
    }
    b[0]
}

fn peers(c: &mut Criterion) {
    let (ours, theirs, lyon) = (cubic(), kurbo_cubic(), lyon_cubic());
    let any = Bezier::from(ours);
    let mut g = c.benchmark_group("cubic_eval");
    long_samples(&mut g);
    g.bench_function("casteljau", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&ours).eval(&black_box(T))))
    });
    g.bench_function("casteljau_any_degree", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&any).eval(&black_box(T))))
    });
    g.bench_function("kurbo", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&theirs).eval(black_box(T))))
    });
    g.bench_function("lyon", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&lyon).sample(black_box(T))))
    });
    g.finish();

    // kurbo has no split at a parameter: its two subsegments are the same curves.
    let mut g = c.benchmark_group("cubic_split");
    long_samples(&mut g);
    g.bench_function("casteljau", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&ours).split_at(&black_box(T))))
    });
    g.bench_function("casteljau_any_degree", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&any).split_at(&black_box(T))))
    });
    g.bench_function("kurbo", |b| {
        b.iter_custom(|iters| {
            cpu_time_of(iters, || {
                let (c, t) = (black_box(&theirs), black_box(T));
                (c.subsegment(0.0..t), c.subsegment(t..1.0))
            })
        })
    });
    g.bench_function("lyon", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&lyon).split(black_box(T))))
    });
    g.finish();

    let quad = Quad::new(QUAD.map(Point2::from));
    let any = Bezier::from(quad);
    let [a, b, c2] = QUAD.map(|[x, y]| (x, y));
    let kquad = QuadBez::new(a, b, c2);
    let [a, b, c2] = QUAD.map(|[x, y]| point(x, y));
    let lquad = QuadraticBezierSegment {
        from: a,
        ctrl: b,
        to: c2,
    };
    let mut g = c.benchmark_group("quad_elevate");
    long_samples(&mut g);
    g.bench_function("casteljau", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&quad).elevate()))
    });
    g.bench_function("casteljau_any_degree", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&any).elevate().unwrap()))
    });
    g.bench_function("kurbo", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&kquad).raise()))
    });
    g.bench_function("lyon", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&lquad).to_cubic()))
    });
    g.finish();

    // a cubic's quartic: more points than the any-degree curve keeps inline
    let mut g = c.benchmark_group("cubic_elevate");
    long_samples(&mut g);
    let ours = cubic();
    let any = Bezier::from(ours);
    g.bench_function("casteljau", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&ours).elevate()))
    });
    g.bench_function("casteljau_any_degree", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&any).elevate().unwrap()))
    });
    g.finish();

    // One cubic at 1,000 parameters in [0, 1]: casteljau's `eval_many` against a loop of
    // per-point `eval` calls, kurbo's and casteljau's.
    let ts: Vec<f64> = (0..1000).map(|i| (i as f64 + 0.5) / 1000.0).collect();
    let ours = cubic();
    let mut out = vec![Point2::new(0.0, 0.0); ts.len()];
    let mut kout = vec![kurbo::Point::ZERO; ts.len()];
    let mut g = c.benchmark_group("cubic_eval_1000");
    long_samples(&mut g);
    g.bench_function("casteljau_eval_many", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&ours).eval_many(black_box(&ts), &mut out)))
    });
    g.bench_function("casteljau_per_point", |b| {
        b.iter_custom(|iters| {
            cpu_time_of(iters, || {
                let c = black_box(&ours);
                for (t, o) in black_box(&ts).iter().zip(out.iter_mut()) {
                    *o = c.eval(t);
                }
            })
        })
    });
    g.bench_function("kurbo_per_point", |b| {
        b.iter_custom(|iters| {
            cpu_time_of(iters, || {
                let c = black_box(&theirs);
                for (t, o) in black_box(&ts).iter().zip(kout.iter_mut()) {
                    *o = c.eval(*t);
                }
            })
        })
    });
    g.finish();

    let array = degree_20();
    let ours = Bezier::from_points(array.map(Point2::from)).unwrap();
    let lyon_points = array.map(|[x, y]| point(x, y));
    let mut g = c.benchmark_group("deg20_eval");
    long_samples(&mut g);
    g.bench_function("casteljau", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || black_box(&ours).eval(&black_box(T))))
    });
    g.bench_function("array", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || array_casteljau(black_box(&array), black_box(T))))
    });
    g.bench_function("plain", |b| {
        b.iter_custom(|iters| cpu_time_of(iters, || plain_casteljau(black_box(&array), black_box(T))))
    });
    // Neither kurbo nor lyon_geom has curves above degree 3: lyon's point lerp in the same
    // de Casteljau loop stands in for them.
    g.bench_function("lyon", |b| {
        b.iter_custom(|iters| {
            cpu_time_of(iters, || {
                let mut p = *black_box(&lyon_points);
                let t = black_box(T);
                for len in (1..21).rev() {
                    for i in 0..len {
                        p[i] = p[i].lerp(p[i + 1], t);
                    }
                }
                p[0]
            })
        })
    });
    g.finish();
}

criterion_group!(benches, peers);
criterion_main!(benches);
