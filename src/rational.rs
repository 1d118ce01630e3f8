//! Rational Bézier curves (stub in progress)
