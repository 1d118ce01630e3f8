//! Judge your float subdivision and elevation in your own tests: compute them with your f64
//! code, compute them exactly, and assert that every coordinate is within the a priori
//! bound of the algorithm you used (`casteljau::judge`, `assert_within_bound!`).
//!
//! `cargo run --example judge_ops`

use casteljau::assert_within_bound;
use casteljau::float::{elevate_bounds, f64_to_rational, split_bounds, SplitForm};
use casteljau::judge::judge;
use casteljau::{BezierCurve, BigRational};

/// Your float code: de Casteljau's split of one coordinate, lerp form, both halves.
fn my_split(b: &[f64], t: f64) -> (Vec<f64>, Vec<f64>) {
    let mut level = b.to_vec();
    let (mut left, mut right) = (vec![b[0]], vec![b[b.len() - 1]]);
    while level.len() > 1 {
        level = level.windows(2).map(|w| w[0] + t * (w[1] - w[0])).collect();
        left.push(level[0]);
        right.push(level[level.len() - 1]);
    }
    right.reverse();
    (left, right)
}

/// Your float code: elevation by one, `(i·b_{i−1} + (n+1−i)·b_i) / (n+1)`.
fn my_elevate(b: &[f64]) -> Vec<f64> {
    let n = b.len() - 1;
    let mut c = vec![b[0]];
    for i in 1..=n {
        c.push((i as f64 * b[i - 1] + (n + 1 - i) as f64 * b[i]) / (n + 1) as f64);
    }
    c.push(b[n]);
    c
}

fn exact_curve(b: &[f64]) -> BezierCurve<BigRational> {
    BezierCurve::from_coords(b.iter().map(|x| vec![f64_to_rational(*x).expect("finite")]).collect()).expect("a curve")
}

/// The largest error in ulps of your split, and whether every coordinate is in its bound.
fn check_split(b: &[f64], t: f64) -> (f64, bool) {
    let (left, right) = exact_curve(b).split_at(&f64_to_rational(t).expect("finite"));
    let (my_left, my_right) = my_split(b, t);
    let (bl, br) = split_bounds(b, t, SplitForm::Lerp);
    let mut worst: f64 = 0.0;
    let mut all_within = true;
    for ((mine, exact), bound) in my_left
        .iter()
        .chain(&my_right)
        .zip(left.points().iter().chain(right.points()))
        .zip(bl.iter().chain(&br))
    {
        let j = judge(*mine, &exact.coords()[0], bound.bound).expect("within the f64 range");
        worst = worst.max(j.error.error_ulps);
        all_within &= j.within_bound;
        assert_within_bound!(*mine, &exact.coords()[0], bound.bound, bound.sum);
    }
    (worst, all_within)
}

fn check_elevate(b: &[f64]) {
    let exact = exact_curve(b).elevate_by(1).expect("a low degree");
    for ((mine, exact), bound) in my_elevate(b).iter().zip(exact.points()).zip(elevate_bounds(b, 1)) {
        assert_within_bound!(*mine, &exact.coords()[0], bound.bound);
    }
}

fn main() {
    let b = [0.0, 1.0, 3.0, 4.5, -2.0, 0.1];
    for t in [0.5, 0.1, 1.0 / 3.0] {
        let (worst, within) = check_split(&b, t);
        println!("split at {t}: worst coordinate {worst:.3} ulp from exact, all within the lerp bound: {within}");
    }
    check_elevate(&b);
    println!("elevation: every coordinate within its bound");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_float_split_and_elevation_are_within_their_bounds_and_a_wrong_one_is_caught() {
        let b = [0.0, 1.0, 3.0, 4.5, -2.0, 0.1];
        assert_eq!(check_split(&b, 0.5).0, 0.0);
        assert!(check_split(&b, 1.0 / 3.0).1);
        check_elevate(&b);
        // a split that forgot a level's rounding direction: one ulp too high everywhere
        let exact = exact_curve(&b).split_at(&f64_to_rational(0.3).unwrap()).0;
        let x = &exact.points()[3].coords()[0];
        let wrong = casteljau::float::nearest_f64(x) * (1.0 + 1e-12);
        let caught = std::panic::catch_unwind(|| {
            assert_within_bound!(wrong, x, split_bounds(&b, 0.3, SplitForm::Lerp).0[3].bound);
        });
        assert!(caught.is_err());
    }
}
