use super::*;
use crate::render::accel::row_rays::RowSquares;

#[test]
fn chapter_screen_pixel_centres() {
    // w = 5, h = 3, z_p = 1 over M = 3 rows and N = 5 columns: one unit per pixel.
    let cam = Camera::pinhole(5.0, 3.0, 1.0)
        .size(Size::new(5, 3))
        .build()
        .unwrap();
    for i in 0..3u32 {
        for j in 0..5u32 {
            let expect = crate::check::f32_point(
                [-2.5 + (j as f32 + 0.5), -1.5 + (i as f32 + 0.5), -1.0],
                Quantity::PlanePoint,
            )
            .unwrap();
            assert_eq!(
                cam.pixel_centre(j, 2 - i),
                expect,
                "chapter pixel ({i}, {j})"
            );
        }
    }
}

#[test]
fn picture_is_upright_and_unmirrored() {
    let cam = Camera::pinhole(2.0, 2.0, 1.0)
        .size(Size::new(10, 10))
        .build()
        .unwrap();
    assert!(cam.ray(5, 0).dir.y > Fx::ZERO, "row 0 looks up");
    assert!(cam.ray(5, 9).dir.y < Fx::ZERO, "last row looks down");
    assert!(cam.ray(0, 5).dir.x < Fx::ZERO, "column 0 looks left");
    let general = Camera::look_at([0.0; 3], [0.0, 0.0, -1.0])
        .fov_degrees(90.0)
        .size(Size::new(10, 10))
        .build()
        .unwrap();
    assert!(general.ray(5, 0).dir.y > Fx::ZERO);
    assert!(general.ray(0, 5).dir.x < Fx::ZERO);
}

#[test]
fn stepping_along_a_row_gives_every_pixel_its_own_ray() {
    let orbit = Camera::orbit([0.0, 0.0, -16.0], 20.0)
        .yaw_degrees(33.0)
        .pitch_degrees(21.0)
        .fov_degrees(75.0)
        .size(Size::new(40, 64))
        .build()
        .unwrap();
    for camera in odd_cameras().into_iter().chain([orbit]) {
        for y in 0..camera.height() {
            let mut towards = camera.row_start(y as u16);
            let mut square = RowSquares::new(towards, camera.column_step());
            for x in 0..camera.width() {
                assert_eq!(towards, camera.towards(x, y), "({x}, {y})");
                assert_eq!(square.carried(), towards.length_squared_wide());
                assert_eq!(square.now(towards), towards.length_squared_wide());
                let ray = camera.ray_along(towards, square.carried());
                assert_eq!(ray, camera.ray(x, y));
                towards = towards + camera.column_step();
                square.step();
            }
            // Skipping ahead lands on the same rays.
            for skip in [0u32, 3, 9, 100] {
                let mut rays = camera.row_rays(y).unwrap();
                rays.nth(4);
                let x = 5 + skip; // past the five rays already taken
                let expected = (x < camera.width()).then(|| camera.ray(x, y));
                assert_eq!(rays.nth(skip as usize), expected, "({x}, {y})");
            }
        }
    }
}

#[test]
fn look_at_down_minus_z_matches_the_pinhole() {
    // A 90° field of view at distance 1 is a 2 × 2 screen.
    let a = Camera::look_at([0.0; 3], [0.0, 0.0, -5.0])
        .up([0.0, 3.0, 0.0])
        .fov_degrees(90.0)
        .size(Size::new(8, 8))
        .build()
        .unwrap();
    let b = Camera::pinhole(2.0, 2.0, 1.0)
        .size(Size::new(8, 8))
        .build()
        .unwrap();
    for (row, col) in [(0, 0), (3, 4), (7, 7)] {
        let (da, db) = (a.ray(col, row).dir, b.ray(col, row).dir);
        for (p, q) in [(da.x, db.x), (da.y, db.y), (da.z, db.z)] {
            assert!((p - q).abs() <= Fx::from_bits(4), "{da:?} vs {db:?}");
        }
    }
}

#[test]
fn directions_of_the_screen_fit_without_scaling() {
    // The ray budget's promise that `towards_sample` relies on for the rows and columns of
    // the screen: every sample's direction is at most 16 384 pixels a component, so it is
    // rounded as it is, never scaled. Tried at the budget's edges.
    let (o, ahead, up) = ([0.0; 3], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]);
    let cameras = [
        Camera::look_at(o, ahead)
            .up(up)
            .fov_degrees(0.841)
            .size(Size::new(320, 240))
            .build()
            .unwrap(),
        Camera::look_at(o, ahead)
            .up(up)
            .fov_degrees(14.722)
            .size(Size::new(4096, 4096))
            .build()
            .unwrap(),
        Camera::look_at(o, ahead)
            .up(up)
            .fov_degrees(151.028)
            .size(Size::new(4096, 4096))
            .build()
            .unwrap(),
        Camera::look_at([1.0, 2.0, 3.0], [-4.0, 0.5, -9.0])
            .up([0.1, 1.0, 0.2])
            .fov_degrees(15.0)
            .size(Size::new(4096, 4096))
            .build()
            .unwrap(),
        Camera::pinhole(1.0, 8.0, 4.0)
            .size(Size::new(1024, 2048))
            .build()
            .unwrap(),
        Camera::pinhole(8.0, 1.0, 16.0)
            .size(Size::new(2048, 1024))
            .build()
            .unwrap(),
    ];
    for camera in cameras {
        let (w, h) = (camera.width(), camera.height());
        for (x, y) in [(0, 0), (w - 1, 0), (0, h - 1), (w - 1, h - 1)] {
            for (s, t, n) in [(0, 0, 1), (0, 0, 16), (15, 15, 16), (0, 15, 16)] {
                let (wide, denom) = camera.towards_wide(x, y, s, t, n);
                assert_eq!(
                    Camera::shift_to_fit(&wide, denom),
                    0,
                    "{camera:?} ({x}, {y})"
                );
            }
        }
    }
}

/// The limit `check_budget` names, worked out in `f64` from the budget's equation
/// `F² − B·F + R² = 0`, before rounding up (narrowest) or down (widest); `None` where it
/// has no root.
fn limit_in_f64(aspect: Fx, cols: u16, rows: u16, narrow: bool) -> Option<f64> {
    let half_height = rows as f64 * aspect.to_num::<f64>() / 2.0;
    let half_width = cols as f64 / 2.0;
    let b = RAY_BUDGET_PX as f64;
    let discriminant = b * b - 4.0 * (half_width * half_width + half_height * half_height);
    if discriminant < 0.0 {
        return None;
    }
    let root = if narrow {
        b + discriminant.sqrt()
    } else {
        b - discriminant.sqrt()
    };
    Some(2.0 * (half_height / (root / 2.0)).atan().to_degrees() * 1000.0)
}

#[test]
fn the_limits_are_those_of_the_budget_in_f64() {
    // Screens from 1 × 1 to 4096 × 4096, square pixels as `look_at` rounds them and any
    // pinhole aspect from 1/4 to 4, each refused past both ends of the budget.
    let mut random = crate::xorshift::XorShift(0x5eed_f00d);
    let named = [(1, 1), (2, 2), (3, 5), (160, 128), (320, 240), (1920, 1080)];
    let drawn = (0..20_000).map(|_| {
        let r = random.next();
        let (cols, rows) = ((r % 4096) as u16 + 1, ((r >> 12) % 4096) as u16 + 1);
        let aspect = match (r >> 24) % 3 {
            0 => (1 << 16) + ((r >> 26) % 9) as i32 - 4,
            _ => (1 << 14) + ((r >> 26) % (15 << 14)) as i32,
        };
        (cols, rows, aspect)
    });
    // The last is 16 384 pixels high: no view distance meets the budget.
    let screens = named
        .map(|(cols, rows)| (cols, rows, 1 << 16))
        .into_iter()
        .chain([(4096, 4096, 4 << 16)]);
    let (mut compared, mut close, mut degenerate) = (0, 0, 0);
    for (cols, rows, aspect) in screens.chain(drawn) {
        let aspect = Fx::from_bits(aspect);
        for (view, narrow) in [(RAY_BUDGET_PX << FRAC | 1, true), (1, false)] {
            let found = check_budget(Fx::from_bits(view as i32), aspect, cols, rows);
            let Some(exact) = limit_in_f64(aspect, cols, rows, narrow) else {
                assert_eq!(
                    found,
                    Err(Error::DegenerateCamera(CameraProblem::DiagonalTooLong))
                );
                degenerate += 1;
                continue;
            };
            let (limit, want) = match found {
                Err(Error::FieldOfViewTooNarrow { min_millidegrees }) if narrow => {
                    (min_millidegrees, exact.ceil())
                }
                Err(Error::FieldOfViewTooWide { max_millidegrees }) if !narrow => {
                    (max_millidegrees, exact.floor())
                }
                other => panic!("{cols}x{rows} at {aspect}: {other:?}"),
            };
            compared += 1;
            // Within 10⁻⁵ of a whole millidegree, rounding may go either way; elsewhere
            // the limit is the f64 one exactly.
            if (exact - exact.round()).abs() < 1e-5 {
                close += 1;
                assert!((limit as f64 - want).abs() <= 1.0, "{cols}x{rows}: {exact}");
            } else {
                assert_eq!(limit as f64, want, "{cols}x{rows} at {aspect}: {exact}");
            }
        }
    }
    assert!(
        compared > 30_000 && degenerate > 1,
        "{compared} {degenerate}"
    );
    assert!(close < 10, "{close} limits within 10⁻⁵ of a millidegree");
}

#[test]
fn doubled_angles_are_good_to_a_millionth_of_a_millidegree() {
    // The table's turns are atan(2⁻ⁱ), and whole angles agree with f64 from 0° to 180°.
    let unit = (1u64 << 32) as f64;
    let mut random = crate::xorshift::XorShift(0xa7a2);
    for _ in 0..20_000 {
        let r = random.next();
        let (x, y) = ((r >> (r % 40)) | 1, random.next() >> ((r >> 8) % 40));
        let want = 2.0 * (y as f64).atan2(x as f64).to_degrees() * 1000.0;
        let found = doubled_angle(x, y) as f64 / unit;
        assert!((found - want).abs() < 1e-6, "{x} {y}: {found} {want}");
    }
    for (x, y, degrees) in [(1, 0, 0.0), (1, 1, 90.0), (1, u64::MAX, 180.0)] {
        let found = doubled_angle(x, y) as f64 / unit;
        assert!((found - degrees * 1000.0).abs() < 1e-6, "{found}");
    }
}

#[test]
fn sample_directions_are_the_wide_ones_divided_once_and_rounded_half_up() {
    // The shift-then-divide rounding of `towards_sample` against one plain division by
    // 2n·2^shift, on and off the screen, for every grid size.
    let wide = Camera::look_at([0.0; 3], [0.0, 0.0, -1.0])
        .fov_degrees(150.0)
        .size(Size::new(4096, 4096))
        .build()
        .unwrap();
    let cameras = odd_cameras().into_iter().chain([wide]);
    let mut random = crate::xorshift::XorShift(0x70_3a2d);
    let mut scaled = 0;
    for camera in cameras {
        for _ in 0..5_000 {
            let r = random.next();
            let n = (r % 16) as u8 + 1;
            let (sx, sy) = ((r >> 4) as u8 % n, (r >> 12) as u8 % n);
            // Any u32 column and row, up to the largest, where the sums come nearest
            // their 2⁵⁷ bound.
            let far = random.next();
            let (x, y) = (far as u32, (far >> 32) as u32);
            let (x, y) = match r >> 61 {
                0 | 1 => (x % camera.width(), y % camera.height()),
                2 => (x, y % camera.height()),
                3 => (x % camera.width(), y),
                4 => (u32::MAX, u32::MAX - (r >> 20) as u32 % 2),
                _ => (x, y),
            };
            let (wide, denom) = camera.towards_wide(x, y, sx, sy, n);
            let shift = if x < camera.width() && y < camera.height() {
                0
            } else {
                Camera::shift_to_fit(&wide, denom)
            };
            scaled += (shift > 0) as u32;
            let divisor = denom << shift;
            let want = wide.map(|w| Fx::from_bits((w + divisor / 2).div_euclid(divisor) as i32));
            let found = camera.towards_sample(x, y, sx, sy, n);
            assert_eq!(
                found,
                Vec3::new(want[0], want[1], want[2]),
                "({x}, {y}) {n}"
            );
        }
    }
    assert!(scaled > 1_000, "{scaled} directions scaled to fit");
}

#[test]
fn rays_far_off_the_screen_continue_its_plane() {
    // The last u32 column looks along `right` (plus at most 2⁻¹⁵ of the view), never
    // wrapped round to the left; the last row looks down.
    let camera = Camera::look_at([1.0, 2.0, 3.0], [-4.0, 0.5, -9.0])
        .up([0.1, 1.0, 0.2])
        .fov_degrees(47.0)
        .size(Size::new(61, 29))
        .build()
        .unwrap();
    let near = |a: Vec3, b: Vec3| {
        let d = a - b;
        d.x.abs().max(d.y.abs()).max(d.z.abs()) <= Fx::from_bits(4)
    };
    let right = camera.right.normalize_or_zero();
    let down = camera.down.normalize_or_zero();
    assert!(near(camera.ray(u32::MAX, 14).dir, right));
    assert!(near(camera.ray(30, u32::MAX).dir, down));
    assert!(near(camera.sample_ray(u32::MAX, 14, 15, 15, 16).dir, right));
    // Pixel centres far off the screen saturate, on the right side.
    let far = camera.pixel_centre(u32::MAX, 14) - camera.eye();
    assert!(far.dot(right) > Fx::ZERO);
}

#[test]
fn sizes_are_one_to_4096_pixels_a_side() {
    let build = |size| {
        Camera::look_at([0.0; 3], [0.0, 0.0, -1.0])
            .size(size)
            .build()
    };
    for size in [Size::new(1, 1), Size::new(4096, 4096), Size::new(1, 4096)] {
        assert_eq!(build(size).map(|c| c.size()), Ok(size));
    }
    for size in [
        Size::zero(),
        Size::new(0, 4),
        Size::new(4097, 1),
        Size::new(1, u32::MAX),
    ] {
        assert!(
            matches!(build(size), Err(Error::DegenerateCamera(_))),
            "{size:?}"
        );
    }
    // A builder whose size was never set has no pixels.
    assert!(matches!(
        Camera::pinhole(1.0, 1.0, 1.0).build(),
        Err(Error::DegenerateCamera(CameraProblem::NoPixels))
    ));
    assert!(Camera::orbit([0.0; 3], 4.0).build().is_err());
    // (width, height) = (columns, rows).
    let camera = build(Size::new(320, 240)).unwrap();
    assert_eq!((camera.width(), camera.height()), (320, 240));
    assert_eq!((camera.cols(), camera.rows()), (320, 240));
}

#[test]
fn degenerate_cameras_are_refused() {
    let up = [0.0, 1.0, 0.0];
    let err = |r: Result<Camera, Error>| r.unwrap_err();
    assert!(matches!(
        err(Camera::look_at([1.0; 3], [1.0; 3])
            .up(up)
            .size(Size::new(4, 4))
            .build()),
        Error::DegenerateCamera(CameraProblem::TargetIsEye)
    ));
    assert!(matches!(
        err(Camera::look_at([0.0; 3], [0.0, 0.0, -1.0])
            .up([0.0; 3])
            .size(Size::new(4, 4))
            .build()),
        Error::DegenerateCamera(CameraProblem::UpIsZero)
    ));
    assert!(matches!(
        err(Camera::look_at([0.0; 3], [0.0, 0.0, -1.0])
            .up(up)
            .fov_degrees(0.0)
            .size(Size::new(4, 4))
            .build()),
        Error::DegenerateCamera(CameraProblem::FieldOfView)
    ));
    assert!(matches!(
        err(Camera::look_at([0.0; 3], [0.0, 0.0, -1.0])
            .up(up)
            .fov_degrees(f32::NAN)
            .size(Size::new(4, 4))
            .build()),
        Error::NotFinite {
            quantity: Quantity::FieldOfView
        }
    ));
    assert!(matches!(
        err(Camera::look_at([0.0; 3], [0.0, 0.0, -1.0])
            .up(up)
            .size(Size::new(0, 4))
            .build()),
        Error::DegenerateCamera(CameraProblem::NoPixels)
    ));
    assert!(matches!(
        err(Camera::pinhole(-1.0, 1.0, 1.0)
            .size(Size::new(4, 4))
            .build()),
        Error::OutOfRange {
            quantity: Quantity::ScreenWidth,
            ..
        }
    ));
    assert!(matches!(
        err(Camera::pinhole(1.0, 1.0, f32::INFINITY)
            .size(Size::new(4, 4))
            .build()),
        Error::NotFinite {
            quantity: Quantity::ScreenDistance
        }
    ));
}

/// A pinhole with non-square pixels and a tilted look-at camera, both of odd sizes: cameras
/// whose rays share nothing with the axes.
fn odd_cameras() -> [Camera; 2] {
    [
        Camera::pinhole(3.7, 2.1, 1.3)
            .size(Size::new(53, 37))
            .build()
            .unwrap(),
        Camera::look_at([1.0, 2.0, 3.0], [-4.0, 0.5, -9.0])
            .up([0.1, 1.0, 0.2])
            .fov_degrees(47.0)
            .size(Size::new(61, 29))
            .build()
            .unwrap(),
    ]
}

#[test]
fn a_spheres_columns_hold_every_column_that_meets_it_and_hug_its_tangents() {
    // Spheres of radius from a hundredth of a unit to 500, from the edge of the eye's plane to
    // far off, seen by cameras of 1° to 179° and up to 1024 columns: every column whose ray
    // meets a sphere lies in its span. Where the span's widening (2⁻¹² of the centre's
    // distance and 2⁻⁷) is under half a column at the tangents, each end lies within 3
    // columns of the exact tangent (worked out in f64 from the camera's own vectors).
    let mut rng = crate::xorshift::XorShift(0x7a46_e175_0f5b_a11e);
    let (mut spans, mut hits, mut hugged) = (0, 0, 0);
    for case in 0..6000 {
        let mut next = |range: f32| rng.signed(range);
        let eye = [next(1000.0), next(1000.0), next(1000.0)];
        let reach = 1.0 + next(1.0).abs() * 60.0;
        let look = [next(1.0), next(1.0), next(1.0)];
        let target = [0, 1, 2].map(|i| eye[i] + look[i] * reach);
        let size = Size::new(
            1 + (2f32.powf(next(1.0).abs() * 10.0)) as u32,
            1 + (next(1.0).abs() * 40.0) as u32,
        );
        let Ok(camera) = Camera::look_at(eye, target)
            .up([next(1.0), next(1.0), next(1.0)])
            .fov_degrees(1.0 + next(1.0).abs() * 178.0)
            .size(size)
            .build()
        else {
            continue;
        };
        let radius = 0.01 * 2f32.powf(next(1.0).abs() * 15.6);
        let centre = [0, 1, 2].map(|i| target[i] + next(0.4) * reach + next(1.0) * radius);
        let Ok(sphere) = crate::Sphere::new(centre, radius) else {
            continue;
        };
        let Some((first, last)) = camera.column_span(sphere.centre(), sphere.radius()) else {
            continue;
        };
        spans += 1;
        for row in (0..camera.rows()).step_by(3) {
            for col in camera.columns_meeting(&sphere, row) {
                hits += 1;
                assert!(
                    (first..=last).contains(&col),
                    "case {case}, row {row}: column {col} outside {first}..={last}"
                );
            }
        }
        // The exact tangents, in the camera's own frame.
        let f = |v: Vec3| [v.x, v.y, v.z].map(|c| c.to_num::<f64>());
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let (right, forward) = (f(camera.right), f(camera.forward));
        let view = dot(forward, forward).sqrt();
        let d = [0, 1, 2].map(|i| f(sphere.centre())[i] - f(camera.eye())[i]);
        let (x, z, r) = (
            dot(right, d),
            dot(forward, d) / view,
            sphere.radius().to_num::<f64>(),
        );
        let k = (x * x + z * z - r * r).sqrt();
        let widening = d.iter().map(|c| c.abs()).sum::<f64>() / 4096.0 + 1.0 / 128.0;
        let column = |t: f64| view * t + camera.cols() as f64 / 2.0 - 0.5;
        let (low, high) = (
            (x * z - r * k) / (z * z - r * r),
            (x * z + r * k) / (z * z - r * r),
        );
        let spread = |t: f64| view * (1.0 + t * t) * widening / k;
        let (a, b) = (column(low), column(high));
        if spread(low).max(spread(high)) < 0.5 && a > 0.0 && b < camera.cols() as f64 {
            hugged += 1;
            assert!(
                f64::from(first) >= a.floor() - 3.0 && f64::from(last) <= b.ceil() + 3.0,
                "case {case}: {first}..={last} against the tangents' {a:.2}..={b:.2}"
            );
        }
    }
    assert!(
        spans > 3000 && hits > 80_000 && hugged > 2000,
        "{spans} spans, {hits} hits, {hugged} hugged"
    );
}

#[test]
fn row_plane_normals_are_within_a_rounding_of_the_rows_plane_however_short_the_rays() {
    // The exact normal, in f64, of the plane through the eye along `right` and the direction
    // towards column 0 of the row (both as the camera rounded them, and exactly representable
    // in f64): the rounded unit normal is within 0.55 of a unit of 2⁻¹⁶ (and 2⁻³⁰ more) a
    // component, on screens of one pixel at the widest views (directions a few raw units
    // long) as on large ones, and on rows far off the screen.
    let mut random = crate::xorshift::XorShift(0x0e37_0009);
    let (mut tried, mut short) = (0, 0);
    let sizes = [(1, 1), (2, 1), (3, 3), (8, 8), (160, 128), (4096, 4096)];
    for case in 0..3000 {
        let (cols, rows) = sizes[case % sizes.len()];
        let eye = [
            random.signed(30.0),
            random.signed(30.0),
            random.signed(30.0),
        ];
        let target = [
            random.signed(30.0),
            random.signed(30.0),
            random.signed(30.0),
        ];
        let up = [random.signed(1.0), random.signed(1.0), random.signed(1.0)];
        let fov = 180.0 - 10f32.powf(random.signed(3.0) - 0.5);
        let Ok(camera) = Camera::look_at(eye, target)
            .up(up)
            .fov_degrees(fov)
            .size(Size::new(cols, rows))
            .build()
        else {
            continue;
        };
        tried += 1;
        short += (camera.view < Fx::from_bits(1 << 10)) as u32;
        let f = |v: Vec3| [v.x.to_num::<f64>(), v.y.to_num(), v.z.to_num()];
        for row in [
            0,
            camera.rows() / 2,
            camera.rows() - 1,
            camera.rows(),
            u16::MAX,
        ] {
            let (r, w) = (f(camera.right), f(camera.towards(0, row.into())));
            let n = [
                r[1] * w[2] - r[2] * w[1],
                r[2] * w[0] - r[0] * w[2],
                r[0] * w[1] - r[1] * w[0],
            ];
            let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            let got = f(camera.row_plane_normal(row).unwrap());
            for i in 0..3 {
                let off = (got[i] - n[i] / length).abs() * 65536.0;
                assert!(
                    off <= 0.55 + 1e-4,
                    "{camera:?} row {row}: component {i} {off} units off"
                );
            }
        }
    }
    assert!(
        tried > 1000 && short > 100,
        "{tried} cameras, {short} short"
    );
}
