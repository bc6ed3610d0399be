//! What a Navier–Stokes run will take, told before it starts: the memory
//! of its grid's flow and the disk of its `--field-series`, from the
//! grid's nodes, measured. `fwav aero2d --model ns` prints the estimate of
//! a run far beyond the default grid's ([`ViscousCost::is_far_beyond_default`])
//! and runs it only with `--yes`: the grid's limits (16 to 8192 nodes
//! each way) let a run ask for more memory than the machine has (8192 ×
//! 8192 nodes: some 27 GB).
//!
//! Measured (2026-12-07, the peak resident memory of the whole process,
//! `/usr/bin/time`, of `fwav aero2d --model ns --duration 0.02` on the
//! default flat plate; the grid's nodes round × out):
//!
//! | grid | nodes | peak memory |
//! | --- | ---: | ---: |
//! | 384 × 256 (the default) | 98,304 | 43 MB |
//! | 768 × 512 | 393,216 | 147 MB |
//! | 1536 × 1024 | 1,572,864 | 604 MB |
//! | 1024 × 2048 | 2,097,152 | 710 MB |
//!
//! 330 to 390 bytes a node past the default (the flow's whole-grid
//! arrays, the grid's metrics, the sweeps' line storage; the more round,
//! the more, as the wall's influence matrix grows as the square of the
//! nodes round), which [`BYTES_PER_NODE`] rounds up; the loads' histories add a few MB a
//! thousand chords. A frame of the field series is 5.2 MB on the default
//! grid (the grid and four fields in single precision,
//! [`SERIES_BYTES_PER_NODE`]).

use std::fmt;

use super::ViscousSection;

/// Resident memory a grid node, bytes (module docs).
pub const BYTES_PER_NODE: f64 = 400.0;

/// Resident memory of the program besides the grid, bytes.
const BASE_BYTES: f64 = 10e6;

/// Disk a grid node takes in a frame of `--field-series`, bytes: 5.2 MB
/// for the 98,304 nodes of the default grid.
pub const SERIES_BYTES_PER_NODE: f64 = 53.0;

/// A run is far beyond the default above this much memory, bytes (4 GB,
/// as for a design run: `crate::config::cost::FAR_MEMORY`).
pub const FAR_MEMORY: f64 = crate::config::cost::FAR_MEMORY;

/// ... or this many times the default grid's nodes (each node costs its
/// arithmetic every step, and a finer grid takes shorter steps too).
pub const FAR_NODES_RATIO: f64 = 16.0;

/// ... or above this much disk for its field series, bytes (20 GB).
pub const FAR_SERIES: f64 = 20e9;

/// The estimated cost of a Navier–Stokes run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViscousCost {
    /// Grid nodes, round × out.
    pub nodes: usize,
    /// Peak memory, bytes.
    pub memory_bytes: f64,
    /// Disk of the field series, bytes (0 without one).
    pub series_bytes: f64,
}

/// Nodes of the default grid.
fn default_nodes() -> usize {
    ViscousSection::DEFAULT_AROUND * ViscousSection::DEFAULT_RADIAL
}

/// Peak memory of a run on `nodes` grid nodes, bytes (module docs).
fn memory_bytes(nodes: usize) -> f64 {
    BASE_BYTES + BYTES_PER_NODE * nodes as f64
}

impl ViscousCost {
    /// The estimate for `section` (module docs), its `field_frames`
    /// frames included.
    pub fn of(section: &ViscousSection) -> Self {
        let nodes = section.around * section.radial;
        Self {
            nodes,
            memory_bytes: memory_bytes(nodes),
            series_bytes: SERIES_BYTES_PER_NODE * (nodes * section.field_frames) as f64,
        }
    }

    /// The nodes over the default grid's.
    pub fn nodes_ratio(&self) -> f64 {
        self.nodes as f64 / default_nodes() as f64
    }

    /// Whether the run is far beyond the default grid's: more than
    /// [`FAR_MEMORY`], [`FAR_NODES_RATIO`] times its nodes or
    /// [`FAR_SERIES`] of frames.
    pub fn is_far_beyond_default(&self) -> bool {
        self.memory_bytes > FAR_MEMORY
            || self.nodes_ratio() > FAR_NODES_RATIO
            || self.series_bytes > FAR_SERIES
    }
}

impl fmt::Display for ViscousCost {
    /// `about 26.9 GB of memory for 67108864 grid nodes (683 times the
    /// default grid's 98304, which take 0.05 GB; …), and 20.8 GB of disk
    /// for the field series`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "about {:.1} GB of memory for {} grid nodes ({:.0} times the default grid's {}, \
             which take {:.2} GB; each node costs its arithmetic every step, and a finer grid \
             takes shorter steps)",
            self.memory_bytes / 1e9,
            self.nodes,
            self.nodes_ratio(),
            default_nodes(),
            memory_bytes(default_nodes()) / 1e9,
        )?;
        if self.series_bytes > 0.0 {
            write!(
                f,
                ", and {:.1} GB of disk for the field series",
                self.series_bytes / 1e9
            )?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aero2d::viscous::ViscousShape;

    fn grid(around: usize, radial: usize, frames: usize) -> ViscousCost {
        let plate = ViscousSection::new(ViscousShape::Plate(0.04));
        ViscousCost::of(&ViscousSection {
            around,
            field_frames: frames,
            ..plate.with_radial(radial)
        })
    }

    /// The estimate against the peaks measured (module docs): within a
    /// fifth above each, never below; the default grid is not far beyond
    /// itself, and the largest grid the limits allow, a series of many
    /// frames and a grid of many nodes are.
    #[test]
    fn the_estimate_bounds_the_measured_memory() {
        for (around, radial, measured_mb) in [
            (384, 256, 43.0),
            (768, 512, 147.0),
            (1536, 1024, 604.0),
            (1024, 2048, 710.0),
        ] {
            let estimate = grid(around, radial, 0).memory_bytes / 1e6;
            assert!(
                (measured_mb..=1.2 * f64::max(measured_mb, 50.0)).contains(&estimate),
                "{around} x {radial}: {estimate:.0} MB against {measured_mb} MB measured"
            );
        }
        assert!(!grid(384, 256, 0).is_far_beyond_default());
        assert!(!grid(384, 256, 500).is_far_beyond_default());
        let largest = grid(8192, 8192, 0);
        assert!(largest.is_far_beyond_default());
        assert!(largest.memory_bytes > 20e9, "{largest}");
        let series = grid(1536, 512, 500);
        assert!(series.memory_bytes < FAR_MEMORY && series.is_far_beyond_default());
        assert!(series.to_string().contains("GB of disk"), "{series}");
        assert!(grid(2048, 1024, 0).is_far_beyond_default());
    }
}
