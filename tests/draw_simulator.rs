//! The `simulator` example, run as a user runs it: its PNG has the right size, is a picture,
//! and holds the framebuffer render's pixels; bad flags are refused without a panic.

#[path = "common/simulator.rs"]
mod simulator_run;

use std::path::{Path, PathBuf};

use embedded_graphics::pixelcolor::{BinaryColor, Gray8, Rgb565, Rgb888};
use embedded_graphics::prelude::{Point, RgbColor};
use simulator_run::simulator;

use fixray::{Framebuffer, FromRgb, demo, render};

fn temp_png(name: &str) -> PathBuf {
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("simulator-{name}.png"));
    let _ = std::fs::remove_file(&path);
    path
}

/// Runs the simulator and decodes its PNG: (width, height, RGB bytes).
fn run_png(name: &str, args: &[&str]) -> (u32, u32, Vec<u8>) {
    let path = temp_png(name);
    let mut all = vec!["--png", path.to_str().unwrap()];
    all.extend_from_slice(args);
    let out = simulator(&all);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{all:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    // It says where the picture went.
    assert!(
        stdout.contains(&format!("simulator-{name}.png")),
        "{stdout}"
    );

    decode(&path)
}

/// Decodes an 8-bit RGB PNG: (width, height, RGB bytes).
fn decode(path: &Path) -> (u32, u32, Vec<u8>) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut bytes = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut bytes).unwrap();
    assert_eq!(
        (info.color_type, info.bit_depth),
        (png::ColorType::Rgb, png::BitDepth::Eight)
    );
    bytes.truncate(info.buffer_size());
    (info.width, info.height, bytes)
}

/// The demo rendered by the core into a framebuffer, with no drawing layer involved.
fn framebuffer<const W: usize, const H: usize>() -> Box<Framebuffer<W, H>> {
    let mut frame = Box::new(Framebuffer::<W, H>::new());
    render(
        &demo::scene(),
        &demo::camera(W as u32, H as u32).unwrap(),
        &mut frame,
    )
    .unwrap();
    frame
}

fn distinct_colours(bytes: &[u8]) -> usize {
    let mut colours: Vec<&[u8]> = bytes.chunks(3).collect();
    colours.sort();
    colours.dedup();
    colours.len()
}

#[test]
fn the_default_picture_is_the_framebuffer_render() {
    let (w, h, bytes) = run_png("rgb888", &[]);
    assert_eq!((w, h), (160, 128));
    assert!(
        distinct_colours(&bytes) > 500,
        "a shaded scene, not a blank or flat image"
    );
    let frame = framebuffer::<160, 128>();
    assert!(
        bytes == frame.bytes().collect::<Vec<u8>>(),
        "PNG differs from the framebuffer render"
    );
}

/// The README's picture is what the renderer draws today.
#[test]
fn the_committed_demo_png_is_up_to_date() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/demo.png");
    let (w, h, bytes) = decode(&path);
    assert_eq!((w, h), (160, 128));
    let frame = framebuffer::<160, 128>();
    assert!(
        bytes == frame.bytes().collect::<Vec<u8>>(),
        "docs/demo.png is stale: regenerate it with \
         `cargo run --release --example simulator -- --png docs/demo.png`"
    );
}

/// Each format's PNG shows what that display would: the framebuffer's pixels converted
/// (and dithered at the same display points) to the format, then expanded back to RGB888.
#[test]
fn every_colour_format_shows_the_framebuffer_render_converted() {
    fn check<C: FromRgb + Into<Rgb888>>(format: &str, frame: &Framebuffer<96, 64>) {
        let (w, h, bytes) = run_png(format, &["--size", "96x64", "--color", format]);
        assert_eq!((w, h), (96, 64), "{format}");
        let expected: Vec<u8> = frame
            .rows()
            .iter()
            .enumerate()
            .flat_map(|(y, row)| {
                row.iter().enumerate().flat_map(move |(x, &c)| {
                    let shown: Rgb888 = C::from_rgb(c, Point::new(x as i32, y as i32)).into();
                    [shown.r(), shown.g(), shown.b()]
                })
            })
            .collect();
        assert!(
            bytes == expected,
            "{format}: PNG differs from the converted framebuffer render"
        );
    }
    let frame = framebuffer::<96, 64>();
    check::<Rgb888>("rgb888", &frame);
    check::<Rgb565>("rgb565", &frame);
    check::<Gray8>("gray8", &frame);
    check::<BinaryColor>("binary", &frame);

    // The one-bit picture is black and white only, and dithered: both appear in the sky.
    let (_, _, bytes) = run_png("binary-sky", &["--size", "96x64", "--color", "binary"]);
    assert!(bytes.iter().all(|&b| b == 0 || b == 255));
    assert!(bytes[..96 * 3].contains(&0) && bytes[..96 * 3].contains(&255));
    // Grey shows more than two shades.
    let (_, _, grey) = run_png("gray8-shades", &["--size", "96x64", "--color", "gray8"]);
    assert!(distinct_colours(&grey) > 50);
    assert!(grey.chunks(3).all(|p| p[0] == p[1] && p[1] == p[2]));
}

#[test]
fn bad_flags_are_refused_with_a_message_not_a_panic() {
    for (args, mentions) in [
        (&["--size", "160"][..], "--size"),
        (&["--size", "0x128"][..], "--size"),
        (&["--size", "5000x10"][..], "--size"),
        (&["--color", "cmyk"][..], "cmyk"),
        (&["--png"][..], "--png"),
        (&["--frobnicate"][..], "--frobnicate"),
    ] {
        let out = simulator(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(mentions), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    }
    // An unwritable path is an error too, exit 1, with the path in the message.
    let out = simulator(&["--png", "/proc/no/such/dir/x.png"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("/proc/no/such/dir"));
}
