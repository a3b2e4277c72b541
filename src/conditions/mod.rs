//! Feasibility conditions. Each is one implementation of [`Condition`], which answers both
//! questions the rest of the core asks:
//!
//! * exactly, along a [`Motion`]: the set of λ ∈ [0, 1] where the condition is violated, as a
//!   certified three-valued [`Partition`];
//! * point-wise, at one pose: violated or not, and a distance where one is meaningful.
//!
//! The verifier, the point-wise baseline, the ray and the per-pose check all go through this
//! trait and never look inside a condition.

pub mod algebra;
mod cable_cable;
mod cable_length;
mod cable_link;
mod cable_shape;
mod interval;
pub mod primitives;
mod closure;
pub mod exists;
mod joint_closure;
mod load;
mod offset;
mod structure;
mod tension;
pub mod tube;
mod winch;
mod wrench_lp;

pub use cable_cable::CableCable;
pub use cable_length::CableLength;
pub use cable_link::CableLink;
pub use cable_shape::CableShape;
pub use closure::{FacetPolys, WrenchClosure, WrenchFeasibility};
pub use joint_closure::JointClosure;
pub use tension::{CableTension, Side, TensionPolys};
pub use winch::{Rate, WinchLimit};
pub use wrench_lp::WrenchFeasibilityLp;

use std::cell::OnceCell;
use std::rc::Rc;

use crate::model::chain::Frame;
use crate::model::{Kinematics, Load, Motion, Pose, Robot};
use crate::poly::{Bern, Partition, Truth};
use crate::query::wrench::{tension_ranges_at, TensionRange};
use crate::scenario::Scenario;
use algebra::{Alg, HVec};
use tube::Tube;
use nalgebra::Vector3;

/// One cable along a motion: the segment base → base + s(λ), with s as a fraction over w.
#[derive(Debug, Clone)]
pub struct SweptCable {
    /// The base anchor.
    pub base: Vector3<f64>,
    /// The cable vector s = p + R b − a (one power of w).
    pub s: HVec,
    /// Balls holding its moving end piece by piece, for pruning.
    pub tube: Tube,
}

/// Everything the exact conditions share along one motion.
#[derive(Debug, Clone)]
pub struct Sweep {
    /// Powers of the motion's denominator.
    pub alg: Alg,
    /// The cables, in robot order.
    pub cables: Vec<SweptCable>,
    /// Width (in λ) below which an undecided piece is reported rather than subdivided further.
    pub tol: f64,
    /// The motion of every link (one, the platform's, for a platform robot), all with one weight
    /// and one parameter.
    pub links: Vec<Motion>,
    /// The wrench polynomials, built by the first tension condition that needs them.
    pub tension: Option<Rc<TensionPolys>>,
    /// The facet polynomials of robots with more than six cables, built likewise.
    pub facets: Option<Rc<FacetPolys>>,
    /// Ordered, disjoint λ-intervals where other conditions are already certainly violated (set
    /// by the caller, kept clear of their ends by a margin): a condition may leave itself
    /// undecided (`Unknown`) there, without pruning or exact work, since its answer cannot change
    /// the union, nor the constraints active at its boundaries.
    pub settled: Vec<(f64, f64)>,
    /// How long the whole trajectory takes (seconds) when it is run in time: the conditions that
    /// depend on speed (inertia, winch limits) take their rates from it. `None` for a motion
    /// without time (a ray, an untimed trajectory): those conditions see the robot at rest.
    pub duration: Option<f64>,
}

impl Sweep {
    /// Prepares the cables of a platform robot along the platform's `motion`.
    pub fn new(robot: &Robot, motion: &Motion, tol: f64) -> Sweep {
        Sweep::of_links(robot, std::slice::from_ref(motion), tol)
    }

    /// Prepares the cables of `robot` along its links' motions `links` (one per link, with a
    /// common weight and parameter; one for a platform robot).
    pub fn of_links(robot: &Robot, links: &[Motion], tol: f64) -> Sweep {
        // each row's polynomials raised once to the row's common degree (at least w's), so that
        // each cable's vectors are plain linear combinations of coefficients
        let w = &links[0].weight;
        let row_degree = |i: usize| links.iter().flat_map(|m| m.rotation[i].iter().chain([&m.position[i]])).map(Bern::degree).fold(w.degree(), usize::max);
        let n = [row_degree(0), row_degree(1), row_degree(2)];
        let lifted: Vec<([Bern; 3], [[Bern; 3]; 3])> = links.iter().map(|m| ([0, 1, 2].map(|i| m.position[i].elevate(n[i])), [0, 1, 2].map(|i| m.rotation[i].each_ref().map(|p| p.elevate(n[i]))))).collect();
        let w_at = n.map(|d| w.elevate(d));
        let mut cables = Vec::with_capacity(robot.cables.len());
        for cable in &robot.cables {
            let (position, rotation) = &lifted[cable.link];
            let b = cable.platform;
            // X̂ = P̂ + M̂ b (one power of w); s = X̂ − a·w
            let tip: [Bern; 3] = [0, 1, 2].map(|i| Bern::linear_combination(&[(&position[i], 1.0), (&rotation[i][0], b[0]), (&rotation[i][1], b[1]), (&rotation[i][2], b[2])]));
            let s: HVec = [0, 1, 2].map(|i| algebra::H { p: Bern::linear_combination(&[(&tip[i], 1.0), (&w_at[i], -cable.base[i])]), k: 1 });
            let tube = Tube::new(cable.base, &tip, w);
            cables.push(SweptCable { base: cable.base, s, tube });
        }
        Sweep { alg: Alg::new(w), cables, tol, links: links.to_vec(), tension: None, facets: None, settled: Vec::new(), duration: None }
    }

    /// The platform's motion (the first link's for a multi-link robot): the weight and the
    /// parameter every link shares.
    pub fn motion(&self) -> &Motion {
        &self.links[0]
    }
}

/// The violation set of a condition that the tube pruning decided outside `undecided` (ordered,
/// disjoint λ-intervals): `False` there, `Unknown` where the sweep's `settled` intervals spare the
/// work, and on each remaining interval (a, b) what `exact` finds on the motion restricted to it —
/// the powers of the restricted w, that w, the restricted cable vectors s of `cables` (in that
/// order), the tolerance in the local parameter, and (a, b) itself — mapped back. Exact work is thus done only where the
/// pruning could not decide and the answer matters.
pub fn on_undecided(
    sweep: &mut Sweep,
    undecided: &[(f64, f64)],
    cables: &[usize],
    mut exact: impl FnMut(&mut Alg, &Bern, &[&HVec], f64, (f64, f64)) -> Partition,
) -> Partition {
    let (work, spared) = subtract(undecided, &sweep.settled);
    if let [(a, b)] = work[..] {
        if a <= 0.0 && b >= 1.0 {
            let Sweep { alg, cables: swept, tol, links, .. } = sweep;
            let s: Vec<&HVec> = cables.iter().map(|&i| &swept[i].s).collect();
            return exact(alg, &links[0].weight, &s, *tol, (0.0, 1.0));
        }
    }
    let mut out = Partition::constant(Truth::False);
    let unknown = Partition::constant(Truth::Unknown);
    for (a, b) in spared {
        out = out.splice((a, b), &unknown, (a, b));
    }
    for (a, b) in work {
        let w = sweep.motion().weight.restrict(a, b);
        let mut alg = Alg::new(&w);
        let s: Vec<HVec> = cables.iter().map(|&i| sweep.cables[i].s.clone().map(|h| algebra::H { p: h.p.restrict(a, b), k: h.k })).collect();
        let s_ref: Vec<&HVec> = s.iter().collect();
        let inner = exact(&mut alg, &w, &s_ref, sweep.tol / (b - a), (a, b));
        out = out.splice((a, b), &inner, (a, b));
    }
    out
}

/// Ordered, disjoint λ-intervals.
type Intervals = Vec<(f64, f64)>;

/// The parts of the ordered, disjoint intervals `from` outside the ordered, disjoint intervals
/// `minus`, and the parts inside.
fn subtract(from: &[(f64, f64)], minus: &[(f64, f64)]) -> (Intervals, Intervals) {
    let (mut outside, mut inside) = (Vec::new(), Vec::new());
    for &(a, b) in from {
        let mut at = a;
        for &(c, d) in minus.iter().filter(|(c, d)| *d > a && *c < b) {
            let (c, d) = (c.max(a), d.min(b));
            if c > at {
                outside.push((at, c));
            }
            inside.push((c, d));
            at = d;
        }
        if at < b {
            outside.push((at, b));
        }
    }
    (outside, inside)
}

/// The outcome of a condition at one pose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PoseCheck {
    /// Whether the condition is violated.
    pub violated: bool,
    /// The distance the condition is about (cable–cable, cable–obstacle, length), where one is
    /// computed exactly; `None` where only membership is decided.
    pub distance: Option<f64>,
}

/// The cables at one pose — base anchor and platform anchor in the world frame, indexable as a
/// slice of pairs — with the pose itself, every link's frame, and the tension ranges, computed at
/// most once per pose for all the tension conditions that ask.
#[derive(Debug, Clone)]
pub struct PoseCables {
    /// The pose (of the platform, or of a multi-link robot's first link).
    pub pose: Pose,
    /// (base anchor, platform anchor) per cable.
    pub cables: Vec<(Vector3<f64>, Vector3<f64>)>,
    /// Every link's frame (the platform's alone for a platform robot).
    pub links: Vec<Frame>,
    /// How the platform moves there, on a timed trajectory; `None`: at rest.
    pub kinematics: Option<Kinematics>,
    tensions: OnceCell<Option<[TensionRange; 6]>>,
}

impl std::ops::Deref for PoseCables {
    type Target = [(Vector3<f64>, Vector3<f64>)];
    fn deref(&self) -> &Self::Target {
        &self.cables
    }
}

impl PoseCables {
    /// The six cables' tension ranges under `load` (the scenario's only one), or `None` at a
    /// singular pose or when the robot does not have six cables.
    pub fn tension_ranges(&self, load: &Load) -> Option<[TensionRange; 6]> {
        *self.tensions.get_or_init(|| tension_ranges_at(&self.cables, &load.wrench.point_at(&self.pose), &self.nominal(load), &load.wrench))
    }

    /// The nominal wrench the cables balance here under `load` (with the platform's weight and,
    /// when moving, its inertia).
    pub fn nominal(&self, load: &Load) -> nalgebra::Vector6<f64> {
        load.nominal_at(&self.pose, self.kinematics.as_ref())
    }

    /// The same cables with the platform moving as `kin`.
    pub fn moving(mut self, kin: Kinematics) -> PoseCables {
        self.kinematics = Some(kin);
        self.tensions = OnceCell::new();
        self
    }
}

/// The cables of a platform robot at `pose`.
pub fn cables_at(robot: &Robot, pose: &Pose) -> PoseCables {
    PoseCables {
        pose: *pose,
        cables: robot.cables.iter().map(|c| (c.base, pose.transform(&c.platform))).collect(),
        links: vec![(pose.position, pose.matrix())],
        kinematics: None,
        tensions: OnceCell::new(),
    }
}

/// The cables of `robot` at configuration `q`: the pose coordinates (x, y, z, φ, θ, σ) of a
/// platform robot, the joint coordinates of a multi-link robot.
pub fn cables_at_config(robot: &Robot, q: &[f64]) -> PoseCables {
    match &robot.chain {
        Some(chain) => cables_of_chain(robot, chain.frames(q)),
        None => cables_at(robot, &Pose::from_coords([q[0], q[1], q[2], q[3], q[4], q[5]])),
    }
}

/// The cables of a multi-link `robot` with its links at `links`.
fn cables_of_chain(robot: &Robot, links: Vec<Frame>) -> PoseCables {
    let (p, r) = links[0];
    let pose = Pose { position: p, rotation: nalgebra::UnitQuaternion::from_matrix(&r) };
    PoseCables {
        pose,
        cables: robot.cables.iter().map(|c| (c.base, links[c.link].0 + links[c.link].1 * c.platform)).collect(),
        links,
        kinematics: None,
        tensions: OnceCell::new(),
    }
}

/// The three families of conditions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Cable length bounds.
    Length,
    /// Cable tensions over the wrench set.
    Tension,
    /// Cable–cable and cable–obstacle clearance.
    Interference,
    /// Winch speed and acceleration limits: only along timed motions (a pose, a ray or a slice
    /// is at rest).
    Winch,
}

/// How much exact work a condition's violation set takes along a motion, cheapest first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Cost {
    /// The signs of a few polynomials in λ (cable lengths, tensions, wrench closure).
    Signs,
    /// One moving cable against a fixed solid: distances in λ and a point of the cable.
    Fixed,
    /// Two moving things (two cables, a cable and a link): products of both motions, higher
    /// degrees.
    Moving,
    /// A search in two variables (cylinders; cones and ellipsoids with a clearance).
    Search,
}

/// One feasibility condition.
pub trait Condition {
    /// How reports name it: `"cables 2-5"`, `"cable 3 - box"`, `"cable 4 length"`.
    fn label(&self) -> String;

    /// What the condition is about, for classifying poses (slice maps).
    fn kind(&self) -> Kind;

    /// The set of λ ∈ [0, 1] where the condition is violated along the sweep's motion.
    fn violation(&self, sweep: &mut Sweep) -> Partition;

    /// How much exact work [`Condition::violation`] takes: the verifier evaluates the cheaper
    /// conditions first, so that the costlier ones may leave the parts of the motion already
    /// settled ([`Sweep::settled`]).
    fn cost(&self) -> Cost {
        Cost::Signs
    }

    /// The condition at one pose, given the cables there.
    fn check(&self, cables: &PoseCables) -> PoseCheck;

    /// The cables (by index) the condition is about, so that a view can colour them: one for a
    /// cable's length, tension, obstacle or link clearance, two for a pair of cables, none for a
    /// condition on all cables together (wrench closure, static feasibility).
    fn cables(&self) -> Vec<usize> {
        Vec::new()
    }
}

/// Every condition a scenario states: cable lengths (where bounded), cable–cable clearance for
/// each pair not sharing an anchor, cable–obstacle clearance for each cable and obstacle; for a
/// multi-link robot cable–link clearance for each cable and link (but a cable's own link where it
/// is attached within the clearance) and joint-space wrench closure; the wrench conditions of the
/// scenario's load (wrench set, weight, inertia): per cable and bound for six cables, the wrench
/// set inside the available wrench set for more; wrench closure where the scenario asks for it.
pub fn for_scenario(s: &Scenario) -> Vec<Box<dyn Condition>> {
    let robot = &s.robot;
    let m = robot.cables.len();
    let mut out: Vec<Box<dyn Condition>> = Vec::new();
    for (i, cable) in robot.cables.iter().enumerate() {
        if cable.length.min > 0.0 || cable.length.max.is_finite() {
            out.push(Box::new(CableLength { cable: i, bounds: cable.length }));
        }
    }
    for i in 0..m {
        for j in (i + 1)..m {
            if !robot.share_anchor(i, j) {
                out.push(Box::new(CableCable { i, j, clearance: s.clearance.cable_cable }));
            }
        }
    }
    for obstacle in &s.obstacles {
        for i in 0..m {
            out.push(Box::new(CableShape::new(i, obstacle, s.clearance.cable_obstacle)));
        }
    }
    if let Some(chain) = &robot.chain {
        let clearance = s.clearance.cable_link;
        for (l, link) in chain.links.iter().enumerate() {
            if link.radius + clearance <= 0.0 {
                continue; // no distance is below 0
            }
            for (i, cable) in robot.cables.iter().enumerate() {
                if cable.link == l && attached_inside(&cable.platform, &link.body, link.radius + clearance) {
                    continue; // reported by the scenario's validation: it would hold nowhere
                }
                out.push(Box::new(CableLink { cable: i, link: l, name: link.name.clone(), body: link.body, radius: link.radius, clearance }));
            }
        }
        out.push(Box::new(JointClosure { chain: Rc::new(chain.clone()), cable_links: robot.cables.iter().map(|c| c.link).collect() }));
    }
    for (rate, limit) in [(Rate::Speed, robot.winch.speed), (Rate::Acceleration, robot.winch.acceleration)] {
        if let Some(limit) = limit {
            out.extend((0..m).map(|cable| Box::new(WinchLimit { cable, rate, limit }) as Box<dyn Condition>));
        }
    }
    if let Some(load) = s.load() {
        let load = Rc::new(load);
        if load.wrench.closure {
            out.push(Box::new(WrenchClosure { load: Rc::clone(&load) }));
        }
        if m == 6 {
            for (i, cable) in robot.cables.iter().enumerate() {
                let bounds = [(Side::Lower, cable.tension.min), (Side::Upper, cable.tension.max)];
                for (side, bound) in bounds.into_iter().filter(|(_, b)| b.is_finite()) {
                    out.push(Box::new(CableTension { cable: i, side, bound, load: Rc::clone(&load) }));
                }
            }
        } else {
            let bounds = robot.cables.iter().map(|c| c.tension).collect();
            if load.wrench.is_single() {
                // one wrench: linear programs, for any number of cables
                out.push(Box::new(WrenchFeasibilityLp { load, bounds }));
            } else {
                // an ellipsoid: its reach against each facet (validation caps the cables)
                out.push(Box::new(WrenchFeasibility { load, bounds }));
            }
        }
    }
    out
}

/// Whether the anchor `b` (in its link's frame) lies within distance `r` of the link's body
/// segment: the cable then starts inside the clearance zone of its own link.
pub fn attached_inside(b: &Vector3<f64>, body: &[Vector3<f64>; 2], r: f64) -> bool {
    crate::query::point_segment_dist2(b, &body[0], &(body[1] - body[0]), None) < r * r
}
