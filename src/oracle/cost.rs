//! Each request's work estimate: the work model of its kernel (`crate::work`), calibrated per
//! op and per kind of input numbers.

use super::Op;
use crate::curve::BezierCurve;
use crate::error::Result;
use crate::work::{
    conic_work, derivative_work, elevate_work, eval_work, fit_cubic_work, kind_of, kinds_in, number_kinds,
    rational_eval_work, split_work, surface_eval_work, to_bezier_work, NumberKind,
};
use num_rational::BigRational;

/// Per kind of input numbers (integers, floats, decimals, other fractions), how many of the
/// oracle's units one unit of an op's model is worth.
///
/// The models count bit² of gcd-reduced arithmetic, but the kernels are fraction-free: they
/// take the common denominator once and then multiply integers, so the model's units cost
/// more or less CPU time by op and by kind of number. Each entry is measured by the ignored
/// `sweep` of `tests/calibration.rs` (the kernel and the answer written as JSON, on one core
/// of a busy 2-core machine), at the size where the op's requests of that kind take 0.25 s of
/// CPU (or at the largest the other limits allow): there, the request's estimate is
/// [`MAX_REQUEST_WORK`](super::MAX_REQUEST_WORK).
struct ByKind([f64; 4]);

impl ByKind {
    /// The calibration for a set of kinds ([`number_kinds`]): the most general one's.
    fn of(&self, kinds: u8) -> f64 {
        kinds_in(kinds).last().map_or(self.0[0], |k| self.0[k as usize])
    }
}

const EVAL: ByKind = ByKind([0.027, 0.81, 0.005, 0.0003]);
const SPLIT: ByKind = ByKind([0.00066, 0.0037, 0.00027, 0.003]);
const ELEVATE: ByKind = ByKind([0.0043, 0.006, 9.4e-5, 0.0048]);
const DERIVATIVE_AT: ByKind = ByKind([3.8e-7, 2.1e-7, 1.2e-8, 2.8e-6]);
const DERIVATIVE: ByKind = ByKind([2.2e-4, 2.6e-4, 2.0e-5, 0.011]);
const TO_BEZIER: ByKind = ByKind([4.0, 2.8, 0.012, 0.062]);
const RATIONAL_EVAL: ByKind = ByKind([0.014, 0.035, 0.019, 0.15]);
// The surface's model of 30-digit fractions grows as about the sixth power of the side, the
// kernel's time as the third: the fraction entry sits at 0.1 s (side 50), not 0.25 s, so that
// nets of shorter fractions, whose model is smaller, are not admitted much further.
const SURFACE_EVAL: ByKind = ByKind([0.63, 0.41, 0.33, 1.0e-4]);
const FIT_CUBIC: ByKind = ByKind([0.16, 0.015, 0.017, 0.0006]);
/// One float operation of a bound (`Op::Judged`), in the oracle's units (5 ns).
const FLOAT_OPERATION: f64 = 1.0e4;
/// One coordinate judged exactly (`Op::Judged`), in the oracle's units (2 µs).
const JUDGED_COORDINATE: f64 = 4.0e6;
const CONIC: ByKind = ByKind([0.17, 0.17, 0.17, 0.17]);

impl Op {
    /// The work this request needs, in units of which [`MAX_REQUEST_WORK`](super::MAX_REQUEST_WORK)
    /// take about a quarter of a second of CPU: its kernel's model (roughly Σ bits² over its
    /// rational operations) times the op's calibration for the kind of its input numbers.
    /// Computed before anything else so that absurd requests are refused at once.
    ///
    /// A request mixing kinds of numbers is calibrated by its most general kind, whose unit
    /// may cost far less than another kind's (decimals' and fractions' models count
    /// denominators the kernels share): it is also estimated for each other kind it holds
    /// alone (the other numbers set to 1), and charged the largest, so that one `"0.1"`
    /// among 40-digit integers costs at least what those integers cost. Integers among floats
    /// (`0`, `3.0`, `1e308`) are left to the floats' calibration: charged as integers, 3-D
    /// fits of floats holding `1e308`, which take 0.01 s, were refused.
    pub fn work(&self) -> f64 {
        let kinds = self.input_kinds();
        let top = kinds_in(kinds).last();
        // integers among floats are floats: the floats' calibration counts them
        let among_floats = |k: &NumberKind| *k == NumberKind::Integer && top == Some(NumberKind::Dyadic);
        kinds_in(kinds)
            .filter(|k| Some(*k) != top && !among_floats(k))
            .filter_map(|k| self.with_only(k).ok())
            .map(|alone| alone.calibrated_work())
            .fold(self.calibrated_work(), f64::max)
    }

    /// The kinds of the request's input numbers (its parameters not counted).
    fn input_kinds(&self) -> u8 {
        match self {
            Op::EvalJudged { curve, .. } => number_kinds(curve.points().iter().flat_map(|p| p.coords())),
            Op::Eval { curve, .. }
            | Op::FloatEval { curve, .. }
            | Op::Split { curve, .. }
            | Op::Elevate { curve, .. }
            | Op::Derivative { curve, .. } => number_kinds(curve.points().iter().flat_map(|p| p.coords())),
            Op::RationalEval { curve, .. } | Op::Conic { curve } => {
                number_kinds(curve.points().iter().flat_map(|p| p.coords()).chain(curve.weights()))
            }
            Op::SurfaceEval { surface, .. } => number_kinds(surface.net().iter().flatten().flat_map(|p| p.coords())),
            Op::FitCubic { data: d } => {
                number_kinds([&d.x0, &d.x1, &d.xh, &d.d0, &d.d1].into_iter().flat_map(|p| p.coords()))
            }
            Op::ToBezier { power } => number_kinds(power.iter().flatten()),
            Op::Judged { op, .. } => op.input_kinds(),
            Op::Batch { ops } => ops.iter().fold(0, |k, op| k | op.input_kinds()),
        }
    }

    /// The request with its input numbers of kinds other than `kind` replaced by 1.
    fn with_only(&self, kind: NumberKind) -> Result<Op> {
        let keep = move |x: &BigRational| -> Result<BigRational> {
            Ok(if kind_of(x) == kind {
                x.clone()
            } else {
                BigRational::from_integer(1.into())
            })
        };
        let point = |p: &crate::point::Point<BigRational>| p.try_map(keep);
        Ok(match self {
            Op::Batch { ops } => Op::Batch {
                ops: ops.iter().map(|op| op.with_only(kind)).collect::<Result<_>>()?,
            },
            Op::Judged { op, approx, method } => Op::Judged {
                op: Box::new(op.with_only(kind)?),
                approx: approx.clone(),
                method: *method,
            },
            Op::Eval { curve, t, .. } => Op::Eval {
                curve: curve.try_map(keep)?,
                t: t.clone(),
                approx: None,
            },
            Op::EvalJudged { curve, t, method, .. } => Op::EvalJudged {
                curve: std::sync::Arc::new(curve.try_map(keep)?),
                t: t.clone(),
                approx: None,
                method: *method,
            },
            Op::FloatEval { curve, t, method } => Op::FloatEval {
                curve: curve.try_map(keep)?,
                t: t.clone(),
                method: *method,
            },
            Op::Split { curve, t } => Op::Split {
                curve: curve.try_map(keep)?,
                t: t.clone(),
            },
            Op::Elevate { curve, by } => Op::Elevate {
                curve: curve.try_map(keep)?,
                by: *by,
            },
            Op::Derivative { curve, order, at } => Op::Derivative {
                curve: curve.try_map(keep)?,
                order: *order,
                at: at.clone(),
            },
            Op::RationalEval { curve, t, .. } => Op::RationalEval {
                curve: curve.try_map(keep)?,
                t: t.clone(),
                approx: None,
            },
            Op::Conic { curve } => Op::Conic {
                curve: curve.try_map(keep)?,
            },
            Op::SurfaceEval { surface, u, v, .. } => Op::SurfaceEval {
                surface: surface.try_map(keep)?,
                u: u.clone(),
                v: v.clone(),
                approx: None,
            },
            Op::FitCubic { data: d } => Op::FitCubic {
                data: crate::fit::CubicFitData {
                    x0: point(&d.x0)?,
                    x1: point(&d.x1)?,
                    xh: point(&d.xh)?,
                    d0: point(&d.d0)?,
                    d1: point(&d.d1)?,
                },
            },
            Op::ToBezier { power } => Op::ToBezier {
                power: power
                    .iter()
                    .map(|c| c.iter().map(keep).collect::<Result<Vec<_>>>())
                    .collect::<Result<_>>()?,
            },
        })
    }

    /// The op's model times the calibration of the most general kind of its numbers.
    fn calibrated_work(&self) -> f64 {
        let kind = |numbers: &mut dyn Iterator<Item = &BigRational>| number_kinds(numbers);
        // integers at a dyadic parameter run the dyadic kernels, whose numbers grow by the
        // parameter's bits at every level (degree 3788 of integers at 0.1 took 5 s as integers)
        let at = |kinds: u8, ts: &[&BigRational]| {
            let top_is_integer = kinds_in(kinds).last() == Some(NumberKind::Integer);
            if top_is_integer && kinds_in(number_kinds(ts.iter().copied())).last() == Some(NumberKind::Dyadic) {
                1 << NumberKind::Dyadic as u8
            } else {
                kinds
            }
        };
        let curve_kind =
            |c: &crate::curve::BezierCurve<BigRational>| kind(&mut c.points().iter().flat_map(|p| p.coords()));
        let rational_kind = |c: &crate::rational::RationalBezierCurve<BigRational>| {
            kind(&mut c.points().iter().flat_map(|p| p.coords()).chain(c.weights()))
        };
        match self {
            Op::Eval { curve, t, .. } | Op::FloatEval { curve, t, .. } => {
                eval_work(curve, t) * EVAL.of(at(curve_kind(curve), &[t]))
            }
            Op::EvalJudged { curve, t, .. } => eval_work(curve, t) * EVAL.of(at(curve_kind(curve), &[t])),
            Op::Split { curve, t } => split_work(curve, t) * SPLIT.of(at(curve_kind(curve), &[t])),
            Op::Elevate { curve, by } => elevate_work(curve, *by) * ELEVATE.of(curve_kind(curve)),
            Op::Derivative { curve, order, at: t } => {
                let (differences, evaluation) = derivative_work(curve, *order, t.as_ref());
                let at_t: Vec<&BigRational> = t.iter().collect();
                let kind = at(curve_kind(curve), at_t.as_slice());
                differences * DERIVATIVE.of(kind) + evaluation * DERIVATIVE_AT.of(kind)
            }
            Op::RationalEval { curve, t, .. } => {
                rational_eval_work(curve, t) * RATIONAL_EVAL.of(at(rational_kind(curve), &[t]))
            }
            Op::Conic { curve } => conic_work(curve) * CONIC.of(rational_kind(curve)),
            Op::SurfaceEval { surface, u, v, .. } => {
                let numbers = &mut surface.net().iter().flatten().flat_map(|p| p.coords());
                surface_eval_work(surface, u, v) * SURFACE_EVAL.of(at(kind(numbers), &[u, v]))
            }
            Op::FitCubic { data } => {
                let d = data;
                let numbers = &mut [&d.x0, &d.x1, &d.xh, &d.d0, &d.d1].into_iter().flat_map(|p| p.coords());
                fit_cubic_work(data) * FIT_CUBIC.of(kind(numbers))
            }
            Op::ToBezier { power } => to_bezier_work(power) * TO_BEZIER.of(kind(&mut power.iter().flatten())),
            // judging an answer reads each exact coordinate about as writing it does, and the
            // bounds are float triangles: a float operation is about 5 ns, a coordinate's
            // judgement (ulps, the bound decided exactly, the condition) about 2 µs
            // each parameter after the first weighted as `eval`'s batches are
            Op::Batch { ops } => ops
                .iter()
                .enumerate()
                .map(|(k, op)| op.calibrated_work() * if k == 0 { 1.0 } else { super::batch::BATCH_WEIGHT })
                .sum(),
            Op::Judged { op, .. } => {
                2.0 * op.calibrated_work()
                    + FLOAT_OPERATION * super::judged::float_work(op)
                    + JUDGED_COORDINATE * super::judged::output_coordinates(op)
            }
        }
    }
}

/// The limit of the whole de Casteljau scheme of `curve` at `t` (`eval --scheme`), which
/// runs every gcd-reduced lerp and prints each: the triangle's model without the calibration
/// of `split`, whose fraction-free kernel writes only the two halves (degree 1000 of
/// three-digit integers at 1/3 took 9 s and printed 1.7 GB).
pub fn check_scheme_work(curve: &BezierCurve<BigRational>, t: &BigRational) -> Result<()> {
    super::protocol::check_work(split_work(curve, t))
}
