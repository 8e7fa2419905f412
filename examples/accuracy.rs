//! Prints how closely the fixed-point renderer matches the f64 reference, per scene and
//! resolution, and can write a difference image.
//!
//! ```text
//! cargo run --release --example accuracy
//! cargo run --release --example accuracy -- --diff out/classic-diff.ppm
//! cargo run --release --example accuracy -- --markdown    # the README's table
//! ```
//!
//! Columns: pixels whose object agrees; pixels within ±2 per channel; of the pixels whose
//! object agrees, those within ±4; the largest channel error where the object agrees (and
//! anywhere); the pixels stable in the reference (their colour moves by at most 4 in every
//! channel when their ray's direction moves by 2⁻¹⁶) and the largest channel error over them;
//! PSNR; and the largest |Δt| (absolute, and relative to t) where both renderers hit the same
//! object. Below each row the plain output lists the stable pixels off by more than 4. The
//! difference image shows the classic scene at 160 × 128, black where the renderers agree
//! exactly and brighter where they differ (|Δ| × 32 per channel).

#[path = "../tests/common/accuracy.rs"]
mod accuracy;

use accuracy::{Accuracy, STABLE_WITHIN, channel_errors};
use fixray::{Camera, Scene, demo};
use fixray_reference::{DCamera, DScene, classic_camera, demo_camera};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let diff = std::env::args().skip_while(|a| a != "--diff").nth(1);
    if markdown() {
        println!(
            "| scene | size | object agrees | within ±2 | agreeing within ±4 | max channel error \
             | stable pixels | max error, stable | PSNR | max \\|Δt\\| (relative) |\n\
             |---|---|---|---|---|---|---|---|---|---|"
        );
    } else {
        println!(
            "{:<20} {:>8} {:>8} {:>7} {:>8} {:>9} {:>8} {:>7} {:>8} {:>9} {:>9}",
            "scene",
            "size",
            "object%",
            "±2 %",
            "±4 ag.%",
            "max err",
            "stable%",
            "st.err",
            "PSNR dB",
            "max |Δt|",
            "Δt/t"
        );
    }
    let demo_scene = demo::scene();
    for (cols, rows) in [(160u32, 128u32), (320, 240), (80, 64), (128, 64)] {
        let camera = demo::camera(cols, rows)?;
        let dcamera = demo_camera(cols, rows).ok_or("demo camera")?;
        row("demo (pinhole)", &demo_scene, &camera, &dcamera, None)?;
    }
    let classic = demo::classic();
    for (cols, rows) in [(160u32, 128u32), (320, 240)] {
        let camera = demo::classic_camera(cols, rows)?;
        let dcamera = classic_camera(cols, rows).ok_or("classic camera")?;
        let path = diff.as_deref().filter(|_| cols == 160);
        row("classic (look-at)", &classic, &camera, &dcamera, path)?;
    }
    Ok(())
}

fn row(
    name: &str,
    scene: &Scene<8>,
    camera: &Camera,
    dcamera: &DCamera,
    diff: Option<&str>,
) -> Result<(), Box<dyn std::error::Error>> {
    let dscene = DScene::from_scene(scene).ok_or("the scene has no f64 twin")?;
    let (cols, rows) = (camera.width(), camera.height());
    let mut image = Vec::with_capacity(cols as usize * rows as usize * 3);
    let mut stable_misses = Vec::new();
    let a = Accuracy::measure_each(scene, camera, &dscene, dcamera, |p| {
        image.extend(channel_errors(p.seen, p.reference).map(|d| d.saturating_mul(32)));
        if p.stable && p.error() > STABLE_WITHIN {
            stable_misses.push(*p);
        }
    });
    if markdown() {
        println!(
            "| {name} | {cols} × {rows} | {:.3} % | {:.3} % | {:.3} % | {} | {:.3} % | {} \
             | {:.1} dB | {} ({}) |",
            a.same_object_percent(),
            a.within_2_percent(),
            a.same_within_4_percent(),
            a.max_channel_error,
            a.stable_percent(),
            a.max_stable_error,
            a.psnr_db(),
            two_digits(a.max_dt),
            scientific(a.max_dt_relative)
        );
    } else {
        println!(
            "{:<20} {:>8} {:>8.3} {:>7.3} {:>8.3} {:>4} ({:>3}) {:>8.3} {:>7} {:>8.1} {:>9.4} \
             {:>9.2e}",
            name,
            format!("{cols}x{rows}"),
            a.same_object_percent(),
            a.within_2_percent(),
            a.same_within_4_percent(),
            a.max_channel_error,
            a.max_channel_error_any,
            a.stable_percent(),
            a.max_stable_error,
            a.psnr_db(),
            a.max_dt,
            a.max_dt_relative
        );
        for p in &stable_misses {
            let (s, r) = (p.seen, p.reference);
            println!(
                "  stable pixel ({}, {}) off by {}: object {:?} (reference {:?}), \
                 ({}, {}, {}) against ({}, {}, {})",
                p.x,
                p.y,
                p.error(),
                p.object,
                p.reference_object,
                s.r,
                s.g,
                s.b,
                r.r,
                r.g,
                r.b
            );
        }
    }
    if let Some(path) = diff {
        let mut ppm = format!("P6\n{cols} {rows}\n255\n").into_bytes();
        ppm.extend(image);
        if let Some(dir) = std::path::Path::new(path).parent() {
            std::fs::create_dir_all(dir)?;
        }
        std::fs::write(path, ppm)?;
        println!("  difference image of {name} {cols}x{rows} written to {path}");
    }
    Ok(())
}

/// Whether to print the table as Markdown, as the README shows it.
fn markdown() -> bool {
    std::env::args().any(|a| a == "--markdown")
}

/// `v` to two significant digits (one decimal from 1 up): 7.7, 0.012.
fn two_digits(v: f64) -> String {
    if v >= 1.0 || v <= 0.0 {
        format!("{v:.1}")
    } else {
        // v < 1, so its first digit is at least one place after the point.
        let places = (-v.log10().floor()) as usize + 1;
        format!("{v:.places$}")
    }
}

/// `v` as `1.9 × 10⁻³`.
fn scientific(v: f64) -> String {
    let text = format!("{v:.1e}");
    let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    let superscript: String = exponent
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            d => ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹']
                [d.to_digit(10).unwrap_or(0) as usize],
        })
        .collect();
    format!("{mantissa} × 10{superscript}")
}
