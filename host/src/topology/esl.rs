//! Step 2 of an ESLSO cycle: the equivalent static loads
//! `f_eq(t_i) = K_L u_N(t_i)` (seed paper, eq. (12); Park & Kang 2003,
//! "Structural optimization for non-linear behavior using equivalent
//! static loads by the finite element method"): the static loads under
//! which the linear model of the current design takes the nonlinear
//! dynamic displacements `u_N` at the sampled times. They carry the
//! inertia and the geometric nonlinearity of the response into the linear
//! static topology optimization as ordinary load cases.

use crate::shell::assembly::AssemblyError;
use crate::shell::linear::LinearStatic;

/// How the load cases of the linear optimization are formed from the
/// nonlinear dynamic response.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum EslForm {
    /// `K_L u_N(t_i)` (seed paper eq. (12)): the linear model takes the
    /// nonlinear displacements exactly. For a thin shell deflecting many
    /// thicknesses the linear model reads the second-order in-plane
    /// shortening of bending as membrane strain, about `12 (w/t)^2` times
    /// the bending energy, and the optimization then answers that
    /// artefact rather than the wing's loads.
    Displacement,
    /// `f_ext(t_i) - M a_N(t_i)` (d'Alembert): the pressure on the
    /// deformed wing less the inertia forces of the nonlinear response.
    /// Identical to `K_L u_N` when the response is linear; carries the
    /// dynamics and the follower pressure but no spurious membrane
    /// energy. The default for the thin FWAV wing.
    #[default]
    Dalembert,
}

/// One equivalent static load case per sampled time (global 6-DOF
/// vectors, N and N·m; zero on the held DOFs, whose reactions the
/// optimization does not need).
#[derive(Clone, Debug, PartialEq)]
pub struct EquivalentStaticLoads {
    /// The load cases.
    pub loads: Vec<Vec<f64>>,
}

impl EquivalentStaticLoads {
    /// `K_L u` for each of `displacements` (global vectors of the model's
    /// mesh: translations m, rotation vectors rad) with `model` the linear
    /// stiffness of the design analysed. Cost: one sparse product a case.
    pub fn new(model: &LinearStatic, displacements: &[Vec<f64>]) -> Result<Self, AssemblyError> {
        let map = model.map();
        let loads = displacements
            .iter()
            .map(|u| {
                if u.len() != map.dofs() {
                    return Err(AssemblyError::Length {
                        got: u.len(),
                        expected: map.dofs(),
                    });
                }
                Ok(map.expand(&model.apply(&map.restrict(u))))
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Self { loads })
    }

    /// The d'Alembert form: the given dynamic loads `f_ext - M a` as they
    /// are (see [`EslForm::Dalembert`]).
    pub fn dalembert(dynamic_loads: Vec<Vec<f64>>) -> Self {
        Self {
            loads: dynamic_loads,
        }
    }

    /// The number of load cases.
    pub fn len(&self) -> usize {
        self.loads.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.loads.is_empty()
    }
}
