//! Exact arithmetic beyond a sign: Shewchuk's expansions, for the two questions fill rules
//! ask that [`orient2d`](super::orient2d) alone cannot answer — *which grid point is
//! nearest to where two edges cross* ([`SnapGrid::crossing`]), and *does an edge pass
//! through the pixel of a grid point* ([`SnapGrid::meets_pixel`]).
//!
//! An expansion is a sum of `f64` components, nonoverlapping and in increasing magnitude,
//! that represents a number exactly; its sign is its largest component's. Sums and
//! products of expansions are exact as long as nothing overflows or underflows, which the
//! range fill rules accept guarantees (see [`in_range`]): coordinates are 0 or of
//! magnitude 2⁻²⁴⁸ to 2¹⁰⁰, every grid value is a multiple of 2⁻³⁰⁰, so every quantity
//! computed here (degree three at most in the coordinates) stays between 2⁻¹⁰⁰⁰ and 2⁴⁰⁰.

use core::cmp::Ordering;

/// A number as a sum of nonoverlapping `f64` components, smallest first (zeros removed).
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Exp(Vec<f64>);

#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bv = s - a;
    let av = s - bv;
    (s, (a - av) + (b - bv))
}

#[inline]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

impl Exp {
    /// The exact sum of some floats.
    pub fn sum(xs: &[f64]) -> Exp {
        let mut e = Exp(Vec::with_capacity(xs.len() + 1));
        for &x in xs {
            e.grow(x);
        }
        e
    }

    /// Adds one float (Shewchuk's Grow-Expansion, zeros eliminated).
    fn grow(&mut self, x: f64) {
        let mut q = x;
        let mut out = 0;
        for i in 0..self.0.len() {
            let (s, h) = two_sum(q, self.0[i]);
            q = s;
            if h != 0.0 {
                self.0[out] = h;
                out += 1;
            }
        }
        self.0.truncate(out);
        if q != 0.0 {
            self.0.push(q);
        }
    }

    /// `self + other`.
    pub fn add(&self, other: &Exp) -> Exp {
        let mut e = self.clone();
        for &x in &other.0 {
            e.grow(x);
        }
        e
    }

    /// `self − other`.
    pub fn sub(&self, other: &Exp) -> Exp {
        let mut e = self.clone();
        for &x in &other.0 {
            e.grow(-x);
        }
        e
    }

    /// `self · b` (Shewchuk's Scale-Expansion, zeros eliminated).
    pub fn scale(&self, b: f64) -> Exp {
        let mut out = Vec::with_capacity(2 * self.0.len());
        let Some((&first, rest)) = self.0.split_first() else {
            return Exp(out);
        };
        let (mut q, h) = two_prod(first, b);
        if h != 0.0 {
            out.push(h);
        }
        for &e in rest {
            let (p1, p0) = two_prod(e, b);
            let (s, h) = two_sum(q, p0);
            if h != 0.0 {
                out.push(h);
            }
            let (s2, h2) = two_sum(p1, s);
            if h2 != 0.0 {
                out.push(h2);
            }
            q = s2;
        }
        if q != 0.0 {
            out.push(q);
        }
        Exp(out)
    }

    /// `self · other`.
    pub fn mul(&self, other: &Exp) -> Exp {
        let mut acc = Exp::default();
        for &b in &other.0 {
            acc = acc.add(&self.scale(b));
        }
        acc
    }

    /// The sign, exactly.
    pub fn sign(&self) -> Ordering {
        match self.0.last() {
            Some(&x) if x > 0.0 => Ordering::Greater,
            Some(&x) if x < 0.0 => Ordering::Less,
            _ => Ordering::Equal,
        }
    }

    /// The value, rounded (an estimate: not for decisions).
    pub fn approx(&self) -> f64 {
        self.0.iter().sum()
    }
}

/// `(b − a) × (c − a)`, the orientation determinant of a, b, c, exactly.
pub(crate) fn orient_exp(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Exp {
    let bx = Exp::sum(&[b[0], -a[0]]);
    let by = Exp::sum(&[b[1], -a[1]]);
    let cx = Exp::sum(&[c[0], -a[0]]);
    let cy = Exp::sum(&[c[1], -a[1]]);
    bx.mul(&cy).sub(&by.mul(&cx))
}

/// Compares `n1 / d1` with `n2 / d2` exactly (denominators nonzero).
fn compare_ratios(n1: &Exp, d1: &Exp, n2: &Exp, d2: &Exp) -> Ordering {
    let s = n1.mul(d2).sub(&n2.mul(d1)).sign();
    if (d1.sign() == Ordering::Less) != (d2.sign() == Ordering::Less) {
        s.reverse()
    } else {
        s
    }
}

/// Smallest grid step, and the magnitude below which `f64`'s own steps are finer.
const TINY: f64 = 4.909_093_465_297_727e-91; // 2^-300
const FINE: f64 = 2.261_564_242_916_331_5e-75; // 2^-248
/// The largest coordinate magnitude fill rules accept.
const HUGE: f64 = 1.267_650_600_228_229_4e30; // 2^100

/// Whether fill rules compute exactly with this coordinate: 0, or magnitude 2⁻²⁴⁸ to 2¹⁰⁰.
pub(crate) fn in_range(x: f64) -> bool {
    x == 0.0 || (x.abs() >= FINE && x.abs() <= HUGE)
}

/// The grid crossing points are rounded to: the values of the coordinate type (`f32`, or
/// `f64` restricted to multiples of 2⁻³⁰⁰, which every accepted input coordinate is). Each
/// grid point's *pixel* is the set of points that round to it: half-open boxes from the
/// midpoint below to the midpoint above in each axis (ties round up).
#[derive(Clone, Copy, Debug)]
pub(crate) struct SnapGrid {
    pub f32: bool,
}

impl SnapGrid {
    /// The grid value after `x` (a grid value).
    pub fn up(self, x: f64) -> f64 {
        if self.f32 {
            f64::from(next_f32(x as f32, true))
        } else {
            next_f64(x, true).max(x + TINY)
        }
    }

    /// The grid value before `x` (a grid value).
    pub fn down(self, x: f64) -> f64 {
        if self.f32 {
            f64::from(next_f32(x as f32, false))
        } else {
            next_f64(x, false).min(x - TINY)
        }
    }

    /// A grid value near `x` (not necessarily the nearest).
    fn near(self, x: f64) -> f64 {
        if self.f32 {
            f64::from(x as f32)
        } else if x.abs() < FINE {
            (x / TINY).round() * TINY
        } else {
            x
        }
    }

    /// The grid value `num / den` rounds to (ties up), exactly.
    fn round(self, num: &Exp, den: &Exp) -> f64 {
        let mut g = self.near(num.approx() / den.approx());
        if !g.is_finite() {
            g = 0.0;
        }
        // value ≥ midpoint(g, up(g)): go up; value < midpoint(down(g), g): go down
        let at_least_mid = |lo: f64, hi: f64| {
            let two_num = num.scale(2.0);
            let mid2 = Exp::sum(&[lo, hi]);
            compare_ratios(&two_num, den, &mid2, &Exp::sum(&[1.0])) != Ordering::Less
        };
        loop {
            let u = self.up(g);
            if at_least_mid(g, u) {
                g = u;
                continue;
            }
            let d = self.down(g);
            if !at_least_mid(d, g) {
                g = d;
                continue;
            }
            return g;
        }
    }

    /// The grid point nearest to where segments a–b and c–d cross (they must cross at a
    /// point interior to both, not collinear), exactly rounded; a zero coordinate is +0.0,
    /// as loading reads the input's, so that a crossing rounded onto a vertex is at its
    /// position bit for bit.
    pub fn crossing(self, a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> [f64; 2] {
        let p = match self.crossing_quickly(a, b, c, d) {
            Some(p) => p,
            None => self.crossing_exactly(a, b, c, d),
        };
        [p[0] + 0.0, p[1] + 0.0]
    }

    /// [`SnapGrid::crossing`] in floating point, where that decides: the crossing
    /// p = a + t·(b − a), t = A / (A − B), A and B the orientations of a and b against
    /// c–d, each with Shewchuk's error bound; `Some` only when every point within the
    /// resulting error bound of the float p lies well inside one grid point's pixel, so
    /// that the exact crossing rounds to it. Most crossings end here.
    fn crossing_quickly(
        self,
        a: [f64; 2],
        b: [f64; 2],
        c: [f64; 2],
        d: [f64; 2],
    ) -> Option<[f64; 2]> {
        const E: f64 = f64::EPSILON;
        // orientation of p against c–d, and a bound on its error (Shewchuk's first bound
        // is 1.5·E·detsum; 4·E is generous)
        let orient = |p: [f64; 2]| {
            let left = (d[0] - c[0]) * (p[1] - c[1]);
            let right = (d[1] - c[1]) * (p[0] - c[0]);
            (left - right, 4.0 * E * (left.abs() + right.abs()))
        };
        let ((oa, ea), (ob, eb)) = (orient(a), orient(b));
        // a proper crossing: opposite sides, each clearly
        if !(oa.abs() > 4.0 * ea && ob.abs() > 4.0 * eb) || (oa > 0.0) == (ob > 0.0) {
            return None;
        }
        let whole = oa.abs() + ob.abs();
        let t = oa / (oa - ob);
        // t's error: first order in the orientations' errors (doubled: they are below a
        // quarter of each), plus the division's rounding
        let dt = 2.0 * (ea * ob.abs() + eb * oa.abs()) / (whole * whole) + 4.0 * E;
        let mut p = [0.0; 2];
        for k in 0..2 {
            let (span, step) = (b[k] - a[k], t * (b[k] - a[k]));
            let g = self.near(a[k] + step);
            // p − g as (a − g) + t·(b − a), with a − g exact (Sterbenz: within a factor
            // 2 of each other, or one of them 0), so that the error is that of t·(b − a),
            // not half a step of p's own rounding
            let sterbenz = (a[k] > 0.0) == (g > 0.0)
                && a[k].abs() <= 2.0 * g.abs()
                && g.abs() <= 2.0 * a[k].abs();
            if !g.is_finite() || !(sterbenz || a[k] == 0.0 || g == 0.0) {
                return None;
            }
            let base = a[k] - g;
            let off = base + step;
            let err = span.abs() * dt + 4.0 * E * (span.abs() + base.abs() + off.abs());
            // the pixel of g: half its steps below and above (exact differences)
            let (below, above) = ((g - self.down(g)) / 2.0, (self.up(g) - g) / 2.0);
            if !(off - err > -below && off + err < above) {
                return None;
            }
            p[k] = g;
        }
        Some(p)
    }

    /// [`SnapGrid::crossing`] in exact arithmetic.
    fn crossing_exactly(self, a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> [f64; 2] {
        // p = (b·A − a·B) / (A − B) with A = orient(c, d, a), B = orient(c, d, b)
        let oa = orient_exp(c, d, a);
        let ob = orient_exp(c, d, b);
        let den = oa.sub(&ob);
        let x = oa.scale(b[0]).sub(&ob.scale(a[0]));
        let y = oa.scale(b[1]).sub(&ob.scale(a[1]));
        [self.round(&x, &den), self.round(&y, &den)]
    }

    /// Whether the closed segment a–b meets the pixel of grid point `q` (a, b and q grid
    /// points), exactly.
    pub fn meets_pixel(self, a: [f64; 2], b: [f64; 2], q: [f64; 2]) -> bool {
        if a == q || b == q {
            return true;
        }
        self.meets_pixel_quickly(a, b, q)
            .unwrap_or_else(|| self.meets_pixel_exactly(a, b, q))
    }

    /// [`SnapGrid::meets_pixel`] in floating point, where that decides: `Some` only with a
    /// margin of several times the rounding errors. The segment's line misses the box
    /// round the pixel (half-widths its larger halves): `false`. The line passes through
    /// the open box inside it (the smaller halves), and that box lies within the segment's
    /// extent along its longer axis, so the line's points there are the segment's: `true`.
    /// (A line meets a box centred at q with half-widths hx, hy exactly when
    /// |(b − a) × (q − a)| ≤ |dy|·hx + |dx|·hy.) Most calls end here: a crossing's pixel
    /// is met well inside by the edges through it, others are far from the line.
    fn meets_pixel_quickly(self, a: [f64; 2], b: [f64; 2], q: [f64; 2]) -> Option<bool> {
        const E: f64 = 8.0 * f64::EPSILON;
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let (qx, qy) = (q[0] - a[0], q[1] - a[1]);
        let det = (dx * qy - dy * qx).abs();
        let err = E * ((dx * qy).abs() + (dy * qx).abs());
        // the pixel's halves below and above q, axis by axis (differences of neighbouring
        // grid values, halved: exact)
        let halves = |x: f64| ((x - self.down(x)) / 2.0, (self.up(x) - x) / 2.0);
        let ((lx, ux), (ly, uy)) = (halves(q[0]), halves(q[1]));
        let outer = dy.abs() * lx.max(ux) + dx.abs() * ly.max(uy);
        if det > outer * (1.0 + E) + err {
            return Some(false);
        }
        let (ix, iy) = (lx.min(ux), ly.min(uy));
        let inner = dy.abs() * ix + dx.abs() * iy;
        if det + err >= inner * (1.0 - E) {
            return None;
        }
        // the inner box's extent along the longer axis, within the segment's
        let (k, half) = if dx.abs() >= dy.abs() {
            (0, ix)
        } else {
            (1, iy)
        };
        let margin = E * (q[k].abs() + half);
        let within = q[k] - half - margin > a[k].min(b[k]) && q[k] + half + margin < a[k].max(b[k]);
        within.then_some(true)
    }

    /// [`SnapGrid::meets_pixel`] in exact arithmetic.
    fn meets_pixel_exactly(self, a: [f64; 2], b: [f64; 2], q: [f64; 2]) -> bool {
        // the segment's parameters t in [0, 1] inside the pixel, axis by axis: the lower
        // and upper bounds as ratios (numerator, denominator, closed)
        let zero = (Exp::default(), Exp::sum(&[1.0]), true);
        let one = (Exp::sum(&[1.0]), Exp::sum(&[1.0]), true);
        let mut lower = vec![zero];
        let mut upper = vec![one];
        for k in 0..2 {
            if a[k] == b[k] {
                if a[k] != q[k] {
                    return false; // grid values: inside the pixel's slab only if equal
                }
                continue;
            }
            // 2·(edge − a) / (2·(b − a)) for the slab's edges at the midpoints
            let den = Exp::sum(&[b[k], -a[k]]).scale(2.0);
            let lo = Exp::sum(&[self.down(q[k]), q[k], -2.0 * a[k]]);
            let hi = Exp::sum(&[q[k], self.up(q[k]), -2.0 * a[k]]);
            if b[k] > a[k] {
                lower.push((lo, den.clone(), true));
                upper.push((hi, den, false));
            } else {
                lower.push((hi, den.clone(), false));
                upper.push((lo, den, true));
            }
        }
        let pick = |bounds: &[(Exp, Exp, bool)], greatest: bool| {
            let mut best = 0;
            for i in 1..bounds.len() {
                let (n, d, closed) = &bounds[i];
                let (bn, bd, bclosed) = &bounds[best];
                let c = compare_ratios(n, d, bn, bd);
                let better = if greatest {
                    c == Ordering::Greater
                } else {
                    c == Ordering::Less
                };
                if better || (c == Ordering::Equal && !closed && *bclosed) {
                    best = i;
                }
            }
            best
        };
        let (lo, hi) = (pick(&lower, true), pick(&upper, false));
        let (ln, ld, lc) = &lower[lo];
        let (un, ud, uc) = &upper[hi];
        match compare_ratios(ln, ld, un, ud) {
            Ordering::Less => true,
            Ordering::Equal => *lc && *uc,
            Ordering::Greater => false,
        }
    }

    /// A bound on the distance from a grid value to the edges of its pixel.
    pub fn half_width(self, x: f64) -> f64 {
        (self.up(x) - x).max(x - self.down(x))
    }
}

/// The `f64` after (`up`) or before `x`.
fn next_f64(x: f64, up: bool) -> f64 {
    if x.is_nan() || (up && x == f64::INFINITY) || (!up && x == f64::NEG_INFINITY) {
        return x;
    }
    if x == 0.0 {
        let tiny = f64::from_bits(1);
        return if up { tiny } else { -tiny };
    }
    let bits = x.to_bits();
    f64::from_bits(if (x > 0.0) == up { bits + 1 } else { bits - 1 })
}

/// The `f32` after (`up`) or before `x`.
fn next_f32(x: f32, up: bool) -> f32 {
    if x.is_nan() || (up && x == f32::INFINITY) || (!up && x == f32::NEG_INFINITY) {
        return x;
    }
    if x == 0.0 {
        let tiny = f32::from_bits(1);
        return if up { tiny } else { -tiny };
    }
    let bits = x.to_bits();
    f32::from_bits(if (x > 0.0) == up { bits + 1 } else { bits - 1 })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn expansions_are_exact_where_floats_round() {
        let e = Exp::sum(&[1e20, 1.0, -1e20]);
        assert_eq!(e.approx(), 1.0);
        let p = Exp::sum(&[1.0 + f64::EPSILON]).mul(&Exp::sum(&[1.0 - f64::EPSILON]));
        // (1 + ε)(1 − ε) = 1 − ε², below 1 though it rounds to 1
        assert_eq!(p.sub(&Exp::sum(&[1.0])).sign(), Ordering::Less);
        assert_eq!(Exp::sum(&[2.0, -2.0]).sign(), Ordering::Equal);
    }

    #[test]
    fn the_grid_steps_over_every_value_of_the_type() {
        let g = SnapGrid { f32: false };
        assert_eq!(g.up(1.0), 1.0 + f64::EPSILON);
        assert_eq!(g.down(1.0), 1.0 - f64::EPSILON / 2.0);
        assert_eq!(g.up(0.0), TINY);
        assert_eq!(g.down(-1.0), -1.0 - f64::EPSILON);
        let g = SnapGrid { f32: true };
        assert_eq!(g.up(1.0), f64::from(1.0f32 + f32::EPSILON));
        assert_eq!(g.down(0.0), -f64::from(f32::from_bits(1)));
    }

    #[test]
    fn crossings_round_to_the_nearest_grid_point() {
        let g = SnapGrid { f32: false };
        // integer crossing: exact
        assert_eq!(
            g.crossing([0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]),
            [1.0, 1.0]
        );
        // x = 1/3: the f64 nearest to one third
        let p = g.crossing([0.0, 0.0], [1.0, 3.0], [0.0, 1.0], [1.0, 1.0]);
        assert_eq!(p, [1.0 / 3.0, 1.0]);
        let g32 = SnapGrid { f32: true };
        let p = g32.crossing([0.0, 0.0], [1.0, 3.0], [0.0, 1.0], [1.0, 1.0]);
        assert_eq!(p, [f64::from(1.0f32 / 3.0), 1.0]);
        // a tie rounds up: x = 1 + ε/2 lies halfway between 1 and 1 + ε
        let e = f64::EPSILON;
        let p = g.crossing([1.0, 0.0], [1.0 + e, 2.0], [0.0, 1.0], [4.0, 1.0]);
        assert_eq!(p, [1.0 + e, 1.0]);
    }

    #[test]
    fn segments_meet_pixels_exactly_with_half_open_edges() {
        let g = SnapGrid { f32: false };
        let e = f64::EPSILON;
        let q = [1.0, 1.0];
        // through the grid point
        assert!(g.meets_pixel([0.0, 0.0], [2.0, 2.0], q));
        // horizontal lines at the grid values next to 1 lie in the next pixels
        assert!(g.meets_pixel([0.0, 1.0], [2.0, 1.0], q));
        assert!(!g.meets_pixel([0.0, g.down(1.0)], [2.0, g.down(1.0)], q));
        assert!(!g.meets_pixel([0.0, g.up(1.0)], [2.0, g.up(1.0)], q));
        // a segment ending short of the pixel misses
        assert!(!g.meets_pixel([0.0, 1.0], [0.5, 1.0], q));
        // the pixel is [1 − ε/4, 1 + ε/2)²: a segment touching only its upper right
        // corner (open) misses, one touching only its lower left corner (closed) meets
        assert!(!g.meets_pixel([1.0, 1.0 + e], [1.0 + e, 1.0], q));
        assert!(g.meets_pixel([1.0 - e / 2.0, 1.0], [1.0, 1.0 - e / 2.0], q));
        // a diagonal through the inside
        assert!(g.meets_pixel([1.0 - e / 2.0, 1.0 + e], [1.0 + e, 1.0 - e / 2.0], q));
    }

    #[test]
    fn the_float_filter_agrees_with_the_exact_test() {
        // segments between grid points and grid points near them (a few pixels off the
        // line, or on it), at magnitudes from 2^-40 to 2^40, on both grids
        let mut rand = crate::testing::unit_random(0x2545_f491_4f6c_dd1d);
        let (mut decided, mut total) = (0, 0);
        for f32 in [false, true] {
            let g = SnapGrid { f32 };
            let snap = |v: f64| if f32 { f64::from(v as f32) } else { v };
            for _ in 0..20_000 {
                let scale = 2f64.powi((rand() * 80.0) as i32 - 40);
                let a = [snap(rand() * scale), snap(rand() * scale)];
                let b = [snap(rand() * scale), snap(rand() * scale)];
                if a == b {
                    continue;
                }
                let t = rand() * 1.2 - 0.1;
                let mut q = [
                    snap(a[0] + t * (b[0] - a[0])),
                    snap(a[1] + t * (b[1] - a[1])),
                ];
                // a few steps off in each axis
                for c in &mut q {
                    for _ in 0..(rand() * 4.0) as usize {
                        *c = if rand() < 0.5 { g.up(*c) } else { g.down(*c) };
                    }
                }
                total += 1;
                if let Some(quick) = g.meets_pixel_quickly(a, b, q) {
                    decided += 1;
                    assert_eq!(quick, g.meets_pixel_exactly(a, b, q), "{a:?} {b:?} {q:?}");
                }
            }
        }
        // the filter is of use: it decides most of these
        assert!(decided * 2 > total, "{decided} of {total}");
    }

    #[test]
    fn the_float_crossing_agrees_with_the_exact_one() {
        let mut rand = crate::testing::unit_random(0x9e37_79b9_7f4a_7c15);
        // (decided, crossing) cases: f32, and f64 with short segments far out
        let (mut f32_cases, mut far_cases) = ((0, 0), (0, 0));
        for f32 in [false, true] {
            let g = SnapGrid { f32 };
            let snap = |v: f64| if f32 { f64::from(v as f32) } else { v };
            for k in 0..20_000 {
                // segments short against their coordinates half the time (map data)
                let scale = 2f64.powi((rand() * 80.0) as i32 - 40);
                let offset = if k % 2 == 0 {
                    0.0
                } else {
                    scale * 2f64.powi((rand() * 30.0) as i32)
                };
                let mut pt = || [snap(offset + rand() * scale), snap(offset + rand() * scale)];
                let (a, b, c) = (pt(), pt(), pt());
                // d: random, or (every fourth case) nearly through a or b
                let d = if k % 4 == 0 {
                    let (e, t) = (if k % 8 == 0 { a } else { b }, 1.0 + rand());
                    [
                        snap(c[0] + t * (e[0] - c[0])),
                        snap(c[1] + t * (e[1] - c[1])),
                    ]
                } else {
                    pt()
                };
                let crosses = |p: [f64; 2], q: [f64; 2], r: [f64; 2], s: [f64; 2]| {
                    let o = |u: [f64; 2], v: [f64; 2], w: [f64; 2]| orient_exp(u, v, w).sign();
                    o(p, q, r) != o(p, q, s)
                        && o(r, s, p) != o(r, s, q)
                        && [o(p, q, r), o(p, q, s), o(r, s, p), o(r, s, q)]
                            .iter()
                            .all(|&x| x != Ordering::Equal)
                };
                if !crosses(a, b, c, d) {
                    continue;
                }
                let quick = g.crossing_quickly(a, b, c, d);
                if let Some(quick) = quick {
                    assert_eq!(
                        quick,
                        g.crossing_exactly(a, b, c, d),
                        "{a:?} {b:?} {c:?} {d:?}"
                    );
                }
                let count = if f32 {
                    &mut f32_cases
                } else if k % 2 == 1 {
                    &mut far_cases
                } else {
                    continue;
                };
                *count = (count.0 + usize::from(quick.is_some()), count.1 + 1);
            }
        }
        // the filter is of use: it decides most f32 crossings, and most f64 ones where the
        // segments are short against their coordinates (map data)
        for (decided, total) in [f32_cases, far_cases] {
            assert!(total > 1_000 && decided * 2 > total, "{decided} of {total}");
        }
    }
}
