//! The time-stepping solver: per step, the influence matrix of the bound
//! rings on the deformed surface, its dense LU solve for the bound
//! circulation with the wake's normal velocity on the right-hand side,
//! the loads, and (when committed) the shedding and convection of the wake
//! (Katz & Plotkin 2001, §13.12; their Program 16 for a rigid wing).
//!
//! The boundary condition at collocation point `p` with normal `n_p`:
//!
//! `Σ_q a_pq Γ_q = −(U∞ − v_surface(p) + v_wake(p)) · n_p`,
//!
//! `a_pq` the normal velocity at `p` of ring `q` of unit circulation (with
//! its mirror image in a symmetric model). The wake term uses the wake of
//! the last committed step behind the shed line of the surface being
//! solved, so [`Uvlm::solve`] can be repeated on updated shapes within a
//! step (fluid–structure iterations) before [`Uvlm::advance`] commits one.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::lu::partial_pivoting::{factor, solve};
use faer::{Conj, Mat, Par};
use nalgebra::Vector3;
use rayon::prelude::*;

use super::lattice::{all_finite, bilinear, Lattice};
use super::loads::{all_segments, loads, Solution};
use super::rings::{shed_line, BoundRings};
use super::settings::UvlmSettings;
use super::vortex::{induced_velocities, mirror, ring_velocity};
use super::wake::WakeSheet;
use super::UvlmError;

/// Unsteady vortex-lattice solver state: the wake sheet, the circulation
/// committed at the last two steps (for `∂Φ/∂t`) and the time.
#[derive(Debug, Clone)]
pub struct Uvlm {
    chordwise: usize,
    spanwise: usize,
    settings: UvlmSettings,
    wake: WakeSheet,
    previous: Vec<f64>,
    /// The circulation committed one step before `previous` (for the
    /// second-order `∂Φ/∂t`), once two steps have been committed.
    older: Option<Vec<f64>>,
    time: f64,
    steps: usize,
}

impl Uvlm {
    /// A solver for lattices of `chordwise x spanwise` panels, at time 0
    /// with no wake and zero circulation (so the first step is an
    /// impulsive start). Checks the settings.
    pub fn new(
        chordwise: usize,
        spanwise: usize,
        settings: UvlmSettings,
    ) -> Result<Self, UvlmError> {
        if chordwise == 0 || spanwise == 0 {
            return Err(UvlmError::EmptyLattice {
                chordwise,
                spanwise,
            });
        }
        settings.validate()?;
        Ok(Self {
            chordwise,
            spanwise,
            wake: WakeSheet::new(spanwise),
            previous: vec![0.0; chordwise * spanwise],
            older: None,
            settings,
            time: 0.0,
            steps: 0,
        })
    }

    /// The settings.
    pub fn settings(&self) -> &UvlmSettings {
        &self.settings
    }

    /// The wake sheet (corner points and ring circulations, for output).
    pub fn wake(&self) -> &WakeSheet {
        &self.wake
    }

    /// Time of the next solve, s (0 at the start, `dt` more per
    /// [`Uvlm::advance`]).
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Steps committed so far.
    pub fn steps(&self) -> usize {
        self.steps
    }

    /// The circulation committed at the last step, m²/s per panel.
    pub fn previous_circulation(&self) -> &[f64] {
        &self.previous
    }

    fn check(&self, surface: &Lattice, corner_velocity: &[Vector3<f64>]) -> Result<(), UvlmError> {
        if surface.chordwise != self.chordwise || surface.spanwise != self.spanwise {
            return Err(UvlmError::Dimensions {
                chordwise: self.chordwise,
                spanwise: self.spanwise,
                got_chordwise: surface.chordwise,
                got_spanwise: surface.spanwise,
            });
        }
        if surface.corners.len() != surface.corner_count() {
            return Err(UvlmError::CornerCount {
                chordwise: surface.chordwise,
                spanwise: surface.spanwise,
                got: surface.corners.len(),
                expected: surface.corner_count(),
            });
        }
        if corner_velocity.len() != surface.corner_count() {
            return Err(UvlmError::Length {
                what: "corner velocities",
                got: corner_velocity.len(),
                expected: surface.corner_count(),
            });
        }
        // The fields are public, so a lattice may have been edited after
        // `Lattice::new` checked it.
        if let Some(index) = surface.corners.iter().position(|c| !all_finite(c)) {
            return Err(UvlmError::NonFinite {
                what: "corner",
                index,
            });
        }
        if let Some(index) = corner_velocity.iter().position(|c| !all_finite(c)) {
            return Err(UvlmError::NonFinite {
                what: "corner velocity",
                index,
            });
        }
        for i in 0..surface.chordwise {
            for j in 0..surface.spanwise {
                if surface.area(i, j) == 0.0 {
                    return Err(UvlmError::DegeneratePanel { i, j });
                }
            }
        }
        Ok(())
    }

    /// Bound circulation and loads of `surface` (at the time
    /// [`Uvlm::time`]) moving with `corner_velocity` (inertial frame, m/s,
    /// indexed like the corners), with the current wake. Does not change
    /// the state.
    pub fn solve(
        &self,
        surface: &Lattice,
        corner_velocity: &[Vector3<f64>],
    ) -> Result<Solution, UvlmError> {
        self.check(surface, corner_velocity)?;
        let s = &self.settings;
        let (nc, ns) = (self.chordwise, self.spanwise);
        let n = nc * ns;
        let shed = shed_line(surface, corner_velocity, &s.freestream, s.dt, s.shed_offset);
        let rings = BoundRings::new(surface, corner_velocity, &shed);
        let panels: Vec<(usize, usize)> =
            (0..nc).flat_map(|i| (0..ns).map(move |j| (i, j))).collect();
        let collocation: Vec<_> = panels
            .iter()
            .map(|&(i, j)| surface.collocation_point(i, j))
            .collect();
        let normals: Vec<_> = panels.iter().map(|&(i, j)| surface.normal(i, j)).collect();
        let ring_corners: Vec<_> = panels.iter().map(|&(i, j)| rings.ring(ns, i, j)).collect();
        // Influence matrix, one row per collocation point, in parallel.
        let (core, symmetric) = (s.core_radius, s.symmetric);
        let rows: Vec<Vec<f64>> = collocation
            .par_iter()
            .zip(&normals)
            .map(|(p, normal)| {
                let image = mirror(p);
                ring_corners
                    .iter()
                    .map(|ring| {
                        let mut v = ring_velocity(ring, 1.0, p, core);
                        if symmetric {
                            // The image ring has the opposite orientation:
                            // its velocity at p is M q(M p).
                            v += mirror(&ring_velocity(ring, 1.0, &image, core));
                        }
                        v.dot(normal)
                    })
                    .collect()
            })
            .collect();
        let a = Mat::from_fn(n, n, |p, q| rows[p][q]);
        let wake_segments = self.wake.segments_behind(&shed);
        let wake_velocity = induced_velocities(&wake_segments, &collocation, core, symmetric);
        let rhs = Mat::from_fn(n, 1, |p, _| {
            let (i, j) = panels[p];
            let corners = [(0, 0), (1, 0), (1, 1), (0, 1)]
                .map(|(di, dj)| corner_velocity[surface.corner_index(i + di, j + dj)]);
            let surface_velocity = bilinear(&corners, 0.75, 0.5);
            -(s.freestream - surface_velocity + wake_velocity[p]).dot(&normals[p])
        });
        let gamma = lu_solve(a, rhs);
        let circulation: Vec<f64> = (0..n).map(|p| gamma[(p, 0)]).collect();
        if circulation.iter().any(|g| !g.is_finite()) {
            return Err(UvlmError::Singular);
        }
        Ok(loads(
            surface,
            corner_velocity,
            &rings,
            circulation,
            &self.previous,
            self.older.as_deref(),
            &self.wake,
            s,
            shed,
        ))
    }

    /// Commits `solution`, computed by [`Uvlm::solve`] for `surface`: sheds
    /// a wake row carrying the trailing-edge circulation (Kutta condition),
    /// convects the wake over `dt` (the youngest `free_wake_rows` point
    /// rows with the velocity induced by the surface, its wake and their
    /// images plus the freestream, evaluated on the committed state; the
    /// older rows with the freestream), truncates it to `wake_rows`,
    /// stores the circulation for the next `∂Γ/∂t` and advances the time.
    pub fn advance(&mut self, surface: &Lattice, solution: &Solution) -> Result<(), UvlmError> {
        let (nc, ns) = (self.chordwise, self.spanwise);
        let s = &self.settings;
        let zero_velocity = vec![Vector3::zeros(); surface.corner_count()];
        self.check(surface, &zero_velocity)?;
        for (what, got, expected) in [
            ("circulation", solution.circulation.len(), nc * ns),
            ("shed line", solution.shed_line.len(), ns + 1),
        ] {
            if got != expected {
                return Err(UvlmError::Length {
                    what,
                    got,
                    expected,
                });
            }
        }
        // Ring velocities are not needed for the induced field; only the
        // ring positions matter here.
        let rings = BoundRings::new(surface, &zero_velocity, &solution.shed_line);
        let mut points = self.wake.points_behind(&solution.shed_line);
        if points.is_empty() {
            points = solution.shed_line.clone();
        }
        let width = ns + 1;
        let free_points = points.len().min(s.free_wake_rows.saturating_mul(width));
        let segments = all_segments(surface, &rings, &solution.circulation, &self.wake);
        let induced = induced_velocities(
            &segments,
            &points[..free_points],
            s.core_radius,
            s.symmetric,
        );
        let mut displacement = vec![s.freestream * s.dt; points.len()];
        for (d, v) in displacement.iter_mut().zip(&induced) {
            *d += v * s.dt;
        }
        let trailing = solution.circulation[(nc - 1) * ns..].to_vec();
        self.wake
            .shed(&solution.shed_line, &trailing, &displacement, s.wake_rows)?;
        let previous = std::mem::replace(&mut self.previous, solution.circulation.clone());
        // Step 1's previous circulation is the rest state before an
        // impulsive start, not a solution: the second-order difference
        // starts from the third step.
        if self.steps >= 1 {
            self.older = Some(previous);
        }
        self.steps += 1;
        self.time = self.steps as f64 * s.dt;
        Ok(())
    }
}

/// Solves `a x = rhs` by faer's dense LU with partial pivoting, run
/// sequentially on the calling thread. Why not `Mat::partial_piv_lu`:
/// that follows faer's global parallelism, whose kernels run on `spindle`
/// worker threads that spin while waiting for work; on the 2-core test
/// machine the rayon-parallel Biot–Savart sums after one parallel faer
/// factorization ran 4x slower (27 instead of 7 ns a segment pair) from
/// then on. A matrix of a few hundred unknowns gains nothing from a
/// parallel factorization anyway.
fn lu_solve(mut a: Mat<f64>, mut rhs: Mat<f64>) -> Mat<f64> {
    let n = a.nrows();
    let (mut forward, mut backward) = (vec![0usize; n], vec![0usize; n]);
    let mut scratch = MemBuffer::new(
        factor::lu_in_place_scratch::<usize, f64>(n, n, Par::Seq, Default::default()).or(
            solve::solve_in_place_scratch::<usize, f64>(n, rhs.ncols(), Par::Seq),
        ),
    );
    let stack = MemStack::new(&mut scratch);
    let (_, permutation) = factor::lu_in_place(
        a.as_mut(),
        &mut forward,
        &mut backward,
        Par::Seq,
        stack,
        Default::default(),
    );
    // The factors share the matrix: L below the diagonal (unit diagonal
    // implied), U on and above it.
    let lower = Mat::from_fn(n, n, |i, j| match i.cmp(&j) {
        std::cmp::Ordering::Greater => a[(i, j)],
        std::cmp::Ordering::Equal => 1.0,
        std::cmp::Ordering::Less => 0.0,
    });
    let upper = Mat::from_fn(n, n, |i, j| if i <= j { a[(i, j)] } else { 0.0 });
    solve::solve_in_place_with_conj(
        lower.as_ref(),
        upper.as_ref(),
        permutation,
        Conj::No,
        rhs.as_mut(),
        Par::Seq,
        stack,
    );
    rhs
}
