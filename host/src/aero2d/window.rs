//! What a run without a period is read for: the loads over a window of
//! its history (a body at rest in a stream, a sudden start: `fwav aero2d
//! --duration`), their means and swings, and the frequency of the lift's
//! oscillation when it sheds (a cylinder's Kármán street: the Strouhal
//! number `f c / U`).

use super::history::History;

/// The loads over a window of a history.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WindowStatistics {
    /// The window, chords travelled.
    pub from: f64,
    /// Its end (the history's last sample).
    pub to: f64,
    /// Mean lift coefficient.
    pub cl_mean: f64,
    /// Half the lift's peak-to-peak swing.
    pub cl_swing: f64,
    /// Mean drag coefficient (the force downstream, `-CT`).
    pub cd_mean: f64,
    /// Half the drag's peak-to-peak swing.
    pub cd_swing: f64,
    /// Mean input power coefficient (zero for a section at rest).
    pub cp_mean: f64,
    /// The lift's oscillation, when it has one.
    pub shedding: Option<Shedding>,
}

/// A lift that oscillates about its mean.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shedding {
    /// Frequency times the chord over the speed, from the upward crossings
    /// of the window's mean lift.
    pub strouhal: f64,
    /// Whole periods between the first and the last crossing.
    pub periods: usize,
}

/// Fewest whole periods in the window for a shedding frequency.
pub const MIN_SHEDDING_PERIODS: usize = 2;

/// A lift whose swing is below this fraction of the mean loads
/// (`|CD| + |CL|`) is steady: its crossings of the mean are round-off.
pub const STEADY_SWING: f64 = 1e-3;

impl WindowStatistics {
    /// The statistics of `history` from `from` (chords travelled) to its
    /// last sample (trapezoidal means over the samples); `None` when fewer
    /// than two samples lie in the window. Cost: two passes over it.
    pub fn of(history: &History, from: f64) -> Option<Self> {
        let start = history.time.partition_point(|&t| t < from);
        let time = &history.time[start..];
        if time.len() < 2 {
            return None;
        }
        let span = time[time.len() - 1] - time[0];
        let mean = |values: &[f64]| -> f64 {
            let v = &values[start..];
            let area: f64 = time
                .windows(2)
                .zip(v.windows(2))
                .map(|(t, v)| 0.5 * (v[0] + v[1]) * (t[1] - t[0]))
                .sum();
            area / span
        };
        let swing = |values: &[f64]| -> f64 {
            let v = &values[start..];
            let high = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let low = v.iter().copied().fold(f64::INFINITY, f64::min);
            0.5 * (high - low)
        };
        let (cl_mean, cd_mean) = (mean(&history.cl), -mean(&history.ct));
        let cl_swing = swing(&history.cl);
        let oscillates = cl_swing > STEADY_SWING * (cd_mean.abs() + cl_mean.abs());
        let shedding = if oscillates {
            shedding(time, &history.cl[start..], cl_mean)
        } else {
            None
        };
        Some(Self {
            from: time[0],
            to: time[time.len() - 1],
            cl_mean,
            cl_swing,
            cd_mean,
            cd_swing: swing(&history.ct),
            cp_mean: mean(&history.cp),
            shedding,
        })
    }
}

/// The lift's frequency from its upward crossings of `mean` (linear
/// between samples), when they span [`MIN_SHEDDING_PERIODS`] or more.
fn shedding(time: &[f64], cl: &[f64], mean: f64) -> Option<Shedding> {
    let crossings: Vec<f64> = time
        .windows(2)
        .zip(cl.windows(2))
        .filter(|(_, c)| c[0] < mean && c[1] >= mean)
        .map(|(t, c)| t[0] + (t[1] - t[0]) * (mean - c[0]) / (c[1] - c[0]))
        .collect();
    let periods = crossings.len().checked_sub(1)?;
    if periods < MIN_SHEDDING_PERIODS {
        return None;
    }
    let span = crossings[periods] - crossings[0];
    Some(Shedding {
        strouhal: periods as f64 / span,
        periods,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A history of `CL = 0.1 + 0.3 sin(2π f t)`, `CD = 1.3 + 0.01 cos(4π
    /// f t)`, no power, sampled every 0.01 to `end`.
    fn shedding_history(f: f64, end: f64) -> History {
        let mut h = History::default();
        let n = (end / 0.01).round() as usize;
        for i in 0..=n {
            let t = i as f64 * 0.01;
            let w = std::f64::consts::TAU * f * t;
            h.time.push(t);
            h.cl.push(0.1 + 0.3 * w.sin());
            h.ct.push(-(1.3 + 0.01 * (2.0 * w).cos()));
            h.cp.push(0.0);
        }
        h
    }

    /// The parameters of a made-up shedding history are read back: its
    /// frequency (Strouhal number 0.2 on a unit chord and speed), mean
    /// lift and drag over whole periods, and the swings.
    #[test]
    fn a_sine_lift_is_read_back() {
        // Ten whole periods, from 50.5 to 100.5; upward crossings of the
        // mean at 55, 60, ..., 100.
        let s = WindowStatistics::of(&shedding_history(0.2, 100.5), 50.5).unwrap();
        let shed = s.shedding.unwrap();
        assert!((shed.strouhal - 0.2).abs() < 1e-6, "{s:?}");
        assert_eq!(shed.periods, 9);
        assert!(
            (s.cl_mean - 0.1).abs() < 1e-6 && (s.cd_mean - 1.3).abs() < 1e-6,
            "{s:?}"
        );
        assert!((s.cl_swing - 0.3).abs() < 1e-4 && (s.cd_swing - 0.01).abs() < 1e-6);
        assert!((s.from - 50.5).abs() < 1e-9 && (s.to - 100.5).abs() < 1e-9);
        assert_eq!(s.cp_mean, 0.0);
    }

    /// A steady lift with round-off noise has no shedding frequency, nor
    /// has a window of less than two periods; a window without two
    /// samples has no statistics.
    #[test]
    fn no_frequency_without_oscillation() {
        let mut steady = shedding_history(0.2, 20.0);
        for (i, c) in steady.cl.iter_mut().enumerate() {
            *c = 0.5 + 1e-12 * if i % 2 == 0 { 1.0 } else { -1.0 };
        }
        assert_eq!(WindowStatistics::of(&steady, 10.0).unwrap().shedding, None);
        let short = shedding_history(0.2, 12.0);
        assert_eq!(WindowStatistics::of(&short, 4.0).unwrap().shedding, None);
        assert_eq!(WindowStatistics::of(&short, 12.0), None);
    }
}
