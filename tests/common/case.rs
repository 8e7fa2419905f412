//! The random case driver: one [`Case`] (a world, a camera, rows, a supersampling factor) drawn
//! from a [`Source`], and every check run on it.

use fixray::{Camera, Vec3};

use super::camera_spec::rounded3;
use super::{
    CameraSpec, Source, View, World, camera_spec, check_camera_spec, check_framebuffer,
    check_progressive, check_rays_past_the_screen, check_row, check_shadows, check_supersampled,
    check_viewport, world,
};

/// Everything one case draws: a world, a camera, rows, and how hard to push.
#[derive(Debug, Clone)]
pub struct Case {
    pub capacity: usize,
    pub world: World,
    pub camera: CameraSpec,
    pub rows: Vec<u32>,
    pub supersample: u8,
}

/// A case: a camera (hostile one value in six), a world of up to 12 objects in a scene of 8, or
/// 66 to 140 in scenes of 70 and 130 where the objects in view come past the 64th.
pub fn case(src: &mut impl Source) -> Case {
    let camera = camera_spec(src, 6);
    let view = match camera {
        CameraSpec::LookAt { eye, target, .. } => match (rounded3(eye), rounded3(target)) {
            (Some(e), Some(t)) => View {
                eye: e,
                forward: (t - e).try_normalize().unwrap_or(-Vec3::Z),
            },
            _ => View {
                eye: Vec3::ZERO,
                forward: -Vec3::Z,
            },
        },
        _ => View {
            eye: Vec3::ZERO,
            forward: -Vec3::Z,
        },
    };
    let (capacity, count, crowded) = match src.below(6) {
        0 => (70, 66 + src.below(5) as usize, true),
        1 => (130, 66 + src.below(75) as usize, true),
        _ => (8, 1 + src.below(12) as usize, false),
    };
    let world = world(src, view, count, crowded);
    let rows = (0..2 + src.below(3))
        .map(|_| {
            if src.one_in(6) {
                src.pick(&[30, 40000, u32::from(u16::MAX) + 1, u32::MAX])
            } else {
                src.below(30) as u32
            }
        })
        .collect();
    Case {
        capacity,
        world,
        camera,
        rows,
        supersample: src.pick(&[0, 1, 2, 3, 17, 255]),
    }
}

/// Runs every check of one case.
pub fn run_case(src: &mut impl Source, case: &Case) {
    let Some(camera) = check_camera_spec(&case.camera, false) else {
        return;
    };
    match case.capacity {
        70 => run_scene::<70>(src, case, &camera),
        130 => run_scene::<130>(src, case, &camera),
        _ => run_scene::<8>(src, case, &camera),
    }
    check_rays_past_the_screen(&case.camera, &camera);
}

fn run_scene<const N: usize>(src: &mut impl Source, case: &Case, camera: &Camera) {
    let Some(scene) = case.world.build::<N>() else {
        return;
    };
    // Big screens are checked on one row, small ones whole: a few seconds in a debug build.
    let (cols, rows) = (camera.width() as usize, camera.height() as usize);
    let small = cols * rows <= 40 * 30;
    let mut checked_rows: Vec<u32> = case.rows.clone();
    if small {
        checked_rows.extend(0..camera.height());
    }
    let mut frame = vec![Vec::new(); if small { rows } else { 0 }];
    for &row in &checked_rows {
        let line = check_row(&scene, camera, row);
        if (row as usize) < frame.len() {
            frame[row as usize] = line.clone();
        }
        if (row as usize) < rows && cols <= 64 && case.rows.contains(&row) {
            let n = if cols <= 8 {
                case.supersample
            } else {
                case.supersample.min(3)
            };
            check_supersampled(&scene, camera, row, n, &line);
        }
        if case.rows.contains(&row) && cols <= 64 {
            check_shadows::<N>(&case.world, camera, row);
        }
    }
    if small {
        check_viewport(src, &scene, camera, &frame);
        check_framebuffer::<N, 12, 9>(src, &scene, camera, &frame);
        check_progressive(src, &scene, camera, &frame);
    }
}
