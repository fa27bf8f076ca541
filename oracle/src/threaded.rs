//! Triangulators on several threads, as the harness runs them: mark-and-cut lowered to
//! rings of [`MARK_AND_CUT_FROM`] nodes in chunks of [`MARK_AND_CUT_CHUNK`], so that
//! generated and fuzzed inputs (a few hundred vertices) take its rounds and their ears
//! straddle chunk boundaries, and one triangulator kept per thread count on each calling
//! thread, so that its pool starts once, not once per input.
//!
//! The fuzz targets and the campaign share these: the same lowering, the same reuse.

use std::cell::RefCell;
use std::thread::LocalKey;

use polytri::{Coord, Triangulator};

/// The ring size from which the kept triangulators clip by mark-and-cut.
pub const MARK_AND_CUT_FROM: usize = 16;

/// The nodes per chunk of their mark-and-cut rounds.
pub const MARK_AND_CUT_CHUNK: usize = 8;

/// Triangulators kept on one calling thread, by thread count.
type Kept<T> = RefCell<Vec<(usize, Triangulator<T>)>>;

thread_local! {
    static KEPT32: Kept<f32> = const { RefCell::new(Vec::new()) };
    static KEPT64: Kept<f64> = const { RefCell::new(Vec::new()) };
}

/// The coordinate types with kept triangulators.
pub trait KeptCoord: Coord + 'static {
    /// This thread's triangulators for the type.
    fn kept() -> &'static LocalKey<Kept<Self>>;
}

impl KeptCoord for f32 {
    fn kept() -> &'static LocalKey<Kept<f32>> {
        &KEPT32
    }
}

impl KeptCoord for f64 {
    fn kept() -> &'static LocalKey<Kept<f64>> {
        &KEPT64
    }
}

/// Calls `f` with this thread's triangulator for `threads` threads (created with
/// mark-and-cut lowered on first use). The caller still asks for the threads in its
/// `Options`; the triangulator only keeps the pool.
pub fn with_kept<T: KeptCoord, R>(threads: usize, f: impl FnOnce(&mut Triangulator<T>) -> R) -> R {
    T::kept().with(|kept| {
        let mut kept = kept.borrow_mut();
        let at = match kept.iter().position(|(n, _)| *n == threads) {
            Some(at) => at,
            None => {
                let mut tri = Triangulator::new();
                tri.set_mark_and_cut(MARK_AND_CUT_FROM, MARK_AND_CUT_CHUNK);
                kept.push((threads, tri));
                kept.len() - 1
            }
        };
        f(&mut kept[at].1)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use polytri::Options;

    #[test]
    fn kept_triangulators_clip_by_mark_and_cut() {
        // a 64-gon: four times the lowered threshold, several chunks
        let ring: Vec<[f64; 2]> = (0..64)
            .map(|i| {
                let t = f64::from(i) * core::f64::consts::TAU / 64.0;
                let r = if i % 2 == 0 { 10.0 } else { 6.0 };
                [r * t.cos(), r * t.sin()]
            })
            .collect();
        let options = Options::new().with_threads(2);
        let mut out = Vec::new();
        let log = with_kept::<f64, _>(2, |tri| {
            let result = tri.triangulate(&ring, &[0], &options, &mut out).map(|_| ());
            result.map(|()| tri.mark_and_cut_log().len())
        });
        assert_eq!(out.len(), 62);
        assert!(log.is_ok_and(|chunks| chunks > 0), "{log:?}");
    }
}
