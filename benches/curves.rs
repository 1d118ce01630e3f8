//! Placeholder; filled by the benchmarks work.
fn main() {}
