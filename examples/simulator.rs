//! A scene (the demo, or the classic one) drawn on an `embedded-graphics-simulator` display, streamed row by row
//! exactly as on a microcontroller, then saved as a PNG or shown in a window.
//!
//! ```text
//! cargo run --release --example simulator                     # writes out/simulator.png
//! cargo run --release --example simulator -- --png docs/demo.png --size 160x128 --color rgb888
//! cargo run --release --example simulator -- --size 128x64 --color binary   # a one-bit OLED
//! cargo run --release --example simulator -- --scene classic --png docs/classic.png
//! cargo run --release --features window --example simulator   # a window (needs libsdl2-dev)
//! ```
//!
//! In the window the arrow keys orbit the camera around the scene, `+` and `-` zoom (the field
//! of view), Escape quits; each change re-renders, and the title shows the render time.

use std::convert::Infallible;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use embedded_graphics::pixelcolor::{BinaryColor, Gray8, Rgb565, Rgb888};
use embedded_graphics::prelude::{Dimensions, PixelColor, Size};
use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay};
use fixray::{Camera, DrawError, FromRgb, MAX_PIXELS, Rgb, Scene, Viewport, demo};

const USAGE: &str = "\
usage: simulator [--scene demo|classic] [--png FILE] [--size WxH] [--color rgb565|rgb888|gray8|binary]

  --scene S     demo (default): matte spheres, one light; classic: tinyraytracer's scene with
                three lights, highlights, shadows, mirrors and a checkerboard floor
  --png FILE    write the picture to FILE (default: out/simulator.png in the crate)
  --size WxH    display size in pixels, 1 to 4096 a side (default: 160x128)
  --color C     the display's colour format (default: rgb888); gray8 and binary are dithered
  --help        this text

Built with `--features window` and without --png, it opens a window instead:
arrow keys orbit, + and - zoom, Escape quits.";

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
    fn camera(self, cols: u16, rows: u16) -> Result<Camera, fixray::Error> {
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
    cols: u16,
    rows: u16,
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

fn parse_size(text: &str) -> Result<(u16, u16), String> {
    let bad = || {
        format!("--size wants WIDTHxHEIGHT, 1 to {MAX_PIXELS} a side (like 160x128), not '{text}'")
    };
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let side = |s: &str| {
        s.parse::<u16>()
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
    let mut display =
        SimulatorDisplay::<C>::new(Size::new(camera.cols().into(), camera.rows().into()));
    let view = Viewport::new(scene, camera, display.bounding_box())?;
    // One row of RAM, as on a microcontroller: 3 bytes a column.
    let mut row = [Rgb::BLACK; MAX_PIXELS as usize];
    let start = Instant::now();
    view.render(&mut row[..camera.cols().into()], &mut display)?;
    Ok((display, start.elapsed()))
}

/// The rendered picture as RGB888 bytes, row by row, for a PNG or a window.
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
    if let Some(path) = &options.png {
        return write_png(options, path);
    }
    #[cfg(feature = "window")]
    {
        window::run(options)
    }
    #[cfg(not(feature = "window"))]
    {
        write_png(
            options,
            Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/out/simulator.png")),
        )
    }
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

/// The SDL window. The simulator crate's own `Window` cannot change its title after it opens,
/// so the window is SDL's; the picture is still the simulator display's output image.
#[cfg(feature = "window")]
mod window {
    use sdl2::event::Event;
    use sdl2::keyboard::Keycode;
    use sdl2::pixels::PixelFormatEnum;

    use super::{Camera, Format, Options, picture};

    /// The camera orbits this point, the middle of the demo's spheres, at a fixed distance;
    /// from azimuth 0 and elevation 0 it sees what the demo camera sees.
    const TARGET: [f32; 3] = [0.0, 0.0, -15.0];
    const DISTANCE: f32 = 15.0;

    /// Where the camera is: angles in degrees.
    struct Orbit {
        azimuth: f32,
        elevation: f32,
        fov: f32,
    }

    impl Orbit {
        fn camera(&self, cols: u16, rows: u16) -> Result<Camera, String> {
            Camera::orbit(
                TARGET,
                DISTANCE,
                self.azimuth,
                self.elevation,
                self.fov,
                cols,
                rows,
            )
            .map_err(|e| e.to_string())
        }

        /// Applies a key; `true` if the view changed.
        fn key(&mut self, key: Keycode) -> bool {
            let before = (self.azimuth, self.elevation, self.fov);
            match key {
                Keycode::LEFT => self.azimuth -= 10.0,
                Keycode::RIGHT => self.azimuth += 10.0,
                // Above −10° the eye stays over the ground (y = −4); below 80° `up` is never
                // parallel to the view.
                Keycode::UP => self.elevation = (self.elevation + 5.0).min(80.0),
                Keycode::DOWN => self.elevation = (self.elevation - 5.0).max(-10.0),
                Keycode::PLUS | Keycode::KP_PLUS | Keycode::EQUALS => {
                    self.fov = (self.fov / 1.25).max(10.0)
                }
                Keycode::MINUS | Keycode::KP_MINUS => self.fov = (self.fov * 1.25).min(120.0),
                _ => {}
            }
            before != (self.azimuth, self.elevation, self.fov)
        }
    }

    pub(super) fn run(options: &Options) -> Result<(), String> {
        let (cols, rows) = (u32::from(options.cols), u32::from(options.rows));
        let scale = (640 / cols).min(480 / rows).clamp(1, 8);
        let sdl = sdl2::init()?;
        let window = sdl
            .video()?
            .window("fixray", cols * scale, rows * scale)
            .position_centered()
            .build()
            .map_err(|e| e.to_string())?;
        let mut canvas = window.into_canvas().build().map_err(|e| e.to_string())?;
        let creator = canvas.texture_creator();
        let mut texture = creator
            .create_texture_streaming(PixelFormatEnum::RGB24, cols, rows)
            .map_err(|e| e.to_string())?;
        let mut events = sdl.event_pump()?;
        let scene = options.scene.scene();
        let mut orbit = Orbit {
            azimuth: 0.0,
            elevation: 0.0,
            fov: 60.0,
        };
        let mut changed = true;
        loop {
            if changed {
                let camera = orbit.camera(options.cols, options.rows)?;
                let frame = picture(&scene, &camera, options.format).map_err(|e| e.to_string())?;
                texture
                    .update(
                        None,
                        frame.image.as_image_buffer().as_raw(),
                        3 * cols as usize,
                    )
                    .map_err(|e| e.to_string())?;
                let title = format!(
                    "fixray {}x{} {}: {:.1} ms a frame (arrows orbit, +/- zoom, Esc quits)",
                    cols,
                    rows,
                    Format::name(options.format),
                    frame.took.as_secs_f64() * 1e3
                );
                canvas
                    .window_mut()
                    .set_title(&title)
                    .map_err(|e| e.to_string())?;
                changed = false;
            }
            canvas.copy(&texture, None, None)?;
            canvas.present();
            match events.wait_event() {
                Event::Quit { .. }
                | Event::KeyDown {
                    keycode: Some(Keycode::ESCAPE),
                    ..
                } => return Ok(()),
                Event::KeyDown {
                    keycode: Some(key), ..
                } => changed = orbit.key(key),
                _ => {}
            }
        }
    }
}
