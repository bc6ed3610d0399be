//! The advection of a step, in conservative form by finite volumes round
//! the nodes, split for the time scheme of [`super::Flow::step`]:
//!
//! - the first-order upwind fluxes `A₁`, by the θ-method with a weight
//!   `θ_f` per face from the face's Courant number ([`implicit_weight`]):
//!   `θ_f` of them in the implicit sweeps, the rest explicit;
//! - the deferred correction `A₃ - A₁` to the third-order upwind-biased
//!   face values, explicit (second-order Adams–Bashforth).
//!
//! The flux through a face is the difference of the relative
//! streamfunction at its two corners (so the fluxes round a cell sum to
//! zero exactly and none crosses the wall) times a face value of the
//! vorticity; the relative streamfunction is the step's middle's
//! (extrapolated from the step's start and the last one's as the corners
//! are formed: [`super::Flow::step`]), so that the velocity is
//! centred in the step as Crank–Nicolson and Adams–Bashforth need.
//! Every flux is shared by the two cells of its face with one weight, so
//! advection changes the fluid's circulation only by what crosses the
//! outer face.

use super::Flow;
use crate::grid::OGrid;
use crate::motion::Motion;
use rayon::prelude::*;

/// The implicit weight `θ` of a first-order upwind flux whose face has
/// the Courant number `courant` (`dt |q| / area`, the larger of the two
/// cells'): `max(½, 1 - 0.28/c)`.
///
/// Why: by von Neumann's analysis of `ω_t + u ω_x = 0` with the θ-method
/// on first-order upwind and second-order Adams–Bashforth on the
/// correction to third-order upwind-biased values, the scheme is stable
/// for `θ` above `θ_min(c)`: ½ to `c` = 0.55, then 0.502 (0.6), 0.622
/// (1), 0.752 (2), 0.815 (4), 0.862 (20). This weight lies above it at
/// every `c` (checked on 180 Courant numbers from 0.05 to 50, largest
/// amplification 1 − 4e-15), and is Crank–Nicolson's ½, second order in
/// time, wherever `c ≤ 0.56`: the first-order term `(θ - ½) c u Δx` of
/// the θ-method's numerical diffusion is paid only in the few cells the
/// step's Courant number exceeds that in (a thin section's edges).
#[must_use]
pub(super) fn implicit_weight(courant: f64) -> f64 {
    // 0.28/0.56 is ½ exactly: one expression (no branch) for both sides.
    1.0 - 0.28 / courant.max(0.56)
}

/// The third-order upwind-biased value at the face between `near` and
/// `far`, the flow going from `near` to `far` and `behind` the node
/// upstream of `near`: `(-behind + 5 near + 2 far)/6`.
fn upwind_face(behind: f64, near: f64, far: f64) -> f64 {
    (-behind + 5.0 * near + 2.0 * far) / 6.0
}

/// One face set's values at each `k` of a ring: the face's speed `q`
/// (the flux per unit vorticity), its first-order flux `q ω_upwind`, its
/// correction `q (ω₃ - ω_upwind)` and its implicit weight.
pub(super) struct Faces<'a> {
    pub(super) speed: &'a mut [f64],
    pub(super) first: &'a mut [f64],
    pub(super) correction: &'a mut [f64],
    pub(super) weight: &'a mut [f64],
}

impl<'a> Faces<'a> {
    /// Four rings of `scratch` (which must hold them) as a face set, and
    /// the rest.
    fn split(scratch: &'a mut [f64], nt: usize) -> (Self, &'a mut [f64]) {
        let (speed, rest) = scratch.split_at_mut(nt);
        let (first, rest) = rest.split_at_mut(nt);
        let (correction, rest) = rest.split_at_mut(nt);
        let (weight, rest) = rest.split_at_mut(nt);
        (
            Self {
                speed,
                first,
                correction,
                weight,
            },
            rest,
        )
    }

    /// Face `k`'s values for speed `q`, upwind values `v1` (first order)
    /// and `v3` (third), Courant number `c`.
    fn set(&mut self, k: usize, q: f64, v1: f64, v3: f64, c: f64) {
        self.speed[k] = q;
        self.first[k] = q * v1;
        self.correction[k] = q * (v3 - v1);
        self.weight[k] = implicit_weight(c);
    }
}

/// One row of radial faces, read ([`RadialFaces::faces`]).
pub(super) struct FaceRow<'a> {
    speed: &'a [f64],
    first: &'a [f64],
    correction: &'a [f64],
    weight: &'a [f64],
}

/// The radial faces of a step, each computed once: row `j` (for `j` in
/// `1..nr - 1`) the faces between rings `j` and `j + 1` and the corners
/// `(j + ½, k + ½)` they run between ([`RateRows::corners`]); ring 1's
/// lower corners are the wall's, and its lower face is the wall's, which
/// no flux crosses (row 0 is not used). Reused from step to step (the
/// empty default only stands in while a step holds it).
#[derive(Default)]
pub(super) struct RadialFaces {
    nt: usize,
    corners: Vec<f64>,
    wall: Vec<f64>,
    speed: Vec<f64>,
    first: Vec<f64>,
    correction: Vec<f64>,
    weight: Vec<f64>,
    /// A row of zeros: the wall's face, which no flux crosses.
    zero: Vec<f64>,
    /// Two rings of work space for the wall's corners.
    wall_middle: Vec<f64>,
}

impl RadialFaces {
    /// Storage for a grid of `nt` nodes round and `nr` rings.
    pub(super) fn new(nt: usize, nr: usize) -> Self {
        let rows = (nr - 1) * nt;
        Self {
            nt,
            corners: vec![0.0; rows],
            wall: vec![0.0; nt],
            speed: vec![0.0; rows],
            first: vec![0.0; rows],
            correction: vec![0.0; rows],
            weight: vec![0.0; rows],
            zero: vec![0.0; nt],
            wall_middle: vec![0.0; 2 * nt],
        }
    }

    /// Every row of `rows`'s flow (rows in parallel), and the relative
    /// streamfunction at the step's start into `start` (every ring: the
    /// next step's previous one).
    fn fill(&mut self, rows: &RateRows<'_>, start: &mut [f64]) {
        let nt = self.nt;
        let nr = start.len() / nt;
        rows.corners(
            usize::MAX,
            &mut self.wall,
            &mut start[..nt],
            &mut self.wall_middle,
        );
        let (_, outer) = start.split_at_mut((nr - 1) * nt);
        rows.relative_at_start(nr - 1, outer);
        self.corners
            .par_chunks_mut(nt)
            .zip(self.speed.par_chunks_mut(nt))
            .zip(self.first.par_chunks_mut(nt))
            .zip(self.correction.par_chunks_mut(nt))
            .zip(self.weight.par_chunks_mut(nt))
            .zip(start.par_chunks_mut(nt))
            .enumerate()
            .skip(1)
            .for_each_init(
                || vec![0.0; 2 * nt],
                |middle, (j, (((((corners, speed), first), correction), weight), start))| {
                    rows.corners(j, corners, start, middle);
                    let mut faces = Faces {
                        speed,
                        first,
                        correction,
                        weight,
                    };
                    rows.radial_faces(j, corners, &mut faces);
                },
            );
    }

    /// The corners of row `j`.
    fn corners(&self, j: usize) -> &[f64] {
        &self.corners[j * self.nt..(j + 1) * self.nt]
    }

    /// The faces of row `j`.
    fn faces(&self, j: usize) -> FaceRow<'_> {
        let r = j * self.nt..(j + 1) * self.nt;
        FaceRow {
            speed: &self.speed[r.clone()],
            first: &self.first[r.clone()],
            correction: &self.correction[r.clone()],
            weight: &self.weight[r],
        }
    }

    /// The wall's face: no flux.
    fn zero_faces(&self) -> FaceRow<'_> {
        FaceRow {
            speed: &self.zero,
            first: &self.zero,
            correction: &self.zero,
            weight: &self.zero,
        }
    }
}

/// The rates of one ring (see [`RateRows::row`]).
pub(super) struct RingRates<'a> {
    /// `(A₃ - A₁) ω`: the explicit correction (Adams–Bashforth).
    pub(super) correction: &'a mut [f64],
    /// What the first (ring) sweep takes explicitly at the step's start:
    /// all the radial diffusion and the ring diffusion's explicit part
    /// (half, but at the start), all of the
    /// radial advection `A₁`, the ring advection's explicit part
    /// `(1 - θ)`.
    pub(super) explicit: &'a mut [f64],
    /// The radial sweep's implicit operator applied to the step's start:
    /// the radial diffusion's implicit part and the `θ` part of the radial
    /// advection.
    pub(super) radial_old: &'a mut [f64],
    /// `θ q` of the radial face above each node and of the ring face
    /// `k + ½` (the sweeps' implicit advection).
    pub(super) radial_speed: &'a mut [f64],
    pub(super) ring_speed: &'a mut [f64],
}

/// The explicit rates and implicit face speeds of the rings (module
/// docs); diffusion round the section by central differences.
pub(super) struct RateRows<'a> {
    pub(super) nt: usize,
    pub(super) nr: usize,
    pub(super) d_theta: f64,
    pub(super) d_eta: f64,
    pub(super) viscosity: f64,
    pub(super) dt: f64,
    /// The diffusion's implicit weight ([`super::Flow::step`]).
    pub(super) diffusion_weight: f64,
    /// The grid (its stretching's `g'` and radial operator at each ring).
    pub(super) grid: &'a OGrid,
    /// The vorticity at the step's start, at all nodes.
    pub(super) w: &'a [f64],
    /// The streamfunction and the rigid motion's at the step's start
    /// (their difference the relative streamfunction), and the relative
    /// streamfunction at the last step's start, at all nodes, and ½ of
    /// the ratio of this step to the last (0 on the first): the relative
    /// streamfunction that carries the vorticity is the step's middle's,
    /// `now + half (now - previous)` ([`super::Flow::step`]).
    pub(super) psi: &'a [f64],
    pub(super) frame_psi: &'a [f64],
    /// The streamfunction of a deforming grid's rigid part at the nodes
    /// (`flow/deforming.rs`), taken off as the frame's is; `None` for a
    /// rigid grid.
    pub(super) grid_psi: Option<&'a [f64]>,
    pub(super) previous_relative: &'a [f64],
    pub(super) half: f64,
    /// `1/J` at all nodes.
    pub(super) inv_jac: &'a [f64],
    /// `1/(w_j Δθ)` per ring: a node's inverse cell area is
    /// `inv_jac · inv_cell`, and a face's Courant number takes the larger
    /// of its two cells'.
    pub(super) inv_cell: &'a [f64],
    /// A deforming grid's swept fluxes of the radial faces (above each
    /// node) and ring faces (`k + ½`), taken off the fluid's at the
    /// step's middle as the relative streamfunction is; `None` for a
    /// rigid grid.
    pub(super) swept: Option<super::deforming::SweptFluxes<'a>>,
}

/// A quantity at the step's middle from its value at the step's start,
/// `now`, and at the last step's, `previous`: `now + half (now -
/// previous)` ([`RateRows::half`]).
pub(super) fn at_middle(now: f64, previous: f64, half: f64) -> f64 {
    now + half * (now - previous)
}

impl RateRows<'_> {
    /// Ring `j` of the nodes' values `f`.
    fn ring<'b>(&self, f: &'b [f64], j: usize) -> &'b [f64] {
        &f[j * self.nt..(j + 1) * self.nt]
    }

    /// Ring `j`'s relative streamfunction at the step's start into `out`.
    fn relative_at_start(&self, j: usize, out: &mut [f64]) {
        let r = j * self.nt..(j + 1) * self.nt;
        for ((o, p), f) in out
            .iter_mut()
            .zip(&self.psi[r.clone()])
            .zip(&self.frame_psi[r])
        {
            *o = p - f;
        }
        if let Some(grid_psi) = self.grid_psi {
            for (o, g) in out.iter_mut().zip(self.ring(grid_psi, j)) {
                *o -= g;
            }
        }
    }

    /// Ring `j`'s relative streamfunction at the step's middle into
    /// `out`: [`Self::relative_at_start`] carried by [`at_middle`], in one
    /// pass.
    fn relative_at_middle(&self, j: usize, out: &mut [f64]) {
        let r = j * self.nt..(j + 1) * self.nt;
        let start = self.psi[r.clone()].iter().zip(&self.frame_psi[r.clone()]);
        let moved = out.iter_mut().zip(&self.previous_relative[r.clone()]);
        match self.grid_psi {
            Some(grid_psi) => {
                for (((m, p), (s, f)), g) in moved.zip(start).zip(&grid_psi[r]) {
                    *m = at_middle(s - f - g, *p, self.half);
                }
            }
            None => {
                for ((m, p), (s, f)) in moved.zip(start) {
                    *m = at_middle(s - f, *p, self.half);
                }
            }
        }
    }

    /// The relative streamfunction at the step's middle at the corners
    /// `(j + ½, k + ½)` of ring `j` (`j + 1` is a ring; the wall's corners
    /// for `j` = `usize::MAX` are the wall's own values, so no flux
    /// crosses it) into `out`, and ring `j`'s (the wall's) at the step's
    /// start into `start`; `middle` two rings of work space.
    fn corners(&self, j: usize, out: &mut [f64], start: &mut [f64], middle: &mut [f64]) {
        let nt = self.nt;
        let wall = j == usize::MAX;
        let ring = if wall { 0 } else { j };
        self.relative_at_start(ring, start);
        let (here, above) = middle.split_at_mut(nt);
        for ((m, s), p) in here
            .iter_mut()
            .zip(&*start)
            .zip(self.ring(self.previous_relative, ring))
        {
            *m = at_middle(*s, *p, self.half);
        }
        if wall {
            for (k, c) in out.iter_mut().enumerate() {
                *c = 0.5 * (here[k] + here[(k + 1) % nt]);
            }
            return;
        }
        self.relative_at_middle(j + 1, above);
        for (k, c) in out.iter_mut().enumerate() {
            let kp = if k + 1 == nt { 0 } else { k + 1 };
            *c = 0.25 * (here[k] + here[kp] + above[k] + above[kp]);
        }
    }

    /// A deforming grid's swept fluxes of ring `j`'s radial faces
    /// (`radial`) or ring faces at the step's middle, taken off the face
    /// speeds `speed`.
    fn take_swept(&self, j: usize, radial: bool, speed: &mut [f64]) {
        match &self.swept {
            Some(swept) if radial => swept.take_off_radial(j, self.half, speed),
            Some(swept) => swept.take_off_ring(j, self.half, speed),
            None => {}
        }
    }

    /// The faces between rings `j` and `j + 1` (outward speed positive,
    /// `1 <= j <= nr - 2`), `corners` those of [`Self::corners`] for `j`.
    /// Without branches on the flow's direction (a select, which
    /// vectorizes): the direction changes from face to face in a wake.
    pub(super) fn radial_faces(&self, j: usize, corners: &[f64], faces: &mut Faces<'_>) {
        let nt = self.nt;
        faces.speed[0] = corners[0] - corners[nt - 1];
        for k in 1..nt {
            faces.speed[k] = corners[k] - corners[k - 1];
        }
        self.take_swept(j, true, faces.speed);
        let (below, here, above) = (
            self.ring(self.w, j - 1),
            self.ring(self.w, j),
            self.ring(self.w, j + 1),
        );
        // A face's inverse area: the larger of its two cells'.
        let (inv_jac, inv_jac_above) = (self.ring(self.inv_jac, j), self.ring(self.inv_jac, j + 1));
        let (cell, cell_above) = (self.inv_cell[j], self.inv_cell[j + 1]);
        let area = |k: usize| (inv_jac[k] * cell).max(inv_jac_above[k] * cell_above);
        if j + 2 == self.nr {
            // The last face: first order where the flow comes in.
            for k in 0..nt {
                let q = faces.speed[k];
                let (v1, v3) = if q >= 0.0 {
                    (here[k], upwind_face(below[k], here[k], above[k]))
                } else {
                    (above[k], above[k])
                };
                faces.set(k, q, v1, v3, self.dt * q.abs() * area(k));
            }
            return;
        }
        let beyond = self.ring(self.w, j + 2);
        for k in 0..nt {
            let q = faces.speed[k];
            let out = q >= 0.0;
            let behind = if out { below[k] } else { beyond[k] };
            let near = if out { here[k] } else { above[k] };
            let far = if out { above[k] } else { here[k] };
            faces.set(
                k,
                q,
                near,
                upwind_face(behind, near, far),
                self.dt * q.abs() * area(k),
            );
        }
    }

    /// The faces `k + ½` round ring `j`, `lower` and `upper` the corners
    /// below and above it, `padded` the ring's vorticity with one node of
    /// the other end before it and two after (`[ω_{n-1}, ω_0 … ω_{n-1},
    /// ω_0, ω_1]`).
    fn ring_faces(
        &self,
        j: usize,
        lower: &[f64],
        upper: &[f64],
        padded: &[f64],
        faces: &mut Faces<'_>,
    ) {
        let nt = self.nt;
        // A face's inverse area, the larger of its two cells', in the
        // weights' place until each face's weight is set.
        let (inv_jac, cell) = (self.ring(self.inv_jac, j), self.inv_cell[j]);
        for (a, (here, next)) in faces
            .weight
            .iter_mut()
            .zip(inv_jac.iter().zip(&inv_jac[1..]))
        {
            *a = (here * cell).max(next * cell);
        }
        faces.weight[nt - 1] = (inv_jac[nt - 1] * cell).max(inv_jac[0] * cell);
        for ((q, l), u) in faces.speed.iter_mut().zip(lower).zip(upper) {
            *q = l - u;
        }
        self.take_swept(j, false, faces.speed);
        for k in 0..nt {
            let q = faces.speed[k];
            // Nodes k - 1, k, k + 1, k + 2.
            let (km, k0, kp, kpp) = (padded[k], padded[k + 1], padded[k + 2], padded[k + 3]);
            let forward = q >= 0.0;
            let behind = if forward { km } else { kpp };
            let near = if forward { k0 } else { kp };
            let far = if forward { kp } else { k0 };
            let area = faces.weight[k];
            faces.set(
                k,
                q,
                near,
                upwind_face(behind, near, far),
                self.dt * q.abs() * area,
            );
        }
    }

    /// Ring `j` (`1 <= j < nr - 1`) of the rates ([`RingRates`]), from
    /// the radial faces and corners of [`RadialFaces`]; `scratch`
    /// [`ROW_SCRATCH`] work rings (the ring faces, and the ring's values
    /// with the other end's beside them, so that the loops round the ring
    /// have no wrap-around to branch on).
    pub(super) fn row(
        &self,
        j: usize,
        radial: &RadialFaces,
        scratch: &mut [f64],
        out: RingRates<'_>,
    ) {
        let nt = self.nt;
        let (mut round, rest) = Faces::split(scratch, nt);
        let (padded, rest) = rest.split_at_mut(nt + 3);
        let (correction_before, rest) = rest.split_at_mut(nt + 1);
        let (explicit_before, _) = rest.split_at_mut(nt + 1);
        let upper = radial.corners(j);
        let above = radial.faces(j);
        let (lower, below) = if j == 1 {
            (&radial.wall[..], radial.zero_faces())
        } else {
            (radial.corners(j - 1), radial.faces(j - 1))
        };
        let w0 = self.ring(self.w, j);
        padded[0] = w0[nt - 1];
        padded[1..=nt].copy_from_slice(w0);
        padded[nt + 1] = w0[0];
        padded[nt + 2] = w0[1];
        self.ring_faces(j, lower, upper, padded, &mut round);
        // Face k - ½ at index k, face k + ½ at k + 1.
        correction_before[1..].copy_from_slice(round.correction);
        correction_before[0] = round.correction[nt - 1];
        for (e, (w, f)) in explicit_before[1..]
            .iter_mut()
            .zip(round.weight.iter().zip(round.first.iter()))
        {
            *e = (1.0 - w) * f;
        }
        explicit_before[0] = explicit_before[nt];
        let (w_below, w_above) = (self.ring(self.w, j - 1), self.ring(self.w, j + 1));
        let inv_jac = self.ring(self.inv_jac, j);
        let cell = self.inv_cell[j];
        let inv_dt2 = 1.0 / (self.d_theta * self.d_theta);
        // ∂ηη - β ∂η by central differences.
        let h2 = 1.0 / (self.d_eta * self.d_eta);
        let (lower, upper) = self.grid.radial_neighbours(j);
        let radial_factor = self.viscosity / (self.grid.slope[j] * self.grid.slope[j]);
        let theta_d = self.diffusion_weight;
        for k in 0..nt {
            // The cell's inverse area.
            let s = inv_jac[k] * cell;
            let correction = above.correction[k] - below.correction[k] + correction_before[k + 1]
                - correction_before[k];
            out.correction[k] = -s * correction;
            let ring_diffusion = self.viscosity
                * inv_jac[k]
                * (padded[k + 2] - 2.0 * padded[k + 1] + padded[k])
                * inv_dt2;
            let radial_diffusion = radial_factor
                * inv_jac[k]
                * (lower * w_below[k] - 2.0 * h2 * w0[k] + upper * w_above[k]);
            let radial_all = above.first[k] - below.first[k];
            let radial_implicit =
                above.weight[k] * above.first[k] - below.weight[k] * below.first[k];
            let ring_explicit = explicit_before[k + 1] - explicit_before[k];
            out.explicit[k] = radial_diffusion + (1.0 - theta_d) * ring_diffusion
                - s * (radial_all + ring_explicit);
            out.radial_old[k] = theta_d * radial_diffusion - s * radial_implicit;
            out.radial_speed[k] = above.weight[k] * above.speed[k];
            out.ring_speed[k] = round.weight[k] * round.speed[k];
        }
        if self.swept.is_some() {
            // The moving cell's share, `ω Σ F_f` (`flow/deforming.rs`):
            // node 0 (whose face `k - ½` is the last) apart, and the rest
            // on slices of the ring's length, without a wrap or bounds to
            // test in the loop.
            let (up, down, round) = (&above.speed[..nt], &below.speed[..nt], &round.speed[..nt]);
            let (inv_jac, w0, explicit) = (&inv_jac[..nt], &w0[..nt], &mut out.explicit[..nt]);
            let net = |k: usize, km: usize| up[k] - down[k] + round[k] - round[km];
            explicit[0] += inv_jac[0] * cell * w0[0] * net(0, nt - 1);
            for k in 1..nt {
                explicit[k] += inv_jac[k] * cell * w0[k] * net(k, k - 1);
            }
        }
    }
}

/// The work rings of [`RateRows::row`] (with room for its padding).
const ROW_SCRATCH: usize = 7;

impl<M: Motion> Flow<M> {
    /// The rates of every interior ring at the step's start (module docs)
    /// for a step of `dt`: rings in parallel, into `self.rate` (the whole
    /// explicit rate of the first sweep: the correction by Adams–Bashforth
    /// with the weights `now` and `before` of this step's and the last
    /// one's, the last one's in `self.previous_rate` and replaced by this
    /// one's, plus the rest), `self.radial_old`, `self.radial_speed`,
    /// `self.ring_speed`; and the outer face's explicit outflow into
    /// `self.outflow_rate` (correction) and `self.outflow_explicit`.
    pub(super) fn advection_rates(&mut self, dt: f64, now: f64, before: f64) {
        let g = &self.grid;
        let (nt, nr) = (g.nt, g.nr);
        // The carrier at the step's middle (module docs of `flow`).
        let half = if self.steps == 0 {
            0.0
        } else {
            0.5 * dt / self.last_dt
        };
        let rows = RateRows {
            nt,
            nr,
            d_theta: g.d_theta,
            d_eta: g.d_eta,
            viscosity: self.viscosity,
            dt,
            diffusion_weight: self.diffusion_weight,
            grid: g,
            w: &self.omega,
            psi: &self.psi,
            frame_psi: &self.frame_psi,
            grid_psi: self.deforming.as_ref().map(|d| &d.rigid_psi[..]),
            previous_relative: &self.previous_relative,
            half,
            inv_jac: &g.inv_jac,
            inv_cell: &self.inv_cell,
            swept: self.deforming.as_ref().map(|d| d.swept(g)),
        };
        let mut radial = std::mem::take(&mut self.radial_faces);
        radial.fill(&rows, &mut self.relative_start);
        self.rate
            .par_chunks_mut(nt)
            .zip(self.previous_rate.par_chunks_mut(nt))
            .zip(self.explicit.par_chunks_mut(nt))
            .zip(self.radial_old.par_chunks_mut(nt))
            .zip(self.radial_speed.par_chunks_mut(nt))
            .zip(self.ring_speed.par_chunks_mut(nt))
            .enumerate()
            .for_each_init(
                || vec![0.0; ROW_SCRATCH * nt + 8],
                |scratch, (j, (((((rate, previous), explicit), radial_old), radial_speed), ring_speed))| {
                    if j == 0 || j == nr - 1 {
                        for out in [rate, previous, explicit, radial_old, radial_speed, ring_speed] {
                            out.fill(0.0);
                        }
                        return;
                    }
                    let out = RingRates {
                        correction: &mut *rate,
                        explicit: &mut *explicit,
                        radial_old,
                        radial_speed,
                        ring_speed,
                    };
                    rows.row(j, &radial, scratch, out);
                    for ((r, p), e) in rate.iter_mut().zip(previous.iter_mut()).zip(explicit.iter()) {
                        let current = *r;
                        *r = now * current + before * *p + e;
                        *p = current;
                    }
                },
            );
        // What leaves through the outer face (rings nr - 2 and nr - 1).
        let outer = radial.faces(nr - 2);
        self.outflow_rate = outer.correction.iter().sum();
        self.outflow_explicit = outer
            .first
            .iter()
            .zip(outer.weight.iter())
            .map(|(f, w)| (1.0 - w) * f)
            .sum();
        self.radial_faces = radial;
        // This step's start is the next one's previous.
        std::mem::swap(&mut self.relative_start, &mut self.previous_relative);
    }

    /// The implicit part of the step's outflow through the outer face (the
    /// explicit part, at the step's start, is the Adams–Bashforth
    /// correction and `(1 - θ)` of the first-order flux):
    /// `θ q` (in `self.radial_speed` of ring `nr - 2`) times the upwind
    /// vorticity at the step's end (the last interior ring's, or the
    /// outer ring's held value of the step's start where the flow enters).
    pub(super) fn outer_implicit_flux(&self) -> f64 {
        let nt = self.grid.nt;
        let j = self.grid.nr - 2;
        (0..nt)
            .map(|k| {
                let q = self.radial_speed[j * nt + k];
                if q >= 0.0 {
                    q * self.omega[j * nt + k]
                } else {
                    q * self.start_outer[k]
                }
            })
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::implicit_weight;
    use realfft::num_complex::Complex64;

    /// The largest amplification over wavenumbers of the 1D scheme of
    /// [`implicit_weight`] at Courant number `c` with weight `theta`:
    /// `ω_t + ω_x = 0` on a periodic grid, first-order upwind by the
    /// θ-method, the correction to third-order upwind-biased face values
    /// by second-order Adams–Bashforth. Von Neumann: the amplification `g`
    /// solves `(1 - θa₁) g² - (1 + (1 - θ)a₁ + 3N/2) g + N/2 = 0` with
    /// `a₁`, `a₃` the symbols of `-c Δ(face value)` and `N = a₃ - a₁`.
    fn amplification(c: f64, theta: f64) -> f64 {
        (1..=400)
            .map(|m| {
                let phi = std::f64::consts::PI * f64::from(m) / 400.0;
                let e = Complex64::from_polar(1.0, phi);
                let shift = Complex64::new(1.0, 0.0) - 1.0 / e;
                let a1 = -c * shift;
                let a3 = -c * shift * (-1.0 / e + 5.0 + 2.0 * e) / 6.0;
                let n = a3 - a1;
                let (qa, qb, qc) = (
                    1.0 - theta * a1,
                    -(1.0 + (1.0 - theta) * a1 + 1.5 * n),
                    0.5 * n,
                );
                let root = (qb * qb - 4.0 * qa * qc).sqrt();
                let g1 = (-qb + root) / (2.0 * qa);
                let g2 = (-qb - root) / (2.0 * qa);
                g1.norm().max(g2.norm())
            })
            .fold(0.0, f64::max)
    }

    #[test]
    fn the_weight_keeps_the_advection_stable_at_any_courant_number() {
        for i in 1..=300 {
            let c = 0.02 * f64::from(i) * (1.0 + f64::from(i) / 30.0);
            let g = amplification(c, implicit_weight(c));
            assert!(g <= 1.0 + 1e-12, "Courant {c:.3}: |g| = {g}");
        }
        // Crank–Nicolson throughout would not be: the weight is needed.
        assert!(amplification(1.0, 0.5) > 1.05);
        assert!(amplification(0.5, 0.5) <= 1.0 + 1e-12);
        assert!((implicit_weight(0.4) - 0.5).abs() < 1e-15);
    }
}
