//! Cameras at their edges: degenerate and extreme screens, rows and columns past the screen,
//! the row checks of every function that takes a row, and the picture across fields of view
//! against the f64 reference.
//!
//! The judge of a ray is an f64 model of the same screen built here from the constructor's
//! own inputs (not from fixray's rounded camera): where a ray lands on that screen, in pixels.

use fixray::internals::shoot_row_skipping;
use fixray::{
    Camera, Error, Fx, LIMIT, Quantity, Ray, Rgb, Size, demo, render_row, render_row_supersampled,
    shoot_row,
};
use fixray_reference::ToF64;
use fixray_reference::{DRay, DScene, DVec3};

type V = [f64; 3];

fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: V, b: V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn unit(a: V) -> V {
    let l = dot(a, a).sqrt();
    [a[0] / l, a[1] / l, a[2] / l]
}

fn f64s(p: [f32; 3]) -> V {
    p.map(f64::from)
}

/// A screen in f64: the eye, the view direction `f`, `right` and `up` (unit), the screen's
/// distance `d` and its pixel pitches, and its size.
struct Exact {
    f: V,
    right: V,
    up: V,
    d: f64,
    pitch: (f64, f64),
    cols: f64,
    rows: f64,
}

impl Exact {
    fn pinhole(w: f32, h: f32, z_p: f32, cols: u32, rows: u32) -> Exact {
        Exact {
            f: [0.0, 0.0, -1.0],
            right: [1.0, 0.0, 0.0],
            up: [0.0, 1.0, 0.0],
            d: z_p.into(),
            pitch: (f64::from(w) / cols as f64, f64::from(h) / rows as f64),
            cols: cols.into(),
            rows: rows.into(),
        }
    }

    fn look_at(eye: [f32; 3], target: [f32; 3], up: [f32; 3], fov: f32, c: u32, r: u32) -> Exact {
        let f = unit(sub(f64s(target), f64s(eye)));
        let right = unit(cross(f, f64s(up)));
        let pitch = 2.0 * (f64::from(fov).to_radians() / 2.0).tan() / r as f64;
        Exact {
            f,
            right,
            up: cross(right, f),
            d: 1.0,
            pitch: (pitch, pitch),
            cols: c.into(),
            rows: r.into(),
        }
    }

    /// The unit direction towards the point `(x, y)` of the screen, in pixels from its top
    /// left corner (pixel centres at half-integers).
    fn towards(&self, x: f64, y: f64) -> V {
        let across = (x - self.cols / 2.0) * self.pitch.0;
        let upward = (self.rows / 2.0 - y) * self.pitch.1;
        unit(std::array::from_fn(|i| {
            self.f[i] * self.d + self.right[i] * across + self.up[i] * upward
        }))
    }

    /// The distance from the eye to the point `(x, y)` of the screen, in pixel widths.
    fn distance(&self, x: f64, y: f64) -> f64 {
        let across = x - self.cols / 2.0;
        let upward = (self.rows / 2.0 - y) * self.pitch.1 / self.pitch.0;
        (self.d / self.pitch.0).hypot(across).hypot(upward)
    }

    /// Where a ray along `dir` meets the screen, in pixels from its top left corner.
    fn landing(&self, dir: V) -> (f64, f64) {
        let t = self.d / dot(dir, self.f);
        let p = dir.map(|c| c * t);
        (
            dot(p, self.right) / self.pitch.0 + self.cols / 2.0,
            self.rows / 2.0 - dot(p, self.up) / self.pitch.1,
        )
    }

    /// How far (pixels) the ray through pixel (`col`, `row`) lands from the pixel's centre.
    fn shift(&self, ray: &Ray, col: u32, row: u32) -> f64 {
        let (x, y) = self.landing(ray.dir().to_f64());
        (x - (col as f64 + 0.5)).hypot(y - (row as f64 + 0.5))
    }
}

fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// Rows (or columns) worth trying on a screen of `n`: its edges and centre, and up to
/// `u32::MAX` past it.
fn lines(n: u32) -> Vec<u32> {
    let mut v = vec![0, n / 2, n - 1, n, n.saturating_add(1)];
    v.extend([
        1000, 4095, 4096, 9999, 32767, 32768, 40000, 65534, 65535, 65536,
    ]);
    v.extend([1 << 24, (1 << 31) - 1, 1 << 31, u32::MAX - 1, u32::MAX]);
    v
}

/// The screen's edges, centre and a grid every `step` pixels.
fn sample(n: u32, step: u32) -> Vec<u32> {
    let mut v: Vec<u32> = (0..n).step_by(step as usize).collect();
    v.extend([n / 2, n - 1]);
    v
}

/// The largest shift (pixels) of a ray of the screen's sampled pixels.
fn largest_shift(camera: &Camera, exact: &Exact, step: u32) -> f64 {
    let mut worst = 0.0f64;
    for row in sample(camera.height(), step) {
        for col in sample(camera.width(), step) {
            worst = worst.max(exact.shift(&camera.ray(col, row), col, row));
        }
    }
    worst
}

/// 2⁻¹⁶ in f64.
const STEP: f64 = 1.0 / 65536.0;

/// Every ray (on and off the screen) is a unit vector and points where the f64 screen
/// plane says.
///
/// The bound on the angle: the unnormalised direction `w` (pixel units) is the view
/// distance `F` times a unit forward vector, plus the offsets `x`, `y` times the unit vectors
/// `right` and `down`. Each of those three Q16.16 vectors is within √3 steps (2⁻¹⁶) of exact,
/// and `F·forward` and `w` are rounded once more (half a step a component), so `w` is off
/// by at most `√3·(F + |x| + |y|) + √3` steps, and `F + |x| + |y| ≤ √3·‖w‖`; normalising adds
/// √3 steps. In all, at most `(3 + √3 + √3/‖w‖)` steps of angle: below `(5 + 2/‖w‖)` steps.
fn assert_rays_continue_the_plane(name: &str, camera: &Camera, exact: &Exact) {
    for row in lines(camera.height()) {
        for col in lines(camera.width()) {
            let dir = camera.ray(col, row).dir().to_f64();
            // Each component is within one Q16.16 step of the unit vector along the rounded
            // direction, so the length is within √3 steps of 1.
            let length = dot(dir, dir).sqrt();
            assert!(
                (length - 1.0).abs() <= 3f64.sqrt() * STEP,
                "{name} ({col}, {row}): length {length}"
            );
            let (x, y) = (col as f64 + 0.5, row as f64 + 0.5);
            let want = exact.towards(x, y);
            let bound = (5.0 + 2.0 / exact.distance(x, y)) * STEP;
            let angle = dot(cross(dir, want), cross(dir, want)).sqrt() / length;
            assert!(
                angle <= bound && dot(dir, want) > 0.0,
                "{name} ({col}, {row}): {dir:?} is {angle:e} rad from {want:?}"
            );
        }
    }
}

#[test]
fn rays_off_the_screen_continue_its_plane() {
    let (o, ahead, up) = ([0.0; 3], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]);
    let (eye, target, tilted) = ([1.0, 2.0, 3.0], [-4.0, 0.5, -9.0], [0.1, 1.0, 0.2]);
    let cases: Vec<(&str, Camera, Exact)> = vec![
        (
            "pinhole 1x1",
            Camera::pinhole(1.0, 1.0, 1.0)
                .size(Size::new(1, 1))
                .build()
                .unwrap(),
            Exact::pinhole(1.0, 1.0, 1.0, 1, 1),
        ),
        (
            "pinhole 2x2, pixels 4 times taller",
            Camera::pinhole(0.5, 2.0, 1.0)
                .size(Size::new(2, 2))
                .build()
                .unwrap(),
            Exact::pinhole(0.5, 2.0, 1.0, 2, 2),
        ),
        (
            "look-at 2x2 60°",
            Camera::look_at(o, ahead)
                .up(up)
                .size(Size::new(2, 2))
                .build()
                .unwrap(),
            Exact::look_at(o, ahead, up, 60.0, 2, 2),
        ),
        (
            "look-at 1x1 170°",
            Camera::look_at(eye, target)
                .up(tilted)
                .fov_degrees(170.0)
                .size(Size::new(1, 1))
                .build()
                .unwrap(),
            Exact::look_at(eye, target, tilted, 170.0, 1, 1),
        ),
        (
            "look-at 160x128 2°",
            Camera::look_at(eye, target)
                .up(tilted)
                .fov_degrees(2.0)
                .size(Size::new(160, 128))
                .build()
                .unwrap(),
            Exact::look_at(eye, target, tilted, 2.0, 160, 128),
        ),
        (
            "look-at 4096x4096 60°",
            Camera::look_at(eye, target)
                .up(tilted)
                .size(Size::new(4096, 4096))
                .build()
                .unwrap(),
            Exact::look_at(eye, target, tilted, 60.0, 4096, 4096),
        ),
        (
            "look-at 4096x4096 150°",
            Camera::look_at(o, ahead)
                .up(up)
                .fov_degrees(150.0)
                .size(Size::new(4096, 4096))
                .build()
                .unwrap(),
            Exact::look_at(o, ahead, up, 150.0, 4096, 4096),
        ),
        (
            "look-at 4096x4096 16°",
            Camera::look_at(eye, target)
                .up(tilted)
                .fov_degrees(16.0)
                .size(Size::new(4096, 4096))
                .build()
                .unwrap(),
            Exact::look_at(eye, target, tilted, 16.0, 4096, 4096),
        ),
    ];
    for (name, camera, exact) in &cases {
        assert_rays_continue_the_plane(name, camera, exact);
    }
}

#[test]
fn a_ray_far_right_of_a_small_screen_looks_right() {
    // 2 × 2 at 60°: column 40 000 is 40 000 pixels right of the centre, nearly straight right.
    let camera = Camera::look_at([0.0; 3], [0.0, 0.0, -1.0])
        .size(Size::new(2, 2))
        .build()
        .unwrap();
    let dir = camera.ray(40000, 0).dir().to_f64();
    assert!(dir[0] > 0.99999 && dir[2] < 0.0, "{dir:?}");
    // And row 40 000 looks down, not up.
    let dir = camera.ray(1, 40000).dir().to_f64();
    assert!(dir[1] < -0.99999 && dir[2] < 0.0, "{dir:?}");
    // The sub-pixel samples too.
    let dir = camera
        .sample_ray(u32::MAX, u32::MAX, 15, 15, 16)
        .dir()
        .to_f64();
    assert!(dir[0] > 0.7 && dir[1] < -0.7, "{dir:?}");
}

#[test]
fn pixel_centres_off_the_screen_continue_it_or_saturate() {
    // One pixel 1024 units wide, 1 unit away (1/1024 of a pixel, exact in Q16.16): column c
    // is at x = 1024·c.
    let camera = Camera::pinhole(1024.0, 1024.0, 1.0)
        .size(Size::new(1, 1))
        .build()
        .unwrap();
    assert_eq!(camera.pixel_centre(0, 0).to_f64(), [0.0, 0.0, -1.0]);
    assert_eq!(camera.pixel_centre(31, 0).to_f64(), [31744.0, 0.0, -1.0]);
    // Column 32 is at x = 32 768, past Q16.16: it saturates, the other coordinates do not.
    let far = camera.pixel_centre(32, u32::MAX).to_f64();
    assert!(far[0] > 32767.99 && far[1] < -32767.99, "{far:?}");
    assert_eq!(far[2], -1.0);
    // A look-at camera's screen is one unit away, whatever the row.
    let camera = Camera::look_at([0.0; 3], [0.0, 0.0, -1.0])
        .fov_degrees(90.0)
        .size(Size::new(2, 2))
        .build()
        .unwrap();
    // Pixel pitch 1: x = col − ½ and y = ½ − row, saturating past ±32 768.
    let saturated = |v: f64| v.clamp(-32768.0, 32_767.999_984_741_21);
    for (col, row) in [
        (0, 0),
        (1, 1),
        (1, 40000),
        (32000, 7),
        (u32::from(u16::MAX), u32::from(u16::MAX)),
        (u32::MAX, 1),
        (0, u32::MAX),
        (u32::MAX, u32::MAX),
    ] {
        let p = camera.pixel_centre(col, row).to_f64();
        let want = [col as f64 - 0.5, 0.5 - row as f64, -1.0].map(saturated);
        for axis in 0..3 {
            assert!(
                (p[axis] - want[axis]).abs() <= STEP,
                "({col}, {row}): {p:?}"
            );
        }
    }
}

#[test]
fn degenerate_pinholes_are_refused_with_the_quantity() {
    // The view distance rounds to zero: the ray would have no direction.
    assert_eq!(
        Camera::pinhole(1.0, 1.0, 1e-6)
            .size(Size::new(1, 1))
            .build()
            .map(|_| ()),
        Err(Error::OutOfRange {
            quantity: Quantity::ScreenDistance,
            min: Fx::DELTA,
            max: LIMIT,
        })
    );
    // A screen distance that rounds fine but is a millionth of a pixel.
    assert!(matches!(
        Camera::pinhole(1000.0, 1000.0, 0.001).size(Size::new(1, 1)).build(),
        Err(Error::FieldOfViewTooWide { max_millidegrees }) if max_millidegrees > 179_990
    ));
    // Pixels narrower than a Q16.16 step.
    assert_eq!(
        Camera::pinhole(1e-4, 1e-4, 1e-4)
            .size(Size::new(16, 16))
            .build()
            .map(|_| ()),
        Err(Error::OutOfRange {
            quantity: Quantity::PixelWidth,
            min: Fx::DELTA,
            max: LIMIT,
        })
    );
    // A screen too far for its pixels: 1024 units away, 1/64 wide over 4 pixels.
    assert!(matches!(
        Camera::pinhole(1.0 / 64.0, 1.0 / 64.0, 1024.0)
            .size(Size::new(4, 4))
            .build(),
        Err(Error::FieldOfViewTooNarrow { .. })
    ));
}

/// Whatever a constructor accepts has rays within half a pixel of the exact screen's: the
/// promise of the ray budget, tried over lengths from 2⁻²⁰ to 2¹⁰ and screens from 1 × 1 to
/// 4096 × 4096.
#[test]
fn every_accepted_pinhole_has_rays_within_half_a_pixel() {
    let lengths: Vec<f32> = (-20..=10).map(|e| 2f32.powi(e) * 0.77).collect();
    let (mut accepted, mut refused) = (0, 0);
    for &(cols, rows) in &[(1, 1), (2, 2), (5, 3), (160, 128), (4096, 4096)] {
        for &w in &lengths {
            for &z_p in &lengths {
                for h in [w, w * 3.0] {
                    match Camera::pinhole(w, h, z_p)
                        .size(Size::new(cols, rows))
                        .build()
                    {
                        Ok(camera) => {
                            accepted += 1;
                            let exact = Exact::pinhole(w, h, z_p, cols, rows);
                            let worst = largest_shift(&camera, &exact, 512);
                            assert!(
                                worst <= 0.5,
                                "{w} × {h} at {z_p}, {cols}x{rows}: {worst} px"
                            );
                        }
                        Err(
                            Error::OutOfRange { .. }
                            | Error::FieldOfViewTooNarrow { .. }
                            | Error::FieldOfViewTooWide { .. }
                            | Error::DegenerateCamera { .. },
                        ) => refused += 1,
                        Err(e) => panic!("{e:?}"),
                    }
                }
            }
        }
    }
    assert!(accepted > 500 && refused > 500, "{accepted} {refused}");
}

#[test]
fn fields_of_view_near_180_degrees_are_refused_not_wrapped() {
    let (o, ahead, up) = ([0.0; 3], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]);
    assert!(matches!(
        Camera::look_at(o, ahead)
            .up(up)
            .fov_degrees(179.999)
            .size(Size::new(1, 1))
            .build(),
        Err(Error::FieldOfViewTooWide {
            max_millidegrees: 179_990..=179_999
        })
    ));
    assert!(matches!(
        Camera::orbit([0.0, 0.0, -16.0], 16.0)
            .fov_degrees(179.999)
            .size(Size::new(1, 1))
            .build(),
        Err(Error::FieldOfViewTooWide { .. })
    ));
    // Every field of view up to 180°, on every screen: refused, or rays within half a pixel.
    for &(cols, rows) in &[(1, 1), (2, 2), (160, 128), (320, 240), (4096, 4096)] {
        for fov in [
            90.0, 120.0, 150.0, 151.0, 160.0, 170.0, 177.0, 178.0, 178.9, 179.0, 179.5, 179.9,
            179.99, 179.999, 179.9999, 179.99998,
        ] {
            match Camera::look_at(o, ahead)
                .up(up)
                .fov_degrees(fov)
                .size(Size::new(cols, rows))
                .build()
            {
                Ok(camera) => {
                    let exact = Exact::look_at(o, ahead, up, fov, cols, rows);
                    let worst = largest_shift(&camera, &exact, 256);
                    assert!(worst <= 0.5, "{fov}° {cols}x{rows}: {worst} px");
                }
                Err(Error::FieldOfViewTooWide { max_millidegrees }) => {
                    assert!((max_millidegrees as f32) < fov * 1000.0, "{fov}°")
                }
                Err(e) => panic!("{fov}° {cols}x{rows}: {e:?}"),
            }
        }
    }
}

/// The limits a look-at camera reports hold: a thousandth of a degree inside them the camera
/// is accepted and its rays are within half a pixel; a thousandth outside it is refused.
#[test]
fn the_field_of_view_limits_are_the_ones_reported() {
    let (o, ahead, up) = ([0.0; 3], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]);
    let camera = |fov: f32, cols, rows| {
        Camera::look_at(o, ahead)
            .up(up)
            .fov_degrees(fov)
            .size(Size::new(cols, rows))
            .build()
    };
    // Expected from F² + R² = 16 384·F, worked out by hand in f64 (README of the limits).
    for (cols, rows, narrowest, widest) in [
        (160, 128, 448, 178_852),
        (320, 240, 840, 177_668),
        (1920, 1080, 3793, 164_313),
        (4096, 4096, 14_721, 151_029),
    ] {
        assert_eq!(
            camera(0.001, cols, rows),
            Err(Error::FieldOfViewTooNarrow {
                min_millidegrees: narrowest
            })
        );
        assert_eq!(
            camera(179.9, cols, rows),
            Err(Error::FieldOfViewTooWide {
                max_millidegrees: widest
            })
        );
        let step = if cols > 1000 { 256 } else { 1 };
        for fov in [narrowest + 1, widest - 1] {
            let fov = fov as f32 / 1000.0;
            let accepted = camera(fov, cols, rows).unwrap();
            let exact = Exact::look_at(o, ahead, up, fov, cols, rows);
            let worst = largest_shift(&accepted, &exact, step);
            assert!(worst <= 0.5, "{fov}° {cols}x{rows}: {worst} px");
            eprintln!("{cols}x{rows} at {fov}°: rays within {worst:.3} px");
        }
        assert!(camera((narrowest - 1) as f32 / 1000.0, cols, rows).is_err());
        assert!(camera((widest + 1) as f32 / 1000.0, cols, rows).is_err());
    }
}

#[test]
fn every_function_that_takes_a_row_checks_it_the_same_way() {
    let (scene, camera) = (demo::scene(), demo::camera(40, 32).unwrap());
    let mut out = [Rgb::BLACK; 40];
    for row in [32, 33, 40000, u32::from(u16::MAX), 1 << 16, u32::MAX] {
        let refused = Err(Error::RowOutOfRange { row, rows: 32 });
        let called = std::cell::Cell::new(false);
        let call = || called.set(true);
        assert_eq!(shoot_row(&scene, &camera, row, |_, _, _| call()), refused);
        assert_eq!(
            shoot_row_skipping(&scene, &camera, row, |_| call(), |_, _, _| call()),
            refused
        );
        assert!(!called.get(), "row {row}: nothing may be shot");
        assert_eq!(render_row(&scene, &camera, row, &mut out), refused);
        assert_eq!(
            render_row_supersampled(&scene, &camera, row, 2, &mut out),
            refused
        );
        assert_eq!(camera.row_rays(row).map(|_| ()), refused);
        // The row is checked before the buffer.
        assert_eq!(render_row(&scene, &camera, row, &mut out[..3]), refused);
    }
    assert_eq!(out, [Rgb::BLACK; 40], "a refused row draws nothing");
    // The last row is a row.
    assert_eq!(shoot_row(&scene, &camera, 31, |_, _, _| {}), Ok(()));
    assert_eq!(
        shoot_row_skipping(&scene, &camera, 31, |_| {}, |_, _, _| {}),
        Ok(())
    );
    assert_eq!(render_row(&scene, &camera, 31, &mut out), Ok(()));
    assert_eq!(camera.row_rays(31).map(|r| r.len()), Ok(40));
    // A row buffer shorter than the row.
    let narrow = Err(Error::BufferLength {
        needed: 40,
        got: 39,
    });
    assert_eq!(render_row(&scene, &camera, 5, &mut out[..39]), narrow);
    assert_eq!(
        render_row_supersampled(&scene, &camera, 5, 3, &mut out[..39]),
        narrow
    );
}

#[test]
fn a_row_far_below_a_small_screen_is_refused_not_shot_upward() {
    // 2 × 2 at 60°: row 40 000 used to wrap and look straight up.
    let scene = demo::scene();
    let camera = Camera::look_at([0.0; 3], [0.0, 0.0, -1.0])
        .size(Size::new(2, 2))
        .build()
        .unwrap();
    assert_eq!(
        shoot_row(&scene, &camera, 40000, |_, _, _| {}),
        Err(Error::RowOutOfRange {
            row: 40000,
            rows: 2
        })
    );
    assert_eq!(
        shoot_row_skipping(&scene, &camera, 40000, |_| {}, |_, _, _| {}),
        Err(Error::RowOutOfRange {
            row: 40000,
            rows: 2
        })
    );
}

/// The demo scene through a look-at camera, fixray against the f64 reference at every pixel.
#[derive(Debug, Default)]
struct FovAccuracy {
    /// The view distance in pixels.
    view: f64,
    pixels: u32,
    /// Pixels where the two see different objects (or one sees nothing).
    mismatches: u32,
    /// The largest distance (pixels) between where fixray's ray of a pixel meets the exact
    /// screen and the pixel's centre.
    ray_shift: f64,
    /// The largest distance (pixels) from the centre of a mismatched pixel to the exact
    /// silhouette: how far the exact picture must move for the two to agree there.
    silhouette_shift: f64,
}

/// Eye, target and up of the field-of-view survey: from the origin at the right limb of the
/// red sphere (1.5, −0.5, −18) r 3, so that its silhouette crosses the screen's centre even at
/// the narrowest field of view.
const SURVEY: ([f32; 3], [f32; 3], [f32; 3]) = ([0.0; 3], [4.5, -0.5, -18.0], [0.0, 1.0, 0.0]);

fn survey(fov: f32, cols: u32, rows: u32) -> FovAccuracy {
    let (eye, target, up) = SURVEY;
    let scene = demo::scene();
    let dscene = DScene::from_scene(&scene).unwrap();
    let camera = Camera::look_at(eye, target)
        .up(up)
        .fov_degrees(fov)
        .size(Size::new(cols, rows))
        .build()
        .unwrap();
    let exact = Exact::look_at(eye, target, up, fov, cols, rows);
    let origin = DVec3::new(0.0, 0.0, 0.0);
    // The object the reference sees through the exact screen's point (x, y).
    let seen = |x: f64, y: f64| {
        let [a, b, c] = exact.towards(x, y);
        let ray = DRay::new(origin, DVec3::new(a, b, c)).unwrap();
        dscene.shoot(&ray).map(|h| h.object)
    };
    let mut a = FovAccuracy {
        view: rows as f64 / 2.0 / (f64::from(fov).to_radians() / 2.0).tan(),
        ..FovAccuracy::default()
    };
    for row in 0..rows {
        for col in 0..cols {
            let ray = camera.ray(col, row);
            let object = scene.shoot(&ray).map(|h| h.object());
            let (x, y) = (col as f64 + 0.5, row as f64 + 0.5);
            a.pixels += 1;
            a.ray_shift = a.ray_shift.max(exact.shift(&ray, col, row));
            if object == seen(x, y) {
                continue;
            }
            a.mismatches += 1;
            // The exact silhouette lies between the centre and the nearest point where the
            // reference sees fixray's object: look for it on circles of growing radius, then
            // bisect towards the centre along the ray that found it.
            let found = (1..=2000).find_map(|k| {
                let radius = k as f64 * 0.0005;
                (0..256).find_map(|i| {
                    let angle = i as f64 * std::f64::consts::TAU / 256.0;
                    let (dx, dy) = (radius * angle.cos(), radius * angle.sin());
                    (seen(x + dx, y + dy) == object).then_some((dx, dy))
                })
            });
            let (dx, dy) = found.expect("fixray's object is within a pixel of the exact one");
            let (mut inside, mut outside) = (1.0, 0.0);
            for _ in 0..40 {
                let mid = (inside + outside) / 2.0;
                if seen(x + mid * dx, y + mid * dy) == object {
                    inside = mid;
                } else {
                    outside = mid;
                }
            }
            a.silhouette_shift = a.silhouette_shift.max(inside * dx.hypot(dy));
        }
    }
    a
}

/// Object agreement with the f64 reference across fields of view, at 320 × 240 (the table of
/// `docs/ACCURACY_FOV.md`). Print it with
/// `cargo test --release --test camera_edges across_fields -- --nocapture`.
///
/// The bounds are the measured values: mismatches at most the count measured (a count can
/// only grow by a new rounding tie, which would be a change worth looking at), and shifts
/// at most the measured largest rounded up to the next 0.001 pixel.
#[test]
fn object_agreement_across_fields_of_view() {
    // fov, mismatched pixels, ray shift and silhouette shift (pixels).
    let measured: [(f32, u32, f64); 7] = [
        (0.841, 20, 0.278),
        (1.75, 8, 0.135),
        (5.0, 0, 0.048),
        (20.0, 4, 0.013),
        (60.0, 1, 0.008),
        (100.0, 0, 0.010),
        (150.0, 0, 0.022),
    ];
    eprintln!(
        "| field of view | view distance (px) | object agrees | mismatched pixels \
         | largest ray shift (px) | largest silhouette shift (px) |"
    );
    eprintln!("|---|---|---|---|---|---|");
    for (fov, mismatches, ray_shift) in measured {
        let a = survey(fov, 320, 240);
        eprintln!(
            "| {fov}° | {:.0} | {:.3} % | {} | {:.3} | {:.3} |",
            a.view,
            100.0 * (a.pixels - a.mismatches) as f64 / a.pixels as f64,
            a.mismatches,
            a.ray_shift,
            a.silhouette_shift
        );
        assert_eq!(a.pixels, 320 * 240);
        // One pixel of headroom: a silhouette tie that another rounding of the hit tests
        // may flip either way.
        assert!(a.mismatches <= mismatches + 1, "{fov}°: {a:?}");
        assert!(a.ray_shift <= ray_shift, "{fov}°: {a:?}");
        // Every disagreement lies within the rays' own shift of the exact silhouette: the
        // hit tests add nothing visible.
        assert!(a.silhouette_shift <= a.ray_shift, "{fov}°: {a:?}");
    }
}

/// At the narrowest field of view a screen allows (the largest view distance), the culling
/// of `render_row` (row planes, column spans, runs) still changes no pixel.
#[test]
fn render_row_equals_trace_at_the_field_of_view_limits() {
    let (eye, target, up) = SURVEY;
    let scene = demo::scene();
    for fov in [0.841, 177.6] {
        let camera = Camera::look_at(eye, target)
            .up(up)
            .fov_degrees(fov)
            .size(Size::new(320, 240))
            .build()
            .unwrap();
        let mut out = [Rgb::BLACK; 320];
        for row in 0..240 {
            render_row(&scene, &camera, row, &mut out).unwrap();
            for (col, &pixel) in (0..).zip(out.iter()) {
                assert_eq!(
                    pixel,
                    scene.trace(&camera.ray(col, row)),
                    "{fov}° ({row}, {col})"
                );
            }
        }
    }
}

/// `v` rounded to Q16.16 (and exactly an `f32` within ±256): inputs that the camera takes as
/// they are, so that the f64 screen built from them is the one fixray is asked for.
fn on_grid(v: V) -> [f32; 3] {
    v.map(|c| ((c * 65536.0).round() / 65536.0) as f32)
}

/// An up vector `angle` degrees off the view from `eye` to `target`, turned towards `towards`
/// (any vector not along the view), on the Q16.16 grid, and its angle to the view as rounded.
fn up_off_the_view(eye: [f32; 3], target: [f32; 3], towards: V, angle: f64) -> ([f32; 3], f64) {
    let f = unit(sub(f64s(target), f64s(eye)));
    let side = unit(cross(f, towards));
    let across = cross(side, f);
    let (s, c) = angle.to_radians().sin_cos();
    let up = on_grid(std::array::from_fn(|i| f[i] * c + across[i] * s));
    let sine = dot(cross(f, unit(f64s(up))), cross(f, unit(f64s(up)))).sqrt();
    (up, sine.asin().to_degrees())
}

/// The README's half pixel holds however close to the view `up` is, where the camera
/// accepts it: `up` a quarter of a degree off a generic view once moved the corners of a
/// 4096 × 4096 screen by more than ten pixels (`right = unit(forward × up)` rounded by about
/// 2⁻¹⁶/sin θ). Where it is refused, it is as parallel to the view.
#[test]
fn look_at_rays_stay_within_half_a_pixel_with_up_near_the_view() {
    let views: [([f32; 3], [f32; 3], V); 4] = [
        ([1.25, 2.5, 3.0], [-4.0, 0.5, -9.0], [0.3, 1.0, 0.1]),
        ([0.0; 3], [5.0, 3.0, -1.0], [0.0, 0.0, 1.0]),
        ([-7.5, 0.75, 12.0], [3.0, -2.25, -30.5], [1.0, -0.2, 0.4]),
        ([100.0, -50.0, 25.0], [99.0, -48.0, 27.5], [-0.7, 0.1, 0.9]),
    ];
    let angles = [0.2, 0.22, 0.23, 0.25, 0.3, 0.5, 1.0, 2.0, 10.0, 90.0];
    let sizes = [(320, 240), (1920, 1080), (4096, 4096)];
    let (mut accepted, mut worst_seen) = (0, 0.0f64);
    for (eye, target, towards) in views {
        for angle in angles {
            let (up, angle) = up_off_the_view(eye, target, towards, angle);
            for (cols, rows) in sizes {
                for fov in [60.0, 20.0, 150.0] {
                    let built = Camera::look_at(eye, target)
                        .up(up)
                        .fov_degrees(fov)
                        .size(Size::new(cols, rows))
                        .build();
                    let camera = match built {
                        Ok(camera) => camera,
                        Err(Error::DegenerateCamera(fixray::CameraProblem::UpAlongView)) => {
                            assert!(angle < 0.25, "{angle}° refused as along the view");
                            continue;
                        }
                        Err(
                            Error::FieldOfViewTooNarrow { .. } | Error::FieldOfViewTooWide { .. },
                        ) => {
                            continue;
                        }
                        Err(e) => panic!("{e:?}"),
                    };
                    accepted += 1;
                    let exact = Exact::look_at(eye, target, up, fov, cols, rows);
                    let worst = largest_shift(&camera, &exact, (cols / 16).max(1));
                    worst_seen = worst_seen.max(worst);
                    assert!(
                        worst <= 0.5,
                        "up {angle:.4}° off the view from {eye:?} to {target:?}, {fov}° at \
                         {cols}x{rows}: a ray {worst:.3} px off"
                    );
                }
            }
        }
    }
    eprintln!("{accepted} cameras, worst ray {worst_seen:.3} px off");
    assert!(accepted > 200, "{accepted}");
}

/// The limits a look-at camera names are fields of view it accepts, and the widest (or
/// narrowest) such in thousandths of a degree: on many screens, square and not, tiny and
/// large, each limit is accepted and a thousandth of a degree past it refused. (The limit was
/// once named from the budget's continuous equation, while the check takes the view distance
/// as rounded: 1 × 1 named 179.993° and refused it.)
#[test]
fn the_field_of_view_limits_named_are_accepted_on_every_screen() {
    // Along an axis (the basis exact) and not (a row step a unit of 2⁻¹⁶ off one pixel).
    for target in [[0.0, 0.0, -1.0], [5.0, 3.0, -1.0]] {
        limits_named_are_accepted(target);
    }
}

fn limits_named_are_accepted(target: [f32; 3]) {
    let camera = |fov: f32, cols, rows| {
        Camera::look_at([0.0; 3], target)
            .fov_degrees(fov)
            .size(Size::new(cols, rows))
            .build()
    };
    let mut sizes = vec![
        (1, 1),
        (2, 1),
        (1, 2),
        (3, 3),
        (8, 8),
        (7, 5),
        (160, 128),
        (320, 240),
        (1920, 1080),
        (4096, 4096),
        (4096, 1),
        (1, 4096),
    ];
    let mut state = 0x9e37_79b9_u32;
    for _ in 0..120 {
        let mut next = |n: u32| {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            1 + state % n
        };
        let n = if sizes.len() % 2 == 0 { 64 } else { 4096 };
        sizes.push((next(n), next(n)));
    }
    let mut wrong = Vec::new();
    for (cols, rows) in sizes {
        match camera(179.9999, cols, rows) {
            Err(Error::FieldOfViewTooWide { max_millidegrees }) => {
                let widest = max_millidegrees as f32 / 1000.0;
                let past = (max_millidegrees + 1) as f32 / 1000.0;
                if camera(widest, cols, rows).is_err() || camera(past, cols, rows).is_ok() {
                    wrong.push(format!(
                        "{cols}x{rows}: widest named {max_millidegrees} m°, which is {:?}; \
                         one more is {:?}",
                        camera(widest, cols, rows).err(),
                        camera(past, cols, rows).err()
                    ));
                }
            }
            other => panic!("{cols}x{rows} at 179.9999°: {other:?}"),
        }
        match camera(0.0001, cols, rows) {
            Err(Error::FieldOfViewTooNarrow { min_millidegrees }) => {
                let narrowest = min_millidegrees as f32 / 1000.0;
                let before = (min_millidegrees - 1) as f32 / 1000.0;
                if camera(narrowest, cols, rows).is_err() || camera(before, cols, rows).is_ok() {
                    wrong.push(format!(
                        "{cols}x{rows}: narrowest named {min_millidegrees} m°, which is {:?}; \
                         one less is {:?}",
                        camera(narrowest, cols, rows).err(),
                        camera(before, cols, rows).err()
                    ));
                }
            }
            other => panic!("{cols}x{rows} at 0.0001°: {other:?}"),
        }
    }
    assert!(
        wrong.is_empty(),
        "{} limits:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
}
