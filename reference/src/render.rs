//! [`render_row`] and [`render`]: the chapter's raycasting loop over every pixel.

use super::{DCamera, DScene, Real};
use fixray::Rgb;

/// Shades display row `y` (0 is the top) into `out`, one colour per column, left to right.
///
/// For each column this is the chapter's loop body: build the ray through the pixel centre,
/// `shoot` it into the scene, and `shade` what it hit ([`DScene::trace`]).
///
/// # Panics
///
/// If `out.len()` is not `camera.width()`: the reference is test machinery, and a buffer of
/// the wrong size is a bug in the test.
pub fn render_row<const N: usize, const L: usize, F: Real>(
    scene: &DScene<N, L, F>,
    camera: &DCamera<F>,
    y: u32,
    out: &mut [Rgb],
) {
    assert_eq!(
        out.len(),
        camera.width() as usize,
        "row buffer length must equal the width"
    );
    for (x, pixel) in (0..camera.width()).zip(out.iter_mut()) {
        *pixel = scene.trace(&camera.ray(x, y)).1;
    }
}

/// [`render_row`] with `n × n` supersampling: each pixel is the mean of the `n²` colours seen
/// through its sub-pixel samples ([`DCamera::sample_ray`]), each channel rounded half up.
///
/// # Panics
///
/// If `out` is not `camera.width()` long.
pub fn render_row_supersampled<const N: usize, const L: usize, F: Real>(
    scene: &DScene<N, L, F>,
    camera: &DCamera<F>,
    y: u32,
    n: u8,
    out: &mut [Rgb],
) {
    assert_eq!(
        out.len(),
        camera.width() as usize,
        "row buffer length must equal the width"
    );
    let n = n.clamp(1, 16);
    let count = u32::from(n) * u32::from(n);
    for (x, pixel) in (0..camera.width()).zip(out.iter_mut()) {
        let mut sum = [0u32; 3];
        for sy in 0..n {
            for sx in 0..n {
                let c = scene.trace(&camera.sample_ray(x, y, sx, sy, n)).1;
                for (s, v) in sum.iter_mut().zip([c.r, c.g, c.b]) {
                    *s += u32::from(v);
                }
            }
        }
        let mean = |s: u32| ((s + count / 2) / count) as u8;
        *pixel = Rgb::new(mean(sum[0]), mean(sum[1]), mean(sum[2]));
    }
}

/// Shades the whole picture into `out`, row-major with row 0 at the top: pixel (`x`, `y`)
/// is `out[y · width + x]`.
///
/// # Panics
///
/// If `out.len()` is not `camera.width() · camera.height()`.
pub fn render<const N: usize, const L: usize, F: Real>(
    scene: &DScene<N, L, F>,
    camera: &DCamera<F>,
    out: &mut [Rgb],
) {
    let width = camera.width() as usize;
    let pixels = camera.height() as usize * width;
    assert_eq!(
        out.len(),
        pixels,
        "frame buffer length must equal width · height"
    );
    for (y, line) in (0..camera.height()).zip(out.chunks_exact_mut(width)) {
        render_row(scene, camera, y, line);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{DObject, DPlane, DSphere, DVec3};

    const SKY: Rgb = Rgb::new(0, 0, 255);
    const BALL: Rgb = Rgb::new(255, 0, 0);
    const FLOOR: Rgb = Rgb::new(0, 255, 0);

    /// A ball straight ahead above a floor, lit only by an ambient of 1 so colours are exact.
    fn scene() -> DScene<2> {
        let mut s = DScene::new(1.0, SKY.into());
        let ball = DSphere::new(DVec3::new(0.0, 0.0, -4.0), 1.0).unwrap();
        let floor = DPlane::new(DVec3::new(0.0, -2.0, 0.0), DVec3::Y).unwrap();
        s.push(DObject::matte(ball.into(), BALL)).unwrap();
        s.push(DObject::matte(floor.into(), FLOOR)).unwrap();
        s
    }

    #[test]
    fn the_picture_is_the_sky_the_ball_and_the_floor() {
        let cam = DCamera::pinhole(3.0, 3.0, 1.0, 3, 3).unwrap();
        let mut frame = [Rgb::BLACK; 9];
        render(&scene(), &cam, &mut frame);
        #[rustfmt::skip]
        let expected = [
            SKY,   SKY,  SKY,
            SKY,   BALL, SKY,
            FLOOR, FLOOR, FLOOR,
        ];
        assert_eq!(frame, expected);
    }

    #[test]
    fn a_row_matches_the_same_row_of_the_frame() {
        let cam = DCamera::look_at(DVec3::ZERO, -DVec3::Z, DVec3::Y, 90.0, 5, 4).unwrap();
        let mut frame = [Rgb::BLACK; 20];
        render(&scene(), &cam, &mut frame);
        let mut line = [Rgb::BLACK; 5];
        for y in 0..4u32 {
            render_row(&scene(), &cam, y, &mut line);
            let start = y as usize * 5;
            assert_eq!(line, frame[start..start + 5]);
        }
    }

    #[test]
    #[should_panic(expected = "width · height")]
    fn a_wrong_sized_frame_is_refused() {
        let cam = DCamera::pinhole(3.0, 3.0, 1.0, 3, 3).unwrap();
        render(&scene(), &cam, &mut [Rgb::BLACK; 8]);
    }
}
