//! The demo scene by fixray's Q16.16 renderer, `render_row` a call of its own: the binary
//! `scripts/firmware.sh` reads the static stack bound from `render_row` down from.

#![no_std]
#![no_main]

fixray_firmware::main!(fixray_firmware::FixedCall, Demo);
