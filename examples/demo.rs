//! Renders the demo scene in fixed point, shows it in the terminal and writes it to a PPM file.
//!
//! ```text
//! cargo run --release --example demo                 # writes out/demo.ppm
//! cargo run --release --example demo -- FILE.ppm     # writes FILE.ppm
//! ```
//!
//! The terminal picture uses 24-bit colour and half-block characters (two pixel rows per text
//! line); set `NO_COLOR` for plain ASCII shading instead.

use std::io::Write;
use std::process::ExitCode;

use fixray::{Framebuffer, Rgb, demo, render};

const W: usize = 160;
const H: usize = 128;

/// Characters from dark to light, for the ASCII view.
const RAMP: &[u8] = b" .:-=+*#%@";

fn main() -> ExitCode {
    let path = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "out/demo.ppm".into());
    match run(&path) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("demo: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(path: &str) -> Result<(), Box<dyn std::error::Error>> {
    let scene = demo::scene();
    let mut frame = Box::new(Framebuffer::<W, H>::new());
    render(&scene, &demo::camera(W as u32, H as u32)?, &mut frame)?;

    // The terminal gets a half-size render of its own: 80 columns fit any terminal.
    let mut small = Framebuffer::<80, 64>::new();
    render(&scene, &demo::camera(80, 64)?, &mut small)?;
    let mut out = std::io::stdout().lock();
    if std::env::var_os("NO_COLOR").is_some() {
        print_ascii(&mut out, &small)?;
    } else {
        print_ansi(&mut out, &small)?;
    }

    if let Some(dir) = std::path::Path::new(path).parent() {
        std::fs::create_dir_all(dir)?;
    }
    let mut ppm = format!("P6\n{W} {H}\n255\n").into_bytes();
    ppm.extend(frame.bytes());
    std::fs::write(path, ppm)?;
    writeln!(out, "fixray: wrote the {W}x{H} demo render to {path}")?;
    Ok(())
}

fn print_ansi<const W: usize, const H: usize>(
    out: &mut impl Write,
    frame: &Framebuffer<W, H>,
) -> std::io::Result<()> {
    for pair in frame.rows().chunks(2) {
        for x in 0..W {
            let top = pair[0][x];
            let bottom = pair.get(1).map_or(Rgb::BLACK, |r| r[x]);
            write!(
                out,
                "\x1b[38;2;{};{};{}m\x1b[48;2;{};{};{}m\u{2580}",
                top.r, top.g, top.b, bottom.r, bottom.g, bottom.b
            )?;
        }
        writeln!(out, "\x1b[0m")?;
    }
    Ok(())
}

fn print_ascii<const W: usize, const H: usize>(
    out: &mut impl Write,
    frame: &Framebuffer<W, H>,
) -> std::io::Result<()> {
    for pair in frame.rows().chunks(2) {
        let line: String = pair[0]
            .iter()
            .map(|p| {
                let luma = (p.r as usize * 54 + p.g as usize * 183 + p.b as usize * 19) >> 8;
                RAMP[luma * (RAMP.len() - 1) / 255] as char
            })
            .collect();
        writeln!(out, "{line}")?;
    }
    Ok(())
}
