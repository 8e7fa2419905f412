//! Progressive passes: a frame traced at a coarse spacing first, then finer, each traced pixel
//! painting its block until a finer pass covers it, the last pass ending exactly on the frame
//! [`render`](crate::render) draws.
//!
//! From a spacing `c`, the first pass traces the pixels whose column and row are both
//! multiples of `c` and paints each one's `c × c` block, its top-left corner. Each pass down
//! to spacing 4 halves the spacing and traces the pixels of that grid no pass traced before:
//! a block of such a pass never covers a pixel traced before it (an earlier pixel's
//! coordinates are multiples of `2s`, and a block spans less than `2s` from a multiple of `s`
//! that is not one). The last two passes complete the rows, even rows first: the one of
//! spacing 2 traces every pixel of the even rows not traced yet and paints it and the pixel
//! below (a `1 × 2` block), the one of spacing 1 traces the odd rows. So after each pass
//! every pixel shows the colour traced for the corner of its block, and after the last its
//! own. From 8, the passes trace 1/64, 3/64, 28/64 and 32/64 of the frame, each pixel once.
//!
//! Why the rows, not a pass of `2 × 2` blocks and one of single pixels: a row's set-up (its
//! culling, its shadow sets) is made again in every pass that traces it. Halving the spacing
//! down to 1 sets up each row 1⅞ times on average (from 8); completing the even rows in one
//! pass and the odd rows in the next, 1⅜ times, and the picture after the pass of spacing 2
//! is sharper than one of `2 × 2` blocks: half of its rows are final.

use embedded_graphics::geometry::Size;

use crate::error::Error;
use crate::framebuffer::Framebuffer;
use crate::render::camera::Camera;
use crate::render::rows::{check_size, render_every};
use crate::scene::{Rgb, Scene};

/// The coarsest spacing a progressive render may start at, in pixels: a pass's pixels then
/// lie at most 128 columns apart, which the row walk steps in one exact step.
pub const MAX_SPACING: u16 = 64;

/// One pass of a progressive render: its spacing, and which of the sequence's kinds it is.
///
/// ```
/// use fixray::{Pass, Size};
/// let passes: Vec<Pass> = Pass::sequence(8)?.collect();
/// let spacings: Vec<u16> = passes.iter().map(|p| p.spacing()).collect();
/// assert_eq!(spacings, [8, 4, 2, 1]);
/// // The first pass traces every 8th column of every 8th row, in blocks of 8 × 8.
/// assert_eq!(passes[0].columns(16).collect::<Vec<_>>(), [(0, 8)]);
/// assert_eq!(passes[0].columns(17).count(), 0);
/// // The second, every 4th column of the rows between them, and the columns between in theirs.
/// assert_eq!(passes[1].columns(4).collect::<Vec<_>>(), [(0, 4)]);
/// assert_eq!(passes[1].columns(8).collect::<Vec<_>>(), [(4, 8)]);
/// // The third completes the even rows, each pixel painted with the one below it.
/// assert_eq!(passes[2].columns(2).collect::<Vec<_>>(), [(0, 1)]);
/// assert_eq!(passes[2].columns(4).collect::<Vec<_>>(), [(1, 2), (2, 4)]);
/// assert_eq!(passes[2].block(), Size::new(1, 2));
/// // The last, the odd rows.
/// assert_eq!(passes[3].columns(5).collect::<Vec<_>>(), [(0, 1)]);
/// assert_eq!(passes[3].columns(4).count(), 0);
/// assert!(Pass::sequence(6).is_err());
/// # Ok::<(), fixray::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Pass {
    spacing: u16,
    kind: Kind,
}

/// What a [`Pass`] traces, given its spacing `s`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
enum Kind {
    /// Every pixel of the grid of spacing `s`.
    First,
    /// The pixels of the grid of spacing `s` that the pass before (of spacing `2s`) did not.
    Grid,
    /// Every pixel of the even rows not traced yet, the finest grid before it of spacing
    /// `after` (2 or 4).
    EvenRows { after: u16 },
    /// Every pixel of the odd rows.
    OddRows,
}

impl Pass {
    /// The passes of a progressive render from spacing `coarsest`: a power of two from 1 to
    /// [`MAX_SPACING`], or [`Error::PassSpacing`]. From 1 there is one pass, the whole frame;
    /// from 2, three (the grid, then the even rows, then the odd rows); from `2^k` with
    /// `k ≥ 2`, `k` grids of halving spacing down to 4, then the even and the odd rows.
    pub fn sequence(coarsest: u16) -> Result<Passes, Error> {
        if !coarsest.is_power_of_two() || coarsest > MAX_SPACING {
            return Err(Error::PassSpacing { spacing: coarsest });
        }
        Ok(Passes {
            next: Some(Pass {
                spacing: coarsest,
                kind: Kind::First,
            }),
        })
    }

    /// The pass's spacing, in pixels: the rows it traces are multiples of it, and its blocks
    /// are as tall.
    #[must_use]
    pub const fn spacing(self) -> u16 {
        self.spacing
    }

    /// The block each traced pixel paints, from its top-left corner until a finer pass covers
    /// it: `spacing × spacing` for a grid, `1 × 2` for the even rows, `1 × 1` for the odd.
    #[must_use]
    pub const fn block(self) -> Size {
        let s = self.spacing as u32;
        match self.kind {
            Kind::First | Kind::Grid => Size::new(s, s),
            Kind::EvenRows { .. } => Size::new(1, 2),
            Kind::OddRows => Size::new(1, 1),
        }
    }

    /// Whether this is the first pass, which paints the whole frame in blocks.
    #[must_use]
    pub const fn is_first(self) -> bool {
        matches!(self.kind, Kind::First)
    }

    /// Whether this is the last pass (spacing 1), after which the frame is complete.
    #[must_use]
    pub const fn is_last(self) -> bool {
        self.spacing == 1
    }

    /// The columns this pass traces in display row `y`: none, or one or two runs of columns
    /// each given as its first and the step between them (columns `first`, `first + step`, …
    /// below the camera's width). Two only where the pass of spacing 2 completes a row a grid
    /// of spacing 4 traced: its odd columns, then those two past a multiple of 4.
    #[must_use]
    pub const fn columns(self, y: u32) -> Columns {
        // Spacings are powers of two: masks, not divisions (the Cortex-M0 has no divider, and
        // a pass asks every row).
        let s = self.spacing as u32;
        let (on_grid, odd) = (y & (s - 1) == 0, y & 1 == 1);
        match self.kind {
            Kind::First if on_grid => Columns::of(&[(0, s)]),
            // A row the coarser pass traced keeps its columns: this pass takes those between.
            Kind::Grid if on_grid => match y & s {
                0 => Columns::of(&[(s, 2 * s)]),
                _ => Columns::of(&[(0, s)]),
            },
            Kind::EvenRows { after } if !odd => match y & (after as u32 - 1) {
                0 if after == 2 => Columns::of(&[(1, 2)]),
                0 => Columns::of(&[(1, 2), (2, 4)]),
                _ => Columns::of(&[(0, 1)]),
            },
            Kind::OddRows if odd => Columns::of(&[(0, 1)]),
            _ => Columns::of(&[]),
        }
    }
}

/// The columns a [`Pass`] traces in one row ([`Pass::columns`]): up to two runs, each as its
/// first column and the step between its columns, in the order the pass's pixels come.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Columns {
    runs: [(u32, u32); 2],
    len: u8,
    next: u8,
}

impl Columns {
    /// The runs of `runs` (at most two are kept).
    const fn of(runs: &[(u32, u32)]) -> Self {
        let mut kept = [(0, 1); 2];
        let mut i = 0;
        while i < runs.len() && i < 2 {
            kept[i] = runs[i];
            i += 1;
        }
        Columns {
            runs: kept,
            len: i as u8,
            next: 0,
        }
    }

    /// How many columns below `width` the runs hold.
    #[must_use]
    pub fn count_below(self, width: u32) -> u32 {
        // Steps are powers of two: a shift, not a division (the Cortex-M0 has no divider).
        let count = |(first, step): (u32, u32)| {
            let shift = step.trailing_zeros();
            (width.saturating_sub(first) + (1 << shift) - 1) >> shift
        };
        self.map(count).sum()
    }

    /// The columns below `width`, run by run: the order in which
    /// [`render_pass_row`] gives their pixels.
    pub fn below(self, width: u32) -> impl Iterator<Item = u32> {
        self.flat_map(move |(first, step)| (first..width).step_by(step as usize))
    }
}

impl Iterator for Columns {
    type Item = (u32, u32);

    fn next(&mut self) -> Option<(u32, u32)> {
        let run = *self
            .runs
            .get(usize::from(self.next))
            .filter(|_| self.next < self.len)?;
        self.next += 1;
        Some(run)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = usize::from(self.len.saturating_sub(self.next));
        (left, Some(left))
    }
}

impl ExactSizeIterator for Columns {}

/// The passes of a progressive render, coarsest first: [`Pass::sequence`].
#[derive(Debug, Clone)]
pub struct Passes {
    next: Option<Pass>,
}

impl Iterator for Passes {
    type Item = Pass;

    fn next(&mut self) -> Option<Pass> {
        let pass = self.next?;
        let spacing = pass.spacing;
        self.next = match pass.kind {
            Kind::First | Kind::Grid if spacing > 4 => Some((spacing / 2, Kind::Grid)),
            // A grid of 4, or a first of 2 or 4, is the finest: the rows come next.
            Kind::First | Kind::Grid if spacing > 1 => Some((2, Kind::EvenRows { after: spacing })),
            Kind::EvenRows { .. } => Some((1, Kind::OddRows)),
            _ => None,
        }
        .map(|(spacing, kind)| Pass { spacing, kind });
        Some(pass)
    }
}

/// The pixels pass `pass` traces in display row `y`, the `i`th of them into `out[i]`, and how
/// many there are: the columns of [`Pass::columns`], run by run ([`Columns::below`]). Each
/// is bit for bit the pixel [`render_row`](crate::render_row) gives that column: the row walk
/// is the same, its column step taken `step` at a time, and a row of two runs is set up once
/// for both. A row the pass does not trace gives 0 and leaves `out` as it is.
///
/// A row outside the screen is [`Error::RowOutOfRange`], and an `out` shorter than the
/// row's traced pixels [`Error::BufferLength`] (one row always holds them).
///
/// ```
/// use fixray::{demo, render_row, render_pass_row, Pass, Rgb};
/// let (scene, camera) = (demo::scene(), demo::camera(40, 32).unwrap());
/// let passes: Vec<Pass> = Pass::sequence(4)?.collect();
/// let (mut traced, mut full) = ([Rgb::BLACK; 40], [Rgb::BLACK; 40]);
/// assert_eq!(render_pass_row(&scene, &camera, passes[0], 20, &mut traced)?, 10);
/// render_row(&scene, &camera, 20, &mut full)?;
/// for i in 0..10 {
///     assert_eq!(traced[i], full[4 * i]);
/// }
/// assert_eq!(render_pass_row(&scene, &camera, passes[0], 21, &mut traced)?, 0);
/// // The even rows' pass completes row 20: its odd columns, then columns 2, 6, 10, …
/// assert_eq!(render_pass_row(&scene, &camera, passes[1], 20, &mut traced)?, 30);
/// let columns = passes[1].columns(20).below(40);
/// for (i, x) in columns.enumerate() {
///     assert_eq!(traced[i], full[x as usize]);
/// }
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
    let columns = pass.columns(y);
    if columns.len() == 0 {
        return Ok(0); // most rows of a coarse pass: asked, and let go at once
    }
    let cols = u32::from(camera.cols());
    let count = columns.count_below(cols) as usize;
    // Firsts below 128 and steps powers of two up to 128: all fit. A run that starts past
    // the row is empty.
    let (mut walks, n) = ([(0..0, 0), (0..0, 0)], columns.len());
    for (walk, (first, step)) in walks.iter_mut().zip(columns) {
        *walk = (first.min(cols) as u16..cols as u16, step.trailing_zeros());
    }
    if count == 0 {
        return Ok(0);
    }
    let got = out.len();
    let out = out
        .get_mut(..count)
        .ok_or(Error::BufferLength { needed: count, got })?;
    render_every(scene, camera, row, walks.get(..n).unwrap_or_default(), out);
    Ok(count)
}

/// Renders pass `pass` into `frame`, whose size must equal the camera's
/// ([`Error::SizeMismatch`]): each pixel the pass traces, and its block ([`Pass::block`],
/// cut at the frame's edges). Run over every pass of [`Pass::sequence`], in order, `frame`
/// holds [`render`](crate::render)'s frame, bit for bit; a sequence begun again from its
/// first pass (for a camera that moved) leaves nothing of an earlier one.
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
    let block = pass.block();
    let (width, height) = (block.width as usize, block.height as usize);
    let mut traced = [Rgb::BLACK; W];
    for y in 0..H {
        let count = render_pass_row(scene, camera, pass, y as u32, &mut traced)?;
        let rows = frame.rows_mut();
        let block_rows = rows.get_mut(y..(y + height).min(H)).unwrap_or_default();
        let columns = pass.columns(y as u32).below(W as u32);
        for (&colour, x) in traced.iter().take(count).zip(columns) {
            let x = x as usize;
            for line in block_rows.iter_mut() {
                if let Some(block) = line.get_mut(x..(x + width).min(W)) {
                    block.fill(colour);
                }
            }
        }
    }
    Ok(())
}
