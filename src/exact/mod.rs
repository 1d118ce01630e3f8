//! Exact arithmetic at integer speed: what runs inside the exact hot loops.
//!
//! [`BigRational`](num_rational::BigRational) is the exact type users exchange; inside, the
//! cheapest representation wins, chosen by measurement (`benches/exact.rs`):
//! - [`small_rational`]: [`SmallRational`], an exact [`Scalar`](crate::Scalar) on machine
//!   words that moves to big integers only when a value does not fit;
//! - [`fraction_free`]: eval, derivatives, scheme, split, elevation, rational curves and
//!   surfaces over integers with one common denominator and one reduction at the end;
//! - [`basis_table`]: [`BernsteinTable`], Bernstein rows at integer and rational parameters,
//!   computed once and shared across threads;
//! - [`gcd`]: Lehmer's gcd, the part-by-part reduction the kernels end with, and the
//!   quotient of two fractions;
//! - `fit_numbers`: text 004's cubic fit over integers, one reduction per number;
//! - `splitting`: the exact Bernstein sum on big integers by binary splitting (what `eval`
//!   runs when machine words overflow), reduced through a remainder tree;
//! - `power_basis`: `to_power` of curves and surfaces, differences over the lcm of the
//!   denominators and one reduction per coefficient;
//! - `elevation_words`: one elevation step point by point, each coordinate on machine
//!   words where it fits 256 bits, and `long_pair` the same pair on up to 16 words on the
//!   stack.
//!
//! The public generic methods reach these kernels through the kernel methods of
//! `BigRational`'s [`Scalar`](crate::Scalar) implementation.

pub mod basis_table;
pub(crate) mod elevation_words;
pub(crate) mod fit_numbers;
pub mod fraction_free;
pub mod gcd;
pub(crate) mod hensel;
pub(crate) mod long_pair;
pub(crate) mod power_basis;
pub mod small_rational;
pub(crate) mod splitting;

pub use basis_table::{BernsteinTable, RationalBasisRow};
pub use small_rational::SmallRational;
