//! ParaView output of a system analysis: the deformed wing (with the
//! pressure jump per element) and its wake (with the ring strengths) at the
//! kept snapshots, as `.vtu` files and one `.pvd` time collection each, so
//! ParaView plays the cycle.

use std::path::{Path, PathBuf};

use crate::aeroelastic::analysis::Snapshot;
use crate::files::Existing;
use crate::shell::mesh::ShellMesh;

use super::vtu::{self, Field, VtuError};

/// Writes `wing-NNNN.vtu`, `wake-NNNN.vtu`, `wing.pvd` and `wake.pvd` into
/// `dir` (created if missing), over files there or not as `existing`
/// says; `elements` are the shell elements. Returns the two `.pvd` paths.
pub fn write_series(
    dir: &Path,
    elements: &[[usize; 4]],
    snapshots: &[Snapshot],
    existing: Existing,
) -> Result<[PathBuf; 2], VtuError> {
    let io = |path: &Path, source| VtuError::Io {
        path: path.display().to_string(),
        source,
    };
    std::fs::create_dir_all(dir).map_err(|e| io(dir, e))?;
    let mut wing_entries = Vec::new();
    let mut wake_entries = Vec::new();
    for (k, s) in snapshots.iter().enumerate() {
        let wing = ShellMesh {
            nodes: s.nodes.clone(),
            elements: elements.to_vec(),
        };
        let name = format!("wing-{k:04}.vtu");
        vtu::write(
            &dir.join(&name),
            &wing,
            &[Field::CellScalar("pressure_jump_pa", &s.element_pressure)],
            existing,
        )?;
        wing_entries.push((s.time, name));
        let (wake, strength) = wake_mesh(s);
        let name = format!("wake-{k:04}.vtu");
        vtu::write(
            &dir.join(&name),
            &wake,
            &[Field::CellScalar("circulation_m2_s", &strength)],
            existing,
        )?;
        wake_entries.push((s.time, name));
    }
    let wing_pvd = dir.join("wing.pvd");
    let wake_pvd = dir.join("wake.pvd");
    for (path, entries) in [(&wing_pvd, &wing_entries), (&wake_pvd, &wake_entries)] {
        crate::files::write_to(path, vtu::collection(entries), existing)?;
    }
    Ok([wing_pvd, wake_pvd])
}

/// The wake rings as a quad mesh (one quad a ring) and their strengths.
fn wake_mesh(s: &Snapshot) -> (ShellMesh, Vec<f64>) {
    let mut nodes = Vec::new();
    let mut elements = Vec::new();
    let mut strength = Vec::new();
    let rows = &s.wake_corners;
    for (r, pair) in rows.windows(2).enumerate() {
        let width = pair[0].len().min(pair[1].len());
        let base = nodes.len();
        nodes.extend_from_slice(&pair[0][..width]);
        nodes.extend_from_slice(&pair[1][..width]);
        for j in 0..width.saturating_sub(1) {
            elements.push([
                base + j,
                base + width + j,
                base + width + j + 1,
                base + j + 1,
            ]);
            strength.push(
                s.wake_strength
                    .get(r)
                    .and_then(|v| v.get(j))
                    .copied()
                    .unwrap_or(0.0),
            );
        }
    }
    (ShellMesh { nodes, elements }, strength)
}
