//! The classic scene without shadow rays, by fixray's Q16.16 renderer: against
//! `fixed_classic`, what shadows cost.

#![no_std]
#![no_main]

fixray_firmware::main!(fixray_firmware::Fixed, ClassicNoShadow);
