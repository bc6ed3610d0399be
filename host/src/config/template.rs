//! The built-in FWAV's configuration as a commented TOML file (`fwav
//! init`, and a design run's `config.toml`): every table and key with its
//! default, unit and allowed range, ready to edit. The values come from
//! [`SystemConfig::default`] through the TOML serializer, so the file
//! always parses back to the default; the comments come from the tables'
//! declarations, and a key without one (or a declaration without a key)
//! is an error.

use fwav_settings::{Template, TemplateError};

use super::{actuator, analysis, design, flight, kinematics, mdois, topology, wing, SystemConfig};

/// The file's opening comment.
const HEADER: &str = "fwav design configuration: the built-in FWAV's values (`fwav init`).
Every key is optional (a missing one takes the value shown); units are in
the key names, angles in degrees; each comment gives the allowed range.
Run it with `fwav design --config FILE [--out DIR]`.";

/// Why the template could not be produced.
#[derive(Debug, thiserror::Error)]
pub enum CommentedTomlError {
    /// The configuration did not serialize (a bug).
    #[error("the configuration does not serialize as TOML: {0}")]
    Serialize(#[from] toml::ser::Error),
    /// The TOML and the declarations disagree (a bug: declare the new key).
    #[error(transparent)]
    Undeclared(#[from] TemplateError),
}

/// The file's tables, in its order, with their declarations.
fn template() -> Template {
    Template::new(HEADER)
        .table(&wing::WING)
        .table(&kinematics::KINEMATICS)
        .table(&flight::FLIGHT)
        .table(&analysis::ANALYSIS)
        .table(&design::DESIGN)
        .table(&topology::TOPOLOGY)
        .table(&mdois::MDOIS)
        .table(&actuator::ACTUATOR)
}

/// The commented TOML of `config` (normally [`SystemConfig::default`]).
pub fn commented_toml(config: &SystemConfig) -> Result<String, CommentedTomlError> {
    let plain = toml::to_string(config)?;
    Ok(template().render(&plain)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The template parses back to the default and documents every key
    /// and table (rendering fails on an undeclared or a stale key).
    #[test]
    fn template_parses_back_to_the_default() {
        let text = commented_toml(&SystemConfig::default()).unwrap();
        assert_eq!(
            SystemConfig::from_toml(&text).unwrap(),
            SystemConfig::default()
        );
        for table in [
            "wing",
            "kinematics",
            "flight",
            "analysis",
            "design",
            "topology",
            "mdois",
            "actuator",
        ] {
            assert!(text.contains(&format!("\n[{table}]\n")), "[{table}]");
        }
        assert!(
            text.contains("# Flapping frequency; [0.1, 200] Hz.\nfrequency_hz = 11.0\n"),
            "{text}"
        );
    }
}
