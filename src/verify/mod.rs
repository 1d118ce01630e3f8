//! (stub: verify — filled by its issue)
