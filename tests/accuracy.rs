//! Whole images: the fixed-point renderer against the f64 reference, pixel by pixel.
//!
//! The thresholds are the ones docs/ACCURACY.md states: for the demo scene the object hit
//! agrees on at least 99.9 % of pixels, and where it agrees every 8-bit channel is within ±2;
//! on both scenes, every pixel that is stable in the reference (its colour moves by at most 4
//! when its ray's direction moves by 2⁻¹⁶) is within ±4, except on the classic scene's mirror
//! ball, whose highlight is held to a looser bound below.

#[path = "common/accuracy.rs"]
mod accuracy;

use accuracy::{Accuracy, STABLE_WITHIN};
use fixray::{Camera, Size, demo};
use fixray_reference::{DCamera, DScene, DVec3};

fn demo_dcamera(cols: u32, rows: u32) -> DCamera {
    fixray_reference::demo_camera(cols, rows).unwrap()
}

fn check(name: &str, a: &Accuracy) {
    eprintln!("{name}: {a:?}");
    assert!(
        a.same_object_percent() >= 99.9,
        "{name}: object agrees on {:.3} % of pixels",
        a.same_object_percent()
    );
    assert!(
        a.max_channel_error <= 2,
        "{name}: a channel is {} off where the object agrees",
        a.max_channel_error
    );
    check_stable(name, a);
}

/// The bound on stable pixels says little if few are: at least 99 % of a frame must be
/// stable, and every stable pixel within ±[`STABLE_WITHIN`].
fn check_stable(name: &str, a: &Accuracy) {
    assert!(
        a.stable_percent() >= 99.0,
        "{name}: only {:.3} % of pixels are stable",
        a.stable_percent()
    );
    assert!(
        a.max_stable_error <= STABLE_WITHIN,
        "{name}: a stable pixel is {} off",
        a.max_stable_error
    );
}

#[test]
fn demo_scene_at_160_by_128_matches_the_reference() {
    let scene = demo::scene();
    let dscene = DScene::from_scene(&scene).unwrap();
    let a = Accuracy::measure(
        &scene,
        &demo::camera(160, 128).unwrap(),
        &dscene,
        &demo_dcamera(160, 128),
    );
    assert_eq!(a.pixels, 160 * 128);
    check("demo 160x128", &a);
}

#[test]
fn demo_scene_through_the_look_at_camera_matches_the_reference() {
    let scene = demo::scene();
    let dscene = DScene::from_scene(&scene).unwrap();
    let (eye, target, up) = (
        [1.0f32, 2.0, 3.0],
        [-1.0f32, -1.0, -15.0],
        [0.0f32, 1.0, 0.2],
    );
    let v = |p: [f32; 3]| DVec3::new(p[0] as f64, p[1] as f64, p[2] as f64);
    let camera = Camera::look_at(eye, target)
        .up(up)
        .fov_degrees(50.0)
        .size(Size::new(160, 128))
        .build()
        .unwrap();
    let dcamera = DCamera::look_at(v(eye), v(target), v(up), 50.0, 160, 128).unwrap();
    check(
        "demo look-at 160x128",
        &Accuracy::measure(&scene, &camera, &dscene, &dcamera),
    );
}

#[test]
fn an_upside_down_render_would_fail() {
    // The comparison itself must be able to fail: a reference camera turned upside down
    // disagrees on most pixels.
    let scene = demo::scene();
    let dscene = DScene::from_scene(&scene).unwrap();
    let flipped = DCamera::look_at(DVec3::ZERO, -DVec3::Z, -DVec3::Y, 60.0, 40, 32).unwrap();
    let a = Accuracy::measure(&scene, &demo::camera(40, 32).unwrap(), &dscene, &flipped);
    assert!(a.same_object_percent() < 90.0, "{a:?}");
}

/// The classic scene against the reference at `cols × rows`. Highlights, shadows, mirrors, a
/// checkerboard and glass amplify rounding (a ray bent twice by the glass ball lands on another
/// square of the board), so it is held to the contract of fixray 0.3's issue: the object
/// agrees on ≥ 99.9 % of pixels, ≥ 99.9 % of pixels are within ±2 per channel, and every
/// stable pixel is within ±4 — the mirror ball's highlight included (a specular weight of 10
/// at a shininess of 1425 turns each unit of 2⁻¹⁶ its cosine is off into several levels:
/// with the half vector made a unit vector before the cosine was taken it was 5, with the
/// normal left at the length `(x − c)/r` 19). Where the object agrees ≥ 99 % of pixels are
/// within ±4.
fn check_classic(cols: u32, rows: u32) {
    let scene = demo::classic();
    let dscene = DScene::from_scene(&scene).unwrap();
    assert!(
        scene
            .objects()
            .iter()
            .any(|o| o.material.refraction().is_some())
    );
    let camera = demo::classic_camera(cols, rows).unwrap();
    let dcamera = fixray_reference::classic_camera(cols, rows).unwrap();
    let mut stable_worst = 0u8;
    let a = Accuracy::measure_each(&scene, &camera, &dscene, &dcamera, |p| {
        if p.stable {
            stable_worst = stable_worst.max(p.error());
        }
    });
    eprintln!("classic {cols}x{rows}: {a:?}; stable pixels at most {stable_worst} off");
    assert!(a.same_object_percent() >= 99.9, "{a:?}");
    assert!(a.within_2_percent() >= 99.9, "{a:?}");
    assert!(a.same_within_4_percent() >= 99.0, "{a:?}");
    assert!(a.stable_percent() >= 99.0, "{a:?}");
    assert!(
        stable_worst <= STABLE_WITHIN,
        "a stable pixel is {stable_worst} off"
    );
}

#[test]
fn classic_scene_at_160_by_128_matches_the_reference() {
    check_classic(160, 128);
}

#[test]
fn classic_scene_at_320_by_240_matches_the_reference() {
    check_classic(320, 240);
}

#[test]
fn supersampled_rows_match_the_reference() {
    // 2 × 2 supersampling of the demo scene at 80 × 64: the same sub-pixel rays in both
    // models, the same averaging. Averaging four colours that are each within ±1 stays within
    // ±1, except where a sample's object differs.
    let scene = demo::scene();
    let dscene = DScene::from_scene(&scene).unwrap();
    let camera = demo::camera(80, 64).unwrap();
    let dcamera = demo_dcamera(80, 64);
    let (mut fixed, mut float) = (vec![fixray::Rgb::BLACK; 80], vec![fixray::Rgb::BLACK; 80]);
    let (mut within_1, mut worst) = (0, 0u8);
    for row in 0..64 {
        fixray::render_row_supersampled(&scene, &camera, row, 2, &mut fixed).unwrap();
        fixray_reference::render_row_supersampled(&dscene, &dcamera, row, 2, &mut float);
        for (a, b) in fixed.iter().zip(&float) {
            let d =
                a.r.abs_diff(b.r)
                    .max(a.g.abs_diff(b.g))
                    .max(a.b.abs_diff(b.b));
            within_1 += (d <= 1) as u32;
            worst = worst.max(d);
        }
    }
    eprintln!("2x2 supersampled demo 80x64: {within_1} of 5120 within ±1, worst {worst}");
    assert!(
        within_1 as f64 >= 0.999 * 5120.0,
        "{within_1} of 5120 within ±1"
    );
    assert!(worst <= 2, "worst channel error {worst}");
}
