//! libFuzzer entry of the `bundle_zip` target; the body is `cad2mo_fuzz::bundle_zip` (fuzz/src/lib.rs).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| cad2mo_fuzz::bundle_zip(data));
