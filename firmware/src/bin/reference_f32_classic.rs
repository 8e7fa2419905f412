//! The classic scene by fixray's reference model in `f32`: soft-float on the Cortex-M0 and
//! RV32IMC, the FPU on the Cortex-M4F.

#![no_std]
#![no_main]

fixray_firmware::main!(fixray_firmware::Reference<f32>, Classic);
