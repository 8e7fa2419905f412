//! [`Viewport::render_pass`]: a progressive render's pass onto a display, each traced pixel's
//! block filled: a row of small blocks that tile their band as one fill of the band, the
//! three pixels between the fourths of an even row as one fill, the others one filled
//! rectangle a block.

use core::ops::Range;

use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::prelude::{Point, Size};
use embedded_graphics::primitives::{PointsIter, Rectangle};

use super::clip::visible;
use super::color::FromRgb;
use super::error::DrawError;
use super::viewport::Viewport;
use crate::error::Error;
use crate::render::progressive::{Pass, render_pass_row};
use crate::scene::colour::Rgb;

/// The widest blocks a row of which is drawn as one fill of its band. An address window costs
/// a display on a serial bus about as many bytes as five or six 16-bit pixels, and its driver
/// more work than a pixel: for blocks of 4 × 4 and smaller a window each costs more than the
/// band's one, and larger blocks go faster as solid fills of their own (one colour repeated,
/// where the colour type does not dither) than as the band's pixels one by one.
const BAND_FILL_SPACING: u32 = 4;

impl<const N: usize, const L: usize> Viewport<'_, N, L> {
    /// Draws pass `pass` of a progressive render ([`Pass::sequence`]) onto `display`: each
    /// pixel the pass traces, with its block ([`Pass::block`] from it, cut at the picture's
    /// edges), as filled rectangles, so that a driver's fast fill is used: where a row's
    /// blocks of at most 4 × 4 tile their band (all the odd rows, half the even ones, two
    /// thirds of a grid's), the band as one `fill_contiguous`, one window for the driver; in
    /// the other even rows, each three pixels between the fourths a grid traced as one;
    /// elsewhere each block as one `fill_solid` (per pixel where the colour type dithers). Drawn
    /// over every pass of a sequence, in order, the display shows what
    /// [`render`](Self::render) draws, bit for bit, dithering included; begun again from a
    /// first pass, as when the view moves, nothing of the sequence before is left.
    ///
    /// `buffer` must hold a row (`camera.width()` pixels, [`Error::BufferLength`]). Clipped to
    /// the display as [`render`](Self::render) is: a row whose blocks do not show is not
    /// traced. The first driver error stops the pass and is returned as
    /// [`DrawError::Display`].
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
    /// use embedded_graphics_simulator::SimulatorDisplay;
    /// use fixray::{demo, Pass, Rgb, Viewport};
    ///
    /// let (scene, camera) = (demo::scene(), demo::camera(160, 128)?);
    /// let view = Viewport::at(&scene, &camera, Point::zero());
    /// let mut display = SimulatorDisplay::<Rgb565>::new(Size::new(160, 128));
    /// let mut row = [Rgb::BLACK; 160];
    /// for pass in Pass::sequence(8)? {
    ///     view.render_pass(pass, &mut row, &mut display)?; // a picture after each
    /// }
    /// let mut full = SimulatorDisplay::<Rgb565>::new(Size::new(160, 128));
    /// view.render(&mut row, &mut full)?;
    /// assert!(display == full);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn render_pass<D>(
        &self,
        pass: Pass,
        buffer: &mut [Rgb],
        display: &mut D,
    ) -> Result<(), DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: FromRgb,
    {
        self.render_pass_rows(pass, 0..self.camera.height(), buffer, display)
    }

    /// [`render_pass`](Self::render_pass) for the pass's rows within `rows` (0 is the
    /// picture's top row): a pass drawn a band at a time can be left between bands when the
    /// view moves. Rows past the picture's last are [`Error::RowOutOfRange`].
    pub fn render_pass_rows<D>(
        &self,
        pass: Pass,
        rows: Range<u32>,
        buffer: &mut [Rgb],
        display: &mut D,
    ) -> Result<(), DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: FromRgb,
    {
        if rows.end > self.camera.height() {
            self.camera.check_row(rows.end - 1)?;
        }
        let width = usize::from(self.camera.cols());
        if buffer.len() < width {
            let got = buffer.len();
            return Err(Error::BufferLength { needed: width, got }.into());
        }
        let (shown_cols, shown_rows) = visible(self.top_left, self.size(), &display.bounding_box());
        if shown_cols.is_empty() {
            return Ok(());
        }
        let block = pass.block();
        let (block_width, block_height) = (block.width, block.height);
        for y in rows {
            let columns = pass.columns(y);
            let block_rows =
                y.max(shown_rows.start)..y.saturating_add(block_height).min(shown_rows.end);
            if columns.count_below(width as u32) == 0 || block_rows.is_empty() {
                continue;
            }
            let count = render_pass_row(self.scene, self.camera, pass, y, buffer)?;
            let colours = buffer.get(..count).unwrap_or_default();
            let corner = |x, y| on_display(self.top_left, x, y);
            let mut runs = columns;
            if let (Some((0, step)), None) = (runs.next(), runs.next())
                && step == block_width
                && step <= BAND_FILL_SPACING
            {
                // The row's blocks tile their band: one fill of the band, one window for a
                // driver to open, each pixel its block's colour.
                let size = Size::new(shown_cols.len() as u32, block_rows.len() as u32);
                let band = Rectangle::new(corner(shown_cols.start, block_rows.start), size);
                let pixels = BandPixels::<D::Color>::new(
                    (colours, 0),
                    step,
                    (shown_cols.clone(), block_rows.clone()),
                    self.top_left,
                );
                display
                    .fill_contiguous(&band, pixels)
                    .map_err(DrawError::Display)?;
                continue;
            }
            let mut runs = columns;
            if let (Some((1, 2)), Some((2, 4))) = (runs.next(), runs.next()) {
                // An even row a grid of 4 traced: three pixels between each fourth, one window
                // for the three (their colours in the order of the columns: an odd one, the
                // one two past a fourth, the next odd one).
                let odd = width / 2;
                for (k, x) in (1..width as u32).step_by(4).enumerate() {
                    let colour = |i: usize| colours.get(i).copied().unwrap_or(Rgb::BLACK);
                    let three = [colour(2 * k), colour(odd + k), colour(2 * k + 1)];
                    let group_cols = x.max(shown_cols.start)..(x + 3).min(shown_cols.end);
                    if group_cols.is_empty() {
                        continue;
                    }
                    let size = Size::new(group_cols.len() as u32, block_rows.len() as u32);
                    let group = Rectangle::new(corner(group_cols.start, block_rows.start), size);
                    let pixels = BandPixels::<D::Color>::new(
                        (&three, x),
                        1,
                        (group_cols, block_rows.clone()),
                        self.top_left,
                    );
                    display
                        .fill_contiguous(&group, pixels)
                        .map_err(DrawError::Display)?;
                }
                continue;
            }
            for (&colour, x) in colours.iter().zip(columns.below(width as u32)) {
                let block_cols =
                    x.max(shown_cols.start)..x.saturating_add(block_width).min(shown_cols.end);
                if block_cols.is_empty() {
                    continue;
                }
                let size = Size::new(block_cols.len() as u32, block_rows.len() as u32);
                let block = Rectangle::new(corner(block_cols.start, block_rows.start), size);
                fill_block(display, &block, colour)?;
            }
        }
        Ok(())
    }
}

/// Fills `area` with `colour` converted at each of its pixels: one solid fill where the
/// conversion gives one colour throughout (every type that does not dither), the pixels one
/// by one in a contiguous fill where it does not.
fn fill_block<D>(display: &mut D, area: &Rectangle, colour: Rgb) -> Result<(), DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: FromRgb,
{
    let at = |p: Point| D::Color::from_rgb(colour, p);
    let first = at(area.top_left);
    let result = if area.points().all(|p| at(p) == first) {
        display.fill_solid(area, first)
    } else {
        display.fill_contiguous(area, area.points().map(at))
    };
    result.map_err(DrawError::Display)
}

/// Picture column `x` and row `y` on the display, the picture's top left at `origin`: below
/// `i32::MAX`, as `visible` keeps only such pixels.
fn on_display(origin: Point, x: u32, y: u32) -> Point {
    Point::new(
        origin.x.wrapping_add(x as i32),
        origin.y.wrapping_add(y as i32),
    )
}

/// The pixels of a band of a pass's row whose blocks tile it, in the order `fill_contiguous`
/// takes them (row by row): each its block's traced colour (`colours[i]` for columns
/// `base + i·spacing` on), converted at its own place on the display (`origin` plus its
/// picture column and row). The block is stepped at its edges, not found by a division a pixel (the
/// Cortex-M0 has no divider), in a loop of its own rather than a chain of adapters.
struct BandPixels<'a, C> {
    colours: &'a [Rgb],
    spacing: u32,
    cols: Range<u32>,
    rows_end: u32,
    origin: Point,
    /// The block and the column past it where each row starts.
    first: (usize, u32),
    /// The next pixel's column and row, its block and that block's end.
    x: u32,
    y: u32,
    block: usize,
    edge: u32,
    colour: core::marker::PhantomData<C>,
}

impl<'a, C> BandPixels<'a, C> {
    fn new(
        (colours, base): (&'a [Rgb], u32),
        spacing: u32,
        (cols, rows): (Range<u32>, Range<u32>),
        origin: Point,
    ) -> Self {
        let spacing = spacing.max(1);
        let block = cols.start.saturating_sub(base) / spacing;
        let first = (block as usize, base + (block + 1) * spacing);
        BandPixels {
            colours,
            spacing,
            x: cols.start,
            cols,
            y: rows.start,
            rows_end: rows.end,
            origin,
            first,
            block: first.0,
            edge: first.1,
            colour: core::marker::PhantomData,
        }
    }
}

impl<C: FromRgb> Iterator for BandPixels<'_, C> {
    type Item = C;

    fn next(&mut self) -> Option<C> {
        if self.x >= self.cols.end {
            (self.x, self.y) = (self.cols.start, self.y + 1);
            (self.block, self.edge) = self.first;
        }
        if self.y >= self.rows_end || self.x >= self.cols.end {
            return None;
        }
        if self.x == self.edge {
            (self.block, self.edge) = (self.block + 1, self.edge + self.spacing);
        }
        let colour = self.colours.get(self.block).copied().unwrap_or(Rgb::BLACK);
        let at = on_display(self.origin, self.x, self.y);
        self.x += 1;
        Some(C::from_rgb(colour, at))
    }
}
