//! A viscous run's wall loads as CSV ([`SurfaceLoads`]): `s, x, y, cp,
//! cf_x, cf_y` (arc length and position in chords, global frame; the
//! pressure coefficient, `(p - p∞)` on `1/2 rho U^2`; the skin friction's
//! shear stress on the wall, `x` downstream, `y` up; all on
//! `1/2 rho U^2`), one row a wall node, counter-clockwise round the
//! section, after a comment line with the time.

use std::io::Write;
use std::path::Path;

use crate::aero2d::viscous::SurfaceLoads;

/// Writes `surface` to `path`, a new file: an existing one is refused
/// (`ErrorKind::AlreadyExists`), never overwritten.
///
/// # Errors
/// The file system's.
pub fn write_surface_csv(surface: &SurfaceLoads, path: &Path) -> std::io::Result<()> {
    let file = std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)?;
    let mut out = std::io::BufWriter::new(file);
    writeln!(
        out,
        "# wall loads at U t / c = {} (cp: p - p_inf on 1/2 rho U^2)",
        surface.time
    )?;
    writeln!(out, "s,x,y,cp,cf_x,cf_y")?;
    for (((s, (x, y)), cp), (fx, fy)) in surface
        .arc
        .iter()
        .zip(&surface.points)
        .zip(&surface.cp)
        .zip(&surface.cf)
    {
        writeln!(out, "{s},{x},{y},{cp},{fx},{fy}")?;
    }
    out.flush()
}
