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
/// period before the last sample, for a periodicity check).
pub fn cycle_means_until(
    history: &History,
    period: f64,
    cycles: usize,
    end: f64,
) -> (f64, f64, f64) {
    let start = end - period * cycles as f64;
    let (mut ct, mut cp, mut n) = (0.0, 0.0, 0usize);
    for ((t, a), b) in history.time.iter().zip(&history.ct).zip(&history.cp) {
        if *t > start && *t <= end {
            ct += a;
            cp += b;
            n += 1;
        }
    }
    let n = n.max(1) as f64;
    (ct / n, cp / n, ct / cp)
}

/// Mean of `values` (sampled at `history.time`) over the `cycles` periods
/// ending at the last sample, e.g. of [`History::cd_friction`]; 0 for an
/// empty series.
pub fn cycle_mean_of(history: &History, values: &[f64], period: f64, cycles: usize) -> f64 {
    let end = *history.time.last().unwrap_or(&0.0);
    let start = end - period * cycles as f64;
    let window: Vec<f64> = history
        .time
        .iter()
        .zip(values)
        .filter(|(t, _)| **t > start && **t <= end)
        .map(|(_, v)| *v)
        .collect();
    if window.is_empty() {
        0.0
    } else {
        window.iter().sum::<f64>() / window.len() as f64
    }
}
