//! The coordinate types the triangulator accepts, widened to `f64` exactly.

/// A coordinate type the triangulator accepts: `f32` or `f64`.
///
/// Coordinates are widened to `f64` when loaded, which is exact, so every predicate gives
/// the exact answer for the coordinates the caller gave.
pub trait Coord: Copy + Send + Sync + sealed::Sealed {
    /// The value as `f64` (exact for both implementations).
    fn to_f64(self) -> f64;
    /// The value of an `f64` that is one of this type's values (exact then; otherwise
    /// rounded).
    fn from_f64(x: f64) -> Self;
    /// Whether this is `f32` (its grid of values is then `f32`'s).
    const IS_F32: bool;
}

impl Coord for f64 {
    #[inline]
    fn to_f64(self) -> f64 {
        self
    }
    #[inline]
    fn from_f64(x: f64) -> Self {
        x
    }
    const IS_F32: bool = false;
}

impl Coord for f32 {
    #[inline]
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
    #[inline]
    fn from_f64(x: f64) -> Self {
        x as f32
    }
    const IS_F32: bool = true;
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for f64 {}
}
