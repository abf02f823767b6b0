//! libFuzzer entry of the `dae` target; the body is `cad2mo_fuzz::dae` (fuzz/src/lib.rs).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| cad2mo_fuzz::dae(data));
