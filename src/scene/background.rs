//! [`Background`]: what a ray that escapes the scene sees.

use crate::numbers::fx::Fx;
use crate::numbers::vec3::Vec3;
use crate::scene::colour::Rgb;
use crate::scene::linear::{Linear, channel_to_linear};

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
    ///
    /// A ray built by hand may carry a direction that is not a unit vector: its `y` is taken
    /// as at most 1 + 2⁻¹⁶ in magnitude, the most a unit direction's component can be after
    /// rounding, so every unit direction blends as before, a longer one blends as the unit
    /// direction nearest it straight up or down, and the blend cannot overflow.
    pub(crate) fn along(&self, dir: Vec3) -> Linear {
        self.along_height(dir.y)
    }

    /// [`Background::along`] for a direction whose `y` is `height`: all a gradient reads.
    // A run of sky blends with a `Blend` of its own.
    pub(crate) fn along_height(&self, height: Fx) -> Linear {
        if let Some(c) = self.plain_colour() {
            // Nothing to blend.
            return [c.r, c.g, c.b].map(channel_to_linear);
        }
        Blend::of(self).at(height)
    }
}

/// A gradient's ends in linear units, converted once for the many heights of a run of sky:
/// [`Background::along_height`]'s blend, which converts them at each call.
#[derive(Clone, Copy)]
pub(crate) struct Blend {
    /// The bottom colour's channels.
    bottom: Linear,
    /// Each channel's way from the bottom colour to the top, within ±1.
    span: Linear,
}

impl Blend {
    /// `background`'s ends.
    pub(crate) fn of(background: &Background) -> Blend {
        let (b, t) = (background.bottom, background.top);
        let bottom = [b.r, b.g, b.b].map(channel_to_linear);
        let top = [t.r, t.g, t.b].map(channel_to_linear);
        Blend {
            bottom,
            span: [top[0] - bottom[0], top[1] - bottom[1], top[2] - bottom[2]],
        }
    }

    /// The colour seen along a direction whose `y` is `height` (see [`Background::along`]).
    pub(crate) fn at(&self, height: Fx) -> Linear {
        const MOST: Fx = Fx::from_bits((1 << 16) + 1);
        // 0 straight down, 1 straight up: within −2⁻¹⁶..=1, whatever the direction is.
        let s = (height.clamp(-MOST, MOST) + Fx::ONE) >> 1;
        // A span within ±1 and `s` within −2⁻¹⁶..=1: the product needs no saturation check,
        // within `mul_unit`'s bounds (below 2¹⁴ times below 2).
        let mix = |i: usize| self.bottom[i] + crate::numbers::fx::mul_unit(self.span[i], s);
        [mix(0), mix(1), mix(2)]
    }
}

impl From<Rgb> for Background {
    fn from(colour: Rgb) -> Self {
        Background::plain(colour)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numbers::fx;

    #[test]
    fn a_gradient_blends_as_the_saturating_product_would() {
        // Every blend factor a direction can give, for the widest spans of a channel and a
        // few between: the product without its saturation check is the same.
        let ends = [
            (0u8, 255u8),
            (255, 0),
            (0, 0),
            (17, 200),
            (200, 17),
            (128, 127),
        ];
        for (bottom, top) in ends {
            let (b, t) = (channel_to_linear(bottom), channel_to_linear(top));
            for raw in -1..=1 << 16 {
                let s = Fx::from_bits(raw);
                assert_eq!(
                    fx::mul_unit(t - b, s),
                    fx::mul(t - b, s),
                    "{bottom} {top} {raw}"
                );
            }
        }
        // The ends of the factor's range, from directions straight down and up, and longer:
        // the longest straight down blends a unit below black, which a pixel holds at 0.
        let sky = Background {
            top: Rgb::new(255, 255, 255),
            bottom: Rgb::new(0, 0, 0),
        };
        let most = Fx::from_bits((1 << 16) + 1);
        for (y, want) in [(-most, -1), (Fx::ZERO, 1 << 15), (most, 1 << 16)] {
            let dir = Vec3::new(Fx::ZERO, y, Fx::ZERO);
            assert_eq!(sky.along(dir), [Fx::from_bits(want); 3], "{y:?}");
        }
    }
}
