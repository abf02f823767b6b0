//! libFuzzer entry of the `mat` target; the body is `cad2mo_fuzz::mat` (fuzz/src/lib.rs).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| cad2mo_fuzz::mat(data));
