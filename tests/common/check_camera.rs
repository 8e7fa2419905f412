//! Oracles for cameras: the documented refusals, and every accepted camera's rays against the
//! chapter's exact camera, on the screen and past its edges.

use fixray::Camera;

use super::exact::{dot, norm, unit};
use super::{CameraSpec, ToF64, ULP, UNIT_TOLERANCE};

/// Constructors: `Err` exactly where the documented rules say so; the accepted camera's rays
/// are unit vectors close to the chapter's exact camera on the screen (and, with
/// `past_edges`, past its edges too: see [`check_rays_past_the_screen`]).
pub fn check_camera_spec(spec: &CameraSpec, past_edges: bool) -> Option<Camera> {
    let built = spec.build();
    // [ASSERT: Err for invalid input] The documented refusals are refusals.
    if let Some(why) = spec.must_refuse() {
        assert!(
            built.is_err(),
            "{spec:?} must be refused ({why}), got {built:?}"
        );
        return None;
    }
    let camera = built.ok()?;
    let (cols, rows) = (camera.width(), camera.height());
    check_rays(
        spec,
        &camera,
        &[
            (0, 0),
            (cols - 1, rows - 1),
            (cols / 2, rows / 2),
            (cols - 1, 0),
        ],
    );
    if past_edges {
        check_rays_past_the_screen(spec, &camera);
    }
    Some(camera)
}

/// [ASSERT: rays past the screen continue it] The docs promise that columns and rows outside
/// the screen, up to the last `u32`, continue the screen plane without wrapping: the rays
/// there are checked like those on it, and `row_rays` of rows past the screen refused.
/// (Separate from the rest, and run last in a case, so that a failure here does not hide the
/// others.)
pub fn check_rays_past_the_screen(spec: &CameraSpec, camera: &Camera) {
    let (cols, rows) = (camera.width(), camera.height());
    let mut pixels = Vec::new();
    for far in [
        cols,
        cols.saturating_add(1),
        cols.saturating_mul(2),
        40000,
        u32::from(u16::MAX),
        u32::MAX,
    ] {
        pixels.push((far, rows / 2));
        pixels.push((cols / 2, far));
    }
    pixels.push((u32::MAX, u32::MAX));
    check_rays(spec, camera, &pixels);
    for y in [rows, u32::from(u16::MAX) + 1, u32::MAX] {
        assert!(camera.row_rays(y).is_err(), "row_rays({y}) past the screen");
    }
}

/// [ASSERT: accepted cameras are usable] Every ray checked is a unit vector, and points where
/// the chapter's camera (in `f64`, from the same rounded inputs) points, on the screen and past
/// its edges.
///
/// The angle allowed, `2⁻¹⁶ · (6 + 2/f + 9/sin θ)` radians with `f` the view distance in
/// pixels and `θ` the angle between the view and up: the view direction and up are unit
/// vectors to one unit of 2⁻¹⁶ a component (√3 units of angle each), their cross product is
/// rounded to half a unit a component, so `right` is off by at most `(2·√3 + √3/2)/sin θ`
/// units of angle before it is normalised (√3 more) and the true up, their cross product, by
/// as much again: below `9/sin θ` for both (the pinhole's basis is exact: `sin θ = 1` and the
/// term a bound to spare). The ray's Q16.16 direction towards the pixel is rounded to half a
/// unit a component (√3/2 units over a length of at least `f` pixels), the view distance in
/// pixels to half a unit (half a unit over `f`), and the normalisation adds √3 units: with
/// the view direction's √3, below `6 + 2/f`.
pub fn check_rays(spec: &CameraSpec, camera: &Camera, pixels: &[(u32, u32)]) {
    let (cols, rows) = (camera.width(), camera.height());
    for &(col, row) in pixels {
        let ray = camera.ray(col, row);
        let (exact, f, sin) = spec.exact_ray(camera, col as f64, row as f64);
        let got = ray.dir().to_f64();
        assert_eq!(
            ray.origin(),
            camera.eye(),
            "ray({col}, {row}) leaves from the eye"
        );
        let len = norm(got);
        assert!(
            (len - 1.0).abs() <= UNIT_TOLERANCE,
            "ray({col}, {row}) of {spec:?}: |dir| = {len} (dir {:?})",
            ray.dir()
        );
        // Where the pixel-unit direction's components may not fit Q16.16 (beyond 2¹⁵ pixels),
        // only the side of the view is promised: the ray must not wrap to the other side.
        let (x, y) = (
            col as f64 + 0.5 - cols as f64 / 2.0,
            row as f64 + 0.5 - rows as f64 / 2.0,
        );
        let fits = (f * f + x * x + y * y).sqrt() < 16384.0;
        if fits {
            let angle = dot(unit(got), exact).clamp(-1.0, 1.0).acos();
            let allowed = ULP * (6.0 + 2.0 / f + 9.0 / sin);
            assert!(
                angle <= allowed,
                "ray({col}, {row}) of {spec:?} is {angle} rad off the exact camera's \
                 (allowed {allowed}; dir {:?}, exact {exact:?})",
                ray.dir()
            );
        } else {
            assert!(
                dot(got, exact) > 0.0,
                "ray({col}, {row}) of {spec:?} looks away from the exact camera's ray: \
                 dir {:?}, exact {exact:?}",
                ray.dir()
            );
        }
        // The supersampling ray at n = 1 (or 0, clamped to 1) is the pixel's ray.
        assert_eq!(camera.sample_ray(col, row, 0, 0, 1), ray, "sample_ray n=1");
        assert_eq!(camera.sample_ray(col, row, 0, 0, 0), ray, "sample_ray n=0");
        let _ = camera.pixel_centre(col, row);
    }
    // [ASSERT: RowRays is Camera::ray] for the last row of the screen.
    let row = rows - 1;
    let rays = camera.row_rays(row).expect("the last row is on the screen");
    for (col, ray) in (0..).zip(rays) {
        if col % 97 == 0 || col + 1 == cols {
            assert_eq!(ray, camera.ray(col, row), "row_rays({row}) column {col}");
        }
    }
    assert_eq!(
        camera.row_rays(row).expect("on the screen").len(),
        cols as usize,
        "a ray per column"
    );
}
