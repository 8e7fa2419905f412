//! The damage of an edit (`Damage::between`) and the redraw of it (`render_changes`): a frame
//! redrawn where the damage says is, bit for bit, the frame of the edited scene, and every
//! pixel that changed lies in the damage.
//!
//! The property test draws random scenes (an infinite ground, bounded planes, several
//! spheres, one to three lights, shadows on), random cameras and random sequences of edits.
//! `FIXRAY_CHANGES_CASES` sets how many sequences of four steps (default 150; thousands in
//! release: `FIXRAY_CHANGES_CASES=5000 cargo test --release --test changes`).

mod common;

use common::{Source, XorShift};
use fixray::{
    Background, Camera, Damage, Error, Framebuffer, Light, Material, Plane, Rgb, Scene, Shape,
    Size, Sphere, demo, render, render_changes, render_row, render_row_span,
};

type World = Scene<8, 3>;

fn rgb(src: &mut XorShift) -> Rgb {
    let b = src.bits();
    Rgb::new(b as u8, (b >> 8) as u8, (b >> 16) as u8)
}

/// A value in `[lo, hi]`.
fn between(src: &mut XorShift, lo: f32, hi: f32) -> f32 {
    lo + (src.uniform(1.0) + 1.0) / 2.0 * (hi - lo)
}

fn matte_or_shiny(src: &mut XorShift) -> Material {
    if src.one_in(3) {
        Material::new(
            rgb(src),
            between(src, 0.3, 1.0),
            between(src, 0.0, 1.0),
            20,
            0.0,
        )
        .unwrap()
    } else {
        Material::matte(rgb(src))
    }
}

fn ball(src: &mut XorShift) -> Sphere {
    Sphere::new(
        [
            between(src, -8.0, 8.0),
            between(src, -3.5, 4.0),
            between(src, -26.0, -6.0),
        ],
        between(src, 0.3, 3.0),
    )
    .unwrap()
}

fn light(src: &mut XorShift) -> Light {
    Light::new(
        [
            between(src, -20.0, 20.0),
            // Now and then a light low enough for a sphere's shadow on the ground to stretch
            // too far to bound.
            if src.one_in(16) {
                between(src, -2.0, 6.0)
            } else {
                between(src, 8.0, 30.0)
            },
            between(src, -30.0, 10.0),
        ],
        between(src, 0.3, 0.9),
    )
    .unwrap()
}

/// A random scene: an infinite ground (sometimes tilted), up to two bounded planes, two to
/// five spheres, one to three lights.
fn scene(src: &mut XorShift) -> World {
    let background = if src.one_in(3) {
        Background {
            top: rgb(src),
            bottom: rgb(src),
        }
    } else {
        Background::plain(rgb(src))
    };
    let mut world = World::new(light(src), between(src, 0.05, 0.3), background).unwrap();
    for _ in 0..src.below(3) {
        world.add_light(light(src)).unwrap();
    }
    let tilt = if src.one_in(4) {
        [between(src, -0.3, 0.3), 1.0, between(src, -0.3, 0.3)]
    } else {
        [0.0, 1.0, 0.0]
    };
    let ground = Plane::new([0.0, -4.0, 0.0], tilt).unwrap();
    let ground_look = if src.one_in(2) {
        Material::matte(rgb(src))
            .with_checker(between(src, 0.5, 3.0), rgb(src))
            .unwrap()
    } else {
        Material::matte(rgb(src))
    };
    world.add_plane(ground, ground_look).unwrap();
    for _ in 0..src.below(3) {
        let plane = match src.below(3) {
            // A back wall facing the camera.
            0 => Plane::new([0.0, 0.0, between(src, -32.0, -20.0)], [0.0, 0.0, 1.0])
                .unwrap()
                .bounded(
                    [between(src, -15.0, -2.0), between(src, -4.0, 0.0)],
                    [between(src, 2.0, 15.0), between(src, 2.0, 12.0)],
                )
                .unwrap(),
            // A side wall.
            1 => Plane::new([between(src, -14.0, 14.0), 0.0, 0.0], [1.0, 0.0, 0.0])
                .unwrap()
                .bounded(
                    [between(src, -4.0, 0.0), between(src, -30.0, -18.0)],
                    [between(src, 1.0, 8.0), between(src, -16.0, -6.0)],
                )
                .unwrap(),
            // A raised platform.
            _ => Plane::new([0.0, between(src, -3.5, -1.0), 0.0], [0.0, 1.0, 0.0])
                .unwrap()
                .bounded(
                    [between(src, -10.0, 0.0), between(src, -26.0, -14.0)],
                    [between(src, 0.5, 10.0), between(src, -13.0, -6.0)],
                )
                .unwrap(),
        };
        world.add_plane(plane, matte_or_shiny(src)).unwrap();
    }
    for _ in 0..2 + src.below(4) {
        world.add_sphere(ball(src), matte_or_shiny(src)).unwrap();
    }
    world
}

fn camera(src: &mut XorShift, size: Size) -> Camera {
    loop {
        let eye = [
            between(src, -7.0, 7.0),
            between(src, -1.0, 7.0),
            between(src, -2.0, 8.0),
        ];
        let target = [
            between(src, -4.0, 4.0),
            between(src, -4.0, 1.0),
            between(src, -20.0, -10.0),
        ];
        if let Ok(camera) = Camera::look_at(eye, target)
            .fov_degrees(between(src, 35.0, 85.0))
            .size(size)
            .build()
        {
            return camera;
        }
    }
}

/// The spheres of a scene, by index.
fn spheres(world: &World) -> Vec<usize> {
    (0..world.objects().len())
        .filter(|&i| matches!(world.objects()[i].shape, Shape::Sphere(_)))
        .collect()
}

/// One random edit, described for the report. Mostly the region's own cases (move, resize,
/// recolour); now and then one that must fall back to the whole screen.
fn edit(src: &mut XorShift, world: &mut World) -> String {
    let balls = spheres(world);
    let index = src.pick(&balls);
    let Shape::Sphere(old) = world.objects()[index].shape else {
        unreachable!()
    };
    let c = old.centre();
    let [x, y, z] = [c.x.to_num::<f32>(), c.y.to_num(), c.z.to_num()];
    let r: f32 = old.radius().to_num();
    match src.below(20) {
        0..=8 => {
            let step = if src.one_in(5) { 6.0 } else { 0.6 };
            let to = [
                x + src.uniform(step),
                (y + src.uniform(step)).clamp(-5.0, 8.0),
                z + src.uniform(step),
            ];
            world
                .set_shape(index, Sphere::new(to, r).unwrap().into())
                .unwrap();
            format!("move sphere {index} from {:?} to {to:?} (r {r})", [x, y, z])
        }
        9..=12 => {
            let to = (r * between(src, 0.6, 1.5)).clamp(0.1, 5.0);
            world
                .set_shape(index, Sphere::new([x, y, z], to).unwrap().into())
                .unwrap();
            format!("resize sphere {index} at {:?} from {r} to {to}", [x, y, z])
        }
        13..=15 => {
            world.set_material(index, matte_or_shiny(src)).unwrap();
            format!("recolour sphere {index}")
        }
        16 => {
            // A plane's new colour: its rectangle if bounded, else the whole screen.
            let planes: Vec<usize> = (0..world.objects().len())
                .filter(|&i| matches!(world.objects()[i].shape, Shape::Plane(_)))
                .collect();
            // The ground (object 0) one time in four, or when there is no other plane.
            let plane = if planes.len() > 1 && !src.one_in(4) {
                src.pick(&planes[1..])
            } else {
                0
            };
            world.set_material(plane, matte_or_shiny(src)).unwrap();
            format!("recolour plane {plane}")
        }
        17 => {
            let to = light(src);
            world.set_light(0, to).unwrap();
            "move light 0".into()
        }
        18 => {
            world
                .set_material(index, Material::new(rgb(src), 0.5, 0.5, 30, 0.6).unwrap())
                .unwrap();
            format!("make sphere {index} a mirror")
        }
        _ => {
            let to = [x + src.uniform(1.0), y, z + src.uniform(1.0)];
            let material = matte_or_shiny(src);
            world
                .set_object(
                    index,
                    fixray::Object::new(Sphere::new(to, r).unwrap().into(), material),
                )
                .unwrap();
            format!("move and recolour sphere {index} to {to:?}")
        }
    }
}

/// What the property test saw, for its report.
#[derive(Default)]
struct Tally {
    edits: u64,
    whole: u64,
    empty: u64,
    damaged: u64,
    changed: u64,
    screen: u64,
    /// The fewest columns between a changed pixel and the end of its row's span.
    edge: u32,
}

/// Renders `scene` into a new frame.
fn frame<const W: usize, const H: usize, const N: usize, const L: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
) -> Framebuffer<W, H> {
    let mut frame = Framebuffer::new();
    render(scene, camera, &mut frame).unwrap();
    frame
}

/// Checks the contract for one edit: every changed pixel in the damage, and the redrawn frame
/// equal to the fresh one. Returns the number of changed pixels.
fn check_edit<const W: usize, const H: usize, const N: usize, const L: usize>(
    before: &Scene<N, L>,
    after: &Scene<N, L>,
    camera: &Camera,
    previous: &Framebuffer<W, H>,
    what: &str,
) -> (Framebuffer<W, H>, Damage, u32, u32) {
    let damage = Damage::between(before, after, camera);
    let full = frame::<W, H, N, L>(after, camera);
    let mut changed = 0;
    let mut edge = u32::MAX;
    for y in 0..H {
        for x in 0..W {
            if previous.pixel(x, y) != full.pixel(x, y) {
                changed += 1;
                if let Some(span) = damage.row_span(y as u32).filter(|_| !damage.is_whole()) {
                    let x = x as u32;
                    // Columns between this pixel and the span's nearer end, off-screen ends
                    // not counted (the screen's edge is not the region's).
                    let left = if span.start > 0 {
                        x.saturating_sub(span.start)
                    } else {
                        u32::MAX
                    };
                    let right = if span.end < W as u32 {
                        (span.end - 1).saturating_sub(x)
                    } else {
                        u32::MAX
                    };
                    edge = edge.min(left).min(right);
                }
                let inside = damage
                    .row_span(y as u32)
                    .is_some_and(|span| span.contains(&(x as u32)));
                assert!(
                    inside,
                    "{what}: pixel ({x}, {y}) changed from {:?} to {:?} outside the damage \
                     {:?}\nbefore: {before:?}\nafter: {after:?}\ncamera: {camera:?}",
                    previous.pixel(x, y),
                    full.pixel(x, y),
                    damage.rectangles().collect::<Vec<_>>(),
                );
            }
        }
    }
    let mut partial = previous.clone();
    render_changes(after, camera, &damage, &mut partial).unwrap();
    assert!(
        partial == full,
        "{what}: the redrawn frame differs from a fresh render"
    );
    (full, damage, changed, edge)
}

/// A unit vector in a random direction.
fn unit(src: &mut XorShift) -> [f32; 3] {
    loop {
        let v = [src.uniform(1.0), src.uniform(1.0), src.uniform(1.0)];
        let length = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        if (0.1..=1.0).contains(&length) {
            return v.map(|c| c / length);
        }
    }
}

/// Where the margins are thin: lights just outside spheres, eyes close to them, fields of
/// view from narrow to very wide.
fn make_wild(src: &mut XorShift, world: &mut World, size: Size) -> Camera {
    let balls = spheres(world);
    let near = |src: &mut XorShift, world: &World, reach: (f32, f32)| {
        let Shape::Sphere(b) = world.objects()[src.pick(&balls)].shape else {
            unreachable!()
        };
        let (c, r) = (b.centre(), b.radius().to_num::<f32>());
        let out = between(src, reach.0, reach.1) * r;
        let dir = unit(src);
        [
            c.x.to_num::<f32>() + dir[0] * out,
            c.y.to_num::<f32>() + dir[1] * out,
            c.z.to_num::<f32>() + dir[2] * out,
        ]
    };
    for index in 0..world.lights().len() {
        if src.one_in(2) {
            let at = near(src, world, (1.02, 1.5));
            world
                .set_light(index, Light::new(at, 0.7).unwrap())
                .unwrap();
        }
    }
    loop {
        let eye = if src.one_in(2) {
            near(src, world, (1.2, 3.0))
        } else {
            [
                src.uniform(8.0),
                between(src, -3.0, 8.0),
                between(src, -4.0, 8.0),
            ]
        };
        let target = [
            src.uniform(6.0),
            between(src, -4.0, 2.0),
            between(src, -24.0, -8.0),
        ];
        let fov = match src.below(3) {
            0 => between(src, 3.0, 25.0),
            1 => between(src, 25.0, 100.0),
            _ => between(src, 100.0, 165.0),
        };
        if let Ok(camera) = Camera::look_at(eye, target)
            .fov_degrees(fov)
            .size(size)
            .build()
        {
            return camera;
        }
    }
}

fn sequence<const W: usize, const H: usize>(seed: u64, wild: bool, tally: &mut Tally) {
    let mut src = XorShift::new(seed);
    let mut world = scene(&mut src);
    let size = Size::new(W as u32, H as u32);
    let camera = if wild {
        make_wild(&mut src, &mut world, size)
    } else {
        camera(&mut src, size)
    };
    let mut previous = frame::<W, H, 8, 3>(&world, &camera);
    for step in 0..4 {
        let before = world.clone();
        let mut what = format!("seed {seed} ({W}x{H}) step {step}:");
        // A mirror shows everything: its step is the whole screen. Turned back to matte the
        // next step, it lets the sequence go on testing the region.
        for index in spheres(&world) {
            if world.objects()[index].material.reflect() != 0 {
                world.set_material(index, matte_or_shiny(&mut src)).unwrap();
                what += &format!(" sphere {index} no longer a mirror;");
            }
        }
        for _ in 0..1 + src.below(2) {
            what += " ";
            what += &edit(&mut src, &mut world);
            what += ";";
        }
        let (full, damage, changed, edge) = check_edit(&before, &world, &camera, &previous, &what);
        tally.edge = tally.edge.min(edge);
        if damage.is_whole() && std::env::var("FIXRAY_CHANGES_WHOLE").is_ok() {
            println!("whole: {what}");
        }
        tally.edits += 1;
        tally.whole += damage.is_whole() as u64;
        tally.empty += damage.is_empty() as u64;
        tally.damaged += damage.pixel_count() as u64;
        tally.changed += changed as u64;
        tally.screen += (W * H) as u64;
        previous = full;
    }
}

/// The number of edit sequences a property test runs: `FIXRAY_CHANGES_CASES` (150 unless
/// set) divided by `share`, rounded up.
fn sequences(share: u64) -> u64 {
    std::env::var("FIXRAY_CHANGES_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(150u64)
        .div_ceil(share)
}

/// Runs `cases` edit sequences (seeds `salt | 0..cases`, the screen sizes in turn), wild or
/// tame, prints what they did under `name` and returns the tally.
fn run_sequences(name: &str, cases: u64, salt: u64, wild: bool) -> Tally {
    let mut tally = Tally {
        edge: u32::MAX,
        ..Tally::default()
    };
    for seed in 0..cases {
        match seed % 3 {
            0 => sequence::<40, 30>(salt | seed, wild, &mut tally),
            1 => sequence::<64, 48>(salt | seed, wild, &mut tally),
            _ => sequence::<96, 64>(salt | seed, wild, &mut tally),
        }
    }
    println!(
        "{name}: {} edits: {} whole screen, {} empty; damage {:.1} % of the screens, changed \
         {:.1} %; nearest a changed pixel came to a span's end: {} columns",
        tally.edits,
        tally.whole,
        tally.empty,
        100.0 * tally.damaged as f64 / tally.screen as f64,
        100.0 * tally.changed as f64 / tally.screen as f64,
        tally.edge,
    );
    tally
}

#[test]
fn a_redrawn_frame_is_the_edited_scenes_frame() {
    let tally = run_sequences("tame", sequences(1), 0, false);
    // The fallbacks are a minority of the edits (lights moved, mirrors made and unmade, the
    // ground recoloured, low lights): most damage must be smaller than the screen, or the
    // test would prove little.
    assert!(tally.whole * 5 < tally.edits * 2, "too many whole screens");
    // And the region is not so wide that it could never fail: some changed pixel lies within
    // two columns of its span's end, so spans narrowed by three columns would miss it.
    assert!(
        tally.edge <= 2,
        "no changed pixel near a span's end: {}",
        tally.edge
    );
}

#[test]
fn wild_scenes_redrawn_are_the_edited_scenes_frames() {
    // A quarter as many sequences as the tame test.
    run_sequences("wild", sequences(4), 1 << 40, true);
}

#[test]
fn spheres_past_the_64th_are_bounded_too() {
    // Objects past the 64th have no culling bit: their silhouettes take every row.
    let camera = demo::camera(64, 48).unwrap();
    let light = Light::new([-20.0, 20.0, 20.0], 0.8).unwrap();
    let mut world: Scene<72, 1> = Scene::new(light, 0.2, Rgb::new(50, 160, 200)).unwrap();
    world
        .add_plane(
            Plane::new([0.0, -4.0, 0.0], [0.0, 1.0, 0.0]).unwrap(),
            Rgb::new(120, 150, 90),
        )
        .unwrap();
    for i in 0..70 {
        let (x, z) = ((i % 10) as f32 * 2.0 - 9.0, -12.0 - (i / 10) as f32 * 2.0);
        world
            .add_sphere(
                Sphere::new([x, -3.5, z], 0.4).unwrap(),
                Rgb::new(200, 90, 40),
            )
            .unwrap();
    }
    let mut previous = frame::<64, 48, 72, 1>(&world, &camera);
    for (index, to) in [
        (3, [-4.0, -3.0, -12.5]),
        (66, [1.5, -3.2, -23.0]),
        (70, [0.0, -2.0, -14.0]),
    ] {
        let before = world.clone();
        world
            .set_shape(index, Sphere::new(to, 0.5).unwrap().into())
            .unwrap();
        let (full, damage, _, _) = check_edit(
            &before,
            &world,
            &camera,
            &previous,
            &format!("move sphere {index}"),
        );
        assert!(!damage.is_whole(), "sphere {index}");
        previous = full;
    }
}

/// `material` without its mirror and its glass.
fn opaque(material: Material) -> Material {
    let m = Material::from_fx(
        material.colour(),
        material.diffuse(),
        material.specular(),
        material.shininess(),
        fixray::Fx::ZERO,
    )
    .unwrap();
    match material.checker() {
        Some(checker) => m.with_checker_fx(checker.size(), checker.other()).unwrap(),
        None => m,
    }
}

#[test]
fn hostile_worlds_keep_the_contract() {
    // The hostile tests' worlds (huge and tiny spheres, planes at any angle, mirrors, eyes
    // on surfaces), edited by swapping in objects of another such world or nudging a sphere.
    let cases = sequences(2);
    let (mut edits, mut whole) = (0, 0);
    for seed in 0..cases {
        let mut src = XorShift::new(1 << 50 | seed);
        let eye = [src.uniform(30.0), src.uniform(30.0), src.uniform(30.0)];
        let target = [src.uniform(30.0), src.uniform(30.0), src.uniform(30.0)];
        let Ok(camera) = Camera::look_at(eye, target)
            .fov_degrees(between(&mut src, 10.0, 120.0))
            .size(Size::new(48, 36))
            .build()
        else {
            continue;
        };
        let view = common::View {
            eye: camera.eye(),
            forward: camera.ray(24, 18).dir(),
        };
        let count = 1 + src.below(8) as usize;
        let Some(mut scene) = common::world(&mut src, view, count, false).build::<8>() else {
            continue;
        };
        // Mirrors and glass make every edit the whole screen: most worlds go without, and
        // those with them follow few bounces, for time (a tree of rays doubles a bounce).
        let plain = !src.one_in(8);
        scene.set_depth(scene.depth().min(3));
        if plain {
            for index in 0..scene.objects().len() {
                let object = scene.objects()[index];
                scene
                    .set_object(
                        index,
                        fixray::Object::new(object.shape, opaque(object.material)),
                    )
                    .unwrap();
            }
        }
        let mut previous = frame::<48, 36, 8, 4>(&scene, &camera);
        for step in 0..3 {
            let before = scene.clone();
            let index = src.below(scene.objects().len() as u64) as usize;
            let what = match scene.objects()[index].shape {
                Shape::Sphere(ball) if !src.one_in(3) => {
                    let c = ball.centre();
                    let nudge = |v: fixray::Fx, s: &mut XorShift| {
                        (v.to_num::<f32>() + s.uniform(2.0)).clamp(-1024.0, 1024.0)
                    };
                    let to = [
                        nudge(c.x, &mut src),
                        nudge(c.y, &mut src),
                        nudge(c.z, &mut src),
                    ];
                    let radius = ball.radius().to_num::<f32>();
                    scene
                        .set_shape(index, Sphere::new(to, radius).unwrap().into())
                        .unwrap();
                    format!("nudge sphere {index} to {to:?}")
                }
                _ => {
                    let other = common::world(&mut src, view, count, false);
                    let Some(&object) = other.objects.get(index) else {
                        continue;
                    };
                    let object = if plain {
                        fixray::Object::new(object.shape, opaque(object.material))
                    } else {
                        object
                    };
                    scene.set_object(index, object).unwrap();
                    format!("swap object {index} for {object:?}")
                }
            };
            let what = format!("hostile seed {seed} step {step}: {what}");
            let (full, damage, _, _) = check_edit(&before, &scene, &camera, &previous, &what);
            edits += 1;
            whole += damage.is_whole() as u32;
            previous = full;
        }
    }
    println!("hostile: {edits} edits, {whole} whole screen");
}

#[test]
fn equal_scenes_damage_nothing() {
    let mut src = XorShift::new(7);
    for _ in 0..20 {
        let world = scene(&mut src);
        let camera = camera(&mut src, Size::new(64, 48));
        let damage = Damage::between(&world, &world.clone(), &camera);
        assert!(damage.is_empty() && !damage.is_whole());
        assert_eq!(damage.pixel_count(), 0);
        assert_eq!(damage.rectangles().count(), 0);
        assert_eq!(damage.row_span(10), None);
    }
}

/// The demo's camera and scene with a small ball added on the ground.
fn demo_with_ball(x: f32, z: f32) -> (Scene<8>, usize) {
    let mut scene = demo::scene();
    let ball = scene
        .add_sphere(
            Sphere::new([x, -3.0, z], 1.0).unwrap(),
            Rgb::new(240, 200, 60),
        )
        .unwrap();
    (scene, ball)
}

#[test]
fn a_new_colour_damages_only_the_sphere() {
    let camera = demo::camera(160, 128).unwrap();
    let (before, ball) = demo_with_ball(-1.0, -9.0);
    let mut after = before.clone();
    after.set_material(ball, Rgb::new(20, 90, 250)).unwrap();
    let damage = Damage::between(&before, &after, &camera);
    let rectangles: Vec<_> = damage.rectangles().collect();
    // The silhouette in a few bands of rows, nothing else.
    assert!((1..=4).contains(&rectangles.len()), "{rectangles:?}");
    // The pixels that see the ball, by the plain path: each in the damage.
    let (mut left, mut top, mut right, mut bottom) = (u32::MAX, u32::MAX, 0, 0);
    for y in 0..128 {
        for x in 0..160 {
            if after.shoot(&camera.ray(x, y)).map(|h| h.object()) == Some(ball) {
                (left, top) = (left.min(x), top.min(y));
                (right, bottom) = (right.max(x + 1), bottom.max(y + 1));
                assert!(
                    damage.row_span(y).is_some_and(|s| s.contains(&x)),
                    "({x}, {y})"
                );
            }
        }
    }
    let (l, t) = rectangles.iter().fold((u32::MAX, u32::MAX), |(l, t), r| {
        (l.min(r.top_left.x as u32), t.min(r.top_left.y as u32))
    });
    let (rr, b) = rectangles.iter().fold((0, 0), |(rr, b), r| {
        let (x, y) = (r.top_left.x as u32, r.top_left.y as u32);
        (rr.max(x + r.size.width), b.max(y + r.size.height))
    });
    println!("sphere seen in {left}..{right} x {top}..{bottom}, damage {l}..{rr} x {t}..{b}");
    assert!(l <= left && t <= top && rr >= right && b >= bottom);
    // The margin around the ball: two pixels (and a rounding), no more.
    assert!(left - l <= 3 && top - t <= 3 && rr - right <= 3 && b - bottom <= 3);
}

#[test]
fn a_new_colour_on_a_bounded_plane_damages_its_rectangle() {
    let camera = demo::camera(96, 64).unwrap();
    let mut before = demo::scene();
    let step = before
        .add_plane(
            Plane::new([0.0, -3.0, 0.0], [0.0, 1.0, 0.0])
                .unwrap()
                .bounded([-2.0, -12.0], [2.0, -8.0])
                .unwrap(),
            Rgb::new(90, 90, 90),
        )
        .unwrap();
    let mut after = before.clone();
    after.set_material(step, Rgb::new(200, 30, 30)).unwrap();
    let damage = Damage::between(&before, &after, &camera);
    assert!(!damage.is_whole() && !damage.is_empty());
    assert!(
        damage.pixel_count() * 4 < 96 * 64,
        "{}",
        damage.pixel_count()
    );
    let mut previous = Framebuffer::<96, 64>::new();
    render(&before, &camera, &mut previous).unwrap();
    check_edit(&before, &after, &camera, &previous, "recolour the step");
    // The infinite ground has no rectangle: the whole screen.
    let mut ground = before.clone();
    ground.set_material(0, Rgb::new(10, 10, 10)).unwrap();
    assert!(Damage::between(&before, &ground, &camera).is_whole());
}

#[test]
fn a_ball_rolling_across_the_demo_floor_damages_a_small_region() {
    let camera = demo::camera(160, 128).unwrap();
    let screen = 160 * 128;
    let (mut scene, ball) = demo_with_ball(-6.0, -9.0);
    let mut previous = Framebuffer::<160, 128>::new();
    render(&scene, &camera, &mut previous).unwrap();
    let (mut damaged, mut changed, mut steps) = (0u32, 0u32, 0u32);
    let mut x = -6.0;
    while x < 6.0 {
        x += 0.25;
        let before = scene.clone();
        scene
            .set_shape(ball, Sphere::new([x, -3.0, -9.0], 1.0).unwrap().into())
            .unwrap();
        let damage = Damage::between(&before, &scene, &camera);
        let mut full = Framebuffer::<160, 128>::new();
        render(&scene, &camera, &mut full).unwrap();
        let mut here = 0;
        for y in 0..128 {
            for col in 0..160 {
                if previous.pixel(col, y) != full.pixel(col, y) {
                    here += 1;
                    let span = damage.row_span(y as u32).unwrap_or(0..0);
                    assert!(span.contains(&(col as u32)), "x = {x}: ({col}, {y}) missed");
                }
            }
        }
        render_changes(&scene, &camera, &damage, &mut previous).unwrap();
        assert!(previous == full, "x = {x}: redraw differs");
        assert!(!damage.is_whole());
        assert!(
            damage.pixel_count() * 5 < screen,
            "x = {x}: {}",
            damage.pixel_count()
        );
        assert!(damage.pixel_count() >= here);
        damaged += damage.pixel_count();
        changed += here;
        steps += 1;
    }
    let (mean_damage, mean_changed) = (damaged / steps, changed / steps);
    println!(
        "radius-1 ball rolling over the demo floor, 160x128, {steps} steps of 0.25: \
         {mean_damage} pixels redrawn a step ({:.1} % of the screen), {mean_changed} changed \
         ({:.1} %), slack {} pixels",
        100.0 * mean_damage as f64 / screen as f64,
        100.0 * mean_changed as f64 / screen as f64,
        mean_damage - mean_changed,
    );
    // Not vacuous: the region is bigger than what changed, and far smaller than the screen.
    assert!(damaged > changed && changed > 0);
    assert!(mean_damage * 10 < screen);
}

#[test]
fn a_damage_that_misses_a_pixel_is_caught() {
    // The oracle itself: redrawing too little (nothing) leaves the frame stale.
    let camera = demo::camera(80, 64).unwrap();
    let (before, ball) = demo_with_ball(0.0, -9.0);
    let mut after = before.clone();
    after
        .set_shape(ball, Sphere::new([0.5, -3.0, -9.0], 1.0).unwrap().into())
        .unwrap();
    let mut stale = Framebuffer::<80, 64>::new();
    render(&before, &camera, &mut stale).unwrap();
    let mut full = Framebuffer::<80, 64>::new();
    render(&after, &camera, &mut full).unwrap();
    render_changes(&after, &camera, &Damage::none(&camera), &mut stale).unwrap();
    assert!(stale != full);
    // And the region is not the trivial answer: smaller than the screen, larger than what
    // changed (its margins).
    let damage = Damage::between(&before, &after, &camera);
    let mut old = Framebuffer::<80, 64>::new();
    render(&before, &camera, &mut old).unwrap();
    let changed = (0..64)
        .flat_map(|y| (0..80).map(move |x| (x, y)))
        .filter(|&(x, y)| old.pixel(x, y) != full.pixel(x, y))
        .count() as u32;
    assert!(!damage.is_whole() && damage.pixel_count() > changed && changed > 0);
}

#[test]
fn the_plain_path_is_the_rows_path() {
    // render_changes traces pixels one by one: the crate's promise that this is render_row's
    // picture, bit for bit, checked on the property test's scenes.
    for seed in 0..40 {
        let mut src = XorShift::new(1000 + seed);
        let world = scene(&mut src);
        let camera = camera(&mut src, Size::new(48, 36));
        let mut row = [Rgb::BLACK; 48];
        let mut span = [Rgb::BLACK; 48];
        for y in 0..36 {
            render_row(&world, &camera, y, &mut row).unwrap();
            render_row_span(&world, &camera, y, 0..48, &mut span).unwrap();
            for x in 0..48 {
                assert_eq!(
                    row[x as usize],
                    world.trace(&camera.ray(x, y)),
                    "seed {seed}"
                );
            }
            assert_eq!(row, span, "seed {seed} row {y}");
        }
    }
}

#[test]
fn bad_sizes_are_errors() {
    let camera = demo::camera(32, 24).unwrap();
    let scene = demo::scene();
    let small = demo::camera(16, 12).unwrap();
    let mut frame = Framebuffer::<32, 24>::new();
    assert!(matches!(
        render_changes(&scene, &camera, &Damage::whole(&small), &mut frame),
        Err(Error::SizeMismatch { .. })
    ));
    let mut other = Framebuffer::<16, 16>::new();
    assert!(matches!(
        render_changes(&scene, &camera, &Damage::whole(&camera), &mut other),
        Err(Error::SizeMismatch { .. })
    ));
    let mut out = [Rgb::BLACK; 4];
    assert_eq!(
        render_row_span(&scene, &camera, 24, 0..4, &mut out),
        Err(Error::RowOutOfRange { row: 24, rows: 24 })
    );
    assert_eq!(
        render_row_span(&scene, &camera, 0, 30..34, &mut out),
        Err(Error::ColumnOutOfRange { col: 33, cols: 32 })
    );
    #[allow(clippy::reversed_empty_ranges)]
    let backwards = 5..1;
    assert_eq!(
        render_row_span(&scene, &camera, 0, backwards, &mut out),
        Err(Error::ColumnOutOfRange { col: 5, cols: 32 })
    );
    assert_eq!(
        render_row_span(&scene, &camera, 0, 0..3, &mut out),
        Err(Error::BufferLength { needed: 3, got: 4 })
    );
    // The whole screen: every row's span is the row.
    let whole = Damage::whole(&camera);
    assert_eq!(whole.row_span(0), Some(0..32));
    assert_eq!(whole.row_span(24), None);
    assert_eq!(whole.pixel_count(), 32 * 24);
    assert_eq!(whole.rectangles().count(), 1);
}

/// `Viewport::redraw` on a display the picture only partly covers (off its left edge, at an
/// offset, dithered to Rgb565): after each frame of the rolling ball, the display equals a
/// fresh render of the frame, and it was sent no more pixels than the damage holds.
#[test]
fn a_viewport_redraws_a_display_through_the_damage() {
    use embedded_graphics::pixelcolor::Rgb565;
    use embedded_graphics::prelude::{DrawTarget, OriginDimensions, Pixel, Point, Size};
    use embedded_graphics_simulator::SimulatorDisplay;
    use fixray::Viewport;

    /// A simulator display that counts the pixels it is sent.
    struct Counted(SimulatorDisplay<Rgb565>, usize);
    impl OriginDimensions for Counted {
        fn size(&self) -> Size {
            self.0.size()
        }
    }
    impl DrawTarget for Counted {
        type Color = Rgb565;
        type Error = core::convert::Infallible;
        fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
            &mut self,
            pixels: I,
        ) -> Result<(), Self::Error> {
            for pixel in pixels {
                self.1 += 1;
                self.0.draw_iter([pixel])?;
            }
            Ok(())
        }
    }

    let camera = fixray::demo::camera(96, 64).unwrap();
    let at = Point::new(-20, 30);
    let mut row = [fixray::Rgb::BLACK; 96];
    let mut display = Counted(SimulatorDisplay::new(Size::new(120, 80)), 0);
    let first = fixray::demo::rolling(0);
    Viewport::at(&first, &camera, at)
        .render(&mut row, &mut display)
        .unwrap();
    for frame in 1..fixray::demo::ROLLING_FRAMES {
        let (before, after) = (
            fixray::demo::rolling(frame - 1),
            fixray::demo::rolling(frame),
        );
        let damage = Damage::between(&before, &after, &camera);
        display.1 = 0;
        Viewport::at(&after, &camera, at)
            .redraw(&damage, &mut row, &mut display)
            .unwrap();
        assert!(
            display.1 as u32 <= damage.pixel_count(),
            "frame {frame}: {} sent",
            display.1
        );
        let mut fresh = SimulatorDisplay::<Rgb565>::new(Size::new(120, 80));
        Viewport::at(&after, &camera, at)
            .render(&mut row, &mut fresh)
            .unwrap();
        assert!(
            display.0 == fresh,
            "frame {frame} differs from a fresh render"
        );
    }
    // The damage must fit the camera.
    let other = fixray::demo::camera(32, 24).unwrap();
    let wrong = Damage::between(&first, &fixray::demo::rolling(1), &other);
    assert!(
        Viewport::at(&first, &camera, at)
            .redraw(&wrong, &mut row, &mut display)
            .is_err()
    );
}
