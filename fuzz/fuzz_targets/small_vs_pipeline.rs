//! Fuzz target `small_vs_pipeline`: see `polytri_oracle::fuzz::small_vs_pipeline` for what
//! it asserts.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    // A finding prints as a JSON corpus case, ready for corpus/cases/.
    if let Err(finding) = polytri_oracle::fuzz::small_vs_pipeline(data) {
        panic!("{finding}");
    }
});
