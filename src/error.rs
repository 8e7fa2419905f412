//! The crate's one error type, and the names of what it refuses.

use core::fmt;

use crate::numbers::fx::{Fx, LIMIT};

/// Why fixray refused an input.
///
/// Every constructor that takes user values checks them and returns one of these instead of
/// panicking, wrapping or dividing by zero later in the render path. Each variant names the
/// problem as data ([`Quantity`], [`CameraProblem`], sizes and indices), so a caller can tell
/// one refusal from another without reading its message.
///
/// ```
/// use fixray::{CameraProblem, Error, Fx, LIMIT, Light, Quantity};
/// let dim = Light::new([0.0; 3], 5.0);
/// assert_eq!(
///     dim,
///     Err(Error::OutOfRange { quantity: Quantity::LightIntensity, min: Fx::ZERO, max: Fx::from_num(4) })
/// );
/// assert_eq!(dim.unwrap_err().to_string(), "light intensity is outside 0 to 4");
///
/// let far = Light::new([0.0, 2000.0, 0.0], 1.0).unwrap_err();
/// assert_eq!(far.to_string(), "light position is outside the overflow-safe range ±1024");
///
/// let blind = Error::DegenerateCamera(CameraProblem::TargetIsEye);
/// assert_eq!(blind.to_string(), "degenerate camera: target is the eye");
///
/// // A positive length: from the smallest Q16.16 value above zero.
/// let near = Error::OutOfRange { quantity: Quantity::ScreenDistance, min: Fx::DELTA, max: LIMIT };
/// assert_eq!(near.to_string(), "screen distance is outside 2⁻¹⁶ (one Q16.16 step) to 1024");
///
/// let short = Error::BufferLength { needed: 40, got: 39 };
/// assert_eq!(short.to_string(), "row buffer holds 39 pixels where a row of the picture has 40");
/// ```
#[derive(Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Error {
    /// A float input was NaN or infinite.
    NotFinite {
        /// The quantity that was not finite.
        quantity: Quantity,
    },
    /// A value lies outside its range: `min ..= max`, both included, compared as the value
    /// was rounded to Q16.16.
    ///
    /// Coordinates must lie within ±[`LIMIT`](crate::LIMIT), the overflow-safe range; weights,
    /// intensities and sizes have ranges of their own (each constructor documents its ranges).
    /// An integer quantity (shininess) has its integer bounds here. A range open at zero,
    /// such as a length that must be positive, starts at [`Fx::DELTA`], the smallest Q16.16
    /// value above zero.
    OutOfRange {
        /// The quantity that was out of range.
        quantity: Quantity,
        /// The smallest value allowed.
        min: Fx,
        /// The largest value allowed.
        max: Fx,
    },
    /// A sphere radius was zero or negative.
    NonPositiveRadius,
    /// A vector that must have a direction (a plane's normal, a ray's direction) was zero.
    ZeroVector {
        /// The vector that was zero.
        quantity: Quantity,
    },
    /// Plane bounds that enclose nothing: `min` must lie below `max` on both axes.
    EmptyBounds,
    /// A material that mirrors or refracts, in a build of fixray without its
    /// `mirrors-and-glass` feature (on by default), which leaves the secondary rays' code out.
    MirrorsAndGlassLeftOut,
    /// A scene or light list is full; the capacity is in its type.
    CapacityExceeded {
        /// The capacity that was reached.
        capacity: usize,
    },
    /// Camera parameters that do not define a view.
    DegenerateCamera(CameraProblem),
    /// A field of view too narrow for a camera's number of rows: its rays could not tell its
    /// pixels apart to within half a pixel.
    FieldOfViewTooNarrow {
        /// The narrowest vertical field of view allowed for that screen, in thousandths of a
        /// degree: for [`Camera::look_at`](crate::Camera::look_at) and
        /// [`Camera::orbit`](crate::Camera::orbit), the narrowest whole number of thousandths
        /// the same camera accepts; for a pinhole, which takes no field of view, the budget's
        /// limit rounded up.
        min_millidegrees: u32,
    },
    /// A field of view too wide for a camera's screen: the rays near its edges would be
    /// rounded by more than half a pixel.
    FieldOfViewTooWide {
        /// The widest vertical field of view allowed for that screen, in thousandths of a
        /// degree: for [`Camera::look_at`](crate::Camera::look_at) and
        /// [`Camera::orbit`](crate::Camera::orbit), the widest whole number of thousandths the
        /// same camera accepts; for a pinhole, which takes no field of view, the budget's
        /// limit rounded down.
        max_millidegrees: u32,
    },
    /// An object index past the last object of a scene.
    NoSuchObject {
        /// The index asked for.
        index: usize,
        /// How many objects the scene has.
        count: usize,
    },
    /// A light index past the last light of a scene.
    NoSuchLight {
        /// The index asked for.
        index: usize,
        /// How many lights the scene has.
        count: usize,
    },
    /// A column past the right edge of the camera's picture.
    ColumnOutOfRange {
        /// The column asked for.
        col: u32,
        /// The columns the camera has (valid columns are `0..cols`).
        cols: u32,
    },
    /// A display row past the bottom of the camera's picture.
    RowOutOfRange {
        /// The row asked for.
        row: u32,
        /// The rows the camera has (valid rows are `0..rows`).
        rows: u32,
    },
    /// A camera and a framebuffer of different sizes.
    SizeMismatch {
        /// Columns and rows the camera was built for.
        camera: (u16, u16),
        /// Columns and rows of the target.
        target: (u16, u16),
    },
    /// A row buffer of the wrong length for the camera's rows: rendering one row needs a
    /// buffer of exactly one row, drawing in bands one of at least one row.
    BufferLength {
        /// The length one row needs: the camera's columns.
        needed: usize,
        /// The buffer's length.
        got: usize,
    },
    /// A progressive render's coarsest spacing that is not a power of two from 1 to
    /// [`MAX_SPACING`](crate::MAX_SPACING) pixels.
    PassSpacing {
        /// The spacing asked for.
        spacing: u16,
    },
}

/// The quantities fixray checks, as named by [`Error`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Quantity {
    /// A sphere's centre.
    SphereCentre,
    /// A sphere's radius.
    SphereRadius,
    /// The point a plane passes through.
    PlanePoint,
    /// The direction a plane faces.
    PlaneNormal,
    /// The corners of a bounded plane's rectangle.
    PlaneBounds,
    /// Where a light is.
    LightPosition,
    /// How strongly a light lights.
    LightIntensity,
    /// A scene's ambient light.
    Ambient,
    /// A material's diffuse weight.
    DiffuseWeight,
    /// A material's specular weight.
    SpecularWeight,
    /// A material's shininess (Phong exponent).
    Shininess,
    /// A material's reflectivity.
    Reflectivity,
    /// A material's refraction weight: the share of light that passes through it.
    Refraction,
    /// A material's refractive index.
    RefractiveIndex,
    /// The side of a checkerboard's squares.
    CheckerSize,
    /// Where a ray starts.
    RayOrigin,
    /// Where a ray goes.
    RayDirection,
    /// Where a camera's eye is.
    CameraEye,
    /// What a camera looks at.
    CameraTarget,
    /// A camera's up direction.
    CameraUp,
    /// A camera's vertical field of view.
    FieldOfView,
    /// A pinhole camera's screen width, in world units.
    ScreenWidth,
    /// A pinhole camera's screen height, in world units.
    ScreenHeight,
    /// How far a pinhole camera's screen is from its eye.
    ScreenDistance,
    /// A pinhole camera's pixel width: its screen width over its columns.
    PixelWidth,
    /// A pinhole camera's pixel height: its screen height over its rows.
    PixelHeight,
    /// How far an orbiting camera is from its target.
    OrbitDistance,
    /// The turn of an orbiting camera about the vertical.
    OrbitYaw,
    /// The height of an orbiting camera above the horizon, as an angle.
    OrbitPitch,
}

impl fmt::Display for Quantity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Quantity::SphereCentre => "sphere centre",
            Quantity::SphereRadius => "sphere radius",
            Quantity::PlanePoint => "plane point",
            Quantity::PlaneNormal => "plane normal",
            Quantity::PlaneBounds => "plane bounds",
            Quantity::LightPosition => "light position",
            Quantity::LightIntensity => "light intensity",
            Quantity::Ambient => "ambient light",
            Quantity::DiffuseWeight => "diffuse weight",
            Quantity::SpecularWeight => "specular weight",
            Quantity::Shininess => "shininess",
            Quantity::Reflectivity => "reflectivity",
            Quantity::Refraction => "refraction weight",
            Quantity::RefractiveIndex => "refractive index",
            Quantity::CheckerSize => "checker size",
            Quantity::RayOrigin => "ray origin",
            Quantity::RayDirection => "ray direction",
            Quantity::CameraEye => "camera eye",
            Quantity::CameraTarget => "camera target",
            Quantity::CameraUp => "camera up",
            Quantity::FieldOfView => "field of view",
            Quantity::ScreenWidth => "screen width",
            Quantity::ScreenHeight => "screen height",
            Quantity::ScreenDistance => "screen distance",
            Quantity::PixelWidth => "pixel width (screen width / cols)",
            Quantity::PixelHeight => "pixel height (screen height / rows)",
            Quantity::OrbitDistance => "orbit distance",
            Quantity::OrbitYaw => "orbit yaw",
            Quantity::OrbitPitch => "orbit pitch",
        })
    }
}

/// What makes camera parameters fail to define a view, as named by
/// [`Error::DegenerateCamera`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum CameraProblem {
    /// No columns or no rows.
    NoPixels,
    /// More than [`MAX_PIXELS`](crate::MAX_PIXELS) columns or rows.
    TooManyPixels,
    /// Pixels more than four times taller than wide, or wider than tall.
    PixelAspect,
    /// A screen more than 16 384 pixels across its diagonal (its pixels stretched tall): no
    /// view distance keeps its rays within half a pixel.
    DiagonalTooLong,
    /// A field of view not strictly between 0° and 180°.
    FieldOfView,
    /// The target is the eye, so there is no view direction.
    TargetIsEye,
    /// Up is the zero vector.
    UpIsZero,
    /// Up is parallel to the view direction (within about 0.2°), so it does not say which way
    /// the picture's top is.
    UpAlongView,
    /// An orbit's pitch not strictly between −90° and 90°.
    OrbitPitch,
}

impl fmt::Display for CameraProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            CameraProblem::NoPixels => "the screen has no pixels",
            CameraProblem::TooManyPixels => "the screen is wider or taller than 4096 pixels",
            CameraProblem::PixelAspect => {
                "pixels more than four times taller than wide, or wider than tall"
            }
            CameraProblem::DiagonalTooLong => {
                "the screen is more than 16 384 pixels across its diagonal (pixels too tall)"
            }
            CameraProblem::FieldOfView => {
                "field of view must lie strictly between 0 and 180 degrees"
            }
            CameraProblem::TargetIsEye => "target is the eye",
            CameraProblem::UpIsZero => "up is the zero vector",
            CameraProblem::UpAlongView => "up is parallel to the view direction",
            CameraProblem::OrbitPitch => "orbit pitch must lie strictly between -90 and 90 degrees",
        })
    }
}

/// Writes the range `min ..= max` as the messages state it: the overflow-safe range by name,
/// a symmetric range as `±max`, and the smallest positive Q16.16 value as `2⁻¹⁶`.
fn write_range(f: &mut fmt::Formatter<'_>, min: Fx, max: Fx) -> fmt::Result {
    let (min, max, limit) = (Decimal(min), Decimal(max), Decimal(LIMIT));
    if min.0 == -LIMIT && max.0 == LIMIT {
        write!(f, "the overflow-safe range ±{limit}")
    } else if min.0 == -max.0 {
        write!(f, "±{max}")
    } else if min.0 == Fx::DELTA {
        write!(f, "2⁻¹⁶ (one Q16.16 step) to {max}")
    } else {
        write!(f, "{min} to {max}")
    }
}

/// As `#[derive(Debug)]` writes it, with each Q16.16 bound written to at most five decimals.
// A variant's name and fields from one table walked by one `debug_struct`, rather than a chain
// of calls a variant as a derive writes: the same text in much less code, which every
// firmware that reports an error carries.
impl fmt::Debug for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        type Fields<'a> = &'a [(&'a str, &'a dyn fmt::Debug)];
        let (name, fields): (&str, Fields<'_>) = match self {
            Error::NotFinite { quantity } => ("NotFinite", &[("quantity", quantity)]),
            Error::OutOfRange { quantity, min, max } => (
                "OutOfRange",
                &[
                    ("quantity", quantity),
                    ("min", &Decimal(*min)),
                    ("max", &Decimal(*max)),
                ],
            ),
            Error::NonPositiveRadius => ("NonPositiveRadius", &[]),
            Error::ZeroVector { quantity } => ("ZeroVector", &[("quantity", quantity)]),
            Error::EmptyBounds => ("EmptyBounds", &[]),
            Error::MirrorsAndGlassLeftOut => ("MirrorsAndGlassLeftOut", &[]),
            Error::CapacityExceeded { capacity } => ("CapacityExceeded", &[("capacity", capacity)]),
            Error::DegenerateCamera(problem) => {
                return f.debug_tuple("DegenerateCamera").field(problem).finish();
            }
            Error::FieldOfViewTooNarrow { min_millidegrees } => (
                "FieldOfViewTooNarrow",
                &[("min_millidegrees", min_millidegrees)],
            ),
            Error::FieldOfViewTooWide { max_millidegrees } => (
                "FieldOfViewTooWide",
                &[("max_millidegrees", max_millidegrees)],
            ),
            Error::NoSuchObject { index, count } => {
                ("NoSuchObject", &[("index", index), ("count", count)])
            }
            Error::NoSuchLight { index, count } => {
                ("NoSuchLight", &[("index", index), ("count", count)])
            }
            Error::ColumnOutOfRange { col, cols } => {
                ("ColumnOutOfRange", &[("col", col), ("cols", cols)])
            }
            Error::RowOutOfRange { row, rows } => {
                ("RowOutOfRange", &[("row", row), ("rows", rows)])
            }
            Error::SizeMismatch { camera, target } => {
                ("SizeMismatch", &[("camera", camera), ("target", target)])
            }
            Error::BufferLength { needed, got } => {
                ("BufferLength", &[("needed", needed), ("got", got)])
            }
            Error::PassSpacing { spacing } => ("PassSpacing", &[("spacing", spacing)]),
        };
        if fields.is_empty() {
            return f.write_str(name);
        }
        let mut out = f.debug_struct(name);
        for (field, value) in fields {
            out.field(field, value);
        }
        out.finish()
    }
}

/// A Q16.16 value written (by `Display` and `Debug` alike) to five decimals, rounded to
/// nearest, trailing zeros dropped: as Q16.16 values lie at least 2⁻¹⁶ > 10⁻⁵ apart, no two
/// write the same. The errors' own formatting: the `fixed` crate's formatter is long code on
/// a microcontroller, which every firmware that writes an error would carry.
struct Decimal(Fx);

impl fmt::Debug for Decimal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

impl fmt::Display for Decimal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let raw = self.0.to_bits();
        // At most 2³¹ · 10⁵ before the shift: well within 64 bits.
        let scaled = (raw.unsigned_abs() as u64 * 100_000 + (1 << 15)) >> 16;
        let (whole, mut fraction) = (scaled / 100_000, (scaled % 100_000) as u32);
        let sign = if raw < 0 && scaled != 0 { "-" } else { "" };
        write!(f, "{sign}{whole}")?;
        if fraction != 0 {
            let mut digits = 5;
            while fraction % 10 == 0 {
                fraction /= 10;
                digits -= 1;
            }
            write!(f, ".{fraction:0digits$}")?;
        }
        Ok(())
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::NotFinite { quantity } => write!(f, "{quantity} is NaN or infinite"),
            Error::OutOfRange { quantity, min, max } => {
                write!(f, "{quantity} is outside ")?;
                write_range(f, *min, *max)
            }
            Error::NonPositiveRadius => write!(f, "sphere radius must be greater than zero"),
            Error::ZeroVector { quantity } => write!(f, "{quantity} is the zero vector"),
            Error::EmptyBounds => {
                write!(
                    f,
                    "plane bounds enclose nothing: min must lie below max on both axes"
                )
            }
            Error::MirrorsAndGlassLeftOut => write!(
                f,
                "a mirror or glass material needs fixray's mirrors-and-glass feature, which this build leaves out"
            ),
            Error::CapacityExceeded { capacity } => {
                write!(f, "capacity of {capacity} is already used")
            }
            Error::DegenerateCamera(problem) => write!(f, "degenerate camera: {problem}"),
            Error::FieldOfViewTooNarrow { min_millidegrees } => write!(
                f,
                "field of view too narrow for this screen: at least {}.{:03} degrees",
                min_millidegrees / 1000,
                min_millidegrees % 1000
            ),
            Error::FieldOfViewTooWide { max_millidegrees } => write!(
                f,
                "field of view too wide for this screen: at most {}.{:03} degrees",
                max_millidegrees / 1000,
                max_millidegrees % 1000
            ),
            Error::NoSuchObject { index, count } => {
                write!(f, "object {index} does not exist: the scene has {count}")
            }
            Error::NoSuchLight { index, count } => {
                write!(f, "light {index} does not exist: the scene has {count}")
            }
            Error::ColumnOutOfRange { col, cols } => {
                write!(f, "column {col} is outside the picture's {cols} columns")
            }
            Error::RowOutOfRange { row, rows } => {
                write!(f, "row {row} is outside the picture's {rows} rows")
            }
            Error::SizeMismatch { camera, target } => write!(
                f,
                "camera is {}x{} pixels but the target is {}x{}",
                camera.0, camera.1, target.0, target.1
            ),
            Error::BufferLength { needed, got } => write!(
                f,
                "row buffer holds {got} pixels where a row of the picture has {needed}"
            ),
            Error::PassSpacing { spacing } => write!(
                f,
                "a progressive render's coarsest spacing is {spacing} pixels, not a power of two \
                 from 1 to {}",
                crate::MAX_SPACING
            ),
        }
    }
}

impl core::error::Error for Error {}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::format;

    /// Every value writes a decimal that reads back as that value, to at most five decimals.
    #[test]
    fn decimals_read_back_as_the_values_written() {
        let mut rng = crate::xorshift::XorShift(0xdec1_0a15_0000_0001);
        let near_zero = -300_000..300_000;
        let anywhere = (0..300_000).map(|_| (rng.next() >> 32) as i32);
        let ends = [
            i32::MIN,
            i32::MIN + 1,
            i32::MAX,
            i32::MAX - 1,
            1 << 16,
            -(1 << 16),
        ];
        for raw in near_zero.chain(anywhere).chain(ends) {
            let text = format!("{}", Decimal(Fx::from_bits(raw)));
            let read: f64 = text.parse().unwrap();
            assert_eq!(
                (read * 65536.0).round() as i64,
                raw as i64,
                "{raw} wrote {text}"
            );
            let decimals = text.split_once('.').map_or(0, |(_, d)| d.len());
            assert!(
                decimals <= 5 && !text.ends_with('0') || decimals == 0,
                "{text}"
            );
            assert_ne!(text, "-0");
        }
        assert_eq!(format!("{}", Decimal(Fx::DELTA)), "0.00002");
        assert_eq!(format!("{:?}", Decimal(-Fx::from_num(0.5))), "-0.5");
        assert_eq!(format!("{}", Decimal(-LIMIT)), "-1024");
    }

    #[test]
    fn debug_writes_what_a_derive_would_with_decimal_bounds() {
        let error = Error::OutOfRange {
            quantity: Quantity::LightIntensity,
            min: Fx::ZERO,
            max: Fx::from_num(2.5),
        };
        assert_eq!(
            format!("{error:?}"),
            "OutOfRange { quantity: LightIntensity, min: 0, max: 2.5 }"
        );
        let row = Error::RowOutOfRange { row: 9, rows: 8 };
        assert_eq!(format!("{row:?}"), "RowOutOfRange { row: 9, rows: 8 }");
        assert_eq!(format!("{:?}", Error::EmptyBounds), "EmptyBounds");
        let camera = Error::DegenerateCamera(CameraProblem::NoPixels);
        assert_eq!(format!("{camera:?}"), "DegenerateCamera(NoPixels)");
        let sizes = Error::SizeMismatch {
            camera: (4, 3),
            target: (8, 6),
        };
        assert_eq!(
            format!("{sizes:?}"),
            "SizeMismatch { camera: (4, 3), target: (8, 6) }"
        );
        // Every other variant, each field under its own name.
        let quantity = Quantity::SphereRadius;
        let rest = [
            (
                Error::NotFinite { quantity },
                "NotFinite { quantity: SphereRadius }",
            ),
            (Error::NonPositiveRadius, "NonPositiveRadius"),
            (Error::MirrorsAndGlassLeftOut, "MirrorsAndGlassLeftOut"),
            (
                Error::ZeroVector { quantity },
                "ZeroVector { quantity: SphereRadius }",
            ),
            (
                Error::CapacityExceeded { capacity: 8 },
                "CapacityExceeded { capacity: 8 }",
            ),
            (
                Error::FieldOfViewTooNarrow {
                    min_millidegrees: 17,
                },
                "FieldOfViewTooNarrow { min_millidegrees: 17 }",
            ),
            (
                Error::FieldOfViewTooWide {
                    max_millidegrees: 170_000,
                },
                "FieldOfViewTooWide { max_millidegrees: 170000 }",
            ),
            (
                Error::NoSuchObject { index: 3, count: 2 },
                "NoSuchObject { index: 3, count: 2 }",
            ),
            (
                Error::NoSuchLight { index: 5, count: 1 },
                "NoSuchLight { index: 5, count: 1 }",
            ),
            (
                Error::ColumnOutOfRange { col: 7, cols: 6 },
                "ColumnOutOfRange { col: 7, cols: 6 }",
            ),
            (
                Error::BufferLength {
                    needed: 40,
                    got: 39,
                },
                "BufferLength { needed: 40, got: 39 }",
            ),
            (
                Error::PassSpacing { spacing: 3 },
                "PassSpacing { spacing: 3 }",
            ),
        ];
        for (error, text) in rest {
            assert_eq!(format!("{error:?}"), text);
        }
        // The alternate form, as a derive's.
        assert_eq!(
            format!("{:#?}", Error::NoSuchLight { index: 5, count: 1 }),
            "NoSuchLight {\n    index: 5,\n    count: 1,\n}"
        );
    }
}
