//! The control loop's sensors: the flapping-angle encoder and the motor
//! current and battery voltage ADC channels.

use core::f32::consts::PI;

use embassy_stm32::adc::{Adc, SampleTime};
use embassy_stm32::peripherals::{ADC1, PA0, PA1, PC0, PC1, TIM5};
use embassy_stm32::timer::qei::{Config as QeiConfig, Qei};
use embassy_stm32::Peri;

use crate::board;

/// Quadrature encoder on TIM5. The timer's counter is read as 16 bits and
/// extended in software; at 10 kHz sampling and ≤ 100 rad/s the counter moves
/// at most ~7 counts a sample, far below half a wrap.
pub struct Encoder {
    qei: Qei<'static, TIM5>,
    last: u16,
    count: i32,
}

impl Encoder {
    /// Starts counting from the current position (angle 0 = rest at boot).
    pub fn new(tim: Peri<'static, TIM5>, a: Peri<'static, PA0>, b: Peri<'static, PA1>) -> Self {
        let qei = Qei::new(tim, a, b, QeiConfig::default());
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
    adc: Adc<'static, ADC1>,
    current: Peri<'static, PC0>,
    battery: Peri<'static, PC1>,
}

impl Analog {
    /// Configures ADC1.
    pub fn new(
        adc: Peri<'static, ADC1>,
        current: Peri<'static, PC0>,
        battery: Peri<'static, PC1>,
    ) -> Self {
        Self {
            adc: Adc::new(adc),
            current,
            battery,
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
