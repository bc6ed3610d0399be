//! The structural discipline (seed paper, "Topology optimization in the
//! structural discipline"): the carbon reinforcement layout of the wing by
//! nonlinear dynamic response topology optimization with equivalent
//! static loads (ESLSO).
//!
//! - [`pressure`]: the pressure history from the system analysis.
//! - [`response`]: step 1, the nonlinear dynamic response of a design.
//! - [`esl`]: step 2, the equivalent static loads `K_L u_N(t_i)`.
//! - [`simp`]: step 3, linear static SIMP with optimality criteria over
//!   every load case, one factorization an iteration.
//! - [`filter`]: SIMP's density filter.
//! - [`eslso`]: the cycle (steps 1–5: 0/1 transformation, stop rule).
//!
//! Imports: [`crate::shell`] (the structure it designs) and the pressure
//! handoff file of [`crate::aeroelastic`]; never the configuration, the
//! design driver or [`crate::output`].

pub mod esl;
pub mod eslso;
pub mod filter;
pub mod pressure;
pub mod response;
pub mod simp;
