//! Stage 3, *nest*.
use crate::triangulator::Context;
use crate::{Error, Nesting};
pub(crate) fn nest(cx: &mut Context, nesting: Nesting) -> Result<usize, Error> { let _ = (cx, nesting); Ok(0) }
