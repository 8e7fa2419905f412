//! The demo scene's rays and nearest hits, without shading: the profile's first two stages.

#![no_std]
#![no_main]

fixray_firmware::main!(fixray_firmware::FixedShoot, Demo);
