//! A viscous run's wall loads as CSV ([`SurfaceLoads`]): `s, x, y, cp,
//! cf_x, cf_y` (arc length and position in chords, global frame; the
//! pressure coefficient, `(p - p∞)` on `1/2 rho U^2`; the skin friction's
//! shear stress on the wall, `x` downstream, `y` up; all on
//! `1/2 rho U^2`), one row a wall node, counter-clockwise round the
//! section, after a comment line with the time.

use std::fmt::Write as _;
use std::path::Path;

use crate::aero2d::viscous::SurfaceLoads;
use crate::files::{write_new, WriteError};

/// Writes `surface` to `path`, a new file: an existing one is refused
/// ([`WriteError::Exists`]), never overwritten, and the file appears
/// whole ([`write_new`]).
///
/// # Errors
/// [`WriteError`]: the name is taken, or the file system refused.
pub fn write_surface_csv(surface: &SurfaceLoads, path: &Path) -> Result<(), WriteError> {
    let mut text = format!(
        "# wall loads at U t / c = {} (cp: p - p_inf on 1/2 rho U^2)\ns,x,y,cp,cf_x,cf_y\n",
        surface.time
    );
    for (((s, (x, y)), cp), (fx, fy)) in surface
        .arc
        .iter()
        .zip(&surface.points)
        .zip(&surface.cp)
        .zip(&surface.cf)
    {
        let _ = writeln!(text, "{s},{x},{y},{cp},{fx},{fy}");
    }
    write_new(path, text)
}
