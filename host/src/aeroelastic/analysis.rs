//! The coupled system analysis: the flexible wing flapping in the flight
//! condition, the unsteady vortex lattice ([`crate::uvlm`]) and the shell
//! in the flapping frame ([`super::floating_frame`]) strongly coupled at
//! every time step.
//!
//! Each step is a block Gauss–Seidel fixed point on the wing's nodal
//! displacements: the lattice takes the shape and surface velocity of the
//! current iterate, its panel forces go to the shell by the conservative
//! transfer of [`super::interface`], the shell steps from the last
//! converged state, and the new displacements are relaxed with Aitken's
//! dynamic factor (Küttler & Wall 2008, Comput. Mech. 43, eq. 44) until the
//! interface residual `|u_new - u| / |u_new|` falls below the tolerance.
//! Only then is the wake shed and convected and the structural state kept,
//! so each step ends in equilibrium of both fields.

use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

use crate::shell::assembly::{pressure_loads, AssemblyError};
use crate::shell::dynamics::{DynamicsError, GeneralizedAlpha, State};
use crate::uvlm::{Lattice, Solution, Uvlm, UvlmError, UvlmSettings};

use super::floating_frame::FloatingFrameWing;
use super::interface::{InterfaceError, SurfaceMap};
use super::kinematics::{FlappingKinematics, KinematicsError, RootMotion};
use super::model::{FlightCondition, WingModel};
use super::relaxation::{norm, Aitken};

/// Settings of a system analysis (the `[analysis]` table of the
/// configuration; every field optional).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SystemSettings {
    /// Flapping cycles simulated, 2 to 100 (the last one is reported, and
    /// compared with the one before).
    pub cycles: usize,
    /// Time steps per flapping cycle.
    pub steps_per_cycle: usize,
    /// Aerodynamic lattice panels along the chord.
    pub chordwise_panels: usize,
    /// Aerodynamic lattice panels along the span.
    pub spanwise_panels: usize,
    /// Rigid wing: no structure, the lattice follows the flapping only.
    pub rigid: bool,
    /// Interface residual at which a step's coupling stops: the larger of
    /// the relative changes of the nodal displacements and velocities.
    pub coupling_tolerance: f64,
    /// Most sub-iterations a step may take.
    pub max_subiterations: usize,
    /// Spectral radius at infinity of the structural integrator.
    pub rho_inf: f64,
    /// Wake rows that roll up freely, in flapping cycles of wake.
    pub free_wake_cycles: f64,
    /// Wake kept behind the wing, in flapping cycles (older rows dropped).
    pub wake_cycles: f64,
    /// Vortex core radius, root chords. Fixed to the geometry, not to the
    /// step: a core of a tenth of the step's travel (the lattice's own
    /// default) shrank to 0.34 mm at 80 steps a cycle, and wake vortices
    /// passing the flexing trailing edge then kicked the loads into a
    /// growing sawtooth. 0.03 c (2.25 mm) is about the laminar Lamb–Oseen
    /// core of wake a flapping cycle old (`r_c = sqrt(4 α ν t)`, `α` =
    /// 1.256, air's `ν` 1.5e-5 m²/s: 2.4 mm at 13 Hz, 2.6 mm at 11 Hz;
    /// Leishman, Principles of Helicopter Aerodynamics, 2nd ed., ch. 10).
    /// The former 0.01 c (0.75 mm, a wake
    /// a few milliseconds old) let the previous stroke's wake, passing the
    /// deflected mylar panels of a 0/1 layout, stall the coupling: the
    /// default wing's first ESLSO layout at 13 Hz and 40° diverged at step
    /// 129 of 160 with it, converges at 0.03 c in 7.8 sub-iterations a
    /// step (0.02 c still left two steps at the sub-iteration cap). The
    /// default case's mean CT moves from 1.248 to 1.319 (+5.7%) with it.
    pub core_radius_chords: f64,
}

impl Default for SystemSettings {
    /// The built-in case: 4 cycles of 40 steps, an 8 x 16 lattice, coupling
    /// to 1e-6 (1e-4 moves the default case's mean CT by 0.5% and runs in
    /// two thirds of the time), rho_inf 0.8, one cycle of free wake in two
    /// kept, a core of 0.03 root chords.
    fn default() -> Self {
        Self {
            cycles: 4,
            steps_per_cycle: 40,
            chordwise_panels: 8,
            spanwise_panels: 16,
            rigid: false,
            coupling_tolerance: 1e-6,
            max_subiterations: 30,
            rho_inf: 0.8,
            free_wake_cycles: 1.0,
            wake_cycles: 2.0,
            core_radius_chords: 0.03,
        }
    }
}

/// Why a system analysis stopped.
#[derive(Debug, thiserror::Error)]
pub enum SystemError {
    /// Bad kinematics.
    #[error(transparent)]
    Kinematics(#[from] KinematicsError),
    /// The structural model could not be built.
    #[error(transparent)]
    Structure(#[from] DynamicsError),
    /// The aerodynamic loads could not be put on the shell.
    #[error(transparent)]
    Loads(#[from] AssemblyError),
    /// The lattice could not be placed.
    #[error(transparent)]
    Interface(#[from] InterfaceError),
    /// The aerodynamic solver failed.
    #[error(transparent)]
    Aerodynamics(#[from] UvlmError),
    /// A setting out of range.
    #[error("system analysis setting {field}: {message}")]
    Setting {
        /// The field.
        field: &'static str,
        /// What is wrong.
        message: String,
    },
    /// The coupled solution blew up.
    #[error(
        "the coupled solution diverged at t = {time:.5} s (step {step}): {what}; the motion is \
         more than this wing takes: lower the frequency or the amplitude, stiffen the wing, or \
         take more steps a cycle ([analysis] steps_per_cycle)"
    )]
    Diverged {
        /// Time, s.
        time: f64,
        /// Step index.
        step: usize,
        /// What was non-finite.
        what: &'static str,
    },
}

/// One time step's record.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StepRecord {
    /// Time, s.
    pub time_s: f64,
    /// Aerodynamic force on the half wing, inertial axes, N.
    pub force_n: [f64; 3],
    /// Aerodynamic power of the wing's motion, W.
    pub power_w: f64,
    /// Thrust coefficient `-F_x / (q S)`.
    pub ct: f64,
    /// Lift coefficient `F_z / (q S)`.
    pub cl: f64,
    /// Power coefficient `P / (q U S)`.
    pub cp: f64,
    /// Aerodynamic moment about the root (the origin), inertial axes, N m.
    pub aero_moment_nm: [f64; 3],
    /// Torque the drive applies about the flapping axis, N m: the wing's
    /// inertia (flexible analysis only) less the aerodynamic moment about
    /// the axis; its product with the flapping rate is the drive's power.
    pub drive_torque_nm: f64,
    /// Elastic displacement of the tip's trailing-edge node in the flapping
    /// frame, m.
    pub tip_displacement_m: [f64; 3],
    /// Coupling sub-iterations taken.
    pub subiterations: usize,
    /// Final relative interface residual (displacements and velocities).
    pub residual: f64,
}

/// Cycle means over the last simulated cycle.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct CycleMeans {
    /// Mean thrust coefficient.
    pub ct: f64,
    /// Mean lift coefficient.
    pub cl: f64,
    /// Mean power coefficient.
    pub cp: f64,
    /// Propulsive efficiency `CT / CP`.
    pub efficiency: f64,
    /// Change of the mean CT from the cycle before the last to the last,
    /// relative (how periodic the answer is; an analysis has two cycles
    /// at least).
    pub ct_change_last_two_cycles: f64,
}

/// A kept picture of the wing and wake at one time (for `.vtu` output).
#[derive(Clone, Debug)]
pub struct Snapshot {
    /// Time, s.
    pub time: f64,
    /// Shell node positions, inertial axes, m.
    pub nodes: Vec<Vector3<f64>>,
    /// Pressure jump per shell element, Pa.
    pub element_pressure: Vec<f64>,
    /// Wake corner grid (rows from the trailing edge back, each
    /// `spanwise + 1` points), m.
    pub wake_corners: Vec<Vec<Vector3<f64>>>,
    /// Wake ring strengths, rows by spanwise panels, m²/s.
    pub wake_strength: Vec<Vec<f64>>,
}

/// What a system analysis hands on.
#[derive(Clone, Debug)]
pub struct SystemResult {
    /// Every step.
    pub steps: Vec<StepRecord>,
    /// Means over the last cycle.
    pub means: CycleMeans,
    /// Mid-span section over the last cycle, one sample a step: the
    /// mid-line points `(x, y)` in chords in the section's flapping frame
    /// (undeformed leading edge at (0, 0), trailing edge at (1, 0)), the
    /// input of the aerodynamic discipline ([`crate::aero2d`]). Sample `k`
    /// is at `(k + 1) dt` after the start of a cycle, where the flapping
    /// angle is `mean + amplitude cos(2 pi f t)`.
    pub section_history: Vec<Vec<[f64; 2]>>,
    /// Pressure jump on each shell element over the last cycle, one sample
    /// a step, Pa (the input of the structural discipline).
    pub pressure_history: Vec<Vec<f64>>,
    /// Snapshots of the last cycle, every `snapshot_every` steps.
    pub snapshots: Vec<Snapshot>,
    /// Mass of the half wing, kg (0 for a rigid analysis).
    pub wing_mass_kg: f64,
    /// Reference area (half-wing planform), m².
    pub reference_area_m2: f64,
    /// Time step, s.
    pub dt_s: f64,
}

/// Runs the system analysis of `wing` flapping with `kinematics` in
/// `flight`; `snapshot_every` keeps a snapshot every that many steps of the
/// last cycle (0: none); `progress` is called after every step with the
/// step index and the total.
pub fn run(
    wing: &WingModel,
    kinematics: &FlappingKinematics,
    flight: &FlightCondition,
    settings: &SystemSettings,
    snapshot_every: usize,
    mut progress: impl FnMut(usize, usize),
) -> Result<SystemResult, SystemError> {
    kinematics.validate()?;
    check(settings, flight)?;
    let mut coupling = Coupling::new(wing, kinematics, flight, settings)?;
    let n_cycle = settings.steps_per_cycle;
    let total = settings.cycles * n_cycle;
    let dt = coupling.dt;
    let (mut load_previous, mut state) = coupling.start()?;
    let mut result = SystemResult {
        steps: Vec::with_capacity(total),
        means: CycleMeans {
            ct: 0.0,
            cl: 0.0,
            cp: 0.0,
            efficiency: 0.0,
            ct_change_last_two_cycles: 0.0,
        },
        section_history: Vec::new(),
        pressure_history: Vec::new(),
        snapshots: Vec::new(),
        wing_mass_kg: coupling.structure.as_ref().map_or(0.0, |s| s.mass()),
        reference_area_m2: coupling.area,
        dt_s: dt,
    };

    for step in 0..total {
        let time = (step + 1) as f64 * dt;
        let motion = kinematics.motion(time);
        let converged = coupling.couple(step, time, &motion, state.as_ref(), &load_previous)?;
        coupling
            .uvlm
            .advance(&converged.surface, &converged.solution)?;
        result
            .steps
            .push(coupling.record(step, time, &motion, &converged)?);
        let last_cycle = step + n_cycle >= total;
        if last_cycle {
            let snapshot = snapshot_every > 0 && (total - 1 - step) % snapshot_every == 0;
            coupling.keep_last_cycle(&mut result, time, &motion, &converged, snapshot);
        }
        if let Some(st) = converged.state {
            state = Some(st);
            load_previous = converged.load;
        }
        progress(step + 1, total);
    }
    result.means = cycle_means(&result.steps, n_cycle);
    Ok(result)
}

/// The coupled problem of one run: the two fields and what stays fixed
/// over the run.
struct Coupling<'a> {
    wing: &'a WingModel,
    kinematics: &'a FlappingKinematics,
    flight: &'a FlightCondition,
    settings: &'a SystemSettings,
    /// Lattice and shell on each other.
    map: SurfaceMap,
    /// The lattice's solver with its wake.
    uvlm: Uvlm,
    /// The shell in the flapping frame (`None` for a rigid wing).
    structure: Option<FloatingFrameWing>,
    /// Time step, s.
    dt: f64,
    /// A zero vector per shell node.
    zero: Vec<Vector3<f64>>,
    /// Reference area (the half wing's planform), m².
    area: f64,
    /// Dynamic pressure, Pa.
    q: f64,
    /// The tip's trailing-edge node.
    tip_te: usize,
    /// The mid-span section's nodes, leading edge first.
    section_nodes: Vec<usize>,
    /// The mid-span section's chord, m.
    mid_chord: f64,
}

/// A step's converged (or last) coupling iterate.
struct Converged {
    /// The lattice in its place.
    surface: Lattice,
    /// Its aerodynamic solution.
    solution: Solution,
    /// The shell's state at the step's end (`None` for a rigid wing).
    state: Option<State>,
    /// The shell's loads at the step's end (empty for a rigid wing).
    load: Vec<f64>,
    /// Sub-iterations taken.
    iterations: usize,
    /// Final relative interface residual (0 for a rigid wing).
    residual: f64,
}

impl<'a> Coupling<'a> {
    /// The interface map, the lattice and the shell for `wing` flapping
    /// with `kinematics` in `flight`.
    fn new(
        wing: &'a WingModel,
        kinematics: &'a FlappingKinematics,
        flight: &'a FlightCondition,
        settings: &'a SystemSettings,
    ) -> Result<Self, SystemError> {
        let planform = &wing.planform;
        let mesh = &wing.wing.mesh;
        let map = SurfaceMap::new(
            planform,
            mesh,
            settings.chordwise_panels,
            settings.spanwise_panels,
        )?;
        let period = kinematics.period();
        let n_cycle = settings.steps_per_cycle;
        let dt = period / n_cycle as f64;
        let rows = |cycles: f64| -> usize {
            if cycles.is_finite() {
                (cycles * n_cycle as f64).ceil() as usize
            } else {
                usize::MAX
            }
        };
        let mut aero_settings =
            UvlmSettings::new(dt, flight.density, Vector3::new(flight.speed, 0.0, 0.0));
        aero_settings.symmetric = true;
        aero_settings.free_wake_rows = rows(settings.free_wake_cycles);
        aero_settings.wake_rows = rows(settings.wake_cycles);
        aero_settings.core_radius = settings.core_radius_chords * planform.root_chord;
        let (nc, ns) = (settings.chordwise_panels, settings.spanwise_panels);
        let uvlm = Uvlm::new(nc, ns, aero_settings)?;
        let structure = if settings.rigid {
            None
        } else {
            Some(FloatingFrameWing::new(
                mesh,
                &wing.sections,
                &wing.wing.clamped_dofs(),
                GeneralizedAlpha {
                    dt,
                    rho_inf: settings.rho_inf,
                    mass_damping: 0.0,
                    stiffness_damping: 0.0,
                },
            )?)
        };
        let nodes = mesh.nodes.len();
        let (chord_elements, span_elements) = (planform.chord_elements, planform.span_elements);
        let mid = span_elements / 2;
        let section_nodes: Vec<usize> = (0..=chord_elements)
            .map(|i| mid * (chord_elements + 1) + i)
            .collect();
        Ok(Self {
            wing,
            kinematics,
            flight,
            settings,
            map,
            uvlm,
            structure,
            dt,
            zero: vec![Vector3::zeros(); nodes],
            area: wing.area(),
            q: 0.5 * flight.density * flight.speed * flight.speed,
            tip_te: span_elements * (chord_elements + 1) + chord_elements,
            mid_chord: planform.chord(mesh.nodes[section_nodes[0]].y),
            section_nodes,
        })
    }

    /// The loads at t = 0 (the frame's inertia on the undeformed wing),
    /// which start the structure and are the first step's previous loads,
    /// and the structure's start (both empty for a rigid wing).
    fn start(&self) -> Result<(Vec<f64>, Option<State>), SystemError> {
        let load = self.structure.as_ref().map_or(Vec::new(), |s| {
            s.inertial_loads(&self.kinematics.motion(0.0), &self.zero, &self.zero)
        });
        let state = match &self.structure {
            Some(s) => Some(s.start_deflected(
                &load,
                2.0 * std::f64::consts::PI * self.kinematics.frequency,
            )?),
            None => None,
        };
        Ok((load, state))
    }

    /// One step's block Gauss–Seidel fixed point from the last converged
    /// `state` under `load_previous`: lattice on the iterate, its loads on
    /// the shell, the shell's step, Aitken's relaxation, until the interface
    /// residual is below the tolerance or the sub-iterations run out.
    fn couple(
        &mut self,
        step: usize,
        time: f64,
        motion: &RootMotion,
        state: Option<&State>,
        load_previous: &[f64],
    ) -> Result<Converged, SystemError> {
        let dt = self.dt;
        let (mut u, mut v) = match (&self.structure, state) {
            (Some(s), Some(st)) => {
                let (u, v) = (s.translations(st), s.velocities(st));
                let predicted = u.iter().zip(&v).map(|(u, v)| u + dt * v).collect();
                (predicted, v)
            }
            _ => (self.zero.clone(), self.zero.clone()),
        };
        let mut aitken = Aitken {
            omega: 0.5,
            last_residual: None,
        };
        let mut iterations = 0;
        loop {
            iterations += 1;
            let (surface, solution) = self.aerodynamics(motion, &u, &v).map_err(|e| {
                match (e, &self.structure, state) {
                    // After the first step, on a flexible wing: the
                    // deformed wing folded onto itself or its wake, and
                    // the coupled solution, not the lattice, failed.
                    (SystemError::Aerodynamics(UvlmError::Singular), Some(_), Some(_)) => {
                        SystemError::Diverged {
                            time,
                            step,
                            what: "the circulation (the deformed lattice's influence \
                                       matrix is singular)",
                        }
                    }
                    (e, _, _) => e,
                }
            })?;
            let (Some(s), Some(st)) = (&self.structure, state) else {
                return Ok(Converged {
                    surface,
                    solution,
                    state: None,
                    load: Vec::new(),
                    iterations,
                    residual: 0.0,
                });
            };
            let load = self.shell_loads(s, motion, &solution, &u, &v)?;
            let trial = s.step(st, load_previous, &load);
            let (u_new, v_new) = (s.translations(&trial), s.velocities(&trial));
            let r: Vec<Vector3<f64>> = u_new.iter().zip(&u).map(|(a, b)| a - b).collect();
            // The lattice feels the surface velocity as much as its shape,
            // and at small steps a small displacement error is a large
            // velocity error: both must be converged.
            let r_v: Vec<Vector3<f64>> = v_new.iter().zip(&v).map(|(a, b)| a - b).collect();
            let root_chord = self.wing.planform.root_chord;
            let scale_u = norm(&u_new).max(1e-12 * root_chord);
            let scale_v = norm(&v_new).max(1e-12 * root_chord / dt);
            let residual = (norm(&r) / scale_u).max(norm(&r_v) / scale_v);
            if !residual.is_finite() {
                return Err(SystemError::Diverged {
                    time,
                    step,
                    what: "interface displacement",
                });
            }
            if residual <= self.settings.coupling_tolerance
                || iterations >= self.settings.max_subiterations
            {
                return Ok(Converged {
                    surface,
                    solution,
                    state: Some(trial),
                    load,
                    iterations,
                    residual,
                });
            }
            aitken.relax(&mut u, &mut v, r, &v_new);
        }
    }

    /// The lattice on the shape and surface velocity of the iterate `u`,
    /// `v` (the nodes' translations and velocities in the flapping frame)
    /// in `motion`, and its solution.
    fn aerodynamics(
        &self,
        motion: &RootMotion,
        u: &[Vector3<f64>],
        v: &[Vector3<f64>],
    ) -> Result<(Lattice, Solution), SystemError> {
        let body: Vec<Vector3<f64>> = self
            .map
            .body_corners()
            .iter()
            .zip(self.map.interpolate(u))
            .map(|(x, d)| x + d)
            .collect();
        let corner_v = self.map.interpolate(v);
        let corners = body.iter().map(|p| motion.position(p)).collect();
        let velocity: Vec<Vector3<f64>> = body
            .iter()
            .zip(&corner_v)
            .map(|(p, w)| motion.velocity(p, w))
            .collect();
        let surface = Lattice::new(
            self.settings.chordwise_panels,
            self.settings.spanwise_panels,
            corners,
        )?;
        let solution = self.uvlm.solve(&surface, &velocity)?;
        Ok((surface, solution))
    }

    /// The shell's loads of the lattice's `solution` and of the frame's
    /// inertia on the iterate `u`, `v`.
    fn shell_loads(
        &self,
        s: &FloatingFrameWing,
        motion: &RootMotion,
        solution: &Solution,
        u: &[Vector3<f64>],
        v: &[Vector3<f64>],
    ) -> Result<Vec<f64>, SystemError> {
        let inverse = motion.rotation.inverse();
        // The pressure goes to the shell as a distributed load on its
        // elements (each taking its panel's jump, along its normal in
        // the flapping frame, as the small-deflection model has it):
        // point forces at the panel centres excite the fine mesh's
        // local modes, which at small steps fed back through the
        // surface velocity into a growing sawtooth. The in-plane
        // leading-edge suction goes to the leading-edge nodes.
        let suction: Vec<Vector3<f64>> = solution
            .leading_edge_suction
            .iter()
            .map(|f| inverse * f)
            .collect();
        let mesh = &self.wing.wing.mesh;
        let mut load = pressure_loads(mesh, &self.map.element_pressures(&solution.pressure_jump))?;
        for (l, f) in load.iter_mut().zip(self.map.nodal_forces(&[], &suction)) {
            *l += f;
        }
        for (l, i) in load.iter_mut().zip(s.inertial_loads(motion, u, v)) {
            *l += i;
        }
        Ok(load)
    }

    /// The record of the step `converged` ends, once its aerodynamic force
    /// is known to be finite.
    fn record(
        &self,
        step: usize,
        time: f64,
        motion: &RootMotion,
        converged: &Converged,
    ) -> Result<StepRecord, SystemError> {
        let solution = &converged.solution;
        let force = solution.force;
        if !(force.iter().all(|f| f.is_finite()) && solution.power.is_finite()) {
            return Err(SystemError::Diverged {
                time,
                step,
                what: "aerodynamic force",
            });
        }
        let moment = aerodynamic_moment(&converged.surface, solution);
        let axis = self.kinematics.axis().into_inner();
        let inertia = match (&self.structure, &converged.state) {
            (Some(s), Some(st)) => s.inertial_torque(motion, st, &axis),
            _ => 0.0,
        };
        let tip = match (&self.structure, &converged.state) {
            (Some(s), Some(st)) => s.translations(st)[self.tip_te],
            _ => Vector3::zeros(),
        };
        let (q, area) = (self.q, self.area);
        Ok(StepRecord {
            time_s: time,
            force_n: [force.x, force.y, force.z],
            power_w: solution.power,
            ct: -force.x / (q * area),
            cl: force.z / (q * area),
            cp: solution.power / (q * self.flight.speed * area),
            aero_moment_nm: [moment.x, moment.y, moment.z],
            drive_torque_nm: inertia - axis.dot(&moment),
            tip_displacement_m: [tip.x, tip.y, tip.z],
            subiterations: converged.iterations,
            residual: converged.residual,
        })
    }

    /// Keeps what the last cycle hands on from the step `converged` ends:
    /// the mid-span section, the element pressures and, if `snapshot`, a
    /// snapshot of wing and wake.
    fn keep_last_cycle(
        &self,
        result: &mut SystemResult,
        time: f64,
        motion: &RootMotion,
        converged: &Converged,
        snapshot: bool,
    ) {
        let mesh = &self.wing.wing.mesh;
        let translations = match (&self.structure, &converged.state) {
            (Some(s), Some(st)) => s.translations(st),
            _ => self.zero.clone(),
        };
        let (section_nodes, mid_chord) = (&self.section_nodes, self.mid_chord);
        result.section_history.push(
            section_nodes
                .iter()
                .map(|&n| {
                    let x = mesh.nodes[n] + translations[n];
                    let le = mesh.nodes[section_nodes[0]];
                    [(x.x - le.x) / mid_chord, x.z / mid_chord]
                })
                .collect(),
        );
        let pressure = self
            .map
            .element_pressures(&converged.solution.pressure_jump);
        if snapshot {
            result.snapshots.push(Snapshot {
                time,
                nodes: mesh
                    .nodes
                    .iter()
                    .zip(&translations)
                    .map(|(x, d)| motion.position(&(x + d)))
                    .collect(),
                element_pressure: pressure.clone(),
                wake_corners: self.uvlm.wake().corner_rows(),
                wake_strength: self.uvlm.wake().strength_rows(),
            });
        }
        result.pressure_history.push(pressure);
    }
}

/// The means over the last cycle of `n_cycle` steps, and the change of the
/// mean CT from the cycle before (an analysis has two at least: `check`).
fn cycle_means(steps: &[StepRecord], n_cycle: usize) -> CycleMeans {
    let total = steps.len();
    let last = &steps[total - n_cycle..];
    let mean = |f: &dyn Fn(&StepRecord) -> f64| last.iter().map(f).sum::<f64>() / n_cycle as f64;
    let (ct, cl, cp) = (mean(&|r| r.ct), mean(&|r| r.cl), mean(&|r| r.cp));
    let before = steps[total - 2 * n_cycle..total - n_cycle]
        .iter()
        .map(|r| r.ct)
        .sum::<f64>()
        / n_cycle as f64;
    CycleMeans {
        ct,
        cl,
        cp,
        efficiency: if cp.abs() > 0.0 { ct / cp } else { 0.0 },
        ct_change_last_two_cycles: if before.abs() > 0.0 {
            ct / before - 1.0
        } else {
            0.0
        },
    }
}

/// Moment about the origin of the panel forces (at the panel centres) and
/// of the leading-edge suction (at the strips' leading-edge middles), N m.
fn aerodynamic_moment(surface: &Lattice, solution: &Solution) -> Vector3<f64> {
    let (nc, ns) = (surface.chordwise, surface.spanwise);
    let corner = |i: usize, j: usize| surface.corners[i * (ns + 1) + j];
    let mut m = Vector3::zeros();
    for i in 0..nc {
        for j in 0..ns {
            let centre =
                (corner(i, j) + corner(i + 1, j) + corner(i + 1, j + 1) + corner(i, j + 1)) / 4.0;
            m += centre.cross(&solution.panel_force[i * ns + j]);
        }
    }
    for (j, f) in solution.leading_edge_suction.iter().enumerate() {
        m += (0.5 * (corner(0, j) + corner(0, j + 1))).cross(f);
    }
    m
}

fn check(s: &SystemSettings, flight: &FlightCondition) -> Result<(), SystemError> {
    let bad = |field: &'static str, message: String| Err(SystemError::Setting { field, message });
    // Two at least: the last is reported and compared with the one before
    // (`CycleMeans::ct_change_last_two_cycles`, `Doubt::NotPeriodic`).
    if !(2..=100).contains(&s.cycles) {
        return bad("cycles", format!("{} is outside 2..=100", s.cycles));
    }
    if !(8..=2000).contains(&s.steps_per_cycle) {
        return bad(
            "steps_per_cycle",
            format!("{} is outside 8..=2000", s.steps_per_cycle),
        );
    }
    if !(1..=64).contains(&s.chordwise_panels) || !(1..=200).contains(&s.spanwise_panels) {
        return bad(
            "lattice",
            format!(
                "{} x {} panels: 1..=64 chordwise, 1..=200 spanwise",
                s.chordwise_panels, s.spanwise_panels
            ),
        );
    }
    if !(s.coupling_tolerance > 0.0 && s.coupling_tolerance < 1.0) || s.max_subiterations == 0 {
        return bad(
            "coupling",
            format!(
                "tolerance {} must be in (0, 1) and max_subiterations ({}) at least 1",
                s.coupling_tolerance, s.max_subiterations
            ),
        );
    }
    if !(0.0..=1.0).contains(&s.rho_inf) {
        return bad("rho_inf", format!("{} is outside [0, 1]", s.rho_inf));
    }
    if !(s.core_radius_chords > 0.0 && s.core_radius_chords < 0.5) {
        return bad(
            "core_radius_chords",
            format!("{} is outside (0, 0.5)", s.core_radius_chords),
        );
    }
    if !(s.free_wake_cycles >= 0.0 && s.wake_cycles > 0.0) {
        return bad(
            "wake",
            format!(
                "free_wake_cycles {} must be >= 0 and wake_cycles {} > 0",
                s.free_wake_cycles, s.wake_cycles
            ),
        );
    }
    let positive = |v: f64| v > 0.0 && v.is_finite();
    if !(positive(flight.speed) && positive(flight.density)) {
        return bad(
            "flight",
            format!(
                "speed {} m/s and density {} kg/m^3 must be positive",
                flight.speed, flight.density
            ),
        );
    }
    Ok(())
}
