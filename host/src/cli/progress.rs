//! The progress bars of the long commands (`fwav kinematics`, `fwav
//! aero2d --model ns`, `fwav study`): drawn on standard error, which the
//! callers show only when it is a terminal (a pipe or a log gets nothing),
//! and redrawn every half second so that the clock runs while a step is
//! long.

use std::time::Duration;

use indicatif::{ProgressBar, ProgressStyle};

/// A bar of `length` units drawn by indicatif's `template` (its plain
/// bar if the template does not parse), ticking every half second.
pub fn bar(length: u64, template: &str) -> ProgressBar {
    let bar = ProgressBar::new(length);
    let style =
        ProgressStyle::with_template(template).unwrap_or_else(|_| ProgressStyle::default_bar());
    bar.set_style(style);
    bar.enable_steady_tick(Duration::from_millis(500));
    bar
}
