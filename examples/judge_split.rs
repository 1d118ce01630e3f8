//! Judge your float subdivision: split a cubic at `t` with your own `f64` code, split the
//! same curve exactly, and report how many ulps each of your control points is from the
//! exact one.
//!
//! `cargo run --example judge_split`

use casteljau::float::{f64_to_rational, ulp_error};
use casteljau::{BezierCurve, BigRational};

type Cubic = [[f64; 2]; 4];

/// Your float code: de Casteljau's split, both halves.
fn my_split(b: Cubic, t: f64) -> (Cubic, Cubic) {
    let lerp = |p: [f64; 2], q: [f64; 2]| [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
    let (b01, b12, b23) = (lerp(b[0], b[1]), lerp(b[1], b[2]), lerp(b[2], b[3]));
    let (b012, b123) = (lerp(b01, b12), lerp(b12, b23));
    let mid = lerp(b012, b123);
    ([b[0], b01, b012, mid], [mid, b123, b23, b[3]])
}

/// The largest error of the float halves' coordinates, in ulps of the exact values.
fn worst_error_ulps(b: Cubic, t: f64) -> f64 {
    let q = |x: f64| f64_to_rational(x).expect("finite input");
    let exact =
        BezierCurve::<BigRational>::from_coords(b.iter().map(|p| vec![q(p[0]), q(p[1])]).collect()).expect("a curve");
    let (left, right) = exact.split_at(&q(t));
    let (my_left, my_right) = my_split(b, t);
    let mut worst: f64 = 0.0;
    for (mine, exact) in my_left
        .iter()
        .chain(&my_right)
        .zip(left.points().iter().chain(right.points()))
    {
        for (x, e) in mine.iter().zip(exact.coords()) {
            worst = worst.max(ulp_error(*x, e).expect("within the f64 range").error_ulps);
        }
    }
    worst
}

fn main() {
    let curve = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]];
    for t in [0.5, 0.1, 1.0 / 3.0] {
        println!(
            "t = {t}: worst control point {:.3} ulp from exact",
            worst_error_ulps(curve, t)
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_split_at_one_half_of_small_integers_is_exact_and_others_are_close() {
        let curve = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]];
        // halving dyadic numbers: every f64 operation is exact
        assert_eq!(worst_error_ulps(curve, 0.5), 0.0);
        let third = worst_error_ulps(curve, 1.0 / 3.0);
        assert!(third > 0.0 && third < 8.0, "{third}");
    }
}
