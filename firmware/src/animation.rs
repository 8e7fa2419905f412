//! The animation the firmware measures: [`demo::rolling`](fixray::demo::rolling), a ball
//! rolling across the demo scene's floor at 160 × 128, each frame redrawn twice — only what
//! [`Damage`] says can have changed, and in full — with the instructions of each counted.
//!
//! Like `renderer.rs`, it uses nothing but fixray, so `examples/frame_hash.rs` compiles this
//! very file and prints the hashes a chip must reproduce: the digest of every redrawn span,
//! frame after frame, and the digest of the last frame in full.

use fixray::{Damage, Error, FrameHash, Rgb, demo, render_row, render_row_span};

use crate::renderer::{COLS, ROWS};

/// What running the animation gives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Totals {
    /// Frames redrawn after the first (which is drawn in full and not counted).
    pub frames: u32,
    /// Counter ticks of the partial redraws: the damage and the spans.
    pub partial_ticks: u64,
    /// Of those, the ticks of `Damage::between` alone.
    pub damage_ticks: u64,
    /// Counter ticks of the full redraws: `render_row` for every row.
    pub full_ticks: u64,
    /// Pixels the partial redraws drew (and a display would be sent).
    pub partial_pixels: u64,
    /// [`FrameHash`] of every redrawn span's pixels, in order.
    pub spans_hash: u32,
    /// [`FrameHash`] of the last frame, drawn in full.
    pub final_hash: u32,
}

/// Runs the animation, timing each step with `ticks` (a free-running counter; differences
/// are taken with wrapping arithmetic, so each step must be shorter than its period).
///
/// The hashing and the loop around the renders are not counted: only `Damage::between` and
/// `render_row_span` for a partial frame, `render_row` for a full one.
pub fn run(mut ticks: impl FnMut() -> u32) -> Result<Totals, Error> {
    let camera = demo::camera(COLS, ROWS)?;
    let mut row = [Rgb::BLACK; COLS as usize];
    let mut spans = FrameHash::new();
    let mut totals = Totals {
        frames: demo::ROLLING_FRAMES - 1,
        partial_ticks: 0,
        damage_ticks: 0,
        full_ticks: 0,
        partial_pixels: 0,
        spans_hash: 0,
        final_hash: 0,
    };
    let mut shown = demo::rolling(0);
    for frame in 1..demo::ROLLING_FRAMES {
        let next = demo::rolling(frame);
        let before = ticks();
        let damage = Damage::between(&shown, &next, &camera);
        let spent = u64::from(ticks().wrapping_sub(before));
        totals.partial_ticks += spent;
        totals.damage_ticks += spent;
        for y in 0..ROWS {
            let Some(span) = damage.row_span(y) else {
                continue;
            };
            let width = span.len();
            let out = row.get_mut(..width).ok_or(Error::BufferLength {
                needed: width,
                got: COLS as usize,
            })?;
            let before = ticks();
            let drawn = render_row_span(&next, &camera, y, span, out);
            totals.partial_ticks += u64::from(ticks().wrapping_sub(before));
            drawn?;
            totals.partial_pixels += width as u64;
            spans.update(out);
        }
        let mut last = FrameHash::new();
        for y in 0..ROWS {
            let before = ticks();
            let drawn = render_row(&next, &camera, y, &mut row);
            totals.full_ticks += u64::from(ticks().wrapping_sub(before));
            drawn?;
            last.update(&row);
        }
        totals.final_hash = last.finish();
        shown = next;
    }
    totals.spans_hash = spans.finish();
    Ok(totals)
}
