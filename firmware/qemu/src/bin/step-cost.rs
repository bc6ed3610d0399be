//! The step-cost benchmark on the emulated Cortex-M4F: instructions per
//! `FlightController` control step and per link frame, as the instruction
//! set really executes them. Run under `-icount shift=0`, where QEMU's
//! virtual clock advances one nanosecond per instruction, so timer 0's
//! counts (40 ns each) count instructions; no interrupt is enabled, so
//! nothing else runs inside a measured span.
//!
//! The flight: the controller configured for the shipped plant (restored
//! from the emulated flash, as at boot), a handshake, the shipped initial
//! design uploaded (11 Hz, ±30°, 1 s ramp), armed, started, telemetry every
//! 100th step, a heartbeat every 0.1 s, for `seconds=S` of the command line
//! (`-append`, 1.5 s by default) of 10 kHz control steps flying the plant.
//! Measured: each control step; the plant's integration over each
//! period (not part of the controller's cost, but of the tick's); each frame from its first byte through the
//! decoder, the handler and the encoding of the answer; each telemetry
//! frame's encoding. Reported over semihosting (`report`), then QEMU exits.

#![cfg_attr(target_os = "none", no_std)]
#![cfg_attr(target_os = "none", no_main)]

#[cfg(not(target_os = "none"))]
fn main() {
    eprintln!("{}", fwav_fc_qemu::HOST_STUB_MESSAGE);
}

#[cfg(target_os = "none")]
mod firmware {
    use cortex_m_rt::{entry, exception, ExceptionFrame};
    use cortex_m_semihosting::debug::{exit, EXIT_FAILURE, EXIT_SUCCESS};
    use fwav_fc_core::flight::{FlightController, Handled, LinkId};
    use fwav_protocol::{
        encode_frame, Command, DeviceMessage, FrameDecoder, Hello, Limits, Reply, Request,
        Response, TelemetryConfig, MAX_FRAME_LEN,
    };
    use panic_semihosting as _;

    use fwav_fc_qemu::board;
    use fwav_fc_qemu::cost::Cost;
    use fwav_fc_qemu::flash::Flash;
    use fwav_fc_qemu::shipped::UPLOAD_INITIAL_DESIGN;
    use fwav_fc_qemu::vehicle::Vehicle;
    use fwav_fc_qemu::{command_line, counter, report, stack};

    /// Simulated seconds flown without `seconds=` on the command line.
    const DEFAULT_SECONDS: f32 = 1.5;
    /// Control steps between heartbeats (0.1 s, as `fwav upload --start`).
    const HEARTBEAT_STEPS: u32 = 1000;
    /// Telemetry decimation (one sample per 100 steps, 100 Hz).
    const TELEMETRY_DECIMATION: u16 = 100;

    /// The device end of the link, fed whole frames.
    struct Link {
        fc: FlightController,
        decoder: FrameDecoder,
        flash: Flash,
        now_us: u64,
        seq: u16,
    }

    impl Link {
        /// Feeds `frame` byte by byte, handles the request it holds and
        /// encodes the answer, timing all of it into `cost`; the answer.
        fn exchange(&mut self, frame: &[u8], cost: &mut Cost) -> Option<DeviceMessage> {
            let mut out = [0u8; MAX_FRAME_LEN];
            let start = counter::now();
            let mut answer = None;
            for &byte in frame {
                if let Some(Ok(request)) = self.decoder.push::<Request>(byte) {
                    let stats = self.decoder.stats();
                    let message = match self.fc.handle(LinkId::Uart, request, self.now_us, stats) {
                        Handled::Reply(message) => message,
                        Handled::Save { seq, record } => {
                            let ok = self.flash.save(&record);
                            self.fc.save_finished(seq, ok)
                        }
                    };
                    let _ = encode_frame(&message, &mut out);
                    answer = Some(message);
                }
            }
            cost.record(counter::now().wrapping_sub(start));
            answer
        }

        /// Frames `command` (not timed: the host's work) and exchanges it.
        fn command(&mut self, command: Command, cost: &mut Cost) -> Option<Reply> {
            self.seq = self.seq.wrapping_add(1);
            let mut frame = [0u8; MAX_FRAME_LEN];
            let request = Request {
                seq: self.seq,
                command,
            };
            let n = encode_frame(&request, &mut frame).ok()?;
            match self.exchange(&frame[..n], cost)? {
                DeviceMessage::Response(Response { reply, .. }) => Some(reply),
                _ => None,
            }
        }
    }

    /// Fails the benchmark with `what` (QEMU exits with status 1).
    fn fail(what: &str) -> ! {
        report::value(what, f64::NAN);
        exit(EXIT_FAILURE);
        loop {
            cortex_m::asm::wfi();
        }
    }

    #[entry]
    fn main() -> ! {
        counter::start();
        let mut line = [0u8; 128];
        let seconds = command_line::value(command_line::read(&mut line), "seconds")
            .and_then(|s| s.parse::<f32>().ok())
            .unwrap_or(DEFAULT_SECONDS);
        let steps = (seconds * board::CONTROL_HZ as f32) as u32;

        // The measurement's own cost: two timer reads around nothing.
        let mut overhead = Cost::NONE;
        for _ in 0..1000 {
            let start = counter::now();
            overhead.record(counter::now().wrapping_sub(start));
        }
        report::cost("empty_span", &overhead);

        let flash = Flash::configured_for_vehicle();
        let mut fc = FlightController::new(Limits::REFERENCE_FWAV);
        if fc.restore(flash.record()).is_err() {
            fail("boot_record_refused");
        }
        let mut link = Link {
            fc,
            decoder: FrameDecoder::new(),
            flash,
            now_us: 0,
            seq: 100,
        };
        let session = open_session(&mut link);
        let (step_cost, amplitude_deg) = fly(&mut link, steps, session);
        report::cost("control_step", &step_cost);
        report::value("amplitude_deg_last_0.1s", amplitude_deg);
        report::value("seconds_flown", f64::from(seconds));
        report::stack(stack::high_water());
        exit(EXIT_SUCCESS);
        loop {
            cortex_m::asm::wfi();
        }
    }

    /// Handshake, status, upload and read-back of the initial design, arm,
    /// start, telemetry on; returns the session. Reports each frame's cost.
    fn open_session(link: &mut Link) -> u32 {
        let mut handshake = Cost::NONE;
        let mut status = Cost::NONE;
        let mut upload = Cost::NONE;
        let mut read_back = Cost::NONE;
        for _ in 0..20 {
            link.command(Command::Handshake(Hello::THIS), &mut handshake);
            link.command(Command::GetStatus, &mut status);
            let accepted = DeviceMessage::Response(Response {
                seq: 1,
                reply: Reply::Ack,
            });
            if link.exchange(&UPLOAD_INITIAL_DESIGN, &mut upload) != Some(accepted) {
                fail("upload_refused");
            }
            link.command(Command::ReadProfile, &mut read_back);
        }
        report::cost("frame_handshake", &handshake);
        report::cost("frame_status", &status);
        report::cost("frame_upload_profile", &upload);
        report::cost("frame_read_profile", &read_back);
        let mut other = Cost::NONE;
        let Some(Reply::Armed { session }) = link.command(Command::Arm, &mut other) else {
            fail("arm_refused");
        };
        if link.command(Command::Start, &mut other) != Some(Reply::Ack) {
            fail("start_refused");
        }
        let telemetry = TelemetryConfig {
            enabled: true,
            decimation: TELEMETRY_DECIMATION,
        };
        link.command(Command::SetTelemetry(telemetry), &mut other);
        session
    }

    /// Flies `steps` control periods; the control steps' cost and the
    /// largest flapping angle over the last 0.1 s, degrees.
    fn fly(link: &mut Link, steps: u32, session: u32) -> (Cost, f64) {
        let mut vehicle = Vehicle::new();
        let mut step_cost = Cost::NONE;
        let mut heartbeat = Cost::NONE;
        let mut telemetry = Cost::NONE;
        let mut plant = Cost::NONE;
        let mut peak = 0.0f64;
        let dt = 1.0 / board::CONTROL_HZ as f32;
        for k in 1..=steps {
            let start = counter::now();
            vehicle.advance();
            plant.record(counter::now().wrapping_sub(start));
            link.now_us = u64::from(k) * board::CONTROL_PERIOD_US;
            let m = vehicle.measure();
            let start = counter::now();
            let act = link.fc.step(link.now_us, dt, &m);
            step_cost.record(counter::now().wrapping_sub(start));
            vehicle.apply(act.duty, act.bridge_enabled);
            if let Some((_, sample)) = act.telemetry {
                let mut out = [0u8; MAX_FRAME_LEN];
                let start = counter::now();
                let _ = encode_frame(&DeviceMessage::Telemetry(sample), &mut out);
                telemetry.record(counter::now().wrapping_sub(start));
            }
            if k % HEARTBEAT_STEPS == 0 {
                link.command(Command::Heartbeat { session }, &mut heartbeat);
            }
            if steps - k < HEARTBEAT_STEPS {
                peak = peak.max(libm::fabs(vehicle.angle_rad()));
            }
        }
        if !link.fc.is_running() {
            fail("not_running_at_the_end");
        }
        report::cost("frame_heartbeat", &heartbeat);
        report::cost("frame_telemetry_encode", &telemetry);
        report::cost("plant_period", &plant);
        (step_cost, peak.to_degrees())
    }

    #[exception]
    unsafe fn HardFault(frame: &ExceptionFrame) -> ! {
        report::hard_fault(frame.pc());
        exit(EXIT_FAILURE);
        loop {
            cortex_m::asm::wfi();
        }
    }
}
