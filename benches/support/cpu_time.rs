//! CPU time for criterion's `iter_custom`: the machine the figures come from is shared, so
//! the time this thread spent on the CPU is what is compared, not wall time.
//!
//! The clock is the thread's CPU clock (`clock_gettime(CLOCK_THREAD_CPUTIME_ID)`, to the
//! nanosecond); a group takes few, long samples of equal length ([`long_samples`]), the
//! protocol of the figures in docs/performance.md.

use criterion::black_box;
use std::time::Duration;

#[path = "../../tests/support/cpu.rs"]
mod cpu;

/// Sets `group` to 10 samples of equal length over 2 s (200 ms each), after 1 s of warm-up.
pub fn long_samples<M: criterion::measurement::Measurement>(group: &mut criterion::BenchmarkGroup<'_, M>) {
    group
        .sampling_mode(criterion::SamplingMode::Flat)
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(2));
}

/// Runs `f` `iters` times and returns the CPU time it took.
pub fn cpu_time_of<R>(iters: u64, mut f: impl FnMut() -> R) -> Duration {
    let start = cpu::thread_cpu();
    for _ in 0..iters {
        black_box(f());
    }
    cpu::thread_cpu() - start
}
