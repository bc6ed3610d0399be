//! What a 2D run reports: the time histories of the loads and their
//! cycle means.

/// Time histories of a run (coefficients on `1/2 rho U^2 c`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct History {
    /// Time, chords travelled.
    pub time: Vec<f64>,
    /// Lift coefficient (force up).
    pub cl: Vec<f64>,
    /// Thrust coefficient (force upstream).
    pub ct: Vec<f64>,
    /// Input power coefficient (on `1/2 rho U^3 c`).
    pub cp: Vec<f64>,
    /// Leading-edge suction parameter A0.
    pub lesp: Vec<f64>,
    /// Bound circulation (clockwise positive), U c.
    pub bound_circulation: Vec<f64>,
    /// Lift coefficient from the rate of the vortex impulse of all the
    /// vorticity, `L = rho d/dt sum Gamma_k x_k` (ccw circulation; Saffman,
    /// Vortex Dynamics, 1992, ch. 3): independent of the pressure
    /// integration, a check of it (they differ by the time discretization
    /// of vortex motion only).
    pub cl_impulse: Vec<f64>,
    /// Streamwise drag coefficient of the laminar skin-friction estimate
    /// (empty without a Reynolds number): net thrust is `ct - cd_friction`.
    pub cd_friction: Vec<f64>,
}

/// Cycle means over the last `cycles` whole periods of a periodic history:
/// `(CT, CP, efficiency)`.
pub fn cycle_means(history: &History, period: f64, cycles: usize) -> (f64, f64, f64) {
    cycle_means_until(
        history,
        period,
        cycles,
        *history.time.last().unwrap_or(&0.0),
    )
}

/// [`cycle_means`] over the `cycles` periods ending at time `end` (e.g. one
/// period before the last sample, for a periodicity check): the samples
/// of [`window`].
pub fn cycle_means_until(
    history: &History,
    period: f64,
    cycles: usize,
    end: f64,
) -> (f64, f64, f64) {
    let samples = window(history, period, cycles, end);
    let n = samples.len().max(1) as f64;
    let ct = history.ct[samples.clone()].iter().sum::<f64>() / n;
    let cp = history.cp[samples].iter().sum::<f64>() / n;
    (ct, cp, ct / cp)
}

/// Mean of `values` (sampled at `history.time`) over the `cycles` periods
/// ending at the last sample ([`window`]), e.g. of
/// [`History::cd_friction`]; 0 for an empty series.
pub fn cycle_mean_of(history: &History, values: &[f64], period: f64, cycles: usize) -> f64 {
    let end = *history.time.last().unwrap_or(&0.0);
    let samples = window(history, period, cycles, end);
    let kept = samples.start.min(values.len())..samples.end.min(values.len());
    if kept.is_empty() {
        0.0
    } else {
        values[kept.clone()].iter().sum::<f64>() / kept.len() as f64
    }
}

/// The indices of the samples of `history` (uniformly sampled, times
/// ascending) in the `cycles` periods ending at `end`:
/// `(end - cycles·period, end]`, both bounds moved half a sampling
/// interval later.
///
/// A window of whole periods of a flow sampled `period / 200` apart (the
/// Navier–Stokes model) starts where a sample of the same phase as its
/// last one lies. Compared as computed, that sample fell inside or
/// outside by rounding, so a two-period window held 400 or 401 samples
/// (the same phase counted twice) and a one-period one 199 or 200, about
/// half the time each; the LDVM's windows (its steps' midpoints, 0.015
/// chords apart: 606.06 in two periods at 11 Hz) held their length
/// rounded up (607), one more than the nearest count whenever its
/// fraction is under a half (until 2026-12-05). With the bounds half
/// a sample later, a rounding error smaller than that picks no other
/// sample, and the window holds the whole number of samples nearest
/// `cycles · period / interval`. Cost: two binary searches.
pub fn window(history: &History, period: f64, cycles: usize, end: f64) -> std::ops::Range<usize> {
    let time = &history.time;
    let half = match time.len() {
        0 | 1 => 0.0,
        n => 0.5 * (time[n - 1] - time[0]) / (n - 1) as f64,
    };
    let start = end - period * cycles as f64;
    let first = time.partition_point(|t| *t <= start + half);
    let last = time.partition_point(|t| *t <= end + half);
    first..last.max(first)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A history sampled at `times`, its CT the sample's index and its CP 1.
    fn indexed(times: Vec<f64>) -> History {
        let n = times.len();
        History {
            time: times,
            ct: (0..n).map(|i| i as f64).collect(),
            cp: vec![1.0; n],
            ..History::default()
        }
    }

    /// The reduced frequencies of the checks: 150 from 0.1 to 2.1, with
    /// no pattern a rounding could share.
    fn frequencies() -> impl Iterator<Item = f64> {
        (0..150).map(|i| 0.1 + 0.013_37 * f64::from(i))
    }

    /// A Navier–Stokes run's samples, as `aero2d::viscous` takes them:
    /// every `period / 200` from the first interval, the time added up
    /// sample by sample, over four periods. Each window of whole periods
    /// must hold 200 samples a period, none of them twice: counted, as
    /// the samples' indices are consecutive. Before the half-sample bounds,
    /// about half of these frequencies gave 401 in the last two periods.
    #[test]
    fn a_window_of_whole_periods_holds_their_samples_once() {
        for k in frequencies() {
            let period = std::f64::consts::PI / k;
            let interval = period / 200.0;
            let (mut times, mut next) = (Vec::new(), interval);
            while next <= 4.0 * period + 1e-9 * interval {
                times.push(next);
                next += interval;
            }
            let history = indexed(times);
            assert_eq!(history.time.len(), 800, "k {k}");
            assert_eq!(window(&history, period, 2, 4.0 * period), 400..800, "k {k}");
            let last = *history.time.last().unwrap();
            assert_eq!(window(&history, period, 2, last), 400..800, "k {k}");
            assert_eq!(
                window(&history, period, 1, last - period),
                400..600,
                "k {k}"
            );
            for stroke in 0..4 {
                let end = (stroke + 1) as f64 * period;
                let range = window(&history, period, 1, end);
                assert_eq!(range, 200 * stroke..200 * (stroke + 1), "k {k}");
            }
            // The mean of the indices 400..800 is 599.5.
            let (ct, cp, _) = cycle_means(&history, period, 2);
            assert_eq!((ct, cp), (599.5, 1.0), "k {k}");
        }
    }

    /// The LDVM's samples, at its steps' midpoints `(n - 1/2) dt`, with
    /// 400 steps a period over three: the last two periods hold 800.
    #[test]
    fn a_window_of_step_midpoints_holds_their_samples_once() {
        for k in frequencies() {
            let period = std::f64::consts::PI / k;
            let dt = period / 400.0;
            let history = indexed((1..=1200).map(|n| (n as f64 - 0.5) * dt).collect());
            assert_eq!(
                cycle_mean_of(&history, &history.ct, period, 2),
                799.5,
                "k {k}"
            );
            assert_eq!(cycle_mean_of(&history, &[], period, 2), 0.0);
        }
    }

    /// The LDVM's samples as the discipline takes them: a step of 0.015
    /// chords, which no period is a multiple of, over four periods. The
    /// last two hold the whole number of samples nearest their length
    /// (606 at 11 Hz, k = 0.691, where the bounds of before took 607).
    #[test]
    fn a_window_of_fractional_periods_holds_the_nearest_count() {
        let dt = 0.015;
        for k in frequencies() {
            let period = std::f64::consts::PI / k;
            let steps = (4.0 * period / dt).floor() as usize;
            let history = indexed((1..=steps).map(|n| (n as f64 - 0.5) * dt).collect());
            let last = *history.time.last().unwrap();
            let range = window(&history, period, 2, last);
            assert_eq!(range.end, steps, "k {k}");
            assert_eq!(range.len(), (2.0 * period / dt).round() as usize, "k {k}");
        }
    }

    /// An empty history has an empty window, and its means are zero.
    #[test]
    fn an_empty_history_has_no_samples_in_its_window() {
        let empty = History::default();
        assert_eq!(window(&empty, 1.0, 2, 0.0), 0..0);
        assert_eq!(cycle_mean_of(&empty, &empty.ct, 1.0, 2), 0.0);
        let (ct, cp, _) = cycle_means(&empty, 1.0, 2);
        assert_eq!((ct, cp), (0.0, 0.0));
    }
}
