//! The H-bridge: TIM8 complementary PWM with dead time on two legs, driven
//! in locked anti-phase (leg A duty (1+d)/2, leg B (1-d)/2), so duty 0 is
//! 50/50 and the average bridge voltage is `d * V_supply` with no dead zone.
//!
//! Disarm switches the main output enable (MOE) off: every gate goes to its
//! idle level in hardware, not just to zero duty. (The timer's break input
//! would do the same on a driver fault without software; it is not wired
//! up yet.)

use embassy_stm32::gpio::OutputType;
use embassy_stm32::time::Hertz;
use embassy_stm32::timer::complementary_pwm::{ComplementaryPwm, ComplementaryPwmPin};
use embassy_stm32::timer::low_level::CountingMode;
use embassy_stm32::timer::simple_pwm::PwmPin;
use embassy_stm32::timer::Channel;

use crate::board;

/// The motor's H-bridge.
pub struct HBridge {
    pwm: ComplementaryPwm<'static, board::BridgeTimer>,
    max: u32,
    enabled: bool,
}

impl HBridge {
    /// Configures the bridge timer with outputs off.
    pub fn new(pins: board::BridgePins) -> Self {
        let mut pwm = ComplementaryPwm::new(
            pins.timer,
            Some(PwmPin::new(pins.a_high, OutputType::PushPull)),
            Some(ComplementaryPwmPin::new(pins.a_low, OutputType::PushPull)),
            Some(PwmPin::new(pins.b_high, OutputType::PushPull)),
            Some(ComplementaryPwmPin::new(pins.b_low, OutputType::PushPull)),
            None,
            None,
            None,
            None,
            Hertz(board::PWM_HZ),
            // Centre-aligned: symmetric switching, half the ripple frequency.
            CountingMode::CenterAlignedUpInterrupts,
        );
        pwm.set_dead_time(board::DEAD_TIME);
        let max = pwm.get_max_duty();
        let mut bridge = Self {
            pwm,
            max,
            enabled: true,
        };
        bridge.set(0.0, false);
        bridge.pwm.enable(Channel::Ch1);
        bridge.pwm.enable(Channel::Ch2);
        bridge
    }

    /// Applies `duty` in [-1, 1] (clamped; NaN is 0) with the outputs on, or
    /// switches every output off.
    pub fn set(&mut self, duty: f32, enabled: bool) {
        let d = if duty.is_finite() {
            duty.clamp(-1.0, 1.0)
        } else {
            0.0
        };
        let half = self.max as f32 * 0.5;
        let a = ((1.0 + d) * half) as u32;
        let b = ((1.0 - d) * half) as u32;
        self.pwm.set_duty(Channel::Ch1, a.min(self.max));
        self.pwm.set_duty(Channel::Ch2, b.min(self.max));
        if enabled != self.enabled {
            self.pwm.set_master_output_enable(enabled);
            self.enabled = enabled;
        }
    }
}
