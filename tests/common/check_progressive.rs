//! The oracle for progressive passes: each pass's traced pixels are the rendered frame's, each
//! pixel after a pass shows its block corner's colour, every pixel is traced once, and the
//! passes drawn through a viewport (dithered, at a hostile corner) end on the viewport's
//! render.

use std::collections::HashMap;

use embedded_graphics::pixelcolor::Gray8;
use embedded_graphics::prelude::Size;
use fixray::{
    Camera, Error, Framebuffer, Pass, Rgb, Scene, Viewport, render_pass, render_pass_row,
};

use super::{Recorder, Source, corner};

/// [ASSERT: progressive passes end on the frame] For a coarsest spacing drawn from `src`:
/// every pixel [`render_pass_row`] gives is `frame`'s pixel at its column, in the order
/// `Pass::columns` names; painting each one's block, after a pass of blocks `w × h` pixel
/// `(x, y)` shows `frame`'s pixel at `(x − x mod w, y − y mod h)`; every pixel is traced
/// exactly once over the passes; and the same passes drawn into a [`Framebuffer`], or through
/// a [`Viewport`] onto a dithered display, leave it as the frame and [`Viewport::render`] do.
pub fn check_progressive<const N: usize>(
    src: &mut impl Source,
    scene: &Scene<N>,
    camera: &Camera,
    frame: &[Vec<Rgb>],
) {
    let (w, h) = (camera.width() as usize, camera.height() as usize);
    let coarsest = src.pick(&[1, 2, 4, 8, 16, 64]);
    let mut shown: Vec<Vec<Option<Rgb>>> = vec![vec![None; w]; h];
    let mut traced = vec![vec![0u8; w]; h];
    let mut line = vec![Rgb::BLACK; w];
    let passes: Vec<Pass> = Pass::sequence(coarsest).expect("a power of two").collect();
    assert_eq!(
        passes.last().map(|p| p.spacing()),
        Some(1),
        "the passes end at spacing 1"
    );
    for &pass in &passes {
        let block = pass.block();
        let (bw, bh) = (block.width as usize, block.height as usize);
        for y in 0..h {
            let n = render_pass_row(scene, camera, pass, y as u32, &mut line).expect("a row");
            let columns: Vec<usize> = pass
                .columns(y as u32)
                .flat_map(|(first, step)| (first as usize..w).step_by(step as usize))
                .collect();
            assert_eq!(n, columns.len(), "pass {pass:?}, row {y}");
            for (i, &x) in columns.iter().enumerate() {
                assert_eq!(line[i], frame[y][x], "pass {pass:?}: pixel ({x}, {y})");
                traced[y][x] += 1;
                for row in shown.iter_mut().skip(y).take(bh) {
                    for pixel in row.iter_mut().skip(x).take(bw) {
                        *pixel = Some(line[i]);
                    }
                }
            }
        }
        for (y, row) in shown.iter().enumerate() {
            for (x, pixel) in row.iter().enumerate() {
                let corner = frame[y - y % bh][x - x % bw];
                assert_eq!(
                    *pixel,
                    Some(corner),
                    "after pass {pass:?}: pixel ({x}, {y})"
                );
            }
        }
    }
    assert!(
        traced.iter().flatten().all(|&n| n == 1),
        "every pixel traced exactly once"
    );
    // A row past the screen, and a buffer too short for a traced row, are refused.
    let first = passes[0];
    assert_eq!(
        render_pass_row(scene, camera, first, h as u32, &mut line),
        Err(Error::RowOutOfRange {
            row: h as u32,
            rows: h as u32
        })
    );
    let needed = (w as u32).div_ceil(u32::from(first.spacing())) as usize;
    assert_eq!(
        render_pass_row(scene, camera, first, 0, &mut line[..needed - 1]),
        Err(Error::BufferLength {
            needed,
            got: needed - 1
        })
    );
    // Into a framebuffer of the camera's size (the cases draw 12 × 9 one time in four), and
    // of any other, which is refused.
    let mut framebuffer = Framebuffer::<12, 9>::new();
    for &pass in &passes {
        let done = render_pass(scene, camera, pass, &mut framebuffer);
        if (w, h) != (12, 9) {
            assert!(matches!(done, Err(Error::SizeMismatch { .. })), "{w} x {h}");
            break;
        }
        assert_eq!(done, Ok(()));
    }
    if (w, h) == (12, 9) {
        for (y, row) in frame.iter().enumerate() {
            for (x, &pixel) in row.iter().enumerate() {
                assert_eq!(
                    framebuffer.pixel(x, y),
                    Some(pixel),
                    "framebuffer ({x}, {y})"
                );
            }
        }
    }
    // Through a viewport, onto a dithered grey display, at a corner that may clip it.
    let viewport = Viewport::at(scene, camera, corner(src));
    let grey = || Recorder::<Gray8> {
        size: Size::new(64, 64),
        pixels: HashMap::new(),
    };
    let (mut passed, mut rendered) = (grey(), grey());
    for &pass in &passes {
        viewport
            .render_pass(pass, &mut line, &mut passed)
            .expect("a row's buffer");
    }
    viewport
        .render(&mut line, &mut rendered)
        .expect("a row's buffer");
    assert!(
        passed.pixels == rendered.pixels,
        "the passes end on the viewport's render"
    );
}
