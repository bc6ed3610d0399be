//! Board configuration of the flight controller: clocks and pin choices.
//!
//! Pins (STM32F405RG, 64-pin): link on USART2 (PA2 TX, PA3 RX). USART1 and
//! USART3 are avoided because the ROM DFU bootloader may seize them.
//! The embassy time driver is TIM12 (named explicitly in Cargo.toml), leaving
//! TIM1/TIM8 for the complementary H-bridge PWM and TIM2/TIM5 (32-bit) for
//! the encoder.

use embassy_stm32::rcc::{
    AHBPrescaler, APBPrescaler, Hse, HseMode, Pll, PllMul, PllPDiv, PllPreDiv, PllQDiv, PllSource,
    Sysclk,
};
use embassy_stm32::time::Hertz;
use embassy_stm32::Config;

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
