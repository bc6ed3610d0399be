//! The step-cost benchmark's full form: a whole pass of the shipped initial
//! design (1 s ramp and 20 s at 11 Hz, +-30 deg) of 10 kHz control steps of
//! the flight-controller core on QEMU's emulated Cortex-M4F, in
//! instructions, against the STM32F405's 16,800 cycles a period
//! (`fwav_e2e::step_cost` says how it counts and which cycles per
//! instruction it assumes). Exits with status 1 when a control step takes
//! more than 30% of the period. About 15 s.
//!
//! `cargo bench -p fwav-e2e --bench step_cost`

use fwav_e2e::emulator::{find_qemu, firmware};
use fwav_e2e::step_cost::{self, Measured, BUDGET_SHARE_LIMIT, CYCLES_PER_INSTRUCTION};

/// A pass of the profile and a little of its hold.
const SECONDS: f64 = 21.5;

fn main() {
    let qemu = match find_qemu() {
        Ok(qemu) => qemu,
        Err(why) => return eprintln!("{why}"),
    };
    let started = std::time::Instant::now();
    let cost = step_cost::run(&qemu, &firmware("step-cost"), SECONDS);
    println!("{}", cost.table());
    println!("wall time {:.1} s", started.elapsed().as_secs_f64());
    let step = cost.get("control_step");
    let worst = Measured::budget_share(step.mean.max(step.max), CYCLES_PER_INSTRUCTION);
    if worst > BUDGET_SHARE_LIMIT {
        eprintln!(
            "over budget: a control step takes up to {:.1}% of the period (limit {:.0}%)",
            100.0 * worst,
            100.0 * BUDGET_SHARE_LIMIT
        );
        std::process::exit(1);
    }
}
