//! Not a test group: what the machine gave a benchmark while it ran, so a
//! slow hour shows why, or that the cause is not in sight. The wall time
//! beside the process's CPU time (user and system, all its threads) and
//! the time the hypervisor took from this virtual machine's CPUs (steal,
//! every CPU summed), both from Linux's `/proc`, in clock ticks.

use std::time::Instant;

/// The start of a measured stretch.
pub struct Stopwatch {
    wall: Instant,
    cpu: f64,
    steal: f64,
}

/// What a stretch took ([`Stopwatch::lap`]), seconds.
pub struct Lap {
    /// Wall-clock time.
    pub wall: f64,
    /// This process's CPU time (user and system).
    pub cpu: f64,
    /// The CPUs' time taken by the hypervisor, every CPU summed.
    pub steal: f64,
}

impl Stopwatch {
    /// Starts a stretch now.
    pub fn start() -> Self {
        Self {
            wall: Instant::now(),
            cpu: process_cpu(),
            steal: stolen(),
        }
    }

    /// What the stretch since [`Self::start`] took.
    pub fn lap(&self) -> Lap {
        Lap {
            wall: self.wall.elapsed().as_secs_f64(),
            cpu: process_cpu() - self.cpu,
            steal: stolen() - self.steal,
        }
    }
}

impl std::fmt::Display for Lap {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{:.1} s ({:.1} s of CPU, {:.2} cores busy; {:.1} s stolen by the host)",
            self.wall,
            self.cpu,
            self.cpu / self.wall,
            self.steal
        )
    }
}

/// Seconds a clock tick of `/proc`.
fn tick() -> f64 {
    1.0 / rustix::param::clock_ticks_per_second() as f64
}

/// This process's user and system time so far, seconds; NaN where
/// `/proc` cannot be read.
fn process_cpu() -> f64 {
    std::fs::read_to_string("/proc/self/stat")
        .ok()
        .and_then(|stat| process_ticks(&stat))
        .map_or(f64::NAN, |ticks| ticks * tick())
}

/// The steal time of every CPU so far, seconds; NaN where `/proc` cannot
/// be read.
fn stolen() -> f64 {
    std::fs::read_to_string("/proc/stat")
        .ok()
        .and_then(|stat| steal_ticks(&stat))
        .map_or(f64::NAN, |ticks| ticks * tick())
}

/// A process's user and system ticks from its `/proc/PID/stat` text:
/// fields 14 and 15, counted after the command's parenthesised name
/// (which may hold spaces and parentheses itself: proc(5)).
fn process_ticks(stat: &str) -> Option<f64> {
    let (_, after_name) = stat.rsplit_once(')')?;
    // From the third field (the state) on: utime and stime are the 12th
    // and 13th.
    let fields: Vec<&str> = after_name.split_whitespace().collect();
    let ticks = |i: usize| fields.get(i)?.parse::<f64>().ok();
    Some(ticks(11)? + ticks(12)?)
}

/// Every CPU's steal ticks from `/proc/stat` text: the first line's
/// (`cpu`, all CPUs summed) eighth value (proc(5)).
fn steal_ticks(stat: &str) -> Option<f64> {
    let line = stat.lines().next()?;
    let mut values = line.split_whitespace();
    if values.next()? != "cpu" {
        return None;
    }
    values.nth(7)?.parse().ok()
}

/// The two files read as proc(5) lays them out: a command name with a
/// space and a parenthesis in it, and the `cpu` line's steal after user,
/// nice, system, idle, iowait, irq and softirq.
#[test]
fn proc_files_are_read_field_by_field() {
    let stat = "4242 (fwav (x) y) R 1 4242 4242 0 -1 4194304 900 0 0 0 1234 56 0 0 20 0 3 0";
    assert_eq!(process_ticks(stat), Some(1290.0));
    assert_eq!(process_ticks("4242 (short"), None);
    let cpu = "cpu  4553997 0 294149 1422366 15878 0 2417 6861 0 0\ncpu0 1 2 3 4 5 6 7 8 9 10\n";
    assert_eq!(steal_ticks(cpu), Some(6861.0));
    assert_eq!(steal_ticks("intr 1 2 3"), None);
    // A stretch reads through them on this machine.
    let lap = Stopwatch::start().lap();
    assert!(lap.cpu >= 0.0 && lap.steal >= 0.0, "{lap}");
}
