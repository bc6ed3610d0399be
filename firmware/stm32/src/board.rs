//! Everything specific to one flight-controller board: clocks, which
//! peripheral and pin does what ([`Board::take`] hands them out by
//! function, so the drivers and `main` never name a pin), interrupt
//! bindings ([`Irqs`]) and sensor scales. Porting fwav to another STM32F4
//! board means editing this file, and, if UART5 is wired on the new board,
//! the spare interrupt that triggers the control executor (`main.rs`'s
//! `#[interrupt] fn UART5`: the attribute takes the interrupt's name).
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

use embassy_stm32::peripherals::{
    ADC1, FLASH, PA0, PA1, PA11, PA12, PA2, PA3, PA7, PB0, PC0, PC1, PC6, PC7, TIM5, TIM8, USART2,
    USB_OTG_FS,
};
use embassy_stm32::{bind_interrupts, flash, usart, usb, Config, Peri, Peripherals};

bind_interrupts!(
    /// The drivers' interrupt handlers: the link UART, USB and flash.
    pub struct Irqs {
        USART2 => usart::BufferedInterruptHandler<LinkUart>;
        OTG_FS => usb::InterruptHandler<UsbPeripheral>;
        FLASH => flash::InterruptHandler;
    }
);

/// The H-bridge's advanced timer.
pub type BridgeTimer = TIM8;
/// The encoder's timer.
pub type EncoderTimer = TIM5;
/// The ADC of the current and battery channels.
pub type SensorAdc = ADC1;
/// The motor-current ADC pin.
pub type CurrentPin = PC0;
/// The battery-voltage ADC pin.
pub type BatteryPin = PC1;
/// The link UART (radio or hil-sim).
pub type LinkUart = USART2;
/// The USB peripheral (CDC-ACM).
pub type UsbPeripheral = USB_OTG_FS;

/// TIM8 with its complementary outputs: the H-bridge.
pub struct BridgePins {
    /// Advanced timer with dead-time generation.
    pub timer: Peri<'static, BridgeTimer>,
    /// Leg A high side (CH1).
    pub a_high: Peri<'static, PC6>,
    /// Leg A low side (CH1N).
    pub a_low: Peri<'static, PA7>,
    /// Leg B high side (CH2).
    pub b_high: Peri<'static, PC7>,
    /// Leg B low side (CH2N).
    pub b_low: Peri<'static, PB0>,
}

/// The flapping-angle quadrature encoder.
pub struct EncoderPins {
    /// Timer in encoder mode.
    pub timer: Peri<'static, EncoderTimer>,
    /// Channel A.
    pub a: Peri<'static, PA0>,
    /// Channel B.
    pub b: Peri<'static, PA1>,
}

/// The ADC and its two channels.
pub struct AnalogPins {
    /// The converter.
    pub adc: Peri<'static, SensorAdc>,
    /// Motor current (shunt amplifier output).
    pub current: Peri<'static, CurrentPin>,
    /// Battery voltage (divider output).
    pub battery: Peri<'static, BatteryPin>,
}

/// The link UART's pins.
pub struct UartPins {
    /// The UART.
    pub uart: Peri<'static, LinkUart>,
    /// Receive.
    pub rx: Peri<'static, PA3>,
    /// Transmit.
    pub tx: Peri<'static, PA2>,
}

/// USB full speed.
pub struct UsbPins {
    /// The OTG_FS peripheral.
    pub usb: Peri<'static, UsbPeripheral>,
    /// D+.
    pub dp: Peri<'static, PA12>,
    /// D-.
    pub dm: Peri<'static, PA11>,
}

/// The board's peripherals by function.
pub struct Board {
    /// H-bridge.
    pub bridge: BridgePins,
    /// Encoder.
    pub encoder: EncoderPins,
    /// Current and battery sensing.
    pub analog: AnalogPins,
    /// Radio / serial link.
    pub uart: UartPins,
    /// USB link.
    pub usb: UsbPins,
    /// Flash controller (parameter and profile storage).
    pub flash: Peri<'static, FLASH>,
}

impl Board {
    /// Hands out the peripherals of [`embassy_stm32::init`] by function
    /// (the wiring table in the module docs).
    pub fn take(p: Peripherals) -> Self {
        Self {
            bridge: BridgePins {
                timer: p.TIM8,
                a_high: p.PC6,
                a_low: p.PA7,
                b_high: p.PC7,
                b_low: p.PB0,
            },
            encoder: EncoderPins {
                timer: p.TIM5,
                a: p.PA0,
                b: p.PA1,
            },
            analog: AnalogPins {
                adc: p.ADC1,
                current: p.PC0,
                battery: p.PC1,
            },
            uart: UartPins {
                uart: p.USART2,
                rx: p.PA3,
                tx: p.PA2,
            },
            usb: UsbPins {
                usb: p.USB_OTG_FS,
                dp: p.PA12,
                dm: p.PA11,
            },
            flash: p.FLASH,
        }
    }
}

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
#[cfg(not(feature = "qemu"))]
pub fn clocks() -> Config {
    use embassy_stm32::rcc::{
        AHBPrescaler, APBPrescaler, Hse, HseMode, Pll, PllMul, PllPDiv, PllPreDiv, PllQDiv,
        PllSource, Sysclk,
    };
    use embassy_stm32::time::Hertz;

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

/// The `qemu` feature's clocks: the reset state (16 MHz HSI, no PLL), for
/// QEMU's `netduinoplus2`, which models no RCC, so the PLL would never
/// report locked. Never for a board: every rate above assumes 168 MHz.
///
/// It does not get the binary booting on QEMU 7.2: embassy-stm32 0.6's
/// clock setup switches the HSI on and waits for its ready flag whatever
/// the configuration (`rcc/f247.rs`, `while !RCC.cr().read().hsirdy()`),
/// and QEMU's RCC reads as zero (README, "Emulated microcontroller").
#[cfg(feature = "qemu")]
pub fn clocks() -> Config {
    Config::default()
}
