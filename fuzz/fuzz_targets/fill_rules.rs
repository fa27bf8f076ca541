//! Fuzz target `fill_rules`: see `polytri_oracle::fuzz::fill_rules` for what it asserts.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    // A finding prints as a JSON corpus case, ready for corpus/cases/.
    if let Err(finding) = polytri_oracle::fuzz::fill_rules(data) {
        panic!("{finding}");
    }
});
