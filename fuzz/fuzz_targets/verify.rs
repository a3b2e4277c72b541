//! libFuzzer harness: Bytes → scenario → exact verification and a ray (see cablenav_fuzz::verify).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    cablenav_fuzz::verify(data);
});
