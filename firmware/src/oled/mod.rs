//! The LM3S6965 evaluation board's OLED as QEMU emulates it: a 128 × 64 panel with 16 grey
//! levels behind a Solomon SSD0323 controller on the chip's SSI0, drawn through
//! embedded-graphics as a `DrawTarget<Color = Gray4>`.
//!
//! The controller holds the picture in its own memory, two pixels a byte (the left one in the
//! high nibble), 64 bytes a row, and takes it through a window: a column range (in bytes, so
//! pairs of pixels) and a row range, filled row by row as data bytes arrive. It cannot be
//! read back over SSI, so [`Ssd0323`] keeps a copy of that memory (4 KiB) to change one pixel
//! of a pair without losing the other, and sends each drawing call's pixels as soon as it is
//! made: a `fill_contiguous` of rows, as `fixray::Viewport` sends, goes out as one window.
//! Nothing waits for a flush.
//!
//! The commands are those QEMU's model acts on (`hw/display/ssd0323.c`). A real panel also
//! wants its analogue settings (contrast, current, phase lengths, grey-scale table, DC-DC
//! converter) set for its glass before it is switched on; QEMU ignores them.

mod ssi;

pub use ssi::Ssi0;

use core::convert::Infallible;

use embedded_graphics::pixelcolor::{Gray4, GrayColor};
use embedded_graphics::prelude::{
    Dimensions, DrawTarget, OriginDimensions, Pixel, Point, PointsIter, Size,
};
use embedded_graphics::primitives::Rectangle;

/// Panel width in pixels.
pub const WIDTH: u32 = 128;
/// Panel height in pixels.
pub const HEIGHT: u32 = 64;
/// Bytes a row of the controller's memory: two pixels a byte.
const ROW_BYTES: usize = WIDTH as usize / 2;

/// Set the column window: first and last byte column (0 to 63).
const SET_COLUMNS: u8 = 0x15;
/// Set the row window: first and last row.
const SET_ROWS: u8 = 0x75;

/// Switched off, then set up, then switched on.
const INIT: [u8; 11] = [
    0xAE, // display off while it is set up
    0xA0, 0x00, // re-map: addresses advance along a row, left pixel in the high nibble
    0xA1, 0x00, // display start line 0
    0xA2, 0x00, // display offset 0
    0xA4, // normal display: memory as it is, not all on, off or inverted
    0xA8, 63,   // multiplex ratio: 64 rows
    0xAF, // display on
];

/// The SSD0323 panel on SSI0: an embedded-graphics display of 128 × 64 `Gray4` pixels.
#[derive(Debug)]
pub struct Ssd0323 {
    bus: Ssi0,
    /// The controller's memory as sent: row by row, [`ROW_BYTES`] a row, the left pixel of
    /// each pair in the high nibble.
    memory: [u8; ROW_BYTES * HEIGHT as usize],
}

impl Ssd0323 {
    /// Sets the controller up, switches the panel on and clears it to black.
    pub fn new(bus: Ssi0) -> Self {
        let mut panel = Ssd0323 {
            bus,
            memory: [0; ROW_BYTES * HEIGHT as usize],
        };
        panel.bus.command(&INIT);
        // The controller's memory is undefined at power-on: make it match the copy.
        panel.send(&panel.bounding_box());
        panel
    }

    /// Writes `colour` at `at` in the copy; `false` if `at` is off the panel.
    fn set(&mut self, at: Point, colour: Gray4) -> bool {
        let (Ok(x), Ok(y)) = (usize::try_from(at.x), usize::try_from(at.y)) else {
            return false;
        };
        if x >= WIDTH as usize {
            return false;
        }
        let Some(byte) = self.memory.get_mut(y * ROW_BYTES + x / 2) else {
            return false;
        };
        let shift = if x % 2 == 0 { 4 } else { 0 };
        *byte = (*byte & !(0x0F << shift)) | (colour.luma() << shift);
        true
    }

    /// Sends the copy's bytes that cover `area`, which lies on the panel, as one window.
    fn send(&mut self, area: &Rectangle) {
        let Some(last) = area.bottom_right() else {
            return; // empty
        };
        let first = area.top_left;
        // On the panel, so within 0..128 and 0..64: every value fits a byte.
        let (first_col, last_col) = (first.x as usize / 2, last.x as usize / 2);
        let (first_row, last_row) = (first.y as usize, last.y as usize);
        self.bus.command(&[
            SET_COLUMNS,
            first_col as u8,
            last_col as u8,
            SET_ROWS,
            first_row as u8,
            last_row as u8,
        ]);
        for row in first_row..=last_row {
            let start = row * ROW_BYTES;
            if let Some(bytes) = self.memory.get(start + first_col..=start + last_col) {
                self.bus.data(bytes);
            }
        }
    }
}

impl OriginDimensions for Ssd0323 {
    fn size(&self) -> Size {
        Size::new(WIDTH, HEIGHT)
    }
}

impl DrawTarget for Ssd0323 {
    type Color = Gray4;
    type Error = Infallible;

    /// Each pixel on the panel goes out on its own, with its neighbour in the byte: seven
    /// bytes on the bus a pixel. Areas are much cheaper through `fill_contiguous`.
    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Infallible>
    where
        I: IntoIterator<Item = Pixel<Gray4>>,
    {
        for Pixel(at, colour) in pixels {
            if self.set(at, colour) {
                self.send(&Rectangle::new(at, Size::new(1, 1)));
            }
        }
        Ok(())
    }

    /// The area's pixels on the panel go into the copy, then out as one window: a byte for
    /// each pair of pixels, a whole row of the panel in 64.
    fn fill_contiguous<I>(&mut self, area: &Rectangle, colours: I) -> Result<(), Infallible>
    where
        I: IntoIterator<Item = Gray4>,
    {
        for (at, colour) in area.points().zip(colours) {
            self.set(at, colour);
        }
        self.send(&area.intersection(&self.bounding_box()));
        Ok(())
    }
}
