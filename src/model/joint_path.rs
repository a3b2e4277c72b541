//! A multi-link robot's path through configurations ([`JointPath`]): its legs cut into steps
//! of tan-half-angle timing ([`Chain::sweep`]), or moved in proportion as CASPR's splines go
//! ([`super::proportional`]), and the configuration at each t.

use super::chain::{Chain, Step};
use super::motion::{Motion, Param, ANGLE_PIECE};
use super::proportional::Leg;

/// A path through configurations of a multi-link robot, verified exactly: from each
/// configuration to the next every joint moves at once, each angle with tan-half-angle timing
/// (its half-angle tangent grows linearly from one end to the other) and each length linearly.
/// Each leg is cut into the fewest equal steps of at most [`ANGLE_PIECE`] in every angle; the
/// path's t runs over [0, 1], the legs taking equal shares and the steps equal shares of their
/// leg. A `proportional` path moves every joint in proportion instead — CASPR's joint splines'
/// path (`super::proportional`), t in proportion to the progress along each leg.
#[derive(Debug, Clone, PartialEq)]
pub struct JointPath {
    /// Its name.
    pub name: String,
    /// The configurations it passes through (at least two).
    pub through: Vec<Vec<f64>>,
    /// Whether every joint progresses in proportion from one configuration to the next.
    pub proportional: bool,
}

impl JointPath {
    /// Its steps: (from, to, t at from, t at to).
    pub fn steps(&self, chain: &Chain) -> Vec<(Vec<f64>, Vec<f64>, f64, f64)> {
        let legs = self.through.len().saturating_sub(1).max(1);
        let mut out = Vec::new();
        for (leg, w) in self.through.windows(2).enumerate() {
            let (a, b) = (&w[0], &w[1]);
            let widest = (0..a.len()).filter(|&i| chain.is_angle(i)).map(|i| (b[i] - a[i]).abs()).fold(0.0, f64::max);
            let n = ((widest / ANGLE_PIECE).ceil() as usize).max(1);
            let at = |j: usize| -> Vec<f64> { if j == n { b.clone() } else { a.iter().zip(b).map(|(x, y)| x + (y - x) * j as f64 / n as f64).collect() } };
            let t = |j: usize| if leg + 1 == legs && j == n { 1.0 } else { (leg as f64 + j as f64 / n as f64) / legs as f64 };
            for j in 0..n {
                out.push((at(j), at(j + 1), t(j), t(j + 1)));
            }
        }
        out
    }

    /// Every link's motion along each step (see [`Chain::sweep`]), or each piece of a
    /// proportional path's legs ([`Leg::sweep`]).
    pub fn motions(&self, chain: &Chain) -> Vec<Vec<Motion>> {
        if let Some(legs) = self.proportional_legs(chain) {
            let n = legs.len() as f64;
            let t = |k: usize| if k == legs.len() { 1.0 } else { k as f64 / n };
            return legs.iter().enumerate().flat_map(|(k, leg)| (0..leg.pieces()).map(move |p| leg.sweep(chain, p, (t(k), t(k + 1))))).collect();
        }
        self.steps(chain).into_iter().map(|(a, b, t0, t1)| chain.sweep(&a, &b, Param::Linear { lo: t0, hi: t1 })).collect()
    }

    /// A proportional path's legs (`None` for another path, or one with a leg that has no
    /// rational form, which validation refuses: [`JointPath::check_legs`]).
    fn proportional_legs(&self, chain: &Chain) -> Option<Vec<Leg>> {
        if !self.proportional {
            return None;
        }
        self.through.windows(2).map(|w| Leg::new(chain, &w[0], &w[1]).ok()).collect()
    }

    /// Why a proportional path's leg has no rational form, with the leg's number (0-based).
    pub fn check_legs(&self, chain: &Chain) -> Result<(), (usize, String)> {
        for (k, w) in self.through.windows(2).enumerate().filter(|_| self.proportional) {
            Leg::new(chain, &w[0], &w[1]).map_err(|e| (k, e))?;
        }
        Ok(())
    }

    /// The configuration at t ∈ [0, 1].
    pub fn config_at(&self, chain: &Chain, t: f64) -> Vec<f64> {
        if let Some(legs) = self.proportional_legs(chain) {
            let at = t.clamp(0.0, 1.0) * legs.len() as f64;
            let k = (at.floor() as usize).min(legs.len().saturating_sub(1));
            return legs.get(k).map_or_else(|| self.through[0].clone(), |leg| leg.config_at(at - k as f64));
        }
        let steps = self.steps(chain);
        let Some((a, b, t0, t1)) = steps.iter().find(|s| t <= s.3).or(steps.last()) else { return self.through.first().cloned().unwrap_or_default() };
        let lam = ((t - t0) / (t1 - t0)).clamp(0.0, 1.0);
        let mut q: Vec<f64> = a.iter().zip(b).map(|(x, y)| x + (y - x) * lam).collect();
        // angles: the tan-half-angle timing of each joint's sweep
        let mut o = 0;
        for link in &chain.links {
            let turns: Vec<(usize, f64)> = match link.joint.steps() {
                // φ, θ and σ − φ ramp; σ = φ + (σ − φ)
                None => {
                    let ramp = |d: f64| 2.0 * ((d / 2.0).tan() * lam).atan();
                    let (dphi, dpsi) = (b[o + 3] - a[o + 3], (b[o + 5] - b[o + 3]) - (a[o + 5] - a[o + 3]));
                    q[o + 3] = a[o + 3] + ramp(dphi);
                    q[o + 4] = a[o + 4] + ramp(b[o + 4] - a[o + 4]);
                    q[o + 5] = q[o + 3] + (a[o + 5] - a[o + 3]) + ramp(dpsi);
                    Vec::new()
                }
                Some(steps) => steps.iter().enumerate().filter(|(_, s)| matches!(s, Step::Turn(_))).map(|(k, _)| (o + k, b[o + k] - a[o + k])).collect(),
            };
            for (i, d) in turns {
                q[i] = a[i] + 2.0 * ((d / 2.0).tan() * lam).atan();
            }
            o += link.joint.dof();
        }
        q
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::chain::tests::{close, tree};

    #[test]
    fn paths_follow_their_configurations() {
        let chain = tree();
        let a = vec![0.2, -0.1, 0.4, 0.3, 0.5, -0.2, 0.3, -0.4, 0.2, 0.15, 0.7, 0.4, -0.6, 0.1, -0.2, 0.8, 0.5, 0.6, 0.7, -0.3, 0.2, 0.4];
        let b = vec![-0.3, 0.2, 0.1, -0.9, 1.1, 0.6, -0.5, 0.4, 1.0, -0.25, -0.8, -0.2, 0.9, 0.3, 0.1, -0.7, -0.4, 0.2, 0.1, 0.6, -0.9, 1.0];
        let c = vec![0.0; 22];
        let path = JointPath { name: "p".into(), through: vec![a.clone(), b.clone(), c.clone()], proportional: false };
        let steps = path.steps(&chain);
        assert!(steps.len() > 2, "the legs are cut into steps of at most π/8");
        assert_eq!((steps[0].2, steps.last().unwrap().3), (0.0, 1.0));
        assert_eq!(path.config_at(&chain, 0.0), a);
        assert_eq!(path.config_at(&chain, 1.0), c);
        assert!(path.config_at(&chain, 0.5).iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-12));
        for (motions, (_, _, t0, t1)) in path.motions(&chain).iter().zip(&steps) {
            // one weight: the same product of the moving joints' weights, multiplied in different
            // orders (each an enclosure of the exact product within its error bound)
            let w = &motions[0].weight;
            for m in motions {
                assert_eq!(m.weight.c.len(), w.c.len());
                assert!(m.weight.c.iter().zip(&w.c).all(|(a, b)| (a - b).abs() <= m.weight.err + w.err), "{:?} vs {:?}", m.weight, w);
            }
            for k in 0..=4 {
                let lam = k as f64 / 4.0;
                let frames = chain.frames(&path.config_at(&chain, t0 + (t1 - t0) * lam));
                for (l, m) in motions.iter().enumerate() {
                    assert!(close(m, lam, &frames[l]), "link {l} at t = {}", t0 + (t1 - t0) * lam);
                }
            }
        }
    }
}
