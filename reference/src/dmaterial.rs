//! [`DMaterial`], [`DRefraction`] and [`DChecker`]: what a surface is made of, how light
//! passes through it, and a two-colour pattern.

use super::Real;
use fixray::Rgb;

/// How a surface answers light: Lambert diffuse, a white Blinn-Phong highlight, a mirror and
/// glass.
///
/// At a hit point seen along the unit direction `d`, with the unit normal `n` turned to face
/// the eye and the surface colour `C` (counted 0..=1 for 0..=255), each light `i` at
/// intensity `I_i` that is in front of the surface and not in shadow, with `l_i` the unit
/// vector towards it and `h_i = (l_i − d)/‖l_i − d‖` the half vector between it and the eye,
/// contributes to
///
/// `local = C·(ambient + diffuse·Σ I_i·(n·l_i)) + specular·Σ I_i·clamp(n·h_i, 0, 1)^shininess`
///
/// and a mirror adds `reflect` times what the reflected ray sees, glass ([`DRefraction`])
/// its weight times what the refracted ray sees (see
/// [`DScene::radiance`](super::DScene::radiance)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DMaterial<F: Real = f64> {
    /// The surface colour under full white light (the even squares of a checkerboard).
    pub colour: Rgb,
    /// Weight of the diffuse term.
    pub diffuse: F,
    /// Weight of the highlight, which is white: it adds to every channel alike.
    pub specular: F,
    /// The highlight's exponent: larger is smaller and sharper.
    pub shininess: u16,
    /// Share of the mirror image added, 0 for none.
    pub reflect: F,
    /// A checkerboard replacing `colour` on a plane.
    pub checker: Option<DChecker<F>>,
    /// Light let through, for a transparent surface.
    pub refract: Option<DRefraction<F>>,
}

/// Glass: how much light a surface lets through and how it bends it.
///
/// The medium around every object has index 1. Crossing a surface from index `η₁` into index
/// `η₂`, a ray at an angle `θ₁` to the normal goes on at `θ₂` with `η₁·sin θ₁ = η₂·sin θ₂`
/// (Snell's law) in the plane of the ray and the normal; where `sin θ₂` would exceed 1 no
/// light passes and all of it is reflected (total internal reflection).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DRefraction<F: Real = f64> {
    /// The refractive index inside the object.
    pub index: F,
    /// Share of the refracted ray's light added.
    pub weight: F,
    /// Whether Schlick's approximation of Fresnel's equations moves a share of `weight` to
    /// the mirror ray.
    pub fresnel: bool,
}

impl<F: Real> DMaterial<F> {
    /// A matte surface: diffuse weight 1, no highlight, no mirror, no checkerboard.
    #[must_use]
    pub const fn matte(colour: Rgb) -> Self {
        DMaterial {
            colour,
            diffuse: F::ONE,
            specular: F::ZERO,
            shininess: 1,
            reflect: F::ZERO,
            checker: None,
            refract: None,
        }
    }
}

impl<F: Real> From<Rgb> for DMaterial<F> {
    fn from(colour: Rgb) -> Self {
        DMaterial::matte(colour)
    }
}

/// Squares of side `size` across a plane, alternating a material's colour with `other`.
///
/// The squares are laid out in the plane's coordinates `(u, v)` (see
/// [`DPlane::coords`](super::DPlane::coords)): square `(⌊u/size⌋, ⌊v/size⌋)` shows the
/// material's colour when the sum of the two indices is even, `other` when it is odd.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DChecker<F: Real = f64> {
    /// Side of a square, in world units; positive.
    pub size: F,
    /// The colour of the odd squares.
    pub other: Rgb,
}

impl<F: Real> DChecker<F> {
    /// The colour at plane coordinates `uv`, where the even squares are `even`.
    #[must_use]
    pub fn colour_at(&self, even: Rgb, uv: [F; 2]) -> Rgb {
        let square = (uv[0] / self.size).floor() + (uv[1] / self.size).floor();
        // `fmod` keeps the sign: an odd negative sum gives −1, an even one ±0.
        if square.fmod(F::TWO) == F::ZERO {
            even
        } else {
            self.other
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const WHITE: Rgb = Rgb::WHITE;
    const BLACK: Rgb = Rgb::BLACK;

    #[test]
    fn squares_alternate_along_both_axes_and_across_zero() {
        let board = DChecker {
            size: 2.0,
            other: BLACK,
        };
        let at = |u: f64, v: f64| board.colour_at(WHITE, [u, v]);
        // Square (0, 0) is even; one step along u or v is odd; a diagonal step is even.
        assert_eq!(at(0.5, 0.5), WHITE);
        assert_eq!(at(2.5, 0.5), BLACK);
        assert_eq!(at(0.5, 2.5), BLACK);
        assert_eq!(at(2.5, 2.5), WHITE);
        // Left of zero is square −1, not a second square 0.
        assert_eq!(at(-0.5, 0.5), BLACK);
        assert_eq!(at(-0.5, -0.5), WHITE);
        assert_eq!(at(-2.5, 0.5), WHITE);
    }

    #[test]
    fn a_square_includes_its_lower_edge() {
        let board = DChecker {
            size: 0.25,
            other: BLACK,
        };
        assert_eq!(board.colour_at(WHITE, [0.25, 0.0]), BLACK);
        assert_eq!(board.colour_at(WHITE, [0.249_999, 0.0]), WHITE);
        assert_eq!(board.colour_at(WHITE, [-0.25, 0.0]), BLACK);
    }

    #[test]
    fn a_colour_is_a_matte_material() {
        let m = DMaterial::from(Rgb::new(1, 2, 3));
        assert_eq!(m.colour, Rgb::new(1, 2, 3));
        assert_eq!((m.diffuse, m.specular, m.reflect), (1.0, 0.0, 0.0));
        assert_eq!(m.checker, None);
    }
}
