//! Classical unsteady thin-airfoil results, used as validation references.
//!
//! - Theodorsen's function `C(k) = H1(k) / (H1(k) + i H0(k)) = F + i G`
//!   (Hankel functions of the second kind; `k = omega b / U`, `b` the
//!   semichord), written with real Bessel functions:
//!   `F = (J1 (J1 + Y0) + Y1 (Y1 - J0)) / D`, `G = -(Y1 Y0 + J1 J0) / D`,
//!   `D = (J1 + Y0)^2 + (Y1 - J0)^2`.
//! - Garrick (1936), pure plunge `h = h0 sin(omega t)`:
//!   `C_T = 4 pi k^2 (h0/c)^2 (F^2 + G^2)`, `C_P = 4 pi k^2 (h0/c)^2 F`,
//!   efficiency `(F^2 + G^2) / F`.
//! - Wagner's indicial lift, Jones' approximation
//!   `phi(s) = 1 - 0.165 e^(-0.0455 s) - 0.335 e^(-0.3 s)`, `s` in semichords.
//!
//! (Formulas as collected in ../shared/REFERENCES.md; Bessel functions from
//! the `puruspe` crate.)

/// Theodorsen's function at reduced frequency `k` (> 0): `(F, G)`.
pub fn theodorsen(k: f64) -> (f64, f64) {
    let (j0, j1) = (puruspe::Jn(0, k), puruspe::Jn(1, k));
    let (y0, y1) = (puruspe::Yn(0, k), puruspe::Yn(1, k));
    let a = j1 + y0;
    let b = y1 - j0;
    let d = a * a + b * b;
    ((j1 * a + y1 * b) / d, -(y1 * y0 + j1 * j0) / d)
}

/// Garrick's cycle-mean thrust and input-power coefficients and the
/// propulsive efficiency of a flat plate plunging with amplitude `h0` (in
/// chords) at reduced frequency `k = omega c / (2 U)`.
pub fn garrick_plunge(k: f64, h0: f64) -> (f64, f64, f64) {
    let (f, g) = theodorsen(k);
    let scale = 4.0 * std::f64::consts::PI * k * k * h0 * h0;
    (scale * (f * f + g * g), scale * f, (f * f + g * g) / f)
}

/// Wagner's function (Jones' approximation) at `s` semichords travelled.
pub fn wagner(s: f64) -> f64 {
    1.0 - 0.165 * (-0.0455 * s).exp() - 0.335 * (-0.3 * s).exp()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// REFERENCES.md: k = 1 gives F = 0.5394, G = -0.1003, efficiency 0.558.
    #[test]
    fn theodorsen_at_k_1_matches_the_tabulated_value() {
        let (f, g) = theodorsen(1.0);
        assert!(
            (f - 0.5394).abs() < 5e-4 && (g + 0.1003).abs() < 5e-4,
            "{f} {g}"
        );
        let (_, _, eta) = garrick_plunge(1.0, 0.05);
        assert!((eta - 0.558).abs() < 1e-3, "{eta}");
    }

    /// Limits: C(k) -> 1 as k -> 0 and 1/2 as k -> infinity, so the
    /// efficiency tends to 1 and 1/2 (REFERENCES.md).
    #[test]
    fn theodorsen_limits() {
        let (f, g) = theodorsen(1e-4);
        assert!((f - 1.0).abs() < 1e-2 && g.abs() < 1e-2, "{f} {g}");
        let (f, g) = theodorsen(200.0);
        assert!((f - 0.5).abs() < 1e-3 && g.abs() < 1e-2, "{f} {g}");
    }
}
