//! Each request's work estimate, from the work model of its kernel (`crate::work`).

use super::Op;
use crate::work::{
    conic_work, derivative_work, elevate_work, eval_work, fit_cubic_work, rational_eval_work, split_work,
    surface_eval_work, to_bezier_work,
};

impl Op {
    /// A rough count of the work this request needs (Σ bits² over its rational operations,
    /// see [`MAX_REQUEST_WORK`](super::MAX_REQUEST_WORK)), computed before anything else so
    /// that absurd requests are refused at once.
    pub fn work(&self) -> f64 {
        match self {
            Op::Eval { curve, t, .. } | Op::FloatEval { curve, t, .. } => eval_work(curve, t),
            Op::Split { curve, t } => split_work(curve, t),
            Op::Elevate { curve, by } => elevate_work(curve, *by),
            Op::Derivative { curve, order, at } => derivative_work(curve, *order, at.as_ref()),
            Op::RationalEval { curve, t, .. } => rational_eval_work(curve, t),
            Op::Conic { curve } => conic_work(curve),
            Op::SurfaceEval { surface, u, v, .. } => surface_eval_work(surface, u, v),
            Op::FitCubic { data } => fit_cubic_work(data),
            Op::ToBezier { power } => to_bezier_work(power),
        }
    }
}
