//! (stub: rational — filled by its issue)
