//! The exact potential flow past a Kármán–Trefftz section, the analytic
//! reference of the panel method's steady validation
//! ([`super::aero2d::panel_karman_trefftz_lift`] and `tests/aero2d_panel.rs`).
//!
//! Independent of the panel method: a conformal map of the flow past a
//! circle (Milne-Thomson, *Theoretical Aerodynamics*, 1958, ch. 7; Katz &
//! Plotkin, *Low-Speed Aerodynamics*, 2nd ed., 2001, section 6.7 for the
//! Joukowski special case). Lengths in the body frame are chords (leading
//! edge at the origin, trailing edge at (1, 0)); angles in radians.

use std::f64::consts::PI;

/// Minimal complex arithmetic for the conformal map.
#[derive(Clone, Copy, Debug)]
struct C(f64, f64);

impl C {
    fn add(self, o: C) -> C {
        C(self.0 + o.0, self.1 + o.1)
    }
    fn sub(self, o: C) -> C {
        C(self.0 - o.0, self.1 - o.1)
    }
    fn mul(self, o: C) -> C {
        C(self.0 * o.0 - self.1 * o.1, self.0 * o.1 + self.1 * o.0)
    }
    fn div(self, o: C) -> C {
        let d = o.0 * o.0 + o.1 * o.1;
        C(
            (self.0 * o.0 + self.1 * o.1) / d,
            (self.1 * o.0 - self.0 * o.1) / d,
        )
    }
    fn scale(self, s: f64) -> C {
        C(self.0 * s, self.1 * s)
    }
    fn abs(self) -> f64 {
        self.0.hypot(self.1)
    }
    fn arg(self) -> f64 {
        self.1.atan2(self.0)
    }
    fn polar(r: f64, t: f64) -> C {
        C(r * t.cos(), r * t.sin())
    }
    /// Principal power.
    fn powf(self, n: f64) -> C {
        C::polar(self.abs().powf(n), n * self.arg())
    }
}

/// A Kármán–Trefftz section and its exact potential flow (conformal map of
/// the flow past a circle; Milne-Thomson, Theoretical Aerodynamics, 1958,
/// ch. 7; Katz & Plotkin 2001, section 6.7 for the Joukowski special case):
/// circle of centre `zeta_c = (-mx, my)` through `zeta = a`,
/// `z = n a [(zeta + a)^n + (zeta - a)^n] / [(zeta + a)^n - (zeta - a)^n]`,
/// `n = 2 - tau/pi` for a trailing-edge angle `tau` (n = 2: Joukowski).
/// In the circle plane the flow at angle `alpha'` with the clockwise
/// circulation `Gamma = 4 pi U R sin(alpha' + beta)` (Kutta: stagnation at
/// `zeta = a`, `beta = atan(my / (a + mx))`) has complex velocity
/// `W = U [e^(-i alpha') - R^2 e^(i alpha') / (zeta - zeta_c)^2] + i Gamma / (2 pi (zeta - zeta_c))`;
/// in the section plane `W / (dz/dzeta)`, with
/// `dz/dzeta = 4 n^2 a^2 w / ((1 - w)^2 (zeta^2 - a^2))`,
/// `w = ((zeta - a)/(zeta + a))^n`; `dz/dzeta -> 1` far away, so the lift
/// is `rho U Gamma` and `CL = 2 Gamma / (U c)`.
#[derive(Clone, Debug)]
pub struct KarmanTrefftz {
    a: f64,
    n: f64,
    centre: C,
    radius: f64,
    beta: f64,
    /// Leading edge (farthest point from the trailing edge), chord, and
    /// chord-line angle, in the section plane.
    le: C,
    chord: f64,
    chord_angle: f64,
}

impl KarmanTrefftz {
    /// The section of the circle through `zeta = a` centred at
    /// `(-mx, my)` (`mx` sets the thickness, `my` the camber, both in the
    /// units of `a`), with trailing-edge angle `tau` (radians).
    pub fn new(a: f64, tau: f64, mx: f64, my: f64) -> Self {
        let centre = C(-mx, my);
        let radius = (a + mx).hypot(my);
        let beta = my.atan2(a + mx);
        let mut s = Self {
            a,
            n: 2.0 - tau / PI,
            centre,
            radius,
            beta,
            le: C(0.0, 0.0),
            chord: 0.0,
            chord_angle: 0.0,
        };
        // Leading edge: the farthest point from the trailing edge (dense
        // sampling, then golden-section refinement).
        let te = s.z(-beta);
        let dist = |t: f64| s.z(t).sub(te).abs();
        let k = (0..3600)
            .max_by(|&i, &j| dist(i as f64 * PI / 1800.0).total_cmp(&dist(j as f64 * PI / 1800.0)))
            .unwrap_or(0);
        let (mut lo, mut hi) = (
            (k as f64 - 1.0) * PI / 1800.0,
            (k as f64 + 1.0) * PI / 1800.0,
        );
        let g = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..100 {
            let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
            if dist(x1) > dist(x2) {
                hi = x2;
            } else {
                lo = x1;
            }
        }
        s.le = s.z(0.5 * (lo + hi));
        s.chord = te.sub(s.le).abs();
        s.chord_angle = te.sub(s.le).arg();
        s
    }

    fn zeta(&self, theta: f64) -> C {
        self.centre.add(C::polar(self.radius, theta))
    }

    fn z(&self, theta: f64) -> C {
        let zeta = self.zeta(theta);
        let a = C(self.a, 0.0);
        let w = zeta.sub(a).div(zeta.add(a)).powf(self.n);
        C(1.0, 0.0)
            .add(w)
            .div(C(1.0, 0.0).sub(w))
            .scale(self.n * self.a)
    }

    /// The surface point at circle angle `theta` (radians) in the body
    /// frame: leading edge at 0, trailing edge at (1, 0), chords.
    pub fn body(&self, theta: f64) -> (f64, f64) {
        let p = self
            .z(theta)
            .sub(self.le)
            .mul(C::polar(1.0, -self.chord_angle))
            .scale(1.0 / self.chord);
        (p.0, p.1)
    }

    /// `panels + 1` points (body frame, chords) clockwise from the trailing
    /// edge (decreasing circle angle: the map keeps the sense of travel),
    /// at the circle angles of [`Self::theta`]; the last repeats the first.
    pub fn points(&self, panels: usize) -> Vec<(f64, f64)> {
        let mut p: Vec<(f64, f64)> = (0..=panels)
            .map(|j| self.body(self.theta(j as f64, panels)))
            .collect();
        p[panels] = p[0];
        p
    }

    /// Circle angle (radians) of point `j` of `panels`, `u = j / panels`:
    /// `u - 0.8 sin(4 pi u) / (4 pi)` of the way round from the trailing
    /// edge (clustered at both edges).
    pub fn theta(&self, j: f64, panels: usize) -> f64 {
        let u = j / panels as f64;
        -self.beta - 2.0 * PI * (u - 0.8 * (4.0 * PI * u).sin() / (4.0 * PI))
    }

    /// The circle angle of the surface point nearest `p` (body frame),
    /// between the circle angles `t0` and `t1` (golden section).
    pub fn nearest(&self, p: [f64; 2], t0: f64, t1: f64) -> f64 {
        let dist = |t: f64| {
            let q = self.body(t);
            (q.0 - p[0]).hypot(q.1 - p[1])
        };
        let (mut lo, mut hi) = (t0.min(t1), t0.max(t1));
        let g = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..80 {
            let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
            if dist(x1) < dist(x2) {
                hi = x2;
            } else {
                lo = x1;
            }
        }
        0.5 * (lo + hi)
    }

    /// Exact `(CL, Cp(theta))` at angle of attack `alpha` (radians) to the
    /// chord: the lift coefficient and the pressure coefficient as a
    /// function of the circle angle (see [`Self::theta`]).
    pub fn flow(&self, alpha: f64) -> (f64, impl Fn(f64) -> f64 + '_) {
        let alpha_z = alpha + self.chord_angle;
        let gamma = 4.0 * PI * self.radius * (alpha_z + self.beta).sin();
        let cl = 2.0 * gamma / self.chord;
        let cp = move |theta: f64| {
            let zeta = self.zeta(theta);
            let r = zeta.sub(self.centre);
            let a = C(self.a, 0.0);
            let w = zeta.sub(a).div(zeta.add(a)).powf(self.n);
            let one_minus = C(1.0, 0.0).sub(w);
            let dz = w
                .scale(4.0 * self.n * self.n * self.a * self.a)
                .div(one_minus.mul(one_minus).mul(zeta.mul(zeta).sub(a.mul(a))));
            let big_w = C::polar(1.0, -alpha_z)
                .sub(C::polar(self.radius * self.radius, alpha_z).div(r.mul(r)))
                .add(C(0.0, gamma / (2.0 * PI)).div(r));
            1.0 - (big_w.abs() / dz.abs()).powi(2)
        };
        (cl, cp)
    }
}
