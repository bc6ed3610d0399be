//! What the emulated board tells the host, over semihosting (QEMU's
//! standard error with `-semihosting-config enable=on,target=native`): one
//! line per report, `fwav-fc-qemu <what>: key=value ...`, read by the
//! end-to-end test and the step-cost benchmark. Virtual-time figures are in
//! nanoseconds (instructions under `-icount shift=0`).

use cortex_m_semihosting::hprintln;

use crate::cost::Cost;
use crate::stack::StackUse;

/// Prefix of every report line.
pub const PREFIX: &str = "fwav-fc-qemu";

/// The served controller's periodic report: uptime, the control steps
/// measured so far, the stack's high-water mark and the stack the main
/// loop's own frames take (`loop_depth`: what lies deeper was used by the
/// calls into the core and by the interrupts).
pub fn running(uptime_ms: u64, steps: &Cost, stack: StackUse, loop_depth: u32) {
    hprintln!(
        "{PREFIX} running: uptime_ms={uptime_ms} steps={} step_mean_ns={} step_max_ns={} stack_used_bytes={} stack_size_bytes={} loop_depth_bytes={loop_depth}",
        steps.count,
        steps.mean_ns(),
        steps.max_ns(),
        stack.used,
        stack.size
    );
}

/// One measured kind of work of the benchmark.
pub fn cost(what: &str, cost: &Cost) {
    hprintln!(
        "{PREFIX} cost: what={what} count={} mean_ns={} max_ns={}",
        cost.count,
        cost.mean_ns(),
        cost.max_ns()
    );
}

/// A named value of the benchmark (the measurement's own overhead, the
/// wing's amplitude...).
pub fn value(what: &str, value: f64) {
    hprintln!("{PREFIX} value: what={what} value={value}");
}

/// The stack's high-water mark.
pub fn stack(stack: StackUse) {
    hprintln!(
        "{PREFIX} stack: used_bytes={} size_bytes={}",
        stack.used,
        stack.size
    );
}

/// A hard fault: where, before QEMU is ended with a failure.
pub fn hard_fault(pc: u32) {
    hprintln!("{PREFIX} hard fault: pc={pc:#010x}");
}
