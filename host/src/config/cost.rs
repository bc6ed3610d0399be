//! What a design run of a configuration will cost, estimated before it
//! starts: memory and time from the shell mesh's element count and the
//! time steps of the dynamic analyses, calibrated on the built-in FWAV's
//! design (a 130 x 52 wing, 6760 elements). `fwav design` prints the
//! estimate of a run far beyond that one and asks for `--yes`.
//!
//! Measured on two cores (one cycle of 40 steps of the system analysis,
//! dev profile; the peak resident memory of the whole process):
//!
//! | elements | time a step | peak memory |
//! | ---: | ---: | ---: |
//! | 1,690 | 0.16 s | 85 MB |
//! | 6,760 | 0.43 s | 336 MB |
//! | 13,616 | 0.96 s | 711 MB |
//! | 27,040 | 4.0 s | 1,605 MB |
//!
//! The memory grows as `n ln n` for `n` elements, the fill of a sparse
//! Cholesky factorization of a 2D mesh under nested dissection: 5.7 kB
//! times `n ln n` matches the 6,760 and 27,040 rows within 3%; the
//! estimate scales the whole design's measured peak (680 MB) by it. The
//! time of a step grows as `n^1.15` from 6,760 to 13,616 elements and
//! `n^2.0` beyond (that row measured while another build ran); the
//! estimate takes `n^1.5`, the factorization's flop count on a 2D mesh
//! (George 1973), times the steps a design cycle's dynamic analyses take,
//! `(analysis.cycles + topology.periods) * analysis.steps_per_cycle`. The
//! vortex lattice and the aerodynamic discipline's LDVM are left out: they
//! do not grow with the mesh, and on the default wing they are a small
//! part. The discipline's Navier–Stokes model (`[design] section_model =
//! "ns"`) is not: its disciplines are added at their measured time
//! ([`NS_DISCIPLINE_SECONDS`] each, [`NS_CYCLES`] of them), scaled by the
//! cycles each evaluation runs (`[design] section_cycles`, over the
//! measured 4: the step follows the flow, and the flow's speeds are
//! alike from stroke to stroke, so a stroke costs about the same).

use std::fmt;

use super::SystemConfig;
use crate::discipline::section_model::SectionModelName;

/// Shell elements of the built-in wing.
pub const DEFAULT_ELEMENTS: usize = 6760;

/// Wall time of the built-in design, s: 441 s on two cores to
/// convergence in three cycles (release build, `cargo bench -p fwav
/// --bench design`, README, with the actuator constraint and leading-edge
/// shedding). The dev profile on the same two cores, shared with three
/// other builds, took 2,007 s (three cycles).
const DEFAULT_SECONDS: f64 = 441.0;

/// Dynamic-analysis steps a cycle of the built-in design:
/// `(4 cycles + 2 periods) * 40 steps`.
const DEFAULT_STEPS: f64 = 240.0;

/// Peak memory of the built-in design, bytes: the process's resident
/// peak, 680 MB, measured on the whole three-cycle run (the two
/// disciplines run side by side; the system analysis alone peaks at 336
/// MB).
const DEFAULT_MEMORY: f64 = 680e6;

/// Wall time of one aerodynamic discipline run with the Navier–Stokes
/// section model at the default resolution (384 × 256 with the far field
/// coarsened, Courant number 3), s, on the 2-core development machine:
/// the first cycle's discipline of the default design with
/// `section_model = "ns"` took 1,671 s (2026-12-06, after the moving
/// grid's trims; `discipline_ns_scores::ns_discipline_benchmark`, the
/// machine otherwise idle; 1,720 s before them the same day, with each
/// plate sample's map moved by its rigid part); the NS
/// design run of the same day took 1,856 s and 1,828 s for its cycles 2
/// and 3 (docs/ns-design). 1,507 s with the maps of before (2026-12-05),
/// 1,950 s on the exponential 384 × 320, the default until that day.
/// Its 19 or 20 evaluations (the 18 rows and the confirmations; the
/// analysed design is a row, found in the cache) run two at a time,
/// each on one core (`ns2d/README.md`, "Speed"), about 170 s each, where the
/// initial design's evaluation took 93 s on two threads before the
/// trims (82 s after the first;
/// `discipline_ns_scores::ns_deforming_evaluation_benchmark`): the
/// array's rows, with their faster strokes, cost more than the initial
/// design on average, so the discipline is measured rather than counted
/// from one evaluation.
pub const NS_DISCIPLINE_SECONDS: f64 = 1671.0;

/// The cycles each evaluation ran in [`NS_DISCIPLINE_SECONDS`]'s run
/// (`[design] section_cycles` of the default design).
const NS_MEASURED_SECTION_CYCLES: f64 = 4.0;

/// Navier–Stokes disciplines of a design run: the cycles of the last
/// default NS design run, which converged in cycle 4 (2026-12-06, on the
/// default 384 × 256 with each plate sample's map moved by its rigid
/// part: 8,038 s of stage time, its four disciplines 2,216, 1,856, 1,828
/// and 1,647 s; docs/ns-design). The section's deformation changes from
/// cycle to cycle, so the cache serves none of an earlier cycle's
/// evaluations. Earlier runs converged in cycle 2 on 384 × 256 and
/// 384 × 240 and in cycle 3 on 384 × 320: a run may end sooner than
/// estimated, or later.
pub const NS_CYCLES: f64 = 4.0;

/// Navier–Stokes evaluations of a design run: each cycle's 21, over
/// [`NS_CYCLES`].
pub const NS_EVALUATIONS: f64 = 21.0 * NS_CYCLES;

/// Exponent of the time a step in the element count.
const TIME_EXPONENT: f64 = 1.5;

/// A run is far beyond the default above this many times its time.
pub const FAR_TIME_RATIO: f64 = 10.0;

/// ... or above this much memory, bytes (4 GB).
pub const FAR_MEMORY: f64 = 4e9;

/// The estimated cost of a design run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CostEstimate {
    /// Shell elements of the wing mesh.
    pub elements: usize,
    /// Peak memory, bytes.
    pub memory_bytes: f64,
    /// Wall time on two cores, s.
    pub seconds: f64,
    /// The part of it the Navier–Stokes section evaluations take, s (0
    /// with the LDVM).
    pub section_seconds: f64,
    /// The time over the built-in design's.
    pub time_ratio: f64,
}

/// `n ln n`, the growth of the factors' memory.
fn fill(n: f64) -> f64 {
    n * n.max(2.0).ln()
}

impl CostEstimate {
    /// The estimate for `config` (see the module documentation).
    pub fn of(config: &SystemConfig) -> Self {
        let elements = config.wing.span_elements * config.wing.chord_elements;
        let n = elements as f64;
        let n0 = DEFAULT_ELEMENTS as f64;
        let steps = ((config.analysis.cycles + config.topology.periods)
            * config.analysis.steps_per_cycle) as f64;
        let mesh_seconds = DEFAULT_SECONDS * (n / n0).powf(TIME_EXPONENT) * steps / DEFAULT_STEPS;
        let section_seconds = match config.design.section_model {
            SectionModelName::Ldvm => 0.0,
            SectionModelName::Ns => {
                NS_CYCLES * NS_DISCIPLINE_SECONDS * config.design.section_cycles as f64
                    / NS_MEASURED_SECTION_CYCLES
            }
        };
        let seconds = mesh_seconds + section_seconds;
        Self {
            elements,
            memory_bytes: DEFAULT_MEMORY * fill(n) / fill(n0),
            seconds,
            section_seconds,
            time_ratio: seconds / DEFAULT_SECONDS,
        }
    }

    /// Whether the run is far beyond the built-in design: more than
    /// [`FAR_TIME_RATIO`] times its time, or more than [`FAR_MEMORY`].
    pub fn is_far_beyond_default(&self) -> bool {
        self.time_ratio > FAR_TIME_RATIO || self.memory_bytes > FAR_MEMORY
    }
}

/// A duration as people read it: `40 s`, `12 minutes`, `3.4 hours`.
fn duration(seconds: f64) -> String {
    if seconds < 120.0 {
        format!("{seconds:.0} s")
    } else if seconds < 3600.0 {
        format!("{:.0} minutes", seconds / 60.0)
    } else {
        format!("{:.1} hours", seconds / 3600.0)
    }
}

impl fmt::Display for CostEstimate {
    /// `about 5.2 GB of memory and 1.9 hours per design cycle (80000 shell
    /// elements; the built-in wing's 6760 take 0.7 GB and 3 minutes)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "about {:.1} GB of memory and {} on two cores ({} shell elements, {:.0} times the \
             built-in design's time; its {DEFAULT_ELEMENTS} elements take {:.1} GB and {})",
            self.memory_bytes / 1e9,
            duration(self.seconds),
            self.elements,
            self.time_ratio,
            DEFAULT_MEMORY / 1e9,
            duration(DEFAULT_SECONDS),
        )?;
        if self.section_seconds > 0.0 {
            write!(
                f,
                ", of which {} for about {NS_EVALUATIONS:.0} Navier–Stokes section evaluations \
                 (design.section_model = \"ns\")",
                duration(self.section_seconds)
            )?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The default is the calibration point; the 400 x 200 mesh
    /// is far beyond it (over 4 GB, hours); the coarse test wing is not.
    #[test]
    fn the_default_is_the_reference_and_a_huge_mesh_is_far_beyond_it() {
        let default = CostEstimate::of(&SystemConfig::default());
        assert_eq!(default.elements, DEFAULT_ELEMENTS);
        assert!((default.time_ratio - 1.0).abs() < 1e-12);
        assert!(!default.is_far_beyond_default());
        let mut huge = SystemConfig::default();
        (huge.wing.span_elements, huge.wing.chord_elements) = (400, 200);
        let e = CostEstimate::of(&huge);
        assert!(e.is_far_beyond_default(), "{e}");
        assert!(e.memory_bytes > 4e9 && e.seconds > 3600.0, "{e}");
        let text = e.to_string();
        assert!(
            text.contains("80000 shell elements") && text.contains("hours"),
            "{text}"
        );
        let mut coarse = SystemConfig::default();
        (coarse.wing.span_elements, coarse.wing.chord_elements) = (16, 6);
        assert!(!CostEstimate::of(&coarse).is_far_beyond_default());
    }

    /// The Navier–Stokes section model's disciplines are in the built-in
    /// design's estimate, which says what they cost. At 1,671 s each (the
    /// default 384 × 256 grid), four of them, they make it about 16 times
    /// the LDVM run, beyond the [`FAR_TIME_RATIO`] at which `fwav design`
    /// asks before it starts. The estimate, about 2.0 hours, against the
    /// default NS design run of 2026-12-06: 8,038 s of stage time (2.2
    /// hours), four cycles (docs/ns-design). (On 2026-12-05, with the
    /// maps of before, it converged in cycle 2 in 54 min 13 s; on the
    /// exponential 384 × 320 it took 9,845 s, three cycles; on 384 × 240,
    /// 78.6 minutes.)
    #[test]
    fn the_ns_section_model_is_in_the_estimate() {
        let mut ns = SystemConfig::default();
        ns.design.section_model = SectionModelName::Ns;
        let e = CostEstimate::of(&ns);
        assert_eq!(e.section_seconds, NS_CYCLES * NS_DISCIPLINE_SECONDS);
        let ldvm = CostEstimate::of(&SystemConfig::default());
        assert!((e.seconds - ldvm.seconds - e.section_seconds).abs() < 1e-9);
        assert!(e.time_ratio > 10.0 && e.is_far_beyond_default(), "{e}");
        assert!(e.to_string().contains("Navier–Stokes"), "{e}");
        // Within a fifth of the measured run's 8,038 s of stage time.
        assert!((e.seconds / 8038.0 - 1.0).abs() < 0.2, "{e}");
        // Three times the strokes, three times the evaluations' time.
        ns.design.section_cycles = 12;
        let long = CostEstimate::of(&ns);
        assert!((long.section_seconds - 3.0 * e.section_seconds).abs() < 1e-9);
    }
}
