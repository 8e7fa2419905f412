//! The extremes of what fixray accepts, and beyond: `Vec3` holds any Q16.16 value, rays and
//! lights may sit at the corners of the overflow-safe range, materials may take every weight
//! at its limit, and display areas any `i32` corner and `u32` size. Every public function
//! they reach must return without a panic (this suite runs with overflow checks on) and, where
//! it means something, with a sane answer: a hit within [0, FAR], a colour, nothing drawn
//! outside the frame. What no constructor accepts it must refuse.

use core::convert::Infallible;

use embedded_graphics::image::ImageDrawable;
use embedded_graphics::pixelcolor::{BinaryColor, Rgb888};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use fixray::internals::{dot_wide, length_squared_wide};
use fixray::{
    Background, Camera, FAR, Framebuffer, Fx, LIMIT, Light, Material, Object, Plane, Ray, Rgb,
    Scene, Shape, Sphere, Vec3, Viewport, demo, render_row,
};

mod common;

// The shared xorshift64: varied values from a fixed seed, so a failure repeats.
use common::{ClampLimit, Source, XorShift};

/// The edges of Q16.16 and of the overflow budget.
const EDGES: [i32; 13] = [
    i32::MIN,
    i32::MIN + 1,
    -(1024 << 16),
    -(1 << 16),
    -1,
    0,
    1,
    1 << 15,
    1 << 16,
    (1 << 16) + 1,
    1024 << 16,
    i32::MAX - 1,
    i32::MAX,
];

/// Hostile values: the edges first, then raw bit patterns of every magnitude.
fn hostile(rng: &mut XorShift, i: usize) -> Fx {
    if let Some(&edge) = EDGES.get(i % (2 * EDGES.len())) {
        return Fx::from_bits(edge);
    }
    let seed = rng.bits();
    Fx::from_bits((seed as i32) >> (seed >> 59))
}

/// A hostile vector: the first `EDGES.len()³` cover every triple of edges, and then each
/// component is an edge or a random pattern, independently.
fn hostile_vec(rng: &mut XorShift, i: usize) -> Vec3 {
    let n = EDGES.len();
    if i < n * n * n {
        let edge = |k: usize| Fx::from_bits(EDGES[k % n]);
        return Vec3::new(edge(i), edge(i / n), edge(i / (n * n)));
    }
    let mut component = |k: usize| {
        let pick = rng.bits() as usize;
        hostile(
            rng,
            if pick.is_multiple_of(2) {
                pick / 2 % n
            } else {
                k + 2 * n
            },
        )
    };
    Vec3::new(component(i), component(i + 1), component(i + 2))
}

/// The corners of the overflow-safe range and its centre: where the exact dot products of a
/// ray's direction and the vector to a sphere's centre sum to the most.
fn corners() -> impl Iterator<Item = Vec3> {
    let c = [-LIMIT, Fx::ZERO, LIMIT];
    (0..27).map(move |i| Vec3::new(c[i % 3], c[i / 3 % 3], c[i / 9]))
}

/// A ray from `origin` along `dir` if `Ray::new` accepts them, after checking that it refuses
/// exactly what lies outside its range.
fn ray(origin: Vec3, dir: Vec3) -> Option<Ray> {
    let valid = origin == origin.clamp_limit() && dir != Vec3::ZERO;
    let ray = Ray::new(origin, dir);
    assert_eq!(ray.is_ok(), valid, "Ray::new({origin:?}, {dir:?})");
    ray.ok()
}

/// A scene with something of everything: a checkered ground, a mirror, a matte ball, a
/// gradient sky, two lights.
fn scene(background: Background) -> Scene<4, 2> {
    let light = Light::from_fx(Vec3::from_ints(-20, 20, 20), Fx::from_num(0.8)).unwrap();
    let mut scene: Scene<4, 2> = Scene::new(light, 0.2, background).unwrap();
    scene
        .add_light(Light::from_fx(Vec3::from_ints(10, 30, -5), Fx::from_num(1.5)).unwrap())
        .unwrap();
    let checker = Material::matte(Rgb::WHITE)
        .with_checker_fx(Fx::from_num(2), Rgb::BLACK)
        .unwrap();
    scene
        .add_plane(
            Plane::from_fx(Vec3::from_ints(0, -4, 0), Vec3::Y).unwrap(),
            checker,
        )
        .unwrap();
    let mirror = Material::from_fx(
        Rgb::new(200, 200, 255),
        Fx::from_num(0.2),
        Fx::from_num(4),
        1425,
        Fx::from_num(0.9),
    )
    .unwrap();
    scene
        .add_sphere(
            Sphere::from_fx(Vec3::from_ints(0, 0, -12), Fx::from_num(3)).unwrap(),
            mirror,
        )
        .unwrap();
    scene
        .add_sphere(
            Sphere::from_fx(Vec3::from_ints(5, -1, -9), Fx::from_num(2)).unwrap(),
            Rgb::new(255, 40, 40),
        )
        .unwrap();
    scene
}

fn gradient() -> Background {
    Background {
        top: Rgb::new(20, 40, 200),
        bottom: Rgb::new(250, 250, 250),
    }
}

fn assert_sane_hit(t: Fx, what: &str) {
    assert!(
        t >= Fx::ZERO && t <= FAR,
        "{what}: t = {t} outside [0, FAR]"
    );
}

// ---------------------------------------------------------------------------------------
// Vec3 at the ends of Q16.16.

#[test]
fn dot_of_the_largest_vectors_saturates() {
    let top = Vec3::new(Fx::MAX, Fx::MAX, Fx::MAX);
    let bottom = Vec3::new(Fx::MIN, Fx::MIN, Fx::MIN);
    assert_eq!(top.dot(top), Fx::MAX);
    assert_eq!(bottom.dot(bottom), Fx::MAX);
    assert_eq!(top.dot(bottom), Fx::MIN);
    assert_eq!(bottom.dot(top), Fx::MIN);
    assert_eq!(dot_wide(top, top), i64::MAX);
    assert_eq!(dot_wide(top, bottom), i64::MIN);
    // (MAX, MIN, 0)·(MAX, MAX, 0) = MAX·(MAX + MIN) = −MAX in raw units squared: the sum
    // of two products near ±2⁶² is small and exact, −½ + 2⁻³², which rounds to −½.
    let mixed = Vec3::new(Fx::MAX, Fx::MIN, Fx::ZERO);
    let other = Vec3::new(Fx::MAX, Fx::MAX, Fx::ZERO);
    assert_eq!(dot_wide(mixed, other), -(i32::MAX as i64));
    assert_eq!(mixed.dot(other), Fx::from_num(-0.5));
}

#[test]
fn vector_arithmetic_at_the_extremes_saturates() {
    let top = Vec3::new(Fx::MAX, Fx::MAX, Fx::MAX);
    let bottom = Vec3::new(Fx::MIN, Fx::MIN, Fx::MIN);
    assert_eq!(-bottom, top);
    assert_eq!(-top, Vec3::new(-Fx::MAX, -Fx::MAX, -Fx::MAX));
    assert_eq!(top + top, top);
    assert_eq!(bottom + bottom, bottom);
    assert_eq!(top - bottom, top);
    assert_eq!(bottom - top, bottom);
    assert_eq!(top.scale(Fx::MAX), top);
    assert_eq!(top.scale(Fx::MIN), bottom);
    assert_eq!(bottom.scale(Fx::MIN), top);
    let c = top.cross(Vec3::new(Fx::MIN, Fx::MAX, Fx::MIN));
    assert_eq!(c.x, Fx::MIN); // MAX·MIN − MAX·MAX, about −2¹⁵ · 2¹⁶
    assert_eq!(c.y, Fx::ZERO); // MAX·MIN − MAX·MIN
    assert_eq!(c.z, Fx::MAX); // MAX·MAX − MAX·MIN
    assert_eq!(top.length(), Fx::MAX);
    assert_eq!(bottom.length(), Fx::MAX);
    let n = bottom.try_normalize().unwrap();
    let third = -Fx::from_num(0.577_350_3);
    for c in [n.x, n.y, n.z] {
        assert!((c - third).abs() <= Fx::from_bits(1), "{n:?}");
    }
}

#[test]
fn vec3_operations_on_hostile_values_return() {
    let mut rng = XorShift(0x0dd_ba11_cafe_f00d);
    for i in 0..20_000 {
        let (a, b) = (hostile_vec(&mut rng, i), hostile_vec(&mut rng, i + 7));
        let k = hostile(&mut rng, i + 3);
        let _ = (
            a.dot(b),
            dot_wide(a, b),
            a.cross(b),
            a.scale(k),
            a + b,
            a - b,
            -a,
        );
        assert!(a.length() >= Fx::ZERO);
        if let Some(n) = a.try_normalize() {
            let l2 = length_squared_wide(n) as f64 / 2f64.powi(32);
            assert!((l2 - 1.0).abs() < 1e-3, "{a:?} → {n:?}");
        }
    }
}

// ---------------------------------------------------------------------------------------
// Drawing at the ends of the display coordinates.

/// A target as large as embedded-graphics allows that only counts what it is given.
struct Counter {
    pixels: usize,
    outside: usize,
}

impl Dimensions for Counter {
    fn bounding_box(&self) -> Rectangle {
        Rectangle::new(Point::zero(), Size::new(64, 64))
    }
}

impl DrawTarget for Counter {
    type Color = Rgb888;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb888>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Infallible> {
        for Pixel(p, _) in pixels {
            if self.bounding_box().contains(p) {
                self.pixels += 1;
            } else {
                self.outside += 1;
            }
        }
        Ok(())
    }
}

fn counter() -> Counter {
    Counter {
        pixels: 0,
        outside: 0,
    }
}

#[test]
fn sub_images_at_the_ends_of_i32_draw_nothing_and_do_not_overflow() {
    let frame = Framebuffer::<8, 6>::new();
    let corners = [
        Point::new(i32::MAX, i32::MAX),
        Point::new(i32::MAX, 0),
        Point::new(0, i32::MAX),
        Point::new(i32::MAX - 1, i32::MAX - 1),
        Point::new(i32::MIN, i32::MIN),
        Point::new(i32::MIN, 0),
        Point::new(0, i32::MIN),
        Point::new(-1, -1),
        Point::new(8, 0),
        Point::new(0, 6),
    ];
    let sizes = [
        Size::new(1, 1),
        Size::new(u32::MAX, u32::MAX),
        Size::new(u32::MAX, 1),
        Size::new(1, u32::MAX),
        Size::new(i32::MAX as u32, i32::MAX as u32),
        Size::new(i32::MAX as u32 + 1, 1),
        Size::new(8, 6),
    ];
    for &top_left in &corners {
        for &size in &sizes {
            let mut target = counter();
            frame
                .draw_sub_image(&mut target, &Rectangle::new(top_left, size))
                .unwrap();
            assert_eq!(target.pixels + target.outside, 0, "{top_left:?} {size:?}");
        }
    }
    // From a corner inside the frame, sizes that reach past it, up to u32::MAX.
    for &size in &sizes[1..6] {
        for top_left in [Point::zero(), Point::new(7, 5)] {
            let mut target = counter();
            frame
                .draw_sub_image(&mut target, &Rectangle::new(top_left, size))
                .unwrap();
            assert_eq!(target.pixels + target.outside, 0, "{top_left:?} {size:?}");
        }
    }
    // What fits is drawn, at the target's origin.
    for (top_left, size, n) in [
        (Point::new(7, 5), Size::new(1, 1), 1),
        (Point::zero(), Size::new(8, 6), 48),
        (Point::new(2, 1), Size::new(6, 5), 30),
        (Point::new(3, 3), Size::new(0, 2), 0),
    ] {
        let mut target = counter();
        frame
            .draw_sub_image(&mut target, &Rectangle::new(top_left, size))
            .unwrap();
        assert_eq!(
            (target.pixels, target.outside),
            (n, 0),
            "{top_left:?} {size:?}"
        );
    }
}

/// A one-bit display that accepts any point and counts the ones on it.
struct AnyPoint {
    inside: usize,
}

impl Dimensions for AnyPoint {
    fn bounding_box(&self) -> Rectangle {
        Rectangle::new(Point::zero(), Size::new(16, 16))
    }
}

impl DrawTarget for AnyPoint {
    type Color = BinaryColor;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Infallible> {
        for Pixel(p, _) in pixels {
            self.inside += self.bounding_box().contains(p) as usize;
        }
        Ok(())
    }
}

#[test]
fn frames_placed_at_the_ends_of_i32_do_not_overflow() {
    let frame = Framebuffer::<8, 6>::new();
    for top_left in [
        Point::new(i32::MAX, i32::MAX),
        Point::new(i32::MAX - 7, i32::MAX - 5),
        Point::new(i32::MAX - 8, i32::MAX - 6),
        Point::new(i32::MIN, i32::MIN),
        Point::new(i32::MIN, i32::MAX - 6),
        Point::new(-4, -3),
    ] {
        let mut display = AnyPoint { inside: 0 };
        frame.draw_at(top_left, &mut display).unwrap();
        let expected = if top_left == Point::new(-4, -3) {
            4 * 3
        } else {
            0
        };
        assert_eq!(display.inside, expected, "{top_left:?}");
    }
    // The whole frame as an image.
    let mut target = counter();
    frame.draw(&mut target).unwrap();
    assert_eq!((target.pixels, target.outside), (48, 0));
}

#[test]
fn viewports_at_the_ends_of_i32_are_drawn_without_overflow() {
    let (scene, camera) = (demo::scene(), demo::camera(8, 6).unwrap());
    // Corners whose far corner passes i32::MAX, or lies just short of it, and the far negative
    // end: nothing shows on a 16 × 16 display and no sum overflows. The last corner shows a
    // 4 × 3 part of the picture, so the display does count what lands on it.
    for top_left in [
        Point::new(i32::MAX, i32::MAX),
        Point::new(i32::MAX - 7, 0),
        Point::new(0, i32::MAX - 5),
        Point::new(i32::MAX - 8, i32::MAX - 6),
        Point::new(i32::MIN, i32::MIN),
        Point::new(i32::MIN, i32::MAX - 6),
        Point::new(-4, -3),
    ] {
        let view = Viewport::at(&scene, &camera, top_left);
        let mut display = AnyPoint { inside: 0 };
        let mut band = [Rgb::BLACK; 8 * 2];
        for rows in view.bands(2) {
            view.render_rows(rows, &mut band, &mut display).unwrap();
        }
        let expected = if top_left == Point::new(-4, -3) {
            4 * 3
        } else {
            0
        };
        assert_eq!(display.inside, expected, "{top_left:?}");
    }
}

// ---------------------------------------------------------------------------------------
// Hand-built rays, hits, materials, lights and checkers.

#[test]
fn the_reproducers_return() {
    // The largest directions normalise to the unit ones.
    let up = ray(Vec3::ZERO, Vec3::new(Fx::ZERO, Fx::MAX, Fx::ZERO)).unwrap();
    let sky = scene(gradient());
    assert_eq!(up.dir(), Vec3::Y);
    assert_eq!(
        sky.trace(&up),
        sky.trace(&Ray::new(Vec3::ZERO, Vec3::Y).unwrap())
    );
    for dir in [
        Vec3::new(Fx::MAX, Fx::MAX, Fx::MAX),
        Vec3::new(Fx::MIN, Fx::MIN, Fx::MIN),
    ] {
        let ray0 = ray(Vec3::ZERO, dir).unwrap();
        for s in [scene(gradient()), scene(Rgb::BLACK.into())] {
            if let Some(hit) = s.shoot(&ray0) {
                assert_sane_hit(hit.hit().t(), "huge direction");
            }
            let _ = s.trace(&ray0);
        }
        let ball = Sphere::from_fx(Vec3::from_ints(0, 0, -10), Fx::from_num(2)).unwrap();
        // From the far corners every product of the exact dot product is near its largest.
        for origin in [
            Vec3::ZERO,
            Vec3::new(-LIMIT, -LIMIT, -LIMIT),
            Vec3::new(LIMIT, LIMIT, LIMIT),
        ] {
            let ray = ray(origin, dir).unwrap();
            if let Some(hit) = ball.intersect(&ray) {
                assert_sane_hit(hit.t(), "ball");
            }
            let _ = scene(gradient()).trace(&ray);
        }
        // Beyond them, Ray::new refuses.
        assert!(ray(Vec3::new(Fx::MIN, Fx::MIN, Fx::MIN), dir).is_none());
    }
}

#[test]
fn shooting_and_tracing_extreme_rays_returns_sane_hits() {
    let mut rng = XorShift(0x5eed_0f4a_75ee_d001);
    let scenes = [scene(gradient()), scene(Rgb::new(10, 20, 30).into())];
    let ball = Sphere::from_fx(Vec3::from_ints(0, 0, -10), Fx::from_num(2)).unwrap();
    let wall = Plane::from_fx(Vec3::from_ints(0, 0, -20), Vec3::from_ints(1, 0, 1)).unwrap();
    let corner_rays = corners().flat_map(|origin| corners().map(move |dir| (origin, dir)));
    let hostile_rays = (0..4_000).map(|i| {
        let origin = if i % 3 == 0 {
            Vec3::ZERO
        } else {
            hostile_vec(&mut XorShift(i as u64 + 1), i + 7)
        };
        // Half the origins as drawn (often refused), half moved into range.
        let origin = if i % 2 == 0 {
            origin
        } else {
            origin.clamp_limit()
        };
        (
            origin,
            hostile_vec(&mut XorShift(i as u64 + 99), (i * 7) % 4_000),
        )
    });
    for (i, (origin, dir)) in corner_rays.chain(hostile_rays).enumerate() {
        let Some(ray) = ray(origin, dir) else {
            continue;
        };
        let _ = ray.at(hostile(&mut rng, i));
        for shape in [Shape::Sphere(ball), Shape::Plane(wall)] {
            if let Some(hit) = shape.intersect(&ray) {
                assert_sane_hit(hit.t(), "shape");
            }
        }
        let s = &scenes[i % 2];
        if let Some(hit) = s.shoot(&ray) {
            assert_sane_hit(hit.hit().t(), "scene");
            assert!(hit.object() < s.objects().len());
            let _ = s.shade(&ray, Some(&hit));
        }
        let _ = s.shoot_among(&ray, rng.bits());
        let _ = s.trace(&ray);
        let _ = s.shade(&ray, None);
    }
}

/// A material from hostile weights: each drawn weight is an edge or a random pattern, and
/// the constructor must refuse it exactly when it lies outside its range; a refused one is
/// replaced by the nearest limit, so that the scene gets materials at their extremes.
fn extreme_material(rng: &mut XorShift, i: usize) -> Material {
    let mut weight = |k: usize, max: i32| {
        let w = hostile(rng, i + k);
        w.clamp(Fx::ZERO, Fx::from_num(max))
    };
    let (diffuse, specular, reflect) = (weight(0, 2), weight(1, 16), weight(2, 1));
    let shininess = [0, 1, 2, 4096, u16::MAX, rng.bits() as u16][i % 6];
    let refused = Material::from_fx(Rgb::WHITE, diffuse, specular, shininess, reflect);
    assert_eq!(
        refused.is_ok(),
        (1..=4096).contains(&shininess),
        "shininess {shininess}"
    );
    let colour = Rgb::new(rng.bits() as u8, rng.bits() as u8, rng.bits() as u8);
    let material =
        Material::from_fx(colour, diffuse, specular, shininess.clamp(1, 4096), reflect).unwrap();
    if i.is_multiple_of(3) {
        return material;
    }
    let size = hostile(rng, i + 3);
    let checkered = material.with_checker_fx(size, Rgb::new(rng.bits() as u8, 0, 255));
    assert_eq!(
        checkered.is_ok(),
        size > Fx::ZERO && size <= LIMIT,
        "checker size {size}"
    );
    checkered.unwrap_or_else(|_| {
        material
            .with_checker_fx(size.clamp(Fx::DELTA, LIMIT), Rgb::BLACK)
            .unwrap()
    })
}

/// A light at a corner of the range or a hostile point moved into it, of an extreme intensity.
fn extreme_light(rng: &mut XorShift, i: usize) -> Light {
    let position = hostile_vec(rng, i);
    let intensity = hostile(rng, i + 4);
    let light = Light::from_fx(position, intensity);
    let valid =
        position == position.clamp_limit() && intensity >= Fx::ZERO && intensity <= Fx::from_num(4);
    assert_eq!(light.is_ok(), valid, "light at {position:?} of {intensity}");
    light.unwrap_or_else(|_| {
        Light::from_fx(
            position.clamp_limit(),
            intensity.clamp(Fx::ZERO, Fx::from_num(4)),
        )
        .unwrap()
    })
}

#[test]
fn extreme_materials_lights_and_checkers_render_and_trace() {
    let mut rng = XorShift(0xfeed_beef_dead_c0de);
    let camera = Camera::look_at([0.0, 1.0, 4.0], [0.0, -1.0, -12.0])
        .fov_degrees(70.0)
        .size(Size::new(12, 9))
        .build()
        .unwrap();
    let mut row = [Rgb::BLACK; 12];
    for i in 0..120 {
        let background = if i % 2 == 0 {
            gradient()
        } else {
            Background::plain(Rgb::new(1, 2, 3))
        };
        let mut s = Scene::<5, 3>::new(extreme_light(&mut rng, i), 0.3, background).unwrap();
        s.add_light(extreme_light(&mut rng, i + 1)).unwrap();
        s.add_plane(
            Plane::from_fx(Vec3::from_ints(0, -4, 0), Vec3::Y).unwrap(),
            extreme_material(&mut rng, i),
        )
        .unwrap();
        s.add(Object {
            shape: Shape::Sphere(
                Sphere::from_fx(Vec3::from_ints(0, 0, -12), Fx::from_num(3)).unwrap(),
            ),
            material: extreme_material(&mut rng, i + 1),
        })
        .unwrap();
        s.add_sphere(
            Sphere::from_fx(Vec3::from_ints(4, -1, -8), Fx::ONE).unwrap(),
            extreme_material(&mut rng, i + 2),
        )
        .unwrap();
        s.add_plane(
            Plane::from_fx(Vec3::from_ints(0, 0, -40), Vec3::Z).unwrap(),
            extreme_material(&mut rng, i + 3),
        )
        .unwrap();
        s.set_shadows(i % 4 != 1);
        s.set_depth((i % 6) as u8);
        for r in 0..camera.height() {
            render_row(&s, &camera, r, &mut row).unwrap();
            // render_row is trace, pixel by pixel, whatever the materials hold.
            for (col, &pixel) in row.iter().enumerate() {
                assert_eq!(
                    pixel,
                    s.trace(&camera.ray(col as u32, r)),
                    "row {r} col {col}"
                );
            }
        }
    }
}

#[test]
fn checkers_of_any_size_give_one_of_their_two_colours() {
    let mut rng = XorShift(0xc4ec_6e75_0000_0001);
    let (even, odd) = (Rgb::new(1, 1, 1), Rgb::new(2, 2, 2));
    for i in 0..20_000 {
        let size = hostile(&mut rng, i);
        let Ok(material) = Material::matte(even).with_checker_fx(size, odd) else {
            assert!(size <= Fx::ZERO || size > LIMIT, "size {size} refused");
            continue;
        };
        let checker = material.checker().unwrap();
        let uv = [hostile(&mut rng, i + 1), hostile(&mut rng, i + 2)];
        let c = checker.colour_at(even, uv);
        assert!(c == even || c == odd);
    }
    // The documented limits still tile.
    for size in [Fx::DELTA, LIMIT] {
        let big = Material::matte(even)
            .with_checker_fx(size, odd)
            .unwrap()
            .checker()
            .unwrap();
        assert_eq!(big.colour_at(even, [Fx::ZERO, Fx::ZERO]), even);
        assert_eq!(big.colour_at(even, [-Fx::from_bits(1), Fx::ZERO]), odd);
    }
}
