//! Cases an outside hostile campaign found (issue 37, item 9), each held here to the crate's
//! own contract or promise:
//!
//! - `render_row` is, bit for bit, `Scene::trace` of `Camera::ray` for every pixel, and the
//!   damage of an edit holds every pixel the edit changes, on the tiniest screens at the
//!   widest fields of view the ray budget allows (view distances of a few units of 2⁻¹⁶
//!   pixels), where a row's plane was found from a cross product with a direction only a few
//!   raw units long;
//! - an orbiting camera refuses a distance that is not positive.
//!
//! The oracles are plain: `trace` of each pixel's ray, and a fresh render compared pixel by
//! pixel with the frame before the edit. `FIXRAY_HOSTILE_CASES` sets how many random scenes
//! each screen size gets (default 300).

mod common;

use common::{Source, XorShift};
use fixray::{
    Background, Camera, Damage, Error, Framebuffer, Fx, Light, Material, Plane, Quantity, Rgb,
    Scene, Size, Sphere, Vec3, render, render_changes, render_row,
};

type World = Scene<6, 2>;

/// How many random scenes each screen size gets.
fn cases() -> u64 {
    std::env::var("FIXRAY_HOSTILE_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(300)
}

/// A value in `[lo, hi]`.
fn between(src: &mut XorShift, lo: f32, hi: f32) -> f32 {
    lo + (src.uniform(1.0) + 1.0) / 2.0 * (hi - lo)
}

fn f64s(v: Vec3) -> [f64; 3] {
    [v.x.to_num(), v.y.to_num(), v.z.to_num()]
}

/// Pixels of `camera`'s row `row` where `render_row` differs from `trace` of the pixel's ray,
/// as `(col, row_pixel, traced)`.
fn disagreements<const N: usize, const L: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
) -> Vec<(u32, u32, Rgb, Rgb)> {
    let mut out = vec![Rgb::BLACK; camera.width() as usize];
    let mut wrong = Vec::new();
    for row in 0..camera.height() {
        render_row(scene, camera, row, &mut out).unwrap();
        for (col, &pixel) in (0..).zip(out.iter()) {
            let traced = scene.trace(&camera.ray(col, row));
            if pixel != traced {
                wrong.push((col, row, pixel, traced));
            }
        }
    }
    wrong
}

/// The campaign's case: a 1 × 1 screen at 179.96°, whose one ray meets the sphere.
#[test]
fn render_row_draws_the_sphere_trace_sees_on_a_one_pixel_wide_view() {
    let camera = Camera::look_at([0.0; 3], [5.0, 3.0, -1.0])
        .fov_degrees(179.96)
        .size(Size::new(1, 1))
        .build()
        .unwrap();
    let mut scene =
        World::new(Light::new([0.0, 50.0, 0.0], 1.0).unwrap(), 0.1, Rgb::BLACK).unwrap();
    scene
        .add_sphere(
            Sphere::new([24.0, 14.0, -5.0], 2.0).unwrap(),
            Rgb::new(255, 255, 255),
        )
        .unwrap();
    let ray = camera.ray(0, 0);
    assert_eq!(scene.shoot(&ray).map(|hit| hit.object()), Some(0));
    let traced = scene.trace(&ray);
    assert_ne!(traced, Rgb::BLACK);
    let mut row = [Rgb::BLACK; 1];
    render_row(&scene, &camera, 0, &mut row).unwrap();
    assert_eq!(row[0], traced);
}

/// A look-at camera of `size` at a field of view within a few degrees of 180° (most within a
/// tenth of a degree of the widest the screen allows), or `None` where it is refused.
fn wide_camera(src: &mut XorShift, size: Size) -> Option<Camera> {
    let eye = [src.uniform(30.0), src.uniform(30.0), src.uniform(30.0)];
    let target = [
        eye[0] + src.uniform(10.0),
        eye[1] + src.uniform(10.0),
        eye[2] + src.uniform(10.0),
    ];
    // 180° less 10^e degrees, e from −2.5 to 0.5.
    let fov = 180.0 - 10f32.powf(between(src, -2.5, 0.5));
    let up = if src.one_in(4) {
        [src.uniform(1.0), src.uniform(1.0), src.uniform(1.0)]
    } else {
        [0.0, 1.0, 0.0]
    };
    Camera::look_at(eye, target)
        .up(up)
        .fov_degrees(fov)
        .size(size)
        .build()
        .ok()
}

/// A sphere that some ray of `camera` meets or nearly meets: about a random pixel's ray, at
/// a random distance, of a random radius (from a hair to most of its distance).
fn sphere_in_view(src: &mut XorShift, camera: &Camera) -> Option<Sphere> {
    let col = src.below(camera.width().into()) as u32;
    let row = src.below(camera.height().into()) as u32;
    let dir = f64s(camera.ray(col, row).dir());
    let eye = f64s(camera.eye());
    let t = f64::from(between(src, 1.0, 60.0));
    let radius = between(src, 0.02, 0.6) * t as f32;
    let off = f64::from(radius) * 1.2;
    let centre: [f32; 3] =
        std::array::from_fn(|i| (eye[i] + dir[i] * t + f64::from(src.uniform(1.0)) * off) as f32);
    Sphere::new(centre, radius).ok()
}

/// A random scene about `camera`'s view: one to four spheres in view, sometimes a ground
/// plane below the eye, one or two lights, shadows on.
fn scene_about(src: &mut XorShift, camera: &Camera) -> Option<World> {
    let eye = f64s(camera.eye());
    let light = |src: &mut XorShift| {
        Light::new(
            [
                (eye[0] + f64::from(src.uniform(50.0))) as f32,
                (eye[1] + f64::from(between(src, -10.0, 50.0))) as f32,
                (eye[2] + f64::from(src.uniform(50.0))) as f32,
            ],
            between(src, 0.4, 1.0),
        )
    };
    let background = if src.one_in(2) {
        Background {
            top: Rgb::new(20, 40, 200),
            bottom: Rgb::new(200, 220, 255),
        }
    } else {
        Background::plain(Rgb::BLACK)
    };
    let mut world = World::new(light(src).ok()?, 0.1, background).ok()?;
    if src.one_in(2) {
        world.add_light(light(src).ok()?).ok()?;
    }
    if src.one_in(2) {
        let ground = [
            0.0,
            (eye[1] - f64::from(between(src, 0.5, 10.0))) as f32,
            0.0,
        ];
        world
            .add_plane(
                Plane::new(ground, [0.0, 1.0, 0.0]).ok()?,
                Material::matte(Rgb::new(120, 200, 90)),
            )
            .ok()?;
    }
    for _ in 0..1 + src.below(4) {
        let sphere = sphere_in_view(src, camera)?;
        let colour = Rgb::new(src.bits() as u8 | 64, 200, 255);
        world.add_sphere(sphere, colour).ok()?;
    }
    Some(world)
}

/// `render_row` against `trace` on random scenes seen by tiny screens at very wide fields of
/// view: how many scenes were compared, and a line for each that differed.
fn compare_tiny(cols: u32, rows: u32, salt: u64) -> (u64, Vec<String>) {
    let (mut scenes, mut wrong) = (0, Vec::new());
    for seed in 0..cases() {
        let mut src = XorShift::new(salt << 32 | seed);
        let Some(camera) = wide_camera(&mut src, Size::new(cols, rows)) else {
            continue;
        };
        let Some(world) = scene_about(&mut src, &camera) else {
            continue;
        };
        scenes += 1;
        let bad = disagreements(&world, &camera);
        if !bad.is_empty() {
            wrong.push((seed, bad.len(), bad[0]));
        }
    }
    let lines = wrong
        .iter()
        .map(|(seed, pixels, first)| {
            format!("{cols}x{rows} seed {seed}: {pixels} pixels, first (col, row, render_row, trace) {first:?}")
        })
        .collect();
    (scenes, lines)
}

#[test]
fn render_row_equals_trace_on_tiny_screens_at_the_widest_views() {
    let mut wrong = Vec::new();
    for (cols, rows, salt) in [(1, 1, 1), (2, 1, 2), (3, 3, 3), (8, 8, 4)] {
        let (scenes, bad) = compare_tiny(cols, rows, salt);
        eprintln!("{cols}x{rows}: {} of {scenes} scenes differ", bad.len());
        assert!(scenes * 2 > cases(), "{cols}x{rows}: only {scenes} scenes");
        wrong.extend(bad);
    }
    assert!(
        wrong.is_empty(),
        "render_row differs from trace:\n{}",
        wrong.join("\n")
    );
}

/// One edit of `before` into `after` seen by `camera`: every pixel that changed lies in the
/// damage, and the redrawn frame is the fresh one.
fn check_damage<const W: usize, const H: usize>(
    before: &World,
    after: &World,
    camera: &Camera,
    what: &str,
) {
    let frame = |scene: &World| {
        let mut frame = Framebuffer::<W, H>::new();
        render(scene, camera, &mut frame).unwrap();
        frame
    };
    let (old, new) = (frame(before), frame(after));
    let damage = Damage::between(before, after, camera);
    for y in 0..H {
        for x in 0..W {
            if old.pixel(x, y) != new.pixel(x, y) {
                let inside = damage
                    .row_span(y as u32)
                    .is_some_and(|span| span.contains(&(x as u32)));
                assert!(
                    inside,
                    "{what}: pixel ({x}, {y}) changed outside the damage {:?}\ncamera: \
                     {camera:?}\nbefore: {before:?}\nafter: {after:?}",
                    damage.rectangles().collect::<Vec<_>>()
                );
            }
        }
    }
    let mut redrawn = old.clone();
    render_changes(after, camera, &damage, &mut redrawn).unwrap();
    assert!(
        redrawn == new,
        "{what}: the redrawn frame is not the fresh one"
    );
}

/// Random edits (a sphere moved into view, resized or removed from view) on tiny screens at
/// very wide fields of view; returns how many edits changed a pixel.
fn damage_tiny<const W: usize, const H: usize>(salt: u64) -> u32 {
    let mut changed = 0;
    for seed in 0..cases() {
        let mut src = XorShift::new(salt << 32 | seed);
        let Some(camera) = wide_camera(&mut src, Size::new(W as u32, H as u32)) else {
            continue;
        };
        let Some(mut world) = scene_about(&mut src, &camera) else {
            continue;
        };
        for step in 0..3 {
            let spheres: Vec<usize> = (0..world.objects().len())
                .filter(|&i| matches!(world.objects()[i].shape, fixray::Shape::Sphere(_)))
                .collect();
            let index = spheres[src.below(spheres.len() as u64) as usize];
            let before = world.clone();
            let Some(sphere) = sphere_in_view(&mut src, &camera) else {
                continue;
            };
            world.set_shape(index, sphere.into()).unwrap();
            let what = format!("{W}x{H} seed {seed} step {step}: sphere {index} to {sphere:?}");
            let frame = |scene: &World| {
                let mut frame = Framebuffer::<W, H>::new();
                render(scene, &camera, &mut frame).unwrap();
                frame
            };
            changed += (frame(&before) != frame(&world)) as u32;
            check_damage::<W, H>(&before, &world, &camera, &what);
        }
    }
    changed
}

#[test]
fn damage_holds_every_changed_pixel_on_tiny_screens_at_the_widest_views() {
    let changed = [
        damage_tiny::<1, 1>(11),
        damage_tiny::<2, 1>(12),
        damage_tiny::<3, 3>(13),
        damage_tiny::<8, 8>(14),
    ];
    // Enough edits change the picture for the test to mean something.
    for count in changed {
        assert!(u64::from(count) * 4 > cases(), "{changed:?}");
    }
}
#[test]
fn orbit_refuses_a_distance_that_is_not_positive() {
    let size = Size::new(160, 128);
    let orbit = |distance: f32| {
        Camera::orbit([0.0, 0.0, -16.0], distance)
            .size(size)
            .build()
    };
    for distance in [-16.0, -1.0, -1e-3, -0.0, 0.0, 1e-7] {
        match orbit(distance) {
            Err(Error::OutOfRange { quantity, min, .. }) => {
                assert_eq!(quantity, Quantity::OrbitDistance, "{distance}");
                assert_eq!(min, Fx::DELTA, "{distance}");
            }
            other => panic!("orbit distance {distance}: {other:?}"),
        }
    }
    assert_eq!(
        orbit(f32::NAN),
        Err(Error::NotFinite {
            quantity: Quantity::OrbitDistance
        })
    );
    // The longest distance two points of the overflow-safe cube can be apart is taken (the
    // eye then in the cube's far corner); past it, the distance itself is refused.
    let reach = 2048.0 * 3f32.sqrt();
    let corner = Camera::orbit([-1024.0, -1024.0, -1024.0], reach * 0.999_99)
        .yaw_degrees(45.0)
        .pitch_degrees(35.264_39)
        .size(size)
        .build();
    assert!(
        !matches!(
            corner,
            Err(Error::OutOfRange {
                quantity: Quantity::OrbitDistance,
                ..
            })
        ),
        "{corner:?}"
    );
    assert!(matches!(
        orbit(reach * 1.000_01),
        Err(Error::OutOfRange {
            quantity: Quantity::OrbitDistance,
            ..
        })
    ));
    let refused = orbit(-16.0).unwrap_err().to_string();
    assert!(refused.contains("orbit distance"), "{refused}");
    // A positive distance still orbits: the eye 16 units from the target.
    let camera = orbit(16.0).unwrap();
    let eye = f64s(camera.eye());
    let distance = (eye[0].powi(2) + eye[1].powi(2) + (eye[2] + 16.0).powi(2)).sqrt();
    assert!((distance - 16.0).abs() < 0.05, "{distance}");
}
