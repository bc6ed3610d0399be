//! The flow of a viscous run at one instant on the grid's nodes: what
//! `fwav aero2d --model ns --field FILE.vtu` (the run's end) and
//! `--field-series DIR` (instants through the run) write for ParaView
//! (`crate::output::flow_field_vtu`); and what takes a run's flows as it
//! reaches them ([`FrameSink`]).

use fwav_ns2d::{Complex64, Flow, OGrid};

use super::SectionPath;

/// The flow at one instant on every node of the grid, in the global
/// frame of [`crate::aero2d::case`] (chords; the picture's frame, the
/// section pitched and plunged), in the run's units (lengths in chords,
/// speeds in the reference speed of its Reynolds number).
///
/// The nodes are stored ring by ring from the wall out: node `k` of
/// ring `j` is `j * around + k`, ring 0 the wall, the last ring the
/// outer boundary; round each ring `k` runs the way the grid's angle
/// does and wraps from `around - 1` to 0.
#[derive(Clone, Debug, PartialEq)]
pub struct FlowField {
    /// The time, chords travelled from the run's start.
    pub time: f64,
    /// Nodes round each ring.
    pub around: usize,
    /// Rings, the wall's included.
    pub rings: usize,
    /// Each node's position, `(x, y)`.
    pub points: Vec<(f64, f64)>,
    /// The vorticity at each node (the absolute vorticity, the same in
    /// any frame that does not turn; on the wall, the no-slip wall's).
    pub vorticity: Vec<f64>,
    /// The streamfunction at each node of the fluid's velocity relative
    /// to the air at rest far away (zero on the outer ring; `u = ∂ψ/∂y`,
    /// `v = -∂ψ/∂x` in these axes: a streamfunction does not change when
    /// the axes turn).
    pub streamfunction: Vec<f64>,
    /// The fluid's velocity at each node relative to the air at rest far
    /// away, `(u, v)` in these axes: `u + iv = -i (ψ_ξ + i ψ_θ) /
    /// conj(∂z/∂ξ)` on the grid's conformal map (`fwav_ns2d::OGrid::velocity`,
    /// the formula the solver's outer ring takes), turned from the
    /// solver's axes into these.
    pub velocity: Vec<(f64, f64)>,
}

impl FlowField {
    /// The field of `flow`, which runs `path`, at its current time.
    /// Cost `O(N)`, a copy of the grid.
    pub(super) fn of(flow: &Flow<SectionPath>, path: &SectionPath) -> Self {
        let g = flow.grid();
        let place = path.placement(flow.time());
        Self {
            time: flow.time(),
            around: g.nt,
            rings: g.nr,
            points: g.z.iter().map(|&z| place(z)).collect(),
            vorticity: flow.vorticity().to_vec(),
            streamfunction: flow.streamfunction().to_vec(),
            velocity: velocity(g, flow.streamfunction(), &place),
        }
    }

    /// The grid's cells as quadrilaterals of node indices, each in the
    /// order ring `j` node `k`, node `k + 1`, then ring `j + 1` node
    /// `k + 1`, node `k`: `(rings - 1) × around` cells, the last of each
    /// ring closing it round.
    #[must_use]
    pub fn quads(&self) -> Vec<[usize; 4]> {
        let n = self.around;
        (0..self.rings.saturating_sub(1))
            .flat_map(|j| {
                (0..n).map(move |k| {
                    let next = (k + 1) % n;
                    [j * n + k, j * n + next, (j + 1) * n + next, (j + 1) * n + k]
                })
            })
            .collect()
    }
}

/// What takes a run's flows as it steps
/// ([`super::ViscousSection::field_frames`],
/// [`super::ViscousSection::run_into`]): each in time order, the last at
/// the run's end. A sink that writes each to disk at once keeps the
/// memory to one flow, and a run that fails keeps the flows it had. The
/// sink is also told how far the run has come ([`Self::reached`]), for a
/// progress display.
pub trait FrameSink {
    /// Takes the flow at one instant.
    ///
    /// # Errors
    /// Any: the run stops with [`super::ViscousError::Frame`].
    fn take(&mut self, frame: &FlowField) -> Result<(), Box<dyn std::error::Error + Send + Sync>>;

    /// The run has reached `time` of its `duration` (chords travelled):
    /// called after each step that passes one or more of the run's load
    /// samples (200 a period, or 2,000 a run without one), in time order.
    /// Nothing by default.
    fn reached(&mut self, time: f64, duration: f64) {
        let _ = (time, duration);
    }
}

/// The flows let go as they come: what [`super::ViscousSection::run`]
/// and the runs without a sink hand theirs to.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoFrames;

impl FrameSink for NoFrames {
    fn take(&mut self, _: &FlowField) -> Result<(), Box<dyn std::error::Error + Send + Sync>> {
        Ok(())
    }
}

/// The flows kept in memory.
impl FrameSink for Vec<FlowField> {
    fn take(&mut self, frame: &FlowField) -> Result<(), Box<dyn std::error::Error + Send + Sync>> {
        self.push(frame.clone());
        Ok(())
    }
}

/// The velocity at every node of `grid` of the streamfunction `psi`
/// ([`FlowField::velocity`]), turned as `place` turns the grid into the
/// field's axes. Cost `O(N)`.
fn velocity(
    grid: &OGrid,
    psi: &[f64],
    place: &impl Fn(Complex64) -> (f64, f64),
) -> Vec<(f64, f64)> {
    let (nt, nr) = (grid.nt, grid.nr);
    // Where the solver's unit vectors point in the field's axes.
    let origin = place(Complex64::new(0.0, 0.0));
    let along = |z: Complex64| {
        let p = place(z);
        (p.0 - origin.0, p.1 - origin.1)
    };
    let (ex, ey) = (
        along(Complex64::new(1.0, 0.0)),
        along(Complex64::new(0.0, 1.0)),
    );
    let mut out = Vec::with_capacity(nt * nr);
    for j in 0..nr {
        for k in 0..nt {
            let w = grid.velocity(psi, j, k);
            out.push((w.re * ex.0 + w.im * ey.0, w.re * ex.1 + w.im * ey.1));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Three rings of four nodes: eight cells, each ring closed round, and
    /// every node in a cell.
    #[test]
    fn the_cells_close_each_ring() {
        let field = FlowField {
            time: 0.0,
            around: 4,
            rings: 3,
            points: vec![(0.0, 0.0); 12],
            vorticity: vec![0.0; 12],
            streamfunction: vec![0.0; 12],
            velocity: vec![(0.0, 0.0); 12],
        };
        let quads = field.quads();
        assert_eq!(quads.len(), 8);
        assert_eq!(quads[3], [3, 0, 4, 7]);
        assert_eq!(quads[7], [7, 4, 8, 11]);
        let mut used = [false; 12];
        for q in &quads {
            for &i in q {
                used[i] = true;
            }
        }
        assert!(used.iter().all(|&u| u));
    }
}
