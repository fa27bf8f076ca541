//! Stage 4, *bridge*.
use crate::triangulator::Context;
use crate::Error;
pub(crate) fn bridge(cx: &mut Context) -> Result<(), Error> { let _ = cx; Ok(()) }
