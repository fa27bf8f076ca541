//! Horizontal bands of edges: the spatial index for ray casts and triangle searches.
#[derive(Debug, Default)]
pub(crate) struct Bands {}
