//! Random and adversarial cases at the edges of the f64 range (subnormal coefficients, tiny
//! parameters, coefficients near 1e308, near-cancellation, mixed scales) and the checks run on
//! them: every method's float answer against its bound (decided exactly) and against the
//! bound's derived formula in rationals, interval enclosures, filtered predicates against
//! exact ones. Shared by `tests/float_edges.rs` and `scripts/float_edges.rs`.

#![allow(dead_code)]

use casteljau::float::{
    binomials, error_at_most, eval_dyadic, gamma_exact, nearest_f64, power_coefficients, UNIT_ROUNDOFF,
};
use casteljau::oracle::FloatMethod;
use casteljau::{filtered_orientation, interval_de_casteljau, tight_interval_de_casteljau, Interval};
use casteljau::{BezierCurve, BigRational};
use num_traits::{One, Signed, Zero};

fn one() -> BigRational {
    <BigRational as One>::one()
}

fn zero() -> BigRational {
    <BigRational as Zero>::zero()
}
use std::cmp::Ordering;

use super::rng::Rng;

/// The methods judged, in the order of the counts.
pub const METHODS: [FloatMethod; 5] = [
    FloatMethod::DeCasteljau,
    FloatMethod::Lerp,
    FloatMethod::Horner,
    FloatMethod::Bernstein,
    FloatMethod::Compensated,
];

/// The case families.
pub const FAMILIES: [&str; 6] = [
    "random",
    "subnormal",
    "tiny t",
    "near 1e308",
    "cancellation",
    "mixed scales",
];

/// Counts of one run.
#[derive(Default, Debug)]
pub struct Counts {
    pub cases: usize,
    /// per method: answers judged, outside the float bound, outside the derived formula,
    /// overflowed (±inf or NaN, judged as such)
    pub judged: [usize; 5],
    pub outside: [usize; 5],
    pub formula_violations: [usize; 5],
    pub formula_checked: [usize; 5],
    pub overflowed: [usize; 5],
    pub intervals: usize,
    pub intervals_missing: usize,
    pub predicates: usize,
    pub predicates_wrong: usize,
    /// the first failures, for the message
    pub failures: Vec<String>,
}

impl Counts {
    pub fn ok(&self) -> bool {
        self.outside.iter().sum::<usize>() == 0
            && self.formula_violations.iter().sum::<usize>() == 0
            && self.intervals_missing == 0
            && self.predicates_wrong == 0
    }

    fn fail(&mut self, what: String) {
        if self.failures.len() < 10 {
            self.failures.push(what);
        }
    }

    pub fn report(&self) -> String {
        let mut out = format!("{} cases\n", self.cases);
        out.push_str("| method | judged | outside its bound | formula checked | outside the formula | overflowed |\n");
        out.push_str("|---|---|---|---|---|---|\n");
        for (k, m) in METHODS.iter().enumerate() {
            out.push_str(&format!(
                "| {} | {} | {} | {} | {} | {} |\n",
                m.as_str(),
                self.judged[k],
                self.outside[k],
                self.formula_checked[k],
                self.formula_violations[k],
                self.overflowed[k]
            ));
        }
        out.push_str(&format!(
            "intervals: {} enclosures, {} missing the exact value\n",
            self.intervals, self.intervals_missing
        ));
        out.push_str(&format!(
            "filtered orientation: {} predicates, {} disagreeing with the exact one\n",
            self.predicates, self.predicates_wrong
        ));
        for f in &self.failures {
            out.push_str(&format!("failure: {f}\n"));
        }
        out
    }
}

fn q(x: f64) -> BigRational {
    BigRational::from_float(x).unwrap()
}

/// A float with a random sign, mantissa and binary exponent in `[lo, hi]` (subnormals when
/// the exponent is below −1022).
fn scaled(rng: &mut Rng, lo: i32, hi: i32) -> f64 {
    let e = lo + (rng.next() % (hi - lo + 1) as u64) as i32;
    let m = 1.0 + rng.unit();
    let x = if e < -1022 {
        // 2^e·m built in two steps so the subnormal is rounded once
        m * 2f64.powi(e + 100) * 2f64.powi(-100)
    } else {
        m * 2f64.powi(e.min(1023))
    };
    let x = if x.is_finite() { x } else { f64::MAX };
    if rng.next() % 2 == 0 {
        -x
    } else {
        x
    }
}

/// A parameter in [0, 1]: one of the hard ones once in `one_in` (never for 0), else uniform.
fn parameter(rng: &mut Rng, one_in: u64) -> f64 {
    let tiny = one_in == 1 || (one_in > 1 && rng.next() % one_in == 0);
    if tiny {
        match rng.next() % 6 {
            0 => 5e-324,
            1 => f64::from_bits(1 + rng.next() % 1_000_000),
            2 => 1e-300,
            3 => rng.unit() * 1e-200,
            4 => f64::MIN_POSITIVE,
            _ => 1.0 - f64::EPSILON / 2.0,
        }
    } else {
        rng.unit()
    }
}

/// Coefficients of `(t − r)^n` in the Bernstein basis, rounded, times `2^k`.
fn cancellation(n: usize, r: f64, k: i32) -> Vec<f64> {
    (0..=n)
        .map(|i| {
            let v = (-q(r)).pow((n - i) as i32) * (one() - q(r)).pow(i as i32);
            nearest_f64(&v) * 2f64.powi(k)
        })
        .collect()
}

/// Case `i` of a run: `(family, coefficients, t)`.
pub fn case(rng: &mut Rng, i: usize) -> (usize, Vec<f64>, f64) {
    let family = i % FAMILIES.len();
    let n = [1usize, 2, 3, 5, 8, 13, 20][rng.next() as usize % 7];
    let (b, t) = match family {
        0 => ((0..=n).map(|_| 2.0 * rng.unit() - 1.0).collect(), parameter(rng, 0)),
        1 => ((0..=n).map(|_| scaled(rng, -1074, -1000)).collect(), parameter(rng, 2)),
        2 => {
            let b = if rng.next() % 2 == 0 {
                (0..=n).map(|_| 2.0 * rng.unit() - 1.0).collect()
            } else {
                (0..=n).map(|_| scaled(rng, -1074, -900)).collect()
            };
            (b, parameter(rng, 1))
        }
        3 => (
            (0..=n)
                .map(|_| {
                    let x = f64::MAX * (0.5 + 0.5 * rng.unit());
                    if rng.next() % 2 == 0 {
                        -x
                    } else {
                        x
                    }
                })
                .collect(),
            parameter(rng, 4),
        ),
        4 => {
            let n = n.clamp(2, 10);
            let r = 0.2 + 0.6 * rng.unit();
            let k = [-1060, -1000, -500, 0, 500, 1000][rng.next() as usize % 6];
            let t = r + (rng.unit() - 0.5) * 10f64.powi(-(1 + (rng.next() % 8) as i32));
            (cancellation(n, r, k), t)
        }
        _ => ((0..=n).map(|_| scaled(rng, -1074, 1023)).collect(), parameter(rng, 3)),
    };
    (family, b, t)
}

fn curve(b: &[BigRational]) -> BezierCurve<BigRational> {
    BezierCurve::from_coords(b.iter().map(|x| vec![x.clone()]).collect()).unwrap()
}

fn exact_at(b: &[f64], t: f64) -> BigRational {
    let c = curve(&b.iter().map(|x| q(*x)).collect::<Vec<_>>());
    eval_dyadic(&c, &q(t)).unwrap().coords()[0].clone()
}

/// `Σ b_i W_i` for de Casteljau's triangle with weights `(wa, wb)` (exact).
fn triangle(b: &[BigRational], wa: &BigRational, wb: &BigRational) -> BigRational {
    let mut buf = b.to_vec();
    let n = b.len() - 1;
    for r in 1..=n {
        for i in 0..=n - r {
            buf[i] = wa * &buf[i] + wb * &buf[i + 1];
        }
    }
    buf[0].clone()
}

fn int(n: usize) -> BigRational {
    BigRational::from_integer(n.into())
}

/// The derived bound of `method` as a formula in rationals (see docs/float-bounds.md).
pub fn formula(method: FloatMethod, b: &[f64], t: f64, p: &BigRational) -> BigRational {
    let n = b.len() - 1;
    if n == 0 {
        return zero();
    }
    let eta = q(5e-324);
    let margin = one() + BigRational::new(1.into(), 1_000_000_000.into());
    let one = one();
    let (tq, sq) = (q(t), q(1.0 - t));
    let alpha = Signed::abs(&(&one - &tq));
    let beta = Signed::abs(&tq);
    let abs_b: Vec<BigRational> = b.iter().map(|x| q(f64::abs(*x))).collect();
    let s_sum = triangle(&abs_b, &alpha, &beta);
    let max1 = |x: BigRational| if x < one { one.clone() } else { x };
    // n(n+1)/2 · G^{n−1} · 2^−1074 · (1 + 10^−9), G = max(1, growth)
    let under = |per_node: BigRational, growth: BigRational| {
        per_node * int(n * (n + 1)) / int(2) * max1(growth).pow(n as i32 - 1) * &eta * &margin
    };
    let convex_growth = Signed::abs(&sq) + &beta;
    match method {
        FloatMethod::DeCasteljau => {
            let k = if sq == &one - &tq { 2 * n } else { 3 * n };
            gamma_exact(k) * &s_sum + under(one.clone(), convex_growth)
        }
        FloatMethod::Lerp => {
            let wa = &alpha + &beta;
            let lerp_sum = triangle(&abs_b, &wa, &beta);
            gamma_exact(4 * n) * lerp_sum + under(one.clone(), &wa + &beta)
        }
        FloatMethod::Horner => {
            let a = power_coefficients(b);
            if a.iter().any(|x| !x.is_finite()) {
                return BigRational::from_integer(num_bigint::BigInt::from(1) << 2000usize);
            }
            let mut sum = zero();
            for x in a.iter().rev() {
                sum = sum * &beta + q(f64::abs(*x));
            }
            gamma_exact(2 * n + 1) * sum + int(n + 1) * max1(beta.clone()).pow(n as i32) * &eta * &margin
        }
        FloatMethod::Bernstein => {
            let c = binomials(n);
            let (gt, gs) = (max1(beta.clone()), max1(Signed::abs(&sq)));
            let mut u = zero();
            for (i, bi) in b.iter().enumerate() {
                u += q(c[i]) * gt.pow(i as i32) * gs.pow((n - i) as i32) * max1(q(f64::abs(*bi)));
            }
            gamma_exact(3 * n + 2) * &s_sum + u * int(n + 1) / int(2) * &eta * &margin
        }
        FloatMethod::Compensated | FloatMethod::Interval => {
            let g = gamma_exact(3 * n);
            q(UNIT_ROUNDOFF) * Signed::abs(p) + int(2) * &g * &g * &s_sum + under(int(3), convex_growth)
        }
    }
}

fn exact_orientation(p: [f64; 2], r: [f64; 2], s: [f64; 2]) -> Ordering {
    let det = (q(r[0]) - q(p[0])) * (q(s[1]) - q(p[1])) - (q(r[1]) - q(p[1])) * (q(s[0]) - q(p[0]));
    det.cmp(&zero())
}

/// Three points for an orientation test, from the same families.
fn triangle_points(rng: &mut Rng, family: usize) -> [[f64; 2]; 3] {
    let pt = |rng: &mut Rng| match family {
        0 | 4 => [rng.unit(), rng.unit()],
        1 | 2 => [scaled(rng, -1074, -990), scaled(rng, -1074, -990)],
        3 => [scaled(rng, 1015, 1023), scaled(rng, 1015, 1023)],
        _ => [scaled(rng, -1074, 1023), scaled(rng, -1074, 1023)],
    };
    let (p, r) = (pt(rng), pt(rng));
    // every other third point on the line p r up to rounding: the hard cases
    let s = if rng.next() % 2 == 0 {
        let a = rng.unit();
        [p[0] + a * (r[0] - p[0]), p[1] + a * (r[1] - p[1])]
    } else {
        pt(rng)
    };
    let s = if s.iter().all(|x| x.is_finite()) { s } else { pt(rng) };
    [p, r, s]
}

/// Runs `cases` cases from `seed`; the derived formulas are checked on every `formula_every`-th.
pub fn run(seed: u64, cases: usize, formula_every: usize) -> Counts {
    let mut rng = Rng(seed);
    let mut c = Counts::default();
    for i in 0..cases {
        let (family, b, t) = case(&mut rng, i);
        c.cases += 1;
        let p = exact_at(&b, t);
        let near = nearest_f64(&p);
        for (k, m) in METHODS.iter().enumerate() {
            let value = m.run(&b, t);
            if !value.is_finite() {
                c.overflowed[k] += 1;
                continue;
            }
            c.judged[k] += 1;
            let bound = m.bound(&b, t, near);
            if !error_at_most(value, &p, bound) {
                c.outside[k] += 1;
                c.fail(format!("{} outside its bound {bound:e}: {b:?} at {t:e}", m.as_str()));
            }
            if i % formula_every == 0 {
                c.formula_checked[k] += 1;
                let err = Signed::abs(&(q(value) - &p));
                if err > formula(*m, &b, t, &p) {
                    c.formula_violations[k] += 1;
                    c.fail(format!("{} outside its formula: {b:?} at {t:e}", m.as_str()));
                }
            }
        }
        // intervals: the convex form, and the generic algorithm when it stays finite
        for conv in [
            interval_de_casteljau(&b, t).unwrap(),
            tight_interval_de_casteljau(&b, t).unwrap(),
        ] {
            c.intervals += 1;
            if !conv.contains(&p) {
                c.intervals_missing += 1;
                c.fail(format!("interval {conv} misses the exact value: {b:?} at {t:e}"));
            }
        }
        let iv: BezierCurve<Interval> =
            BezierCurve::from_coords(b.iter().map(|x| vec![Interval::point(*x).unwrap()]).collect()).unwrap();
        let g = iv.eval(&Interval::point(t).unwrap()).coords()[0];
        c.intervals += 1;
        if !g.contains(&p) {
            c.intervals_missing += 1;
            c.fail(format!("generic interval {g} misses the exact value: {b:?} at {t:e}"));
        }
        let [p0, p1, p2] = triangle_points(&mut rng, family);
        c.predicates += 1;
        if filtered_orientation(p0, p1, p2).unwrap() != exact_orientation(p0, p1, p2) {
            c.predicates_wrong += 1;
            c.fail(format!("orientation of {p0:?} {p1:?} {p2:?}"));
        }
    }
    c
}
