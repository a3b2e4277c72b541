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
mod joint_forces;
mod joint_statics;
mod lipschitz;
mod load;
mod offset;
mod speed;
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
pub use joint_statics::JointStatics;
pub use tension::{CableTension, TensionPolys, TensionSide};
pub use speed::PlatformSpeed;
pub use winch::{Rate, WinchLimit, WinchPolys};
pub use wrench_lp::WrenchFeasibilityLp;

use std::cell::OnceCell;
use std::rc::Rc;

use crate::axes::{each_axis, per_axis, per_component};
use crate::model::{Anchor, Bounds, Load, Motion, Robot};
use crate::poly::{Bern, Partition, Truth};
use crate::query::cables::{attached_inside, PoseCables};
use crate::scenario::Scenario;
use algebra::{Alg, HVec};
use load::{load_polys, reference_law, LoadPolys};
pub use load::TimeLaw;
use tube::Tube;
use nalgebra::Vector3;

/// One cable along a motion: the segment base → base + s(λ), with s as a fraction over w; for a
/// multi-link robot, one segment of a cable ([`crate::model::Robot::segments`]), whose start may
/// move with a link too.
#[derive(Debug, Clone)]
pub struct SweptCable {
    /// The base anchor (the start, when it is fixed to the base).
    pub base: Vector3<f64>,
    /// The start Ŝ (over w, as the links' positions) when it moves with a link; `None`: fixed at
    /// `base`.
    pub start: Option<[Bern; 3]>,
    /// The cable vector s = p + R b − a (one power of w).
    pub s: HVec,
    /// Balls holding its moving end piece by piece, for pruning.
    pub tube: Tube,
}

impl SweptCable {
    /// The segment from the start Ŝ (`None`: fixed at `base`) to the end X̂, over `w`.
    fn new(base: Vector3<f64>, start: Option<[Bern; 3]>, tip: &[Bern; 3], w: &Bern) -> SweptCable {
        let w_at = |d: usize| w.elevate(d.max(w.degree()));
        let s = match &start {
            None => per_axis(|i| algebra::H { p: Bern::linear_combination(&[(&tip[i], 1.0), (&w_at(tip[i].degree()), -base[i])]), k: 1 }),
            Some(a) => per_axis(|i| algebra::H { p: tip[i].sub(&a[i]), k: 1 }),
        };
        let tube = SweptCable::tube(base, start.as_ref(), tip, w);
        SweptCable { base, start, s, tube }
    }

    /// The pruning tube of the segment from `base` (or the moving start Ŝ) to X̂ = `tip`.
    fn tube(base: Vector3<f64>, start: Option<&[Bern; 3]>, tip: &[Bern; 3], w: &Bern) -> Tube {
        match start {
            None => Tube::new(base, tip, w),
            Some(a) => Tube::moving(a, tip, w),
        }
    }

    /// P = ŝ·ŝ, its squared length times w².
    pub fn len2(&self) -> Bern {
        norm2([&self.s[0].p, &self.s[1].p, &self.s[2].p])
    }

    /// Its start Ŝ over `w` (the motion's weight).
    pub fn start_hat(&self, w: &Bern) -> [Bern; 3] {
        match &self.start {
            Some(a) => a.clone(),
            None => per_axis(|i| w.scale(self.base[i])),
        }
    }

    /// Its end X̂ = Ŝ + ŝ over `w`.
    pub fn tip_hat(&self, w: &Bern) -> [Bern; 3] {
        let start = self.start_hat(w);
        per_axis(|i| self.s[i].p.add(&start[i]))
    }
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
    /// A multi-link robot's joint-space structure numerators, built by the first of its closure
    /// and statics conditions that needs them.
    pub joint_rows: Option<Rc<Vec<Vec<Bern>>>>,
    /// The winch limits' polynomials, built likewise.
    pub winch: WinchPolys,
    /// Ordered, disjoint λ-intervals where other conditions are already certainly violated (set
    /// by the caller, kept clear of their ends by a margin): a condition may leave itself
    /// undecided (`Unknown`) there, without pruning or exact work, since its answer cannot change
    /// the union, nor the constraints active at its boundaries.
    pub settled: Vec<(f64, f64)>,
    /// How long the whole trajectory takes (seconds) when it is run in time: the conditions that
    /// depend on speed (inertia, winch limits) take their rates from it. `None` for a motion
    /// without time (a ray, an untimed trajectory): those conditions see the robot at rest.
    pub duration: Option<f64>,
    /// How λ runs in time for a duration of one second, when not uniformly (a part of a
    /// time-optimal law, `crate::plan::timing`): `duration` still scales it (1/T²). `None`: the
    /// uniform law of the motion's parameter.
    pub law: Option<TimeLaw>,
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
        let lifted: Vec<([Bern; 3], [[Bern; 3]; 3])> = links.iter().map(|m| (per_axis(|i| m.position[i].elevate(n[i])), per_axis(|i| each_axis(&m.rotation[i], |p| p.elevate(n[i]))))).collect();
        // an anchor's X̂ (one power of w): P̂ + M̂ b on a link, b·w on the base
        let point = |a: &Anchor| -> [Bern; 3] {
            match a.link {
                Some(l) => body_point(&lifted[l].0, &lifted[l].1, &a.point),
                None => per_axis(|i| w.elevate(n[i]).scale(a.point[i])),
            }
        };
        let cables = robot.segments().iter().map(|seg| SweptCable::new(seg.from.point, seg.from.link.map(|_| point(&seg.from)), &point(&seg.to), w)).collect();
        Sweep { alg: Alg::new(w), cables, tol, links: links.to_vec(), tension: None, facets: None, joint_rows: None, winch: WinchPolys::default(), settled: Vec::new(), duration: None, law: None }
    }

    /// The platform's motion (the first link's for a multi-link robot): the weight and the
    /// parameter every link shares.
    pub fn motion(&self) -> &Motion {
        &self.links[0]
    }

    /// The sweep along the part [a, b] ⊆ [0, 1] of a trajectory's motion (re-parametrised to
    /// [0, 1], with the same tolerance and duration), run by `law` there (for one second; `None`:
    /// its uniform law). What the conditions prepared in this sweep ([`Condition::prepare`]) is
    /// restricted to the part rather than expanded again — the timing certifies hundreds of
    /// short parts of one motion. Nothing already settled carries over.
    pub fn part(&self, (a, b): (f64, f64), law: Option<TimeLaw>) -> Sweep {
        let links: Vec<Motion> = self.links.iter().map(|m| m.part(a, b)).collect();
        let w = &links[0].weight;
        let cables = self
            .cables
            .iter()
            .map(|c| {
                let start = c.start.as_ref().map(|p| each_axis(p, |p| p.restrict(a, b)));
                let s: HVec = each_axis(&c.s, |h| algebra::H { p: h.p.restrict(a, b), k: h.k });
                let tip: [Bern; 3] = match &start {
                    None => per_axis(|i| Bern::linear_combination(&[(&s[i].p, 1.0), (w, c.base[i])])),
                    Some(st) => per_axis(|i| s[i].p.add(&st[i])),
                };
                let tube = SweptCable::tube(c.base, start.as_ref(), &tip, w);
                SweptCable { base: c.base, start, tube, s }
            })
            .collect();
        let mut part = Sweep {
            alg: Alg::new(w),
            cables,
            tol: self.tol,
            links,
            tension: None,
            facets: None,
            joint_rows: None,
            winch: self.winch.part((a, b)),
            settled: Vec::new(),
            duration: self.duration,
            law,
        };
        let law = reference_law(&part);
        part.tension = self.tension.as_ref().and_then(|t| t.part((a, b), law.as_ref())).map(Rc::new);
        part.facets = self.facets.as_ref().and_then(|f| f.part((a, b), law.as_ref())).map(Rc::new);
        part
    }
}

/// X̂ = P̂ + M̂ b: the point `b` of a body (its frame) along the body's motion, over the motion's
/// weight as its position P̂ and rotation M̂ are.
fn body_point(position: &[Bern; 3], rotation: &[[Bern; 3]; 3], b: &Vector3<f64>) -> [Bern; 3] {
    per_axis(|i| Bern::linear_combination(&[(&position[i], 1.0), (&rotation[i][0], b[0]), (&rotation[i][1], b[1]), (&rotation[i][2], b[2])]))
}

/// v·v for a vector of polynomials.
fn norm2(v: [&Bern; 3]) -> Bern {
    Bern::sum_of_products(&[(v[0], v[0], 1.0), (v[1], v[1], 1.0), (v[2], v[2], 1.0)])
}

/// A motion's polynomials on a sub-interval of λ (all of [0, 1] or a piece being refined),
/// re-expanded there so that error bounds scale with the local magnitudes.
#[derive(Debug, Clone)]
pub(crate) struct Local {
    /// P̂ = p·w.
    pub(crate) position: [Bern; 3],
    /// M̂ = R·w.
    pub(crate) rotation: [[Bern; 3]; 3],
    /// w.
    pub(crate) weight: Bern,
    /// (base anchor, s̃ = s·w) per cable.
    pub(crate) cables: Vec<(Vector3<f64>, [Bern; 3])>,
    /// The wrench the cables balance ([`load`]).
    pub(crate) load: LoadPolys,
    /// How λ runs in time for a duration of one second, along a timed motion.
    pub(crate) law: Option<TimeLaw>,
    /// The inertial rows under `law`, built by the first condition that needs them.
    inertial: OnceCell<Option<[Bern; 6]>>,
}

impl Local {
    /// The sweep's motion and the load along it (with the inertial wrench, for any duration, when
    /// the sweep is timed).
    pub(crate) fn of(sweep: &Sweep, load: &Load) -> Local {
        let m = sweep.motion();
        let mut local = Local {
            position: m.position.clone(),
            rotation: m.rotation.clone(),
            weight: m.weight.clone(),
            cables: sweep.cables.iter().map(|c| (c.base, [c.s[0].p.clone(), c.s[1].p.clone(), c.s[2].p.clone()])).collect(),
            load: LoadPolys { rows: per_component(|_| Bern::constant(0.0)), inertial: None, scale: None },
            law: reference_law(sweep),
            inertial: OnceCell::new(),
        };
        // timed: the inertial rows, scaled to the sweep's duration when used
        local.load = load_polys(&local, load, local.law.is_some(), m.spin.as_ref());
        local
    }

    /// The inertial rows under the motion's law for one second (a duration T divides them by
    /// T²), along a timed motion.
    pub(crate) fn inertial(&self) -> Option<&[Bern; 6]> {
        self.inertial.get_or_init(|| Some(self.load.inertial.as_ref()?.under(self.law.as_ref()?))).as_ref()
    }

    /// P_i = ‖s̃_i‖² per cable (the squared cable lengths times w²).
    pub(crate) fn len2(&self) -> Vec<Bern> {
        self.cables.iter().map(|(_, s)| norm2([&s[0], &s[1], &s[2]])).collect()
    }

    pub(crate) fn restrict(&self, a: f64, b: f64) -> Local {
        let r = |p: &Bern| p.restrict(a, b);
        Local {
            position: each_axis(&self.position, r),
            rotation: each_axis(&self.rotation, |row| each_axis(row, r)),
            weight: r(&self.weight),
            cables: self.cables.iter().map(|(base, s)| (*base, each_axis(s, r))).collect(),
            load: self.load.restrict(a, b),
            law: self.law.as_ref().map(|l| TimeLaw { square: r(&l.square), accel: r(&l.accel) }),
            // the rows under the law, restricted if they were built
            inertial: self.inertial.get().map(|rows| OnceCell::from(rows.as_ref().map(|rows| per_component(|j| r(&rows[j]))))).unwrap_or_default(),
        }
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

/// The three families of conditions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Cable length bounds.
    Length,
    /// Cable tensions over the wrench set.
    Tension,
    /// Cable–cable and cable–obstacle clearance.
    Interference,
    /// Speed limits — the winches' cable speed and acceleration, the platform's speed: only
    /// along timed motions (a pose, a ray or a slice is at rest).
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

    /// The set of λ ∈ [0, 1] where the condition is violated along the sweep's motion; it may
    /// leave pieces undecided that [`Condition::refine`] can still decide by costlier local work.
    fn violation(&self, sweep: &mut Sweep) -> Partition;

    /// `found`, [`Condition::violation`]'s answer on this sweep, with its undecided pieces wider
    /// than the sweep's tolerance (narrower ones are certified boundaries) decided by costlier
    /// local work where that can succeed and matters: outside the sweep's settled intervals. The
    /// verifier calls it once every condition has given its first answer, so that the settled
    /// intervals spare the most, and only where such pieces are left. Most conditions have
    /// nothing more to do.
    fn refine(&self, _sweep: &mut Sweep, found: Partition) -> Partition {
        found
    }

    /// [`Condition::violation`], then [`Condition::refine`]: the condition's whole answer alone.
    fn decided(&self, sweep: &mut Sweep) -> Partition {
        let found = self.violation(sweep);
        self.refine(sweep, found)
    }

    /// Builds into `sweep` the polynomials the condition keeps there, so that parts of it
    /// ([`Sweep::part`]) restrict them instead of expanding them again. Most conditions keep
    /// nothing that a part could restrict: the default does nothing.
    fn prepare(&self, _sweep: &mut Sweep) {}

    /// A cheap guess of the first λ where the condition is violated along the sweep's motion
    /// (`f64::INFINITY` where it seems to hold throughout), or `None` where the condition makes
    /// none. A hint, never an answer: the verifier takes conditions of equal cost in the order of
    /// their guesses, so that the stretches the first ones settle spare the others.
    fn hint(&self, _sweep: &mut Sweep) -> Option<f64> {
        None
    }

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
    let segments = robot.segments();
    // how reports name a segment: its cable, and its number along a routed cable
    let routed = |seg: &crate::model::CableSegment| !robot.cables[seg.cable].via.is_empty();
    let name = |seg: &crate::model::CableSegment| {
        if routed(seg) { format!("cable {} segment {}", seg.cable + 1, seg.index + 1) } else { format!("cable {}", seg.cable + 1) }
    };
    let mut out: Vec<Box<dyn Condition>> = Vec::new();
    for (i, cable) in robot.cables.iter().enumerate() {
        if cable.length.min > 0.0 || cable.length.max.is_finite() {
            let own = (0..segments.len()).filter(|&k| segments[k].cable == i).collect();
            out.push(Box::new(CableLength { cable: i, segments: own, bounds: cable.length }));
        }
    }
    for i in 0..segments.len() {
        for j in (i + 1)..segments.len() {
            let (a, b) = (&segments[i], &segments[j]);
            if !Robot::segments_meet(a, b) {
                let label = if routed(a) || routed(b) { format!("{} - {}", name(a), name(b)) } else { format!("cables {}-{}", a.cable + 1, b.cable + 1) };
                out.push(Box::new(CableCable { i, j, cables: [a.cable, b.cable], name: label, clearance: s.clearance.cable_cable }));
            }
        }
    }
    for obstacle in &s.obstacles {
        for (k, seg) in segments.iter().enumerate() {
            out.push(Box::new(CableShape::new(seg.cable, k, name(seg), obstacle, s.clearance.cable_obstacle)));
        }
    }
    if let Some(chain) = &robot.chain {
        let clearance = s.clearance.cable_link;
        for (l, link) in chain.links.iter().enumerate() {
            if link.radius + clearance <= 0.0 {
                continue; // no distance is below 0
            }
            for (k, seg) in segments.iter().enumerate() {
                let attached = [seg.from, seg.to].iter().any(|a| a.link == Some(l) && attached_inside(&a.point, &link.body, link.radius + clearance));
                if attached {
                    continue; // reported by the scenario's validation: it would hold nowhere
                }
                out.push(Box::new(CableLink { cable: seg.cable, segment: k, cable_name: name(seg), link: l, name: link.name.clone(), body: link.body, radius: link.radius, clearance }));
            }
        }
        let chain = Rc::new(chain.clone());
        if chain.is_loaded() {
            let bounds = robot.cables.iter().map(|c| c.tension).collect();
            out.push(Box::new(JointStatics { chain: Rc::clone(&chain), segments: segments.clone(), bounds }));
        }
        if chain.closure {
            out.push(Box::new(JointClosure { chain, segments, cables: m }));
        }
    }
    for (rate, limit) in [(Rate::Speed, robot.winch.speed), (Rate::Acceleration, robot.winch.acceleration)] {
        if let Some(limit) = limit {
            out.extend((0..m).map(|cable| Box::new(WinchLimit { cable, rate, limit }) as Box<dyn Condition>));
        }
    }
    if let Some(limit) = robot.speed {
        out.push(Box::new(PlatformSpeed { limit }));
    }
    if let Some(load) = s.load() {
        let load = Rc::new(load);
        if load.wrench.closure {
            if crate::scenario::validate::facets_enumerable(m, robot.mobility) {
                out.push(Box::new(WrenchClosure { load: Rc::clone(&load) }));
            } else {
                // beyond the facets' reach: the linear programs' certificates
                out.push(Box::new(WrenchFeasibilityLp::closure(&load, m)));
            }
        }
        if m == robot.mobility.dof() {
            for (i, cable) in robot.cables.iter().enumerate() {
                let bounds = [(TensionSide::Lower, cable.tension.min), (TensionSide::Upper, cable.tension.max)];
                for (side, bound) in bounds.into_iter().filter(|(_, b)| b.is_finite()) {
                    out.push(Box::new(CableTension { cable: i, side, bound, load: Rc::clone(&load) }));
                }
            }
        } else {
            let bounds: Vec<Bounds> = robot.cables.iter().map(|c| c.tension).collect();
            // the zero wrench within (f_min, f_max) follows from closure (a positive null vector,
            // scaled below every f_max) where no lower bound is positive: closure alone decides
            // it then (its failure has a strict certificate; this condition's would not)
            let implied_by_closure = load.wrench.closure && load.is_zero() && bounds.iter().all(|b| b.min <= 0.0 && b.max > 0.0);
            if implied_by_closure {
                // nothing to add
            } else if load.wrench.is_single() || !crate::scenario::validate::facets_enumerable(m, robot.mobility) {
                // one wrench: linear programs, for any number of cables; an ellipsoid beyond the
                // facets' reach: the same system with a cover of the wrench directions
                out.push(Box::new(WrenchFeasibilityLp::new(load, bounds)));
            } else {
                // an ellipsoid: its reach against each facet
                out.push(Box::new(WrenchFeasibility { load, bounds }));
            }
        }
    }
    out
}
