//! [`Picture`]: a [`Viewport`] as an embedded-graphics `Drawable`, with its own row buffer.

use core::marker::PhantomData;

use embedded_graphics::Drawable;
use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::prelude::Dimensions;
use embedded_graphics::primitives::Rectangle;

use super::color::FromRgb;
use super::error::DrawError;
use super::viewport::Viewport;
use crate::scene::colour::Rgb;

/// A scene's picture placed on a display, drawn the embedded-graphics way:
/// `picture.draw(&mut display)`. Made by [`Viewport::picture`].
///
/// Drawing renders the picture row by row into a row buffer of `W` pixels that lives on the
/// stack while it draws (`3 · W` bytes), converts each row to the display colour `C` and sends
/// it with one `fill_contiguous` call, clipped to the display exactly as
/// [`Viewport::render`] with a one-row buffer: the pixels are the same. The camera was
/// checked against `W` when the picture was made, so the only error left is the driver's,
/// returned unchanged, as [`Drawable`] wants. To do other work between bands, or to choose the
/// band height, use [`Viewport::bands`] and [`Viewport::render_rows`] instead.
///
/// ```
/// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
/// use embedded_graphics_simulator::SimulatorDisplay;
/// use fixray::{demo, Viewport};
///
/// let mut oled = SimulatorDisplay::<BinaryColor>::new(Size::new(128, 64));
/// let (scene, camera) = (demo::scene(), demo::camera(64, 64)?);
/// let picture = Viewport::at(&scene, &camera, Point::new(32, 0)).picture::<BinaryColor, 64>()?;
/// picture.draw(&mut oled)?;
/// assert_eq!(picture.bounding_box().top_left, Point::new(32, 0));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Picture<'a, C, const W: usize, const N: usize, const L: usize = 4> {
    pub(super) view: Viewport<'a, N, L>,
    /// The display colour, chosen by the caller; `fn() -> C` so the picture is `Send` and
    /// `Sync` whatever `C` is.
    pub(super) colour: PhantomData<fn() -> C>,
}

impl<'a, C, const W: usize, const N: usize, const L: usize> Picture<'a, C, W, N, L> {
    /// The viewport the picture draws.
    #[must_use]
    pub const fn viewport(&self) -> Viewport<'a, N, L> {
        self.view
    }
}

impl<C: FromRgb, const W: usize, const N: usize, const L: usize> Drawable
    for Picture<'_, C, W, N, L>
{
    type Color = C;
    type Output = ();

    fn draw<D>(&self, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let mut row = [Rgb::BLACK; W];
        match self.view.render(&mut row, target) {
            Ok(()) => Ok(()),
            Err(DrawError::Display(e)) => Err(e),
            // Unreachable: `Viewport::picture` checked that a row fits the buffer, and
            // `render` asks only for the picture's own rows. Nothing is drawn past it.
            Err(DrawError::Render(_)) => Ok(()),
        }
    }
}

impl<C, const W: usize, const N: usize, const L: usize> Dimensions for Picture<'_, C, W, N, L> {
    /// The display rectangle the picture covers, on the display or not.
    fn bounding_box(&self) -> Rectangle {
        self.view.area()
    }
}
