//! The wing as the system analysis sees it: planform, shell mesh and the
//! two-layer sections (carbon design layer with its SIMP densities over a
//! mylar skin), plus the flight condition.

use serde::{Deserialize, Serialize};

use crate::shell::material::{Layer, Section};
use crate::shell::mesh::MeshError;
use crate::shell::wing::{Planform, WingMesh};

/// SIMP penalty of the design layer (seed paper: 3).
pub const SIMP_PENALTY: f64 = 3.0;

/// The flight condition.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct FlightCondition {
    /// Flight speed, m/s (built-in: 3 m/s, a documented choice).
    pub speed: f64,
    /// Air density, kg/m³ (sea level: 1.225).
    pub density: f64,
}

impl FlightCondition {
    /// The built-in FWAV's: 3 m/s at sea level.
    pub const FWAV: FlightCondition = FlightCondition {
        speed: 3.0,
        density: 1.225,
    };
}

/// Why a wing model was refused.
#[derive(Debug, thiserror::Error)]
pub enum WingModelError {
    /// The planform could not be meshed.
    #[error(transparent)]
    Mesh(#[from] MeshError),
    /// Wrong number of densities or a value outside [0, 1].
    #[error("carbon densities: {0}")]
    Densities(String),
}

/// A meshed wing with its layer sections.
#[derive(Clone, Debug)]
pub struct WingModel {
    /// The planform.
    pub planform: Planform,
    /// Its mesh, spar flags and root attachment.
    pub wing: WingMesh,
    /// Carbon density per element in [0, 1] (spar elements are carbon
    /// whatever the design says: the spar is not part of the design
    /// domain).
    pub densities: Vec<f64>,
    /// Section per element.
    pub sections: Vec<Section>,
}

impl WingModel {
    /// Meshes `planform` and builds the sections from the carbon densities
    /// (one per element; `None`: the uniform starting design of the
    /// topology optimization, every element at `uniform`).
    pub fn new(
        planform: Planform,
        carbon: &Layer,
        mylar: &Layer,
        densities: Option<&[f64]>,
        uniform: f64,
    ) -> Result<Self, WingModelError> {
        let wing = planform.mesh()?;
        let count = wing.mesh.elements.len();
        let mut rho = match densities {
            Some(d) if d.len() != count => {
                return Err(WingModelError::Densities(format!(
                    "{} values for {count} elements",
                    d.len()
                )))
            }
            Some(d) => d.to_vec(),
            None => vec![uniform; count],
        };
        if let Some((e, v)) = rho
            .iter()
            .enumerate()
            .find(|(_, v)| !(v.is_finite() && (0.0..=1.0).contains(*v)))
        {
            return Err(WingModelError::Densities(format!(
                "element {e} has {v}, outside [0, 1]"
            )));
        }
        for (r, &spar) in rho.iter_mut().zip(&wing.spar) {
            if spar {
                *r = 1.0;
            }
        }
        let sections = rho
            .iter()
            .map(|&r| Section::two_layer(carbon, mylar, r, SIMP_PENALTY))
            .collect();
        Ok(Self {
            planform,
            wing,
            densities: rho,
            sections,
        })
    }

    /// The built-in FWAV wing (paper's materials and mesh) at the uniform
    /// starting design `uniform` (the mass fraction).
    pub fn fwav(uniform: f64) -> Result<Self, WingModelError> {
        Self::new(Planform::FWAV, &Layer::CARBON, &Layer::MYLAR, None, uniform)
    }

    /// Planform area of the (half) wing, m².
    pub fn area(&self) -> f64 {
        let p = &self.planform;
        0.5 * (p.root_chord + p.tip_chord) * p.semi_span
    }
}
