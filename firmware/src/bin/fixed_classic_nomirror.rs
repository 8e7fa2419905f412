//! The classic scene without mirrors, by fixray's Q16.16 renderer: against `fixed_classic`,
//! what mirrors cost.

#![no_std]
#![no_main]

fixray_firmware::main!(fixray_firmware::Fixed, ClassicNoMirror);
