//! [`FromRgb`]: from a shaded [`Rgb`] to the colour a display takes, for every colour type of
//! embedded-graphics.

use embedded_graphics::pixelcolor::{
    Bgr555, Bgr565, Bgr666, Bgr888, BinaryColor, Gray2, Gray4, Gray8, Rgb555, Rgb565, Rgb666,
    Rgb888,
};
use embedded_graphics::prelude::{Point, RgbColor};

use super::dither::{dither, luma};
use crate::scene::colour::Rgb;

/// A display colour fixray can produce from a shaded [`Rgb`].
///
/// Every colour type of `embedded_graphics::pixelcolor` has it, so any embedded-graphics
/// display draws a fixray picture as it is. The position is the pixel's place on the display
/// (not in the viewport), so dithered formats keep one fixed pattern however the picture is
/// split into bands or clipped.
///
/// | colour | conversion | error per pixel |
/// | --- | --- | --- |
/// | [`Rgb888`], [`Bgr888`] | the channels as they are | none |
/// | [`Rgb565`], [`Bgr565`] | each channel rounded to 5 or 6 bits (embedded-graphics' own rounding) | ½ step |
/// | [`Rgb666`], [`Bgr666`], [`Rgb555`], [`Bgr555`] | each channel ordered-dithered to 6 or 5 bits | < 1 step |
/// | [`Gray8`], [`Gray4`], [`Gray2`] | BT.601 [`luma`], ordered-dithered to the level count | < 1 level |
/// | [`BinaryColor`] | luma ordered-dithered to off/on ([`dither`]) | on or off |
///
/// Dithered formats are exact on average: over an aligned 8 × 8 block of one colour the mean
/// level is the true one within 1/128 of a level. The three channels of a pixel share its
/// threshold, so a grey stays grey. The 565 formats round instead: their pictures are the
/// ones fixray has always drawn on the most common SPI displays, and a panel wired BGR shows
/// what the same panel wired RGB shows.
///
/// ```
/// use embedded_graphics::pixelcolor::{Bgr565, BinaryColor, Gray2, Gray8, Rgb565, Rgb666};
/// use embedded_graphics::prelude::{GrayColor, Point, RgbColor};
/// use fixray::{FromRgb, Rgb};
/// let at = Point::new(3, 1);
/// assert_eq!(Rgb565::from_rgb(Rgb::WHITE, at), Rgb565::WHITE);
/// assert_eq!(Bgr565::from_rgb(Rgb::new(255, 0, 0), at), Bgr565::RED);
/// assert_eq!(Rgb666::from_rgb(Rgb::new(0, 255, 0), at), Rgb666::GREEN);
/// assert_eq!(Gray8::from_rgb(Rgb::new(90, 90, 90), at), Gray8::new(90));
/// assert_eq!(BinaryColor::from_rgb(Rgb::BLACK, at), BinaryColor::Off);
/// // A mid grey on a four-level display: levels 1 and 2 side by side, nothing else.
/// let grey = Rgb::new(128, 128, 128);
/// let row: Vec<u8> = (0..8).map(|x| Gray2::from_rgb(grey, Point::new(x, 0)).luma()).collect();
/// assert!(row.contains(&1) && row.contains(&2) && row.iter().all(|l| (1..=2).contains(l)));
/// ```
///
/// # A colour type of your own
///
/// A display driver with a colour type of its own (an e-paper's three inks, a palette) has
/// two ways in. If the type converts from [`Rgb888`], as embedded-graphics asks of colour
/// types, draw through embedded-graphics' `color_converted` adapter with nothing to write;
/// if the driver's crate is yours, or you want dithering, implement this trait: the type is
/// yours, so the orphan rule allows it, and [`dither`] and [`luma`] are public for it.
///
/// ```
/// use core::convert::Infallible;
/// use embedded_graphics::{pixelcolor::{raw::RawU2, Rgb888}, prelude::*};
/// use fixray::draw::{dither, luma};
/// use fixray::{demo, FromRgb, Rgb, Viewport};
///
/// /// An e-paper's inks: white, black, red.
/// #[derive(Debug, Clone, Copy, PartialEq, Eq)]
/// enum Ink { White, Black, Red }
///
/// impl PixelColor for Ink {
///     type Raw = RawU2;
/// }
///
/// // The adapter's way: a conversion from Rgb888.
/// impl From<Rgb888> for Ink {
///     fn from(c: Rgb888) -> Self {
///         if c.r() > 160 && c.g() < 100 { Ink::Red } else if c.g() > 127 { Ink::White } else { Ink::Black }
///     }
/// }
///
/// // fixray's way: dithered black and white (and the reds kept red).
/// impl FromRgb for Ink {
///     fn from_rgb(c: Rgb, at: Point) -> Self {
///         if c.r > 160 && c.g < 100 { Ink::Red }
///         else if dither(luma(c), 1, at) == 1 { Ink::White } else { Ink::Black }
///     }
/// }
///
/// /// A stand-in for the driver: counts the red pixels.
/// struct Epaper { red: usize }
/// impl OriginDimensions for Epaper {
///     fn size(&self) -> Size { Size::new(40, 30) }
/// }
/// impl DrawTarget for Epaper {
///     type Color = Ink;
///     type Error = Infallible;
///     fn draw_iter<I: IntoIterator<Item = Pixel<Ink>>>(&mut self, pixels: I) -> Result<(), Infallible> {
///         self.red += pixels.into_iter().filter(|p| p.1 == Ink::Red).count();
///         Ok(())
///     }
/// }
///
/// let (scene, camera) = (demo::scene(), demo::camera(40, 30)?);
/// let view = Viewport::at(&scene, &camera, Point::zero());
/// let mut row = [Rgb::BLACK; 40];
/// let mut display = Epaper { red: 0 };
/// view.render(&mut row, &mut display)?; // FromRgb
/// view.render(&mut row, &mut display.color_converted::<Rgb888>())?; // From<Rgb888>
/// assert!(display.red > 0, "the demo has a red sphere");
/// # Ok::<(), Box<dyn std::error::Error>>(())
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

/// The channels as they are, or each rounded to the type's bits by embedded-graphics'
/// conversion from [`Rgb888`].
macro_rules! rounded {
    ($($colour:ident),+) => {$(
        impl FromRgb for $colour {
            #[inline]
            fn from_rgb(colour: Rgb, _at: Point) -> Self {
                Rgb888::from(colour).into()
            }
        }
    )+};
}

rounded!(Rgb888, Bgr888, Rgb565, Bgr565);

/// A channel (0 to 255) ordered-dithered to 0 to `max` at display pixel `at`: a grey's luma is
/// 256 times its channel, so [`dither`] does it exactly.
#[inline]
fn channel(value: u8, max: u8, at: Point) -> u8 {
    dither(256 * u32::from(value), max, at)
}

/// Each channel ordered-dithered to the type's bits, all three with the pixel's threshold.
macro_rules! dithered {
    ($($colour:ident),+) => {$(
        impl FromRgb for $colour {
            #[inline]
            fn from_rgb(colour: Rgb, at: Point) -> Self {
                $colour::new(
                    channel(colour.r, $colour::MAX_R, at),
                    channel(colour.g, $colour::MAX_G, at),
                    channel(colour.b, $colour::MAX_B, at),
                )
            }
        }
    )+};
}

dithered!(Rgb555, Bgr555, Rgb666, Bgr666);

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
