//! libFuzzer harness: Arbitrary bytes → Scenario::from_json (see cablenav_fuzz::scenario_parse).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    cablenav_fuzz::scenario_parse(data);
});
