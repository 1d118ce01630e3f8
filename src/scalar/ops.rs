//! The operators of casteljau's own number types, written once.

/// Implements `+ − ×` for the four combinations of values and references, `+= −= ×=` for
/// a value and a reference, and unary `−` for both, all from the type's [`Ring`] methods
/// (num-rational's pattern: the arithmetic is written once, on references).
///
/// [`Ring`]: crate::scalar::Ring
macro_rules! forward_ring_ops {
    ($T:ty) => {
        $crate::scalar::forward_ring_ops!(@binary $T, Add, add, AddAssign, add_assign, add_ref);
        $crate::scalar::forward_ring_ops!(@binary $T, Sub, sub, SubAssign, sub_assign, sub_ref);
        $crate::scalar::forward_ring_ops!(@binary $T, Mul, mul, MulAssign, mul_assign, mul_ref);
        impl ::std::ops::Neg for $T {
            type Output = $T;
            #[inline]
            fn neg(self) -> $T {
                $crate::scalar::Ring::neg_ref(&self)
            }
        }
        impl ::std::ops::Neg for &$T {
            type Output = $T;
            #[inline]
            fn neg(self) -> $T {
                $crate::scalar::Ring::neg_ref(self)
            }
        }
    };
    (@binary $T:ty, $Op:ident, $op:ident, $OpAssign:ident, $op_assign:ident, $method:ident) => {
        impl ::std::ops::$Op<&$T> for &$T {
            type Output = $T;
            #[inline]
            fn $op(self, rhs: &$T) -> $T {
                $crate::scalar::Ring::$method(self, rhs)
            }
        }
        impl ::std::ops::$Op<&$T> for $T {
            type Output = $T;
            #[inline]
            fn $op(self, rhs: &$T) -> $T {
                $crate::scalar::Ring::$method(&self, rhs)
            }
        }
        impl ::std::ops::$Op<$T> for &$T {
            type Output = $T;
            #[inline]
            fn $op(self, rhs: $T) -> $T {
                $crate::scalar::Ring::$method(self, &rhs)
            }
        }
        impl ::std::ops::$Op<$T> for $T {
            type Output = $T;
            #[inline]
            fn $op(self, rhs: $T) -> $T {
                $crate::scalar::Ring::$method(&self, &rhs)
            }
        }
        impl ::std::ops::$OpAssign<&$T> for $T {
            #[inline]
            fn $op_assign(&mut self, rhs: &$T) {
                *self = $crate::scalar::Ring::$method(self, rhs);
            }
        }
        impl ::std::ops::$OpAssign<$T> for $T {
            #[inline]
            fn $op_assign(&mut self, rhs: $T) {
                *self = $crate::scalar::Ring::$method(self, &rhs);
            }
        }
    };
}

pub(crate) use forward_ring_ops;
