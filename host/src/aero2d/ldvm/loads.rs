//! The LDVM's loads of a step: the pressure jump's integrals over the
//! bound vortices (unsteady Bernoulli), the deforming camber line's share
//! of its rate term, the vorticity's impulse, and their record at the half
//! step.

use std::f64::consts::PI;

use super::{circulation, Chord, History, Kinematics, Ldvm};

/// The pressure-jump integrals of one step (c = U = rho = 1).
#[derive(Clone, Copy, Debug)]
pub(super) struct LoadIntegrals {
    /// sum V_t Gamma_j: the quasi-steady normal force.
    normal: f64,
    /// sum V_t Gamma_j x_j.
    moment: f64,
    /// Leading-edge suction pi A0^2.
    suction: f64,
    /// sum Gamma_j (1 - x_j), whose rate is the unsteady normal force.
    q_normal: f64,
    /// sum Gamma_j (1 - x_j^2) / 2, whose rate is the unsteady moment.
    q_moment: f64,
    /// Quasi-steady work rate against the camber motion, sum V_t Gamma_j eta_t,j.
    deform_quasi: f64,
    /// Quasi-steady chordwise force of the pressure on the sloped camber
    /// line, -sum V_t Gamma_j eta_x,j (positive towards the trailing edge).
    axial_quasi: f64,
}

/// The unsteady parts of the deforming camber line's loads at one step
/// (those of the pressure jump's rate term, station by station).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct CamberUnsteady {
    /// Work rate against the camber motion, int dPhi/dt eta_t dx.
    work: f64,
    /// Chordwise force, -int dPhi/dt eta_x dx.
    axial: f64,
}

impl Ldvm {
    /// Loads from the pressure jump (unsteady Bernoulli) on the bound
    /// vortices: N = sum V_t Gamma_j + d/dt sum Gamma_j (1 - x_j),
    /// M_LE = -(sum V_t Gamma_j x_j + d/dt sum Gamma_j (1 - x_j^2) / 2),
    /// plus the leading-edge suction pi A0^2 along the chord; the
    /// potential jump along the plate starts from `edge_jump`.
    pub(super) fn load_integrals(
        &self,
        a: &[f64],
        tangential: &[f64],
        chord: &Chord,
        edge_jump: f64,
    ) -> LoadIntegrals {
        let mut now = LoadIntegrals {
            normal: 0.0,
            moment: 0.0,
            suction: PI * a[0] * a[0],
            q_normal: edge_jump,
            q_moment: 0.5 * edge_jump,
            deform_quasi: 0.0,
            axial_quasi: 0.0,
        };
        for (j, (v, &(xb, _, _))) in self.bound.iter().zip(&chord.stations).enumerate() {
            let g = -v.gamma; // clockwise
            let vt = tangential[j];
            now.normal += vt * g;
            now.moment += vt * g * xb;
            now.q_normal += g * (1.0 - xb);
            now.q_moment += g * 0.5 * (1.0 - xb * xb);
            now.deform_quasi += vt * g * chord.slopes[j].1;
            now.axial_quasi -= vt * g * chord.slopes[j].0;
        }
        now
    }

    /// The unsteady pressure jump's share of the camber line's loads: per
    /// station the jump's rate times its width, dx_j dPhi_j/dt (Phi: running
    /// bound circulation to the station's centre, from `edge_jump` at the
    /// leading edge), against the camber rate (work) and slope (chordwise
    /// force). Keeps this step's running circulation for the next.
    pub(super) fn unsteady_camber(&mut self, edge_jump: f64) -> CamberUnsteady {
        let dt = self.settings.dt;
        let mut running = Vec::with_capacity(self.bound.len());
        let mut sum = edge_jump;
        for v in &self.bound {
            let g = -v.gamma;
            running.push(sum + 0.5 * g);
            sum += g;
        }
        let mut loads = CamberUnsteady::default();
        if self.running_previous.len() == running.len() {
            let dtheta = PI / self.theta.len() as f64;
            // The jump's rate is a backward difference, the rate at the
            // half step: the camber's slope and rate are taken there too,
            // as `record` takes the kinematics. At the step's end the
            // unsteady jump (large at high k, in quadrature with the
            // camber's rate) leaked into the mean deformation work through
            // an O(omega dt) phase error: a camber that is a rigid pitch
            // took 12 % more power than the pitch at k = 5, 113 % at k = 20.
            let half_step = self.time - 0.5 * dt;
            for ((p, q), th) in running.iter().zip(&self.running_previous).zip(&self.theta) {
                let (_, slope, rate) = self.shape(0.5 * (1.0 - th.cos()), half_step);
                let jump = 0.5 * th.sin() * dtheta * (p - q) / dt;
                loads.work += jump * rate;
                loads.axial -= jump * slope;
            }
        }
        self.running_previous = running;
        loads
    }

    /// The vertical impulse of all the vorticity, bound and free (ccw
    /// circulation times x; frame-independent since it sums to zero).
    pub(super) fn impulse(&self) -> f64 {
        self.bound
            .iter()
            .chain(&self.wake)
            .chain(&self.leading)
            .map(|v| v.gamma * v.x)
            .sum()
    }

    /// Records the loads of the half step between the load integrals
    /// `prev` and `now` in `history`, with the Glauert coefficients `a`
    /// of this step.
    pub(super) fn record(
        &self,
        history: &mut History,
        now: &LoadIntegrals,
        prev: &LoadIntegrals,
        a: &[f64],
        unsteady_camber: CamberUnsteady,
        impulse_now: f64,
    ) {
        let dt = self.settings.dt;
        let pivot = self.motion.pivot;
        // The backward differences are the loads at the half step: take
        // the kinematics there too, or the added-mass force (large at
        // high k, in quadrature with the velocity) leaks into the mean
        // power through an O(omega dt) phase error.
        let tm = self.time - 0.5 * dt;
        let Kinematics {
            x_dot: x_dot_m,
            h_dot: h_dot_m,
            alpha: alpha_m,
            alpha_dot: alpha_dot_m,
            ..
        } = self.kinematics(tm);
        let normal = 0.5 * (now.normal + prev.normal) + (now.q_normal - prev.q_normal) / dt;
        let moment_le = -(0.5 * (now.moment + prev.moment) + (now.q_moment - prev.q_moment) / dt);
        let suction = 0.5 * (now.suction + prev.suction);
        // The pressure on a sloped camber line pushes along the chord too
        // (Wu 1961, J. Fluid Mech. 10, the thrust of a flexible plate:
        // suction plus int dp eta_x dx): a twisted section's normal force
        // tilts forward. Without it a pitch written as camber would feel the
        // suction but not the normal force's drag (d'Alembert broken).
        let axial = 0.5 * (now.axial_quasi + prev.axial_quasi) + unsteady_camber.axial;
        let (sm, cm) = alpha_m.sin_cos();
        let fx = normal * sm - suction * cm + axial * cm;
        let fy = normal * cm + suction * sm - axial * sm;
        let m_pivot_nose_up = moment_le + pivot * normal;
        let deformation = 0.5 * (now.deform_quasi + prev.deform_quasi) + unsteady_camber.work;
        let power = -fx * x_dot_m - fy * h_dot_m - m_pivot_nose_up * alpha_dot_m - deformation;
        history.time.push(tm);
        history.cl.push(2.0 * fy);
        history.ct.push(-2.0 * fx);
        if let Some(re) = self.settings.reynolds {
            history
                .cd_friction
                .push(crate::aero2d::friction::streamwise_friction(
                    re, alpha_m, h_dot_m, x_dot_m,
                ));
        }
        history.cp.push(2.0 * power);
        history.lesp.push(a[0]);
        history
            .cl_impulse
            .push(2.0 * (impulse_now - self.impulse_prev) / dt);
        history.bound_circulation.push(circulation(a));
    }
}
