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
//! - Wagner's indicial lift `phi(s)`, `s` in semichords travelled: exactly,
//!   as the inverse Laplace transform of `C(p)/p` (`C(p) = K1/(K0 + K1)`,
//!   Theodorsen's function continued to the Laplace variable), whose only
//!   singularity besides the pole at 0 is the branch cut along the negative
//!   axis. There `K_n(x e^(i pi)) = (-1)^n K_n(x) - i pi I_n(x)` and the
//!   Wronskian `I0 K1 + I1 K0 = 1/x` leave a real, exponentially damped
//!   integral (Garrick's form):
//!   `phi(s) = 1 - int_0^inf e^(-x s) / (x^2 [(K0 - K1)^2 + pi^2 (I0 + I1)^2]) dx`;
//!   and Jones' approximation `1 - 0.165 e^(-0.0455 s) - 0.335 e^(-0.3 s)`
//!   (REFERENCES.md), which is 1% low at s = 1.
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

/// Wagner's function at `s >= 0` semichords travelled, from the exact
/// branch-cut integral above (composite Simpson in `x = u^2`, 4000
/// intervals; accurate to about 1e-7 for s up to a few hundred). Cost:
/// 16 000 Bessel evaluations.
pub fn wagner(s: f64) -> f64 {
    use std::f64::consts::PI;
    // x = u^2 takes the x ln x behaviour at 0 out of the integrand; beyond
    // x = 40 it is below e^-80.
    let integrand = |u: f64| -> f64 {
        if u == 0.0 {
            return 0.0;
        }
        let x = u * u;
        let (k0, k1) = (puruspe::Kn(0, x), puruspe::Kn(1, x));
        let (i0, i1) = (puruspe::In(0, x), puruspe::In(1, x));
        let d = x * x * ((k0 - k1).powi(2) + PI * PI * (i0 + i1).powi(2));
        2.0 * u * (-x * s).exp() / d
    };
    let (n, top) = (4000, 40f64.sqrt());
    let h = top / n as f64;
    let mut sum = integrand(0.0) + integrand(top);
    for i in 1..n {
        sum += if i % 2 == 1 { 4.0 } else { 2.0 } * integrand(i as f64 * h);
    }
    1.0 - sum * h / 3.0
}

/// Jones' (1940) two-exponential approximation of Wagner's function
/// (REFERENCES.md), `s` in semichords.
pub fn wagner_jones(s: f64) -> f64 {
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

    /// The exact Wagner function: `phi(0) = 1/2` (half the steady lift at
    /// the start) and `phi -> 1`; at s = 1, 2, 5, 10 it equals the values
    /// computed independently from the Fourier form
    /// `phi(s) = 1/2 + 2/pi int_0^inf (F(k) - 1/2) sin(k s) / k dk`
    /// (mpmath `quadosc` with mpmath's own Bessel functions, 12 digits):
    /// 0.600606, 0.669290, 0.788203, 0.875045; and Jones' approximation
    /// stays within 1.1% of it.
    #[test]
    fn wagner_function_exact_and_jones() {
        assert!((wagner(0.0) - 0.5).abs() < 1e-6, "{}", wagner(0.0));
        // Rising towards 1 (the quadrature resolves s up to a few hundred).
        let samples: Vec<f64> = (0..=50).map(|s| wagner(s as f64)).collect();
        assert!(samples.windows(2).all(|w| w[1] > w[0]) && samples[50] < 1.0);
        assert!((samples[50] / wagner_jones(50.0) - 1.0).abs() < 0.01);
        for (s, reference) in [
            (1.0, 0.600_606),
            (2.0, 0.669_290),
            (5.0, 0.788_203),
            (10.0, 0.875_045),
        ] {
            assert!((wagner(s) - reference).abs() < 2e-6, "{s}: {}", wagner(s));
            assert!((wagner_jones(s) / wagner(s) - 1.0).abs() < 0.011);
        }
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
