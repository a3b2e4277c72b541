//! The progress bar of long commands: fed by the core's progress counters
//! ([`cablenav::command::Progress`]), drawn on stderr only when stderr is a terminal, so piped
//! and redirected runs stay silent.

use cablenav::command::Progress;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;

/// A progress bar on stderr, or nothing when stderr is not a terminal.
pub struct Bar {
    bar: Option<ProgressBar>,
    stage: &'static str,
}

impl Bar {
    /// A bar drawn on stderr if it is a terminal; silent otherwise.
    pub fn for_stderr() -> Bar {
        let bar = std::io::stderr().is_terminal().then(|| {
            let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
            bar.set_style(ProgressStyle::with_template("{spinner} {elapsed:>4} [{bar:30}] {pos}/{len} {msg}").unwrap_or_else(|_| ProgressStyle::default_bar()).progress_chars("=> "));
            bar
        });
        Bar { bar, stage: "" }
    }

    /// Shows `p`; a new stage restarts the bar with its own length.
    pub fn update(&mut self, p: Progress) {
        let Some(bar) = &self.bar else { return };
        if p.stage != self.stage {
            self.stage = p.stage;
            bar.reset_elapsed();
            bar.set_message(p.stage);
        }
        bar.set_length(p.total as u64);
        bar.set_position(p.done as u64);
    }

    /// Removes the bar before the report is printed.
    pub fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}
