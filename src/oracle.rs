//! (stub: oracle — filled by its issue)
