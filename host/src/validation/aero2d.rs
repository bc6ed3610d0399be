//! Validation of the 2D unsteady aerodynamics ([`crate::aero2d`]): the
//! thin-plate discrete-vortex method (LDVM) against Garrick's plunge,
//! Wagner's indicial lift and the CFD of the LDVM paper's case 1; the
//! panel method against the exact Kármán–Trefftz flow, the NACA 0012 lift
//! slope and Garrick's plunge. Resolutions are those of
//! `tests/aero2d.rs` and `tests/aero2d_panel.rs`. Coefficients are per
//! unit span on the chord; times in chords travelled (`U t / c`).

use std::f64::consts::PI;
use std::sync::Arc;

use super::karman_trefftz::KarmanTrefftz;
use super::{missing, shared, ErrorKind, Memo, Solver, Spec, Validation, ValidationError};
use crate::aero2d::camber::CamberHistory;
use crate::aero2d::ldvm::{cycle_means, History, Ldvm, Motion, PitchRamp, Settings};
use crate::aero2d::naca::{Naca4, TrailingEdge};
use crate::aero2d::panel::{
    solve_steady, PanelSettings, PanelSolver, SectionShape, DEFAULT_PANELS,
};
use crate::aero2d::theory::wagner;

/// Theodorsen's function at k = 1, `C(1) = F + i G` as tabulated
/// (Theodorsen 1935, NACA Report 496; REFERENCES.md): F.
pub const THEODORSEN_F_K1: f64 = 0.5394;
/// Theodorsen's function at k = 1: G (see [`THEODORSEN_F_K1`]).
pub const THEODORSEN_G_K1: f64 = -0.1003;

/// Garrick's (1936, NACA Report 567) cycle-mean thrust coefficient of a
/// plate plunging `h = h0 c sin(omega t)` at k = 1,
/// `CT = 4 pi k^2 (h0/c)^2 (F^2 + G^2)` with the tabulated `C(1)`
/// ([`THEODORSEN_F_K1`], [`THEODORSEN_G_K1`]); `h0` in chords.
pub fn garrick_thrust_k1(h0: f64) -> f64 {
    let (f, g) = (THEODORSEN_F_K1, THEODORSEN_G_K1);
    4.0 * PI * h0 * h0 * (f * f + g * g)
}

/// Camber line of the SD7003 (max 1.46% at 35% chord), chords, at
/// x = 0, 0.05, ... 1, from the mean of the upper and lower surfaces of the
/// coordinates the LDVM paper used (`sd7003_fine.dat` beside its case
/// files; the section is Selig's, UIUC airfoil coordinates database).
pub const SD7003_CAMBER: [f64; 21] = [
    0.0, 0.00601, 0.00942, 0.01159, 0.01302, 0.01393, 0.01441, 0.01457, 0.01444, 0.01409, 0.01357,
    0.01291, 0.01215, 0.01131, 0.0104, 0.00939, 0.00824, 0.00688, 0.00524, 0.00311, 0.0,
];

/// The CFD lift of the LDVM paper's case 1 (Ramesh et al. 2014, J. Fluid
/// Mech. 751; CFL3D, `tests/data/ldvm_case1_cfd.dat`, where the source is
/// described): `(t, alpha in degrees, CL)`, `t` in chords travelled.
pub fn ldvm_case1_cfd() -> Result<Vec<(f64, f64, f64)>, ValidationError> {
    include_str!("../../tests/data/ldvm_case1_cfd.dat")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let v: Vec<f64> = l
                .split_whitespace()
                .map(str::parse)
                .collect::<Result<_, _>>()
                .map_err(|e| missing(format!("ldvm_case1_cfd.dat: {l:?}: {e}")))?;
            match v[..] {
                [t, alpha, cl, ..] => Ok((t, alpha, cl)),
                _ => Err(missing(format!(
                    "ldvm_case1_cfd.dat: {l:?}: 3 columns expected"
                ))),
            }
        })
        .collect()
}

/// The aero2d cases, in the order `fwav validate` runs them.
pub fn cases() -> Vec<Validation> {
    vec![
        ldvm_garrick_thrust(),
        ldvm_garrick_efficiency(),
        ldvm_wagner_s1(),
        ldvm_wagner_s5(),
        ldvm_case1_mean_lift(),
        ldvm_case1_peak_lift(),
        panel_karman_trefftz_lift(),
        panel_naca0012_lift_slope(),
        panel_garrick_thrust(),
    ]
}

/// LDVM, pure plunge h0 = 0.05 c at k = 1, 5 cycles, dt = 0.02: `(CT, CP,
/// efficiency)` over the last 2 cycles (as `tests/aero2d.rs`).
fn ldvm_garrick_run() -> Result<(f64, f64, f64), ValidationError> {
    static RUN: Memo<(f64, f64, f64)> = Memo::new();
    shared(&RUN, || {
        let k = 1.0;
        let period = PI / k;
        let settings = Settings {
            dt: 0.02,
            duration: 5.0 * period,
            ..Settings::default()
        };
        let history = Ldvm::new(Motion::plunge(k, 0.05), settings).run();
        Ok(cycle_means(&history, period, 2))
    })
}

/// LDVM flat plate plunging h0 = 0.05 c at k = 1: cycle-mean thrust
/// against Garrick (1936), within 10%.
pub fn ldvm_garrick_thrust() -> Validation {
    Validation {
        spec: Spec {
            name: "aero2d/ldvm-garrick-thrust",
            solver: Solver::Aero2d,
            reference: "Garrick (1936) NACA Rep. 567, CT = 4 pi k^2 (h0/c)^2 (F^2 + G^2), \
                        C(1) = 0.5394 - 0.1003i (Theodorsen 1935, NACA Rep. 496)",
            quantity: "cycle-mean CT, flat plate, plunge h0 = 0.05 c, k = 1",
            units: "1",
            error_kind: ErrorKind::Relative,
            tolerance: 0.10,
        },
        reference: || garrick_thrust_k1(0.05),
        compute: || Ok(ldvm_garrick_run()?.0.into()),
    }
}

/// The same run's propulsive efficiency against Garrick's
/// `(F^2 + G^2) / F` = 0.558 at k = 1 (REFERENCES.md), within 10%.
pub fn ldvm_garrick_efficiency() -> Validation {
    Validation {
        spec: Spec {
            name: "aero2d/ldvm-garrick-efficiency",
            solver: Solver::Aero2d,
            reference: "Garrick (1936) NACA Rep. 567, efficiency (F^2 + G^2) / F = 0.558 at k = 1",
            quantity: "propulsive efficiency CT/CP, flat plate, plunge h0 = 0.05 c, k = 1",
            units: "1",
            error_kind: ErrorKind::Relative,
            tolerance: 0.10,
        },
        reference: || 0.558,
        compute: || Ok(ldvm_garrick_run()?.2.into()),
    }
}

/// LDVM lift of a flat plate `s` semichords after a sudden start at 0.05
/// rad, over the steady thin-plate lift `2 pi sin(alpha)`, time step `dt`
/// (chords), the whole wake free.
pub fn ldvm_indicial_lift(dt: f64, s: f64) -> Result<f64, ValidationError> {
    let alpha = 0.05;
    let history = Ldvm::new(
        Motion::steady(alpha),
        Settings {
            dt,
            duration: s / 2.0 + 0.1,
            far_wake: 1e9,
            ..Settings::default()
        },
    )
    .run();
    let i = history
        .time
        .iter()
        .position(|&t| t >= s / 2.0 - 1e-9)
        .ok_or_else(|| missing(format!("the run ends before s = {s}")))?;
    Ok(history.cl[i] / (2.0 * PI * alpha.sin()))
}

const WAGNER_REFERENCE: &str = "Wagner (1925) indicial lift phi(s), exact \
     (Garrick's branch-cut integral, fwav::aero2d::theory::wagner; Jones' fit is 1.1% low at s = 1)";

/// Wagner's function 1 semichord after the start, dt = 0.01, within 3%
/// (measured +0.26%). Until 2026-12-07 this case ran at dt = 0.00125,
/// the step the nascent trailing-edge vortex needed while the LDVM's
/// loads converged as `sqrt(dt)` (+1.95% at it, +5.3% at 0.01); since the
/// edge placement (`fwav::aero2d::ldvm`, "The wake next to the edge"),
/// +0.32% at it (`tests/aero2d.rs`).
pub fn ldvm_wagner_s1() -> Validation {
    Validation {
        spec: Spec {
            name: "aero2d/ldvm-wagner-s1",
            solver: Solver::Aero2d,
            reference: WAGNER_REFERENCE,
            quantity: "CL / (2 pi sin alpha) at s = 1 semichord, sudden start, dt = 0.01",
            units: "1",
            error_kind: ErrorKind::Relative,
            tolerance: 0.03,
        },
        reference: || wagner(1.0),
        compute: || Ok(ldvm_indicial_lift(0.01, 1.0)?.into()),
    }
}

/// Wagner's function 5 semichords after the start, dt = 0.01, within 3%.
pub fn ldvm_wagner_s5() -> Validation {
    Validation {
        spec: Spec {
            name: "aero2d/ldvm-wagner-s5",
            solver: Solver::Aero2d,
            reference: WAGNER_REFERENCE,
            quantity: "CL / (2 pi sin alpha) at s = 5 semichords, sudden start, dt = 0.01",
            units: "1",
            error_kind: ErrorKind::Relative,
            tolerance: 0.03,
        },
        reference: || wagner(5.0),
        compute: || Ok(ldvm_indicial_lift(0.01, 5.0)?.into()),
    }
}

/// The LDVM paper's case 1 (Ramesh et al. 2014, J. Fluid Mech. 751): the
/// SD7003 camber line pitched 0 -> 25 deg about the leading edge by
/// Eldredge's ramp (K = 0.11, a = 11, from t = 1), to t = 4.1, default
/// resolution, leading-edge vortices shed beyond the critical LESP
/// `lesp_critical` (the paper's 0.18; `None`: attached flow).
pub fn ldvm_case1_run(lesp_critical: Option<f64>) -> Result<History, ValidationError> {
    let stations: Vec<f64> = (0..=20).map(|i| i as f64 / 20.0).collect();
    let camber = CamberHistory::steady(stations, SD7003_CAMBER.to_vec())?;
    let motion = Motion {
        pivot: 0.0,
        ..Motion::steady(0.0)
    };
    let ramp = PitchRamp {
        amplitude: 25f64.to_radians(),
        pitch_rate: 0.11,
        smoothing: 11.0,
        start: 1.0,
    };
    Ok(Ldvm::new(
        motion,
        Settings {
            duration: 4.1,
            lesp_critical,
            ..Settings::default()
        },
    )
    .with_camber(camber)
    .with_pitch_ramp(ramp)
    .run())
}

/// Mean of the values at times in `[from, to]`.
pub fn window_mean(time: &[f64], values: &[f64], from: f64, to: f64) -> f64 {
    let inside: Vec<f64> = time
        .iter()
        .zip(values)
        .filter(|(t, _)| (from..=to).contains(*t))
        .map(|(_, v)| *v)
        .collect();
    inside.iter().sum::<f64>() / inside.len() as f64
}

/// The peak over `t` in [1.5, 3] of the lift averaged over +-0.05 chords
/// travelled (the LDVM's step-to-step shedding noise).
pub fn smoothed_peak(history: &History) -> f64 {
    history
        .time
        .iter()
        .filter(|t| (1.5..=3.0).contains(*t))
        .map(|&t| window_mean(&history.time, &history.cl, t - 0.05, t + 0.05))
        .fold(f64::MIN, f64::max)
}

/// [`ldvm_case1_run`] with shedding at the paper's LESP 0.18, run once per
/// process (the case-1 validation cases share it).
pub fn ldvm_case1_shedding() -> Result<Arc<History>, ValidationError> {
    static RUN: Memo<Arc<History>> = Memo::new();
    shared(&RUN, || Ok(Arc::new(ldvm_case1_run(Some(0.18))?)))
}

const CASE1_REFERENCE: &str = "Ramesh et al. (2014) J. Fluid Mech. 751, case 1, CFL3D lift \
     (tests/data/ldvm_case1_cfd.dat)";

/// Case 1, mean lift over the shedding phase (t from 2, near the LEV
/// onset, to 4, the start of the return) against the CFD's mean over the
/// same window, within 15%.
pub fn ldvm_case1_mean_lift() -> Validation {
    Validation {
        spec: Spec {
            name: "aero2d/ldvm-case1-mean-lift",
            solver: Solver::Aero2d,
            reference: CASE1_REFERENCE,
            quantity: "mean CL over U t / c = 2..4, SD7003 pitch ramp 0-25 deg, LESP 0.18",
            units: "1",
            error_kind: ErrorKind::Relative,
            tolerance: 0.15,
        },
        reference: || {
            ldvm_case1_cfd().map_or(f64::NAN, |cfd| {
                let (t, cl): (Vec<f64>, Vec<f64>) = cfd.iter().map(|p| (p.0, p.2)).unzip();
                window_mean(&t, &cl, 2.0, 4.0)
            })
        },
        compute: || {
            let h = ldvm_case1_shedding()?;
            Ok(window_mean(&h.time, &h.cl, 2.0, 4.0).into())
        },
    }
}

/// Case 1, peak lift ([`smoothed_peak`]) against the CFD's peak, within
/// 15%.
pub fn ldvm_case1_peak_lift() -> Validation {
    Validation {
        spec: Spec {
            name: "aero2d/ldvm-case1-peak-lift",
            solver: Solver::Aero2d,
            reference: CASE1_REFERENCE,
            quantity: "peak CL (averaged over +-0.05 c), SD7003 pitch ramp 0-25 deg, LESP 0.18",
            units: "1",
            error_kind: ErrorKind::Relative,
            tolerance: 0.15,
        },
        reference: || {
            ldvm_case1_cfd().map_or(f64::NAN, |cfd| {
                cfd.iter().map(|p| p.2).fold(f64::MIN, f64::max)
            })
        },
        compute: || {
            let h = ldvm_case1_shedding()?;
            Ok(smoothed_peak(&h).into())
        },
    }
}

/// The cambered Kármán–Trefftz section of `tests/aero2d_panel.rs` (10 deg
/// trailing-edge angle, 11% thick, 1% camber).
pub fn karman_trefftz_section() -> KarmanTrefftz {
    KarmanTrefftz::new(0.25, 10f64.to_radians(), 0.02, 0.01)
}

/// Panel method, steady lift of the Kármán–Trefftz section at 5 deg on
/// the default 160 panels against its exact potential flow, within 1%.
pub fn panel_karman_trefftz_lift() -> Validation {
    Validation {
        spec: Spec {
            name: "aero2d/panel-karman-trefftz-lift",
            solver: Solver::Aero2d,
            reference: "exact conformal-map flow (Milne-Thomson 1958 ch. 7; Katz & Plotkin 2001 \
                        sec. 6.7), fwav::validation::karman_trefftz",
            quantity: "steady CL, Karman-Trefftz section 11% thick, 1% camber, alpha = 5 deg, \
                       160 panels",
            units: "1",
            error_kind: ErrorKind::Relative,
            tolerance: 0.01,
        },
        reference: || karman_trefftz_section().flow(5f64.to_radians()).0,
        compute: || {
            let section = karman_trefftz_section();
            let shape = SectionShape::new(&section.points(DEFAULT_PANELS))?;
            Ok(solve_steady(&shape, 5f64.to_radians()).cl.into())
        },
    }
}

/// A closed NACA 4-digit section of `panels` panels.
pub fn naca(designation: &str, panels: usize) -> Result<SectionShape, ValidationError> {
    let naca: Naca4 = designation.parse()?;
    Ok(SectionShape::new(
        &naca.points(panels, TrailingEdge::Closed)?,
    )?)
}

/// Panel method, NACA 0012 lift slope from the steady lift at 2 deg
/// (`CL / sin alpha`, 160 panels) within 2% of `2 pi (1 + 0.77 t/c)`.
pub fn panel_naca0012_lift_slope() -> Validation {
    Validation {
        spec: Spec {
            name: "aero2d/panel-naca0012-lift-slope",
            solver: Solver::Aero2d,
            reference: "2 pi (1 + 0.77 t/c), thin-airfoil slope with the Joukowski thickness \
                        factor (secondary; Abbott & von Doenhoff give 6.9-7.0 /rad)",
            quantity: "potential-flow lift slope CL / sin(alpha), NACA 0012, alpha = 2 deg",
            units: "1/rad",
            error_kind: ErrorKind::Relative,
            tolerance: 0.02,
        },
        reference: || 2.0 * PI * (1.0 + 0.77 * 0.12),
        compute: || {
            let alpha = 2f64.to_radians();
            let steady = solve_steady(&naca("0012", DEFAULT_PANELS)?, alpha);
            Ok((steady.cl / alpha.sin()).into())
        },
    }
}

/// Panel method, NACA 0006 plunging h0 = 0.05 c at k = 1 (4 cycles,
/// default settings, means over the last 2): thrust against Garrick,
/// within 10% (`tests/aero2d_panel.rs`).
pub fn panel_garrick_thrust() -> Validation {
    Validation {
        spec: Spec {
            name: "aero2d/panel-garrick-thrust",
            solver: Solver::Aero2d,
            reference: "Garrick (1936) NACA Rep. 567, CT = 4 pi k^2 (h0/c)^2 (F^2 + G^2), \
                        C(1) = 0.5394 - 0.1003i (Theodorsen 1935)",
            quantity: "cycle-mean CT, NACA 0006, plunge h0 = 0.05 c, k = 1",
            units: "1",
            error_kind: ErrorKind::Relative,
            tolerance: 0.10,
        },
        reference: || garrick_thrust_k1(0.05),
        compute: || {
            let period = PI;
            let settings = PanelSettings {
                duration: 4.0 * period,
                ..PanelSettings::default()
            };
            let history = PanelSolver::new(
                &naca("0006", DEFAULT_PANELS)?,
                Motion::plunge(1.0, 0.05),
                settings,
            )?
            .run();
            Ok(cycle_means(&history, period, 2).0.into())
        },
    }
}
