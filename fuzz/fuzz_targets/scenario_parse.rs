//! Arbitrary bytes → `Scenario::from_json` (when they are UTF-8). Parsing and validation must
//! return `Ok` or an `Err` naming the field, never panic.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        let _ = cablenav::Scenario::from_json(text);
    }
});
