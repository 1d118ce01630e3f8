//! A small deterministic generator (xorshift64*) for the float experiments, so that a failing
//! case reproduces from its seed. Shared by `tests/float_bounds.rs` and
//! `scripts/float_errors.rs`, which run the same random sets.

pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}
