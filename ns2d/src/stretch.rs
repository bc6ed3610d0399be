//! The radial stretching `ξ = g(η)` that places the O-grid's rings.
//!
//! Two are offered:
//! - [`RadialStretch`], exponential: every cell a constant ratio larger
//!   than the one inside it, from a given first cell at the wall to the
//!   outer boundary. `g''/g'` is a constant.
//! - [`TailedStretch`]: the exponential of a finer grid ([`FarStretch`]'s
//!   `near_radial` rings) near the wall, the same rings but for the
//!   turn's smooth onset (`ξ` 0.025 % larger forty rings inside the turn,
//!   0.25 % twenty rings inside, on a grid like the default's), then a
//!   faster growth (`growth` a cell) to the outer boundary. It keeps
//!   the near field's resolution on fewer rings by coarsening only the
//!   far field, where the wake has spread and decayed. On the default FWAV
//!   section it keeps the 320-ring exponential grid's cells to about 0.8
//!   chords on 256 rings, and the long mean of the thrust within 0.2 %
//!   (the host's `ViscousSection::new`).
//!
//! The solver takes `g'` and `g''/g'` at every ring
//! ([`RingSpacing`]), so any smooth stretching is one more constructor
//! here.

use crate::error::NsError;

/// `ξ = g(η) = A (exp(sη) - 1)`: exponential growth of the radial cells
/// from a given first cell at the wall to a given outer radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RadialStretch {
    amplitude: f64,
    rate: f64,
}

impl RadialStretch {
    /// The stretching with `g(1) = xi_max` and a first cell of `first_cell`
    /// in `ξ`, `g'(0) Δη`, on `cells` uniform `η` intervals (Newton on
    /// `(e^s - 1)/s = xi_max / (cells first_cell)`).
    ///
    /// # Errors
    /// [`NsError::NoStretching`] when the first cell is not finer than a
    /// uniform grid's.
    pub fn new(xi_max: f64, first_cell: f64, cells: usize) -> Result<Self, NsError> {
        let uniform = xi_max / cells as f64;
        let ratio = uniform / first_cell;
        if ratio.is_nan() || ratio <= 1.0 + 1e-9 {
            return Err(NsError::NoStretching {
                first: first_cell,
                uniform,
            });
        }
        // f(s) = (e^s - 1)/s - ratio is convex and increasing for s > 0.
        let mut s = 2.0 * ratio.ln().max(0.1);
        for _ in 0..100 {
            let e = s.exp();
            let f = (e - 1.0) / s - ratio;
            let df = (s * e - (e - 1.0)) / (s * s);
            let next = s - f / df;
            let next = if next <= 0.0 { 0.5 * s } else { next };
            if (next - s).abs() < 1e-14 * s {
                s = next;
                break;
            }
            s = next;
        }
        Ok(Self {
            amplitude: xi_max / s.exp_m1(),
            rate: s,
        })
    }

    /// `g(η)`.
    #[must_use]
    pub fn xi(&self, eta: f64) -> f64 {
        self.amplitude * (self.rate * eta).exp_m1()
    }

    /// `g'(η)`.
    #[must_use]
    pub fn slope(&self, eta: f64) -> f64 {
        self.amplitude * self.rate * (self.rate * eta).exp()
    }

    /// `g''(η)/g'(η)` (a constant for the exponential).
    #[must_use]
    pub fn curvature(&self) -> f64 {
        self.rate
    }

    /// The ratio of each cell to the one inside it on `cells` intervals,
    /// `exp(s / cells)`.
    #[must_use]
    pub fn growth(&self, cells: usize) -> f64 {
        (self.rate / cells as f64).exp()
    }
}

/// A grid's far field coarsened ([`TailedStretch`]): the rings near the
/// wall are those of the exponential grid of `near_radial` rings (the
/// same first cell and outer boundary); past them the cells grow by
/// `growth` a cell.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FarStretch {
    /// Rings (wall and outer boundary included) of the exponential grid
    /// whose rings are kept near the wall: more than the grid's own.
    pub near_radial: usize,
    /// Each far cell over the one inside it (more than the near grid's
    /// growth; at most [`MAX_FAR_GROWTH`]).
    pub growth: f64,
}

/// The most a far cell may grow on the one inside it
/// ([`FarStretch::growth`]): past it the far rings are too coarse to
/// carry the wake out.
pub const MAX_FAR_GROWTH: f64 = 1.5;

impl FarStretch {
    /// The same stretching on `radial` rings where this one has `from`
    /// (a refinement or a coarsening by `r = (radial - 1)/(from - 1)`
    /// in `η`): `near_radial - 1` cells scaled by `r`, the far growth
    /// raised to `1/r`.
    #[must_use]
    pub fn scaled(&self, from: usize, radial: usize) -> Self {
        let r = (radial.max(2) - 1) as f64 / (from.max(2) - 1) as f64;
        Self {
            near_radial: (self.near_radial.saturating_sub(1) as f64 * r).round() as usize + 1,
            growth: self.growth.powf(1.0 / r),
        }
    }

    /// The fewest rings to which a grid of `radial` rings with this
    /// stretching can be coarsened as a whole ([`Self::scaled`]) with its
    /// far cells growing by at most [`MAX_FAR_GROWTH`]:
    /// `growth^((radial - 1)/(m - 1)) ≤ MAX_FAR_GROWTH` (29 for the
    /// host's default of 256 rings growing by 1.045).
    pub fn fewest_rings(&self, radial: usize) -> usize {
        let cells = (radial.max(2) - 1) as f64 * self.growth.ln() / MAX_FAR_GROWTH.ln();
        // ceil, less a rounding's worth, so that an exact fit is kept.
        (cells - 1e-9).ceil().max(1.0) as usize + 1
    }
}

/// How sharply (in `η`) a [`TailedStretch`] turns from the near growth
/// to the far one: over about `1/TURN_SHARPNESS` of the rings (8 of
/// 256).
const TURN_SHARPNESS: f64 = 30.0;

/// Simpson intervals a cell for a [`TailedStretch`]'s `ξ`: `g'` varies
/// by a few per cent over a cell, so `ξ` is exact to rounding.
const SIMPSON_INTERVALS: usize = 32;

/// `ln g'(η) = ln g'_0 + s₁ η + (s₃/k) softplus(k (η - η₂))`: the near
/// grid's exponential growth `s₁` (each cell `exp(s₁ Δη)` the one
/// inside), turning smoothly at `η₂` to `s₁ + s₃` (each cell
/// [`FarStretch::growth`] the one inside). `g'_0 Δη` is the near grid's
/// first cell (so ring `j` is the near grid's ring `j` but for the
/// turn's onset), and `η₂` is found by bisection so that `g(1) = ξ_max`.
/// `g''/g' = s₁ + s₃ σ(k (η - η₂))`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TailedStretch {
    ln_first_slope: f64,
    near_rate: f64,
    far_rate: f64,
    turn: f64,
}

impl TailedStretch {
    /// The stretching of `cells` uniform `η` intervals with a first cell
    /// of `first_cell` and `g(1) = xi_max`, as `far` says. Cost: a
    /// bisection of 60 Simpson integrations (a few ms).
    ///
    /// # Errors
    /// [`NsError::NoStretching`] when the first cell is not finer than
    /// the near grid's uniform one; [`NsError::BadGrid`] when the near
    /// grid has no more rings than this one, or the far growth is not
    /// above the near one (or above [`MAX_FAR_GROWTH`]); [`NsError::NoTail`] when these
    /// rings cannot reach the outer boundary at that growth.
    pub fn new(
        xi_max: f64,
        first_cell: f64,
        cells: usize,
        far: FarStretch,
    ) -> Result<Self, NsError> {
        let near_cells = far.near_radial.saturating_sub(1);
        if near_cells <= cells {
            return Err(NsError::BadGrid {
                what: "far stretch's near_radial (must exceed the grid's radial)",
                value: far.near_radial as f64,
                min: (cells + 2) as f64,
                max: 8192.0,
            });
        }
        let near = RadialStretch::new(xi_max, first_cell, near_cells)?;
        let near_growth = near.growth(near_cells);
        if !(far.growth > near_growth && far.growth <= MAX_FAR_GROWTH) {
            return Err(NsError::BadGrid {
                what: "far stretch's growth",
                value: far.growth,
                min: near_growth,
                max: MAX_FAR_GROWTH,
            });
        }
        let n = cells as f64;
        let near_rate = n * near_growth.ln();
        let d_eta = 1.0 / n;
        let mut stretch = Self {
            // The near grid's g'(0) Δη (RadialStretch's first cell), so
            // that ring j is the near grid's ring j.
            ln_first_slope: (first_cell / d_eta).ln(),
            near_rate,
            far_rate: n * far.growth.ln() - near_rate,
            turn: 0.0,
        };
        // g(1) falls as the turn moves out: bracket it in [0, 1].
        let reach = |s: &Self| s.nodes(cells)[cells];
        let (mut lo, mut hi) = (0.0, 1.0);
        stretch.turn = lo;
        let earliest = reach(&stretch);
        stretch.turn = hi;
        let latest = reach(&stretch);
        if !(earliest >= xi_max && latest <= xi_max) {
            return Err(NsError::NoTail {
                radial: cells + 1,
                near_radial: far.near_radial,
                growth: far.growth,
            });
        }
        for _ in 0..60 {
            stretch.turn = 0.5 * (lo + hi);
            if reach(&stretch) > xi_max {
                lo = stretch.turn;
            } else {
                hi = stretch.turn;
            }
        }
        stretch.turn = 0.5 * (lo + hi);
        Ok(stretch)
    }

    /// `ln g'(η)`.
    fn ln_slope(&self, eta: f64) -> f64 {
        let x = TURN_SHARPNESS * (eta - self.turn);
        let softplus = if x > 30.0 { x } else { x.exp().ln_1p() };
        self.ln_first_slope + self.near_rate * eta + self.far_rate / TURN_SHARPNESS * softplus
    }

    /// `g'(η)`.
    #[must_use]
    pub fn slope(&self, eta: f64) -> f64 {
        self.ln_slope(eta).exp()
    }

    /// `g''(η)/g'(η)`.
    #[must_use]
    pub fn curvature(&self, eta: f64) -> f64 {
        let sigma = 1.0 / (1.0 + (-TURN_SHARPNESS * (eta - self.turn)).exp());
        self.near_rate + self.far_rate * sigma
    }

    /// Where the growth turns, `η₂` (the ring `η₂ · cells`).
    #[must_use]
    pub fn turn(&self) -> f64 {
        self.turn
    }

    /// `ξ_j = g(j/cells)`, `j = 0..=cells` (Simpson's rule on
    /// 32 intervals a cell).
    #[must_use]
    pub fn nodes(&self, cells: usize) -> Vec<f64> {
        let d_eta = 1.0 / cells as f64;
        let h = d_eta / SIMPSON_INTERVALS as f64;
        let mut xi = Vec::with_capacity(cells + 1);
        xi.push(0.0);
        let mut sum_to = 0.0;
        for j in 0..cells {
            let start = j as f64 * d_eta;
            let mut sum = 0.0;
            for i in 0..=SIMPSON_INTERVALS {
                let weight = if i == 0 || i == SIMPSON_INTERVALS {
                    1.0
                } else if i % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                sum += weight * self.slope(start + i as f64 * h);
            }
            sum_to += sum * h / 3.0;
            xi.push(sum_to);
        }
        xi
    }
}

/// The rings' `ξ`, `g'` and `g''/g'` (what the solver takes of a
/// stretching).
#[derive(Debug, Clone, PartialEq)]
pub struct RingSpacing {
    /// `ξ_j`.
    pub xi: Vec<f64>,
    /// `g'(η_j)`.
    pub slope: Vec<f64>,
    /// `g''(η_j)/g'(η_j)`.
    pub curvature: Vec<f64>,
}

impl RingSpacing {
    /// The `radial` rings from the wall (`ξ = 0`) to `xi_max`, the first
    /// cell `first_cell`: exponential, or tailed as `far` says.
    ///
    /// # Errors
    /// [`NsError::BadGrid`] for fewer than 3 rings; those of
    /// [`RadialStretch::new`] and [`TailedStretch::new`].
    pub fn new(
        xi_max: f64,
        first_cell: f64,
        radial: usize,
        far: Option<FarStretch>,
    ) -> Result<Self, NsError> {
        if radial < 3 {
            return Err(NsError::BadGrid {
                what: "radial",
                value: radial as f64,
                min: 3.0,
                max: 8192.0,
            });
        }
        let cells = radial - 1;
        let d_eta = 1.0 / cells as f64;
        let eta = |j: usize| j as f64 * d_eta;
        Ok(match far {
            None => {
                let s = RadialStretch::new(xi_max, first_cell, cells)?;
                Self {
                    xi: (0..radial).map(|j| s.xi(eta(j))).collect(),
                    slope: (0..radial).map(|j| s.slope(eta(j))).collect(),
                    curvature: vec![s.curvature(); radial],
                }
            }
            Some(far) => {
                let s = TailedStretch::new(xi_max, first_cell, cells, far)?;
                Self {
                    xi: s.nodes(cells),
                    slope: (0..radial).map(|j| s.slope(eta(j))).collect(),
                    curvature: (0..radial).map(|j| s.curvature(eta(j))).collect(),
                }
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stretching_meets_its_ends() {
        let s = RadialStretch::new(4.6, 0.002, 200).unwrap();
        assert!(s.xi(0.0).abs() < 1e-15);
        assert!((s.xi(1.0) - 4.6).abs() < 1e-12);
        assert!((s.slope(0.0) / 200.0 - 0.002).abs() < 1e-12);
    }

    #[test]
    fn a_first_cell_coarser_than_uniform_is_refused() {
        assert!(matches!(
            RadialStretch::new(1.0, 0.1, 100),
            Err(NsError::NoStretching { .. })
        ));
    }

    /// The tailed grid keeps the near grid's rings (the exponential of
    /// `near_radial` rings, computed in closed form) to the bit's
    /// neighbourhood until its turn, reaches the outer boundary, and
    /// grows by the far growth past the turn.
    #[test]
    fn the_tailed_stretching_keeps_the_near_rings_and_reaches_the_boundary() {
        let (xi_max, first) = (4.1, 1.6e-3);
        let far = FarStretch {
            near_radial: 320,
            growth: 1.045,
        };
        let tailed = RingSpacing::new(xi_max, first, 256, Some(far)).unwrap();
        let near = RingSpacing::new(xi_max, first, 320, None).unwrap();
        let stretch = TailedStretch::new(xi_max, first, 255, far).unwrap();
        let turn_ring = (stretch.turn() * 255.0) as usize;
        assert!((150..250).contains(&turn_ring), "turn at ring {turn_ring}");
        // Inside the turn the rings differ from the near grid's only by
        // the turn's smooth onset, ln g' raised by at most
        // (s₃/k) e^{k(η - η₂)}.
        for j in 1..turn_ring {
            let onset = stretch.far_rate / TURN_SHARPNESS
                * (TURN_SHARPNESS * (j as f64 / 255.0 - stretch.turn())).exp();
            let error = (tailed.xi[j] / near.xi[j] - 1.0).abs();
            assert!(
                error <= 1.01 * onset + 1e-12,
                "ring {j}: {} against {}",
                tailed.xi[j],
                near.xi[j]
            );
        }
        // 2.5e-4 forty rings inside the turn (measured).
        assert!((tailed.xi[turn_ring - 40] / near.xi[turn_ring - 40] - 1.0).abs() < 5e-4);
        assert!((tailed.xi[255] - xi_max).abs() < 1e-9 * xi_max);
        let ratio = (tailed.xi[255] - tailed.xi[254]) / (tailed.xi[254] - tailed.xi[253]);
        assert!((ratio - 1.045).abs() < 2e-3, "far growth {ratio}");
        // g''/g' is the logarithmic derivative of the g' it gives.
        for j in 1..255 {
            let d = (tailed.slope[j + 1].ln() - tailed.slope[j - 1].ln()) * 255.0 / 2.0;
            assert!((d - tailed.curvature[j]).abs() < 0.05 * tailed.curvature[j].abs().max(1.0));
        }
    }

    /// Refined from 256 rings to 320 the default far stretch keeps the
    /// rings of 400 near the wall and grows `1.045^(255/319)` a far ring;
    /// coarsened back it is the same; a corrupt one (no rings) scales
    /// without a panic and is refused where the grid is built.
    #[test]
    fn a_far_stretch_scales_with_the_rings() {
        let far = FarStretch {
            near_radial: 320,
            growth: 1.045,
        };
        let fine = far.scaled(256, 320);
        assert_eq!(fine.near_radial, 400);
        assert!((fine.growth - 1.045f64.powf(255.0 / 319.0)).abs() < 1e-12);
        let back = fine.scaled(320, 256);
        assert_eq!(back.near_radial, 320);
        assert!((back.growth - 1.045).abs() < 1e-12);
        let corrupt = FarStretch {
            near_radial: 0,
            growth: 1.0,
        }
        .scaled(256, 128);
        assert!(RingSpacing::new(4.1, 1.6e-3, 128, Some(corrupt)).is_err());
        assert!(RingSpacing::new(4.1, 1.6e-3, 2, None).is_err());
    }

    /// The host's default (256 rings, the near grid's 320, growing by
    /// 1.045) coarsens as a whole to 29 rings and no fewer:
    /// `1.045^(255/28) = 1.493`, `1.045^(255/27) = 1.516`.
    #[test]
    fn the_fewest_rings_keep_the_far_growth() {
        let far = FarStretch {
            near_radial: 320,
            growth: 1.045,
        };
        let fewest = far.fewest_rings(256);
        assert_eq!(fewest, 29);
        assert!(far.scaled(256, fewest).growth <= MAX_FAR_GROWTH);
        assert!(far.scaled(256, fewest - 1).growth > MAX_FAR_GROWTH);
        assert!(RingSpacing::new(4.1, 1.6e-3, fewest, Some(far.scaled(256, fewest))).is_ok());
        assert!(matches!(
            RingSpacing::new(4.1, 1.6e-3, fewest - 1, Some(far.scaled(256, fewest - 1))),
            Err(NsError::BadGrid { .. })
        ));
        // The count does not depend on the grid it is scaled from.
        let fine = far.scaled(256, 320);
        assert_eq!(fine.fewest_rings(320), 29);
    }

    #[test]
    fn a_tail_that_cannot_reach_the_boundary_is_refused() {
        let far = |near_radial, growth| FarStretch {
            near_radial,
            growth,
        };
        // Too few rings for a gentle far growth.
        assert!(matches!(
            TailedStretch::new(4.1, 1.6e-3, 63, far(320, 1.03)),
            Err(NsError::NoTail { .. })
        ));
        // No coarsening: the near grid is no finer.
        assert!(matches!(
            TailedStretch::new(4.1, 1.6e-3, 255, far(256, 1.045)),
            Err(NsError::BadGrid { .. })
        ));
        // A far growth below the near one.
        assert!(matches!(
            TailedStretch::new(4.1, 1.6e-3, 255, far(320, 1.001)),
            Err(NsError::BadGrid { .. })
        ));
    }
}
