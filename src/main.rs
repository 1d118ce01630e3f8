//! The `casteljau` command.
use casteljau::{BezierCurve, BigRational, Point, Scalar};

fn main() {
    let q = |p, d| BigRational::from_ratio(p, d).unwrap();
    let a = |c: &[i64]| Point::from_ints(c).unwrap();
    let coeffs = vec![a(&[1, 0]), a(&[0, 1]), a(&[-1, 0]), a(&[0, -1])];
    let c = BezierCurve::from_power_on(&coeffs, &q(-1, 1), &q(1, 1)).unwrap();
    println!("text 000 §1.3: Bézier points of (-u^2+1, -u^3+u), -1 <= u <= 1: {c}");
    println!("{}", c.scheme(&q(1, 3)));
}
