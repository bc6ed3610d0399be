//! The step-cost benchmark of the emulated Cortex-M4F (`firmware/qemu`'s
//! `step-cost` program): instructions per control step and per link frame,
//! and their share of the control period's cycle budget on the STM32F405.
//!
//! Counting: under `-icount shift=0` QEMU's virtual clock advances exactly
//! one nanosecond per executed instruction; the program times each piece
//! of work with a timer clocked from that virtual clock (25 MHz: 40
//! instructions a count, averaged over thousands of steps) and reports
//! nanoseconds, that is instructions.
//!
//! Budget: a 10 kHz loop on a 168 MHz STM32F405 has 16,800 cycles a
//! period. Cycles are instructions times [`CYCLES_PER_INSTRUCTION`], an
//! assumption (QEMU models no pipeline): the Cortex-M4 executes integer
//! and single-precision FPU arithmetic in one cycle, loads in two (one
//! when pipelined), taken branches in two to four and `vdiv` in 14, and at
//! 168 MHz the STM32F405's five flash wait states are mostly hidden by its
//! ART accelerator (prefetch and a 64-line instruction cache) for code
//! that loops; 1.25 is a typical average of such code. The real figure
//! needs a board's DWT cycle counter.

use std::path::Path;
use std::time::Duration;

use crate::emulator::{Emulator, Report};

/// Cycles of one 100 µs control period at 168 MHz.
pub const CONTROL_PERIOD_CYCLES: f64 = 168e6 / 10e3;
/// Cortex-M4 cycles per instruction assumed (see the module docs).
pub const CYCLES_PER_INSTRUCTION: f64 = 1.25;
/// The benchmark fails when a control step takes more than this share of
/// the period's cycles.
pub const BUDGET_SHARE_LIMIT: f64 = 0.30;

/// One kind of measured work.
#[derive(Clone, Debug, PartialEq)]
pub struct Measured {
    /// `control_step`, `frame_status`, `plant_period`, ...
    pub what: String,
    /// Times measured.
    pub count: u64,
    /// Mean instructions.
    pub mean: f64,
    /// Largest instruction count of one.
    pub max: f64,
}

impl Measured {
    /// Share of a control period's cycles that `instructions` take at
    /// `cycles_per_instruction`.
    pub fn budget_share(instructions: f64, cycles_per_instruction: f64) -> f64 {
        instructions * cycles_per_instruction / CONTROL_PERIOD_CYCLES
    }
}

/// What one run of the benchmark measured.
#[derive(Clone, Debug, PartialEq)]
pub struct StepCost {
    /// Every measured kind of work, in the order reported.
    pub measured: Vec<Measured>,
    /// The wing's largest angle over the last 0.1 s of the flight, degrees
    /// (the loop closed: the profile's amplitude is 30).
    pub amplitude_deg: f64,
    /// Seconds of control steps flown.
    pub seconds: f64,
    /// Stack high-water mark of the program, bytes.
    pub stack_used: u64,
}

impl StepCost {
    /// The measurement of `what`.
    pub fn get(&self, what: &str) -> &Measured {
        self.measured
            .iter()
            .find(|m| m.what == what)
            .unwrap_or_else(|| panic!("the benchmark measured no {what}: {self:?}"))
    }

    /// A table for people: instructions and budget shares at 1.0, 1.25
    /// and 2.0 cycles per instruction.
    pub fn table(&self) -> String {
        let mut out = format!(
            "emulated Cortex-M4F (QEMU mps2-an386, -icount shift=0), {} s of 10 kHz steps; budget {} cycles (168 MHz / 10 kHz)\n\
             {:<24} {:>7} {:>12} {:>10} {:>22}\n",
            self.seconds, CONTROL_PERIOD_CYCLES, "work", "count", "mean instr", "max instr", "mean % budget at CPI 1 / 1.25 / 2"
        );
        for m in &self.measured {
            let share = |cpi| 100.0 * Measured::budget_share(m.mean, cpi);
            out += &format!(
                "{:<24} {:>7} {:>12.0} {:>10.0} {:>8.1} / {:>5.1} / {:>5.1}\n",
                m.what,
                m.count,
                m.mean,
                m.max,
                share(1.0),
                share(CYCLES_PER_INSTRUCTION),
                share(2.0)
            );
        }
        out +=
            "(control_step is the budgeted work; a frame is decoded, handled and answered at the \
                link's priority, below the control step; plant_period is the emulator's plant, \
                not firmware)\n";
        out += &format!(
            "wing amplitude over the last 0.1 s: {:.3} deg; stack high-water mark {} bytes",
            self.amplitude_deg, self.stack_used
        );
        out
    }
}

/// Runs the `step-cost` program (`elf`) for `seconds` of control steps and
/// collects its reports. Panics with QEMU's output if the program fails.
pub fn run(qemu: &Path, elf: &Path, seconds: f64) -> StepCost {
    let append = format!("seconds={seconds}");
    let emulator = Emulator::start(qemu, elf, 0, Some(&append));
    let within = Duration::from_secs_f64(60.0 + 10.0 * seconds);
    let (status, lines) = emulator.wait(within);
    assert!(
        status.success(),
        "the benchmark failed ({status}): {lines:?}"
    );
    let reports: Vec<Report> = lines.iter().filter_map(|l| Report::parse(l)).collect();
    let measured = reports
        .iter()
        .filter(|r| r.kind == "cost")
        .map(|r| Measured {
            what: r.values["what"].clone(),
            count: r.number("count") as u64,
            // Nanoseconds of virtual time at one per instruction.
            mean: r.number("mean_ns"),
            max: r.number("max_ns"),
        })
        .collect();
    let value = |what: &str| {
        reports
            .iter()
            .find(|r| r.kind == "value" && r.values["what"] == what)
            .unwrap_or_else(|| panic!("no {what} reported: {lines:?}"))
            .number("value")
    };
    let stack = reports
        .iter()
        .find(|r| r.kind == "stack")
        .unwrap_or_else(|| panic!("no stack reported: {lines:?}"));
    StepCost {
        measured,
        amplitude_deg: value("amplitude_deg_last_0.1s"),
        seconds: value("seconds_flown"),
        stack_used: stack.number("used_bytes") as u64,
    }
}
