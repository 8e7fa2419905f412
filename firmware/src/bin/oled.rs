//! The demo scene on the LM3S6965EVB's emulated OLED: 128 × 64 pixels in 16 greys, drawn
//! through `fixray::Viewport` one row at a time, Bayer-dithered to `Gray4` by fixray, onto the
//! SSD0323 controller over SSI0.
//!
//! It then says so over semihosting (`oled: drawn ...`) and waits, so that the panel can be
//! captured: `scripts/oled.sh` takes QEMU's screendump and compares it with the host's render.
//! Any failure exits QEMU non-zero instead.
//!
//! ```text
//! cargo build --release --target thumbv7m-none-eabi --features oled --bin oled
//! ```

#![no_std]
#![no_main]

#[cfg(not(board = "lm3s6965evb"))]
compile_error!("the oled firmware drives the LM3S6965EVB's panel: build it for thumbv7m-none-eabi");

use embedded_graphics::prelude::Point;
use fixray::{Rgb, Viewport, demo};
use fixray_firmware::exit;
use fixray_firmware::oled::{HEIGHT, Ssd0323, Ssi0, WIDTH};
use semihosting::{eprintln, println};

#[cortex_m_rt::entry]
fn main() -> ! {
    let Some(bus) = Ssi0::take() else {
        eprintln!("oled: SSI0 is already taken");
        exit::with(exit::FAULT)
    };
    let mut panel = Ssd0323::new(bus);
    let scene = demo::scene();
    let camera = demo::camera(WIDTH, HEIGHT).unwrap_or_else(|e| refused(e));
    // One row of the picture: the renderer's only RAM.
    let mut row = [Rgb::BLACK; WIDTH as usize];
    Viewport::at(&scene, &camera, Point::zero())
        .render(&mut row, &mut panel)
        .unwrap_or_else(|e| refused(e));
    println!("oled: drawn the demo scene, {WIDTH}x{HEIGHT} Gray4; waiting for the capture");
    loop {
        // SAFETY: `wfi` only waits for an interrupt, and none is enabled: the core sleeps
        // while QEMU's monitor takes the screendump and quits.
        unsafe { core::arch::asm!("wfi", options(nomem, nostack)) };
    }
}

/// Reports fixray's refusal and ends the run.
fn refused(error: impl core::fmt::Debug) -> ! {
    eprintln!("oled: fixray refused the picture: {error:?}");
    exit::with(exit::RENDER_FAILED)
}
