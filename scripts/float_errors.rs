//! The error-distribution table of the README: f64 de Casteljau (convex form, with its a
//! priori and running bounds), casteljau's generic `BezierCurve<f64>::eval` (the lerp form;
//! for cubics the nested Bernstein sum),
//! compensated de Casteljau and kurbo (cubics), every error measured exactly.
//!
//! `cargo run --release --example float_errors [cases]` (default 100,000 random cases and
//! 10,000 near multiple roots). Prints a Markdown table and the bound checks; exits 1 on
//! any violated bound.

use casteljau::float::{
    a_priori_index, compensated_de_casteljau, de_casteljau, de_casteljau_running, error_at_most, eval_dyadic,
    gamma_exact, ulp_error, UNIT_ROUNDOFF,
};
use casteljau::Interval;
use casteljau::{BezierCurve, BigRational, Scalar};
use kurbo::{CubicBez, ParamCurve};
use num_traits::Signed;

#[path = "../tests/support/rng.rs"]
mod rng;
use rng::Rng;

fn q(x: f64) -> BigRational {
    BigRational::from_f64(x).unwrap()
}

fn exact_eval(b: &[f64], t: f64) -> BigRational {
    let c = BezierCurve::from_coords(b.iter().map(|x| vec![q(*x)]).collect()).unwrap();
    eval_dyadic(&c, &q(t)).unwrap().coords()[0].clone()
}

#[derive(Default)]
struct Stats {
    ulps: Vec<u64>,
    ratio: Vec<f64>,
}

impl Stats {
    fn row(&mut self, set: &str, n: usize, method: &str) -> String {
        self.ulps.sort_unstable();
        self.ratio.sort_by(|a, b| a.total_cmp(b));
        let at = |v: &Vec<u64>, p: f64| v[((v.len() - 1) as f64 * p).round() as usize];
        let tight = if self.ratio.is_empty() {
            "—".to_string()
        } else {
            let r = &self.ratio;
            format!("{:.2e} / {:.2e}", r[(r.len() - 1) / 2], r[r.len() - 1])
        };
        format!(
            "| {set} | {n} | {method} | {} | {} | {} | {} | {tight} |",
            self.ulps.len(),
            at(&self.ulps, 0.5),
            at(&self.ulps, 0.99),
            self.ulps.last().unwrap()
        )
    }
}

fn multiple_root(n: usize, r: f64) -> Vec<f64> {
    let one = BigRational::from_integer(1.into());
    (0..=n)
        .map(|i| Scalar::to_f64(&((-q(r)).pow((n - i) as i32) * (&one - q(r)).pow(i as i32))))
        .collect()
}

fn main() {
    let cases: usize = std::env::args()
        .nth(1)
        .map_or(100_000, |s| s.parse().expect("a number of cases"));
    let ill_cases = cases / 10;
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut violations = [0usize; 5]; // a priori, running, compensated, interval, compensated > 1 ulp
    let mut random_total = 0usize;
    println!("| set | degree | method | cases | median ulps | p99 ulps | max ulps | error / bound (median / max) |");
    println!("|---|---|---|---|---|---|---|---|");
    for (set, count) in [("random", cases), ("near a multiple root", ill_cases)] {
        for n in [3usize, 5, 10, 20] {
            let mut plain = Stats::default();
            let mut lerp = Stats::default();
            let mut comp = Stats::default();
            let mut kurbo_stats = Stats::default();
            for _ in 0..count / 4 {
                let (b, t) = if set == "random" {
                    (
                        (0..=n).map(|_| 2.0 * rng.unit() - 1.0).collect::<Vec<f64>>(),
                        rng.unit(),
                    )
                } else {
                    let r = 0.2 + 0.6 * rng.unit();
                    let delta = (rng.unit() - 0.5) * 10f64.powi(-(1 + (rng.next() % 5) as i32));
                    (multiple_root(n, r), r + delta)
                };
                let p = exact_eval(&b, t);
                let abs: Vec<f64> = b.iter().map(|x| f64::abs(*x)).collect();
                let sum = exact_eval(&abs, t);
                let err = |x: f64| Signed::abs(&(q(x) - &p));
                // plain de Casteljau and its bounds
                let value = de_casteljau(&b, t);
                let bound = gamma_exact(a_priori_index(n, t)) * &sum;
                if err(value) > bound {
                    violations[0] += 1;
                }
                if !error_at_most(value, &p, de_casteljau_running(&b, t).1) {
                    violations[1] += 1;
                }
                plain.ulps.push(ulp_error(value, &p).unwrap().ulps);
                plain.ratio.push(Scalar::to_f64(&(err(value) / &bound)));
                // the crate's generic f64 eval (b_i + t (b_{i+1} − b_i); a cubic's nested sum)
                let curve: BezierCurve<f64> = BezierCurve::from_coords(b.iter().map(|x| vec![*x]).collect()).unwrap();
                lerp.ulps.push(ulp_error(curve.eval(&t).coords()[0], &p).unwrap().ulps);
                // compensated
                let (c, _) = compensated_de_casteljau(&b, t);
                let g = gamma_exact(3 * n);
                let cbound = q(UNIT_ROUNDOFF) * Signed::abs(&p) + &g * &g * &sum;
                if err(c) > cbound {
                    violations[2] += 1;
                }
                let cu = ulp_error(c, &p).unwrap().ulps;
                if set == "random" {
                    random_total += 1;
                    if cu > 1 {
                        violations[4] += 1;
                    }
                }
                comp.ulps.push(cu);
                comp.ratio.push(Scalar::to_f64(&(err(c) / &cbound)));
                // intervals through the generic algorithm
                let iv: BezierCurve<Interval> =
                    BezierCurve::from_coords(b.iter().map(|x| vec![Interval::from_f64(*x).unwrap()]).collect())
                        .unwrap();
                if !iv.eval(&Interval::from_f64(t).unwrap()).coords()[0].contains(&p) {
                    violations[3] += 1;
                }
                if n == 3 {
                    let pt = |x: f64| kurbo::Point::new(x, 0.0);
                    let k = CubicBez::new(pt(b[0]), pt(b[1]), pt(b[2]), pt(b[3])).eval(t).x;
                    kurbo_stats.ulps.push(ulp_error(k, &p).unwrap().ulps);
                }
            }
            println!("{}", plain.row(set, n, "f64 de Casteljau"));
            println!("{}", lerp.row(set, n, "f64 `BezierCurve::eval`"));
            println!("{}", comp.row(set, n, "compensated"));
            if n == 3 {
                println!("{}", kurbo_stats.row(set, n, "kurbo `CubicBez::eval`"));
            }
        }
    }
    println!();
    println!(
        "bound violations (checked exactly): a priori {}, running {}, compensated {}; interval misses {}",
        violations[0], violations[1], violations[2], violations[3]
    );
    println!(
        "compensated within 1 ulp of the correctly rounded value: {} of {} random cases ({:.3}%)",
        random_total - violations[4],
        random_total,
        100.0 * (random_total - violations[4]) as f64 / random_total as f64
    );
    if violations[..4].iter().any(|&v| v > 0) {
        std::process::exit(1);
    }
}
