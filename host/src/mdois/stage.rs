//! The three stages of a design cycle as functions from files to files.
//! Each stage reads its inputs from the files of the stages before it
//! (the previous cycle's proposals, this cycle's system analysis) and
//! writes its own into `cycle-N/` atomically; a fresh run and a resumed
//! one therefore compute from the same numbers.
//!
//! - system analysis: `cycle-N/system.json`
//!   ([`super::records::SystemRecord`]), and the handoff files
//!   `section.json`, `pressure.json`, `steps.csv`
//!   ([`crate::aeroelastic::handoff`]);
//! - aerodynamic discipline: `cycle-N/kinematics.json`
//!   ([`super::records::KinematicRecord`]), the 2D evaluations kept in
//!   `evaluations.json`;
//! - structural discipline: `cycle-N/topology.json`
//!   ([`super::records::TopologyRecord`]) and `wing-cycle-N.vtu` (the wing
//!   with the cycle's layout, written by `super::output`).
//!
//! Here is the computation of each stage (a method of the stages' shared `Context` that
//! returns the analysis's or discipline's result) and the order of reading,
//! computing and writing; the records are in [`super::records`], the
//! pictures and ParaView files in [`super::output`].

use std::path::PathBuf;
use std::time::Instant;

use crate::aeroelastic::handoff::{self, SectionFile};
use crate::aeroelastic::kinematics::FlappingKinematics;
use crate::aeroelastic::{run, SystemResult, WingModel};
use crate::config::SystemConfig;
use crate::discipline::cache::EvaluationCache;
use crate::discipline::kinematic::{
    optimize_reporting, KinematicError, KinematicResult, ObjectiveReference, Weights,
};
use crate::discipline::section::SectionCase;
use crate::files::{write_atomic, Existing};
use crate::optimize::nsga2::Nsga2Config;
use crate::topology::eslso::{optimize_from, DesignProblem, EslsoProgress, EslsoResult};
use crate::topology::pressure::PressureHistory;
use fwav_actuator::controller_model::checked_controller_model;

use super::error::DesignError;
use super::output::files::write_cycle_wing;
use super::plant::designed_vehicle;
use super::progress::{Event, Progress};
use super::records::system::load_system;
use super::records::{
    self, cycle_dir, cycle_file, cycle_path, load_kinematics, load_topology, KinematicRecord,
    SystemRecord, TopologyRecord,
};
use super::state::{Stage, StageRecord};

/// The evaluation cache's file in the run's directory.
pub const CACHE_FILE: &str = "evaluations.json";

/// The design one cycle analyses: its kinematics and the carbon density
/// per shell element.
#[derive(Clone, Debug, PartialEq)]
pub struct Design {
    /// The kinematics.
    pub kinematics: FlappingKinematics,
    /// Carbon density per element (0/1 after the first cycle).
    pub densities: Vec<f64>,
}

/// What the stages share.
pub(crate) struct Context<'a> {
    /// The run's directory.
    pub dir: PathBuf,
    /// The run's configuration.
    pub config: SystemConfig,
    /// The wing at the uniform starting design.
    pub base: WingModel,
    /// The structural design problem on the wing's mesh.
    pub problem: DesignProblem,
    /// 2D evaluations, kept in [`CACHE_FILE`].
    pub cache: EvaluationCache,
    /// This invocation's number.
    pub run: usize,
    /// When this invocation started.
    pub started: Instant,
    /// The progress display.
    pub progress: &'a (dyn Fn(&Progress) + Sync),
}

/// The layout as densities (1 carbon, 0 mylar only).
pub fn layout_densities(layout: &[bool]) -> Vec<f64> {
    layout.iter().map(|&c| f64::from(u8::from(c))).collect()
}

/// A stage under way: its cycle, its kind and its clock.
struct Running {
    cycle: usize,
    stage: Stage,
    clock: Instant,
}

impl Context<'_> {
    fn report(&self, cycle: usize, stage: Stage, event: Event) {
        (self.progress)(&Progress {
            cycle,
            stage,
            event,
            elapsed: self.started.elapsed(),
        });
    }

    /// Reports a stage reused from an earlier invocation.
    pub fn reused(&self, cycle: usize, stage: Stage) {
        self.report(cycle, stage, Event::Reused);
    }

    /// Starts the clock of `stage` of `cycle` and reports it.
    fn start(&self, cycle: usize, stage: Stage) -> Running {
        self.report(cycle, stage, Event::Started);
        Running {
            cycle,
            stage,
            clock: Instant::now(),
        }
    }

    /// Reports progress `done` of `total` of a stage (`inner`: the ESLSO
    /// cycle).
    fn advanced(&self, running: &Running, done: usize, total: usize, inner: Option<usize>) {
        self.report(
            running.cycle,
            running.stage,
            Event::Advanced { done, total, inner },
        );
    }

    /// The directory of `cycle`'s stage files, made if missing.
    fn cycle_path(&self, cycle: usize) -> Result<PathBuf, DesignError> {
        let path = self.dir.join(cycle_dir(cycle));
        std::fs::create_dir_all(&path).map_err(DesignError::io(&path))?;
        Ok(path)
    }

    /// The design cycle `cycle` analyses: the configuration's for cycle 1,
    /// else the proposals of the cycle before.
    pub fn design(&self, cycle: usize) -> Result<Design, DesignError> {
        if cycle <= 1 {
            return Ok(Design {
                kinematics: self.config.kinematics(),
                densities: self.base.densities.clone(),
            });
        }
        let kinematics = load_kinematics(&self.dir, cycle - 1)?.proposed;
        let topology = load_topology(&self.dir, cycle - 1)?;
        Ok(Design {
            kinematics,
            densities: layout_densities(&topology.result.layout),
        })
    }

    /// Stops the clock of a stage whose files are written, reports it and
    /// makes its state record.
    fn finished(&self, running: Running, files: Vec<String>) -> StageRecord {
        let seconds = running.clock.elapsed().as_secs_f64();
        self.report(running.cycle, running.stage, Event::Finished { seconds });
        StageRecord {
            run: self.run,
            seconds,
            files,
        }
    }

    /// The system analysis of `cycle`'s design: `system.json` and the
    /// handoff files.
    pub fn system(&self, cycle: usize) -> Result<StageRecord, DesignError> {
        let running = self.start(cycle, Stage::System);
        let design = self.design(cycle)?;
        let result = self.analyse(&running, &design)?;
        let steps_per_cycle = self.config.analysis.steps_per_cycle;
        let record = SystemRecord::of(design.kinematics, &result, steps_per_cycle);
        let path = self.cycle_path(cycle)?;
        handoff::write(&path, &result, Existing::Replace)?;
        let system_file = records::system::FORMAT.file;
        write_atomic(&path, system_file, record.to_json()?)?;
        let files = handoff::FILES
            .iter()
            .chain([&system_file])
            .map(|f| cycle_file(cycle, f))
            .collect();
        Ok(self.finished(running, files))
    }

    /// The coupled 3D analysis of `design`; one whose result is not to
    /// be trusted ([`SystemResult::doubts`]) is an error.
    fn analyse(&self, running: &Running, design: &Design) -> Result<SystemResult, DesignError> {
        let wing = self.config.wing_model_with(Some(&design.densities))?;
        let analysis = &self.config.analysis;
        let result = run(
            &wing,
            &design.kinematics,
            &self.config.flight(),
            analysis,
            0,
            |done, total| self.advanced(running, done, total, None),
        )
        .map_err(|source| DesignError::System {
            cycle: running.cycle,
            source,
        })?;
        match result
            .doubts(analysis, self.config.wing.semi_span_m)
            .first()
        {
            Some(&doubt) => Err(DesignError::Doubtful {
                cycle: running.cycle,
                doubt,
            }),
            None => Ok(result),
        }
    }

    /// Refuses the reused system analysis of `cycle` (a resumed design's
    /// `system.json`) for what a new one would be refused for
    /// ([`Self::analyse`]): a record written before the doubts were asked
    /// (2026-12-07) may hold one, and the disciplines would choose on it.
    pub fn check_trusted(&self, cycle: usize) -> Result<(), DesignError> {
        let record = load_system(&self.dir, cycle)?;
        match record
            .doubts(&self.config.analysis, self.config.wing.semi_span_m)
            .first()
        {
            Some(&doubt) => Err(DesignError::DoubtfulRecord { cycle, doubt }),
            None => Ok(()),
        }
    }

    /// The aerodynamic discipline of `cycle`, on the mid-span section of
    /// the cycle's system analysis: `kinematics.json` and the evaluation
    /// cache.
    pub fn kinematics(&self, cycle: usize) -> Result<StageRecord, DesignError> {
        let running = self.start(cycle, Stage::Kinematics);
        let design = self.design(cycle)?;
        let section =
            SectionFile::read(&cycle_path(&self.dir, cycle, handoff::section::FORMAT.file))?;
        let before = self.cache.len();
        let result = self.optimize_kinematics(&running, &design, self.section_case(section))?;
        let computed = self.cache.len().saturating_sub(before)
            + records::kinematics::evaluations_failed(&result);
        let record = KinematicRecord::of(design.kinematics, result, computed);
        let file = records::kinematics::FILE;
        write_atomic(
            &self.cycle_path(cycle)?,
            file,
            records::to_json(&record, file)?,
        )?;
        self.cache.save(&self.dir.join(CACHE_FILE))?;
        Ok(self.finished(running, vec![cycle_file(cycle, file)]))
    }

    /// The 2D case of the mid-span section deforming as in `section`.
    fn section_case(&self, section: SectionFile) -> SectionCase {
        SectionCase {
            deformation: section.samples,
            ..self.config.section_case()
        }
    }

    /// Refuses to go on if the flight controller cannot be set to the
    /// vehicle's model ([`checked_controller_model`]), or if the design of
    /// `cycle` (the initial design in cycle 1) cannot be flown by the
    /// design's actuator with its
    /// reserve, judged on the vehicle of the cycle's system analysis (its
    /// wing's inertia and the damping calibrated on its drive work: the
    /// model the aerodynamic discipline judges its candidates on; the
    /// quasi-steady damping before any analysis is about half the
    /// analysed one on the default wing, too optimistic to stop on).
    pub fn check_flyable(&self, cycle: usize) -> Result<(), DesignError> {
        let design = self.design(cycle)?;
        let vehicle = designed_vehicle(&self.dir, &self.config, cycle, &design.densities)?;
        let demand = crate::vehicle::Vehicle::demand(&design.kinematics);
        checked_controller_model(&vehicle.plant(demand.frequency_hz))
            .map_err(|model| DesignError::BeyondDevice { cycle, model })?;
        let verdict = vehicle
            .check(&demand)
            .map_err(|source| DesignError::Vehicle { cycle, source })?;
        if verdict.feasible {
            return Ok(());
        }
        Err(DesignError::InitialInfeasible {
            frequency_hz: demand.frequency_hz,
            amplitude_deg: demand.amplitude_deg,
            mean_deg: demand.mean_deg,
            limiting: verdict.limiting.to_string(),
            margin_percent: 100.0 * verdict.limiting.margin,
            reserve_percent: 100.0 * verdict.reserve,
        })
    }

    /// The kinematic optimization from `design`'s kinematics on `case`
    /// (new evaluations go into the cache), every candidate judged on the
    /// vehicle of the cycle's system analysis.
    fn optimize_kinematics(
        &self,
        running: &Running,
        design: &Design,
        case: SectionCase,
    ) -> Result<KinematicResult, DesignError> {
        let design_config = &self.config.design;
        let weights = Weights {
            thrust: design_config.thrust_weight,
            efficiency: design_config.efficiency_weight,
        };
        let nsga = Nsga2Config {
            seed: design_config.seed,
            ..Nsga2Config::default()
        };
        let vehicle = designed_vehicle(&self.dir, &self.config, running.cycle, &design.densities)?;
        optimize_reporting(
            &case,
            &self.config.design_space(),
            design.kinematics,
            weights,
            &nsga,
            self.objective_reference(running.cycle)?,
            &self.cache,
            &|k: &FlappingKinematics| vehicle.violation(k),
            &|done, total| self.advanced(running, done, total, None),
        )
        .map_err(|source| DesignError::Kinematics {
            cycle: running.cycle,
            source,
        })
    }

    /// The combined objective's reference of `cycle`'s aerodynamic
    /// discipline: the first cycle's (its initial design's run, from its
    /// `kinematics.json`), so the objective stays the same through the
    /// design; None in the first cycle, which sets it.
    fn objective_reference(&self, cycle: usize) -> Result<Option<ObjectiveReference>, DesignError> {
        if cycle <= 1 {
            return Ok(None);
        }
        let first = load_kinematics(&self.dir, 1)?.result;
        let reference = match (first.reference, &first.initial.result) {
            (Some(r), _) => r,
            (None, Ok(initial)) => ObjectiveReference::of(initial)
                .map_err(|source| DesignError::Kinematics { cycle: 1, source })?,
            (None, Err(e)) => {
                return Err(DesignError::Kinematics {
                    cycle: 1,
                    source: KinematicError::Initial(e.clone()),
                })
            }
        };
        Ok(Some(reference))
    }

    /// The structural discipline of `cycle`, on the pressure history of
    /// the cycle's system analysis, from the cycle's layout:
    /// `topology.json` and the wing's ParaView file.
    pub fn topology(&self, cycle: usize) -> Result<StageRecord, DesignError> {
        let running = self.start(cycle, Stage::Topology);
        let design = self.design(cycle)?;
        let file = handoff::PressureFile::read(&cycle_path(
            &self.dir,
            cycle,
            handoff::pressure::FORMAT.file,
        ))?;
        let pressure = PressureHistory::from_file(file, self.problem.mesh.elements.len())
            .map_err(|source| DesignError::Pressure { cycle, source })?;
        let result = self.optimize_layout(&running, &design, &pressure)?;
        let record = TopologyRecord::of(&self.problem, &design.densities, result);
        let file = records::topology::FILE;
        write_atomic(
            &self.cycle_path(cycle)?,
            file,
            records::to_json(&record, file)?,
        )?;
        let vtu_name = write_cycle_wing(
            &self.dir,
            cycle,
            &self.problem,
            &design.densities,
            &record.result,
            &pressure,
        )?;
        Ok(self.finished(running, vec![cycle_file(cycle, file), vtu_name]))
    }

    /// ESLSO from `design`'s densities under `pressure`; SIMP starts where
    /// the last cycle's ended (see [`optimize_from`]).
    fn optimize_layout(
        &self,
        running: &Running,
        design: &Design,
        pressure: &PressureHistory,
    ) -> Result<EslsoResult, DesignError> {
        let cycle = running.cycle;
        let warm = if cycle > 1 {
            let last = load_topology(&self.dir, cycle - 1)?.result.design_variables;
            (last.len() == self.problem.mesh.elements.len()).then_some(last)
        } else {
            None
        };
        optimize_from(
            &self.problem,
            pressure,
            &design.densities,
            warm.as_deref(),
            &self.config.topology.settings(),
            |p| match p {
                EslsoProgress::Step {
                    cycle: inner,
                    done,
                    total,
                } => self.advanced(running, done, total, Some(inner)),
                EslsoProgress::Cycle(c) => self.report(
                    cycle,
                    Stage::Topology,
                    Event::InnerCycle {
                        inner: c.cycle,
                        elements_changed: c.changed,
                    },
                ),
            },
        )
        .map_err(|source| DesignError::Topology { cycle, source })
    }
}
