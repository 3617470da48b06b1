//! What the benches print of the machine beside their times: a shared machine stretches wall
//! time, so each figure goes with the load average and, where it matters, the CPU time.

/// The load average over 1, 5 and 15 minutes, from /proc/loadavg ("unknown" elsewhere).
pub fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map(|s| s.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|_| "unknown".into())
}

/// CPU time of this process (user + system, all threads), s, from /proc/self/stat (clock ticks of
/// 1/100 s): on a machine shared with other work, wall time stretches and CPU time does not.
#[allow(dead_code)] // not every bench reads it
pub fn cpu_seconds() -> f64 {
    std::fs::read_to_string("/proc/self/stat")
        .ok()
        .and_then(|s| {
            // Fields after the command's closing parenthesis; utime and stime are the 14th and 15th.
            let rest = s.rsplit_once(')')?.1;
            let fields: Vec<&str> = rest.split_whitespace().collect();
            let utime: f64 = fields.get(11)?.parse().ok()?;
            let stime: f64 = fields.get(12)?.parse().ok()?;
            Some((utime + stime) / 100.0)
        })
        .unwrap_or(f64::NAN)
}
