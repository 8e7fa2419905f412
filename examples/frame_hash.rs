//! The hashes the firmware must reproduce: the demo scene at 160 × 128, rendered row by row
//! by the Q16.16 renderer and by the f64 reference, each digested with [`FrameHash`].
//!
//! `scripts/firmware.sh` compares these with what each chip prints under QEMU. Run with
//!
//! ```text
//! cargo run --features reference --example frame_hash
//! ```
//!
//! It prints one line per renderer, e.g. `fixed 0x........`.

use fixray::reference::{self, DCamera, DScene};
use fixray::{FrameHash, Rgb, demo};

/// Columns of the firmware's frame.
const COLS: u16 = 160;
/// Rows of the firmware's frame.
const ROWS: u16 = 128;

fn main() -> Result<(), fixray::Error> {
    let scene = demo::scene();
    let camera = demo::camera(COLS, ROWS)?;
    let mut row = [Rgb::BLACK; COLS as usize];

    let mut fixed = FrameHash::new();
    for y in 0..ROWS {
        fixray::render_row(&scene, &camera, y, &mut row)?;
        fixed.update(&row);
    }
    println!("fixed {:#010x}", fixed.finish());

    // The demo camera in f64, built exactly as the firmware builds it.
    let twin = DScene::from_scene(&scene).expect("the demo scene has an f64 twin");
    let h = f64::from(demo::SCREEN_HEIGHT);
    let w = h * f64::from(COLS) / f64::from(ROWS);
    let z_p = f64::from(demo::SCREEN_DISTANCE);
    let twin_camera = DCamera::pinhole(w, h, z_p, ROWS, COLS).expect("a valid camera");
    let mut float = FrameHash::new();
    for y in 0..ROWS {
        reference::render_row(&twin, &twin_camera, y, &mut row);
        float.update(&row);
    }
    println!("reference-f64 {:#010x}", float.finish());
    Ok(())
}
