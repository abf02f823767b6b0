//! libFuzzer entry of the `convert` target; the body is `cad2mo_fuzz::convert` (fuzz/src/lib.rs).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| cad2mo_fuzz::convert(data));
