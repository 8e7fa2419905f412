//! Progressive passes: a frame traced at a coarse spacing first, then finer, each traced pixel
//! painting its block until a finer pass covers it, the last pass ending exactly on the frame
//! [`render`](crate::render) draws.
//!
//! With spacing `s`, a pass traces the pixels whose column and row are both multiples of `s`
//! and that no coarser pass traced (the first pass traces them all), and paints each one's
//! `s × s` block, its top-left corner. A block of a later pass never covers a pixel traced
//! before it (an earlier pixel's coordinates are multiples of `2s`, and a block spans less
//! than `2s` from a multiple of `s` that is not one), so after the pass of spacing `s` every
//! pixel shows the colour traced for the corner of its `s × s` block, and after the pass of
//! spacing 1 every pixel its own. Spacings halve: from 8, the passes trace 1/64, 3/64, 12/64
//! and 48/64 of the frame, each pixel once.

use crate::error::Error;
use crate::framebuffer::Framebuffer;
use crate::render::camera::Camera;
use crate::render::rows::{check_size, render_every};
use crate::scene::{Rgb, Scene};

/// The coarsest spacing a progressive render may start at, in pixels: a pass's pixels then
/// lie at most 128 columns apart, which the row walk steps in one exact step.
pub const MAX_SPACING: u16 = 64;

/// One pass of a progressive render: its spacing, and whether it is the first, which traces
/// every pixel at that spacing (the others trace those the pass before did not).
///
/// ```
/// use fixray::Pass;
/// let passes: Vec<Pass> = Pass::sequence(8)?.collect();
/// let spacings: Vec<u16> = passes.iter().map(|p| p.spacing()).collect();
/// assert_eq!(spacings, [8, 4, 2, 1]);
/// // The first pass traces every 8th column of every 8th row.
/// assert_eq!(passes[0].columns(16), Some((0, 8)));
/// assert_eq!(passes[0].columns(17), None);
/// // The second, every 4th column of the rows between them, and the columns between in theirs.
/// assert_eq!(passes[1].columns(4), Some((0, 4)));
/// assert_eq!(passes[1].columns(8), Some((4, 8)));
/// assert!(Pass::sequence(6).is_err());
/// # Ok::<(), fixray::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Pass {
    spacing: u16,
    first: bool,
}

impl Pass {
    /// The passes of a progressive render from spacing `coarsest` down to 1, halving: a power
    /// of two from 1 to [`MAX_SPACING`], or [`Error::PassSpacing`]. From 1 there is one pass,
    /// the whole frame.
    pub fn sequence(coarsest: u16) -> Result<Passes, Error> {
        if !coarsest.is_power_of_two() || coarsest > MAX_SPACING {
            return Err(Error::PassSpacing { spacing: coarsest });
        }
        Ok(Passes {
            next: Some(Pass {
                spacing: coarsest,
                first: true,
            }),
        })
    }

    /// The pass's spacing, in pixels: the side of the blocks it paints.
    #[must_use]
    pub const fn spacing(self) -> u16 {
        self.spacing
    }

    /// Whether this is the first pass, which paints the whole frame in blocks.
    #[must_use]
    pub const fn is_first(self) -> bool {
        self.first
    }

    /// Whether this is the last pass (spacing 1), after which the frame is complete.
    #[must_use]
    pub const fn is_last(self) -> bool {
        self.spacing == 1
    }

    /// The columns this pass traces in display row `y`, as the first and the step between
    /// them (columns `first`, `first + step`, … below the camera's width), or `None` where it
    /// traces none of that row.
    #[must_use]
    pub const fn columns(self, y: u32) -> Option<(u32, u32)> {
        let s = self.spacing as u32;
        if !y.is_multiple_of(s) {
            return None;
        }
        // A row the coarser pass traced keeps its columns: this pass takes those between.
        if self.first || (y / s) % 2 == 1 {
            Some((0, s))
        } else {
            Some((s, 2 * s))
        }
    }
}

/// The passes of a progressive render, coarsest first: [`Pass::sequence`].
#[derive(Debug, Clone)]
pub struct Passes {
    next: Option<Pass>,
}

impl Iterator for Passes {
    type Item = Pass;

    fn next(&mut self) -> Option<Pass> {
        let pass = self.next?;
        self.next = (pass.spacing > 1).then_some(Pass {
            spacing: pass.spacing / 2,
            first: false,
        });
        Some(pass)
    }
}

/// The pixels pass `pass` traces in display row `y`, the `i`th of them into `out[i]`, and how
/// many there are: columns `first + i·step` of [`Pass::columns`]. Each is bit for bit the
/// pixel [`render_row`](crate::render_row) gives that column: the row walk is the same, its
/// column step taken `step` at a time. A row the pass does not trace gives 0 and leaves `out`
/// as it is.
///
/// A row outside the screen is [`Error::RowOutOfRange`], and an `out` shorter than the
/// row's traced pixels [`Error::BufferLength`] (one row always holds them).
///
/// ```
/// use fixray::{demo, render_row, render_pass_row, Pass, Rgb};
/// let (scene, camera) = (demo::scene(), demo::camera(40, 32).unwrap());
/// let first = Pass::sequence(4)?.next().unwrap();
/// let (mut coarse, mut full) = ([Rgb::BLACK; 40], [Rgb::BLACK; 40]);
/// assert_eq!(render_pass_row(&scene, &camera, first, 20, &mut coarse)?, 10);
/// render_row(&scene, &camera, 20, &mut full)?;
/// for i in 0..10 {
///     assert_eq!(coarse[i], full[4 * i]);
/// }
/// assert_eq!(render_pass_row(&scene, &camera, first, 21, &mut coarse)?, 0);
/// # Ok::<(), fixray::Error>(())
/// ```
pub fn render_pass_row<const N: usize, const L: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
    pass: Pass,
    y: u32,
    out: &mut [Rgb],
) -> Result<usize, Error> {
    let row = camera.check_row(y)?;
    let Some((first, step)) = pass.columns(y) else {
        return Ok(0);
    };
    let cols = u32::from(camera.cols());
    if first >= cols {
        return Ok(0);
    }
    let count = (cols - first).div_ceil(step) as usize;
    let got = out.len();
    let out = out
        .get_mut(..count)
        .ok_or(Error::BufferLength { needed: count, got })?;
    // Below the width, and the step a power of two up to 128: both fit.
    render_every(
        scene,
        camera,
        row,
        first as u16..cols as u16,
        step.trailing_zeros(),
        out,
    );
    Ok(count)
}

/// Renders pass `pass` into `frame`, whose size must equal the camera's
/// ([`Error::SizeMismatch`]): each pixel the pass traces, and its block
/// (`spacing × spacing` from it, cut at the frame's edges). Run over every pass of
/// [`Pass::sequence`], in order, `frame` holds [`render`](crate::render)'s frame, bit for bit;
/// a sequence begun again from its first pass (for a camera that moved) leaves nothing of an
/// earlier one.
///
/// ```
/// use fixray::{demo, render, render_pass, Framebuffer, Pass};
/// let (scene, camera) = (demo::scene(), demo::camera(32, 24).unwrap());
/// let mut frame = Framebuffer::<32, 24>::new();
/// for pass in Pass::sequence(8)? {
///     render_pass(&scene, &camera, pass, &mut frame)?;
/// }
/// let mut full = Framebuffer::<32, 24>::new();
/// render(&scene, &camera, &mut full)?;
/// assert_eq!(frame, full);
/// # Ok::<(), fixray::Error>(())
/// ```
pub fn render_pass<const N: usize, const L: usize, const W: usize, const H: usize>(
    scene: &Scene<N, L>,
    camera: &Camera,
    pass: Pass,
    frame: &mut Framebuffer<W, H>,
) -> Result<(), Error> {
    check_size::<W, H>(camera)?;
    let spacing = usize::from(pass.spacing());
    let mut traced = [Rgb::BLACK; W];
    for y in 0..H {
        let Some((first, step)) = pass.columns(y as u32) else {
            continue;
        };
        let count = render_pass_row(scene, camera, pass, y as u32, &mut traced)?;
        let rows = frame.rows_mut();
        let block_rows = rows.get_mut(y..(y + spacing).min(H)).unwrap_or_default();
        for (i, &colour) in traced.iter().enumerate().take(count) {
            let x = first as usize + i * step as usize;
            for line in block_rows.iter_mut() {
                if let Some(block) = line.get_mut(x..(x + spacing).min(W)) {
                    block.fill(colour);
                }
            }
        }
    }
    Ok(())
}
