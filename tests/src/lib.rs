//! # fwav-e2e — end-to-end tests across the fwav crates
//!
//! The tests in `tests/tests/` drive the real code paths of several crates
//! together: the host's profile file → protocol frames → the flight
//! controller's portable core running in hil-sim's virtual flight controller
//! → reply frames → the host.
