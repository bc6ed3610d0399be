//! Issue 23's convergence at the default resolution: the default FWAV
//! section's evaluation as the aerodynamic discipline scores a design
//! ([`SectionCase::evaluate`]: four strokes from rest, strokes 3 and 4
//! scored) at the built-in initial kinematics (11 Hz, ±30°, mean angle
//! 0°, vertical stroke plane), rigid and deforming as the default
//! design's first system analysis found
//! (`host/tests/data/fwav_cycle1_section.json`), on the default
//! 384 × 256 (the far field coarsened, Courant 3). Each case is the
//! change of the net CT or the net efficiency when one of the two is
//! refined, `refined / default − 1`:
//!
//! - the step halved: Courant 1.5;
//! - the grid: 480 nodes round and 320 rings, the far stretch scaled
//!   with the rings ([`ViscousPlate::with_radial`]).
//!
//! These are verifications, not comparisons with published data: the
//! reference is 0 (a converged result does not change when refined), and
//! the tolerance is the 3 %. The flows are deterministic, the
//! same to the bit on any thread count, so a case's figure is the same
//! on every run.
//!
//! Measured (2026-12-06, one thread a run, two runs at a time; the
//! integration benchmark `discipline_ns_scores::ns_deforming_evaluation_benchmark`
//! with `FWAV_NS_COURANT`, or `FWAV_NS_AROUND=480 FWAV_NS_RADIAL=320`;
//! `ns2d/README.md`, "The default section's evaluation refined"): at the
//! default, CT 0.07104 and efficiency 0.04180 rigid, 0.08980 and 0.03447
//! deforming;
//!
//! | refined | rigid CT | rigid efficiency | deforming CT | deforming efficiency |
//! | --- | --- | --- | --- | --- |
//! | the step halved (Courant 1.5) | −0.86 % | −0.12 % | +0.52 % | +0.63 % |
//! | the grid (480 × 320) | +0.33 % | +1.11 % | +0.49 % | +0.65 % |
//! | (Courant 2, not a case) | −1.84 % | −1.23 % | +0.67 % | +0.75 % |
//!
//! The six runs took 88 s, 150 s and 197 s rigid, 145 s, 268 s and 294 s
//! deforming (default, step, grid; one thread each).
//!
//! What this does not show: the L18 rows far from the initial design
//! (±40° strokes, 13 Hz, mean angles of ±10°, stroke planes of 70° or
//! 110°) shed vortices that
//! do not repeat from stroke to stroke, and there the scores move by up
//! to 14.5 % when refined (integration test
//! `discipline_ns_scatter::the_long_means_change_less_than_3_percent_when_the_step_and_the_grid_are_refined`,
//! ignored and failing; `NS_LONG_MEAN_SCATTER`).
//!
//! [`SectionCase::evaluate`]: crate::discipline::section::SectionCase::evaluate
//! [`ViscousPlate::with_radial`]: crate::discipline::section_model::ViscousPlate::with_radial

use crate::aero2d::viscous::ViscousSection;
use crate::aeroelastic::handoff::section::SectionFile;
use crate::aeroelastic::FlappingKinematics;
use crate::discipline::section::{SectionCase, SectionResult};
use crate::discipline::section_model::{SectionFlowModel, ViscousPlate};
use crate::validation::{
    missing, shared, ErrorKind, Measured, Memo, Solver, Spec, Validation, ValidationError,
};

/// The deformation of the default design's first system analysis at the
/// mid-span section (the discipline's input in its first cycle).
const FIRST_CYCLE_SECTION: &str = include_str!("../../../tests/data/fwav_cycle1_section.json");

/// The criterion the cases are held to.
const CRITERION: &str = "issue 23: a converged result changes by less than 3 % when the grid \
                         and the time step are refined (reference 0: the change itself)";

/// Whether the section deforms.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Shape {
    Rigid,
    Deforming,
}

/// The resolution a run is made at.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Resolution {
    /// 384 × 256, the far field coarsened, Courant 3.
    Default,
    /// The step halved: Courant 1.5.
    Step,
    /// The grid refined: 480 round, 320 rings.
    Grid,
}

/// A scored quantity.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Score {
    Thrust,
    Efficiency,
}

/// The plate of a resolution.
fn plate(resolution: Resolution) -> ViscousPlate {
    let default = ViscousPlate::new(ViscousSection::DEFAULT_THICKNESS);
    match resolution {
        Resolution::Default => default,
        Resolution::Step => ViscousPlate {
            courant: 0.5 * default.courant,
            ..default
        },
        Resolution::Grid => ViscousPlate {
            around: 480,
            ..default.with_radial(320)
        },
    }
}

/// The evaluation of the initial kinematics at `resolution`.
fn evaluate(shape: Shape, resolution: Resolution) -> Result<SectionResult, ValidationError> {
    let deformation = match shape {
        Shape::Rigid => Vec::new(),
        Shape::Deforming => {
            SectionFile::from_json(FIRST_CYCLE_SECTION)
                .map_err(|e| missing(format!("fwav_cycle1_section.json: {e}")))?
                .samples
        }
    };
    let case = SectionCase {
        deformation,
        model: SectionFlowModel::Ns(plate(resolution)),
        ..SectionCase::fwav_mid_span()
    };
    case.evaluate(&FlappingKinematics::INITIAL)
        .map_err(|e| missing(format!("Navier-Stokes, the default section: {e}")))
}

/// [`evaluate`], once per process for each of the six runs.
fn run(shape: Shape, resolution: Resolution) -> Result<SectionResult, ValidationError> {
    static RUNS: [Memo<SectionResult>; 6] = [const { Memo::new() }; 6];
    let index = 3 * usize::from(shape == Shape::Deforming)
        + match resolution {
            Resolution::Default => 0,
            Resolution::Step => 1,
            Resolution::Grid => 2,
        };
    shared(&RUNS[index], || evaluate(shape, resolution))
}

/// The change of `score` from the default resolution to `refined`.
fn change(shape: Shape, refined: Resolution, score: Score) -> Result<Measured, ValidationError> {
    let read = |r: &SectionResult| match score {
        Score::Thrust => r.ct_net,
        Score::Efficiency => r.efficiency_net,
    };
    let default = read(&run(shape, Resolution::Default)?);
    let finer = read(&run(shape, refined)?);
    Ok(Measured {
        value: finer / default - 1.0,
        note: Some(format!("{default:.4} at the default, {finer:.4} refined")),
    })
}

/// The case of `score` for a shape and a refinement, its name and
/// quantity put together from their words (a word for the name, a phrase
/// for the quantity).
macro_rules! convergence_case {
    (($shape:ident, $shape_word:literal, $shape_phrase:literal),
     ($refined:ident, $refined_word:literal, $refined_phrase:literal),
     ($score:ident, $score_word:literal, $score_phrase:literal)) => {
        Validation {
            spec: Spec {
                name: concat!(
                    "ns2d/refined-",
                    $refined_word,
                    "-",
                    $shape_word,
                    "-",
                    $score_word
                ),
                solver: Solver::Ns2d,
                reference: CRITERION,
                quantity: concat!(
                    "change of the default section's ",
                    $score_phrase,
                    " (",
                    $shape_phrase,
                    ", initial kinematics, strokes 3-4 of 4) when ",
                    $refined_phrase
                ),
                units: "1",
                error_kind: ErrorKind::Absolute,
                tolerance: 0.03,
            },
            reference: || 0.0,
            compute: || change(Shape::$shape, Resolution::$refined, Score::$score),
        }
    };
}

/// The CT and efficiency cases of a shape and a refinement.
macro_rules! convergence_pair {
    ($shape:tt, $refined:tt) => {
        [
            convergence_case!($shape, $refined, (Thrust, "ct", "net CT")),
            convergence_case!(
                $shape,
                $refined,
                (Efficiency, "efficiency", "net efficiency")
            ),
        ]
    };
}

/// The eight cases: rigid and deforming (as the first system analysis
/// found), the step halved (Courant 3 to 1.5) and the grid refined (384 x
/// 256 to 480 x 320), CT and efficiency. Measured (2026-12-06): see
/// [`self`]'s docs and `ns2d/README.md`, "The default section's
/// evaluation refined".
pub fn cases() -> Vec<Validation> {
    [
        convergence_pair!(
            (Rigid, "rigid", "rigid"),
            (Step, "step", "the step is halved (Courant 3 to 1.5)")
        ),
        convergence_pair!(
            (Rigid, "rigid", "rigid"),
            (
                Grid,
                "grid",
                "the grid is refined from 384 x 256 to 480 x 320"
            )
        ),
        convergence_pair!(
            (
                Deforming,
                "deforming",
                "deforming as the first system analysis found"
            ),
            (Step, "step", "the step is halved (Courant 3 to 1.5)")
        ),
        convergence_pair!(
            (
                Deforming,
                "deforming",
                "deforming as the first system analysis found"
            ),
            (
                Grid,
                "grid",
                "the grid is refined from 384 x 256 to 480 x 320"
            )
        ),
    ]
    .into_iter()
    .flatten()
    .collect()
}
