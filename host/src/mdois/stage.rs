//! The three stages of a design cycle as functions from files to files.
//! Each stage reads its inputs from the files of the stages before it
//! (the previous cycle's proposals, this cycle's system analysis) and
//! writes its own into `cycle-N/` atomically; a fresh run and a resumed
//! one therefore compute from the same numbers.
//!
//! - system analysis: `cycle-N/system.json` ([`SystemRecord`]),
//!   `section.json`, `pressure.json`, `steps.csv`;
//! - aerodynamic discipline: `cycle-N/kinematics.json`
//!   ([`KinematicRecord`]), the 2D evaluations kept in `evaluations.json`;
//! - structural discipline: `cycle-N/topology.json` ([`TopologyRecord`])
//!   and `wing-cycle-N.vtu` (the wing with the cycle's layout).

use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use crate::aeroelastic::handoff::{self, SectionFile};
use crate::aeroelastic::kinematics::FlappingKinematics;
use crate::aeroelastic::{run, CycleMeans, StepRecord, WingModel};
use crate::config::SystemConfig;
use crate::discipline::cache::EvaluationCache;
use crate::discipline::kinematic::{optimize_reporting, KinematicResult, Weights};
use crate::discipline::section::{SectionCase, SectionResult};
use crate::files::write_atomic;
use crate::optimize::nsga2::Nsga2Config;
use crate::shell::vtu::{self, Field};
use crate::topology::eslso::{optimize_from, DesignProblem, EslsoProgress, EslsoResult};
use crate::topology::pressure::PressureHistory;

use super::error::DesignError;
use super::progress::{Event, Progress};
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

/// `cycle-N/system.json`: the system analysis of the cycle's design.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SystemRecord {
    /// The kinematics analysed.
    pub kinematics: FlappingKinematics,
    /// Means over the last simulated cycle (3D thrust, lift, power,
    /// efficiency).
    pub means: CycleMeans,
    /// Every time step.
    pub steps: Vec<StepRecord>,
    /// Time steps a flapping cycle.
    pub steps_per_cycle: usize,
    /// Half of the tip's peak-to-peak flapwise deflection over the last
    /// cycle, m.
    pub tip_deflection_amplitude_m: f64,
    /// Mass of the half wing, kg.
    pub wing_mass_kg: f64,
    /// Reference area (half-wing planform), m².
    pub reference_area_m2: f64,
    /// Time step, s.
    pub dt_s: f64,
}

/// `cycle-N/kinematics.json`: the aerodynamic discipline's run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct KinematicRecord {
    /// The kinematics of the cycle's design (the discipline's initial
    /// design and reference).
    pub analysed: FlappingKinematics,
    /// What the discipline proposes: the chosen candidate, or the
    /// analysed design when no candidate beats it.
    pub proposed: FlappingKinematics,
    /// The chosen candidate's method, if one was chosen.
    pub chosen: Option<String>,
    /// The proposed design's 2D result (None if it failed).
    pub proposed_2d: Option<SectionResult>,
    /// 2D evaluations found in the cache.
    pub evaluations_reused: usize,
    /// The whole discipline run (array, ANOM, surfaces, Pareto front,
    /// candidates).
    pub result: KinematicResult,
}

/// `cycle-N/topology.json`: the structural discipline's run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TopologyRecord {
    /// Design-domain elements whose carbon density differs between the
    /// analysed design and the new layout.
    pub elements_changed: usize,
    /// Elements of the design domain.
    pub design_elements: usize,
    /// Carbon mass fraction of the analysed design.
    pub analysed_mass_fraction: f64,
    /// Carbon mass fraction of the new layout.
    pub mass_fraction: f64,
    /// The ESLSO run (cycles, layout, last SIMP densities).
    pub result: EslsoResult,
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

/// The directory of a cycle's stage files, relative to the run's.
pub fn cycle_dir(cycle: usize) -> String {
    format!("cycle-{cycle}")
}

/// Reads a file of the run (`relative` to `dir`): its path and text.
fn read_run_file(dir: &Path, relative: &str) -> Result<(PathBuf, String), DesignError> {
    let path = dir.join(relative);
    let text = std::fs::read_to_string(&path).map_err(DesignError::io(&path))?;
    Ok((path, text))
}

/// Reads a JSON file of the run (`relative` to `dir`).
pub fn load_json<T: DeserializeOwned>(dir: &Path, relative: &str) -> Result<T, DesignError> {
    let (path, text) = read_run_file(dir, relative)?;
    serde_json::from_str(&text).map_err(|e| DesignError::State {
        path,
        message: e.to_string(),
    })
}

fn to_json<T: Serialize>(value: &T, file: &str) -> Result<String, DesignError> {
    serde_json::to_string(value).map_err(|e| DesignError::output(file, e))
}

/// The system analysis record of `cycle`.
pub fn load_system(dir: &Path, cycle: usize) -> Result<SystemRecord, DesignError> {
    load_json(dir, &format!("{}/system.json", cycle_dir(cycle)))
}

/// The aerodynamic discipline's record of `cycle`.
pub fn load_kinematics(dir: &Path, cycle: usize) -> Result<KinematicRecord, DesignError> {
    load_json(dir, &format!("{}/kinematics.json", cycle_dir(cycle)))
}

/// The structural discipline's record of `cycle`.
pub fn load_topology(dir: &Path, cycle: usize) -> Result<TopologyRecord, DesignError> {
    load_json(dir, &format!("{}/topology.json", cycle_dir(cycle)))
}

/// The layout as densities (1 carbon, 0 mylar only).
pub fn layout_densities(layout: &[bool]) -> Vec<f64> {
    layout.iter().map(|&c| f64::from(u8::from(c))).collect()
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

    fn finished(
        &self,
        cycle: usize,
        stage: Stage,
        clock: Instant,
        files: Vec<String>,
    ) -> StageRecord {
        let seconds = clock.elapsed().as_secs_f64();
        self.report(cycle, stage, Event::Finished { seconds });
        StageRecord {
            run: self.run,
            seconds,
            files,
        }
    }

    /// The system analysis of `cycle`'s design.
    pub fn system(&self, cycle: usize) -> Result<StageRecord, DesignError> {
        let stage = Stage::System;
        let clock = Instant::now();
        self.report(cycle, stage, Event::Started);
        let design = self.design(cycle)?;
        let wing = self.config.wing_model_with(Some(&design.densities))?;
        let analysis = &self.config.analysis;
        let result = run(
            &wing,
            &design.kinematics,
            &self.config.flight(),
            analysis,
            0,
            |done, total| {
                self.report(
                    cycle,
                    stage,
                    Event::Advanced {
                        done,
                        total,
                        inner: None,
                    },
                );
            },
        )
        .map_err(|source| DesignError::System { cycle, source })?;
        let last = &result.steps[result.steps.len().saturating_sub(analysis.steps_per_cycle)..];
        let (low, high) = last
            .iter()
            .map(|s| s.tip_displacement_m[2])
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), z| {
                (l.min(z), h.max(z))
            });
        let record = SystemRecord {
            kinematics: design.kinematics,
            means: result.means,
            steps: result.steps.clone(),
            steps_per_cycle: analysis.steps_per_cycle,
            tip_deflection_amplitude_m: if last.is_empty() {
                0.0
            } else {
                0.5 * (high - low)
            },
            wing_mass_kg: result.wing_mass_kg,
            reference_area_m2: result.reference_area_m2,
            dt_s: result.dt_s,
        };
        let path = self.cycle_path(cycle)?;
        let prefix = cycle_dir(cycle);
        write_atomic(&path, "section.json", handoff::section_json(&result))?;
        write_atomic(&path, "pressure.json", handoff::pressure_json(&result))?;
        write_atomic(&path, "steps.csv", handoff::steps_csv(&result))?;
        write_atomic(&path, "system.json", to_json(&record, "system.json")?)?;
        let files = ["section.json", "pressure.json", "steps.csv", "system.json"]
            .iter()
            .map(|f| format!("{prefix}/{f}"))
            .collect();
        Ok(self.finished(cycle, stage, clock, files))
    }

    /// The aerodynamic discipline of `cycle`, on the mid-span section of
    /// the cycle's system analysis.
    pub fn kinematics(&self, cycle: usize) -> Result<StageRecord, DesignError> {
        let stage = Stage::Kinematics;
        let clock = Instant::now();
        self.report(cycle, stage, Event::Started);
        let design = self.design(cycle)?;
        let prefix = cycle_dir(cycle);
        let (section_path, text) = read_run_file(&self.dir, &format!("{prefix}/section.json"))?;
        let section = SectionFile::from_json(&text).map_err(|e| DesignError::State {
            path: section_path,
            message: e.to_string(),
        })?;
        let planform = self.config.planform();
        let radius = 0.5 * planform.semi_span;
        let case = SectionCase {
            chord: planform.chord(radius),
            radius,
            flight: self.config.flight(),
            deformation: section.samples,
            ..SectionCase::fwav_mid_span()
        };
        let design_config = &self.config.design;
        let weights = Weights {
            thrust: design_config.thrust_weight,
            efficiency: design_config.efficiency_weight,
        };
        let nsga = Nsga2Config {
            seed: design_config.seed,
            ..Nsga2Config::default()
        };
        let initial = design.kinematics;
        let before = self.cache.len();
        let result = optimize_reporting(
            &case,
            &self.config.design_space(),
            initial,
            weights,
            &nsga,
            &self.cache,
            &|done, total| {
                self.report(
                    cycle,
                    stage,
                    Event::Advanced {
                        done,
                        total,
                        inner: None,
                    },
                );
            },
        )
        .map_err(|source| DesignError::Kinematics { cycle, source })?;
        // Failed evaluations are not cached: each was computed.
        let failed = std::iter::once(&result.initial)
            .chain(&result.runs)
            .chain(result.candidates.iter().skip(1).map(|c| &c.confirmation))
            .filter(|e| e.result.is_err())
            .count();
        let computed = self.cache.len().saturating_sub(before) + failed;
        let evaluations = 1 + result.runs.len() + 2;
        let (proposed, chosen, proposed_2d) = match result.chosen {
            Some(i) => {
                let c = &result.candidates[i];
                (
                    c.confirmation.design,
                    Some(c.method.clone()),
                    c.confirmation.result.clone().ok(),
                )
            }
            None => (initial, None, result.initial.result.clone().ok()),
        };
        let record = KinematicRecord {
            analysed: design.kinematics,
            proposed,
            chosen,
            proposed_2d,
            evaluations_reused: evaluations.saturating_sub(computed),
            result,
        };
        let path = self.cycle_path(cycle)?;
        write_atomic(
            &path,
            "kinematics.json",
            to_json(&record, "kinematics.json")?,
        )?;
        self.cache.save(&self.dir.join(CACHE_FILE))?;
        Ok(self.finished(
            cycle,
            stage,
            clock,
            vec![format!("{prefix}/kinematics.json")],
        ))
    }

    /// The structural discipline of `cycle`, on the pressure history of
    /// the cycle's system analysis, from the cycle's layout.
    pub fn topology(&self, cycle: usize) -> Result<StageRecord, DesignError> {
        let stage = Stage::Topology;
        let clock = Instant::now();
        self.report(cycle, stage, Event::Started);
        let design = self.design(cycle)?;
        let prefix = cycle_dir(cycle);
        let (_, text) = read_run_file(&self.dir, &format!("{prefix}/pressure.json"))?;
        let elements = self.problem.mesh.elements.len();
        let pressure = PressureHistory::from_json(&text, elements)
            .map_err(|source| DesignError::Pressure { cycle, source })?;
        let settings = self.config.topology.settings();
        // SIMP starts where the last cycle's ended (see `optimize_from`).
        let warm = if cycle > 1 {
            let last = load_topology(&self.dir, cycle - 1)?.result.design_variables;
            (last.len() == elements).then_some(last)
        } else {
            None
        };
        let result = optimize_from(
            &self.problem,
            &pressure,
            &design.densities,
            warm.as_deref(),
            &settings,
            |p| match p {
                EslsoProgress::Step {
                    cycle: inner,
                    done,
                    total,
                } => self.report(
                    cycle,
                    stage,
                    Event::Advanced {
                        done,
                        total,
                        inner: Some(inner),
                    },
                ),
                EslsoProgress::Cycle(c) => self.report(
                    cycle,
                    stage,
                    Event::InnerCycle {
                        inner: c.cycle,
                        elements_changed: c.changed,
                    },
                ),
            },
        )
        .map_err(|source| DesignError::Topology { cycle, source })?;
        let layout = layout_densities(&result.layout);
        let design_flags = &self.problem.design;
        let elements_changed = design
            .densities
            .iter()
            .zip(&layout)
            .zip(design_flags)
            .filter(|((a, b), &d)| d && a != b)
            .count();
        let record = TopologyRecord {
            elements_changed,
            design_elements: design_flags.iter().filter(|&&d| d).count(),
            analysed_mass_fraction: self.problem.mass_fraction(&design.densities),
            mass_fraction: self.problem.mass_fraction(&layout),
            result,
        };
        let path = self.cycle_path(cycle)?;
        write_atomic(&path, "topology.json", to_json(&record, "topology.json")?)?;
        let vtu_name = format!("wing-cycle-{cycle}.vtu");
        let mean_pressure: Vec<f64> = (0..elements)
            .map(|e| {
                pressure.samples.iter().map(|s| s[e]).sum::<f64>() / pressure.samples.len() as f64
            })
            .collect();
        let domain = layout_densities(design_flags);
        vtu::write(
            &self.dir.join(&vtu_name),
            &self.problem.mesh,
            &[
                Field::CellScalar("carbon", &layout),
                Field::CellScalar("carbon_analysed", &design.densities),
                Field::CellScalar("simp_density", &record.result.densities),
                Field::CellScalar("design_domain", &domain),
                Field::CellScalar("mean_pressure_jump_pa", &mean_pressure),
            ],
        )
        .map_err(|e| DesignError::output(&vtu_name, e))?;
        Ok(self.finished(
            cycle,
            stage,
            clock,
            vec![format!("{prefix}/topology.json"), vtu_name],
        ))
    }
}
