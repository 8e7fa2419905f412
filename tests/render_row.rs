//! `render_row` culls, skips and hints its way along a row; none of it may change a pixel.

use fixray::{Rgb, Size, demo, render_row};

/// Every pixel of `render_row` against `trace` of the camera's own ray for it.
fn rows_match_tracing_each_pixel<const N: usize, const L: usize>(
    scene: &fixray::Scene<N, L>,
    camera: &fixray::Camera,
) {
    let mut out = vec![Rgb::BLACK; camera.width() as usize];
    for row in 0..camera.height() {
        render_row(scene, camera, row, &mut out).unwrap();
        for (col, pixel) in (0..).zip(&out) {
            let traced = scene.trace(&camera.ray(col, row));
            assert_eq!(*pixel, traced, "row {row}, column {col}");
        }
    }
}

/// [`fixray::render`]'s frame of 96 × 72 pixels against the plain path's, pixel by pixel.
fn frame_matches_tracing_each_pixel<const N: usize>(
    scene: &fixray::Scene<N>,
    camera: &fixray::Camera,
) {
    let mut frame = Box::new(fixray::Framebuffer::<96, 72>::new());
    fixray::render(scene, camera, &mut frame).unwrap();
    for (row, pixels) in (0..).zip(frame.rows()) {
        for (col, pixel) in (0..).zip(pixels) {
            let traced = scene.trace(&camera.ray(col, row));
            assert_eq!(*pixel, traced, "frame row {row}, column {col}");
        }
    }
}

/// A scene with and without shadows, through a camera at two sizes.
fn rows_match_with_and_without_shadows(
    mut scene: fixray::Scene<8>,
    camera: fn(u32, u32) -> Result<fixray::Camera, fixray::Error>,
    odd_size: (u32, u32),
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
        let camera = fixray::Camera::orbit([0.0, 0.0, -16.0], 22.0)
            .yaw_degrees(yaw)
            .pitch_degrees(pitch)
            .size(Size::new(64, 48))
            .build()
            .unwrap();
        rows_match_tracing_each_pixel(&scene, &camera);
    }
}

/// A scene of `N` objects, 64 or more, whose first 64 are a floor and a grid of small spheres
/// on it, and whose last ones, past the 64th, are in view, cast shadows on one another and on
/// the ground, and one of which is a mirror: the culling's 64-bit masks have no bit of their
/// own for them.
fn crowded<const N: usize>() -> fixray::Scene<N> {
    use fixray::{Fx, Light, Material, Plane, Sphere, Vec3};
    let light = Light::from_fx(Vec3::from_ints(-10, 20, 10), Fx::from_num(0.8)).unwrap();
    let mut scene: fixray::Scene<N> =
        fixray::Scene::new(light, 0.2, Rgb::new(30, 60, 200)).unwrap();
    let ball = |x: i16, y: i16, z: i16, r: f32| {
        Sphere::from_fx(Vec3::from_ints(x, y, z), Fx::from_num(r)).unwrap()
    };
    scene
        .add_plane(
            Plane::from_fx(Vec3::from_ints(0, -4, 0), Vec3::Y).unwrap(),
            Rgb::new(120, 120, 120),
        )
        .unwrap();
    // A grid of small spheres, some in view and some off to the sides, up to the 64th object.
    let mut i = 0i16;
    while scene.objects().len() < 64 {
        let (x, z) = (-40 + 6 * (i % 14), -10 - 7 * (i / 14));
        scene
            .add_sphere(ball(x, -3, z, 0.9), Rgb::new(200, 40 + 3 * i as u8, 40))
            .unwrap();
        i += 1;
    }
    let mirror = Material::from_fx(
        Rgb::WHITE,
        Fx::from_num(0.2),
        Fx::ONE,
        50,
        Fx::from_num(0.7),
    )
    .unwrap();
    // Past the 64th: a large mirror in the middle, and more spheres around and above it.
    if scene.objects().len() < N {
        scene.add_sphere(ball(0, 0, -16, 3.5), mirror).unwrap();
    }
    let mut k = 0i16;
    while scene.objects().len() < N {
        let (x, y) = (-9 + 3 * (k % 7), 5 + 2 * (k / 7 % 4));
        scene
            .add_sphere(
                ball(x, y, -20 - k / 28, 0.7),
                Rgb::new(40, 200, 60 + k as u8),
            )
            .unwrap();
        k += 1;
    }
    scene
}

#[test]
fn scenes_of_64_objects_and_more_equal_their_pixels_traced_one_by_one() {
    let camera = fixray::Camera::look_at([0.0, 3.0, 6.0], [0.0, -1.0, -16.0])
        .size(Size::new(96, 72))
        .build()
        .unwrap();
    let mut sixty_four = crowded::<64>();
    let mut seventy = crowded::<70>();
    let mut one_thirty = crowded::<130>();
    for shadows in [true, false] {
        sixty_four.set_shadows(shadows);
        seventy.set_shadows(shadows);
        one_thirty.set_shadows(shadows);
        rows_match_tracing_each_pixel(&sixty_four, &camera);
        rows_match_tracing_each_pixel(&seventy, &camera);
        rows_match_tracing_each_pixel(&one_thirty, &camera);
        // Whole frames, whose rows share what they find of the spheres' shadowers.
        frame_matches_tracing_each_pixel(&sixty_four, &camera);
        frame_matches_tracing_each_pixel(&one_thirty, &camera);
    }
    // The objects past the 64th are really in view.
    let seen = |scene: &fixray::Scene<130>| {
        let mut seen = [false; 130];
        for row in 0..camera.height() {
            for col in 0..camera.width() {
                if let Some(hit) = scene.shoot(&camera.ray(col, row)) {
                    seen[hit.object()] = true;
                }
            }
        }
        seen
    };
    let seen = seen(&one_thirty);
    assert!(seen[64], "the mirror");
    assert!(seen[65..].iter().filter(|&&s| s).count() > 20);
}

/// A room of matte planes, floor and ceiling, unbounded and far enough from the eye that the
/// rows nearest the horizon meet them past `FAR`, under a sky gradient and three lights, with
/// spheres between them that shadow both: each level camera's floor and ceiling rows are found
/// and shaded whole (`accel/matte.rs`), and every pixel must be the one traced.
#[test]
fn matte_floors_and_ceilings_equal_their_pixels_traced_one_by_one() {
    use fixray::{Background, Camera, Light, Material, Plane, Scene, Sphere};
    let sky = Background {
        top: Rgb::new(20, 40, 160),
        bottom: Rgb::new(200, 220, 250),
    };
    let mut scene: Scene<6, 3> =
        Scene::new(Light::new([-300.0, 60.0, 300.0], 0.8).unwrap(), 0.15, sky).unwrap();
    for (position, intensity) in [([90.0, 40.0, -450.0], 0.7), ([0.0, 20.0, -120.0], 0.5)] {
        scene
            .add_light(Light::new(position, intensity).unwrap())
            .unwrap();
    }
    let floor = Material::matte(Rgb::new(120, 150, 90))
        .with_checker(25.0, Rgb::new(40, 60, 30))
        .unwrap();
    let level = |y: f32| Plane::new([0.0, y, 0.0], [0.0, 1.0, 0.0]).unwrap();
    scene.add_plane(level(-90.0), floor).unwrap();
    scene
        .add_plane(level(75.0), Rgb::new(180, 170, 160))
        .unwrap();
    for (centre, r) in [
        ([-30.0, -60.0, -180.0], 15.0),
        ([40.0, 25.0, -300.0], 25.0),
        ([0.0, 0.0, -600.0], 30.0),
    ] {
        let ball = Sphere::new(centre, r).unwrap();
        scene.add_sphere(ball, Rgb::new(200, 60, 40)).unwrap();
    }
    let eyes = [
        ([0.0, 0.0, 0.0], 0.0),
        ([15.0, -20.0, 30.0], 25.0),
        ([-45.0, 35.0, -75.0], 200.0),
    ];
    for (eye, yaw) in eyes {
        let camera = Camera::orbit(eye, 0.001)
            .yaw_degrees(yaw)
            .size(Size::new(72, 54))
            .build()
            .unwrap();
        for shadows in [true, false] {
            scene.set_shadows(shadows);
            rows_match_tracing_each_pixel(&scene, &camera);
        }
    }
}

/// A floor, a ceiling and two walls of one colour each under one light, the common case that
/// `render_row` walks in a loop of its own, seen level (the floor and ceiling meet each row
/// along it) from eyes turned every way, so that the walls do too where a row runs along them,
/// and the row moves along one or two axes.
#[test]
fn floors_ceilings_and_walls_under_one_light_equal_their_pixels_traced_one_by_one() {
    use fixray::{Background, Camera, Light, Plane, Scene, Sphere};
    let mut scene: Scene<8, 1> = Scene::new(
        Light::new([-25.0, 30.0, 20.0], 0.8).unwrap(),
        0.2,
        Background::plain(Rgb::new(40, 60, 90)),
    )
    .unwrap();
    let planes = [
        ([0.0, -3.0, 0.0], [0.0, 1.0, 0.0], Rgb::new(120, 150, 90)),
        ([0.0, 45.0, 0.0], [0.0, -1.0, 0.0], Rgb::new(200, 190, 180)),
        ([60.0, 0.0, 0.0], [-1.0, 0.0, 0.0], Rgb::new(150, 140, 170)),
        ([0.0, 0.0, -80.0], [0.0, 0.0, 1.0], Rgb::new(90, 130, 160)),
    ];
    for (point, normal, colour) in planes {
        scene
            .add_plane(Plane::new(point, normal).unwrap(), colour)
            .unwrap();
    }
    for (centre, r) in [([-4.0, -1.0, -14.0], 2.0), ([6.0, 2.0, -24.0], 3.5)] {
        let ball = Sphere::new(centre, r).unwrap();
        scene.add_sphere(ball, Rgb::new(200, 60, 40)).unwrap();
    }
    for yaw in [0.0, 25.0, 90.0, 180.0, 200.0, 270.0, 333.0] {
        for pitch in [0.0, 12.0] {
            let camera = Camera::orbit([0.0, 0.0, -16.0], 18.0)
                .yaw_degrees(yaw)
                .pitch_degrees(pitch)
                .size(Size::new(61, 47))
                .build()
                .unwrap();
            for shadows in [true, false] {
                scene.set_shadows(shadows);
                rows_match_tracing_each_pixel(&scene, &camera);
            }
        }
    }
}

/// Spheres sunk into a floor, resting on it, and lifted off it by less than, about and more
/// than the margin `render_row` keeps before trying a sphere's hit ahead of the floor's, and
/// one through a wall, seen from eyes above the floor, just over it and below it: the planes
/// may go untried only where no hit of theirs could be nearer, and every pixel must be the one
/// traced.
#[test]
fn spheres_on_and_through_planes_equal_their_pixels_traced_one_by_one() {
    use fixray::{Background, Camera, Light, Plane, Scene, Sphere};
    let mut scene: Scene<10, 2> = Scene::new(
        Light::new([-8.0, 12.0, 6.0], 0.8).unwrap(),
        0.2,
        Background::plain(Rgb::new(40, 60, 90)),
    )
    .unwrap();
    scene
        .add_light(Light::new([6.0, 3.0, -2.0], 0.4).unwrap())
        .unwrap();
    let floor = Plane::new([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
    let wall = Plane::new([0.0, 0.0, -14.0], [0.2, 0.0, 1.0]).unwrap();
    scene.add_plane(floor, Rgb::new(120, 150, 90)).unwrap();
    scene.add_plane(wall, Rgb::new(150, 140, 170)).unwrap();
    // Centre heights over the floor for radius 1: sunk, resting, lifted by 2⁻⁹ (inside the
    // margin), by 0.02 (about it), by 0.2, and one through the wall.
    for (x, y, z) in [
        (-5.0, 0.4, -8.0),
        (-2.5, 1.0, -8.0),
        (0.0, 1.0 + 1.0 / 512.0, -8.0),
        (2.5, 1.02, -8.0),
        (5.0, 1.2, -8.0),
        (1.0, 2.5, -13.6),
    ] {
        let ball = Sphere::new([x, y, z], 1.0).unwrap();
        scene.add_sphere(ball, Rgb::new(200, 80, 60)).unwrap();
    }
    for (eye, target) in [
        ([0.0, 4.0, 4.0], [0.0, 0.5, -8.0]),
        ([1.0, 0.05, 2.0], [0.0, 0.6, -8.0]),
        ([-1.0, 1.0, -4.0], [3.0, 1.0, -8.0]),
        ([0.0, -3.0, 3.0], [0.0, 0.0, -8.0]),
    ] {
        let camera = Camera::look_at(eye, target)
            .fov_degrees(70.0)
            .size(Size::new(96, 64))
            .build()
            .unwrap();
        for shadows in [true, false] {
            scene.set_shadows(shadows);
            rows_match_tracing_each_pixel(&scene, &camera);
        }
    }
}

#[test]
fn spheres_whose_fronts_meet_equal_their_pixels_traced_one_by_one() {
    // Pairs of balls whose near sides touch or nearly touch on the line of sight through
    // their centres, one of them flatter: about that line each is the nearer on one side,
    // by less than the rounding of a hit, and the nearest found so far may leave the other
    // only where none of its hits can be nearer. Either ball first, and nudged by a few
    // units of 2⁻¹⁶ either way.
    use fixray::{Background, Camera, Light, Scene, Sphere};
    let camera = Camera::look_at([0.0, 0.0, 0.0], [0.0, 0.0, -10.0])
        .fov_degrees(20.0)
        .size(Size::new(96, 64))
        .build()
        .unwrap();
    for nudge in [-3.0, 0.0, 1.0, 5.0] {
        let far = -12.0 + nudge / 65536.0;
        let balls = [
            Sphere::new([0.0, 0.0, -10.0], 2.0).unwrap(),
            Sphere::new([0.0, 0.0, far], 4.0).unwrap(),
            Sphere::new([0.3, -0.2, far - 0.5], 4.5).unwrap(),
        ];
        for order in [[0, 1, 2], [2, 1, 0], [1, 0, 2]] {
            let mut scene: Scene<4> = Scene::new(
                Light::new([-6.0, 8.0, 4.0], 0.9).unwrap(),
                0.1,
                Background::plain(Rgb::new(20, 30, 40)),
            )
            .unwrap();
            for (k, i) in order.into_iter().enumerate() {
                let colour = Rgb::new(60 + 60 * k as u8, 200 - 50 * k as u8, 90);
                scene.add_sphere(balls[i], colour).unwrap();
            }
            rows_match_tracing_each_pixel(&scene, &camera);
        }
    }
}

/// Marsaglia's xorshift64: the random fields below, the same on every run.
struct XorShift(u64);

impl XorShift {
    /// A value drawn evenly from `lo..hi`.
    fn between(&mut self, lo: f32, hi: f32) -> f32 {
        let s = &mut self.0;
        *s ^= *s << 13;
        *s ^= *s >> 7;
        *s ^= *s << 17;
        lo + (*s >> 40) as f32 / (1u64 << 24) as f32 * (hi - lo)
    }
}

/// A random field of `count` objects in a scene of capacity `N`: a floor, now and then a
/// tilted wall or a ceiling among them (anywhere in the order, so planes get bits past the
/// 64th too), and spheres of every size on, above, through and around the floor, some shiny
/// and a few mirrors; one to three lights, one of them now and then among the spheres.
fn random_field<const N: usize>(rng: &mut XorShift, count: usize) -> fixray::Scene<N> {
    use fixray::{Light, Material, Plane, Sphere};
    let light = |rng: &mut XorShift| {
        let at = [
            rng.between(-30.0, 30.0),
            rng.between(1.0, 30.0),
            rng.between(-40.0, 15.0),
        ];
        Light::new(at, rng.between(0.3, 0.9)).unwrap()
    };
    let mut scene: fixray::Scene<N> =
        fixray::Scene::new(light(rng), 0.15, Rgb::new(20, 40, 90)).unwrap();
    for _ in 0..rng.between(0.0, 2.99) as usize {
        scene.add_light(light(rng)).unwrap();
    }
    let floor = Plane::new([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
    scene.add_plane(floor, Rgb::new(150, 150, 140)).unwrap();
    while scene.objects().len() < count {
        let colour = Rgb::new(
            rng.between(30.0, 250.0) as u8,
            rng.between(30.0, 250.0) as u8,
            rng.between(30.0, 250.0) as u8,
        );
        let kind = rng.between(0.0, 1.0);
        if kind < 0.04 {
            let normal = [rng.between(-1.0, 1.0), rng.between(-0.3, 0.3), 1.0];
            let at = [0.0, 0.0, rng.between(-70.0, -30.0)];
            scene
                .add_plane(Plane::new(at, normal).unwrap(), colour)
                .unwrap();
            continue;
        }
        if kind < 0.06 {
            let ceiling = Plane::new([0.0, rng.between(12.0, 30.0), 0.0], [0.0, -1.0, 0.0]);
            scene.add_plane(ceiling.unwrap(), colour).unwrap();
            continue;
        }
        let z = rng.between(-50.0, -3.0);
        let x = rng.between(-1.0, 1.0) * (4.0 - z * 0.6);
        let radius = rng.between(0.2, if kind < 0.1 { 6.0 } else { 1.5 });
        let y = radius * rng.between(-0.5, 1.0) + rng.between(0.0, 4.0).powi(2);
        let material = match kind {
            k if k < 0.12 => Material::new(colour, 0.3, 0.8, 60, 0.6).unwrap(),
            k if k < 0.3 => Material::new(colour, 0.8, 0.5, 20, 0.0).unwrap(),
            _ => Material::matte(colour),
        };
        let sphere = Sphere::new([x, y, z], radius).unwrap();
        scene.add_sphere(sphere, material).unwrap();
    }
    scene
}

/// Random fields of spheres and planes with 64, 65 and 200 objects in scenes of capacity 64,
/// 65 and 200, and of 20 objects in one of capacity 200, seen from several places: past 32
/// objects every shadow ray goes by its light's sweep, past a capacity of 64 every row names
/// its objects by a crowd, and past 64 objects that a row can meet some are its extras.
#[test]
fn random_fields_past_32_and_64_objects_equal_their_pixels_traced_one_by_one() {
    let mut rng = XorShift(0x0f1e_1d5a_ba5e_64ff);
    let views = [
        ([0.0, 6.0, 8.0], [0.0, 0.0, -20.0]),
        ([-12.0, 2.0, 4.0], [6.0, 1.0, -30.0]),
        ([3.0, 25.0, -10.0], [0.0, 0.0, -25.0]),
        ([0.0, 0.7, 2.0], [0.0, 0.7, -40.0]),
    ];
    for round in 0..3 {
        let (eye, target) = views[round % views.len()];
        let camera = fixray::Camera::look_at(eye, target)
            .fov_degrees(50.0 + 20.0 * round as f32)
            .size(Size::new(72, 54))
            .build()
            .unwrap();
        rows_match_tracing_each_pixel(&random_field::<64>(&mut rng, 64), &camera);
        rows_match_tracing_each_pixel(&random_field::<65>(&mut rng, 65), &camera);
        rows_match_tracing_each_pixel(&random_field::<200>(&mut rng, 200), &camera);
        rows_match_tracing_each_pixel(&random_field::<200>(&mut rng, 20), &camera);
    }
    let (eye, target) = views[3];
    let camera = fixray::Camera::look_at(eye, target)
        .size(Size::new(72, 54))
        .build()
        .unwrap();
    let mut crowd = random_field::<200>(&mut rng, 200);
    crowd.set_shadows(false);
    rows_match_tracing_each_pixel(&crowd, &camera);
}
