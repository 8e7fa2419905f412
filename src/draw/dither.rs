//! Ordered (Bayer) dithering: grey levels and on/off pixels that still show shading.
//!
//! A 128 × 64 monochrome OLED has one bit a pixel. Thresholding a shaded sphere at half
//! brightness draws a flat silhouette; comparing each pixel against a position-dependent
//! threshold from an 8 × 8 Bayer matrix instead turns a 40 % grey into 40 % of the pixels lit,
//! spread evenly, so the eye sees the shading again. The same rule rounds the 16-bit luma to
//! `Gray8`, `Gray4` or `Gray2` levels, where it spreads the fraction between two levels over
//! neighbouring pixels instead of dropping it.
//!
//! Integer maths only: one multiply-add for the luma, one multiply and one division for the
//! level. The threshold is keyed on display coordinates, so the pattern stays put when a
//! picture is drawn band by band or moved to another viewport.

use embedded_graphics::prelude::Point;

use crate::scene::colour::Rgb;

/// Luma of white: `(77 + 150 + 29) · 255`, so [`luma`] runs from 0 to this.
pub const LUMA_MAX: u32 = 256 * 255;

/// The 8 × 8 Bayer index matrix, row `y` then column `x`: every value 0 to 63 once, and any
/// aligned 2 × 2, 4 × 4 or 8 × 8 block holds thresholds spread evenly over its range.
///
/// Built by the usual recursion `M₂ₙ = [[4Mₙ, 4Mₙ + 2], [4Mₙ + 3, 4Mₙ + 1]]` from `M₁ = [0]`.
pub const BAYER_8X8: [[u8; 8]; 8] = bayer();

const fn bayer() -> [[u8; 8]; 8] {
    let mut m = [[0u8; 8]; 8];
    let mut size = 1;
    while size < 8 {
        // Fill the three new quadrants from the top-left one, then scale the top-left one.
        let mut y = 0;
        while y < size {
            let mut x = 0;
            while x < size {
                let v = 4 * m[y][x];
                m[y][x + size] = v + 2;
                m[y + size][x] = v + 3;
                m[y + size][x + size] = v + 1;
                m[y][x] = v;
                x += 1;
            }
            y += 1;
        }
        size *= 2;
    }
    m
}

/// The Bayer index (0 to 63) of display pixel `at`; negative coordinates continue the tiling.
#[inline]
#[must_use]
pub const fn bayer_index(at: Point) -> u8 {
    // `& 7` on two's complement is the Euclidean remainder, so −1 maps to 7.
    BAYER_8X8[(at.y & 7) as usize][(at.x & 7) as usize]
}

/// Luma of `colour` with ITU-R BT.601 weights in 256ths (77, 150, 29), unscaled: 0 for
/// black to [`LUMA_MAX`] for white. A grey `(c, c, c)` has luma exactly `256 · c`.
#[inline]
#[must_use]
pub const fn luma(colour: Rgb) -> u32 {
    77 * colour.r as u32 + 150 * colour.g as u32 + 29 * colour.b as u32
}

/// Quantises `luma` (0 to [`LUMA_MAX`]) to a level from 0 to `max_level`, dithered at display
/// pixel `at`.
///
/// With `v = luma · max_level / LUMA_MAX` (the exact level, a fraction) and the pixel's
/// threshold `t = (index + ½) / 64`, the level is `⌊v + t⌋`. So every pixel is within one
/// level of `v`, black and white are never dithered, and over any aligned 8 × 8 block of a
/// flat colour the mean level equals `v` to within 1/128 of a level. A `luma` above
/// [`LUMA_MAX`] counts as white.
///
/// ```
/// use embedded_graphics::prelude::Point;
/// use fixray::draw::{dither, LUMA_MAX};
/// // Half grey on a one-bit display: exactly half of an 8 × 8 tile is lit.
/// let lit = (0..64)
///     .filter(|i| dither(LUMA_MAX / 2, 1, Point::new(i % 8, i / 8)) == 1)
///     .count();
/// assert_eq!(lit, 32);
/// // White stays white everywhere, whatever the threshold.
/// assert_eq!(dither(LUMA_MAX, 15, Point::new(5, 3)), 15);
/// ```
#[inline]
#[must_use]
pub const fn dither(luma: u32, max_level: u8, at: Point) -> u8 {
    let luma = if luma > LUMA_MAX { LUMA_MAX } else { luma };
    // ⌊(luma · max · 128 + (2 · index + 1) · LUMA_MAX) / (LUMA_MAX · 128)⌋. The largest
    // numerator, 65 280 · (255 · 128 + 127) ≈ 2.14 × 10⁹, fits u32.
    let threshold = 2 * bayer_index(at) as u32 + 1;
    let level = (luma * max_level as u32 * 128 + threshold * LUMA_MAX) / (LUMA_MAX * 128);
    level as u8
}
