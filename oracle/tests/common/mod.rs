//! Helpers shared by the integration tests.

use polytri::{Options, Strategy, Triangulator};
use polytri_oracle::Input;

/// Triangulates `input` in f64 with the nesting convention it names (`Auto` for explicit
/// roles), in `strategy`, strict or lenient; the error as its message.
pub fn run(input: &Input, strategy: Strategy, lenient: bool) -> Result<Vec<[u32; 3]>, String> {
    let nesting = input.nesting.to_polytri().unwrap_or(polytri::Nesting::Auto);
    let options = Options::default()
        .with_strategy(strategy)
        .with_nesting(nesting)
        .with_lenient(lenient);
    let mut out = Vec::new();
    Triangulator::<f64>::new()
        .triangulate(&input.vertices, &input.ring_starts, &options, &mut out)
        .map(|_| out)
        .map_err(|e| e.to_string())
}
