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
//! With `--frames N` it animates instead, and redraws each frame after the first only where
//! the edit of the scene can change it, as an animation on a microcontroller would, to send
//! the display only those pixels: on the demo a ball bounces across the floor (its picture and
//! its shadow are the damage), on the classic scene the first light circles (a moved light
//! damages the whole screen: the fallback). [`fixray::Damage::between`] gives the region and
//! [`fixray::render_row_span`] redraws it span by span into the simulator display. Each frame
//! is checked against a full render (every frame up to 320 × 240, the last one above), and
//! written as a PNG, and with `--apng` as a frame of an animated PNG that stores only the
//! part of each frame that changed.
//!
//! ```text
//! cargo run --release --example simulator -- --frames 24 --size 160x128
//! cargo run --release --example simulator -- --frames 48 --apng docs/animation.png
//! cargo run --release --example simulator -- --frames 12 --scene classic --png-dir out/classic
//! ```
//!
//! With `--progressive DIR` it draws the picture in passes instead, as a display shows a frame
//! that takes long to trace: the first pass traces every 8th pixel of every 8th row
//! (`--spacing N` starts at another power of two up to 64) and paints each one's block, each
//! next pass down to spacing 4 halves the spacing and traces only the pixels no pass traced
//! before, and the last two complete the even rows, then the odd ones. [`Viewport::render_pass`] draws each pass onto
//! the simulator display, written after each pass to `DIR/pass-1.png`, `DIR/pass-2.png`, …;
//! the display the passes leave is checked against a plain render.
//!
//! ```text
//! cargo run --release --example simulator -- --progressive out/passes
//! cargo run --release --example simulator -- --scene classic --progressive out/passes --spacing 16
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
use fixray::{
    Camera, DrawError, FromRgb, MAX_PIXELS, MAX_SPACING, Pass, Rgb, Scene, Viewport, demo,
};

const USAGE: &str = "\
usage: simulator [--scene demo|classic] [--png FILE] [--size WxH] [--color rgb565|rgb888|gray8|binary]
       simulator --frames N [--png-dir DIR] [--apng FILE] [--scene S] [--size WxH] [--color C]
       simulator --progressive DIR [--spacing N] [--scene S] [--size WxH] [--color C]

  --scene S      demo (default): matte spheres, one light; classic: tinyraytracer's scene with
                 three lights, highlights, shadows, mirrors, a glass ball and a checkerboard floor
  --png FILE     write the picture to FILE (default: out/simulator.png in the crate)
  --size WxH     display size in pixels, 1 to 4096 a side (default: 160x128)
  --color C      the display's colour format (default: rgb888); gray8 and binary are dithered
  --frames N     animate N frames (1 to 10000) instead: on the demo a ball bounces across the
                 floor, on the classic scene the first light circles; each frame after the
                 first redraws only what the edit can change, and is checked against a full render
  --png-dir DIR  with --frames: write frame-000.png, frame-001.png, ... to DIR
                 (default: out/frames in the crate)
  --apng FILE    with --frames: also write the frames as one animated PNG, looping
  --progressive DIR
                 draw the picture in passes instead, coarse to fine, the last one complete,
                 and write the display after each pass to DIR/pass-1.png, DIR/pass-2.png, ...;
                 the final picture is checked against a plain render
  --spacing N    with --progressive: the first pass's spacing, a power of two from 1 to 64
                 (default: 8); each pass after halves it, down to 1
  --help         this text

For a window (arrow keys orbit, + and - zoom, A animates), run the window crate:
cd window && cargo run --release";

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
    /// `Some` to animate that many frames.
    frames: Option<u32>,
    png_dir: Option<PathBuf>,
    apng: Option<PathBuf>,
    /// `Some` to draw in passes, each written to that directory.
    progressive: Option<PathBuf>,
    /// The first pass's spacing, if `--spacing` gave one.
    spacing: Option<u16>,
}

/// The most frames `--frames` takes: at 160 × 128, a few minutes of animation.
const MAX_FRAMES: u32 = 10_000;

/// The first pass's spacing without `--spacing`: its blocks are small enough to show the
/// scene's shapes, and it traces a 64th of the picture, so it comes quickly.
const FIRST_SPACING: u16 = 8;

/// `Ok(None)` means `--help`.
fn parse(args: impl IntoIterator<Item = String>) -> Result<Option<Options>, String> {
    let mut options = Options {
        scene: Which::Demo,
        png: None,
        cols: 160,
        rows: 128,
        format: Format::Rgb888,
        frames: None,
        png_dir: None,
        apng: None,
        progressive: None,
        spacing: None,
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
            "--frames" => {
                let text = value()?;
                let frames = text
                    .parse::<u32>()
                    .ok()
                    .filter(|n| (1..=MAX_FRAMES).contains(n))
                    .ok_or(format!(
                        "--frames wants a count of frames from 1 to {MAX_FRAMES}, not '{text}'"
                    ))?;
                options.frames = Some(frames);
            }
            "--png-dir" => options.png_dir = Some(PathBuf::from(value()?)),
            "--apng" => options.apng = Some(PathBuf::from(value()?)),
            "--progressive" => options.progressive = Some(PathBuf::from(value()?)),
            "--spacing" => {
                let text = value()?;
                // The library's own check, so that the example takes exactly what it does.
                let spacing = text
                    .parse::<u16>()
                    .ok()
                    .filter(|&s| Pass::sequence(s).is_ok())
                    .ok_or(format!(
                        "--spacing wants a power of two from 1 to {MAX_SPACING}, not '{text}'"
                    ))?;
                options.spacing = Some(spacing);
            }
            other => return Err(format!("unknown argument '{other}'")),
        }
    }
    // Each mode's outputs with the other's would be silently ignored: refuse them instead.
    if options.progressive.is_some() {
        if options.frames.is_some() {
            return Err("--progressive draws one picture in passes: not with --frames".into());
        }
        if options.png_dir.is_some() || options.apng.is_some() {
            return Err(
                "--progressive writes its passes to its own directory: not with --png-dir or --apng"
                    .into(),
            );
        }
        if options.png.is_some() {
            return Err("--progressive writes its passes to its directory: not with --png".into());
        }
    } else if options.spacing.is_some() {
        return Err(
            "--spacing chooses the first pass of --progressive: it needs --progressive DIR".into(),
        );
    }
    if options.frames.is_some() && options.png.is_some() {
        return Err("--png writes one picture: with --frames use --png-dir or --apng".into());
    }
    if options.frames.is_none() && (options.png_dir.is_some() || options.apng.is_some()) {
        return Err("--png-dir and --apng write an animation: they need --frames N".into());
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
    if let Some(frames) = options.frames {
        return animation::run(options, frames);
    }
    if let Some(dir) = &options.progressive {
        return progressive::run(options, dir);
    }
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

/// `--progressive`: the picture drawn in passes, coarse to fine, each one written.
mod progressive {
    use embedded_graphics::prelude::{Dimensions, PointsIter};

    use super::*;

    pub(super) fn run(options: &Options, dir: &Path) -> Result<(), String> {
        match options.format {
            Format::Rgb565 => passes::<Rgb565>(options, dir),
            Format::Rgb888 => passes::<Rgb888>(options, dir),
            Format::Gray8 => passes::<Gray8>(options, dir),
            Format::Binary => passes::<BinaryColor>(options, dir),
        }
    }

    /// How many pixels `pass` traces in a picture `cols × rows`: its columns in each row it
    /// traces, as [`Pass::columns`] gives them (counted, not traced again: `render_pass_row`
    /// would give the same count for a second trace of the row).
    fn traced(pass: Pass, cols: u32, rows: u32) -> u32 {
        (0..rows).map(|y| pass.columns(y).count_below(cols)).sum()
    }

    fn passes<C>(options: &Options, dir: &Path) -> Result<(), String>
    where
        C: FromRgb + From<BinaryColor> + Into<Rgb888> + PartialEq,
    {
        let (cols, rows) = (options.cols, options.rows);
        let spacing = options.spacing.unwrap_or(FIRST_SPACING);
        let sequence = Pass::sequence(spacing).map_err(|e| e.to_string())?;
        let camera = options
            .scene
            .camera(cols, rows)
            .map_err(|e| e.to_string())?;
        let scene = options.scene.scene();
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
        let shown_dir = std::path::absolute(dir).unwrap_or_else(|_| dir.to_path_buf());
        println!(
            "the {} scene, {cols}x{rows} {}, in passes from spacing {spacing} down to 1",
            options.scene.name(),
            options.format.name(),
        );

        let mut display = SimulatorDisplay::<C>::new(camera.size());
        let view = Viewport::at(&scene, &camera, Point::zero());
        let mut line = vec![Rgb::BLACK; cols as usize];
        let screen = cols * rows;
        let mut count = 0;
        for (number, pass) in (1u32..).zip(sequence) {
            let start = Instant::now();
            view.render_pass(pass, &mut line, &mut display)
                .map_err(|e| e.to_string())?;
            let took = start.elapsed();
            // Written as --png writes its picture.
            let path = dir.join(format!("pass-{number}.png"));
            display
                .to_rgb_output_image(&OutputSettings::default())
                .save_png(&path)
                .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
            let pixels = traced(pass, cols, rows);
            println!(
                "pass {number}: spacing {:2}, traced {pixels:7} px ({:5.1} % of the picture) \
                 in {:.2} ms, wrote {}",
                pass.spacing(),
                100.0 * f64::from(pixels) / f64::from(screen),
                took.as_secs_f64() * 1e3,
                shown_dir
                    .join(path.file_name().unwrap_or_default())
                    .display(),
            );
            count = number;
        }

        // The promise of the passes: together they draw what one plain render draws.
        let (full, _) = render::<C>(&scene, &camera).map_err(|e| e.to_string())?;
        if full != display {
            let wrong = display
                .bounding_box()
                .points()
                .filter(|&p| display.get_pixel(p) != full.get_pixel(p))
                .count();
            return Err(format!(
                "after the last pass the picture differs from a plain render in {wrong} pixels"
            ));
        }
        let files = match count {
            1 => "1 PNG file, pass-1.png,".to_string(),
            _ => format!("{count} PNG files, pass-1.png to pass-{count}.png,"),
        };
        println!(
            "wrote {files} in {}; the last equals a plain render",
            shown_dir.display()
        );
        Ok(())
    }
}

/// `--frames`: the scene edited between frames and redrawn where [`Damage`] says it may have
/// changed.
mod animation {
    use std::f32::consts::TAU;
    use std::fs::File;
    use std::io::BufWriter;

    use embedded_graphics::draw_target::DrawTarget;
    use embedded_graphics::prelude::{Dimensions, PointsIter, Size};
    use embedded_graphics::primitives::Rectangle;
    use fixray::{Damage, Fx, Light, Shape, Sphere, Vec3, render_row_span};

    use super::*;

    /// The bouncing ball's colour: brighter than anything else in the demo.
    const BALL: Rgb = Rgb::new(255, 200, 0);
    /// Bounces in one cycle, there and back.
    const BOUNCES: f32 = 4.0;
    /// How high the ball's bottom rises above the floor, in world units.
    const HEIGHT: f32 = 1.6;
    /// The frame rate the animated PNG plays at.
    const APNG_FPS: u16 = 24;

    /// Up to this many pixels every frame is compared with a full render; above, the last.
    const CHECK_ALL_UP_TO: u32 = 320 * 240;

    /// A scene and what moves in it.
    struct Motion {
        which: Which,
        scene: Scene<8>,
        /// The ball's index among the demo's objects.
        ball: usize,
    }

    impl Motion {
        fn new(which: Which) -> Result<Self, fixray::Error> {
            let mut scene = which.scene();
            // The demo has five objects and room for eight: the ball is one more.
            let ball = match which {
                Which::Demo => scene.add_sphere(ball_at(0.0)?, BALL)?,
                Which::Classic => 0,
            };
            let mut motion = Motion { which, scene, ball };
            motion.pose(0.0)?;
            Ok(motion)
        }

        /// Sets the scene as it is at `t` of the way through the cycle (0 to 1, the end
        /// meeting the start, so that a looping animation has no jump).
        fn pose(&mut self, t: f32) -> Result<(), fixray::Error> {
            match self.which {
                Which::Demo => self.scene.set_shape(self.ball, Shape::Sphere(ball_at(t)?)),
                Which::Classic => {
                    // Light 0 starts at (−20, 20, 20), and circles the y axis at that height
                    // and distance, keeping its intensity.
                    let start = demo::classic().lights()[0];
                    let radius = 800.0f32.sqrt();
                    let angle = 20.0f32.atan2(-20.0) + TAU * t;
                    let at = Vec3::new(
                        Fx::from_num(radius * angle.cos()),
                        start.position().y,
                        Fx::from_num(radius * angle.sin()),
                    );
                    self.scene
                        .set_light(0, Light::from_fx(at, start.intensity())?)
                }
            }
        }
    }

    /// The demo's ball at `t` of the cycle: it crosses the view in front of the other
    /// spheres (z = −8, never meeting them) and back, bouncing on the floor (y = −4) on
    /// parabolas, as under gravity.
    fn ball_at(t: f32) -> Result<Sphere, fixray::Error> {
        let across = 1.0 - (2.0 * t - 1.0).abs();
        let hop = (BOUNCES * t).fract();
        let x = -4.5 + 9.0 * across;
        let y = -3.0 + HEIGHT * 4.0 * hop * (1.0 - hop);
        Sphere::new([x, y, -8.0], 1.0)
    }

    /// Redraws the pixels of `damage` on `display`, row span by row span, as a driver would
    /// send them: a window of the row's span, then its pixels.
    fn redraw<C: FromRgb>(
        scene: &Scene<8>,
        camera: &Camera,
        damage: &Damage,
        line: &mut [Rgb],
        display: &mut SimulatorDisplay<C>,
    ) -> Result<(), DrawError<Infallible>> {
        // The whole screen (a moved light, a mirror in the scene): the plain row-by-row path.
        if damage.is_whole() {
            return Viewport::at(scene, camera, Point::zero()).render(line, display);
        }
        for y in 0..camera.height() {
            let Some(span) = damage.row_span(y) else {
                continue;
            };
            // The span lies within the row, and the row buffer is a row long.
            let Some(out) = line.get_mut(..span.len()) else {
                continue;
            };
            render_row_span(scene, camera, y, span.clone(), out)?;
            // Rows and columns are at most 4096: they fit i32.
            let area = Rectangle::new(
                Point::new(span.start as i32, y as i32),
                Size::new(span.len() as u32, 1),
            );
            let colours = (span.start..)
                .zip(out.iter())
                .map(|(x, &colour)| C::from_rgb(colour, Point::new(x as i32, y as i32)));
            let Ok(()) = display.fill_contiguous(&area, colours);
        }
        Ok(())
    }

    /// The display as RGB888 bytes, row by row: what a PNG holds.
    fn bytes<C: PixelColor + Into<Rgb888>>(display: &SimulatorDisplay<C>) -> Vec<u8> {
        use embedded_graphics::pixelcolor::RgbColor;
        display
            .bounding_box()
            .points()
            .flat_map(|p| {
                let c: Rgb888 = display.get_pixel(p).into();
                [c.r(), c.g(), c.b()]
            })
            .collect()
    }

    /// How many pixels differ between two pictures `cols` wide, and the smallest rectangle
    /// holding them (`None` if none does): left, top, width, height.
    fn changes(before: &[u8], after: &[u8], cols: u32) -> (u32, Option<[u32; 4]>) {
        let mut count = 0;
        let (mut min, mut max) = ([u32::MAX; 2], [0u32; 2]);
        for (i, (a, b)) in (0u32..).zip(before.chunks_exact(3).zip(after.chunks_exact(3))) {
            if a != b {
                count += 1;
                let (x, y) = (i % cols, i / cols);
                min = [min[0].min(x), min[1].min(y)];
                max = [max[0].max(x), max[1].max(y)];
            }
        }
        let area = (count > 0).then(|| [min[0], min[1], max[0] - min[0] + 1, max[1] - min[1] + 1]);
        (count, area)
    }

    /// An animated PNG being written: the first frame whole, each next one only the
    /// rectangle that changed, drawn over the last (so the file grows with the motion, not
    /// with the screen).
    struct Apng {
        writer: png::Writer<BufWriter<File>>,
        path: PathBuf,
    }

    impl Apng {
        fn create(path: &Path, cols: u32, rows: u32, frames: u32) -> Result<Self, String> {
            let fail = |e: &dyn std::fmt::Display| format!("cannot write {}: {e}", path.display());
            create_parent(path)?;
            let file = File::create(path).map_err(|e| fail(&e))?;
            let mut encoder = png::Encoder::new(BufWriter::new(file), cols, rows);
            encoder.set_color(png::ColorType::Rgb);
            encoder.set_depth(png::BitDepth::Eight);
            // Written once and shown often (the README's animation): worth the slower encoding.
            encoder.set_compression(png::Compression::High);
            encoder.set_animated(frames, 0).map_err(|e| fail(&e))?;
            encoder.set_frame_delay(1, APNG_FPS).map_err(|e| fail(&e))?;
            encoder
                .set_dispose_op(png::DisposeOp::None)
                .map_err(|e| fail(&e))?;
            encoder
                .set_blend_op(png::BlendOp::Source)
                .map_err(|e| fail(&e))?;
            let writer = encoder.write_header().map_err(|e| fail(&e))?;
            Ok(Apng {
                writer,
                path: path.to_path_buf(),
            })
        }

        /// Adds a frame: `picture` whole for the first, and its rectangle `[x, y, w, h]`
        /// after (a frame that changes nothing still takes one pixel: APNG has no empty
        /// frame).
        fn frame(
            &mut self,
            picture: &[u8],
            cols: u32,
            area: Option<[u32; 4]>,
        ) -> Result<(), String> {
            let [x, y, w, h] = area.unwrap_or([0, 0, 1, 1]);
            let mut part = Vec::with_capacity((w * h * 3) as usize);
            for row in y..y + h {
                let start = ((row * cols + x) * 3) as usize;
                part.extend_from_slice(
                    picture
                        .get(start..start + (w * 3) as usize)
                        .unwrap_or_default(),
                );
            }
            let path = &self.path;
            let fail = |e: png::EncodingError| format!("cannot write {}: {e}", path.display());
            // The position goes to the corner first, so that the new size always fits.
            self.writer.reset_frame_position().map_err(fail)?;
            self.writer.set_frame_dimension(w, h).map_err(fail)?;
            self.writer.set_frame_position(x, y).map_err(fail)?;
            self.writer.write_image_data(&part).map_err(fail)
        }

        fn finish(self) -> Result<(), String> {
            let path = self.path;
            self.writer
                .finish()
                .map_err(|e| format!("cannot write {}: {e}", path.display()))
        }
    }

    fn create_parent(path: &Path) -> Result<(), String> {
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir)
                .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
        }
        Ok(())
    }

    pub(super) fn run(options: &Options, frames: u32) -> Result<(), String> {
        match options.format {
            Format::Rgb565 => animate::<Rgb565>(options, frames),
            Format::Rgb888 => animate::<Rgb888>(options, frames),
            Format::Gray8 => animate::<Gray8>(options, frames),
            Format::Binary => animate::<BinaryColor>(options, frames),
        }
    }

    fn ms(d: Duration) -> f64 {
        d.as_secs_f64() * 1e3
    }

    /// The median of `times`, in seconds (0 for none).
    fn median(times: &mut [Duration]) -> f64 {
        times.sort_unstable();
        times
            .get(times.len() / 2)
            .map_or(0.0, |middle| middle.as_secs_f64())
    }

    fn animate<C>(options: &Options, frames: u32) -> Result<(), String>
    where
        C: FromRgb + From<BinaryColor> + Into<Rgb888> + PartialEq,
    {
        let (cols, rows) = (options.cols, options.rows);
        let camera = options
            .scene
            .camera(cols, rows)
            .map_err(|e| e.to_string())?;
        let mut motion = Motion::new(options.scene).map_err(|e| e.to_string())?;
        let default = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/out/frames"));
        let dir = options.png_dir.as_deref().unwrap_or(default);
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
        let mut apng = match &options.apng {
            Some(path) => Some(Apng::create(path, cols, rows, frames)?),
            None => None,
        };
        let screen = cols * rows;
        let check_all = screen <= CHECK_ALL_UP_TO;
        println!(
            "{} frames of the {} scene, {cols}x{rows} {}: frame 0 in full, then only the damage{}",
            frames,
            options.scene.name(),
            options.format.name(),
            if check_all {
                ", each checked against a full render"
            } else {
                "; the last checked against a full render"
            }
        );

        // Frame 0: the whole picture, row by row.
        let (mut display, first) =
            render::<C>(&motion.scene, &camera).map_err(|e| e.to_string())?;
        let mut picture = bytes(&display);
        let save = |index: u32, display: &SimulatorDisplay<C>| {
            let path = dir.join(format!("frame-{index:03}.png"));
            display
                .to_rgb_output_image(&OutputSettings::default())
                .save_png(&path)
                .map_err(|e| format!("cannot write {}: {e}", path.display()))
        };
        save(0, &display)?;
        if let Some(apng) = &mut apng {
            apng.frame(&picture, cols, Some([0, 0, cols, rows]))?;
        }
        println!("frame   0: full render {:.2} ms", ms(first));

        let mut line = vec![Rgb::BLACK; cols as usize];
        let (mut damaged, mut changed) = (0u64, 0u64);
        // Times of each redraw and each checking full render, for their medians: a single
        // frame's time jumps with whatever else the machine is doing.
        let (mut redraws, mut fulls) = (Vec::new(), Vec::new());
        for index in 1..frames {
            let before = motion.scene.clone();
            motion
                .pose(index as f32 / frames as f32)
                .map_err(|e| e.to_string())?;
            let start = Instant::now();
            let damage = Damage::between(&before, &motion.scene, &camera);
            let bounded = start.elapsed();
            redraw(&motion.scene, &camera, &damage, &mut line, &mut display)
                .map_err(|e| e.to_string())?;
            let took = start.elapsed();
            redraws.push(took);

            let next = bytes(&display);
            let (count, area) = changes(&picture, &next, cols);
            picture = next;
            let region = damage.pixel_count();
            damaged += u64::from(region);
            changed += u64::from(count);

            let mut full_note = String::new();
            if check_all || index == frames - 1 {
                let (full, full_took) =
                    render::<C>(&motion.scene, &camera).map_err(|e| e.to_string())?;
                if full != display {
                    let wrong = changes(&bytes(&full), &picture, cols).0;
                    return Err(format!(
                        "frame {index}: the redrawn frame differs from a full render in {wrong} \
                         pixels: the damage missed a change"
                    ));
                }
                fulls.push(full_took);
                full_note = format!(", full render {:.2} ms", ms(full_took));
            }
            save(index, &display)?;
            if let Some(apng) = &mut apng {
                apng.frame(&picture, cols, area)?;
            }
            println!(
                "frame {index:3}: damage {region:6} px ({:5.1} %, {}), changed {count:6} px, \
                 redraw {:.2} ms (damage {:.3} ms){full_note}",
                100.0 * f64::from(region) / f64::from(screen),
                if damage.is_whole() {
                    "the whole screen".into()
                } else {
                    format!("{} rectangles", damage.rectangles().count())
                },
                ms(took),
                ms(bounded),
            );
        }

        if frames > 1 {
            let redrawn = f64::from(frames - 1);
            let (redraw, full) = (median(&mut redraws), median(&mut fulls));
            println!(
                "frames 1 to {}: damage {:.1} % of the screen on average, {:.0} px a frame, \
                 {:.0} px a frame changed ({:.1} % of the damage)",
                frames - 1,
                100.0 * damaged as f64 / (redrawn * f64::from(screen)),
                damaged as f64 / redrawn,
                changed as f64 / redrawn,
                100.0 * changed as f64 / (damaged as f64).max(1.0),
            );
            println!(
                "median redraw {:.2} ms a frame ({:.0} frames/s) against a full render's {:.2} ms \
                 ({:.0} frames/s): {:.1} times as fast; frames checked equal to a full render: {}",
                redraw * 1e3,
                1.0 / redraw,
                full * 1e3,
                1.0 / full,
                full / redraw,
                fulls.len(),
            );
        }
        let shown = std::path::absolute(dir).unwrap_or_else(|_| dir.to_path_buf());
        println!(
            "wrote {frames} PNG files, frame-000.png to frame-{:03}.png, in {}",
            frames - 1,
            shown.display()
        );
        if let Some(apng) = apng {
            let path = apng.path.clone();
            apng.finish()?;
            let size = std::fs::metadata(&path).map(|m| m.len()).unwrap_or(0);
            println!(
                "wrote the animation, {frames} frames at {APNG_FPS} frames/s, {:.1} KB, to {}",
                size as f64 / 1024.0,
                std::path::absolute(&path).unwrap_or(path).display()
            );
        }
        Ok(())
    }
}
