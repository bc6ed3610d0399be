//! # fwav-ns2d — laminar Navier–Stokes of a moving 2D section
//!
//! The viscous section model of fwav's aerodynamic discipline: the
//! incompressible Navier–Stokes equations round a section that plunges,
//! surges and pitches, in a stream or in still air (hover).
//!
//! ## Method, and why
//! Vorticity–streamfunction on a body-fitted O-grid that is the conformal
//! image of a polar grid ([`SectionMap`], [`OGrid`]), in the section's
//! frame ([`Motion`], [`FrameState`]), stepped by [`Flow`]:
//! - **Body-fitted, as the paper's C-mesh**: the boundary layer of a
//!   Re 15,000 section needs wall cells of 1e-4 chord; a body-fitted grid
//!   puts them there and nowhere else, where a Cartesian immersed boundary
//!   would refine a whole box (and a thin plate shows the immersed
//!   boundary's force kinks).
//! - **Conformal, so the Poisson matrix never changes**: in conformal
//!   coordinates the Laplacian is the polar one divided by `J`; the
//!   section only enters the right-hand side. The streamfunction solve is
//!   an FFT round each ring plus one tridiagonal solve per mode
//!   ([`StreamSolver`], factored once), `O(N log N)` per step, for a
//!   rigid or a deforming section alike.
//! - **Body frame**: the grid moves with the section, so a plunging,
//!   surging, pitching section keeps its wall cells on its wall; the
//!   absolute vorticity is carried by the velocity relative to the grid.
//! - **Implicit where the cells are small**: a conformal grid crowds a thin
//!   section's ends with cells a hundred times smaller than mid-chord's
//!   (4% plate, 256 round: 1.9e-3 c along the wall, 1.4e-4 c across it).
//!   An explicit advection holds the whole flow to their Courant number
//!   (242,533 steps for four strokes of the default FWAV section); the
//!   first-order part of the advection is implicit there, by a θ-method
//!   whose weight rises with the face's Courant number, and stays
//!   second-order Crank–Nicolson elsewhere ([`Flow`]'s docs).
//!
//! - **Rings where the flow needs them**: the radial stretching places
//!   the rings ([`RingSpacing`]): exponential from the wall
//!   ([`RadialStretch`]), or the same rings near the wall and a faster
//!   growth past them ([`FarStretch`], [`TailedStretch`]), which keeps
//!   the near field's resolution on fewer rings (the default FWAV
//!   section's long-run thrust within 0.2 % of 320 exponential rings' on
//!   256, a fifth less cost). The solver takes `g''/g'` ring by ring.
//!
//! Measured cost on this project's 2-core machine: the stream solve and
//! the sweeps run on both cores, each step on a worker of rayon's pool
//! ([`Flow::step`]), the pool's other workers kept awake through a step
//! called from outside it (`awake_pool.rs`). (The impulsively started
//! cylinder at Re 550 to U t/R = 3 on 256 × 192, dt 0.004: 2.1 s in
//! release, on a machine shared with other builds.) Where a step of the
//! default FWAV section deforming on 384 × 320 spends its time (timers
//! round the phases of [`Flow::step`], two threads, 2026-12-04): moving
//! the grid 24 %, the advection's rates 20 %, the ring sweep 15 %, the
//! radial sweep 11 %, the wall rings' streamfunction (with the frame's
//! at every node) 11 %, the full streamfunction 9 %, the wall's
//! correction 3 % and its LU solve 2 %. The relative streamfunction
//! extrapolated to the step's middle is formed with the advection's
//! corners (a pass fewer), the second solve transforms only the rings
//! the wall's correction reached, and the circulation's rings are
//! summed in parallel: the same flow to the bit, 5 % sooner (107.7 and
//! 111.9 s against 117.7 s for three strokes, run alternately); the
//! ring sweep's interleaved systems set up with the lanes inner, 1.5 %
//! more.
//!
//! The validation cases (cylinders at Re 100, 200, impulsively started
//! cylinders, the hovering ellipse of Wang, Birch & Dickinson 2004) are in
//! [`cases`] and `tests/`, each beside its reference; `fwav validate
//! --only ns2d/` runs them at their validated resolutions.
//!
//! Any simple closed section ([`Contour`]: points, NACA 4-digit with a
//! rounded trailing edge, a thin plate or cambered membrane of finite
//! thickness; a coordinate file's sharp trailing edge made blunt first,
//! [`Contour::with_blunt_trailing_edge`], as a corner has no conformal
//! map) gets its map from [`SectionMap::from_contour`] (Wegmann's
//! Newton method after a Joukowski/circular-arc pre-map; about 2-4 ms for
//! 256 points on this loaded machine, `examples/fit_timing.rs`; a
//! section inside which no circular-arc slit fits, on the contour itself
//! from the geodesic zipper's correspondence, 0.05 to 0.9 s).
//!
//! The host runs it behind `fwav aero2d --model ns` (`fwav::aero2d::viscous`:
//! harmonic plunge and pitch, and the discipline's flapping section).
//! A deforming section ([`Deformation`]: a periodic history of maps,
//! each coefficient interpolated in time) runs on the grid moved to each
//! step's map ([`Flow::deforming`]; arbitrary Lagrangian–Eulerian, the
//! streamfunction's factored operator unchanged: `flow/deforming.rs`).

#![forbid(unsafe_code)]
#![warn(missing_docs)]
#![warn(clippy::too_many_lines)]

mod awake_pool;
mod blocks;
pub mod cases;
mod contour;
mod correspondence;
mod deformation;
mod error;
mod flow;
mod grid;
mod history;
mod motion;
mod reference_curve;
mod section_map;
mod spline;
mod stream;
mod stretch;

pub use contour::Contour;
pub use deformation::{trigonometric_terms, Deformation, MapState};
pub use error::NsError;
pub use flow::{Flow, WallLoads};
pub use grid::{check_around, GridSpec, OGrid, AROUND, RADIAL};
pub use history::{ForceHistory, WakeStatistics};
pub use motion::{FrameState, Motion, PlungePitch, RigidField, SteadyStream};
/// The complex numbers of the solver's interface (positions, velocities
/// and forces as `x + i y`).
pub use realfft::num_complex::Complex64;
pub use reference_curve::{interpolate, ReferenceCurve};
pub use section_map::SectionMap;
pub use stream::StreamSolver;
pub use stretch::{FarStretch, RadialStretch, RingSpacing, TailedStretch, MAX_FAR_GROWTH};
