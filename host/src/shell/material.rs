//! Layers and the through-thickness section of the two-layer wing skin.
//!
//! Both layers share the nodes and the reference surface (the paper's
//! model: a carbon design layer and a mylar non-design layer meshed on the
//! same nodes), so their membrane, bending and shear stiffnesses add, the
//! carbon's scaled by the SIMP interpolation `rho^p` of its element density
//! and its mass by `rho` (Bendsøe & Sigmund, Topology Optimization, 2003,
//! ch. 1).

/// An isotropic layer (SI units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layer {
    /// Young's modulus, Pa.
    pub young: f64,
    /// Poisson's ratio.
    pub poisson: f64,
    /// Density, kg/m^3.
    pub density: f64,
    /// Thickness, m.
    pub thickness: f64,
}

impl Layer {
    /// The paper's carbon design layer: 0.5 mm, E = 170.3 GPa, nu = 0.3,
    /// rho = 2001.2 kg/m^3.
    pub const CARBON: Layer = Layer {
        young: 170.3e9,
        poisson: 0.3,
        density: 2001.2,
        thickness: 0.5e-3,
    };
    /// The paper's mylar membrane: 0.1 mm, E = 3.28 GPa, nu = 0.4,
    /// rho = 1400.6 kg/m^3.
    pub const MYLAR: Layer = Layer {
        young: 3.28e9,
        poisson: 0.4,
        density: 1400.6,
        thickness: 0.1e-3,
    };

    /// Plane-stress stiffness `E/(1 - nu^2) [[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu)/2]]`, Pa.
    fn plane_stress(&self) -> [[f64; 3]; 3] {
        let (e, nu) = (self.young, self.poisson);
        let c = e / (1.0 - nu * nu);
        [
            [c, c * nu, 0.0],
            [c * nu, c, 0.0],
            [0.0, 0.0, c * (1.0 - nu) / 2.0],
        ]
    }
}

/// Resultant stiffness and inertia of a section per unit area, about the
/// shared reference surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Section {
    /// Membrane stiffness `A`, N/m.
    pub membrane: [[f64; 3]; 3],
    /// Bending stiffness `D`, N m.
    pub bending: [[f64; 3]; 3],
    /// Transverse shear stiffness `k G t` (k = 5/6), N/m.
    pub shear: f64,
    /// Mass per unit area, kg/m^2.
    pub mass: f64,
    /// Rotary inertia per unit area `sum rho t^3 / 12`, kg.
    pub rotary: f64,
}

impl Section {
    /// `scale` times this layer's contribution.
    fn add(&mut self, layer: &Layer, stiffness_scale: f64, mass_scale: f64) {
        let t = layer.thickness;
        let q = layer.plane_stress();
        for (i, row) in q.iter().enumerate() {
            for (j, v) in row.iter().enumerate() {
                self.membrane[i][j] += stiffness_scale * v * t;
                self.bending[i][j] += stiffness_scale * v * t.powi(3) / 12.0;
            }
        }
        let g = layer.young / (2.0 * (1.0 + layer.poisson));
        self.shear += stiffness_scale * 5.0 / 6.0 * g * t;
        self.mass += mass_scale * layer.density * t;
        self.rotary += mass_scale * layer.density * t.powi(3) / 12.0;
    }

    /// One homogeneous layer.
    pub fn single(layer: &Layer) -> Self {
        let mut s = Self::zero();
        s.add(layer, 1.0, 1.0);
        s
    }

    /// The wing skin: `skin` always, `design` with SIMP density `density`
    /// in [0, 1] (stiffness `density^penalty`, mass `density`).
    pub fn two_layer(design: &Layer, skin: &Layer, density: f64, penalty: f64) -> Self {
        let mut s = Self::single(skin);
        s.add(design, density.powf(penalty), density);
        s
    }

    fn zero() -> Self {
        Self {
            membrane: [[0.0; 3]; 3],
            bending: [[0.0; 3]; 3],
            shear: 0.0,
            mass: 0.0,
            rotary: 0.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A full-density two-layer section is the sum of its layers; an empty
    /// design layer leaves the mylar alone; D = E t^3 / 12 (1 - nu^2).
    #[test]
    fn layers_add() {
        let c = Section::single(&Layer::CARBON);
        let m = Section::single(&Layer::MYLAR);
        let both = Section::two_layer(&Layer::CARBON, &Layer::MYLAR, 1.0, 3.0);
        assert!((both.bending[0][0] - c.bending[0][0] - m.bending[0][0]).abs() < 1e-12);
        // (Equal to rounding: 0 + x t^3/12 is not bit-identical to x t^3/12
        // computed through a different association.)
        let empty = Section::two_layer(&Layer::CARBON, &Layer::MYLAR, 0.0, 3.0);
        assert!((empty.bending[0][1] / m.bending[0][1] - 1.0).abs() < 1e-12);
        assert!((empty.mass - m.mass).abs() < 1e-15);
        assert!((empty.shear - m.shear).abs() < 1e-9);
        let d = 170.3e9 * 0.5e-3f64.powi(3) / (12.0 * (1.0 - 0.09));
        assert!((c.bending[0][0] / d - 1.0).abs() < 1e-12);
        let half = Section::two_layer(&Layer::CARBON, &Layer::MYLAR, 0.5, 3.0);
        assert!((half.mass - m.mass - 0.5 * c.mass).abs() < 1e-12);
        assert!((half.shear - m.shear - 0.125 * c.shear).abs() < 1e-6);
    }
}
