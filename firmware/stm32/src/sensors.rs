//! The control loop's sensors: the flapping-angle encoder and the motor
//! current and battery voltage ADC channels.

use core::f32::consts::PI;

use embassy_stm32::adc::{Adc, SampleTime};
use embassy_stm32::timer::qei::{Config as QeiConfig, Qei};
use embassy_stm32::Peri;

use crate::board;

/// Quadrature encoder on TIM5. The timer's counter is read as 16 bits and
/// extended in software; at 10 kHz sampling and ≤ 100 rad/s the counter moves
/// at most ~7 counts a sample, far below half a wrap.
pub struct Encoder {
    qei: Qei<'static, board::EncoderTimer>,
    last: u16,
    count: i32,
}

impl Encoder {
    /// Starts counting from the current position (angle 0 = rest at boot).
    pub fn new(pins: board::EncoderPins) -> Self {
        let qei = Qei::new(pins.timer, pins.a, pins.b, QeiConfig::default());
        let last = qei.count();
        Self {
            qei,
            last,
            count: 0,
        }
    }

    /// Flapping angle, rad.
    pub fn angle(&mut self) -> f32 {
        let now = self.qei.count();
        // Wrapping difference of two u16 readings is the signed motion.
        self.count = self
            .count
            .wrapping_add(i32::from(now.wrapping_sub(self.last) as i16));
        self.last = now;
        self.count as f32 * (2.0 * PI / board::ENCODER_COUNTS_PER_REV as f32)
    }
}

/// Motor current and battery voltage on ADC1.
pub struct Analog {
    adc: Adc<'static, board::SensorAdc>,
    current: Peri<'static, board::CurrentPin>,
    battery: Peri<'static, board::BatteryPin>,
}

impl Analog {
    /// Configures ADC1.
    pub fn new(pins: board::AnalogPins) -> Self {
        Self {
            adc: Adc::new(pins.adc),
            current: pins.current,
            battery: pins.battery,
        }
    }

    fn volts(raw: u16) -> f32 {
        f32::from(raw) * (board::ADC_VREF / 4095.0)
    }

    /// Motor current, A. 15-cycle sampling at 21 MHz: < 1.5 µs a channel.
    pub fn current_a(&mut self) -> f32 {
        let raw = self
            .adc
            .blocking_read(&mut self.current, SampleTime::CYCLES15);
        (Self::volts(raw) - board::CURRENT_ZERO_V) * board::CURRENT_A_PER_V
    }

    /// Battery voltage, V.
    pub fn battery_v(&mut self) -> f32 {
        let raw = self
            .adc
            .blocking_read(&mut self.battery, SampleTime::CYCLES15);
        Self::volts(raw) * board::BATTERY_V_PER_V
    }
}
