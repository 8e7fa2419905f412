//! The demo camera's rays alone: the profile's first stage.

#![no_std]
#![no_main]

fixray_firmware::main!(fixray_firmware::FixedRays, Demo);
