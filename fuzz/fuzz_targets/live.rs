//! libFuzzer entry of the `live` target; the body is `cad2mo_fuzz::live` (fuzz/src/lib.rs).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| cad2mo_fuzz::live(data));
