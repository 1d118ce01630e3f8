//! The one error type of casteljau.
//!
//! Every API that takes user data returns [`Result`], never panics on bad input: empty
//! polygons, mismatched dimensions, zero denominators, absurd sizes all come back as an
//! [`Error`] whose `Display` says in plain words what is wrong.

use thiserror::Error as ThisError;

/// Largest degree any curve or surface may reach (after elevation too), in the library, the
/// command line and the oracle alike.
///
/// Bernstein algorithms are quadratic in the degree and exact binomials grow linearly in
/// bits, so past this size a request is far more likely a typo than an intent.
pub const MAX_DEGREE: usize = 4_096;

/// Largest number of coordinates a point may have.
pub const MAX_DIMENSION: usize = 1_024;

/// What went wrong, in words a person understands.
#[derive(Debug, Clone, PartialEq, Eq, ThisError)]
#[non_exhaustive]
pub enum Error {
    /// A control polygon, net or point list had no points at all.
    #[error("empty input: {0} needs at least one point")]
    Empty(&'static str),
    /// Too few points for what was asked (for example a conic needs exactly three).
    #[error("{what} needs {needed} points, got {got}")]
    WrongCount {
        /// what was being built
        what: &'static str,
        /// how many were needed
        needed: usize,
        /// how many were given
        got: usize,
    },
    /// Points of different dimensions were mixed.
    #[error("dimension mismatch: expected {expected} coordinates, found {found} (at {context})")]
    DimensionMismatch {
        /// the dimension of the first point
        expected: usize,
        /// the offending dimension
        found: usize,
        /// where it was found
        context: String,
    },
    /// A point with zero coordinates.
    #[error("a point needs at least one coordinate")]
    ZeroDimension,
    /// Division by an exact or floating zero.
    #[error("division by zero: {0}")]
    DivisionByZero(String),
    /// A NaN or infinite float where a finite number is required.
    #[error("not a finite number: {0}")]
    NotFinite(String),
    /// A size beyond the documented limits.
    #[error("{what} is too large: {value} (limit {limit})")]
    TooLarge {
        /// what was too large
        what: &'static str,
        /// the requested size, as written
        value: String,
        /// the limit
        limit: String,
    },
    /// A derivative order higher than the degree where the caller needs a meaningful curve.
    #[error("derivative of order {order} asked of a degree-{degree} curve (order must be at most the degree)")]
    DerivativeOrder {
        /// the requested order
        order: usize,
        /// the degree of the curve
        degree: usize,
    },
    /// Barycentric weights whose sum is not exactly one.
    #[error("barycentric weights must sum to 1, they sum to {0}")]
    NotAffine(String),
    /// A parameter or argument outside its allowed domain.
    #[error("{0}")]
    Domain(String),
    /// A linear system without a unique solution.
    #[error("singular system: {0}")]
    Singular(String),
    /// Text that could not be parsed.
    #[error("parse error: {0}")]
    Parse(String),
    /// Numbers of two different quadratic fields, such as √2 and √3, were mixed.
    #[error("cannot mix quadratic irrationals of different fields: sqrt({0}) and sqrt({1})")]
    MixedField(i64, i64),
}

/// `Result` with casteljau's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;

/// Checks that a degree (or a degree after elevation) stays within [`MAX_DEGREE`].
#[inline]
pub fn check_degree(what: &'static str, degree: u128) -> Result<usize> {
    if degree > MAX_DEGREE as u128 {
        return Err(Error::TooLarge {
            what,
            value: degree.to_string(),
            limit: MAX_DEGREE.to_string(),
        });
    }
    Ok(degree as usize)
}
