//! Helpers shared by the integration tests (each test uses some of them).
#![allow(dead_code)]

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

/// splitmix64: a small seeded generator for the tests' choices.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number below `n` (0 for `n` = 0).
    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// `rings` with random starts, either winding for all of them, in a random quarter turn
/// (exact): which vertex is rightmost-lowest changes.
pub fn shuffled(mut rings: Vec<Vec<[f64; 2]>>, rng: &mut Rng) -> Vec<Vec<[f64; 2]>> {
    for ring in &mut rings {
        let k = rng.below(ring.len());
        ring.rotate_left(k);
    }
    if rng.below(2) == 1 {
        for ring in &mut rings {
            ring.reverse();
        }
    }
    let quarter = rng.below(4);
    for p in rings.iter_mut().flatten() {
        let [x, y] = *p;
        *p = match quarter {
            0 => [x, y],
            1 => [-y, x],
            2 => [-x, -y],
            _ => [y, -x],
        };
    }
    rings
}

/// Fails, listing them, when there are failures.
pub fn assert_no_failures(failures: &[String]) {
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
