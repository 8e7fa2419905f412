//! Animation by redrawing only what changed: a small ball rolls across the demo's floor at
//! 160 × 128, and each frame redraws the pixels `Damage::between` bounds, not the screen.
//!
//! ```text
//! cargo run --release --example animate
//! ```
//!
//! Each line is one frame: the rectangles of the damage, the pixels redrawn and the pixels
//! that did change, and the time to bound and redraw against a full render. Every redrawn
//! frame is checked against a full render of the same scene, bit for bit.

use std::time::{Duration, Instant};

use fixray::{Damage, Framebuffer, Rgb, Sphere, demo, render, render_changes};

const W: usize = 160;
const H: usize = 128;

fn main() -> Result<(), fixray::Error> {
    let camera = demo::camera(W as u32, H as u32)?;
    let mut scene = demo::scene();
    let ball = scene.add_sphere(
        Sphere::new([-6.0, -3.0, -9.0], 1.0)?,
        Rgb::new(240, 200, 60),
    )?;
    let mut frame = Box::new(Framebuffer::<W, H>::new());
    render(&scene, &camera, &mut frame)?;
    let mut full = Box::new(Framebuffer::<W, H>::new());
    let (mut partial_time, mut full_time) = (Duration::ZERO, Duration::ZERO);
    let (mut redrawn, mut changed, mut frames) = (0u64, 0u64, 0u64);
    println!("frame  x      rects  redrawn  changed  bound+redraw  full render");
    for step in 1..=48 {
        let x = -6.0 + 0.25 * step as f32;
        let before = scene.clone();
        scene.set_shape(ball, Sphere::new([x, -3.0, -9.0], 1.0)?.into())?;

        let started = Instant::now();
        let damage = Damage::between(&before, &scene, &camera);
        let previous = frame.clone();
        render_changes(&scene, &camera, &damage, &mut frame)?;
        let partial = started.elapsed();

        let started = Instant::now();
        render(&scene, &camera, &mut full)?;
        let whole = started.elapsed();
        assert!(
            frame == full,
            "frame {step}: the redraw differs from a full render"
        );

        let differ = (0..H)
            .flat_map(|y| (0..W).map(move |x| (x, y)))
            .filter(|&(x, y)| previous.pixel(x, y) != full.pixel(x, y))
            .count() as u64;
        println!(
            "{step:>5}  {x:>5.2}  {:>5}  {:>7}  {differ:>7}  {:>9.0} µs  {:>8.0} µs",
            damage.rectangles().count(),
            damage.pixel_count(),
            partial.as_secs_f64() * 1e6,
            whole.as_secs_f64() * 1e6,
        );
        partial_time += partial;
        full_time += whole;
        redrawn += u64::from(damage.pixel_count());
        changed += differ;
        frames += 1;
    }
    let screen = (W * H) as f64;
    println!(
        "mean a frame: {:.0} pixels redrawn ({:.1} % of the screen), {:.0} changed; \
         {:.0} µs against {:.0} µs for a full render",
        redrawn as f64 / frames as f64,
        100.0 * redrawn as f64 / frames as f64 / screen,
        changed as f64 / frames as f64,
        partial_time.as_secs_f64() * 1e6 / frames as f64,
        full_time.as_secs_f64() * 1e6 / frames as f64,
    );
    Ok(())
}
