//! Drawing on any `embedded-graphics` display: streamed, dithered, placed, clipped.
//!
//! fixray renders one row at a time ([`render_row`](crate::render_row)), so it can draw
//! straight into a display driver on a chip whose RAM cannot hold a frame. This module is the
//! thin layer between the two: a [`Viewport`] places the camera's picture on a
//! [`DrawTarget`](embedded_graphics::draw_target::DrawTarget) with its top left pixel at a
//! point ([`Viewport::at`]; the size is the camera's), renders a band of rows into a buffer,
//! converts each shaded [`Rgb`](crate::Rgb) with [`FromRgb`] and pushes the band with one
//! `fill_contiguous` call. Two ways to draw it:
//!
//! - [`Viewport::picture`] makes a [`Picture`], an embedded-graphics
//!   [`Drawable`](embedded_graphics::Drawable) with a row buffer of its own:
//!   `view.picture::<Rgb565, 320>()?.draw(&mut display).map_err(DrawError::Display)?`
//!   (see [Errors](#errors) for the `map_err`).
//! - [`Viewport::bands`] and [`Viewport::render_rows`], with a buffer the caller owns, draw
//!   band by band so the caller can do other work between bands and pick the band height.
//!
//! Either way the picture is clipped to the display's bounding box: rows off the display are
//! never traced, and only the columns on it are sent (a row that shows is traced whole). A
//! 400 × 300 picture on a 320 × 240 display traces 240 rows and sends 76 800 pixels.
//!
//! Colours: every colour type of `embedded_graphics::pixelcolor`. `Rgb888` and `Bgr888` as
//! they are, `Rgb565` and `Bgr565` rounded, `Rgb666`, `Bgr666`, `Rgb555` and `Bgr555`
//! dithered per channel, `Gray8`, `Gray4`, `Gray2` and `BinaryColor` dithered in luma, all
//! with ordered (Bayer 8 × 8) [`dither`]ing keyed on display coordinates, so a one-bit OLED
//! shows shading, not a silhouette. Integer maths only. A driver's own colour type works
//! through `color_converted::<Rgb888>()` or its own [`FromRgb`]: see there.
//!
//! The whole-frame [`Framebuffer`](crate::Framebuffer) is an embedded-graphics image
//! (`Image::new(&frame, point)`) and a `DrawTarget<Color = Rgb888>`, and
//! [`Framebuffer::draw_at`](crate::Framebuffer::draw_at) draws it on any `FromRgb` display,
//! clipped and dithered the same way, pixel for pixel what a streamed render draws.
//!
//! # Errors
//!
//! Placing a viewport cannot fail. Making a [`Picture`] whose buffer is narrower than the
//! camera is an [`Error`](crate::Error), found before anything is drawn. Every call that
//! draws on a display returns [`DrawError`]: [`DrawError::Render`] when fixray refuses (rows
//! outside the picture, a buffer shorter than a row), [`DrawError::Display`] with the driver's
//! own error, unchanged, when the driver fails. `DrawError` converts from `Error`, so `?`
//! joins set-up and drawing in one function. [`Picture::draw`](embedded_graphics::Drawable::draw)
//! alone returns the driver's error as it is, as embedded-graphics' `Drawable` prescribes;
//! nothing is left for fixray to refuse by then. Drivers' errors seldom implement
//! `core::error::Error` (`mipidsi`'s, `st7735-lcd`'s and `ili9341`'s do not), so `?` cannot
//! join one with fixray's as it is: wrap it, `.draw(&mut display).map_err(DrawError::Display)?`,
//! and the function returns `DrawError` (`examples/driver.rs` does, on `mipidsi`).
//!
//! # Buffered displays: `flush`
//!
//! Some drivers draw into a frame buffer of their own in RAM and send it to the panel only
//! when asked: `ssd1306` in buffered-graphics mode, most e-paper drivers, the simulator's
//! window. On those, the picture appears after the driver's `flush()` (or `update`), which
//! fixray cannot call for you, as it knows only the `DrawTarget`. Draw, then flush:
//!
//! ```ignore
//! // ssd1306, 128 × 64 in buffered-graphics mode, BinaryColor; in a function that returns
//! // `Result<_, DrawError<DisplayError>>`.
//! let mut display = Ssd1306::new(interface, DisplaySize128x64, DisplayRotation::Rotate0)
//!     .into_buffered_graphics_mode();
//! display.init().map_err(DrawError::Display)?;
//! Viewport::at(&scene, &camera, Point::zero())
//!     .picture::<BinaryColor, 128>()?
//!     .draw(&mut display)
//!     .map_err(DrawError::Display)?;
//! display.flush().map_err(DrawError::Display)?; // nothing shows until the buffer is sent
//! ```
//!
//! Drivers that write each `fill_contiguous` straight to the panel (`mipidsi`, `ili9341`,
//! `st7735-lcd`) need no flush: each band shows as soon as it is drawn.
//!
//! # RAM and stack
//!
//! The renderer's RAM is the row buffer the caller passes, 3 bytes a column, and the stack
//! below the call; nothing else grows with the display. For a 320 × 240 display, drawn one
//! row at a time:
//!
//! | what | bytes |
//! | --- | --- |
//! | row buffer, `[Rgb; 320]` | 960 |
//! | the [`Viewport`] (two references and a point, 32-bit target) | 16 |
//! | stack below [`Viewport::render`], the deepest chip and scene | under 3.5 KB |
//! | **total** | **under 4.5 KB** |
//!
//! A framebuffer for the same display would take 230 400 bytes. The scene (`Scene<8>`, about
//! 1 KB with its shadow cones) and camera (56 bytes) are the caller's, wherever it keeps
//! them; a band of `k` rows costs `960 · k` bytes and saves `k − 1` driver calls per band.
//! A [`Picture`] holds the same one-row buffer on the stack while it draws (`[Rgb; W]`, with
//! `W` the width it was made for), so its total is the same, all of it stack.
//!
//! The stack is measured on each chip under QEMU by the firmware's `draw` binary
//! (`firmware/src/bin/draw.rs`, run by `scripts/firmware.sh`), through [`Viewport::render`]
//! and through a [`Picture`], for the demo and the classic scene; the figures are the README's
//! table *Stack below a draw*, and the deepest, the Cortex-M0's render of the classic scene
//! (mirrors, glass, highlights and three lights' shadows), is under 3.5 KB. A picture adds its
//! row buffer and a few words to that. Nothing on the stack is sized by the picture, and
//! nothing recurses (mirror and glass rays are a loop), so neither the display's size nor the
//! mirror depth changes the figure. The display's `fill_contiguous` is included; it runs
//! beside `render_row` rather than below it, so a real driver adds to the total only where it
//! needs more than that branch.

mod clip;
mod color;
mod dither;
mod error;
mod framebuffer;
mod passes;
mod picture;
mod viewport;

pub use color::FromRgb;
pub use dither::{BAYER_8X8, LUMA_MAX, bayer_index, dither, luma};
pub use error::DrawError;
pub use picture::Picture;
pub use viewport::{Bands, Viewport};
