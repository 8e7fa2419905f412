//! The [`Framebuffer`] as an embedded-graphics image and draw target.
//!
//! A frame stores [`Rgb`](crate::Rgb), which is [`Rgb888`] by another name, so that is its colour on both
//! sides: `Image::new(&frame, point)` draws it like any other image, and anything
//! embedded-graphics can draw (text, a frame rate, a crosshair) can be drawn onto it.
//! [`Framebuffer::draw_at`] draws it on a display of any [`FromRgb`] colour, dithered the
//! same way as a streamed render.

use core::convert::Infallible;

use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::image::{GetPixel, ImageDrawable};
use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::{Dimensions, OriginDimensions, Pixel, Point, Size};
use embedded_graphics::primitives::Rectangle;

use super::clip::visible;
use super::color::{FromRgb, converted};
use super::error::DrawError;
use crate::framebuffer::Framebuffer;

/// `W` or `H` as an embedded-graphics dimension; no frame that fits in memory is wider.
const fn dimension(n: usize) -> u32 {
    if n > i32::MAX as usize {
        i32::MAX as u32
    } else {
        n as u32
    }
}

impl<const W: usize, const H: usize> OriginDimensions for Framebuffer<W, H> {
    fn size(&self) -> Size {
        Size::new(dimension(W), dimension(H))
    }
}

impl<const W: usize, const H: usize> DrawTarget for Framebuffer<W, H> {
    type Color = Rgb888;
    type Error = Infallible;

    /// Sets each pixel; pixels outside the frame are skipped, as embedded-graphics expects.
    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Infallible>
    where
        I: IntoIterator<Item = Pixel<Rgb888>>,
    {
        for Pixel(at, colour) in pixels {
            if let (Ok(x), Ok(y)) = (usize::try_from(at.x), usize::try_from(at.y)) {
                self.set_pixel(x, y, colour.into());
            }
        }
        Ok(())
    }
}

impl<const W: usize, const H: usize> GetPixel for Framebuffer<W, H> {
    type Color = Rgb888;

    fn pixel(&self, at: Point) -> Option<Rgb888> {
        let (x, y) = (usize::try_from(at.x).ok()?, usize::try_from(at.y).ok()?);
        Framebuffer::pixel(self, x, y).map(Rgb888::from)
    }
}

impl<const W: usize, const H: usize> ImageDrawable for Framebuffer<W, H> {
    type Color = Rgb888;

    fn draw<D>(&self, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = Rgb888>,
    {
        let pixels = self.rows().as_flattened().iter();
        target.fill_contiguous(&self.bounding_box(), pixels.map(|&c| Rgb888::from(c)))
    }

    /// Draws `area` of the frame at the target's origin; an area not wholly inside the frame
    /// draws nothing, as for embedded-graphics' own images.
    fn draw_sub_image<D>(&self, target: &mut D, area: &Rectangle) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = Rgb888>,
    {
        // The range check in `usize`, checked: embedded-graphics' `bottom_right` adds the size
        // to the corner in `i32` and overflows for an area near `i32::MAX`.
        let span = |start: i32, len: u32, limit: usize| {
            let start = usize::try_from(start).ok()?;
            let end = start.checked_add(usize::try_from(len).ok()?)?;
            (len > 0 && end <= limit).then_some(start)
        };
        let (Some(x0), Some(y0)) = (
            span(area.top_left.x, area.size.width, W),
            span(area.top_left.y, area.size.height, H),
        ) else {
            return Ok(());
        };
        let (w, h) = (area.size.width as usize, area.size.height as usize);
        let pixels = self.rows()[y0..y0 + h]
            .iter()
            .flat_map(|row| &row[x0..x0 + w])
            .map(|&c| Rgb888::from(c));
        target.fill_contiguous(&Rectangle::new(Point::zero(), area.size), pixels)
    }
}

impl<const W: usize, const H: usize> Framebuffer<W, H> {
    /// Draws the frame with its top left pixel at display point `top_left`, converted to the
    /// display's colour by [`FromRgb`], in one `fill_contiguous` call.
    ///
    /// Only the part on the display's bounding box is sent; any point will do, and a frame
    /// wholly off the display draws nothing. For dithered colours the pattern is keyed on
    /// display points, so this draws exactly the pixels a streamed
    /// [`Viewport`](crate::Viewport) render of the same picture would. A driver error comes
    /// back as [`DrawError::Display`], unchanged; fixray refuses nothing here.
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
    /// use embedded_graphics_simulator::SimulatorDisplay;
    /// use fixray::{Framebuffer, Rgb};
    /// let mut frame = Framebuffer::<8, 8>::new();
    /// frame.rows_mut()[0] = [Rgb::WHITE; 8];
    /// let mut oled = SimulatorDisplay::<BinaryColor>::new(Size::new(128, 64));
    /// frame.draw_at(Point::new(10, 20), &mut oled)?;
    /// assert_eq!(oled.get_pixel(Point::new(17, 20)), BinaryColor::On);
    /// assert_eq!(oled.get_pixel(Point::new(17, 21)), BinaryColor::Off);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn draw_at<D>(&self, top_left: Point, display: &mut D) -> Result<(), DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: FromRgb,
    {
        let size = OriginDimensions::size(self);
        let (cols, rows) = visible(top_left, size, &display.bounding_box());
        if cols.is_empty() || rows.is_empty() {
            return Ok(());
        }
        // On the display and below i32::MAX (`visible` keeps only such pixels), and within
        // the frame, whose sides are below i32::MAX too.
        let corner = Point::new(
            top_left.x.wrapping_add(cols.start as i32),
            top_left.y.wrapping_add(rows.start as i32),
        );
        let area = Rectangle::new(corner, Size::new(cols.len() as u32, rows.len() as u32));
        let span = cols.start as usize..cols.end as usize;
        // `get` never misses (the ranges lie within the frame); it stands in for an index.
        let lines = self
            .rows()
            .get(rows.start as usize..rows.end as usize)
            .unwrap_or_default()
            .iter()
            .map(|line| line.get(span.clone()).unwrap_or_default());
        display
            .fill_contiguous(&area, converted::<D::Color>(lines, corner))
            .map_err(DrawError::Display)
    }
}
