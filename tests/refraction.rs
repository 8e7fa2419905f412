//! Glass: rays refracted through spheres leave at the angles Snell's law gives, totally
//! internally reflected light goes to the mirror ray, and Schlick's share is mirrored.
//!
//! The scenes are lit by nothing the pixels show: the glass is black with no diffuse or
//! highlight, and the background is a gradient from black straight down to white straight up,
//! so a pixel is `255 · (y + 1)/2` for the `y` of the last ray's direction. The expected
//! directions are worked out here in `f64` from the geometry.

use fixray::{Background, Fx, Light, Material, Object, Ray, Rgb, Scene, Shape, Sphere, Vec3};

/// Black to white from straight down to straight up.
const GRADIENT: Background = Background {
    top: Rgb::WHITE,
    bottom: Rgb::BLACK,
};

/// A black glass sphere of index `index` at the origin, radius 1, letting `weight` through.
fn glass_scene(index: f32, weight: f32, fresnel: bool, depth: u8) -> Scene<2> {
    let mut glass = Material::new(Rgb::BLACK, 0.0, 0.0, 1, 0.0)
        .unwrap()
        .with_refraction(index, weight)
        .unwrap();
    if fresnel {
        glass = glass.with_fresnel();
    }
    let light = Light::new([0.0, 50.0, 0.0], 1.0).unwrap();
    let mut scene = Scene::new(light, 0.0, GRADIENT).unwrap();
    let ball = Sphere::new([0.0; 3], 1.0).unwrap();
    scene.add(Object::new(Shape::Sphere(ball), glass)).unwrap();
    scene.set_depth(depth);
    scene
}

fn v(x: f64, y: f64, z: f64) -> Vec3 {
    Vec3::new(Fx::from_num(x), Fx::from_num(y), Fx::from_num(z))
}

fn ray(origin: [f64; 3], dir: [f64; 3]) -> Ray {
    let n = (dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]).sqrt();
    Ray::new(
        v(origin[0], origin[1], origin[2]),
        v(dir[0] / n, dir[1] / n, dir[2] / n),
    )
    .unwrap()
}

/// The gradient's grey for a direction with this `y`.
fn grey(y: f64) -> f64 {
    255.0 * (y + 1.0) / 2.0
}

fn assert_grey(got: Rgb, want: f64, what: &str) {
    for c in [got.r, got.g, got.b] {
        assert!(
            (f64::from(c) - want).abs() <= 1.0,
            "{what}: got {got:?}, want {want:.2}"
        );
    }
}

#[test]
fn a_ray_through_the_centre_goes_straight_through() {
    // Normal incidence on the way in and out: undeviated for any index.
    for index in [0.5, 1.0, 1.5, 2.4, 4.0] {
        let scene = glass_scene(index, 1.0, false, 4);
        for (dir, y) in [([0.0, 0.0, -1.0], 0.0), ([0.0, -1.0, 0.0], -1.0)] {
            let from = [-5.0 * dir[0], -5.0 * dir[1], -5.0 * dir[2]];
            assert_grey(
                scene.trace(&ray(from, dir)),
                grey(y),
                &format!("index {index}"),
            );
        }
    }
}

#[test]
fn a_ray_leaves_at_the_angle_snells_law_gives() {
    // A ray along +x at height b enters at incidence θ₁ = asin b, bends to θ₂ with
    // sin θ₂ = sin θ₁ / η, crosses a chord that meets the surface again at θ₂, and leaves at
    // θ₁: it turns towards the axis by 2(θ₁ − θ₂).
    for index in [1.0, 1.2, 1.5, 2.0, 3.0] {
        let scene = glass_scene(index as f32, 1.0, false, 4);
        for b in [0.1, 0.3, 0.5, 0.7, 0.9] {
            let incidence = f64::asin(b);
            let inside = f64::asin(b / index);
            let turn = 2.0 * (incidence - inside);
            let colour = scene.trace(&ray([-5.0, b, 0.0], [1.0, 0.0, 0.0]));
            assert_grey(
                colour,
                grey(-turn.sin()),
                &format!("index {index}, height {b}"),
            );
        }
    }
}

#[test]
fn index_one_glass_is_invisible() {
    // Seen through glass of index 1 every ray goes on as if it were not there.
    let scene = glass_scene(1.0, 1.0, false, 4);
    for i in 0..40 {
        let t = f64::from(i) / 40.0;
        let dir = [1.0, 0.9 * (t - 0.5), 0.3 * t - 0.1];
        let n = (dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]).sqrt();
        assert_grey(
            scene.trace(&ray([-5.0, 0.0, 0.0], dir)),
            grey(dir[1] / n),
            &format!("ray {i}"),
        );
    }
}

/// `d − 2(d·n)n`.
fn mirrored(d: [f64; 3], n: [f64; 3]) -> [f64; 3] {
    let k = 2.0 * (d[0] * n[0] + d[1] * n[1] + d[2] * n[2]);
    [d[0] - k * n[0], d[1] - k * n[1], d[2] - k * n[2]]
}

#[test]
fn totally_internally_reflected_light_goes_to_the_mirror_ray() {
    // The eye inside glass of index 1.5 (critical angle 41.8°), looking along +x from
    // height 0.6: it meets the surface at incidence asin 0.6 = 36.9°, and passes; from
    // height 0.9, at 64.2°, it is reflected, and meets the surface again at the same angle.
    let d = [1.0, 0.0, 0.0];
    let height = 0.9_f64;
    let p = [(1.0 - height * height).sqrt(), height, 0.0];
    let d1 = mirrored(d, p);
    // From p along d1 the unit sphere is met again at q = p + t·d1, t = −2 p·d1.
    let t = -2.0 * (p[0] * d1[0] + p[1] * d1[1]);
    let q = [p[0] + t * d1[0], p[1] + t * d1[1], 0.0];
    let d2 = mirrored(d1, q);
    for (depth, y) in [(0, d1[1]), (1, d2[1])] {
        let scene = glass_scene(1.5, 1.0, false, depth);
        let colour = scene.trace(&ray([0.0, height, 0.0], d));
        assert_grey(colour, grey(y), &format!("depth {depth}"));
    }
    // Below the critical angle the ray leaves, bent away from the normal (0.8, 0.6):
    // sin θ₂ = 1.5 · 0.6 = 0.9, so it turns downwards by θ₂ − θ₁.
    let scene = glass_scene(1.5, 1.0, false, 4);
    let colour = scene.trace(&ray([0.0, 0.6, 0.0], d));
    let turn = f64::asin(0.9) - f64::asin(0.6);
    assert_grey(colour, grey(-turn.sin()), "below the critical angle");
}

#[test]
fn fresnel_mirrors_schlicks_share() {
    // Looking straight down through the glass: what leaves downwards sees black, what leaves
    // upwards white. Without Fresnel weighting nothing is mirrored. With it, every crossing
    // is at normal incidence and mirrors R = ((1.5 − 1)/(1.5 + 1))² = 0.04: upwards go R at
    // the top (generation 1), then (1 − R)·R·(1 − R) mirrored inside at the bottom and out of
    // the top (generation 3), and (1 − R)·R³·(1 − R) (generation 5, past depth 4: it sees
    // the background it points at, white).
    let down = ray([0.0, 5.0, 0.0], [0.0, -1.0, 0.0]);
    assert_eq!(glass_scene(1.5, 1.0, false, 4).trace(&down), Rgb::BLACK);
    let with = glass_scene(1.5, 1.0, true, 4).trace(&down);
    let r = 0.04;
    let up = r + (1.0 - r) * r * (1.0 - r) + (1.0 - r) * r * r * r * (1.0 - r);
    assert_grey(with, 255.0 * up, "Fresnel at normal incidence");
}

#[test]
fn refraction_is_checked() {
    use fixray::{Error, Quantity};
    let m = Material::matte(Rgb::WHITE);
    for (index, weight, quantity) in [
        (0.2, 0.5, Quantity::RefractiveIndex),
        (4.5, 0.5, Quantity::RefractiveIndex),
        (f32::NAN, 0.5, Quantity::RefractiveIndex),
        (1.5, 0.0, Quantity::Refraction),
        (1.5, 1.5, Quantity::Refraction),
    ] {
        let got = m.with_refraction(index, weight);
        assert!(
            matches!(got, Err(Error::OutOfRange { quantity: q, .. }) if q == quantity)
                || matches!(got, Err(Error::NotFinite { .. })),
            "{index} {weight}: {got:?}"
        );
    }
    let glass = m.with_refraction(0.25, 1.0).unwrap().with_fresnel();
    let r = glass.refraction().unwrap();
    assert_eq!(
        (r.index(), r.weight(), r.fresnel()),
        (Fx::from_num(0.25), Fx::ONE, true)
    );
    // Fresnel weighting without refraction changes nothing.
    assert_eq!(m.with_fresnel(), m);
}

/// The eye at the centre of a glass ball (index 1, half mirrored, half let through) inside a
/// grey mirrored room: every ray meets a surface head on, each glass hit sends two rays on
/// and each wall hit one, so generation `g` has F(g+2) rays (Fibonacci) and the tree at
/// depth `d` holds 2, 3, 5, 8, 13, 21, 34, … rays a generation: 52 up to depth 6, 86 up to 7.
fn hall_of_mirrors(depth: u8) -> Scene<2> {
    let glass = Material::new(Rgb::BLACK, 0.0, 0.0, 1, 0.5)
        .unwrap()
        .with_refraction(1.0, 0.5)
        .unwrap();
    let wall = Material::new(Rgb::new(200, 200, 200), 0.0, 0.0, 1, 0.6).unwrap();
    let light = Light::new([0.0, 0.0, 0.0], 1.0).unwrap();
    let mut scene = Scene::new(light, 0.2, Rgb::BLACK).unwrap();
    let ball = Sphere::new([0.0; 3], 1.0).unwrap();
    let room = Sphere::new([0.0; 3], 4.0).unwrap();
    scene.add(Object::new(Shape::Sphere(ball), glass)).unwrap();
    scene.add(Object::new(Shape::Sphere(room), wall)).unwrap();
    scene.set_depth(depth);
    scene
}

#[test]
fn a_pixel_follows_every_ray_up_to_max_rays_and_no_more() {
    let along = ray([0.0; 3], [0.3, -0.2, 1.0]);
    let dray = fixray_reference::DRay::new(
        fixray_reference::DVec3::ZERO,
        fixray_reference::DVec3::new(0.3, -0.2, 1.0),
    )
    .unwrap();
    let grey = |depth: u8| {
        let scene = hall_of_mirrors(depth);
        let twin: fixray_reference::DScene<2, 4> =
            fixray_reference::DScene::from_scene(&scene).unwrap();
        (scene.trace(&along).r, twin.trace(&dray).1.r)
    };
    // Up to depth 6 (52 rays) the whole tree is followed, as the reference follows it.
    for depth in 0..=6 {
        let (fixed, exact) = grey(depth);
        assert!(
            fixed.abs_diff(exact) <= 1,
            "depth {depth}: {fixed} against {exact}"
        );
    }
    // At depth 16 the tree would hold thousands of rays: past 64 they see the black sky, and
    // the pixel is darker than the full tree's.
    assert_eq!(Scene::<2>::MAX_RAYS, 64);
    let (fixed, exact) = grey(16);
    assert!(
        fixed + 2 < exact,
        "depth 16: {fixed} against the full tree's {exact}"
    );
}
