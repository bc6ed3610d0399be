//! # fwav — design and fly the flapping wing of a flapping-wing air vehicle
//!
//! The library behind the `fwav` program: the MDOIS design process of the
//! seed paper ([`mdois`]: the 3D aeroelastic system analysis of
//! [`aeroelastic`], the kinematic optimization of [`discipline`] on the 2D
//! unsteady aerodynamics of [`aero2d`], the ESL topology optimization of
//! [`topology`]; the design file's tables, checks and template in
//! [`config`]; the pictures and ParaView files of the results in
//! [`output`], which no solver imports; the designed wing on the design's
//! actuator, as the plant the feasibility check judges and hil-sim flies,
//! in [`vehicle`]; many design runs of one base configuration, on a local
//! pool or a Slurm job array, in [`study`]) and the link side: the
//! kinematics profile file that `fwav design` writes and `fwav upload`
//! sends ([`profile_file`]), serial ports
//! ([`port`]), the framed request/response client with retries ([`link`])
//! and the operations on a connected flight controller ([`device`]).
//!
//! The program (`src/main.rs`) only parses arguments and prints; everything
//! else is here and returns typed errors.

#![forbid(unsafe_code)]
#![warn(missing_docs)]
#![warn(clippy::too_many_lines)]

pub mod aero2d;
pub mod aeroelastic;
pub mod config;
pub mod device;
pub mod discipline;
pub mod file_format;
pub use fwav_files as files;
pub mod link;
pub mod mdois;
pub mod optimize;
pub mod output;
pub mod periodicity;
pub mod port;
pub mod profile_file;
pub mod shell;
pub mod study;
pub mod topology;
pub mod uvlm;
pub mod validation;
pub mod vehicle;
