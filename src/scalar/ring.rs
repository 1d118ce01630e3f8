//! [`Ring`]: the arithmetic every number of casteljau has, the scalars of the geometry and
//! the prover's degree bounds and rational functions alike.

use num_rational::BigRational;
use num_traits::{One, Zero};
use std::fmt::{Debug, Display};

/// A commutative ring with the integers in it: `0`, `1`, `n`, and `+ − ×` on references.
///
/// The arithmetic is a method on `&self` (`a.mul_ref(&b)`) so that generic code needs no
/// bound on `&T`: a bound like `for<'a> &'a T: Mul<&'a T>` is not implied by any trait of
/// `T` and would have to be repeated on every generic item. casteljau's own number types get
/// their operators (`&a * &b`, `a += &b`, ...) from these methods, by one macro.
///
/// ```
/// use casteljau::{BigRational, Ring};
/// let half = BigRational::new(1.into(), 2.into());
/// assert_eq!(half.add_ref(&half), <BigRational as Ring>::one());
/// assert_eq!(half.sub_ref(&half).neg_ref(), <BigRational as Ring>::zero());
/// assert_eq!(<f64 as Ring>::from_i64(3).mul_ref(&0.5), 1.5);
/// ```
pub trait Ring: Clone + Debug + Display {
    /// The additive identity.
    fn zero() -> Self;
    /// The multiplicative identity.
    fn one() -> Self;
    /// The integer `n`.
    fn from_i64(n: i64) -> Self;
    /// `self + rhs`
    fn add_ref(&self, rhs: &Self) -> Self;
    /// `self - rhs`
    fn sub_ref(&self, rhs: &Self) -> Self;
    /// `self * rhs`
    fn mul_ref(&self, rhs: &Self) -> Self;
    /// `-self`
    fn neg_ref(&self) -> Self;
}

impl Ring for f64 {
    #[inline]
    fn zero() -> Self {
        0.0
    }
    #[inline]
    fn one() -> Self {
        1.0
    }
    #[inline]
    fn from_i64(n: i64) -> Self {
        n as f64
    }
    #[inline]
    fn add_ref(&self, rhs: &Self) -> Self {
        self + rhs
    }
    #[inline]
    fn sub_ref(&self, rhs: &Self) -> Self {
        self - rhs
    }
    #[inline]
    fn mul_ref(&self, rhs: &Self) -> Self {
        self * rhs
    }
    #[inline]
    fn neg_ref(&self) -> Self {
        -self
    }
}

impl Ring for BigRational {
    fn zero() -> Self {
        Zero::zero()
    }
    fn one() -> Self {
        One::one()
    }
    fn from_i64(n: i64) -> Self {
        BigRational::from_integer(n.into())
    }
    #[inline]
    fn add_ref(&self, rhs: &Self) -> Self {
        self + rhs
    }
    #[inline]
    fn sub_ref(&self, rhs: &Self) -> Self {
        self - rhs
    }
    #[inline]
    fn mul_ref(&self, rhs: &Self) -> Self {
        self * rhs
    }
    #[inline]
    fn neg_ref(&self) -> Self {
        -self
    }
}
