//! [`Framebuffer`]: a whole frame of [`Rgb`] pixels in fixed-size storage.

use crate::scene::colour::Rgb;

/// `W × H` pixels, row-major, with the storage inside the value.
///
/// The capacity is in the type, as in `heapless`, and there is no length to track: a frame is
/// always full, so a plain array is the storage and [`Framebuffer::new`] is `const`, which lets
/// a frame live in a `static`. It takes `3 · W · H` bytes (61 440 for 160 × 128): on a chip
/// whose RAM cannot hold that, render row by row with [`render_row`](crate::render_row).
///
/// ```
/// use fixray::{Framebuffer, Rgb};
/// static FRAME: Framebuffer<160, 128> = Framebuffer::new();
/// assert_eq!(FRAME.pixel(159, 127), Some(Rgb::BLACK));
/// assert_eq!(FRAME.pixel(160, 0), None);
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Framebuffer<const W: usize, const H: usize> {
    rows: [[Rgb; W]; H],
}

impl<const W: usize, const H: usize> Framebuffer<W, H> {
    /// A black frame.
    #[must_use]
    pub const fn new() -> Self {
        Framebuffer {
            rows: [[Rgb::BLACK; W]; H],
        }
    }

    /// Width in pixels.
    #[must_use]
    pub const fn width(&self) -> usize {
        W
    }

    /// Height in pixels.
    #[must_use]
    pub const fn height(&self) -> usize {
        H
    }

    /// The pixel at column `x`, row `y` (row 0 at the top), or `None` outside the frame.
    #[must_use]
    pub fn pixel(&self, x: usize, y: usize) -> Option<Rgb> {
        self.rows.get(y)?.get(x).copied()
    }

    /// Sets the pixel at column `x`, row `y`; outside the frame it does nothing and returns
    /// `false`.
    pub fn set_pixel(&mut self, x: usize, y: usize, colour: Rgb) -> bool {
        match self.rows.get_mut(y).and_then(|row| row.get_mut(x)) {
            Some(p) => {
                *p = colour;
                true
            }
            None => false,
        }
    }

    /// The rows, top first.
    #[must_use]
    pub fn rows(&self) -> &[[Rgb; W]; H] {
        &self.rows
    }

    /// The rows, top first, to write into.
    pub fn rows_mut(&mut self) -> &mut [[Rgb; W]; H] {
        &mut self.rows
    }

    /// The frame's bytes, row by row, `r, g, b` for each pixel: what a PPM file holds and what
    /// [`FrameHash`](crate::FrameHash) digests.
    pub fn bytes(&self) -> impl Iterator<Item = u8> + '_ {
        self.rows.iter().flatten().flat_map(|p| [p.r, p.g, p.b])
    }
}

impl<const W: usize, const H: usize> Default for Framebuffer<W, H> {
    fn default() -> Self {
        Self::new()
    }
}
