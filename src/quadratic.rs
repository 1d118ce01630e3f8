//! (stub: quadratic — filled by its issue)
