//! The scenes shared by the examples, the tests and the firmware (feature `demo`).
//!
//! - [`scene`]: four matte spheres over a ground plane, lit from the upper left behind the
//!   viewer, seen by the chapter's pinhole camera ([`camera`]) from the origin down −z with a
//!   60° vertical field of view.
//! - [`classic`]: the same four spheres as ivory, glass, red rubber and a mirror, three lights,
//!   and a checkerboard floor — the geometry of ssloy's tinyraytracer — seen by the look-at
//!   camera ([`classic_camera`]).

use embedded_graphics::geometry::Size;

use crate::error::{CameraProblem, Error};
use crate::geometry::plane::Plane;
use crate::geometry::sphere::Sphere;
use crate::numbers::fx::Fx;
use crate::numbers::vec3::Vec3;
use crate::render::camera::Camera;
use crate::scene::Scene;
use crate::scene::background::Background;
use crate::scene::colour::Rgb;
use crate::scene::light::Light;
use crate::scene::material::Material;

/// Sky blue, where rays miss.
pub const BACKGROUND: Rgb = Rgb::new(51, 178, 204);

/// The demo scene: ground plane y = −4 facing up; spheres at (−3, 0, −16) r 2,
/// (−1, −1.5, −12) r 2, (1.5, −0.5, −18) r 3 and (7, 5, −18) r 4; a point light at
/// (−20, 20, 20) of intensity 0.8 and ambient 0.2.
#[must_use]
pub fn scene() -> Scene<8> {
    let fx = Fx::from_num::<f32>;
    let light = Light::new_unchecked(Vec3::from_ints(-20, 20, 20), fx(0.8));
    let mut scene = match Scene::new(light, fx(0.2), BACKGROUND) {
        Ok(s) => s,
        Err(_) => unreachable!("0.2 is a valid ambient term"),
    };
    let spheres = [
        (Vec3::from_ints(-3, 0, -16), 2.0, Rgb::new(230, 220, 180)), // ivory
        (
            Vec3::new(fx(-1.0), fx(-1.5), fx(-12.0)),
            2.0,
            Rgb::new(90, 140, 230),
        ), // blue
        (
            Vec3::new(fx(1.5), fx(-0.5), fx(-18.0)),
            3.0,
            Rgb::new(200, 50, 40),
        ), // red
        (Vec3::from_ints(7, 5, -18), 4.0, Rgb::new(210, 210, 215)),  // silver
    ];
    let ground = Plane::new_unchecked(Vec3::from_ints(0, -4, 0), Vec3::Y);
    // Eight slots, five objects: these pushes cannot fail.
    let _ = scene.add_plane(ground, Rgb::new(120, 150, 90));
    for (centre, radius, colour) in spheres {
        let _ = scene.add_sphere(Sphere::new_unchecked(centre, fx(radius)), colour);
    }
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
/// fixray does not refract, so the glass sphere is a faint mirror with a sharp highlight and
/// a little diffuse light in place of tinyraytracer's transparency.
#[must_use]
pub fn classic() -> Scene<8> {
    let fx = Fx::from_num::<f32>;
    let sky = Background {
        top: Rgb::new(20, 90, 170),
        bottom: Rgb::new(51, 178, 204),
    };
    let lights = [
        Light::new_unchecked(Vec3::from_ints(-20, 20, 20), fx(1.5)),
        Light::new_unchecked(Vec3::from_ints(30, 50, -25), fx(1.8)),
        Light::new_unchecked(Vec3::from_ints(30, 20, 30), fx(1.7)),
    ];
    let mut scene = match Scene::new(lights[0], Fx::ZERO, sky) {
        Ok(s) => s,
        Err(_) => unreachable!("zero is a valid ambient term"),
    };
    // Three lights in a scene of capacity four, five objects in eight: these cannot fail.
    let _ = scene.add_light(lights[1]);
    let _ = scene.add_light(lights[2]);
    let material = |colour, diffuse, specular, shininess, reflect| Material {
        colour,
        diffuse: fx(diffuse),
        specular: fx(specular),
        shininess,
        reflect: fx(reflect),
        checker: None,
    };
    let ivory = material(Rgb::new(102, 102, 77), 0.6, 0.3, 50, 0.1);
    let glass = material(Rgb::new(153, 179, 204), 0.1, 0.5, 125, 0.3);
    let rubber = material(Rgb::new(77, 26, 26), 0.9, 0.1, 10, 0.0);
    let mirror = material(Rgb::WHITE, 0.0, 10.0, 1425, 0.8);
    let floor_material = Material {
        checker: Some(crate::scene::material::Checker {
            size: fx(2.0),
            other: Rgb::new(77, 51, 26),
        }),
        ..Material::matte(Rgb::new(77, 77, 77))
    };
    let floor = Plane::new_unchecked(Vec3::from_ints(0, -4, 0), Vec3::Y)
        .bounded([fx(-10.0), fx(-30.0)], [fx(10.0), fx(-10.0)]);
    if let Ok(floor) = floor {
        let _ = scene.add_plane(floor, floor_material);
    }
    let spheres = [
        (Vec3::from_ints(-3, 0, -16), 2.0, ivory),
        (Vec3::new(fx(-1.0), fx(-1.5), fx(-12.0)), 2.0, glass),
        (Vec3::new(fx(1.5), fx(-0.5), fx(-18.0)), 3.0, rubber),
        (Vec3::from_ints(7, 5, -18), 4.0, mirror),
    ];
    for (centre, radius, m) in spheres {
        let _ = scene.add_sphere(Sphere::new_unchecked(centre, fx(radius)), m);
    }
    scene
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
