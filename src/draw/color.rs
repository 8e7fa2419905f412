//! [`FromRgb`]: from a shaded [`Rgb`] to the colour a display takes.

use embedded_graphics::pixelcolor::{BinaryColor, Gray2, Gray4, Gray8, Rgb565, Rgb888};
use embedded_graphics::prelude::{Point, RgbColor};

use super::dither::{dither, luma};
use crate::scene::colour::Rgb;

/// A display colour fixray can produce from a shaded [`Rgb`].
///
/// The position is the pixel's place on the display (not in the viewport), so dithered
/// formats keep one fixed pattern however the picture is split into bands.
///
/// | colour | conversion | error per pixel |
/// | --- | --- | --- |
/// | [`Rgb888`] | the channels as they are | none |
/// | [`Rgb565`] | each channel rounded to 5 or 6 bits (embedded-graphics' own rounding) | ½ step |
/// | [`Gray8`], [`Gray4`], [`Gray2`] | BT.601 [`luma`], ordered-dithered to the level count | < 1 level |
/// | [`BinaryColor`] | luma ordered-dithered to off/on ([`dither`]) | on or off |
///
/// Dithered formats are exact on average: over an aligned 8 × 8 block of one colour the mean
/// level is the true luma within 1/128 of a level. Implement this trait for another colour
/// type (say a display's `Rgb666`) to draw on it; [`dither`] and [`luma`] are public for that.
///
/// ```
/// use embedded_graphics::pixelcolor::{BinaryColor, Gray8, Rgb565};
/// use embedded_graphics::prelude::{Point, RgbColor};
/// use fixray::{FromRgb, Rgb};
/// let at = Point::new(3, 1);
/// assert_eq!(Rgb565::from_rgb(Rgb::WHITE, at), Rgb565::WHITE);
/// assert_eq!(Gray8::from_rgb(Rgb::new(90, 90, 90), at), Gray8::new(90));
/// assert_eq!(BinaryColor::from_rgb(Rgb::BLACK, at), BinaryColor::Off);
/// ```
pub trait FromRgb: embedded_graphics::prelude::PixelColor {
    /// The display colour for `colour` at display pixel `at`.
    fn from_rgb(colour: Rgb, at: Point) -> Self;
}

impl From<Rgb> for Rgb888 {
    #[inline]
    fn from(c: Rgb) -> Self {
        Rgb888::new(c.r, c.g, c.b)
    }
}

impl From<Rgb888> for Rgb {
    #[inline]
    fn from(c: Rgb888) -> Self {
        Rgb::new(c.r(), c.g(), c.b())
    }
}

impl FromRgb for Rgb888 {
    #[inline]
    fn from_rgb(colour: Rgb, _at: Point) -> Self {
        colour.into()
    }
}

impl FromRgb for Rgb565 {
    #[inline]
    fn from_rgb(colour: Rgb, _at: Point) -> Self {
        Rgb888::from(colour).into()
    }
}

impl FromRgb for Gray8 {
    #[inline]
    fn from_rgb(colour: Rgb, at: Point) -> Self {
        Gray8::new(dither(luma(colour), 255, at))
    }
}

impl FromRgb for Gray4 {
    #[inline]
    fn from_rgb(colour: Rgb, at: Point) -> Self {
        Gray4::new(dither(luma(colour), 15, at))
    }
}

impl FromRgb for Gray2 {
    #[inline]
    fn from_rgb(colour: Rgb, at: Point) -> Self {
        Gray2::new(dither(luma(colour), 3, at))
    }
}

impl FromRgb for BinaryColor {
    #[inline]
    fn from_rgb(colour: Rgb, at: Point) -> Self {
        BinaryColor::from(dither(luma(colour), 1, at) == 1)
    }
}

/// Converts `lines` of pixels, the first pixel of the first line at display point `top_left`,
/// into display colours in `fill_contiguous` order (left to right, top to bottom).
///
/// The position only keys the dither pattern, which repeats every 8 pixels, so the steps wrap
/// instead of overflowing: no coordinate can make this panic.
pub(crate) fn converted<'a, C: FromRgb>(
    lines: impl Iterator<Item = &'a [Rgb]>,
    top_left: Point,
) -> impl Iterator<Item = C> {
    lines.enumerate().flat_map(move |(dy, line)| {
        let y = top_left.y.wrapping_add(dy as i32);
        line.iter().enumerate().map(move |(dx, &colour)| {
            C::from_rgb(colour, Point::new(top_left.x.wrapping_add(dx as i32), y))
        })
    })
}
