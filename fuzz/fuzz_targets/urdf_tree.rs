//! libFuzzer entry of the `urdf_tree` target; the body is `cad2mo_fuzz::urdf_tree` (fuzz/src/lib.rs).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| cad2mo_fuzz::urdf_tree(data));
