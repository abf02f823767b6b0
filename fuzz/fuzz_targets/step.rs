//! libFuzzer entry of the `step` target; the body is `cad2mo_fuzz::step` (fuzz/src/lib.rs).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| cad2mo_fuzz::step(data));
