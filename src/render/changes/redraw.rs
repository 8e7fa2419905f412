//! Redrawing the damage: [`render_row_span`], a part of a row, and [`render_changes`], the
//! damaged pixels of a frame.

use core::ops::Range;

use super::Damage;
use crate::error::Error;
use crate::framebuffer::Framebuffer;
use crate::render::camera::Camera;
use crate::scene::Scene;
use crate::scene::colour::Rgb;

/// Renders columns `cols` of display row `row` into `out`, one colour per column: the
/// pixels [`render_row`](crate::render_row) gives them, bit for bit, for a display that is
/// sent only the part of a row that changed ([`Damage::row_span`]).
///
/// The span is walked as [`render_row`](crate::render_row) walks the whole row (its culling,
/// its runs of columns, its rays by column steps), started and stopped at the span's ends. A row off the screen is [`Error::RowOutOfRange`], columns
/// past its right edge (or a range that ends before it starts) [`Error::ColumnOutOfRange`],
/// and a buffer that is not `cols.len()` long [`Error::BufferLength`].
///
/// ```
/// use fixray::{demo, render_row, render_row_span, Rgb};
/// let (scene, camera) = (demo::scene(), demo::camera(32, 24)?);
/// let mut row = [Rgb::BLACK; 32];
/// render_row(&scene, &camera, 20, &mut row)?;
/// let mut part = [Rgb::BLACK; 8];
/// render_row_span(&scene, &camera, 20, 10..18, &mut part)?;
/// assert_eq!(part, row[10..18]);
/// assert!(render_row_span(&scene, &camera, 20, 30..33, &mut [Rgb::BLACK; 3]).is_err());
/// # Ok::<(), fixray::Error>(())
/// ```
pub fn render_row_span<const N: usize, const L: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
    row: u32,
    cols: Range<u32>,
    out: &mut [Rgb],
) -> Result<(), Error> {
    let line = camera.check_row(row)?;
    if cols.start > cols.end {
        return Err(Error::ColumnOutOfRange {
            col: cols.start,
            cols: camera.width(),
        });
    }
    if cols.end > camera.width() {
        return Err(Error::ColumnOutOfRange {
            col: cols.end - 1,
            cols: camera.width(),
        });
    }
    let needed = cols.len();
    if out.len() != needed {
        return Err(Error::BufferLength {
            needed,
            got: out.len(),
        });
    }
    // The checks above bound both ends by the width, at most MAX_PIXELS: they fit a u16.
    let (first, end) = (cols.start as u16, cols.end as u16);
    crate::render::rows::render_columns(scene, camera, line, first..end, out);
    Ok(())
}

/// Redraws into `frame` the pixels `damage` holds ([`Damage::row_span`] of each row), as
/// [`render`](crate::render) would draw them for `scene`: a frame of the scene before an
/// edit, so redrawn with the damage of that edit, is the frame of the edited scene, bit for
/// bit.
///
/// The frame must have the camera's size, and the damage must have been made for a camera
/// of that size: otherwise [`Error::SizeMismatch`], and nothing is drawn. See
/// [`Damage::between`] for an example.
pub fn render_changes<const N: usize, const L: usize, const W: usize, const H: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
    damage: &Damage,
    frame: &mut Framebuffer<W, H>,
) -> Result<(), Error> {
    let camera_size = (camera.cols(), camera.rows());
    if (camera_size.0 as usize, camera_size.1 as usize) != (W, H) {
        return Err(Error::SizeMismatch {
            camera: camera_size,
            target: (
                W.min(u16::MAX as usize) as u16,
                H.min(u16::MAX as usize) as u16,
            ),
        });
    }
    if (damage.cols, damage.rows) != camera_size {
        return Err(Error::SizeMismatch {
            camera: camera_size,
            target: (damage.cols, damage.rows),
        });
    }
    for (y, pixels) in (0..).zip(frame.rows_mut().iter_mut()) {
        if let Some(span) = damage.row_span(y)
            && let Some(out) = pixels.get_mut(span.start as usize..span.end as usize)
        {
            render_row_span(scene, camera, y, span, out)?;
        }
    }
    Ok(())
}
