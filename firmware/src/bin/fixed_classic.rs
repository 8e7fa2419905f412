//! The classic scene (highlights, three lights, shadows, mirrors, a checkerboard) by fixray's
//! Q16.16 renderer.

#![no_std]
#![no_main]

fixray_firmware::main!(fixray_firmware::Fixed, Classic);
