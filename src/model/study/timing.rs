//! In-process wall-clock timing of repeated solves (for work-precision; never used in tests).

use std::time::{Duration, Instant};

/// Median seconds per call of `f`, over at least `min_repeats` calls and at least `min_total` of time.
pub fn median_seconds<T>(mut f: impl FnMut() -> T, min_repeats: usize, min_total: Duration) -> f64 {
    let mut times = Vec::with_capacity(min_repeats.max(1));
    let start = Instant::now();
    while times.len() < min_repeats.max(1) || start.elapsed() < min_total {
        let t0 = Instant::now();
        std::hint::black_box(f());
        times.push(t0.elapsed().as_secs_f64());
        if times.len() >= 10_000 {
            break;
        }
    }
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}
