//! A deforming section's runs ([`ViscousSection::run_deforming`],
//! [`ViscousSection::run_deflecting`]): its samples made into a history
//! of maps for the moving grid, or its rigid part taken into the frame
//! ([`super::RigidDeflection`]).

use fwav_ns2d::{Complex64, Contour, Deformation, Flow, NsError, SectionMap};

use crate::aero2d::camber::check_midlines;

use super::{
    RigidDeflection, SectionPath, ViscousError, ViscousRun, ViscousSection, ViscousShape,
    CONTOUR_POINTS,
};

impl ViscousSection {
    /// [`Self::run`] with the section deforming through `samples` over
    /// each period of `path` (sample `i` at `i · period / n`), in the
    /// section's kinematic frame (chords, leading edge at (0, 0)): for the
    /// plate, mid-lines from the leading to the trailing edge, each the
    /// mid-line of a membrane of the plate's thickness shortened by half
    /// the thickness at each end (so that a flat sample is the rigid
    /// plate); for a contour or an ellipse, whole contours. The grid moves
    /// to each step's map ([`Flow::deforming`]). Cost: the rigid run's
    /// and the grid's motion, three inverse FFTs a ring a step: 82.2 s
    /// for the default section's 4 cycles deforming as the built-in
    /// design's first system analysis found, 54.3 s rigid (384 × 256,
    /// 2026-12-06; `discipline_ns_scores::ns_deforming_evaluation_benchmark`).
    ///
    /// # Errors
    /// As [`Self::run`]; [`ViscousError::DeformingWithoutPeriod`] for a
    /// path without a period, [`ViscousError::Midline`] for a plate's
    /// sample that is not a mid-line of the chord's length,
    /// [`ViscousError::DeformedShape`] for a sample that cannot be mapped.
    pub fn run_deforming(
        &self,
        path: SectionPath,
        reynolds: f64,
        duration: f64,
        samples: &[Vec<(f64, f64)>],
    ) -> Result<ViscousRun, ViscousError> {
        self.run_deforming_into(path, reynolds, duration, samples, &mut super::NoFrames)
    }

    /// [`Self::run_deforming`], handing `frames` the flows
    /// [`Self::field_frames`] asks for as the run reaches them.
    ///
    /// # Errors
    /// As [`Self::run_deforming`], and [`ViscousError::Frame`] when
    /// `frames` fails.
    pub fn run_deforming_into(
        &self,
        path: SectionPath,
        reynolds: f64,
        duration: f64,
        samples: &[Vec<(f64, f64)>],
        frames: &mut dyn super::FrameSink,
    ) -> Result<ViscousRun, ViscousError> {
        if matches!(self.shape, ViscousShape::Plate(_)) {
            check_midlines(samples)?;
        }
        let k = path.reduced_frequency();
        if k.is_nan() || k <= 0.0 {
            return Err(ViscousError::DeformingWithoutPeriod);
        }
        let period = std::f64::consts::PI / k;
        let build =
            |section: &Self, path: SectionPath| -> Result<Flow<SectionPath>, ViscousError> {
                let deformation = section.deformation(path.pivot(), samples, period)?;
                let spec = section.grid(&deformation.map_at(0.0), reynolds)?;
                Ok(Flow::deforming(deformation, spec, path, 1.0 / reynolds)?)
            };
        self.run_flows(build, path, reynolds, duration, frames)
    }

    /// A flapping section deforming by `samples` (as
    /// [`Self::run_deforming`] takes them) with the rigid part of its
    /// deformation ([`RigidDeflection`]: the wing's bending and twist at
    /// the section) in the moving frame ([`SectionPath::Deflected`]), and
    /// only its change of shape on the moving grid; or, when the shape
    /// changes by at most `shape_tolerance` chords beyond that part
    /// ([`RigidDeflection::shape_change`]), that change left out and the
    /// undeformed section carried and turned on a grid that moves only
    /// with the frame ([`Self::run`]). A path other than
    /// [`SectionPath::Flapping`], or samples [`RigidDeflection::fit`]
    /// cannot hold, run as [`Self::run_deforming`].
    ///
    /// Why (`ns2d/README.md`, "The deformation's rigid part"): the grid's motion
    /// costs half again a rigid step, which the section without its
    /// change of shape does not pay; but the default section's change of
    /// shape, 1.05e-3 chords, moves CT by 3.7 %, and the discipline keeps
    /// the whole deformation on the moving grid
    /// ([`crate::discipline::section_model::ViscousPlate::shape_tolerance`]),
    /// where [`Self::run_deforming`] gives the same flow as this with the
    /// change of shape on the grid (the first stroke's CT within 0.07 %).
    ///
    /// # Errors
    /// As [`Self::run_deforming`].
    pub fn run_deflecting(
        &self,
        path: SectionPath,
        reynolds: f64,
        duration: f64,
        samples: &[Vec<(f64, f64)>],
        shape_tolerance: f64,
    ) -> Result<ViscousRun, ViscousError> {
        if matches!(self.shape, ViscousShape::Plate(_)) {
            check_midlines(samples)?;
        }
        let SectionPath::Flapping(flapping) = path else {
            return self.run_deforming(path, reynolds, duration, samples);
        };
        let period = std::f64::consts::PI / flapping.reduced_frequency;
        let Some(deflection) = RigidDeflection::fit(samples, path.pivot(), period) else {
            return self.run_deforming(path, reynolds, duration, samples);
        };
        let deflected = SectionPath::Deflected(flapping, Box::new(deflection));
        if deflection.shape_change() <= shape_tolerance {
            self.run(deflected, reynolds, duration)
        } else {
            let shape = deflection.residual(samples, path.pivot());
            self.run_deforming(deflected, reynolds, duration, &shape)
        }
    }

    /// The deformation history through `samples` over `period` (chords
    /// travelled), sample `i` at `i · period / n`, in the section's
    /// kinematic frame (chords, leading edge at (0, 0)), the pitch axis
    /// `pivot` put at the origin: for the plate, mid-lines from the
    /// leading to the trailing edge, each the mid-line of a membrane of
    /// the plate's thickness ([`Contour::membrane`]) shortened by half the
    /// thickness at each end, so that a flat sample is the rigid plate;
    /// for a contour or an ellipse, whole contours
    /// ([`ViscousShape::from_points`]). Each shape is drawn on the same
    /// number of points, the `i`-th the same point of the section, which
    /// [`Deformation::followed`] follows.
    ///
    /// The plate's samples are first split into their rigid part
    /// ([`RigidDeflection`]) and their change of shape: each sample's map
    /// is the map fitted to its change of shape, then moved rigidly by
    /// its rigid part (exactly: [`SectionMap::moved`]). Why: a map fitted
    /// to each carried and turned plate on its own is not the turned map
    /// of the others, and the grid follows the fits' small differences
    /// between the samples (presumably at the plate's rounded ends, where
    /// the cells are finest). On the default FWAV section with its change
    /// of shape taken out, the first stroke's CT was 4.5 % above the same
    /// rigid motion as the frame's at Courant 3 (0.10225 against 0.09788)
    /// and 0.4 % at Courant 0.75 (0.09882 against 0.09841); with the maps
    /// moved exactly, 0.09778 at Courant 3 (2026-12-06, `ns2d/README.md` "The
    /// deformation's rigid part").
    /// Samples the fit cannot hold keep their own fitted maps.
    ///
    /// Cost: a map fit a sample (a few ms each).
    fn deformation(
        &self,
        pivot: f64,
        samples: &[Vec<(f64, f64)>],
        period: f64,
    ) -> Result<Deformation, ViscousError> {
        let rigid = match self.shape {
            ViscousShape::Plate(_) => RigidDeflection::fit(samples, pivot, period),
            ViscousShape::Ellipse(_) | ViscousShape::Contour(_) => None,
        };
        let Some(rigid) = rigid else {
            let maps = Deformation::followed(&self.shape_maps(pivot, samples)?)?;
            return Ok(Deformation::periodic(&maps, period)?);
        };
        let shapes = rigid.residual(samples, pivot);
        let n = shapes.len();
        let maps: Vec<SectionMap> = Deformation::followed(&self.shape_maps(pivot, &shapes)?)?
            .iter()
            .enumerate()
            .map(|(i, map)| {
                let state = rigid.state(period * i as f64 / n as f64);
                map.moved(state.angle, state.translation)
            })
            .collect();
        Ok(Deformation::periodic(&maps, period)?)
    }

    /// Each of `samples`' shapes ([`Self::deformation`]) mapped, the pitch
    /// axis `pivot` put at the origin: the map and the angles of its
    /// points on the unit circle.
    pub(super) fn shape_maps(
        &self,
        pivot: f64,
        samples: &[Vec<(f64, f64)>],
    ) -> Result<Vec<(SectionMap, Vec<f64>)>, ViscousError> {
        let terms = self.laurent_terms()?;
        let n = samples.len();
        let shift = |z: &Complex64| (z.re - pivot, z.im);
        samples
            .iter()
            .enumerate()
            .map(|(sample, points)| {
                let failed = |source: NsError| ViscousError::DeformedShape {
                    sample,
                    samples: n,
                    source,
                };
                let contour = match &self.shape {
                    ViscousShape::Plate(t) => {
                        let midline = shortened_midline(points, 0.5 * t);
                        Contour::membrane(&midline, *t, CONTOUR_POINTS).map_err(failed)?
                    }
                    ViscousShape::Ellipse(_) | ViscousShape::Contour(_) => {
                        // A sharp trailing edge made blunt, as the rigid
                        // section's (`from_points` gives a contour).
                        let blunt = match ViscousShape::from_points(points) {
                            Ok(ViscousShape::Contour(p)) => p,
                            Ok(_) => points.clone(),
                            Err(ViscousError::Solver(e)) => return Err(failed(e)),
                            Err(e) => return Err(e),
                        };
                        Contour::from_points(&blunt).map_err(failed)?
                    }
                };
                let points: Vec<(f64, f64)> = contour.points().iter().map(shift).collect();
                let contour = Contour::from_points(&points).map_err(failed)?;
                SectionMap::from_contour_with_angles(&contour, terms).map_err(failed)
            })
            .collect()
    }
}

/// The mid-line `points` (leading to trailing edge) shortened by `cut`
/// of its length at each end (the membrane's semicircular ends add it
/// back); unchanged when shorter than `4 cut`.
fn shortened_midline(points: &[(f64, f64)], cut: f64) -> Vec<(f64, f64)> {
    let length: f64 = points
        .windows(2)
        .map(|p| (p[1].0 - p[0].0).hypot(p[1].1 - p[0].1))
        .sum();
    if length.is_nan() || length <= 4.0 * cut {
        return points.to_vec();
    }
    // The leading end's cut; then the reversed line's.
    let trim = |line: &[(f64, f64)]| -> Vec<(f64, f64)> {
        let mut left = cut;
        for (i, p) in line.windows(2).enumerate() {
            let d = (p[1].0 - p[0].0).hypot(p[1].1 - p[0].1);
            if d > left {
                let f = left / d;
                let start = (
                    p[0].0 + f * (p[1].0 - p[0].0),
                    p[0].1 + f * (p[1].1 - p[0].1),
                );
                let mut out = vec![start];
                out.extend_from_slice(&line[i + 1..]);
                return out;
            }
            left -= d;
        }
        line.to_vec()
    };
    let mut reversed = trim(points);
    reversed.reverse();
    let mut out = trim(&reversed);
    out.reverse();
    out
}
