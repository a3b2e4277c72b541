//! Plot geometry shared by the SVG plots: linear scales, round tick values, and SVG path text
//! for polylines with gaps and for bands. Plain functions, tested natively.

/// A linear map from the data interval [d0, d1] to the drawing interval [r0, r1].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scale {
    /// Data start.
    pub d0: f64,
    /// Data end.
    pub d1: f64,
    /// Drawing start.
    pub r0: f64,
    /// Drawing end.
    pub r1: f64,
}

impl Scale {
    /// The scale from [d0, d1] to [r0, r1]; an empty or non-finite data interval is widened to
    /// a unit one around its middle so that nothing divides by zero.
    pub fn new(d0: f64, d1: f64, r0: f64, r1: f64) -> Scale {
        let (d0, d1) = if d0.is_finite() && d1.is_finite() && d1 > d0 {
            (d0, d1)
        } else if d0.is_finite() {
            (d0 - 0.5, d0 + 0.5)
        } else {
            (0.0, 1.0)
        };
        Scale { d0, d1, r0, r1 }
    }

    /// Where data value `x` is drawn.
    pub fn at(&self, x: f64) -> f64 {
        self.r0 + (x - self.d0) / (self.d1 - self.d0) * (self.r1 - self.r0)
    }
}

/// Round tick values (1, 2 or 5 × 10^k apart) inside [lo, hi], their count as near `n` as
/// these steps allow (ties: fewer ticks).
pub fn ticks(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if !(lo.is_finite() && hi.is_finite()) || hi <= lo || n == 0 {
        return if lo.is_finite() { vec![lo] } else { vec![] };
    }
    let mag = 10f64.powf(((hi - lo) / n as f64).log10().floor());
    let count = |step: f64| (hi / step).floor() as i64 - (lo / step).ceil() as i64 + 1;
    let step = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * mag)
        .min_by_key(|&st| ((count(st) - n as i64).abs(), -(st / mag) as i64))
        .unwrap_or(mag);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last).map(|k| k as f64 * step).map(|v| if v.abs() < step * 1e-9 { 0.0 } else { v }).collect()
}

/// The range [min, max] of the finite values, widened by `pad` of its width on each side (a
/// unit range around a single value; `None` with no finite value).
pub fn extent(values: impl IntoIterator<Item = f64>, pad: f64) -> Option<[f64; 2]> {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.into_iter().filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if lo > hi {
        return None;
    }
    if hi - lo < 1e-12 {
        return Some([lo - 0.5, hi + 0.5]);
    }
    let w = hi - lo;
    Some([lo - pad * w, hi + pad * w])
}

/// A number in SVG path text: 2 decimals, enough for a drawing in pixels.
fn n(x: f64) -> String {
    let s = format!("{x:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}

/// SVG path data of a polyline with gaps: a run of `Some` points is one sub-path; `None` breaks
/// it. Lone points become zero-length sub-paths (visible with round caps).
pub fn polyline(points: &[Option<(f64, f64)>]) -> String {
    let mut out = String::new();
    let mut pen_down = false;
    for p in points {
        match p {
            Some((x, y)) => {
                out += &format!("{}{} {} ", if pen_down { "L" } else { "M" }, n(*x), n(*y));
                pen_down = true;
            }
            None => pen_down = false,
        }
    }
    out.trim_end().to_string()
}

/// SVG path data of the band between `lower` and `upper` over the same xs: one closed polygon
/// per run of samples where both are known.
pub fn band(xs: &[f64], lower: &[Option<f64>], upper: &[Option<f64>]) -> String {
    let mut out = Vec::new();
    let mut run: Vec<(f64, f64, f64)> = Vec::new();
    let mut flush = |run: &mut Vec<(f64, f64, f64)>| {
        if !run.is_empty() {
            let top: Vec<_> = run.iter().map(|&(x, _, hi)| Some((x, hi))).collect();
            let mut d = polyline(&top);
            for &(x, lo, _) in run.iter().rev() {
                d += &format!(" L{} {}", n(x), n(lo));
            }
            out.push(d + " Z");
            run.clear();
        }
    };
    for ((x, lo), hi) in xs.iter().zip(lower).zip(upper) {
        match (lo, hi) {
            (Some(lo), Some(hi)) => run.push((*x, *lo, *hi)),
            _ => flush(&mut run),
        }
    }
    flush(&mut run);
    out.join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scales_map_ends_and_survive_empty_ranges() {
        let s = Scale::new(0.0, 1.0, 40.0, 540.0);
        assert_eq!(s.at(0.0), 40.0);
        assert_eq!(s.at(1.0), 540.0);
        assert_eq!(s.at(0.5), 290.0);
        let flipped = Scale::new(-1.0, 1.0, 200.0, 0.0);
        assert_eq!(flipped.at(1.0), 0.0);
        let empty = Scale::new(2.0, 2.0, 0.0, 10.0);
        assert_eq!(empty.at(2.0), 5.0);
        assert!(Scale::new(f64::NAN, 1.0, 0.0, 1.0).at(0.5).is_finite());
    }

    #[test]
    fn ticks_are_round_and_inside() {
        let t = ticks(0.0, 1.0, 5);
        assert_eq!(t, [0.0, 0.2, 0.4, 0.6000000000000001, 0.8, 1.0]);
        let t = ticks(-3.1, 3.1, 6);
        assert_eq!(t, [-3.0, -2.0, -1.0, 0.0, 1.0, 2.0, 3.0]);
        let t = ticks(0.013, 0.049, 4);
        assert!(t.iter().all(|v| (0.013..=0.049).contains(v)) && t.len() >= 3, "{t:?}");
        assert_eq!(ticks(1.0, 1.0, 5), [1.0]);
        assert!(ticks(f64::NAN, 1.0, 5).is_empty());
    }

    #[test]
    fn extents_pad_and_skip_non_finite() {
        assert_eq!(extent([1.0, f64::NAN, 3.0], 0.5), Some([0.0, 4.0]));
        assert_eq!(extent([2.0], 0.1), Some([1.5, 2.5]));
        assert_eq!(extent([f64::INFINITY], 0.1), None);
    }

    #[test]
    fn polylines_break_at_gaps() {
        let p = [Some((0.0, 1.0)), Some((2.5, 3.0)), None, Some((4.0, 5.126))];
        assert_eq!(polyline(&p), "M0 1 L2.5 3 M4 5.13");
        assert_eq!(polyline(&[None, None]), "");
    }

    #[test]
    fn bands_close_each_run() {
        let xs = [0.0, 1.0, 2.0, 3.0];
        let lo = [Some(0.0), Some(1.0), None, Some(2.0)];
        let hi = [Some(5.0), Some(6.0), Some(7.0), Some(8.0)];
        assert_eq!(band(&xs, &lo, &hi), "M0 5 L1 6 L1 1 L0 0 Z M3 8 L3 2 Z");
    }
}
