//! (stub: strategies — filled by its issue)
