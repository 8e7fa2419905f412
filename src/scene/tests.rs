use super::*;
use crate::geometry::ray::Ray;
use crate::numbers::vec3::Vec3;

fn lit_from_above() -> Scene<4> {
    let light = Light::from_fx(Vec3::from_ints(0, 100, 0), Fx::from_num(0.75)).unwrap();
    Scene::new(light, 0.25, Rgb::new(1, 2, 3)).unwrap()
}

#[test]
fn nearest_object_wins_whatever_the_order() {
    let mut scene = lit_from_above();
    let far = Sphere::from_fx(Vec3::from_ints(0, 0, -20), Fx::from_num(2)).unwrap();
    let near = Sphere::from_fx(Vec3::from_ints(0, 0, -10), Fx::from_num(2)).unwrap();
    scene.add_sphere(far, Rgb::WHITE).unwrap();
    let near_index = scene.add_sphere(near, Rgb::WHITE).unwrap();
    let hit = scene
        .shoot(&Ray::new(Vec3::ZERO, -Vec3::Z).unwrap())
        .unwrap();
    assert_eq!((hit.object, hit.hit.t), (near_index, Fx::from_num(8)));
}

#[test]
fn lambert_shading_follows_the_angle_to_the_light() {
    let mut scene = lit_from_above();
    let ground = Plane::from_fx(Vec3::from_ints(0, -4, 0), Vec3::Y).unwrap();
    scene.add_plane(ground, Rgb::new(200, 100, 0)).unwrap();
    // Straight below the light: n·l = 1, so k = 0.25 + 0.75 = 1.
    let down = Ray::new(Vec3::ZERO, -Vec3::Y).unwrap();
    assert_eq!(scene.trace(&down), Rgb::new(200, 100, 0));
    // A wall lit from behind gets only the ambient quarter.
    let behind = Light::from_fx(Vec3::from_ints(0, 0, -100), Fx::from_num(0.75)).unwrap();
    let mut dark: Scene<1> = Scene::new(behind, 0.25, Rgb::BLACK).unwrap();
    let wall = Plane::from_fx(Vec3::from_ints(0, 0, -5), Vec3::Z).unwrap();
    dark.add_plane(wall, Rgb::new(200, 100, 0)).unwrap();
    assert_eq!(
        dark.trace(&Ray::new(Vec3::ZERO, -Vec3::Z).unwrap()),
        Rgb::new(50, 25, 0)
    );
}

#[test]
fn misses_show_the_background() {
    let scene = lit_from_above();
    assert_eq!(
        scene.trace(&Ray::new(Vec3::ZERO, Vec3::X).unwrap()),
        Rgb::new(1, 2, 3)
    );
}

#[test]
fn ambient_outside_zero_to_one_is_refused() {
    let light = Light::from_fx(Vec3::ZERO, Fx::ONE).unwrap();
    assert_eq!(
        Scene::<1>::new(light, 1.5, Rgb::BLACK).map(|_| ()),
        Err(Error::OutOfRange {
            quantity: Quantity::Ambient,
            min: Fx::ZERO,
            max: Fx::ONE,
        })
    );
}

#[test]
fn shadow_cones_never_skip_an_occluder() {
    // Shadow rays from points all over the classic scene's floor and spheres, towards each
    // light: the cone-culled test must agree with the test that tries every object (light
    // index out of range: no cones).
    let scene = crate::demo::classic();
    let mut rng = crate::xorshift::XorShift(0x1234_5678_9abc_def0);
    let mut next = |range: f64| {
        let seed = rng.next();
        Fx::from_num(((seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0) * range)
    };
    let mut blocked = 0;
    for _ in 0..20_000 {
        let point = Vec3::new(
            next(12.0),
            next(8.0) - Fx::from_num(2),
            next(12.0) - Fx::from_num(18),
        );
        for (index, light) in scene.lights().iter().enumerate() {
            let to_light = light.position - point;
            let Some(l) = to_light.try_normalize() else {
                continue;
            };
            let ray = Ray::new_unchecked(point, l);
            let d2 = to_light.length_squared_wide();
            let culled = scene.occluded_among(ray.origin(), ray.dir(), d2, usize::MAX, index, !0);
            assert_eq!(
                culled,
                scene.occluded(ray.origin(), ray.dir(), d2, usize::MAX),
                "{point:?} light {index}"
            );
            blocked += culled as u32;
        }
    }
    assert!(
        blocked > 1000,
        "the sample must include shadowed points: {blocked}"
    );
}

#[test]
fn only_objects_that_cannot_shadow_a_receiver_are_skipped() {
    // Random scenes of spheres crowded around a floor and a wall, lit from anywhere (inside
    // spheres, below the floor, level with them), and shadow rays from points on each object's
    // surface: the test that tries only the receiver's shadowers (and its cones) must agree
    // with the one that tries every object.
    let mut rng = crate::xorshift::XorShift(0x0bad_5eed_f00d_cafe);
    let mut next = move |range: f64| {
        let seed = rng.next();
        ((seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0) * range
    };
    let (mut blocked, mut skipped) = (0u32, 0u32);
    for _ in 0..300 {
        let light = |next: &mut dyn FnMut(f64) -> f64| {
            Light::new(
                [
                    next(12.0) as f32,
                    next(12.0) as f32 + 4.0,
                    next(12.0) as f32,
                ],
                1.0,
            )
            .unwrap()
        };
        let mut scene: Scene<10, 2> = Scene::new(light(&mut next), 0.1, Rgb::BLACK).unwrap();
        scene.add_light(light(&mut next)).unwrap();
        let floor = Plane::new([0.0, next(2.0) as f32 - 2.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
        scene.add_plane(floor, Rgb::WHITE).unwrap();
        let wall = Plane::new([0.0, 0.0, -12.0], [next(0.3) as f32, 0.0, 1.0]).unwrap();
        scene.add_plane(wall, Rgb::WHITE).unwrap();
        for _ in 0..8 {
            let centre = [next(6.0) as f32, next(4.0) as f32, next(6.0) as f32 - 4.0];
            let ball = Sphere::new(centre, (next(1.0).abs() * 2.5 + 0.2) as f32).unwrap();
            scene.add_sphere(ball, Rgb::WHITE).unwrap();
        }
        for (receiver, object) in scene.objects().iter().enumerate() {
            for _ in 0..40 {
                // A point on the surface, as a rounded hit point would be.
                let point = match object.shape {
                    Shape::Sphere(ball) => {
                        let Some(u) = Vec3::new(
                            Fx::from_num(next(1.0)),
                            Fx::from_num(next(1.0)),
                            Fx::from_num(next(1.0)),
                        )
                        .try_normalize() else {
                            continue;
                        };
                        ball.centre() + u.scale(ball.radius())
                    }
                    Shape::Plane(plane) => {
                        let (x, y) = (Fx::from_num(next(14.0)), Fx::from_num(next(8.0)));
                        let along = |p: Vec3| Vec3::new(x, p.y, p.z);
                        let on = Ray::new(
                            along(plane.point()) + Vec3::new(Fx::ZERO, y, Fx::ZERO),
                            -plane.normal(),
                        )
                        .ok()
                        .and_then(|r| {
                            plane.intersect(&r).or_else(|| {
                                plane.intersect(&Ray::new(r.origin(), plane.normal()).ok()?)
                            })
                        });
                        let Some(hit) = on else { continue };
                        hit.point()
                    }
                };
                for light in 0..scene.lights().len() {
                    let to_light = scene.lights()[light].position - point;
                    let Some(l) = to_light.try_normalize() else {
                        continue;
                    };
                    let ray = Ray::new_unchecked(point, l);
                    let d2 = to_light.length_squared_wide();
                    let every = scene.occluded(ray.origin(), ray.dir(), d2, receiver);
                    assert_eq!(
                        scene.occluded_among(ray.origin(), ray.dir(), d2, receiver, light, !0),
                        every,
                        "object {receiver} at {point:?}, light {light}"
                    );
                    blocked += every as u32;
                }
            }
            skipped += (scene
                .shadow_caches()
                .shadowers(0, receiver)
                .unwrap()
                .count_ones()
                + 1
                < 10) as u32;
        }
    }
    assert!(
        blocked > 5_000,
        "the sample must include shadowed points: {blocked}"
    );
    assert!(
        skipped > 1_000,
        "the sets must leave objects out: {skipped}"
    );
}

/// Two mirrors face each other a unit apart, a floor and a ceiling, and a ray leaves the eye
/// between them almost level: each bounce carries it about 7 300 further along −z, so its
/// second hit (z ≈ −10 900) lies past the budget every hit point keeps (±(LIMIT + FAR)), and
/// a third, from there, would test the sphere from beyond the overflow budget. Past the
/// budget a secondary ray's hit is a miss: the picture is the one without the ceiling, whose
/// mirror ray sees the sky. (Before that rule, debug builds stopped at the sphere test's
/// bound, and a longer chain could wrap a hit point.)
#[test]
fn secondary_hits_stay_inside_the_budget() {
    let mirror = Material::new(Rgb::new(90, 90, 90), 0.5, 0.0, 1, 0.9).unwrap();
    let build = |ceiling: bool| {
        let mut scene = lit_from_above();
        scene.set_depth(Scene::<4>::MAX_DEPTH);
        scene.set_shadows(false); // the ceiling would shade the floor
        let floor = Plane::from_fx(Vec3::ZERO, Vec3::Y).unwrap();
        scene.add_plane(floor, mirror).unwrap();
        if ceiling {
            let top = Plane::from_fx(Vec3::from_ints(0, 1, 0), -Vec3::Y).unwrap();
            scene.add_plane(top, mirror).unwrap();
        }
        let ball = Sphere::from_fx(Vec3::from_ints(0, 5, -20), Fx::ONE).unwrap();
        scene.add_sphere(ball, Rgb::WHITE).unwrap();
        scene
    };
    let eye = Vec3::new(Fx::ZERO, Fx::from_num(0.5), Fx::ZERO);
    let ray = Ray::new(eye, Vec3::new(Fx::ZERO, Fx::from_bits(-9), -Fx::ONE)).unwrap();
    let (with, without) = (build(true), build(false));
    let first = with.shoot(&ray).unwrap();
    assert_eq!(first.object, 0, "the floor, first");
    assert!(
        first.hit.point.z < Fx::from_num(-3000),
        "{:?}",
        first.hit.point
    );
    // The ceiling is met from the floor's hit, within FAR of it, but past the budget.
    // (Past LIMIT, as a secondary ray's origin may be: `Ray::new` would refuse it.)
    let up = Vec3::new(Fx::ZERO, Fx::from_bits(9), -Fx::ONE);
    let from_floor = Ray::new_unchecked(first.hit.point, up);
    let ceiling = with.objects()[1].shape.intersect(&from_floor).unwrap();
    assert!(ceiling.point.z < -(crate::numbers::fx::LIMIT + crate::FAR));
    // `shoot` drops it as the secondary rays do: the ray sees what it sees without a ceiling.
    assert_eq!(with.shoot(&from_floor), None);
    assert_eq!(without.shoot(&from_floor), None);
    assert_eq!(with.trace(&ray), without.trace(&ray));
}

#[test]
fn a_plain_matte_pixel_is_each_channel_times_its_brightness_rounded_once() {
    // k = ambient + weight · diffuse, each channel c·k rounded half up and held at 255: the
    // f64 reference's formula, in exact integers here.
    let mut rng = crate::xorshift::XorShift(0x6a09_e667_f3bc_c909);
    let diffuse_values: [Fx; 5000] =
        core::array::from_fn(|_| Fx::from_bits((rng.next() >> 44) as i32));
    let ends = [
        0,
        1,
        0x7fff,
        0x8000,
        0x1_0000,
        0x1_0001,
        0xff_ffff,
        0x100_0000,
        i32::MAX,
    ]
    .map(Fx::from_bits);
    for ambient in [0.0, 0.25, 1.0] {
        let light = Light::from_fx(Vec3::from_ints(0, 100, 0), Fx::ONE).unwrap();
        let scene = Scene::<1>::new(light, ambient, Rgb::BLACK).unwrap();
        for weight in [0.0, 0.6, 1.0, 2.0] {
            let material = Material::new(Rgb::new(0, 128, 255), weight, 0.0, 1, 0.0).unwrap();
            for &diffuse in ends.iter().chain(&diffuse_values) {
                let k = scene.ambient().saturating_add(if weight == 1.0 {
                    diffuse
                } else {
                    crate::numbers::fx::mul(material.diffuse, diffuse)
                });
                let exact = |c: u8| {
                    let product = c as i64 * k.to_bits() as i64; // exact: below 2⁴⁰
                    ((product + (1 << 15)) >> 16).clamp(0, 255) as u8
                };
                for colour in [Rgb::new(0, 128, 255), Rgb::new(1, 2, 3), Rgb::WHITE] {
                    assert_eq!(
                        scene.matte_pixel(&material, diffuse, colour),
                        Rgb::new(exact(colour.r), exact(colour.g), exact(colour.b)),
                        "ambient {ambient}, weight {weight}, diffuse {diffuse:?}, {colour:?}"
                    );
                }
            }
        }
    }
}
