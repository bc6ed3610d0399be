//! The validation cases of fwav's solvers: each computes one number with
//! the library and compares it with a published or analytic reference
//! value (`fwav validate` runs them; the integration tests in `tests/`
//! assert on many of them).
//!
//! One file per solver family: [`aero2d`] (the discrete-vortex LDVM and the
//! panel method), [`shell`] (shell finite elements: linear, modal,
//! transient, geometrically nonlinear), [`uvlm`] (the unsteady vortex
//! lattice) and [`optimizers`] (L18, RSM, NSGA-II). [`all`] lists every
//! case in that order.
//!
//! A case is a [`Validation`]: what is compared ([`Spec`]: name, quantity
//! and units, the citation, how the error is measured and the tolerance),
//! a function giving the reference value and a function computing the value
//! with the solver. [`Validation::run`] turns them into a [`Case`]: value,
//! reference value, error, pass. A solver error (or panic) fails the case
//! with its text instead of stopping the run. Reference values are the
//! cited publications' numbers, or analytic solutions evaluated
//! independently of the solver under test (each case says which); the
//! Navier–Stokes convergence cases (`ns2d::convergence`) compare a change,
//! the result refined against the result, with 0 (a verification that
//! issue 23 asks for, not a comparison with published data).
//!
//! Some cases share one expensive computation (the three Leissa modes come
//! from one modal analysis, the NAFEMS 21T numbers from one transient run):
//! it runs once per process, on the first case that needs it, and is
//! remembered (the inputs are fixed, the results deterministic).
//!
//! Imports: the solver rooms it checks ([`crate::aero2d`], [`crate::uvlm`],
//! [`crate::shell`], [`crate::optimize`]), and for the convergence cases
//! the discipline's section evaluation ([`crate::discipline::section`])
//! and the system analysis's section file it reads; nothing imports it
//! but the program.

use std::sync::{Arc, OnceLock};
use std::time::Instant;

use serde::Serialize;

pub mod aero2d;
pub mod karman_trefftz;
pub mod ns2d;
pub mod optimizers;
pub mod shell;
pub mod uvlm;

/// The solver family a case validates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Solver {
    /// 2D unsteady aerodynamics: the thin-plate discrete-vortex method
    /// (LDVM) and the source/doublet panel method ([`crate::aero2d`]).
    Aero2d,
    /// Shell finite elements ([`crate::shell`]).
    Shell,
    /// The unsteady vortex-lattice method ([`crate::uvlm`]).
    Uvlm,
    /// Design of experiments, response surfaces and NSGA-II
    /// ([`crate::optimize`]).
    Optimizers,
    /// The laminar Navier–Stokes section solver (`fwav-ns2d`).
    Ns2d,
}

impl Solver {
    /// The family's name as printed (`aero2d`, `shell`, `uvlm`,
    /// `optimizers`).
    pub fn name(self) -> &'static str {
        match self {
            Solver::Aero2d => "aero2d",
            Solver::Shell => "shell",
            Solver::Uvlm => "uvlm",
            Solver::Optimizers => "optimizers",
            Solver::Ns2d => "ns2d",
        }
    }
}

/// How a case measures its error.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ErrorKind {
    /// `value / reference - 1` (a fraction, not per cent).
    Relative,
    /// `value - reference`, in the case's units.
    Absolute,
}

/// What a case compares: everything but the numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spec {
    /// Unique name, `family/case` (what `fwav validate --only` matches).
    pub name: &'static str,
    /// The solver family.
    pub solver: Solver,
    /// The source of the reference value: publication, table or equation.
    pub reference: &'static str,
    /// The quantity compared.
    pub quantity: &'static str,
    /// Units of the value and the reference value (`1` when
    /// dimensionless).
    pub units: &'static str,
    /// How the error is measured.
    pub error_kind: ErrorKind,
    /// The case passes when `|error|` is below this (a fraction for
    /// [`ErrorKind::Relative`], the case's units for
    /// [`ErrorKind::Absolute`]), or the error is exactly 0.
    pub tolerance: f64,
}

/// A value computed by a case's solver, with an optional remark (where a
/// worst deviation occurred, say).
#[derive(Clone, Debug, PartialEq)]
pub struct Measured {
    /// The value, in the case's units.
    pub value: f64,
    /// A remark printed beside the result.
    pub note: Option<String>,
}

impl From<f64> for Measured {
    fn from(value: f64) -> Self {
        Self { value, note: None }
    }
}

/// Why a case's value could not be computed.
#[derive(Debug, thiserror::Error)]
pub enum ValidationError {
    /// The shell mesh was refused.
    #[error("shell mesh: {0}")]
    Mesh(#[from] crate::shell::mesh::MeshError),
    /// Shell assembly or linear solution failed.
    #[error("shell assembly: {0}")]
    Assembly(#[from] crate::shell::assembly::AssemblyError),
    /// The shell eigenvalue analysis failed.
    #[error("shell modal analysis: {0}")]
    Modal(#[from] crate::shell::modal::ModalError),
    /// The linear shell transient failed.
    #[error("shell transient: {0}")]
    Dynamics(#[from] crate::shell::dynamics::DynamicsError),
    /// The nonlinear static shell analysis failed.
    #[error("shell nonlinear static: {0}")]
    Nonlinear(#[from] crate::shell::nonlinear::NonlinearError),
    /// The panel method failed.
    #[error("panel method: {0}")]
    Panel(#[from] crate::aero2d::panel::PanelError),
    /// A section shape was refused.
    #[error("section shape: {0}")]
    Shape(#[from] crate::aero2d::panel::ShapeError),
    /// A NACA section could not be generated.
    #[error("NACA section: {0}")]
    Naca(#[from] crate::aero2d::naca::NacaError),
    /// A camber line was refused.
    #[error("camber line: {0}")]
    Camber(#[from] crate::aero2d::camber::CamberError),
    /// The vortex-lattice solver failed.
    #[error("UVLM: {0}")]
    Uvlm(#[from] crate::uvlm::UvlmError),
    /// An orthogonal array or design failed.
    #[error("design of experiments: {0}")]
    Doe(#[from] crate::optimize::doe::DoeError),
    /// ANOM failed.
    #[error("ANOM: {0}")]
    Anom(#[from] crate::optimize::anom::AnomError),
    /// A response surface fit failed.
    #[error("response surface: {0}")]
    Rsm(#[from] crate::optimize::rsm::RsmError),
    /// NSGA-II refused its setup.
    #[error("NSGA-II: {0}")]
    Nsga2(#[from] crate::optimize::nsga2::Nsga2Error),
    /// A ZDT problem was evaluated wrongly.
    #[error("ZDT problem: {0}")]
    Zdt(#[from] crate::optimize::zdt::ZdtError),
    /// A front metric failed.
    #[error("front metric: {0}")]
    Metric(#[from] crate::optimize::metrics::MetricError),
    /// The solver ran but its result lacks what the case reads (a mode, a
    /// node, a load step, a sample), or the built-in reference data is
    /// malformed.
    #[error("{0}")]
    Missing(String),
    /// The shared computation this case reads failed (once, for every case
    /// that reads it).
    #[error(transparent)]
    Shared(Arc<ValidationError>),
}

/// One case's result (serialized as it is for `fwav validate --json`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Case {
    /// Unique name, `family/case`.
    pub name: &'static str,
    /// The solver family.
    pub solver: Solver,
    /// The source of the reference value.
    pub reference: &'static str,
    /// The quantity compared.
    pub quantity: &'static str,
    /// Units of `value` and `reference_value`.
    pub units: &'static str,
    /// The solver's value (`None` when the solver failed).
    pub value: Option<f64>,
    /// The reference value.
    pub reference_value: f64,
    /// How `error` and `tolerance` are measured.
    pub error_kind: ErrorKind,
    /// `value / reference_value - 1` or `value - reference_value` (`None`
    /// when the solver failed).
    pub error: Option<f64>,
    /// The case passes when `|error|` is below this (or exactly 0).
    pub tolerance: f64,
    /// Whether `|error| < tolerance` or `error == 0` (false when the solver
    /// failed or the value is not finite).
    pub pass: bool,
    /// A remark on the value (where a worst deviation occurred, say).
    pub note: Option<String>,
    /// The solver's error text when it failed.
    pub failure: Option<String>,
    /// Wall-clock time of the case, seconds (including a shared
    /// computation when this case ran it first).
    pub run_time_s: f64,
}

/// A validation case: what it compares, its reference value and how its
/// value is computed.
#[derive(Clone, Copy, Debug)]
pub struct Validation {
    /// What is compared.
    pub spec: Spec,
    /// The reference value (in `spec.units`; never computed by the solver
    /// under test).
    pub reference: fn() -> f64,
    /// The value, computed by the solver under test.
    pub compute: fn() -> Result<Measured, ValidationError>,
}

impl Validation {
    /// Runs the case: computes the value, compares it with the reference.
    /// A solver error or panic gives a failed case with its text.
    pub fn run(&self) -> Case {
        let started = Instant::now();
        let reference_value = (self.reference)();
        let computed = std::panic::catch_unwind(self.compute).unwrap_or_else(|panic| {
            let text = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            Err(ValidationError::Missing(format!("panicked: {text}")))
        });
        let s = self.spec;
        let (value, note, failure) = match computed {
            Ok(m) => (Some(m.value), m.note, None),
            Err(e) => (None, None, Some(e.to_string())),
        };
        let error = value.map(|v| match s.error_kind {
            ErrorKind::Relative => v / reference_value - 1.0,
            ErrorKind::Absolute => v - reference_value,
        });
        Case {
            name: s.name,
            solver: s.solver,
            reference: s.reference,
            quantity: s.quantity,
            units: s.units,
            value,
            reference_value,
            error_kind: s.error_kind,
            error,
            tolerance: s.tolerance,
            pass: error.is_some_and(|e| e.abs() < s.tolerance || e == 0.0),
            note,
            failure,
            run_time_s: started.elapsed().as_secs_f64(),
        }
    }
}

/// Every validation case, family by family (aero2d, shell, uvlm,
/// optimizers, ns2d).
pub fn all() -> Vec<Validation> {
    let mut cases = aero2d::cases();
    cases.extend(shell::cases());
    cases.extend(uvlm::cases());
    cases.extend(optimizers::cases());
    cases.extend(ns2d::cases());
    cases
}

/// The cases whose name contains `filter` (all of them for `None`).
pub fn matching(filter: Option<&str>) -> Vec<Validation> {
    all()
        .into_iter()
        .filter(|v| filter.is_none_or(|f| v.spec.name.contains(f)))
        .collect()
}

/// The remembered result of a computation several cases share.
type Memo<T> = OnceLock<Result<T, Arc<ValidationError>>>;

/// A computation shared by several cases: run once per process by the
/// first caller, remembered in `cell` (an error too, shared by every
/// caller).
fn shared<T: Clone>(
    cell: &'static Memo<T>,
    compute: impl FnOnce() -> Result<T, ValidationError>,
) -> Result<T, ValidationError> {
    cell.get_or_init(|| compute().map_err(Arc::new))
        .clone()
        .map_err(ValidationError::Shared)
}

/// `Missing` with a message.
fn missing(what: impl Into<String>) -> ValidationError {
    ValidationError::Missing(what.into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_prefixed_by_their_family() {
        let cases = all();
        let mut names: Vec<&str> = cases.iter().map(|v| v.spec.name).collect();
        for v in &cases {
            assert!(
                v.spec
                    .name
                    .starts_with(&format!("{}/", v.spec.solver.name())),
                "{}",
                v.spec.name
            );
            assert!(v.spec.tolerance >= 0.0 && !v.spec.reference.is_empty());
        }
        names.sort_unstable();
        let n = names.len();
        names.dedup();
        assert_eq!(names.len(), n);
        for solver in [
            Solver::Aero2d,
            Solver::Shell,
            Solver::Uvlm,
            Solver::Optimizers,
        ] {
            assert!(cases.iter().any(|v| v.spec.solver == solver));
        }
    }

    #[test]
    fn errors_and_panics_fail_the_case() {
        let spec = Spec {
            name: "shell/test",
            solver: Solver::Shell,
            reference: "none",
            quantity: "x",
            units: "1",
            error_kind: ErrorKind::Relative,
            tolerance: 0.1,
        };
        let failing = Validation {
            spec,
            reference: || 1.0,
            compute: || Err(missing("no such node")),
        };
        let case = failing.run();
        assert!(!case.pass);
        assert_eq!(case.failure.as_deref(), Some("no such node"));
        let panicking = Validation {
            spec,
            reference: || 1.0,
            compute: || panic!("index out of bounds"),
        };
        let case = panicking.run();
        assert!(!case.pass && case.failure.unwrap().contains("index out of bounds"));
        let close = Validation {
            spec,
            reference: || 2.0,
            compute: || Ok(2.1.into()),
        };
        let case = close.run();
        assert!(case.pass && (case.error.unwrap() - 0.05).abs() < 1e-12);
        let nan = Validation {
            spec,
            reference: || 2.0,
            compute: || Ok(f64::NAN.into()),
        };
        assert!(!nan.run().pass);
    }
}
