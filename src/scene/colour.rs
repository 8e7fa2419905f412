//! [`Rgb`]: the colour fixray shades with, 8 bits a channel.

/// An 8-bit-per-channel colour: a material's colour, a background, or a shaded pixel.
///
/// Three bytes and no padding, so a row of pixels is exactly `3 × width` bytes; the frame hash
/// the firmware prints is taken over these bytes, row by row, in `r, g, b` order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub struct Rgb {
    /// Red.
    pub r: u8,
    /// Green.
    pub g: u8,
    /// Blue.
    pub b: u8,
}

impl Rgb {
    /// Black.
    pub const BLACK: Rgb = Rgb::new(0, 0, 0);
    /// White.
    pub const WHITE: Rgb = Rgb::new(255, 255, 255);

    /// A colour from its three channels.
    #[inline]
    #[must_use]
    pub const fn new(r: u8, g: u8, b: u8) -> Self {
        Rgb { r, g, b }
    }
}
