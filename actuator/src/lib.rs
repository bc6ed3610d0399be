//! # fwav-actuator — the flapping actuator's model
//!
//! The physics of the fwav reference actuator, in one place for the two
//! programs that need it: the plant's parameters ([`params`]: DC motor,
//! H-bridge and battery, gearbox and spring, wing, and the sensors and time
//! stepping a simulation of it uses, read from TOML with the documented
//! defaults of `actuator/plant.toml`), its continuous equations ([`plant`]:
//! the motor, bridge, battery, gearbox, spring and wing-drive dynamics with
//! blade-element aerodynamic torque, integrated by RK4 with an energy
//! ledger), and the same equations run backwards ([`feasibility`]: can the
//! actuator fly a given frequency and amplitude, and if not, what nearest
//! kinematics it can).
//!
//! `fwav` (the design library, which judges its optimum before writing the
//! profile) and `fwav-hil-sim` (the simulator, which integrates the plant
//! around the firmware core) both use this crate, so neither depends on the
//! other. It may import `fwav-protocol` (the device's envelope and the
//! firmware's default current limit) and nothing of the firmware core, the
//! host or the simulator.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod controller_model;
pub mod feasibility;
pub mod params;
pub mod plant;
