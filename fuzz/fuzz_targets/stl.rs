//! libFuzzer entry of the `stl` target; the body is `cad2mo_fuzz::stl` (fuzz/src/lib.rs).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| cad2mo_fuzz::stl(data));
