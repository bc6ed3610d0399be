//! Validation of the shell finite elements ([`crate::shell`]) against
//! classical plate and shell solutions: Timoshenko's square plates,
//! Leissa's cantilever plate frequencies, the Scordelis–Lo roof, Sze, Liu
//! & Lo's geometrically nonlinear strips and the NAFEMS 21T transient.
//! Meshes, load steps and time steps are those of `tests/integration/shell.rs`.
//! SI units unless a benchmark is stated in consistent units of its own
//! (Scordelis–Lo, Sze–Liu–Lo).

use std::f64::consts::PI;

use nalgebra::Vector3;

use super::{
    missing, shared, ErrorKind, Measured, Memo, Solver, Spec, Validation, ValidationError,
};
use crate::shell::assembly::pressure_loads;
use crate::shell::corotational::Configuration;
use crate::shell::dynamics::{GeneralizedAlpha, Transient};
use crate::shell::linear::LinearStatic;
use crate::shell::material::{Layer, Section};
use crate::shell::mesh::ShellMesh;
use crate::shell::modal::modes;
use crate::shell::nonlinear::{NewtonSettings, NonlinearStatic};

/// Young's modulus of the test plates, Pa.
pub const PLATE_YOUNG: f64 = 1.0e9;
/// Poisson's ratio of the test plates (Timoshenko's and Leissa's tables
/// are for 0.3).
pub const PLATE_POISSON: f64 = 0.3;

/// The test plates' layer: [`PLATE_YOUNG`], [`PLATE_POISSON`], 1000
/// kg/m^3, `thickness` m.
pub fn plate_layer(thickness: f64) -> Layer {
    Layer {
        young: PLATE_YOUNG,
        poisson: PLATE_POISSON,
        density: 1000.0,
        thickness,
    }
}

/// Flexural rigidity `D = E t^3 / 12 (1 - nu^2)` of the test plates, N m,
/// for thickness `t` m.
pub fn flexural_rigidity(t: f64) -> f64 {
    PLATE_YOUNG * t.powi(3) / (12.0 * (1.0 - PLATE_POISSON * PLATE_POISSON))
}

/// Edge support of a square plate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Support {
    /// All six DOFs held.
    Clamped,
    /// Hard simple support: w and the rotation along the edge held.
    Simple,
}

/// The single-layer section of every element of `mesh`.
fn uniform(mesh: &ShellMesh, layer: &Layer) -> Vec<Section> {
    vec![Section::single(layer); mesh.elements.len()]
}

/// The one node at `(x, y)` of a flat mesh.
fn node_at(mesh: &ShellMesh, x: f64, y: f64) -> Result<usize, ValidationError> {
    mesh.nodes_where(|p| (p.x - x).abs() < 1e-9 && (p.y - y).abs() < 1e-9)
        .first()
        .copied()
        .ok_or_else(|| missing(format!("no node at ({x}, {y})")))
}

/// Centre deflection of a unit square plate (side a = 1 m, a/t = 100) on
/// an `n x n` mesh under uniform pressure q, as `w D / (q a^4)`
/// (dimensionless).
pub fn square_plate(n: usize, support: Support) -> Result<f64, ValidationError> {
    let (a, t, q) = (1.0, 0.01, 1.0e3);
    let mesh = ShellMesh::rectangle(a, a, n, n)?;
    let sections = uniform(&mesh, &plate_layer(t));
    let mut fixed = Vec::new();
    for (node, p) in mesh.nodes.iter().enumerate() {
        let on_x_edge = p.x.abs() < 1e-9 || (p.x - a).abs() < 1e-9;
        let on_y_edge = p.y.abs() < 1e-9 || (p.y - a).abs() < 1e-9;
        if !(on_x_edge || on_y_edge) {
            continue;
        }
        let held: &[usize] = match support {
            Support::Clamped => &[0, 1, 2, 3, 4, 5],
            // Edges x = const keep theta_x (dw/dy = 0 along them), edges
            // y = const keep theta_y.
            Support::Simple => match (on_x_edge, on_y_edge) {
                (true, true) => &[0, 1, 2, 3, 4],
                (true, false) => &[0, 1, 2, 3],
                _ => &[0, 1, 2, 4],
            },
        };
        fixed.extend(held.iter().map(|c| 6 * node + c));
    }
    let model = LinearStatic::new(&mesh, &sections, &fixed)?;
    let f = pressure_loads(&mesh, &vec![q; mesh.elements.len()])?;
    let u = model.solve(&[f])?;
    let centre = node_at(&mesh, 0.5 * a, 0.5 * a)?;
    Ok(u[0][6 * centre + 2] * flexural_rigidity(t) / (q * a.powi(4)))
}

/// The shell cases, in the order `fwav validate` runs them.
pub fn cases() -> Vec<Validation> {
    vec![
        timoshenko_clamped_plate(),
        timoshenko_simply_supported_plate(),
        leissa_cantilever_mode(1),
        leissa_cantilever_mode(2),
        scordelis_lo_roof(),
        sze_liu_lo_end_shear(),
        sze_liu_lo_end_moment(),
        nafems_21t_peak(),
    ]
}

/// Timoshenko & Woinowsky-Krieger, *Theory of Plates and Shells* (1959),
/// table 35 (nu = 0.3): clamped square plate, centre deflection
/// `0.00126 q a^4 / D`; 16 x 16 mesh, within 2%.
pub fn timoshenko_clamped_plate() -> Validation {
    Validation {
        spec: Spec {
            name: "shell/timoshenko-clamped-plate",
            solver: Solver::Shell,
            reference: "Timoshenko & Woinowsky-Krieger (1959) table 35: w = 0.00126 q a^4 / D",
            quantity: "centre deflection w D / (q a^4), clamped square plate, a/t = 100, 16 x 16",
            units: "1",
            error_kind: ErrorKind::Relative,
            tolerance: 0.02,
        },
        reference: || 0.00126,
        compute: || Ok(square_plate(16, Support::Clamped)?.into()),
    }
}

/// Timoshenko & Woinowsky-Krieger (1959), table 8 (nu = 0.3): simply
/// supported square plate, centre deflection `0.00406 q a^4 / D`; 16 x 16
/// mesh, within 2%.
pub fn timoshenko_simply_supported_plate() -> Validation {
    Validation {
        spec: Spec {
            name: "shell/timoshenko-simply-supported-plate",
            solver: Solver::Shell,
            reference: "Timoshenko & Woinowsky-Krieger (1959) table 8: w = 0.00406 q a^4 / D",
            quantity: "centre deflection w D / (q a^4), simply supported square plate, \
                       a/t = 100, 16 x 16",
            units: "1",
            error_kind: ErrorKind::Relative,
            tolerance: 0.02,
        },
        reference: || 0.00406,
        compute: || Ok(square_plate(16, Support::Simple)?.into()),
    }
}

/// The bending frequencies of a square cantilever plate (a = 1 m, t =
/// 0.01 m, clamped at x = 0, free elsewhere) on an `n x n` mesh as
/// `omega a^2 sqrt(rho t / D)`, lowest first: the out-of-plane modes among
/// the lowest five (in-plane modes are far higher).
pub fn cantilever_plate_frequencies(n: usize) -> Result<Vec<f64>, ValidationError> {
    let (a, t) = (1.0, 0.01);
    let layer = plate_layer(t);
    let mesh = ShellMesh::rectangle(a, a, n, n)?;
    let sections = uniform(&mesh, &layer);
    let fixed: Vec<usize> = mesh
        .nodes_where(|p| p.x.abs() < 1e-9)
        .into_iter()
        .flat_map(|n| (0..6).map(move |c| 6 * n + c))
        .collect();
    let found = modes(&mesh, &sections, &fixed, 5)?;
    let scale = a * a * (layer.density * t / flexural_rigidity(t)).sqrt();
    Ok(found
        .iter()
        .filter(|m| {
            let w: f64 = m.shape.iter().skip(2).step_by(6).map(|v| v * v).sum();
            let u: f64 = m.shape.iter().step_by(6).map(|v| v * v).sum();
            w > u
        })
        .map(|m| 2.0 * PI * m.frequency * scale)
        .collect())
}

/// Leissa, *Vibration of Plates* (NASA SP-160, 1969), table 4.30: square
/// cantilever plate, nu = 0.3, `omega a^2 sqrt(rho t / D)` of the first
/// three modes (1st bending, 1st torsion, 2nd bending).
pub const LEISSA_CANTILEVER: [f64; 3] = [3.492, 8.525, 21.43];

/// Leissa's cantilever plate, bending mode `mode` (1 or 2; 3 is in
/// [`LEISSA_CANTILEVER`] too) on 20 x 20, within 2%. One modal analysis
/// serves every mode.
pub fn leissa_cantilever_mode(mode: usize) -> Validation {
    static FREQUENCIES: Memo<Vec<f64>> = Memo::new();
    fn frequency(mode: usize) -> Result<Measured, ValidationError> {
        let all = shared(&FREQUENCIES, || cantilever_plate_frequencies(20))?;
        all.get(mode - 1)
            .map(|&f| f.into())
            .ok_or_else(|| missing(format!("only {} bending modes found", all.len())))
    }
    let spec = Spec {
        name: "shell/leissa-cantilever-mode1",
        solver: Solver::Shell,
        reference: "Leissa (1969) NASA SP-160 table 4.30: 3.492, 8.525, 21.43",
        quantity: "1st bending frequency omega a^2 sqrt(rho t / D), square cantilever plate, \
                   20 x 20",
        units: "1",
        error_kind: ErrorKind::Relative,
        tolerance: 0.02,
    };
    match mode {
        2 => Validation {
            spec: Spec {
                name: "shell/leissa-cantilever-mode2",
                quantity: "1st torsion frequency omega a^2 sqrt(rho t / D), square cantilever \
                           plate, 20 x 20",
                ..spec
            },
            reference: || LEISSA_CANTILEVER[1],
            compute: || frequency(2),
        },
        3 => Validation {
            spec: Spec {
                name: "shell/leissa-cantilever-mode3",
                quantity: "2nd bending frequency omega a^2 sqrt(rho t / D), square cantilever \
                           plate, 20 x 20",
                ..spec
            },
            reference: || LEISSA_CANTILEVER[2],
            compute: || frequency(3),
        },
        _ => Validation {
            spec,
            reference: || LEISSA_CANTILEVER[0],
            compute: || frequency(1),
        },
    }
}

/// Scordelis–Lo roof (MacNeal & Harder 1985): cylindrical shell R = 25,
/// L = 50, 80 deg arc, t = 0.25, E = 4.32e8, nu = 0, gravity 90 per unit
/// area, rigid diaphragms at the curved ends; a quarter on an `n x n`
/// mesh. Returns the downward displacement at the midside of the free
/// edge (the benchmark's consistent length unit).
pub fn scordelis_lo(n: usize) -> Result<f64, ValidationError> {
    let (r, half_length, half_angle) = (25.0, 25.0, 40f64.to_radians());
    // Quarter: x in [0, L/2] from the diaphragm to the midspan, phi from
    // the crown (0) to the free edge (40 deg); y across, z up.
    let mesh = ShellMesh::mapped(n, n, |s, tt| {
        let phi = tt * half_angle;
        Vector3::new(s * half_length, r * phi.sin(), r * phi.cos())
    })?;
    let layer = Layer {
        young: 4.32e8,
        poisson: 0.0,
        density: 1.0,
        thickness: 0.25,
    };
    let sections = uniform(&mesh, &layer);
    let mut fixed = Vec::new();
    for (node, p) in mesh.nodes.iter().enumerate() {
        let d = |c: usize| 6 * node + c;
        if p.x.abs() < 1e-9 {
            // Diaphragm: rigid in its own plane.
            fixed.extend([d(1), d(2)]);
        }
        if (p.x - half_length).abs() < 1e-9 {
            // Symmetry about x = L/2.
            fixed.extend([d(0), d(4), d(5)]);
        }
        if p.y.abs() < 1e-9 {
            // Symmetry about the crown plane y = 0.
            fixed.extend([d(1), d(3), d(5)]);
        }
    }
    fixed.sort_unstable();
    fixed.dedup();
    let model = LinearStatic::new(&mesh, &sections, &fixed)?;
    // Gravity: 90 per unit area, a quarter of each element's area to each
    // corner, downward.
    let mut f = vec![0.0; mesh.dofs()];
    for e in 0..mesh.elements.len() {
        let area = mesh.element_area(e);
        for &node in &mesh.elements[e] {
            f[6 * node + 2] -= 90.0 * area / 4.0;
        }
    }
    let u = model.solve(&[f])?;
    let corner = node_at(&mesh, half_length, r * half_angle.sin())?;
    Ok(-u[0][6 * corner + 2])
}

/// The Scordelis–Lo roof on a 16 x 16 quarter model against the deep-shell
/// value 0.3024 (REFERENCES.md; MacNeal & Harder quote 0.3086), within 2%.
pub fn scordelis_lo_roof() -> Validation {
    Validation {
        spec: Spec {
            name: "shell/scordelis-lo-roof",
            solver: Solver::Shell,
            reference: "Scordelis-Lo roof, MacNeal & Harder (1985) benchmark: 0.3024 \
                        (deep-shell value; MacNeal & Harder quote 0.3086)",
            quantity: "vertical displacement at the midside of the free edge, 16 x 16 quarter",
            units: "length (benchmark units)",
            error_kind: ErrorKind::Relative,
            tolerance: 0.02,
        },
        reference: || 0.3024,
        compute: || Ok(scordelis_lo(16)?.into()),
    }
}

/// The Sze, Liu & Lo (2004) strips' section: t = 0.1, E = 1.2e6, nu = 0
/// (consistent units).
pub const SZE_LAYER: Layer = Layer {
    young: 1.2e6,
    poisson: 0.0,
    density: 1.0,
    thickness: 0.1,
};

/// A strip `[0, length] x [0, width]` of `n x 1` elements, one layer,
/// clamped at x = 0, loaded at its tip.
#[derive(Clone, Debug)]
pub struct Strip {
    /// The mesh.
    pub mesh: ShellMesh,
    /// One section an element.
    pub sections: Vec<Section>,
    /// The held DOFs (all six at x = 0).
    pub root: Vec<usize>,
    /// The nodes at x = length.
    pub tip: Vec<usize>,
}

impl Strip {
    /// The clamped strip of `n x 1` elements.
    pub fn clamped(
        length: f64,
        width: f64,
        layer: Layer,
        n: usize,
    ) -> Result<Self, ValidationError> {
        let mesh = ShellMesh::rectangle(length, width, n, 1)?;
        let sections = uniform(&mesh, &layer);
        let root = mesh
            .nodes_where(|p| p.x.abs() < 1e-9)
            .into_iter()
            .flat_map(|n| (0..6).map(move |c| 6 * n + c))
            .collect();
        let tip = mesh.nodes_where(|p| (p.x - length).abs() < 1e-9);
        Ok(Self {
            mesh,
            sections,
            root,
            tip,
        })
    }

    /// `total` shared equally by the tip nodes on DOF `component` (0-2
    /// forces, 3-5 moments).
    pub fn tip_load(&self, component: usize, total: f64) -> Vec<f64> {
        let mut load = vec![0.0; self.mesh.dofs()];
        for &n in &self.tip {
            load[6 * n + component] = total / self.tip.len() as f64;
        }
        load
    }

    /// Nonlinear equilibrium path under `load` in 20 load steps: `(load
    /// factor, configuration)` a step.
    pub fn path(&self, load: &[f64]) -> Result<Vec<(f64, Configuration)>, ValidationError> {
        let settings = NewtonSettings {
            steps: 20,
            ..NewtonSettings::default()
        };
        Ok(NonlinearStatic::new(&self.mesh, &self.sections, &self.root)?.solve(load, settings)?)
    }

    /// Mean tip displacement `(-u, w)` at load factor `lambda` of a path.
    pub fn tip_at(
        &self,
        path: &[(f64, Configuration)],
        lambda: f64,
    ) -> Result<(f64, f64), ValidationError> {
        let (_, c) = path
            .iter()
            .find(|(l, _)| (l - lambda).abs() < 1e-9)
            .ok_or_else(|| missing(format!("no load step at factor {lambda}")))?;
        let d = self
            .tip
            .iter()
            .map(|&n| c.displacement[n])
            .sum::<Vector3<f64>>()
            / self.tip.len() as f64;
        Ok((-d.x, d.z))
    }
}

/// Sze, Liu & Lo (2004), Finite Elem. Anal. Des. 40: the cantilever strip
/// 10 x 1 x 0.1 under an end shear P_max = 4 (dead load), 16 x 1
/// elements, 20 steps: tip `(-u, w)` at `P / P_max` = 0.05, 0.5 and 1.
pub fn sze_liu_lo_end_shear_path() -> Result<Vec<(f64, f64)>, ValidationError> {
    static PATH: Memo<Vec<(f64, f64)>> = Memo::new();
    shared(&PATH, || {
        let strip = Strip::clamped(10.0, 1.0, SZE_LAYER, 16)?;
        let path = strip.path(&strip.tip_load(2, 4.0))?;
        [0.05, 0.5, 1.0]
            .iter()
            .map(|&l| strip.tip_at(&path, l))
            .collect()
    })
}

/// Sze, Liu & Lo's published tip `(-u, w)` of the end-shear strip at
/// `P / P_max` = 0.05, 0.5, 1 (their 16 x 1 reference mesh).
pub const SZE_END_SHEAR: [(f64, f64); 3] = [(0.026, 0.663), (1.604, 4.933), (3.286, 6.698)];

/// The end-shear strip's tip deflection w at P_max against Sze, Liu & Lo's
/// 6.698, within 2%.
pub fn sze_liu_lo_end_shear() -> Validation {
    Validation {
        spec: Spec {
            name: "shell/sze-liu-lo-end-shear",
            solver: Solver::Shell,
            reference: "Sze, Liu & Lo (2004) Finite Elem. Anal. Des. 40, cantilever strip under \
                        end shear: w = 6.698 at P_max",
            quantity: "tip deflection w at P = P_max = 4, strip 10 x 1 x 0.1, 16 x 1, 20 steps",
            units: "length (benchmark units)",
            error_kind: ErrorKind::Relative,
            tolerance: 0.02,
        },
        reference: || SZE_END_SHEAR[2].1,
        compute: || {
            let tips = sze_liu_lo_end_shear_path()?;
            let (u, w) = tips[2];
            Ok(Measured {
                value: w,
                note: Some(format!("-u = {u:.4} (published {})", SZE_END_SHEAR[2].0)),
            })
        },
    }
}

/// Sze, Liu & Lo (2004): the cantilever strip 12 x 1 x 0.1 under an end
/// moment, `M_max = 2 pi E I / L = 50 pi / 3`, 16 x 1 elements, 20 steps:
/// tip `(-u, w)` at `M / M_max` = 0.5 and 1.
pub fn sze_liu_lo_end_moment_path() -> Result<Vec<(f64, f64)>, ValidationError> {
    static PATH: Memo<Vec<(f64, f64)>> = Memo::new();
    shared(&PATH, || {
        let strip = Strip::clamped(12.0, 1.0, SZE_LAYER, 16)?;
        // A negative moment about y curls the strip up (+z).
        let path = strip.path(&strip.tip_load(4, -50.0 * PI / 3.0))?;
        [0.5, 1.0].iter().map(|&l| strip.tip_at(&path, l)).collect()
    })
}

/// Sze, Liu & Lo's tip `(-u, w)` of the end-moment strip (L = 12) at
/// `M / M_max` = 0.5, a semicircle (`-u = L`, `w = 2 L / pi`), and 1, a
/// full circle (the tip back at the root: `-u = L`, `w = 0`).
pub const SZE_END_MOMENT: [(f64, f64); 2] = [(12.0, 7.639), (12.0, 0.0)];

/// The end-moment strip at half the moment rolls into a semicircle: tip
/// w = 2 L / pi = 7.639 (Sze, Liu & Lo 2004), within 1% of L = 0.12.
pub fn sze_liu_lo_end_moment() -> Validation {
    Validation {
        spec: Spec {
            name: "shell/sze-liu-lo-end-moment",
            solver: Solver::Shell,
            reference: "Sze, Liu & Lo (2004) Finite Elem. Anal. Des. 40, strip under end moment: \
                        semicircle at M_max / 2, w = 2 L / pi = 7.639",
            quantity: "tip deflection w at M = M_max / 2, strip 12 x 1 x 0.1, 16 x 1, 20 steps \
                       (tolerance 1% of L)",
            units: "length (benchmark units)",
            error_kind: ErrorKind::Absolute,
            tolerance: 0.12,
        },
        reference: || SZE_END_MOMENT[0].1,
        compute: || {
            let tips = sze_liu_lo_end_moment_path()?;
            let ((u, w), (u_full, w_full)) = (tips[0], tips[1]);
            Ok(Measured {
                value: w,
                note: Some(format!(
                    "-u = {u:.4} (12); full circle at M_max: -u = {u_full:.4} (12), \
                     w = {w_full:.4} (0)"
                )),
            })
        },
    }
}

/// Hard simply supported edges of a rectangle `[0, a] x [0, b]` in z = 0:
/// w, u, v held, and the rotation along each edge.
pub fn simply_supported(mesh: &ShellMesh, a: f64, b: f64) -> Vec<usize> {
    let mut fixed = Vec::new();
    for (node, p) in mesh.nodes.iter().enumerate() {
        let on_x = p.x.abs() < 1e-9 || (p.x - a).abs() < 1e-9;
        let on_y = p.y.abs() < 1e-9 || (p.y - b).abs() < 1e-9;
        if on_x || on_y {
            fixed.extend([6 * node, 6 * node + 1, 6 * node + 2]);
        }
        if on_x {
            fixed.push(6 * node + 3);
        }
        if on_y {
            fixed.push(6 * node + 4);
        }
    }
    fixed.sort_unstable();
    fixed.dedup();
    fixed
}

/// NAFEMS 21T results of [`nafems_21t`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Nafems21t {
    /// Static centre deflection, m.
    pub static_m: f64,
    /// Peak dynamic centre deflection, m.
    pub peak_m: f64,
    /// Time of the peak, s.
    pub peak_time_s: f64,
}

/// NAFEMS test 21T (linear transient): simply supported plate 10 x 10 x 1
/// m, E = 200 GPa, nu = 0.3, rho = 8000 kg/m^3, 1 MPa pressure applied as
/// a step, 2% damping at the fundamental 288.379 rad/s (here
/// stiffness-proportional, `a_K = 2 zeta / omega`), 12 x 12 mesh, 200
/// steps a fundamental period, to 0.02 s. Run once.
pub fn nafems_21t() -> Result<Nafems21t, ValidationError> {
    static RUN: Memo<Nafems21t> = Memo::new();
    shared(&RUN, || {
        let (a, q) = (10.0, 1.0e6);
        let layer = Layer {
            young: 200e9,
            poisson: 0.3,
            density: 8000.0,
            thickness: 1.0,
        };
        let mesh = ShellMesh::rectangle(a, a, 12, 12)?;
        let sections = uniform(&mesh, &layer);
        let fixed = simply_supported(&mesh, a, a);
        let centre = node_at(&mesh, 5.0, 5.0)?;
        let load = pressure_loads(&mesh, &vec![q; mesh.elements.len()])?;
        let static_m = LinearStatic::new(&mesh, &sections, &fixed)?
            .solve(std::slice::from_ref(&load))?[0][6 * centre + 2];
        let omega = 288.379;
        let settings = GeneralizedAlpha {
            dt: 2.0 * PI / omega / 200.0,
            rho_inf: 1.0,
            mass_damping: 0.0,
            stiffness_damping: 2.0 * 0.02 / omega,
        };
        let model = Transient::new(&mesh, &sections, &fixed, settings)?;
        let map = model.model().map().clone();
        let f = map.restrict(&load);
        let mut state = model.start(vec![0.0; f.len()], &f);
        let w_dof = map
            .free(6 * centre + 2)
            .ok_or_else(|| missing("the centre deflection is held"))?;
        let (mut peak_m, mut peak_time_s) = (0.0f64, 0.0);
        while state.time < 0.02 {
            model.step(&mut state, &f);
            if state.u[w_dof] > peak_m {
                peak_m = state.u[w_dof];
                peak_time_s = state.time;
            }
        }
        Ok(Nafems21t {
            static_m,
            peak_m,
            peak_time_s,
        })
    })
}

/// NAFEMS 21T's dynamic peak, 4.524 mm (REFERENCES.md), within 2%.
pub fn nafems_21t_peak() -> Validation {
    Validation {
        spec: Spec {
            name: "shell/nafems-21t-peak",
            solver: Solver::Shell,
            reference: "NAFEMS test 21T (linear transient, step pressure): peak centre \
                        deflection 4.524 mm at t = 0.0108 s, static 2.333 mm",
            quantity: "peak centre deflection, SS plate 10 x 10 x 1 m, 1 MPa step, 12 x 12",
            units: "mm",
            error_kind: ErrorKind::Relative,
            tolerance: 0.02,
        },
        reference: || 4.524,
        compute: || {
            let r = nafems_21t()?;
            Ok(Measured {
                value: 1e3 * r.peak_m,
                note: Some(format!(
                    "at t = {:.5} s (0.0108); static {:.4} mm (2.333)",
                    r.peak_time_s,
                    1e3 * r.static_m
                )),
            })
        },
    }
}
