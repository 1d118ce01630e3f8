//! Oracle throughput: cubic `eval` requests with float inputs and `approx` (the issue's
//! target is ≥ 100,000 per second in one process), through `handle_line` and through the
//! whole `serve` loop on a piped batch.
//!
//! `cargo bench --bench oracle`.

use casteljau::oracle::{handle_line, serve};
use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use std::time::Duration;

/// `count` cubic eval requests with random float points and the float result as `approx`.
fn requests(count: usize) -> Vec<String> {
    let mut state = 0x2545_F491_4F6C_DD1Du64;
    let mut unit = move || {
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        (state.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..count)
        .map(|id| {
            let pts: Vec<[f64; 2]> = (0..4).map(|_| [2.0 * unit() - 1.0, 2.0 * unit() - 1.0]).collect();
            let t = unit();
            let mut b = pts.clone();
            for r in 1..4 {
                for i in 0..4 - r {
                    let next = b[i + 1];
                    for (x, y) in b[i].iter_mut().zip(next) {
                        *x = (1.0 - t) * *x + t * y;
                    }
                }
            }
            format!(
                r#"{{"id":{id},"op":"eval","points":{},"t":{t:?},"approx":[{:?},{:?}]}}"#,
                serde_json::to_string(&pts).unwrap(),
                b[0][0],
                b[0][1]
            )
        })
        .collect()
}

fn throughput(c: &mut Criterion) {
    let lines = requests(1000);
    let mut group = c.benchmark_group("oracle_throughput");
    group.sample_size(20).measurement_time(Duration::from_secs(3));
    group.throughput(Throughput::Elements(lines.len() as u64));
    group.bench_function("handle_line/cubic_eval_approx", |b| {
        b.iter(|| {
            for l in &lines {
                black_box(handle_line(black_box(l)));
            }
        })
    });
    let piped = lines.join("\n") + "\n";
    group.bench_function("serve/cubic_eval_approx", |b| {
        b.iter(|| {
            let mut out = Vec::with_capacity(piped.len() * 2);
            serve(piped.as_bytes(), &mut out).unwrap();
            black_box(out)
        })
    });
    group.finish();
}

criterion_group!(benches, throughput);
criterion_main!(benches);
