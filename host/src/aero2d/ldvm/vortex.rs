//! The LDVM's free vortices: a vortex with a Vatistas core, the velocity
//! it induces, and the far wake lumped for induction.

use std::f64::consts::PI;

/// A free vortex (counter-clockwise circulation positive).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FreeVortex {
    /// Position, chords.
    pub x: f64,
    /// Position, chords.
    pub y: f64,
    /// Circulation, U c.
    pub gamma: f64,
}

/// Far-wake vortices lumped together for induction.
pub(super) const FAR_GROUP: usize = 8;

/// Velocity induced at `(x, y)` by a ccw vortex with a Vatistas (n = 2)
/// core of squared radius `core2`. Beyond ten core radii the core changes
/// the kernel by less than 5e-5 relative, and the plain `1/r^2` kernel
/// (no square root) is used.
#[inline]
pub(crate) fn induced(v: &FreeVortex, x: f64, y: f64, core2: f64) -> (f64, f64) {
    let (dx, dy) = (x - v.x, y - v.y);
    let r2 = dx * dx + dy * dy;
    let denominator = if r2 > 100.0 * core2 {
        r2
    } else {
        (r2 * r2 + core2 * core2).sqrt()
    };
    let k = v.gamma / (2.0 * PI * denominator);
    (-dy * k, dx * k)
}

/// The far wake for induction: groups of [`FAR_GROUP`] consecutive
/// vortices as one, at their |Gamma|-weighted centroid with their total
/// circulation (their spread is small against their distance).
pub(super) fn far_proxies(far: &[FreeVortex]) -> impl Iterator<Item = FreeVortex> + '_ {
    far.chunks(FAR_GROUP).map(|group| {
        let weight: f64 = group
            .iter()
            .map(|v| v.gamma.abs())
            .sum::<f64>()
            .max(f64::MIN_POSITIVE);
        let x = group.iter().map(|v| v.x * v.gamma.abs()).sum::<f64>() / weight;
        let y = group.iter().map(|v| v.y * v.gamma.abs()).sum::<f64>() / weight;
        FreeVortex {
            x,
            y,
            gamma: group.iter().map(|v| v.gamma).sum(),
        }
    })
}

/// Index of the first vortex of the near wake: vortices are kept in
/// shedding order and drift downstream, so the far wake (beyond `limit`) is
/// a prefix.
pub(super) fn near_start(vortices: &[FreeVortex], limit: f64) -> usize {
    vortices
        .iter()
        .position(|v| v.x <= limit)
        .unwrap_or(vortices.len())
}
