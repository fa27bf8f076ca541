//! Fuzz target `quality_vs_cdt`: see `polytri_oracle::fuzz::quality_vs_cdt` for what it asserts.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    // A finding prints as a JSON corpus case, ready for corpus/cases/.
    if let Err(finding) = polytri_oracle::fuzz::quality_vs_cdt(data) {
        panic!("{finding}");
    }
});
