//! # fwav-e2e — end-to-end tests across the fwav crates
//!
//! The tests in `tests/tests/` drive the real code paths of several crates
//! together: the host's profile file → protocol frames → the flight
//! controller's portable core running in hil-sim's virtual flight controller
//! → reply frames → the host; and the same core compiled for the
//! microcontroller, running on QEMU's emulated Cortex-M4F ([`emulator`],
//! [`step_cost`]).

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::thread::JoinHandle;

pub mod emulator;
pub mod step_cost;

use fwav_actuator::params::PlantParams;
use fwav_hil_sim::serve::Server;

/// hil-sim serving in real time on a pty, until dropped.
pub struct Served {
    /// The pty's path, for `fwav::port::open`.
    pub path: String,
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

impl Served {
    /// Starts the default plant's server in real time on a new pty.
    pub fn start() -> Self {
        let mut server = Server::new(&PlantParams::default(), 1.0).expect("pty");
        let path = server.path().to_owned();
        let stop = Arc::new(AtomicBool::new(false));
        let flag = stop.clone();
        let thread = std::thread::spawn(move || {
            server
                .run(|| flag.load(Ordering::Relaxed))
                .expect("server runs");
        });
        Self {
            path,
            stop,
            thread: Some(thread),
        }
    }
}

impl Drop for Served {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}
