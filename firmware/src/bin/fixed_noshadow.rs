//! The demo scene without shadow rays, by fixray's Q16.16 renderer: against `fixed`, what
//! the demo's shadows cost.

#![no_std]
#![no_main]

fixray_firmware::main!(fixray_firmware::Fixed, DemoNoShadow);
