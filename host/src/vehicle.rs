//! One vehicle from wing to motor: the designed wing's dynamics about the
//! flapping axis (its inertia from the shell model's mass, its
//! aerodynamic moment from the system analysis) and the design file's
//! actuator, as the actuator crate's plant ([`PlantParams`]) that the
//! feasibility check judges and hil-sim flies.
//!
//! - [`inertia`]: the wing's inertia about the flapping axis.
//! - [`aero_damping`]: the aerodynamic moment's law `c_a phi'|phi'|`,
//!   calibrated on the system analysis's work per cycle.
//! - [`spring`]: a given spring or one tuned to resonance.
//!
//! The plant's wing is described, as its file format has it, by a
//! planform and a drag coefficient whose blade-element integral is the
//! damping (`c_a = 1/2 rho C_D int c r^3 dr`,
//! [`fwav_actuator::params::Wing::aero_damping`]); the calibrated `c_a` is
//! written as the drag coefficient that gives it on the designed
//! planform, so the plant's damping is `c_a` to rounding.
//!
//! May import: [`crate::aeroelastic`], [`crate::shell`] and
//! `fwav-actuator`; the configuration room converts its `[actuator]`
//! table into an [`Actuator`] (this module does not import it).

pub mod aero_damping;
pub mod inertia;
pub mod spring;

use fwav_actuator::feasibility::{
    actuator_demand, check, ActuatorDemand, ActuatorLimits, Feasibility, FeasibilityError,
    FlappingDemand,
};
use fwav_actuator::params::{Motor, PlantParams, Supply, Transmission, Wing};
use serde::Serialize;

use crate::aeroelastic::kinematics::FlappingKinematics;
use crate::aeroelastic::model::{FlightCondition, WingModel};
use crate::aeroelastic::StepRecord;

pub use aero_damping::{AeroDamping, CalibrationError};
pub use inertia::{AxisInertia, InertiaError};
pub use spring::Spring;

/// Drag coefficient of the quasi-steady blade-element damping used when
/// no system analysis is at hand: revolving wings at high angle of attack,
/// `C_D ~ 3` (Dickinson, Lehmann & Sane 1999, Science 284; the actuator
/// crate's default plant, `actuator/plant.toml`).
pub const QUASI_STEADY_DRAG_COEFFICIENT: f64 = 3.0;

/// The aerodynamic damping of the built-in FWAV's initial design: `c_a`
/// calibrated on the full-size system analysis of the default design file
/// at 11 Hz, ±30°, mean 0 (drive work 0.0412 J per cycle, 0.453 W),
/// measured with `fwav system-analysis` at commit 720cb81; stored because
/// that analysis is too slow for a test. hil-sim's default plant
/// (`actuator/plant.toml`) carries it, N m s^2.
pub const INITIAL_DESIGN_AERO_DAMPING: f64 = 2.2523e-5;

/// The actuator of the design file, in the actuator crate's types.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Actuator {
    /// DC motor.
    pub motor: Motor,
    /// Battery and bridge.
    pub supply: Supply,
    /// Motor turns per flapping-axis turn.
    pub gear_ratio: f64,
    /// Gearbox efficiency in (0, 1].
    pub gear_efficiency: f64,
    /// The spring about the flapping axis.
    pub spring: Spring,
    /// The controller's current limit and the reserve.
    pub limits: ActuatorLimits,
}

/// Where the aerodynamic damping came from.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "source")]
pub enum AeroSource {
    /// Calibrated on a system analysis's drive work per cycle at these
    /// kinematics ([`aero_damping`]).
    SystemAnalysis {
        /// The drive's work per cycle reproduced, J.
        work_per_cycle_j: f64,
        /// Analysed frequency, Hz.
        frequency_hz: f64,
        /// Analysed amplitude, deg.
        amplitude_deg: f64,
        /// Analysed mean angle, deg.
        mean_deg: f64,
    },
    /// The quasi-steady blade-element model of the actuator crate with
    /// this drag coefficient.
    QuasiSteady {
        /// Drag coefficient normal to the wing.
        drag_coefficient: f64,
    },
}

/// Why a vehicle could not be built or judged.
#[derive(Debug, thiserror::Error)]
pub enum VehicleError {
    /// The wing's inertia.
    #[error("wing inertia: {0}")]
    Inertia(#[from] InertiaError),
    /// The aerodynamic damping's calibration.
    #[error("aerodynamic damping: {0}")]
    Calibration(#[from] CalibrationError),
    /// The plant or the demand is out of range.
    #[error(transparent)]
    Feasibility(#[from] FeasibilityError),
}

/// The designed wing on the design's actuator.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Vehicle {
    /// Half-wing mass, kg.
    pub wing_mass_kg: f64,
    /// Wing inertia about the flapping axis, kg m^2.
    pub wing_inertia_kg_m2: f64,
    /// `c_a` of the aerodynamic moment `c_a phi'|phi'|`, N m s^2.
    pub aero_damping_nms2: f64,
    /// Where `c_a` came from.
    pub aero_source: AeroSource,
    /// Semi-span, m.
    pub span_m: f64,
    /// Root chord, m.
    pub root_chord_m: f64,
    /// Tip chord, m.
    pub tip_chord_m: f64,
    /// Air density, kg/m^3.
    pub air_density_kg_m3: f64,
    /// The actuator.
    pub actuator: Actuator,
}

/// A tuned spring against none.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct TunedSpring {
    /// Frequency tuned to, Hz.
    pub frequency_hz: f64,
    /// Inertia at the flapping axis (wing + N^2 rotor), kg m^2.
    pub inertia_kg_m2: f64,
    /// `k = J omega^2`, N m/rad.
    pub stiffness_nm_per_rad: f64,
    /// The demand's peaks with the tuned spring.
    pub tuned: ActuatorDemand,
    /// The demand's peaks without a spring.
    pub without: ActuatorDemand,
    /// Peak current saved by the spring, A.
    pub peak_current_saved_a: f64,
    /// RMS current saved by the spring, A.
    pub rms_current_saved_a: f64,
}

impl Vehicle {
    /// The wing `model` (its current layout) about the flapping axis of
    /// `kinematics`, with the aerodynamic damping `c_a` from `aero`.
    fn build(
        model: &WingModel,
        kinematics: &FlappingKinematics,
        flight: &FlightCondition,
        aero: (f64, AeroSource),
        actuator: Actuator,
    ) -> Result<Self, VehicleError> {
        let i = inertia::axis_inertia(&model.wing.mesh, &model.sections, &kinematics.axis())?;
        let p = &model.planform;
        Ok(Self {
            wing_mass_kg: i.mass_kg,
            wing_inertia_kg_m2: i.inertia_kg_m2,
            aero_damping_nms2: aero.0,
            aero_source: aero.1,
            span_m: p.semi_span,
            root_chord_m: p.root_chord,
            tip_chord_m: p.tip_chord,
            air_density_kg_m3: flight.density,
            actuator,
        })
    }

    /// The wing of `model` with `c_a` calibrated on the system analysis
    /// of `kinematics` whose time steps are `steps` (`SystemResult::steps`
    /// or a stored record's; [`aero_damping`]).
    pub fn from_analysis(
        model: &WingModel,
        kinematics: &FlappingKinematics,
        flight: &FlightCondition,
        steps: &[StepRecord],
        steps_per_cycle: usize,
        actuator: Actuator,
    ) -> Result<Self, VehicleError> {
        let d = aero_damping::from_analysis(steps, kinematics, steps_per_cycle)?;
        let source = AeroSource::SystemAnalysis {
            work_per_cycle_j: d.work_per_cycle_j,
            frequency_hz: kinematics.frequency,
            amplitude_deg: kinematics.amplitude_deg(),
            mean_deg: kinematics.mean_angle_deg(),
        };
        Self::build(
            model,
            kinematics,
            flight,
            (d.coefficient_nms2, source),
            actuator,
        )
    }

    /// The wing of `model` with the quasi-steady blade-element damping
    /// ([`QUASI_STEADY_DRAG_COEFFICIENT`]) when no analysis is at hand.
    pub fn quasi_steady(
        model: &WingModel,
        kinematics: &FlappingKinematics,
        flight: &FlightCondition,
        actuator: Actuator,
    ) -> Result<Self, VehicleError> {
        let p = &model.planform;
        let c_a = blade_element_integral(p.semi_span, p.root_chord, p.tip_chord, flight.density)
            * QUASI_STEADY_DRAG_COEFFICIENT;
        let source = AeroSource::QuasiSteady {
            drag_coefficient: QUASI_STEADY_DRAG_COEFFICIENT,
        };
        Self::build(model, kinematics, flight, (c_a, source), actuator)
    }

    /// Inertia at the flapping axis: wing and rotor through the gearbox,
    /// `J_wing + N^2 J_rotor`, kg m^2.
    pub fn total_inertia_kg_m2(&self) -> f64 {
        let n = self.actuator.gear_ratio;
        self.wing_inertia_kg_m2 + n * n * self.actuator.motor.rotor_inertia_kg_m2
    }

    /// The spring's stiffness flying at `frequency_hz`, N m/rad.
    pub fn spring_nm_per_rad(&self, frequency_hz: f64) -> f64 {
        self.actuator
            .spring
            .stiffness(self.total_inertia_kg_m2(), frequency_hz)
    }

    /// The plant hil-sim flies and the check judges at `frequency_hz`
    /// (which sets a tuned spring): the wing and actuator of this vehicle,
    /// the sensors and time stepping of the actuator crate's default plant.
    pub fn plant(&self, frequency_hz: f64) -> PlantParams {
        let defaults = PlantParams::default();
        let unit = blade_element_integral(
            self.span_m,
            self.root_chord_m,
            self.tip_chord_m,
            self.air_density_kg_m3,
        );
        PlantParams {
            motor: self.actuator.motor.clone(),
            supply: self.actuator.supply.clone(),
            transmission: Transmission {
                gear_ratio: self.actuator.gear_ratio,
                efficiency: self.actuator.gear_efficiency,
                spring_nm_per_rad: self.spring_nm_per_rad(frequency_hz),
            },
            wing: Wing {
                inertia_kg_m2: self.wing_inertia_kg_m2,
                span_m: self.span_m,
                root_chord_m: self.root_chord_m,
                tip_chord_m: self.tip_chord_m,
                air_density_kg_m3: self.air_density_kg_m3,
                drag_coefficient: if unit > 0.0 {
                    self.aero_damping_nms2 / unit
                } else {
                    0.0
                },
            },
            sensors: defaults.sensors,
            simulation: defaults.simulation,
        }
    }

    /// Judges `demand` on this vehicle's plant at the demand's frequency.
    pub fn check(&self, demand: &FlappingDemand) -> Result<Feasibility, VehicleError> {
        let plant = self.plant(demand.frequency_hz);
        Ok(check(&plant, &self.actuator.limits, demand)?)
    }

    /// The demand of flying `kinematics` harmonically: its frequency,
    /// amplitude and mean angle (the stroke plane is a mounting angle, not
    /// a motor command).
    pub fn demand(kinematics: &FlappingKinematics) -> FlappingDemand {
        FlappingDemand {
            frequency_hz: kinematics.frequency,
            amplitude_deg: kinematics.amplitude_deg(),
            mean_deg: kinematics.mean_angle_deg(),
        }
    }

    /// The total constraint violation of flying `kinematics` on this
    /// vehicle, the measure of constrained domination (Deb, Pratap,
    /// Agarwal & Meyarivan 2002, section VI): `sum_q max(0, r - m_q)` over
    /// the torque, current and voltage margins `m_q` with the reserve `r`
    /// ([`Feasibility`]); 0 exactly when the check calls the demand
    /// feasible. A demand the check refuses as out of range (e.g. a zero
    /// frequency) violates by [`f64::MAX`], worse than any flyable one.
    pub fn violation(&self, kinematics: &FlappingKinematics) -> f64 {
        match self.check(&Self::demand(kinematics)) {
            Ok(f) => f
                .margins()
                .iter()
                .map(|m| (f.reserve - m.margin).max(0.0))
                .sum(),
            Err(_) => f64::MAX,
        }
    }

    /// The spring tuned to `demand`'s frequency against no spring: the
    /// stiffness and the current it saves.
    pub fn tuned_spring(&self, demand: &FlappingDemand) -> Result<TunedSpring, VehicleError> {
        let f = demand.frequency_hz;
        let inertia = self.total_inertia_kg_m2();
        let stiffness = spring::tuned_stiffness(inertia, f);
        let mut plant = self.plant(f);
        plant.transmission.spring_nm_per_rad = stiffness;
        let tuned = actuator_demand(&plant, demand)?;
        plant.transmission.spring_nm_per_rad = 0.0;
        let without = actuator_demand(&plant, demand)?;
        Ok(TunedSpring {
            frequency_hz: f,
            inertia_kg_m2: inertia,
            stiffness_nm_per_rad: stiffness,
            tuned,
            without,
            peak_current_saved_a: without.peak_current_a - tuned.peak_current_a,
            rms_current_saved_a: without.rms_current_a - tuned.rms_current_a,
        })
    }
}

/// `1/2 rho int_0^R c(r) r^3 dr` of the actuator crate's blade-element
/// wing (its damping per unit drag coefficient), N m s^2.
fn blade_element_integral(span_m: f64, root_chord_m: f64, tip_chord_m: f64, density: f64) -> f64 {
    Wing {
        inertia_kg_m2: 1.0,
        span_m,
        root_chord_m,
        tip_chord_m,
        air_density_kg_m3: density,
        drag_coefficient: 1.0,
    }
    .aero_damping()
}

#[cfg(test)]
mod tests {
    use super::*;
    use fwav_actuator::feasibility::demand_waveform;

    /// A vehicle with the default plant's motor and supply, a given wing
    /// inertia and damping, and `spring`.
    fn vehicle(aero: f64, spring: Spring) -> Vehicle {
        let p = PlantParams::default();
        Vehicle {
            wing_mass_kg: 0.01,
            wing_inertia_kg_m2: 6.7e-5,
            aero_damping_nms2: aero,
            aero_source: AeroSource::QuasiSteady {
                drag_coefficient: 0.0,
            },
            span_m: 0.15,
            root_chord_m: 0.075,
            tip_chord_m: 0.045,
            air_density_kg_m3: 1.225,
            actuator: Actuator {
                motor: p.motor,
                supply: p.supply,
                gear_ratio: 20.0,
                gear_efficiency: 0.9,
                spring,
                limits: ActuatorLimits::default(),
            },
        }
    }

    /// At resonance the tuned spring cancels the inertial torque: with no
    /// air and no friction, the torque the gearbox delivers over the
    /// harmonic stroke `phi = A sin(w t)` is `J phi'' + k phi = (k - J
    /// w^2) phi = 0` (to rounding), while without the spring it peaks at
    /// `J A w^2`.
    #[test]
    fn tuned_spring_cancels_the_inertial_torque_at_resonance() {
        let mut v = vehicle(0.0, Spring::Tuned);
        v.actuator.motor.coulomb_friction_nm = 0.0;
        v.actuator.motor.viscous_friction_nms_per_rad = 0.0;
        let demand = FlappingDemand {
            frequency_hz: 11.0,
            amplitude_deg: 30.0,
            mean_deg: 0.0,
        };
        let w = 2.0 * std::f64::consts::PI * 11.0;
        let j = v.total_inertia_kg_m2();
        let peak = j * 30f64.to_radians() * w * w;
        let tuned = demand_waveform(&v.plant(11.0), &demand).unwrap();
        let worst = tuned
            .iter()
            .map(|s| s.load_torque_nm.abs())
            .fold(0.0, f64::max);
        assert!(worst < 1e-12 * peak, "{worst} vs {peak}");
        v.actuator.spring = Spring::Fixed(0.0);
        let free = demand_waveform(&v.plant(11.0), &demand).unwrap();
        let worst = free
            .iter()
            .map(|s| s.load_torque_nm.abs())
            .fold(0.0, f64::max);
        assert!((worst / peak - 1.0).abs() < 1e-4, "{worst} vs {peak}");
        // The report: k = J w^2, and all the current is saved: the peak
        // without the spring is at least the inertial `J A w^2 / (N K_t)`
        // (more where the gearbox loss applies) and none is left.
        let t = v.tuned_spring(&demand).unwrap();
        assert!((t.stiffness_nm_per_rad / (j * w * w) - 1.0).abs() < 1e-12);
        assert!(t.tuned.peak_current_a < 1e-9, "{t:?}");
        let kt_n = 20.0 * v.actuator.motor.torque_constant_nm_per_a;
        assert!(
            t.without.peak_current_a >= peak / kt_n * (1.0 - 1e-9),
            "{t:?}"
        );
        assert!((t.peak_current_saved_a - t.without.peak_current_a).abs() < 1e-9);
    }

    /// The plant's wing carries the vehicle's damping `c_a` (as a drag
    /// coefficient on the planform) and inertia.
    #[test]
    fn plant_carries_the_damping_and_inertia() {
        let v = vehicle(2.5e-5, Spring::Fixed(0.05));
        let p = v.plant(11.0);
        assert!((p.wing.aero_damping() / 2.5e-5 - 1.0).abs() < 1e-12);
        assert_eq!(p.wing.inertia_kg_m2, 6.7e-5);
        assert_eq!(p.transmission.spring_nm_per_rad, 0.05);
        p.validate().unwrap();
        let back = PlantParams::from_toml(&toml::to_string(&p).unwrap()).unwrap();
        assert_eq!(back, p);
    }

    /// hil-sim's default plant (`actuator/plant.toml`) is the built-in
    /// FWAV's initial design on the default actuator: rebuilt here from
    /// the vehicle model (the default wing's inertia and planform) and the
    /// `[actuator]` defaults, with the stored analysis damping
    /// [`INITIAL_DESIGN_AERO_DAMPING`] and the spring tuned at 11 Hz. The
    /// file holds 8 significant digits of the computed values (1e-6).
    #[test]
    fn shipped_default_plant_is_the_initial_design() {
        use crate::config::SystemConfig;
        let config = SystemConfig::default();
        let model = config.wing_model().unwrap();
        let k = config.kinematics();
        assert_eq!(
            (k.frequency, k.amplitude_deg(), k.mean_angle_deg()),
            (11.0, 30.0, 0.0)
        );
        let mut v = Vehicle::quasi_steady(&model, &k, &config.flight(), config.actuator.actuator())
            .unwrap();
        v.aero_damping_nms2 = INITIAL_DESIGN_AERO_DAMPING;
        let rebuilt = v.plant(11.0);
        let shipped = PlantParams::default();
        assert_eq!(shipped.motor, rebuilt.motor);
        assert_eq!(shipped.supply, rebuilt.supply);
        assert_eq!(shipped.sensors, rebuilt.sensors);
        assert_eq!(shipped.simulation, rebuilt.simulation);
        let close = |a: f64, b: f64, what: &str| {
            assert!(
                (a / b - 1.0).abs() < 1e-6,
                "{what}: shipped {a}, rebuilt {b}"
            );
        };
        let (s, r) = (&shipped.transmission, &rebuilt.transmission);
        assert_eq!([s.gear_ratio, s.efficiency], [r.gear_ratio, r.efficiency]);
        close(s.spring_nm_per_rad, r.spring_nm_per_rad, "spring");
        let (s, r) = (&shipped.wing, &rebuilt.wing);
        assert_eq!(
            [s.span_m, s.root_chord_m, s.tip_chord_m, s.air_density_kg_m3],
            [r.span_m, r.root_chord_m, r.tip_chord_m, r.air_density_kg_m3]
        );
        close(s.inertia_kg_m2, r.inertia_kg_m2, "wing inertia");
        close(
            s.aero_damping(),
            INITIAL_DESIGN_AERO_DAMPING,
            "aero damping",
        );
    }
}
