//! `hil-sim serve`: the virtual flight controller behind a pseudo-terminal,
//! paced to real time (or a multiple of it).

use std::io::{ErrorKind, Read, Write};
use std::time::{Duration, Instant};

use fwav_actuator::controller_model::BeyondDevice;
use fwav_actuator::params::PlantParams;
use fwav_settings::Shown;
use serialport::{SerialPort, TTYPort};

use crate::sim::Simulator;

/// Why the server stopped.
#[derive(Debug, thiserror::Error)]
pub enum ServeError {
    /// The pseudo-terminal could not be created or used.
    #[error("pseudo-terminal: {0}")]
    Pty(#[from] serialport::Error),
    /// Reading or writing it failed.
    #[error("pseudo-terminal I/O: {0}")]
    Io(#[from] std::io::Error),
    /// A pace outside [`PACE`] (a pace of 0 or less was taken as 1
    /// without a word, and printed as given; 1e-30 overflowed the wait).
    #[error("a pace of {} simulated seconds per wall-clock second: give one from {} to {} (1 is real time, 10 ten times faster)", Shown(*speed), PACE.start(), PACE.end())]
    Speed {
        /// The pace given.
        speed: f64,
    },
    /// The plant's controller model has a value the device refuses: the
    /// board would keep that parameter's default (it did, without a word).
    #[error("{0}")]
    Plant(#[from] BeyondDevice),
}

/// The paces a server runs at, simulated seconds per wall-clock second: a
/// thousandth of real time to a thousand times it (the simulator's own
/// speed, `cargo bench -p fwav-hil-sim`, bounds how fast it really goes).
pub const PACE: std::ops::RangeInclusive<f64> = 1e-3..=1e3;

/// A virtual flight controller on a pseudo-terminal.
pub struct Server {
    sim: Simulator,
    master: TTYPort,
    /// Kept open so the device path exists and reopening it works.
    _slave: TTYPort,
    path: String,
    speed: f64,
}

impl Server {
    /// Creates the pty pair; `speed` is simulated seconds per wall second,
    /// in [`PACE`].
    pub fn new(plant: &PlantParams, speed: f64) -> Result<Self, ServeError> {
        if !PACE.contains(&speed) {
            return Err(ServeError::Speed { speed });
        }
        let mut sim = Simulator::new(plant);
        // The board flies this plant: its controller's model is the plant's.
        sim.configure_for_plant()?;
        let (mut master, slave) = TTYPort::pair()?;
        master.set_timeout(Duration::from_millis(0))?;
        let path = slave.name().unwrap_or_default();
        // Nobody reads the energy ledger here; without it a step is ~20% cheaper.
        sim.plant.keep_ledger = false;
        Ok(Self {
            sim,
            master,
            _slave: slave,
            path,
            speed,
        })
    }

    /// The device path a host opens (e.g. /dev/pts/7).
    pub fn path(&self) -> &str {
        &self.path
    }

    /// Runs until `stop()` returns true (checked every millisecond of
    /// simulated time).
    pub fn run(&mut self, mut stop: impl FnMut() -> bool) -> Result<(), ServeError> {
        let start = Instant::now();
        let dt = self.sim.params().control_dt();
        let steps_per_ms = ((1e-3 / dt).round() as usize).max(1);
        let mut buf = [0u8; 512];
        while !stop() {
            loop {
                match self.master.read(&mut buf) {
                    Ok(0) => break,
                    Ok(n) => self.sim.receive(&buf[..n]),
                    Err(e)
                        if matches!(
                            e.kind(),
                            ErrorKind::TimedOut | ErrorKind::WouldBlock | ErrorKind::Interrupted
                        ) =>
                    {
                        break
                    }
                    Err(e) => return Err(e.into()),
                }
            }
            for _ in 0..steps_per_ms {
                self.sim.step();
            }
            let out = self.sim.take_output();
            if !out.is_empty() {
                // Nobody reading: the bytes are lost, as on a real UART.
                match self.master.write(&out) {
                    Ok(_) => {}
                    Err(e)
                        if matches!(
                            e.kind(),
                            ErrorKind::TimedOut | ErrorKind::WouldBlock | ErrorKind::Interrupted
                        ) => {}
                    Err(e) => return Err(e.into()),
                }
            }
            // Pace: simulated time must not run ahead of wall time * speed.
            let ahead = self.sim.time_s() / self.speed - start.elapsed().as_secs_f64();
            if ahead > 0.0 {
                std::thread::sleep(Duration::from_secs_f64(ahead));
            }
        }
        Ok(())
    }
}
