//! Laminar skin-friction estimate of a thin section, so net thrust can be
//! reported beside the inviscid thrust of the potential-flow solvers.
//!
//! Quasi-steady Blasius: each side of a flat plate in a laminar boundary
//! layer carries `D = 0.664 rho V^2 c / sqrt(Re_V)` (Schlichting, Boundary
//! Layer Theory, ch. 7), `Re_V = V c / nu`. With `V` the speed of the flow
//! relative to the section along its chord, on `1/2 rho U^2 c` and with
//! `Re = U c / nu`, both sides give `C_f = 2.656 |V/U|^(3/2) / sqrt(Re)`.
//! It ignores the unsteadiness of the boundary layer, the pressure
//! gradient, separation and transition: an estimate of the right size (the
//! paper's 3D analysis is viscous), not a validated viscous model.

/// Chordwise friction force coefficient (on `1/2 rho U^2 c`, both sides)
/// for a relative chordwise flow speed `tangential` (in units of `U`, signed:
/// the force follows the flow) at chord Reynolds number `reynolds`
/// (`U c / nu`, > 0).
pub fn laminar_friction(reynolds: f64, tangential: f64) -> f64 {
    2.656 * tangential.abs().powf(1.5) / reynolds.sqrt() * tangential.signum()
}

/// Streamwise friction drag (on `1/2 rho U^2 c`) of a section at pitch
/// `alpha` (rad) plunging at `h_dot` and surging downstream at `x_dot` (U):
/// the chordwise relative flow `(1 - x') cos alpha + h' sin alpha`
/// (freestream, surge and plunge; pitch moves the chord along itself only
/// at second order), its force along the chord `(cos alpha, -sin alpha)`.
pub fn streamwise_friction(reynolds: f64, alpha: f64, h_dot: f64, x_dot: f64) -> f64 {
    let (s, c) = alpha.sin_cos();
    laminar_friction(reynolds, (1.0 - x_dot) * c + h_dot * s) * c
}

/// [`streamwise_friction`] of a rigidly moving section at `times` (chords
/// travelled).
pub fn friction_history(motion: &super::motion::Motion, times: &[f64], reynolds: f64) -> Vec<f64> {
    times
        .iter()
        .map(|&t| {
            let (_, h_dot, alpha, _) = motion.at(t);
            streamwise_friction(reynolds, alpha, h_dot, 0.0)
        })
        .collect()
}

/// Chord Reynolds number of the built-in FWAV's wing root in flight: 3
/// m/s, 0.075 m chord, air at sea level (nu = 1.5e-5 m^2/s), 15,000 (the
/// issue's round figure; the aerodynamic discipline's mid-span section,
/// 0.06 m with the configuration's air, is at 12,329:
/// `SectionCase::fwav_mid_span`). Written as the number: the product in
/// floating point is 14999.999999999998, which `fwav aero2d --help`
/// printed as the default.
pub const FWAV_REYNOLDS: f64 = 15_000.0;

#[cfg(test)]
mod tests {
    use super::*;

    /// Blasius (Schlichting): a plate aligned with the flow at Re = 10^4
    /// has C_D = 1.328 / sqrt(Re) per side, 0.02656 for both.
    #[test]
    fn blasius_plate() {
        assert!((laminar_friction(1e4, 1.0) - 0.02656).abs() < 1e-12);
        // The force follows the relative flow and grows like V^1.5.
        assert!((laminar_friction(1e4, -4.0) + 8.0 * 0.02656).abs() < 1e-12);
    }
}
