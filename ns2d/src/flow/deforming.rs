//! The grid of a deforming section ([`crate::Deformation`]): the
//! conformal grid moved to each step's map, and what its motion changes
//! in the step (arbitrary Lagrangian–Eulerian, ALE).
//!
//! The grid's nodes keep their `(ξ, θ)` and move with the map: at fixed
//! `ζ`, `z(ζ, t) = F(ζ, t)`, so the grid velocity `w = ∂F/∂t` is the map's
//! own (an inverse FFT round each ring gives `z`, `∂z/∂ξ` and `w` at its
//! nodes). The streamfunction's operator is the polar Laplacian whatever
//! the map, so the factored [`crate::StreamSolver`] serves every step; the
//! map enters through `J` and the wall's conditions:
//!
//! - **Advection relative to the moving cells.** The grid's velocity is
//!   split into its rigid part `w_r = V + iα̇ z` (the turn of the map's
//!   leading coefficient and the translation that goes with it:
//!   [`rigid_part`]) and the rest, the change of shape's. The rigid part
//!   has a streamfunction, taken off the fluid's as the frame's is, so its
//!   fluxes are differences at the faces' corners, exact round every cell:
//!   a plunge or pitch given as deformation is the frame's motion to
//!   rounding (`tests/deforming_sections.rs`; until 2026-12-06, when the
//!   whole `w` was swept by the midpoint rule, 0.2 % off on 256 × 192).
//!   A face's flux is then the fluid's (the difference of the relative
//!   streamfunction at its corners) less the flux the face sweeps with
//!   the rest `w'`, `∫ w'·n ds` by the midpoint rule: `Re(conj(z_ξ) w')
//!   Δθ` through a radial face, `Im(conj(z_ξ) w') Δξ` through a ring
//!   face. The grid velocity is not solenoidal (`w` is
//!   analytic in `z`: `div w = 2 ∂(Re w)/∂x`), so the fluxes round a cell
//!   sum to minus its area's growth; the transport is taken in the form
//!   `A dω/dt = -Σ F_f ω_f + ω Σ F_f`, which keeps a uniform vorticity
//!   uniform whatever the grid does (the discrete geometric conservation
//!   law: Thomas & Lombard 1979, *AIAA J.* 17; Demirdžić & Perić 1988),
//!   the added term explicit.
//! - **The wall moves with the grid.** The wall's velocity is the grid's
//!   there (the contour's points slide along it as the map's
//!   correspondence changes; for a membrane whose surfaces neither
//!   stretch nor slide this tangential sliding is the one approximation of
//!   the wall condition): its streamfunction varies along the wall as the
//!   rigid part's and by the rest's normal flux `∫ Re(conj(z_ξ) w') dθ` (a
//!   net flux, the area's change, is spread round), its `ψ_ξ` by
//!   `Im(conj(w) z_ξ)`, and Kelvin's
//!   bookkeeping counts the wall's own circulation `∮ w·ds` with the
//!   rotation's `2ΩA`.
//! - **Loads**: the wall's acceleration adds `∂²F/∂t² + 2iΩw` to the
//!   frame's, the power `-∮ f·w ds`, and the friction is
//!   `ν (ω - 2Ω + 2 n·∂w/∂s)` (the tangential stress `μ(ω + 2 n·∂u/∂s)` of
//!   a no-slip wall moving at `u`).
//!
//! The map's circle is turned per shape to follow the section's points
//! ([`crate::Deformation::of_shapes`]); without that, `J` at the wall of
//! the default FWAV plate, which pitches by ±1.4° as it bends, drifted 2%
//! every hundred steps (the fitted map's points slid round the wall by
//! the pitch angle), and the influence matrix was rebuilt as often;
//! with it, about eight times a period.
//!
//! Cost, measured on the default FWAV section (256 × 160, two cores): the
//! grid's motion adds about half a rigid step (three inverse FFTs a ring,
//! and the metrics and swept fluxes fused into the same pass):
//! the 4 periods deforming as the built-in design's first system
//! analysis found took 48.5 s, rigid 25.9 s (the deforming run's larger
//! motion also took a third more steps). With `fwav`'s step that follows
//! the flow (lengthened where it has room) and the influence matrix built
//! from the streamfunction's turned responses (4 ms instead of 45), 29.9 s
//! and 18.1 s (256 × 160, Courant number 1.5).
//!
//! Where a step's time goes on the default 384 × 160 grid (timers round
//! the phases of [`super::Flow::step`], seconds per 10,000 steps, two
//! cores; rigid, then deforming): advection 2.3, 2.7; moving the grid
//! (this module) 0, 4.1; ring sweep 1.9, 1.9; radial sweep 1.3, 1.5; the
//! wall rings' streamfunction (with the frame's at every node) 1.3, 1.6;
//! the wall's correction 0.7, 0.8, and its second radial pass 0.3, 0.4;
//! the full streamfunction 1.1, 1.3; the rest 0.4, 0.5: 9.2 and 14.8. The
//! grid's motion is 28 % of a deforming step, its FFTs about two thirds
//! of that. Truncating a ring's series where its terms fall below
//! rounding would spare little: the default plate's maps keep 192 terms
//! out to `|ζ| = 1.1`, 35 at 2.2 and 7 at the outer ring.
//!
//! A profile of three strokes on one thread (2026-12-06, `perf`) put the
//! deforming step at 1.62 times the same strokes' with the change of
//! shape left out; this module's own lines were a sixth of the step.
//! Trimmed, the same flow to the bit: each ring's powers end where they
//! underflow (counting the nonzero ones on every call was a quarter of
//! [`fill`]'s time), the series' orders are read beside the terms (so
//! `fill`'s loops vectorize), the swept fluxes are taken off the faces'
//! speeds in loops with no bounds or wrap to test (they had been 8 % of
//! the step), and the grid's velocity is kept at the wall's and the
//! outer ring's nodes only. Three strokes on one thread, the two
//! binaries side by side: 109.1 s and 107.6 s against 123.9 s and
//! 122.5 s (−12 %, two pairs).
//!
//! The step moves the grid once, between its explicit part (at the
//! step's start, with the start's grid, and the swept fluxes extrapolated
//! to the step's middle as the fluid's velocity is: [`super::Flow::step`])
//! and its implicit sweeps and streamfunction solves (at the step's
//! end): first order in the grid's motion, whose time scale (a flapping
//! period) is thousands of steps (the plunging and pitching ellipse given
//! as a deformation converges at second order in the step all the same:
//! `tests/deforming_sections.rs`; a rigid motion given as deformation
//! is the frame's to rounding, and the first stroke of the default FWAV
//! section's rigid part alone, which was 4.5 % above the frame's at
//! Courant 3, was so through its maps fitted sample by sample, not
//! through this: `ns2d/README.md`, "The deformation's rigid part"). The
//! wall's influence matrix is built on the grid of its time and rebuilt when `J` in the wall's two rings
//! has moved by more than [`INFLUENCE_DRIFT`] since (each time step in
//! use has its own) ([`super::Flow::wall_residual`] shows what the drift
//! leaves).

use std::sync::Arc;

use rayon::prelude::*;
use realfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};

use super::advection::at_middle;
use super::Flow;
use crate::deformation::{Deformation, MapState};
use crate::error::NsError;
use crate::grid::OGrid;
use crate::motion::{Motion, RigidField};

/// The relative change of `J` at the wall's two rings since the wall's
/// influence matrix was built beyond which it is built again.
pub(super) const INFLUENCE_DRIFT: f64 = 0.02;

/// Whether the wall's rings have moved so far since an influence matrix
/// was built on `J = before` that it is built again (`J = now`).
pub(super) fn drifted(before: &[f64], now: &[f64]) -> bool {
    before.len() != now.len()
        || before
            .iter()
            .zip(now)
            .any(|(b, n)| (n / b - 1.0).abs() > INFLUENCE_DRIFT)
}

/// The deforming grid's state (module docs).
pub(super) struct DeformingGrid {
    deformation: Deformation,
    fft: Arc<dyn Fft<f64>>,
    /// Each ring's [`ring_powers`], and the wall series' (all 1: they are
    /// taken on `|ζ| = 1`).
    powers: Vec<Vec<f64>>,
    unit_powers: Vec<f64>,
    /// The terms' orders `1, 2, …` ([`RingTerms`]).
    orders: Vec<f64>,
    /// `∂z/∂t` (body axes) at the wall's nodes, then the outer ring's:
    /// the rings whose loads and pressure level want it (elsewhere it is
    /// formed in a ring's scratch and swept: one grid-sized array fewer
    /// written every step). And `conj(z_ξ) w'` at every node, `w'`
    /// the grid's velocity less its rigid part ([`rigid_part`]; from which
    /// the faces' swept fluxes are taken: [`SweptFluxes`]), also as it was
    /// at the last step's start.
    velocity: Vec<Complex64>,
    swept_node: NodeFlux,
    previous_node: NodeFlux,
    /// The streamfunction of the grid's rigid part at the nodes
    /// ([`RigidField::streamfunction`]), and that part.
    pub(super) rigid_psi: Vec<f64>,
    rigid: RigidField,
    /// At the wall: the deformation's streamfunction and `ψ_ξ`, its
    /// acceleration `∂²z/∂t²` and `∂w/∂θ`.
    pub(super) wall_psi: Vec<f64>,
    pub(super) wall_slope: Vec<f64>,
    wall_acceleration: Vec<Complex64>,
    wall_velocity_theta: Vec<Complex64>,
    /// The circulation of the wall's deformation velocity, `∮ w·ds`.
    pub(super) circulation: f64,
}

/// The rigid part of the grid's motion `state`, `w_r = V + iα̇ z` (body
/// axes; a [`RigidField`], as the frame's is):
/// the turn of the map's leading coefficient `a`, `α̇ = Im(ȧ/a)`, and the
/// translation that goes with it, `V = ż0 - iα̇ z0`. A map that merely
/// moves (`F = e^{iα} F_0 + d`) has `w = w_r` exactly; the rest of the
/// grid's velocity, `w - w_r`, is the change of shape's.
///
/// Why split: a rigid grid velocity has a streamfunction,
/// `Im(conj(V) z) - α̇|z|²/2`, so the faces' fluxes of the rigid part are
/// differences of its values at the corners, as the frame's are, exact
/// round every cell; by the midpoint rule (as the rest is swept) they
/// are not. Measured (2026-12-06): an ellipse's plunge or pitch given as
/// deformation was the frame's to 2e-3 (256 × 192) and is now to 2e-10
/// (`tests/deforming_sections.rs`); the default FWAV section's first
/// stroke moved by 0.25 % in CT and 0.15 % in CP (384 × 256, Courant 3).
fn rigid_part(state: &MapState) -> RigidField {
    let (a, a_rate) = (state.coefficients[0], state.rate[0]);
    let rate = (a_rate * a.conj()).im / a.norm_sqr();
    let velocity = state.rate[1] - Complex64::new(0.0, rate) * state.coefficients[1];
    RigidField { velocity, rate }
}

/// Which series of a ring's inverse FFT ([`fill`]).
#[derive(Clone, Copy)]
enum Series {
    /// `F` (or its time derivatives, given theirs).
    Value,
    /// `ζ F' = ∂/∂ξ`.
    Radial,
    /// `∂/∂θ`.
    Around,
}

/// The powers `rho^-1, rho^-2, …` of the ring `|ζ| = rho` that [`fill`]
/// weighs the Laurent terms `b_1 …` by, at most `terms` of them: each the
/// last times `1/rho`, ending where that underflows to zero (the terms
/// past it are zero on the ring). The rings do not move in `ξ`, so each
/// ring's are made once ([`DeformingGrid::new`]), and where they end
/// with them: counting the nonzero powers on every call was a quarter of
/// [`fill`]'s time (2026-12-06).
fn ring_powers(rho: f64, terms: usize) -> Vec<f64> {
    let inv = 1.0 / rho;
    let mut power = inv;
    (0..terms)
        .map(|_| {
            let p = power;
            power *= inv;
            p
        })
        .take_while(|&p| p != 0.0)
        .collect()
}

/// What [`fill`] weighs a ring's Laurent terms `b_1 …` by: the ring's
/// [`ring_powers`], and the terms' orders `m = 1, 2, …` as numbers
/// ([`DeformingGrid`]'s `orders`: read beside the terms, where a count
/// converted in the loop kept the loop from vectorizing).
#[derive(Clone, Copy)]
struct RingTerms<'a> {
    powers: &'a [f64],
    orders: &'a [f64],
}

/// The ring's spectrum of the coefficients `c` = `[a, z0, b_1 …]` into
/// `buf` (length `nt`; frequency `-k` at `nt - k`), the ring `|ζ| = rho`
/// whose [`ring_powers`] are `powers`.
///
/// Each series has its own loop over the Laurent terms (a branch per
/// series, not per term): the terms are written, not added to a zeroed
/// buffer, and each is the product `(factor · b) · power` that a complex
/// factor `1`, `-m` or `-i m` gives, written out, so the spectrum is the
/// same to the bit. The loops stop where the ring's powers end (where
/// they underflow: [`ring_powers`]).
fn fill(buf: &mut [Complex64], c: &[Complex64], rho: f64, ring: RingTerms<'_>, series: Series) {
    let RingTerms { powers, orders } = ring;
    let nt = buf.len();
    let i = Complex64::new(0.0, 1.0);
    let zero = Complex64::new(0.0, 0.0);
    let (first, mean) = match series {
        Series::Value => (c[0] * rho, c[1]),
        Series::Radial => (c[0] * rho, zero),
        Series::Around => (i * c[0] * rho, zero),
    };
    // The terms `b_m ρ^-m` at frequencies `-m`, `nt - 1` down.
    let used = powers.len().min(c.len() - 2);
    let (rest, tail) = buf.split_at_mut(nt - used);
    let terms = tail.iter_mut().rev().zip(&c[2..]).zip(powers);
    match series {
        Series::Value => {
            for ((out, b), &power) in terms {
                *out = *b * power;
            }
        }
        Series::Radial => {
            for (((out, b), &power), &m) in terms.zip(orders) {
                let m = -m;
                *out = Complex64::new(m * b.re * power, m * b.im * power);
            }
        }
        Series::Around => {
            for (((out, b), &power), &m) in terms.zip(orders) {
                *out = Complex64::new(m * b.im * power, -m * b.re * power);
            }
        }
    }
    // Added to zero, as a sum has them (`-0.0` becomes `0.0`).
    rest.fill(zero);
    rest[0] += mean;
    rest[1] += first;
}

impl DeformingGrid {
    /// The state for `deformation` on a grid of `nt` nodes round.
    fn new(deformation: Deformation, grid: &OGrid) -> Self {
        let (nt, n) = (grid.nt, grid.len());
        let zero = Complex64::new(0.0, 0.0);
        let terms = deformation.terms();
        let powers = grid
            .xi
            .iter()
            .map(|xi| ring_powers(xi.exp(), terms))
            .collect();
        Self {
            deformation,
            fft: FftPlanner::new().plan_fft_inverse(nt),
            powers,
            unit_powers: vec![1.0; terms],
            orders: (1..=terms).map(|m| m as f64).collect(),
            velocity: vec![zero; 2 * nt],
            swept_node: NodeFlux::zeros(n),
            previous_node: NodeFlux::zeros(n),
            rigid_psi: vec![0.0; n],
            rigid: RigidField::default(),
            wall_psi: vec![0.0; nt],
            wall_slope: vec![0.0; nt],
            wall_acceleration: vec![zero; nt],
            wall_velocity_theta: vec![zero; nt],
            circulation: 0.0,
        }
    }

    /// The wall's series of `state`: its acceleration and `∂w/∂θ`.
    fn wall_series(&mut self, state: &MapState) {
        let fft = &self.fft;
        for (buf, coefficients, series) in [
            (
                &mut self.wall_acceleration,
                &state.acceleration,
                Series::Value,
            ),
            (&mut self.wall_velocity_theta, &state.rate, Series::Around),
        ] {
            let ring = RingTerms {
                powers: &self.unit_powers,
                orders: &self.orders,
            };
            fill(buf, coefficients, 1.0, ring, series);
            fft.process(buf);
        }
    }

    /// The wall's streamfunction, `ψ_ξ` and circulation of the grid's
    /// velocity (module docs): the streamfunction the rigid part's
    /// ([`RigidField::streamfunction`], exact) and the rest's normal flux
    /// (the real part of the wall ring's `swept_node`, per `dθ`) summed
    /// round; `ψ_ξ` and the circulation from the whole `conj(z_ξ) w` (the
    /// rigid part added back), its imaginary part `-ψ_ξ` and the
    /// circulation per `dθ`.
    fn wall_conditions(&mut self, grid: &OGrid) {
        let nt = grid.nt;
        let rigid = self.rigid;
        let (rest, rest_im) = (&self.swept_node.re[..nt], &self.swept_node.im[..nt]);
        // The rigid part's streamfunction at the wall's nodes, as
        // [`Flow::move_grid`] has just formed it.
        let rigid_psi = &self.rigid_psi[..nt];
        self.wall_psi[0] = 0.0;
        for k in 1..nt {
            self.wall_psi[k] = self.wall_psi[k - 1] + 0.5 * (rest[k - 1] + rest[k]) * grid.d_theta;
        }
        // A net flux (the area's change) spread round the wall.
        let closure = self.wall_psi[nt - 1] + 0.5 * (rest[nt - 1] + rest[0]) * grid.d_theta;
        let start = rigid_psi[0];
        for (k, (p, r)) in self.wall_psi.iter_mut().zip(rigid_psi).enumerate() {
            *p += r - start - closure * k as f64 / nt as f64;
        }
        for (k, slope) in self.wall_slope.iter_mut().enumerate() {
            let whole = Complex64::new(rest[k], rest_im[k])
                + grid.dz_dxi[k].conj() * rigid.velocity_at(grid.z[k]);
            *slope = -whole.im;
        }
        // `Σ Im(whole) = -Σ ψ_ξ` (negating is exact, so the same sum).
        self.circulation = -self.wall_slope.iter().sum::<f64>() * grid.d_theta;
    }

    /// The faces' swept fluxes at the current step's start and at the
    /// last one's ([`SweptFluxes`]) on `grid`.
    pub(super) fn swept<'a>(&'a self, grid: &'a OGrid) -> SweptFluxes<'a> {
        SweptFluxes {
            now: &self.swept_node,
            before: &self.previous_node,
            xi: &grid.xi,
            d_theta: grid.d_theta,
        }
    }

    /// Keep the nodes' `conj(z_ξ) w` as the last step's before the grid
    /// moves (a swap: [`Flow::move_grid`] writes every node).
    pub(super) fn keep_swept_as_previous(&mut self) {
        std::mem::swap(&mut self.swept_node, &mut self.previous_node);
    }
}

/// `conj(z_ξ) w'` at every node ([`DeformingGrid`]), its real part (a
/// radial face's swept flux per `dθ`) and its imaginary part (a ring
/// face's per `dξ`) apart: each face's loop reads only the part it
/// sweeps ([`SweptFluxes`]), half the bytes of the whole numbers.
pub(super) struct NodeFlux {
    re: Vec<f64>,
    im: Vec<f64>,
}

impl NodeFlux {
    /// Zero at `n` nodes.
    fn zeros(n: usize) -> Self {
        Self {
            re: vec![0.0; n],
            im: vec![0.0; n],
        }
    }

    /// At node `i`.
    fn at(&self, i: usize) -> Complex64 {
        Complex64::new(self.re[i], self.im[i])
    }
}

/// The fluxes the faces sweep (module docs), by the midpoint rule from
/// the nodes' `conj(z_ξ) w` at the step's start (`now`) and at the last
/// step's (`before`), taken at the step's middle, `now + half (now -
/// before)` (`half` = ½ of the ratio of the steps; 0 on the first), as
/// the fluid's relative streamfunction is ([`super::Flow::step`]). Taken
/// where the advection needs them, not kept for every face.
pub(super) struct SweptFluxes<'a> {
    now: &'a NodeFlux,
    before: &'a NodeFlux,
    xi: &'a [f64],
    d_theta: f64,
}

impl SweptFluxes<'_> {
    /// Take the swept fluxes of ring `j`'s radial faces (above its nodes,
    /// outward; `j` below the outer ring) at the step's middle off their
    /// speeds `speed`.
    pub(super) fn take_off_radial(&self, j: usize, half: f64, speed: &mut [f64]) {
        let nt = speed.len();
        if j + 1 >= self.xi.len() {
            return;
        }
        let at = j * nt;
        // Slices of the ring's length (the ring and the next out, now and
        // before), so the loop has no bounds to check.
        let (now, now_above) = self.now.re[at..at + 2 * nt].split_at(nt);
        let (before, before_above) = self.before.re[at..at + 2 * nt].split_at(nt);
        let d_theta = self.d_theta;
        let flux = |a: &f64, b: &f64| 0.5 * (a + b) * d_theta;
        let nodes = now
            .iter()
            .zip(now_above)
            .zip(before.iter().zip(before_above));
        for (q, ((a, b), (c, d))) in speed.iter_mut().zip(nodes) {
            *q -= at_middle(flux(a, b), flux(c, d), half);
        }
    }

    /// Take the swept fluxes of ring `j`'s ring faces `k + ½` (forward;
    /// none on the wall's and the outer ring) at the step's middle off
    /// their speeds `speed`.
    pub(super) fn take_off_ring(&self, j: usize, half: f64, speed: &mut [f64]) {
        let (nt, xi) = (speed.len(), self.xi);
        if j == 0 || j + 1 >= xi.len() {
            return;
        }
        // The ring face spans the corners below and above: the wall itself
        // below ring 1.
        let below = if j == 1 {
            xi[0]
        } else {
            0.5 * (xi[j - 1] + xi[j])
        };
        let span = 0.5 * (xi[j] + xi[j + 1]) - below;
        let (now, before) = (
            &self.now.im[j * nt..(j + 1) * nt],
            &self.before.im[j * nt..(j + 1) * nt],
        );
        let flux = |a: &f64, b: &f64| 0.5 * (a + b) * span;
        // The faces `k + ½` but the last, then the last (round to node 0):
        // no wrap to test in the loop.
        let pairs = (now.iter().zip(&now[1..])).zip(before.iter().zip(&before[1..]));
        for (q, ((a, b), (c, d))) in speed.iter_mut().zip(pairs) {
            *q -= at_middle(flux(a, b), flux(c, d), half);
        }
        speed[nt - 1] -= at_middle(
            flux(&now[nt - 1], &now[0]),
            flux(&before[nt - 1], &before[0]),
            half,
        );
    }
}

impl<M: Motion> Flow<M> {
    /// A flow at rest round the section deforming by `deformation` (its
    /// map at `t = 0` the grid's start) and moving by `motion` (module
    /// docs of `flow/deforming.rs`); as [`Flow::new`] otherwise.
    ///
    /// # Errors
    /// [`Flow::new`]'s; [`NsError::BadGrid`] when the maps have more
    /// Laurent terms than the grid has nodes round, less two.
    pub fn deforming(
        deformation: Deformation,
        spec: crate::GridSpec,
        motion: M,
        viscosity: f64,
    ) -> Result<Self, NsError> {
        let terms = deformation.terms();
        if terms + 2 > spec.around {
            return Err(NsError::BadGrid {
                what: "around (at least the deformation's Laurent terms + 2)",
                value: spec.around as f64,
                min: (terms + 2) as f64,
                max: 8192.0,
            });
        }
        let map = deformation.map_at(0.0);
        let mut flow = Self::new(&map, spec, motion, viscosity)?;
        flow.deforming = Some(DeformingGrid::new(deformation, &flow.grid));
        flow.move_grid(0.0);
        flow.evaluate(0.0);
        Ok(flow)
    }

    /// Move a deforming section's grid to the map of time `t`: nodes,
    /// metrics, the grid's velocity, the faces' swept fluxes
    /// and the wall's conditions (module docs). Cost: three inverse FFTs a
    /// ring and `O(N)` passes.
    pub(super) fn move_grid(&mut self, t: f64) {
        let Some(d) = self.deforming.as_mut() else {
            return;
        };
        let state = d.deformation.state(t);
        let rigid = rigid_part(&state);
        d.rigid = rigid;
        let g = &mut self.grid;
        let nt = g.nt;
        let fft = Arc::clone(&d.fft);
        let orders = &d.orders[..];
        let scratch_len = fft.get_inplace_scratch_len();
        let zero = Complex64::new(0.0, 0.0);
        // The rings whose velocity is kept (the wall's and the outer ring's).
        let (wall_velocity, outer_velocity) = d.velocity.split_at_mut(nt);
        let mut kept: Vec<Option<&mut [Complex64]>> = (0..g.nr).map(|_| None).collect();
        kept[0] = Some(wall_velocity);
        kept[g.nr - 1] = Some(outer_velocity);
        g.z.par_chunks_mut(nt)
            .zip(g.dz_dxi.par_chunks_mut(nt))
            .zip(kept.into_par_iter())
            .zip(d.swept_node.re.par_chunks_mut(nt))
            .zip(d.swept_node.im.par_chunks_mut(nt))
            .zip(d.rigid_psi.par_chunks_mut(nt))
            .zip(g.jac.par_chunks_mut(nt))
            .zip(g.inv_jac.par_chunks_mut(nt))
            .zip(g.xi.par_iter())
            .zip(d.powers.par_iter())
            .for_each_init(
                || (vec![zero; scratch_len], vec![zero; nt]),
                |(scratch, ring_velocity),
                 (
                    ((((((((z, dz), kept), swept_re), swept_im), rigid_psi), jac), inv_jac), xi),
                    powers,
                )| {
                    let v = kept.unwrap_or(ring_velocity);
                    let rho = xi.exp();
                    for (series, coefficients, out) in [
                        (Series::Value, &state.coefficients, &mut *z),
                        (Series::Radial, &state.coefficients, &mut *dz),
                        (Series::Value, &state.rate, &mut *v),
                    ] {
                        let ring = RingTerms { powers, orders };
                        fill(out, coefficients, rho, ring, series);
                        fft.process_with_scratch(out, scratch);
                    }
                    let nodes = jac.iter_mut().zip(inv_jac.iter_mut()).zip(z.iter());
                    let swept = swept_re.iter_mut().zip(swept_im.iter_mut());
                    let grid_motion = v.iter().zip(swept).zip(rigid_psi.iter_mut());
                    for ((((j, ij), z), d), ((w, (s_re, s_im)), p)) in
                        nodes.zip(dz.iter()).zip(grid_motion)
                    {
                        *j = d.norm_sqr();
                        *ij = 1.0 / *j;
                        let s = d.conj() * (w - rigid.velocity_at(*z));
                        (*s_re, *s_im) = (s.re, s.im);
                        *p = rigid.streamfunction(*z);
                    }
                },
            );
        d.wall_series(&state);
        d.wall_conditions(g);
        self.area = state.map().area();
        // The rigid field's streamfunction moves with the nodes.
        self.frame_time = None;
    }

    /// The deformation's share of the wall's acceleration at node `k`
    /// (body axes): `∂²F/∂t² + 2iΩw`; its velocity `w`; and its share of
    /// the friction's vorticity, `2 n·∂w/∂s` (zero without deformation).
    pub(super) fn wall_deformation(&self, k: usize) -> (Complex64, Complex64, f64) {
        let Some(d) = &self.deforming else {
            let zero = Complex64::new(0.0, 0.0);
            return (zero, zero, 0.0);
        };
        let w = d.velocity[k];
        let accel = d.wall_acceleration[k] + Complex64::new(0.0, 2.0 * self.frame.rate) * w;
        let dz = self.grid.dz_dxi[k];
        let stretch = 2.0 * (dz.conj() * d.wall_velocity_theta[k]).re * self.grid.inv_jac[k];
        (accel, w, stretch)
    }

    /// The streamfunction of the flow relative to the frame and to the
    /// grid's rigid part ([`rigid_part`]) at node `i`, and
    /// [`Self::swept_rest`] there: the relative flow's streamfunction
    /// derivatives less the latter are its fluxes.
    pub(super) fn relative_at(&self, i: usize) -> (f64, Complex64) {
        (
            self.psi[i] - self.frame_psi[i] - self.grid_rigid_psi(i),
            self.swept_rest(i),
        )
    }

    /// The streamfunction of the grid's rigid part at node `i` (zero for
    /// a rigid section).
    pub(super) fn grid_rigid_psi(&self, i: usize) -> f64 {
        self.deforming.as_ref().map_or(0.0, |d| d.rigid_psi[i])
    }

    /// `conj(z_ξ) w'` at node `i`, `w'` the grid's velocity less its rigid
    /// part (zero for a rigid section).
    pub(super) fn swept_rest(&self, i: usize) -> Complex64 {
        self.deforming
            .as_ref()
            .map_or(Complex64::new(0.0, 0.0), |d| d.swept_node.at(i))
    }

    /// The grid's velocity at node `k` of the wall's ring (`outer`:
    /// false) or the outer ring's (zero for a rigid section).
    pub(super) fn grid_velocity(&self, outer: bool, k: usize) -> Complex64 {
        let at = if outer { self.grid.nt + k } else { k };
        self.deforming
            .as_ref()
            .map_or(Complex64::new(0.0, 0.0), |d| d.velocity[at])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The grid's velocity `w` and position `z` at `|ζ| = rho`, angle
    /// `theta`, of the history `d` at `t`; and its rigid part there.
    fn velocity_and_rigid(d: &Deformation, t: f64, rho: f64, theta: f64) -> (Complex64, Complex64) {
        let state = d.state(t);
        let zeta = Complex64::from_polar(rho, theta);
        let z = state.map().point(zeta);
        let w = crate::SectionMap::from_coefficients(&state.rate).point(zeta);
        (w, rigid_part(&state).velocity_at(z))
    }

    /// A map that merely moves (turned about and carried off the origin)
    /// has a grid velocity that is its rigid part, everywhere; a map that
    /// also changes its shape (an ellipse whose thickness breathes) does
    /// not. Between the samples the coefficients are interpolated, and a
    /// turn `e^{iα}` interpolated from 12 samples of `α = 0.3 sin` is a
    /// turn and a scaling by `1 ± 1e-7` or so: measured 7.4e-8 of the
    /// velocity off its rigid part, held to 1e-6 (breathing: 0.93).
    #[test]
    fn a_moving_map_is_its_rigid_part() {
        let period = 2.0;
        let samples = 12;
        let at = |i: usize, breathe: f64| {
            let phase = std::f64::consts::TAU * i as f64 / samples as f64;
            crate::SectionMap::ellipse(0.5, 0.1 * (1.0 + breathe * phase.sin()), (0.2, 0.05))
                .unwrap()
                .moved(
                    0.3 * phase.sin(),
                    Complex64::new(0.1 * phase.cos(), 0.25 * phase.sin()),
                )
        };
        for (breathe, rigid) in [(0.0, true), (0.2, false)] {
            let maps: Vec<_> = (0..samples).map(|i| at(i, breathe)).collect();
            let d = Deformation::periodic(&maps, period).unwrap();
            let mut worst: f64 = 0.0;
            for t in [0.0, 0.31, 0.9, 1.55] {
                for rho in [1.0, 1.7, 9.0] {
                    for k in 0..16 {
                        let theta = std::f64::consts::TAU * k as f64 / 16.0;
                        let (w, r) = velocity_and_rigid(&d, t, rho, theta);
                        worst = worst.max((w - r).norm() / w.norm().max(1e-3));
                    }
                }
            }
            if rigid {
                assert!(worst < 1e-6, "moved: {worst:e}");
            } else {
                assert!(worst > 1e-2, "breathing: {worst:e}");
            }
        }
    }

    /// The ring series are the map's: `F`, `ζF'` and `∂F/∂θ` of an
    /// ellipse moved off the origin and turned, at `|ζ| = 1.3`.
    #[test]
    fn the_ring_series_are_the_maps() {
        let map = crate::SectionMap::ellipse(0.5, 0.2, (0.1, 0.0))
            .unwrap()
            .moved(0.4, Complex64::new(0.0, 0.2));
        let (a, z0, b) = map.coefficients();
        let mut c = vec![a, z0];
        c.extend_from_slice(b);
        let nt = 16;
        let fft = FftPlanner::new().plan_fft_inverse(nt);
        let rho: f64 = 1.3;
        let powers = ring_powers(rho, b.len());
        let orders: Vec<f64> = (1..=b.len()).map(|m| m as f64).collect();
        let mut out = vec![vec![Complex64::new(0.0, 0.0); nt]; 3];
        for (buf, s) in out
            .iter_mut()
            .zip([Series::Value, Series::Radial, Series::Around])
        {
            let ring = RingTerms {
                powers: &powers,
                orders: &orders,
            };
            fill(buf, &c, rho, ring, s);
            fft.process(buf);
        }
        let (value, rest) = out.split_first().unwrap();
        for (k, ((z, radial), around)) in value.iter().zip(&rest[0]).zip(&rest[1]).enumerate() {
            let zeta = Complex64::from_polar(rho, std::f64::consts::TAU * k as f64 / nt as f64);
            assert!((z - map.point(zeta)).norm() < 1e-13);
            let d = map.radial_derivative(zeta);
            assert!((radial - d).norm() < 1e-13);
            assert!((around - Complex64::new(0.0, 1.0) * d).norm() < 1e-13);
        }
    }
}
