//! Layer 2, structures: the node pool that holds every ring as a circular doubly linked
//! list by index, the uniform grids that answer "which nodes or edges lie near here", and
//! the set of ear tips known to fail, and a table of positions by their coordinates. They store positions and links; every geometric
//! decision about them is made in [`crate::geom`].

mod boxes;
mod grid;
mod pool;
pub(crate) mod positions;
mod tips;

pub(crate) use grid::{scale, shape, slot, Cells, EdgeGrid};
pub(crate) use pool::{Node, NodeId, Pool};
pub(crate) use tips::Tips;
