//! The demo scene by fixray's Q16.16 renderer: integer arithmetic only.

#![no_std]
#![no_main]

fixray_firmware::main!(fixray_firmware::Fixed, Demo);
