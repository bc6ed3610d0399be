//! NSGA-II: elitist multi-objective evolutionary minimization, real-coded,
//! in a box.
//!
//! Reference: Deb, Pratap, Agarwal & Meyarivan (2002), "A fast and elitist
//! multiobjective genetic algorithm: NSGA-II", IEEE Trans. Evol. Comput.
//! 6(2), 182–197: fast non-dominated sorting (section III-A), crowding
//! distance (III-B), the crowded-comparison operator ≺n used in binary
//! tournaments and to truncate the last admitted front (III-B, III-C), the
//! (μ+λ) main loop (III-C) and constrained domination (section VI,
//! definition 1). Variation: simulated binary crossover (SBX) and polynomial
//! mutation, Deb & Agrawal (1995), Complex Systems 9(2), 115–148, in the
//! bounded form of Deb's reference implementation (the spread factor's
//! distribution is truncated so children stay in the box, instead of being
//! clipped, which would pile points up on the bounds).
//!
//! Evaluations of one generation run in parallel with rayon; the random
//! numbers are drawn only in the sequential variation step from a ChaCha8
//! generator seeded by [`Nsga2Config::seed`], so a run is reproducible from
//! its seed whatever the thread count. An evaluation that fails (the closure
//! returns `Err`, wrong objective count, a non-finite objective) is recorded
//! in [`Nsga2Result::failures`] and its individual is dominated by every
//! successful one, so it dies out at the next survival step.

use std::cmp::Ordering;
use std::fmt;

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use super::pareto::FrontSorter;

/// Settings of an NSGA-II run. Defaults: the usual settings of
/// REFERENCES.md (population 100, 250 generations, SBX p = 0.9, η_c = 20,
/// polynomial mutation p = 1/n, η_m = 20), seed 0, parallel evaluation.
#[derive(Debug, Clone, PartialEq)]
pub struct Nsga2Config {
    /// Population size N (parents and offspring per generation), ≥ 4.
    pub population: usize,
    /// Number of generations including the initial random population, ≥ 1:
    /// the run makes `population × generations` evaluations.
    pub generations: usize,
    /// Probability that a pair of parents is recombined by SBX, in [0, 1].
    pub crossover_probability: f64,
    /// SBX distribution index η_c ≥ 0 (larger: children nearer parents).
    pub crossover_eta: f64,
    /// Per-variable mutation probability in [0, 1]; `None`: 1/n.
    pub mutation_probability: Option<f64>,
    /// Polynomial-mutation distribution index η_m ≥ 0.
    pub mutation_eta: f64,
    /// Seed of the ChaCha8 random generator.
    pub seed: u64,
    /// Evaluate each generation in parallel with rayon (turn off for
    /// closures that are not worth a thread hop, or that are already
    /// parallel inside).
    pub parallel: bool,
}

impl Default for Nsga2Config {
    fn default() -> Self {
        Self {
            population: 100,
            generations: 250,
            crossover_probability: 0.9,
            crossover_eta: 20.0,
            mutation_probability: None,
            mutation_eta: 20.0,
            seed: 0,
            parallel: true,
        }
    }
}

/// Errors of setting up an NSGA-II run (evaluation failures are not errors:
/// they are recorded in the result).
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum Nsga2Error {
    /// The bounds are empty, of different lengths, not finite or reversed.
    #[error("invalid bounds: {0}")]
    Bounds(String),
    /// A setting is out of range.
    #[error("invalid setting: {0}")]
    Config(String),
}

/// The box of the decision variables: `lower[i] ≤ x[i] ≤ upper[i]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Bounds {
    lower: Vec<f64>,
    upper: Vec<f64>,
}

impl Bounds {
    /// Checks and stores the bounds: equal non-zero lengths, finite, and
    /// lower ≤ upper (equal bounds fix a variable).
    pub fn new(lower: Vec<f64>, upper: Vec<f64>) -> Result<Self, Nsga2Error> {
        if lower.is_empty() || lower.len() != upper.len() {
            return Err(Nsga2Error::Bounds(format!(
                "{} lower and {} upper bounds",
                lower.len(),
                upper.len()
            )));
        }
        for (i, (l, u)) in lower.iter().zip(&upper).enumerate() {
            if !(l.is_finite() && u.is_finite() && l <= u) {
                return Err(Nsga2Error::Bounds(format!("variable {i}: [{l}, {u}]")));
            }
        }
        Ok(Self { lower, upper })
    }

    /// Number of decision variables.
    pub fn n_variables(&self) -> usize {
        self.lower.len()
    }

    /// Lower bounds.
    pub fn lower(&self) -> &[f64] {
        &self.lower
    }

    /// Upper bounds.
    pub fn upper(&self) -> &[f64] {
        &self.upper
    }
}

/// What an evaluation returns: the objectives to minimize and the total
/// constraint violation (0 or less: feasible).
#[derive(Debug, Clone, PartialEq)]
pub struct Evaluation {
    /// Objective values, all minimized.
    pub objectives: Vec<f64>,
    /// Total constraint violation, e.g. Σ max(0, g_j(x)); values ≤ 0 mean
    /// feasible.
    pub violation: f64,
}

impl From<Vec<f64>> for Evaluation {
    /// An unconstrained evaluation.
    fn from(objectives: Vec<f64>) -> Self {
        Self {
            objectives,
            violation: 0.0,
        }
    }
}

impl<const M: usize> From<[f64; M]> for Evaluation {
    /// An unconstrained evaluation.
    fn from(objectives: [f64; M]) -> Self {
        objectives.to_vec().into()
    }
}

/// A member of the population.
#[derive(Debug, Clone, PartialEq)]
pub struct Individual {
    /// Decision vector, inside the bounds.
    pub x: Vec<f64>,
    /// Objectives (empty when the evaluation failed).
    pub objectives: Vec<f64>,
    /// Total constraint violation, ≥ 0 (0: feasible).
    pub violation: f64,
    /// The evaluation failed: dominated by every successful individual.
    pub failed: bool,
    /// 0-based non-domination rank in the last survival sort (0: first front).
    pub rank: usize,
    /// Crowding distance within its front (+∞ at a front's extremes).
    pub crowding: f64,
}

impl Individual {
    /// Evaluated successfully and feasible.
    pub fn is_feasible(&self) -> bool {
        !self.failed && self.violation == 0.0
    }
}

/// An evaluation that failed.
#[derive(Debug, Clone, PartialEq)]
pub struct FailedEvaluation {
    /// 0-based generation (0: the initial population).
    pub generation: usize,
    /// The decision vector.
    pub x: Vec<f64>,
    /// Why: the closure's error, or what was wrong with its result.
    pub message: String,
}

/// Statistics of the population after one generation's survival.
#[derive(Debug, Clone, PartialEq)]
pub struct GenerationStats {
    /// 0-based generation (0: the initial population).
    pub generation: usize,
    /// Evaluations so far.
    pub evaluations: usize,
    /// Failed evaluations so far.
    pub failures: usize,
    /// Feasible, successfully evaluated members of the population.
    pub feasible: usize,
    /// Size of the population's first front.
    pub first_front: usize,
    /// Component-wise minimum of the objectives over the feasible members
    /// (the ideal point of the population); `None` if none is feasible.
    pub ideal: Option<Vec<f64>>,
}

/// The outcome of an NSGA-II run.
#[derive(Debug, Clone, PartialEq)]
pub struct Nsga2Result {
    /// The seed the run used (reproduces it with the same settings).
    pub seed: u64,
    /// The final population, sorted by (rank, −crowding).
    pub population: Vec<Individual>,
    /// The feasible members of the final population's first front: the
    /// Pareto-front approximation (decision vectors and objectives).
    pub front: Vec<Individual>,
    /// One entry per generation, the initial population first.
    pub history: Vec<GenerationStats>,
    /// Every failed evaluation.
    pub failures: Vec<FailedEvaluation>,
    /// Total evaluations made.
    pub evaluations: usize,
}

fn check_config(config: &Nsga2Config, n_objectives: usize) -> Result<(), Nsga2Error> {
    let bad = |s: String| Err(Nsga2Error::Config(s));
    if n_objectives == 0 {
        return bad("at least one objective is needed".into());
    }
    if config.population < 4 {
        return bad(format!("population {} < 4", config.population));
    }
    if config.generations == 0 {
        return bad("generations must be at least 1".into());
    }
    let probability = |p: f64| (0.0..=1.0).contains(&p);
    if !probability(config.crossover_probability) {
        return bad(format!(
            "crossover probability {} not in [0, 1]",
            config.crossover_probability
        ));
    }
    if let Some(p) = config.mutation_probability {
        if !probability(p) {
            return bad(format!("mutation probability {p} not in [0, 1]"));
        }
    }
    for (name, eta) in [
        ("crossover", config.crossover_eta),
        ("mutation", config.mutation_eta),
    ] {
        if !(eta.is_finite() && eta >= 0.0) {
            return bad(format!(
                "{name} distribution index {eta} must be finite and ≥ 0"
            ));
        }
    }
    Ok(())
}

/// Minimizes the `n_objectives` objectives returned by `evaluate` over the
/// box `bounds` with NSGA-II.
///
/// `evaluate` returns the objectives (`Vec<f64>` or `[f64; M]`) or an
/// [`Evaluation`] with a constraint violation (constrained domination then
/// applies: feasible before infeasible, infeasible by smaller violation);
/// an `Err` is recorded and the individual treated as dominated.
pub fn minimize<F, R, E>(
    bounds: &Bounds,
    n_objectives: usize,
    config: &Nsga2Config,
    evaluate: F,
) -> Result<Nsga2Result, Nsga2Error>
where
    F: Fn(&[f64]) -> Result<R, E> + Sync,
    R: Into<Evaluation>,
    E: fmt::Display,
{
    check_config(config, n_objectives)?;
    let n = bounds.n_variables();
    let n_pop = config.population;
    let mut rng = ChaCha8Rng::seed_from_u64(config.seed);
    let mut failures = Vec::new();
    let mut history = Vec::with_capacity(config.generations);
    let mut sorter = FrontSorter::default();
    let variation = Variation {
        bounds,
        crossover_probability: config.crossover_probability,
        crossover_eta: config.crossover_eta,
        mutation_probability: config.mutation_probability.unwrap_or(1.0 / n as f64),
        mutation_eta: config.mutation_eta,
    };

    let initial: Vec<Vec<f64>> = (0..n_pop)
        .map(|_| {
            bounds
                .lower
                .iter()
                .zip(&bounds.upper)
                .map(|(&l, &u)| l + rng.random::<f64>() * (u - l))
                .collect()
        })
        .collect();
    let mut population = evaluate_all(
        initial,
        &evaluate,
        n_objectives,
        config.parallel,
        0,
        &mut failures,
    );
    survive(&mut population, n_pop, &mut sorter);
    let mut evaluations = n_pop;
    history.push(stats(
        &population,
        0,
        evaluations,
        failures.len(),
        n_objectives,
    ));

    for generation in 1..config.generations {
        let mut children = Vec::with_capacity(n_pop + 1);
        while children.len() < n_pop {
            let p1 = tournament(&population, &mut rng);
            let p2 = tournament(&population, &mut rng);
            let (c1, c2) = variation.offspring(&population[p1].x, &population[p2].x, &mut rng);
            children.push(c1);
            children.push(c2);
        }
        // Pairs make two children; an odd population drops the last one.
        children.truncate(n_pop);
        let offspring = evaluate_all(
            children,
            &evaluate,
            n_objectives,
            config.parallel,
            generation,
            &mut failures,
        );
        evaluations += n_pop;
        population.extend(offspring);
        survive(&mut population, n_pop, &mut sorter);
        history.push(stats(
            &population,
            generation,
            evaluations,
            failures.len(),
            n_objectives,
        ));
    }

    let front = population
        .iter()
        .filter(|p| p.rank == 0 && p.is_feasible())
        .cloned()
        .collect();
    Ok(Nsga2Result {
        seed: config.seed,
        population,
        front,
        history,
        failures,
        evaluations,
    })
}

/// Evaluates the decision vectors, in parallel if asked; failures become
/// dominated individuals and are recorded.
fn evaluate_all<F, R, E>(
    xs: Vec<Vec<f64>>,
    evaluate: &F,
    n_objectives: usize,
    parallel: bool,
    generation: usize,
    failures: &mut Vec<FailedEvaluation>,
) -> Vec<Individual>
where
    F: Fn(&[f64]) -> Result<R, E> + Sync,
    R: Into<Evaluation>,
    E: fmt::Display,
{
    // Convert inside the worker so only plain data crosses threads (R and E
    // need not be Send).
    let one = |x: &Vec<f64>| -> Result<Evaluation, String> {
        let e: Evaluation = evaluate(x).map_err(|e| e.to_string())?.into();
        if e.objectives.len() != n_objectives {
            return Err(format!(
                "returned {} objectives, expected {n_objectives}",
                e.objectives.len()
            ));
        }
        if e.objectives.iter().any(|f| !f.is_finite()) {
            return Err(format!("non-finite objective {:?}", e.objectives));
        }
        if e.violation.is_nan() {
            return Err("constraint violation is NaN".into());
        }
        Ok(e)
    };
    let outcomes: Vec<Result<Evaluation, String>> = if parallel {
        xs.par_iter().map(one).collect()
    } else {
        xs.iter().map(one).collect()
    };
    xs.into_iter()
        .zip(outcomes)
        .map(|(x, outcome)| match outcome {
            Ok(e) => Individual {
                x,
                objectives: e.objectives,
                violation: e.violation.max(0.0),
                failed: false,
                rank: 0,
                crowding: 0.0,
            },
            Err(message) => {
                failures.push(FailedEvaluation {
                    generation,
                    x: x.clone(),
                    message,
                });
                Individual {
                    x,
                    objectives: Vec::new(),
                    violation: 0.0,
                    failed: true,
                    rank: 0,
                    crowding: 0.0,
                }
            }
        })
        .collect()
}

/// Elitist survival: sorts `population` (parents ∪ offspring) into fronts,
/// keeps whole fronts while they fit and the most crowding-distant members
/// of the first front that does not (Deb et al. 2002, section III-C), and
/// leaves the survivors ordered by the crowded comparison.
fn survive(population: &mut Vec<Individual>, keep: usize, sorter: &mut FrontSorter) {
    sorter.rank_and_crowd(population);
    // Sorting by (rank, −crowding) and truncating is exactly "whole fronts,
    // then the least crowded of the split front".
    population.sort_by(crowded_order);
    population.truncate(keep);
}

/// The crowded-comparison operator ≺n as an ordering: lower rank first,
/// then larger crowding distance.
fn crowded_order(a: &Individual, b: &Individual) -> Ordering {
    a.rank
        .cmp(&b.rank)
        .then_with(|| b.crowding.total_cmp(&a.crowding))
}

/// Binary tournament by ≺n between two distinct random members; a tie goes
/// to the first drawn (itself random).
fn tournament(population: &[Individual], rng: &mut ChaCha8Rng) -> usize {
    let a = rng.random_range(0..population.len());
    let mut b = rng.random_range(0..population.len() - 1);
    if b >= a {
        b += 1;
    }
    if crowded_order(&population[b], &population[a]) == Ordering::Less {
        b
    } else {
        a
    }
}

/// Summary of the population after survival.
fn stats(
    population: &[Individual],
    generation: usize,
    evaluations: usize,
    failures: usize,
    n_objectives: usize,
) -> GenerationStats {
    let feasible: Vec<&Individual> = population.iter().filter(|p| p.is_feasible()).collect();
    let ideal = (!feasible.is_empty()).then(|| {
        (0..n_objectives)
            .map(|k| {
                feasible
                    .iter()
                    .map(|p| p.objectives[k])
                    .fold(f64::INFINITY, f64::min)
            })
            .collect()
    });
    GenerationStats {
        generation,
        evaluations,
        failures,
        feasible: feasible.len(),
        first_front: population.iter().filter(|p| p.rank == 0).count(),
        ideal,
    }
}

/// SBX crossover and polynomial mutation in a box.
struct Variation<'a> {
    bounds: &'a Bounds,
    crossover_probability: f64,
    crossover_eta: f64,
    mutation_probability: f64,
    mutation_eta: f64,
}

/// Parents closer than this in a variable are not recombined there (the
/// spread factor's formulas divide by their distance).
const SBX_MIN_DISTANCE: f64 = 1e-14;

impl Variation<'_> {
    /// Two children of two parents: SBX with the crossover probability,
    /// then polynomial mutation of each child.
    fn offspring(&self, p1: &[f64], p2: &[f64], rng: &mut ChaCha8Rng) -> (Vec<f64>, Vec<f64>) {
        let mut c1 = p1.to_vec();
        let mut c2 = p2.to_vec();
        if rng.random::<f64>() < self.crossover_probability {
            self.sbx(&mut c1, &mut c2, rng);
        }
        self.mutate(&mut c1, rng);
        self.mutate(&mut c2, rng);
        (c1, c2)
    }

    /// Bounded simulated binary crossover (Deb & Agrawal 1995). Each
    /// variable is recombined with probability 1/2. For parents y1 < y2 in
    /// [l, u], the spread factor β has density ∝ β^η (β ≤ 1),
    /// ∝ β^−(η+2) (β > 1), truncated at the β that would reach the bound:
    /// with βb = 1 + 2 (y1 − l)/(y2 − y1) (toward l) and α = 2 − βb^−(η+1),
    /// β_q = (uα)^(1/(η+1)) if u ≤ 1/α, else (1/(2 − uα))^(1/(η+1)), and the
    /// child is ½[(y1 + y2) − β_q (y2 − y1)]; likewise toward u.
    fn sbx(&self, c1: &mut [f64], c2: &mut [f64], rng: &mut ChaCha8Rng) {
        let eta = self.crossover_eta;
        for i in 0..c1.len() {
            let (l, u) = (self.bounds.lower[i], self.bounds.upper[i]);
            if rng.random::<f64>() >= 0.5 || (c1[i] - c2[i]).abs() <= SBX_MIN_DISTANCE {
                continue;
            }
            let (y1, y2) = if c1[i] < c2[i] {
                (c1[i], c2[i])
            } else {
                (c2[i], c1[i])
            };
            let d = y2 - y1;
            let r: f64 = rng.random();
            let beta_q = |beta_bound: f64| {
                let alpha = 2.0 - beta_bound.powf(-(eta + 1.0));
                if r <= 1.0 / alpha {
                    (r * alpha).powf(1.0 / (eta + 1.0))
                } else {
                    (1.0 / (2.0 - r * alpha)).powf(1.0 / (eta + 1.0))
                }
            };
            let low = (0.5 * ((y1 + y2) - beta_q(1.0 + 2.0 * (y1 - l) / d) * d)).clamp(l, u);
            let high = (0.5 * ((y1 + y2) + beta_q(1.0 + 2.0 * (u - y2) / d) * d)).clamp(l, u);
            // Which child gets which value is random, so neither child is
            // biased toward the lower bound.
            if rng.random::<f64>() < 0.5 {
                (c1[i], c2[i]) = (high, low);
            } else {
                (c1[i], c2[i]) = (low, high);
            }
        }
    }

    /// Bounded polynomial mutation (Deb & Agrawal 1995, in the bounded form
    /// of Deb's NSGA-II reference code): each variable mutates with the mutation
    /// probability; with δ1 = (y − l)/(u − l), δ2 = (u − y)/(u − l) and r
    /// uniform, δ_q = [2r + (1 − 2r)(1 − δ1)^(η+1)]^(1/(η+1)) − 1 for
    /// r < ½, else 1 − [2(1 − r) + 2(r − ½)(1 − δ2)^(η+1)]^(1/(η+1)); the
    /// mutant y + δ_q (u − l) stays in [l, u] by construction.
    fn mutate(&self, c: &mut [f64], rng: &mut ChaCha8Rng) {
        let eta = self.mutation_eta;
        let power = 1.0 / (eta + 1.0);
        for (i, y) in c.iter_mut().enumerate() {
            let (l, u) = (self.bounds.lower[i], self.bounds.upper[i]);
            if rng.random::<f64>() >= self.mutation_probability || u <= l {
                continue;
            }
            let span = u - l;
            let r: f64 = rng.random();
            let delta_q = if r < 0.5 {
                let d1 = (*y - l) / span;
                (2.0 * r + (1.0 - 2.0 * r) * (1.0 - d1).powf(eta + 1.0)).powf(power) - 1.0
            } else {
                let d2 = (u - *y) / span;
                1.0 - (2.0 * (1.0 - r) + 2.0 * (r - 0.5) * (1.0 - d2).powf(eta + 1.0)).powf(power)
            };
            *y = (*y + delta_q * span).clamp(l, u);
        }
    }
}
