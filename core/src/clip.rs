//! Stage 5, *clip*.
use crate::triangulator::Context;
use crate::{Error, Strategy};
#[derive(Debug, Default)]
pub(crate) struct ClipScratch {}
pub(crate) fn clip(cx: &mut Context, strategy: Strategy, out: &mut Vec<[u32; 3]>) -> Result<usize, Error> { let _ = (cx, strategy, out); Ok(0) }
