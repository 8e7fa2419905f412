//! [`Material`]: how a surface answers light, and [`Checker`], a two-colour pattern.

use crate::check;
use crate::error::{Error, Quantity};
use crate::numbers::fx::{self, Fx};
use crate::scene::colour::Rgb;
use crate::scene::linear::least_lit_base;

/// The largest shininess [`Material::new`] accepts.
const MAX_SHININESS: u16 = 4096;

/// Whether this build follows mirror and refracted rays (the `mirrors-and-glass` feature).
const MIRRORS_AND_GLASS: bool = cfg!(feature = "mirrors-and-glass");

/// How a surface shades: Lambert diffuse, Blinn-Phong specular, mirror reflection and
/// refraction.
///
/// For a hit seen along `v` (towards the eye), lit by lights `l` with intensities `I` that are
/// not in shadow, and with `h = (l + v)/‖l + v‖` the half vector:
///
/// `local = colour · (ambient + diffuse · Σ I·max(0, n·l)) + specular · Σ I·max(0, n·h)^shininess`
///
/// and the pixel is `local + reflect · (what the mirror ray sees) + refract · (what the
/// refracted ray sees)`, each channel clamped to 0..=255 at the end. `colour` counts 0..=255
/// as 0..=1. Refraction ([`Material::with_refraction`]) follows Snell's law with the
/// material's refractive index; where it has no solution (total internal reflection) the
/// refraction weight goes to the mirror ray instead.
///
/// [`Material::new`] checks the ranges below.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Material {
    pub(crate) colour: Rgb,
    pub(crate) diffuse: Fx,
    pub(crate) specular: Fx,
    pub(crate) shininess: u16,
    /// The least `n·h`, in raw Q16.16 units, whose highlight is not 0 at this shininess
    /// (`linear::least_lit_base`): below it a highlight takes no power.
    pub(crate) highlight_from: u16,
    pub(crate) reflect: Fx,
    pub(crate) refraction: Option<Refraction>,
    pub(crate) checker: Option<Checker>,
}

/// How much light passes through a surface, and how it bends: see
/// [`Material::with_refraction`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Refraction {
    weight: Fx,
    index: Fx,
    /// `1/index`: the ratio of indices for a ray entering the material.
    pub(crate) inverse: Fx,
    /// Schlick's `R₀ = ((index − 1)/(index + 1))²`.
    pub(crate) r0: Fx,
    fresnel: bool,
}

impl Refraction {
    /// Share of the refracted image added, above 0 and at most 1.
    #[must_use]
    pub const fn weight(&self) -> Fx {
        self.weight
    }

    /// The refractive index `η` of the material (the medium outside counts as 1).
    #[must_use]
    pub const fn index(&self) -> Fx {
        self.index
    }

    /// Whether the weight is split by Schlick's Fresnel approximation (see
    /// [`Material::with_fresnel`]).
    #[must_use]
    pub const fn fresnel(&self) -> bool {
        self.fresnel
    }
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
            highlight_from: least_lit_base(1),
            reflect: Fx::ZERO,
            refraction: None,
            checker: None,
        }
    }

    /// Whether a surface of this material shows its own diffuse light alone: no highlight, no
    /// mirror, no refraction.
    #[must_use]
    pub(crate) const fn is_plain_matte(&self) -> bool {
        self.specular.to_bits() == 0 && self.reflect.to_bits() == 0 && self.refraction.is_none()
    }

    /// Whether a hit on this material sends on a mirror or a refracted ray. Never in a build
    /// without the `mirrors-and-glass` feature, where no material can: the compiler then
    /// leaves the tree of secondary rays out of the renderer.
    pub(crate) const fn sends_rays(&self) -> bool {
        MIRRORS_AND_GLASS && (self.reflect.to_bits() != 0 || self.refraction.is_some())
    }

    /// A material, checked: `diffuse` 0 to 2, `specular` 0 to 16, `shininess` 1 to 4096,
    /// `reflect` 0 to 1.
    ///
    /// ```
    /// use fixray::{Error, Fx, Material, Quantity, Rgb};
    /// let ivory = Material::new(Rgb::new(102, 102, 77), 0.6, 0.3, 50, 0.1)?;
    /// assert_eq!(ivory.shininess(), 50);
    /// assert_eq!(
    ///     Material::new(Rgb::WHITE, 1.0, 0.0, 0, 0.0),
    ///     Err(Error::OutOfRange { quantity: Quantity::Shininess, min: Fx::ONE, max: Fx::from_num(4096) })
    /// );
    /// # Ok::<(), Error>(())
    /// ```
    pub fn new(
        colour: Rgb,
        diffuse: f32,
        specular: f32,
        shininess: u16,
        reflect: f32,
    ) -> Result<Self, Error> {
        let weight = |value, max, quantity| check::f32_within(value, Fx::ZERO, max, quantity);
        Material::from_fx(
            colour,
            weight(diffuse, MAX_DIFFUSE, Quantity::DiffuseWeight)?,
            weight(specular, MAX_SPECULAR, Quantity::SpecularWeight)?,
            shininess,
            weight(reflect, Fx::ONE, Quantity::Reflectivity)?,
        )
    }

    /// [`Material::new`] in fixed point, for `const` and `static` scenes: the same checks, at
    /// compile time when the values are constants.
    pub const fn from_fx(
        colour: Rgb,
        diffuse: Fx,
        specular: Fx,
        shininess: u16,
        reflect: Fx,
    ) -> Result<Self, Error> {
        let weights = [
            (diffuse, MAX_DIFFUSE, Quantity::DiffuseWeight),
            (specular, MAX_SPECULAR, Quantity::SpecularWeight),
            (reflect, Fx::ONE, Quantity::Reflectivity),
        ];
        let mut i = 0;
        while i < weights.len() {
            let (value, max, quantity) = weights[i];
            if let Err(e) = check::within(value, Fx::ZERO, max, quantity) {
                return Err(e);
            }
            i += 1;
        }
        // A u16 may exceed Q16.16's 32 767, so the exponent is compared as an integer; its
        // bounds, 1 and 4096, are whole Q16.16 values for the error.
        if shininess < 1 || shininess > MAX_SHININESS {
            return Err(Error::OutOfRange {
                quantity: Quantity::Shininess,
                min: Fx::ONE,
                max: Fx::const_from_int(MAX_SHININESS as i32),
            });
        }
        if reflect.to_bits() != 0 && !MIRRORS_AND_GLASS {
            return Err(Error::MirrorsAndGlassLeftOut);
        }
        Ok(Material {
            colour,
            diffuse,
            specular,
            shininess,
            highlight_from: least_lit_base(shininess),
            reflect,
            refraction: None,
            checker: None,
        })
    }

    /// The same material with a checkerboard of `size`-wide squares (above 0, at most
    /// [`LIMIT`](crate::LIMIT)) alternating its colour with `other`.
    pub fn with_checker(self, size: f32, other: Rgb) -> Result<Self, Error> {
        self.with_checker_fx(
            check::f32_within(size, Fx::DELTA, crate::LIMIT, Quantity::CheckerSize)?,
            other,
        )
    }

    /// [`Material::with_checker`] in fixed point, for `const` and `static` scenes.
    pub const fn with_checker_fx(self, size: Fx, other: Rgb) -> Result<Self, Error> {
        // Above zero: the smallest Q16.16 value above it is one step.
        if let Err(e) = check::within(size, Fx::DELTA, crate::LIMIT, Quantity::CheckerSize) {
            return Err(e);
        }
        let mut material = self;
        material.checker = Some(Checker {
            size,
            other,
            shift: power_of_two(size),
        });
        Ok(material)
    }

    /// The same material, transparent: `weight` (above 0, at most 1) of what a ray refracted
    /// through the surface sees is added, bent by Snell's law for the refractive `index`
    /// (¼ to 4; the medium outside counts as 1).
    ///
    /// A ray entering a sphere bends by `1/index` and meets the same sphere from inside, where
    /// it bends by `index` on leaving; where Snell's law has no solution there (total internal
    /// reflection) the weight goes to the mirror ray, which stays inside. A plane is a sheet
    /// with no thickness: light passes through it undeviated. Shadow rays are stopped by
    /// transparent objects as by any other (tinyraytracer's choice), and, as for any object, a
    /// sphere does not shadow itself, on its inside either; see
    /// [`Scene::trace`](crate::Scene::trace) for the ray tree and its depth.
    ///
    /// ```
    /// use fixray::{Material, Rgb};
    /// // tinyraytracer's glass: a faint mirror, a sharp highlight, 0.8 of the light through.
    /// let glass = Material::new(Rgb::new(153, 179, 204), 0.0, 0.5, 125, 0.1)?
    ///     .with_refraction(1.5, 0.8)?;
    /// assert_eq!(glass.refraction().map(|r| r.index()), Some(fixray::Fx::from_num(1.5)));
    /// assert!(Material::matte(Rgb::WHITE).with_refraction(0.1, 0.5).is_err());
    /// # Ok::<(), fixray::Error>(())
    /// ```
    pub fn with_refraction(self, index: f32, weight: f32) -> Result<Self, Error> {
        self.with_refraction_fx(
            check::f32_within(index, MIN_INDEX, MAX_INDEX, Quantity::RefractiveIndex)?,
            check::f32_within(weight, Fx::DELTA, Fx::ONE, Quantity::Refraction)?,
        )
    }

    /// [`Material::with_refraction`] in fixed point, for `const` and `static` scenes.
    pub const fn with_refraction_fx(self, index: Fx, weight: Fx) -> Result<Self, Error> {
        if let Err(e) = check::within(index, MIN_INDEX, MAX_INDEX, Quantity::RefractiveIndex) {
            return Err(e);
        }
        if let Err(e) = check::within(weight, Fx::DELTA, Fx::ONE, Quantity::Refraction) {
            return Err(e);
        }
        if !MIRRORS_AND_GLASS {
            return Err(Error::MirrorsAndGlassLeftOut);
        }
        // index in [¼, 4], raw in [2¹⁴, 2¹⁸]: 2³²/index lies in [2¹⁴, 2¹⁸] too, and
        // |index − 1| < index + 1, so the quotient below is under 1.
        let raw = index.to_bits() as i64;
        let inverse = Fx::from_bits((((1i64 << 32) + raw / 2) / raw) as i32);
        let (below, above) = (raw - (1 << 16), raw + (1 << 16));
        let q = ((below << 16) + above / 2).div_euclid(above);
        let r0 = Fx::from_bits(((q * q + (1 << 15)) >> 16) as i32);
        let mut material = self;
        material.refraction = Some(Refraction {
            weight,
            index,
            inverse,
            r0,
            fresnel: false,
        });
        Ok(material)
    }

    /// The same material with its refraction weight split by Schlick's approximation of
    /// Fresnel's equations: at an angle `θ` to the normal a share
    /// `F = R₀ + (1 − R₀)(1 − cos θ)⁵`, `R₀ = ((η − 1)/(η + 1))²`, of the weight goes to the
    /// mirror ray and the rest, `1 − F`, through the surface (`θ` is the larger of the two
    /// angles, the one on the side of the lower index). Without refraction it changes nothing.
    #[must_use]
    pub const fn with_fresnel(self) -> Self {
        let mut material = self;
        if let Some(refraction) = &mut material.refraction {
            refraction.fresnel = true;
        }
        material
    }

    /// How the surface refracts, if it is transparent.
    #[must_use]
    pub const fn refraction(&self) -> Option<Refraction> {
        self.refraction
    }

    /// The surface colour under full white light.
    #[must_use]
    pub const fn colour(&self) -> Rgb {
        self.colour
    }

    /// Weight of the diffuse (Lambert) term, 0 to 2.
    #[must_use]
    pub const fn diffuse(&self) -> Fx {
        self.diffuse
    }

    /// Weight of the specular (Blinn-Phong) highlight, 0 to 16.
    #[must_use]
    pub const fn specular(&self) -> Fx {
        self.specular
    }

    /// Specular exponent, 1 to 4096: larger is a smaller, sharper highlight.
    #[must_use]
    pub const fn shininess(&self) -> u16 {
        self.shininess
    }

    /// Share of the mirror image added, 0 to 1.
    #[must_use]
    pub const fn reflect(&self) -> Fx {
        self.reflect
    }

    /// The checkerboard that alternates the colour with another, for planes, if any.
    #[must_use]
    pub const fn checker(&self) -> Option<Checker> {
        self.checker
    }
}

/// The largest diffuse weight [`Material::new`] accepts.
const MAX_DIFFUSE: Fx = Fx::const_from_int(2);
/// The largest specular weight [`Material::new`] accepts.
const MAX_SPECULAR: Fx = Fx::const_from_int(16);
/// The refractive indices [`Material::with_refraction`] accepts: past them Snell's law bends
/// rays so far that nothing but total internal reflection is left to draw.
const MIN_INDEX: Fx = Fx::from_bits(1 << 14);
const MAX_INDEX: Fx = Fx::const_from_int(4);

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
#[derive(Clone, Copy, PartialEq, Eq)]
pub struct Checker {
    size: Fx,
    other: Rgb,
    /// `k` where `size` is `2^k` raw units, [`NOT_A_POWER`] otherwise: then a square's index
    /// is a shift, where a division is a library call.
    shift: u8,
}

/// [`Checker`]'s `shift` for a size that is not a power of two.
const NOT_A_POWER: u8 = u8::MAX;

/// `k` for a raw `size` of `2^k`, [`NOT_A_POWER`] for any other.
const fn power_of_two(size: Fx) -> u8 {
    let raw = size.to_bits();
    if raw > 0 && raw & (raw - 1) == 0 {
        raw.trailing_zeros() as u8
    } else {
        NOT_A_POWER
    }
}

// Written out so that it shows what the checker is, not the shift it keeps to find squares.
impl core::fmt::Debug for Checker {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Checker")
            .field("size", &self.size)
            .field("other", &self.other)
            .finish()
    }
}

impl Checker {
    /// Side of a square, in world units.
    #[must_use]
    pub const fn size(&self) -> Fx {
        self.size
    }

    /// The colour of the odd squares.
    #[must_use]
    pub const fn other(&self) -> Rgb {
        self.other
    }

    /// `⌊c / size⌋`, the index of the squares' row or column that coordinate `c` lies in;
    /// with `SHIFTS`, by an arithmetic shift where the size is a power of two. Shifts are
    /// taken only where a division is a library call (the Cortex-M0): elsewhere it is one
    /// instruction, and the test for a power would cost more. Both forms are compiled
    /// everywhere, so the host tests check them.
    fn index<const SHIFTS: bool>(&self, c: Fx) -> i32 {
        if SHIFTS && self.shift != NOT_A_POWER {
            c.to_bits() >> self.shift
        } else {
            // Positive, as its constructor checked; `max` keeps the division visibly safe. A
            // positive divisor cannot overflow a 32-bit division, which every chip fixray
            // targets does in hardware or in a short routine (a 64-bit one is a long call).
            c.to_bits().div_euclid(self.size.to_bits().max(1))
        }
    }

    /// The colour of the square at plane coordinates `uv`.
    #[must_use]
    pub fn colour_at(&self, even: Rgb, uv: [Fx; 2]) -> Rgb {
        // The sum's parity survives wrapping.
        let index = |c: Fx| self.index::<{ fx::NO_DIVIDE }>(c);
        if index(uv[0]).wrapping_add(index(uv[1])) & 1 == 0 {
            even
        } else {
            self.other
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mirrors_and_glass_are_refused_only_without_their_feature() {
        let mirror = Material::from_fx(Rgb::WHITE, Fx::ZERO, Fx::ZERO, 1, Fx::from_num(0.5));
        let glass = Material::matte(Rgb::WHITE).with_refraction_fx(Fx::from_num(1.5), Fx::ONE);
        if cfg!(feature = "mirrors-and-glass") {
            assert!(mirror.is_ok_and(|m| m.sends_rays()));
            assert!(glass.is_ok_and(|m| m.sends_rays()));
        } else {
            assert_eq!(mirror, Err(Error::MirrorsAndGlassLeftOut));
            assert_eq!(glass, Err(Error::MirrorsAndGlassLeftOut));
        }
        // A value out of range is named as such in either build; a matte surface is not refused.
        let too_bright = Material::from_fx(Rgb::WHITE, Fx::ZERO, Fx::ZERO, 1, Fx::from_num(2));
        assert!(matches!(
            too_bright,
            Err(Error::OutOfRange {
                quantity: Quantity::Reflectivity,
                ..
            })
        ));
        let matte = Material::from_fx(Rgb::WHITE, Fx::ONE, Fx::ONE, 8, Fx::ZERO);
        assert!(matte.is_ok_and(|m| !m.sends_rays()));
    }

    #[test]
    fn a_checker_shows_its_size_and_other_colour() {
        extern crate std;
        let checker = Material::matte(Rgb::WHITE)
            .with_checker_fx(Fx::from_num(2), Rgb::BLACK)
            .unwrap()
            .checker()
            .unwrap();
        assert_eq!(
            std::format!("{checker:?}"),
            std::format!(
                "Checker {{ size: {:?}, other: {:?} }}",
                Fx::from_num(2),
                Rgb::BLACK
            )
        );
    }

    #[test]
    fn checker_squares_are_those_of_the_exact_floor_division() {
        // Any side a checker takes (2⁻¹⁶ to 1024) and any coordinate, signs and ends included.
        let (even, odd) = (Rgb::WHITE, Rgb::BLACK);
        let mut rng = crate::xorshift::XorShift(0x00c4_ec4e_75a1_2e00);
        let mut sizes = [
            1,
            2,
            3,
            0xFFFF,
            1 << 16,
            1 << 17,
            3 << 15,
            (1 << 26) - 1,
            1 << 26,
        ]
        .to_vec();
        let mut coordinates = [0, 1, -1, i32::MIN, i32::MAX, 1 << 17, -(1 << 17)].to_vec();
        for _ in 0..200 {
            let seed = rng.next();
            sizes.push(
                ((seed as i32) >> (seed >> 59))
                    .unsigned_abs()
                    .clamp(1, 1 << 26) as i32,
            );
            coordinates.push((seed >> 32) as i32 >> (seed >> 59 & 15));
        }
        for &size in &sizes {
            let checker = Material::matte(even)
                .with_checker_fx(Fx::from_bits(size), odd)
                .unwrap()
                .checker()
                .unwrap();
            for &u in &coordinates {
                for &v in coordinates.iter().step_by(3) {
                    let index = |c: i32| (c as i64).div_euclid(size as i64);
                    let expected = if (index(u) + index(v)) % 2 == 0 {
                        even
                    } else {
                        odd
                    };
                    let uv = [Fx::from_bits(u), Fx::from_bits(v)];
                    assert_eq!(checker.colour_at(even, uv), expected, "{u} {v} / {size}");
                    // Both ways to an index, whichever this chip takes.
                    let c = Fx::from_bits(u);
                    assert_eq!(checker.index::<true>(c) as i64, index(u), "{u} / {size}");
                    assert_eq!(checker.index::<false>(c) as i64, index(u), "{u} / {size}");
                }
            }
        }
    }
}
