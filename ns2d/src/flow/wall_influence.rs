//! The wall's influence matrix (`Flow::step`): how Thom's wall vorticity
//! at the step's end answers a unit wall vorticity at each wall node, by
//! the step's radial diffusion; factored once per time step in use and
//! kept.

use super::{deforming, Flow};
use crate::error::NsError;
use crate::motion::Motion;

/// Wall influence matrices kept ([`Flow::step`]): one per time step in
/// use (`N_θ²` values each: 1.2 MB at the default 384 wall nodes).
const INFLUENCE_CACHE: usize = 8;

impl<M: Motion> Flow<M> {
    /// The index in the cache of the wall's influence matrix for steps of
    /// `dt` at the current diffusion weight, built when the cache has none
    /// (or, on a deforming grid, only ones built on a grid that has since
    /// drifted, [`deforming::INFLUENCE_DRIFT`]). The cache keeps the
    /// [`INFLUENCE_CACHE`] latest, so a step that changes among a few
    /// values (`fwav`'s step control) builds each once.
    pub(super) fn influence_for(&mut self, dt: f64) -> Result<usize, NsError> {
        let wall_jac = &self.grid.jac[..2 * self.grid.nt];
        let deforming = self.deforming.is_some();
        self.influences
            .retain(|w| !(deforming && deforming::drifted(&w.wall_jac, wall_jac)));
        let weight = self.diffusion_weight;
        if let Some(i) = self
            .influences
            .iter()
            .position(|w| w.dt == dt && w.diffusion_weight == weight)
        {
            return Ok(i);
        }
        if self.influences.len() == INFLUENCE_CACHE {
            self.influences.remove(0);
        }
        let built = self.wall_influence(dt)?;
        self.influences.push(built);
        Ok(self.influences.len() - 1)
    }

    /// The wall's influence matrix for steps of `dt`: column `k` is Thom's
    /// wall vorticity of the step's response to a unit wall vorticity at
    /// node `k` by radial diffusion alone (the wall enters the step in
    /// the radial sweep, the last; homogeneous conditions, no explicit
    /// rate, no advection: the matrix depends on `dt` and the grid only);
    /// factored as `I - M`.
    ///
    /// The radial sweep's lines are independent, so one sweep with a unit
    /// wall vorticity on every line gives every column's vorticity at
    /// once, each on its own line; the streamfunction of a source on one
    /// line is a sum of the solver's turned responses to a unit source on
    /// each ring ([`crate::StreamSolver::wall_responses`], computed once per
    /// flow: the operator is the polar one for any section and any
    /// deformation), over the rings where the line's source is above
    /// rounding. Cost: one radial sweep and `N_θ²` products per ring the
    /// wall's diffusion reaches (4 ms on the default FWAV section, where
    /// a radial sweep and a streamfunction solve per column took 45 ms).
    fn wall_influence(&mut self, dt: f64) -> Result<WallInfluence, NsError> {
        let (nt, nr) = (self.grid.nt, self.grid.nr);
        let saved = (self.omega.clone(), self.psi.clone(), self.rate.clone());
        // The diffusion's matrix: no explicit rate, no advection.
        let n = self.grid.len();
        let radial_old = std::mem::replace(&mut self.radial_old, vec![0.0; n]);
        let radial_speed = std::mem::replace(&mut self.radial_speed, vec![0.0; n]);
        let ring_speed = std::mem::replace(&mut self.ring_speed, vec![0.0; n]);
        self.rate.fill(0.0);
        let ones = vec![1.0; nt];
        self.omega.fill(0.0);
        self.radial_crank_nicolson(dt, &ones);
        self.omega[..nt].copy_from_slice(&ones);
        let responses = match self.stream_responses.take() {
            Some(r) => r,
            None => self.stream.wall_responses(),
        };
        // The source J ω of every column, line by line.
        let source: Vec<f64> = self
            .grid
            .jac
            .iter()
            .zip(&self.omega)
            .map(|(j, w)| j * w)
            .collect();
        let inv_n = 1.0 / nt as f64;
        let mut matrix = nalgebra::DMatrix::<f64>::identity(nt, nt);
        let mut column = vec![0.0; nt];
        self.wall_shape.fill(0.0);
        self.wall_slope.fill(0.0);
        for k in 0..nt {
            let line = |j: usize| source[j * nt + k];
            let largest = (0..nr - 1).fold(0.0_f64, |m, j| m.max(line(j).abs()));
            self.psi[..2 * nt].fill(0.0);
            for j in (0..nr - 1).filter(|&j| line(j).abs() > 1e-17 * largest) {
                let s = line(j);
                for r in 0..2 {
                    let response = &responses[(2 * j + r) * nt..(2 * j + r + 1) * nt];
                    let ring = &mut self.psi[r * nt..(r + 1) * nt];
                    // Turned by k: node i answers response[i - k].
                    let (before, after) = ring.split_at_mut(k);
                    for (p, v) in after.iter_mut().zip(response) {
                        *p += s * v;
                    }
                    for (p, v) in before.iter_mut().zip(&response[nt - k..]) {
                        *p += s * v;
                    }
                }
            }
            // The fluid's circulation of the column (trapezoidal in `ξ`,
            // as `Self::circulation`).
            let circulation: f64 = (0..nr - 1)
                .map(|j| self.widths[j] * self.grid.d_theta * line(j))
                .sum();
            self.thom(true, &mut column);
            for (i, c) in column.iter().enumerate() {
                matrix[(i, k)] -= c;
            }
            // Thom's equations less their mean (the streamfunction's mean
            // no-slip row already holds it), plus Kelvin's: the step's
            // circulation (see `step`).
            let mean = (0..nt).map(|i| matrix[(i, k)]).sum::<f64>() * inv_n;
            for i in 0..nt {
                matrix[(i, k)] += circulation * inv_n - mean;
            }
        }
        self.stream_responses = Some(responses);
        let (omega, psi, rate) = saved;
        self.radial_old = radial_old;
        self.radial_speed = radial_speed;
        self.ring_speed = ring_speed;
        self.omega = omega;
        self.psi = psi;
        self.rate = rate;
        let lu = matrix.lu();
        if !lu.is_invertible() {
            return Err(NsError::SingularWall { dt });
        }
        Ok(WallInfluence {
            dt,
            diffusion_weight: self.diffusion_weight,
            wall_jac: self.grid.jac[..2 * nt].to_vec(),
            lu,
        })
    }
}

/// The factored `I - M` of the implicit wall vorticity (see
/// `Flow::wall_influence`), for one time step.
pub(super) struct WallInfluence {
    dt: f64,
    diffusion_weight: f64,
    /// `J` at the wall's two rings of the grid it was built on.
    wall_jac: Vec<f64>,
    lu: nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>,
}

impl WallInfluence {
    /// Solve `(I - M) x = b` in place.
    pub(super) fn solve(&self, b: &mut [f64]) {
        let rhs = nalgebra::DVector::from_column_slice(b);
        if let Some(x) = self.lu.solve(&rhs) {
            b.copy_from_slice(x.as_slice());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flow::{small_ellipse_flow, Extent};

    impl<M: Motion> Flow<M> {
        /// The influence matrix column by column, as defined: a radial
        /// sweep, a streamfunction solve and Thom's per unit wall vorticity
        /// (the construction `wall_influence` replaces), unfactored.
        fn influence_by_columns(&mut self, dt: f64) -> nalgebra::DMatrix<f64> {
            let nt = self.grid.nt;
            let n = self.grid.len();
            self.radial_old = vec![0.0; n];
            self.radial_speed = vec![0.0; n];
            self.ring_speed = vec![0.0; n];
            self.rate.fill(0.0);
            let mut matrix = nalgebra::DMatrix::<f64>::identity(nt, nt);
            let (mut unit, mut column) = (vec![0.0; nt], vec![0.0; nt]);
            for k in 0..nt {
                unit.fill(0.0);
                unit[k] = 1.0;
                self.omega.fill(0.0);
                self.radial_crank_nicolson(dt, &unit);
                self.omega[..nt].copy_from_slice(&unit);
                let circulation = self.circulation();
                self.solve_stream(0.0, true, Extent::Wall);
                self.thom(true, &mut column);
                for (i, c) in column.iter().enumerate() {
                    matrix[(i, k)] -= c;
                }
                let mean = (0..nt).map(|i| matrix[(i, k)]).sum::<f64>() / nt as f64;
                for i in 0..nt {
                    matrix[(i, k)] += (circulation - mean * nt as f64) / nt as f64;
                }
            }
            matrix
        }
    }

    /// The influence matrix built from the streamfunction's turned unit
    /// responses is the one built column by column, to rounding, on an
    /// ellipse at Re 200 (either diffusion weight).
    #[test]
    fn the_influence_matrix_from_turned_responses_is_the_column_by_column_one() {
        let mut flow = small_ellipse_flow(1.0 / 200.0);
        for weight in [1.0, 0.5] {
            flow.diffusion_weight = weight;
            let dt = 2e-3;
            let built = flow.wall_influence(dt).unwrap();
            let direct = flow.influence_by_columns(dt);
            let mut worst = 0.0_f64;
            for k in 0..flow.grid.nt {
                let mut b: Vec<f64> = direct.column(k).iter().copied().collect();
                built.solve(&mut b);
                for (i, v) in b.iter().enumerate() {
                    let expected = if i == k { 1.0 } else { 0.0 };
                    worst = worst.max((v - expected).abs());
                }
            }
            assert!(worst < 1e-10, "weight {weight}: {worst:e}");
        }
    }
}
