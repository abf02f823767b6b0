//! libFuzzer entry of the `urdf` target; the body is `cad2mo_fuzz::urdf` (fuzz/src/lib.rs).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| cad2mo_fuzz::urdf(data));
