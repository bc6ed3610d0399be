//! The host end of the fwav link: [`Link`] (requests with sequence numbers,
//! retries, timeouts, telemetry buffering) and [`LinkError`], from the
//! `fwav-link` crate, which hil-sim's scenarios use too. Re-exported here so
//! that `fwav::link::...` names the one client.

pub use fwav_link::{command_name, Link, LinkError};
