//! libFuzzer entry of the `xml` target; the body is `cad2mo_fuzz::xml` (fuzz/src/lib.rs).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| cad2mo_fuzz::xml(data));
