//! The flow model of the aerodynamic discipline's section analyses
//! (`[design] section_model`), and what it leaves out of the section, for
//! every report of the discipline's results.
//!
//! - [`SectionFlowModel::Ldvm`] (the default): the inviscid LDVM with
//!   leading-edge shedding and a laminar friction estimate
//!   ([`crate::aero2d::ldvm`]), of the deforming mid-line; a fraction of a
//!   second an evaluation.
//! - [`SectionFlowModel::Ns`]: laminar Navier–Stokes
//!   ([`crate::aero2d::viscous`]) of a thin plate of finite thickness with
//!   semicircular ends ([`ViscousPlate`]; the 0.1 mm membrane is far
//!   thinner than the solver can grid); its forces include the friction.
//!   The deformation history bends the plate's mid-line, on a grid that
//!   moves with it ([`ViscousSection::run_deforming`]); the reports say
//!   what was modelled ([`ModelledSection`]). Cost: the default
//!   section's 4 cycles at the default resolution on the 2-core
//!   development machine, about 43 s rigid (384 × 320 cells, Courant
//!   number 3, [`ViscousSection::run`]), about 77 s deforming as the
//!   built-in design's first system analysis found, in a normal hour (on
//!   384 × 240 31.9 s and 57.3 s were measured; 320 rings cost 1.34
//!   times as much in one hour; this slow hour, 118 s and 190 s); some
//!   900 to 1,700 times the LDVM's.

use serde::{Deserialize, Serialize};

use crate::aero2d::viscous::{ViscousSection, ViscousShape};

/// The model's name, as `[design] section_model` and the reports spell
/// it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SectionModelName {
    /// [`SectionFlowModel::Ldvm`].
    #[default]
    Ldvm,
    /// [`SectionFlowModel::Ns`].
    Ns,
}

impl SectionModelName {
    /// The word of the setting and the reports: `"ldvm"` or `"ns"`.
    pub fn word(self) -> &'static str {
        match self {
            Self::Ldvm => "ldvm",
            Self::Ns => "ns",
        }
    }
}

/// The flow model of one section evaluation, with what it needs beyond
/// the case (written with the case, so it is part of the evaluation
/// cache's key: see [`super::cache`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(tag = "name", rename_all = "lowercase")]
pub enum SectionFlowModel {
    /// The LDVM of the deforming mid-line.
    #[default]
    Ldvm,
    /// Laminar Navier–Stokes of this rigid plate at this resolution.
    Ns(ViscousPlate),
}

impl SectionFlowModel {
    /// The Navier–Stokes model of a plate `thickness` chords thick at the
    /// default resolution.
    pub fn ns(thickness: f64) -> Self {
        Self::Ns(ViscousPlate::new(thickness))
    }

    /// Its name.
    pub fn name(&self) -> SectionModelName {
        match self {
            Self::Ldvm => SectionModelName::Ldvm,
            Self::Ns(_) => SectionModelName::Ns,
        }
    }

    /// Whether this is the LDVM (then the case is written as before the
    /// model existed, so older evaluation caches still match).
    pub fn is_ldvm(&self) -> bool {
        matches!(self, Self::Ldvm)
    }

    /// How much one evaluation's scores scatter from the flow's own
    /// unsteadiness: the relative standard deviation of the net thrust
    /// coefficient and of the net efficiency averaged over the scored
    /// window (the last two strokes), as `(thrust, efficiency)`.
    ///
    /// - The LDVM's flow repeats from stroke to stroke: 0.
    /// - The Navier–Stokes flow does not ([`NS_WINDOW_SCATTER`]).
    pub fn window_scatter(&self) -> (f64, f64) {
        match self {
            Self::Ldvm => (0.0, 0.0),
            Self::Ns(_) => NS_WINDOW_SCATTER,
        }
    }

    /// Whether the model takes the section's deformation history (both
    /// do: the LDVM as its camber, the Navier–Stokes model as the plate's
    /// mid-line on a moving grid).
    pub fn takes_deformation(&self) -> bool {
        true
    }
}

/// The relative standard deviation of one Navier–Stokes evaluation's net
/// thrust coefficient and net efficiency, each averaged over two strokes
/// (the scored window, strokes 3 and 4): what two evaluations of one
/// design differ by when anything changes what brought the flow to its
/// window. The flow round the deforming plate has not settled by then,
/// and on many designs never does (the vortices shed in earlier strokes
/// meet the plate again where small differences put them; README, "The
/// evaluation's window"), so any small change moves the window's scores.
///
/// Measured (2026-12-04) as a change of the time step on the first
/// cycle's 18 L18 rows, the default section deforming as the default
/// design's first system analysis found (384 × 320 nodes): Courant
/// number 4 (`discipline_ns_scores::ns_discipline_benchmark` with
/// `FWAV_NS_COURANT=4`) against the default 3 (docs/ns-design,
/// `l18-384x320.txt`) moved CT by 5.59 % RMS (up to 12.8 %) and the
/// efficiency by 4.95 % RMS (up to 11.7 %), the mean by +0.7 %: two
/// draws, so one evaluation's deviation is those over √2, **3.95 %** and
/// **3.50 %**. The rows that moved most, at a step half the default's
/// (Courant 1.5, `discipline_ns_scores::ns_window_time_step_benchmark`), were
/// as far from Courant 3's (Courant 3's CT −9.9 %, −4.3 %, −9.8 %,
/// −0.6 % from Courant 1.5's for rows 4, 14, 18 and the initial design,
/// row 2): the window's scores do not converge with the step; they
/// scatter.
///
/// From window to window of one 12-stroke run (strokes 3 to 12 as five
/// windows of two; `discipline_ns_scores::ns_deforming_window_scatter_benchmark`,
/// `viscous_default_section::ns_evaluation_window_scatter_benchmark`)
/// the scatter is smaller, as these designs' flows settle:
///
/// | section, kinematics | CT | efficiency |
/// | --- | --- | --- |
/// | rigid, 11 Hz, ±30° | 0.20 % (periodic from the fourth stroke) | 0.32 % |
/// | deforming, 11 Hz, ±30° | 1.65 % (0.0850, 0.0885, 0.0885, 0.0869, 0.0877) | 1.38 % (0.0341, 0.0352, 0.0352, 0.0346, 0.0349) |
/// | deforming, 13 Hz, ±20°, plane 110° | 1.99 % (0.0814, 0.0831, 0.0826, 0.0851, 0.0853) | 0.52 % |
///
/// Until 2026-12-04 these window-to-window figures were the declared
/// scatter (2.0 % and 1.4 %), but the L18 rows' own last two strokes
/// differ by up to 22 % in CT (row 4, `ct_change`), which two designs'
/// settled flows did not show.
pub const NS_WINDOW_SCATTER: (f64, f64) = (0.0395, 0.035);

/// The Navier–Stokes model's thin plate and grid ([`ViscousSection`]'s
/// fields for [`ViscousShape::Plate`]).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ViscousPlate {
    /// Thickness, chords (0.005 to 0.3; the ends are semicircles).
    pub thickness: f64,
    /// Grid nodes round the plate.
    pub around: usize,
    /// Grid nodes from the wall to the outer boundary.
    pub radial: usize,
    /// Outer boundary, chords from mid-chord.
    pub outer_chords: f64,
    /// First cell at mid-chord, in boundary-layer thicknesses
    /// `c / sqrt(Re)`.
    pub first_cell_layers: f64,
    /// The largest Courant number of the time step.
    #[serde(default = "default_courant")]
    pub courant: f64,
    /// Whether the strokes before the scored window (the last two) run
    /// on the spin-up grid ([`ViscousSection::spin_up_grid`]) and the
    /// window on this one ([`SectionCase::evaluate`]); files without the
    /// key were written by evaluations without it (false). Off by
    /// default, and no `[design]` setting: it changes the deforming
    /// default section's scores far beyond their scatter (docs/ns-design,
    /// "The spin-up": over the L18 rows CT by 13 % RMS, up to 29 %).
    ///
    /// [`SectionCase::evaluate`]: super::section::SectionCase::evaluate
    #[serde(default)]
    pub spin_up: bool,
}

/// [`ViscousSection::DEFAULT_COURANT`], for files without the key.
fn default_courant() -> f64 {
    ViscousSection::DEFAULT_COURANT
}

impl ViscousPlate {
    /// A plate `thickness` chords thick at [`ViscousSection::plate`]'s
    /// default resolution (384 × 320 nodes out to 30 chords).
    pub fn new(thickness: f64) -> Self {
        let s = ViscousSection::plate(thickness);
        Self {
            thickness,
            around: s.around,
            radial: s.radial,
            outer_chords: s.outer_chords,
            first_cell_layers: s.first_cell_layers,
            courant: s.courant,
            spin_up: false,
        }
    }

    /// What the reports add for the spin-up: `"; the strokes before the
    /// scored window spun up on 256 x 214 nodes"`, or nothing.
    fn spin_up_clause(&self) -> String {
        if !self.spin_up {
            return String::new();
        }
        // The spin-up's grid does not depend on the run's length.
        let grid = self.section(0).spin_up_grid();
        format!(
            "; the strokes before the scored window spun up on {} x {} nodes",
            grid.around, grid.radial
        )
    }

    /// The solver's section, for a run whose last two of `cycles`
    /// periods are scored (the ones before them the spin-up's, when the
    /// plate has one).
    pub fn section(&self, cycles: usize) -> ViscousSection {
        ViscousSection {
            shape: ViscousShape::Plate(self.thickness),
            around: self.around,
            radial: self.radial,
            outer_chords: self.outer_chords,
            first_cell_layers: self.first_cell_layers,
            courant: self.courant,
            spin_up_periods: if self.spin_up {
                cycles.saturating_sub(2) as f64
            } else {
                0.0
            },
        }
    }
}

/// What the discipline's evaluations modelled of the section: written
/// with its results (`fwav kinematics`, `kinematics.json`,
/// `summary.json`, `report.md`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ModelledSection {
    /// The flow model.
    pub model: SectionModelName,
    /// Whether the system analysis gave the section a deformation.
    pub deformation_given: bool,
    /// Whether the evaluations took it.
    pub deformation_modelled: bool,
    /// The above as a sentence, e.g. `"ns: rigid section, the
    /// deformation is not modelled ..."`.
    pub note: String,
}

impl ModelledSection {
    /// The record of `model` on a section whose deformation was given or
    /// not.
    pub fn new(model: &SectionFlowModel, deformation_given: bool) -> Self {
        let deformation_modelled = deformation_given && model.takes_deformation();
        let word = model.name().word();
        let note = match (model, deformation_given) {
            (SectionFlowModel::Ldvm, true) => {
                format!("{word}: the section deforms as the system analysis found")
            }
            (SectionFlowModel::Ldvm, false) => {
                format!("{word}: rigid flat section (no deformation given)")
            }
            (SectionFlowModel::Ns(p), false) => format!(
                "{word}: rigid plate {} chords thick (no deformation given{})",
                p.thickness,
                p.spin_up_clause()
            ),
            (SectionFlowModel::Ns(p), true) => format!(
                "{word}: the section deforms as the system analysis found (a plate {} chords \
                 thick round the deforming mid-line{})",
                p.thickness,
                p.spin_up_clause()
            ),
        };
        Self {
            model: model.name(),
            deformation_given,
            deformation_modelled,
            note,
        }
    }
}
