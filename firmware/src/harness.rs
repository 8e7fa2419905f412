//! The measured run: calibrate the counter, set up the scene, render the frame row by row,
//! report, exit.
//!
//! What it prints, one `key=value` line per topic, is what `scripts/firmware.sh` parses:
//!
//! ```text
//! board=microbit target=thumbv6m-none-eabi renderer=fixed-classic
//! counter: SysTick, 16 MHz core clock instructions_per_tick=62.5
//! calibration: expected=20000000 measured=20000062
//! setup: instructions=12062
//! frame: cols=160 rows=128 hash=0x9fdef876 instructions=183186250 per_pixel=8944.6
//! memory: flash=40784 static_ram=4 peak_stack=3908
//! ```

use core::fmt::{self, Debug, Display};

use fixray::{FrameHash, Rgb};
use semihosting::{eprintln, println};

use crate::renderer::{COLS, ROWS, Renderer, Variant};
use crate::{calibrate, counter, exit, memory, stack};

/// Renders and measures one frame of `variant` with `R`, prints the report and ends the QEMU
/// run.
///
/// The peak stack it reports is that of the set-up and the frame (painted after the first
/// reports, read before the last), counted from the top of the stack, so it includes `main`
/// and the row buffer but not the printing.
pub fn run<R: Renderer>(variant: Variant) -> ! {
    println!(
        "board={} target={} renderer={}{}",
        crate::MACHINE,
        crate::TARGET,
        R::NAME,
        variant.suffix()
    );
    check_counter();

    stack::paint();
    let before = counter::ticks();
    // The renderer is used where `new` put it, inside its `Result`: moved out, it took a
    // second slot of the scene's size (1.2 KiB) in this frame, under the whole render.
    let set_up = R::new(variant, COLS, ROWS);
    let renderer = set_up.as_ref().unwrap_or_else(|e| refused("set-up", *e));
    let setup = counter::ticks().wrapping_sub(before);
    println!(
        "setup: instructions={}",
        counter::instructions(setup.into())
    );

    let (hash, instructions) = frame(renderer);
    let peak = stack::peak();
    let pixels = u64::from(COLS) * u64::from(ROWS);
    let per_pixel = Tenths::of((instructions, pixels));
    println!(
        "frame: cols={COLS} rows={ROWS} hash={hash:#010x} instructions={instructions} \
         per_pixel={per_pixel}"
    );

    let usage = memory::usage();
    println!(
        "memory: flash={} static_ram={} peak_stack={peak}",
        usage.flash, usage.static_ram
    );
    exit::with(exit::SUCCESS)
}

/// Runs the animation of [`crate::animation`], prints its report and ends the QEMU run:
///
/// ```text
/// animate: frames=15 partial=... damage=... full=... pixels=... spans_hash=0x........ final_hash=0x........
/// ```
///
/// `partial` and `full` are the instructions of all the partial and all the full redraws,
/// `damage` the part of `partial` that finding the changed region took, `pixels` those the
/// partial redraws drew. The peak stack is the whole run's.
pub fn run_animation() -> ! {
    println!(
        "board={} target={} renderer=animate",
        crate::MACHINE,
        crate::TARGET
    );
    check_counter();
    stack::paint();
    let totals = crate::animation::run(counter::ticks).unwrap_or_else(|e| refused("a frame", e));
    let peak = stack::peak();
    println!(
        "animate: frames={} partial={} damage={} full={} pixels={} spans_hash={:#010x} \
         final_hash={:#010x}",
        totals.frames,
        counter::instructions(totals.partial_ticks),
        counter::instructions(totals.damage_ticks),
        counter::instructions(totals.full_ticks),
        totals.partial_pixels,
        totals.spans_hash,
        totals.final_hash
    );
    let usage = memory::usage();
    println!(
        "memory: flash={} static_ram={} peak_stack={peak}",
        usage.flash, usage.static_ram
    );
    exit::with(exit::SUCCESS)
}

/// Runs the progressive passes of [`crate::progressive`], prints their report and ends the
/// QEMU run:
///
/// ```text
/// progressive: passes=4 pass1=... pass2=... pass3=... pass4=... pixels=... passes_hash=0x........ passes_digest=0x........
/// ```
///
/// `passK` are the instructions of each pass's `render_pass_row` calls, `pixels` each pass's
/// traced pixels (`/`-separated). The peak stack is the whole run's.
pub fn run_progressive() -> ! {
    println!(
        "board={} target={} renderer=progressive",
        crate::MACHINE,
        crate::TARGET
    );
    check_counter();
    stack::paint();
    let totals = crate::progressive::run(counter::ticks).unwrap_or_else(|e| refused("a pass", e));
    let peak = stack::peak();
    let [p1, p2, p3, p4] = totals.pass_ticks.map(counter::instructions);
    let [n1, n2, n3, n4] = totals.pass_pixels;
    println!(
        "progressive: passes={} pass1={p1} pass2={p2} pass3={p3} pass4={p4} \
         pixels={n1}/{n2}/{n3}/{n4} passes_hash={:#010x} passes_digest={:#010x}",
        crate::progressive::PASSES,
        totals.passes_hash,
        totals.passes_digest
    );
    let usage = memory::usage();
    println!(
        "memory: flash={} static_ram={} peak_stack={peak}",
        usage.flash, usage.static_ram
    );
    exit::with(exit::SUCCESS)
}

/// Starts the counter and times the loop of known length; a counter that disagrees ends the
/// run, since every figure after it would be wrong.
fn check_counter() {
    counter::start();
    let per_tick = Tenths::of(counter::PER_TICK);
    println!(
        "counter: {} instructions_per_tick={per_tick}",
        counter::NAME
    );
    let calibration = calibrate::run();
    let (expected, measured) = (calibration.expected, calibration.measured);
    println!("calibration: expected={expected} measured={measured}");
    if !calibration.agrees() {
        let tolerance = calibrate::Calibration::TOLERANCE;
        eprintln!("the counter is off by more than {tolerance} instructions");
        exit::with(exit::COUNTER_WRONG);
    }
}

/// Renders the frame one row at a time into a single row buffer: its [`FrameHash`] and the
/// instructions the `render_row` calls took (hashing the rows is not counted).
fn frame(renderer: &impl Renderer) -> (u32, u64) {
    let mut row = [Rgb::BLACK; COLS as usize];
    let mut hash = FrameHash::new();
    let mut ticks = 0_u64;
    for y in 0..ROWS {
        let before = counter::ticks();
        let rendered = renderer.render_row(y, &mut row);
        ticks += u64::from(counter::ticks().wrapping_sub(before));
        rendered.unwrap_or_else(|e| refused("a row", e));
        hash.update(&row);
    }
    (hash.finish(), counter::instructions(ticks))
}

/// Reports a renderer's refusal and ends the run.
fn refused(what: &str, error: impl Debug) -> ! {
    eprintln!("the renderer refused {what}: {error:?}");
    exit::with(exit::RENDER_FAILED)
}

/// A quotient printed to one decimal place (rounded down).
struct Tenths(u64);

impl Tenths {
    /// `numerator / denominator` in tenths.
    fn of((numerator, denominator): (u64, u64)) -> Self {
        Tenths(numerator * 10 / denominator)
    }
}

impl Display for Tenths {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}.{}", self.0 / 10, self.0 % 10)
    }
}
