//! The `[flight]` table: the flight condition.

use fwav_settings::{Allowed, Interval, Setting, Table, Value};
use serde::{Deserialize, Serialize};

use crate::aeroelastic::model::FlightCondition;

/// The `[flight]` table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct FlightConfig {
    /// Flight speed, m/s.
    pub speed_m_s: f64,
    /// Air density, kg/m³.
    pub density_kg_m3: f64,
}

impl Default for FlightConfig {
    fn default() -> Self {
        Self {
            speed_m_s: FlightCondition::FWAV.speed,
            density_kg_m3: FlightCondition::FWAV.density,
        }
    }
}

impl FlightConfig {
    /// The flight condition in SI.
    pub fn condition(&self) -> FlightCondition {
        FlightCondition {
            speed: self.speed_m_s,
            density: self.density_kg_m3,
        }
    }
}

/// The `[flight]` table's settings.
pub const FLIGHT: Table<FlightConfig> = Table {
    name: "flight",
    doc: "The flight condition.",
    settings: &[
        Setting {
            key: "speed_m_s",
            unit: "m/s",
            allowed: Allowed::Real(Interval::closed(0.1, 50.0)),
            doc: "Flight speed",
            value: |f| Value::Real(f.speed_m_s),
        },
        Setting {
            key: "density_kg_m3",
            unit: "kg/m^3",
            allowed: Allowed::Real(Interval::closed(0.01, 5.0)),
            doc: "Air density; at most 5 (four times sea level's 1.225): a denser fluid loads \
                  the light membrane wing beyond the small-deflection floating frame (coarse \
                  16 x 6 wing: at 100 the tip swings 112 mm on a 150 mm semi-span, at 2000 \
                  187 mm with every step's coupling at its sub-iteration cap)",
            value: |f| Value::Real(f.density_kg_m3),
        },
    ],
};
