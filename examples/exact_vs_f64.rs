//! Evaluate a curve exactly and compare your `f64` result with it.
//!
//! Your float code evaluates a cubic at `t`; casteljau evaluates the very same curve (the
//! f64 inputs read as the exact rationals they are) in exact arithmetic, and says how far
//! your answer is from the exact value, in units in the last place.
//!
//! `cargo run --example exact_vs_f64`

use casteljau::float::{f64_to_rational, ulp_error, UlpError};
use casteljau::{BezierCurve, BigRational};

/// Your float code: a cubic by the power form (Horner), one coordinate.
fn my_cubic_eval(b: [f64; 4], t: f64) -> f64 {
    let (c0, c1, c2, c3) = (
        b[0],
        3.0 * (b[1] - b[0]),
        3.0 * (b[2] - 2.0 * b[1] + b[0]),
        b[3] - 3.0 * b[2] + 3.0 * b[1] - b[0],
    );
    ((c3 * t + c2) * t + c1) * t + c0
}

/// Your answer at `t` and its error against the exact value.
fn judge(b: [f64; 4], t: f64) -> (f64, UlpError) {
    let mine = my_cubic_eval(b, t);
    let q = |x: f64| f64_to_rational(x).expect("finite input");
    let curve = BezierCurve::<BigRational>::from_coords(b.iter().map(|&x| vec![q(x)]).collect()).expect("a curve");
    let exact = curve.eval(&q(t)).coords()[0].clone();
    (
        mine,
        ulp_error(mine, &exact).expect("an exact value within the f64 range"),
    )
}

/// (t − 3/4)³ in Bernstein form: near its triple root, the power form cancels.
const CUBIC: [f64; 4] = [-0.421875, 0.140625, -0.046875, 0.015625];

fn main() {
    for t in [0.3, 0.7500001] {
        let (mine, err) = judge(CUBIC, t);
        println!(
            "t = {t}: mine {mine:e}, exact ≈ {:e}, {} f64 steps from it, error {:.3} ulp",
            err.nearest, err.ulps, err.error_ulps
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_float_answer_is_judged_exactly() {
        // far from the root the power form is within an ulp
        let (_, far) = judge(CUBIC, 0.3);
        assert!(far.error_ulps < 1.0, "{far:?}");
        // next to it, it returns 0 for a value near 1e-21: every digit lost
        let (mine, near) = judge(CUBIC, 0.7500001);
        assert_eq!(mine, 0.0);
        assert!(near.nearest > 9.9e-22 && near.nearest < 1.0e-21, "{near:?}");
        assert!(near.error_ulps > 1e15, "{near:?}");
    }
}
