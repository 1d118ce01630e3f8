//! Work linear in the degree takes time linear in the degree on big numbers: one elevation
//! step and the first derivative of curves whose coordinates are 100-digit fractions, each
//! over its own denominator. A kernel that puts the whole curve over one common denominator
//! makes every point `n` times longer and these operations quadratic (elevation by 1 was).

use casteljau::{BezierCurve, BigInt, BigRational, Point};
use std::sync::Mutex;
use std::time::Duration;

// CPU time of the timing thread, not wall time: on a loaded machine the wall counts the other
// processes too.
#[path = "support/cpu.rs"]
mod cpu;
use cpu::thread_cpu;

/// One timing at a time: tests run on parallel threads, and a measurement taken while
/// another test computes is the other test's too.
static TIMING: Mutex<()> = Mutex::new(());

/// A deterministic stream (splitmix64).
struct Stream(u64);

impl Stream {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A 100-digit positive integer.
    fn hundred_digits(&mut self) -> BigInt {
        let mut digits = String::from("1");
        while digits.len() < 100 {
            digits.push_str(&format!("{:019}", self.next() % 10_000_000_000_000_000_000));
        }
        digits.truncate(100);
        digits.parse().expect("digits")
    }
}

/// A planar curve of degree `n`: 100-digit numerators, random signs, over 100-digit
/// denominators (distinct with overwhelming probability).
fn curve(n: usize, seed: u64) -> BezierCurve<BigRational> {
    let mut s = Stream(seed);
    let points = (0..=n)
        .map(|_| {
            let coords = (0..2)
                .map(|_| {
                    let num = s.hundred_digits();
                    let num = if s.next() & 1 == 1 { -num } else { num };
                    BigRational::new(num, s.hundred_digits())
                })
                .collect();
            Point::new(coords).expect("two coordinates")
        })
        .collect();
    BezierCurve::new(points).expect("a valid curve")
}

/// The least of five CPU timings of `f` (the others are the machine's noise: caches shared
/// with other processes slow a thread's CPU time too).
fn least_time(mut f: impl FnMut()) -> Duration {
    (0..5)
        .map(|_| {
            let start = thread_cpu();
            f();
            thread_cpu() - start
        })
        .min()
        .expect("five runs")
}

/// Time at degree 800 over time at degree 100: 8 when linear, 64 when quadratic (caches and
/// the allocator make the larger case somewhat slower per point than linear).
fn growth(op: impl Fn(&BezierCurve<BigRational>)) -> f64 {
    let (small, large) = (curve(100, 1), curve(800, 2));
    let _alone = TIMING.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    let a = least_time(|| op(&small));
    let b = least_time(|| op(&large));
    b.as_secs_f64() / a.as_secs_f64()
}

#[test]
fn one_elevation_step_is_linear_in_the_degree() {
    let ratio = growth(|c| {
        std::hint::black_box(c.elevate_by(1).unwrap());
    });
    assert!(ratio < 48.0, "elevate_by(1): degree 800 took {ratio:.1}× degree 100");
    let ratio = growth(|c| {
        std::hint::black_box(c.elevate().unwrap());
    });
    assert!(ratio < 48.0, "elevate: degree 800 took {ratio:.1}× degree 100");
}

#[test]
fn the_first_derivative_is_linear_in_the_degree() {
    let ratio = growth(|c| {
        std::hint::black_box(c.derivative(1).unwrap());
    });
    assert!(ratio < 48.0, "derivative(1): degree 800 took {ratio:.1}× degree 100");
}

#[test]
fn elevation_by_steps_equals_the_closed_form() {
    // The kernel's paths for r = 1 (one pairwise step) and r ≥ 2 (the closed form) against (8) on the
    // scalar type.
    let c = curve(6, 3);
    for r in [1, 2, 5, 6, 7, 12] {
        assert_eq!(c.elevate_by(r).unwrap(), c.elevate_by_reference(r).unwrap(), "r = {r}");
    }
}
