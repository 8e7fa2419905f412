//! fixray in embedded-graphics-simulator's window: the demo scene (or the classic one) drawn
//! row by row into a simulator display, exactly as on a microcontroller, and shown in the
//! simulator's SDL window.
//!
//! ```text
//! cd window && cargo run --release                       # the demo, 160 × 128
//! cd window && cargo run --release -- --scene classic --size 320x240
//! cd window && cargo run --release -- --animate          # a ball bouncing on the floor
//! ```
//!
//! The arrow keys orbit the camera around the scene, `+` and `-` zoom (the field of view),
//! `A` starts and stops the animation, Escape or closing the window quits. Each change of the
//! view re-renders; the render time is written under the picture and printed to the terminal.
//!
//! The animation edits the scene between frames, as a program on a microcontroller would: a
//! ball bounces across the floor in front of the spheres, and each frame redraws only the
//! pixels [`Damage::between`] the scene before and after can change (the ball where it was and
//! is, and its shadows), span by span with [`render_row_span`]. On the classic scene, whose
//! mirror and glass can show the ball anywhere, the damage is the whole screen. Once a second
//! the frame rate, the damage and the redraw time are written under the picture and printed.
//!
//! Needs SDL2 (Debian: `libsdl2-dev`).

use std::process::ExitCode;
use std::time::{Duration, Instant};

use embedded_graphics::mono_font::MonoTextStyle;
use embedded_graphics::mono_font::ascii::FONT_6X10;
use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use embedded_graphics::text::{Baseline, Text};
use embedded_graphics_simulator::sdl2::Keycode;
use embedded_graphics_simulator::{
    OutputSettingsBuilder, SimulatorDisplay, SimulatorEvent, Window,
};
use fixray::{
    Camera, Damage, MAX_PIXELS, Rgb, Scene, Shape, Sphere, Viewport, demo, render_row_span,
};

const USAGE: &str = "\
usage: fixray-window [--scene demo|classic] [--size WxH] [--animate]

  --scene S     demo (default): matte spheres, one light; classic: tinyraytracer's scene with
                three lights, highlights, shadows, mirrors and a checkerboard floor
  --size WxH    picture size in pixels, 1 to 1024 a side (default: 160x128)
  --animate     start with the animation running: a ball bouncing on the floor, each frame
                redrawn only where it can change; frames per second printed once a second
  --help        this text

In the window: arrow keys orbit, + and - zoom, A starts and stops the animation, Escape quits.";

/// The widest picture: the row buffer's length. Wider is slow to watch anyway.
const MAX_COLS: usize = 1024;

/// Height of the status line under the picture: one line of the 6 × 10 font.
const STATUS: u32 = 12;

/// The camera orbits this point, the middle of the demo's spheres, at a fixed distance; from
/// azimuth 0 and elevation 0 it sees what the demo camera sees.
const TARGET: [f32; 3] = [0.0, 0.0, -15.0];
const DISTANCE: f32 = 15.0;

/// Where the camera is: angles in degrees.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Orbit {
    azimuth: f32,
    elevation: f32,
    fov: f32,
}

impl Orbit {
    fn camera(&self, cols: u32, rows: u32) -> Result<Camera, fixray::Error> {
        Camera::orbit(TARGET, DISTANCE)
            .yaw_degrees(self.azimuth)
            .pitch_degrees(self.elevation)
            .fov_degrees(self.fov)
            .size(Size::new(cols, rows))
            .build()
    }

    /// The orbit after `key`.
    fn key(self, key: Keycode) -> Orbit {
        let mut next = self;
        match key {
            Keycode::LEFT => next.azimuth -= 10.0,
            Keycode::RIGHT => next.azimuth += 10.0,
            // Above −10° the eye stays over the ground (y = −4); below 80° `up` is never
            // parallel to the view.
            Keycode::UP => next.elevation = (self.elevation + 5.0).min(80.0),
            Keycode::DOWN => next.elevation = (self.elevation - 5.0).max(-10.0),
            Keycode::PLUS | Keycode::KP_PLUS | Keycode::EQUALS => {
                next.fov = (self.fov / 1.25).max(10.0)
            }
            Keycode::MINUS | Keycode::KP_MINUS => next.fov = (self.fov * 1.25).min(120.0),
            _ => {}
        }
        next
    }
}

/// The bouncing ball's colour: brighter than anything else in the demo.
const BALL: Rgb = Rgb::new(255, 200, 0);

/// The most frames a second the window shows: `Window::update` waits out the rest of each.
const MAX_FPS: u32 = 60;

/// Seconds the ball takes across the view and back.
const CYCLE: f32 = 4.0;

/// The ball at `t` of its cycle (0 to 1): across the view and back, bouncing four times on
/// the floor (y = −4) on parabolas, as under gravity. On the demo's endless floor it passes
/// in front of the spheres (z = −8); the classic floor ends at z = −10, so there it passes
/// behind them (z = −22), over the checkerboard. Neither path meets a sphere.
fn ball_at(t: f32, classic: bool) -> Result<Sphere, fixray::Error> {
    let (z, reach) = if classic { (-22.0, 6.0) } else { (-8.0, 4.5) };
    let across = 1.0 - (2.0 * t - 1.0).abs();
    let hop = (4.0 * t).fract();
    let x = reach * (2.0 * across - 1.0);
    let y = -3.0 + 1.6 * 4.0 * hop * (1.0 - hop);
    Sphere::new([x, y, z], 1.0)
}

/// The animation's counts since they were last reported.
#[derive(Debug, Default)]
struct Tally {
    frames: u32,
    /// Pixels redrawn, over all frames.
    damaged: u64,
    /// Time spent working out the damage and redrawing it.
    redraw: Duration,
}

/// What the command line asked for.
struct Options {
    classic: bool,
    cols: u32,
    rows: u32,
    animate: bool,
}

/// `Ok(None)` means `--help`.
fn parse(args: impl IntoIterator<Item = String>) -> Result<Option<Options>, String> {
    let mut options = Options {
        classic: false,
        cols: 160,
        rows: 128,
        animate: false,
    };
    let mut args = args.into_iter();
    while let Some(arg) = args.next() {
        let (flag, inline) = match arg.split_once('=') {
            Some((flag, value)) if flag.starts_with("--") => (flag.to_string(), Some(value.into())),
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
            "--animate" if inline.is_none() => options.animate = true,
            "--animate" => return Err("--animate takes no value".into()),
            "--scene" => {
                options.classic = match value()?.as_str() {
                    "demo" => false,
                    "classic" => true,
                    other => return Err(format!("unknown scene '{other}': use demo or classic")),
                }
            }
            "--size" => {
                let text = value()?;
                let bad = || format!("--size wants WIDTHxHEIGHT, 1 to 1024 a side, not '{text}'");
                let (w, h) = text.split_once(['x', 'X']).ok_or_else(bad)?;
                let side = |s: &str| {
                    s.parse::<u32>()
                        .ok()
                        .filter(|&n| n >= 1 && n as usize <= MAX_COLS && n <= MAX_PIXELS)
                };
                options.cols = side(w).ok_or_else(bad)?;
                options.rows = side(h).ok_or_else(bad)?;
            }
            other => return Err(format!("unknown argument '{other}'")),
        }
    }
    Ok(Some(options))
}

/// Renders the whole picture onto the top of `display` and returns the time it took.
fn full(
    scene: &Scene<8>,
    camera: &Camera,
    display: &mut SimulatorDisplay<Rgb888>,
) -> Result<Duration, String> {
    let picture = Viewport::at(scene, camera, Point::zero())
        .picture::<Rgb888, MAX_COLS>()
        .map_err(|e| e.to_string())?;
    let start = Instant::now();
    // The simulator display cannot fail: its error type is `Infallible`.
    let Ok(()) = picture.draw(display);
    Ok(start.elapsed())
}

/// Redraws the pixels of `damage` on the top of `display`, one row span at a time, as a
/// driver would send them to a display: a window of the span, then its pixels.
fn redraw(
    scene: &Scene<8>,
    camera: &Camera,
    damage: &Damage,
    line: &mut [Rgb],
    display: &mut SimulatorDisplay<Rgb888>,
) -> Result<(), String> {
    if damage.is_whole() {
        // A moved light, or a mirror that may show the ball anywhere: the plain path.
        return full(scene, camera, display).map(|_| ());
    }
    for y in 0..camera.height() {
        let Some(span) = damage.row_span(y) else {
            continue;
        };
        // The span lies within the row, and the buffer is a row long.
        let Some(out) = line.get_mut(..span.len()) else {
            continue;
        };
        render_row_span(scene, camera, y, span.clone(), out).map_err(|e| e.to_string())?;
        // Rows and columns are at most 1024: they fit i32.
        let area = Rectangle::new(
            Point::new(span.start as i32, y as i32),
            Size::new(span.len() as u32, 1),
        );
        let Ok(()) = display.fill_contiguous(&area, out.iter().map(|&c| Rgb888::from(c)));
    }
    Ok(())
}

/// Writes `text` on the status line under the picture, and prints `long` (or `text`).
fn status(
    text: &str,
    long: Option<&str>,
    options: &Options,
    display: &mut SimulatorDisplay<Rgb888>,
) {
    // At most 4096 rows (parse keeps them so): the row fits i32.
    let line = Point::new(1, options.rows as i32 + 1);
    let under = Rectangle::new(
        Point::new(0, options.rows as i32),
        Size::new(options.cols, STATUS),
    );
    let Ok(()) = display.fill_solid(&under, Rgb888::BLACK);
    let style = MonoTextStyle::new(&FONT_6X10, Rgb888::WHITE);
    let Ok(_) = Text::with_baseline(text, line, style, Baseline::Top).draw(display);
    println!("{}", long.unwrap_or(text));
}

/// Renders the whole picture, and writes the time it took and the view under it.
fn frame(
    scene: &Scene<8>,
    orbit: Orbit,
    options: &Options,
    display: &mut SimulatorDisplay<Rgb888>,
) -> Result<Camera, String> {
    let camera = orbit
        .camera(options.cols, options.rows)
        .map_err(|e| e.to_string())?;
    let took = full(scene, &camera, display)?;
    let text = format!(
        "{:.1} ms  az {:.0} el {:.0} fov {:.0}",
        took.as_secs_f64() * 1e3,
        orbit.azimuth,
        orbit.elevation,
        orbit.fov
    );
    status(&text, None, options, display);
    Ok(camera)
}

fn run(options: &Options) -> Result<(), String> {
    let mut scene = if options.classic {
        demo::classic()
    } else {
        demo::scene()
    };
    let (cols, rows) = (options.cols, options.rows);
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(cols, rows + STATUS));
    let scale = (640 / cols).min(480 / rows).clamp(1, 8);
    let mut window = Window::new(
        "fixray: arrows orbit, +/- zoom, A animates, Esc quits",
        &OutputSettingsBuilder::new().scale(scale).build(),
    );
    window.set_max_fps(MAX_FPS);
    let mut orbit = Orbit {
        azimuth: 0.0,
        elevation: 0.0,
        fov: 60.0,
    };
    // The ball joins the scene (both scenes have room) when the animation first starts: until
    // then the scene is the one the still pictures show.
    let mut ball = None;
    let mut animating = false;
    // Where the ball is in its cycle, kept while the animation is stopped.
    let mut phase = 0.0f32;
    let mut last = Instant::now();
    let mut tally = Tally::default();
    let mut reported = Instant::now();
    let mut line = vec![Rgb::BLACK; cols as usize];
    let mut camera = frame(&scene, orbit, options, &mut display)?;
    let mut toggle = options.animate;
    loop {
        if toggle {
            toggle = false;
            animating = !animating;
            if animating && ball.is_none() {
                let index = scene
                    .add_sphere(
                        ball_at(phase, options.classic).map_err(|e| e.to_string())?,
                        BALL,
                    )
                    .map_err(|e| e.to_string())?;
                ball = Some(index);
                camera = frame(&scene, orbit, options, &mut display)?;
            }
            (last, reported, tally) = (Instant::now(), Instant::now(), Tally::default());
            println!(
                "animation {}",
                if animating { "on: A stops it" } else { "off" }
            );
        }
        if let (true, Some(index)) = (animating, ball) {
            let now = Instant::now();
            phase = (phase + (now - last).as_secs_f32() / CYCLE).fract();
            last = now;
            let before = scene.clone();
            let start = Instant::now();
            scene
                .set_shape(
                    index,
                    Shape::Sphere(ball_at(phase, options.classic).map_err(|e| e.to_string())?),
                )
                .map_err(|e| e.to_string())?;
            let damage = Damage::between(&before, &scene, &camera);
            redraw(&scene, &camera, &damage, &mut line, &mut display)?;
            tally.redraw += start.elapsed();
            tally.frames += 1;
            tally.damaged += u64::from(damage.pixel_count());
            let since = reported.elapsed();
            if since >= Duration::from_secs(1) {
                let frames = f64::from(tally.frames.max(1));
                let fps = f64::from(tally.frames) / since.as_secs_f64();
                let damage = 100.0 * tally.damaged as f64 / (frames * f64::from(cols * rows));
                let redraw = tally.redraw.as_secs_f64() / frames;
                // Short enough for the status line of a 160-pixel picture.
                let text = format!("{fps:.0} fps dmg {damage:.1}% {:.2} ms", redraw * 1e3);
                let long = format!(
                    "{fps:.0} frames/s (the window shows at most {MAX_FPS}); damage {damage:.1} % \
                     of the screen a frame; redraw {:.2} ms a frame (damage and pixels), \
                     {:.0} frames/s without the window's limit",
                    redraw * 1e3,
                    1.0 / redraw.max(1e-9),
                );
                status(&text, Some(&long), options, &mut display);
                (reported, tally) = (Instant::now(), Tally::default());
            }
        }
        // Shows the display and waits out the rest of a `MAX_FPS`th of a second.
        window.update(&display);
        let mut next = orbit;
        for event in window.events() {
            match event {
                SimulatorEvent::Quit
                | SimulatorEvent::KeyDown {
                    keycode: Keycode::ESCAPE,
                    ..
                } => return Ok(()),
                SimulatorEvent::KeyDown {
                    keycode: Keycode::A,
                    repeat: false,
                    ..
                } => toggle = true,
                SimulatorEvent::KeyDown { keycode, .. } => next = next.key(keycode),
                _ => {}
            }
        }
        if next != orbit {
            orbit = next;
            camera = frame(&scene, orbit, options, &mut display)?;
        }
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
                eprintln!("fixray-window: {message}");
                ExitCode::FAILURE
            }
        },
        Err(message) => {
            eprintln!("fixray-window: {message} (see --help)");
            ExitCode::from(2)
        }
    }
}
