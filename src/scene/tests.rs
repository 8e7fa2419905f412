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
            let culled = scene.occluded(&ray, d2, usize::MAX, index);
            assert_eq!(
                culled,
                scene.occluded(&ray, d2, usize::MAX, usize::MAX),
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
