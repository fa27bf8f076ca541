//! Layer 5, the stages of the pipeline, in the order the triangulator runs them:
//! [`load`] → [`clean`] (→ [`lobes`], lenient) → [`nest`] → [`touch`] → [`bridge`] →
//! [`clip`]; [`small`] stands in for all of them on one small polygon. Each is a function
//! over the [`Context`](crate::context::Context) and its own scratch; no stage imports
//! another — what one stage leaves for the next is in the context, and `ARCHITECTURE.md`
//! states it as each stage's guarantee.

pub(crate) mod bridge;
pub(crate) mod clean;
pub(crate) mod clip;
pub(crate) mod load;
pub(crate) mod lobes;
pub(crate) mod nest;
pub(crate) mod resolve;
pub(crate) mod seidel;
pub(crate) mod small;
pub(crate) mod touch;
