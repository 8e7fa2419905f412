//! Oracles for rows: every row entry point against the per-pixel trace, supersampling against
//! the mean of its sample rays, and shadows against a brute-force occlusion test.

use std::collections::HashMap;

use fixray::{Camera, Fx, Light, Rgb, Scene, SceneHit};

use super::{UNIT_TOLERANCE, World, check_hit, check_surface_through_origin, length};

/// [ASSERT: render_row equals per-pixel trace; shoot_row and shoot_row_skipping equal shoot]
/// One row, every entry point: the rendered pixels, the rows of hits and the skipped runs
/// against the per-pixel ray of the camera, traced one by one. Also every hit (check_hit) and
/// the surface-through-origin rule. Rows past the screen are refused by `render_row` and
/// `render_row_supersampled`.
pub fn check_row<const N: usize>(scene: &Scene<N>, camera: &Camera, row: u32) -> Vec<Rgb> {
    let cols = camera.width() as usize;
    let mut out = vec![Rgb::BLACK; cols];
    let rendered = fixray::render_row(scene, camera, row, &mut out);
    // [ASSERT: Err for rows out of range and wrong buffers]
    let mut short = vec![Rgb::BLACK; cols - 1];
    assert!(
        fixray::render_row(scene, camera, row, &mut short).is_err(),
        "short buffer"
    );
    let mut long = vec![Rgb::BLACK; cols + 1];
    assert!(
        fixray::render_row(scene, camera, row, &mut long).is_err(),
        "long buffer"
    );
    let mut hits = Vec::with_capacity(cols);
    let shot_row = fixray::shoot_row(scene, camera, row, |col, ray, hit| {
        hits.push((col, *ray, hit))
    });
    let mut skipped = Vec::new();
    let mut seen = Vec::new();
    let skipped_row = fixray::internals::shoot_row_skipping(
        scene,
        camera,
        row,
        |run| skipped.push(run),
        |col, ray, hit| seen.push((col, *ray, hit)),
    );
    if row >= camera.height() {
        assert!(
            rendered.is_err(),
            "render_row({row}) past the screen must be refused"
        );
        assert!(
            fixray::render_row_supersampled(scene, camera, row, 2, &mut out).is_err(),
            "render_row_supersampled({row}) past the screen must be refused"
        );
        // Every row entry point refuses the row the same way, and hands nothing over.
        let refused = fixray::Error::RowOutOfRange {
            row,
            rows: camera.height(),
        };
        assert_eq!(rendered, Err(refused), "render_row({row})");
        assert_eq!(shot_row, Err(refused), "shoot_row({row})");
        assert_eq!(skipped_row, Err(refused), "shoot_row_skipping({row})");
        assert!(hits.is_empty() && seen.is_empty() && skipped.is_empty());
        assert!(camera.row_rays(row).is_err(), "row_rays({row})");
        return Vec::new();
    }
    shot_row.unwrap_or_else(|e| panic!("shoot_row({row}) refused a row on the screen: {e}"));
    skipped_row
        .unwrap_or_else(|e| panic!("shoot_row_skipping({row}) refused a row on the screen: {e}"));
    rendered.unwrap_or_else(|e| panic!("render_row({row}) refused a row on the screen: {e}"));
    assert_eq!(hits.len(), cols, "shoot_row hands over every column");
    for (col, (c, ray, hit)) in hits.iter().enumerate() {
        assert_eq!(*c as usize, col, "shoot_row in column order");
        let own = camera.ray(*c, row);
        assert_eq!(*ray, own, "shoot_row's ray is the camera's, column {col}");
        let shot = scene.shoot(&own);
        assert_eq!(
            *hit, shot,
            "shoot_row's hit is shoot's, row {row} column {col}"
        );
        check_hit(scene, &own, shot);
        check_surface_through_origin(scene, &own);
        let traced = scene.trace(&own);
        assert_eq!(
            scene.shade(&own, shot.as_ref()),
            traced,
            "trace is shade(shoot)"
        );
        assert_eq!(
            out[col], traced,
            "render_row({row}) differs from trace at column {col}"
        );
    }
    // shoot_row_skipping: every column once, in order; skipped runs meet nothing.
    let mut next = 0u32;
    let (mut s, mut e) = (skipped.iter().peekable(), seen.iter().peekable());
    while (next as usize) < cols {
        if let Some(run) = s.peek()
            && run.start == next
        {
            assert!(run.end > run.start, "an empty skipped run");
            for col in (*run).clone() {
                let ray = camera.ray(col, row);
                assert_eq!(
                    scene.shoot(&ray),
                    None,
                    "shoot_row_skipping skipped column {col} of row {row}, which hits"
                );
            }
            next = run.end;
            s.next();
        } else if let Some((col, ray, hit)) = e.peek()
            && *col == next
        {
            assert_eq!(*ray, camera.ray(*col, row));
            assert_eq!(*hit, scene.shoot(ray));
            next += 1;
            e.next();
        } else {
            panic!("shoot_row_skipping left out column {next} of row {row}");
        }
    }
    assert!(
        s.next().is_none() && e.next().is_none(),
        "columns past the row"
    );
    out
}

/// [ASSERT: supersampling] `n` of 0 and 1 give `render_row`; larger `n` the rounded mean of the
/// traced sample rays (n clamped to 16).
pub fn check_supersampled<const N: usize>(
    scene: &Scene<N>,
    camera: &Camera,
    row: u32,
    n: u8,
    plain: &[Rgb],
) {
    let mut out = vec![Rgb::BLACK; camera.width() as usize];
    fixray::render_row_supersampled(scene, camera, row, n, &mut out)
        .unwrap_or_else(|e| panic!("render_row_supersampled({row}, {n}): {e}"));
    if n <= 1 {
        assert_eq!(out, plain, "supersampling by {n} is render_row");
        return;
    }
    let n = n.min(16);
    for (col, pixel) in (0..).zip(out.iter()) {
        let mut sum = [0u32; 3];
        for sy in 0..n {
            for sx in 0..n {
                let ray = camera.sample_ray(col, row, sx, sy, n);
                let length = length(ray.dir());
                assert!((length - 1.0).abs() <= UNIT_TOLERANCE, "sample ray {ray:?}");
                let c = scene.trace(&ray);
                sum = [
                    sum[0] + c.r as u32,
                    sum[1] + c.g as u32,
                    sum[2] + c.b as u32,
                ];
            }
        }
        let count = n as u32 * n as u32;
        let mean = sum.map(|s| ((s + count / 2) / count) as u8);
        assert_eq!(
            *pixel,
            Rgb::new(mean[0], mean[1], mean[2]),
            "column {col}, n {n}"
        );
    }
}

/// [ASSERT: shadows equal a brute-force occlusion test] For each pixel whose first hit is a
/// surface that does not mirror (the pixel is then that surface's own light), the light
/// reaching it is decided here by brute force: a shadow ray from the hit point towards each
/// light, the light's direction normalised from its exact squared distance, testing every
/// object but the one the ray leaves, occluded when some hit distance `t` has `t² < distance²`
/// (both exact, in Q32.32). The pixel with shadows on must then equal the pixel of the same
/// scene lit only by the lights found unoccluded, with shadows off.
///
/// Mirrors and glass are left out: their secondary rays start from points the public API does
/// not give (they are private to the shading), so the same brute force cannot follow them.
pub fn check_shadows<const N: usize>(world: &World, camera: &Camera, row: u32) {
    if row >= camera.height() {
        return;
    }
    let Some(scene) = world.build_with_lights::<N>(&world.lights, true) else {
        return;
    };
    let mut lit_only: HashMap<u32, Scene<N>> = HashMap::new();
    for col in 0..camera.width() {
        let ray = camera.ray(col, row);
        let Some(hit) = scene.shoot(&ray) else {
            continue;
        };
        let material = scene.objects()[hit.object()].material;
        if material.reflect() != Fx::ZERO || material.refraction().is_some() {
            continue;
        }
        let mut mask = 0u32;
        for (li, light) in scene.lights().iter().enumerate() {
            if !occluded(&scene, &hit, light) {
                mask |= 1 << li;
            }
        }
        let unshadowed = lit_only.entry(mask).or_insert_with(|| {
            let lights: Vec<Light> = (scene.lights().iter().enumerate())
                .filter(|(i, _)| mask & (1 << i) != 0)
                .map(|(_, l)| *l)
                .collect();
            world
                .build_with_lights::<N>(&lights, false)
                .expect("the same objects fit")
        });
        assert_eq!(
            scene.trace(&ray),
            unshadowed.trace(&ray),
            "row {row} column {col}: shadows differ from the brute-force test \
             (lights reaching the hit: {mask:#b}; hit {hit:?})"
        );
    }
}

/// Whether anything but the object `hit` is on lies between it and `light`, by brute force.
pub fn occluded<const N: usize>(scene: &Scene<N>, hit: &SceneHit, light: &Light) -> bool {
    let to_light = light.position() - hit.hit().point();
    let distance_squared = fixray::internals::length_squared_wide(to_light);
    // The shadow ray's direction is `to_light` normalised, as the renderer's is; its origin is
    // a hit point, which may lie past ±LIMIT (up to LIMIT + FAR).
    let Ok(shadow) = fixray::internals::ray_from_hit_point(hit.hit().point(), to_light) else {
        return false; // a light at the hit point: it lights nothing there either way
    };
    scene.objects().iter().enumerate().any(|(i, object)| {
        i != hit.object()
            && object.shape.intersect(&shadow).is_some_and(|hit| {
                let t = hit.t().to_bits() as u32 as u64;
                t * t < distance_squared
            })
    })
}
