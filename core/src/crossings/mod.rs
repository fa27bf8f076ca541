//! Layer 3, the input check: do any two edges of the rings cross or touch?
//!
//! - [`proof`] first tries to *prove* that no two edges meet (except neighbours at their
//!   shared vertex), comparing only edges whose boxes overlap, within a linear budget;
//! - [`sweep`] is the full Shamos–Hoey plane sweep, run when the proof gives up or finds a
//!   meeting: it reports the first crossing and every T-junction before it;
//! - [`status`] holds the sweep's status (the edges crossing the sweep line, in order),
//!   flat while short, in blocks once long.
//!
//! They work on the node pool alone; the `clean` stage decides what to do with the answer.

pub(crate) mod proof;
pub(crate) mod status;
pub(crate) mod sweep;
