//! The work limits against the clock: for every oracle op and every `figure` kind, with each
//! kind of number (small integers, floats, short decimals, 30-digit fractions with distinct
//! denominators, and mixtures the calibration did not see: 40-digit integers, integers at a
//! 30-digit or a float parameter, floats at 1/3), the largest request the work estimate
//! admits is found by bisection on its size (estimates only, no work), then it and the
//! request of half its size are run, the answer written as JSON included: each must finish
//! within [`BUDGET_SECONDS`] of CPU time.
//! The largest admitted request is where an estimate that is too lax shows first.
//! Requests known to be cheap must be admitted (an estimate that is too strict fails too).
//!
//! Timings mean something only in an optimised build: under a debug build the test checks
//! the estimates' monotonicity and the cheap requests but not the clock.
//! `CALIBRATION_REPORT=1` prints every measurement (estimate, seconds, units per second).

use casteljau::figure::{FigureKind, FigureRequest};
use casteljau::oracle::{FloatMethod, Op, MAX_REQUEST_WORK};
use casteljau::CubicFitData;
use casteljau::{BezierCurve, BezierSurface, BigInt, BigRational, Point, RationalBezierCurve};

#[path = "support/cpu.rs"]
mod cpu;

/// CPU seconds any admitted request may take here, on a busy shared 2-core machine. The
/// limits aim at about a third of a second (the calibration in `src/oracle/cost.rs`): the
/// margin is for a loaded CI machine, whose shared caches slow a thread's CPU time too.
const BUDGET_SECONDS: f64 = 2.0;

/// CPU time of this thread: the clock the budget is stated in (another process on the
/// machine does not count against a request).
fn cpu_seconds() -> f64 {
    cpu::thread_cpu().as_secs_f64()
}

fn timed<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let start = cpu_seconds();
    let out = f();
    (out, cpu_seconds() - start)
}

/// An answer as the oracle sends it: the numbers written out are part of a request's work
/// (a split of degree 360 at 0.1 writes 8 MB of digits).
fn answered(answer: casteljau::Result<casteljau::oracle::Answer>) -> casteljau::Result<usize> {
    answer.map(|a| serde_json::Value::Object(a.to_json()).to_string().len())
}

/// A deterministic stream of numbers of one kind (xorshift: the test needs no seed handling).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Small,
    Float,
    Decimal,
    Fraction,
    /// 40-digit integers (at `t = 1/3`)
    Big,
    /// one-digit integers at a parameter of 30-digit fractions
    SmallWideT,
    /// floats at `t = 1/3`
    FloatThird,
    /// one-digit integers at a float parameter
    SmallFloatT,
}

/// The kinds the estimates are calibrated on.
const KINDS: [Kind; 4] = [Kind::Small, Kind::Float, Kind::Decimal, Kind::Fraction];

/// Every kind, with the mixtures the calibration did not see.
const ALL_KINDS: [Kind; 8] = [
    Kind::Small,
    Kind::Float,
    Kind::Decimal,
    Kind::Fraction,
    Kind::Big,
    Kind::SmallWideT,
    Kind::FloatThird,
    Kind::SmallFloatT,
];

struct Numbers(u64);

impl Numbers {
    fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    fn digits(&mut self, count: usize) -> BigInt {
        let mut x = BigInt::from(1 + self.next_u64() % 9);
        for _ in 1..count {
            x = x * 10 + (self.next_u64() % 10);
        }
        x
    }

    fn number(&mut self, kind: Kind) -> BigRational {
        let sign = if self.next_u64() % 2 == 0 { 1 } else { -1 };
        match kind {
            Kind::Small | Kind::SmallWideT | Kind::SmallFloatT => {
                BigRational::from_integer(BigInt::from(sign * (self.next_u64() % 10) as i64))
            }
            Kind::Big => BigRational::from_integer(BigInt::from(sign) * self.digits(40)),
            Kind::Float | Kind::FloatThird => {
                let x = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
                BigRational::from_float(sign as f64 * x).expect("finite")
            }
            Kind::Decimal => BigRational::new(BigInt::from(sign) * self.digits(6), BigInt::from(10u32).pow(6)),
            Kind::Fraction => BigRational::new(BigInt::from(sign) * self.digits(30), self.digits(30)),
        }
    }

    /// A parameter in (0, 1) of the kind.
    fn param(&mut self, kind: Kind) -> BigRational {
        let numbers = match kind {
            Kind::SmallWideT => Kind::Fraction,
            Kind::SmallFloatT => Kind::Float,
            other => other,
        };
        let x = self.number(numbers);
        let x = if x < BigRational::from_integer(0.into()) { -x } else { x };
        match kind {
            Kind::Small | Kind::Big | Kind::FloatThird => BigRational::new(1.into(), 3.into()),
            // a fraction in (0, 1): the smaller over the larger
            _ if x > BigRational::from_integer(1.into()) => x.recip(),
            _ if x == BigRational::from_integer(0.into()) => BigRational::new(1.into(), 3.into()),
            _ => x,
        }
    }

    fn point(&mut self, kind: Kind, dim: usize) -> Point<BigRational> {
        Point::new((0..dim).map(|_| self.number(kind)).collect()).expect("a point")
    }

    fn curve(&mut self, kind: Kind, degree: usize, dim: usize) -> BezierCurve<BigRational> {
        BezierCurve::new((0..=degree).map(|_| self.point(kind, dim)).collect()).expect("a curve")
    }

    fn weights(&mut self, kind: Kind, count: usize) -> Vec<BigRational> {
        // positive weights, away from zero
        (0..count)
            .map(|_| {
                let w = self.number(kind);
                let w = if w < BigRational::from_integer(0.into()) { -w } else { w };
                w + BigRational::from_integer(1.into())
            })
            .collect()
    }
}

fn text(x: &BigRational) -> String {
    x.to_string()
}

fn points_text(points: &[Point<BigRational>]) -> String {
    points
        .iter()
        .map(|p| p.coords().iter().map(text).collect::<Vec<_>>().join(","))
        .collect::<Vec<_>>()
        .join("; ")
}

/// An oracle op with requests growing with their size.
type Family = (&'static str, Box<dyn Fn(Kind, usize) -> Op>);

/// Derivatives of degree-`n` curves, of order `order(n)`, at a parameter or as curves.
fn derivative_family(order: fn(usize) -> usize, at: bool) -> Box<dyn Fn(Kind, usize) -> Op> {
    Box::new(move |k, n| {
        let mut g = seed(n);
        Op::Derivative {
            curve: g.curve(k, n, 2),
            order: order(n),
            at: at.then(|| g.param(k)),
        }
    })
}

/// The numbers of the requests of one size.
fn seed(size: usize) -> Numbers {
    Numbers(0x9e37_79b9_7f4a_7c15 ^ size as u64)
}

fn oracle_families() -> Vec<Family> {
    vec![
        (
            "eval",
            Box::new(move |k, n| {
                let mut g = seed(n);
                Op::Eval {
                    curve: g.curve(k, n, 2),
                    t: g.param(k),
                    approx: None,
                }
            }),
        ),
        (
            "split",
            Box::new(move |k, n| {
                let mut g = seed(n);
                Op::Split {
                    curve: g.curve(k, n, 2),
                    t: g.param(k),
                }
            }),
        ),
        (
            "elevate",
            Box::new(move |k, n| {
                let mut g = seed(n);
                Op::Elevate {
                    curve: g.curve(k, n, 2),
                    by: n,
                }
            }),
        ),
        ("derivative", derivative_family(|_| 2, true)),
        // the whole derivative curve, of half the degree's order
        ("derivative_curve", derivative_family(|n| n.div_ceil(2), false)),
        // a derivative of half the degree's order at a parameter
        ("derivative_high", derivative_family(|n| n.div_ceil(2), true)),
        (
            "to_bezier",
            Box::new(move |k, n| {
                let mut g = seed(n);
                Op::ToBezier {
                    power: (0..2).map(|_| (0..=n).map(|_| g.number(k)).collect()).collect(),
                }
            }),
        ),
        (
            "rational_eval",
            Box::new(move |k, n| {
                let mut g = seed(n);
                let points = (0..=n).map(|_| g.point(k, 2)).collect();
                let weights = g.weights(k, n + 1);
                Op::RationalEval {
                    curve: RationalBezierCurve::new(points, weights).expect("a rational curve"),
                    t: g.param(k),
                    approx: None,
                }
            }),
        ),
        (
            "surface_eval",
            Box::new(move |k, n| {
                let mut g = seed(n);
                let net = (0..=n).map(|_| (0..=n).map(|_| g.point(k, 3)).collect()).collect();
                Op::SurfaceEval {
                    surface: BezierSurface::new(net).expect("a net"),
                    u: g.param(k),
                    v: g.param(k),
                    approx: None,
                }
            }),
        ),
        (
            // the size is the dimension
            "fit_cubic",
            Box::new(move |k, n| {
                let mut g = seed(n);
                let data = CubicFitData::new(
                    g.point(k, n),
                    g.point(k, n),
                    g.point(k, n),
                    g.point(k, n),
                    g.point(k, n),
                )
                .expect("fit data");
                Op::FitCubic { data }
            }),
        ),
        (
            // the size is the number of digits (three points and weights, nothing else grows)
            "conic",
            Box::new(move |k, n| {
                let mut g = seed(n);
                let big = |g: &mut Numbers| BigRational::new(g.digits(n.max(1)), g.digits(n.max(1))) + g.number(k);
                let points = (0..3)
                    .map(|_| Point::new(vec![big(&mut g), big(&mut g)]).expect("a point"))
                    .collect();
                let weights = (0..3).map(|_| big(&mut g)).collect();
                Op::Conic {
                    curve: RationalBezierCurve::new(points, weights).expect("an arc"),
                }
            }),
        ),
    ]
}

/// The largest size in `1..=cap` that `admitted` accepts, assuming that larger sizes are
/// never cheaper; 0 when none is.
fn largest_admitted(cap: usize, admitted: impl Fn(usize) -> bool) -> usize {
    if admitted(cap) {
        return cap;
    }
    let (mut lo, mut hi) = (0, cap);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if admitted(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

fn report() -> bool {
    std::env::var_os("CALIBRATION_REPORT").is_some()
}

fn measured_in_release() -> bool {
    !cfg!(debug_assertions)
}

/// Whether an op takes a parameter (the mixtures of points and parameters only matter there).
fn has_parameter(name: &str) -> bool {
    matches!(
        name,
        "eval" | "split" | "derivative" | "derivative_high" | "rational_eval" | "surface_eval"
    )
}

#[test]
fn admitted_oracle_requests_of_growing_size_stay_within_the_budget() {
    let mut over = Vec::new();
    for (name, make) in oracle_families() {
        for kind in ALL_KINDS {
            if !has_parameter(name) && matches!(kind, Kind::SmallWideT | Kind::FloatThird | Kind::SmallFloatT) {
                continue;
            }
            // sizes where the inputs alone stay small (a net of side 400 is already 480k numbers)
            let cap = match name {
                "fit_cubic" => 64,
                "surface_eval" => 400,
                "conic" => 2000,
                _ => 4096,
            };
            let largest = largest_admitted(cap, |n| make(kind, n).check_limits().is_ok());
            // half and all of the largest admitted size, where a lax estimate shows
            for size in [largest / 2, largest] {
                if size == 0 {
                    continue;
                }
                let op = make(kind, size);
                assert!(
                    op.check_limits().is_ok(),
                    "{name} {kind:?}: size {size} refused below {largest}"
                );
                let work = op.work();
                if !measured_in_release() {
                    continue;
                }
                let (result, seconds) = timed(|| answered(op.run()));
                if report() {
                    eprintln!(
                        "{name:16} {kind:?}: size {size}, work {work:.2e} ({:.2} of MAX_REQUEST_WORK), {seconds:.3} s, ok {}",
                        work / MAX_REQUEST_WORK,
                        result.is_ok()
                    );
                }
                if seconds > BUDGET_SECONDS {
                    over.push(format!("{name} {kind:?} size {size}: {seconds:.2} s"));
                }
            }
        }
    }
    assert!(over.is_empty(), "admitted requests over {BUDGET_SECONDS} s: {over:?}");
}

#[test]
fn cheap_oracle_requests_are_admitted() {
    let mut g = Numbers(7);
    // float inputs are dyadic: their exact evaluations cost little at high degrees
    for n in [99, 300] {
        let points = (0..=n).map(|_| g.point(Kind::Float, 2)).collect();
        let op = Op::RationalEval {
            curve: RationalBezierCurve::new(points, g.weights(Kind::Float, n + 1)).unwrap(),
            t: g.param(Kind::Float),
            approx: None,
        };
        assert!(
            op.check_limits().is_ok(),
            "rational_eval of degree {n} with floats refused"
        );
        if measured_in_release() {
            let (_, seconds) = timed(|| answered(op.run()).unwrap());
            assert!(seconds < 0.2, "rational_eval of degree {n}: {seconds} s");
        }
    }
    for (op, what) in [
        (
            Op::Eval {
                curve: g.curve(Kind::Float, 1000, 2),
                t: g.param(Kind::Float),
                approx: None,
            },
            "eval of degree 1000 with floats",
        ),
        (
            Op::Split {
                curve: g.curve(Kind::Small, 40, 2),
                t: BigRational::new(1.into(), 3.into()),
            },
            "split of degree 40 at 1/3",
        ),
        (
            Op::FloatEval {
                curve: g.curve(Kind::Float, 500, 2),
                t: g.param(Kind::Float),
                method: FloatMethod::Compensated,
            },
            "float_eval of degree 500",
        ),
        (
            Op::Split {
                curve: g.curve(Kind::Decimal, 200, 2),
                t: g.param(Kind::Decimal),
            },
            "split of degree 200 with decimals",
        ),
        (
            Op::Elevate {
                curve: g.curve(Kind::Decimal, 200, 2),
                by: 200,
            },
            "elevation of degree 200 by 200 with decimals",
        ),
        (
            Op::Derivative {
                curve: g.curve(Kind::Fraction, 100, 2),
                order: 50,
                at: None,
            },
            "derivative of order 50 of degree 100 with fractions",
        ),
        (
            Op::ToBezier {
                power: (0..2)
                    .map(|_| (0..=100).map(|_| g.number(Kind::Decimal)).collect())
                    .collect(),
            },
            "to_bezier of degree 100 with decimals",
        ),
        (
            Op::FitCubic {
                data: CubicFitData::new(
                    g.point(Kind::Fraction, 8),
                    g.point(Kind::Fraction, 8),
                    g.point(Kind::Fraction, 8),
                    g.point(Kind::Fraction, 8),
                    g.point(Kind::Fraction, 8),
                )
                .unwrap(),
            },
            "fit_cubic of 8-D fractions",
        ),
        (
            Op::SurfaceEval {
                surface: BezierSurface::new(
                    (0..=15)
                        .map(|_| (0..=15).map(|_| g.point(Kind::Fraction, 3)).collect())
                        .collect(),
                )
                .unwrap(),
                u: g.param(Kind::Fraction),
                v: g.param(Kind::Fraction),
                approx: None,
            },
            "surface_eval of a 16×16 net of 3-D fractions",
        ),
    ] {
        assert!(op.check_limits().is_ok(), "{what} refused: work {:.2e}", op.work());
        if measured_in_release() {
            let (_, seconds) = timed(|| answered(op.run()).unwrap());
            assert!(seconds < 0.2, "{what}: {seconds} s");
        }
    }
}

fn figure_request(kind: FigureKind, numbers: Kind, n: usize) -> FigureRequest {
    let mut g = Numbers(0x5851_f42d_4c95_7f2d ^ n as u64);
    let dim = if kind == FigureKind::Fit { 3 } else { 2 };
    let mut request = FigureRequest::new(kind);
    match kind {
        FigureKind::Net | FigureKind::Enneper => {
            let net: Vec<String> = (0..=n)
                .map(|_| points_text(&(0..=n).map(|_| g.point(numbers, 3)).collect::<Vec<_>>()))
                .collect();
            request.input = Some(net.join(" | "));
        }
        FigureKind::Conics => {
            request.input = Some(points_text(&(0..3).map(|_| g.point(numbers, 2)).collect::<Vec<_>>()));
        }
        FigureKind::Bernstein => request.degree = Some(n.to_string()),
        FigureKind::Projection => {
            // a quadratic in space above the plane z = 0: heights x² + 1
            let lifted: Vec<_> = (0..3)
                .map(|_| {
                    let p = g.point(numbers, 2);
                    let (x, y) = (p.coords()[0].clone(), p.coords()[1].clone());
                    let z = &(&x * &x) + &BigRational::from_integer(1.into());
                    casteljau::Point::new(vec![x, y, z]).unwrap()
                })
                .collect();
            request.input = Some(points_text(&lifted));
        }
        _ => request.input = Some(points_text(g.curve(numbers, n, dim).points())),
    }
    if matches!(
        kind,
        FigureKind::Construction | FigureKind::Subdivision | FigureKind::Bernstein
    ) {
        request.t = Some(text(&g.param(numbers)));
    }
    request
}

#[test]
fn every_figure_kind_up_to_the_degree_limit_is_quick_or_refused() {
    let mut over = Vec::new();
    for kind in FigureKind::ALL {
        for numbers in KINDS {
            for n in [3, 20, 40, 64] {
                let request = figure_request(kind, numbers, n);
                let (result, seconds) = timed(|| request.figure());
                if report() {
                    eprintln!(
                        "figure {:12} {numbers:?} degree {n}: {seconds:.3} s, {}",
                        kind.name(),
                        result.as_ref().map_or_else(|e| e.to_string(), |_| "drawn".into())
                    );
                }
                if let Err(e) = &result {
                    // only a limit may refuse a well-formed request, and it says which
                    let message = e.to_string();
                    assert!(message.contains("limit"), "{} degree {n}: {message}", kind.name());
                    assert!(seconds < 0.2 || !measured_in_release(), "refused slowly: {message}");
                }
                if measured_in_release() && seconds > BUDGET_SECONDS {
                    over.push(format!("{} {numbers:?} degree {n}: {seconds:.2} s", kind.name()));
                }
            }
        }
    }
    assert!(over.is_empty(), "figures over {BUDGET_SECONDS} s: {over:?}");
}

#[test]
fn figures_of_degree_20_with_small_numbers_are_drawn() {
    for kind in FigureKind::ALL {
        let request = figure_request(kind, Kind::Small, 20);
        let (result, seconds) = timed(|| request.figure().and_then(|f| f.to_svg()));
        assert!(result.is_ok(), "{}: {:?}", kind.name(), result.err());
        assert!(
            seconds < 0.25 || !measured_in_release(),
            "{} of degree 20: {seconds:.3} s",
            kind.name()
        );
    }
}

/// `CALIBRATION_SWEEP=1 cargo test --release --test calibration sweep -- --ignored --nocapture`:
/// estimate against CPU time for every op and kind at growing sizes, admitted or not, until
/// a request takes a second; the table the weights of `src/work.rs` are fitted to.
#[test]
#[ignore]
fn sweep() {
    let only = std::env::var("SWEEP_OP").ok();
    for (name, make) in oracle_families() {
        if only.as_deref().is_some_and(|o| o != name) {
            continue;
        }
        for kind in KINDS {
            let mut n = if name == "fit_cubic" { 2 } else { 1 };
            let cap = match name {
                "fit_cubic" => 64,
                "surface_eval" => 400,
                "conic" => 2000,
                _ => 4096,
            };
            while n <= cap {
                let op = make(kind, n);
                let work = op.work();
                let (mut reps, mut total) = (0, 0.0);
                while total < 0.03 && reps < 50 {
                    let (_, s) = timed(|| answered(op.run_without_limits()));
                    total += s;
                    reps += 1;
                }
                let seconds = total / reps as f64;
                println!(
                    "{name:14} {kind:?} size {n}: work {work:.2e} ({:.3} of max), {seconds:.4} s, {:.2e} units/s, admitted {}",
                    work / MAX_REQUEST_WORK,
                    work / seconds,
                    work <= MAX_REQUEST_WORK
                );
                if seconds > 1.0 {
                    break;
                }
                n = (n * 3 / 2).max(n + 1);
            }
        }
    }
}
