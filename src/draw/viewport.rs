//! [`Viewport`]: a scene rendered straight onto a display at a point, band by band, clipped
//! to the display.

use core::iter::FusedIterator;
use core::marker::PhantomData;
use core::ops::Range;

use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::prelude::{Dimensions, Point, Size};
use embedded_graphics::primitives::Rectangle;

use super::clip::visible;
use super::color::{FromRgb, converted};
use super::error::DrawError;
use super::picture::Picture;
use crate::error::Error;
use crate::render::camera::Camera;
use crate::render::changes::{Damage, render_row_span};
use crate::render::rows::render_row;
use crate::scene::Scene;
use crate::scene::colour::Rgb;

/// A scene seen through a camera, placed on a display with its top left pixel at a point.
///
/// The picture is the camera's size. It renders rows with [`render_row`] into a buffer the
/// caller supplies and pushes them with one [`fill_contiguous`](DrawTarget::fill_contiguous)
/// per band, so no frame is ever held: the buffer is the renderer's RAM. Its length picks the
/// band height: a buffer of `k` rows sends `k` rows per call, and one row is enough. For a
/// one-call draw with a buffer of its own, see [`Viewport::picture`].
///
/// The picture is clipped to the display's
/// [`bounding_box`](embedded_graphics::prelude::Dimensions::bounding_box): rows off the display
/// are never traced, and only the visible columns are sent. `render_row` traces whole rows,
/// so a row that shows is traced across the camera's full width even when only part of it is
/// on the display. The rest of the display is left alone.
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
/// use embedded_graphics_simulator::SimulatorDisplay;
/// use fixray::{demo, FromRgb, Rgb, Viewport};
///
/// let mut display = SimulatorDisplay::<Rgb565>::new(Size::new(128, 96));
/// let (scene, camera) = (demo::scene(), demo::camera(64, 48)?);
/// // The lower right quarter of the display, drawn 16 rows at a time.
/// let view = Viewport::at(&scene, &camera, Point::new(64, 48));
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
    pub(super) scene: &'a Scene<N, L>,
    pub(super) camera: &'a Camera,
    pub(super) top_left: Point,
}

impl<'a, const N: usize, const L: usize> Viewport<'a, N, L> {
    /// Places the camera's picture on a display with its top left pixel at `top_left`.
    ///
    /// Any point will do: the part of the picture off the display, on any side, is clipped
    /// when drawing, and a picture wholly off it draws nothing.
    #[must_use]
    pub const fn at(scene: &'a Scene<N, L>, camera: &'a Camera, top_left: Point) -> Self {
        Viewport {
            scene,
            camera,
            top_left,
        }
    }

    /// The display point of the picture's top left pixel.
    #[must_use]
    pub const fn top_left(&self) -> Point {
        self.top_left
    }

    /// The picture's size, the camera's: width by height.
    #[must_use]
    pub const fn size(&self) -> Size {
        self.camera.size()
    }

    /// The display rectangle the picture covers, on the display or not.
    #[must_use]
    pub fn area(&self) -> Rectangle {
        Rectangle::new(self.top_left, self.size())
    }

    /// Renders rows `rows` of the picture (0 is the picture's top row) onto `display`,
    /// clipped to the display.
    ///
    /// `buffer` must hold at least one row (`camera.width()` pixels, even when fewer columns
    /// show); each `fill_contiguous` call sends as many rows as it holds, each cut to its
    /// visible columns. Rows off the display are skipped before they are traced. Rows past the
    /// picture's last are an error ([`Error::RowOutOfRange`], the last row asked for), a
    /// buffer shorter than a row is one too ([`Error::BufferLength`]), and an empty range
    /// draws nothing. The first driver error stops the
    /// render and is returned as [`DrawError::Display`], unchanged.
    pub fn render_rows<D>(
        &self,
        rows: Range<u32>,
        buffer: &mut [Rgb],
        display: &mut D,
    ) -> Result<(), DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: FromRgb,
    {
        self.draw_rows(rows, buffer, display, |y, line| {
            render_row(self.scene, self.camera, y, line)
        })
    }

    /// Renders the whole picture: [`render_rows`](Self::render_rows) over every row.
    pub fn render<D>(&self, buffer: &mut [Rgb], display: &mut D) -> Result<(), DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: FromRgb,
    {
        self.render_rows(0..self.camera.height(), buffer, display)
    }

    /// Sends the display only what an edit of the scene changed: the pixels `damage` holds
    /// ([`Damage::between`](crate::Damage::between) of the scene before and after, for this
    /// viewport's camera), one row span at a time through `buffer` (at least the widest span;
    /// a row is always enough), each as one [`fill_contiguous`](DrawTarget::fill_contiguous)
    /// of a one-row window. The display, showing the picture of the scene before the edit,
    /// then shows the picture of the scene after it, as [`render`](Self::render) would draw it,
    /// dithering included; clipped to the display as it is.
    ///
    /// A damage made for another size of camera is [`Error::SizeMismatch`], and a buffer
    /// shorter than a span [`Error::BufferLength`]; nothing is sent for that span on.
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
    /// use embedded_graphics_simulator::SimulatorDisplay;
    /// use fixray::{demo, Damage, Rgb, Sphere, Viewport};
    ///
    /// let camera = demo::camera(160, 128)?;
    /// let mut scene = demo::scene();
    /// let ball = scene.add_sphere(Sphere::new([1.0, -3.0, -9.0], 1.0)?, Rgb::WHITE)?;
    /// let mut display = SimulatorDisplay::<Rgb565>::new(Size::new(160, 128));
    /// let mut row = [Rgb::BLACK; 160];
    /// Viewport::at(&scene, &camera, Point::zero()).render(&mut row, &mut display)?;
    ///
    /// let before = scene.clone();
    /// scene.set_shape(ball, Sphere::new([1.5, -3.0, -9.0], 1.0)?.into())?;
    /// let damage = Damage::between(&before, &scene, &camera);
    /// Viewport::at(&scene, &camera, Point::zero()).redraw(&damage, &mut row, &mut display)?;
    ///
    /// let mut fresh = SimulatorDisplay::<Rgb565>::new(Size::new(160, 128));
    /// Viewport::at(&scene, &camera, Point::zero()).render(&mut row, &mut fresh)?;
    /// assert!(display == fresh);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn redraw<D>(
        &self,
        damage: &Damage,
        buffer: &mut [Rgb],
        display: &mut D,
    ) -> Result<(), DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: FromRgb,
    {
        let (cols, rows) = (self.camera.cols(), self.camera.rows());
        if damage.size() != Size::new(u32::from(cols), u32::from(rows)) {
            let size = damage.size();
            return Err(Error::SizeMismatch {
                camera: (cols, rows),
                target: (size.width as u16, size.height as u16),
            }
            .into());
        }
        let (shown_cols, shown_rows) = visible(self.top_left, self.size(), &display.bounding_box());
        for y in shown_rows {
            let Some(span) = damage.row_span(y) else {
                continue;
            };
            let span = span.start.max(shown_cols.start)..span.end.min(shown_cols.end);
            if span.is_empty() {
                continue;
            }
            let got = buffer.len();
            let line = buffer.get_mut(..span.len()).ok_or(Error::BufferLength {
                needed: span.len(),
                got,
            })?;
            render_row_span(self.scene, self.camera, y, span.clone(), line)?;
            // On the display, below i32::MAX: `visible` keeps only such pixels.
            let top_left = Point::new(
                self.top_left.x.wrapping_add(span.start as i32),
                self.top_left.y.wrapping_add(y as i32),
            );
            let area = Rectangle::new(top_left, Size::new(span.len() as u32, 1));
            display
                .fill_contiguous(&area, converted(core::iter::once(&*line), top_left))
                .map_err(DrawError::Display)?;
        }
        Ok(())
    }

    /// The picture as an embedded-graphics [`Drawable`](embedded_graphics::Drawable) in
    /// display colour `C`, with a row buffer of its own, `W` pixels wide (on the stack while it
    /// draws: `3 · W` bytes).
    ///
    /// A camera wider than `W` columns is [`Error::BufferLength`]; the check is here, so that
    /// drawing can fail only in the driver.
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
    /// use embedded_graphics_simulator::SimulatorDisplay;
    /// use fixray::{demo, FromRgb, Viewport};
    ///
    /// let mut display = SimulatorDisplay::<Rgb565>::new(Size::new(320, 240));
    /// let (scene, camera) = (demo::scene(), demo::camera(400, 300)?);
    /// // Larger than the display: only the 320 × 240 pixels that show are traced.
    /// Viewport::at(&scene, &camera, Point::zero())
    ///     .picture::<Rgb565, 400>()?
    ///     .draw(&mut display)?;
    /// let sky = Rgb565::from_rgb(demo::BACKGROUND, Point::zero());
    /// assert_eq!(display.get_pixel(Point::new(319, 0)), sky);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn picture<C: FromRgb, const W: usize>(&self) -> Result<Picture<'a, C, W, N, L>, Error> {
        let needed = usize::from(self.camera.cols());
        if needed > W {
            return Err(Error::BufferLength { needed, got: W });
        }
        Ok(Picture {
            view: *self,
            colour: PhantomData,
        })
    }

    /// The picture's rows in bands of `rows_per_band` (the last may be shorter), for callers
    /// that do other work between bands. A band height of 0 counts as 1.
    ///
    /// ```
    /// use fixray::{demo, Viewport};
    /// use embedded_graphics::prelude::*;
    /// let (scene, camera) = (demo::scene(), demo::camera(16, 10)?);
    /// let view = Viewport::at(&scene, &camera, Point::zero());
    /// assert_eq!(view.bands(4).collect::<Vec<_>>(), [0..4, 4..8, 8..10]);
    /// # Ok::<(), fixray::Error>(())
    /// ```
    #[must_use]
    pub fn bands(&self, rows_per_band: u32) -> Bands {
        Bands {
            next: 0,
            end: self.camera.height(),
            step: rows_per_band.max(1),
        }
    }

    /// [`render_rows`](Self::render_rows) with the row tracer `trace(y, line)` as a
    /// parameter, so the crate's tests can count which rows are traced.
    pub(crate) fn draw_rows<D, T>(
        &self,
        rows: Range<u32>,
        buffer: &mut [Rgb],
        display: &mut D,
        mut trace: T,
    ) -> Result<(), DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: FromRgb,
        T: FnMut(u32, &mut [Rgb]) -> Result<(), Error>,
    {
        let (cols, total) = (self.camera.cols(), self.camera.height());
        if rows.end > total {
            // The last row asked for is past the picture's last: `check_row` refuses it.
            self.camera.check_row(rows.end - 1)?;
        }
        let width = usize::from(cols);
        // Whole rows that fit the buffer (cols ≥ 1, so the division is never by zero).
        let band_rows = buffer
            .len()
            .checked_div(width)
            .unwrap_or(0)
            .min(total as usize);
        if band_rows == 0 {
            return Err(Error::BufferLength {
                needed: width,
                got: buffer.len(),
            }
            .into());
        }
        // Within the camera's columns and rows.
        let (shown_cols, shown_rows) = visible(self.top_left, self.size(), &display.bounding_box());
        let span = shown_cols.start as usize..shown_cols.end as usize;
        let mut row = rows.start.max(shown_rows.start);
        let end = rows.end.min(shown_rows.end);
        if span.is_empty() {
            return Ok(());
        }
        while row < end {
            // band_rows ≤ total ≤ 4096.
            let n = (band_rows as u32).min(end - row);
            for (line, r) in buffer.chunks_exact_mut(width).zip(row..row + n) {
                trace(r, line)?;
            }
            // `span` lies within the row (`visible` keeps it within the camera's columns), so
            // `get` never comes back empty; it stands in for a slice index that could panic.
            // On the display, below i32::MAX: `visible` keeps only such pixels.
            let top_left = Point::new(
                self.top_left.x.wrapping_add(shown_cols.start as i32),
                self.top_left.y.wrapping_add(row as i32),
            );
            let area = Rectangle::new(top_left, Size::new(span.len() as u32, n));
            let lines = buffer
                .chunks_exact(width)
                .take(n as usize)
                .map(|line| line.get(span.clone()).unwrap_or_default());
            display
                .fill_contiguous(&area, converted(lines, top_left))
                .map_err(DrawError::Display)?;
            row += n;
        }
        Ok(())
    }
}

impl<const N: usize, const L: usize> Dimensions for Viewport<'_, N, L> {
    /// The display rectangle the picture covers: [`Viewport::area`].
    fn bounding_box(&self) -> Rectangle {
        self.area()
    }
}

/// Row ranges covering a picture, top to bottom: see [`Viewport::bands`].
#[derive(Debug, Clone)]
pub struct Bands {
    next: u32,
    end: u32,
    step: u32,
}

impl Iterator for Bands {
    type Item = Range<u32>;

    fn next(&mut self) -> Option<Range<u32>> {
        if self.next >= self.end {
            return None;
        }
        let start = self.next;
        self.next = start.saturating_add(self.step).min(self.end);
        Some(start..self.next)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = (self.end.saturating_sub(self.next) as usize).div_ceil(self.step as usize);
        (left, Some(left))
    }
}

impl ExactSizeIterator for Bands {}

impl FusedIterator for Bands {}

#[cfg(test)]
mod tests {
    use core::convert::Infallible;

    use embedded_graphics::pixelcolor::Rgb888;
    use embedded_graphics::prelude::{OriginDimensions, Pixel};

    use super::*;
    use crate::demo;

    /// A display that counts the pixels it is sent and the ones that land outside it.
    struct Counter {
        size: Size,
        drawn: usize,
        outside: usize,
    }

    impl OriginDimensions for Counter {
        fn size(&self) -> Size {
            self.size
        }
    }

    impl DrawTarget for Counter {
        type Color = Rgb888;
        type Error = Infallible;

        fn draw_iter<I: IntoIterator<Item = Pixel<Rgb888>>>(
            &mut self,
            pixels: I,
        ) -> Result<(), Infallible> {
            for Pixel(at, _) in pixels {
                self.drawn += 1;
                self.outside += usize::from(!self.bounding_box().contains(at));
            }
            Ok(())
        }
    }

    /// Draws a `width × height` demo picture at `top_left` on a `display`-sized display through
    /// the viewport's own row loop, with the real tracer behind a counter: (rows traced,
    /// pixels traced, pixels drawn, pixels drawn outside).
    fn traced(
        width: u32,
        height: u32,
        top_left: Point,
        display: Size,
    ) -> (usize, usize, usize, usize) {
        let (scene, camera) = (demo::scene(), demo::camera(width, height).unwrap());
        let view = Viewport::at(&scene, &camera, top_left);
        let mut counter = Counter {
            size: display,
            drawn: 0,
            outside: 0,
        };
        let mut buffer = [Rgb::BLACK; 512 * 4];
        let buffer = &mut buffer[..width as usize * 4];
        let (mut traced_rows, mut traced_pixels) = (0, 0);
        view.draw_rows(0..height, buffer, &mut counter, |y, line| {
            traced_rows += 1;
            traced_pixels += line.len();
            render_row(&scene, &camera, y, line)
        })
        .unwrap();
        (traced_rows, traced_pixels, counter.drawn, counter.outside)
    }

    #[test]
    fn a_picture_larger_than_the_display_traces_only_the_rows_that_show() {
        // 400 × 300 on 320 × 240: 240 rows traced (whole, 400 pixels each: 96 000 rather
        // than 120 000), 76 800 pixels drawn, none outside.
        assert_eq!(
            traced(400, 300, Point::zero(), Size::new(320, 240)),
            (240, 96_000, 76_800, 0)
        );
    }

    #[test]
    fn every_side_off_the_display_is_cut_before_tracing() {
        let display = Size::new(48, 32);
        // (top left, rows that show, columns that show) for a 40 × 30 picture.
        for (at, rows, cols) in [
            (Point::new(-10, 0), 30, 30),
            (Point::new(20, 0), 30, 28),
            (Point::new(0, -12), 18, 40),
            (Point::new(0, 25), 7, 40),
            (Point::new(-39, -29), 1, 1),
            (Point::new(47, 31), 1, 1),
            (Point::new(-40, 0), 0, 0),
            (Point::new(0, 32), 0, 0),
            (Point::new(i32::MIN, i32::MIN), 0, 0),
            (Point::new(i32::MAX, i32::MAX), 0, 0),
        ] {
            let (traced_rows, traced_pixels, drawn, outside) = traced(40, 30, at, display);
            // A picture with no column on the display traces nothing at all.
            let expected_rows = if cols == 0 { 0 } else { rows };
            assert_eq!(traced_rows, expected_rows, "{at:?}");
            assert_eq!(traced_pixels, 40 * expected_rows, "{at:?}");
            assert_eq!(drawn, rows * cols, "{at:?}");
            assert_eq!(outside, 0, "{at:?}");
        }
    }
}
