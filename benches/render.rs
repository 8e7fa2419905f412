//! The demo frame at 160 × 128, rendered by the fixed-point renderer and by the f64 reference
//! in one run, so their medians can be compared side by side.
//!
//! ```text
//! cargo bench --bench render
//! ```

use criterion::{Criterion, criterion_group, criterion_main};
use fixray::{Framebuffer, Rgb, demo, render};
use fixray_reference::{self as reference, DScene};
use std::hint::black_box;

const W: u32 = 160;
const H: u32 = 128;

fn frame(c: &mut Criterion) {
    let scene = demo::scene();
    let camera = demo::camera(W, H).unwrap();
    let dscene = DScene::from_scene(&scene).unwrap();
    let dcamera = reference::demo_camera::<f64>(W, H).unwrap();

    let mut group = c.benchmark_group("demo 160x128 frame");
    let mut fixed = Box::new(Framebuffer::<{ W as usize }, { H as usize }>::new());
    group.bench_function("fixed Q16.16", |b| {
        b.iter(|| render(black_box(&scene), black_box(&camera), &mut fixed).unwrap())
    });
    let mut float = vec![Rgb::BLACK; W as usize * H as usize];
    group.bench_function("f64 reference", |b| {
        b.iter(|| reference::render(black_box(&dscene), black_box(&dcamera), &mut float))
    });
    group.finish();
}

criterion_group!(benches, frame);
criterion_main!(benches);
