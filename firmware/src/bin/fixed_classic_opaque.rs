//! The classic scene with its glass opaque, by fixray's Q16.16 renderer: against
//! `fixed_classic`, what refraction costs.

#![no_std]
#![no_main]

fixray_firmware::main!(fixray_firmware::Fixed, ClassicOpaque);
