//! Progressive passes over the crate's own scenes: through a framebuffer and through viewports
//! of full colour and of dithered ones, after each pass and after the last, begun again when
//! the view moves. Random and hostile scenes and cameras go through the same oracle in
//! `tests/hostile.rs` (`common::check_progressive`).

mod common;

use std::collections::HashMap;

use common::Recorder;
use embedded_graphics::pixelcolor::{BinaryColor, PixelColor, Rgb565};
use embedded_graphics::prelude::{Point, Size};
use fixray::{
    Camera, Error, Framebuffer, MAX_SPACING, Pass, Rgb, Scene, Viewport, demo, render, render_pass,
    render_pass_row,
};

fn recorder<C>(width: u32, height: u32) -> Recorder<C> {
    Recorder {
        size: Size::new(width, height),
        pixels: HashMap::new(),
    }
}

/// The frame `render` draws, for a camera of `W × H`.
fn full<const N: usize, const W: usize, const H: usize>(
    scene: &Scene<N>,
    camera: &Camera,
) -> Framebuffer<W, H> {
    let mut frame = Framebuffer::new();
    render(scene, camera, &mut frame).unwrap();
    frame
}

/// Every pass of `coarsest`'s sequence into a framebuffer: after each pass, each pixel shows
/// the full frame's pixel at the corner of its block, and after the last it is the full frame.
fn passes_end_on_the_frame<const N: usize, const W: usize, const H: usize>(
    scene: &Scene<N>,
    camera: &Camera,
    coarsest: u16,
) {
    let want = full::<N, W, H>(scene, camera);
    let mut frame = Framebuffer::<W, H>::new();
    for pass in Pass::sequence(coarsest).unwrap() {
        render_pass(scene, camera, pass, &mut frame).unwrap();
        let (bw, bh) = (pass.block().width as usize, pass.block().height as usize);
        for y in 0..H {
            for x in 0..W {
                assert_eq!(
                    frame.pixel(x, y),
                    want.pixel(x - x % bw, y - y % bh),
                    "from {coarsest}, after the pass {pass:?}: pixel ({x}, {y})"
                );
            }
        }
    }
    assert_eq!(frame, want, "from {coarsest}");
}

#[test]
fn the_demo_and_classic_scenes_end_on_their_frames_from_every_spacing() {
    for coarsest in [1, 2, 4, 8, 16, 32, 64] {
        let camera = demo::camera(61, 37).unwrap();
        passes_end_on_the_frame::<8, 61, 37>(&demo::scene(), &camera, coarsest);
        let camera = demo::classic_camera(40, 30).unwrap();
        passes_end_on_the_frame::<8, 40, 30>(&demo::classic(), &camera, coarsest);
    }
    // Screens narrower and shorter than the first pass's blocks.
    let camera = demo::camera(5, 3).unwrap();
    passes_end_on_the_frame::<8, 5, 3>(&demo::scene(), &camera, 64);
}

#[test]
fn passes_from_eight_trace_a_sixty_fourth_then_three_then_the_even_rows_then_the_odd() {
    let (scene, camera) = (demo::scene(), demo::camera(160, 128).unwrap());
    let mut row = [Rgb::BLACK; 160];
    let (mut counts, mut rows) = (Vec::new(), Vec::new());
    for pass in Pass::sequence(8).unwrap() {
        let (mut count, mut traced) = (0, 0);
        for y in 0..128 {
            let n = render_pass_row(&scene, &camera, pass, y, &mut row).unwrap();
            (count, traced) = (count + n, traced + usize::from(n > 0));
        }
        counts.push(count);
        rows.push(traced);
    }
    // Each row is set up once a pass that traces it: 1⅜ times on average, not 1⅞ as halving
    // the spacing down to 1 would.
    assert_eq!(rows, [16, 32, 64, 64]);
    let pixels = 160 * 128;
    assert_eq!(
        counts,
        [
            pixels / 64,
            3 * pixels / 64,
            28 * pixels / 64,
            32 * pixels / 64
        ]
    );
}

/// The passes drawn through a viewport onto a display of colour `C` at `corner`, each pass
/// checked as it lands, end on the viewport's own render.
fn viewport_passes_end_on_its_render<C: PixelColor + fixray::FromRgb + std::fmt::Debug>(
    corner: Point,
) {
    let (scene, camera) = (demo::classic(), demo::classic_camera(48, 32).unwrap());
    let view = Viewport::at(&scene, &camera, corner);
    let mut row = [Rgb::BLACK; 48];
    let mut rendered = recorder::<C>(40, 40);
    view.render(&mut row, &mut rendered).unwrap();
    let frame = full::<_, 48, 32>(&scene, &camera);
    for coarsest in [1, 4, 8, 64] {
        let mut passed = recorder::<C>(40, 40);
        for pass in Pass::sequence(coarsest).unwrap() {
            view.render_pass(pass, &mut row, &mut passed).unwrap();
            // Each pixel shown: its block's traced pixel, converted at its own place.
            let (bw, bh) = (pass.block().width as i32, pass.block().height as i32);
            for (&(px, py), &got) in &passed.pixels {
                let p = Point::new(px, py);
                let (x, y) = (px - corner.x, py - corner.y);
                let traced = frame.pixel((x - x % bw) as usize, (y - y % bh) as usize);
                let want = C::from_rgb(traced.unwrap(), p);
                assert_eq!(got, want, "from {coarsest}, {pass:?}, at {p:?}");
            }
        }
        assert!(
            passed.pixels == rendered.pixels,
            "from {coarsest} at {corner:?}: {} pixels against {}",
            passed.pixels.len(),
            rendered.pixels.len()
        );
    }
}

#[test]
fn viewports_end_on_their_render_in_full_and_dithered_colour_wherever_they_are() {
    for corner in [Point::zero(), Point::new(-5, 9), Point::new(30, -3)] {
        viewport_passes_end_on_its_render::<Rgb565>(corner);
        viewport_passes_end_on_its_render::<BinaryColor>(corner);
    }
}

#[test]
fn a_sequence_begun_again_for_a_moved_view_leaves_nothing_of_the_old_one() {
    let scene = demo::scene();
    let old = demo::camera(40, 30).unwrap();
    let moved = Camera::orbit([0.0, 0.0, -16.0], 22.0)
        .yaw_degrees(30.0)
        .pitch_degrees(20.0)
        .size(Size::new(40, 30))
        .build()
        .unwrap();
    let want = full::<8, 40, 30>(&scene, &moved);
    let mut row = [Rgb::BLACK; 40];
    let mut frame = Framebuffer::<40, 30>::new();
    let mut display = recorder::<Rgb565>(40, 30);
    let old_view = Viewport::at(&scene, &old, Point::zero());
    // The old view's first two passes, and the third abandoned half-way down.
    for (k, pass) in Pass::sequence(8).unwrap().enumerate().take(3) {
        let rows = if k == 2 { 0..15 } else { 0..30 };
        old_view
            .render_pass_rows(pass, rows, &mut row, &mut display)
            .unwrap();
        render_pass(&scene, &old, pass, &mut frame).unwrap();
    }
    let new_view = Viewport::at(&scene, &moved, Point::zero());
    for pass in Pass::sequence(4).unwrap() {
        new_view.render_pass(pass, &mut row, &mut display).unwrap();
        render_pass(&scene, &moved, pass, &mut frame).unwrap();
    }
    assert_eq!(frame, want);
    let mut fresh = recorder::<Rgb565>(40, 30);
    new_view.render(&mut row, &mut fresh).unwrap();
    assert!(display.pixels == fresh.pixels);
}

#[test]
fn bad_spacings_rows_buffers_and_sizes_are_refused() {
    for spacing in [0, 3, 6, 100, 128, MAX_SPACING + 1, u16::MAX] {
        assert_eq!(
            Pass::sequence(spacing).err(),
            Some(Error::PassSpacing { spacing })
        );
    }
    assert_eq!(
        Pass::sequence(MAX_SPACING).unwrap().count(),
        MAX_SPACING.trailing_zeros() as usize + 1
    );
    let (scene, camera) = (demo::scene(), demo::camera(16, 8).unwrap());
    let first = Pass::sequence(4).unwrap().next().unwrap();
    let mut row = [Rgb::BLACK; 16];
    for y in [8, 9, u32::MAX] {
        assert_eq!(
            render_pass_row(&scene, &camera, first, y, &mut row),
            Err(Error::RowOutOfRange { row: y, rows: 8 })
        );
    }
    assert_eq!(
        render_pass_row(&scene, &camera, first, 4, &mut row[..3]),
        Err(Error::BufferLength { needed: 4, got: 3 })
    );
    let mut wrong = Framebuffer::<16, 9>::new();
    assert!(matches!(
        render_pass(&scene, &camera, first, &mut wrong),
        Err(Error::SizeMismatch { .. })
    ));
    let view = Viewport::at(&scene, &camera, Point::zero());
    let mut display = recorder::<Rgb565>(16, 8);
    assert!(
        view.render_pass(first, &mut row[..15], &mut display)
            .is_err()
    );
    assert!(
        view.render_pass_rows(first, 0..9, &mut row, &mut display)
            .is_err()
    );
    assert!(
        display.pixels.is_empty(),
        "nothing drawn for a refused pass"
    );
}
