//! One evaluation of the aerodynamic discipline: the mid-span section of
//! the wing flapping with given kinematics, deforming as the system
//! analysis found (held fixed within the cycle, as the seed paper's
//! discipline holds it), analysed in 2D by the LDVM of [`crate::aero2d`].
//!
//! Physical to non-dimensional: the section of chord `c` at `r` from the
//! flapping axis in a flight at `U` flaps at the reduced frequency `k = pi f
//! c / U` and sweeps `r / c` chords about the axis ([`SectionFlapping`]:
//! plunge, and the surge of an inclined stroke plane). The deformation
//! samples cover one cycle of the system analysis; a changed frequency
//! stretches them over the new cycle (the shape history is kept in phase
//! with the stroke).
//!
//! Separation: the LDVM sheds leading-edge vortices whenever the leading-edge
//! suction parameter `|A0|` exceeds the section's critical value
//! ([`SectionCase::lesp_critical`], default [`FWAV_LESP_CRITICAL`]; Ramesh,
//! Gopalarathnam, Granlund, Ol & Edwards 2014, J. Fluid Mech. 751, 500-538),
//! so a large amplitude no longer gains thrust from leading-edge suction the
//! edge cannot hold. Viscosity: the laminar friction estimate is subtracted
//! from the inviscid thrust ([`SectionResult::ct_net`]), and the discipline
//! optimizes the net quantities.
//!
//! The flow model is the case's ([`SectionCase::model`],
//! [`super::section_model`]): the LDVM above, or laminar Navier–Stokes of
//! a thin plate ([`crate::aero2d::viscous`]) at the chord Reynolds number
//! `U c / nu` ([`AIR_KINEMATIC_VISCOSITY`]), summarized the same way (the
//! periods after the first [`TRANSIENT_CYCLES`] of `cycles`). Its forces
//! include the friction, so its friction history is zero and `ct_net ==
//! ct`; it sheds vorticity where the flow does, so the critical LESP does
//! not apply to it (the setting stays, unused: [`SectionCase::modelled`]);
//! it takes the deformation as the plate's mid-line, on a grid that moves
//! with it ([`SectionCase::modelled_section`]).

use fwav_settings::Shown;
use serde::{Deserialize, Serialize};

use crate::aero2d::camber::{CamberError, CamberHistory};
use crate::aero2d::case::{MAX_REDUCED_FREQUENCY, MAX_STEPS};
use crate::aero2d::friction::streamwise_friction;
use crate::aero2d::ldvm::{
    cycle_mean_of, cycle_means, cycle_means_until, History, Ldvm, Motion, SectionFlapping, Settings,
};
use crate::aero2d::panel::{PanelError, PanelSettings, PanelSolver, SectionShape};
use crate::aero2d::viscous::{SectionPath, ViscousError};
use crate::aeroelastic::kinematics::{FlappingKinematics, KinematicsError};
use crate::aeroelastic::model::FlightCondition;

use super::section_model::{LdvmFlow, ModelledSection, SectionFlowModel};

/// Kinematic viscosity of sea-level air, m²/s (for the chord Reynolds
/// number of the friction estimate).
pub const AIR_KINEMATIC_VISCOSITY: f64 = 1.46e-5;

/// Critical LESP of the FWAV's mid-span section (thin mylar membrane,
/// sharp leading edge, chord Reynolds number about 12,000-15,000): 0.11.
///
/// Ramesh et al. (2014, J. Fluid Mech. 751) show the critical LESP is a
/// property of the section shape and the Reynolds number, not of the
/// motion, and that it falls with the leading-edge radius (SD7003, a
/// rounded 8.5% section at Re 30,000: 0.18, the repository's validation
/// case 1). For a flat plate the LDVM's authors use 0.11 (Ramesh's
/// UNSflow flat-plate cases, after Eldredge's canonical pitch-up at
/// Re 1,000). A membrane of zero leading-edge radius is the flat-plate
/// limit; its separation is fixed by the sharp edge, so the Reynolds
/// number dependence measured for rounded edges (boundary-layer
/// tolerance of the suction peak) is taken as weak from Re 1,000 to
/// 15,000. This is an extrapolation in Reynolds number, not a value
/// measured at the section's Re.
pub const FWAV_LESP_CRITICAL: f64 = 0.11;

/// The periods each analysis runs before the ones it scores: the start's
/// transient. An analysis of `cycles` periods is scored by the means over
/// its last `cycles - 2` ([`SectionCase::scored_cycles`]): strokes 3 and 4
/// of the default 4.
pub const TRANSIENT_CYCLES: usize = 2;

/// The section and how to analyse it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SectionCase {
    /// Section chord, m.
    pub chord: f64,
    /// Distance of the section from the flapping axis, m.
    pub radius: f64,
    /// Flight condition.
    pub flight: FlightCondition,
    /// Mid-line samples over one cycle, chords, in the section's flapping
    /// frame, sample `k` at `(k + 1) dt` after a cycle start (the system
    /// analysis's `section_history`); empty: a rigid flat section.
    pub deformation: Vec<Vec<[f64; 2]>>,
    /// Cycles simulated; all after the first [`TRANSIENT_CYCLES`] are
    /// averaged (`[design] section_cycles`).
    pub cycles: usize,
    /// Time steps per cycle (at least; the step is also at most 0.015
    /// chords travelled).
    pub steps_per_cycle: usize,
    /// Critical leading-edge suction parameter beyond which leading-edge
    /// vortices are shed (separation); None: attached flow. The LDVM's
    /// only (the Navier–Stokes model separates where the flow does).
    #[serde(default)]
    pub lesp_critical: Option<f64>,
    /// The flow model (LDVM in files written before it was chosen; not
    /// written for the LDVM, so those files still read. The evaluation
    /// cache's keys add the model's results revision:
    /// `discipline::cache::key`).
    #[serde(default, skip_serializing_if = "SectionFlowModel::is_ldvm")]
    pub model: SectionFlowModel,
}

/// The cycle-mean results of one evaluation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SectionResult {
    /// Reduced frequency `k = pi f c / U`.
    pub reduced_frequency: f64,
    /// Mean thrust coefficient, on `1/2 rho U^2 c`: the LDVM's inviscid
    /// one; the Navier–Stokes model's includes the friction.
    pub ct: f64,
    /// Mean thrust coefficient less the laminar friction estimate (the
    /// Navier–Stokes model's `ct`: it has no separate estimate).
    pub ct_net: f64,
    /// Mean power coefficient, on `1/2 rho U^3 c`.
    pub cp: f64,
    /// Propulsive efficiency `CT / CP` (the LDVM's inviscid; equal to
    /// `efficiency_net` for the Navier–Stokes model).
    pub efficiency: f64,
    /// Net propulsive efficiency `ct_net / CP` (the discipline's
    /// efficiency objective).
    pub efficiency_net: f64,
    /// Change of the mean CT between the last two cycles (periodicity).
    pub ct_change: f64,
}

/// Why an evaluation failed.
#[derive(Debug, thiserror::Error)]
pub enum EvaluationError {
    /// Kinematics out of range.
    #[error(transparent)]
    Kinematics(#[from] KinematicsError),
    /// The deformation samples are unusable.
    #[error("section deformation: {0}")]
    Deformation(#[from] CamberError),
    /// The section's chord, its radius from the flapping axis or the
    /// flight speed is not positive.
    #[error(
        "section case: chord {chord_m} m, radius {radius_m} m and speed {speed_m_s} m/s must each \
         be positive and finite"
    )]
    NotPositive {
        /// The chord, m.
        chord_m: f64,
        /// The section's radius from the flapping axis, m.
        radius_m: f64,
        /// The flight speed, m/s.
        speed_m_s: f64,
    },
    /// Too few cycles, or too few steps a cycle, to score.
    #[error(
        "section case: needs at least 3 cycles of 20 steps each (got {cycles} cycles of \
         {steps_per_cycle} steps)"
    )]
    TooShort {
        /// Cycles asked for.
        cycles: usize,
        /// Steps a cycle asked for.
        steps_per_cycle: usize,
    },
    /// The critical LESP is not positive.
    #[error("section case: critical LESP {0} must be positive (or none for attached flow)")]
    LespCritical(f64),
    /// The panel method refused the section
    /// ([`SectionCase::evaluate_panel`]).
    #[error("the panel section analysis: {0}")]
    Panel(#[from] PanelError),
    /// The Navier–Stokes model failed (the solver refused the case or
    /// diverged, a bad plate thickness, a time step that kept falling).
    #[error("the Navier–Stokes section analysis: {0}")]
    Viscous(#[from] ViscousError),
    /// The solution is not finite (the solver diverged).
    #[error("the 2D analysis diverged (non-finite {0})")]
    Diverged(&'static str),
    /// The drive puts no power into the flow over the scored cycles: the
    /// section has no propulsive efficiency (its ratio to a negative power
    /// would flip the thrust's sign). At 0.1 m/s the default section flaps
    /// at reduced frequency 20.7, and the LDVM on its analysed deformation
    /// gave CP -1.56e7 with CT +2651 (such a flight is now refused before
    /// the run: [`EvaluationError::BeyondModels`]).
    #[error(
        "the section's mean power coefficient is {cp:.4e} at reduced frequency \
         {reduced_frequency:.3}: the drive puts no power into the flow (the flow does work on \
         the section instead), so the section has no propulsive efficiency; check the flight \
         speed and the frequency (k = pi f c / U)"
    )]
    NoInputPower {
        /// Mean power coefficient of the scored cycles.
        cp: f64,
        /// The section's reduced frequency `pi f c / U`.
        reduced_frequency: f64,
    },
    /// A frequency so high for the section and flight speed that the
    /// reduced frequency is past the 2D models' range
    /// ([`MAX_REDUCED_FREQUENCY`]): the flight is nearly hover for this
    /// flapping.
    #[error(
        "{frequency_hz} Hz flaps the section at reduced frequency {reduced_frequency:.4}, past \
         the 2D section models' {max} (the flight is nearly hover for this flapping, and the \
         models scale the flow by the flight speed); at most {max_frequency_hz} Hz at this \
         flight speed"
    )]
    BeyondModels {
        /// The flapping frequency, Hz.
        frequency_hz: f64,
        /// Its reduced frequency.
        reduced_frequency: f64,
        /// The most the models take ([`MAX_REDUCED_FREQUENCY`]).
        max: f64,
        /// The highest frequency that fits, Hz, rounded down to 0.001
        /// ([`Shown::at_most`]: it passes as printed).
        max_frequency_hz: f64,
    },
    /// A frequency so low for the section and flight speed that a period
    /// is hundreds of chords: the analysis would take too many steps.
    #[error(
        "{frequency_hz} Hz flaps the section at reduced frequency {reduced_frequency:.4}: \
         {steps} time steps an analysis (at most {max}); at least {min_frequency_hz} Hz \
         is needed at this flight speed"
    )]
    TooManySteps {
        /// The flapping frequency, Hz.
        frequency_hz: f64,
        /// Its reduced frequency.
        reduced_frequency: f64,
        /// Steps the analysis would take.
        steps: usize,
        /// The most allowed ([`MAX_STEPS`]).
        max: usize,
        /// The lowest frequency that fits, Hz, rounded up to 0.001
        /// ([`Shown::at_least`]: it passes as printed).
        min_frequency_hz: f64,
    },
}

impl SectionCase {
    /// The built-in FWAV's mid-span section: chord 0.06 m at 0.075 m from
    /// the axis, 3 m/s at sea level, rigid, 4 cycles of at least 100 steps,
    /// leading-edge shedding beyond [`FWAV_LESP_CRITICAL`], the LDVM.
    pub fn fwav_mid_span() -> Self {
        Self {
            chord: 0.06,
            radius: 0.075,
            flight: FlightCondition::FWAV,
            deformation: Vec::new(),
            cycles: 4,
            steps_per_cycle: 100,
            lesp_critical: Some(FWAV_LESP_CRITICAL),
            model: SectionFlowModel::Ldvm,
        }
    }

    /// The case as its model reads it: for the Navier–Stokes model,
    /// without the critical LESP, which it does not take (so the
    /// evaluation cache does not tell apart cases it would compute
    /// alike); the LDVM's case as it is.
    pub fn modelled(&self) -> SectionCase {
        match self.model {
            SectionFlowModel::Ldvm => self.clone(),
            SectionFlowModel::Ns(_) => SectionCase {
                lesp_critical: None,
                ..self.clone()
            },
        }
    }

    /// What this case's evaluations model of the section, for the
    /// reports.
    pub fn modelled_section(&self) -> ModelledSection {
        ModelledSection::new(&self.model, !self.deformation.is_empty(), self.cycles)
    }

    /// The chord Reynolds number `U c / nu` in sea-level air.
    pub fn reynolds(&self) -> f64 {
        self.flight.speed * self.chord / AIR_KINEMATIC_VISCOSITY
    }

    /// The reduced frequency `k = pi f c / U` of flapping at
    /// `frequency_hz`.
    pub fn reduced_frequency(&self, frequency_hz: f64) -> f64 {
        std::f64::consts::PI * frequency_hz * self.chord / self.flight.speed
    }

    /// The LDVM settings of an analysis at reduced frequency `k`:
    /// `cycles` periods of at least `steps_per_cycle` steps of at most
    /// 0.015 chords.
    fn settings(&self, k: f64) -> Settings {
        let period = std::f64::consts::PI / k;
        Settings {
            dt: (period / self.steps_per_cycle as f64).min(Settings::default().dt),
            duration: self.cycles as f64 * period,
            reynolds: Some(self.reynolds()),
            lesp_critical: self.lesp_critical,
            ..Settings::default()
        }
    }

    /// Refuses a frequency whose analysis would take more than
    /// [`MAX_STEPS`] time steps (a period of hundreds of chords), with
    /// the lowest frequency that fits.
    pub fn check_work(&self, frequency_hz: f64) -> Result<(), EvaluationError> {
        let k = self.reduced_frequency(frequency_hz);
        if k > MAX_REDUCED_FREQUENCY {
            return Err(EvaluationError::BeyondModels {
                frequency_hz,
                reduced_frequency: k,
                max: MAX_REDUCED_FREQUENCY,
                max_frequency_hz: Shown::at_most(frequency_hz * MAX_REDUCED_FREQUENCY / k, 3).0,
            });
        }
        let s = self.settings(k);
        // Saturates: an endless analysis (k = 0) counts usize::MAX steps.
        let steps = (s.duration / s.dt).round() as usize;
        if steps <= MAX_STEPS {
            return Ok(());
        }
        let min_k =
            self.cycles as f64 * std::f64::consts::PI / (MAX_STEPS as f64 * Settings::default().dt);
        Err(EvaluationError::TooManySteps {
            frequency_hz,
            reduced_frequency: k,
            steps,
            max: MAX_STEPS,
            min_frequency_hz: Shown::at_least(frequency_hz * min_k / k, 3).0,
        })
    }

    /// Refuses a Navier–Stokes case whose grid cannot resolve its
    /// Reynolds number ([`crate::aero2d::viscous::ViscousSection::check_resolution`]);
    /// the LDVM takes any.
    ///
    /// # Errors
    /// [`EvaluationError::Viscous`] with
    /// [`crate::aero2d::viscous::ViscousError::Unresolved`].
    pub fn check_resolution(&self) -> Result<(), EvaluationError> {
        match &self.model {
            SectionFlowModel::Ns(plate) => Ok(plate.section().check_resolution(self.reynolds())?),
            SectionFlowModel::Ldvm => Ok(()),
        }
    }

    /// The periods the scores average: all after the first
    /// [`TRANSIENT_CYCLES`].
    pub fn scored_cycles(&self) -> usize {
        self.cycles.saturating_sub(TRANSIENT_CYCLES)
    }

    /// How much one evaluation's scores scatter (relative standard
    /// deviations of the net thrust and efficiency) for this case's model
    /// and scored periods ([`SectionFlowModel::window_scatter`]).
    pub fn scatter(&self) -> (f64, f64) {
        let flow = LdvmFlow::of(self.lesp_critical.is_some(), !self.deformation.is_empty());
        self.model.window_scatter(self.scored_cycles(), flow)
    }

    /// Runs the 2D analysis for `kinematics` by the case's model and
    /// summarizes its periods after the first [`TRANSIENT_CYCLES`].
    ///
    /// Cost: the LDVM a fraction of a second; the Navier–Stokes model at
    /// the default resolution 67.5 s (rigid) to 99.3 s (deforming as the
    /// built-in design's first system analysis found) for 4 cycles on
    /// the two-core development machine (2026-12-05), in proportion to
    /// the cycles for more
    /// ([`crate::aero2d::viscous::ViscousSection::run`]).
    ///
    /// # Errors
    /// [`EvaluationError`]: kinematics or case values out of range, an
    /// analysis too long, unusable deformation samples, a solver failure
    /// or divergence.
    pub fn evaluate(
        &self,
        kinematics: &FlappingKinematics,
    ) -> Result<SectionResult, EvaluationError> {
        let (history, k) = self.history(kinematics)?;
        summarize(&history, std::f64::consts::PI / k, k, self.scored_cycles())
    }

    /// The loads' history of the analysis [`Self::evaluate`] summarizes,
    /// `cycles` periods sampled uniformly, and the reduced frequency.
    ///
    /// # Errors
    /// As [`Self::evaluate`].
    pub fn history(
        &self,
        kinematics: &FlappingKinematics,
    ) -> Result<(History, f64), EvaluationError> {
        let flapping = self.flapping(kinematics)?;
        let k = flapping.reduced_frequency;
        let period = std::f64::consts::PI / k;
        let history = match &self.model {
            SectionFlowModel::Ldvm => self.ldvm_history(flapping, period)?,
            SectionFlowModel::Ns(plate) => {
                let (path, duration) =
                    (SectionPath::Flapping(flapping), self.cycles as f64 * period);
                let section = plate.section();
                let run = if self.deformation.is_empty() {
                    section.run(path, self.reynolds(), duration)?
                } else {
                    let samples = self.samples();
                    match plate.shape_tolerance {
                        Some(tolerance) => section.run_deflecting(
                            path,
                            self.reynolds(),
                            duration,
                            &samples,
                            tolerance,
                        )?,
                        None => section.run_deforming(path, self.reynolds(), duration, &samples)?,
                    }
                };
                run.history
            }
        };
        Ok((history, k))
    }

    /// The section's motion when the wing flaps by `kinematics`, once
    /// the kinematics, the case and the analysis's length are checked.
    fn flapping(
        &self,
        kinematics: &FlappingKinematics,
    ) -> Result<SectionFlapping, EvaluationError> {
        kinematics.validate()?;
        self.check()?;
        self.check_work(kinematics.frequency)?;
        Ok(SectionFlapping {
            reduced_frequency: self.reduced_frequency(kinematics.frequency),
            radius: self.radius / self.chord,
            amplitude: kinematics.amplitude,
            mean_angle: kinematics.mean_angle,
            stroke_plane: kinematics.stroke_plane,
        })
    }

    /// The section flapping by `kinematics` as the rigid thick section
    /// `shape` by the unsteady panel method
    /// ([`PanelSolver::with_flapping`]), with the LDVM's steps and the
    /// same laminar friction estimate subtracted for the net values: the
    /// third model of the comparison over the L18 rows (docs/ns-design),
    /// not one of the discipline's (no deformation, no leading-edge
    /// shedding). Cost: about a second for the default section on 160
    /// panels.
    ///
    /// # Errors
    /// As [`Self::evaluate`]; [`EvaluationError::Panel`] when the solver
    /// refuses the section.
    pub fn evaluate_panel(
        &self,
        kinematics: &FlappingKinematics,
        shape: &SectionShape,
    ) -> Result<SectionResult, EvaluationError> {
        let flapping = self.flapping(kinematics)?;
        let k = flapping.reduced_frequency;
        let steps = self.settings(k);
        let settings = PanelSettings {
            dt: steps.dt,
            duration: steps.duration,
            ..PanelSettings::default()
        };
        let mut history = PanelSolver::new(shape, Motion::plunge(k, 0.0), settings)?
            .with_flapping(flapping)
            .run();
        let reynolds = self.reynolds();
        history.cd_friction = history
            .time
            .iter()
            .map(|&t| {
                let (_, x_dot, _, h_dot) = flapping.at(t);
                streamwise_friction(reynolds, 0.0, h_dot, x_dot)
            })
            .collect();
        summarize(&history, std::f64::consts::PI / k, k, self.scored_cycles())
    }

    /// Refuses case values out of range: a chord, radius or speed not
    /// positive, fewer than 3 cycles of 20 steps, a critical LESP not
    /// positive.
    fn check(&self) -> Result<(), EvaluationError> {
        let positive = |v: f64| v.is_finite() && v > 0.0;
        if !(positive(self.chord) && positive(self.radius) && positive(self.flight.speed)) {
            return Err(EvaluationError::NotPositive {
                chord_m: self.chord,
                radius_m: self.radius,
                speed_m_s: self.flight.speed,
            });
        }
        if self.cycles < 3 || self.steps_per_cycle < 20 {
            return Err(EvaluationError::TooShort {
                cycles: self.cycles,
                steps_per_cycle: self.steps_per_cycle,
            });
        }
        if let Some(l) = self.lesp_critical {
            if !(l.is_finite() && l > 0.0) {
                return Err(EvaluationError::LespCritical(l));
            }
        }
        Ok(())
    }

    /// The deformation's mid-lines, sample `i` at `i` periods over their
    /// number after a cycle's start (the system analysis's sample `k` is
    /// at `(k + 1) dt`: its last is the cycle's start).
    fn samples(&self) -> Vec<Vec<(f64, f64)>> {
        let n = self.deformation.len();
        (0..n)
            .map(|i| {
                self.deformation[(i + n - 1) % n]
                    .iter()
                    .map(|p| (p[0], p[1]))
                    .collect()
            })
            .collect()
    }

    /// The LDVM's history of the section flapping as `flapping` (period
    /// `period` chords travelled), deforming as [`Self::deformation`].
    fn ldvm_history(
        &self,
        flapping: SectionFlapping,
        period: f64,
    ) -> Result<History, EvaluationError> {
        let k = flapping.reduced_frequency;
        let mut solver =
            Ldvm::new(Motion::plunge(k, 0.0), self.settings(k)).with_flapping(flapping);
        if !self.deformation.is_empty() {
            let samples = self.samples();
            let stations = samples.iter().map(Vec::len).max().unwrap_or(0).max(21);
            solver = solver.with_camber(CamberHistory::from_section_points(
                &samples, period, stations,
            )?);
        }
        Ok(solver.run())
    }
}

/// The cycle means of the last `scored` periods of `history` (period
/// `period`, reduced frequency `k`), the friction estimate's mean
/// subtracted for the net values (zero for the Navier–Stokes model, whose
/// forces include the friction: there `ct_net == ct`), and the change of
/// the mean CT from the second-last period to the last.
fn summarize(
    history: &History,
    period: f64,
    k: f64,
    scored: usize,
) -> Result<SectionResult, EvaluationError> {
    let (ct, cp, efficiency) = cycle_means(history, period, scored);
    let end = history.time.last().copied().unwrap_or(0.0);
    let (ct_before, _, _) = cycle_means_until(history, period, 1, end - period);
    let (ct_last, _, _) = cycle_means(history, period, 1);
    let friction = cycle_mean_of(history, &history.cd_friction, period, scored);
    let result = SectionResult {
        reduced_frequency: k,
        ct,
        ct_net: ct - friction,
        cp,
        efficiency,
        efficiency_net: (ct - friction) / cp,
        ct_change: if ct_before.abs() > 0.0 {
            ct_last / ct_before - 1.0
        } else {
            0.0
        },
    };
    for (name, v) in [("CT", result.ct), ("CP", result.cp), ("friction", friction)] {
        if !v.is_finite() {
            return Err(EvaluationError::Diverged(name));
        }
    }
    // Before the efficiency, which a power of 0 makes infinite.
    if result.cp <= 0.0 {
        return Err(EvaluationError::NoInputPower {
            cp: result.cp,
            reduced_frequency: k,
        });
    }
    if !result.efficiency_net.is_finite() {
        return Err(EvaluationError::Diverged("net efficiency"));
    }
    Ok(result)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A history of three periods of 1 s with constant loads (CT, CP).
    fn steady_history(ct: f64, cp: f64) -> History {
        let time: Vec<f64> = (0..=300).map(|i| f64::from(i) / 100.0).collect();
        let n = time.len();
        History {
            ct: vec![ct; n],
            cp: vec![cp; n],
            cl: vec![0.0; n],
            lesp: vec![0.0; n],
            bound_circulation: vec![0.0; n],
            cl_impulse: vec![0.0; n],
            cd_friction: vec![0.0; n],
            time,
        }
    }

    /// A section the drive puts no power into has no propulsive efficiency:
    /// its evaluation is refused as such, whatever its thrust (at 0.1 m/s the
    /// initial design's LDVM run had CT +2651 and CP -1.56e7, and the
    /// discipline asked for kinematics that "produce thrust"; a candidate
    /// like it would have been scored with an efficiency of the wrong sign).
    #[test]
    fn a_section_without_input_power_has_no_efficiency() {
        let fine = summarize(&steady_history(0.06, 2.87), 1.0, 0.69, 2).unwrap();
        assert!((fine.efficiency - 0.06 / 2.87).abs() < 1e-12, "{fine:?}");
        for cp in [-1.56e7, 0.0] {
            let e = summarize(&steady_history(2651.0, cp), 1.0, 20.7, 2).unwrap_err();
            assert!(
                matches!(e, EvaluationError::NoInputPower { reduced_frequency, .. }
                    if reduced_frequency == 20.7),
                "{e}"
            );
            assert!(
                e.to_string()
                    .contains("at reduced frequency 20.700: the drive puts no power"),
                "{e}"
            );
        }
    }

    /// A case out of range is refused before any analysis, its error
    /// carrying the values that are wrong.
    #[test]
    fn a_case_out_of_range_is_refused_with_its_values() {
        let design = FlappingKinematics::INITIAL;
        let base = SectionCase::fwav_mid_span();
        let no_chord = SectionCase {
            chord: 0.0,
            ..base.clone()
        };
        match no_chord.evaluate(&design) {
            Err(EvaluationError::NotPositive {
                chord_m,
                radius_m,
                speed_m_s,
            }) => {
                assert_eq!(chord_m, 0.0);
                assert_eq!(radius_m, base.radius);
                assert_eq!(speed_m_s, base.flight.speed);
            }
            other => panic!("a zero chord gave {other:?}"),
        }
        let short = SectionCase {
            cycles: 2,
            ..base.clone()
        };
        let err = short.evaluate(&design).unwrap_err();
        assert!(matches!(
            err,
            EvaluationError::TooShort {
                cycles: 2,
                steps_per_cycle: 100
            }
        ));
        assert_eq!(
            err.to_string(),
            "section case: needs at least 3 cycles of 20 steps each (got 2 cycles of 100 steps)"
        );
        let bad_lesp = SectionCase {
            lesp_critical: Some(-0.1),
            ..base
        };
        let err = bad_lesp.evaluate(&design).unwrap_err();
        assert!(matches!(err, EvaluationError::LespCritical(l) if l == -0.1));
        assert_eq!(
            err.to_string(),
            "section case: critical LESP -0.1 must be positive (or none for attached flow)"
        );
    }
}
