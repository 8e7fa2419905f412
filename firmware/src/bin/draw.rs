//! The drawing layer's stack, measured: the demo and the classic scene drawn at 160 × 128
//! through `Viewport::render` with a one-row buffer and through a `Picture`, onto an `Rgb565`
//! display that digests every pixel it is sent.
//!
//! Before each draw the free stack is painted; after it, the deepest word the draw wrote,
//! counted from the stack pointer at the call, is the stack the draw takes below its caller:
//! the viewport's frame, `render_row` and everything it calls, and the display's
//! `fill_contiguous`. Nothing else runs meanwhile (no counter is started, so no timer
//! interrupt pushes onto the stack). It prints one line per scene and way of drawing:
//!
//! ```text
//! draw: scene=classic via=render hash=0x........ pixels=20480 stack=....
//! ```
//!
//! `hash` is the [`FrameHash`] of the `Rgb565` pixels widened back to 8 bits a channel, in
//! raster order; `examples/draw_hash.rs` computes the same digest on the host from
//! `render_row` and the colour conversion alone, for `scripts/firmware.sh` to compare. `stack`
//! is in bytes; a picture's includes its own row buffer (3 bytes a column), a render's does
//! not (the caller's buffer is in the caller's frame).

#![no_std]
#![no_main]

use core::convert::Infallible;

use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
use embedded_graphics::prelude::{OriginDimensions, Pixel, Point, Size};
use embedded_graphics::primitives::Rectangle;
use embedded_graphics::{Drawable, draw_target::DrawTarget};
use fixray::{Camera, DrawError, FrameHash, Rgb, Scene, Viewport, demo};
use fixray_firmware::{COLS, ROWS, exit, memory, stack};
use semihosting::{eprintln, println};

#[cfg_attr(target_arch = "arm", cortex_m_rt::entry)]
#[cfg_attr(target_arch = "riscv32", riscv_rt::entry)]
fn main() -> ! {
    println!(
        "board={} target={} renderer=draw",
        fixray_firmware::MACHINE,
        fixray_firmware::TARGET
    );
    let scenes = [
        ("demo", demo::scene(), demo::camera(COLS, ROWS)),
        ("classic", demo::classic(), demo::classic_camera(COLS, ROWS)),
    ];
    // The caller's one-row buffer for `render`, outside the measured frames.
    let mut row = [Rgb::BLACK; COLS as usize];
    for (name, scene, camera) in &scenes {
        let Ok(camera) = camera else {
            failed(name, "the camera");
        };
        for via in ["render", "picture"] {
            let mut display = Digest::new();
            stack::paint();
            let at = stack_pointer();
            let drawn = if via == "render" {
                render(scene, camera, &mut row, &mut display)
            } else {
                picture(scene, camera, &mut display)
            };
            // Both are addresses in RAM below the top of the stack; the deepest written word
            // lies below `at`.
            let deepest = memory::stack_top() - stack::peak();
            let below = at.saturating_sub(deepest);
            if !drawn || display.misplaced != 0 || display.pixels != COLS * ROWS {
                failed(name, via);
            }
            println!(
                "draw: scene={name} via={via} hash={:#010x} pixels={} stack={below}",
                display.hash.finish(),
                display.pixels
            );
        }
    }
    exit::with(exit::SUCCESS)
}

/// The whole picture through `Viewport::render` with the caller's one-row buffer. Not
/// inlined, so that the stack below the call is this function's frame and what it calls.
#[inline(never)]
fn render(scene: &Scene<8>, camera: &Camera, row: &mut [Rgb], display: &mut Digest) -> bool {
    let view = Viewport::at(scene, camera, Point::zero());
    let drawn: Result<(), DrawError<Infallible>> = view.render(row, display);
    drawn.is_ok()
}

/// The whole picture as a `Picture`, whose row buffer is on the stack while it draws. Not
/// inlined, as [`render`].
#[inline(never)]
fn picture(scene: &Scene<8>, camera: &Camera, display: &mut Digest) -> bool {
    let view = Viewport::at(scene, camera, Point::zero());
    match view.picture::<Rgb565, { COLS as usize }>() {
        Ok(picture) => picture.draw(display).is_ok(),
        Err(_) => false,
    }
}

/// The stack pointer of the function this is inlined into.
#[inline(always)]
fn stack_pointer() -> usize {
    let sp: usize;
    // SAFETY: reads a register, touches no memory.
    unsafe {
        #[cfg(target_arch = "arm")]
        core::arch::asm!("mov {}, sp", out(reg) sp, options(nomem, nostack, preserves_flags));
        #[cfg(target_arch = "riscv32")]
        core::arch::asm!("mv {}, sp", out(reg) sp, options(nomem, nostack, preserves_flags));
    }
    sp
}

/// Reports a draw that failed or did not cover the display once in raster order, and ends
/// the run.
fn failed(scene: &str, what: &str) -> ! {
    eprintln!("scene {scene}: {what} failed or drew the wrong pixels");
    exit::with(exit::RENDER_FAILED)
}

/// A `COLS × ROWS` `Rgb565` display that digests what it is sent, as a driver streams it to a
/// panel: each pixel widened back to 8 bits a channel and fed to a [`FrameHash`], counting
/// what does not arrive in raster order.
struct Digest {
    hash: FrameHash,
    /// Pixels received.
    pixels: u32,
    /// Pixels and fills that were not the next in raster order, or not whole.
    misplaced: u32,
}

impl Digest {
    fn new() -> Self {
        Digest {
            hash: FrameHash::new(),
            pixels: 0,
            misplaced: 0,
        }
    }

    /// The point of the next pixel in raster order.
    fn next(&self) -> Point {
        Point::new((self.pixels % COLS) as i32, (self.pixels / COLS) as i32)
    }

    /// Feeds one pixel to the digest.
    fn feed(&mut self, colour: Rgb565) {
        self.hash.update(&[Rgb::from(Rgb888::from(colour))]);
        self.pixels += 1;
    }
}

impl OriginDimensions for Digest {
    fn size(&self) -> Size {
        Size::new(COLS, ROWS)
    }
}

impl DrawTarget for Digest {
    type Color = Rgb565;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Infallible> {
        for Pixel(at, colour) in pixels {
            self.misplaced += u32::from(at != self.next());
            self.feed(colour);
        }
        Ok(())
    }

    /// As a driver does: the colours fill `area` row by row, and only the area is looked at,
    /// not each pixel's point. The picture is the display's size, so each band is whole rows
    /// that follow the last.
    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        colours: I,
    ) -> Result<(), Infallible> {
        let start = self.pixels;
        self.misplaced += u32::from(area.top_left != self.next() || area.size.width != COLS);
        for colour in colours {
            self.feed(colour);
        }
        let sent = self.pixels - start;
        self.misplaced += u32::from(sent != area.size.width * area.size.height);
        Ok(())
    }
}
