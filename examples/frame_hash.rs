//! The hashes the firmware must reproduce: each scene drawn by each firmware renderer at
//! 160 × 128, row by row, digested with [`FrameHash`].
//!
//! The scenes, cameras and renderers are not written again here: this example compiles the
//! firmware's own `firmware/src/renderer.rs`, which uses nothing but fixray and its reference
//! model (`fixray-reference`), so the host runs
//! the very code the chips run. `scripts/firmware.sh` compares these hashes with what each
//! chip prints under QEMU. Run with
//!
//! ```text
//! cargo run --example frame_hash
//! ```
//!
//! It prints one line per renderer and scene, named as the firmware names its row, e.g.
//! `fixed-classic 0x........`; there are more lines than the table has rows. Two more lines
//! are the animation's (`firmware/src/animation.rs`): `animate-spans`, the digest of every
//! span its partial redraws draw, and `animate-final`, its last frame; two the progressive
//! passes' (`firmware/src/progressive.rs`): `progressive-hash`, every pixel they trace, and
//! `progressive-digest`, the frame they leave.

// `FixedCall` draws as `Fixed` does, for the firmware's stack bound: no hash of its own here.
#[allow(dead_code)]
#[path = "../firmware/src/renderer.rs"]
mod renderer;

#[path = "../firmware/src/animation.rs"]
mod animation;

#[path = "../firmware/src/progressive.rs"]
mod progressive;

use fixray::{FrameHash, Rgb};
use renderer::{COLS, Fixed, FixedRays, FixedShoot, ROWS, Reference, Renderer, Variant};

fn main() {
    print_hashes::<Fixed>();
    print_hashes::<FixedRays>();
    print_hashes::<FixedShoot>();
    print_hashes::<Reference<f64>>();
    print_hashes::<Reference<f32>>();
    // The animation's digests: every span its partial redraws draw, and its last frame.
    let totals = animation::run(|| 0).expect("the animation's scenes are valid");
    println!("animate-spans {:#010x}", totals.spans_hash);
    println!("animate-final {:#010x}", totals.final_hash);
    // The progressive passes': every traced pixel in order, and the frame they leave, which
    // must be the full frame's.
    let passes = progressive::run(|| 0).expect("the demo scene's passes are valid");
    let frame = progressive::frame_digest().expect("the demo scene renders");
    assert_eq!(passes.passes_digest, frame, "the passes end on the frame");
    println!("progressive-hash {:#010x}", passes.passes_hash);
    println!("progressive-digest {frame:#010x}");
}

/// Prints `name hash` for every scene drawn by `R`.
fn print_hashes<R: Renderer>() {
    for &variant in Variant::ALL {
        let renderer = R::new(variant, COLS, ROWS).expect("the firmware's scenes are valid");
        let mut row = [Rgb::BLACK; COLS as usize];
        let mut hash = FrameHash::new();
        for y in 0..ROWS {
            renderer.render_row(y, &mut row).expect("a row renders");
            hash.update(&row);
        }
        println!("{}{} {:#010x}", R::NAME, variant.suffix(), hash.finish());
    }
}
