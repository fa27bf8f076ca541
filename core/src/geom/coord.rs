//! The coordinate types the triangulator accepts, widened to `f64` exactly.

/// A coordinate type the triangulator accepts: `f32` or `f64`.
///
/// Coordinates are widened to `f64` when loaded, which is exact, so every predicate gives
/// the exact answer for the coordinates the caller gave.
pub trait Coord: Copy + Send + Sync + sealed::Sealed {
    /// The value as `f64` (exact for both implementations).
    fn to_f64(self) -> f64;
}

impl Coord for f64 {
    #[inline]
    fn to_f64(self) -> f64 {
        self
    }
}

impl Coord for f32 {
    #[inline]
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for f64 {}
}
