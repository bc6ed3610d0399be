//! Pareto ranking for NSGA-II: constrained domination, fast non-dominated
//! sorting in O(m N²) and the crowding distance.
//!
//! Reference: Deb, Pratap, Agarwal & Meyarivan (2002), IEEE TEC 6(2):
//! section III-A (fast non-dominated sort: each pair compared once, the
//! domination count n_p and dominated set S_p of every solution, then
//! fronts peeled by decrementing counts), section III-B (crowding
//! distance: per objective, the extremes get ∞ and every other member the
//! normalized gap between its neighbours, summed over objectives), and
//! section VI, definition 1 (constrained domination).

use std::cmp::Ordering;

use super::nsga2::Individual;

/// The outcome of comparing two individuals.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dominance {
    /// The first dominates the second.
    First,
    /// The second dominates the first.
    Second,
    /// Neither dominates.
    Neither,
}

/// Constrained domination (Deb et al. 2002, section VI, definition 1),
/// extended with failed evaluations: a successful individual dominates a
/// failed one; a feasible one dominates an infeasible one; of two
/// infeasible ones the smaller violation dominates; of two feasible ones,
/// Pareto domination on the objectives (no worse in all, better in one;
/// all minimized).
pub fn compare(a: &Individual, b: &Individual) -> Dominance {
    match (a.failed, b.failed) {
        (true, true) => return Dominance::Neither,
        (false, true) => return Dominance::First,
        (true, false) => return Dominance::Second,
        (false, false) => {}
    }
    if a.violation > 0.0 || b.violation > 0.0 {
        return match a.violation.total_cmp(&b.violation) {
            Ordering::Less => Dominance::First,
            Ordering::Greater => Dominance::Second,
            Ordering::Equal => Dominance::Neither,
        };
    }
    let (mut a_better, mut b_better) = (false, false);
    for (fa, fb) in a.objectives.iter().zip(&b.objectives) {
        if fa < fb {
            a_better = true;
        } else if fb < fa {
            b_better = true;
        }
        if a_better && b_better {
            return Dominance::Neither;
        }
    }
    match (a_better, b_better) {
        (true, false) => Dominance::First,
        (false, true) => Dominance::Second,
        _ => Dominance::Neither,
    }
}

/// Reusable buffers for non-dominated sorting and crowding, so that a run
/// allocates them once rather than every generation.
#[derive(Debug, Default, Clone)]
pub struct FrontSorter {
    /// S_p: the members each member dominates.
    dominated: Vec<Vec<u32>>,
    /// n_p: how many members dominate each member.
    count: Vec<u32>,
    /// Members in front order; front `f` is `order[starts[f]..starts[f + 1]]`.
    order: Vec<usize>,
    starts: Vec<usize>,
    /// Scratch: a front sorted by one objective.
    by_objective: Vec<usize>,
}

impl FrontSorter {
    /// Fast non-dominated sort of `population` (section III-A): after it,
    /// [`Self::fronts`] yields the fronts, best first. O(m N²) comparisons.
    pub fn sort(&mut self, population: &[Individual]) {
        let n = population.len();
        self.dominated.resize_with(n, Vec::new);
        self.dominated.iter_mut().for_each(Vec::clear);
        self.count.clear();
        self.count.resize(n, 0);
        // Each unordered pair is compared once; indices fit u32 for any
        // population that fits in memory alongside its N² comparisons.
        for i in 0..n {
            for j in (i + 1)..n {
                match compare(&population[i], &population[j]) {
                    Dominance::First => {
                        self.dominated[i].push(j as u32);
                        self.count[j] += 1;
                    }
                    Dominance::Second => {
                        self.dominated[j].push(i as u32);
                        self.count[i] += 1;
                    }
                    Dominance::Neither => {}
                }
            }
        }
        self.order.clear();
        self.order.extend((0..n).filter(|&i| self.count[i] == 0));
        self.starts.clear();
        self.starts.push(0);
        let mut begin = 0;
        while begin < self.order.len() {
            let end = self.order.len();
            self.starts.push(end);
            for k in begin..end {
                let p = self.order[k];
                for d in 0..self.dominated[p].len() {
                    let q = self.dominated[p][d] as usize;
                    self.count[q] -= 1;
                    if self.count[q] == 0 {
                        self.order.push(q);
                    }
                }
            }
            begin = end;
        }
    }

    /// The fronts of the last [`Self::sort`], best first, as member indices.
    pub fn fronts(&self) -> impl Iterator<Item = &[usize]> + '_ {
        self.starts.windows(2).map(|w| &self.order[w[0]..w[1]])
    }

    /// Sorts `population` into fronts and writes each member's `rank`
    /// (0-based front index) and `crowding` distance within its front.
    pub fn rank_and_crowd(&mut self, population: &mut [Individual]) {
        self.sort(population);
        for f in 0..self.starts.len().saturating_sub(1) {
            let (lo, hi) = (self.starts[f], self.starts[f + 1]);
            for k in lo..hi {
                let i = self.order[k];
                population[i].rank = f;
                population[i].crowding = 0.0;
            }
            crowd(population, &self.order[lo..hi], &mut self.by_objective);
        }
    }
}

/// Crowding distance of the members `front` of `population` (section
/// III-B), accumulated into their `crowding` fields (zeroed by the caller).
/// Fronts of one or two members, and the extremes of each objective, get
/// +∞ so that the ends of a front are always kept. Failed members (no
/// objectives) keep 0.
fn crowd(population: &mut [Individual], front: &[usize], scratch: &mut Vec<usize>) {
    if front.iter().any(|&i| population[i].failed) {
        return;
    }
    if front.len() <= 2 {
        front
            .iter()
            .for_each(|&i| population[i].crowding = f64::INFINITY);
        return;
    }
    let m = population[front[0]].objectives.len();
    for k in 0..m {
        scratch.clear();
        scratch.extend_from_slice(front);
        // Index as the tie-break keeps the order, and so a run,
        // deterministic.
        scratch.sort_unstable_by(|&a, &b| {
            population[a].objectives[k]
                .total_cmp(&population[b].objectives[k])
                .then(a.cmp(&b))
        });
        let first = scratch[0];
        let last = scratch[scratch.len() - 1];
        let range = population[last].objectives[k] - population[first].objectives[k];
        population[first].crowding = f64::INFINITY;
        population[last].crowding = f64::INFINITY;
        if range <= 0.0 {
            continue;
        }
        for w in scratch.windows(3) {
            let gap = population[w[2]].objectives[k] - population[w[0]].objectives[k];
            population[w[1]].crowding += gap / range;
        }
    }
}
