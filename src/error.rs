//! The crate's one error type.

use core::fmt;

/// Why fixray refused an input.
///
/// Every constructor that takes user values checks them and returns one of these instead of
/// panicking, wrapping or dividing by zero later in the render path.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Error {
    /// A float input was NaN or infinite.
    NotFinite {
        /// The quantity that was not finite.
        what: &'static str,
    },
    /// A value lies outside the range fixray documents as overflow-safe ([`LIMIT`](crate::LIMIT)).
    OutOfRange {
        /// The quantity that was out of range.
        what: &'static str,
        /// The range it must lie in.
        range: &'static str,
    },
    /// A sphere radius was zero or negative.
    NonPositiveRadius,
    /// A vector that must have a direction (a normal, a ray direction) was zero.
    ZeroVector {
        /// The vector that was zero.
        what: &'static str,
    },
    /// A scene or light list is full; the capacity is in its type.
    CapacityExceeded {
        /// The capacity that was reached.
        capacity: usize,
    },
    /// Camera parameters that do not define a view.
    DegenerateCamera {
        /// What is wrong with them.
        why: &'static str,
    },
    /// A field of view too narrow for a camera's number of rows: its rays could not tell its
    /// pixels apart to within half a pixel.
    FieldOfViewTooNarrow {
        /// The narrowest vertical field of view allowed for that screen, in thousandths of a
        /// degree (rounded up).
        min_millidegrees: u32,
    },
    /// A field of view too wide for a camera's screen: the rays near its edges would be
    /// rounded by more than half a pixel.
    FieldOfViewTooWide {
        /// The widest vertical field of view allowed for that screen, in thousandths of a
        /// degree (rounded down).
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
        col: u16,
        /// The columns the camera has (valid columns are `0..cols`).
        cols: u16,
    },
    /// A display row past the bottom of the camera's picture.
    RowOutOfRange {
        /// The row asked for.
        row: u16,
        /// The rows the camera has (valid rows are `0..rows`).
        rows: u16,
    },
    /// A camera and a framebuffer (or display area, or row buffer) of different sizes.
    SizeMismatch {
        /// Columns and rows the camera was built for.
        camera: (u16, u16),
        /// Columns and rows of the target.
        target: (u16, u16),
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::NotFinite { what } => write!(f, "{what} is NaN or infinite"),
            Error::OutOfRange { what, range } => write!(f, "{what} is outside {range}"),
            Error::NonPositiveRadius => write!(f, "sphere radius must be greater than zero"),
            Error::ZeroVector { what } => write!(f, "{what} is the zero vector"),
            Error::CapacityExceeded { capacity } => {
                write!(f, "capacity of {capacity} is already used")
            }
            Error::DegenerateCamera { why } => write!(f, "degenerate camera: {why}"),
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
        }
    }
}

impl core::error::Error for Error {}
