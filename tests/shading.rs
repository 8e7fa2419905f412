//! Shading, checked against expectations derived from the geometry of each set-up: shadows,
//! mirrors, highlights, checkerboards and supersampling.

use fixray::Size;
use fixray::{
    Background, Camera, Fx, Light, Material, Plane, Ray, Rgb, Scene, Sphere, Vec3, render_row,
    render_row_supersampled,
};
use fixray_reference::ToF64;

fn fx(x: f64) -> Fx {
    Fx::from_num(x)
}

fn v(x: f64, y: f64, z: f64) -> Vec3 {
    Vec3::new(fx(x), fx(y), fx(z))
}

fn ray(origin: Vec3, towards: Vec3) -> Ray {
    Ray::new(origin, towards - origin).unwrap()
}

const GREY: Rgb = Rgb::new(200, 200, 200);
const SKY: Rgb = Rgb::new(10, 20, 30);

/// A floor at y = 0 lit straight from above, with a ball hanging between it and the light.
fn shadow_scene() -> Scene<2> {
    let light = Light::from_fx(v(0.0, 100.0, 0.0), Fx::ONE).unwrap();
    let mut scene = Scene::new(light, 0.25, SKY).unwrap();
    scene
        .add_plane(Plane::from_fx(Vec3::ZERO, Vec3::Y).unwrap(), GREY)
        .unwrap();
    scene
        .add_sphere(Sphere::from_fx(v(0.0, 5.0, 0.0), fx(1.0)).unwrap(), GREY)
        .unwrap();
    scene
}

#[test]
fn a_point_in_a_sphere_shadow_gets_only_ambient_light() {
    let scene = shadow_scene();
    let eye = v(0.0, 20.0, 30.0);
    // Straight below the ball the light is blocked: 0.25 · 200 = 50.
    let shaded = scene.trace(&ray(eye, v(0.0, 0.0, 0.0)));
    assert_eq!(shaded, Rgb::new(50, 50, 50));
    // Three units aside, outside the shadow's unit radius, the floor is lit: n·l ≈ 1.
    let lit = scene.trace(&ray(eye, v(3.0, 0.0, 0.0)));
    assert!(lit.r >= 198, "{lit:?}");
    // With shadows off the same point is lit too.
    let mut no_shadows = shadow_scene();
    no_shadows.set_shadows(false);
    assert!(no_shadows.trace(&ray(eye, v(0.0, 0.0, 0.0))).r >= 198);
}

#[test]
fn the_shadow_edge_lies_where_the_geometry_puts_it() {
    // The light is 100 up and the ball's radius is 1 at height 5: the shadow's radius on the
    // floor is 1 · 100 / 95 ≈ 1.0526 (to first order; the exact cone differs by < 0.001).
    let scene = shadow_scene();
    let eye = v(0.0, 20.0, 30.0);
    assert_eq!(
        scene.trace(&ray(eye, v(1.03, 0.0, 0.0))).r,
        50,
        "inside the shadow"
    );
    assert!(
        scene.trace(&ray(eye, v(1.08, 0.0, 0.0))).r > 150,
        "outside the shadow"
    );
}

/// A checkerboard floor of unit squares, two dark colours that differ in each channel.
fn checker_floor() -> Material {
    Material::matte(Rgb::new(100, 100, 100))
        .with_checker_fx(fx(1.0), Rgb::new(40, 80, 120))
        .unwrap()
}

#[test]
fn checker_squares_alternate_at_the_expected_coordinates() {
    let light = Light::from_fx(v(0.0, 100.0, 0.0), Fx::ONE).unwrap();
    let mut scene: Scene<1> = Scene::new(light, 0.0, SKY).unwrap();
    scene
        .add_plane(
            Plane::from_fx(Vec3::ZERO, Vec3::Y).unwrap(),
            checker_floor(),
        )
        .unwrap();
    let down = |x: f64, z: f64| scene.trace(&ray(v(x, 1.0, z), v(x, 0.0, z)));
    // Square (⌊x⌋, ⌊z⌋): even sum → the material colour, odd → the other. Lit straight from
    // above with intensity 1 and no ambient, each shows its own colour.
    let even = Rgb::new(100, 100, 100);
    let odd = Rgb::new(40, 80, 120);
    for (x, z, expect) in [
        (0.5, 0.5, even),
        (1.5, 0.5, odd),
        (0.5, 1.5, odd),
        (1.5, 1.5, even),
        (-0.5, 0.5, odd),
        (-0.5, -0.5, even),
        (2.5, -3.5, even),
        (0.98, 0.5, even),
        (1.02, 0.5, odd),
    ] {
        let seen = down(x, z);
        assert!(
            seen.r.abs_diff(expect.r) <= 1 && seen.b.abs_diff(expect.b) <= 1,
            "({x}, {z}): {seen:?}"
        );
    }
}

#[test]
fn a_bounded_floor_ends_at_its_edges() {
    let light = Light::from_fx(v(0.0, 100.0, 0.0), Fx::ONE).unwrap();
    let mut scene: Scene<1> = Scene::new(light, 0.0, SKY).unwrap();
    let floor = Plane::from_fx(Vec3::ZERO, Vec3::Y)
        .unwrap()
        .bounded([-10.0, -30.0], [10.0, -10.0])
        .unwrap();
    scene.add_plane(floor, GREY).unwrap();
    let down = |x: f64, z: f64| scene.trace(&ray(v(x, 1.0, z), v(x, 0.0, z)));
    assert_ne!(down(0.0, -20.0), SKY);
    assert_ne!(down(9.9, -10.1), SKY);
    assert_eq!(down(10.1, -20.0), SKY);
    assert_eq!(down(0.0, -9.9), SKY);
    assert_eq!(down(0.0, -30.1), SKY);
}

#[test]
fn a_mirror_shows_the_checkerboard() {
    // A perfect black mirror wall at z = −5 facing +z, above a checkerboard floor at y = −1.
    // Reflection in z = −5 maps z to −10 − z, so a ray from (x, 0, 0) aimed at (x, −1, −9.5)
    // is, after the mirror, the ray that meets the floor at (x, −1, −0.5).
    let light = Light::from_fx(v(0.0, 50.0, 2.0), Fx::ONE).unwrap();
    let mut scene: Scene<2> = Scene::new(light, 0.0, SKY).unwrap();
    scene
        .add_plane(
            Plane::from_fx(v(0.0, -1.0, 0.0), Vec3::Y).unwrap(),
            checker_floor(),
        )
        .unwrap();
    let mirror = Material::from_fx(Rgb::BLACK, Fx::ZERO, Fx::ZERO, 1, Fx::ONE).unwrap();
    scene
        .add_plane(Plane::from_fx(v(0.0, 0.0, -5.0), Vec3::Z).unwrap(), mirror)
        .unwrap();
    for x in [0.5, 1.5, -0.5, 2.5] {
        let in_mirror = scene.trace(&ray(v(x, 0.0, 0.0), v(x, -1.0, -9.5)));
        // The floor point itself, seen directly from above (Lambert shading does not depend
        // on where it is seen from).
        let direct = scene.trace(&ray(v(x, 0.0, -0.5), v(x, -1.0, -0.5)));
        for (m, d) in [
            (in_mirror.r, direct.r),
            (in_mirror.g, direct.g),
            (in_mirror.b, direct.b),
        ] {
            assert!(
                m.abs_diff(d) <= 1,
                "x = {x}: mirror {in_mirror:?}, floor {direct:?}"
            );
        }
    }
    // And the squares it shows alternate: (0.5, −0.5) is square (0, −1), odd; (1.5, −0.5)
    // is square (1, −1), even. Lit from nearly straight above (n·l ≈ 0.9990), each shows
    // its colour within a level.
    let a = scene.trace(&ray(v(0.5, 0.0, 0.0), v(0.5, -1.0, -9.5)));
    let b = scene.trace(&ray(v(1.5, 0.0, 0.0), v(1.5, -1.0, -9.5)));
    assert!(
        a.b.abs_diff(120) <= 1 && a.r.abs_diff(40) <= 1,
        "odd square: {a:?}"
    );
    assert!(
        b.b.abs_diff(100) <= 1 && b.r.abs_diff(100) <= 1,
        "even square: {b:?}"
    );
}

#[test]
fn the_highlight_lies_where_the_half_vector_meets_the_normal() {
    // Only a dim specular term (no diffuse, no ambient, no clamping), so brightness rises
    // with n·h alone. The light is up and to the right of the eye.
    let light_at = [6.0, 8.0, 0.0];
    let light = Light::from_fx(v(light_at[0], light_at[1], light_at[2]), Fx::ONE).unwrap();
    let mut scene: Scene<1> = Scene::new(light, 0.0, Rgb::BLACK).unwrap();
    let centre = [0.0, 0.0, -10.0];
    let shiny = Material::from_fx(Rgb::WHITE, Fx::ZERO, fx(0.5), 50, Fx::ZERO).unwrap();
    scene
        .add_sphere(
            Sphere::from_fx(v(centre[0], centre[1], centre[2]), fx(2.0)).unwrap(),
            shiny,
        )
        .unwrap();
    let camera = Camera::look_at([0.0; 3], centre.map(|c| c as f32))
        .fov_degrees(25.0)
        .size(Size::new(64, 64))
        .build()
        .unwrap();

    // n·h at a surface point, in f64, from the geometry alone.
    let unit = |a: [f64; 3]| {
        let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        a.map(|c| c / l)
    };
    let n_dot_h = |p: [f64; 3]| {
        let n = unit([p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]]);
        let l = unit([light_at[0] - p[0], light_at[1] - p[1], light_at[2] - p[2]]);
        let e = unit([-p[0], -p[1], -p[2]]);
        let h = unit([l[0] + e[0], l[1] + e[1], l[2] + e[2]]);
        n[0] * h[0] + n[1] * h[1] + n[2] * h[2]
    };
    let (mut best_nh, mut brightest) = (f64::MIN, (0u8, f64::MIN));
    let mut row = [Rgb::BLACK; 64];
    for y in 0..64 {
        render_row(&scene, &camera, y, &mut row).unwrap();
        for (x, pixel) in row.iter().enumerate() {
            if let Some(hit) = scene.shoot(&camera.ray(x as u32, y)) {
                let nh = n_dot_h(hit.hit().point().to_f64());
                best_nh = best_nh.max(nh);
                if pixel.r > brightest.0 || (pixel.r == brightest.0 && nh > brightest.1) {
                    brightest = (pixel.r, nh);
                }
            }
        }
    }
    // The brightest pixel is within a pixel's worth of the n·h maximum, and is lit.
    assert!(brightest.0 > 100, "{brightest:?}");
    assert!(
        best_nh - brightest.1 < 1e-3,
        "brightest pixel has n·h {}, the best is {best_nh}",
        brightest.1
    );
    assert!(
        best_nh > 0.999,
        "the grid reaches the highlight's centre: {best_nh}"
    );
}

#[test]
fn a_gradient_background_runs_from_bottom_to_top() {
    let light = Light::from_fx(Vec3::ZERO, Fx::ONE).unwrap();
    let sky = Background {
        top: Rgb::new(0, 0, 255),
        bottom: Rgb::new(200, 100, 0),
    };
    let scene: Scene<1> = Scene::new(light, 0.0, sky).unwrap();
    let look = |d: Vec3| scene.trace(&Ray::new(Vec3::ZERO, d).unwrap());
    assert_eq!(look(Vec3::Y), Rgb::new(0, 0, 255));
    assert_eq!(look(-Vec3::Y), Rgb::new(200, 100, 0));
    // Level: halfway.
    assert_eq!(look(Vec3::X), Rgb::new(100, 50, 128));
}

#[test]
fn supersampling_blends_an_edge() {
    // A white wall covering the left half of the view, on black: the pixel column straddling
    // the edge gets a mixture; columns away from it do not change.
    let light = Light::from_fx(v(0.0, 0.0, 10.0), Fx::ONE).unwrap();
    let mut scene: Scene<1> = Scene::new(light, 1.0, Rgb::BLACK).unwrap();
    // x = 0 plane facing +x: a wall seen edge-on? Use a sphere edge instead: a big sphere
    // whose rim crosses the middle column.
    scene
        .add_sphere(
            Sphere::from_fx(v(-50.0, 0.0, -100.0), fx(50.0)).unwrap(),
            Rgb::WHITE,
        )
        .unwrap();
    let camera = Camera::pinhole(2.0, 2.0, 1.0)
        .size(Size::new(9, 9))
        .build()
        .unwrap();
    let (mut plain, mut smooth) = ([Rgb::BLACK; 9], [Rgb::BLACK; 9]);
    render_row(&scene, &camera, 4, &mut plain).unwrap();
    render_row_supersampled(&scene, &camera, 4, 4, &mut smooth).unwrap();
    assert_eq!(plain[0], smooth[0]);
    assert_eq!(plain[8], smooth[8]);
    let mixed = smooth.iter().filter(|p| p.r > 0 && p.r < 255).count();
    assert!(mixed >= 1, "{smooth:?}");
    assert_eq!(
        plain.iter().filter(|p| p.r > 0 && p.r < 255).count(),
        0,
        "{plain:?}"
    );
}

#[test]
fn materials_and_lights_at_their_limits_saturate_without_panicking() {
    // Every weight at the top of its range, four of the brightest lights, the sharpest
    // checker: the sums saturate to white rather than wrap.
    let light = Light::new([0.0, 100.0, 0.0], 4.0).unwrap();
    let mut scene: Scene<2, 4> = Scene::new(light, 1.0, SKY).unwrap();
    for _ in 0..3 {
        scene.add_light(light).unwrap();
    }
    let wild = Material::new(Rgb::new(10, 20, 30), 2.0, 16.0, 1, 1.0)
        .unwrap()
        .with_checker_fx(Fx::DELTA, Rgb::BLACK)
        .unwrap();
    scene
        .add_plane(Plane::from_fx(v(0.0, -1.0, 0.0), Vec3::Y).unwrap(), wild)
        .unwrap();
    scene
        .add_sphere(Sphere::from_fx(v(0.0, 2.0, -5.0), fx(1.0)).unwrap(), wild)
        .unwrap();
    let camera = Camera::pinhole(2.0, 2.0, 1.0)
        .size(Size::new(8, 8))
        .build()
        .unwrap();
    let mut row = [Rgb::BLACK; 8];
    for y in 0..8 {
        render_row(&scene, &camera, y, &mut row).unwrap();
    }
    assert_eq!(row[4], Rgb::WHITE, "the floor saturates");
}
