//! fixray in embedded-graphics-simulator's window: the demo scene (or the classic one) drawn
//! row by row into a simulator display, exactly as on a microcontroller, and shown in the
//! simulator's SDL window.
//!
//! ```text
//! cd window && cargo run --release                       # the demo, 160 × 128
//! cd window && cargo run --release -- --scene classic --size 320x240
//! ```
//!
//! The arrow keys orbit the camera around the scene, `+` and `-` zoom (the field of view),
//! Escape or closing the window quits. Each change re-renders; the render time is written
//! under the picture and printed to the terminal. Needs SDL2 (Debian: `libsdl2-dev`).

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
use fixray::{Camera, MAX_PIXELS, Scene, Viewport, demo};

const USAGE: &str = "\
usage: fixray-window [--scene demo|classic] [--size WxH]

  --scene S     demo (default): matte spheres, one light; classic: tinyraytracer's scene with
                three lights, highlights, shadows, mirrors and a checkerboard floor
  --size WxH    picture size in pixels, 1 to 1024 a side (default: 160x128)
  --help        this text

In the window: arrow keys orbit, + and - zoom, Escape quits.";

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

/// What the command line asked for.
struct Options {
    classic: bool,
    cols: u32,
    rows: u32,
}

/// `Ok(None)` means `--help`.
fn parse(args: impl IntoIterator<Item = String>) -> Result<Option<Options>, String> {
    let mut options = Options {
        classic: false,
        cols: 160,
        rows: 128,
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

/// Renders the picture onto the top of `display` and writes the time it took, and the view,
/// on the status line below it.
fn frame(
    scene: &Scene<8>,
    orbit: Orbit,
    options: &Options,
    display: &mut SimulatorDisplay<Rgb888>,
) -> Result<Duration, String> {
    let camera = orbit
        .camera(options.cols, options.rows)
        .map_err(|e| e.to_string())?;
    let picture = Viewport::at(scene, &camera, Point::zero())
        .picture::<Rgb888, MAX_COLS>()
        .map_err(|e| e.to_string())?;
    let start = Instant::now();
    // The simulator display cannot fail: its error type is `Infallible`.
    let Ok(()) = picture.draw(display);
    let took = start.elapsed();

    let status = format!(
        "{:.1} ms  az {:.0} el {:.0} fov {:.0}",
        took.as_secs_f64() * 1e3,
        orbit.azimuth,
        orbit.elevation,
        orbit.fov
    );
    // At most 4096 rows (parse keeps them so): the row fits i32.
    let line = Point::new(1, options.rows as i32 + 1);
    let under = Rectangle::new(
        Point::new(0, options.rows as i32),
        Size::new(options.cols, STATUS),
    );
    let Ok(()) = display.fill_solid(&under, Rgb888::BLACK);
    let style = MonoTextStyle::new(&FONT_6X10, Rgb888::WHITE);
    let Ok(_) = Text::with_baseline(&status, line, style, Baseline::Top).draw(display);
    println!("{status}");
    Ok(took)
}

fn run(options: &Options) -> Result<(), String> {
    let scene = if options.classic {
        demo::classic()
    } else {
        demo::scene()
    };
    let (cols, rows) = (options.cols, options.rows);
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(cols, rows + STATUS));
    let scale = (640 / cols).min(480 / rows).clamp(1, 8);
    let mut window = Window::new(
        "fixray: arrows orbit, +/- zoom, Esc quits",
        &OutputSettingsBuilder::new().scale(scale).build(),
    );
    let mut orbit = Orbit {
        azimuth: 0.0,
        elevation: 0.0,
        fov: 60.0,
    };
    frame(&scene, orbit, options, &mut display)?;
    loop {
        // Shows the display and waits out the rest of a 60th of a second.
        window.update(&display);
        let mut next = orbit;
        for event in window.events() {
            match event {
                SimulatorEvent::Quit
                | SimulatorEvent::KeyDown {
                    keycode: Keycode::ESCAPE,
                    ..
                } => return Ok(()),
                SimulatorEvent::KeyDown { keycode, .. } => next = next.key(keycode),
                _ => {}
            }
        }
        if next != orbit {
            orbit = next;
            frame(&scene, orbit, options, &mut display)?;
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
