//! Validation of the unsteady vortex-lattice method ([`crate::uvlm`]):
//! the sudden start of a rectangular wing against Katz & Plotkin's own
//! Program 16, and a heaving plate of large aspect ratio against Garrick's
//! thrust. Lattices and steps are those of `tests/integration/uvlm.rs`. Lengths in
//! chords, the freestream along +x; coefficients on the (semi-span) wing
//! area.

use nalgebra::Vector3;
use std::f64::consts::PI;

use super::aero2d::garrick_thrust_k1;
use super::{missing, ErrorKind, Measured, Solver, Spec, Validation, ValidationError};
use crate::uvlm::{Lattice, PotentialRate, TimeDerivative, Uvlm, UvlmSettings};

/// Katz & Plotkin's Program 16 output for aspect ratio `ar` (4 or 8;
/// `tests/data/katz_plotkin_sudden_start_ar*.dat`, where the source is
/// described): `CL` per step (step 1 at t = 0) and the steady `CL` of the
/// same program (its mode 1, U dt = 10 c, 5 steps).
pub fn katz_plotkin(ar: u32) -> Result<(Vec<f64>, f64), ValidationError> {
    let text = match ar {
        4 => include_str!("../../tests/data/katz_plotkin_sudden_start_ar4.dat"),
        8 => include_str!("../../tests/data/katz_plotkin_sudden_start_ar8.dat"),
        _ => return Err(missing(format!("no Program 16 data for aspect ratio {ar}"))),
    };
    let bad = |what: &str| missing(format!("katz_plotkin_sudden_start_ar{ar}.dat: {what}"));
    // "Steady-state CL from the same program's mode 1\n# (dt = 10
    // chords, 5 steps): 0.3218"
    let steady = text
        .split_once("Steady-state CL")
        .and_then(|(_, rest)| rest.split_once(':'))
        .and_then(|(_, rest)| rest.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .ok_or_else(|| bad("no steady CL in the header"))?;
    let cl = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            l.split_whitespace()
                .nth(2)
                .and_then(|v| v.parse().ok())
                .ok_or_else(|| bad(&format!("{l:?}: no CL in the third column")))
        })
        .collect::<Result<_, _>>()?;
    Ok((cl, steady))
}

/// CL per step (total force `z` and normal-pressure force `z`, on the
/// semi-span area) of Program 16's case: flat rectangular wing, chord 1,
/// alpha = 5 deg, 4 x 13 rings on the semi-span `semi_span` (chords) with
/// the mirror image, `U dt = dt_chords c`, the youngest `free_rows` wake
/// rows free, the shed vortex 0.3 U dt behind the trailing edge, `dΦ/dt`
/// from the mean of neighbouring rings by a first-order difference, no
/// core (the program's cut-off only).
pub fn sudden_start(
    semi_span: f64,
    steps: usize,
    dt_chords: f64,
    free_rows: usize,
) -> Result<Vec<(f64, f64)>, ValidationError> {
    let (u, chord) = (10.0, 1.0);
    let wing = Lattice::rectangle(chord, semi_span, 4, 13, 5f64.to_radians())?;
    let mut settings = UvlmSettings::new(dt_chords * chord / u, 1.0, Vector3::new(u, 0.0, 0.0));
    settings.symmetric = true;
    settings.free_wake_rows = free_rows;
    settings.core_radius = 0.0;
    settings.shed_offset = 0.3;
    settings.potential_rate = PotentialRate::NeighbourMean;
    settings.time_derivative = TimeDerivative::FirstOrder;
    let mut uvlm = Uvlm::new(4, 13, settings)?;
    let at_rest = vec![Vector3::zeros(); wing.corner_count()];
    let q_area = 0.5 * u * u * chord * semi_span;
    (0..steps)
        .map(|_| {
            let solution = uvlm.solve(&wing, &at_rest)?;
            uvlm.advance(&wing, &solution)?;
            let normal: f64 = solution.panel_force.iter().map(|f| f.z).sum();
            Ok((solution.force.z / q_area, normal / q_area))
        })
        .collect()
}

/// The uvlm cases, in the order `fwav validate` runs them.
pub fn cases() -> Vec<Validation> {
    vec![
        katz_plotkin_sudden_start(),
        katz_plotkin_steady(),
        garrick_heave_thrust(),
    ]
}

/// Katz & Plotkin (2001), *Low-Speed Aerodynamics*, 2nd ed., §13.12, Fig.
/// 13.34: the sudden start of an aspect-ratio-4 wing (alpha = 5 deg, U dt
/// / c = 1/16, 160 steps) against their Program 16's output with the same
/// discretization: the largest relative CL deviation over steps 2-160
/// (step 1 is the added-mass spike, in the note), at most 3%.
pub fn katz_plotkin_sudden_start() -> Validation {
    Validation {
        spec: Spec {
            name: "uvlm/katz-plotkin-sudden-start",
            solver: Solver::Uvlm,
            reference: "Katz & Plotkin (2001) Low-Speed Aerodynamics 2nd ed. sec. 13.12 \
                        Fig. 13.34, Program 16 output (tests/data/katz_plotkin_sudden_start_ar4.dat)",
            quantity: "largest relative CL deviation from Program 16 over steps 2-160, AR 4, \
                       alpha = 5 deg, 4 x 13 rings, U dt / c = 1/16",
            units: "1",
            error_kind: ErrorKind::Absolute,
            tolerance: 0.03,
        },
        reference: || 0.0,
        compute: || {
            let (reference, _) = katz_plotkin(4)?;
            let cl = sudden_start(2.0, reference.len(), 1.0 / 16.0, 5)?;
            let (step, worst) = (1..cl.len().min(reference.len()))
                .map(|s| (s + 1, cl[s].0 / reference[s] - 1.0))
                .fold((0, 0.0f64), |a, b| if b.1.abs() > a.1.abs() { b } else { a });
            let last = cl.len() - 1;
            Ok(Measured {
                value: worst,
                note: Some(format!(
                    "at step {step}; step 1 (spike) CL {:.4} vs {:.4}; step {} CL {:.4} vs {:.4}",
                    cl[0].0,
                    reference[0],
                    last + 1,
                    cl[last].0,
                    reference[last]
                )),
            })
        },
    }
}

/// The same wing's steady CL (a long frozen wake: U dt = 10 c, 5 steps,
/// Program 16's steady mode) against the program's steady value, within
/// 2%.
pub fn katz_plotkin_steady() -> Validation {
    Validation {
        spec: Spec {
            name: "uvlm/katz-plotkin-steady",
            solver: Solver::Uvlm,
            reference: "Katz & Plotkin (2001) Program 16 steady mode (U dt = 10 c, 5 steps), \
                        AR 4: CL 0.3218",
            quantity: "steady CL, AR 4 flat wing, alpha = 5 deg, frozen wake, 4 x 13 rings",
            units: "1",
            error_kind: ErrorKind::Relative,
            tolerance: 0.02,
        },
        reference: || katz_plotkin(4).map_or(f64::NAN, |(_, steady)| steady),
        compute: || {
            let cl = sudden_start(2.0, 5, 10.0, 0)?;
            cl.last()
                .map(|c| c.0.into())
                .ok_or_else(|| missing("no steps"))
        },
    }
}

/// Cycle means and first harmonics of a heaving plate (see [`heave`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Heave {
    /// Thrust coefficient `-F_x / (q c b)`, last cycle.
    pub ct: f64,
    /// The same over the cycle before the last.
    pub ct_before: f64,
    /// Power coefficient `P / (q U c b)`, last cycle.
    pub cp: f64,
    /// Lift coefficient `F_z / (q c b)` = `cl_sin` sin(ωt) + `cl_cos`
    /// cos(ωt) + ..., last cycle.
    pub cl_sin: f64,
    /// See `cl_sin`.
    pub cl_cos: f64,
    /// Peak |CL| over the last cycle.
    pub cl_peak: f64,
}

/// A rigid flat rectangular plate of chord 1 heaving `h = h0 c sin(ωt)` in
/// a unit stream, `k = ωc / (2U)`: `nc x ns` panels on the semi-span
/// `semi_span` (chords) with the mirror image, spanwise stations clustered
/// towards the tip (`y = b sin(π/2 j/ns)`), `steps_per_chord` steps per
/// chord travelled, `cycles` cycles from an impulsive start; default
/// settings otherwise (second-order `dΦ/dt`, mean of neighbouring rings)
/// with the wake options `(free_wake_rows, wake_rows)`.
#[allow(clippy::too_many_arguments)]
pub fn heave(
    k: f64,
    h0: f64,
    nc: usize,
    ns: usize,
    semi_span: f64,
    steps_per_chord: usize,
    cycles: usize,
    wake: (usize, usize),
) -> Result<Heave, ValidationError> {
    let (chord, u) = (1.0, 1.0);
    let omega = 2.0 * k * u / chord;
    let period = 2.0 * PI / omega;
    let per_cycle = (period * u / chord * steps_per_chord as f64).round() as usize;
    if per_cycle == 0 || cycles < 2 {
        return Err(missing("the heave needs 2 cycles of at least one step"));
    }
    let dt = period / per_cycle as f64;
    let mut settings = UvlmSettings::new(dt, 1.0, Vector3::new(u, 0.0, 0.0));
    settings.symmetric = true;
    (settings.free_wake_rows, settings.wake_rows) = wake;
    let corners = (0..=nc)
        .flat_map(|i| {
            (0..=ns).map(move |j| {
                let y = semi_span * (0.5 * PI * j as f64 / ns as f64).sin();
                Vector3::new(chord * i as f64 / nc as f64, y, 0.0)
            })
        })
        .collect();
    let wing = Lattice::new(nc, ns, corners)?;
    let mut uvlm = Uvlm::new(nc, ns, settings)?;
    let q_area = 0.5 * u * u * chord * semi_span;
    let mut history = Vec::new();
    for _ in 0..cycles * per_cycle {
        let t = uvlm.time();
        let (s, c) = (omega * t).sin_cos();
        let surface = wing.translated(&Vector3::new(0.0, 0.0, h0 * chord * s));
        let velocity = vec![Vector3::new(0.0, 0.0, h0 * chord * omega * c); wing.corner_count()];
        let solution = uvlm.solve(&surface, &velocity)?;
        uvlm.advance(&surface, &solution)?;
        history.push((
            t,
            -solution.force.x / q_area,
            solution.power / (q_area * u),
            solution.force.z / q_area,
        ));
    }
    let last = &history[history.len() - per_cycle..];
    let before = &history[history.len() - 2 * per_cycle..history.len() - per_cycle];
    let n = per_cycle as f64;
    let mean = |rows: &[(f64, f64, f64, f64)], f: fn(&(f64, f64, f64, f64)) -> f64| {
        rows.iter().map(f).sum::<f64>() / n
    };
    Ok(Heave {
        ct: mean(last, |r| r.1),
        ct_before: mean(before, |r| r.1),
        cp: mean(last, |r| r.2),
        cl_sin: 2.0 * last.iter().map(|r| r.3 * (omega * r.0).sin()).sum::<f64>() / n,
        cl_cos: 2.0 * last.iter().map(|r| r.3 * (omega * r.0).cos()).sum::<f64>() / n,
        cl_peak: last.iter().map(|r| r.3.abs()).fold(0.0, f64::max),
    })
}

/// Garrick (1936): a rigid plate of aspect ratio 40 (semi-span 20 c with
/// the mirror image) heaving h0 = 0.05 c at k = 1, 8 x 6 panels, 8 steps a
/// chord, a frozen flat wake (linear theory), 3 cycles: cycle-mean thrust
/// within 10% of `4 pi k^2 (h0/c)^2 (F^2 + G^2)`.
pub fn garrick_heave_thrust() -> Validation {
    Validation {
        spec: Spec {
            name: "uvlm/garrick-heave-thrust",
            solver: Solver::Uvlm,
            reference: "Garrick (1936) NACA Rep. 567, CT = 4 pi k^2 (h0/c)^2 (F^2 + G^2), \
                        C(1) = 0.5394 - 0.1003i (Theodorsen 1935)",
            quantity: "cycle-mean CT, AR 40 rigid plate, heave h0 = 0.05 c, k = 1, 8 x 6 panels, \
                       frozen wake",
            units: "1",
            error_kind: ErrorKind::Relative,
            tolerance: 0.10,
        },
        reference: || garrick_thrust_k1(0.05),
        compute: || {
            let r = heave(1.0, 0.05, 8, 6, 20.0, 8, 3, (0, usize::MAX))?;
            Ok(Measured {
                value: r.ct,
                note: Some(format!(
                    "cycle before the last {:.5}; efficiency {:.3}",
                    r.ct_before,
                    r.ct / r.cp
                )),
            })
        },
    }
}
