//! The LDVM's free vortices: a vortex with a Vatistas core, the velocity
//! it induces, the far wake lumped for induction, and the step's sources
//! of induced velocity.

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

/// The free vortices that induce velocity during one step: the near wakes
/// vortex by vortex, the far wakes as proxies.
pub(super) struct Sources {
    /// First near vortex of the trailing-edge wake.
    pub(super) near_from: usize,
    /// First near vortex of the leading-edge vortices.
    pub(super) lev_near_from: usize,
    /// The near vortices, then the far wakes' proxies.
    pub(super) vortices: Vec<FreeVortex>,
}

impl Sources {
    /// The sources of the trailing-edge `wake` and the `leading`-edge
    /// vortices: those up to `limit` downstream one by one, those beyond
    /// as [`far_proxies`].
    pub(super) fn split(wake: &[FreeVortex], leading: &[FreeVortex], limit: f64) -> Self {
        let near_from = near_start(wake, limit);
        let lev_near_from = near_start(leading, limit);
        let vortices = wake[near_from..]
            .iter()
            .chain(&leading[lev_near_from..])
            .copied()
            .chain(far_proxies(&wake[..near_from]))
            .chain(far_proxies(&leading[..lev_near_from]))
            .collect();
        Self {
            near_from,
            lev_near_from,
            vortices,
        }
    }

    /// Velocity induced at `(x, y)`, each vortex with its squared core
    /// from `cores2` (in the order of `vortices`: the vortices' own,
    /// `repeat(core2)`, or the chord's stations', `Chord::core2`).
    pub(super) fn induced_at(
        &self,
        x: f64,
        y: f64,
        cores2: impl IntoIterator<Item = f64>,
    ) -> (f64, f64) {
        let (mut u, mut v) = (0.0, 0.0);
        for (fv, core2) in self.vortices.iter().zip(cores2) {
            let (du, dv) = induced(fv, x, y, core2);
            u += du;
            v += dv;
        }
        (u, v)
    }
}

/// Index of the first vortex of the near wake: vortices are kept in
/// shedding order and drift downstream, so the far wake (beyond `limit`) is
/// a prefix.
fn near_start(vortices: &[FreeVortex], limit: f64) -> usize {
    vortices
        .iter()
        .position(|v| v.x <= limit)
        .unwrap_or(vortices.len())
}
