//! The progressive render the firmware measures: the demo scene at 160 × 128 in passes from
//! spacing [`COARSEST`] down to 1 (`fixray::Pass`), each pass's instructions counted, against
//! the full frame of the `fixed` binary (`scripts/firmware.sh` divides the two).
//!
//! A chip cannot hold the frame (the micro:bit has 16 KiB of RAM), so what the passes leave is
//! checked without it: each pixel a pass traces goes into a digest keyed by its position, and a
//! frame is what the passes leave when every pixel is traced exactly once with the colour
//! `render_row` gives it there (fixray's tests check that every block a pass paints is covered
//! by a finer pass's pixels or is its own pixel). The digest of the full frame, made the same
//! way ([`frame_digest`], on the host), must equal it. Like `animation.rs` it uses nothing but fixray, so
//! `examples/frame_hash.rs` compiles this very file and prints what a chip must reproduce.

use fixray::{Error, FrameHash, Pass, Rgb, render_pass_row, render_row};

use crate::renderer::{COLS, ROWS, Variant};

/// The first pass's spacing: its pixels are 1/64 of the frame.
pub const COARSEST: u16 = 8;

/// How many passes there are from [`COARSEST`]: spacings 8, 4, 2 and 1.
pub const PASSES: usize = 4;

/// What running the passes gives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Totals {
    /// Counter ticks of each pass's `render_pass_row` calls.
    pub pass_ticks: [u64; PASSES],
    /// Pixels each pass traced.
    pub pass_pixels: [u32; PASSES],
    /// [`FrameHash`] of every traced pixel, pass by pass, row by row, in column order.
    pub passes_hash: u32,
    /// [`digest`] of every traced pixel at its place: the frame the passes leave.
    pub passes_digest: u32,
}

/// Runs the passes, timing each call with `ticks` (a free-running counter; differences are
/// taken with wrapping arithmetic).
pub fn run(mut ticks: impl FnMut() -> u32) -> Result<Totals, Error> {
    let scene = Variant::Demo.scene();
    let camera = Variant::Demo.camera(COLS, ROWS)?;
    let mut row = [Rgb::BLACK; COLS as usize];
    let mut totals = Totals {
        pass_ticks: [0; PASSES],
        pass_pixels: [0; PASSES],
        passes_hash: 0,
        passes_digest: 0,
    };
    let mut hash = FrameHash::new();
    for (k, pass) in Pass::sequence(COARSEST)?.enumerate().take(PASSES) {
        for y in 0..ROWS {
            let before = ticks();
            let traced = render_pass_row(scene, &camera, pass, y, &mut row);
            totals.pass_ticks[k] += u64::from(ticks().wrapping_sub(before));
            let count = traced?;
            if count == 0 {
                continue;
            }
            let pixels = row.get(..count).unwrap_or_default();
            hash.update(pixels);
            for (&colour, x) in pixels.iter().zip(pass.columns(y).below(COLS)) {
                totals.passes_digest = totals.passes_digest.wrapping_add(digest(x, y, colour));
            }
            totals.pass_pixels[k] += count as u32;
        }
    }
    totals.passes_hash = hash.finish();
    Ok(totals)
}

/// The [`digest`] of the full frame, `render_row` row by row: what the passes must leave. The
/// host works it out (`examples/frame_hash.rs`); the firmware does not render the frame, so
/// that its `render_row` is the passes' alone, as in a program that draws only passes.
pub fn frame_digest() -> Result<u32, Error> {
    let scene = Variant::Demo.scene();
    let camera = Variant::Demo.camera(COLS, ROWS)?;
    let mut row = [Rgb::BLACK; COLS as usize];
    let mut sum = 0u32;
    for y in 0..ROWS {
        render_row(scene, &camera, y, &mut row)?;
        for (x, &colour) in (0..).zip(&row) {
            sum = sum.wrapping_add(digest(x, y, colour));
        }
    }
    Ok(sum)
}

/// One pixel's share of a frame's digest: its place and colour mixed (a 32-bit finaliser), so
/// that a sum over the pixels, in any order, changes with any one of them.
pub fn digest(x: u32, y: u32, colour: Rgb) -> u32 {
    let place = y.wrapping_mul(COLS).wrapping_add(x);
    let rgb = u32::from(colour.r) << 16 | u32::from(colour.g) << 8 | u32::from(colour.b);
    let mut h = place.wrapping_mul(0x9e37_79b9) ^ rgb.wrapping_mul(0x85eb_ca6b);
    h ^= h >> 16;
    h = h.wrapping_mul(0x7feb_352d);
    h ^= h >> 15;
    h = h.wrapping_mul(0x846c_a68b);
    h ^ h >> 16
}
