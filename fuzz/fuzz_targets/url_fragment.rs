//! libFuzzer harness: Bytes as the page's URL hash → link decoding → scenario (see cablenav_fuzz::url_fragment).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    cablenav_fuzz::url_fragment(data);
});
