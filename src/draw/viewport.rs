//! [`Viewport`]: a scene rendered straight into a display rectangle, band by band.

use core::iter::FusedIterator;
use core::ops::Range;

use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::prelude::{Point, Size};
use embedded_graphics::primitives::Rectangle;

use super::color::{FromRgb, converted};
use super::error::DrawError;
use crate::error::Error;
use crate::render::camera::Camera;
use crate::render::rows::render_row;
use crate::scene::Scene;
use crate::scene::colour::Rgb;

/// A scene seen through a camera, placed on a rectangle of a display.
///
/// It renders rows with [`render_row`] into a buffer the caller supplies and pushes them with
/// one [`fill_contiguous`](DrawTarget::fill_contiguous) per band, so no frame is ever held:
/// the buffer is the renderer's RAM. Its length picks the band height: a buffer of `k` rows
/// sends `k` rows per call, and one row is enough.
///
/// The rectangle's size must equal the camera's; the rest of the display is left alone.
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
/// use embedded_graphics_simulator::SimulatorDisplay;
/// use fixray::{demo, FromRgb, Rgb, Viewport};
///
/// let mut display = SimulatorDisplay::<Rgb565>::new(Size::new(128, 96));
/// let (scene, camera) = (demo::scene(), demo::camera(64, 48)?);
/// // The lower right quarter of the display, drawn 16 rows at a time.
/// let view = Viewport::new(&scene, &camera, Rectangle::new(Point::new(64, 48), Size::new(64, 48)))?;
/// let mut band = [Rgb::BLACK; 64 * 16];
/// for rows in view.bands(16) {
///     view.render_rows(rows, &mut band, &mut display)?;
///     // ... poll buttons, feed the watchdog ...
/// }
/// let sky = Rgb565::from_rgb(demo::BACKGROUND, Point::zero());
/// assert_eq!(display.get_pixel(Point::new(64, 48)), sky);
/// assert_eq!(display.get_pixel(Point::new(0, 0)), Rgb565::BLACK);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Viewport<'a, const N: usize, const L: usize = 4> {
    scene: &'a Scene<N, L>,
    camera: &'a Camera,
    area: Rectangle,
}

impl<'a, const N: usize, const L: usize> Viewport<'a, N, L> {
    /// Places the camera's picture on `area` of a display.
    ///
    /// `area` must be exactly `camera.cols() × camera.rows()` pixels, and its far corner must
    /// be a representable display point; otherwise this is an error.
    pub fn new(scene: &'a Scene<N, L>, camera: &'a Camera, area: Rectangle) -> Result<Self, Error> {
        let (cols, rows) = (camera.cols(), camera.rows());
        if area.size != Size::new(cols.into(), rows.into()) {
            let clamp = |v: u32| v.min(u16::MAX.into()) as u16;
            return Err(Error::SizeMismatch {
                camera: (cols, rows),
                target: (clamp(area.size.width), clamp(area.size.height)),
            });
        }
        let fits = area.top_left.x.checked_add(cols.into()).is_some()
            && area.top_left.y.checked_add(rows.into()).is_some();
        if !fits {
            return Err(Error::OutOfRange {
                what: "viewport position",
                range: "display points whose far corner fits in i32",
            });
        }
        Ok(Viewport {
            scene,
            camera,
            area,
        })
    }

    /// The display rectangle the picture fills.
    #[must_use]
    pub const fn area(&self) -> Rectangle {
        self.area
    }

    /// Renders rows `rows` of the picture (0 is the viewport's top row) onto `display`.
    ///
    /// `buffer` must hold at least one row (`camera.cols()` pixels); each
    /// `fill_contiguous` call sends as many whole rows as it holds. Rows past the picture's
    /// last are an error, and an empty range draws nothing. The first driver error stops the
    /// render and is returned as [`DrawError::Display`], unchanged.
    pub fn render_rows<D>(
        &self,
        rows: Range<u16>,
        buffer: &mut [Rgb],
        display: &mut D,
    ) -> Result<(), DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: FromRgb,
    {
        let (cols, total) = (self.camera.cols(), self.camera.rows());
        if rows.end > total {
            return Err(Error::SizeMismatch {
                camera: (cols, total),
                target: (cols, rows.end),
            }
            .into());
        }
        let width = usize::from(cols);
        // Whole rows that fit the buffer (cols ≥ 1, so the division is never by zero).
        let band_rows = buffer
            .len()
            .checked_div(width)
            .unwrap_or(0)
            .min(usize::from(total));
        if band_rows == 0 {
            return Err(Error::SizeMismatch {
                camera: (cols, total),
                // Shorter than one row, so below u16::MAX.
                target: (buffer.len() as u16, 1),
            }
            .into());
        }
        let mut row = rows.start;
        while row < rows.end {
            // band_rows ≤ total, a u16.
            let n = (band_rows as u16).min(rows.end - row);
            for (line, r) in buffer.chunks_exact_mut(width).zip(row..row + n) {
                render_row(self.scene, self.camera, r, line)?;
            }
            // Inside i32: `new` checked the viewport's far corner.
            let top_left = self.area.top_left + Point::new(0, row.into());
            let area = Rectangle::new(top_left, Size::new(cols.into(), n.into()));
            let lines = buffer.chunks_exact(width).take(n.into());
            display
                .fill_contiguous(&area, converted(lines, top_left))
                .map_err(DrawError::Display)?;
            row += n;
        }
        Ok(())
    }

    /// Renders the whole picture: [`render_rows`](Self::render_rows) over every row.
    pub fn render<D>(&self, buffer: &mut [Rgb], display: &mut D) -> Result<(), DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: FromRgb,
    {
        self.render_rows(0..self.camera.rows(), buffer, display)
    }

    /// The picture's rows in bands of `rows_per_band` (the last may be shorter), for callers
    /// that do other work between bands. A band height of 0 counts as 1.
    ///
    /// ```
    /// use fixray::{demo, Viewport};
    /// use embedded_graphics::{prelude::*, primitives::Rectangle};
    /// let (scene, camera) = (demo::scene(), demo::camera(16, 10)?);
    /// let view = Viewport::new(&scene, &camera, Rectangle::new(Point::zero(), Size::new(16, 10)))?;
    /// assert_eq!(view.bands(4).collect::<Vec<_>>(), [0..4, 4..8, 8..10]);
    /// # Ok::<(), fixray::Error>(())
    /// ```
    #[must_use]
    pub fn bands(&self, rows_per_band: u16) -> Bands {
        Bands {
            next: 0,
            end: self.camera.rows(),
            step: rows_per_band.max(1),
        }
    }
}

/// Row ranges covering a picture, top to bottom: see [`Viewport::bands`].
#[derive(Debug, Clone)]
pub struct Bands {
    next: u16,
    end: u16,
    step: u16,
}

impl Iterator for Bands {
    type Item = Range<u16>;

    fn next(&mut self) -> Option<Range<u16>> {
        if self.next >= self.end {
            return None;
        }
        let start = self.next;
        self.next = start.saturating_add(self.step).min(self.end);
        Some(start..self.next)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = usize::from(self.end.saturating_sub(self.next)).div_ceil(usize::from(self.step));
        (left, Some(left))
    }
}

impl ExactSizeIterator for Bands {}

impl FusedIterator for Bands {}
