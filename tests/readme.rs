//! What the README states, held to the code.
//!
//! - The README gives the demo and classic scenes' frame hashes at 160 × 128, the figures the
//!   firmware's frames are checked against on every chip. This renders both scenes as the
//!   firmware does (`firmware/src/renderer.rs`: the scene's camera at 160 × 128, `render_row`
//!   from the top row down, each row fed to a `FrameHash`) and reads the hashes from the
//!   README's text, so a change of pixels that leaves the README behind fails here.
//! - The README's driver code is a `rust,ignore` block (it needs a board's SPI bus); its lines
//!   must be lines of `examples/driver.rs`, which compiles and runs, so the README cannot show
//!   code that no longer builds.

use fixray::{Camera, FrameHash, Rgb, Scene, demo, render_row};

const COLS: u32 = 160;
const ROWS: u32 = 128;

/// The sentence of the README that states the hashes starts with this.
const README: &str = include_str!("../README.md");

const LEAD: &str = "Frame hashes at 160 × 128";

fn frame_hash(scene: &Scene<8>, camera: &Camera) -> u32 {
    let mut row = [Rgb::BLACK; COLS as usize];
    let mut hash = FrameHash::new();
    for y in 0..ROWS {
        render_row(scene, camera, y, &mut row).expect("a row of the picture renders");
        hash.update(&row);
    }
    hash.finish()
}

/// The hash the README's sentence gives for `scene`, written `` scene `0x12345678` ``.
fn readme_hash(scene: &str) -> u32 {
    // Lines joined, paragraphs kept apart: the sentence may wrap anywhere.
    let text = README.replace("\n\n", "\0").replace('\n', " ");
    let start = text
        .find(LEAD)
        .unwrap_or_else(|| panic!("README.md has no sentence starting {LEAD:?}"));
    let sentence = text[start..].split('\0').next().unwrap_or_default();
    let label = format!("{scene} `0x");
    let at = sentence
        .find(&label)
        .unwrap_or_else(|| panic!("README.md's {LEAD:?} sentence gives no {scene} hash"));
    let digits = &sentence[at + label.len()..];
    let digits = &digits[..digits.find('`').expect("the hash is in backquotes")];
    assert_eq!(
        digits.len(),
        8,
        "the {scene} hash has 8 hex digits: {digits:?}"
    );
    u32::from_str_radix(digits, 16).expect("the hash is hexadecimal")
}

#[test]
fn demo_frame_hash_is_the_readmes() {
    let camera = demo::camera(COLS, ROWS).expect("the demo camera is valid");
    let hash = frame_hash(&demo::scene(), &camera);
    assert_eq!(
        hash,
        readme_hash("demo"),
        "the demo frame hashes to {hash:#010x}; update README.md if the change of pixels is meant"
    );
}

#[test]
fn classic_frame_hash_is_the_readmes() {
    let camera = demo::classic_camera(COLS, ROWS).expect("the classic camera is valid");
    let hash = frame_hash(&demo::classic(), &camera);
    assert_eq!(
        hash,
        readme_hash("classic"),
        "the classic frame hashes to {hash:#010x}; update README.md if the change of pixels is meant"
    );
}

#[test]
fn readme_driver_code_is_the_examples() {
    let start = README
        .find("```rust,ignore\n")
        .expect("README.md shows the driver code in a rust,ignore block");
    let block = &README[start..];
    let block = &block[block.find('\n').expect("the fence ends its line") + 1..];
    let block = &block[..block.find("```").expect("the block is closed")];
    let example = include_str!("../examples/driver.rs");
    let example: Vec<&str> = example.lines().map(str::trim).collect();
    let mut shown = 0;
    let mut after = 0;
    for line in block.lines().map(str::trim).filter(|l| !l.is_empty()) {
        // The `use` lines are gathered in the README; the example may spread them.
        if line.starts_with("use ") {
            for name in line.split(|c: char| !(c.is_alphanumeric() || c == '_')) {
                assert!(
                    name.is_empty()
                        || example
                            .iter()
                            .any(|l| l.starts_with("use ") && l.contains(name)),
                    "README.md imports {name}, examples/driver.rs does not"
                );
            }
            continue;
        }
        // The other lines appear in the example in the same order.
        let at = example[after..]
            .iter()
            .position(|l| *l == line)
            .unwrap_or_else(|| {
                panic!("README.md's driver line {line:?} is not in examples/driver.rs (in order)")
            });
        after += at + 1;
        shown += 1;
    }
    assert!(
        shown >= 10,
        "the README shows the driver's core, {shown} lines"
    );
}
