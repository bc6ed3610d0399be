//! The step-cost benchmark's quick form (`fwav_e2e::step_cost`): 1.5 s of
//! 10 kHz control steps of the unchanged flight-controller core flying the
//! shipped initial design on QEMU's emulated Cortex-M4F, counted in
//! instructions. It fails when a control step, on average or at its
//! longest, would take more than 30% of the STM32F405's 16,800 cycles a
//! period at the assumed 1.25 cycles per instruction. The full form (a
//! whole profile pass) is `cargo bench -p fwav-e2e --bench step_cost`.
//! Skipped, saying so, only where `qemu-system-arm` is not installed.

use fwav_e2e::emulator::{find_qemu, firmware};
use fwav_e2e::step_cost::{self, Measured, BUDGET_SHARE_LIMIT, CYCLES_PER_INSTRUCTION};

#[test]
fn a_control_step_takes_under_30_percent_of_the_period_on_the_cortex_m4() {
    let qemu = match find_qemu() {
        Ok(qemu) => qemu,
        Err(why) => return eprintln!("{why}"),
    };
    let cost = step_cost::run(&qemu, &firmware("step-cost"), 1.5);
    println!("{}", cost.table());

    let step = cost.get("control_step");
    assert_eq!(step.count, 15_000, "one measurement per control step");
    for (what, instructions) in [("mean", step.mean), ("longest", step.max)] {
        let share = Measured::budget_share(instructions, CYCLES_PER_INSTRUCTION);
        assert!(
            share <= BUDGET_SHARE_LIMIT,
            "the {what} control step takes {instructions:.0} instructions, {:.1}% of the period at {CYCLES_PER_INSTRUCTION} cycles per instruction (limit {:.0}%)",
            100.0 * share,
            100.0 * BUDGET_SHARE_LIMIT
        );
    }
    // The loop closed on the emulated CPU: the wing flies the profile's
    // +-30 deg (within 2%) after the 1 s ramp.
    assert!(
        (cost.amplitude_deg - 30.0).abs() < 0.02 * 30.0,
        "amplitude {} deg",
        cost.amplitude_deg
    );
    // Every frame kind was measured, from its first byte to its answer.
    for what in [
        "frame_handshake",
        "frame_status",
        "frame_upload_profile",
        "frame_read_profile",
        "frame_heartbeat",
        "frame_telemetry_encode",
    ] {
        let frame = cost.get(what);
        assert!(frame.count > 0 && frame.mean > 0.0, "{frame:?}");
    }
}
