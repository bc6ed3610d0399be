//! The emulated board's parameter store. The STM32 keeps the profile and
//! parameters in flash and restores them at boot; here the store is RAM
//! (lost when QEMU ends), and it starts out as a board configured for its
//! vehicle: a record holding the controller's model of the shipped plant
//! ([`shipped::CONTROLLER_MODEL`](crate::shipped::CONTROLLER_MODEL)),
//! which the flight controller restores at boot through the same
//! `StoredState` path the STM32 takes.

use fwav_fc_core::storage::{StoredState, MAX_RECORD_LEN};

use crate::shipped::CONTROLLER_MODEL;

/// The stored record.
pub struct Flash {
    record: [u8; MAX_RECORD_LEN],
    len: usize,
}

impl Default for Flash {
    fn default() -> Self {
        Self::configured_for_vehicle()
    }
}

impl Flash {
    /// A store holding the vehicle's controller model and no profile.
    pub fn configured_for_vehicle() -> Self {
        let mut flash = Flash {
            record: [0; MAX_RECORD_LEN],
            len: 0,
        };
        let params = CONTROLLER_MODEL.iter().copied().collect();
        // Eight parameters fit a record (a record holds all of them).
        if let Ok(n) = StoredState::new(None, params).encode(&mut flash.record) {
            flash.len = n;
        }
        flash
    }

    /// The stored record's bytes.
    pub fn record(&self) -> &[u8] {
        &self.record[..self.len]
    }

    /// Stores `record` (an encoded `StoredState`); false if it does not fit.
    pub fn save(&mut self, record: &StoredState) -> bool {
        match record.encode(&mut self.record) {
            Ok(n) => {
                self.len = n;
                true
            }
            Err(_) => false,
        }
    }
}
