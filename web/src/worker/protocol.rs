//! The messages between the page and its workers: a [`Job`] goes in (with an id), [`Reply`]s
//! come out (with the same id): any number of [`Reply::Progress`], then one final reply. All are
//! JSON text, so that a job is a plain value and the protocol is tested natively.

use cablenav::lattice::LatticeReport;
use cablenav::model::Pose;
use cablenav::report::{Boundary, Seconds, Side, TensionEnvelope, VerifyReport};
use cablenav::verify::profile::{ClearanceProfile, ClearanceSample, Closest};
use cablenav::verify::slice::Class;
use cablenav::Scenario;
use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use serde::{Deserialize, Serialize};

/// A slice map as the page asks for it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SliceSpec {
    /// The scenario JSON.
    pub scenario: String,
    /// The pose (or configuration) the other coordinates come from.
    pub pose: String,
    /// The two coordinates, by name.
    pub axes: [String; 2],
    /// Cells per side.
    pub res: usize,
    /// The axes' ranges, crossing bit for bit.
    #[serde(with = "bits")]
    pub range: [[f64; 2]; 2],
}

/// The default of [`Job::Plan`]'s `identify_angles`: angles as angles.
fn angles_identified() -> bool {
    true
}

/// The message a worker sends once it listens.
pub const READY: &str = r#"{"ready":true}"#;

/// Work for a worker. Externally tagged (`{"plan": {…}}`): an internally tagged enum is decoded
/// through serde's buffered `Content`, which grows the page by tens of kilobytes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Job {
    /// Plan query `query` of the scenario JSON `scenario` with planner `planner` (an id of
    /// [`crate::state::PLANNERS`]), at most `max_charts` charts (or the planner's own budget);
    /// the lattice planner with `steps` grid values per free coordinate (`--steps`); the atlas
    /// planner with the angles as angles, or as plain coordinates (`identify_angles` false,
    /// `--identify-angles false`: paper 1's way).
    Plan {
        scenario: String,
        query: String,
        planner: String,
        max_charts: usize,
        steps: usize,
        #[serde(default = "angles_identified")]
        identify_angles: bool,
    },
    /// Rows `rows[0]..rows[1]` of the slice map `map` (all: `[0, res]`).
    Slice { map: SliceSpec, rows: [usize; 2] },
    /// The singularity curves (det J = 0) of the slice map `map`, sampled at its cells' corners.
    Singular { map: SliceSpec },
    /// Rays `rays[0]..rays[1]` (in the core's `LatticeSpec::ray_at` order) of the ray lattice
    /// over `axes` (coordinate names) with `ranges` and `steps` values per axis, the other
    /// coordinates from pose `pose` (all rays: `[0, total]`; the page splits them over workers
    /// and joins them with [`super::jobs::join_lattice`]).
    LatticeRays { scenario: String, pose: String, axes: Vec<String>, ranges: Vec<[f64; 2]>, steps: usize, rays: [usize; 2] },
    /// The plots along the path `name` at the samples `(t, pose)` (see [`pose_to_wire`]): its
    /// clearances and its tension envelope. `trajectory` names the scenario's trajectory the
    /// samples follow, if they do: when it is timed, its tensions include the platform's inertia
    /// (the samples must then be at t = k/n, as `cablenav envelope` takes them).
    Profiles { scenario: String, name: String, samples: Vec<(f64, [u64; 7])>, trajectory: Option<String> },
    /// The exact verification of trajectory `index` (clamped to the scenario's) of the scenario
    /// at its own timing, without the time-scale search (a drag's live verification,
    /// [`crate::live`]: the page adds the search when the drag ends).
    Verify { scenario: String, index: usize },
    /// The exact verification of every trajectory of the scenario, as [`Job::Verify`] each (the
    /// page draws them together: the thesis' families of paths, Figs. 4.4, 4.6 and 4.7).
    VerifyEvery { scenario: String },
    /// The fastest safe timing of trajectory `index` (clamped) of the scenario, as `cablenav
    /// time` gives it with its defaults (docs/timing.md).
    Time { scenario: String, index: usize },
}

/// What a worker answers.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Reply {
    /// How far the job is: a fraction in [0, 1] (never going back) and a line for people.
    Progress { fraction: f64, detail: String },
    /// The atlas planner's atlas as it grows (sent with the progress): charts `from..` of its
    /// slice over `coords`, each as it was when sent; the `Planned` reply has the final states.
    Charts { coords: Vec<String>, from: usize, charts: Vec<WireChart> },
    /// A planning run ended: its status (`found`, `no_path`, `budget`, `unrepaired`), a summary,
    /// the path (when there is one) as poses (see [`pose_to_wire`]), the lattice planner's A*
    /// polyline (empty for the atlas), the planned trajectory with its exact verification, and
    /// the atlas planner's charts on a 2-D slice.
    Planned { status: String, summary: String, path: Vec<[u64; 7]>, polyline: Vec<[u64; 7]>, trajectory: Option<Box<PlannedTrajectory>>, atlas: Option<WireAtlas> },
    /// Rays `rays[0]..rays[1]` of a lattice: each ray's feasible and uncertain intervals, as bits
    /// (so the join builds the very graph the core builds).
    LatticeRays { rays: [usize; 2], sections: Vec<RaySections> },
    /// The clearances and the tension envelope along a path (each, or why not).
    Profiles { clearances: Result<WireClearances, String>, tension: Result<WireEnvelope, String> },
    /// A trajectory's exact verification (or why not) and the worker's time for it (ms).
    Verified { report: Result<WireReport, String>, ms: f64 },
    /// Every trajectory's exact verification (or why not), in the scenario's order.
    VerifiedEvery { reports: Vec<Result<WireReport, String>> },
    /// A trajectory's fastest safe timing as `cablenav time --json` prints it (empty when there
    /// is none), or why there is none (`error`, empty otherwise), and the worker's time for it
    /// (ms). As text, so the page decodes the report straight from JSON (no `Result` of it to
    /// decode: the page stays smaller).
    Timed { report: String, error: String, ms: f64 },
    /// A slice map's rows `rows[0]..rows[1]`: their cells' classes, row-major.
    Sliced { rows: [usize; 2], classes: Vec<Class> },
    /// A slice's singularity curves, polylines of [first axis, second axis] points.
    Singular { curves: Vec<Vec<[f64; 2]>> },
    /// The job could not run; why.
    Failed { error: String },
}

/// The atlas planner's charts on a 2-D or 3-D slice, as the page draws them over the slice map
/// (Fig. 6 of paper 1) or in the slice's space (Fig. 7): the core's
/// `plan::atlas::view::AtlasView`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct WireAtlas {
    /// The slice's coordinates, by name (two or three).
    pub coords: Vec<String>,
    /// The charts.
    pub charts: Vec<WireChart>,
}

/// One chart of a [`WireAtlas`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct WireChart {
    /// Its centre, one entry per coordinate.
    pub centre: Vec<f64>,
    /// A 2-D slice: its polytope, a convex polygon in cyclic order.
    pub polygon: Vec<[f64; 2]>,
    /// A 3-D slice: its polytope's faces, each a convex polygon in cyclic order.
    pub faces: Vec<Vec<[f64; 3]>>,
    /// `expanded`, `open`, `out_of_bounds` or `blocked`.
    pub state: String,
    /// Whether the path runs through it.
    pub on_path: bool,
}

impl WireChart {
    /// A chart of the core's view.
    pub fn of(c: &cablenav::plan::atlas::view::ChartView) -> WireChart {
        let pair = |v: &Vec<f64>| [v[0], v[1]];
        let triple = |v: &Vec<f64>| [v[0], v[1], v[2]];
        WireChart {
            centre: c.centre.clone(),
            polygon: c.polygon.iter().map(pair).collect(),
            faces: c.faces.iter().map(|f| f.iter().map(triple).collect()).collect(),
            state: c.state.to_string(),
            on_path: c.on_path,
        }
    }
}

impl WireAtlas {
    /// The charts of a 2-D or 3-D slice's atlas; `None` for another dimension.
    pub fn of(view: &cablenav::plan::atlas::view::AtlasView) -> Option<WireAtlas> {
        WireAtlas::drawn(&view.coords).then(|| WireAtlas { coords: view.coords.clone(), charts: view.charts.iter().map(WireChart::of).collect() })
    }

    /// Whether the page draws the atlas of a slice over `coords`: two (over the slice map) or
    /// three (in the slice's own space).
    pub fn drawn(coords: &[String]) -> bool {
        (2..=3).contains(&coords.len())
    }
}

/// A planned trajectory as the page keeps it: the scenario with the trajectory added under a new
/// name (as `cablenav plan --out` writes it, so `cablenav verify` checks the same thing) and the
/// trajectory's exact verification there.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlannedTrajectory {
    /// The scenario JSON with the planned trajectory appended.
    pub scenario: String,
    /// The planned trajectory's name in it.
    pub name: String,
    /// Its verification, or why it failed.
    pub report: Result<WireReport, String>,
}

/// A [`VerifyReport`] that crosses bit for bit (numbers as their bits).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct WireReport {
    trajectory: String,
    method: String,
    step: Option<u64>,
    feasible: Vec<[u64; 2]>,
    infeasible: Vec<[u64; 2]>,
    feasible_tau: Vec<[u64; 2]>,
    infeasible_tau: Vec<[u64; 2]>,
    /// (t, τ, constraint, whether it enters the feasible set)
    boundaries: Vec<(u64, u64, String, bool)>,
    uncertain: Vec<[u64; 2]>,
    warnings: Vec<String>,
    /// A timed trajectory's sections in seconds (as numbers: JSON's shortest representation
    /// round-trips them exactly).
    seconds: Option<Box<Seconds>>,
}

fn to_bits(v: &[[f64; 2]]) -> Vec<[u64; 2]> {
    v.iter().map(|p| p.map(f64::to_bits)).collect()
}

fn from_bits(v: &[[u64; 2]]) -> Vec<[f64; 2]> {
    v.iter().map(|p| p.map(f64::from_bits)).collect()
}

impl From<&VerifyReport> for WireReport {
    fn from(r: &VerifyReport) -> WireReport {
        WireReport {
            trajectory: r.trajectory.clone(),
            method: r.method.clone(),
            step: r.step.map(f64::to_bits),
            feasible: to_bits(&r.feasible),
            infeasible: to_bits(&r.infeasible),
            feasible_tau: to_bits(&r.feasible_tau),
            infeasible_tau: to_bits(&r.infeasible_tau),
            boundaries: r.boundaries.iter().map(|b| (b.t.to_bits(), b.tau.to_bits(), b.constraint.clone(), b.enters == Side::Feasible)).collect(),
            uncertain: to_bits(&r.uncertain),
            warnings: r.warnings.clone(),
            seconds: r.seconds.clone(),
        }
    }
}

impl WireReport {
    /// The report sent, bit for bit.
    pub fn report(&self) -> VerifyReport {
        VerifyReport {
            trajectory: self.trajectory.clone(),
            method: self.method.clone(),
            step: self.step.map(f64::from_bits),
            feasible: from_bits(&self.feasible),
            infeasible: from_bits(&self.infeasible),
            feasible_tau: from_bits(&self.feasible_tau),
            infeasible_tau: from_bits(&self.infeasible_tau),
            boundaries: self
                .boundaries
                .iter()
                .map(|(t, tau, c, feasible)| Boundary {
                    t: f64::from_bits(*t),
                    tau: f64::from_bits(*tau),
                    constraint: c.clone(),
                    enters: if *feasible { Side::Feasible } else { Side::Infeasible },
                })
                .collect(),
            uncertain: from_bits(&self.uncertain),
            warnings: self.warnings.clone(),
            seconds: self.seconds.clone(),
        }
    }
}

/// One ray's exact sections: feasible and uncertain intervals of the varied coordinate, as bits.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RaySections {
    /// Feasible intervals.
    pub feasible: Vec<[u64; 2]>,
    /// Uncertain intervals.
    pub uncertain: Vec<[u64; 2]>,
}

impl RaySections {
    /// The sections as sent.
    pub fn new(feasible: &[[f64; 2]], uncertain: &[[f64; 2]]) -> RaySections {
        RaySections { feasible: to_bits(feasible), uncertain: to_bits(uncertain) }
    }

    /// The feasible intervals, bit for bit.
    pub fn feasible(&self) -> Vec<[f64; 2]> {
        from_bits(&self.feasible)
    }

    /// The uncertain intervals, bit for bit.
    pub fn uncertain(&self) -> Vec<[f64; 2]> {
        from_bits(&self.uncertain)
    }
}

/// A [`TensionEnvelope`] for the plot (numbers as JSON decimals: within an ulp).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct WireEnvelope {
    trajectory: String,
    t: Vec<f64>,
    tension_min: Vec<Option<Vec<f64>>>,
    tension_max: Vec<Option<Vec<f64>>>,
    bounds: Vec<[f64; 2]>,
}

impl From<TensionEnvelope> for WireEnvelope {
    fn from(e: TensionEnvelope) -> WireEnvelope {
        WireEnvelope { trajectory: e.trajectory, t: e.t, tension_min: e.tension_min, tension_max: e.tension_max, bounds: e.bounds }
    }
}

impl From<WireEnvelope> for TensionEnvelope {
    fn from(e: WireEnvelope) -> TensionEnvelope {
        TensionEnvelope { trajectory: e.trajectory, t: e.t, tension_min: e.tension_min, tension_max: e.tension_max, bounds: e.bounds }
    }
}

/// One clearance sample on the wire: t, the least cable–cable and cable–obstacle distances with
/// what they are between, and the conditions violated.
type WireSample = (f64, Option<(f64, String)>, Option<(f64, String)>, Vec<String>);

/// A [`ClearanceProfile`] for the plot (numbers as JSON decimals: within an ulp). Each sample:
/// t, the least cable–cable and cable–obstacle distances with what they are between, and the
/// conditions violated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct WireClearances {
    samples: Vec<WireSample>,
    clearances: [f64; 2],
    membership_only: Vec<String>,
}

impl From<ClearanceProfile> for WireClearances {
    fn from(p: ClearanceProfile) -> WireClearances {
        let closest = |c: Option<Closest>| c.map(|c| (c.distance, c.between));
        WireClearances {
            samples: p.samples.into_iter().map(|s| (s.t, closest(s.cable_cable), closest(s.cable_obstacle), s.violated)).collect(),
            clearances: [p.clearance_cable_cable, p.clearance_cable_obstacle],
            membership_only: p.membership_only,
        }
    }
}

impl From<WireClearances> for ClearanceProfile {
    fn from(w: WireClearances) -> ClearanceProfile {
        let closest = |c: Option<(f64, String)>| c.map(|(distance, between)| Closest { distance, between });
        ClearanceProfile {
            samples: w.samples.into_iter().map(|(t, cc, co, violated)| ClearanceSample { t, cable_cable: closest(cc), cable_obstacle: closest(co), violated }).collect(),
            clearance_cable_cable: w.clearances[0],
            clearance_cable_obstacle: w.clearances[1],
            membership_only: w.membership_only,
        }
    }
}

/// A ray lattice as the page draws it (the core's [`LatticeReport`], owned and serialisable both
/// ways; ray ends as JSON decimals, so within an ulp of the core's).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LatticeResult {
    /// The chosen coordinates' names.
    pub axes: Vec<String>,
    /// Their indices in a configuration (x, y, z, φ, θ, σ for a platform robot; a multi-link
    /// robot's joint coordinates in order).
    pub axis_index: Vec<usize>,
    /// Which of them are angles.
    pub axis_angle: Vec<bool>,
    /// Their ranges.
    pub ranges: Vec<[f64; 2]>,
    /// Their numbers of grid values.
    pub steps: Vec<usize>,
    /// The configuration the other coordinates are held at.
    pub fixed: Vec<f64>,
    /// Every ray.
    pub rays: Vec<LatticeRay>,
    /// Feasible ray pieces (the graph's nodes).
    pub pieces: usize,
    /// Connected components of the graph.
    pub components: usize,
    /// Grid points.
    pub grid_points: usize,
    /// Grid points feasible on every ray through them.
    pub feasible_points: usize,
    /// Rays with an uncertain section.
    pub uncertain_rays: usize,
    /// Components holding grid points, slivers between grid points, the point-wise grid's
    /// components of the same points and the separations it misses (the core's
    /// `LatticeReport` fields of those names).
    pub split: [usize; 4],
}

/// One ray of a [`LatticeResult`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LatticeRay {
    /// The varied coordinate's name.
    pub vary: String,
    /// The whole configuration at the ray's start (the varied coordinate at its range's start).
    pub at: Vec<f64>,
    /// Feasible intervals of the varied coordinate.
    pub feasible: Vec<[f64; 2]>,
    /// The component of each feasible interval.
    pub components: Vec<usize>,
}

impl LatticeResult {
    /// The page's copy of the core's lattice report on scenario `s` (which names its coordinates:
    /// x … σ, or a multi-link robot's joint coordinates).
    pub fn of(s: &Scenario, r: &LatticeReport) -> LatticeResult {
        let index = |name: &str| s.coord("axes", name).ok().map(|c| c.index());
        let rays = r
            .rays
            .iter()
            .zip(&r.piece_components)
            .map(|(ray, comps)| {
                let mut at = r.fixed.clone();
                for (name, v) in &ray.fixed {
                    if let Some(slot) = index(name).and_then(|i| at.get_mut(i)) {
                        *slot = *v;
                    }
                }
                let a = r.axes.iter().position(|n| *n == ray.vary).unwrap_or(0);
                if let Some(slot) = index(&ray.vary).and_then(|i| at.get_mut(i)) {
                    *slot = r.ranges[a][0];
                }
                LatticeRay { vary: ray.vary.to_string(), at, feasible: ray.feasible.clone(), components: comps.clone() }
            })
            .collect();
        let coords: Vec<Option<cablenav::model::Coord>> = r.axes.iter().map(|n| s.coord("axes", n).ok()).collect();
        LatticeResult {
            axes: r.axes.clone(),
            axis_index: coords.iter().map(|c| c.map_or(0, |c| c.index())).collect(),
            axis_angle: coords.iter().map(|c| c.is_some_and(|c| c.is_angle())).collect(),
            ranges: r.ranges.clone(),
            steps: r.steps.clone(),
            fixed: r.fixed.clone(),
            rays,
            pieces: r.pieces,
            components: r.components,
            grid_points: r.grid_points,
            feasible_points: r.feasible_points,
            uncertain_rays: r.uncertain_rays,
            split: [r.grid_components, r.sliver_components, r.pointwise_components, r.missed_separations],
        }
    }
}

/// A message: a job or a reply, and the id that pairs them.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Envelope<T> {
    /// Chosen by the host, echoed by the worker.
    pub id: u32,
    /// The job or reply.
    pub body: T,
}

/// A job message.
pub fn encode_job(id: u32, job: &Job) -> String {
    serde_json::to_string(&Envelope { id, body: job }).unwrap_or_default()
}

/// Reads a job message.
pub fn decode_job(text: &str) -> Result<Envelope<Job>, String> {
    serde_json::from_str(text).map_err(|e| e.to_string())
}

/// A reply message.
pub fn encode_reply(id: u32, reply: &Reply) -> String {
    serde_json::to_string(&Envelope { id, body: reply }).unwrap_or_default()
}

/// Reads a worker's message: `None` for the ready message, else the reply or why it is not one.
pub fn decode_reply(text: &str) -> Option<Result<Envelope<Reply>, String>> {
    (text != READY).then(|| serde_json::from_str(text).map_err(|e| e.to_string()))
}

/// A pose as the bits of `[x, y, z, qw, qx, qy, qz]` (JSON integers cross exactly; JSON
/// decimals may not come back to the same last bit).
pub fn pose_to_wire(p: &Pose) -> [u64; 7] {
    let q = p.quaternion();
    [p.position.x, p.position.y, p.position.z, q[0], q[1], q[2], q[3]].map(f64::to_bits)
}

/// The pose sent by [`pose_to_wire`], bit for bit (the quaternion is not renormalised).
pub fn pose_from_wire(w: &[u64; 7]) -> Pose {
    let w = w.map(f64::from_bits);
    Pose {
        position: Vector3::new(w[0], w[1], w[2]),
        rotation: UnitQuaternion::new_unchecked(Quaternion::new(w[3], w[4], w[5], w[6])),
    }
}

/// Numbers that must cross exactly, sent as their bits.
mod bits {
    use serde::{Deserialize, Deserializer, Serializer};

    pub fn serialize<S: Serializer>(v: &[[f64; 2]; 2], s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(v.iter().map(|r| r.map(f64::to_bits)))
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<[[f64; 2]; 2], D::Error> {
        Ok(<[[u64; 2]; 2]>::deserialize(d)?.map(|r| r.map(f64::from_bits)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn jobs_and_replies_round_trip_as_json() {
        let job = Job::Plan { scenario: "{}".into(), query: "q1-q2".into(), planner: "continuation".into(), max_charts: 7, steps: 7, identify_angles: false };
        let text = encode_job(3, &job);
        assert!(text.contains(r#""body":{"plan":{"#), "{text}");
        assert_eq!(decode_job(&text), Ok(Envelope { id: 3, body: job }));
        let reply = Reply::Sliced { rows: [0, 2], classes: vec![Class::Feasible, Class::Singular] };
        assert_eq!(decode_reply(&encode_reply(9, &reply)), Some(Ok(Envelope { id: 9, body: reply })));
        assert_eq!(decode_reply(READY), None);
        let map = SliceSpec { scenario: "{}".into(), pose: "q1".into(), axes: ["x".into(), "y".into()], res: 4, range: [[0.1, 2.0 / 3.0], [-1e-300, 7.0]] };
        let slice = Job::Slice { map: map.clone(), rows: [0, 4] };
        assert_eq!(decode_job(&encode_job(1, &slice)).unwrap().body, slice, "the range crosses bit for bit");
        let singular = Job::Singular { map };
        assert_eq!(decode_job(&encode_job(2, &singular)).unwrap().body, singular);
        assert!(decode_job(r#"{"id":1,"body":{"dance":{}}}"#).is_err());
    }

    #[test]
    fn reports_cross_bit_for_bit() {
        let s = crate::logic::parse_scenario(crate::presets::PRESETS[crate::presets::find("cdpr7-tree").unwrap()].json).unwrap();
        let report = crate::logic::verify(&s, 0).unwrap();
        assert!(!report.boundaries.is_empty());
        let text = serde_json::to_string(&WireReport::from(&report)).unwrap();
        assert_eq!(serde_json::from_str::<WireReport>(&text).unwrap().report(), report);
    }

    #[test]
    fn poses_cross_bit_for_bit() {
        let p = Pose::from_tilt_torsion(Vector3::new(0.1, -2.0 / 3.0, 1e-17), [0.3, 1.1, -2.9]);
        let wire = pose_to_wire(&p);
        let text = serde_json::to_string(&wire).unwrap();
        let back = pose_from_wire(&serde_json::from_str(&text).unwrap());
        assert_eq!(back, p);
    }
}
