//! The `[analysis]` table: the system analysis's settings. Its type is
//! the solver's own [`SystemSettings`]; the declarations here are the
//! ranges [`crate::aeroelastic::run`] accepts, so a design run is refused
//! before it starts.

use fwav_settings::{Allowed, Integers, Interval, Setting, Table, Value};

use crate::aeroelastic::analysis::SystemSettings;

/// The `[analysis]` table's settings.
pub const ANALYSIS: Table<SystemSettings> = Table {
    name: "analysis",
    doc: "The system analysis: unsteady vortex lattice strongly coupled to the shell.",
    settings: &[
        Setting {
            key: "cycles",
            unit: "",
            allowed: Allowed::Integer(Integers::between(2, 100)),
            doc: "Flapping cycles simulated (the last one is reported, and compared with the one before: whether the answer is periodic)",
            value: |a| Value::unsigned(a.cycles),
        },
        Setting {
            key: "steps_per_cycle",
            unit: "",
            allowed: Allowed::Integer(Integers::between(8, 2000)),
            doc: "Time steps per flapping cycle",
            value: |a| Value::unsigned(a.steps_per_cycle),
        },
        Setting {
            key: "chordwise_panels",
            unit: "",
            allowed: Allowed::Integer(Integers::between(1, 64)),
            doc: "Vortex-lattice panels along the chord",
            value: |a| Value::unsigned(a.chordwise_panels),
        },
        Setting {
            key: "spanwise_panels",
            unit: "",
            allowed: Allowed::Integer(Integers::between(1, 200)),
            doc: "Vortex-lattice panels along the span",
            value: |a| Value::unsigned(a.spanwise_panels),
        },
        Setting {
            key: "rigid",
            unit: "",
            allowed: Allowed::Flag,
            doc: "Rigid wing (no structure)",
            value: |a| Value::Flag(a.rigid),
        },
        Setting {
            key: "coupling_tolerance",
            unit: "",
            allowed: Allowed::Real(Interval::closed(1e-12, 0.5)),
            doc: "Interface residual that ends a step's coupling iterations",
            value: |a| Value::Real(a.coupling_tolerance),
        },
        Setting {
            key: "max_subiterations",
            unit: "",
            allowed: Allowed::Integer(Integers::between(1, 1000)),
            doc: "Coupling iterations allowed a step",
            value: |a| Value::unsigned(a.max_subiterations),
        },
        Setting {
            key: "rho_inf",
            unit: "",
            allowed: Allowed::Real(Interval::closed(0.0, 1.0)),
            doc: "Spectral radius at infinity of the structural integrator",
            value: |a| Value::Real(a.rho_inf),
        },
        Setting {
            key: "free_wake_cycles",
            unit: "flapping cycles",
            allowed: Allowed::Real(Interval::closed(0.0, 100.0)),
            doc: "Wake that rolls up freely",
            value: |a| Value::Real(a.free_wake_cycles),
        },
        Setting {
            key: "wake_cycles",
            unit: "flapping cycles",
            allowed: Allowed::Real(Interval::closed(0.01, 100.0)),
            doc: "Wake kept behind the wing",
            value: |a| Value::Real(a.wake_cycles),
        },
        Setting {
            key: "core_radius_chords",
            unit: "root chords",
            allowed: Allowed::Real(Interval::closed(1e-6, 0.49)),
            doc: "Vortex core radius",
            value: |a| Value::Real(a.core_radius_chords),
        },
    ],
};
