//! The structural discipline's topology optimization (ESLSO, seed paper):
//! the linear static SIMP step over many load cases, with its density
//! filter. (The equivalent static loads and the outer ESLSO loop are to
//! come.)
//!
//! - [`filter`]: the density filter.
//! - [`simp`]: SIMP with optimality criteria, one factorization an
//!   iteration for every load case.

pub mod filter;
pub mod simp;
