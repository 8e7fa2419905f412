//! libFuzzer drives the choices of `tests/common` (the generators and oracles of
//! `tests/hostile.rs`): each input's bytes, read as a stream of `u64`s, pick a scene, a camera,
//! rows, a viewport and a supersampling factor, and every check of the property suite runs on
//! them. Built by `cargo fuzz` with debug assertions, so overflow checks are on and a wrap is a
//! crash like any failed assertion.
#![no_main]

use arbitrary::Unstructured;
use libfuzzer_sys::fuzz_target;

#[path = "../../tests/common/mod.rs"]
mod common;

use common::Source;

/// The fuzzer's bytes as the source of choices; an input that has run out reads as zeros, which
/// every generator accepts (zero picks the first, often the most hostile, option).
struct Bytes<'a>(Unstructured<'a>);

impl Source for Bytes<'_> {
    fn bits(&mut self) -> u64 {
        self.0.arbitrary::<u64>().unwrap_or(0)
    }
}

fuzz_target!(|data: &[u8]| {
    let mut src = Bytes(Unstructured::new(data));
    // One input in eight renders the demo or classic scene through a fuzzed camera: the scenes
    // the firmware runs, as seeds to grow from.
    if src.below(8) == 0 {
        let spec = common::camera_spec(&mut src, 4);
        let Some(camera) = common::check_camera_spec(&spec, false) else {
            return;
        };
        let scene = if src.one_in(2) {
            fixray::demo::scene()
        } else {
            fixray::demo::classic()
        };
        for _ in 0..2 {
            let row = src.below(camera.height() as u64 + 2) as u32;
            common::check_row(&scene, &camera, row);
        }
        common::check_rays_past_the_screen(&spec, &camera);
        return;
    }
    let case = common::case(&mut src);
    common::run_case(&mut src, &case);
});
