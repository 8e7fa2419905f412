//! Drawing on any `embedded-graphics` display: streamed, dithered, placed.
//!
//! fixray renders one row at a time ([`render_row`](crate::render_row)), so it can draw
//! straight into a display driver on a chip whose RAM cannot hold a frame. This module is the
//! thin layer between the two: a [`Viewport`] places the camera's picture on a rectangle of a
//! [`DrawTarget`](embedded_graphics::draw_target::DrawTarget), renders a band of rows into a
//! buffer the caller owns, converts each shaded [`Rgb`](crate::Rgb) with [`FromRgb`] and
//! pushes the band with one `fill_contiguous` call. Band by band ([`Viewport::bands`],
//! [`Viewport::render_rows`]) the caller can do other work between bands. Driver errors come
//! back unchanged inside [`DrawError::Display`].
//!
//! Colours: [`Rgb888`](embedded_graphics::pixelcolor::Rgb888) and
//! [`Rgb565`](embedded_graphics::pixelcolor::Rgb565) directly; `Gray8`, `Gray4`, `Gray2` and
//! `BinaryColor` through ordered (Bayer 8 × 8) [`dither`]ing keyed on display coordinates, so
//! a one-bit OLED shows shading, not a silhouette. Integer maths only.
//!
//! The whole-frame [`Framebuffer`](crate::Framebuffer) is an embedded-graphics image
//! (`Image::new(&frame, point)`) and a `DrawTarget<Color = Rgb888>`, and
//! [`Framebuffer::draw_at`](crate::Framebuffer::draw_at) draws it on any `FromRgb` display
//! with the same dithering, pixel for pixel what a streamed render draws.
//!
//! # RAM and stack
//!
//! The renderer's RAM is the row buffer the caller passes, 3 bytes a column, and nothing
//! else grows with the display. For a 320 × 240 display, drawn one row at a time:
//!
//! | what | bytes |
//! | --- | --- |
//! | row buffer, `[Rgb; 320]` | 960 |
//! | the [`Viewport`] (two references and a rectangle, 32-bit target) | 24 |
//! | stack below [`Viewport::render`] on a Cortex-M0, deepest path | about 1 200 |
//! | **total** | **about 2.2 KB** |
//!
//! A framebuffer for the same display would take 230 400 bytes. The scene (`Scene<8>`, about
//! 1 KB with its shadow cones) and camera (56 bytes) are the caller's, wherever it keeps
//! them; a band of `k` rows costs `960 · k` bytes and saves `k − 1` driver calls per band.
//!
//! The stack figure is measured, not estimated: a `Viewport::render` call for `Rgb565` and for
//! `BinaryColor` into a display that consumes its pixels, built for `thumbv6m-none-eabi` with
//! `opt-level = 3` and fat LTO, disassembled, and each function's frame (its `push` and
//! `sub sp`) summed along the deepest call chain: render (128 or 144 bytes, the dithered
//! format being the larger) → `render_row` (784, of which 256 are the per-row table of sphere
//! column spans that culling uses, the rest shading and shadows inlined) → a shape's
//! `hit_distance` (120) → the integer square root (64) → the 64-bit helpers (under 140). A
//! real driver's `fill_contiguous` runs from the render's frame, beside `render_row` rather
//! than below it, so it adds to the total only where it needs more than that branch. Nothing
//! recurses.

mod color;
mod dither;
mod error;
mod framebuffer;
mod viewport;

pub use color::FromRgb;
pub use dither::{BAYER_8X8, LUMA_MAX, bayer_index, dither, luma};
pub use error::DrawError;
pub use viewport::{Bands, Viewport};
