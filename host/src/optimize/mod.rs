//! Design of experiments and optimization: the generic math of the
//! aerodynamic discipline (kinematics) optimization of the MDOIS process.
//!
//! The paper's flow for the flapping kinematics is: a Taguchi L18 array
//! ([`doe`]) screens the design variables, the analysis of means ([`anom`])
//! picks the promising levels, a quadratic response surface ([`rsm`]) is fit
//! around them, and NSGA-II ([`nsga2`]) searches the trade-off between the
//! objectives, on the fast non-dominated sorting and crowding distance of
//! [`pareto`]. [`zdt`] holds the standard bi-objective test problems with
//! their analytic Pareto fronts, and [`metrics`] the inverted generational
//! distance used to score an obtained front against them.
//!
//! Nothing here knows about wings: every part takes plain numbers or a
//! closure and returns typed errors. References are in
//! `shared/REFERENCES.md`, section "Design of experiments and optimization".
//!
//! Imports: no other room of the crate.

pub mod anom;
pub mod doe;
pub mod metrics;
pub mod nsga2;
pub mod pareto;
pub mod rsm;
pub mod zdt;
