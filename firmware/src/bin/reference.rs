//! The demo scene by fixray's f64 reference model: `libm` and the compiler's soft-float
//! routines on every one of these chips (the Cortex-M4F's FPU does single precision only).

#![no_std]
#![no_main]

fixray_firmware::main!(fixray_firmware::Reference<f64>, Demo);
