//! Editing a scene between frames: after any edit the render is exactly that of a scene built
//! from scratch with the edited values, shadow cones and all.

use fixray::Size;
use fixray::{
    Background, Camera, Error, Fx, Light, Material, Object, Plane, Quantity, Rgb, Scene, Shape,
    Sphere, Vec3, render_row,
};

const SKY: Rgb = Rgb::new(40, 60, 200);

fn ball(x: i16, y: i16, z: i16, r: f32) -> Shape {
    Shape::Sphere(Sphere::from_fx(Vec3::from_ints(x, y, z), Fx::from_num(r)).unwrap())
}

fn ground() -> Shape {
    Shape::Plane(Plane::from_fx(Vec3::from_ints(0, -4, 0), Vec3::Y).unwrap())
}

fn light(x: i16, y: i16, z: i16) -> Light {
    Light::from_fx(Vec3::from_ints(x, y, z), Fx::from_num(0.8)).unwrap()
}

fn shiny() -> Material {
    Material::from_fx(
        Rgb::new(200, 200, 40),
        Fx::ONE,
        Fx::ONE,
        40,
        Fx::from_num(0.4),
    )
    .unwrap()
}

/// A scene of `objects` lit by `lights`, built from scratch.
fn build(objects: &[Object], lights: &[Light], background: Background) -> Scene<6, 2> {
    let mut scene = Scene::new(lights[0], 0.2, background).unwrap();
    for light in &lights[1..] {
        scene.add_light(*light).unwrap();
    }
    for object in objects {
        scene.add(*object).unwrap();
    }
    scene
}

fn frame(scene: &Scene<6, 2>, camera: &Camera) -> Vec<Rgb> {
    let mut out = vec![Rgb::BLACK; camera.width() as usize * camera.height() as usize];
    for (row, line) in (0..).zip(out.chunks_mut(camera.width() as usize)) {
        render_row(scene, camera, row, line).unwrap();
    }
    out
}

#[test]
fn every_edit_renders_as_a_scene_built_with_it() {
    let camera = Camera::look_at([0.0, 2.0, 4.0], [0.0, -1.0, -14.0])
        .size(Size::new(96, 72))
        .build()
        .unwrap();
    let mut objects = vec![
        Object {
            shape: ground(),
            material: Rgb::new(120, 120, 120).into(),
        },
        Object {
            shape: ball(-3, -1, -14, 2.0),
            material: Rgb::new(200, 40, 40).into(),
        },
        Object {
            shape: ball(3, 0, -16, 2.5),
            material: shiny(),
        },
    ];
    let mut lights = vec![light(-20, 20, 10), light(20, 30, -5)];
    let mut background = Background::from(SKY);
    let mut scene = build(&objects, &lights, background);

    // A sequence of edits, each checked against a scene built with everything so far.
    for step in 0..8 {
        match step {
            0 => {
                // A sphere moves across the floor: its shadow must move with it.
                objects[1].shape = ball(0, -2, -12, 2.0);
                scene.set_shape(1, objects[1].shape).unwrap();
            }
            1 => {
                objects[2].material = Rgb::new(10, 200, 10).into();
                scene.set_material(2, objects[2].material).unwrap();
            }
            2 => {
                // A light moves: every shadow cone of it is stale.
                lights[0] = light(15, 25, 15);
                scene.set_light(0, lights[0]).unwrap();
            }
            3 => {
                objects[2] = Object {
                    shape: ball(-4, 1, -18, 3.0),
                    material: shiny(),
                };
                scene.set_object(2, objects[2]).unwrap();
            }
            4 => {
                // A sphere replaced by a plane and back.
                objects[1].shape = Shape::Plane(
                    Plane::from_fx(Vec3::from_ints(0, 0, -30), Vec3::Z)
                        .unwrap()
                        .bounded([-3.0, -3.0], [1.0, 1.0])
                        .unwrap(),
                );
                scene.set_shape(1, objects[1].shape).unwrap();
            }
            5 => {
                objects[1].shape = ball(2, -3, -10, 1.0);
                scene.set_shape(1, objects[1].shape).unwrap();
            }
            6 => {
                background = Background::from(Rgb::new(5, 5, 5));
                scene.set_background(background);
            }
            _ => {
                lights[1] = light(-5, 40, -20);
                scene.set_light(1, lights[1]).unwrap();
            }
        }
        let fresh = build(&objects, &lights, background);
        assert_eq!(
            frame(&scene, &camera),
            frame(&fresh, &camera),
            "after edit {step}"
        );
    }
}

#[test]
fn edits_of_what_is_not_there_are_refused() {
    let mut scene = build(
        &[Object {
            shape: ground(),
            material: Rgb::WHITE.into(),
        }],
        &[light(0, 10, 0)],
        SKY.into(),
    );
    assert_eq!(
        scene.set_shape(1, ball(0, 0, -5, 1.0)),
        Err(Error::NoSuchObject { index: 1, count: 1 })
    );
    assert_eq!(
        scene.set_material(7, Rgb::BLACK),
        Err(Error::NoSuchObject { index: 7, count: 1 })
    );
    assert_eq!(
        scene.set_light(1, light(0, 1, 0)),
        Err(Error::NoSuchLight { index: 1, count: 1 })
    );
    assert_eq!(
        scene.set_ambient(1.5),
        Err(Error::OutOfRange {
            quantity: Quantity::Ambient,
            min: Fx::ZERO,
            max: Fx::ONE
        })
    );
    // Nothing changed.
    assert_eq!(scene.objects().len(), 1);
    assert_eq!(scene.ambient(), Fx::from_num(0.2));
}

#[test]
fn pick_names_the_object_render_row_shades() {
    let scene = build(
        &[
            Object {
                shape: ground(),
                material: Rgb::WHITE.into(),
            },
            Object {
                shape: ball(0, 0, -10, 2.0),
                material: Rgb::new(200, 0, 0).into(),
            },
        ],
        &[light(0, 10, 0)],
        SKY.into(),
    );
    let camera = Camera::look_at([0.0; 3], [0.0, 0.0, -1.0])
        .size(Size::new(40, 30))
        .build()
        .unwrap();
    let mut row = vec![Rgb::BLACK; 40];
    let mut seen = [0usize; 3];
    for y in 0..30 {
        render_row(&scene, &camera, y, &mut row).unwrap();
        for x in 0..40 {
            let hit = scene.pick(&camera, x, y).unwrap();
            seen[hit.map_or(2, |h| h.object())] += 1;
            // The pixel is the shade of exactly that hit.
            let ray = camera.ray(x, y);
            assert_eq!(
                row[x as usize],
                scene.shade(&ray, hit.as_ref()),
                "({x}, {y})"
            );
        }
    }
    assert!(
        seen.iter().all(|&n| n > 0),
        "ground, ball and sky: {seen:?}"
    );
    assert_eq!(
        scene.pick(&camera, 40, 0),
        Err(Error::ColumnOutOfRange { col: 40, cols: 40 })
    );
    assert_eq!(
        scene.pick(&camera, 0, 30),
        Err(Error::RowOutOfRange { row: 30, rows: 30 })
    );
}
