//! What the Pico program (boards/rp2040-st7789) draws on its ST7789, drawn on the host: the
//! demo scene with the demo camera at the display's 240 × 135, through fixray's `Viewport`
//! into an in-memory `Rgb565` display.
//!
//! ```text
//! cargo run --release -- FILE
//! ```
//!
//! FILE gets the picture as the panel's memory holds it: row by row from the top left, two
//! bytes a pixel, the high byte first (`Rgb565` as it goes over the wire). scripts/pico.sh
//! compares it with what scripts/pico/decode.mjs reads from the emulated program's bus.
//!
//! The board program renders rows with `fixray::render_row` and converts them itself "as
//! `Viewport` converts them"; drawing through `Viewport` here checks that claim as well.

use std::convert::Infallible;
use std::process::ExitCode;

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::pixelcolor::raw::{RawData, RawU16};
use embedded_graphics::prelude::*;
use fixray::{Rgb, Viewport, demo};

/// The board program's display, in landscape.
const WIDTH: usize = 240;
const HEIGHT: usize = 135;

/// A display in memory: every pixel drawn, row by row.
struct Panel {
    pixels: Vec<Rgb565>,
}

impl OriginDimensions for Panel {
    fn size(&self) -> Size {
        Size::new(WIDTH as u32, HEIGHT as u32)
    }
}

impl DrawTarget for Panel {
    type Color = Rgb565;
    type Error = Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Infallible>
    where
        I: IntoIterator<Item = Pixel<Rgb565>>,
    {
        for Pixel(at, colour) in pixels {
            // Viewport clips to the display; a pixel outside it would be a bug worth seeing.
            let (x, y) = (at.x as usize, at.y as usize);
            assert!(x < WIDTH && y < HEIGHT, "a pixel off the display: {at:?}");
            self.pixels[y * WIDTH + x] = colour;
        }
        Ok(())
    }
}

fn main() -> ExitCode {
    let Some(path) = std::env::args().nth(1) else {
        eprintln!("usage: fixray-pico-host-render FILE");
        return ExitCode::from(2);
    };
    let scene = demo::scene();
    let camera = demo::camera(WIDTH as u32, HEIGHT as u32).expect("the demo camera fits");
    let mut panel = Panel {
        pixels: vec![Rgb565::BLACK; WIDTH * HEIGHT],
    };
    let mut row = [Rgb::BLACK; WIDTH];
    if let Err(e) = Viewport::at(&scene, &camera, Point::zero()).render(&mut row, &mut panel) {
        eprintln!("fixray-pico-host-render: {e:?}");
        return ExitCode::FAILURE;
    }
    let bytes: Vec<u8> = panel
        .pixels
        .iter()
        .flat_map(|&colour| RawU16::from(colour).into_inner().to_be_bytes())
        .collect();
    if let Err(e) = std::fs::write(&path, bytes) {
        eprintln!("fixray-pico-host-render: {path}: {e}");
        return ExitCode::FAILURE;
    }
    ExitCode::SUCCESS
}
