//! The scenes shared by the examples, the tests and the firmware (feature `demo`).
//!
//! - [`scene`]: four matte spheres over a ground plane, lit from the upper left behind the
//!   viewer, seen by the chapter's pinhole camera ([`camera`]) from the origin down −z with a
//!   60° vertical field of view.
//! - [`classic`]: the same four spheres as ivory, glass, red rubber and a mirror, three lights,
//!   and a checkerboard floor — the geometry of ssloy's tinyraytracer — seen by the look-at
//!   camera ([`classic_camera`]). It and its variants need the `mirrors-and-glass` feature (on
//!   by default).

use embedded_graphics::geometry::Size;

use crate::check::valid;
use crate::error::{CameraProblem, Error};
use crate::geometry::plane::Plane;
use crate::geometry::shape::Shape;
use crate::geometry::sphere::Sphere;
use crate::numbers::fx::Fx;
use crate::numbers::vec3::Vec3;
use crate::render::camera::Camera;
use crate::scene::background::Background;
use crate::scene::colour::Rgb;
use crate::scene::light::Light;
use crate::scene::material::Material;
use crate::scene::{Object, Scene};

/// Sky blue, where rays miss.
pub const BACKGROUND: Rgb = Rgb::new(51, 178, 204);

/// `tenths / 10` in Q16.16, rounded to nearest: the scenes' decimal values, in a `const`.
const fn tenths(tenths: i32) -> Fx {
    let scaled = tenths as i64 * 65_536;
    Fx::from_bits(((scaled + scaled.signum() * 5) / 10) as i32)
}

/// A point from coordinates in tenths.
const fn point(x: i32, y: i32, z: i32) -> Vec3 {
    Vec3::new(tenths(x), tenths(y), tenths(z))
}

/// The sphere centres and radii both scenes share, in tenths: tinyraytracer's four.
const SPHERES: [(Vec3, i32); 4] = [
    (point(-30, 0, -160), 20),
    (point(-10, -15, -120), 20),
    (point(15, -5, -180), 30),
    (point(70, 50, -180), 40),
];

/// The ground both scenes stand on: y = −4, facing up.
const GROUND: Plane = valid(Plane::from_fx(Vec3::from_ints(0, -4, 0), Vec3::Y));

/// A scene of capacity `N` with `light` and its objects added, each checked by the compiler.
const fn scene_with<const N: usize>(
    light: Light,
    ambient: Fx,
    background: Background,
    objects: &[Object],
) -> Scene<N> {
    let mut scene = match Scene::from_fx(light, ambient, background) {
        Ok(scene) => scene,
        Err(_) => panic!("the demo scenes' values are in range"),
    };
    let mut i = 0;
    while i < objects.len() {
        valid(scene.add(objects[i]));
        i += 1;
    }
    scene
}

/// A sphere of [`SPHERES`] made of `material`.
const fn sphere(index: usize, material: Material) -> Object {
    let (centre, radius) = SPHERES[index];
    Object::new(
        Shape::Sphere(valid(Sphere::from_fx(centre, tenths(radius)))),
        material,
    )
}

/// The demo scene: ground plane y = −4 facing up; spheres at (−3, 0, −16) r 2,
/// (−1, −1.5, −12) r 2, (1.5, −0.5, −18) r 3 and (7, 5, −18) r 4; a point light at
/// (−20, 20, 20) of intensity 0.8 and ambient 0.2. Built at compile time, so it can be a
/// `static`.
#[must_use]
pub const fn scene() -> Scene<8> {
    // Built once by the compiler: at run time a call is a copy, with no set-up on the stack.
    const SCENE: Scene<8> = demo_scene();
    SCENE
}

/// [`scene`], built.
const fn demo_scene() -> Scene<8> {
    const fn matte(r: u8, g: u8, b: u8) -> Material {
        Material::matte(Rgb::new(r, g, b))
    }
    scene_with(
        valid(Light::from_fx(Vec3::from_ints(-20, 20, 20), tenths(8))),
        tenths(2),
        Background::plain(BACKGROUND),
        &[
            Object::new(Shape::Plane(GROUND), matte(120, 150, 90)),
            sphere(0, matte(230, 220, 180)), // ivory
            sphere(1, matte(90, 140, 230)),  // blue
            sphere(2, matte(200, 50, 40)),   // red
            sphere(3, matte(210, 210, 215)), // silver
        ],
    )
}

/// How many frames [`rolling`] has: the ball crosses the floor in this many steps.
pub const ROLLING_FRAMES: u32 = 16;

/// Frame `frame` of the demo scene's animation: a yellow ball of radius 1 rolls across the
/// floor in front of the blue sphere, from x = −4 at frame 0 half a unit a frame (x = 3.5 at
/// frame 15), resting on the ground at z = −9. Frames past the last show the last.
///
/// The ball is added after the demo's five objects, as object 5.
///
/// ```
/// use fixray::demo;
/// let (first, last) = (demo::rolling(0), demo::rolling(demo::ROLLING_FRAMES - 1));
/// assert_eq!(first.objects().len(), demo::scene().objects().len() + 1);
/// assert_ne!(first.objects()[5], last.objects()[5]);
/// ```
#[must_use]
pub const fn rolling(frame: u32) -> Scene<8> {
    let step = if frame < ROLLING_FRAMES {
        frame as i32
    } else {
        ROLLING_FRAMES as i32 - 1
    };
    let ball = valid(Sphere::from_fx(point(-40 + 5 * step, -30, -90), Fx::ONE));
    let mut scene = scene();
    valid(scene.add(Object::new(
        Shape::Sphere(ball),
        Material::matte(Rgb::new(240, 200, 60)),
    )));
    scene
}

/// Screen height of the demo camera (world units), 2 units at distance √3: 60° vertically.
pub const SCREEN_HEIGHT: f32 = 2.0;
/// Screen distance of the demo camera: √3.
pub const SCREEN_DISTANCE: f32 = 1.732_050_8;

/// The demo camera, `width × height` pixels: the chapter's pinhole camera with square
/// pixels, a screen `2 · width / height` wide and [`SCREEN_HEIGHT`] high at
/// [`SCREEN_DISTANCE`].
pub fn camera(width: u32, height: u32) -> Result<Camera, Error> {
    if height == 0 {
        return Err(Error::DegenerateCamera(CameraProblem::NoPixels));
    }
    let screen_w = SCREEN_HEIGHT * width as f32 / height as f32;
    Camera::pinhole(screen_w, SCREEN_HEIGHT, SCREEN_DISTANCE)
        .size(Size::new(width, height))
        .build()
}

/// The classic scene: tinyraytracer's spheres at (−3, 0, −16) r 2 (ivory), (−1, −1.5, −12) r 2
/// (glass), (1.5, −0.5, −18) r 3 (red rubber) and (7, 5, −18) r 4 (mirror); lights at
/// (−20, 20, 20), (30, 50, −25) and (30, 20, 30) of intensity 1.5, 1.8 and 1.7; a checkerboard
/// floor of 2-unit squares at y = −4 for |x| < 10 and −30 < z < −10; a sky gradient.
///
/// The glass is tinyraytracer's: refractive index 1.5, 0.8 of the refracted light, 0.1 of the
/// mirror image, a highlight of 0.5 with shininess 125 and no diffuse term (no Fresnel
/// weighting, as there). [`classic_opaque`] is the same scene with the glass's refraction
/// left out, to show what refraction costs.
#[cfg(feature = "mirrors-and-glass")]
#[must_use]
pub const fn classic() -> Scene<8> {
    // Built once by the compiler, as [`scene`] is.
    const CLASSIC: Scene<8> = classic_scene(true, true);
    CLASSIC
}

/// [`classic`], built; with `refracts` false, [`classic_opaque`]; with `mirrors` false,
/// [`classic_without_mirrors`].
#[cfg(feature = "mirrors-and-glass")]
const fn classic_scene(refracts: bool, mirrors: bool) -> Scene<8> {
    const fn material(
        colour: Rgb,
        diffuse: i32,
        specular: i32,
        shininess: u16,
        reflect: i32,
    ) -> Material {
        valid(Material::from_fx(
            colour,
            tenths(diffuse),
            tenths(specular),
            shininess,
            tenths(reflect),
        ))
    }
    // Every reflection times 0 or 1.
    let m = mirrors as i32;
    const fn light(x: i16, y: i16, z: i16, intensity: i32) -> Light {
        valid(Light::from_fx(Vec3::from_ints(x, y, z), tenths(intensity)))
    }
    let floor = valid(GROUND.bounded_fx(
        [Fx::const_from_int(-10), Fx::const_from_int(-30)],
        [Fx::const_from_int(10), Fx::const_from_int(-10)],
    ));
    let floor_material = valid(
        Material::matte(Rgb::new(77, 77, 77))
            .with_checker_fx(Fx::const_from_int(2), Rgb::new(77, 51, 26)),
    );
    let opaque = material(Rgb::new(153, 179, 204), 0, 5, 125, m);
    let glass = if refracts {
        valid(opaque.with_refraction_fx(Fx::from_bits(3 << 15), tenths(8)))
    } else {
        opaque
    };
    let sky = Background {
        top: Rgb::new(20, 90, 170),
        bottom: Rgb::new(51, 178, 204),
    };
    let mut scene = scene_with(
        light(-20, 20, 20, 15),
        Fx::ZERO,
        sky,
        &[
            Object::new(Shape::Plane(floor), floor_material),
            sphere(0, material(Rgb::new(102, 102, 77), 6, 3, 50, m)), // ivory
            sphere(1, glass),                                         // glass
            sphere(2, material(Rgb::new(77, 26, 26), 9, 1, 10, 0)),   // red rubber
            sphere(3, material(Rgb::WHITE, 0, 100, 1425, 8 * m)),     // mirror
        ],
    );
    valid(scene.add_light(light(30, 50, -25, 18)));
    valid(scene.add_light(light(30, 20, 30, 17)));
    scene
}

/// [`classic`] with its glass opaque: the same material without refraction.
#[cfg(feature = "mirrors-and-glass")]
#[must_use]
pub const fn classic_opaque() -> Scene<8> {
    const OPAQUE: Scene<8> = classic_scene(false, true);
    OPAQUE
}

/// [`classic`] with no mirror: every material's reflection 0, all else (the glass's refraction
/// too) kept, to show what mirrors cost.
#[cfg(feature = "mirrors-and-glass")]
#[must_use]
pub const fn classic_without_mirrors() -> Scene<8> {
    const WITHOUT_MIRRORS: Scene<8> = classic_scene(true, false);
    WITHOUT_MIRRORS
}

/// Vertical field of view of the classic camera, as in tinyraytracer.
pub const CLASSIC_FOV_DEGREES: f32 = 60.0;

/// The classic camera, `width × height` pixels: the look-at camera at the origin, looking
/// down −z, with a [`CLASSIC_FOV_DEGREES`] vertical field of view.
pub fn classic_camera(width: u32, height: u32) -> Result<Camera, Error> {
    Camera::look_at([0.0, 0.0, 0.0], [0.0, 0.0, -1.0])
        .fov_degrees(CLASSIC_FOV_DEGREES)
        .size(Size::new(width, height))
        .build()
}
