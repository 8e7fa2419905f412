//! A mipidsi display interface that sends pixels by DMA, so that the SPI transfer of one band
//! goes on while the cores render the next.
//!
//! mipidsi's own `SpiInterface` drives the bus through embedded-hal's blocking `SpiDevice`:
//! the CPU feeds every byte. This one owns the RP2040's SPI peripheral, a DMA channel and two
//! byte buffers of `N` bytes. `send_pixels` packs the pixels into the free buffer and, each
//! time a buffer is full, starts a DMA transfer of it and goes on packing into the other; it
//! returns as soon as the last full buffer is on its way. A command (the next band's address
//! window) first waits for the transfer in flight to end. The board program makes a band
//! exactly `N` bytes, so each band is one DMA transfer; a shorter run of pixels (the text) is
//! written by the CPU.
//!
//! Only full buffers go by DMA because a transfer's length is its buffer's: the HAL takes a
//! `&'static mut [u8; N]` and gives it back when the transfer ends, and a shorter slice of it
//! could not be turned back into the whole buffer without unsafe code.
//!
//! Chip select is low from the start of a command or a run of pixels until its last bit has
//! left; between them it goes high, as embedded-hal's `SpiDevice` does for mipidsi's own
//! interface (the ST7789 goes on writing memory across such a gap until the next command).

use embedded_hal::digital::OutputPin;
use embedded_hal::spi::SpiBus;
use mipidsi::interface::{Interface, InterfaceKind};
use rp2040_hal::dma::{SingleChannel, WriteTarget, single_buffer};

/// A failure on the display's bus.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BusError {
    /// The SPI peripheral reported an error.
    Spi,
    /// The data/command or chip-select pin could not be set.
    Pin,
}

/// The display interface: the SPI peripheral `S` and DMA channel `C`, the data/command pin
/// `DC` and chip select `CS`, and two DMA buffers of `N` bytes.
pub struct DmaInterface<C, S, DC, CS, const N: usize>
where
    C: SingleChannel,
    S: WriteTarget<TransmittedWord = u8> + SpiBus<u8>,
{
    /// The channel and the peripheral while no transfer runs; exactly one of `idle` and
    /// `sending` holds them.
    idle: Option<(C, S)>,
    /// The transfer in flight, which holds the channel, the peripheral and one buffer.
    sending: Option<single_buffer::Transfer<C, &'static mut [u8; N], S>>,
    /// The buffers neither in flight nor being packed.
    free: [Option<&'static mut [u8; N]>; 2],
    dc: DC,
    cs: CS,
}

impl<C, S, DC, CS, const N: usize> DmaInterface<C, S, DC, CS, N>
where
    C: SingleChannel,
    S: WriteTarget<TransmittedWord = u8> + SpiBus<u8>,
    DC: OutputPin,
    CS: OutputPin,
{
    /// The interface over an enabled 8-bit SPI peripheral, with chip select `cs` high.
    pub fn new(channel: C, spi: S, dc: DC, cs: CS, buffers: [&'static mut [u8; N]; 2]) -> Self {
        Self {
            idle: Some((channel, spi)),
            sending: None,
            free: buffers.map(Some),
            dc,
            cs,
        }
    }

    /// Waits for the transfer in flight, if any, to end, and gives back its buffer; returns
    /// the peripheral, idle.
    fn wait(&mut self) -> Result<&mut S, BusError> {
        if let Some(transfer) = self.sending.take() {
            let (channel, buffer, spi) = transfer.wait();
            self.idle = Some((channel, spi));
            self.put_back(buffer);
        }
        // The two fields hold the peripheral by turns; an error rather than a panic if a bug
        // ever lost it.
        self.idle.as_mut().map(|(_, spi)| spi).ok_or(BusError::Spi)
    }

    /// Waits until every byte written has left the wire, then lets chip select go high.
    fn release(&mut self) -> Result<(), BusError> {
        self.wait()?.flush().map_err(|_| BusError::Spi)?;
        self.cs.set_high().map_err(|_| BusError::Pin)
    }

    /// Writes `bytes` with the CPU, after any transfer in flight.
    fn write(&mut self, bytes: &[u8]) -> Result<(), BusError> {
        self.wait()?.write(bytes).map_err(|_| BusError::Spi)
    }

    /// Starts a DMA transfer of the full buffer `buffer`, after any transfer in flight.
    fn start(&mut self, buffer: &'static mut [u8; N]) -> Result<(), BusError> {
        self.wait()?;
        let (channel, spi) = self.idle.take().ok_or(BusError::Spi)?;
        self.sending = Some(single_buffer::Config::new(channel, buffer, spi).start());
        Ok(())
    }

    /// Takes a free buffer, waiting for the transfer in flight if both are in use.
    fn take_free(&mut self) -> Result<&'static mut [u8; N], BusError> {
        if let Some(buffer) = self.free.iter_mut().find_map(Option::take) {
            return Ok(buffer);
        }
        self.wait()?;
        self.free
            .iter_mut()
            .find_map(Option::take)
            .ok_or(BusError::Spi)
    }

    fn put_back(&mut self, buffer: &'static mut [u8; N]) {
        if let Some(slot) = self.free.iter_mut().find(|slot| slot.is_none()) {
            *slot = Some(buffer);
        }
    }
}

impl<C, S, DC, CS, const N: usize> Interface for DmaInterface<C, S, DC, CS, N>
where
    C: SingleChannel,
    S: WriteTarget<TransmittedWord = u8> + SpiBus<u8>,
    DC: OutputPin,
    CS: OutputPin,
{
    type Word = u8;
    type Error = BusError;

    const KIND: InterfaceKind = InterfaceKind::Serial4Line;

    fn send_command(&mut self, command: u8, args: &[u8]) -> Result<(), BusError> {
        // The data/command pin must not change under a byte still on the wire.
        self.release()?;
        self.cs.set_low().map_err(|_| BusError::Pin)?;
        self.dc.set_low().map_err(|_| BusError::Pin)?;
        self.write(&[command])?;
        self.wait()?.flush().map_err(|_| BusError::Spi)?;
        self.dc.set_high().map_err(|_| BusError::Pin)?;
        self.write(args)?;
        self.release()
    }

    fn send_pixels<const M: usize>(
        &mut self,
        pixels: impl IntoIterator<Item = [u8; M]>,
    ) -> Result<(), BusError> {
        // After a command the pins are as the pixels need them (data, chip select high); after
        // earlier pixels a transfer may still run, and chip select stays low for it.
        self.cs.set_low().map_err(|_| BusError::Pin)?;
        self.dc.set_high().map_err(|_| BusError::Pin)?;
        let mut buffer = self.take_free()?;
        let mut filled = 0;
        for pixel in pixels {
            for byte in wire_order(pixel) {
                buffer[filled] = byte;
                filled += 1;
                if filled == N {
                    self.start(buffer)?;
                    buffer = self.take_free()?;
                    filled = 0;
                }
            }
        }
        // A run that filled its last buffer exactly returns with that buffer on its way; a run
        // shorter than a buffer (or its tail) goes by the CPU.
        let result = if filled == 0 {
            Ok(())
        } else {
            self.write(&buffer[..filled])
        };
        self.put_back(buffer);
        result
    }

    fn send_repeated_pixel<const M: usize>(
        &mut self,
        pixel: [u8; M],
        count: u32,
    ) -> Result<(), BusError> {
        self.cs.set_low().map_err(|_| BusError::Pin)?;
        self.dc.set_high().map_err(|_| BusError::Pin)?;
        for _ in 0..count {
            self.write(&pixel)?;
        }
        self.release()
    }
}

/// A pixel's bytes in the order they go on the wire: as mipidsi gives them (for `Rgb565`, the
/// high byte first, as the ST7789 takes it). The `fault-byte-swap` feature reverses them, a
/// fault that scripts/pico.sh must see in the emulated panel's picture.
fn wire_order<const M: usize>(pixel: [u8; M]) -> [u8; M] {
    if cfg!(feature = "fault-byte-swap") {
        let mut swapped = pixel;
        swapped.reverse();
        swapped
    } else {
        pixel
    }
}
