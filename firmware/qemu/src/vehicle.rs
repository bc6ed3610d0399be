//! The vehicle the emulated board flies: the shipped plant
//! (`actuator/plant.toml`, as the constants of [`crate::shipped`]) integrated
//! by `fwav-plant` — the equations and RK4 steps hil-sim integrates — and
//! the sensors the flight controller reads.
//!
//! The sensors are hil-sim's without the noise: the encoder quantizes the
//! flapping angle to its counts, the current sensor adds its offset, the
//! supply is the battery's open-circuit voltage. (hil-sim's Gaussian
//! current noise needs a random generator and a normal sampler; the noise
//! tests the controller's filtering, which hil-sim covers, not the
//! instruction set.)
//!
//! Time stepping: [`SUBSTEPS`] RK4 steps per control period, not the plant
//! file's 10. The plant is `f64`, which the Cortex-M4F computes in software
//! (its FPU is single precision): one RK4 step costs about 11,000
//! instructions (the step-cost benchmark reports `plant_period`), and the
//! whole control period has 100,000 (10 kHz at QEMU's one instruction per
//! nanosecond under `-icount shift=0`), so 10 steps would overrun the tick.
//! Four steps of 25 µs keep the motor's electrical pole (`R/L`, about
//! 40,000 /s) at `h R/L` about 1, well inside RK4's stability limit (2.8)
//! and resolved (RK4's decay factor per step 0.354 against the exact
//! 0.345); the mechanical motion (11 Hz) is resolved either way. It runs in
//! the control interrupt, outside the measured control step.

use fwav_fc_core::controller::Measurement;
use fwav_plant::{Drive, Plant};

use crate::board;
use crate::shipped::{CURRENT_OFFSET_A, ENCODER_COUNTS_PER_REV, PHYSICS, PLANT_CONTROL_HZ};

/// RK4 steps of the plant per control period (see the module docs).
pub const SUBSTEPS: u32 = 4;

const _: () = assert!(
    PLANT_CONTROL_HZ == board::CONTROL_HZ as f64,
    "actuator/plant.toml's control rate must be the firmware's"
);

/// The plant, its last drive and its sensors.
pub struct Vehicle {
    plant: Plant,
    drive: Drive,
}

impl Default for Vehicle {
    fn default() -> Self {
        Self::new()
    }
}

impl Vehicle {
    /// The shipped plant at rest, bridge off.
    pub fn new() -> Self {
        let mut plant = Plant::new(PHYSICS);
        // Nobody reads the energy ledger here (as in `hil-sim serve`).
        plant.keep_ledger = false;
        Self {
            plant,
            drive: Drive {
                duty: 0.0,
                enabled: false,
            },
        }
    }

    /// Integrates one control period under the drive last applied.
    pub fn advance(&mut self) {
        let h = 1.0 / (f64::from(board::CONTROL_HZ) * f64::from(SUBSTEPS));
        self.plant.advance(self.drive, h, SUBSTEPS);
    }

    /// Applies the flight controller's output for the next period.
    pub fn apply(&mut self, duty: f32, bridge_enabled: bool) {
        self.drive = Drive {
            duty: f64::from(duty),
            enabled: bridge_enabled,
        };
    }

    /// What the sensors read now.
    pub fn measure(&self) -> Measurement {
        let per_rad = f64::from(ENCODER_COUNTS_PER_REV) / (2.0 * core::f64::consts::PI);
        let count = libm::round(self.plant.state.angle_rad * per_rad);
        let per_count = 2.0 * core::f64::consts::PI / f64::from(ENCODER_COUNTS_PER_REV);
        Measurement {
            angle_rad: (count * per_count) as f32,
            current_a: (self.plant.state.current_a + CURRENT_OFFSET_A) as f32,
            supply_v: Some(self.plant.battery_v as f32),
        }
    }

    /// The true flapping angle, rad.
    pub fn angle_rad(&self) -> f64 {
        self.plant.state.angle_rad
    }
}
