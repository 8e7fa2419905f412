//! [`Material`]: how a surface answers light, and [`Checker`], a two-colour pattern.

use crate::error::{Error, Quantity, within};
use crate::numbers::fx::Fx;
use crate::scene::colour::Rgb;

/// The largest shininess [`Material::new`] accepts.
const MAX_SHININESS: u16 = 4096;

/// How a surface shades: Lambert diffuse, Blinn-Phong specular and mirror reflection.
///
/// For a hit seen along `v` (towards the eye), lit by lights `l` with intensities `I` that are
/// not in shadow, and with `h = (l + v)/‖l + v‖` the half vector:
///
/// `local = colour · (ambient + diffuse · Σ I·max(0, n·l)) + specular · Σ I·max(0, n·h)^shininess`
///
/// and the pixel is `local + reflect · (what the mirror ray sees)`, each channel clamped to
/// 0..=255 at the end. `colour` counts 0..=255 as 0..=1.
///
/// [`Material::new`] checks the ranges below. The fields are public, so a material built by
/// hand may hold any value: shading then saturates every weighted sum instead of wrapping,
/// and a weight outside its range gives a colour clamped to 0..=255, not a panic.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Material {
    /// The surface colour under full white light.
    pub colour: Rgb,
    /// Weight of the diffuse (Lambert) term, 0 to 2.
    pub diffuse: Fx,
    /// Weight of the specular (Blinn-Phong) highlight, 0 to 16.
    pub specular: Fx,
    /// Specular exponent, 1 to 4096: larger is a smaller, sharper highlight.
    pub shininess: u16,
    /// Share of the mirror image added, 0 to 1.
    pub reflect: Fx,
    /// A checkerboard that alternates `colour` with another colour, for planes.
    pub checker: Option<Checker>,
}

impl Material {
    /// A matte surface: full diffuse, no highlight, no mirror.
    #[must_use]
    pub const fn matte(colour: Rgb) -> Self {
        Material {
            colour,
            diffuse: Fx::ONE,
            specular: Fx::ZERO,
            shininess: 1,
            reflect: Fx::ZERO,
            checker: None,
        }
    }

    /// A material, checked against the ranges above.
    ///
    /// ```
    /// use fixray::{Error, Fx, Material, Quantity, Rgb};
    /// let ivory = Material::new(Rgb::new(102, 102, 77), Fx::from_num(0.6), Fx::from_num(0.3), 50, Fx::from_num(0.1));
    /// assert!(ivory.is_ok());
    /// let bad = Material::new(Rgb::WHITE, Fx::ONE, Fx::ZERO, 0, Fx::ZERO);
    /// assert_eq!(
    ///     bad,
    ///     Err(Error::OutOfRange { quantity: Quantity::Shininess, min: Fx::ONE, max: Fx::from_num(4096) })
    /// );
    /// ```
    pub fn new(
        colour: Rgb,
        diffuse: Fx,
        specular: Fx,
        shininess: u16,
        reflect: Fx,
    ) -> Result<Self, Error> {
        let weight = |value, max, quantity| within(value, Fx::ZERO, max, quantity);
        weight(diffuse, Fx::const_from_int(2), Quantity::DiffuseWeight)?;
        weight(specular, Fx::const_from_int(16), Quantity::SpecularWeight)?;
        weight(reflect, Fx::ONE, Quantity::Reflectivity)?;
        // A u16 may exceed Q16.16's 32 767, so the exponent is compared as an integer; its
        // bounds, 1 and 4096, are whole Q16.16 values for the error.
        if !(1..=MAX_SHININESS).contains(&shininess) {
            return Err(Error::OutOfRange {
                quantity: Quantity::Shininess,
                min: Fx::ONE,
                max: Fx::const_from_int(MAX_SHININESS as i32),
            });
        }
        Ok(Material {
            colour,
            diffuse,
            specular,
            shininess,
            reflect,
            checker: None,
        })
    }

    /// The same material with a checkerboard of `size`-wide squares alternating its colour
    /// with `other`.
    pub fn with_checker(self, size: Fx, other: Rgb) -> Result<Self, Error> {
        // Above zero: the smallest Q16.16 value above it is one step.
        within(size, Fx::DELTA, crate::LIMIT, Quantity::CheckerSize)?;
        Ok(Material {
            checker: Some(Checker { size, other }),
            ..self
        })
    }
}

impl From<Rgb> for Material {
    fn from(colour: Rgb) -> Self {
        Material::matte(colour)
    }
}

/// Squares of side `size` that alternate a material's colour with `other`.
///
/// The squares lie in the two world coordinates across a plane: those left when the axis the
/// plane's normal is closest to is dropped — `(x, z)` for a floor, `(x, y)` for a wall facing
/// ±z, `(y, z)` for a wall facing ±x. Square `(⌊u/size⌋, ⌊v/size⌋)` has the material's colour
/// when the sum of its indices is even.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Checker {
    /// Side of a square, in world units.
    pub size: Fx,
    /// The colour of the odd squares.
    pub other: Rgb,
}

impl Checker {
    /// The colour of the square at plane coordinates `uv`.
    #[must_use]
    pub fn colour_at(&self, even: Rgb, uv: [Fx; 2]) -> Rgb {
        // `size` is a public field: a square of no size is one colour, not a division by zero.
        let size = self.size.to_bits() as i64;
        if size <= 0 {
            return even;
        }
        let index = |c: Fx| (c.to_bits() as i64).div_euclid(size);
        if (index(uv[0]) + index(uv[1])) & 1 == 0 {
            even
        } else {
            self.other
        }
    }
}
