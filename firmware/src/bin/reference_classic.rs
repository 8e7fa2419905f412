//! The classic scene by fixray's f64 reference model, soft-float on every chip.

#![no_std]
#![no_main]

fixray_firmware::main!(fixray_firmware::Reference<f64>, Classic);
