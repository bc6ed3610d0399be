//! The plant model against analytic solutions.

use std::f64::consts::PI;

use fwav_actuator::params::PlantParams;
use fwav_actuator::plant::{Drive, Plant};

/// Blade elements vs the closed form for a linear taper:
/// `int_0^R c(r) r^3 dr = c_root R^4/4 + (c_tip - c_root) R^4/5`.
#[test]
fn blade_element_integral_matches_the_closed_form() {
    let w = PlantParams::default().wing;
    let r4 = w.span_m.powi(4);
    let exact = 0.5
        * w.air_density_kg_m3
        * w.drag_coefficient
        * (w.root_chord_m * r4 / 4.0 + (w.tip_chord_m - w.root_chord_m) * r4 / 5.0);
    let rel = (w.aero_damping() - exact).abs() / exact;
    assert!(rel < 1e-4, "relative error {rel}");
}

/// With the bridge open and no losses the wing is an undamped oscillator:
/// period 2 pi sqrt(J / k), energy conserved.
#[test]
fn free_oscillation_has_the_spring_mass_period() {
    let mut p = PlantParams::default();
    p.wing.drag_coefficient = 0.0;
    p.motor.coulomb_friction_nm = 0.0;
    p.motor.viscous_friction_nms_per_rad = 0.0;
    let mut plant = Plant::new(&p);
    plant.state.angle_rad = 0.3;
    let e0 = plant.stored_energy();
    let period = 2.0 * PI * (plant.inertia() / p.transmission.spring_nm_per_rad).sqrt();
    let dt = 1e-5;
    let off = Drive {
        duty: 0.0,
        enabled: false,
    };
    // Time of the 10th upward zero crossing.
    let mut crossings = Vec::new();
    let mut prev = plant.state.angle_rad;
    while crossings.len() < 10 {
        plant.step(off, dt);
        let now = plant.state.angle_rad;
        if prev < 0.0 && now >= 0.0 {
            crossings.push(plant.time_s - dt * now / (now - prev));
        }
        prev = now;
    }
    let measured = (crossings[9] - crossings[0]) / 9.0;
    assert!(
        (measured - period).abs() / period < 1e-6,
        "{measured} vs {period}"
    );
    assert!(
        (plant.stored_energy() - e0).abs() / e0 < 1e-8,
        "energy drift"
    );
}

/// Locked rotor at full duty: the current settles at V_b / (R + R_b) with
/// time constant L / (R + R_b).
#[test]
fn locked_rotor_current_is_ohms_law() {
    let p = PlantParams::default();
    let mut plant = Plant::new(&p);
    plant.stalled = true;
    let on = Drive {
        duty: 1.0,
        enabled: true,
    };
    let r = p.motor.resistance_ohm + p.supply.internal_resistance_ohm;
    let tau = p.motor.inductance_h / r;
    let dt = 1e-6;
    let steps = (tau / dt).round() as usize;
    for _ in 0..steps {
        plant.step(on, dt);
    }
    let i_final = p.supply.battery_v / r;
    let t = steps as f64 * dt;
    let expected = i_final * (1.0 - (-t / tau).exp());
    assert!(
        (plant.state.current_a - expected).abs() / expected < 1e-4,
        "{} vs {expected}",
        plant.state.current_a
    );
    for _ in 0..20 * steps {
        plant.step(on, dt);
    }
    assert!((plant.state.current_a - i_final).abs() / i_final < 1e-6);
}
