//! Progress bar (on a terminal only) and the closing throughput line of a sweep.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::time::Instant;

/// Progress of a sweep over `total` points.
pub struct Progress {
    bar: ProgressBar,
    start: Instant,
    quiet: bool,
}

impl Progress {
    /// A bar on stderr when it is a terminal and `quiet` is off; hidden otherwise.
    pub fn new(total: u64, quiet: bool) -> Self {
        let target = if !quiet && std::io::stderr().is_terminal() {
            ProgressDrawTarget::stderr()
        } else {
            ProgressDrawTarget::hidden()
        };
        let bar = ProgressBar::with_draw_target(Some(total), target);
        if let Ok(style) = ProgressStyle::with_template(
            "{spinner} [{elapsed_precise}] {wide_bar} {human_pos}/{human_len} points (eta {eta})",
        ) {
            bar.set_style(style);
        }
        Self {
            bar,
            start: Instant::now(),
            quiet,
        }
    }

    /// `n` more points done.
    pub fn advance(&self, n: u64) {
        self.bar.inc(n);
    }

    /// Clear the bar and, unless quiet, print the throughput on stderr.
    pub fn finish(&self, what: &str, points: u64, laws: usize) {
        self.bar.finish_and_clear();
        if self.quiet {
            return;
        }
        let secs = self.start.elapsed().as_secs_f64();
        let impacts = points.saturating_mul(laws as u64);
        let rate = impacts as f64 / secs.max(1e-9);
        eprintln!(
            "impax {what}: {points} points × {laws} laws = {impacts} impacts in {secs:.3} s: {:.2} M impacts/s on {} threads",
            rate / 1e6,
            rayon::current_num_threads()
        );
    }
}
