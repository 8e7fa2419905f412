//! The chapter's double loop: for each pixel, shoot a ray through its centre and shade it.

use crate::camera::Camera;
use crate::color::Rgb;
use crate::error::Error;
use crate::framebuffer::Framebuffer;
use crate::scene::Scene;

/// Renders display row `row` (0 at the top) into `out`, one colour per column.
///
/// This is the streaming form: RAM for one row, so a chip that cannot hold a frame can send
/// each row to its display as it is finished. `out` must hold exactly `camera.cols()` pixels and
/// `row` must be below `camera.rows()`.
///
/// ```
/// use fixray::{demo, render_row, Rgb};
/// let (scene, camera) = (demo::scene(), demo::camera(16, 8).unwrap());
/// let mut row = [Rgb::BLACK; 16];
/// render_row(&scene, &camera, 7, &mut row).unwrap();
/// // The bottom row of the demo looks down at the ground plane, not the sky.
/// assert_ne!(row[0], scene.background());
/// ```
pub fn render_row<const N: usize>(
    scene: &Scene<N>,
    camera: &Camera,
    row: u16,
    out: &mut [Rgb],
) -> Result<(), Error> {
    if out.len() != camera.cols() as usize || row >= camera.rows() {
        return Err(Error::SizeMismatch {
            camera: (camera.cols(), camera.rows()),
            target: (
                out.len().min(u16::MAX as usize) as u16,
                row.saturating_add(1),
            ),
        });
    }
    for (col, pixel) in out.iter_mut().enumerate() {
        let ray = camera.ray(row, col as u16);
        *pixel = scene.shade(scene.shoot(&ray).as_ref());
    }
    Ok(())
}

/// Renders the whole frame into `frame`, whose size must equal the camera's.
///
/// ```
/// use fixray::{demo, render, Framebuffer};
/// let mut frame = Framebuffer::<32, 24>::new();
/// render(&demo::scene(), &demo::camera(32, 24).unwrap(), &mut frame).unwrap();
/// // The wrong size is an error, not a panic.
/// assert!(render(&demo::scene(), &demo::camera(16, 16).unwrap(), &mut frame).is_err());
/// ```
pub fn render<const N: usize, const W: usize, const H: usize>(
    scene: &Scene<N>,
    camera: &Camera,
    frame: &mut Framebuffer<W, H>,
) -> Result<(), Error> {
    if (camera.cols() as usize, camera.rows() as usize) != (W, H) {
        return Err(Error::SizeMismatch {
            camera: (camera.cols(), camera.rows()),
            target: (
                W.min(u16::MAX as usize) as u16,
                H.min(u16::MAX as usize) as u16,
            ),
        });
    }
    for (row, pixels) in frame.rows_mut().iter_mut().enumerate() {
        render_row(scene, camera, row as u16, pixels)?;
    }
    Ok(())
}
