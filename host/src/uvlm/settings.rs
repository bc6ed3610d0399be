//! Settings of the unsteady vortex-lattice method: time step, air, onset
//! flow, symmetry, wake model and the conventions of the loads.

use nalgebra::Vector3;

use super::UvlmError;

/// Which potential jump the unsteady term `ρ ∂Φ/∂t` of the pressure uses
/// on panel `(i, j)` (Katz & Plotkin 2001, §13.12; the three coincide as
/// the lattice is refined, they differ by `O(Δx ∂Γ/∂t)` on a coarse one).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PotentialRate {
    /// `Φ = Γ(i, j)`: the ring strength (the textbook's lifting-surface
    /// pressure formula, `∂Γ_ij/∂t`).
    Ring,
    /// `Φ = (Γ(i, j) + Γ(i − 1, j)) / 2`, `Γ(−1, j) = 0`: the mean of the
    /// ring and the one ahead of it, as in Katz & Plotkin's Program 16
    /// (App. D, `SIGMA1 = (0.5 GAMAIJ + SIGMA) DX`).
    NeighbourMean,
    /// `Φ = 3/4 Γ(i, j) + 1/4 Γ(i − 1, j)`: the mean over the panel of the
    /// potential jump of the ring lattice, whose rings start at the panel's
    /// quarter chord (the jump is `Γ(i − 1, j)` on the panel's first
    /// quarter, `Γ(i, j)` on the rest), so the chord integral of `ΔΦ` is
    /// exact for the discrete vortex sheet.
    PanelAverage,
}

/// How `∂Φ/∂t` is taken from the potential jumps of successive steps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TimeDerivative {
    /// `(Φ_n − Φ_{n−1}) / dt` (Katz & Plotkin's Program 16). Centred half
    /// a step behind the rest of the load, which costs an `O(dt)` phase
    /// error: on a plate heaving at k = 1 with 25 steps a cycle and 8
    /// chordwise panels the cycle-mean power is 17% above Garrick's.
    FirstOrder,
    /// `(3 Φ_n − 4 Φ_{n−1} + Φ_{n−2}) / (2 dt)`, the second-order backward
    /// difference, from the third step on (the first two steps use the
    /// first-order difference, so that an impulsive start keeps its
    /// impulse `ρ Φ`); the same heaving case is within 4% of Garrick's
    /// power.
    SecondOrder,
}

/// Settings of [`super::Uvlm`]. SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct UvlmSettings {
    /// Time step, s.
    pub dt: f64,
    /// Air density, kg/m³.
    pub density: f64,
    /// Velocity of the air far from the wing in the inertial frame, m/s
    /// (e.g. `(U, 0, 0)` for a wing flying towards −x).
    pub freestream: Vector3<f64>,
    /// Adds the mirror image about the root plane y = 0: the lattice is
    /// the right half of a symmetric pair (the root corners are assumed
    /// to lie on y = 0).
    pub symmetric: bool,
    /// Number of the youngest wake point rows, counting the row being shed
    /// at the trailing edge as the first, that convect with the local
    /// velocity (freestream + induced); older rows move with the
    /// freestream only (Katz & Plotkin 2001, §13.12 wake rollup; Program
    /// 16's `NW`). `0` is a frozen (prescribed, flat) wake, `usize::MAX`
    /// a fully free wake.
    pub free_wake_rows: usize,
    /// Wake ring rows kept; older rows are dropped. `usize::MAX` keeps all.
    pub wake_rows: usize,
    /// Core radius of the Biot–Savart kernel, m ([`super::vortex`]).
    pub core_radius: f64,
    /// Distance of the shed vortex behind the trailing edge as a fraction
    /// of the distance the air travels past the trailing edge in one step,
    /// `|U∞ − v_TE| dt` (the wing's last ring extends that far behind the
    /// trailing edge; Katz & Plotkin 2001, §13.12: 0.2–0.3, their Program
    /// 16 uses 0.3).
    pub shed_offset: f64,
    /// The potential-jump convention of the unsteady pressure term.
    pub potential_rate: PotentialRate,
    /// The difference formula of `∂Φ/∂t`.
    pub time_derivative: TimeDerivative,
}

impl UvlmSettings {
    /// Settings with the defaults: no symmetry, a fully free and
    /// untruncated wake, `shed_offset = 0.3`, core radius one tenth of the
    /// distance the freestream travels in a step (`0.1 |U∞| dt`, so the
    /// core scales with the wake panels; set it explicitly for a hovering
    /// wing, where it would be zero), [`PotentialRate::NeighbourMean`] and
    /// [`TimeDerivative::SecondOrder`] (the most accurate pair against
    /// Theodorsen's lift and Garrick's power, tests/integration/uvlm.rs).
    pub fn new(dt: f64, density: f64, freestream: Vector3<f64>) -> Self {
        Self {
            dt,
            density,
            freestream,
            symmetric: false,
            free_wake_rows: usize::MAX,
            wake_rows: usize::MAX,
            core_radius: 0.1 * freestream.norm() * dt,
            shed_offset: 0.3,
            potential_rate: PotentialRate::NeighbourMean,
            time_derivative: TimeDerivative::SecondOrder,
        }
    }

    /// Checks that the numbers are usable: `dt` and `density` positive,
    /// `core_radius` and `shed_offset` non-negative, all finite.
    pub fn validate(&self) -> Result<(), UvlmError> {
        let check = |name: &'static str, value: f64, ok: bool, requirement: &'static str| {
            if value.is_finite() && ok {
                Ok(())
            } else {
                Err(UvlmError::Parameter {
                    name,
                    value,
                    requirement,
                })
            }
        };
        check("dt", self.dt, self.dt > 0.0, "must be positive and finite")?;
        check(
            "density",
            self.density,
            self.density > 0.0,
            "must be positive and finite",
        )?;
        check(
            "core_radius",
            self.core_radius,
            self.core_radius >= 0.0,
            "must be non-negative and finite",
        )?;
        check(
            "shed_offset",
            self.shed_offset,
            self.shed_offset >= 0.0,
            "must be non-negative and finite",
        )?;
        for (k, name) in ["freestream.x", "freestream.y", "freestream.z"]
            .into_iter()
            .enumerate()
        {
            check(name, self.freestream[k], true, "must be finite")?;
        }
        Ok(())
    }
}
