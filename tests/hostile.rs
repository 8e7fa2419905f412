//! Hostile input, many times over: random scenes, cameras, rows, viewports and supersampling
//! factors, with out-of-range and non-finite values, degenerate cameras, scenes past 64
//! objects, and hand-built values that skip every check. In the debug build `cargo test` runs,
//! overflow checks are on, so a wrapping operation is a panic and fails the case.
//!
//! Each test runs a number of seeded cases (a few seconds in all by default) and fails with the
//! seed of every failing case and its description. Environment:
//! - `FIXRAY_HOSTILE_CASES=1000000` runs that many cases per test (a long run);
//! - `FIXRAY_HOSTILE_SEED=0x…` runs the one case of that seed (to reproduce a failure).
//!
//! The checks themselves live in `common/mod.rs`, shared with the `cargo fuzz` target in
//! `fuzz/`. Every public item of fixray is called somewhere here or there:
//! - numbers: `Fx`, `fx_from_f32`, `mul`, `isqrt`, `LIMIT`, `FAR`, `Vec3` (`new`, `from_ints`,
//!   `from_f32`, `check_range`, `to_f64`, `scale`, `dot_wide`, `dot`, `cross`,
//!   `length_squared_wide`, `length`, `try_normalize`, `normalize_or_zero`, `+`, `-`, negation);
//! - geometry: `Ray` (`new`, `new_unchecked`, `at`), `Plane` (`new`, `new_unchecked`, `bounded`,
//!   `coords`, `bounds`, `point`, `normal`, `distance`, `intersect`, `hit_distance`, `hit_at`),
//!   `Sphere` (`new`, `new_unchecked`, `centre`, `radius`, `intersect`, `hit_distance`,
//!   `hit_at`, `normal_at`), `Hit`, `Shape` (`intersect`, `hit_distance`, `hit_at`);
//! - the world: `Scene` (`new`, `add`, `add_sphere`, `add_plane`, `add_light`, `set_shadows`,
//!   `set_depth`, `objects`, `lights`, `ambient`, `background`, `shadows`, `depth`, `shoot`,
//!   `seen_from_row`, `shoot_among`, `shade`, `trace`), `Object::colour_at`, `Material`
//!   (`matte`, `new`, `with_checker`, `From<Rgb>`), `Checker::colour_at`, `Light` (`new`,
//!   `new_unchecked`), `Background` (`plain`, `From<Rgb>`), `Rgb`, `Error` (`Display`);
//! - viewing: `Camera` (`pinhole`, `look_at`, `orbit`, `cols`, `rows`, `eye`, `pixel_centre`,
//!   `ray`, `row_rays`, `sample_ray`), `RowRays`, `MAX_PIXELS`;
//! - output: `render`, `render_row`, `render_row_supersampled`, `shoot_row`,
//!   `shoot_row_skipping`, `Framebuffer` (`new`, `width`, `height`, `pixel`, `set_pixel`,
//!   `rows`, `rows_mut`, `bytes`, `draw_at`, and as `DrawTarget`, `GetPixel`, `ImageDrawable`),
//!   `FrameHash`;
//! - `draw`: `Viewport` (`new`, `area`, `render_rows`, `render`, `bands`), `Bands`, `FromRgb`
//!   for each colour type, `dither`, `luma`, `bayer_index`, `BAYER_8X8`, `LUMA_MAX`,
//!   `DrawError`;
//! - `demo`: `scene`, `camera`, `classic`, `classic_camera`, `BACKGROUND`, `SCREEN_HEIGHT`,
//!   `SCREEN_DISTANCE`, `CLASSIC_FOV_DEGREES`.
//!
//! The f64 reference model (the `fixray-reference` crate) is what the other tests judge by; it
//! is not fed hostile input here.

mod common;

use fixray_reference::ToF64;
use std::cell::RefCell;
use std::collections::BTreeMap;
use std::panic::{self, AssertUnwindSafe};
use std::sync::Once;

use common::{Source, XorShift};
use embedded_graphics::prelude::{Point, Size};
use fixray::draw::{self, FromRgb};
use fixray::{
    Background, Camera, CameraProblem, Error, FAR, Fx, LIMIT, Light, Material, Object, Plane,
    Quantity, Ray, Rgb, Scene, Shape, Sphere, Vec3, demo,
};

/// The refusal of `quantity` outside `min ..= max`.
fn range(quantity: Quantity, min: Fx, max: Fx) -> Error {
    Error::OutOfRange { quantity, min, max }
}

/// The refusal of `quantity` outside the overflow-safe range ±1024.
fn outside(quantity: Quantity) -> Error {
    range(quantity, -LIMIT, LIMIT)
}

// ---------------------------------------------------------------------------------------------
// The harness: seeded cases, each panic caught and reported with its seed.
// ---------------------------------------------------------------------------------------------

thread_local! {
    /// The last panic's message and place on this thread, while a case runs.
    static CAUGHT: RefCell<Option<String>> = const { RefCell::new(None) };
    static QUIET: RefCell<bool> = const { RefCell::new(false) };
}

/// Panics inside a case are recorded instead of printed; any other panic prints as usual.
fn install_hook() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let default = panic::take_hook();
        panic::set_hook(Box::new(move |info| {
            if QUIET.with(|q| *q.borrow()) {
                let place = info
                    .location()
                    .map(|l| format!("{}:{}", l.file(), l.line()))
                    .unwrap_or_default();
                let message = info
                    .payload()
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| info.payload().downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default();
                CAUGHT.with(|c| *c.borrow_mut() = Some(format!("{place}: {message}")));
            } else {
                default(info);
            }
        }));
    });
}

fn env_u64(name: &str) -> Option<u64> {
    let v = std::env::var(name).ok()?;
    let v = v.trim();
    match v.strip_prefix("0x") {
        Some(hex) => u64::from_str_radix(hex, 16).ok(),
        None => v.parse().ok(),
    }
}

/// Runs `cases` seeded cases of `body` (or `FIXRAY_HOSTILE_CASES`, or the one
/// `FIXRAY_HOSTILE_SEED`), and fails listing each distinct failure: where it panicked, how
/// many cases did, the first seed, and the case `describe` gives for it.
fn run<D: std::fmt::Debug>(
    test: &str,
    cases: u64,
    describe: impl Fn(&mut XorShift) -> D,
    body: impl Fn(&mut XorShift),
) {
    install_hook();
    let seeds: Vec<u64> = match env_u64("FIXRAY_HOSTILE_SEED") {
        Some(seed) => vec![seed],
        None => {
            let n = env_u64("FIXRAY_HOSTILE_CASES").unwrap_or(cases);
            // The test's name keeps the tests' seeds apart.
            let base = test
                .bytes()
                .fold(0u64, |h, b| h.wrapping_mul(31).wrapping_add(b as u64));
            (0..n)
                .map(|i| base.wrapping_mul(1 << 20).wrapping_add(i))
                .collect()
        }
    };
    // One seed asked for: its panic prints in full (with RUST_BACKTRACE=1, where it came from).
    let quiet = env_u64("FIXRAY_HOSTILE_SEED").is_none();
    let mut failures: BTreeMap<String, (u64, u64, String)> = BTreeMap::new();
    for &seed in &seeds {
        QUIET.with(|q| *q.borrow_mut() = quiet);
        let result = panic::catch_unwind(AssertUnwindSafe(|| body(&mut XorShift::new(seed))));
        QUIET.with(|q| *q.borrow_mut() = false);
        if result.is_err() {
            let message = CAUGHT
                .with(|c| c.borrow_mut().take())
                .unwrap_or("(printed above)".into());
            // One entry per place in the code that panicked.
            let key: String = message.split(": ").next().unwrap_or("").to_string();
            let entry = failures.entry(key).or_insert_with(|| {
                let description = format!("{:#?}", describe(&mut XorShift::new(seed)));
                (0, seed, format!("{message}\n{}", shorten(&description)))
            });
            entry.0 += 1;
        }
    }
    if !failures.is_empty() {
        let mut report = format!(
            "{} of {} cases failed in {} ways:\n",
            failures.values().map(|f| f.0).sum::<u64>(),
            seeds.len(),
            failures.len()
        );
        for (count, seed, text) in failures.values() {
            report.push_str(&format!(
                "\n--- {count} case(s); first: FIXRAY_HOSTILE_SEED={seed:#x} cargo test --test \
                 hostile {test}\n{text}\n"
            ));
        }
        panic!("{report}");
    }
}

/// A long description cut to its first lines (scenes of 130 objects print long).
fn shorten(s: &str) -> String {
    let lines: Vec<&str> = s.lines().collect();
    if lines.len() <= 80 {
        s.to_string()
    } else {
        format!(
            "{}\n… ({} more lines)",
            lines[..80].join("\n"),
            lines.len() - 80
        )
    }
}

// ---------------------------------------------------------------------------------------------
// Whole scenes
// ---------------------------------------------------------------------------------------------

/// Random scenes (up to 140 objects, the interesting ones past the 64th in the big ones),
/// cameras of every kind with hostile values, rows on and off the screen, viewports,
/// framebuffers and supersampling; every assertion group of `common`.
#[test]
fn random_scenes_cameras_and_rows() {
    run("random_scenes_cameras_and_rows", 160, common::case, |src| {
        let case = common::case(src);
        common::run_case(src, &case);
    });
}

/// The demo and classic scenes through hostile cameras, rows and viewports.
#[test]
fn demo_scenes_through_hostile_cameras() {
    run(
        "demo_scenes_through_hostile_cameras",
        60,
        |src| common::camera_spec(src, 3),
        |src| {
            let spec = common::camera_spec(src, 3);
            let Some(camera) = common::check_camera_spec(&spec, false) else {
                return;
            };
            let scene = if src.one_in(2) {
                demo::scene()
            } else {
                demo::classic()
            };
            let (cols, rows) = (camera.width() as usize, camera.height() as usize);
            let all_rows = cols * rows <= 40 * 30;
            let rows_checked: Vec<u32> = if all_rows {
                (0..camera.height())
                    .chain([camera.height(), u32::from(u16::MAX) + 1, u32::MAX])
                    .collect()
            } else {
                vec![0, camera.height() - 1, camera.height()]
            };
            let mut frame = vec![Vec::new(); if all_rows { rows } else { 0 }];
            for row in rows_checked {
                let line = common::check_row(&scene, &camera, row);
                if let Some(slot) = frame.get_mut(row as usize) {
                    *slot = line;
                }
            }
            if all_rows {
                common::check_viewport(src, &scene, &camera, &frame);
                common::check_framebuffer::<8, 12, 9>(src, &scene, &camera, &frame);
            }
            common::check_rays_past_the_screen(&spec, &camera);
        },
    );
}

/// Whether a screen of `cols × rows` square pixels with the demo's 60° of height breaks
/// `Camera`'s documented ray budget, `F² + R² ≤ 16 384·F` (view distance `F`, half-diagonal
/// `R`, in pixels), by more than rounding could decide.
fn past_the_ray_budget(cols: u32, rows: u32) -> bool {
    let f = rows as f64 * (demo::SCREEN_DISTANCE / demo::SCREEN_HEIGHT) as f64;
    let r2 = (cols as f64 * cols as f64 + rows as f64 * rows as f64) / 4.0;
    f * f + r2 > 16_384.0 * f * 1.001
}

/// The demo module's own cameras at hostile sizes: refused exactly where the screen has no
/// pixels or more than 4096 a side.
#[test]
fn demo_cameras_at_hostile_sizes() {
    run(
        "demo_cameras_at_hostile_sizes",
        200,
        |_| (),
        |src| {
            let pick =
                |s: &mut XorShift| s.pick(&[0, 1, 2, 3, 160, 4096, 4097, 65_536 + 160, u32::MAX]);
            let (cols, rows) = (pick(src), pick(src));
            let bad = cols == 0 || rows == 0 || cols > 4096 || rows > 4096;
            for camera in [demo::camera(cols, rows), demo::classic_camera(cols, rows)] {
                match camera {
                    // [ASSERT: Err for invalid input]
                    Err(e) if bad => {
                        let problem = if cols == 0 || rows == 0 {
                            CameraProblem::NoPixels
                        } else {
                            CameraProblem::TooManyPixels
                        };
                        assert_eq!(e, Error::DegenerateCamera(problem), "{cols}×{rows}");
                    }
                    Err(e) if 2 * u64::from(cols) > 1024 * u64::from(rows) => {
                        // The demo's screen is 2 units high and its pixels square: wider than
                        // 512 pixels per row it is more than 1024 units wide, out of range.
                        assert!(
                            matches!(
                                e,
                                Error::OutOfRange {
                                    quantity: Quantity::ScreenWidth,
                                    ..
                                } | Error::FieldOfViewTooWide { .. }
                            ),
                            "{e}"
                        );
                    }
                    Err(e) if past_the_ray_budget(cols, rows) => {
                        // [ASSERT: Err for invalid input] A screen so wide for its 60° of
                        // height that its corners leave Camera's ray budget.
                        assert!(matches!(e, Error::FieldOfViewTooWide { .. }), "{e}");
                    }
                    Err(e) => panic!("demo camera {cols}×{rows} refused: {e}"),
                    Ok(c) => {
                        assert!(!bad, "demo camera {cols}×{rows} must be refused");
                        assert!(
                            !past_the_ray_budget(cols, rows),
                            "demo camera {cols}×{rows} is past the ray budget"
                        );
                        assert_eq!((c.width(), c.height()), (cols, rows));
                        let _ = c.ray(cols - 1, rows - 1);
                    }
                }
            }
            assert_eq!(demo::SCREEN_HEIGHT, 2.0);
            // The demo's screen: SCREEN_HEIGHT at SCREEN_DISTANCE, the classic's field of view.
            let half = (demo::SCREEN_HEIGHT / 2.0 / demo::SCREEN_DISTANCE)
                .atan()
                .to_degrees();
            assert!(
                (2.0 * half - demo::CLASSIC_FOV_DEGREES).abs() < 1e-3,
                "both are 60°"
            );
            assert_eq!(
                demo::scene().background(),
                Background::plain(demo::BACKGROUND)
            );
        },
    );
}

// ---------------------------------------------------------------------------------------------
// Constructors
// ---------------------------------------------------------------------------------------------

/// Hostile values for every checked constructor: `Err` exactly where the documented ranges
/// are left, and an accepted value that holds what was asked.
#[test]
fn constructors_refuse_exactly_the_invalid_values() {
    run(
        "constructors_refuse_exactly_the_invalid_values",
        3000,
        |_| (),
        |src| {
            let in_limit = |v: Fx| v >= -LIMIT && v <= LIMIT;
            let vec_in_limit = |v: Vec3| in_limit(v.x) && in_limit(v.y) && in_limit(v.z);

            // [ASSERT: Err for invalid input] The f32 constructors: a coordinate, then a point.
            let f = common::f32_around(src, 2000.0, 3);
            let q = Quantity::SphereCentre;
            match Sphere::new([f, 0.0, 0.0], 1.0).map(|s| s.centre().x) {
                Ok(v) => {
                    assert!(f.is_finite() && f.abs() <= 1024.0, "{f} accepted");
                    assert_eq!(v, Fx::from_num(f), "{f} converts to the nearest Q16.16");
                }
                Err(Error::NotFinite { quantity }) if quantity == q => {
                    assert!(!f.is_finite(), "{f}")
                }
                Err(Error::OutOfRange { quantity, min, max })
                    if (quantity, min, max) == (q, -LIMIT, LIMIT) =>
                {
                    assert!(f.is_finite() && f.abs() > 1024.0, "{f}")
                }
                Err(e) => panic!("{f}: wrong error {e}"),
            }
            let v3 = [
                common::f32_around(src, 1500.0, 4),
                common::f32_around(src, 1500.0, 4),
                common::f32_around(src, 1500.0, 4),
            ];
            let ok = v3.iter().all(|c| c.is_finite() && c.abs() <= 1024.0);
            let vec3 = Light::new(v3, 1.0).map(|light| light.position());
            assert_eq!(vec3.is_ok(), ok, "{v3:?}");
            if let Err(e) = vec3 {
                // Components are checked in order: the first one refused names the error.
                let first = v3
                    .into_iter()
                    .find(|c| !(c.is_finite() && c.abs() <= 1024.0));
                let want = match first {
                    Some(c) if !c.is_finite() => Error::NotFinite {
                        quantity: Quantity::LightPosition,
                    },
                    _ => outside(Quantity::LightPosition),
                };
                assert_eq!(e, want, "{v3:?}");
            }

            // [ASSERT: Err for invalid input] Ray::new: origin in range, direction non-zero.
            let (origin, dir) = (common::vec_any(src), common::direction(src));
            match Ray::new(origin, dir) {
                Ok(ray) => {
                    assert!(
                        vec_in_limit(origin) && dir != Vec3::ZERO,
                        "{origin:?} {dir:?}"
                    );
                    let len = common::length(ray.dir());
                    assert!((len - 1.0).abs() <= common::UNIT_TOLERANCE, "{ray:?}");
                    assert_eq!(ray.at(Fx::ZERO), origin);
                }
                Err(e) if !vec_in_limit(origin) => assert_eq!(e, outside(Quantity::RayOrigin)),
                Err(e) => assert_eq!(
                    (e, dir),
                    (
                        Error::ZeroVector {
                            quantity: Quantity::RayDirection
                        },
                        Vec3::ZERO
                    )
                ),
            }

            // [ASSERT: Err for invalid input] Sphere::new: centre in range, 0 < r ≤ 1024.
            let (centre, radius) = (common::vec_any(src), common::fx_any(src));
            match Sphere::from_fx(centre, radius) {
                Ok(s) => {
                    assert!(vec_in_limit(centre) && radius > Fx::ZERO && radius <= LIMIT);
                    assert_eq!((s.centre(), s.radius()), (centre, radius));
                    // Straight up from the centre: the top of the sphere, seen from inside, so
                    // its normal faces down, back at the ray.
                    let up = Ray::new(centre, Vec3::Y).expect("valid");
                    let hit = s
                        .intersect(&up)
                        .expect("a ray from the centre leaves the sphere");
                    assert_eq!((hit.t(), hit.normal()), (radius, -Vec3::Y), "{s:?}");
                }
                Err(e) if !vec_in_limit(centre) => assert_eq!(e, outside(Quantity::SphereCentre)),
                Err(Error::NonPositiveRadius) => assert!(radius <= Fx::ZERO),
                Err(e) => assert_eq!((e, radius > LIMIT), (outside(Quantity::SphereRadius), true)),
            }

            // [ASSERT: Err for invalid input] Plane::new and bounded.
            let (point, normal) = (common::vec_any(src), common::direction(src));
            match Plane::from_fx(point, normal) {
                Ok(p) => {
                    assert!(vec_in_limit(point) && normal != Vec3::ZERO);
                    let len = common::length(p.normal());
                    assert!((len - 1.0).abs() <= common::UNIT_TOLERANCE, "{p:?}");
                    assert_eq!(p.point(), point);
                    assert_eq!(p.distance(point), Fx::ZERO);
                    let (lo, hi) = (
                        [common::fx_any(src), common::fx_any(src)],
                        [common::fx_any(src), common::fx_any(src)],
                    );
                    let ok = [lo[0], lo[1], hi[0], hi[1]].into_iter().all(in_limit)
                        && lo[0] < hi[0]
                        && lo[1] < hi[1];
                    match p.bounded_fx(lo, hi) {
                        Ok(b) => {
                            assert!(ok, "bounds {lo:?} {hi:?} accepted");
                            assert_eq!(b.bounds(), Some([lo, hi]));
                            let _ = b.coords(point);
                        }
                        Err(e) => {
                            assert!(!ok, "bounds {lo:?} {hi:?} refused");
                            let corners = [lo[0], lo[1], hi[0], hi[1]];
                            let want = if corners.into_iter().all(in_limit) {
                                Error::EmptyBounds
                            } else {
                                outside(Quantity::PlaneBounds)
                            };
                            assert_eq!(e, want, "bounds {lo:?} {hi:?}");
                        }
                    }
                }
                Err(e) if !vec_in_limit(point) => assert_eq!(e, outside(Quantity::PlanePoint)),
                Err(e) => assert_eq!(
                    (e, normal),
                    (
                        Error::ZeroVector {
                            quantity: Quantity::PlaneNormal
                        },
                        Vec3::ZERO
                    )
                ),
            }

            // [ASSERT: Err for invalid input] Light::new: position in range, 0 ≤ I ≤ 4.
            let (position, intensity) = (common::vec_any(src), common::fx_any(src));
            let ok =
                vec_in_limit(position) && intensity >= Fx::ZERO && intensity <= Fx::from_num(4);
            let light = Light::from_fx(position, intensity);
            assert_eq!(light.is_ok(), ok, "{position:?} {intensity}");
            if let Err(e) = light {
                let want = if !vec_in_limit(position) {
                    outside(Quantity::LightPosition)
                } else {
                    range(Quantity::LightIntensity, Fx::ZERO, Fx::from_num(4))
                };
                assert_eq!(e, want, "{position:?} {intensity}");
            }

            // [ASSERT: Err for invalid input] Material::new and with_checker.
            let (d, s, r) = (
                common::fx_any(src),
                common::fx_any(src),
                common::fx_any(src),
            );
            let shininess = src.pick(&[0, 1, 50, 4096, 4097, u16::MAX]);
            let within = |v: Fx, max: i32| v >= Fx::ZERO && v <= Fx::from_num(max);
            let ok =
                within(d, 2) && within(s, 16) && within(r, 1) && (1..=4096).contains(&shininess);
            let material = Material::from_fx(Rgb::WHITE, d, s, shininess, r);
            assert_eq!(material.is_ok(), ok, "{d} {s} {shininess} {r}");
            if let Err(e) = material {
                // The first value outside its range, in the order of the arguments' checks.
                let weight = |q, max: i32| range(q, Fx::ZERO, Fx::from_num(max));
                let want = if !within(d, 2) {
                    weight(Quantity::DiffuseWeight, 2)
                } else if !within(s, 16) {
                    weight(Quantity::SpecularWeight, 16)
                } else if !within(r, 1) {
                    weight(Quantity::Reflectivity, 1)
                } else {
                    range(Quantity::Shininess, Fx::ONE, Fx::from_num(4096))
                };
                assert_eq!(e, want, "{d} {s} {shininess} {r}");
            }
            let size = common::fx_any(src);
            let checked = Material::matte(Rgb::BLACK).with_checker_fx(size, Rgb::WHITE);
            assert_eq!(
                checked.map(|m| m.checker().map(|c| c.size())),
                if size > Fx::ZERO && size <= LIMIT {
                    Ok(Some(size))
                } else {
                    // Above zero: from the smallest positive Q16.16 value.
                    Err(range(Quantity::CheckerSize, Fx::DELTA, LIMIT))
                },
                "checker {size}"
            );
            assert_eq!(Material::from(Rgb::WHITE), Material::matte(Rgb::WHITE));

            // [ASSERT: Err for invalid input] Scene::new: ambient within 0..=1; capacities.
            let ambient = common::fx_any(src);
            let light = Light::from_fx(Vec3::ZERO, Fx::ONE).expect("valid");
            let scene = Scene::<2, 2>::from_fx(light, ambient, Rgb::BLACK.into());
            assert_eq!(
                scene.as_ref().err().copied(),
                (ambient < Fx::ZERO || ambient > Fx::ONE).then_some(range(
                    Quantity::Ambient,
                    Fx::ZERO,
                    Fx::ONE
                )),
                "{ambient}"
            );
            if let Ok(mut scene) = scene {
                assert_eq!(scene.ambient(), ambient);
                assert!(scene.add_light(light).is_ok());
                assert_eq!(
                    scene.add_light(light),
                    Err(Error::CapacityExceeded { capacity: 2 })
                );
                let ball = Sphere::from_fx(Vec3::ZERO, Fx::ONE).expect("valid");
                assert_eq!(scene.add_sphere(ball, Rgb::WHITE), Ok(0));
                assert_eq!(
                    scene.add_plane(
                        Plane::from_fx(Vec3::ZERO, Vec3::Y).expect("valid"),
                        Rgb::WHITE
                    ),
                    Ok(1)
                );
                assert!(scene.add_sphere(ball, Rgb::WHITE).is_err());
                assert!(scene.shadows());
                let _ = format!("{}", Error::CapacityExceeded { capacity: 2 });
            }

            // [ASSERT: Err for invalid input; accepted cameras are usable] Cameras with every
            // kind of hostile value.
            let spec = common::camera_spec(src, 2);
            common::check_camera_spec(&spec, true);
        },
    );
}

// ---------------------------------------------------------------------------------------------
// Values at their limits
// ---------------------------------------------------------------------------------------------

/// A value of `fx_any` moved into `min ..= max`: hostile values pushed to the nearest limit a
/// constructor accepts, so that every extreme is reached.
fn clamped(src: &mut impl common::Source, min: Fx, max: Fx) -> Fx {
    common::fx_any(src).clamp(min, max)
}

/// Rays, lights, materials and checkers at the extremes their constructors accept (anything
/// past them is refused, as the constructor tests check): no public function may panic or
/// wrap on them.
///
/// In four parts, each its own test, so that a panic in one does not hide the others: rays
/// against shapes, scenes of extreme lights and materials along the camera's rays, extreme
/// rays into a scene, and their hits shaded.
fn extremes(test: &str, part: u8) {
    run(
        test,
        1500,
        |src| {
            (
                common::vec_any(src),
                common::vec_any(src),
                common::vec_any(src),
                common::fx_any(src),
            )
        },
        |src| {
            // [ASSERT: no panic] Any accepted ray against any valid shape.
            let origin = Vec3::new(
                clamped(src, -LIMIT, LIMIT),
                clamped(src, -LIMIT, LIMIT),
                clamped(src, -LIMIT, LIMIT),
            );
            let Ok(ray) = Ray::new(origin, common::vec_any(src)) else {
                return;
            };
            let sphere = Sphere::from_fx(
                common::vec_within(src, 1024.0),
                clamped(src, Fx::DELTA, LIMIT),
            )
            .expect("valid");
            let plane = Plane::from_fx(common::vec_within(src, 1024.0), Vec3::Y)
                .expect("valid")
                .bounded_fx([-LIMIT, -LIMIT], [LIMIT, LIMIT])
                .expect("valid");
            if part == 0 {
                for shape in [Shape::Sphere(sphere), Shape::Plane(plane)] {
                    if let Some(hit) = shape.intersect(&ray) {
                        let t = hit.t();
                        assert!(t >= Fx::ZERO && t <= FAR, "hit at {t} for {ray:?}");
                        assert!(
                            hit.normal().dot(ray.dir()) <= Fx::ZERO,
                            "normal faces the ray"
                        );
                    }
                }
                let _ = plane.distance(ray.dir());
                let _ = ray.at(common::fx_any(src));
                return;
            }

            // [ASSERT: no panic] A scene of extreme lights, materials and checkers, shot and
            // shaded along extreme rays.
            let light = Light::from_fx(
                common::vec_within(src, 1024.0),
                clamped(src, Fx::ZERO, Fx::from_num(4)),
            )
            .expect("valid");
            let mut material = Material::from_fx(
                Rgb::new(src.bits() as u8, 255, 0),
                clamped(src, Fx::ZERO, Fx::from_num(2)),
                clamped(src, Fx::ZERO, Fx::from_num(16)),
                (src.bits() as u16).clamp(1, 4096),
                clamped(src, Fx::ZERO, Fx::ONE),
            )
            .expect("valid");
            if src.one_in(2) {
                material = material
                    .with_checker_fx(clamped(src, Fx::DELTA, LIMIT), Rgb::WHITE)
                    .expect("valid");
            }
            let background = Background {
                top: Rgb::new(src.bits() as u8, 0, 255),
                bottom: Rgb::new(0, src.bits() as u8, 255),
            };
            let mut scene = Scene::<4>::new(light, 1.0, background).expect("valid");
            let _ = scene.add_light(
                Light::from_fx(common::vec_within(src, 1024.0), Fx::from_num(4)).expect("valid"),
            );
            let _ = scene.add_sphere(sphere, material);
            let _ = scene.add_plane(plane, material);
            let wall = Plane::from_fx(common::vec_within(src, 1024.0), Vec3::Z).expect("valid");
            let _ = scene.add(Object::new(Shape::Plane(wall), material));
            scene.set_depth(src.pick(&[0, 1, 16, 255]));
            let camera = demo::camera(8, 6).expect("valid");
            if part == 1 {
                for row in 0..6 {
                    for col in 0..8 {
                        let _ = scene.trace(&camera.ray(col, row));
                    }
                }
                let _ = scene.seen_from_row(&camera, src.bits() as u16);
                let _ = scene.shoot_among(&camera.ray(src.bits() as u32, src.bits() as u32), !0);
                for object in scene.objects() {
                    let _ = object.colour_at(common::vec_any(src));
                }
                return;
            }
            let hit = scene.shoot(&ray);
            if part == 2 {
                let _ = scene.shoot_among(&ray, src.bits());
                assert_eq!(scene.trace(&ray), scene.shade(&ray, hit.as_ref()));
                let _ = scene.shade(&ray, None);
                return;
            }
            if let Some(hit) = hit {
                assert!(hit.object() < scene.objects().len());
                let _ = scene.shade(&ray, Some(&hit));
                // A hit shaded along another ray (the hit is the scene's, the ray any).
                let _ = scene.shade(&camera.ray(4, 3), Some(&hit));
            }
        },
    );
}

#[test]
fn extreme_rays_against_shapes() {
    extremes("extreme_rays_against_shapes", 0);
}

#[test]
fn extreme_lights_materials_and_checkers() {
    extremes("extreme_lights_materials_and_checkers", 1);
}

#[test]
fn extreme_rays_into_scenes() {
    extremes("extreme_rays_into_scenes", 2);
}

#[test]
fn extreme_hits_shaded() {
    extremes("extreme_hits_shaded", 3);
}

// ---------------------------------------------------------------------------------------------
// Numbers
// ---------------------------------------------------------------------------------------------

/// The exact value of a Q32.32 sum, rounded half up to Q16.16 and saturated, as i64 raw.
fn narrow_exact(wide: i128) -> i64 {
    let rounded = (wide + (1 << 15)) >> 16;
    rounded.clamp(i32::MIN as i128, i32::MAX as i128) as i64
}

/// Vector arithmetic on any Q16.16 values: saturating where documented, exact products
/// rounded once, integer square roots exact.
#[test]
fn numbers_saturate_instead_of_wrapping() {
    run(
        "numbers_saturate_instead_of_wrapping",
        20000,
        |src| (common::vec_any(src), common::vec_any(src)),
        |src| {
            let (a, b) = (common::vec_any(src), common::vec_any(src));
            let raw = |v: Fx| v.to_bits() as i128;
            let dot_exact = raw(a.x) * raw(b.x) + raw(a.y) * raw(b.y) + raw(a.z) * raw(b.z);

            // [ASSERT: dot_wide is exact where it fits, saturated where not]
            let wide = fixray::internals::dot_wide(a, b);
            let clamped = dot_exact.clamp(i64::MIN as i128, i64::MAX as i128);
            assert_eq!(wide as i128, clamped, "dot_wide of {a:?}, {b:?}");
            // [ASSERT: dot is the exact product rounded once, saturating]
            let dot = a.dot(b).to_bits() as i64;
            let expect = narrow_exact(clamped);
            assert!(
                (dot - expect).abs() <= 1,
                "dot of {a:?}, {b:?}: {dot} where the saturated exact value is {expect}"
            );
            // [ASSERT: cross products are formed at 64 bits and rounded once (saturating)]
            let c = a.cross(b);
            let exact = [
                raw(a.y) * raw(b.z) - raw(a.z) * raw(b.y),
                raw(a.z) * raw(b.x) - raw(a.x) * raw(b.z),
                raw(a.x) * raw(b.y) - raw(a.y) * raw(b.x),
            ];
            for (got, e) in [c.x, c.y, c.z].into_iter().zip(exact) {
                assert!(
                    (got.to_bits() as i64 - narrow_exact(e)).abs() <= 1,
                    "cross of {a:?}, {b:?}: {got} against {}",
                    narrow_exact(e)
                );
            }
            // [ASSERT: lengths exact]
            let square = (raw(a.x) * raw(a.x) + raw(a.y) * raw(a.y) + raw(a.z) * raw(a.z)) as u128;
            assert_eq!(
                fixray::internals::length_squared_wide(a) as u128,
                square,
                "{a:?}"
            );
            let root = fixray::internals::isqrt(fixray::internals::length_squared_wide(a)) as u128;
            assert!(
                root * root <= square && (root + 1) * (root + 1) > square,
                "isqrt"
            );
            let length = a.length().to_bits() as i64;
            assert_eq!(length, root.min(i32::MAX as u128) as i64, "length of {a:?}");
            // [ASSERT: normalisation within one unit a component]
            match a.try_normalize() {
                None => assert_eq!(a, Vec3::ZERO),
                Some(u) => {
                    let exact = a.to_f64().map(|c| c / (square as f64).sqrt() * 65536.0);
                    for (got, e) in [u.x, u.y, u.z].into_iter().zip(exact) {
                        assert!(
                            (got.to_bits() as f64 - e * 65536.0).abs() <= 1.0,
                            "normalising {a:?}: {u:?}"
                        );
                    }
                }
            }
            assert_eq!(
                a.normalize_or_zero(),
                a.try_normalize().unwrap_or(Vec3::ZERO)
            );
            // [ASSERT: sums, differences, negation and scaling saturate]
            let sat = |v: i128| v.clamp(i32::MIN as i128, i32::MAX as i128) as i32;
            assert_eq!((a + b).x.to_bits(), sat(raw(a.x) + raw(b.x)));
            assert_eq!((a - b).y.to_bits(), sat(raw(a.y) - raw(b.y)));
            let _ = -a;
            let k = common::fx_any(src);
            let scaled = a.scale(k).z.to_bits() as i64;
            assert!(
                (scaled - narrow_exact(raw(a.z) * raw(k))).abs() <= 1,
                "scale"
            );
            let in_limit = [a.x, a.y, a.z].iter().all(|&c| c >= -LIMIT && c <= LIMIT);
            assert_eq!(
                Light::from_fx(a, Fx::ONE).map(|light| light.position()),
                if in_limit {
                    Ok(a)
                } else {
                    Err(outside(Quantity::LightPosition))
                }
            );
            let n = src.bits() >> src.below(64);
            let r = fixray::internals::isqrt(n) as u128;
            assert!(
                r * r <= n as u128 && (r + 1) * (r + 1) > n as u128,
                "isqrt({n})"
            );
            let _ = Vec3::from_ints(src.bits() as i16, i16::MIN, i16::MAX);

            // [ASSERT: dithering stays within its levels for any luma and point]
            let at = Point::new(src.bits() as i32, src.bits() as i32);
            let luma = src.bits() as u32 >> src.below(32);
            let max = src.bits() as u8;
            assert!(draw::dither(luma, max, at) <= max, "dither");
            assert!(draw::bayer_index(at) < 64);
            assert!(draw::luma(Rgb::WHITE) <= draw::LUMA_MAX);
            assert_eq!(
                draw::BAYER_8X8
                    .as_flattened()
                    .iter()
                    .map(|&v| v as u32)
                    .sum::<u32>(),
                2016
            );
            let colour = Rgb::new(src.bits() as u8, src.bits() as u8, src.bits() as u8);
            let _ = <embedded_graphics::pixelcolor::Gray4 as FromRgb>::from_rgb(colour, at);
            let _ = <embedded_graphics::pixelcolor::Gray2 as FromRgb>::from_rgb(colour, at);
            let _ = <embedded_graphics::pixelcolor::Rgb565 as FromRgb>::from_rgb(colour, at);
        },
    );
}

/// A camera is the one thing a user cannot build by hand; `Camera` is `Copy` and comparable,
/// and its accessors give back what it was built with.
#[test]
fn camera_accessors() {
    let camera = Camera::look_at([1.0, 2.0, 3.0], [1.0, 2.0, -3.0])
        .size(Size::new(7, 5))
        .build()
        .expect("valid");
    assert_eq!((camera.width(), camera.height()), (7, 5));
    assert_eq!(camera.eye(), Vec3::from_ints(1, 2, 3));
    let too_wide = fixray::MAX_PIXELS + 1;
    assert!(
        Camera::look_at([0.0; 3], [0.0, 0.0, -1.0])
            .size(Size::new(too_wide, 5))
            .build()
            .is_err()
    );
}
