//! How the cost of a frame grows with the scene: seeded random fields of 16, 63, 64, 65, 128
//! and 256 spheres on a ground plane under two lights, at 160 × 128, in one run (63 spheres
//! and the plane are 64 objects, the most a scene's 64-bit culling masks name one by one). Criterion's
//! throughput is in pixels, so each size's time a pixel and its ratio to 16's can be read off
//! side by side (docs/PERFORMANCE.md).
//!
//! On a shared host one size's time moves between runs, and so does the ratio of two sizes
//! timed a few seconds apart; so the bench then draws the sizes in turn, 40 frames each, and
//! prints each size's fastest frame a pixel and its ratio to 16's: the steadier figure.
//!
//! ```text
//! cargo bench --bench sphere_fields
//! ```

use criterion::{Criterion, Throughput, criterion_group};
use fixray::{Camera, Framebuffer, Light, Material, Plane, Rgb, Scene, Size, Sphere, render};
use std::hint::black_box;

const W: u32 = 160;
const H: u32 = 128;

/// Marsaglia's xorshift64 from a fixed seed: every run draws the same fields.
struct XorShift(u64);

impl XorShift {
    /// A value drawn evenly from `lo..hi`.
    fn between(&mut self, lo: f32, hi: f32) -> f32 {
        let s = &mut self.0;
        *s ^= *s << 13;
        *s ^= *s >> 7;
        *s ^= *s << 17;
        lo + (*s >> 40) as f32 / (1u64 << 24) as f32 * (hi - lo)
    }
}

/// A field of `N − 1` spheres of radius 0.4 to 1.4 on or up to 2 above the ground plane
/// `y = 0`, scattered over the patch 5 to 45 away in front of the camera that it sees, a fifth of
/// them shiny; lit by two lights. The same seed for every size: a larger field holds a smaller
/// one's spheres and more.
fn field<const N: usize>() -> Scene<N, 2> {
    let mut rng = XorShift(0x5eed_f1e1_d0f5_fe5e);
    let key = Light::new([-20.0, 30.0, 20.0], 0.7).unwrap();
    let fill = Light::new([25.0, 18.0, -10.0], 0.5).unwrap();
    let mut scene: Scene<N, 2> = Scene::new(key, 0.15, Rgb::new(40, 70, 160)).unwrap();
    scene.add_light(fill).unwrap();
    let ground = Plane::new([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
    scene.add_plane(ground, Rgb::new(150, 150, 140)).unwrap();
    while scene.objects().len() < N {
        let z = rng.between(-45.0, -5.0);
        // The patch widens with the distance, as the view does.
        let x = rng.between(-1.0, 1.0) * (3.0 - z * 0.5);
        let radius = rng.between(0.4, 1.4);
        let lift = if rng.between(0.0, 1.0) < 0.7 {
            0.0
        } else {
            rng.between(0.0, 2.0)
        };
        let colour = Rgb::new(
            rng.between(40.0, 250.0) as u8,
            rng.between(40.0, 250.0) as u8,
            rng.between(40.0, 250.0) as u8,
        );
        let material = if rng.between(0.0, 1.0) < 0.2 {
            Material::new(colour, 0.8, 0.4, 30, 0.0).unwrap()
        } else {
            Material::matte(colour)
        };
        let sphere = Sphere::new([x, radius + lift, z], radius).unwrap();
        scene.add_sphere(sphere, material).unwrap();
    }
    scene
}

/// The camera every field is seen through: from 7 above the ground, looking down the patch.
fn camera() -> Camera {
    Camera::look_at([0.0, 7.0, 8.0], [0.0, 0.0, -20.0])
        .size(Size::new(W, H))
        .build()
        .unwrap()
}

/// Times the frame of a field of `N − 1` spheres.
fn bench_field<const N: usize>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    frame: &mut Framebuffer<{ W as usize }, { H as usize }>,
) {
    let (scene, camera) = (field::<N>(), camera());
    group.bench_function(format!("{} spheres", N - 1), |b| {
        b.iter(|| render(black_box(&scene), black_box(&camera), frame).unwrap())
    });
}

fn fields(c: &mut Criterion) {
    let mut group = c.benchmark_group("sphere fields 160x128");
    group.throughput(Throughput::Elements(u64::from(W * H)));
    let mut frame = Box::new(Framebuffer::<{ W as usize }, { H as usize }>::new());
    bench_field::<17>(&mut group, &mut frame);
    bench_field::<64>(&mut group, &mut frame);
    bench_field::<65>(&mut group, &mut frame);
    bench_field::<66>(&mut group, &mut frame);
    bench_field::<129>(&mut group, &mut frame);
    bench_field::<257>(&mut group, &mut frame);
    group.finish();
}

/// Each size's fastest of `rounds` frames, the sizes drawn in turn, in ns a pixel and as a
/// multiple of 16 spheres'.
fn fastest_in_turn(rounds: u32) {
    let (s16, s63, s64, s128, s256) = (
        field::<17>(),
        field::<64>(),
        field::<65>(),
        field::<129>(),
        field::<257>(),
    );
    let camera = camera();
    let mut frame = Box::new(Framebuffer::<{ W as usize }, { H as usize }>::new());
    let mut fastest = [f64::MAX; 5];
    for _ in 0..rounds {
        let mut time =
            |k: usize, draw: &mut dyn FnMut(&mut Framebuffer<{ W as usize }, { H as usize }>)| {
                let start = std::time::Instant::now();
                draw(&mut frame);
                fastest[k] = fastest[k].min(start.elapsed().as_secs_f64());
            };
        time(0, &mut |f| render(black_box(&s16), &camera, f).unwrap());
        time(1, &mut |f| render(black_box(&s63), &camera, f).unwrap());
        time(2, &mut |f| render(black_box(&s64), &camera, f).unwrap());
        time(3, &mut |f| render(black_box(&s128), &camera, f).unwrap());
        time(4, &mut |f| render(black_box(&s256), &camera, f).unwrap());
    }
    let ns = fastest.map(|t| t * 1e9 / f64::from(W * H));
    println!("fastest of {rounds} frames, sizes in turn, ns a pixel (x 16's):");
    for (spheres, each) in [16, 63, 64, 128, 256].iter().zip(ns) {
        println!("  {spheres:3} spheres: {each:6.1} ({:.2})", each / ns[0]);
    }
}

criterion_group!(benches, fields);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    fastest_in_turn(40);
}
