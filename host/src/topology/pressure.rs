//! The structural discipline's load: the pressure jump on every shell
//! element over one flapping period, handed on by the system analysis
//! (seed paper, "Topology optimization in the structural discipline": the
//! dynamic pressures of the aeroelastic analysis are imposed on the
//! non-design mylar layer at every time step of the nonlinear dynamic
//! analysis).
//!
//! The file form is the `pressure.json` that `fwav system-analysis` writes
//! ([`PressureFile`]): one sample a step, sample `k` at `(k + 1) dt` after
//! the start of a period, pressures in Pa (lower minus upper surface,
//! positive along the element normal).
//!
//! May import: the handoff file type of [`crate::aeroelastic::handoff`].

use crate::aeroelastic::handoff::PressureFile;
use crate::file_format::FormatError;

/// A periodic pressure history, Pa per element.
#[derive(Clone, Debug, PartialEq)]
pub struct PressureHistory {
    /// Time between samples, s.
    pub dt: f64,
    /// Pressure jump per element, one sample a step over one period;
    /// sample `k` is at `(k + 1) dt`, so the last is at the period's end
    /// (the same as its start).
    pub samples: Vec<Vec<f64>>,
}

/// What is wrong with a pressure history.
#[derive(Debug, thiserror::Error)]
pub enum PressureError {
    /// Not a `pressure.json` of this version ([`PressureFile`]).
    #[error(transparent)]
    File(#[from] FormatError),
    /// No samples.
    #[error("pressure history has no samples")]
    Empty,
    /// A time step that is not a positive finite number.
    #[error("pressure history dt_s = {0} is not a positive time step")]
    Step(f64),
    /// A sample with the wrong number of element values.
    #[error(
        "pressure sample {sample} has {got} element values; the wing mesh has {expected} elements"
    )]
    Shape {
        /// Sample index.
        sample: usize,
        /// Values given.
        got: usize,
        /// Elements of the mesh.
        expected: usize,
    },
    /// A value that is not a finite number.
    #[error("pressure sample {sample}, element {element} is {value}, not a finite pressure")]
    NotFinite {
        /// Sample index.
        sample: usize,
        /// Element index.
        element: usize,
        /// The value.
        value: f64,
    },
}

impl PressureHistory {
    /// A history checked against a mesh of `elements` elements.
    pub fn new(dt: f64, samples: Vec<Vec<f64>>, elements: usize) -> Result<Self, PressureError> {
        let history = Self { dt, samples };
        history.check(elements)?;
        Ok(history)
    }

    /// Reads the `pressure.json` form ([`PressureFile`]) and checks it
    /// against a mesh of `elements` elements.
    pub fn from_json(text: &str, elements: usize) -> Result<Self, PressureError> {
        Self::from_file(PressureFile::from_json(text)?, elements)
    }

    /// The history of a `pressure.json`, checked against a mesh of
    /// `elements` elements.
    pub fn from_file(file: PressureFile, elements: usize) -> Result<Self, PressureError> {
        Self::new(file.dt_s, file.samples, elements)
    }

    /// Checks the step, the sample count and shape and every value.
    pub fn check(&self, elements: usize) -> Result<(), PressureError> {
        if !(self.dt.is_finite() && self.dt > 0.0) {
            return Err(PressureError::Step(self.dt));
        }
        if self.samples.is_empty() {
            return Err(PressureError::Empty);
        }
        for (sample, values) in self.samples.iter().enumerate() {
            if values.len() != elements {
                return Err(PressureError::Shape {
                    sample,
                    got: values.len(),
                    expected: elements,
                });
            }
            if let Some((element, &value)) = values.iter().enumerate().find(|(_, v)| !v.is_finite())
            {
                return Err(PressureError::NotFinite {
                    sample,
                    element,
                    value,
                });
            }
        }
        Ok(())
    }

    /// The period, s.
    pub fn period(&self) -> f64 {
        self.dt * self.samples.len() as f64
    }

    /// The largest pressure magnitude over all samples and elements, Pa.
    pub fn peak(&self) -> f64 {
        self.samples
            .iter()
            .flatten()
            .fold(0.0f64, |m, p| m.max(p.abs()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The system analysis's file reads back; each kind of bad input is
    /// refused with its own error.
    #[test]
    fn reads_and_refuses() {
        let file = |body: &str| {
            format!(r#"{{"format": "fwav-pressure-history", "format_version": 1, {body}}}"#)
        };
        let ok =
            PressureHistory::from_json(&file(r#""dt_s": 0.5, "samples": [[1, 2], [3, -4]]"#), 2)
                .unwrap();
        assert_eq!(ok.period(), 1.0);
        assert_eq!(ok.peak(), 4.0);
        let bad = |body: &str| PressureHistory::from_json(&file(body), 2).unwrap_err();
        assert!(matches!(bad(r#""dt_s": 1"#), PressureError::File(_)));
        assert!(matches!(
            PressureHistory::from_json(r#"{"dt_s": 1, "samples": [[1, 2]]}"#, 2).unwrap_err(),
            PressureError::File(FormatError::WrongFormat { .. })
        ));
        assert!(matches!(
            bad(r#""dt_s": 0, "samples": [[1, 2]]"#),
            PressureError::Step(_)
        ));
        assert!(matches!(
            bad(r#""dt_s": 1, "samples": []"#),
            PressureError::Empty
        ));
        assert!(matches!(
            bad(r#""dt_s": 1, "samples": [[1, 2], [1]]"#),
            PressureError::Shape { sample: 1, .. }
        ));
        let nan = PressureHistory::new(1.0, vec![vec![1.0, f64::NAN]], 2).unwrap_err();
        assert!(matches!(nan, PressureError::NotFinite { element: 1, .. }));
    }
}
