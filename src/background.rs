//! [`Background`]: what a ray that escapes the scene sees.

use crate::color::Rgb;
use crate::fx::Fx;
use crate::shading::{Linear, channel_to_linear};
use crate::vec3::Vec3;

/// A vertical gradient: `bottom` for rays looking straight down, `top` straight up, blended
/// linearly in between by `(u_r.y + 1) / 2`. Equal ends give a plain colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Background {
    /// Seen looking straight up.
    pub top: Rgb,
    /// Seen looking straight down.
    pub bottom: Rgb,
}

impl Background {
    /// One colour in every direction.
    #[must_use]
    pub const fn plain(colour: Rgb) -> Self {
        Background {
            top: colour,
            bottom: colour,
        }
    }

    /// The one colour of a plain background, or `None` for a gradient.
    pub(crate) fn plain_colour(&self) -> Option<Rgb> {
        (self.top == self.bottom).then_some(self.top)
    }

    /// The colour seen along the unit direction `dir`, in linear units (1 = 255).
    pub(crate) fn along(&self, dir: Vec3) -> Linear {
        if let Some(c) = self.plain_colour() {
            // Nothing to blend.
            return [c.r, c.g, c.b].map(channel_to_linear);
        }
        let s = (dir.y + Fx::ONE) >> 1; // 0 straight down, 1 straight up
        let mix = |b: u8, t: u8| {
            let (b, t) = (channel_to_linear(b), channel_to_linear(t));
            b + crate::fx::mul(t - b, s)
        };
        [
            mix(self.bottom.r, self.top.r),
            mix(self.bottom.g, self.top.g),
            mix(self.bottom.b, self.top.b),
        ]
    }
}

impl From<Rgb> for Background {
    fn from(colour: Rgb) -> Self {
        Background::plain(colour)
    }
}
