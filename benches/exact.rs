//! Exact arithmetic at integer speed: evaluation of a planar curve with small integer control
//! points at t = 1/3, naive (generic de Casteljau on `BigRational`, a gcd per step) against
//! the nested integer sum of `eval_nested`, and generic de Casteljau on `SmallRational`; and the proof engine's hot
//! spot, Bernstein values at sample points, rebuilt per use against cached tables.
//!
//! The group `exact_big` is the case no shortcut flatters: planar curves of degree 20, 200
//! and 1000 with random 30-digit rational coordinates, each over its own denominator, and a
//! random 20-digit parameter; `eval`, `split_at` and `elevate` as users call them, and up
//! to degree 200 `derivative`, `derivative_at`, `to_power`, `from_power`, the rational
//! curve's `eval`, `derivative_at` and (degree 20) `split_at`, and the surface's `eval`,
//! `to_power`, `derivative_u` and `split_u` on the same kind of numbers. It
//! measures CPU time (of this thread), not wall time, so that the ratios to the Python
//! peers of `scripts/exact_big.py`, which draws the same numbers, hold on a shared machine.
//!
//! The group `exact_gcd` compares the big-integer gcd of the final reductions with
//! num-bigint's.
//!
//! `cargo bench --bench exact` (add `-- --quick` for a fast look).

use casteljau::exact::{BernsteinTable, SmallRational};
use casteljau::{BezierCurve, BezierSurface, BigInt, BigRational, Point, RationalBezierCurve, Scalar};
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use num_traits::Signed;
use std::time::Duration;

// `long_samples` is for the groups measured in long flat samples; this group keeps its own.
#[allow(dead_code)]
#[path = "support/cpu_time.rs"]
mod cpu_time;
use cpu_time::cpu_time_of;

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
    short_samples(&mut group);
    for n in [3usize, 10, 20, 50, 200] {
        let exact = curve(n);
        let small = exact.try_map(SmallRational::from_rational).expect("exact");
        // The naive path at degree 200 takes about half a second per call: skip it there.
        if n <= 50 {
            group.bench_with_input(BenchmarkId::new("naive", n), &exact, |b, c| {
                b.iter(|| c.eval_reference(black_box(&t)))
            });
        }
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
    short_samples(&mut group);
    for n in [3usize, 10, 20] {
        let d = n as i64;
        let points: Vec<BigRational> = (0..=d).map(|k| BigRational::from_ratio(k, d).expect("d ≥ 1")).collect();
        group.bench_with_input(BenchmarkId::new("rebuilt_rational", n), &n, |b, &n| {
            b.iter(|| {
                for t in &points {
                    for j in 0..=n {
                        black_box(casteljau::bernstein(j, n, t).expect("exact"));
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

/// splitmix64, the generator `scripts/exact_big.py` repeats to draw the same numbers.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number of exactly `k ≤ 38` decimal digits.
    fn digits(&mut self, k: u32) -> u128 {
        let low = 10u128.pow(k - 1);
        let wide = (u128::from(self.next()) << 64) | u128::from(self.next());
        low + wide % (9 * low)
    }
}

/// A 30-digit numerator (random sign) over a 30-digit denominator.
fn thirty_digit_fraction(rng: &mut SplitMix) -> BigRational {
    let magnitude = BigInt::from(rng.digits(30));
    let numerator = if rng.next() & 1 == 1 { -magnitude } else { magnitude };
    BigRational::new(numerator, BigInt::from(rng.digits(30)))
}

/// A 20-digit `p/q` in (0, 1).
fn twenty_digit_parameter(rng: &mut SplitMix) -> BigRational {
    let (mut p, mut q) = (rng.digits(20), rng.digits(20));
    if p > q {
        std::mem::swap(&mut p, &mut q);
    }
    if p == q {
        q += 1;
    }
    BigRational::new(p.into(), q.into())
}

/// The `exact_big` case of degree `n`: a planar curve whose coordinates are 30-digit
/// numerators (random signs) over 30-digit denominators, and a 20-digit `t = p/q` in (0, 1).
fn big_case(n: usize) -> (BezierCurve<BigRational>, BigRational) {
    let mut rng = SplitMix(1000 + n as u64);
    let coords: Vec<Vec<BigRational>> = (0..=n)
        .map(|_| vec![thirty_digit_fraction(&mut rng), thirty_digit_fraction(&mut rng)])
        .collect();
    let t = twenty_digit_parameter(&mut rng);
    (BezierCurve::from_coords(coords).expect("valid curve"), t)
}

/// The rational curve of degree `n`: the points of [`big_case`] and positive 30-digit
/// weights over 30-digit denominators, drawn from their own stream.
fn big_rational_case(n: usize) -> (RationalBezierCurve<BigRational>, BigRational) {
    let (curve, t) = big_case(n);
    let mut rng = SplitMix(2000 + n as u64);
    let weights = (0..=n).map(|_| Signed::abs(&thirty_digit_fraction(&mut rng))).collect();
    let curve = RationalBezierCurve::new(curve.into_points(), weights).expect("nonzero weights");
    (curve, t)
}

/// The surface of degrees `(m, m)`: a net of planar 30-digit fractions, and 20-digit `u`, `v`.
fn big_surface_case(m: usize) -> (BezierSurface<BigRational>, BigRational, BigRational) {
    let mut rng = SplitMix(3000 + m as u64);
    let net: Vec<Vec<Point<BigRational>>> = (0..=m)
        .map(|_| {
            (0..=m)
                .map(|_| {
                    Point::new(vec![thirty_digit_fraction(&mut rng), thirty_digit_fraction(&mut rng)]).expect("2D")
                })
                .collect()
        })
        .collect();
    let (u, v) = (twenty_digit_parameter(&mut rng), twenty_digit_parameter(&mut rng));
    (BezierSurface::new(net).expect("valid net"), u, v)
}

fn exact_big(c: &mut Criterion) {
    let mut group = c.benchmark_group("exact_big");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(3))
        .warm_up_time(Duration::from_millis(500));
    for n in [20usize, 200, 1000] {
        let (curve, t) = big_case(n);
        group.bench_with_input(BenchmarkId::new("eval", n), &curve, |b, c| {
            b.iter_custom(|iters| cpu_time_of(iters, || c.eval(black_box(&t))))
        });
        // A split reduces 2(n+1) points of up to n·67 + n·100 bits each: at degree 1000, a
        // minute per call, too long for a bench run (the script's Python peers skip it too).
        if n <= 200 {
            group.bench_with_input(BenchmarkId::new("split_at", n), &curve, |b, c| {
                b.iter_custom(|iters| cpu_time_of(iters, || c.split_at(black_box(&t))))
            });
        }
        group.bench_with_input(BenchmarkId::new("elevate", n), &curve, |b, c| {
            b.iter_custom(|iters| cpu_time_of(iters, || c.elevate().expect("degree within limit")))
        });
        // What any elevation that returns `BigRational`s must do at least: allocate the
        // result's points and integers and write their digits. Here they are cloned from the
        // result itself, with no arithmetic at all.
        let elevated = curve.elevate().expect("degree within limit");
        group.bench_with_input(BenchmarkId::new("elevate_output_floor", n), &elevated, |b, e| {
            b.iter_custom(|iters| cpu_time_of(iters, || e.points().to_vec()))
        });
        if n > 200 {
            continue;
        }
        // The other public exact operations on the same inputs (scripts/exact_big.py has a
        // gmpy2 counterpart for each).
        group.bench_with_input(BenchmarkId::new("derivative", n), &curve, |b, c| {
            b.iter_custom(|iters| cpu_time_of(iters, || c.derivative(1).expect("n ≥ 1")))
        });
        group.bench_with_input(BenchmarkId::new("derivative_at", n), &curve, |b, c| {
            b.iter_custom(|iters| cpu_time_of(iters, || c.derivative_at(1, black_box(&t)).expect("n ≥ 1")))
        });
        group.bench_with_input(BenchmarkId::new("to_power", n), &curve, |b, c| {
            b.iter_custom(|iters| cpu_time_of(iters, || c.to_power().expect("exact")))
        });
        // The case's points read as power-basis coefficients.
        group.bench_with_input(BenchmarkId::new("from_power", n), curve.points(), |b, coeffs| {
            b.iter_custom(|iters| cpu_time_of(iters, || BezierCurve::from_power(black_box(coeffs)).expect("exact")))
        });
        let (rational, t) = big_rational_case(n);
        group.bench_with_input(BenchmarkId::new("rational_eval", n), &rational, |b, c| {
            b.iter_custom(|iters| cpu_time_of(iters, || c.eval(black_box(&t)).expect("positive weights")))
        });
        group.bench_with_input(BenchmarkId::new("rational_derivative_at", n), &rational, |b, c| {
            b.iter_custom(|iters| cpu_time_of(iters, || c.derivative_at(black_box(&t)).expect("positive weights")))
        });
        // As for `split_at` above, the peer's de Casteljau steps take seconds past degree 20.
        if n <= 20 {
            group.bench_with_input(BenchmarkId::new("rational_split_at", n), &rational, |b, c| {
                b.iter_custom(|iters| cpu_time_of(iters, || c.split_at(black_box(&t)).expect("positive weights")))
            });
        }
    }
    for m in [10usize, 20] {
        let (surface, u, v) = big_surface_case(m);
        group.bench_with_input(BenchmarkId::new("surface_eval", m), &surface, |b, s| {
            b.iter_custom(|iters| cpu_time_of(iters, || s.eval(black_box(&u), black_box(&v))))
        });
        group.bench_with_input(BenchmarkId::new("surface_to_power", m), &surface, |b, s| {
            b.iter_custom(|iters| cpu_time_of(iters, || s.to_power().expect("exact")))
        });
        group.bench_with_input(BenchmarkId::new("surface_derivative_u", m), &surface, |b, s| {
            b.iter_custom(|iters| cpu_time_of(iters, || s.derivative_u(1).expect("m ≥ 1")))
        });
        group.bench_with_input(BenchmarkId::new("surface_split_u", m), &surface, |b, s| {
            b.iter_custom(|iters| cpu_time_of(iters, || s.split_u(black_box(&u))))
        });
    }
    group.finish();
}

/// The gcd of two big integers that share a factor of half their length (as a numerator and
/// a denominator do before the final reduction): casteljau's (dashu-int's) against
/// num-bigint's, from 3 to 4,100 words.
fn exact_gcd(c: &mut Criterion) {
    use num_bigint::BigUint;
    use num_integer::Integer;
    let mut group = c.benchmark_group("exact_gcd");
    short_samples(&mut group);
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut digits = |n: usize| -> BigUint {
        let words: Vec<u32> = (0..n)
            .map(|_| {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                state as u32
            })
            .collect();
        BigUint::new(words)
    };
    for words in [4usize, 64, 1024, 8192] {
        let common = digits(words / 2 + 2);
        let (x, y) = (&common * digits(words / 2), &common * digits(words / 2));
        assert_eq!(casteljau::exact::gcd::gcd(&x, &y), x.gcd(&y));
        let bits = x.bits();
        group.bench_function(BenchmarkId::new("casteljau", bits), |b| {
            b.iter_custom(|iters| cpu_time_of(iters, || casteljau::exact::gcd::gcd(black_box(&x), black_box(&y))))
        });
        group.bench_function(BenchmarkId::new("num_bigint", bits), |b| {
            b.iter_custom(|iters| cpu_time_of(iters, || black_box(&x).gcd(black_box(&y))))
        });
    }
    group.finish();
}

/// The sampling of three groups: 10 samples over 2 s after 300 ms of warm-up.
fn short_samples<M: criterion::measurement::Measurement>(group: &mut criterion::BenchmarkGroup<'_, M>) {
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(300));
}

criterion_group!(benches, exact_eval, prove_hot, exact_big, exact_gcd);
criterion_main!(benches);
