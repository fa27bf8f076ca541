//! Replays what the fuzzers found or kept — `fuzz/corpus/TARGET`, `fuzz/regressions/TARGET`
//! and any crash left in `fuzz/artifacts/TARGET` — through the same target bodies, on
//! stable, so every fuzz finding stays a regression test.
//!
//! Also a few hand-made inputs per target, so the bodies run even before any corpus exists.

use std::path::{Path, PathBuf};

use polytri_oracle::fuzz::{decode_case, run_target, TARGETS};

fn fuzz_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../fuzz")
}

/// Every file of `fuzz/{corpus,regressions,artifacts}/target`.
fn inputs(target: &str) -> Vec<PathBuf> {
    let mut files = Vec::new();
    for kind in ["corpus", "regressions", "artifacts"] {
        let Ok(entries) = std::fs::read_dir(fuzz_dir().join(kind).join(target)) else {
            continue;
        };
        files.extend(entries.flatten().map(|e| e.path()).filter(|p| p.is_file()));
    }
    files.sort();
    files
}

/// Inputs that reach every decoding branch: empty, each coordinate mode, nonsense starts.
fn hand_made() -> Vec<Vec<u8>> {
    let mut inputs = vec![Vec::new(), vec![0], vec![0xff; 64]];
    for flags in [0u8, 1, 2, 3, 4, 5, 6, 7, 0x80, 0x83] {
        let mut bytes = vec![flags, 2, 4, 4];
        bytes.extend((0u8..=200).map(|i| i.wrapping_mul(37)));
        inputs.push(bytes);
    }
    inputs
}

#[test]
fn fuzz_findings_stay_fixed() {
    let mut failures = Vec::new();
    let mut replayed = 0;
    for (target, _) in TARGETS {
        let files = inputs(target);
        let datas = files
            .iter()
            .map(|f| {
                (
                    f.display().to_string(),
                    std::fs::read(f).unwrap_or_default(),
                )
            })
            .chain(
                hand_made()
                    .into_iter()
                    .enumerate()
                    .map(|(k, d)| (format!("hand-made #{k}"), d)),
            );
        for (name, data) in datas {
            replayed += 1;
            if let Some(Err(finding)) = run_target(target, &data) {
                failures.push(format!("{target} on {name}: {finding}"));
            }
        }
    }
    assert!(replayed >= TARGETS.len() * hand_made().len());
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

#[test]
fn every_target_is_listed_in_the_fuzz_crate() {
    let manifest = std::fs::read_to_string(fuzz_dir().join("Cargo.toml")).expect("fuzz/Cargo.toml");
    for (target, _) in TARGETS {
        assert!(
            manifest.contains(&format!("name = \"{target}\"")),
            "{target} missing"
        );
        let body = fuzz_dir().join("fuzz_targets").join(format!("{target}.rs"));
        let text = std::fs::read_to_string(&body).expect("fuzz target source");
        assert!(text.contains(&format!("polytri_oracle::fuzz::{target}(")));
    }
}

#[test]
fn inputs_decode_to_corpus_cases() {
    for (target, _) in TARGETS {
        let data: Vec<u8> = (0u8..=255).collect();
        let case = decode_case(target, &data).expect("known target");
        assert_eq!(case.source, format!("fuzz:{target}"));
        let back = polytri_oracle::Case::from_json(&case.to_json()).expect("round trip");
        assert_eq!(back.input.vertices.len(), case.input.vertices.len());
    }
    assert!(decode_case("no_such_target", &[]).is_none());
}

/// The oracle half of the harness must notice a broken triangulator: a target body fed a
/// triangulation with one triangle dropped reports it. (The planted-bug experiment of the
/// fuzzing issue is described in the README; this keeps the detection path tested.)
#[test]
fn a_dropped_triangle_is_a_finding() {
    use polytri_oracle::{check_with, CheckOptions, Family, Params};
    let case = polytri_oracle::generate(Family::ManyHoles, 7, &Params::new(60));
    let mut out = Vec::new();
    polytri::Triangulator::<f64>::new()
        .triangulate(
            &case.input.vertices,
            &case.input.ring_starts,
            &polytri::Options::default(),
            &mut out,
        )
        .expect("valid input");
    assert!(check_with(&case.input, &out, &CheckOptions::fast()).valid);
    out.pop();
    assert!(!check_with(&case.input, &out, &CheckOptions::fast()).valid);
}

/// `fuzz/regressions/fill_rules` seeds the `fill_rules` target (replayed above with the
/// rest): one input per crossing family and raw rings, each named by what it decodes to —
/// family, seed, size, rule, strategy and precision — so a renamed or re-encoded seed shows.
#[test]
fn fill_rules_seeds_decode_as_named() {
    use polytri_oracle::fuzz::fill_case;
    use polytri_oracle::gen::crossing::CrossingFamily;
    let dir = fuzz_dir().join("regressions/fill_rules");
    let mut families = Vec::new();
    let mut raw = 0;
    for entry in std::fs::read_dir(&dir)
        .expect("fuzz/regressions/fill_rules")
        .flatten()
    {
        let name = entry.file_name().to_string_lossy().into_owned();
        let case = fill_case(&std::fs::read(entry.path()).expect("readable"));
        let precision = if case.f32 { "f32" } else { "f64" };
        let tail = format!(
            "{}_{}_{precision}",
            case.rule.name(),
            format!("{:?}", case.strategy).to_lowercase()
        )
        .replace('-', "_");
        if case.origin == "raw rings" {
            assert!(
                name.starts_with("raw_") && name.ends_with(&tail),
                "{name}: {case}"
            );
            raw += 1;
        } else {
            let expected = format!("{}_{tail}", case.origin.replace(['-', ' '], "_"));
            assert_eq!(name, expected, "{case}");
            families.push(case.origin.split(' ').next().unwrap_or("").to_owned());
        }
    }
    for family in CrossingFamily::ALL {
        assert!(
            families.iter().any(|f| f == family.name()),
            "no seed of {family}"
        );
    }
    assert!(raw >= 1, "no raw rings seed");
}
