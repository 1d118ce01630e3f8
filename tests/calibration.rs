//! The work limits against the clock: for every oracle op and every `figure` kind, with each
//! kind of number (small integers, floats, short decimals, 30-digit fractions with distinct
//! denominators), the largest request the work estimate admits is found by bisection on its
//! size (estimates only, no work), then run once: it must finish within [`BUDGET_SECONDS`] of
//! CPU time. The largest admitted request is where an estimate that is too lax shows first.
//! Requests known to be cheap must be admitted (an estimate that is too strict fails too).
//!
//! Timings mean something only in an optimised build: under a debug build the test checks
//! the estimates' monotonicity and the cheap requests but not the clock.
//! `CALIBRATION_REPORT=1` prints every measurement (estimate, seconds, units per second).

use casteljau::figure::{FigureKind, FigureRequest};
use casteljau::oracle::{FloatMethod, Op, MAX_REQUEST_WORK};
use casteljau::CubicFitData;
use casteljau::{BezierCurve, BezierSurface, BigInt, BigRational, Point, RationalBezierCurve};

/// CPU seconds any admitted request may take, on a busy shared 2-core machine. The limits
/// aim at about half of it, so a slower CI machine still passes.
const BUDGET_SECONDS: f64 = 1.0;

/// CPU time of this thread: the clock the budget is stated in (another process on the
/// machine does not count against a request). Linux only; elsewhere wall time.
fn cpu_seconds() -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<f64>().ok())
        .map(|ns| ns / 1e9)
        .unwrap_or_else(|| {
            use std::sync::OnceLock;
            static START: OnceLock<std::time::Instant> = OnceLock::new();
            START.get_or_init(std::time::Instant::now).elapsed().as_secs_f64()
        })
}

fn timed<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let start = cpu_seconds();
    let out = f();
    (out, cpu_seconds() - start)
}

/// A deterministic stream of numbers of one kind (xorshift: the test needs no seed handling).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Small,
    Float,
    Decimal,
    Fraction,
}

const KINDS: [Kind; 4] = [Kind::Small, Kind::Float, Kind::Decimal, Kind::Fraction];

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
            Kind::Small => BigRational::from_integer(BigInt::from(sign * (self.next_u64() % 10) as i64)),
            Kind::Float => {
                let x = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
                BigRational::from_float(sign as f64 * x).expect("finite")
            }
            Kind::Decimal => BigRational::new(BigInt::from(sign) * self.digits(6), BigInt::from(10u32).pow(6)),
            Kind::Fraction => BigRational::new(BigInt::from(sign) * self.digits(30), self.digits(30)),
        }
    }

    /// A parameter in (0, 1) of the kind.
    fn param(&mut self, kind: Kind) -> BigRational {
        let x = self.number(kind);
        let x = if x < BigRational::from_integer(0.into()) { -x } else { x };
        match kind {
            Kind::Small => BigRational::new(1.into(), 3.into()),
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

fn oracle_families() -> Vec<Family> {
    let seed = |size: usize| Numbers(0x9e37_79b9_7f4a_7c15 ^ size as u64);
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
        (
            "derivative",
            Box::new(move |k, n| {
                let mut g = seed(n);
                Op::Derivative {
                    curve: g.curve(k, n, 2),
                    order: 2,
                    at: Some(g.param(k)),
                }
            }),
        ),
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

#[test]
fn the_largest_admitted_oracle_request_of_every_op_stays_within_the_budget() {
    let mut over = Vec::new();
    for (name, make) in oracle_families() {
        for kind in KINDS {
            // sizes where the inputs alone stay small (a net of side 400 is already 480k numbers)
            let cap = match name {
                "fit_cubic" => 64,
                "surface_eval" => 400,
                "conic" => 2000,
                _ => 4096,
            };
            let size = largest_admitted(cap, |n| make(kind, n).check_limits().is_ok());
            if size == 0 {
                continue;
            }
            let op = make(kind, size);
            let work = op.work();
            if !measured_in_release() {
                continue;
            }
            let (result, seconds) = timed(|| op.run());
            if report() {
                eprintln!(
                    "{name:14} {kind:?}: size {size}, work {work:.2e} ({:.2} of MAX_REQUEST_WORK), {seconds:.3} s, {:.2e} units/s, ok {}",
                    work / MAX_REQUEST_WORK,
                    work / seconds,
                    result.is_ok()
                );
            }
            if seconds > BUDGET_SECONDS {
                over.push(format!("{name} {kind:?} size {size}: {seconds:.2} s"));
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
            let (_, seconds) = timed(|| op.run().unwrap());
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
    ] {
        assert!(op.check_limits().is_ok(), "{what} refused: work {:.2e}", op.work());
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
