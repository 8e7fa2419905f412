//! Scenes at the edges of what fixray accepts: more objects than a 64-bit mask has bits, and
//! an eye placed exactly on a surface. Each test is a reproducer of a wrong picture that an
//! outside check once found.

#[path = "common/accuracy.rs"]
mod accuracy;

use fixray::{Camera, Fx, Light, Material, Plane, Rgb, Scene, Size, Sphere, Vec3, render_row};

const SKY: Rgb = Rgb::new(40, 60, 200);

fn light() -> Light {
    Light::from_fx(Vec3::from_ints(-20, 30, 20), Fx::from_num(0.8)).unwrap()
}

fn sphere(x: f32, y: f32, z: f32, r: f32) -> Sphere {
    Sphere::new([x, y, z], r).unwrap()
}

fn look_ahead(cols: u32, rows: u32) -> Camera {
    Camera::look_at([0.0; 3], [0.0, 0.0, -1.0])
        .size(Size::new(cols, rows))
        .build()
        .unwrap()
}

/// Every pixel of `render_row` against `trace` of the camera's own ray for it; returns how
/// many differ.
fn pixels_unlike_tracing<const N: usize>(scene: &Scene<N>, camera: &Camera) -> usize {
    let mut out = vec![Rgb::BLACK; camera.width() as usize];
    let mut differ = 0;
    for row in 0..camera.height() {
        render_row(scene, camera, row, &mut out).unwrap();
        for (col, pixel) in (0..).zip(&out) {
            differ += usize::from(*pixel != scene.trace(&camera.ray(col, row)));
        }
    }
    differ
}

/// The whole frame through `render_row`.
fn frame<const N: usize>(scene: &Scene<N>, camera: &Camera) -> Vec<Rgb> {
    let mut out = vec![Rgb::BLACK; camera.width() as usize * camera.height() as usize];
    for (row, line) in (0..).zip(out.chunks_mut(camera.width() as usize)) {
        render_row(scene, camera, row, line).unwrap();
    }
    out
}

#[test]
fn objects_past_the_64th_are_drawn_when_object_63_is_out_of_the_run() {
    let mut scene: Scene<70> = Scene::new(light(), 0.2, SKY).unwrap();
    for i in 0..63 {
        // Behind the camera: never in view.
        scene
            .add_sphere(sphere(i as f32, 0.0, 30.0, 0.5), Rgb::WHITE)
            .unwrap();
    }
    let small = scene
        .add_sphere(sphere(-5.0, 0.0, -10.0, 0.5), Rgb::new(200, 0, 0))
        .unwrap();
    let large = scene
        .add_sphere(sphere(0.0, 0.0, -12.0, 3.0), Rgb::new(0, 200, 0))
        .unwrap();
    assert_eq!((small, large), (63, 64));
    let camera = look_ahead(160, 128);
    assert_eq!(
        scene.shoot(&camera.ray(80, 64)).map(|h| h.object()),
        Some(64),
        "the centre pixel sees object 64"
    );
    assert_eq!(pixels_unlike_tracing(&scene, &camera), 0);
}

#[test]
fn a_mirror_past_the_64th_object_does_not_see_itself() {
    let ground = || Plane::from_fx(Vec3::from_ints(0, -2, 0), Vec3::Y).unwrap();
    let far = |i: i32| sphere(-300.0 + 10.0 * i as f32, 40.0, -900.0, 1.0);
    let mirror = Material::from_fx(
        Rgb::WHITE,
        Fx::from_num(0.1),
        Fx::ZERO,
        1,
        Fx::from_num(0.8),
    )
    .unwrap();
    let ball = || sphere(0.0, 0.0, -6.0, 1.5);

    let mut mirror_last: Scene<70> = Scene::new(light(), 0.2, SKY).unwrap();
    for i in 0..64 {
        mirror_last.add_sphere(far(i), Rgb::WHITE).unwrap();
    }
    mirror_last
        .add_plane(ground(), Rgb::new(90, 90, 90))
        .unwrap();
    assert_eq!(mirror_last.add_sphere(ball(), mirror).unwrap(), 65);

    let mut mirror_first: Scene<70> = Scene::new(light(), 0.2, SKY).unwrap();
    mirror_first.add_sphere(ball(), mirror).unwrap();
    for i in 0..64 {
        mirror_first.add_sphere(far(i), Rgb::WHITE).unwrap();
    }
    mirror_first
        .add_plane(ground(), Rgb::new(90, 90, 90))
        .unwrap();

    let camera = look_ahead(96, 72);
    let (last, first) = (frame(&mirror_last, &camera), frame(&mirror_first, &camera));
    let differ = last.iter().zip(&first).filter(|(a, b)| a != b).count();
    assert_eq!(differ, 0, "of {} pixels", last.len());
    assert_eq!(pixels_unlike_tracing(&mirror_last, &camera), 0);
}

#[test]
fn an_eye_on_top_of_a_sphere_sees_the_sky_above_it() {
    let mut scene: Scene<2> = Scene::new(light(), 0.2, SKY).unwrap();
    let big = scene
        .add_sphere(sphere(0.0, -50.0, 0.0, 50.0), Rgb::new(200, 200, 0))
        .unwrap();
    let small = scene
        .add_sphere(sphere(0.0, 2.0, -20.0, 1.0), Rgb::new(200, 0, 0))
        .unwrap();
    let camera = look_ahead(160, 128);
    for row in 0..camera.height() {
        for col in 0..camera.width() {
            let ray = camera.ray(col, row);
            let seen = scene.shoot(&ray).map(|h| h.object());
            if ray.dir().y > Fx::ZERO {
                // Above the horizon the eye leaves the big sphere: only the small ball or sky.
                assert_ne!(seen, Some(big), "row {row}, column {col}");
            } else if ray.dir().y < Fx::ZERO {
                // Below it every ray crosses the big sphere, whose inside is all it sees.
                assert_eq!(seen, Some(big), "row {row}, column {col}");
            }
        }
    }
    let centre = camera.ray(80, 54); // 2/20 up: the small ball's centre row
    assert_eq!(scene.shoot(&centre).map(|h| h.object()), Some(small));
    assert_eq!(pixels_unlike_tracing(&scene, &camera), 0);
}

#[test]
fn an_eye_on_a_plane_sees_it_edge_on_and_not_at_all() {
    let mut scene: Scene<2> = Scene::new(light(), 0.2, SKY).unwrap();
    scene
        .add_plane(Plane::from_fx(Vec3::ZERO, Vec3::Y).unwrap(), Rgb::WHITE)
        .unwrap();
    let ball = scene
        .add_sphere(sphere(0.0, 0.0, -10.0, 2.0), Rgb::new(200, 0, 0))
        .unwrap();
    let camera = look_ahead(80, 64);
    let mut sky = 0;
    for row in 0..camera.height() {
        for col in 0..camera.width() {
            let hit = scene.shoot(&camera.ray(col, row));
            assert!(
                hit.is_none_or(|h| h.object() == ball),
                "row {row}, column {col}: {hit:?}"
            );
            sky += usize::from(hit.is_none());
        }
    }
    assert!(sky > 80 * 64 / 2, "mostly sky: {sky}");
    assert_eq!(pixels_unlike_tracing(&scene, &camera), 0);
}

/// Object agreement with the f64 reference, which decides a ray from a surface by its own
/// rule (the sign of the quadratic's constant term), for the two eyes on surfaces above.
#[test]
fn the_reference_agrees_on_eyes_placed_on_surfaces() {
    use crate::accuracy::Accuracy;
    use fixray_reference::{DCamera, DScene, DVec3};
    let dcamera = DCamera::look_at(
        DVec3::ZERO,
        DVec3::new(0.0, 0.0, -1.0),
        DVec3::new(0.0, 1.0, 0.0),
        60.0,
        160,
        128,
    )
    .unwrap();
    let camera = look_ahead(160, 128);

    let mut on_sphere: Scene<2> = Scene::new(light(), 0.2, SKY).unwrap();
    on_sphere
        .add_sphere(sphere(0.0, -50.0, 0.0, 50.0), Rgb::new(200, 200, 0))
        .unwrap();
    on_sphere
        .add_sphere(sphere(0.0, 2.0, -20.0, 1.0), Rgb::new(200, 0, 0))
        .unwrap();
    let mut on_plane: Scene<2> = Scene::new(light(), 0.2, SKY).unwrap();
    on_plane
        .add_plane(Plane::from_fx(Vec3::ZERO, Vec3::Y).unwrap(), Rgb::WHITE)
        .unwrap();
    on_plane
        .add_sphere(sphere(0.0, 0.0, -10.0, 2.0), Rgb::new(200, 0, 0))
        .unwrap();
    for (name, scene) in [("on a sphere", &on_sphere), ("on a plane", &on_plane)] {
        let dscene = DScene::from_scene(scene).unwrap();
        let a = Accuracy::measure(scene, &camera, &dscene, &dcamera);
        eprintln!("eye {name}: {a:?}");
        // No row of an even-sized screen looks along the horizon, where rounding could tie.
        assert!(
            a.same_object == a.pixels,
            "eye {name}: {} of {} pixels see another object",
            a.pixels - a.same_object,
            a.pixels
        );
    }
}
