//! Declared settings: every key of a configuration file written once, as
//! data — its table, name, unit, allowed range and doc — and everything
//! people see about it derived from that declaration:
//!
//! - the range check of a parsed file ([`Table::check`]), whose error
//!   ([`SettingError`]) names the qualified key `table.key`, the value and
//!   the range as text generated from the declared range and unit;
//! - the commented TOML template of the file ([`Template`]), each key's
//!   comment being its doc, range and unit, and a key without a
//!   declaration (or a declaration without a key) an error.
//!
//! ```
//! use fwav_settings::{Allowed, Interval, Setting, Table, Value};
//!
//! struct Motor {
//!     resistance_ohm: f64,
//! }
//!
//! const MOTOR: Table<Motor> = Table {
//!     name: "motor",
//!     doc: "The DC motor.",
//!     settings: &[Setting {
//!         key: "resistance_ohm",
//!         unit: "ohm",
//!         allowed: Allowed::Real(Interval::positive()),
//!         doc: "Winding resistance",
//!         value: |m| Value::Real(m.resistance_ohm),
//!     }],
//! };
//!
//! let e = MOTOR.check(&Motor { resistance_ohm: 0.0 }).unwrap_err();
//! assert_eq!(e.to_string(), "motor.resistance_ohm = 0 is outside (0, inf) ohm");
//! ```
//!
//! Parsing stays with the caller (serde and TOML in the programs that use
//! this crate); this crate depends on nothing but `thiserror`.
//!
//! - [`range`]: allowed ranges as data and their text.
//! - [`setting`]: a declared key, a table of them, and the check.
//! - [`template`]: the commented TOML template.
//! - [`shown`]: a real number as a message shows it ([`Shown`]).

#![warn(missing_docs)]

pub mod range;
pub mod setting;
pub mod shown;
pub mod template;

pub use range::{Allowed, Bound, Integers, Interval, Limits};
pub use setting::{Setting, SettingError, Table, Value};
pub use shown::Shown;
pub use template::{Template, TemplateError};
