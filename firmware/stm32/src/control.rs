//! The control loop: every 100 µs read the sensors, step the flight
//! controller, drive the bridge, queue telemetry, pet the watchdog. It runs
//! on the high-priority executor so link traffic never delays it.

use embassy_time::{Duration, Instant, Ticker};
use fwav_fc_core::controller::Measurement;
use fwav_protocol::DeviceMessage;

use crate::board;
use crate::bridge::HBridge;
use crate::sensors::{Analog, Encoder};
use crate::shared::{now_us, outbox, with_fc};
use crate::watchdog;

/// The control task.
#[embassy_executor::task]
pub async fn run(mut bridge: HBridge, mut encoder: Encoder, mut analog: Analog) {
    let period = Duration::from_hz(board::CONTROL_HZ);
    let mut ticker = Ticker::every(period);
    let dt = 1.0 / board::CONTROL_HZ as f32;
    let mut last = Instant::now();
    loop {
        ticker.next().await;
        // After a stall (a flash erase halts the CPU for seconds, only while
        // disarmed) the ticker would fire once per missed period back to
        // back; start afresh instead.
        let now = Instant::now();
        if now - last > period * 10 {
            ticker.reset();
        }
        last = now;
        let m = Measurement {
            angle_rad: encoder.angle(),
            current_a: analog.current_a(),
            supply_v: Some(analog.battery_v()),
        };
        let now = now_us();
        match with_fc(|fc| fc.step(now, dt, &m)) {
            Some(act) => {
                bridge.set(act.duty, act.bridge_enabled);
                if let Some((link, sample)) = act.telemetry {
                    // A full outbox drops the sample; its seq shows the gap.
                    let _ = outbox(link).try_send(DeviceMessage::Telemetry(sample));
                }
            }
            None => bridge.set(0.0, false),
        }
        watchdog::pet();
    }
}
