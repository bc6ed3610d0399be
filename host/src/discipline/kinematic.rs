//! The aerodynamic discipline (seed paper): choose the flapping kinematics
//! that maximize the mean thrust coefficient and the propulsive efficiency
//! of the deforming mid-span section, by the paper's three candidates:
//!
//! 1. the best row of the Taguchi L18 array (four three-level factors in
//!    the columns that support a full quadratic,
//!    [`l18_quadratic_columns`](crate::optimize::doe::l18_quadratic_columns));
//! 2. ANOM: the best level of each factor for the combined objective, its
//!    additive prediction and a confirmation run;
//! 3. a reduced quadratic response surface per objective (coded variables
//!    in [-1, 1], QR least squares, [`fit_reduced`]) searched by NSGA-II
//!    for the CT–efficiency Pareto front, the point of the front with the
//!    best combined objective, and a confirmation run.
//!
//! The combined objective (the stated rule for choosing): `w_ct CT / CT_0 +
//! w_eta eta / eta_0`, each objective relative to the reference design's
//! (the weights say how much a relative gain in each is worth). The
//! reference is fixed for the whole design: the initial design of the
//! first cycle ([`ObjectiveReference`]; the design driver hands it to the
//! later cycles). Taken from each cycle's own design instead, the
//! objective changed from cycle to cycle, and two designs on a front could
//! each beat the other relative to itself: the default design on the
//! Navier–Stokes model alternated between them until its cycle cap
//! (docs/ns-design). CT is the net
//! thrust ([`SectionResult::ct_net`]: the LDVM's thrust, with leading-edge
//! shedding, less the laminar friction estimate) and eta the net efficiency
//! `CT_net / CP` ([`SectionResult::efficiency_net`]); the response surfaces
//! fit the same two quantities. The inviscid CT stays in the records. With
//! the Navier–Stokes model (`[design] section_model = "ns"`) CT is its
//! thrust, friction included, on the rigid section; the result records the
//! model and what it leaves out ([`KinematicResult::section`]). The
//! answer is the feasible confirmed candidate (direct runs only: the L18
//! row, the ANOM and RSM confirmations) with the best combined objective,
//! or the initial design if none beats it by more than the evaluations'
//! own scatter ([`KinematicResult::adoption_margin`]: one standard
//! deviation of the difference of two runs; zero only for the attached
//! LDVM, whose flow converges with its step and repeats from stroke to
//! stroke). Without it, the earlier Navier–Stokes design runs moved, cycle
//! after cycle, among designs whose scores differed by less than a run's
//! scatter (docs/ns-design).
//!
//! Feasibility: every candidate is judged by a [`Violation`] closure (the
//! design's actuator model, analytic: the caller builds it, this room
//! does not know the vehicle), its total constraint violation, 0 when
//! every actuator margin keeps the reserve. The best L18 row is the best
//! feasible row; ANOM's pick is its best levels if they are feasible,
//! else the feasible level combination with the best additive prediction;
//! NSGA-II searches the surfaces under constrained domination (Deb et al.
//! 2002, section VI) and its knee is taken from the feasible front; a
//! candidate that is still infeasible (no feasible row, no feasible level
//! combination) is recorded with its violation and never chosen. Every
//! evaluation runs in parallel (rayon); a failed
//! one is recorded with its reason and counts as the worst response seen,
//! and an array whose rows all failed stops the discipline with the first
//! row's reason ([`KinematicError::EveryRowFailed`]).

use std::sync::{Mutex, PoisonError};

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::aeroelastic::kinematics::FlappingKinematics;
use crate::optimize::anom::{Anom, Goal};
use crate::optimize::doe::{DoeError, OrthogonalArray};
use crate::optimize::nsga2::{minimize, Bounds, Evaluation, Nsga2Config};
use crate::optimize::rsm::{fit_reduced, ReduceOptions, ReducedFit, RsmError};

pub use super::design_space::DesignSpace;
pub use error::KinematicError;
pub use objective::{ObjectiveReference, Weights};

use super::cache::EvaluationCache;
use super::section::{SectionCase, SectionResult};
use super::section_model::ModelledSection;

mod error;
mod objective;

use objective::Objective;

/// One direct evaluation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Evaluated {
    /// The design evaluated.
    pub design: FlappingKinematics,
    /// The results, or why the run failed.
    pub result: Result<SectionResult, String>,
}

/// A candidate design and how it was found.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Candidate {
    /// `"best L18 row"`, `"ANOM"` or `"RSM + NSGA-II"`.
    pub method: String,
    /// The predicted combined objective (None for a direct run).
    pub predicted: Option<f64>,
    /// The confirmation (direct) run.
    pub confirmation: Evaluated,
    /// Its combined objective (None if it failed).
    pub combined: Option<f64>,
    /// Its total constraint violation on the actuator (0: feasible; see
    /// [`Violation`]).
    #[serde(default)]
    pub violation: f64,
}

/// The actuator's judgement of some kinematics: the total constraint
/// violation of its margins against the reserve, 0 when feasible (larger:
/// further from feasible). Analytic and cheap: it is called for every
/// NSGA-II individual.
pub type Violation<'a> = &'a (dyn Fn(&FlappingKinematics) -> f64 + Sync);

/// No constraint: every design is feasible.
pub fn unconstrained(_: &FlappingKinematics) -> f64 {
    0.0
}

/// What the discipline hands on.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct KinematicResult {
    /// The initial design's run.
    pub initial: Evaluated,
    /// The initial design's constraint violation on the actuator (0:
    /// feasible; an infeasible initial design is no bar a candidate must
    /// beat). 0 in records written before it was recorded.
    #[serde(default)]
    pub initial_violation: f64,
    /// The 18 runs of the array.
    pub runs: Vec<Evaluated>,
    /// The actuator's constraint violation of each run (0: feasible).
    #[serde(default)]
    pub run_violations: Vec<f64>,
    /// Level means of the combined objective per factor (ANOM).
    pub level_means: Vec<Vec<f64>>,
    /// R², adjusted R² and PRESS of the CT and efficiency surfaces.
    pub surface_quality: [(f64, f64, Option<f64>); 2],
    /// The Pareto front of the surfaces: design, predicted CT and
    /// efficiency.
    pub pareto: Vec<(FlappingKinematics, f64, f64)>,
    /// The three candidates.
    pub candidates: Vec<Candidate>,
    /// Index of the chosen candidate, None: the initial design stays.
    pub chosen: Option<usize>,
    /// How far a candidate's combined objective had to exceed the initial
    /// design's to be chosen: the scatter of the difference of two
    /// evaluations (the flow model's [`window_scatter`]; 0 for the
    /// attached LDVM, and in records written before it was recorded).
    ///
    /// [`window_scatter`]: crate::discipline::section_model::SectionFlowModel::window_scatter
    #[serde(default)]
    pub adoption_margin: f64,
    /// The objective's reference (None in records written before it was
    /// recorded: the initial design's run).
    #[serde(default)]
    pub reference: Option<ObjectiveReference>,
    /// The evaluations' flow model and what it leaves out of the section
    /// (None in records written before it was recorded: the LDVM).
    #[serde(default)]
    pub section: Option<ModelledSection>,
}

impl KinematicResult {
    /// Every direct evaluation the run made (from its cache or not): the
    /// initial design's, the array's rows and the candidates'
    /// confirmations. A design may appear twice (the best row is a
    /// candidate too).
    pub fn evaluations(&self) -> impl Iterator<Item = &Evaluated> {
        std::iter::once(&self.initial)
            .chain(&self.runs)
            .chain(self.candidates.iter().map(|c| &c.confirmation))
    }
}

/// Direct evaluations a run of the discipline makes: the initial design,
/// the 18 array rows and the ANOM and RSM confirmations.
pub const EVALUATIONS: usize = 21;

/// Runs the discipline on `case` over `space` from the `initial` design,
/// unconstrained; `cache` supplies evaluations already done and receives
/// the new ones.
pub fn optimize(
    case: &SectionCase,
    space: &DesignSpace,
    initial: FlappingKinematics,
    weights: Weights,
    nsga: &Nsga2Config,
    cache: &EvaluationCache,
) -> Result<KinematicResult, KinematicError> {
    optimize_feasible(case, space, initial, weights, nsga, cache, &unconstrained)
}

/// [`optimize`] with every candidate judged by `violation` (the actuator):
/// the answer is feasible or the initial design.
pub fn optimize_feasible(
    case: &SectionCase,
    space: &DesignSpace,
    initial: FlappingKinematics,
    weights: Weights,
    nsga: &Nsga2Config,
    cache: &EvaluationCache,
    violation: Violation,
) -> Result<KinematicResult, KinematicError> {
    optimize_reporting(
        case,
        space,
        initial,
        weights,
        nsga,
        None,
        cache,
        violation,
        &|_, _| {},
    )
}

/// [`optimize_feasible`] with the objective's `reference` (None: the
/// initial design's run), calling `progress(done, total)` after each
/// direct evaluation (cached ones included; `total` is [`EVALUATIONS`])
/// from whichever thread made it.
#[allow(clippy::too_many_arguments)]
pub fn optimize_reporting(
    case: &SectionCase,
    space: &DesignSpace,
    initial: FlappingKinematics,
    weights: Weights,
    nsga: &Nsga2Config,
    reference: Option<ObjectiveReference>,
    cache: &EvaluationCache,
    violation: Violation,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<KinematicResult, KinematicError> {
    let evaluations = Evaluations {
        case,
        cache,
        progress,
        done: Mutex::new(0),
    };
    let initial_violation = violation(&initial);
    let initial = evaluations.run(initial);
    let initial_result = initial.result.clone().map_err(KinematicError::Initial)?;
    let reference = match reference {
        Some(r) => r,
        None => ObjectiveReference::of(&initial_result)?,
    };
    let objective = Objective {
        weights,
        reference,
        violation,
    };

    // 1. The array; its best feasible row (the least violating one if
    // none is feasible: recorded, never chosen).
    let array = ArrayRuns::evaluate(space, &evaluations)?;
    let scores = worst(array.runs.iter().map(|e| objective.score(e)).collect());
    let run_violations: Vec<f64> = array.runs.iter().map(|e| violation(&e.design)).collect();
    let best_row = (0..array.runs.len())
        .max_by(|&a, &b| {
            run_violations[b]
                .total_cmp(&run_violations[a])
                .then(scores[a].total_cmp(&scores[b]))
        })
        .ok_or(KinematicError::Array(DoeError::Empty))?;

    // 2. ANOM on the combined objective: its best levels if feasible,
    // else the feasible level combination it predicts best.
    let anom = Anom::new(&array.array, &array.columns, &scores)?;
    let (anom_design, anom_prediction) = feasible_levels(&anom, space, violation)?;

    // 3. Response surfaces in coded levels, NSGA-II on them.
    let surfaces = Surfaces::search(&array, space, nsga, &objective)?;

    // Confirmations.
    let candidates = confirm(
        &evaluations,
        &objective,
        array.runs[best_row].clone(),
        (anom_design, anom_prediction),
        (surfaces.knee_design, surfaces.knee_prediction),
    );
    // An infeasible initial design is no bar to beat (the design driver
    // stops before the disciplines if cycle 1's cannot be flown; a later
    // cycle's vehicle may no longer fly the design it analyses).
    let initial_score = if initial_violation == 0.0 {
        objective.combined(&initial_result)
    } else {
        f64::NEG_INFINITY
    };
    // A candidate must beat it by more than the two runs' scatter.
    let adoption_margin = objective.margin(&initial_result, case.scatter());
    let chosen = best_beyond(&candidates, initial_score + adoption_margin);
    let section = case.modelled_section();
    Ok(KinematicResult {
        initial,
        initial_violation,
        runs: array.runs,
        run_violations,
        level_means: anom.level_means.clone(),
        surface_quality: [quality(&surfaces.ct_fit), quality(&surfaces.eta_fit)],
        pareto: surfaces.pareto,
        candidates,
        chosen,
        adoption_margin,
        reference: Some(reference),
        section: Some(section),
    })
}

/// The feasible candidate with the best combined objective above `bar`,
/// if any.
fn best_beyond(candidates: &[Candidate], bar: f64) -> Option<usize> {
    let score = |i: usize| candidates[i].combined.unwrap_or(f64::NEG_INFINITY);
    (0..candidates.len())
        .filter(|&i| candidates[i].violation == 0.0 && score(i) > bar)
        .max_by(|&a, &b| score(a).total_cmp(&score(b)))
}

/// ANOM's pick: the best levels and their additive prediction if they
/// are feasible; otherwise, of the 3^4 level combinations, the feasible
/// one with the best additive prediction (ANOM's model, REFERENCES.md);
/// if none is feasible, the best levels (recorded with their violation,
/// never chosen).
fn feasible_levels(
    anom: &Anom,
    space: &DesignSpace,
    violation: Violation,
) -> Result<(FlappingKinematics, f64), KinematicError> {
    let design = |levels: &[u8]| {
        FlappingKinematics::from_degrees(
            [0, 1, 2, 3].map(|f| space.levels()[f][usize::from(levels[f])]),
        )
    };
    let (best_levels, best_prediction) = anom.optimum(Goal::LargerIsBetter);
    let best = design(&best_levels);
    if violation(&best) == 0.0 {
        return Ok((best, best_prediction));
    }
    let mut pick: Option<(FlappingKinematics, f64)> = None;
    for code in 0..81u32 {
        let levels: Vec<u8> = (0..4).map(|f| ((code / 3u32.pow(f)) % 3) as u8).collect();
        let d = design(&levels);
        if violation(&d) != 0.0 {
            continue;
        }
        let y = anom.predict(&levels)?;
        if pick.is_none_or(|(_, p)| y > p) {
            pick = Some((d, y));
        }
    }
    Ok(pick.unwrap_or((best, best_prediction)))
}

/// The values with each missing one (a failed run) replaced by the worst
/// value seen.
fn worst(values: Vec<Option<f64>>) -> Vec<f64> {
    let floor = values
        .iter()
        .flatten()
        .copied()
        .fold(f64::INFINITY, f64::min);
    values.into_iter().map(|v| v.unwrap_or(floor)).collect()
}

/// R², adjusted R² and PRESS of a fitted surface.
fn quality(f: &ReducedFit) -> (f64, f64, Option<f64>) {
    (
        f.surface.r_squared,
        f.surface.adjusted_r_squared,
        f.surface.press,
    )
}

/// The discipline's direct evaluations: from the cache or run (and then
/// cached), each one counted for the progress report.
struct Evaluations<'a> {
    case: &'a SectionCase,
    cache: &'a EvaluationCache,
    progress: &'a (dyn Fn(usize, usize) + Sync),
    /// Evaluations done, held while `progress` is told, so that its counts
    /// arrive in order from the parallel evaluations (counted apart from
    /// the telling, a thread paused between the two could report 5 after
    /// another's 6).
    done: Mutex<usize>,
}

impl Evaluations<'_> {
    /// Evaluates `design` (a failure is recorded with its reason).
    fn run(&self, design: FlappingKinematics) -> Evaluated {
        let result = match self.cache.get(self.case, &design) {
            Some(r) => Ok(r),
            None => {
                let r = self.case.evaluate(&design).map_err(|e| e.to_string());
                if let Ok(r) = &r {
                    self.cache.insert(self.case, &design, *r);
                }
                r
            }
        };
        let mut done = self.done.lock().unwrap_or_else(PoisonError::into_inner);
        *done += 1;
        (self.progress)(*done, EVALUATIONS);
        Evaluated { design, result }
    }
}

/// Step 1: the L18 array over the design space's levels and its runs.
struct ArrayRuns {
    array: OrthogonalArray,
    columns: Vec<usize>,
    runs: Vec<Evaluated>,
}

impl ArrayRuns {
    /// Lays out the array over `space` and evaluates its rows in parallel.
    ///
    /// # Errors
    /// [`KinematicError::Array`] if the array cannot be laid out,
    /// [`KinematicError::EveryRowFailed`] if no row's analysis succeeded.
    fn evaluate(space: &DesignSpace, evaluations: &Evaluations) -> Result<Self, KinematicError> {
        let (array, columns, designs) = space.l18_layout()?;
        let runs: Vec<Evaluated> = designs
            .into_par_iter()
            .map(|design| evaluations.run(design))
            .collect();
        Self::new(array, columns, runs)
    }

    /// The array's `runs`, refused if there are none or every one failed.
    fn new(
        array: OrthogonalArray,
        columns: Vec<usize>,
        runs: Vec<Evaluated>,
    ) -> Result<Self, KinematicError> {
        let Some(first) = runs.first() else {
            return Err(KinematicError::Array(DoeError::Empty));
        };
        if let Err(reason) = &first.result {
            if runs.iter().all(|e| e.result.is_err()) {
                return Err(KinematicError::EveryRowFailed {
                    rows: runs.len(),
                    first: reason.clone(),
                });
            }
        }
        Ok(Self {
            array,
            columns,
            runs,
        })
    }

    /// Each run's factor levels coded in [-1, 1].
    fn coded(&self) -> Vec<Vec<f64>> {
        (0..self.runs.len())
            .map(|r| {
                self.columns
                    .iter()
                    .map(|&c| f64::from(self.array.runs[r][c]) - 1.0)
                    .collect()
            })
            .collect()
    }
}

/// Step 3: the CT and efficiency surfaces, their Pareto front and its
/// knee (the front's best combined objective).
struct Surfaces {
    ct_fit: ReducedFit,
    eta_fit: ReducedFit,
    pareto: Vec<(FlappingKinematics, f64, f64)>,
    knee_design: FlappingKinematics,
    knee_prediction: f64,
}

impl Surfaces {
    /// Fits the surfaces to the array's runs and searches them by NSGA-II.
    fn search(
        array: &ArrayRuns,
        space: &DesignSpace,
        nsga: &Nsga2Config,
        objective: &Objective,
    ) -> Result<Self, KinematicError> {
        let coded = array.coded();
        let ct = worst(
            array
                .runs
                .iter()
                .map(|e| e.result.as_ref().ok().map(|r| r.ct_net))
                .collect(),
        );
        let eta = worst(
            array
                .runs
                .iter()
                .map(|e| e.result.as_ref().ok().map(|r| r.efficiency_net))
                .collect(),
        );
        let surface = |response: &'static str, values: &[f64]| {
            fit_reduced(&coded, values, ReduceOptions::default())
                .map_err(|source| KinematicError::Surface { response, source })
        };
        let ct_fit = surface("thrust", &ct)?;
        let eta_fit = surface("efficiency", &eta)?;
        let bounds = Bounds::new(vec![-1.0; 4], vec![1.0; 4])?;
        let front = minimize(&bounds, 2, nsga, |x: &[f64]| {
            let c = ct_fit.surface.predict(x)?;
            let e = eta_fit.surface.predict(x)?;
            Ok::<_, RsmError>(Evaluation {
                objectives: vec![-c, -e],
                violation: (objective.violation)(&space.decode(x)),
            })
        })?
        .front;
        let knee = front
            .iter()
            .max_by(|a, b| {
                objective
                    .predicted(&a.objectives)
                    .total_cmp(&objective.predicted(&b.objectives))
            })
            .ok_or(KinematicError::NothingFlyable)?;
        let knee_design = space.decode(&knee.x);
        let knee_prediction = objective.predicted(&knee.objectives);
        let pareto = front
            .iter()
            .map(|i| (space.decode(&i.x), -i.objectives[0], -i.objectives[1]))
            .collect();
        Ok(Self {
            ct_fit,
            eta_fit,
            pareto,
            knee_design,
            knee_prediction,
        })
    }
}

/// The three candidates: the best array row as it ran, and the ANOM and
/// RSM designs (each with its predicted combined objective) confirmed by
/// direct runs in parallel.
fn confirm(
    evaluations: &Evaluations,
    objective: &Objective,
    best_row: Evaluated,
    (anom_design, anom_prediction): (FlappingKinematics, f64),
    (rsm_design, rsm_prediction): (FlappingKinematics, f64),
) -> Vec<Candidate> {
    let confirmations: Vec<Evaluated> = [anom_design, rsm_design]
        .par_iter()
        .map(|&d| evaluations.run(d))
        .collect();
    let candidate = |method: &str, predicted: Option<f64>, confirmation: Evaluated| Candidate {
        method: method.to_string(),
        predicted,
        combined: objective.score(&confirmation),
        violation: (objective.violation)(&confirmation.design),
        confirmation,
    };
    let mut confirmations = confirmations.into_iter();
    vec![
        candidate("best L18 row", None, best_row),
        candidate(
            "ANOM",
            Some(anom_prediction),
            confirmations
                .next()
                .unwrap_or_else(|| evaluations.run(anom_design)),
        ),
        candidate(
            "RSM + NSGA-II",
            Some(rsm_prediction),
            confirmations
                .next()
                .unwrap_or_else(|| evaluations.run(rsm_design)),
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::discipline::section_model::{
        LdvmFlow, SectionFlowModel, LDVM_SHEDDING_DEFORMING_SCATTER, LDVM_SHEDDING_SCATTER,
    };

    fn candidate(combined: Option<f64>, violation: f64) -> Candidate {
        Candidate {
            method: "test".into(),
            predicted: None,
            confirmation: Evaluated {
                design: FlappingKinematics::INITIAL,
                result: Err("not run".into()),
            },
            combined,
            violation,
        }
    }

    /// Only a feasible candidate above the bar is chosen, the best of
    /// them: a better one within the margin leaves the analysed design.
    #[test]
    fn a_candidate_must_clear_the_margin() {
        let candidates = [
            candidate(Some(2.30), 0.1),
            candidate(Some(2.10), 0.0),
            candidate(Some(2.05), 0.0),
            candidate(None, 0.0),
        ];
        assert_eq!(best_beyond(&candidates, 2.0), Some(1));
        assert_eq!(best_beyond(&candidates, 2.07), Some(1));
        assert_eq!(best_beyond(&candidates, 2.0 + 0.113), None);
        assert_eq!(best_beyond(&candidates, f64::NEG_INFINITY), Some(1));
    }

    /// The objective of equal weights on the reference CT 0.07 and
    /// efficiency 0.04, its violation `violation`'s.
    fn equal_weights(violation: Violation<'_>) -> Objective<'_> {
        Objective {
            weights: Weights {
                thrust: 1.0,
                efficiency: 1.0,
            },
            reference: ObjectiveReference {
                ct_net: 0.07,
                efficiency_net: 0.04,
            },
            violation,
        }
    }

    /// The margin is one standard deviation of the difference of two
    /// runs: at the reference design, with equal weights and a 4 %
    /// scatter in each objective, `√2 (0.04 + 0.04)`; none for the
    /// attached LDVM, and the declared scatter's for the shedding one, on
    /// a rigid or a deforming section.
    #[test]
    fn the_margin_is_the_scatter_of_a_difference() {
        let violation = |_: &FlappingKinematics| 0.0;
        let objective = equal_weights(&violation);
        let at_reference = SectionResult {
            reduced_frequency: 0.7,
            ct: 0.07,
            ct_net: 0.07,
            cp: 1.75,
            efficiency: 0.04,
            efficiency_net: 0.04,
            ct_change: 0.0,
        };
        let margin = objective.margin(&at_reference, (0.04, 0.04));
        assert!((margin - std::f64::consts::SQRT_2 * 0.08).abs() < 1e-12);
        assert_eq!(
            objective.margin(
                &at_reference,
                SectionFlowModel::Ldvm.window_scatter(2, LdvmFlow::Attached)
            ),
            0.0
        );
        for (flow, (thrust, efficiency)) in [
            (LdvmFlow::Shedding, LDVM_SHEDDING_SCATTER),
            (LdvmFlow::SheddingDeforming, LDVM_SHEDDING_DEFORMING_SCATTER),
        ] {
            let margin = objective.margin(
                &at_reference,
                SectionFlowModel::Ldvm.window_scatter(2, flow),
            );
            assert!((margin - std::f64::consts::SQRT_2 * (thrust + efficiency)).abs() < 1e-12);
            assert!(margin > 0.05, "{flow:?}: {margin}");
        }
    }

    /// The L18 rows of the built-in design space, each row's result
    /// `result(i)`.
    fn rows(result: impl Fn(usize) -> Result<SectionResult, String>) -> Vec<Evaluated> {
        let (_, _, designs) = DesignSpace::fwav().l18_layout().unwrap();
        designs
            .into_iter()
            .enumerate()
            .map(|(i, design)| Evaluated {
                design,
                result: result(i),
            })
            .collect()
    }

    /// A row's result of efficiency `0.04 + 0.001 i` and thrust `thrust`.
    fn row(i: usize, thrust: f64) -> SectionResult {
        let efficiency = 0.04 + 0.001 * i as f64;
        SectionResult {
            reduced_frequency: 0.7,
            ct: thrust,
            ct_net: thrust,
            cp: thrust / efficiency,
            efficiency,
            efficiency_net: efficiency,
            ct_change: 0.0,
        }
    }

    /// An array whose rows all failed is refused naming the first row's
    /// reason; one row that ran is enough to go on.
    #[test]
    fn an_array_whose_rows_all_failed_says_why_the_first_did() {
        let (array, columns, _) = DesignSpace::fwav().l18_layout().unwrap();
        let failed = |i: usize| Err(format!("row {i} refused"));
        match ArrayRuns::new(array.clone(), columns.clone(), rows(failed)) {
            Err(e @ KinematicError::EveryRowFailed { rows: 18, .. }) => assert_eq!(
                e.to_string(),
                "every one of the 18 L18 rows' 2D analyses failed, the first with: row 0 \
                 refused; bring the design space's levels within what the section model can run"
            ),
            Err(e) => panic!("{e}"),
            Ok(_) => panic!("rows that all failed were taken"),
        }
        let one_ran = |i: usize| if i == 17 { Ok(row(i, 0.07)) } else { failed(i) };
        assert!(ArrayRuns::new(array.clone(), columns.clone(), rows(one_ran)).is_ok());
        assert!(matches!(
            ArrayRuns::new(array, columns, Vec::new()),
            Err(KinematicError::Array(DoeError::Empty))
        ));
    }

    /// A response that cannot be fitted (here thrust not finite on a
    /// row) is named with the fit's own reason.
    #[test]
    fn a_surface_that_cannot_be_fitted_names_its_response() {
        let space = DesignSpace::fwav();
        let (array, columns, _) = space.l18_layout().unwrap();
        let thrust = |i: usize| Ok(row(i, if i == 3 { f64::NAN } else { 0.07 }));
        let array_runs = ArrayRuns::new(array, columns, rows(thrust)).unwrap();
        let violation = |_: &FlappingKinematics| 0.0;
        let objective = equal_weights(&violation);
        let err = Surfaces::search(&array_runs, &space, &Nsga2Config::default(), &objective)
            .err()
            .expect("a thrust that is not finite cannot be fitted");
        assert!(
            matches!(
                err,
                KinematicError::Surface {
                    response: "thrust",
                    source: RsmError::NonFinite { run: 3 }
                }
            ),
            "{err:?}"
        );
        assert_eq!(
            err.to_string(),
            "the thrust response surface over the L18 rows: run 3 has a non-finite value"
        );
    }
}
