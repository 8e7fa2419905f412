//! A scene (the demo, or the classic one) drawn on an `embedded-graphics-simulator` display,
//! streamed row by row exactly as on a microcontroller, then saved as a PNG. Headless: it
//! needs no window system.
//!
//! ```text
//! cargo run --release --example simulator                     # writes out/simulator.png
//! cargo run --release --example simulator -- --png docs/demo.png --size 160x128 --color rgb888
//! cargo run --release --example simulator -- --size 128x64 --color binary   # a one-bit OLED
//! cargo run --release --example simulator -- --scene classic --png docs/classic.png
//! ```
//!
//! To look around a scene in the simulator's own window, see the `window` crate beside this
//! one (`cd window && cargo run --release`).

use std::convert::Infallible;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use embedded_graphics::pixelcolor::{BinaryColor, Gray8, Rgb565, Rgb888};
use embedded_graphics::prelude::{PixelColor, Point};
use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay};
use fixray::{Camera, DrawError, FromRgb, MAX_PIXELS, Rgb, Scene, Viewport, demo};

const USAGE: &str = "\
usage: simulator [--scene demo|classic] [--png FILE] [--size WxH] [--color rgb565|rgb888|gray8|binary]

  --scene S     demo (default): matte spheres, one light; classic: tinyraytracer's scene with
                three lights, highlights, shadows, mirrors, a glass ball and a checkerboard floor
  --png FILE    write the picture to FILE (default: out/simulator.png in the crate)
  --size WxH    display size in pixels, 1 to 4096 a side (default: 160x128)
  --color C     the display's colour format (default: rgb888); gray8 and binary are dithered
  --help        this text

For a window (arrow keys orbit, + and - zoom), run the window crate: cd window && cargo run";

/// The display's colour format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Format {
    Rgb565,
    Rgb888,
    Gray8,
    Binary,
}

impl Format {
    fn name(self) -> &'static str {
        match self {
            Format::Rgb565 => "rgb565",
            Format::Rgb888 => "rgb888",
            Format::Gray8 => "gray8",
            Format::Binary => "binary",
        }
    }
}

/// Which scene to draw.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Which {
    Demo,
    Classic,
}

impl Which {
    fn name(self) -> &'static str {
        match self {
            Which::Demo => "demo",
            Which::Classic => "classic",
        }
    }

    fn scene(self) -> Scene<8> {
        match self {
            Which::Demo => demo::scene(),
            Which::Classic => demo::classic(),
        }
    }

    /// The scene's own camera, looking from the origin down −z.
    fn camera(self, cols: u32, rows: u32) -> Result<Camera, fixray::Error> {
        match self {
            Which::Demo => demo::camera(cols, rows),
            Which::Classic => demo::classic_camera(cols, rows),
        }
    }
}

/// What the command line asked for.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Options {
    scene: Which,
    png: Option<PathBuf>,
    cols: u32,
    rows: u32,
    format: Format,
}

/// `Ok(None)` means `--help`.
fn parse(args: impl IntoIterator<Item = String>) -> Result<Option<Options>, String> {
    let mut options = Options {
        scene: Which::Demo,
        png: None,
        cols: 160,
        rows: 128,
        format: Format::Rgb888,
    };
    let mut args = args.into_iter();
    while let Some(arg) = args.next() {
        let (flag, inline) = match arg.split_once('=') {
            Some((flag, value)) if flag.starts_with("--") => {
                (flag.to_string(), Some(value.to_string()))
            }
            _ => (arg, None),
        };
        let mut value = || {
            inline
                .clone()
                .or_else(|| args.next())
                .ok_or(format!("{flag} needs a value"))
        };
        match flag.as_str() {
            "-h" | "--help" => return Ok(None),
            "--png" => options.png = Some(PathBuf::from(value()?)),
            "--scene" => {
                options.scene = match value()?.as_str() {
                    "demo" => Which::Demo,
                    "classic" => Which::Classic,
                    other => return Err(format!("unknown scene '{other}': use demo or classic")),
                }
            }
            "--size" => (options.cols, options.rows) = parse_size(&value()?)?,
            "--color" | "--colour" => {
                options.format = match value()?.as_str() {
                    "rgb565" => Format::Rgb565,
                    "rgb888" => Format::Rgb888,
                    "gray8" | "grey8" => Format::Gray8,
                    "binary" => Format::Binary,
                    other => {
                        return Err(format!(
                            "unknown colour format '{other}': use rgb565, rgb888, gray8 or binary"
                        ));
                    }
                }
            }
            other => return Err(format!("unknown argument '{other}'")),
        }
    }
    Ok(Some(options))
}

fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let bad = || {
        format!("--size wants WIDTHxHEIGHT, 1 to {MAX_PIXELS} a side (like 160x128), not '{text}'")
    };
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let side = |s: &str| {
        s.parse::<u32>()
            .ok()
            .filter(|&n| (1..=MAX_PIXELS).contains(&n))
    };
    Ok((side(w).ok_or_else(bad)?, side(h).ok_or_else(bad)?))
}

/// Renders `scene` through `camera` onto a new simulator display, one row at a time, and
/// returns the display with the time the render took.
fn render<C>(
    scene: &Scene<8>,
    camera: &Camera,
) -> Result<(SimulatorDisplay<C>, Duration), DrawError<Infallible>>
where
    C: FromRgb + From<BinaryColor>,
{
    let mut display = SimulatorDisplay::<C>::new(camera.size());
    let view = Viewport::at(scene, camera, Point::zero());
    // One row of RAM, as on a microcontroller: 3 bytes a column.
    let mut row = [Rgb::BLACK; MAX_PIXELS as usize];
    let start = Instant::now();
    view.render(&mut row[..camera.width() as usize], &mut display)?;
    Ok((display, start.elapsed()))
}

/// The rendered picture as RGB888 bytes, row by row, for a PNG.
struct Picture {
    image: embedded_graphics_simulator::OutputImage<Rgb888>,
    took: Duration,
}

fn picture(
    scene: &Scene<8>,
    camera: &Camera,
    format: Format,
) -> Result<Picture, DrawError<Infallible>> {
    fn output<C: PixelColor + Into<Rgb888>>(
        (display, took): (SimulatorDisplay<C>, Duration),
    ) -> Picture {
        Picture {
            image: display.to_rgb_output_image(&OutputSettings::default()),
            took,
        }
    }
    Ok(match format {
        Format::Rgb565 => output(render::<Rgb565>(scene, camera)?),
        Format::Rgb888 => output(render::<Rgb888>(scene, camera)?),
        Format::Gray8 => output(render::<Gray8>(scene, camera)?),
        Format::Binary => output(render::<BinaryColor>(scene, camera)?),
    })
}

fn write_png(options: &Options, path: &Path) -> Result<(), String> {
    let camera = options
        .scene
        .camera(options.cols, options.rows)
        .map_err(|e| e.to_string())?;
    let picture =
        picture(&options.scene.scene(), &camera, options.format).map_err(|e| e.to_string())?;
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    }
    picture
        .image
        .save_png(path)
        .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    let shown = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    println!(
        "wrote the {} scene, {}x{} {}, rendered in {:.1} ms, to {}",
        options.scene.name(),
        options.cols,
        options.rows,
        options.format.name(),
        picture.took.as_secs_f64() * 1e3,
        shown.display()
    );
    Ok(())
}

fn run(options: &Options) -> Result<(), String> {
    let default = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/out/simulator.png"));
    write_png(options, options.png.as_deref().unwrap_or(default))
}

fn main() -> ExitCode {
    match parse(std::env::args().skip(1)) {
        Ok(None) => {
            println!("{USAGE}");
            ExitCode::SUCCESS
        }
        Ok(Some(options)) => match run(&options) {
            Ok(()) => ExitCode::SUCCESS,
            Err(message) => {
                eprintln!("simulator: {message}");
                ExitCode::FAILURE
            }
        },
        Err(message) => {
            eprintln!("simulator: {message} (see --help)");
            ExitCode::from(2)
        }
    }
}
