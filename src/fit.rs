//! (stub: fit — filled by its issue)
