//! Stage 2, *clean*.
use crate::triangulator::Context;
use crate::Error;
pub(crate) fn clean(cx: &mut Context) -> Result<(), Error> { let _ = cx; Ok(()) }
