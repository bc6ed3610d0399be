//! The virtual flight controller: `fwav-fc-core`'s [`FlightController`] —
//! the code the STM32 runs — stepped at its control rate against the
//! simulated [`Plant`], reading a quantized encoder and a noisy current
//! sensor, and reached through the same framed byte link as the board (the
//! [`Simulator`] is a byte port: what is written to it is received, what
//! it sent is read back).

use std::f64::consts::PI;
use std::io::{ErrorKind, Read, Write};

use fwav_fc_core::controller::Measurement;
use fwav_fc_core::flight::{FlightController, Handled, LinkId};
use fwav_fc_core::storage::MAX_RECORD_LEN;
use fwav_protocol::frame::encode_frame_vec;
use fwav_protocol::{Command, DeviceMessage, FrameDecoder, Limits, Request};
use rand::rngs::StdRng;
use rand::SeedableRng;
use rand_distr::{Distribution, Normal};

use fwav_actuator::controller_model::{checked_controller_model, BeyondDevice};
use fwav_actuator::params::PlantParams;
use fwav_actuator::plant::{Drive, Plant};

/// Faults that can be injected.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct InjectedFaults {
    /// The encoder reading is frozen at its last value.
    pub encoder_lost: bool,
    /// The rotor is locked.
    pub stalled: bool,
    /// The battery's open-circuit voltage, if dropped, V.
    pub battery_v: Option<f64>,
}

/// What one control period did, for traces and metrics.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Time at the end of the period, s.
    pub time_s: f64,
    /// True flapping angle, rad.
    pub angle_rad: f64,
    /// Encoder reading given to the controller, rad.
    pub measured_rad: f32,
    /// True motor current, A.
    pub current_a: f64,
    /// Duty commanded (applied over the next period).
    pub duty: f32,
    /// Terminal voltage of the motor over the period just simulated, V:
    /// the averaged bridge's `d (V_b - R_b d i)` with the duty applied over
    /// that period and its mean current (0 with the bridge off). With the
    /// switching bridge model, the same average over the PWM periods.
    pub terminal_v: f64,
    /// Bridge enabled.
    pub armed: bool,
    /// Battery energy drawn since the start (the plant's ledger), J.
    pub battery_j: f64,
}

/// The simulated flight controller and its plant.
pub struct Simulator {
    /// The plant.
    pub plant: Plant,
    /// The flight controller (the firmware core, unchanged).
    pub fc: FlightController,
    params: PlantParams,
    decoder: FrameDecoder,
    noise: Normal<f64>,
    rng: StdRng,
    faults: InjectedFaults,
    frozen_count: Option<i64>,
    duty: f32,
    armed: bool,
    time_us: u64,
    /// Bytes the device has sent and the host not yet taken.
    outgoing: Vec<u8>,
    /// The "flash" of the virtual board.
    pub flash: Vec<u8>,
}

impl Simulator {
    /// A simulator of `params` with a disarmed controller and the
    /// reference vehicle's limits.
    pub fn new(params: &PlantParams) -> Self {
        let sigma = params.sensors.current_noise_a;
        Self {
            plant: Plant::new(params),
            fc: FlightController::new(Limits::REFERENCE_FWAV),
            decoder: FrameDecoder::new(),
            // Validated: sigma is finite and >= 0.
            noise: Normal::new(0.0, sigma)
                .unwrap_or_else(|_| Normal::new(0.0, 0.0).expect("0 is valid")),
            rng: StdRng::seed_from_u64(params.sensors.seed),
            params: params.clone(),
            faults: InjectedFaults::default(),
            frozen_count: None,
            duty: 0.0,
            armed: false,
            time_us: 0,
            outgoing: Vec::new(),
            flash: Vec::new(),
        }
    }

    /// Sets the controller's model parameters to the plant's
    /// ([`checked_controller_model`]) through the link's `SetParam`
    /// command, as a board configured for this vehicle before the host
    /// connects; the acknowledgements are not sent. A plant whose model
    /// the device would refuse is an error before any is set: the board
    /// would keep that parameter's default and feed forward another plant.
    pub fn configure_for_plant(&mut self) -> Result<(), BeyondDevice> {
        let model = checked_controller_model(&self.params)?;
        for (seq, value) in model.into_iter().enumerate() {
            let request = Request {
                seq: seq as u16,
                command: Command::SetParam(value),
            };
            let _ack = self.handle(request);
        }
        Ok(())
    }

    /// Plant parameters.
    pub fn params(&self) -> &PlantParams {
        &self.params
    }

    /// Simulated time, s.
    pub fn time_s(&self) -> f64 {
        self.time_us as f64 * 1e-6
    }

    /// Injects (or clears) faults.
    pub fn set_faults(&mut self, faults: InjectedFaults) {
        if faults.encoder_lost && !self.faults.encoder_lost {
            self.frozen_count = Some(self.encoder_count());
        }
        if !faults.encoder_lost {
            self.frozen_count = None;
        }
        self.faults = faults;
        self.plant.stalled = faults.stalled;
        self.plant.battery_v = faults.battery_v.unwrap_or(self.params.supply.battery_v);
    }

    fn encoder_count(&self) -> i64 {
        let per_rad = f64::from(self.params.sensors.encoder_counts_per_rev) / (2.0 * PI);
        (self.plant.state.angle_rad * per_rad).round() as i64
    }

    /// Bytes from the host (any chunking); answers are queued for
    /// [`Simulator::take_output`].
    pub fn receive(&mut self, bytes: &[u8]) {
        let requests: Vec<Request> = self.decoder.feed(bytes).filter_map(Result::ok).collect();
        for request in requests {
            let answer = self.handle(request);
            self.send(&answer);
        }
    }

    fn handle(&mut self, request: Request) -> DeviceMessage {
        match self
            .fc
            .handle(LinkId::Uart, request, self.time_us, self.decoder.stats())
        {
            Handled::Reply(message) => message,
            Handled::Save { seq, record } => {
                let mut buf = vec![0u8; MAX_RECORD_LEN];
                let ok = match record.encode(&mut buf) {
                    Ok(n) => {
                        buf.truncate(n);
                        self.flash = buf;
                        true
                    }
                    Err(_) => false,
                };
                self.fc.save_finished(seq, ok)
            }
        }
    }

    fn send(&mut self, message: &DeviceMessage) {
        // Every device message fits a frame (protocol tests).
        if let Ok(frame) = encode_frame_vec(message) {
            self.outgoing.extend(frame);
        }
    }

    /// Counters of the device's frame decoder.
    pub fn link_stats(&self) -> fwav_protocol::LinkStats {
        self.decoder.stats()
    }

    /// Bytes the device sent since the last call.
    pub fn take_output(&mut self) -> Vec<u8> {
        std::mem::take(&mut self.outgoing)
    }

    /// One control period: sensors → flight controller → bridge → plant
    /// (RK4 substeps).
    pub fn step(&mut self) -> Sample {
        let dt = self.params.control_dt();
        let substeps = self.params.simulation.substeps;
        let h = dt / f64::from(substeps);
        let drive = Drive {
            duty: f64::from(self.duty),
            enabled: self.armed,
        };
        let mut current_sum = 0.0;
        for _ in 0..substeps {
            let before = self.plant.state.current_a;
            self.plant.step(drive, h);
            current_sum += 0.5 * (before + self.plant.state.current_a);
        }
        let mean_current = current_sum / f64::from(substeps);
        let terminal_v = if drive.enabled {
            drive.duty
                * (self.plant.battery_v
                    - self.params.supply.internal_resistance_ohm * drive.duty * mean_current)
        } else {
            0.0
        };
        self.time_us += (dt * 1e6).round() as u64;

        let count = self.frozen_count.unwrap_or_else(|| self.encoder_count());
        let per_count = 2.0 * PI / f64::from(self.params.sensors.encoder_counts_per_rev);
        let measured = (count as f64 * per_count) as f32;
        let current = self.plant.state.current_a
            + self.params.sensors.current_offset_a
            + self.noise.sample(&mut self.rng);
        let m = Measurement {
            angle_rad: measured,
            current_a: current as f32,
            supply_v: Some(self.plant.battery_v as f32),
        };
        let act = self.fc.step(self.time_us, dt as f32, &m);
        self.duty = act.duty;
        self.armed = act.bridge_enabled;
        if let Some((_, sample)) = act.telemetry {
            self.send(&DeviceMessage::Telemetry(sample));
        }
        Sample {
            time_s: self.time_s(),
            angle_rad: self.plant.state.angle_rad,
            measured_rad: measured,
            current_a: self.plant.state.current_a,
            duty: self.duty,
            terminal_v,
            armed: self.armed,
            battery_j: self.plant.ledger.battery_j,
        }
    }
}

/// The simulator as the device end of a byte link, for an in-process host
/// (`fwav_link::Link<Simulator>`): writing is [`Simulator::receive`] (the
/// answers are queued at once), reading takes the queued bytes in order,
/// and an empty queue reads as [`ErrorKind::WouldBlock`] (nothing yet, as a
/// serial port's timeout). Simulated time advances only by
/// [`Simulator::step`].
impl Write for Simulator {
    fn write(&mut self, bytes: &[u8]) -> std::io::Result<usize> {
        self.receive(bytes);
        Ok(bytes.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

impl Read for Simulator {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        if self.outgoing.is_empty() {
            return Err(ErrorKind::WouldBlock.into());
        }
        let n = buf.len().min(self.outgoing.len());
        buf[..n].copy_from_slice(&self.outgoing[..n]);
        self.outgoing.drain(..n);
        Ok(n)
    }
}
