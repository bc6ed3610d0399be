//! Force histories and what is read from them.

use realfft::num_complex::Complex64;

/// A force-coefficient history `(t, CD + i CL)`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ForceHistory {
    samples: Vec<(f64, Complex64)>,
}

/// The statistics of a periodic wake.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WakeStatistics {
    /// Mean drag coefficient.
    pub drag: f64,
    /// Lift amplitude, half the peak-to-peak.
    pub lift_amplitude: f64,
    /// Mean lift coefficient (zero for a wake symmetric on average).
    pub lift_mean: f64,
    /// Shedding frequency times the reference length over the speed
    /// (from the lift's upward zero crossings).
    pub strouhal: f64,
    /// Shedding periods counted.
    pub periods: usize,
}

impl ForceHistory {
    /// Append a sample.
    pub fn push(&mut self, time: f64, coefficients: Complex64) {
        self.samples.push((time, coefficients));
    }

    /// The samples.
    #[must_use]
    pub fn samples(&self) -> &[(f64, Complex64)] {
        &self.samples
    }

    /// Statistics over whole shedding periods after `from`: the span
    /// between the first and the last upward zero crossing of the lift
    /// (NaN Strouhal number when fewer than two crossings).
    #[must_use]
    pub fn wake_statistics(&self, from: f64) -> WakeStatistics {
        let tail: Vec<&(f64, Complex64)> = self.samples.iter().filter(|s| s.0 >= from).collect();
        let mut crossings = Vec::new();
        for pair in tail.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            if a.1.im < 0.0 && b.1.im >= 0.0 {
                crossings.push(a.0 + (b.0 - a.0) * (-a.1.im) / (b.1.im - a.1.im));
            }
        }
        if crossings.len() < 2 {
            return WakeStatistics {
                drag: f64::NAN,
                lift_amplitude: f64::NAN,
                lift_mean: f64::NAN,
                strouhal: f64::NAN,
                periods: 0,
            };
        }
        let (start, end) = (crossings[0], crossings[crossings.len() - 1]);
        let periods = crossings.len() - 1;
        let whole: Vec<&&(f64, Complex64)> =
            tail.iter().filter(|s| s.0 >= start && s.0 <= end).collect();
        // Trapezoidal mean over the whole periods.
        let mut area = Complex64::new(0.0, 0.0);
        for pair in whole.windows(2) {
            area += 0.5 * (pair[0].1 + pair[1].1) * (pair[1].0 - pair[0].0);
        }
        let (high, low) = whole.iter().fold((f64::MIN, f64::MAX), |(h, l), s| {
            (h.max(s.1.im), l.min(s.1.im))
        });
        let span = whole[whole.len() - 1].0 - whole[0].0;
        WakeStatistics {
            drag: area.re / span,
            lift_amplitude: 0.5 * (high - low),
            lift_mean: area.im / span,
            strouhal: periods as f64 / (end - start),
            periods,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A made-up periodic history: CD = 1.3 + 0.01 cos(4πft), CL = 0.05 +
    /// 0.3 sin(2πft), f = 0.2: the statistics are read back.
    #[test]
    fn the_statistics_of_a_sine_are_its_parameters() {
        let mut h = ForceHistory::default();
        let f = 0.2;
        for n in 0..20_000 {
            let t = n as f64 * 0.005;
            let w = std::f64::consts::TAU * f * t;
            h.push(
                t,
                Complex64::new(1.3 + 0.01 * (2.0 * w).cos(), 0.05 + 0.3 * w.sin()),
            );
        }
        let s = h.wake_statistics(20.0);
        assert!((s.strouhal - f).abs() < 1e-6, "{s:?}");
        assert!((s.drag - 1.3).abs() < 1e-5, "{s:?}");
        assert!((s.lift_amplitude - 0.3).abs() < 1e-4, "{s:?}");
        assert!((s.lift_mean - 0.05).abs() < 1e-5, "{s:?}");
        assert_eq!(s.periods, 15);
    }
}
