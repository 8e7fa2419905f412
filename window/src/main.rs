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
//! `A` starts and stops the animation, Escape or closing the window quits.
//!
//! Each change of the view is drawn in progressive passes ([`Pass::sequence`]): first the
//! whole picture in 8 × 8 blocks, one pixel traced in 64, so that the view follows the keys
//! while one is held; then, once no key is held, the finer passes (the grid of 4, the even
//! rows, the odd rows) a band of rows at a time with [`Viewport::render_pass_rows`], the keys
//! read between frames, so that a key
//! pressed before the picture is complete abandons it for the new view's blocks. The time to
//! the first picture, and once refined the time all its passes took, are written under the
//! picture and printed to the terminal with the view.
//!
//! The animation edits the scene between frames, as a program on a microcontroller would: a
//! ball bounces across the floor in front of the spheres, and each frame redraws only the
//! pixels [`Damage::between`] the scene before and after can change (the ball where it was and
//! is, and its shadows), span by span with [`render_row_span`]. On the classic scene, whose
//! mirror and glass can show the ball anywhere, the damage is the whole screen. Once a second
//! the frame rate, the damage and the redraw time are written under the picture and printed.
//! While the animation runs, a change of the view is drawn whole at once, as the damage of the
//! next frame is worked out against a complete picture.
//!
//! Needs SDL2 (Debian: `libsdl2-dev`).

use std::ops::Range;
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
    Camera, Damage, MAX_PIXELS, Pass, Passes, Rgb, Scene, Shape, Sphere, Viewport, demo,
    render_row_span,
};

const USAGE: &str = "\
usage: fixray-window [--scene demo|classic] [--size WxH] [--animate]

  --scene S     demo (default): matte spheres, one light; classic: tinyraytracer's scene with
                three lights, highlights, shadows, mirrors and a checkerboard floor
  --size WxH    picture size in pixels, 1 to 1024 a side (default: 160x128)
  --animate     start with the animation running: a ball bouncing on the floor, each frame
                redrawn only where it can change; frames per second printed once a second
  --help        this text

In the window: arrow keys orbit, + and - zoom, A starts and stops the animation, Escape quits.
A new view is drawn in 8x8 blocks first, then refined (4x4, 2x2, single pixels) once no key is
held; under the picture: the time to the first picture, then the time all passes took.";

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

    /// Whether `key` is one of those [`key`](Self::key) moves the view with.
    fn steers(key: Keycode) -> bool {
        matches!(
            key,
            Keycode::LEFT
                | Keycode::RIGHT
                | Keycode::UP
                | Keycode::DOWN
                | Keycode::PLUS
                | Keycode::KP_PLUS
                | Keycode::EQUALS
                | Keycode::MINUS
                | Keycode::KP_MINUS
        )
    }
}

/// The keys that move the view and are down: while one is, the view is still changing, and
/// refining its picture would only be thrown away at the key's next repeat.
#[derive(Debug, Default)]
struct Held(Vec<Keycode>);

impl Held {
    fn press(&mut self, key: Keycode) {
        if Orbit::steers(key) && !self.0.contains(&key) {
            self.0.push(key);
        }
    }

    fn release(&mut self, key: Keycode) {
        self.0.retain(|&held| held != key);
    }

    /// Whether no key moves the view: it rests, and its picture can be refined.
    fn none(&self) -> bool {
        self.0.is_empty()
    }
}

/// The first pass's spacing: one pixel traced in 64, quick enough to follow a held key.
const COARSEST: u16 = 8;

/// Rows of a finer pass drawn in one go: a key pressed meanwhile waits for the band at most.
const BAND: u32 = 16;

/// What is left to draw of a view's picture: the first pass, then the finer ones a band of
/// rows at a time, so that a change of the view between bands abandons them.
#[derive(Debug, Clone)]
struct Progress {
    /// The passes after `pass`.
    passes: Passes,
    /// The pass being drawn; `None` once the picture is complete.
    pass: Option<Pass>,
    /// The first row of `pass` not drawn yet.
    row: u32,
    /// The picture's height.
    rows: u32,
}

impl Progress {
    /// A new view's picture, nothing of it drawn yet.
    fn new(rows: u32) -> Result<Progress, fixray::Error> {
        let mut passes = Pass::sequence(COARSEST)?;
        let pass = passes.next();
        Ok(Progress {
            passes,
            pass,
            row: 0,
            rows,
        })
    }

    /// The picture was drawn whole another way: nothing is left.
    fn finish(&mut self) {
        self.pass = None;
    }

    fn is_complete(&self) -> bool {
        self.pass.is_none()
    }

    /// The pass and the rows of it to draw next, marked drawn. The first pass comes
    /// whole, whether the view rests or not: the old view's picture is all there is otherwise.
    /// The finer passes come a band at a time, and only while the view `rests`: drawn while a
    /// key moves it, they would slow the blocks that follow the key.
    fn next_band(&mut self, rests: bool) -> Option<(Pass, Range<u32>)> {
        let pass = self.pass?;
        if !pass.is_first() && !rests {
            return None;
        }
        let end = if pass.is_first() {
            self.rows
        } else {
            self.row.saturating_add(BAND).min(self.rows)
        };
        let band = self.row..end;
        if end >= self.rows {
            self.pass = self.passes.next();
            self.row = 0;
        } else {
            self.row = end;
        }
        Some((pass, band))
    }
}

/// The longest the finer passes draw before the window shows them and the keys are read
/// again: a frame's time, so that refining delays a key by a frame at most (by a band, when
/// one band takes longer).
const BUDGET: Duration = Duration::from_micros(1_000_000 / MAX_FPS as u64);

/// The view on the screen and how far its picture has come.
struct View {
    orbit: Orbit,
    camera: Camera,
    progress: Progress,
    /// The time the first pass took: the first picture's.
    first: Duration,
    /// The time the passes drawn so far took, the first included; not the time between bands,
    /// which waits for the window's frames.
    spent: Duration,
}

impl View {
    /// The view from `orbit`, nothing of its picture drawn yet.
    fn new(orbit: Orbit, options: &Options) -> Result<View, String> {
        let camera = orbit
            .camera(options.cols, options.rows)
            .map_err(|e| e.to_string())?;
        Ok(View {
            orbit,
            camera,
            progress: Progress::new(options.rows).map_err(|e| e.to_string())?,
            first: Duration::ZERO,
            spent: Duration::ZERO,
        })
    }

    /// Draws the next of the picture onto the top of `display`: the first pass alone, so that
    /// the window shows it at once, or, while the view `rests`, bands of the finer passes for
    /// up to [`BUDGET`]. Writes the times under the picture after the first pass and the last.
    fn draw(
        &mut self,
        scene: &Scene<8>,
        rests: bool,
        line: &mut [Rgb],
        options: &Options,
        display: &mut SimulatorDisplay<Rgb888>,
    ) -> Result<(), String> {
        let view = Viewport::at(scene, &self.camera, Point::zero());
        let start = Instant::now();
        while let Some((pass, band)) = self.progress.next_band(rests) {
            let began = Instant::now();
            view.render_pass_rows(pass, band, line, display)
                .map_err(|e| e.to_string())?;
            let took = began.elapsed();
            self.spent += took;
            if pass.is_first() {
                self.first = took;
            }
            if pass.is_first() || self.progress.is_complete() {
                self.report(options, display);
                break;
            }
            if start.elapsed() >= BUDGET {
                break;
            }
        }
        Ok(())
    }

    /// Writes the time to the first picture under it, and once it is complete the time all
    /// passes took; the view too where the line has room. Prints them with the view.
    fn report(&self, options: &Options, display: &mut SimulatorDisplay<Rgb888>) {
        let first = self.first.as_secs_f64() * 1e3;
        let all = self.spent.as_secs_f64() * 1e3;
        let place = format!(
            "az {:.0} el {:.0} fov {:.0}",
            self.orbit.azimuth, self.orbit.elevation, self.orbit.fov
        );
        let (times, long) = if self.progress.is_complete() {
            (
                format!("first {first:.1} ms  all {all:.1} ms"),
                format!("{place}: refined, all passes {all:.1} ms (first picture {first:.1} ms)"),
            )
        } else {
            (
                format!("first {first:.1} ms"),
                format!("{place}: first picture {first:.1} ms, {COARSEST} x {COARSEST} blocks"),
            )
        };
        let text = format!("{times}  {place}");
        let text = if fits(&text, options.cols) {
            text
        } else {
            times
        };
        status(&text, Some(&long), options, display);
    }

    /// Renders the whole picture at once, for the animation, whose redraw of the damage needs
    /// a complete picture under it, and writes the time it took and the view under it.
    fn whole(
        &mut self,
        scene: &Scene<8>,
        options: &Options,
        display: &mut SimulatorDisplay<Rgb888>,
    ) -> Result<(), String> {
        let took = full(scene, &self.camera, display)?;
        self.progress.finish();
        let text = format!(
            "{:.1} ms  az {:.0} el {:.0} fov {:.0}",
            took.as_secs_f64() * 1e3,
            self.orbit.azimuth,
            self.orbit.elevation,
            self.orbit.fov
        );
        status(&text, None, options, display);
        Ok(())
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

/// Whether `text` fits the status line of a picture `cols` wide, in the 6 × 10 font.
fn fits(text: &str, cols: u32) -> bool {
    // The line starts a pixel in.
    text.len() as u64 * 6 < u64::from(cols)
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
    let orbit = Orbit {
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
    // The first frame draws its first pass.
    let mut view = View::new(orbit, options)?;
    let mut held = Held::default();
    let mut toggle = options.animate;
    loop {
        if toggle {
            toggle = false;
            animating = !animating;
            if animating {
                let added = ball.is_none();
                if added {
                    let index = scene
                        .add_sphere(
                            ball_at(phase, options.classic).map_err(|e| e.to_string())?,
                            BALL,
                        )
                        .map_err(|e| e.to_string())?;
                    ball = Some(index);
                }
                // The redraw of the damage needs the whole picture of the scene before it:
                // the ball is new in it, or A cut a refinement short.
                if added || !view.progress.is_complete() {
                    view.whole(&scene, options, &mut display)?;
                }
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
            let damage = Damage::between(&before, &scene, &view.camera);
            redraw(&scene, &view.camera, &damage, &mut line, &mut display)?;
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
        } else {
            view.draw(&scene, held.none(), &mut line, options, &mut display)?;
        }
        // Shows the display and waits out the rest of a `MAX_FPS`th of a second.
        window.update(&display);
        let mut next = view.orbit;
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
                SimulatorEvent::KeyDown { keycode, .. } => {
                    held.press(keycode);
                    next = next.key(keycode);
                }
                SimulatorEvent::KeyUp { keycode, .. } => held.release(keycode),
                _ => {}
            }
        }
        if next != view.orbit {
            // Whatever is left of the old view's passes is dropped: the new one's first pass
            // covers the whole picture.
            view = View::new(next, options)?;
            if animating {
                view.whole(&scene, options, &mut display)?;
            }
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Every band `progress` gives while the view rests, as (spacing, rows).
    fn rest(progress: &mut Progress) -> Vec<(u16, Range<u32>)> {
        std::iter::from_fn(|| progress.next_band(true))
            .map(|(pass, rows)| (pass.spacing(), rows))
            .collect()
    }

    #[test]
    fn first_pass_whole_then_bands_while_resting() {
        let mut progress = Progress::new(40).unwrap();
        assert!(!progress.is_complete());
        let (first, rows) = progress.next_band(false).unwrap();
        assert!(first.is_first());
        assert_eq!((first.spacing(), rows), (COARSEST, 0..40));
        // A key held: nothing more until it is released.
        assert_eq!(progress.next_band(false), None);
        assert!(!progress.is_complete());
        let bands = [0..16, 16..32, 32..40];
        let expected: Vec<(u16, Range<u32>)> = [4, 2, 1]
            .into_iter()
            .flat_map(|spacing| bands.iter().map(move |rows| (spacing, rows.clone())))
            .collect();
        assert_eq!(rest(&mut progress), expected);
        assert!(progress.is_complete());
        assert_eq!(progress.next_band(true), None);
    }

    #[test]
    fn a_key_pressed_mid_refinement_pauses_it_where_it_was() {
        let mut progress = Progress::new(64).unwrap();
        progress.next_band(true);
        let second = progress.next_band(true).unwrap();
        assert_eq!((second.0.spacing(), second.1), (4, 0..16));
        assert_eq!(progress.next_band(false), None);
        let third = progress.next_band(true).unwrap();
        assert_eq!((third.0.spacing(), third.1), (4, 16..32));
    }

    #[test]
    fn each_pass_covers_every_row_once() {
        for rows in [1, 7, 16, 17, 128, 1024] {
            let mut progress = Progress::new(rows).unwrap();
            let bands = rest(&mut progress);
            for spacing in [8, 4, 2, 1] {
                let mut next = 0;
                for (_, band) in bands.iter().filter(|(s, _)| *s == spacing) {
                    assert_eq!(band.start, next, "{rows} rows, spacing {spacing}");
                    assert!(!band.is_empty());
                    assert!(spacing == COARSEST || band.len() as u32 <= BAND);
                    next = band.end;
                }
                assert_eq!(next, rows, "{rows} rows, spacing {spacing}");
            }
            assert!(progress.is_complete());
        }
    }

    /// The picture's pixels on `display`, the status line left out.
    fn picture(display: &SimulatorDisplay<Rgb888>, options: &Options) -> Vec<Rgb888> {
        let area = Rectangle::new(Point::zero(), Size::new(options.cols, options.rows));
        area.points().map(|p| display.get_pixel(p)).collect()
    }

    #[test]
    fn the_passes_end_on_the_whole_picture_after_an_abandoned_one() {
        let options = Options {
            classic: false,
            cols: 40,
            rows: 36,
            animate: false,
        };
        let scene = demo::scene();
        let size = Size::new(options.cols, options.rows + STATUS);
        let mut display = SimulatorDisplay::<Rgb888>::new(size);
        let mut line = vec![Rgb::BLACK; options.cols as usize];
        let start = Orbit {
            azimuth: 0.0,
            elevation: 0.0,
            fov: 60.0,
        };
        // Refined partly, then the view moves.
        let mut view = View::new(start, &options).unwrap();
        view.draw(&scene, false, &mut line, &options, &mut display)
            .unwrap();
        for _ in 0..2 {
            let (pass, band) = view.progress.next_band(true).unwrap();
            Viewport::at(&scene, &view.camera, Point::zero())
                .render_pass_rows(pass, band, &mut line, &mut display)
                .unwrap();
        }
        assert!(!view.progress.is_complete());
        let moved = start.key(Keycode::LEFT);
        let mut view = View::new(moved, &options).unwrap();
        // A key held: the first pass only.
        view.draw(&scene, false, &mut line, &options, &mut display)
            .unwrap();
        view.draw(&scene, false, &mut line, &options, &mut display)
            .unwrap();
        assert!(!view.progress.is_complete());
        assert_eq!(view.first, view.spent);
        while !view.progress.is_complete() {
            view.draw(&scene, true, &mut line, &options, &mut display)
                .unwrap();
        }
        assert!(view.spent >= view.first);
        let mut whole = SimulatorDisplay::<Rgb888>::new(size);
        full(&scene, &view.camera, &mut whole).unwrap();
        assert!(picture(&display, &options) == picture(&whole, &options));
    }

    #[test]
    fn finished_progress_draws_nothing() {
        let mut progress = Progress::new(40).unwrap();
        progress.finish();
        assert!(progress.is_complete());
        assert_eq!(progress.next_band(true), None);
    }

    #[test]
    fn held_counts_only_keys_that_move_the_view() {
        let mut held = Held::default();
        assert!(held.none());
        held.press(Keycode::A);
        held.press(Keycode::SPACE);
        assert!(held.none());
        held.press(Keycode::LEFT);
        // A repeat of a held key, then a second key.
        held.press(Keycode::LEFT);
        held.press(Keycode::KP_PLUS);
        held.release(Keycode::LEFT);
        assert!(!held.none());
        held.release(Keycode::KP_PLUS);
        assert!(held.none());
        // A release without its press (the key went down before the window had focus).
        held.release(Keycode::DOWN);
        assert!(held.none());
    }

    #[test]
    fn the_keys_that_steer_are_those_that_move_the_view() {
        let orbit = Orbit {
            azimuth: 0.0,
            elevation: 0.0,
            fov: 60.0,
        };
        for key in [
            Keycode::LEFT,
            Keycode::RIGHT,
            Keycode::UP,
            Keycode::DOWN,
            Keycode::PLUS,
            Keycode::KP_PLUS,
            Keycode::EQUALS,
            Keycode::MINUS,
            Keycode::KP_MINUS,
        ] {
            assert!(Orbit::steers(key));
            assert_ne!(orbit.key(key), orbit);
        }
        for key in [Keycode::A, Keycode::SPACE, Keycode::ESCAPE] {
            assert!(!Orbit::steers(key));
            assert_eq!(orbit.key(key), orbit);
        }
    }

    #[test]
    fn status_text_fits_the_line() {
        assert!(fits("first 0.4 ms  all 12.3 ms", 160));
        assert!(!fits("first 0.4 ms  all 12.3 ms  az 10 el 0 fov 60", 160));
        assert!(fits("first 0.4 ms  all 12.3 ms  az 10 el 0 fov 60", 320));
    }
}
