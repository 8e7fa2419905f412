//! fixray on a real display driver: the demo scene drawn through `mipidsi` onto an ST7789
//! 240 × 240 panel, twice: 16 rows at a time with a buffer of the caller's, then in one call
//! as an embedded-graphics `Drawable` (a `Picture`).
//!
//! The SPI bus and the data/command pin are fakes that play the panel's part: they decode the
//! bytes the driver sends (column and row windows, then pixel data after each memory write)
//! into the panel's memory. After each draw every pixel must have crossed the bus exactly once
//! and the panel must hold the host's own render of the scene, converted to `Rgb565` by
//! embedded-graphics. So this example compiles against the driver as it is published and
//! fails if the picture does not arrive whole; on a board, the fakes are the HAL's SPI device,
//! pins and delay, and nothing else changes.
//!
//! ```text
//! cargo run --example driver
//! ```

use std::cell::RefCell;
use std::convert::Infallible;
use std::rc::Rc;

use embedded_graphics::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
use embedded_graphics::prelude::*;
use embedded_hal::delay::DelayNs;
use embedded_hal::digital::{ErrorType as PinErrorType, OutputPin};
use embedded_hal::spi::{ErrorType as SpiErrorType, Operation, SpiDevice};
use fixray::{Camera, DrawError, Rgb, Scene, Viewport, demo, render_row};
use mipidsi::Builder;
use mipidsi::interface::SpiInterface;
use mipidsi::models::ST7789;
use mipidsi::options::ColorInversion;

const SIZE: u16 = 240;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let panel = Rc::new(RefCell::new(Panel::new()));
    let (spi, dc, mut delay) = (Bus(panel.clone()), DataCommand(panel.clone()), NoDelay);

    // The driver, as on a board: an SPI device, the data/command pin, a delay.
    let mut spi_buffer = [0u8; 512];
    let interface = SpiInterface::new(spi, dc, &mut spi_buffer);
    let mut display = Builder::new(ST7789, interface)
        .display_size(240, 240)
        .invert_colors(ColorInversion::Inverted)
        .init(&mut delay)
        .expect("the display starts");
    panel.borrow_mut().bytes = 0; // the draws' bytes only, not the start-up commands'

    // The picture: a camera the size of the display, drawn 16 rows per bus transfer.
    let (scene, camera) = (demo::scene(), demo::camera(240, 240)?);
    let viewport = Viewport::at(&scene, &camera, Point::zero());
    let mut band = [Rgb::BLACK; 240 * 16];
    viewport.render(&mut band, &mut display)?;
    let banded = shows_the_scene(&mut panel.borrow_mut(), &scene, &camera)?;

    // Or in one call, a row at a time. `Drawable::draw` returns the driver's own error, which
    // `DrawError::Display` holds as `render`'s errors do.
    viewport
        .picture::<Rgb565, 240>()?
        .draw(&mut display)
        .map_err(DrawError::Display)?;
    let pictured = shows_the_scene(&mut panel.borrow_mut(), &scene, &camera)?;

    let pixels = usize::from(SIZE) * usize::from(SIZE);
    for (how, (writes, bytes)) in [("in bands", banded), ("as a picture", pictured)] {
        println!(
            "driver: {pixels} pixels {how} in {writes} memory writes, {bytes} bytes on the bus; \
             the panel shows the demo scene"
        );
    }
    Ok(())
}

/// Checks that every pixel went over the bus once since the last check and that the panel
/// shows the scene, then blanks the panel for the next draw. Returns the memory writes and
/// the bytes the draw took.
fn shows_the_scene(
    panel: &mut Panel,
    scene: &Scene<8>,
    camera: &Camera,
) -> Result<(usize, usize), fixray::Error> {
    let pixels = usize::from(SIZE) * usize::from(SIZE);
    assert_eq!(panel.pixels_written, pixels, "pixels sent over the bus");
    let mut row = [Rgb::BLACK; SIZE as usize];
    for y in 0..SIZE {
        render_row(scene, camera, y.into(), &mut row)?;
        for (x, pixel) in row.iter().enumerate() {
            let expected = Rgb565::from(Rgb888::new(pixel.r, pixel.g, pixel.b));
            let shown = panel.memory[usize::from(y) * usize::from(SIZE) + x];
            assert_eq!(
                shown,
                RawU16::from(expected).into_inner(),
                "pixel ({x}, {y})"
            );
        }
    }
    let sent = (panel.memory_writes, panel.bytes);
    panel.memory.fill(0);
    (panel.pixels_written, panel.memory_writes, panel.bytes) = (0, 0, 0);
    Ok(sent)
}

/// The panel's side of the bus: enough of the ST7789's command set to place pixel data.
struct Panel {
    /// The level of the data/command pin: `true` for data.
    data: bool,
    /// The last command byte, and the parameter bytes that followed it.
    command: u8,
    params: Vec<u8>,
    /// The address window, inclusive, from CASET and RASET.
    columns: (u16, u16),
    rows: (u16, u16),
    /// Where the next pixel of a memory write goes, and the first byte of a pixel in flight.
    cursor: (u16, u16),
    high_byte: Option<u8>,
    memory: Vec<u16>,
    pixels_written: usize,
    memory_writes: usize,
    bytes: usize,
}

const CASET: u8 = 0x2a;
const RASET: u8 = 0x2b;
const RAMWR: u8 = 0x2c;

impl Panel {
    fn new() -> Self {
        Panel {
            data: false,
            command: 0,
            params: Vec::new(),
            columns: (0, SIZE - 1),
            rows: (0, SIZE - 1),
            cursor: (0, 0),
            high_byte: None,
            memory: vec![0; usize::from(SIZE) * usize::from(SIZE)],
            pixels_written: 0,
            memory_writes: 0,
            bytes: 0,
        }
    }

    fn receive(&mut self, byte: u8) {
        self.bytes += 1;
        if !self.data {
            self.command = byte;
            self.params.clear();
            if byte == RAMWR {
                self.cursor = (self.columns.0, self.rows.0);
                self.high_byte = None;
                self.memory_writes += 1;
            }
            return;
        }
        match self.command {
            CASET | RASET => {
                self.params.push(byte);
                if let [a, b, c, d] = self.params[..] {
                    let range = (u16::from_be_bytes([a, b]), u16::from_be_bytes([c, d]));
                    if self.command == CASET {
                        self.columns = range;
                    } else {
                        self.rows = range;
                    }
                }
            }
            RAMWR => match self.high_byte.take() {
                None => self.high_byte = Some(byte),
                Some(high) => self.pixel(u16::from_be_bytes([high, byte])),
            },
            _ => {}
        }
    }

    /// Stores a pixel at the cursor and moves it on, row by row through the window.
    fn pixel(&mut self, value: u16) {
        let (x, y) = self.cursor;
        assert!(
            x < SIZE && y < SIZE,
            "pixel outside the panel at ({x}, {y})"
        );
        self.memory[usize::from(y) * usize::from(SIZE) + usize::from(x)] = value;
        self.pixels_written += 1;
        self.cursor = if x < self.columns.1 {
            (x + 1, y)
        } else {
            (self.columns.0, y + 1)
        };
    }
}

/// The SPI device: every byte written goes to the panel.
struct Bus(Rc<RefCell<Panel>>);

impl SpiErrorType for Bus {
    type Error = Infallible;
}

impl SpiDevice for Bus {
    fn transaction(&mut self, operations: &mut [Operation<'_, u8>]) -> Result<(), Infallible> {
        let mut panel = self.0.borrow_mut();
        for operation in operations {
            match operation {
                Operation::Write(bytes) => bytes.iter().for_each(|&b| panel.receive(b)),
                Operation::Transfer(read, write) => {
                    write.iter().for_each(|&b| panel.receive(b));
                    read.fill(0);
                }
                Operation::TransferInPlace(bytes) => {
                    bytes.iter().for_each(|&b| panel.receive(b));
                    bytes.fill(0);
                }
                Operation::Read(bytes) => bytes.fill(0),
                Operation::DelayNs(_) => {}
            }
        }
        Ok(())
    }
}

/// The data/command pin: low for a command byte, high for its parameters and pixel data.
struct DataCommand(Rc<RefCell<Panel>>);

impl PinErrorType for DataCommand {
    type Error = Infallible;
}

impl OutputPin for DataCommand {
    fn set_low(&mut self) -> Result<(), Infallible> {
        self.0.borrow_mut().data = false;
        Ok(())
    }

    fn set_high(&mut self) -> Result<(), Infallible> {
        self.0.borrow_mut().data = true;
        Ok(())
    }
}

/// The panel needs no time to wake up.
struct NoDelay;

impl DelayNs for NoDelay {
    fn delay_ns(&mut self, _ns: u32) {}
}
