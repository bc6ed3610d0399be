//! The built-in FWAV's configuration as a commented TOML file (`fwav
//! init`): every table and key with its default, unit and allowed range,
//! ready to edit. The values come from [`SystemConfig::default`] through
//! the TOML serializer, so the file always parses back to the default; the
//! comments come from [`KEYS`], and a key without one is an error (a new
//! configuration field must be documented here).

use crate::aeroelastic::config::SystemConfig;

/// A table's comment, written above its header.
const TABLES: [(&str, &str); 7] = [
    (
        "wing",
        "The wing: planform, shell mesh, and the carbon design layer over the mylar skin.",
    ),
    (
        "kinematics",
        "The initial flapping kinematics (the first system analysis flies them).",
    ),
    ("flight", "The flight condition."),
    (
        "analysis",
        "The system analysis: unsteady vortex lattice strongly coupled to the shell.",
    ),
    (
        "design",
        "The aerodynamic discipline: three levels (low, initial, high) of each kinematic\n# variable for the L18 array, and the weights of the combined objective\n# w_ct CT/CT_0 + w_eta eta/eta_0.",
    ),
    (
        "topology",
        "The structural discipline: ESLSO (nonlinear dynamic response, equivalent\n# static loads, linear SIMP, 0/1 layout).",
    ),
    (
        "mdois",
        "The MDOIS cycle loop: system analysis, then both disciplines, until no design\n# variable changes.",
    ),
];

/// Every key's comment: `(table, key, what it is, unit and allowed range)`.
pub const KEYS: &[(&str, &str, &str)] = &[
    ("wing", "semi_span_m", "Semi-span, m; [0.01, 2]."),
    ("wing", "root_chord_m", "Root chord, m; [0.005, 1]."),
    ("wing", "tip_chord_m", "Tip chord, m; [0.005, 1]."),
    (
        "wing",
        "spar_width_m",
        "Leading-edge carbon spar width (outside the design domain), m; [0.0001, 0.1].",
    ),
    (
        "wing",
        "root_attachment_m",
        "Root attachment length from the leading edge (clamped), m; [0.0001, 1].",
    ),
    (
        "wing",
        "span_elements",
        "Shell elements along the span; 2..=400.",
    ),
    (
        "wing",
        "chord_elements",
        "Shell elements along the chord; 2..=200.",
    ),
    (
        "wing",
        "carbon_fraction",
        "Uniform carbon density of the starting design (before the first layout); [0, 1].",
    ),
    (
        "kinematics",
        "frequency_hz",
        "Flapping frequency, Hz; [0.1, 200].",
    ),
    (
        "kinematics",
        "amplitude_deg",
        "Flapping amplitude (half the stroke), degrees; [0, 80].",
    ),
    (
        "kinematics",
        "mean_angle_deg",
        "Mean flapping angle, degrees; [-60, 60].",
    ),
    (
        "kinematics",
        "stroke_plane_deg",
        "Stroke-plane inclination (90: flapping across the flight direction), degrees; [0, 180].",
    ),
    ("flight", "speed_m_s", "Flight speed, m/s; [0.1, 50]."),
    (
        "flight",
        "density_kg_m3",
        "Air density, kg/m^3; [0.01, 2000].",
    ),
    (
        "analysis",
        "cycles",
        "Flapping cycles simulated (the last one is reported); 1..=100.",
    ),
    (
        "analysis",
        "steps_per_cycle",
        "Time steps per flapping cycle; 8..=2000.",
    ),
    (
        "analysis",
        "chordwise_panels",
        "Vortex-lattice panels along the chord; 1..=64.",
    ),
    (
        "analysis",
        "spanwise_panels",
        "Vortex-lattice panels along the span; 1..=200.",
    ),
    (
        "analysis",
        "rigid",
        "Rigid wing (no structure); true or false.",
    ),
    (
        "analysis",
        "coupling_tolerance",
        "Interface residual that ends a step's coupling iterations; [1e-12, 0.5].",
    ),
    (
        "analysis",
        "max_subiterations",
        "Coupling iterations allowed a step; 1..=1000.",
    ),
    (
        "analysis",
        "rho_inf",
        "Spectral radius at infinity of the structural integrator; [0, 1].",
    ),
    (
        "analysis",
        "free_wake_cycles",
        "Wake that rolls up freely, flapping cycles; [0, 100].",
    ),
    (
        "analysis",
        "wake_cycles",
        "Wake kept behind the wing, flapping cycles; [0.01, 100].",
    ),
    (
        "analysis",
        "core_radius_chords",
        "Vortex core radius, root chords; [1e-6, 0.49].",
    ),
    (
        "design",
        "frequency_hz",
        "Frequency levels, Hz; increasing, in [0.1, 200].",
    ),
    (
        "design",
        "amplitude_deg",
        "Amplitude levels, degrees; increasing, in [0, 80].",
    ),
    (
        "design",
        "mean_angle_deg",
        "Mean angle levels, degrees; increasing, in [-60, 60].",
    ),
    (
        "design",
        "stroke_plane_deg",
        "Stroke-plane levels, degrees; increasing, in [0, 180].",
    ),
    (
        "design",
        "thrust_weight",
        "Weight of the relative thrust gain CT/CT_0; [0, 100].",
    ),
    (
        "design",
        "efficiency_weight",
        "Weight of the relative efficiency gain eta/eta_0; [0, 100].",
    ),
    (
        "design",
        "seed",
        "Seed of the genetic algorithm (NSGA-II); any non-negative integer.",
    ),
    (
        "topology",
        "mass_fraction",
        "Carbon mass allowed over the design domain, fraction of the full layer; [0.01, 1].",
    ),
    ("topology", "penalty", "SIMP penalty; [1, 6]."),
    (
        "topology",
        "filter_radius_mm",
        "Density filter radius, mm; [0.01, 1000].",
    ),
    (
        "topology",
        "move_limit",
        "SIMP move limit an iteration; [0.01, 1].",
    ),
    (
        "topology",
        "simp_iterations",
        "SIMP iterations allowed an ESLSO cycle; 1..=10000.",
    ),
    (
        "topology",
        "simp_tolerance",
        "SIMP stops when no density changes more than this; [1e-9, 0.5].",
    ),
    (
        "topology",
        "threshold",
        "Density at and above which an element keeps its carbon (0/1 layout); [0.01, 0.99].",
    ),
    (
        "topology",
        "max_cycles",
        "ESLSO cycles allowed in one structural discipline run; 1..=100.",
    ),
    (
        "topology",
        "layout_tolerance",
        "ESLSO stops when a cycle that analysed a 0/1 layout flips at most this fraction\n# of the design elements (0: none, the paper's rule); [0, 0.5].",
    ),
    (
        "topology",
        "periods",
        "Pressure periods of the nonlinear dynamic analysis (the last is sampled); 2..=50.",
    ),
    (
        "topology",
        "sample_every",
        "One equivalent static load case every this many steps; 1..=10000, at most the steps a period.",
    ),
    (
        "topology",
        "rho_inf",
        "Generalized-alpha spectral radius of the dynamic analysis; [0, 1].",
    ),
    (
        "topology",
        "newton_tolerance",
        "Newton tolerance of the dynamic analysis, relative; [1e-12, 0.1].",
    ),
    (
        "topology",
        "esl",
        "Load cases: \"dalembert\" (f - M a) or \"displacement\" (K_L u_N, the paper's eq. (12)).",
    ),
    (
        "mdois",
        "max_cycles",
        "Design cycles allowed; 1..=50. At the cap the last proposal is analysed once more and the cap reported.",
    ),
    (
        "mdois",
        "kinematics_tolerance",
        "A kinematic variable is unchanged when it moved by at most this fraction of its\n# level range (high - low level of [design]); [0, 0.5].",
    ),
    (
        "mdois",
        "layout_tolerance",
        "The layout is unchanged when at most this fraction of the design elements\n# changed (0: none, the paper's rule; 0.01 by default, see the topology key); [0, 0.5].",
    ),
];

/// Why the template could not be produced.
#[derive(Debug, thiserror::Error)]
pub enum TemplateError {
    /// The default configuration did not serialize (a bug).
    #[error("the default configuration does not serialize as TOML: {0}")]
    Serialize(String),
    /// A key has no comment in [`KEYS`] (a bug: document the new key).
    #[error("configuration key {table}.{key} has no comment in the template")]
    Undocumented {
        /// The table.
        table: String,
        /// The key.
        key: String,
    },
}

/// The commented TOML of `config` (normally [`SystemConfig::default`]).
pub fn commented_toml(config: &SystemConfig) -> Result<String, TemplateError> {
    let plain = toml::to_string(config).map_err(|e| TemplateError::Serialize(e.to_string()))?;
    let mut out = String::from(
        "# fwav design configuration: the built-in FWAV's values (`fwav init`).\n\
         # Every key is optional (a missing one takes the value shown); units are in\n\
         # the key names, angles in degrees; each comment gives the allowed range.\n\
         # Run it with `fwav design --config FILE [--out DIR]`.\n",
    );
    let mut table = String::new();
    for line in plain.lines() {
        let trimmed = line.trim();
        if let Some(name) = trimmed.strip_prefix('[').and_then(|t| t.strip_suffix(']')) {
            table = name.to_string();
            let comment = TABLES
                .iter()
                .find(|(t, _)| *t == name)
                .map(|(_, c)| *c)
                .ok_or_else(|| TemplateError::Undocumented {
                    table: name.to_string(),
                    key: String::new(),
                })?;
            out.push_str(&format!("\n# {comment}\n{trimmed}\n"));
        } else if let Some((key, _)) = trimmed.split_once('=') {
            let key = key.trim();
            let comment = KEYS
                .iter()
                .find(|(t, k, _)| *t == table && *k == key)
                .map(|(_, _, c)| *c)
                .ok_or_else(|| TemplateError::Undocumented {
                    table: table.clone(),
                    key: key.to_string(),
                })?;
            out.push_str(&format!("# {comment}\n{trimmed}\n"));
        } else if !trimmed.is_empty() {
            out.push_str(trimmed);
            out.push('\n');
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The template parses back to the default, documents every key once
    /// and carries no comment for a key that no longer exists.
    #[test]
    fn template_parses_back_to_the_default() {
        let text = commented_toml(&SystemConfig::default()).unwrap();
        assert_eq!(
            SystemConfig::from_toml(&text).unwrap(),
            SystemConfig::default()
        );
        let keys = text
            .lines()
            .filter(|l| !l.starts_with('#') && l.contains('='))
            .count();
        assert_eq!(keys, KEYS.len(), "{text}");
        for (table, _) in TABLES {
            assert!(text.contains(&format!("[{table}]")), "[{table}]");
        }
    }
}
