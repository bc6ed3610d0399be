//! # fwav-plant — the flapping actuator's equations of motion
//!
//! The flapping actuator and wing: a DC motor with winding inductance, an
//! H-bridge on a battery with internal resistance, a gearbox with
//! load-dependent loss, a torsional spring, the wing's inertia and its
//! blade-element aerodynamic torque. Integrated with fixed-step RK4
//! together with an energy ledger, so the balance
//! `E_in = E_resistive + E_friction + E_aero + dE_stored` checks the model
//! and the integrator.
//!
//! Equations (flapping axis; `N` gear ratio, `omega` flapping rate):
//! - `L di/dt = V - R i - K_t N omega`
//! - `J omega' = N K_t i - T_gear - T_friction - k phi - c_a omega |omega|`,
//!   `J = J_wing + N^2 J_rotor`
//! - gear loss `T_gear = (1 - eta) |N K_t i| s(omega)` (a Coulomb-like loss
//!   proportional to load, always dissipative), motor friction
//!   `T_friction = N T_c s(omega) + N^2 b omega`, with the regularized sign
//!   `s = clamp(omega / eps, -1, 1)`, `eps = 0.05 rad/s` (odd, continuous,
//!   `s omega >= 0`: friction never adds energy; the usual saturated-viscous
//!   regularization of Coulomb friction, and cheap: it is evaluated 40 times
//!   per control period)
//! - aerodynamic torque from blade elements over the planform,
//!   `c_a = 1/2 rho C_D int_0^R c(r) r^3 dr`, the flat plate at high angle of
//!   attack: quasi-steady drag only (no added mass, no wake), the usual
//!   actuator-level model of flapping-wing drive design.
//! - bridge: averaged `V = d V_bus` or switching `V = +-V_bus` at the PWM
//!   frequency (locked anti-phase), `V_bus = V_batt - R_batt i_supply`;
//!   a disabled bridge is an open circuit (`i = 0`).
//!

//!
//! `no_std` (floating-point functions from `libm`), so that the one copy
//! of these equations is integrated by hil-sim on the host and by the
//! emulated microcontroller (`firmware/qemu`) around the firmware core.
//! The parameters are a plain [`Physics`] record; `fwav-actuator` reads
//! them from `plant.toml`, checks them and converts them.
//!
//! Cost: one [`Plant::step`] is four evaluations of the derivative, in
//! `f64` (about 100 floating-point operations without the ledger).

#![no_std]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

use serde::{Deserialize, Serialize};

/// The H-bridge model.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PwmModel {
    /// Average voltage over a PWM period (fast).
    #[default]
    Averaged,
    /// Resolve each PWM period's switching (needs substeps well below the
    /// PWM period).
    Switching,
}

/// The physical parameters the equations use, SI units, referred as in
/// the module docs (`fwav_actuator::params::PlantParams` documents and
/// checks each one; this record is what it converts to).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Physics {
    /// Winding resistance `R`, ohm.
    pub resistance_ohm: f64,
    /// Winding inductance `L`, H.
    pub inductance_h: f64,
    /// Torque constant = back-EMF constant `K_t`, N m/A.
    pub torque_constant_nm_per_a: f64,
    /// Rotor inertia, kg m^2.
    pub rotor_inertia_kg_m2: f64,
    /// Coulomb friction `T_c` at the motor shaft, N m.
    pub coulomb_friction_nm: f64,
    /// Viscous friction `b` at the motor shaft, N m s/rad.
    pub viscous_friction_nms_per_rad: f64,
    /// Open-circuit battery voltage, V.
    pub battery_v: f64,
    /// Battery internal resistance `R_b`, ohm.
    pub internal_resistance_ohm: f64,
    /// Bridge model.
    pub pwm: PwmModel,
    /// PWM frequency of the switching model, Hz.
    pub pwm_hz: f64,
    /// Gear ratio `N` (motor turns per flapping-axis turn).
    pub gear_ratio: f64,
    /// Gearbox efficiency `eta` in (0, 1].
    pub gear_efficiency: f64,
    /// Torsional spring `k` about the flapping axis, N m/rad.
    pub spring_nm_per_rad: f64,
    /// Wing (and linkage) inertia about the flapping axis, kg m^2.
    pub wing_inertia_kg_m2: f64,
    /// Quadratic aerodynamic damping `c_a`, N m s^2.
    pub aero_damping_nms2: f64,
}

/// 1 / rate scale of the regularized sign of friction (0.05 rad/s), s/rad.
pub const FRICTION_SLOPE: f64 = 1.0 / 0.05;

/// The state of the plant.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct State {
    /// Motor current, A.
    pub current_a: f64,
    /// Flapping angle, rad.
    pub angle_rad: f64,
    /// Flapping rate, rad/s.
    pub rate_rad_s: f64,
}

/// Energies integrated since the start, J.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct EnergyLedger {
    /// Drawn from the battery.
    pub battery_j: f64,
    /// Into the motor terminals.
    pub electrical_in_j: f64,
    /// Lost in the battery's internal resistance.
    pub battery_loss_j: f64,
    /// Lost in the winding resistance.
    pub resistive_j: f64,
    /// Lost in motor friction and the gearbox.
    pub friction_j: f64,
    /// Work done on the air.
    pub aero_j: f64,
}

/// What the bridge applies during a step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drive {
    /// Duty in [-1, 1].
    pub duty: f64,
    /// Outputs on.
    pub enabled: bool,
}

/// Electrical coefficients of one bridge state (see [`Plant::electrical`]).
#[derive(Clone, Copy, Debug)]
struct Electrical {
    f: f64,
    e0: f64,
    e1: f64,
    e2: f64,
}

/// Products of parameters the derivative needs, computed once.
#[derive(Clone, Copy, Debug)]
struct Coefficients {
    /// N K_t / J, etc.: the accelerations per unit current, rate, angle.
    a_motor: f64,
    a_gear: f64,
    a_coulomb: f64,
    a_viscous: f64,
    a_spring: f64,
    a_aero: f64,
    /// N K_t, N m/A (= V s/rad at the flapping axis).
    kt_n: f64,
    /// 1 - efficiency.
    gear_loss: f64,
    /// N T_c, N m.
    coulomb: f64,
    /// N^2 b, N m s/rad.
    viscous: f64,
    /// 1 / L.
    inv_inductance: f64,
}

/// The plant: parameters, state, ledger and injected mechanical faults.
#[derive(Clone, Debug)]
pub struct Plant {
    p: Physics,
    c: Coefficients,
    inertia: f64,
    aero: f64,
    /// State now.
    pub state: State,
    /// Energies so far.
    pub ledger: EnergyLedger,
    /// Time, s.
    pub time_s: f64,
    /// Battery voltage now (a supply drop changes it), V.
    pub battery_v: f64,
    /// The rotor is locked (stall fault).
    pub stalled: bool,
    /// Keep the energy ledger (on by default; `hil-sim serve` turns it off since
    /// nobody reads it there, which makes each step ~20% cheaper).
    pub keep_ledger: bool,
}

/// Mechanical and electrical state: current, angle, rate.
type Vector = [f64; 3];
/// Energy rates: battery, terminals, battery loss, resistive, friction, aero (W).
type Rates = [f64; 6];

impl Plant {
    /// A plant of `physics` at rest (anything that converts into
    /// [`Physics`]: `fwav-actuator`'s checked `&PlantParams`, say).
    pub fn new(physics: impl Into<Physics>) -> Self {
        let p = physics.into();
        let n = p.gear_ratio;
        let inertia = p.wing_inertia_kg_m2 + n * n * p.rotor_inertia_kg_m2;
        let aero = p.aero_damping_nms2;
        let kt_n = n * p.torque_constant_nm_per_a;
        Self {
            c: Coefficients {
                a_motor: kt_n / inertia,
                a_gear: (1.0 - p.gear_efficiency) * kt_n / inertia,
                a_coulomb: n * p.coulomb_friction_nm / inertia,
                a_viscous: n * n * p.viscous_friction_nms_per_rad / inertia,
                a_spring: p.spring_nm_per_rad / inertia,
                a_aero: aero / inertia,
                kt_n: n * p.torque_constant_nm_per_a,
                gear_loss: 1.0 - p.gear_efficiency,
                coulomb: n * p.coulomb_friction_nm,
                viscous: n * n * p.viscous_friction_nms_per_rad,
                inv_inductance: 1.0 / p.inductance_h,
            },
            inertia,
            aero,
            battery_v: p.battery_v,
            p,
            state: State::default(),
            ledger: EnergyLedger::default(),
            time_s: 0.0,
            stalled: false,
            keep_ledger: true,
        }
    }

    /// Inertia about the flapping axis (wing + reflected rotor), kg m^2.
    pub fn inertia(&self) -> f64 {
        self.inertia
    }

    /// Quadratic aerodynamic damping coefficient, N m s^2.
    pub fn aero_damping(&self) -> f64 {
        self.aero
    }

    /// Energy stored now: inductor, wing motion, spring, J.
    pub fn stored_energy(&self) -> f64 {
        let s = &self.state;
        0.5 * self.p.inductance_h * s.current_a * s.current_a
            + 0.5 * self.inertia * s.rate_rad_s * s.rate_rad_s
            + 0.5 * self.p.spring_nm_per_rad * s.angle_rad * s.angle_rad
    }

    /// Bridge voltage sign for switching PWM at time `t` (+1 or -1): locked
    /// anti-phase, positive for a fraction (1 + duty) / 2 of each period.
    fn bridge_factor(&self, duty: f64, t: f64) -> f64 {
        // `x - trunc(x)`, which is what std's `f64::fract` computes.
        let cycles = t * self.p.pwm_hz;
        let phase = cycles - libm::trunc(cycles);
        if phase < 0.5 * (1.0 + duty) {
            1.0
        } else {
            -1.0
        }
    }

    /// Electrical coefficients for bridge factor `f` (duty when averaged,
    /// +-1 when switching): `di/dt = e0 - e1 i - e2 omega` with
    /// `e0 = f V_b / L`, `e1 = (R + f^2 R_b) / L`, `e2 = N K_t / L`.
    #[inline(always)]
    fn electrical(&self, f: f64, enabled: bool) -> Electrical {
        if !enabled {
            return Electrical {
                f: 0.0,
                e0: 0.0,
                e1: 0.0,
                e2: 0.0,
            };
        }
        let c = &self.c;
        Electrical {
            f,
            e0: f * self.battery_v * c.inv_inductance,
            e1: (self.p.resistance_ohm + f * f * self.p.internal_resistance_ohm) * c.inv_inductance,
            e2: c.kt_n * c.inv_inductance,
        }
    }

    /// Derivatives of the state, and the energy rates (off the critical
    /// path: they do not feed back).
    #[inline(always)]
    fn derivative(&self, x: &Vector, e: &Electrical) -> (Vector, Rates) {
        let c = &self.c;
        let (i, phi, omega) = (x[0], x[1], x[2]);
        let s = (omega * FRICTION_SLOPE).clamp(-1.0, 1.0);
        let di = e.e0 - e.e1 * i - e.e2 * omega;
        // Accelerations with 1/J folded into the coefficients.
        let domega = if self.stalled {
            0.0
        } else {
            c.a_motor * i
                - s * (c.a_gear * i.abs() + c.a_coulomb)
                - c.a_viscous * omega
                - c.a_spring * phi
                - c.a_aero * omega * omega.abs()
        };
        let dphi = if self.stalled { 0.0 } else { omega };
        // Energy rates in physical units.
        let supply_i = e.f * i;
        let r_batt = self.p.internal_resistance_ohm;
        let bus = self.battery_v - r_batt * supply_i;
        let losses = (c.gear_loss * (c.kt_n * i).abs() + c.coulomb) * s + c.viscous * omega;
        (
            [di, dphi, domega],
            [
                self.battery_v * supply_i,
                e.f * bus * i,
                r_batt * supply_i * supply_i,
                self.p.resistance_ohm * i * i,
                losses * omega,
                self.aero * omega * omega.abs() * omega,
            ],
        )
    }

    /// Advances by `dt` seconds (one RK4 step) under `drive`.
    pub fn step(&mut self, drive: Drive, dt: f64) {
        if self.keep_ledger {
            self.step_with::<true>(drive, dt);
        } else {
            self.step_with::<false>(drive, dt);
        }
    }

    /// Advances by `substeps` RK4 steps of `dt` seconds under one `drive`
    /// (one control period).
    pub fn advance(&mut self, drive: Drive, dt: f64, substeps: u32) {
        for _ in 0..substeps {
            self.step(drive, dt);
        }
    }

    #[inline(always)]
    fn step_with<const LEDGER: bool>(&mut self, drive: Drive, dt: f64) {
        let drive = Drive {
            duty: drive.duty.clamp(-1.0, 1.0),
            ..drive
        };
        // Averaged: one bridge state for the whole step. Switching: the state
        // at each stage's time.
        let averaged = match self.p.pwm {
            PwmModel::Averaged => Some(self.electrical(drive.duty, drive.enabled)),
            PwmModel::Switching => None,
        };
        let s = &self.state;
        let x: Vector = [s.current_a, s.angle_rad, s.rate_rad_s];
        let t = self.time_s;
        // Averaged: one bridge state for the whole period. Switching: the
        // state at each stage's time.
        let bridge = |at: f64| {
            averaged.unwrap_or_else(|| {
                self.electrical(self.bridge_factor(drive.duty, at), drive.enabled)
            })
        };
        let (b0, b1, b2) = (bridge(t), bridge(t + 0.5 * dt), bridge(t + dt));
        // The ledger does not feed back into the dynamics: its rates ride
        // along with the stages and are summed with the same RK4 weights.
        let add = |a: &Vector, b: &Vector, h: f64| -> Vector {
            [a[0] + h * b[0], a[1] + h * b[1], a[2] + h * b[2]]
        };
        let (k1, e1) = self.derivative(&x, &b0);
        let (k2, e2) = self.derivative(&add(&x, &k1, 0.5 * dt), &b1);
        let (k3, e3) = self.derivative(&add(&x, &k2, 0.5 * dt), &b1);
        let (k4, e4) = self.derivative(&add(&x, &k3, dt), &b2);
        let w = dt / 6.0;
        let y: Vector =
            core::array::from_fn(|k| x[k] + w * (k1[k] + 2.0 * k2[k] + 2.0 * k3[k] + k4[k]));
        let de: Rates = if LEDGER {
            core::array::from_fn(|k| w * (e1[k] + 2.0 * e2[k] + 2.0 * e3[k] + e4[k]))
        } else {
            [0.0; 6]
        };
        let l = &self.ledger;
        let y = [
            y[0],
            y[1],
            y[2],
            l.battery_j + de[0],
            l.electrical_in_j + de[1],
            l.battery_loss_j + de[2],
            l.resistive_j + de[3],
            l.friction_j + de[4],
            l.aero_j + de[5],
        ];
        let mut resistive_j = y[6];
        if !drive.enabled && s.current_a != 0.0 {
            // Opening the bridge dumps the inductor's energy into the
            // freewheeling diodes: book it as a resistive loss.
            resistive_j += 0.5 * self.p.inductance_h * s.current_a * s.current_a;
        }
        self.state = State {
            current_a: if drive.enabled { y[0] } else { 0.0 },
            angle_rad: y[1],
            rate_rad_s: y[2],
        };
        if self.stalled {
            self.state.rate_rad_s = 0.0;
        }
        self.ledger = EnergyLedger {
            battery_j: y[3],
            electrical_in_j: y[4],
            battery_loss_j: y[5],
            resistive_j,
            friction_j: y[7],
            aero_j: y[8],
        };
        self.time_s += dt;
    }
}

/// The energy balance since a reference point: `E_in - (losses + dE_stored)`
/// as a fraction of `E_in`.
pub fn balance_residual(start: &EnergyLedger, start_stored: f64, plant: &Plant) -> f64 {
    let l = &plant.ledger;
    let e_in = l.electrical_in_j - start.electrical_in_j;
    let out = (l.resistive_j - start.resistive_j)
        + (l.friction_j - start.friction_j)
        + (l.aero_j - start.aero_j)
        + (plant.stored_energy() - start_stored);
    (e_in - out) / e_in.abs().max(f64::MIN_POSITIVE)
}
