//! `render_row` culls, skips and hints its way along a row; none of it may change a pixel.

use fixray::{Rgb, demo, render_row};

/// Every pixel of `render_row` against `trace` of the camera's own ray for it.
fn rows_match_tracing_each_pixel<const N: usize, const L: usize>(
    scene: &fixray::Scene<N, L>,
    camera: &fixray::Camera,
) {
    let mut out = vec![Rgb::BLACK; camera.cols() as usize];
    for row in 0..camera.rows() {
        render_row(scene, camera, row, &mut out).unwrap();
        for (col, pixel) in (0..).zip(&out) {
            let traced = scene.trace(&camera.ray(row, col));
            assert_eq!(*pixel, traced, "row {row}, column {col}");
        }
    }
}

/// A scene with and without shadows, through a camera at two sizes.
fn rows_match_with_and_without_shadows(
    mut scene: fixray::Scene<8>,
    camera: fn(u16, u16) -> Result<fixray::Camera, fixray::Error>,
    odd_size: (u16, u16),
) {
    for (cols, rows) in [(160, 128), odd_size] {
        let camera = camera(cols, rows).unwrap();
        for shadows in [true, false] {
            scene.set_shadows(shadows);
            rows_match_tracing_each_pixel(&scene, &camera);
        }
    }
}

#[test]
fn demo_rows_equal_their_pixels_traced_one_by_one() {
    rows_match_with_and_without_shadows(demo::scene(), demo::camera, (97, 61));
}

#[test]
fn classic_rows_equal_their_pixels_traced_one_by_one() {
    rows_match_with_and_without_shadows(demo::classic(), demo::classic_camera, (83, 67));
}

#[test]
fn orbiting_views_equal_their_pixels_traced_one_by_one() {
    let scene = demo::classic();
    for (yaw, pitch) in [(0.0, 10.0), (70.0, 35.0), (200.0, 5.0), (300.0, 60.0)] {
        let camera =
            fixray::Camera::orbit([0.0, 0.0, -16.0], 22.0, yaw, pitch, 60.0, 64, 48).unwrap();
        rows_match_tracing_each_pixel(&scene, &camera);
    }
}
