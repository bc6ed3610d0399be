//! The served flight controller on the emulated Cortex-M4F: the unchanged
//! `fwav-fc-core` [`FlightController`] with its link handler on two UARTs
//! (QEMU's `-serial pty` puts each on a pseudo-terminal the ordinary `fwav`
//! commands open: UART0 is the radio link, UART1 stands in for the STM32
//! board's USB link) and its control step on the 10 kHz SysTick interrupt
//! flying the shared plant model, as the STM32 binary does with embassy
//! around the same core.
//!
//! - SysTick (highest priority): integrate the plant over the period just
//!   ended, read its sensors, run the control step (timed with timer 0),
//!   apply the duty, queue a telemetry sample.
//! - UART receive interrupts: move the received byte to its link's queue.
//! - Main loop: per link, decode frames from the receive queue, have the
//!   flight controller handle each request, frame the answers and the
//!   telemetry into the transmit queue and send what the UART takes; report
//!   over semihosting once a simulated second; sleep until an interrupt.
//!
//! Every byte from a link goes through the core's frame decoder and request
//! handler as on the STM32; a panic ends QEMU with the message on
//! semihosting (`panic-semihosting`), a hard fault likewise.

#![cfg_attr(target_os = "none", no_std)]
#![cfg_attr(target_os = "none", no_main)]

#[cfg(not(target_os = "none"))]
fn main() {
    eprintln!("{}", fwav_fc_qemu::HOST_STUB_MESSAGE);
}

#[cfg(target_os = "none")]
mod firmware {
    use core::cell::{Cell, RefCell};
    use core::sync::atomic::{AtomicU32, Ordering};

    use cortex_m::peripheral::scb::SystemHandler;
    use cortex_m::peripheral::syst::SystClkSource;
    use cortex_m::peripheral::NVIC;
    use cortex_m_rt::{entry, exception, ExceptionFrame};
    use critical_section::Mutex;
    use fwav_fc_core::flight::{FlightController, Handled, LinkId};
    use fwav_protocol::{
        encode_frame, DeviceMessage, FrameDecoder, Limits, Request, TelemetrySample, MAX_FRAME_LEN,
    };
    use heapless::Deque;
    use panic_semihosting as _;

    use fwav_fc_qemu::board::{self, Irq};
    use fwav_fc_qemu::cost::Cost;
    use fwav_fc_qemu::flash::Flash;
    use fwav_fc_qemu::uart::{Uart, UART0, UART1};
    use fwav_fc_qemu::vehicle::Vehicle;
    use fwav_fc_qemu::{counter, report, stack};

    /// Bytes received on one link and not yet decoded.
    type Received = Mutex<RefCell<Deque<u8, 256>>>;

    /// The flight controller; `None` only before `main` installs it.
    static FC: Mutex<RefCell<Option<FlightController>>> = Mutex::new(RefCell::new(None));
    /// Per link (UART0, UART1), the received bytes. QEMU delivers a byte only
    /// after the last was read, so a full queue holds the sender, losing
    /// nothing.
    static RECEIVED: [Received; 2] = [
        Mutex::new(RefCell::new(Deque::new())),
        Mutex::new(RefCell::new(Deque::new())),
    ];
    /// Telemetry samples of the control step and their link, to be framed
    /// and sent. A full queue drops the sample (its sequence number shows
    /// the gap).
    static TELEMETRY: Mutex<RefCell<Deque<(LinkId, TelemetrySample), 8>>> =
        Mutex::new(RefCell::new(Deque::new()));
    /// The control steps' measured cost.
    static STEPS: Mutex<Cell<Cost>> = Mutex::new(Cell::new(Cost::NONE));
    /// Control periods since boot.
    static TICKS: AtomicU32 = AtomicU32::new(0);

    /// Bytes framed and waiting for a UART.
    const OUTGOING_LEN: usize = 2048;

    /// One link: its UART, interrupt, decoder and transmit queue.
    struct Port {
        link: LinkId,
        uart: Uart,
        rx_irq: Irq,
        received: &'static Received,
        decoder: FrameDecoder,
        outgoing: Deque<u8, OUTGOING_LEN>,
    }

    fn now_us() -> u64 {
        u64::from(TICKS.load(Ordering::Relaxed)) * board::CONTROL_PERIOD_US
    }

    #[entry]
    fn main() -> ! {
        let mut core = cortex_m::Peripherals::take().expect("taken once, at boot");
        counter::start();
        UART0.start();
        UART1.start();
        let mut flash = Flash::configured_for_vehicle();
        let mut fc = FlightController::new(Limits::REFERENCE_FWAV);
        // The vehicle's controller model, as a board restores it from flash.
        fc.restore(flash.record())
            .expect("the boot record is this build's");
        critical_section::with(|cs| FC.borrow(cs).replace(Some(fc)));

        // SAFETY: priorities are set before the interrupts are enabled:
        // the control tick preempts the UARTs, never the other way round.
        unsafe {
            core.SCB.set_priority(SystemHandler::SysTick, 0);
            for irq in [Irq::Uart0Rx, Irq::Uart0Tx, Irq::Uart1Rx, Irq::Uart1Tx] {
                core.NVIC.set_priority(irq, 0x80);
                NVIC::unmask(irq);
            }
        }
        core.SYST.set_clock_source(SystClkSource::Core);
        core.SYST.set_reload(board::SYSTICK_RELOAD);
        core.SYST.clear_current();
        core.SYST.enable_interrupt();
        core.SYST.enable_counter();

        let port = |link, uart, rx_irq, index: usize| Port {
            link,
            uart,
            rx_irq,
            received: &RECEIVED[index],
            decoder: FrameDecoder::new(),
            outgoing: Deque::new(),
        };
        let mut ports = [
            port(LinkId::Uart, UART0, Irq::Uart0Rx, 0),
            port(LinkId::Usb, UART1, Irq::Uart1Rx, 1),
        ];
        let mut next_report_ms = 1000;
        let loop_depth = stack::depth();
        loop {
            for port in &mut ports {
                serve(port, &mut flash);
            }
            while let Some((link, sample)) =
                critical_section::with(|cs| TELEMETRY.borrow_ref_mut(cs).pop_front())
            {
                if let Some(port) = ports.iter_mut().find(|p| p.link == link) {
                    queue(&DeviceMessage::Telemetry(sample), &mut port.outgoing);
                }
            }
            for port in &mut ports {
                transmit(port);
            }
            let uptime_ms = now_us() / 1000;
            if uptime_ms >= next_report_ms {
                next_report_ms = uptime_ms + 1000;
                let steps = critical_section::with(|cs| STEPS.borrow(cs).get());
                report::running(uptime_ms, &steps, stack::high_water(), loop_depth);
            }
            sleep_until_interrupt(&ports);
        }
    }

    /// Decodes what `port` received and queues the flight controller's
    /// answers.
    fn serve(port: &mut Port, flash: &mut Flash) {
        while let Some(byte) =
            critical_section::with(|cs| port.received.borrow_ref_mut(cs).pop_front())
        {
            // Frames that fail to decode are counted in the decoder's stats.
            if let Some(Ok(request)) = port.decoder.push::<Request>(byte) {
                let answer = handle(port.link, request, &port.decoder, flash);
                queue(&answer, &mut port.outgoing);
            }
        }
        // SAFETY: the receive interrupt only moves bytes into the queue
        // this loop has just emptied.
        unsafe { NVIC::unmask(port.rx_irq) };
    }

    /// Sends what the UART takes; asks for its interrupt if bytes remain.
    fn transmit(port: &mut Port) {
        while let Some(&byte) = port.outgoing.front() {
            if !port.uart.try_send(byte) {
                break;
            }
            port.outgoing.pop_front();
        }
        port.uart.wake_when_sendable(!port.outgoing.is_empty());
    }

    /// The flight controller's answer to `request` from `link` (a save
    /// goes to the emulated board's RAM store).
    fn handle(
        link: LinkId,
        request: Request,
        decoder: &FrameDecoder,
        flash: &mut Flash,
    ) -> DeviceMessage {
        let stats = decoder.stats();
        let handled = with_fc(|fc| fc.handle(link, request, now_us(), stats));
        match handled {
            Handled::Reply(message) => message,
            Handled::Save { seq, record } => {
                let ok = flash.save(&record);
                with_fc(|fc| fc.save_finished(seq, ok))
            }
        }
    }

    /// Runs `f` on the installed flight controller with interrupts masked.
    fn with_fc<R>(f: impl FnOnce(&mut FlightController) -> R) -> R {
        critical_section::with(|cs| {
            let mut fc = FC.borrow_ref_mut(cs);
            f(fc.as_mut()
                .expect("installed by main before the interrupts"))
        })
    }

    /// Frames `message` into `outgoing`, or drops it if it does not fit
    /// (the host is not reading).
    fn queue(message: &DeviceMessage, outgoing: &mut Deque<u8, OUTGOING_LEN>) {
        let mut frame = [0u8; MAX_FRAME_LEN];
        let Ok(n) = encode_frame(message, &mut frame) else {
            return;
        };
        if outgoing.capacity() - outgoing.len() < n {
            return;
        }
        for &byte in &frame[..n] {
            let _ = outgoing.push_back(byte);
        }
    }

    /// Sleeps unless received bytes or samples are waiting or a UART can
    /// take queued bytes; an interrupt arriving after the check still ends
    /// the `wfi` (it wakes on a pending interrupt with interrupts masked,
    /// which then run on unmasking).
    fn sleep_until_interrupt(ports: &[Port]) {
        critical_section::with(|cs| {
            let busy = !TELEMETRY.borrow_ref(cs).is_empty()
                || ports.iter().any(|p| {
                    !p.received.borrow_ref(cs).is_empty()
                        || (!p.outgoing.is_empty() && p.uart.can_send())
                });
            if !busy {
                cortex_m::asm::wfi();
            }
        });
    }

    #[exception]
    fn SysTick() {
        static mut VEHICLE: Option<Vehicle> = None;
        let vehicle = VEHICLE.get_or_insert_with(Vehicle::new);
        vehicle.advance();
        let ticks = TICKS.load(Ordering::Relaxed).wrapping_add(1);
        TICKS.store(ticks, Ordering::Relaxed);
        let m = vehicle.measure();
        let dt = 1.0 / board::CONTROL_HZ as f32;
        let now = u64::from(ticks) * board::CONTROL_PERIOD_US;
        let act = critical_section::with(|cs| {
            let mut fc = FC.borrow_ref_mut(cs);
            let fc = fc.as_mut()?;
            let start = counter::now();
            let act = fc.step(now, dt, &m);
            let counts = counter::now().wrapping_sub(start);
            let steps = STEPS.borrow(cs);
            let mut cost = steps.get();
            cost.record(counts);
            steps.set(cost);
            if let Some(telemetry) = act.telemetry {
                let _ = TELEMETRY.borrow_ref_mut(cs).push_back(telemetry);
            }
            Some(act)
        });
        match act {
            Some(act) => vehicle.apply(act.duty, act.bridge_enabled),
            None => vehicle.apply(0.0, false),
        }
    }

    /// The UARTs' interrupts (every external interrupt lands here: no
    /// device crate builds a vector table for this machine).
    #[exception]
    unsafe fn DefaultHandler(irqn: i16) {
        let (uart, index) = match Irq::from_number(irqn) {
            Some(Irq::Uart0Rx) => (UART0, 0),
            Some(Irq::Uart1Rx) => (UART1, 1),
            // A transmit buffer freed: the main loop sends the rest.
            Some(Irq::Uart0Tx) => return UART0.wake_when_sendable(false),
            Some(Irq::Uart1Tx) => return UART1.wake_when_sendable(false),
            None => return,
        };
        critical_section::with(|cs| {
            let mut received = RECEIVED[index].borrow_ref_mut(cs);
            while !received.is_full() {
                match uart.receive() {
                    Some(byte) => {
                        let _ = received.push_back(byte);
                    }
                    None => return,
                }
            }
            // Full: the next byte waits in the UART (and the sender in the
            // pty) until the main loop has made room and unmasks.
            NVIC::mask(if index == 0 {
                Irq::Uart0Rx
            } else {
                Irq::Uart1Rx
            });
        });
    }

    #[exception]
    unsafe fn HardFault(frame: &ExceptionFrame) -> ! {
        report::hard_fault(frame.pc());
        cortex_m_semihosting::debug::exit(cortex_m_semihosting::debug::EXIT_FAILURE);
        loop {
            cortex_m::asm::wfi();
        }
    }
}
