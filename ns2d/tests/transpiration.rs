//! The transpiring wall (`Flow::transpiring`) against the moving wall.
//!
//! A section whose shape changes a little about a mean can be run on a
//! grid that stays on the mean shape, the deformation given to the flow
//! by the wall's velocity alone (the transpiration condition: Lighthill
//! 1958, *J. Fluid Mech.* 4, "On displacement thickness"). What it leaves
//! out is where the wall is, so it is exact to first order in the
//! displacement: a plunge of amplitude `h` given so differs from the
//! same plunge as the frame's motion (the path validated against the
//! published cylinders and Wang's hovering ellipse,
//! `tests/reference_flows.rs`) by a lift of order `h²`, against the
//! plunge's own lift of order `h`. The test measures that order: the
//! difference relative to the plunge's lift halves with the amplitude.
//!
//! Case: an ellipse of thickness ratio 0.2 (chord 1) in a unit stream at
//! Re 200, plunging `h sin(πt)` over one period of 2 chords travelled,
//! 128 × 96 nodes, dt 0.004; the lift compared over the period's second
//! half, past the start.

use std::f64::consts::PI;

use fwav_ns2d::{
    Complex64, Deformation, Flow, GridSpec, Motion, PlungePitch, SectionMap, SteadyStream,
};

const PERIOD: f64 = 2.0;
const STEPS: usize = 500;
const SAMPLES: usize = 16;
const VISCOSITY: f64 = 1.0 / 200.0;

fn ellipse() -> SectionMap {
    SectionMap::ellipse(0.5, 0.1, (0.0, 0.0)).unwrap()
}

fn grid() -> GridSpec {
    GridSpec {
        around: 128,
        radial: 96,
        outer_radius: 40.0,
        first_cell: 0.01,
        far: None,
    }
}

/// The lift each step of `flow`, over one period.
fn lift<M: Motion + Send>(mut flow: Flow<M>) -> Vec<f64> {
    let dt = PERIOD / STEPS as f64;
    (0..STEPS)
        .map(|_| {
            flow.step(dt).unwrap();
            flow.loads().force.im
        })
        .collect()
}

/// The plunge `h sin(πt)` as the frame's motion.
fn frame_plunge(h: f64) -> PlungePitch {
    PlungePitch {
        speed: 1.0,
        omega: PI,
        plunge: h,
        mean_pitch: 0.0,
        pitch: 0.0,
        phase: 0.0,
    }
}

/// The same plunge as a deformation: the ellipse's map carried by it.
fn plunge_history(h: f64) -> Deformation {
    let maps: Vec<SectionMap> = (0..SAMPLES)
        .map(|i| {
            let t = PERIOD * i as f64 / SAMPLES as f64;
            ellipse().moved(0.0, Complex64::new(0.0, h * (PI * t).sin()))
        })
        .collect();
    Deformation::periodic(&maps, PERIOD).unwrap()
}

/// The largest lift difference over the period's second half between the
/// plunge of `h` as the frame's and as the wall's transpiration, relative
/// to the frame's largest lift there.
fn transpiration_error(h: f64) -> f64 {
    let still = SteadyStream {
        speed: 1.0,
        kick_rate: 0.0,
        kick_period: 1.0,
    };
    let exact = lift(Flow::new(&ellipse(), grid(), frame_plunge(h), VISCOSITY).unwrap());
    let flow = Flow::transpiring(plunge_history(h), grid(), still, VISCOSITY).unwrap();
    let transpired = lift(flow);
    let half = STEPS / 2;
    let scale = exact[half..].iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    exact[half..]
        .iter()
        .zip(&transpired[half..])
        .map(|(a, b)| (a - b).abs() / scale)
        .fold(0.0, f64::max)
}

/// First order in the displacement: the lift's relative error halves as
/// the amplitude halves (an observed order between 0.7 and 1.4), and is
/// below 4 % at `h` = 0.02 chords.
#[test]
#[ignore = "fails, so the transpiring wall is not adopted: the lift's relative error is 2.58, 2.41, 2.36 at h = 0.04, 0.02, 0.01 (2026-12-06; no-slip at the mean wall misses d·∂u/∂n, of the plunge velocity's order)"]
fn a_small_plunge_by_transpiration_is_the_plunge_to_first_order() {
    let errors: Vec<f64> = [0.04, 0.02, 0.01]
        .iter()
        .map(|&h| transpiration_error(h))
        .collect();
    let orders: Vec<f64> = errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect();
    eprintln!("relative lift errors {errors:?}, observed orders {orders:?}");
    for order in &orders {
        assert!((0.7..1.4).contains(order), "{errors:?} {orders:?}");
    }
    assert!(errors[1] < 0.04, "{errors:?}");
}
