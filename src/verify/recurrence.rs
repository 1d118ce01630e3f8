//! Claims that state a recurrence of sums (placeholder).
