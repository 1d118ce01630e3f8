//! (stub: surface — filled by its issue)
