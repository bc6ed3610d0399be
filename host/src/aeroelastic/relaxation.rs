//! Aitken's dynamic relaxation of the fluid–structure interface iterate,
//! and the norms of interface fields it and the coupling's convergence test use.

use nalgebra::Vector3;

/// Aitken's dynamic relaxation of the interface iterate (Küttler & Wall
/// 2008, eq. 44).
pub(super) struct Aitken {
    /// The relaxation factor.
    pub(super) omega: f64,
    /// The displacement residual of the previous sub-iteration.
    pub(super) last_residual: Option<Vec<Vector3<f64>>>,
}

impl Aitken {
    /// Moves the iterate `u`, `v` towards the shell's answer by the
    /// relaxation factor updated with the displacement residual `r`
    /// (`v_new` the shell's velocities).
    pub(super) fn relax(
        &mut self,
        u: &mut [Vector3<f64>],
        v: &mut [Vector3<f64>],
        r: Vec<Vector3<f64>>,
        v_new: &[Vector3<f64>],
    ) {
        if let Some(previous) = &self.last_residual {
            let dr: Vec<Vector3<f64>> = r.iter().zip(previous).map(|(a, b)| a - b).collect();
            let denominator = dot(&dr, &dr);
            if denominator > 0.0 {
                self.omega = -self.omega * dot(previous, &dr) / denominator;
            }
        }
        self.omega = self.omega.clamp(-2.0, 2.0);
        let omega = self.omega;
        for (ui, ri) in u.iter_mut().zip(&r) {
            *ui += omega * ri;
        }
        for (vi, vn) in v.iter_mut().zip(v_new) {
            *vi += omega * (vn - *vi);
        }
        self.last_residual = Some(r);
    }
}

fn dot(a: &[Vector3<f64>], b: &[Vector3<f64>]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x.dot(y)).sum()
}

pub(super) fn norm(a: &[Vector3<f64>]) -> f64 {
    dot(a, a).sqrt()
}
