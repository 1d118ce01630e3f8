//! CPU time for criterion's `iter_custom`: the machine the figures come from is shared, so
//! the time this thread spent on the CPU is what is compared, not wall time.
//!
//! The kernel's count moves at scheduler ticks (a few milliseconds), so a group measured
//! with it takes few, long samples of equal length ([`long_samples`]): a sample of a few
//! iterations would read zero.

use criterion::black_box;
use std::time::{Duration, Instant};

/// CPU time of this thread so far (the scheduler's count, in nanoseconds); `None` where the
/// kernel does not expose it.
fn thread_cpu_time() -> Option<Duration> {
    let text = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    Some(Duration::from_nanos(text.split_whitespace().next()?.parse().ok()?))
}

/// Sets `group` to 10 samples of equal length over 2 s (200 ms each, against a tick of at
/// most 4 ms), after 1 s of warm-up.
pub fn long_samples<M: criterion::measurement::Measurement>(group: &mut criterion::BenchmarkGroup<'_, M>) {
    group
        .sampling_mode(criterion::SamplingMode::Flat)
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(2));
}

/// Runs `f` `iters` times and returns the CPU time it took (wall time where there is no
/// thread CPU clock).
pub fn cpu_time_of<R>(iters: u64, mut f: impl FnMut() -> R) -> Duration {
    let (cpu, wall) = (thread_cpu_time(), Instant::now());
    for _ in 0..iters {
        black_box(f());
    }
    match (cpu, thread_cpu_time()) {
        (Some(start), Some(end)) => end - start,
        _ => wall.elapsed(),
    }
}
