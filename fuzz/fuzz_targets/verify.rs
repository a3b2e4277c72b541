//! Arbitrary bytes → `Scenario::from_json`; when it parses, exact verification of every
//! trajectory, and a ray through the first pose in a coordinate and over a small range chosen
//! from the input's bytes. Errors are fine; panics are bugs.
#![no_main]

use cablenav::model::Coord;
use cablenav::verify::{ray, verify_trajectory};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(s) = cablenav::Scenario::from_json(text) else { return };
    for traj in &s.trajectories {
        let _ = verify_trajectory(&s, traj);
    }
    if let Some((name, pose)) = s.poses.first() {
        // The JSON must stay valid, so the choice comes from a hash of the whole input: the
        // coordinate, and a range of width 0.05 to 0.8 (m or rad) around the pose's value.
        let h = data.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| (h ^ b as u64).wrapping_mul(0x0100_0000_01b3));
        let coord = Coord::ALL[(h % 6) as usize];
        let width = 0.05 + 0.75 * ((h >> 8) % 1024) as f64 / 1023.0;
        let shift = ((h >> 18) % 1024) as f64 / 1023.0; // where the pose's value sits in the range
        let c = pose.coords()[coord.index()];
        let lo = c - shift * width;
        let _ = ray(&s, name, coord, lo, lo + width);
    }
});
