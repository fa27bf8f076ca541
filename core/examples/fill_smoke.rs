//! Scratch: random crossing rings through every fill rule, counting errors.
use polytri::{FillRule, Options, Strategy, Triangulator};

fn main() {
    let mut seed = 12345u64;
    let mut rnd = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut bad = 0;
    for case in 0..3000 {
        let rings = 1 + (rnd() * 3.0) as usize;
        let mut v: Vec<[f64; 2]> = Vec::new();
        let mut starts = Vec::new();
        for _ in 0..rings {
            starts.push(v.len());
            let n = 3 + (rnd() * 8.0) as usize;
            for _ in 0..n {
                if case % 2 == 0 {
                    v.push([(rnd() * 10.0).floor(), (rnd() * 10.0).floor()]);
                } else {
                    v.push([rnd() * 10.0, rnd() * 10.0]);
                }
            }
        }
        for rule in FillRule::ALL {
            for strategy in [Strategy::Fast, Strategy::Quality] {
                let opts = Options::new().with_fill_rule(rule).with_strategy(strategy);
                let mut out = Vec::new();
                let r64 = Triangulator::<f64>::new()
                    .triangulate(&v, &starts, &opts, &mut out)
                    .map(|_| ());
                let v32: Vec<[f32; 2]> = v.iter().map(|p| [p[0] as f32, p[1] as f32]).collect();
                let r32 = Triangulator::<f32>::new()
                    .triangulate(&v32, &starts, &opts, &mut out)
                    .map(|_| ());
                if r64.is_err() || r32.is_err() {
                    bad += 1;
                    if bad < 5 {
                        eprintln!("case {case} {rule:?} {strategy:?}: {r64:?} {r32:?}\n  {v:?} {starts:?}");
                    }
                }
            }
        }
    }
    eprintln!("errors: {bad}");
}
