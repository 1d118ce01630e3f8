//! Certified floating point: ulps measured exactly, error-free transformations, de Casteljau
//! with a priori and running error bounds, and compensated de Casteljau.
//!
//! The exact side of casteljau judges float code: [`ulp_error`] measures a float against an
//! exact value; [`a_priori_bound`] and [`de_casteljau_running`] say how large the error of
//! de Casteljau's algorithm may be; [`compensated_de_casteljau`] makes it about as accurate as
//! the correctly rounded value, for curves, their derivatives and tensor-product surfaces
//! ([`compensated_surface`]). Other programs' evaluation orders have their own a priori
//! bounds ([`lerp_bound`], [`horner_bound`], [`bernstein_bound`]). Every bound holds on the
//! whole `f64` range, underflow included, and is checked exactly, in rationals, by the tests.

mod casteljau;
mod compensated;
mod compensated_pairs;
mod dispatch;
mod dyadic;
mod eft;
mod methods;
mod ops;
mod scratch;
mod ulp;

pub use casteljau::{
    a_priori_bound, a_priori_index, abs_bernstein_sum, de_casteljau, de_casteljau_running, gamma, gamma_exact,
    next_down, next_up, rational_a_priori_bound, surface_a_priori_bound, underflow_term, UNIT_ROUNDOFF,
};
pub(crate) use casteljau::{add_up, gamma_computed};
pub use compensated::{
    compensated_a_priori_bound, compensated_de_casteljau, compensated_de_casteljau_by, compensated_derivative,
    compensated_surface,
};
pub(crate) use dispatch::{enclose_fixed, enclose_points};
pub use dyadic::{dyadic_ratio, eval_dyadic};
pub use eft::{fast_two_sum, two_product, two_product_dekker, two_product_fma, two_sum, TWO_PRODUCT_METHOD};
pub(crate) use eft::{ExactRange, Factor};
pub use methods::{
    bernstein_bound, bernstein_sum, binomials, condition_number, horner, horner_bound, lerp_bound, lerp_de_casteljau,
    power_coefficients,
};
pub use ops::{
    derivative_bounds, elevate_bounds, split_bounds, to_bezier_bounds, OpBound, SplitForm, TO_BEZIER_MAX_DEGREE,
};
pub(crate) use scratch::with_scratch;
pub use scratch::STACK_COEFFICIENTS;
pub use ulp::{
    decompose, error_at_most, exact_f64, f64_to_rational, nearest_f64, pow2_exact, round_scaled, scale_pow2_up, ulp,
    ulp_distance, ulp_error, ulp_exponent, ulp_exponent_f64, UlpError,
};
