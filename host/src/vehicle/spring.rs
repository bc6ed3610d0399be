//! The spring about the flapping axis: a given stiffness, or tuned to
//! resonance at the flapping frequency, `k = J omega^2` with `J` the whole
//! inertia the drive moves at the flapping axis (the wing and the rotor
//! reflected through the gearbox, `J_wing + N^2 J_rotor`). At resonance
//! the spring's torque `k phi` cancels the inertial torque `J phi''` of a
//! harmonic stroke about the spring's neutral angle (`phi'' = -omega^2
//! (phi - phi_0)` with `phi_0 = 0`), so the motor is left with the
//! aerodynamic and friction torques and the spring's static torque at a
//! mean angle `k phi_0` (resonant flapping drives: Baek, Ma & Fearing,
//! "Efficient resonant drive of flapping-wing robots", IROS 2009; Campolo
//! et al., "Can DC motors directly drive flapping wings at high frequency
//! and large wing strokes?", IEEE/ASME Trans. Mechatronics, 2014).
//!
//! May import nothing of the crate.

use serde::Serialize;

/// The spring of the design file's `[actuator]` table.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Spring {
    /// A given stiffness, N m/rad (0: no spring).
    Fixed(f64),
    /// Tuned to resonance at the flapping frequency flown.
    Tuned,
}

/// `k = J (2 pi f)^2`, N m/rad, for the inertia `J` (kg m^2) at the
/// flapping axis and the frequency `f` (Hz).
pub fn tuned_stiffness(inertia_kg_m2: f64, frequency_hz: f64) -> f64 {
    let w = 2.0 * std::f64::consts::PI * frequency_hz;
    inertia_kg_m2 * w * w
}

impl Spring {
    /// Its stiffness for flapping at `frequency_hz` with the inertia
    /// `inertia_kg_m2` at the flapping axis, N m/rad.
    pub fn stiffness(&self, inertia_kg_m2: f64, frequency_hz: f64) -> f64 {
        match *self {
            Spring::Fixed(k) => k,
            Spring::Tuned => tuned_stiffness(inertia_kg_m2, frequency_hz),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `k = J w^2`: 1e-4 kg m^2 at 1/(2 pi) Hz is 1e-4 N m/rad; a fixed
    /// spring ignores the frequency.
    #[test]
    fn stiffness_is_j_omega_squared() {
        let f = 1.0 / (2.0 * std::f64::consts::PI);
        assert!((tuned_stiffness(1e-4, f) - 1e-4).abs() < 1e-18);
        assert!((Spring::Tuned.stiffness(2e-4, 3.0 * f) - 18e-4).abs() < 1e-15);
        assert_eq!(Spring::Fixed(0.2).stiffness(2e-4, 11.0), 0.2);
    }
}
