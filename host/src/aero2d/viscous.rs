//! The viscous section model: laminar Navier–Stokes ([`fwav_ns2d`]) of a
//! plunging and pitching section, behind the same [`super::case::Case`] as
//! the inviscid models, in the same units (chords, `U = 1`, time in chords
//! travelled) and with the same [`History`].
//!
//! The section is set in the solver's body frame with the pitch axis at
//! the origin, the chord along `+x` from the leading edge at `x = -pivot`;
//! the stream is along `+x`. Thrust is the force upstream (`-Fx`), lift
//! the force across (`Fy`), the input power the work rate of the
//! section's motion relative to steady flight (the wall's work rate on the
//! fluid less the flight's, `-T U`: `viscous/march.rs`; as the inviscid
//! models and Garrick's theory count it, so a section at rest in the
//! stream has none), all on `1/2 rho U^2 c` (`U^3` for the power). The forces
//! include the wall's friction: the thrust is net of it, and the run's
//! friction history is zero (the inviscid models' estimate is not added).
//!
//! Sections ([`ViscousShape`]): a thin plate of a chosen thickness with
//! semicircular ends (the model of a membrane), any closed contour (a
//! NACA section or a point file, a sharp trailing edge made blunt), both
//! by the solver's numerical conformal map, or an ellipse (exact map).
//!
//! The grid ([`ViscousSection::new`]): 384 nodes round, 256 rings out to
//! 30 chords, the first ring a tenth of the boundary layer's thickness
//! from the wall; the rings are those of the exponential grid of 320 out
//! to about 0.8 chords, where the separated shear layers and the young
//! wake lie, and grow 4.5 % a ring past it ([`FarStretch`]), which keeps
//! the default FWAV section's long-run thrust within 0.2 % of the
//! exponential grid's at a fifth less cost.
//!
//! The time step is the one of a chosen largest Courant number
//! ([`ViscousSection::courant`], [`fwav_ns2d::Flow::stable_dt`]): the
//! solver's advection is implicit where the Courant number exceeds ½, so
//! any step is stable and accuracy chooses it. It is checked as the flow
//! develops, shortened when the flow outgrows it and lengthened when it
//! has room, on a ladder of steps a factor 2^¼ apart (`StepControl` in
//! `viscous/march.rs`);
//! the first use of a rung costs one build of the wall's influence
//! matrix (4 ms on the default grid). The loads are sampled at a fixed interval by
//! linear interpolation between steps, so the cycle means of
//! [`super::history`] see uniform samples.
//!
//! A periodic run may spin up ([`ViscousSection::spin_up_periods`]): its
//! first periods, which only bring the flow to its state and are not
//! scored, run on a grid [`SPIN_UP_COARSENING`] times coarser each way
//! ([`ViscousSection::spin_up_grid`]), and the flow is then carried over
//! to the full grid ([`fwav_ns2d::Flow::continue_from`]: the vorticity
//! interpolated, the wall layer rebuilt by the first steps). A spin-up
//! period costs about a quarter of a full one (the default FWAV section,
//! rigid, in a slow hour: 5.2 s a period on 256 × 160 nodes, 19.5 s on
//! 384 × 240, the default then; fewer cells and longer steps). It keeps an attached,
//! periodic flow (a plunging plate's loads a period after the hand-over
//! within 0.2 % of the full run's), but not the default FWAV section's:
//! spun up through the two strokes before the aerodynamic discipline's
//! scored window, the window's CT moved by 13 % RMS over the L18 rows,
//! against the 2–3 % the full grid's own windows scatter by, as the full
//! grid's flow carries a slowly decaying mean lift from its start that
//! the coarse grid's loses (docs/ns-design, "The spin-up"). So the
//! discipline does not spin up
//! ([`crate::discipline::section_model::ViscousPlate::spin_up`]).

use fwav_ns2d::{Complex64, Contour, FarStretch, Flow, GridSpec, SectionMap, MAX_FAR_GROWTH};

pub mod cost;
mod deflection;
mod deforming;
mod error;
mod field;
mod march;
mod path;
mod shape;
mod surface;

use super::history::History;
use super::ldvm::FreeVortex;
pub use cost::ViscousCost;
pub use deflection::{DeflectionState, RigidDeflection, MAX_DEFLECTION_SAMPLES};
pub use error::ViscousError;
pub use field::{FlowField, FrameSink, NoFrames};
pub(crate) use march::load_interval;
use march::March;
pub use path::{SectionPath, STILL_KICK_CHORDS, STILL_KICK_RATE};
use shape::CONTOUR_POINTS;
pub use shape::{ViscousShape, CORNER_TURNING, MIRROR_TOLERANCE, TRAILING_EDGE_THICKNESS};
pub use surface::SurfaceLoads;

/// Most grid cells drawn in the vorticity picture.
const PICTURE_CELLS: usize = 20_000;

/// Radius, chords about the pivot, of the vorticity picture.
const PICTURE_RADIUS: f64 = 6.0;

/// How much coarser the spin-up's grid is each way
/// ([`ViscousSection::spin_up_grid`]): 384 × 256 becomes 256 × 170, its
/// near rings those of 212 rather than 320 and its far cells growing
/// 6.9 % rather than 4.5 % (384 × 240, the exponential default when the
/// spin-up was measured, 256 × 160).
pub const SPIN_UP_COARSENING: f64 = 1.5;

/// Steps a run may take before it is refused as beyond this machine.
pub const MAX_VISCOUS_STEPS: usize = 2_000_000;

/// The laminar boundary layer's thickness at the trailing edge, chords
/// times `√Re`: the flat plate's `δ₉₉ = 5.0 x / √Re_x` (Blasius 1908;
/// Schlichting & Gersten, *Boundary-Layer Theory*, 9th ed., 2017, the
/// flat plate at zero incidence) at `x = c`, the thickest an attached
/// laminar layer grows along the chord. A grid whose longest wall cell
/// is longer than this cannot resolve the layer anywhere along the wall
/// and is refused ([`ViscousError::Unresolved`]). Passing it is necessary, not
/// sufficient: the default FWAV plate at Re 12,329 converges with 384
/// nodes round, cells 0.19 of this thickness, and 256 round (0.29)
/// still moved its first stroke's CT by +21 % (`ns2d/README.md`, "The
/// step's velocity, and the default resolution").
pub const TRAILING_EDGE_LAYER: f64 = 5.0;

/// The viscous model's section and resolution.
#[derive(Clone, Debug, PartialEq)]
pub struct ViscousSection {
    /// The section.
    pub shape: ViscousShape,
    /// Nodes round the section.
    pub around: usize,
    /// Nodes from the wall to the outer boundary.
    pub radial: usize,
    /// The far field coarsened: the rings of a finer exponential grid
    /// near the wall, faster growth past them ([`FarStretch`]); `None`
    /// for the exponential stretching throughout. Change `radial` with
    /// [`Self::with_radial`], which scales this with it.
    pub far: Option<FarStretch>,
    /// Outer boundary, chords from the pivot.
    pub outer_chords: f64,
    /// First cell at the wall where the grid is coarsest along it
    /// (mid-chord of a thin section), in boundary-layer thicknesses
    /// `c / sqrt(Re)`.
    pub first_cell_layers: f64,
    /// The largest advective Courant number the time step is chosen for
    /// (the advection is implicit where it exceeds ½, so any is stable;
    /// accuracy sets it: see [`ViscousSection::DEFAULT_COURANT`]).
    pub courant: f64,
    /// Periods of the motion run first on a grid [`SPIN_UP_COARSENING`]
    /// times coarser each way ([`Self::spin_up_grid`]), the flow then
    /// carried over to this grid ([`fwav_ns2d::Flow::continue_from`]):
    /// the strokes that only bring a periodic flow to its state, at
    /// about a quarter of the cost; 0 for none (the default of
    /// [`Self::new`]; module docs: it does not keep the default FWAV
    /// section's scores).
    pub spin_up_periods: f64,
    /// Flows handed to a [`FrameSink`] as the run steps
    /// ([`Self::run_into`]), for a ParaView series: at `i / field_frames`
    /// of the run's length for `i` = 1 to `field_frames` (each at the
    /// first step's end that reaches it, the last at the run's end), the
    /// spin-up's on its own grid. 0 (the default) for none. Each is a copy
    /// of the grid (4.7 MB on the default FWAV section), the sink's until
    /// it lets it go.
    pub field_frames: usize,
}

impl ViscousSection {
    /// Default thickness of the thin plate, chords. Four times the
    /// vehicle's carbon leading edge (0.6 mm on the 60 mm mid-span chord,
    /// 0.01 c), and the thrust grows about in proportion to it (the
    /// suction on the rounded nose): on the default FWAV section's first
    /// stroke CT 0.0138, 0.0370, 0.0779 at 0.01, 0.02, 0.04 c, CP within
    /// 3 % (`ns2d/README.md`, "The plate's thickness"; the failing
    /// `viscous_default_section::the_scores_hardly_depend_on_the_plates_thickness`).
    pub const DEFAULT_THICKNESS: f64 = 0.04;

    /// Default largest Courant number of a step. On the default FWAV
    /// section's first stroke (384 × 160) the thrust converges as the
    /// square of the Courant number since the advection is carried by the
    /// velocity of the step's middle (`fwav_ns2d::Flow::step`): CT
    /// 0.0753, 0.0739, 0.0733, 0.0729, 0.0727, 0.0728, 0.0727 at 6, 4, 3,
    /// 2, 1.5, 0.5, 0.25, so 3 is within 0.8 % of the converged step and
    /// halving it moves CT 0.8 % (CP 1.7297 to 1.7236, 0.4 %); on the
    /// default 384 × 240, 2.0 % (0.0758 to 0.0743) and CP 0.4 %. With the
    /// step start's velocity, before 2026-12-03, CT kept falling as the
    /// step was refined (0.0791, 0.0785, 0.0777, 0.0767, 0.0749 at 1.5,
    /// 1, 0.75, 0.5, 0.25) and the default was 1.5.
    /// (`viscous_default_section::default_section_four_cycles_benchmark` with
    /// `FWAV_NS_CYCLES=1 FWAV_NS_COURANT=...`.)
    pub const DEFAULT_COURANT: f64 = 3.0;
    /// The default rings: 256 from the wall to 30 chords, the first 200
    /// or so those of the exponential grid of 320 ([`Self::DEFAULT_FAR`]).
    pub const DEFAULT_RADIAL: usize = 256;
    /// Nodes round the section of [`Self::new`].
    pub const DEFAULT_AROUND: usize = 384;
    /// The default far stretch: near the wall the rings of the
    /// exponential grid of 320 (each cell 1.06 % larger than the one
    /// inside it on the default FWAV section), turning to 4.5 % a cell
    /// past about 0.8 chords, where the wake has spread.
    ///
    /// Chosen on the default FWAV section, rigid, twelve strokes at
    /// Courant 3, the mean over strokes 3 to 12 against the exponential
    /// 384 x 320 (CT 0.07148, CP 1.7105, 204 s; 2026-12-05, the same hour,
    /// a scratch build of this stretching whose first cell was 0.5 %
    /// higher):
    ///
    /// | rings | far growth | CT | CP | strokes 3 and 4 | time |
    /// | --- | --- | --- | --- | --- | --- |
    /// | 272 | 3.5 % | −0.07 % | +0.01 % | 0.0713 | 175 s |
    /// | **256** | **4.5 %** | **−0.2 %** | **+0.01 %** | **−0.2 %** | **161 s** |
    /// | 240 | 7.5 % | −0.9 % | −0.4 % | −1.5 % | 154 s |
    ///
    /// A grid with the same rings coarser where the shear layers lie
    /// (0.06 to 0.36 c: cells growing 2 % a ring to square ones, then
    /// held, on 272 rings) shed aperiodically, its long mean −4.7 %, as the
    /// exponential 240 rings (−5.1 %): the near field's radial resolution
    /// decides the flow, the far field's hardly.
    ///
    /// Converged as the exponential 384 x 320 was (issue 23's 3 %;
    /// `viscous_default_section::the_long_mean_converges_with_the_resolution`,
    /// 2026-12-05): the long mean on 384 x 256 is CT 0.0713 (standard
    /// error 0.1 %: periodic), efficiency 0.0417; the step halved moves
    /// them −0.6 % and +0.0 %, the grid refined to 320 rings (the near
    /// grid's 400, 3.6 % a far cell: [`Self::with_radial`]) −0.1 % and
    /// +0.3 %, 512 round −0.5 % and +1.2 %.
    pub const DEFAULT_FAR: FarStretch = FarStretch {
        near_radial: 320,
        growth: 1.045,
    };

    /// The default resolution round `shape`: 384 nodes round,
    /// [`Self::DEFAULT_RADIAL`] rings out to 30 chords with the far field
    /// coarsened ([`Self::DEFAULT_FAR`]), first cell a tenth of the
    /// boundary layer's thickness. The exponential grid it keeps near the
    /// wall was chosen on the default FWAV section (Courant number 3, the
    /// step centred in time: [`Self::DEFAULT_COURANT`]). The first
    /// stroke's CT and CP on exponential grids:
    ///
    /// | grid | 160 rings | 240 rings | 320 rings | 400 rings |
    /// | --- | --- | --- | --- | --- |
    /// | 384 round | 0.0733, 1.730 | 0.0758, 1.712 | **0.0779, 1.707** | 0.0784, 1.706 |
    /// | 512 round | 0.0710, 1.701 | 0.0768, 1.709 | 0.0791, 1.706 | |
    /// | 768 round | 0.0670, 1.683 | 0.0756, 1.705 | 0.0783, 1.702 | |
    ///
    /// On 240 rings and more the nodes round are converged (within 1.5 %);
    /// the rings decide it. The first stroke alone had chosen 240 rings
    /// (320 moved CT 2.8 %). But over 12 strokes the flow on
    /// 240 rings never settles: its strokes wander by 4 % and their mean
    /// over strokes 3 to 12 (CT 0.0680, efficiency 0.0425) moves 5.1 % and
    /// 2.7 % with 320 rings, 3.6 % and 2.8 % with 512 round, where every
    /// finer grid settles into one periodic flow within 1.6 % (the
    /// `ns2d/README.md`'s "The long mean"; `viscous_default_section::the_long_mean_converges_with_the_resolution`).
    /// On 384 × 320 the flow is periodic from the fourth stroke, and the
    /// mean over strokes 3 to 12 (CT 0.0715, efficiency 0.0436) moves
    /// −0.2 % and +0.2 % with 400 rings, −0.7 % and +1.1 % with 512
    /// round, −1.6 % and −0.5 % with the step halved; the first stroke
    /// +0.6 %, +1.5 % and −1.8 % in CT. It costs a third more than 240
    /// rings. 256 round: 0.0917 on 160 and 240 rings.
    ///
    /// Until 2026-12-03 the default was 384 × 160 at Courant number 1.5,
    /// chosen when the step was first order in the velocity's change:
    /// its time error (+8.8 % in CT there) and the grid's (−3 % to −7 %)
    /// had cancelled (384 × 160, 512 × 240 and 768 × 320 gave CT 0.0791,
    /// 0.0791, 0.0803 then).
    pub fn new(shape: ViscousShape) -> Self {
        Self {
            shape,
            around: Self::DEFAULT_AROUND,
            radial: Self::DEFAULT_RADIAL,
            far: Some(Self::DEFAULT_FAR),
            outer_chords: 30.0,
            first_cell_layers: 0.1,
            courant: Self::DEFAULT_COURANT,
            spin_up_periods: 0.0,
            field_frames: 0,
        }
    }

    /// This section with `radial` rings, the grid refined or coarsened
    /// as a whole: its far stretch, if any, scaled with the rings
    /// ([`FarStretch::scaled`]).
    #[must_use]
    pub fn with_radial(&self, radial: usize) -> Self {
        Self {
            radial,
            far: self.far.map(|f| f.scaled(self.radial, radial)),
            ..self.clone()
        }
    }

    /// A plate of `thickness` chords at the default resolution.
    pub fn plate(thickness: f64) -> Self {
        Self::new(ViscousShape::Plate(thickness))
    }

    /// Checks, before any step, that this grid can resolve the flow at
    /// `reynolds` ([`TRAILING_EDGE_LAYER`]): what [`Self::run`] checks
    /// first, for a caller that wants to refuse a case early (a design's
    /// configuration). Cost: the section's map.
    ///
    /// # Errors
    /// [`ViscousError::Unresolved`]; the map's errors for a bad section.
    pub fn check_resolution(&self, reynolds: f64) -> Result<(), ViscousError> {
        self.grid(&self.map(0.0)?, reynolds).map(|_| ())
    }

    /// The conformal map of the section, the pitch axis `pivot` (chords
    /// from the leading edge) at the origin.
    fn map(&self, pivot: f64) -> Result<SectionMap, ViscousError> {
        let terms = self.laurent_terms()?;
        match self.outline(pivot)? {
            Outline::Contour(contour) => Ok(SectionMap::from_contour(&contour, terms)?),
            Outline::Ellipse(t) => Ok(SectionMap::ellipse(0.5, 0.5 * t, (0.5 - pivot, 0.0))?),
        }
    }

    /// How far the grid's section departs from the given one, chords,
    /// where it departs most among the map's samples
    /// ([`SectionMap::from_contour_with_deviation`]): the conformal map's
    /// series, kept to half the nodes round, smooths a corner or a fold.
    /// `None` for the ellipse, whose map is exact. Cost: one fit of
    /// the map (milliseconds; up to about a second for a contour no
    /// pre-map opens).
    ///
    /// # Errors
    /// As the run's: a bad thickness, a contour that is no simple curve,
    /// a map that does not converge or is not one-to-one.
    pub fn map_deviation(&self) -> Result<Option<f64>, ViscousError> {
        let terms = self.laurent_terms()?;
        match self.outline(0.0)? {
            Outline::Contour(contour) => Ok(Some(
                SectionMap::from_contour_with_deviation(&contour, terms)?.1,
            )),
            Outline::Ellipse(_) => Ok(None),
        }
    }

    /// The section's outline, the pitch axis `pivot` (chords from the
    /// leading edge) at the origin, its thickness checked.
    fn outline(&self, pivot: f64) -> Result<Outline, ViscousError> {
        let shifted = |points: &[(f64, f64)]| -> Vec<(f64, f64)> {
            points.iter().map(|&(x, y)| (x - pivot, y)).collect()
        };
        let contour = match &self.shape {
            ViscousShape::Ellipse(t) | ViscousShape::Plate(t) if !(0.005..=0.3).contains(t) => {
                return Err(ViscousError::Thickness(*t))
            }
            ViscousShape::Ellipse(t) => return Ok(Outline::Ellipse(*t)),
            ViscousShape::Plate(t) => {
                let plate = Contour::flat_plate(1.0 - t, *t, CONTOUR_POINTS)?;
                let points: Vec<(f64, f64)> = plate
                    .points()
                    .iter()
                    .map(|z| (z.re + 0.5 * t, z.im))
                    .collect();
                Contour::from_points(&shifted(&points))?
            }
            ViscousShape::Contour(points) => Contour::from_points(&shifted(points))?,
        };
        Ok(Outline::Contour(contour))
    }

    /// The Laurent terms of the section's maps: half the nodes round,
    /// once those are checked as the grid checks them (the map's own check
    /// of its terms would name those instead).
    fn laurent_terms(&self) -> Result<usize, ViscousError> {
        fwav_ns2d::check_around(self.around)?;
        Ok(self.around / 2)
    }

    /// The grid of this resolution for the map `map` at `reynolds`.
    ///
    /// # Errors
    /// [`ViscousError::Unresolved`] when its wall cells are longer than
    /// the laminar boundary layer is thick ([`TRAILING_EDGE_LAYER`]).
    fn grid(&self, map: &SectionMap, reynolds: f64) -> Result<GridSpec, ViscousError> {
        // The first cell's physical height over its height in ξ is
        // |∂z/∂ξ| at the wall: sized where that is largest. The map is
        // conformal, so the wall's cells are |∂z/∂ξ| dθ long.
        let stretch = (0..64)
            .map(|k| {
                let theta = f64::from(k) * std::f64::consts::TAU / 64.0;
                map.radial_derivative(Complex64::from_polar(1.0, theta))
                    .norm()
            })
            .fold(0.0, f64::max);
        self.wall_cells_resolve(stretch, reynolds)?;
        let first = self.first_cell_layers / reynolds.sqrt() / stretch;
        let outer_radius = self.outer_chords / map.scale();
        // At a low Reynolds number the layer is thick: the first cell is
        // kept at most half a uniform grid's, so that the rings still
        // crowd to the wall (a cylinder at Re 100 on 320 rings).
        // With a far stretch the wall's rings are the near grid's, so its
        // uniform cell is the one to stay below.
        let rings = self.far.map_or(self.radial, |f| f.near_radial);
        let uniform = outer_radius.ln() / (rings.max(2) - 1) as f64;
        Ok(GridSpec {
            around: self.around,
            radial: self.radial,
            outer_radius,
            first_cell: first.min(0.05).min(0.5 * uniform),
            far: self.far,
        })
    }

    /// Checks that the longest wall cell, `stretch` (the largest
    /// `|∂z/∂ξ|` at the wall, chords) times `2π / around`, is no longer
    /// than the laminar boundary layer at `reynolds` is thick at the
    /// trailing edge ([`TRAILING_EDGE_LAYER`]).
    ///
    /// # Errors
    /// [`ViscousError::Unresolved`], naming the fewest nodes round that
    /// would pass.
    fn wall_cells_resolve(&self, stretch: f64, reynolds: f64) -> Result<(), ViscousError> {
        let layer = TRAILING_EDGE_LAYER / reynolds.sqrt();
        let cell = stretch * std::f64::consts::TAU / self.around as f64;
        if cell <= layer {
            return Ok(());
        }
        let around =
            ((stretch * std::f64::consts::TAU / layer).ceil() as usize).next_multiple_of(2);
        Err(ViscousError::Unresolved {
            reynolds,
            cell,
            layer,
            around,
        })
    }
}

/// How far (chords) the grid's section may depart from the given contour
/// ([`ViscousSection::map_deviation`]) before `fwav aero2d --model ns`
/// warns. With 128 terms, smooth sections show 1.7e-5 to 3.3e-5 (NACA
/// 0012, 2412 and 6106 from 256 points: six to twelve times below), and
/// a NACA lower surface's corner at `x = p` or fold 1.4e-3 to 7.4e-3
/// (9112, 6130, 8120, 9120; `ns2d/tests/section_maps.rs`; 9112 through
/// the command's 512-point contour, 1.3e-3). A smooth section on too few
/// terms may pass it too (NACA 0012's boundary is 1.1e-4 chords off with
/// 32 terms): the warning names both causes.
pub const MAP_DEVIATION_WARNING: f64 = 2e-4;

/// A section's outline as its map is built ([`ViscousSection::map`]).
enum Outline {
    /// The ellipse of this thickness (chords), mapped exactly.
    Ellipse(f64),
    /// A contour, whose map is fitted.
    Contour(Contour),
}

/// What a viscous run leaves.
#[derive(Clone, Debug, PartialEq)]
pub struct ViscousRun {
    /// Loads sampled every `sample` chords travelled; no friction
    /// estimate (the forces include the friction).
    pub history: History,
    /// The sampling interval, chords travelled.
    pub sample: f64,
    /// The smallest time step taken, chords travelled.
    pub dt: f64,
    /// Time steps taken (the spin-up's included).
    pub steps: usize,
    /// Of which on the spin-up's grid ([`ViscousSection::spin_up_grid`]).
    pub spin_up_steps: usize,
    /// The grid's cells near the section as point vortices (their
    /// circulation), global frame, for a picture.
    pub vorticity: Vec<FreeVortex>,
    /// The section's outline at the end, global frame.
    pub body: Vec<(f64, f64)>,
    /// The wall's pressure and skin friction at the end.
    pub surface: SurfaceLoads,
    /// The flow at the end on every node (for ParaView).
    pub field: FlowField,
}

impl ViscousSection {
    /// Runs `path` at `reynolds` for `duration` chords travelled,
    /// sampling the loads every `period / 200` (or `duration / 2000`
    /// without a period); the first [`Self::spin_up_periods`] on a grid
    /// [`SPIN_UP_COARSENING`] times coarser each way ([`Self::spin_up_grid`]).
    /// The flows [`Self::field_frames`] asks for are let go
    /// ([`NoFrames`]): [`Self::run_into`] hands them on.
    ///
    /// Cost: 25.8 ns per cell per step (wall time, both cores of this
    /// 2-core machine, whose speed varies by up to half from hour to
    /// hour; 2026-12-05) on the default FWAV section at the default
    /// 384 × 256 nodes; the number of steps is set by the Courant number
    /// in the small cells at a thin section's ends as the stroke goes:
    /// 22,960 for that section's 4 cycles at Courant number 3, 58.2 s
    /// (`viscous_default_section::default_section_four_cycles_benchmark`;
    /// see [`ViscousError::TooManySteps`]).
    ///
    /// # Errors
    /// [`ViscousError`]: a bad thickness, the solver's, a time step that
    /// keeps falling, a spin-up as long as the run.
    pub fn run(
        &self,
        path: SectionPath,
        reynolds: f64,
        duration: f64,
    ) -> Result<ViscousRun, ViscousError> {
        self.run_into(path, reynolds, duration, &mut NoFrames)
    }

    /// [`Self::run`], handing `frames` the flows [`Self::field_frames`]
    /// asks for as the run reaches them.
    ///
    /// # Errors
    /// As [`Self::run`], and [`ViscousError::Frame`] when `frames` fails.
    pub fn run_into(
        &self,
        path: SectionPath,
        reynolds: f64,
        duration: f64,
        frames: &mut dyn FrameSink,
    ) -> Result<ViscousRun, ViscousError> {
        let build =
            |section: &Self, path: SectionPath| -> Result<Flow<SectionPath>, ViscousError> {
                let map = section.map(path.pivot())?;
                let spec = section.grid(&map, reynolds)?;
                Ok(Flow::new(&map, spec, path, 1.0 / reynolds)?)
            };
        self.run_flows(build, path, reynolds, duration, frames)
    }

    /// The grid of the spin-up ([`Self::spin_up_periods`]): its cells
    /// [`SPIN_UP_COARSENING`] times this grid's each way (the node
    /// counts divided by it, kept even and at least 16; the first cell
    /// that much higher); the section's map has half as many terms as
    /// nodes round, as every grid's.
    pub fn spin_up_grid(&self) -> Self {
        let fewer = |n: usize| ((n as f64 / SPIN_UP_COARSENING / 2.0).round() as usize * 2).max(16);
        Self {
            around: fewer(self.around),
            first_cell_layers: SPIN_UP_COARSENING * self.first_cell_layers,
            spin_up_periods: 0.0,
            ..self.with_radial(fewer(self.radial))
        }
    }

    /// Steps the flows `build` makes of this section (and of its
    /// spin-up grid first, when it has one) through `path` to
    /// `duration` at `reynolds`, sampling their loads and handing
    /// `frames` the flows [`Self::field_frames`] asks for.
    fn run_flows(
        &self,
        build: impl Fn(&Self, SectionPath) -> Result<Flow<SectionPath>, ViscousError>,
        path: SectionPath,
        reynolds: f64,
        duration: f64,
        frames: &mut dyn FrameSink,
    ) -> Result<ViscousRun, ViscousError> {
        self.far_growth_kept()?;
        let mut march = March::new(path.clone(), duration, self.courant);
        march.keep_frames(self.field_frames);
        let spin_up = self.spin_up_time(&path, duration)?;
        let mut flow = match spin_up {
            Some(until) => {
                let mut coarse = build(&self.spin_up_grid(), path.clone())?;
                march.to(&mut coarse, until, frames)?;
                march.spin_up_steps = march.steps;
                let mut fine = build(self, path.clone())?;
                fine.continue_from(&coarse)?;
                fine
            }
            None => build(self, path.clone())?,
        };
        march.to(&mut flow, duration, frames)?;
        let (vorticity, body) = picture(&flow, &path);
        let surface = SurfaceLoads::of(&flow, &path, 1.0 / reynolds);
        let field = FlowField::of(&flow, &path);
        march.last_frame(&field, frames)?;
        Ok(ViscousRun {
            history: march.history,
            sample: march.sample,
            dt: march.smallest,
            steps: march.steps,
            spin_up_steps: march.spin_up_steps,
            vorticity,
            body,
            surface,
            field,
        })
    }

    /// Checks that the far cells grow by at most [`MAX_FAR_GROWTH`], on
    /// this grid and on its spin-up's ([`Self::spin_up_grid`]) when it
    /// has one.
    ///
    /// # Errors
    /// [`ViscousError::FarTooCoarse`] when they grow by more (the grid
    /// coarsened too far as a whole), naming the fewest rings of this
    /// grid that would do.
    fn far_growth_kept(&self) -> Result<(), ViscousError> {
        let far_growth = |s: &Self| s.far.map_or(1.0, |f| f.growth);
        let coarsest = |s: &Self| {
            if s.spin_up_periods > 0.0 {
                far_growth(s).max(far_growth(&s.spin_up_grid()))
            } else {
                far_growth(s)
            }
        };
        let growth = coarsest(self);
        let Some(far) = self.far.filter(|_| growth > MAX_FAR_GROWTH) else {
            return Ok(());
        };
        // This grid's own bound, and past it the first whose spin-up keeps
        // the growth too.
        let fewest = (far.fewest_rings(self.radial).max(self.radial)..=8192)
            .find(|&n| coarsest(&self.with_radial(n)) <= MAX_FAR_GROWTH)
            .unwrap_or(8192);
        Err(ViscousError::FarTooCoarse {
            radial: self.radial,
            growth,
            max: MAX_FAR_GROWTH,
            fewest,
        })
    }

    /// When the spin-up ends (chords travelled), if the section has one.
    ///
    /// # Errors
    /// [`ViscousError::SpinUp`] for a spin-up on a path without a period,
    /// or not shorter than the run.
    fn spin_up_time(&self, path: &SectionPath, duration: f64) -> Result<Option<f64>, ViscousError> {
        let periods = self.spin_up_periods;
        if periods == 0.0 {
            return Ok(None);
        }
        let k = path.reduced_frequency();
        let until = periods * std::f64::consts::PI / k;
        if !(periods > 0.0 && k > 0.0 && until < duration) {
            return Err(ViscousError::SpinUp {
                periods,
                run: duration * k / std::f64::consts::PI,
            });
        }
        Ok(Some(until))
    }
}

/// The cells within [`PICTURE_RADIUS`] as point vortices and the wall,
/// in the global frame of [`super::case`] (the pivot at `x = pivot` plus
/// the surge, plunged by `h`).
fn picture(flow: &Flow<SectionPath>, path: &SectionPath) -> (Vec<FreeVortex>, Vec<(f64, f64)>) {
    let g = flow.grid();
    let placement = path.placement(flow.time());
    let place = |x: f64, y: f64| placement(Complex64::new(x, y));
    let omega = flow.vorticity();
    let mut cells: Vec<FreeVortex> = (1..g.nr - 1)
        .flat_map(|j| (0..g.nt).map(move |k| (j, k)))
        .filter_map(|(j, k)| {
            let i = g.at(j, k);
            let z = g.z[i];
            (z.re.hypot(z.im) < PICTURE_RADIUS).then(|| {
                let (x, y) = place(z.re, z.im);
                let area = g.jac[i] * g.slope[j] * g.d_eta * g.d_theta;
                FreeVortex {
                    x,
                    y,
                    gamma: omega[i] * area,
                }
            })
        })
        .collect();
    if cells.len() > PICTURE_CELLS {
        cells.sort_by(|a, b| b.gamma.abs().total_cmp(&a.gamma.abs()));
        cells.truncate(PICTURE_CELLS);
    }
    let body = (0..g.nt)
        .map(|k| {
            let z = g.z[g.at(0, k)];
            place(z.re, z.im)
        })
        .collect();
    (cells, body)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The default plate coarsened to 28 rings is refused naming 29
    /// (`1.045^(255/28) = 1.493`); with a spin-up, whose grid has 1.5
    /// times fewer rings, it names the fewest whose spin-up grid keeps
    /// the growth too.
    #[test]
    fn a_grid_coarsened_too_far_names_the_fewest_rings() {
        let plate = ViscousSection::plate(ViscousSection::DEFAULT_THICKNESS);
        let refused = |s: &ViscousSection| match s.far_growth_kept() {
            Err(ViscousError::FarTooCoarse { fewest, growth, .. }) => {
                assert!(growth > MAX_FAR_GROWTH);
                Some(fewest)
            }
            _ => None,
        };
        assert_eq!(refused(&plate.with_radial(28)), Some(29));
        assert_eq!(refused(&plate.with_radial(29)), None);
        let spun = ViscousSection {
            spin_up_periods: 2.0,
            ..plate.clone()
        };
        let fewest = refused(&spun.with_radial(29)).unwrap();
        let growth = |s: &ViscousSection| s.far.unwrap().growth;
        assert!(growth(&spun.with_radial(fewest).spin_up_grid()) <= MAX_FAR_GROWTH);
        assert!(growth(&spun.with_radial(fewest - 1).spin_up_grid()) > MAX_FAR_GROWTH);
        assert_eq!(refused(&spun.with_radial(fewest)), None);
        assert_eq!(refused(&spun), None);
    }

    /// More nodes round than a grid takes are named as such, not by the
    /// map's Laurent terms (half of them) that it would otherwise meet
    /// first.
    #[test]
    fn nodes_round_beyond_the_grids_range_are_named() {
        for around in [0, 8194, 100_000, 65] {
            let section = ViscousSection {
                around,
                ..ViscousSection::plate(ViscousSection::DEFAULT_THICKNESS)
            };
            let e = section.map(0.25).unwrap_err().to_string();
            let named = if around % 2 == 0 {
                format!("grid around = {around} is outside 16..=8192")
            } else {
                format!("grid around = {around} is odd: the nodes round must be even")
            };
            assert!(e.contains(&named) && !e.contains("Laurent"), "{e}");
            // A deforming section's maps are checked the same way, once,
            // not per sample.
            let flat = vec![vec![(0.0, 0.0), (0.5, 0.0), (1.0, 0.0)]; 4];
            let e = section.shape_maps(0.25, &flat).unwrap_err().to_string();
            assert!(e.contains(&named) && !e.contains("sample"), "{e}");
        }
    }

    /// A grid whose wall cells are longer than the laminar layer is thick
    /// at the trailing edge ([`TRAILING_EDGE_LAYER`]) is refused before
    /// any step, naming the fewest nodes round that pass; the default
    /// plate at the default FWAV section's Reynolds number (12,329, the
    /// discipline's) and at the CLI's (15,000) passes, its longest cells
    /// 0.19 and 0.21 of the layer. The plate's conformal map stretches
    /// the wall most at mid-chord, by `c / 2` per radian for a flat
    /// plate (Joukowski's map) and 5 % more for the 4 % plate's round
    /// ends: 384 round give cells of 0.00859 c against `π c / 384`.
    #[test]
    fn a_grid_too_coarse_for_the_reynolds_number_names_the_nodes_round() {
        let plate = ViscousSection::plate(ViscousSection::DEFAULT_THICKNESS);
        let map = plate.map(0.25).unwrap();
        let grid = |s: &ViscousSection, reynolds: f64| s.grid(&map, reynolds);
        for reynolds in [12_329.0, 15_000.0] {
            let layer = TRAILING_EDGE_LAYER / f64::sqrt(reynolds);
            let spec = grid(&plate, reynolds).unwrap();
            assert_eq!(spec.around, 384);
            // About a fifth of the layer, 5 % over a flat plate's π c / 384.
            let cell = match grid(
                &ViscousSection {
                    around: 16,
                    ..plate.clone()
                },
                reynolds,
            ) {
                Err(ViscousError::Unresolved { cell, .. }) => cell * 16.0 / 384.0,
                other => panic!("{other:?}"),
            };
            assert!(cell < 0.22 * layer, "{cell} {layer}");
            let flat = std::f64::consts::PI / 384.0;
            assert!(cell > flat && cell < 1.06 * flat, "{cell}");
        }
        // Re 1e8 on 64 nodes round (a run that once reported a thrust).
        let coarse = ViscousSection {
            around: 64,
            ..plate.clone()
        };
        let Err(e @ ViscousError::Unresolved { around, .. }) = grid(&coarse, 1e8) else {
            panic!("Re 1e8 on 64 round passed");
        };
        assert!(
            e.to_string()
                .contains(&format!("give at least {around} nodes round")),
            "{e}"
        );
        assert_eq!(around % 2, 0);
        let with = |around| ViscousSection {
            around,
            ..plate.clone()
        };
        assert!(grid(&with(around), 1e8).is_ok());
        assert!(matches!(
            grid(&with(around - 2), 1e8),
            Err(ViscousError::Unresolved { .. })
        ));
    }
}
