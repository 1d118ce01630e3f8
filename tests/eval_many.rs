//! `eval_many` and `sample` give, at every parameter, the bits of the per-point `eval`: on
//! curves of every degree up to past the stack column, in 1 to 3 dimensions, at parameters
//! inside and outside [0, 1] (zeros, subnormals, large values), for any number of parameters
//! (whole groups of `LANES` and a rest).

use casteljau::{Bezier, BezierN, Cubic, Error, Point2, PointN, Quad, LANES};

/// xorshift64*: a fixed stream of floats of varied magnitudes and signs.
struct Stream(u64);

impl Stream {
    fn bits(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn unit(&mut self) -> f64 {
        (self.bits() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn coord(&mut self) -> f64 {
        let scale = [1.0, 1e-3, 1e6, 1e-300, 1e300][(self.bits() % 5) as usize];
        (self.unit() * 2.0 - 1.0) * scale
    }
    fn param(&mut self) -> f64 {
        match self.bits() % 8 {
            0 => 0.0,
            1 => 1.0,
            2 => 5e-324,
            3 => self.unit() * 4.0 - 2.0,
            4 => -0.0,
            _ => self.unit(),
        }
    }
}

fn bits<const D: usize>(p: &PointN<f64, D>) -> [u64; D] {
    p.0.map(f64::to_bits)
}

fn check_any<const D: usize>(rng: &mut Stream, points: usize) {
    let curve =
        Bezier::from_points((0..points).map(|_| PointN::<f64, D>(std::array::from_fn(|_| rng.coord())))).unwrap();
    for count in [0, 1, LANES - 1, LANES, LANES + 3, 5 * LANES, 101] {
        let ts: Vec<f64> = (0..count).map(|_| rng.param()).collect();
        let many = curve.sample(&ts);
        assert_eq!(many.len(), count);
        for (t, p) in ts.iter().zip(&many) {
            assert_eq!(
                bits(p),
                bits(&curve.eval(t)),
                "{points} points, {D} coordinates, t = {t:e}"
            );
        }
    }
}

fn check_fixed<const D: usize, const N: usize>(rng: &mut Stream) {
    let curve: BezierN<PointN<f64, D>, N> =
        BezierN::new(std::array::from_fn(|_| PointN(std::array::from_fn(|_| rng.coord()))));
    let any = Bezier::from(curve);
    let ts: Vec<f64> = (0..3 * LANES + 5).map(|_| rng.param()).collect();
    let mut out = vec![PointN([f64::NAN; D]); ts.len()];
    curve.eval_many(&ts, &mut out).unwrap();
    for (t, p) in ts.iter().zip(&out) {
        assert_eq!(bits(p), bits(&curve.eval(t)), "{N} points, t = {t:e}");
        assert_eq!(bits(p), bits(&any.eval(t)), "{N} points, t = {t:e}");
    }
}

#[test]
fn any_degree_many_equals_each_bit_for_bit() {
    let mut rng = Stream(0x9e37_79b9_7f4a_7c15);
    for _ in 0..20 {
        for points in [1, 2, 3, 4, 5, 8, 21, 24, 25, 40] {
            check_any::<2>(&mut rng, points);
        }
        check_any::<1>(&mut rng, 4);
        check_any::<3>(&mut rng, 4);
        check_any::<3>(&mut rng, 11);
    }
}

#[test]
fn fixed_degree_many_equals_each_bit_for_bit() {
    let mut rng = Stream(0x0123_4567_89ab_cdef);
    for _ in 0..200 {
        check_fixed::<2, 1>(&mut rng);
        check_fixed::<2, 2>(&mut rng);
        check_fixed::<2, 3>(&mut rng);
        check_fixed::<2, 4>(&mut rng);
        check_fixed::<3, 4>(&mut rng);
        check_fixed::<2, 7>(&mut rng);
        check_fixed::<2, 17>(&mut rng);
    }
}

#[test]
fn nan_and_infinite_parameters_give_what_eval_gives() {
    let c = Cubic::new([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]].map(Point2::from));
    let ts = [
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        0.5,
        1e308,
        -1e308,
        0.25,
        0.75,
    ];
    let many = c.sample(&ts);
    for (t, p) in ts.iter().zip(&many) {
        assert_eq!(bits(p), bits(&c.eval(t)), "t = {t}");
    }
}

#[test]
fn an_output_of_the_wrong_length_is_an_error_and_untouched() {
    let q = Quad::new([[0.0, 0.0], [1.0, 2.0], [3.0, 0.5]].map(Point2::from));
    let ts = [0.1; 10];
    let mut out = vec![Point2::new(7.0, 7.0); 9];
    let err = q.eval_many(&ts, &mut out).unwrap_err();
    assert_eq!(
        err,
        Error::WrongCount {
            what: "the output of eval_many (one point per parameter)",
            needed: 10,
            got: 9
        }
    );
    assert!(out.iter().all(|p| *p == Point2::new(7.0, 7.0)));
    assert!(Bezier::from(q).eval_many(&ts, &mut out).is_err());
    assert!(out.iter().all(|p| *p == Point2::new(7.0, 7.0)));
}
