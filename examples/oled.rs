//! What QEMU's emulated OLED should show: the demo scene at 128 × 64, drawn through
//! `Viewport` into an in-memory `Gray4` display, written as the 512 × 256 PPM that QEMU's
//! `screendump` makes of the LM3S6965EVB's SSD0323 panel.
//!
//! ```text
//! cargo run --example oled -- FILE.ppm
//! ```
//!
//! `scripts/oled.sh` compares it, pixel for pixel, with the screendump of the firmware
//! `firmware/src/bin/oled.rs`, which draws the same scene through the same `Viewport` onto the
//! emulated controller. QEMU's model (`hw/display/ssd0323.c`) draws each panel pixel as a
//! 4 × 4 block (its `MAGNIFY`), and grey level `n` of 0 to 15 as `(n << 4) | n`, so 17 · n,
//! in each of red, green and blue.

use std::process::ExitCode;

use embedded_graphics::pixelcolor::{Gray4, GrayColor};
use embedded_graphics::prelude::*;
use embedded_graphics_simulator::SimulatorDisplay;
use fixray::{Rgb, Viewport, demo};

/// The panel, pixels.
const WIDTH: u32 = 128;
const HEIGHT: u32 = 64;
/// QEMU's magnification of the panel on its console.
const MAGNIFY: u32 = 4;

fn main() -> ExitCode {
    let Some(path) = std::env::args().nth(1) else {
        eprintln!("usage: oled FILE.ppm");
        return ExitCode::from(2);
    };
    match run(&path) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("oled: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(path: &str) -> Result<(), Box<dyn std::error::Error>> {
    let scene = demo::scene();
    let camera = demo::camera(WIDTH, HEIGHT)?;
    let mut panel = SimulatorDisplay::<Gray4>::new(Size::new(WIDTH, HEIGHT));
    // One row at a time, as the firmware draws it.
    let mut row = [Rgb::BLACK; WIDTH as usize];
    Viewport::at(&scene, &camera, Point::zero()).render(&mut row, &mut panel)?;

    let (width, height) = (WIDTH * MAGNIFY, HEIGHT * MAGNIFY);
    let mut ppm = format!("P6\n{width} {height}\n255\n").into_bytes();
    for y in 0..height {
        for x in 0..width {
            let at = Point::new((x / MAGNIFY) as i32, (y / MAGNIFY) as i32);
            let level = panel.get_pixel(at).luma();
            ppm.extend([(level << 4) | level; 3]);
        }
    }
    std::fs::write(path, ppm)?;
    println!("oled: wrote what the emulated panel should show to {path}");
    Ok(())
}
