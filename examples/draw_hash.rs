//! The hashes the firmware's `draw` binary must reproduce: the demo and the classic scene at
//! 160 × 128 as an `Rgb565` display receives them, each pixel widened back to 8 bits a channel
//! and digested with [`FrameHash`] in raster order.
//!
//! The firmware draws through `Viewport`; this example does not, so a pixel lost, repeated
//! or misplaced on the way to the display shows as a different hash. It renders each row with
//! `render_row` and converts each pixel with `FromRgb` itself. `scripts/firmware.sh` compares
//! these lines with what each chip prints under QEMU. Run with
//!
//! ```text
//! cargo run --example draw_hash
//! ```
//!
//! It prints `draw-demo 0x........` and `draw-classic 0x........`.

use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
use embedded_graphics::prelude::Point;
use fixray::{Camera, FrameHash, FromRgb, Rgb, Scene, demo, render_row};

/// The firmware's frame size (firmware/src/renderer.rs: `COLS`, `ROWS`).
const COLS: u32 = 160;
const ROWS: u32 = 128;

fn main() -> Result<(), fixray::Error> {
    let scenes = [
        ("demo", demo::scene(), demo::camera(COLS, ROWS)?),
        (
            "classic",
            demo::classic(),
            demo::classic_camera(COLS, ROWS)?,
        ),
    ];
    for (name, scene, camera) in &scenes {
        println!("draw-{name} {:#010x}", digest(scene, camera)?);
    }
    Ok(())
}

/// The frame's pixels through `Rgb565` and back, digested row by row.
fn digest(scene: &Scene<8>, camera: &Camera) -> Result<u32, fixray::Error> {
    let mut row = [Rgb::BLACK; COLS as usize];
    let mut hash = FrameHash::new();
    for y in 0..ROWS {
        render_row(scene, camera, y, &mut row)?;
        for (x, pixel) in row.iter_mut().enumerate() {
            let shown = Rgb565::from_rgb(*pixel, Point::new(x as i32, y as i32));
            *pixel = Rgb::from(Rgb888::from(shown));
        }
        hash.update(&row);
    }
    Ok(hash.finish())
}
