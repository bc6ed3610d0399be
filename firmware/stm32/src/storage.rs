//! The profile and parameters in flash: sectors 10–11 (2 × 128 KiB) as a
//! wear-levelled key-value map (sequential-storage) holding one record, the
//! core's `StoredState` frame.

use embassy_stm32::flash::{Async, Flash};
use fwav_fc_core::storage::MAX_RECORD_LEN;
use sequential_storage::cache::{Cache, Uncached};
use sequential_storage::map::{MapConfig, MapStorage};

use crate::board;

/// The only key: the flight controller's state record.
const STATE_KEY: u8 = 1;

/// Scratch for sequential-storage: key + value + item header, rounded up to
/// the flash word.
const SCRATCH_LEN: usize = MAX_RECORD_LEN + 64;

type Map = MapStorage<u8, Flash<'static, Async>, Cache<Uncached, Uncached, Uncached, u8>>;

/// Checked at compile time: the range must start and end on erase pages.
const MAP_CONFIG: MapConfig<Flash<'static, Async>> = MapConfig::new(board::STORAGE_RANGE);

/// The flight controller's flash store.
pub struct Store {
    map: Map,
    scratch: [u8; SCRATCH_LEN],
}

impl Store {
    /// Uses the storage sectors of [`board::STORAGE_RANGE`].
    pub fn new(flash: Flash<'static, Async>) -> Self {
        Self {
            map: MapStorage::new(flash, MAP_CONFIG, Cache::new_uncached()),
            scratch: [0; SCRATCH_LEN],
        }
    }

    /// Reads the stored record into `out`; returns its length, or None if
    /// there is none or the store is unreadable.
    pub async fn load(&mut self, out: &mut [u8]) -> Option<usize> {
        match self
            .map
            .fetch_item::<&[u8]>(&mut self.scratch, &STATE_KEY)
            .await
        {
            Ok(Some(bytes)) if bytes.len() <= out.len() => {
                out[..bytes.len()].copy_from_slice(bytes);
                Some(bytes.len())
            }
            Ok(_) => None,
            Err(e) => {
                defmt::warn!("flash store unreadable: {}", e);
                None
            }
        }
    }

    /// Writes `record` (may erase a 128 KiB sector: the CPU stalls for
    /// seconds; call only with the bridge off and the watchdog lengthened).
    pub async fn save(&mut self, record: &[u8]) -> bool {
        match self
            .map
            .store_item(&mut self.scratch, &STATE_KEY, &record)
            .await
        {
            Ok(()) => true,
            Err(e) => {
                defmt::warn!("flash store write failed: {}", e);
                false
            }
        }
    }
}
