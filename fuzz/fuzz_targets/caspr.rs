//! libFuzzer harness: Bytes as a CASPR bodies + cables pair → import (see cablenav_fuzz::caspr_import).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    cablenav_fuzz::caspr_import(data);
});
