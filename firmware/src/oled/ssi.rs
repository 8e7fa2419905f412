//! The wires between the LM3S6965 and its OLED controller, as QEMU's `lm3s6965evb` lays them
//! out (`hw/arm/stellaris.c`): SSI0 (an Arm PL022 at 0x4000_8000) carries the bytes, GPIO
//! PC7 says whether they are commands (low) or display data (high), and PD0 selects.
//!
//! PD0 is the SD card's chip select (active low) on the same SSI bus. QEMU wires it to the
//! OLED's select as well, active high there, so holding PD0 high both deselects the card and
//! selects the panel. On the board itself the panel is selected by SSI0's own frame signal
//! (SSI0Fss on PA3), which the SSI drives low while it sends; setting PA2–PA5 to SSI0 covers
//! that. QEMU models neither PA's alternate function nor the clock gates, but both are set as
//! the chip needs them.
//!
//! QEMU's PL022 moves each byte the moment it is written, but stalls once its 8-entry receive
//! FIFO is full, as a real one overflows. The panel answers nothing, so every byte sent is
//! matched by one read and dropped.

use core::ptr;
use core::sync::atomic::{AtomicBool, Ordering};

/// System control: clock gating of the peripherals.
const SYSCTL: usize = 0x400F_E000;
/// Run-mode clock gating 1: bit 4 is SSI0.
const RCGC1: usize = SYSCTL + 0x104;
/// Run-mode clock gating 2: bit n is GPIO port n (A = 0).
const RCGC2: usize = SYSCTL + 0x108;

/// GPIO ports A, C and D (Luminary's PL061).
const GPIO_A: usize = 0x4000_4000;
const GPIO_C: usize = 0x4000_6000;
const GPIO_D: usize = 0x4000_7000;
/// Direction (1 = output).
const GPIO_DIR: usize = 0x400;
/// Alternate function select.
const GPIO_AFSEL: usize = 0x420;
/// Digital enable.
const GPIO_DEN: usize = 0x51C;
/// The data register is a window of 256 words: address bits 9..2 mask which pins a write
/// changes, so a write at `pins << 2` sets only `pins`.
const fn gpio_data(port: usize, pins: u32) -> usize {
    port + ((pins as usize) << 2)
}

/// PC7: data (high) or command (low).
const DATA_COMMAND: u32 = 1 << 7;
/// PD0: the SD card's select, and in QEMU the panel's.
const SELECT: u32 = 1 << 0;
/// PA2 (clock), PA3 (frame), PA4 (receive), PA5 (transmit): SSI0's pins.
const SSI0_PINS: u32 = 0b11_1100;

/// SSI0, an Arm PL022.
const SSI0: usize = 0x4000_8000;
/// Control 0: serial clock rate, phase, polarity, frame format, data size.
const SSI_CR0: usize = SSI0;
/// Control 1: bit 1 enables the port; bit 2 clear makes it the master.
const SSI_CR1: usize = SSI0 + 0x04;
/// Data: writes go to the transmit FIFO, reads come from the receive FIFO.
const SSI_DR: usize = SSI0 + 0x08;
/// Status.
const SSI_SR: usize = SSI0 + 0x0C;
/// Clock prescale divisor: even, at least 2.
const SSI_CPSR: usize = SSI0 + 0x10;
/// Status: the transmit FIFO is not full.
const SR_TNF: u32 = 1 << 1;
/// Status: the receive FIFO is not empty.
const SR_RNE: u32 = 1 << 2;
/// Status: a byte is being sent, or the transmit FIFO is not empty.
const SR_BSY: u32 = 1 << 4;

/// Control 0: 8-bit frames (DSS = 7), Motorola SPI (FRF = 0) in mode 3 (SPO = SPH = 1: the
/// clock idles high and the controller reads each bit on its rising edge), SCR = 1. With the
/// prescaler of 2 the bit clock is the system clock / (2 · (1 + SCR)): 3.125 MHz at the
/// 12.5 MHz the chip starts on. QEMU ignores the rate and the format.
const CR0: u32 = (1 << 8) | (1 << 7) | (1 << 6) | 7;
/// Control 1: enabled, master.
const CR1_ENABLE: u32 = 1 << 1;

/// Whether [`Ssi0::take`] has handed out the port.
static TAKEN: AtomicBool = AtomicBool::new(false);

/// SSI0 and the two GPIO lines of the OLED, set up; one exists at most.
#[derive(Debug)]
pub struct Ssi0 {
    /// Not constructible outside this module: [`Ssi0::take`] is the only way in.
    _private: (),
}

impl Ssi0 {
    /// Sets up the clocks, the pins and the port the first time; `None` afterwards, so that
    /// two drivers never share the registers.
    pub fn take() -> Option<Self> {
        if TAKEN.swap(true, Ordering::AcqRel) {
            return None;
        }
        // SAFETY: the registers of system control, GPIO ports A, C and D and SSI0, which only
        // this value (there is one at most) touches; each read-modify-write keeps the bits of
        // pins it does not own.
        unsafe {
            set_bits(RCGC1, 1 << 4);
            set_bits(RCGC2, 0b1101); // ports A, C and D
            set_bits(GPIO_A + GPIO_AFSEL, SSI0_PINS);
            set_bits(GPIO_A + GPIO_DEN, SSI0_PINS);
            for (port, pin) in [(GPIO_C, DATA_COMMAND), (GPIO_D, SELECT)] {
                set_bits(port + GPIO_DEN, pin);
                set_bits(port + GPIO_DIR, pin);
            }
            write(gpio_data(GPIO_D, SELECT), SELECT);
            write(gpio_data(GPIO_C, DATA_COMMAND), 0);
            write(SSI_CR1, 0); // disabled while it is configured
            write(SSI_CR0, CR0);
            write(SSI_CPSR, 2);
            write(SSI_CR1, CR1_ENABLE);
        }
        Some(Ssi0 { _private: () })
    }

    /// Sends `bytes` as commands (PC7 low).
    pub fn command(&mut self, bytes: &[u8]) {
        self.send(false, bytes);
    }

    /// Sends `bytes` as display data (PC7 high).
    pub fn data(&mut self, bytes: &[u8]) {
        self.send(true, bytes);
    }

    /// Sets PC7 to `data`, once the bytes before have left under the old level, then sends
    /// `bytes`.
    fn send(&mut self, data: bool, bytes: &[u8]) {
        self.finish();
        // SAFETY: PC7's bit of port C's data window; only this value writes it.
        unsafe {
            write(
                gpio_data(GPIO_C, DATA_COMMAND),
                if data { DATA_COMMAND } else { 0 },
            )
        };
        for &byte in bytes {
            // SAFETY: SSI0's status and data registers; only this value uses them.
            unsafe {
                while read(SSI_SR) & SR_TNF == 0 {
                    drain();
                }
                write(SSI_DR, u32::from(byte));
                drain();
            }
        }
    }

    /// Waits until every byte has left the port and drops what came back.
    fn finish(&mut self) {
        // SAFETY: SSI0's status and data registers; only this value uses them.
        unsafe {
            while read(SSI_SR) & SR_BSY != 0 {
                drain();
            }
            drain();
        }
    }
}

/// Reads and drops what the receive FIFO holds.
///
/// # Safety
///
/// SSI0 must be the caller's alone.
unsafe fn drain() {
    // SAFETY: the caller owns SSI0; reading its data register pops the receive FIFO.
    unsafe {
        while read(SSI_SR) & SR_RNE != 0 {
            read(SSI_DR);
        }
    }
}

/// # Safety
///
/// `address` is a peripheral register the caller owns.
unsafe fn read(address: usize) -> u32 {
    // SAFETY: as the caller promises.
    unsafe { ptr::read_volatile(address as *const u32) }
}

/// # Safety
///
/// `address` is a peripheral register the caller owns.
unsafe fn write(address: usize, value: u32) {
    // SAFETY: as the caller promises.
    unsafe { ptr::write_volatile(address as *mut u32, value) }
}

/// Sets `bits` in the register at `address`, keeping the others.
///
/// # Safety
///
/// `address` is a peripheral register the caller owns.
unsafe fn set_bits(address: usize, bits: u32) {
    // SAFETY: as the caller promises.
    unsafe { write(address, read(address) | bits) }
}
