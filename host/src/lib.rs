//! # fwav — design and fly the flapping wing of a flapping-wing air vehicle
//!
//! The library behind the `fwav` program. It will carry the MDOIS design
//! process of the seed paper (3D aeroelastic system analysis, kinematic
//! optimization on 2D unsteady aerodynamics, ESL topology optimization) and
//! the serial uploader; today it holds the link side: the kinematics profile
//! file that `fwav design` writes and `fwav upload` sends ([`profile_file`]),
//! serial ports ([`port`]), the framed request/response client with retries
//! ([`link`]) and the operations on a connected flight controller
//! ([`device`]).
//!
//! The program (`src/main.rs`) only parses arguments and prints; everything
//! else is here and returns typed errors.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod aero2d;
pub mod aeroelastic;
pub mod device;
pub mod discipline;
pub mod files;
pub mod link;
pub mod optimize;
pub mod port;
pub mod profile_file;
pub mod shell;
pub mod topology;
pub mod uvlm;
