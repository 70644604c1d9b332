//! Stage timings for profiling, off unless the `VBI_TIMINGS` environment
//! variable is set (to anything but `0` or nothing): each timed stage then
//! prints one line to stderr when it ends,
//! `timing: <stage>: wall 1.234 s, cpu 2.345 s`, the CPU time being the
//! whole process's (every thread's user and system time) over the stage.
//! Nested stages are indented. Nothing else changes: stdout and every file
//! written are the same with and without it.

use std::sync::OnceLock;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

/// Whether `VBI_TIMINGS` asks for timings (read once).
pub fn enabled() -> bool {
    static ENABLED: OnceLock<bool> = OnceLock::new();
    *ENABLED.get_or_init(|| {
        std::env::var("VBI_TIMINGS").is_ok_and(|v| !v.trim().is_empty() && v.trim() != "0")
    })
}

/// Nesting depth of the stages running now (for the indentation).
static DEPTH: AtomicUsize = AtomicUsize::new(0);

/// A stage being timed; prints its line when dropped.
#[must_use = "the stage is timed until the guard is dropped"]
pub struct Stage {
    name: String,
    depth: usize,
    wall: Instant,
    cpu: f64,
}

/// Starts timing the stage `name` when timings are on ([`enabled`]); the
/// stage ends when the guard returned is dropped.
pub fn stage(name: impl FnOnce() -> String) -> Option<Stage> {
    if !enabled() {
        return None;
    }
    Some(Stage {
        name: name(),
        depth: DEPTH.fetch_add(1, Ordering::Relaxed),
        wall: Instant::now(),
        cpu: cpu_seconds(),
    })
}

/// Prints a line of facts about the stage running now (sizes, counts)
/// when timings are on.
pub fn note(text: impl FnOnce() -> String) {
    if enabled() {
        eprintln!(
            "timing: {:indent$}({})",
            "",
            text(),
            indent = 2 * DEPTH.load(Ordering::Relaxed)
        );
    }
}

impl Drop for Stage {
    fn drop(&mut self) {
        DEPTH.fetch_sub(1, Ordering::Relaxed);
        eprintln!(
            "timing: {:indent$}{}: wall {:.3} s, cpu {:.3} s",
            "",
            self.name,
            self.wall.elapsed().as_secs_f64(),
            cpu_seconds() - self.cpu,
            indent = 2 * self.depth
        );
    }
}

/// The process's CPU time so far (user + system, every thread), s.
#[cfg(unix)]
fn cpu_seconds() -> f64 {
    // SAFETY: getrusage writes the struct it is given, zeroed here.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    if unsafe { libc::getrusage(libc::RUSAGE_SELF, &mut usage) } != 0 {
        return f64::NAN;
    }
    let seconds = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    seconds(usage.ru_utime) + seconds(usage.ru_stime)
}

/// The process's CPU time: not measured here.
#[cfg(not(unix))]
fn cpu_seconds() -> f64 {
    f64::NAN
}
