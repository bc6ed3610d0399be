//! The section of a [`super::Case`] and so its solver ([`SectionModel`]):
//! what a section name means to each model (`flat`, a NACA 4-digit name,
//! a point file), and a thick section's deformation history held to it
//! ([`check_contour_history`]).

use std::path::Path;

use super::{CaseError, MAX_NACA_THICKNESS, MIN_SECTION_POINTS, NACA_SIDE_POINTS};
use crate::aero2d::naca::{read_points, Naca4, NacaError, TrailingEdge};
use crate::aero2d::panel::{SectionShape, DEFAULT_PANELS};
use crate::aero2d::viscous::{ViscousSection, ViscousShape};

/// The section and, with it, the solver.
#[derive(Clone, Debug, PartialEq)]
pub enum SectionModel {
    /// A thin line (flat plate, or the deforming mid-line): LDVM.
    Flat,
    /// A closed contour: the panel method.
    Thick(SectionShape),
    /// Laminar Navier–Stokes ([`crate::aero2d::viscous`]).
    Viscous(ViscousSection),
}

impl SectionModel {
    /// The section a name means: `flat`, a NACA 4-digit name (closed
    /// trailing edge, [`DEFAULT_PANELS`] panels), or a point file (Selig
    /// order or clockwise from the trailing edge, chords).
    pub fn named(name: &str) -> Result<Self, CaseError> {
        if name == "flat" {
            return Ok(Self::Flat);
        }
        let points = match name.parse::<Naca4>() {
            Ok(naca) if naca.thickness > MAX_NACA_THICKNESS => {
                return Err(CaseError::TooThick {
                    name: name.to_string(),
                    thickness_percent: 100.0 * naca.thickness,
                    max_percent: 100.0 * MAX_NACA_THICKNESS,
                })
            }
            Ok(naca) => naca.points(DEFAULT_PANELS, TrailingEdge::Closed)?,
            Err(naca) => {
                let points = point_file(name, naca)?;
                if points.len() < MIN_SECTION_POINTS {
                    return Err(CaseError::TooFewPoints {
                        path: name.to_string(),
                        got: points.len(),
                        min: MIN_SECTION_POINTS,
                    });
                }
                points
            }
        };
        Ok(Self::Thick(SectionShape::new(&points)?))
    }

    /// The section a name means to the viscous model: `flat` (a plate of
    /// `plate_thickness` chords with semicircular ends), a NACA 4-digit
    /// name or a point file (any closed contour, chords): a sharp trailing
    /// edge is opened to [`crate::aero2d::viscous::TRAILING_EDGE_THICKNESS`], see
    /// [`ViscousShape::from_points`].
    pub fn named_viscous(name: &str, plate_thickness: f64) -> Result<ViscousShape, CaseError> {
        Self::named_viscous_deforming(name, plate_thickness, None)
    }

    /// [`Self::named_viscous`], its deformation `history` (if any) checked
    /// against the section's points as given: a thick section's history
    /// must be its whole contour at each sample ([`check_contour_history`];
    /// the plate's mid-lines are checked by the run).
    ///
    /// # Errors
    /// As [`Self::named_viscous`]; [`CaseError::ContourPoints`].
    pub fn named_viscous_deforming(
        name: &str,
        plate_thickness: f64,
        history: Option<&[Vec<(f64, f64)>]>,
    ) -> Result<ViscousShape, CaseError> {
        let Some(points) = Self::viscous_points(name)? else {
            return Ok(ViscousShape::Plate(plate_thickness));
        };
        if let Some(samples) = history {
            check_contour_history(&points, samples)?;
        }
        Ok(ViscousShape::from_points(&points)?)
    }

    /// The points a named section is drawn through for the viscous model,
    /// as given (before a sharp trailing edge is opened): a NACA 4-digit
    /// name's 401, the last repeating the first (400 distinct), a point
    /// file's; `None` for `flat`, the plate.
    fn viscous_points(name: &str) -> Result<Option<Vec<(f64, f64)>>, CaseError> {
        if name == "flat" {
            return Ok(None);
        }
        let points = match name.parse::<Naca4>() {
            Ok(naca) => naca.points(2 * NACA_SIDE_POINTS, TrailingEdge::Closed)?,
            Err(naca) => point_file(name, naca)?,
        };
        Ok(Some(points))
    }

    /// Whether it is the thin line.
    pub fn is_flat(&self) -> bool {
        matches!(self, Self::Flat)
    }
}

/// Checks that each of a thick section's deformation `samples` gives as
/// many points as `section`, as the deformation's samples must (its whole
/// contour, point for point in the section's order: [`super::Case::deformation`]);
/// a last point within `1e-9` of the contour's size of the first is
/// counted on neither, as the panel method closes a contour
/// ([`SectionShape::new`]). The Navier–Stokes model runs the samples'
/// shapes, so this count is what ties them to the section it names: the
/// panel method checks its vertices alike
/// ([`crate::aero2d::panel::PanelError::HistoryMismatch`]). A history of
/// another section drawn on as many points still passes.
///
/// # Errors
/// [`CaseError::ContourPoints`] naming the first sample that differs.
pub fn check_contour_history(
    section: &[(f64, f64)],
    samples: &[Vec<(f64, f64)>],
) -> Result<(), CaseError> {
    let distinct = |points: &[(f64, f64)]| {
        let size = points
            .iter()
            .map(|p| p.0.abs().max(p.1.abs()))
            .fold(0.0_f64, f64::max);
        match (points.first(), points.last()) {
            (Some(a), Some(b))
                if points.len() > 1 && (a.0 - b.0).hypot(a.1 - b.1) <= 1e-9 * size =>
            {
                points.len() - 1
            }
            _ => points.len(),
        }
    };
    let expected = distinct(section);
    match samples
        .iter()
        .map(|s| distinct(s))
        .enumerate()
        .find(|&(_, found)| found != expected)
    {
        Some((sample, found)) => Err(CaseError::ContourPoints {
            sample,
            found,
            expected,
        }),
        None => Ok(()),
    }
}

/// The points of the section file `name`, or, when there is no such
/// file, why `name` is no section (it was not a NACA name either:
/// `naca`).
fn point_file(name: &str, naca: NacaError) -> Result<Vec<(f64, f64)>, CaseError> {
    let path = Path::new(name);
    if !path.exists() {
        return Err(CaseError::SectionName {
            name: name.to_string(),
            naca,
        });
    }
    Ok(read_points(path)?.points)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A thick section's history must give its whole contour at every
    /// sample: as many points as the section, a closing point that
    /// repeats the first (to rounding) counted on neither side; the first
    /// sample that differs is named.
    #[test]
    fn a_contour_history_is_held_to_the_sections_points() {
        let square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        let closed: Vec<(f64, f64)> = square.iter().chain(&square[..1]).copied().collect();
        let moved: Vec<(f64, f64)> = square.iter().map(|&(x, y)| (x, y + 0.1)).collect();
        assert!(check_contour_history(&square, &[closed.clone(), moved.clone()]).is_ok());
        assert!(check_contour_history(&closed, &[square.to_vec(), moved.clone()]).is_ok());
        // Closed to rounding, as a file's last point may be.
        let mut rounded = closed.clone();
        rounded[4].1 += 1e-12;
        assert!(check_contour_history(&square, &[rounded]).is_ok());
        let short = square[..3].to_vec();
        match check_contour_history(&closed, &[moved, short.clone(), short]) {
            Err(CaseError::ContourPoints {
                sample: 1,
                found: 3,
                expected: 4,
            }) => {}
            other => panic!("{other:?}"),
        }
    }
}
