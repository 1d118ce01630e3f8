//! (stub: input — filled by its issue)
