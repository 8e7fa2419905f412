//! The demo scene shared by the examples, the tests and the firmware.
//!
//! Four spheres over a ground plane, lit from the upper left behind the viewer, seen by the
//! chapter's pinhole camera from the origin down −z with a 60° vertical field of view.

use crate::camera::Camera;
use crate::color::Rgb;
use crate::error::Error;
use crate::fx::Fx;
use crate::light::Light;
use crate::plane::Plane;
use crate::scene::Scene;
use crate::sphere::Sphere;
use crate::vec3::Vec3;

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

/// The demo camera at `cols × rows`: the chapter's pinhole camera with square pixels, a
/// screen `2 · cols / rows` wide and [`SCREEN_HEIGHT`] high at [`SCREEN_DISTANCE`].
pub fn camera(cols: u16, rows: u16) -> Result<Camera, Error> {
    if rows == 0 {
        return Err(Error::DegenerateCamera {
            why: "the screen has no pixels",
        });
    }
    let width = SCREEN_HEIGHT * cols as f32 / rows as f32;
    Camera::pinhole(width, SCREEN_HEIGHT, SCREEN_DISTANCE, rows, cols)
}
