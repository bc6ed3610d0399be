//! Everything specific to one flight-controller board: clocks, pins, sensor
//! scales. Porting fwav to another STM32F4 board means editing this file.
//!
//! | function | peripheral | pins (STM32F405RG, LQFP64) |
//! | --- | --- | --- |
//! | H-bridge, phase A high/low | TIM8 CH1 / CH1N | PC6 / PA7 |
//! | H-bridge, phase B high/low | TIM8 CH2 / CH2N | PC7 / PB0 |
//! | flapping-angle encoder A / B | TIM5 (32-bit) CH1 / CH2 | PA0 / PA1 |
//! | motor current (shunt amplifier) | ADC1 IN10 | PC0 |
//! | battery voltage (divider) | ADC1 IN11 | PC1 |
//! | USB (CDC-ACM), VBUS sense | OTG_FS | PA12 DP, PA11 DM, PA9 VBUS |
//! | radio / hil-sim link | USART2 | PA2 TX, PA3 RX |
//! | time driver | TIM12 | — |
//! | debug (probe-rs, defmt over RTT) | SWD | PA13 SWDIO, PA14 SWCLK |
//!
//! USART1/USART3 are avoided (the ROM DFU bootloader may seize them), and
//! PA9 stays free for VBUS sensing, which a battery-powered board needs.
//! PA6 (TIM8 BKIN) is kept free for the bridge driver's fault line; the
//! firmware does not use the hardware break input yet.

use embassy_stm32::rcc::{
    AHBPrescaler, APBPrescaler, Hse, HseMode, Pll, PllMul, PllPDiv, PllPreDiv, PllQDiv, PllSource,
    Sysclk,
};
use embassy_stm32::time::Hertz;
use embassy_stm32::Config;

/// Control loop rate, Hz (period 100 µs).
pub const CONTROL_HZ: u64 = 10_000;

/// H-bridge PWM frequency, Hz (above hearing; the motor's electrical time
/// constant smooths it).
pub const PWM_HZ: u32 = 25_000;

/// Dead time between a leg's high and low switch, as TIM8's DTG register
/// value: 34 ticks of 168 MHz ≈ 200 ns, enough for common gate drivers.
pub const DEAD_TIME: u16 = 34;

/// Encoder counts per revolution of the flapping axis (a 1024-line
/// quadrature encoder, x4).
pub const ENCODER_COUNTS_PER_REV: i32 = 4096;

/// Motor current per ADC volt: 10 mΩ shunt × gain 50 amplifier = 0.5 V/A,
/// bidirectional around mid-supply.
pub const CURRENT_A_PER_V: f32 = 2.0;
/// Amplifier output at zero current, V.
pub const CURRENT_ZERO_V: f32 = 1.65;
/// Battery volts per ADC volt (divider 10 kΩ / 1 kΩ).
pub const BATTERY_V_PER_V: f32 = 11.0;
/// ADC reference, V; 12-bit full scale.
pub const ADC_VREF: f32 = 3.3;

/// Flash offset (from 0x0800_0000) and size of the storage area: sectors 10
/// and 11, kept out of the program by `memory.x`.
pub const STORAGE_RANGE: core::ops::Range<u32> = 0x000C_0000..0x0010_0000;

/// 8 MHz crystal → PLL (/4 ×168 /2) → 168 MHz SYSCLK, 48 MHz for USB (/7);
/// APB1 42 MHz, APB2 84 MHz (timer clocks 84 / 168 MHz).
pub fn clocks() -> Config {
    let mut config = Config::default();
    config.rcc.hse = Some(Hse {
        freq: Hertz(8_000_000),
        mode: HseMode::Oscillator,
    });
    config.rcc.pll_src = PllSource::HSE;
    config.rcc.pll = Some(Pll {
        prediv: PllPreDiv::DIV4,
        mul: PllMul::MUL168,
        divp: Some(PllPDiv::DIV2),
        divq: Some(PllQDiv::DIV7),
        divr: None,
    });
    config.rcc.ahb_pre = AHBPrescaler::DIV1;
    config.rcc.apb1_pre = APBPrescaler::DIV4;
    config.rcc.apb2_pre = APBPrescaler::DIV2;
    config.rcc.sys = Sysclk::PLL1_P;
    config
}
