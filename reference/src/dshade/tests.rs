//! Shading against answers worked out from the geometry by hand.

use super::*;
use crate::{DChecker, DLight, DMaterial, DPlane, DSphere};
use fixray::{Background, Rgb};

const SKY: Rgb = Rgb::new(10, 20, 30);
const RED: Rgb = Rgb::new(200, 0, 0);
const BLUE: Rgb = Rgb::new(0, 0, 200);

fn plane(point: [f64; 3], normal: DVec3) -> DPlane {
    DPlane::new(DVec3::new(point[0], point[1], point[2]), normal).unwrap()
}

fn ball(centre: [f64; 3], radius: f64) -> DSphere {
    DSphere::new(DVec3::new(centre[0], centre[1], centre[2]), radius).unwrap()
}

fn ray(from: [f64; 3], to: [f64; 3]) -> DRay {
    let from = DVec3::new(from[0], from[1], from[2]);
    DRay::new(from, DVec3::new(to[0], to[1], to[2]) - from).unwrap()
}

fn scene(ambient: f64, lights: &[DLight], objects: &[DObject]) -> DScene<4> {
    let mut s = DScene::new(ambient, Background::plain(SKY));
    for light in lights {
        s.push_light(*light).unwrap();
    }
    for object in objects {
        s.push(*object).unwrap();
    }
    s
}

/// A black surface that only reflects: what it shows is all mirror image.
fn mirror(reflect: f64) -> DMaterial {
    DMaterial {
        reflect,
        ..DMaterial::matte(Rgb::BLACK)
    }
}

/// A black surface that only has a highlight.
fn glossy(shininess: u16) -> DMaterial {
    DMaterial {
        diffuse: 0.0,
        specular: 1.0,
        shininess,
        ..DMaterial::matte(Rgb::BLACK)
    }
}

#[test]
fn a_point_in_a_balls_shadow_gets_only_ambient() {
    // Light straight above the floor's origin, a ball between them.
    let light = DLight::new(DVec3::new(0.0, 10.0, 0.0), 0.5);
    let floor = DObject::matte(plane([0.0; 3], DVec3::Y).into(), Rgb::new(200, 100, 40));
    let blocker = DObject::matte(ball([0.0, 2.0, 0.0], 1.0).into(), Rgb::WHITE);
    let mut s = scene(0.25, &[light], &[floor, blocker]);
    // From (4, 3, 0) the ray to the origin passes the ball 1.6 from its centre.
    let look = ray([4.0, 3.0, 0.0], [0.0; 3]);
    assert_eq!(s.shoot(&look).map(|h| h.object), Some(0));
    // Ambient only: 0.25 · (200, 100, 40).
    assert_eq!(s.trace(&look).1, Rgb::new(50, 25, 10));
    // Without shadows the light reaches it head on: k = 0.25 + 0.5 · 1.
    s.set_shadows(false);
    assert_eq!(s.trace(&look).1, Rgb::new(150, 75, 30));
}

#[test]
fn only_objects_between_the_point_and_the_light_cast_shadows() {
    // The ball is above the light: the shadow ray stops at the light first.
    let light = DLight::new(DVec3::new(0.0, 10.0, 0.0), 0.5);
    let floor = DObject::matte(plane([0.0; 3], DVec3::Y).into(), Rgb::new(200, 100, 40));
    let above = DObject::matte(ball([0.0, 20.0, 0.0], 1.0).into(), Rgb::WHITE);
    let s = scene(0.25, &[light], &[floor, above]);
    assert_eq!(
        s.trace(&ray([4.0, 3.0, 0.0], [0.0; 3])).1,
        Rgb::new(150, 75, 30)
    );
}

#[test]
fn a_ball_does_not_shadow_itself() {
    // Lit from behind the eye: the lit point faces the light squarely. Its own shadow ray
    // leaves the surface at t = 0, which must not count.
    let light = DLight::new(DVec3::new(0.0, 0.0, 10.0), 1.0);
    let front = DObject::matte(ball([0.0, 0.0, -5.0], 1.0).into(), Rgb::new(40, 80, 120));
    let s = scene(0.0, &[light], &[front]);
    assert_eq!(
        s.trace(&ray([0.0; 3], [0.0, 0.0, -1.0])).1,
        Rgb::new(40, 80, 120)
    );
}

#[test]
fn lights_add_and_those_behind_the_surface_count_nothing() {
    let floor = || DObject::matte(plane([0.0; 3], DVec3::Y).into(), Rgb::new(200, 100, 40));
    let down = ray([0.0, 5.0, 0.0], [0.0; 3]);
    let overhead = |i| DLight::new(DVec3::new(0.0, 10.0, 0.0), i);
    let below = DLight::new(DVec3::new(0.0, -10.0, 0.0), 4.0);
    let one = scene(0.0, &[overhead(0.5)], &[floor()]);
    let two = scene(0.0, &[overhead(0.25), overhead(0.25), below], &[floor()]);
    assert_eq!(one.trace(&down).1, Rgb::new(100, 50, 20));
    assert_eq!(two.trace(&down).1, Rgb::new(100, 50, 20));
    // At 60° from the normal: cos = 0.5, so (200, 100, 40) · 0.5.
    let slanted = DLight::new(DVec3::new(libm::sqrt(3.0), 1.0, 0.0), 1.0);
    let s = scene(0.0, &[slanted], &[floor()]);
    assert_eq!(s.trace(&down).1, Rgb::new(100, 50, 20));
}

#[test]
fn a_ball_seen_from_inside_is_lit_on_its_inner_side() {
    // The light at the centre, the eye too: the facing normal points back at both.
    let light = DLight::new(DVec3::ZERO, 0.5);
    let room = DObject::matte(ball([0.0; 3], 2.0).into(), Rgb::WHITE);
    let s = scene(0.25, &[light], &[room]);
    for to in [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [1.0, 2.0, -3.0]] {
        // k = 0.25 + 0.5 · 1 = 0.75: 255 · 0.75 = 191.25.
        assert_eq!(s.trace(&ray([0.0; 3], to)).1, Rgb::new(191, 191, 191));
    }
}

#[test]
fn a_checkerboard_alternates_across_x_equal_size() {
    // A floor with 0.5-wide squares, lit by ambient alone so each shows its exact colour.
    let board = DMaterial {
        checker: Some(DChecker {
            size: 0.5,
            other: BLUE,
        }),
        ..DMaterial::matte(RED)
    };
    let floor = DObject::new(plane([0.0, -1.0, 0.0], DVec3::Y).into(), board);
    let s = scene(1.0, &[], &[floor]);
    let at = |x: f64| s.trace(&ray([x, 0.0, 0.25], [x, -1.0, 0.25])).1;
    // z = 0.25 is in square 0 along z, so the colour follows ⌊x/0.5⌋.
    assert_eq!(at(0.25), RED);
    assert_eq!(at(0.499), RED);
    assert_eq!(at(0.5), BLUE);
    assert_eq!(at(0.75), BLUE);
    assert_eq!(at(1.0), RED);
    assert_eq!(at(-0.25), BLUE);
    assert_eq!(at(-0.75), RED);
}

#[test]
fn a_mirror_facing_a_red_wall_shows_red_times_reflect() {
    // Eye at the origin looking down −z at a mirror at z = −5; behind the eye a red wall at
    // z = 5 faces it. The mirror is black, so all it shows is 0.5 · the wall.
    let glass = DObject::new(plane([0.0, 0.0, -5.0], DVec3::Z).into(), mirror(0.5));
    let wall = DObject::matte(plane([0.0, 0.0, 5.0], -DVec3::Z).into(), RED);
    let s = scene(1.0, &[], &[glass, wall]);
    let (hit, colour) = s.trace(&ray([0.0; 3], [0.0, 0.0, -1.0]));
    assert_eq!(hit.map(|h| h.object), Some(0));
    assert_eq!(colour, Rgb::new(100, 0, 0));
}

#[test]
fn a_mirror_at_45_degrees_turns_the_ray_by_90() {
    // A mirror floor seen at 45° reflects the ray up at 45°, into a wall at x = 2.
    let floor = DObject::new(plane([0.0; 3], DVec3::Y).into(), mirror(1.0));
    let wall = DObject::matte(plane([2.0, 0.0, 0.0], -DVec3::X).into(), BLUE);
    let s = scene(1.0, &[], &[floor, wall]);
    assert_eq!(s.trace(&ray([0.0, 1.0, 0.0], [1.0, 0.0, 0.0])).1, BLUE);
    // Cut the wall to y ≤ 0.5 (its (u, v) is (y, z)): the reflected ray meets x = 2 at
    // y = 1, above it, and sees the sky.
    let short = plane([2.0, 0.0, 0.0], -DVec3::X)
        .bounded([0.0, -10.0], [0.5, 10.0])
        .unwrap();
    let s = scene(1.0, &[], &[floor, DObject::matte(short.into(), BLUE)]);
    assert_eq!(s.trace(&ray([0.0, 1.0, 0.0], [1.0, 0.0, 0.0])).1, SKY);
}

#[test]
fn facing_mirrors_stop_after_depth_bounces() {
    // Two half-silvered black mirrors face each other; the sky is white. Each bounce halves
    // the weight, and the ray leaving bounce `depth` sees the sky: 255 · 0.5^(depth + 1).
    let a = DObject::new(plane([0.0, 0.0, -5.0], DVec3::Z).into(), mirror(0.5));
    let b = DObject::new(plane([0.0, 0.0, 5.0], -DVec3::Z).into(), mirror(0.5));
    let mut s: DScene<2> = DScene::new(1.0, Background::plain(Rgb::WHITE));
    s.push(a).unwrap();
    s.push(b).unwrap();
    let look = ray([0.0; 3], [0.0, 0.0, -1.0]);
    // 127.5, 63.75, 31.875 and 15.94 rounded.
    for (depth, grey) in [(0, 128), (1, 64), (2, 32), (3, 16)] {
        s.set_depth(depth);
        assert_eq!(
            s.trace(&look).1,
            Rgb::new(grey, grey, grey),
            "depth {depth}"
        );
        let sum = s.radiance(&look, s.shoot(&look).as_ref());
        assert_eq!(sum, [libm::pow(0.5, f64::from(depth) + 1.0); 3]);
    }
}

#[test]
fn the_highlight_peaks_where_the_half_vector_is_the_normal() {
    // Eye at (2, 2, 0), light at (−2, 2, 0): at the origin l and v are mirror images, so
    // h = n and the highlight is the full intensity, 0.4 · 255 = 102, in every channel.
    let light = DLight::new(DVec3::new(-2.0, 2.0, 0.0), 0.4);
    let floor = DObject::new(plane([0.0; 3], DVec3::Y).into(), glossy(50));
    let s = scene(0.0, &[light], &[floor]);
    let at = |x: f64| {
        let look = ray([2.0, 2.0, 0.0], [x, 0.0, 0.0]);
        s.radiance(&look, s.shoot(&look).as_ref())[0]
    };
    assert_eq!(
        s.trace(&ray([2.0, 2.0, 0.0], [0.0; 3])).1,
        Rgb::new(102, 102, 102)
    );
    assert!(libm::fabs(at(0.0) - 0.4) < 1e-15);
    // It falls off on both sides.
    for step in [0.05, 0.1, 0.2, 0.4] {
        assert!(
            at(step) < at(step / 2.0) && at(-step) < at(-step / 2.0),
            "{step}"
        );
    }
}

#[test]
fn the_highlight_is_cos_to_the_shininess() {
    // Eye straight above the point, light 60° from the normal: h is 30° from n, so
    // n·h = cos 30° and (n·h)² = 0.75: 191.25 grey.
    let light = DLight::new(DVec3::new(libm::sqrt(3.0), 1.0, 0.0), 1.0);
    let floor = DObject::new(plane([0.0; 3], DVec3::Y).into(), glossy(2));
    let s = scene(0.0, &[light], &[floor]);
    let down = ray([0.0, 5.0, 0.0], [0.0; 3]);
    assert_eq!(s.trace(&down).1, Rgb::new(191, 191, 191));
    // Diffuse and highlight together: red 200 · 0.5 (cos 60°), plus 0.75 white.
    let both = DMaterial {
        diffuse: 1.0,
        colour: RED,
        ..glossy(2)
    };
    let floor = DObject::new(plane([0.0; 3], DVec3::Y).into(), both);
    let s = scene(0.0, &[light], &[floor]);
    assert_eq!(s.trace(&down).1, Rgb::new(255, 191, 191));
    // A light behind the floor adds no highlight either.
    let behind = DLight::new(DVec3::new(0.0, -10.0, 0.0), 1.0);
    let s = scene(0.0, &[behind], &[floor]);
    assert_eq!(s.trace(&down).1, Rgb::BLACK);
}

#[test]
fn a_miss_sees_the_gradient_along_the_ray() {
    let sky = Background {
        top: Rgb::new(0, 0, 255),
        bottom: Rgb::new(255, 0, 0),
    };
    let s: DScene<1> = DScene::new(0.0, sky);
    assert_eq!(s.trace(&ray([0.0; 3], [0.0, 1.0, 0.0])).1, sky.top);
    assert_eq!(s.trace(&ray([0.0; 3], [0.0, -1.0, 0.0])).1, sky.bottom);
    // Level: s = ½, so 127.5 of each, rounded up.
    assert_eq!(
        s.trace(&ray([0.0; 3], [0.0, 0.0, -1.0])).1,
        Rgb::new(128, 0, 128)
    );
}

/// A black ball of glass that lets all light through, bending it by `index`.
fn glass(index: f64) -> DMaterial {
    DMaterial {
        diffuse: 0.0,
        refract: Some(crate::DRefraction {
            index,
            weight: 1.0,
            fresnel: false,
        }),
        ..DMaterial::matte(Rgb::BLACK)
    }
}

/// A sky that is black straight down and white straight up: a ray's grey tells its `y`.
fn grey_sky(objects: &[DObject]) -> DScene<4> {
    let mut s = DScene::new(
        0.0,
        Background {
            top: Rgb::WHITE,
            bottom: Rgb::BLACK,
        },
    );
    for object in objects {
        s.push(*object).unwrap();
    }
    s
}

#[test]
fn glass_of_index_1_is_invisible() {
    let ball = DObject::new(ball([0.0, 0.0, -5.0], 1.0).into(), glass(1.0));
    let s = grey_sky(&[ball]);
    let empty = grey_sky(&[]);
    for to in [[0.0, 0.0, -5.0], [0.3, 0.5, -5.0], [0.0, -0.9, -5.0]] {
        let seen = s.radiance(&ray([0.0; 3], to), s.shoot(&ray([0.0; 3], to)).as_ref());
        let through = empty.radiance(&ray([0.0; 3], to), None);
        for (a, b) in seen.iter().zip(through) {
            assert!((a - b).abs() < 1e-12, "{seen:?} for {through:?}");
        }
    }
}

#[test]
fn snell_bends_by_the_ratio_of_sines_and_reflects_past_the_critical_angle() {
    let n = DVec3::Z;
    // 45° from air into glass of index 1.5: sin θ₂ = sin 45° / 1.5.
    let d = DVec3::new(1.0, 0.0, -1.0).try_normalize().unwrap();
    let bent = snell(d, n, 1.0 / 1.5).unwrap();
    assert!((bent.x - libm::sqrt(0.5) / 1.5).abs() < 1e-15);
    assert!((bent.length() - 1.0).abs() < 1e-15 && bent.z < 0.0);
    // From inside glass at 45°: sin θ₂ = 1.06 > 1, all reflected; at 40° (below the critical
    // 41.8°) it passes, at sin θ₂ = 1.5 · sin 40°.
    assert_eq!(snell(d, n, 1.5), None);
    let forty = 40f64.to_radians();
    let d = DVec3::new(libm::sin(forty), 0.0, -libm::cos(forty));
    let bent = snell(d, n, 1.5).unwrap();
    assert!((bent.x - 1.5 * libm::sin(forty)).abs() < 1e-15);
    // Straight on, nothing bends.
    assert_eq!(snell(-DVec3::Z, n, 1.5), Some(-DVec3::Z));
}

#[test]
fn a_ray_through_a_glass_ball_off_centre_comes_out_where_snell_sends_it() {
    // A ray down −z at height h = 0.5 meets the unit ball at sin θ₁ = 0.5, bends to
    // sin θ₂ = 0.5/1.5 inside and leaves turned by 2(θ₁ − θ₂) towards the axis.
    let ball = DObject::new(ball([0.0, 0.0, -5.0], 1.0).into(), glass(1.5));
    let s = grey_sky(&[ball]);
    let r = ray([0.0, 0.5, 0.0], [0.0, 0.5, -5.0]);
    let (t1, t2) = (libm::asin(0.5), libm::asin(0.5 / 1.5));
    let turn = 2.0 * (t1 - t2);
    // The leaving direction is (0, −sin turn, −cos turn): its y gives the sky's grey.
    let y = -libm::sin(turn);
    let want = (y + 1.0) / 2.0;
    let seen = s.radiance(&r, s.shoot(&r).as_ref());
    assert!((seen[0] - want).abs() < 1e-12, "{seen:?}, want {want}");
}

#[test]
fn inside_glass_past_the_critical_angle_the_light_stays_in() {
    // The eye at the centre of a glass ball of index 1.5 in a red room: every ray from the
    // centre meets the wall head on and leaves, showing the room. From a point near the wall
    // looking along it, rays meet the wall at a steep angle and are reflected until the
    // depth runs out: with depth 0 the mirror ray sees the sky only.
    let room = DObject::matte(ball([0.0; 3], 10.0).into(), RED);
    let lens = DObject::new(ball([0.0, 0.0, -5.0], 1.0).into(), glass(1.5));
    let mut s = scene(1.0, &[], &[room, lens]);
    let centre = [0.0, 0.0, -5.0];
    assert_eq!(s.trace(&ray(centre, [0.0, 1.0, -5.0])).1, RED);
    s.set_depth(0);
    // From (0, −0.9, −5) along +x: the wall is met at 64° from its normal, past 41.8°.
    let r = ray([0.0, -0.9, -5.0], [1.0, -0.9, -5.0]);
    assert_eq!(s.shoot(&r).map(|h| h.object), Some(1));
    assert_eq!(s.trace(&r).1, SKY);
}

#[test]
fn schlick_reflects_r0_head_on_and_everything_at_grazing() {
    assert!((schlick(1.5, 1.0) - 0.04).abs() < 1e-15);
    assert_eq!(schlick(1.5, 0.0), 1.0);
    assert!(schlick(1.5, 0.5) > 0.04 && schlick(1.5, 0.5) < 0.1);
}
