//! A warmed-up `Triangulator` allocates nothing: the second call on the same input, with the
//! same output `Vec`, makes zero allocations — for every strategy, strict, lenient and by a
//! fill rule, and both precisions.
//!
//! Only this test binary installs the counting allocator. It counts allocations made by the
//! current thread while counting is switched on, so the test harness's own threads do not
//! disturb the count.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::path::Path;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use polytri::{FillRule, Nesting, Options, Strategy, Triangulator};
use serde_json::Value;

type Rings = Vec<Vec<[f64; 2]>>;

/// Rings as the triangulator takes them: every point in one list, and each ring's start.
struct Flat {
    vertices: Vec<[f64; 2]>,
    ring_starts: Vec<usize>,
}

/// Concatenates rings; empty rings are left out (ring starts must increase).
fn flatten(rings: &[Vec<[f64; 2]>]) -> Flat {
    let mut ring_starts = Vec::new();
    let mut vertices = Vec::new();
    for ring in rings.iter().filter(|r| !r.is_empty()) {
        ring_starts.push(vertices.len());
        vertices.extend_from_slice(ring);
    }
    Flat {
        vertices,
        ring_starts,
    }
}

/// A JSON file of the corpus (`corpus/<relative>`).
fn read_json(relative: &str) -> Value {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../corpus")
        .join(relative);
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("bad JSON in {}: {e}", path.display()))
}

/// Rings JSON: `[[[x, y], …], …]`.
fn rings_json(value: &Value) -> Rings {
    serde_json::from_value(value.clone()).expect("rings JSON")
}

fn to_f32(vertices: &[[f64; 2]]) -> Vec<[f32; 2]> {
    vertices
        .iter()
        .map(|&[x, y]| [x as f32, y as f32])
        .collect()
}

struct Counting;

thread_local! {
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    static COUNT: Cell<usize> = const { Cell::new(0) };
}

/// Allocations on every thread while `EVERY_THREAD` is on (for the pool's threads; this
/// binary has one test, so no other test allocates meanwhile).
static EVERY_THREAD: AtomicBool = AtomicBool::new(false);
static EVERY_COUNT: AtomicUsize = AtomicUsize::new(0);

fn note_allocation() {
    // `try_with`: the thread-locals may be gone while a thread shuts down.
    let _ = COUNTING.try_with(|on| {
        if on.get() {
            let _ = COUNT.try_with(|c| c.set(c.get() + 1));
        }
    });
    if EVERY_THREAD.load(Ordering::Relaxed) {
        EVERY_COUNT.fetch_add(1, Ordering::Relaxed);
    }
}

// SAFETY: every call is forwarded unchanged to `System`; the bookkeeping only touches
// const-initialised thread-locals, which never allocate.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        note_allocation();
        System.alloc(layout)
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        note_allocation();
        System.alloc_zeroed(layout)
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        note_allocation();
        System.realloc(ptr, layout, new_size)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Allocations made by `f` on this thread.
fn allocations<R>(f: impl FnOnce() -> R) -> (usize, R) {
    COUNT.with(|c| c.set(0));
    COUNTING.with(|on| on.set(true));
    let r = f();
    COUNTING.with(|on| on.set(false));
    (COUNT.with(|c| c.get()), r)
}

fn inputs() -> Vec<(String, Flat, Nesting)> {
    let mut v = Vec::new();
    let shapes: Vec<Rings> =
        serde_json::from_value(read_json("datasets/rect_circles.json")).expect("shapes JSON");
    let all: Rings = shapes.into_iter().flatten().collect();
    v.push(("rect_circles".to_string(), flatten(&all), Nesting::Auto));
    // (building: one ring of 15 vertices with a closing point, the small stage's)
    for name in [
        "building",
        "water",
        "dude",
        "eberly-6",
        "touching-holes",
        "issue83",
        "steiner",
    ] {
        let rings = rings_json(&read_json(&format!("earcut/fixtures/{name}.json")));
        v.push((name.to_string(), flatten(&rings), Nesting::FirstIsOuter));
    }
    // weakly simple rings: cracks, walls and segments walked several times (touch's
    // alternating order and its reading of cracks at the far ends)
    for name in [
        "crack_between_two_ring_visits",
        "island_fills_its_holes_corner",
        "spiral_walking_segments_three_times",
        "two_lobes_joined_by_a_wall_at_the_rightmost_vertex",
    ] {
        let rings = rings_json(&read_json(&format!("cases/{name}.json"))["rings"]);
        v.push((name.to_string(), flatten(&rings), Nesting::Auto));
    }
    // two figure eights sharing a lobe (raw_rings seed 41): lenient mode cuts both into
    // lobes and nests those, in both conventions
    let eights = vec![
        vec![
            [11.0, 11.0],
            [-3.0, 0.0],
            [0.0, 0.0],
            [5.0, -12.0],
            [-12.0, -12.0],
        ],
        vec![
            [-12.0, -12.0],
            [11.0, 11.0],
            [-3.0, 0.0],
            [0.0, 0.0],
            [-4.0, -8.0],
        ],
    ];
    for nesting in [Nesting::Auto, Nesting::FirstIsOuter] {
        v.push((
            format!("figure eights {nesting:?}"),
            flatten(&eights),
            nesting,
        ));
    }
    // a star: the sweep line crosses thousands of spikes, so the check's status is chunked
    let mut seed = 12345u64;
    let star: Vec<[f64; 2]> = (0..4000)
        .map(|i| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let r = 0.2 + 0.8 * ((seed >> 11) as f64 / (1u64 << 53) as f64);
            let a = i as f64 * core::f64::consts::TAU / 4000.0;
            [r * a.cos(), r * a.sin()]
        })
        .collect();
    v.push(("star".to_string(), flatten(&[star]), Nesting::FirstIsOuter));
    // a comb of more than 2^14 vertices: the fast strategy lays its nodes out in ring order
    // first, and its walk jumps over the teeth
    let teeth = 4200;
    let mut comb: Vec<[f64; 2]> = (0..teeth)
        .flat_map(|t| {
            let x = 2.0 * t as f64;
            [[x, 1.0], [x, 10.0], [x + 1.0, 10.0], [x + 1.0, 1.0]]
        })
        .collect();
    comb.extend([[2.0 * teeth as f64 - 1.0, 0.0], [0.0, 0.0]]);
    v.push(("comb".to_string(), flatten(&[comb]), Nesting::FirstIsOuter));
    v
}

#[test]
fn warmed_up_triangulator_does_not_allocate() {
    warmed_up_triangulate_many_allocates_its_results_and_one_job();
    let mut failures = Vec::new();
    let mut tri64 = Triangulator::<f64>::new();
    let mut tri32 = Triangulator::<f32>::new();
    let mut out: Vec<[u32; 3]> = Vec::new();
    // Warm up on every input first, so buffers have grown to the largest size.
    let inputs = inputs();
    // every strategy strict and lenient, and by the even-odd rule
    let runs = [Strategy::Fast, Strategy::Quality, Strategy::Seidel]
        .into_iter()
        .flat_map(|s| [(s, Some(true)), (s, Some(false)), (s, None)]);
    for (strategy, lenient) in runs {
        for (name, flat, nesting) in &inputs {
            let opts = Options::default()
                .with_strategy(strategy)
                .with_nesting(*nesting);
            let opts = match lenient {
                Some(lenient) => opts.with_lenient(lenient),
                None => opts.with_fill_rule(FillRule::EvenOdd),
            };
            let strategy = format!(
                "{strategy:?}{}",
                match lenient {
                    Some(true) => " lenient",
                    Some(false) => "",
                    None => " even-odd",
                }
            );
            let v32 = to_f32(&flat.vertices);
            let warm64 = tri64
                .triangulate(&flat.vertices, &flat.ring_starts, &opts, &mut out)
                .map(|r| r.triangles);
            let first64 = out.clone();
            let (n64, again64) = allocations(|| {
                tri64
                    .triangulate(&flat.vertices, &flat.ring_starts, &opts, &mut out)
                    .map(|r| r.triangles)
            });
            // The one known exception: rounding a crossing to f64 whose float filter is
            // unsure (water's rings cross at such points; f32's coarser grid decides
            // them in floating point) computes with exact expansions, which live on the
            // heap (`geom::exact::Exp`).
            let rounds_exactly =
                name == "water" && (lenient.is_none() || strategy.starts_with("Seidel"));
            if n64 != 0 && !rounds_exactly {
                failures.push(format!(
                    "{name} {strategy} f64: {n64} allocation(s) on the second call"
                ));
            }
            if warm64 != again64 || first64 != out {
                failures.push(format!(
                    "{name} {strategy} f64: second call gave a different result"
                ));
            }
            let _ = tri32.triangulate(&v32, &flat.ring_starts, &opts, &mut out);
            let (n32, _) = allocations(|| {
                tri32
                    .triangulate(&v32, &flat.ring_starts, &opts, &mut out)
                    .map(|r| r.triangles)
            });
            if n32 != 0 {
                failures.push(format!(
                    "{name} {strategy} f32: {n32} allocation(s) on the second call"
                ));
            }
        }
    }
    // And once more over all inputs in turn: buffers already large enough, nothing grows.
    for (name, flat, nesting) in &inputs {
        let opts = Options::default().with_nesting(*nesting).with_lenient(true);
        let (n, _) = allocations(|| {
            tri64
                .triangulate(&flat.vertices, &flat.ring_starts, &opts, &mut out)
                .map(|r| r.triangles)
        });
        if n != 0 {
            failures.push(format!(
                "{name} Fast f64 after other inputs: {n} allocation(s)"
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "{} failure(s):\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// `triangulate_many`, warm: one thread allocates only the returned `Vec` of results; on
/// two threads, also the job handed to the pool's thread, and the workers only while
/// their buffers grow to the inputs they meet. (Called from the test above: counting the
/// pool's threads counts every thread, so nothing else may run meanwhile.)
fn warmed_up_triangulate_many_allocates_its_results_and_one_job() {
    let shapes: Vec<Rings> =
        serde_json::from_value(read_json("datasets/lorem_latin.json")).expect("shapes JSON");
    let flats: Vec<Flat> = shapes.iter().map(|rings| flatten(rings)).collect();
    let polygons: Vec<(&[[f64; 2]], &[usize])> = flats
        .iter()
        .map(|f| (&f.vertices[..], &f.ring_starts[..]))
        .collect();
    assert!(polygons.len() > 40);
    let mut tri = Triangulator::<f64>::new();
    let mut out = Vec::new();
    let opts = Options::default().with_nesting(Nesting::FirstIsOuter);
    tri.triangulate_many(&polygons, &opts, &mut out);
    let (n, ok) = allocations(|| {
        tri.triangulate_many(&polygons, &opts, &mut out)
            .iter()
            .all(Result::is_ok)
    });
    assert!(ok);
    assert_eq!(n, 1, "one thread: the results Vec only");
    if cfg!(feature = "threads") {
        let opts = opts.with_threads(2);
        // which worker takes which input varies from call to call: a few calls give each
        // worker buffers for the largest input
        for _ in 0..8 {
            tri.triangulate_many(&polygons, &opts, &mut out);
        }
        EVERY_COUNT.store(0, Ordering::Relaxed);
        EVERY_THREAD.store(true, Ordering::Relaxed);
        let ok = tri
            .triangulate_many(&polygons, &opts, &mut out)
            .iter()
            .all(Result::is_ok);
        EVERY_THREAD.store(false, Ordering::Relaxed);
        assert!(ok);
        let n = EVERY_COUNT.load(Ordering::Relaxed);
        eprintln!("ALLOC two threads {n}");
        // the results Vec, and the job handed to the pool's thread (rayon boxes a
        // spawned job; the caller works on its own worker meanwhile); and rarely a worker
        // that meets a larger input than on any call before grows a buffer once (which
        // thread takes which inputs varies)
        assert!(
            (2..=2 + 2 * 2).contains(&n),
            "two threads: {n} allocations for {} inputs",
            polygons.len()
        );
        warmed_up_mark_and_cut_allocates_nothing();
    }
}

/// Mark-and-cut (one large polygon on two threads, the size it starts at lowered) keeps
/// its marks between calls: once each thread has worked, a call allocates nothing on any
/// thread (two calls in a row).
fn warmed_up_mark_and_cut_allocates_nothing() {
    let (name, flat, nesting) = inputs()
        .into_iter()
        .find(|(name, _, _)| name == "star")
        .expect("the star input");
    let mut tri = Triangulator::<f64>::new();
    tri.set_mark_and_cut(1000, 256);
    let opts = Options::default().with_nesting(nesting).with_threads(2);
    let mut out = Vec::new();
    let mut one = Vec::new();
    let single = Options::default().with_nesting(nesting);
    Triangulator::<f64>::new()
        .triangulate(&flat.vertices, &flat.ring_starts, &single, &mut one)
        .expect("valid");
    tri.triangulate(&flat.vertices, &flat.ring_starts, &opts, &mut out)
        .expect("valid");
    assert_ne!(out, one, "{name}: mark-and-cut did not run");
    // A pool thread that woke too late to take a chunk in the first call allocates its
    // buffers on its first chunk, in a later call (a loaded machine): the calls settle
    // within a few, and from then on allocate nothing.
    let mut counts = Vec::new();
    for _ in 0..8 {
        EVERY_COUNT.store(0, Ordering::Relaxed);
        EVERY_THREAD.store(true, Ordering::Relaxed);
        let again = tri.triangulate(&flat.vertices, &flat.ring_starts, &opts, &mut out);
        EVERY_THREAD.store(false, Ordering::Relaxed);
        assert!(again.is_ok());
        counts.push(EVERY_COUNT.load(Ordering::Relaxed));
        if counts.ends_with(&[0, 0]) {
            return;
        }
    }
    panic!("{name} by mark-and-cut: allocations on each call after the first: {counts:?}");
}
