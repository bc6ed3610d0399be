//! The aerodynamic discipline's design space: the four kinematic
//! variables' three levels each, the L18 array's designs over them (step 1
//! of [`super::kinematic`]) and the coded values the response surfaces
//! use.

use serde::{Deserialize, Serialize};

use crate::aeroelastic::kinematics::FlappingKinematics;
use crate::optimize::doe::{l18_quadratic_columns, OrthogonalArray};

use super::kinematic::KinematicError;

/// The four design variables and their three levels (physical units:
/// Hz and degrees, as a person sets them), low, middle (the initial
/// design) and high; the RSM and NSGA-II search between low and high.
/// Its fields are the level keys of the design file's `[design]` table
/// (a missing one keeps [`DesignSpace::fwav`]'s).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct DesignSpace {
    /// Flapping frequency levels, Hz.
    pub frequency_hz: [f64; 3],
    /// Flapping amplitude levels, degrees.
    pub amplitude_deg: [f64; 3],
    /// Mean flapping angle levels, degrees.
    pub mean_angle_deg: [f64; 3],
    /// Stroke-plane inclination levels, degrees.
    pub stroke_plane_deg: [f64; 3],
}

impl Default for DesignSpace {
    /// [`DesignSpace::fwav`].
    fn default() -> Self {
        Self::fwav()
    }
}

impl DesignSpace {
    /// Three levels around the built-in initial design (11 Hz, ±30°, 0°,
    /// 90°): 9/11/13 Hz, 20/30/40°, -10/0/10°, 70/90/110° (a documented
    /// choice; the paper's design table is lost in the copy here).
    pub fn fwav() -> Self {
        Self {
            frequency_hz: [9.0, 11.0, 13.0],
            amplitude_deg: [20.0, 30.0, 40.0],
            mean_angle_deg: [-10.0, 0.0, 10.0],
            stroke_plane_deg: [70.0, 90.0, 110.0],
        }
    }

    /// The 18 designs of step 1: the L18 array over this space's levels,
    /// on the columns that support a full quadratic
    /// ([`l18_quadratic_columns`]), in the array's row order.
    ///
    /// # Errors
    /// [`KinematicError::Array`] if the array cannot be laid out (not for
    /// a space of three levels a factor).
    pub fn l18_designs(&self) -> Result<Vec<FlappingKinematics>, KinematicError> {
        Ok(self.l18_layout()?.2)
    }

    /// The L18 array, its four columns and the designs they lay out
    /// ([`Self::l18_designs`]).
    pub(super) fn l18_layout(
        &self,
    ) -> Result<(OrthogonalArray, Vec<usize>, Vec<FlappingKinematics>), KinematicError> {
        let array = OrthogonalArray::l18();
        let columns = l18_quadratic_columns(4)?;
        let levels: Vec<Vec<f64>> = self.levels().iter().map(|l| l.to_vec()).collect();
        let plan = array.design(&columns, &levels)?;
        let designs = plan
            .iter()
            .map(|x| FlappingKinematics::from_degrees([x[0], x[1], x[2], x[3]]))
            .collect();
        Ok((array, columns, designs))
    }

    pub(super) fn levels(&self) -> [[f64; 3]; 4] {
        [
            self.frequency_hz,
            self.amplitude_deg,
            self.mean_angle_deg,
            self.stroke_plane_deg,
        ]
    }

    /// The kinematics at coded values (`-1` low, `0` middle, `1` high;
    /// the middle need not be halfway, so each half is mapped on its own,
    /// in Hz and degrees, then converted by
    /// [`FlappingKinematics::from_degrees`]).
    pub fn decode(&self, coded: &[f64]) -> FlappingKinematics {
        let mut x = [0.0; 4];
        for (f, l) in self.levels().iter().enumerate() {
            let c = coded[f].clamp(-1.0, 1.0);
            x[f] = if c < 0.0 {
                l[1] + c * (l[1] - l[0])
            } else {
                l[1] + c * (l[2] - l[1])
            };
        }
        FlappingKinematics::from_degrees(x)
    }
}
