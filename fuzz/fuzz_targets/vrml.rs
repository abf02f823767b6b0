//! libFuzzer entry of the `vrml` target; the body is `cad2mo_fuzz::vrml` (fuzz/src/lib.rs).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| cad2mo_fuzz::vrml(data));
