//! The campaign engine: it passes polytri, catches a deliberately broken triangulator,
//! shrinks what it catches to a smaller valid case that still fails, writes it as corpus
//! JSON, and gives the same results whatever the number of threads.

use std::path::PathBuf;

use polytri_oracle::campaign::{self, Budget, Config, Fault, Polytri, Report, Run, Subject};
use polytri_oracle::gen::validate;
use polytri_oracle::{check_with, Case, CheckOptions, Family, Input};

/// polytri, but it drops the last triangle of every input with a hole.
fn drops_a_triangle(input: &Input, run: Run) -> Result<Vec<[u32; 3]>, String> {
    let mut triangles = Polytri.triangulate(input, run)?;
    if input.ring_count() >= 2 {
        triangles.pop();
    }
    Ok(triangles)
}

/// A fresh directory under the system's temporary one.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("polytri-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn config(cases: u64, families: &[Family]) -> Config {
    Config {
        budget: Budget::Cases(cases),
        families: families.to_vec(),
        max_vertices: 300,
        jobs: 2,
        ..Config::default()
    }
}

/// What must not depend on scheduling: the numbers (not the timings) and the shrunk cases.
fn fingerprint(report: &Report) -> Vec<String> {
    let mut lines: Vec<String> = report
        .families
        .iter()
        .map(|f| {
            format!(
                "{} {} {} {} {} {} {:?} {:?} {:?}",
                f.family,
                f.cases,
                f.runs,
                f.failed_runs,
                f.f32_invalid,
                f.vertices,
                f.fast_min_angles,
                f.quality_min_angles,
                f.cdt_min_angles
            )
        })
        .collect();
    // The shrunk cases, not their descriptions: the oracle's messages may differ in the
    // last digit of a float sum.
    lines.extend(
        report
            .failures
            .iter()
            .map(|f| format!("{} {:?}", f.case.name, f.case.input.rings())),
    );
    lines
}

#[test]
fn polytri_passes_every_family_in_both_strategies_and_precisions() {
    let report = campaign::run(&config(48, &Family::ALL), &Polytri, &|_| {});
    assert_eq!(report.cases(), 48);
    for family in &report.families {
        assert_eq!(family.cases, 4, "{}", family.family);
        assert!(family.runs >= 8, "{}: {} runs", family.family, family.runs);
        assert_eq!(family.fast_min_angles.len(), 4, "{}", family.family);
        assert_eq!(family.cdt_min_angles.len(), 4, "{}", family.family);
    }
    let failures: Vec<_> = report.failures.iter().map(|f| &f.runs).collect();
    assert!(report.passed(), "{failures:?}");
}

#[test]
fn a_dropped_triangle_is_caught_shrunk_and_written() {
    let out = scratch("campaign-broken");
    let mut config = config(12, &[Family::Star, Family::ManyHoles]);
    config.out_dir = Some(out.clone());
    let report = campaign::run(&config, &drops_a_triangle, &|_| {});

    // Stars have one ring: untouched. Every many-holes case fails in every run.
    assert_eq!(report.families[0].failed_runs, 0);
    assert_eq!(report.families[1].failed_cases, 6);
    assert_eq!(report.failures.len(), 6);
    for found in &report.failures {
        assert_eq!(found.plan.family, Family::ManyHoles);
        let first = &found.runs[0];
        assert_eq!(first.run, Run::ALL[0]);
        assert!(matches!(first.fault, Fault::Rejected(_)), "{first:?}");

        // Smaller, still valid, still failing the same way: an outer ring and one hole.
        let small = &found.case;
        assert!(small.input.vertices.len() < found.original_size.0);
        assert_eq!(small.input.ring_count(), 2, "{}", small.to_json());
        assert!(small.input.vertices.len() <= 8, "{}", small.to_json());
        assert!(validate(&small.input, false).is_ok());
        let triangles = drops_a_triangle(&small.input, first.run).expect("triangulates");
        let verdict = check_with(&small.input, &triangles, &CheckOptions::fast());
        assert!(!verdict.valid);
        assert!(verdict.check(first.fault.tag()).is_some_and(|c| !c.passed));

        // Named after what failed, and readable back from its file.
        assert!(
            small.name.starts_with(&format!(
                "campaign_many_holes_seed{}_fast_f64_",
                found.plan.seed
            )),
            "{}",
            small.name
        );
        assert_eq!(small.source, "campaign");
        assert_eq!(small.seed, Some(found.plan.seed));
        assert!(
            small.description.contains("fast_f64"),
            "{}",
            small.description
        );
        let path = found.written.clone().expect("an out dir").expect("written");
        assert_eq!(path, out.join(format!("{}.json", small.name)));
        let text = std::fs::read_to_string(&path).expect("readable");
        let back = Case::from_json(&text).expect("corpus JSON");
        assert_eq!(&back, small);
    }
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn results_do_not_depend_on_the_number_of_threads() {
    let families = [Family::Comb, Family::NestedIslands, Family::TouchingHoles];
    let mut one = config(15, &families);
    one.jobs = 1;
    let mut three = one.clone();
    three.jobs = 3;
    let a = campaign::run(&one, &drops_a_triangle, &|_| {});
    let b = campaign::run(&three, &drops_a_triangle, &|_| {});
    assert!(!a.failures.is_empty());
    assert_eq!(fingerprint(&a), fingerprint(&b));
    let ks: Vec<u64> = b.failures.iter().map(|f| f.k).collect();
    assert!(ks.windows(2).all(|w| w[0] < w[1]), "case order: {ks:?}");
}

#[test]
fn plans_draw_every_size_and_placement() {
    let config = Config::default();
    let plans: Vec<_> = (0..2000).map(|k| config.plan(k)).collect();
    assert!(plans.iter().all(|p| p.params.is_exact()));
    assert!(plans.iter().any(|p| p.params.vertices <= 10));
    assert!(plans.iter().any(|p| p.params.vertices > 2000));
    assert!(plans.iter().any(|p| p.params.offset[0].abs() > 1e6));
    assert!(plans.iter().any(|p| p.params.effective_scale() < 1e-3));
    assert!(plans.iter().any(|p| p.params.effective_scale() > 1e3));
    assert_eq!(plans[13].family, Family::ALL[1]);
    assert_eq!(plans[13].seed, 14);
    assert_eq!(config.plan(13), plans[13]);
}

#[test]
fn peers_are_judged_by_the_same_oracle() {
    let mut config = config(6, &[Family::Circles, Family::Spiral]);
    config.peers = true;
    let report = campaign::run(&config, &Polytri, &|_| {});
    for family in &report.families {
        assert_eq!(family.peers.len(), 5);
        for (peer, stats) in &family.peers {
            assert_eq!(
                stats.judged + stats.not_judged,
                family.cases,
                "{peer} on {}",
                family.family
            );
        }
    }
}

#[test]
fn runs_on_threads_are_judged_and_must_agree_across_thread_counts() {
    // polytri on 2 threads (mark-and-cut from 16 nodes, in chunks of 8): judged, and equal
    // to 3 threads
    let mut threaded = config(24, &Family::ALL);
    threaded.threads = 2;
    let report = campaign::run(&threaded, &Polytri, &|_| {});
    let failures: Vec<_> = report.failures.iter().map(|f| &f.runs).collect();
    assert!(report.passed(), "{failures:?}");
    let sequential = campaign::run(&config(24, &Family::ALL), &Polytri, &|_| {});
    // one more run per case
    assert_eq!(report.runs(), sequential.runs() + 24);

    // A stand-in whose triangles depend on the thread count: caught by `threads_agree`,
    // named after the threaded run, shrunk to a case that still fails so.
    let rotates_on_three = |input: &Input, run: Run| {
        let mut triangles = Polytri.triangulate(input, run)?;
        if run.threads == 3 {
            triangles.rotate_left(1);
        }
        Ok(triangles)
    };
    let mut broken = config(4, &[Family::Comb]);
    broken.threads = 2;
    let report = campaign::run(&broken, &rotates_on_three, &|_| {});
    assert_eq!(report.failures.len(), 4);
    for found in &report.failures {
        assert_eq!(found.runs.len(), 1, "{:?}", found.runs);
        let first = &found.runs[0];
        assert_eq!(first.run, Run::on_threads(2));
        assert_eq!(first.fault, Fault::Rejected(campaign::THREADS_AGREE.into()));
        assert!(first.detail.contains("2 and 3 threads"), "{}", first.detail);
        assert!(found.case.name.contains("_fast_f64_threads2_threads_agree"));
        assert!(found.case.input.vertices.len() <= found.original_size.0);
    }
}
