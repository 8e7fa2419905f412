//! Prints how closely the fixed-point renderer matches the f64 reference, per scene and
//! resolution.
//!
//! ```text
//! cargo run --release --example accuracy
//! ```
//!
//! Columns: pixels whose object agrees, pixels within ±2 per channel, the largest channel
//! error where the object agrees (and anywhere), PSNR, and the largest |Δt| (absolute, and
//! relative to t) where both renderers hit the same object.

use fixray::reference::{Accuracy, DCamera, DScene};
use fixray::{Camera, Error, demo};

fn main() -> Result<(), Error> {
    println!(
        "{:<22} {:>9} {:>8} {:>8} {:>10} {:>9} {:>9} {:>10}",
        "scene", "size", "object%", "±2 %", "max err", "PSNR dB", "max |Δt|", "max Δt/t"
    );
    let scene = demo::scene();
    let Some(dscene) = DScene::from_scene(&scene) else {
        return Err(Error::DegenerateCamera {
            why: "demo scene did not convert",
        });
    };
    for (cols, rows) in [(160u16, 128u16), (320, 240), (80, 64), (128, 64)] {
        let camera = demo::camera(cols, rows)?;
        let dcamera = demo_dcamera(cols, rows);
        row(
            "demo (pinhole)",
            cols,
            rows,
            &Accuracy::measure(&scene, &camera, &dscene, &dcamera),
        );
    }
    for (cols, rows) in [(160u16, 128u16), (320, 240)] {
        let (eye, target, up) = ([0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]);
        let camera = Camera::look_at(eye, target, up, 60.0, cols, rows)?;
        let d = |v: [f32; 3]| fixray::reference::DVec3::new(v[0] as f64, v[1] as f64, v[2] as f64);
        let dcamera =
            DCamera::look_at(d(eye), d(target), d(up), 60.0, cols, rows).expect("a valid camera");
        row(
            "demo (look-at 60°)",
            cols,
            rows,
            &Accuracy::measure(&scene, &camera, &dscene, &dcamera),
        );
    }
    Ok(())
}

/// The reference twin of [`demo::camera`], built from the same numbers.
fn demo_dcamera(cols: u16, rows: u16) -> DCamera {
    let h = demo::SCREEN_HEIGHT as f64;
    let w = h * cols as f64 / rows as f64;
    DCamera::pinhole(w, h, demo::SCREEN_DISTANCE as f64, rows, cols).expect("a valid camera")
}

fn row(name: &str, cols: u16, rows: u16, a: &Accuracy) {
    println!(
        "{:<22} {:>9} {:>8.3} {:>8.3} {:>5} ({:>3}) {:>9.1} {:>9.5} {:>10.2e}",
        name,
        format!("{cols}x{rows}"),
        a.same_object_percent(),
        a.within_2_percent(),
        a.max_channel_error,
        a.max_channel_error_any,
        a.psnr_db(),
        a.max_dt,
        a.max_dt_relative
    );
}
