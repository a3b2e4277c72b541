//! What the 3-D view draws, as vertex data: the base frame, anchors and a ground grid, the cables
//! at the shown pose (coloured by tension margin, red when interfering), the platform, the
//! obstacles, the trajectory in its verified sections and the planned path. Plain Rust over the
//! core's results; the GL side only uploads and draws these buffers.

use super::tessellate::{self, dv, Tris};
use crate::logic::StripModel;
use crate::palette::*;
use cablenav::model::chain::Frame;
use cablenav::model::{Chain, Pose};
use cablenav::verify::profile::CableState;
use cablenav::Scenario;
use glam::DVec3;
use nalgebra::Vector3;

/// Floats per vertex: position (3), normal (3, zero for unlit), colour RGBA (4).
pub const STRIDE: usize = 10;

/// Vertex data for the three passes.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Geometry {
    /// Opaque lit triangles.
    pub solid: Vec<f32>,
    /// Unlit line segments (2 vertices each).
    pub lines: Vec<f32>,
    /// Translucent lit triangles, drawn last (the platform and the obstacles).
    pub translucent: Vec<f32>,
}

fn push(out: &mut Vec<f32>, p: DVec3, n: DVec3, c: Rgba) {
    out.extend([p.x as f32, p.y as f32, p.z as f32, n.x as f32, n.y as f32, n.z as f32]);
    out.extend(c);
}

fn push_tris(out: &mut Vec<f32>, t: &Tris, c: Rgba) {
    for (p, n) in t.positions.iter().zip(&t.normals) {
        push(out, *p, *n, c);
    }
}

fn line(out: &mut Vec<f32>, a: DVec3, b: DVec3, c: Rgba) {
    push(out, a, DVec3::ZERO, c);
    push(out, b, DVec3::ZERO, c);
}

/// How a cable is drawn, by its state: its class name (for the legend and tests) and colour.
/// Interference and a length out of bounds are red; otherwise the tension margin, relative to
/// the bounds' span, runs from purple (out of bounds) through orange (zero) to blue (a quarter
/// of the span or more); dark grey without tension information.
pub fn cable_look(s: &CableState) -> (&'static str, Rgba) {
    if s.interfering {
        return ("interfering", RED);
    }
    if !s.length_ok {
        return ("length", RED);
    }
    match s.tension_margin {
        None => ("plain", CABLE),
        Some(m) if m <= 0.0 => ("tension-out", CABLE_OUT),
        Some(m) => {
            let f = (m / (0.25 * s.tension_span.max(1e-12))).clamp(0.0, 1.0) as f32;
            ("tension-margin", std::array::from_fn(|k| CABLE_TIGHT[k] * (1.0 - f) + CABLE_EASY[k] * f))
        }
    }
}

/// A piece of a path drawn in one colour: the poses along it.
#[derive(Debug, Clone, PartialEq)]
pub struct Polyline {
    /// Its colour.
    pub colour: Rgba,
    /// The poses, in order.
    pub poses: Vec<Pose>,
}

/// Poses per unit of t when sampling a section for drawing.
const SAMPLES_PER_T: f64 = 240.0;

/// A path cut at the verifier's section ends, each piece sampled (ends included) by `pose_at` (the
/// pose drawn at t: a trajectory's, or a multi-link robot's last link's, see [`end_pose`]) and
/// coloured by its kind, so colour changes exactly where the report says.
pub fn section_polylines(model: &StripModel, pose_at: impl Fn(f64) -> Pose) -> Vec<Polyline> {
    model
        .sections
        .iter()
        .map(|s| {
            let n = (((s.t1 - s.t0) * SAMPLES_PER_T).ceil() as usize).max(1);
            let poses = (0..=n).map(|k| pose_at(s.t0 + (s.t1 - s.t0) * k as f64 / n as f64)).collect();
            Polyline { colour: kind_colour(s.kind), poses }
        })
        .collect()
}

/// A link frame as a pose.
fn frame_pose((p, r): &Frame) -> Pose {
    Pose { position: *p, rotation: nalgebra::UnitQuaternion::from_matrix(r) }
}

/// The pose of a multi-link robot's last link at configuration `q`: what its paths trace (its
/// joint, and the tip of its body as the tool point).
pub fn end_pose(chain: &Chain, q: &[f64]) -> Pose {
    chain.frames(q).last().map_or_else(|| Pose::from_coords([0.0; 6]), frame_pose)
}

/// Samples along an angle ray piece (position rays are straight: their two ends).
const ANGLE_SAMPLES: usize = 16;

/// A ray lattice's pieces as coloured poses (see [`crate::rays::ray_pieces`]): feasible
/// pieces in their component's colour, as in the cross-section panel; the infeasible ones in red
/// when `infeasible`, else left out. A multi-link robot's pieces are its last link's poses
/// ([`end_pose`]).
pub fn lattice_polylines(s: &Scenario, l: &crate::worker::protocol::LatticeResult, infeasible: bool) -> Vec<Polyline> {
    crate::rays::ray_pieces(l)
        .into_iter()
        .filter(|p| infeasible || p.component.is_some())
        .map(|p| {
            let n = if p.angle { ANGLE_SAMPLES } else { 1 };
            let poses = (0..=n)
                .map(|k| {
                    let mut c = p.at.clone();
                    c[p.vary] = p.from + (p.to - p.from) * k as f64 / n as f64;
                    match &s.robot.chain {
                        Some(chain) => end_pose(chain, &c),
                        None => Pose::from_slice(&c),
                    }
                })
                .collect();
            Polyline { colour: component_rgba(p.component), poses }
        })
        .collect()
}

/// What the [`Backdrop`] and the scene's box depend on: the obstacles, the base anchors and the
/// points the robot reaches at every named pose or configuration (cable ends, link bodies).
/// Cheap to make and compare, so that a change elsewhere (a trajectory's via point) rebuilds
/// nothing of the backdrop.
#[derive(Debug, Clone, PartialEq)]
pub struct BackdropKey {
    obstacles: Vec<cablenav::shape::Obstacle>,
    bases: Vec<DVec3>,
    reached: Vec<DVec3>,
}

impl BackdropKey {
    /// The key of scenario `s`.
    pub fn of(s: &Scenario) -> BackdropKey {
        let mut reached = vec![];
        for (_, pose) in &s.poses {
            let shown = Shown::Platform(*pose);
            reached.extend((0..s.robot.cables.len()).map(|i| dv(&shown.cable_end(s, i))));
        }
        if let Some(chain) = &s.robot.chain {
            for (_, q) in &s.configs {
                let frames = chain.frames(q);
                for (link, f) in chain.links.iter().zip(&frames) {
                    reached.extend(link.body.iter().map(|b| dv(&(f.0 + f.1 * b))));
                }
                let shown = Shown::Links(frames);
                reached.extend((0..s.robot.cables.len()).flat_map(|i| shown.cable_points(s, i)).map(|p| dv(&p)));
            }
        }
        // the anchors fixed to the base (a routed cable's may all be on links)
        let bases = s.robot.cables.iter().flat_map(|c| c.anchors()).filter(|a| a.link.is_none()).map(|a| dv(&a.point)).collect();
        BackdropKey { obstacles: s.obstacles.clone(), bases, reached }
    }
}

/// The box the scene occupies: base anchors, obstacles, and the robot at every named pose or
/// configuration.
pub fn bounds(s: &Scenario) -> (DVec3, DVec3) {
    let key = BackdropKey::of(s);
    let shapes: Vec<Tris> = key.obstacles.iter().map(|o| tessellate::shape(&o.shape)).collect();
    box_of(&key, &shapes)
}

/// The box of a key's points and the obstacles' tessellations `shapes`.
fn box_of(key: &BackdropKey, shapes: &[Tris]) -> (DVec3, DVec3) {
    let points = key.bases.iter().chain(&key.reached).chain(shapes.iter().flat_map(|t| &t.positions));
    let (min, max) = points.fold((DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    if !min.is_finite() || !max.is_finite() {
        return (DVec3::splat(-1.0), DVec3::splat(1.0));
    }
    (min, max)
}

/// The tool point whose trace shows a path's orientation: on the platform's z axis, as far from
/// its origin as its farthest anchor (at least a tenth of the scene); for a multi-link robot the
/// tip of its last link's body.
fn tool_point(s: &Scenario, extent: f64) -> Vector3<f64> {
    if let Some(tip) = s.robot.chain.as_ref().and_then(|c| c.links.last()).map(|l| l.body[1]).filter(|b| b.norm() > 1e-9) {
        return tip;
    }
    let reach = s.robot.cables.iter().map(|c| c.platform.norm()).fold(0.0, f64::max);
    Vector3::new(0.0, 0.0, reach.max(extent * 0.1))
}

/// The robot as shown: a platform robot's pose, or a multi-link robot's link frames.
#[derive(Debug, Clone, PartialEq)]
pub enum Shown {
    /// The platform at this pose.
    Platform(Pose),
    /// Every link's frame (position, rotation), in link order.
    Links(Vec<Frame>),
}

impl Shown {
    /// A multi-link robot's links at configuration `q`.
    pub fn config(chain: &Chain, q: &[f64]) -> Shown {
        Shown::Links(chain.frames(q))
    }

    /// Where cable `i` of `s` meets the moving part (world frame).
    pub fn cable_end(&self, s: &Scenario, i: usize) -> Vector3<f64> {
        let c = &s.robot.cables[i];
        match self {
            Shown::Platform(pose) => pose.transform(&c.platform),
            Shown::Links(f) => f.get(c.link).map_or(c.platform, |(p, r)| p + r * c.platform),
        }
    }

    /// Every anchor of cable `i` of `s` in order (world frame): its base anchor and its end for a
    /// straight cable, and the anchors between for a routed one.
    pub fn cable_points(&self, s: &Scenario, i: usize) -> Vec<Vector3<f64>> {
        let c = &s.robot.cables[i];
        match self {
            Shown::Platform(_) => vec![c.base, self.cable_end(s, i)],
            Shown::Links(f) => c.anchors().iter().map(|a| a.link.and_then(|l| f.get(l)).map_or(a.point, |(p, r)| p + r * a.point)).collect(),
        }
    }
}

/// Everything to draw.
pub struct SceneInput<'a> {
    /// The scenario.
    pub scenario: &'a Scenario,
    /// The robot shown (cables and platform or links), if any.
    pub shown: Option<Shown>,
    /// The cables' states at `shown`, in cable order.
    pub cables: &'a [CableState],
    /// The trajectory's pieces (see [`section_polylines`]).
    pub trajectory: &'a [Polyline],
    /// Paths drawn beside the trajectory: the planned path, the lattice planner's A* polyline.
    pub paths: &'a [Polyline],
    /// The ray lattice's pieces (see [`lattice_polylines`]), drawn as thin lines.
    pub lattice: &'a [Polyline],
    /// The draggable handles (m, world frame), the selected one's index and, for it, the axis
    /// (0, 1, 2) a drag is constrained to, if any.
    pub handles: &'a [DVec3],
    /// The selected handle.
    pub selected: Option<usize>,
    /// The selected handle's drag axis, drawn as a guide line.
    pub axis: Option<usize>,
    /// Clearance tubes to draw around cables at `pose`: (cable index, radius), see
    /// [`clearance_tubes`].
    pub tubes: &'a [(usize, f64)],
}

/// The clearance tubes that show a boundary's constraint (its name as the core gives it): for
/// `cables i-j`, a tube of half the cable–cable clearance around each (they touch exactly when the
/// centrelines are the clearance apart); for `cable i - <obstacle>`, a tube of the cable–obstacle
/// clearance around the cable (it touches the obstacle's surface at the boundary). Clearances are
/// between centrelines (the cable diameter is informational in the format). Other constraints
/// (lengths, tensions) have no tube. Cable indices are 0-based.
pub fn clearance_tubes(s: &Scenario, constraint: &str) -> Vec<(usize, f64)> {
    // a cable's number (`3`, or `3 segment 2` for a segment of a routed cable: the whole cable)
    let cable = |n: &str| n.split_whitespace().next()?.parse::<usize>().ok().filter(|&k| k >= 1 && k <= s.robot.cables.len()).map(|k| k - 1);
    if let Some((a, b)) = constraint.strip_prefix("cables ").and_then(|r| r.split_once('-')) {
        let r = s.clearance.cable_cable / 2.0;
        return [cable(a), cable(b)].into_iter().flatten().map(|i| (i, r)).collect();
    }
    match constraint.strip_prefix("cable ").and_then(|r| r.split_once(" - ")) {
        // segments of two routed cables (`cable 1 segment 2 - cable 3 segment 1`)
        Some((i, other)) if other.starts_with("cable ") => {
            let r = s.clearance.cable_cable / 2.0;
            [cable(i), other.strip_prefix("cable ").and_then(cable)].into_iter().flatten().map(|i| (i, r)).collect()
        }
        Some((i, _obstacle)) => cable(i).map(|i| vec![(i, s.clearance.cable_obstacle)]).unwrap_or_default(),
        None => vec![],
    }
}

/// What does not move while a path, a pose or a plan changes: the ground grid, the world frame,
/// the base anchors and the obstacles (drawn once per scenario change that touches them, not at
/// every drag step or planned path), and the box the scene occupies.
#[derive(Debug, Clone, PartialEq)]
pub struct Backdrop {
    /// Its vertex data.
    pub geometry: Geometry,
    /// The scene's box ([`bounds`]).
    pub bounds: (DVec3, DVec3),
}

/// The scene's size and the thin line radius it implies.
fn sizes(bounds: (DVec3, DVec3)) -> (f64, f64) {
    let extent = (bounds.1 - bounds.0).length().max(1e-3);
    (extent, extent * 0.0025)
}

/// Builds the backdrop of a scenario from its key (see [`Backdrop`]).
pub fn backdrop(key: &BackdropKey) -> Backdrop {
    let mut g = Geometry::default();
    let shapes: Vec<Tris> = key.obstacles.iter().map(|o| tessellate::shape(&o.shape)).collect();
    let (min, max) = box_of(key, &shapes);
    let (extent, thin) = sizes((min, max));

    // ground grid at the lowest base anchor, over the anchors' footprint, 10 lines each way
    let floor = key.bases.iter().map(|b| b.z).fold(f64::INFINITY, f64::min).min(min.z);
    for k in 0..=10 {
        let f = k as f64 / 10.0;
        let x = min.x + (max.x - min.x) * f;
        let y = min.y + (max.y - min.y) * f;
        line(&mut g.lines, DVec3::new(x, min.y, floor), DVec3::new(x, max.y, floor), GRID);
        line(&mut g.lines, DVec3::new(min.x, y, floor), DVec3::new(max.x, y, floor), GRID);
    }
    // world frame
    for (k, c) in AXES.iter().enumerate() {
        let tip = DVec3::from_array(std::array::from_fn(|i| if i == k { extent * 0.12 } else { 0.0 }));
        let mut t = Tris::default();
        tessellate::tube(&mut t, DVec3::ZERO, tip, thin * 1.2, 6);
        push_tris(&mut g.solid, &t, *c);
    }
    // base anchors
    let a = extent * 0.008;
    let mut anchors = Tris::default();
    for b in &key.bases {
        tessellate::cuboid(&mut anchors, std::array::from_fn(|i| *b + DVec3::new(bit(i, 0), bit(i, 1), bit(i, 2)) * a));
    }
    push_tris(&mut g.solid, &anchors, ANCHOR);
    for (k, t) in shapes.iter().enumerate() {
        push_tris(&mut g.translucent, t, OBSTACLES[k % OBSTACLES.len()]);
    }
    Backdrop { geometry: g, bounds: (min, max) }
}

/// Builds the vertex data of what moves in a scene (drawn over its [`Backdrop`], whose box
/// `bounds` sizes it): the robot shown, the paths, the lattice and the handles.
pub fn build(input: &SceneInput, bounds: (DVec3, DVec3)) -> Geometry {
    let s = input.scenario;
    let mut g = Geometry::default();
    let (extent, thin) = sizes(bounds);

    if let Some(shown) = &input.shown {
        for i in 0..s.robot.cables.len() {
            let colour = input.cables.get(i).map_or(CABLE, |st| cable_look(st).1);
            let mut t = Tris::default();
            for w in shown.cable_points(s, i).windows(2) {
                tessellate::tube(&mut t, dv(&w[0]), dv(&w[1]), thin, 6);
            }
            push_tris(&mut g.solid, &t, colour);
        }
        match shown {
            Shown::Platform(pose) => platform(&mut g, s, pose, extent),
            Shown::Links(frames) => links(&mut g, s, frames, extent),
        }
        let mut tubes = Tris::default();
        for &(i, r) in input.tubes.iter().filter(|(i, _)| *i < s.robot.cables.len()) {
            for w in shown.cable_points(s, i).windows(2) {
                tessellate::tube(&mut tubes, dv(&w[0]), dv(&w[1]), r, 18);
            }
        }
        push_tris(&mut g.translucent, &tubes, TUBE);
    }

    let tool = tool_point(s, extent);
    let pieces = input.trajectory.iter().chain(input.paths);
    for piece in pieces {
        let mut t = Tris::default();
        let positions: Vec<DVec3> = piece.poses.iter().map(|p| dv(&p.position)).collect();
        let tips: Vec<DVec3> = piece.poses.iter().map(|p| dv(&p.transform(&tool))).collect();
        for w in positions.windows(2).chain(tips.windows(2)) {
            if (w[1] - w[0]).length() > 1e-12 {
                tessellate::tube(&mut t, w[0], w[1], thin * 1.6, 6);
            }
        }
        push_tris(&mut g.solid, &t, piece.colour);
    }

    // the lattice: the platform origin's trace along position rays, the tool point's along
    // angle rays (where the origin stays put)
    for piece in input.lattice {
        let positions: Vec<DVec3> = piece.poses.iter().map(|p| dv(&p.position)).collect();
        let still = positions.windows(2).all(|w| (w[1] - w[0]).length() <= 1e-12);
        let trace: Vec<DVec3> = if still { piece.poses.iter().map(|p| dv(&p.transform(&tool))).collect() } else { positions };
        for w in trace.windows(2) {
            line(&mut g.lines, w[0], w[1], piece.colour);
        }
    }

    // handles: small cubes, the selected one larger and orange, with its drag axis as a line
    let (mut idle, mut picked) = (Tris::default(), Tris::default());
    for (i, h) in input.handles.iter().enumerate() {
        let sel = input.selected == Some(i);
        let r = extent * if sel { 0.014 } else { 0.01 };
        tessellate::cuboid(if sel { &mut picked } else { &mut idle }, std::array::from_fn(|c| *h + DVec3::new(bit(c, 0), bit(c, 1), bit(c, 2)) * r));
        if let (true, Some(k)) = (sel, input.axis) {
            let dir = DVec3::from_array(std::array::from_fn(|j| if j == k { extent } else { 0.0 }));
            line(&mut g.lines, *h - dir, *h + dir, AXES[k]);
        }
    }
    push_tris(&mut g.solid, &idle, HANDLE);
    push_tris(&mut g.solid, &picked, HANDLE_SELECTED);
    g
}

/// ±1 by bit `b` of `i` (cuboid corner order).
fn bit(i: usize, b: usize) -> f64 {
    if i >> b & 1 == 0 { -1.0 } else { 1.0 }
}

/// The platform: the box spanning its anchors in its own frame (thickened if flat), posed, and
/// its frame axes.
fn platform(g: &mut Geometry, s: &Scenario, pose: &Pose, extent: f64) {
    let mut lo = Vector3::repeat(f64::INFINITY);
    let mut hi = Vector3::repeat(f64::NEG_INFINITY);
    for c in &s.robot.cables {
        lo = lo.inf(&c.platform);
        hi = hi.sup(&c.platform);
    }
    let size = (hi - lo).max().max(extent * 0.02);
    let pad = Vector3::from_fn(|i, _| ((size * 0.05) - (hi[i] - lo[i]) / 2.0).max(0.0));
    let (lo, hi) = (lo - pad, hi + pad);
    let corners = std::array::from_fn(|i| {
        let local = Vector3::new(pick(i, 0, &lo, &hi), pick(i, 1, &lo, &hi), pick(i, 2, &lo, &hi));
        dv(&pose.transform(&local))
    });
    let mut t = Tris::default();
    tessellate::cuboid(&mut t, corners);
    // translucent: a large platform must not hide the cables and paths behind it
    push_tris(&mut g.translucent, &t, PLATFORM);
    let origin = dv(&pose.position);
    for (k, c) in AXES.iter().enumerate() {
        let tip = pose.transform(&Vector3::from_fn(|i, _| if i == k { size * 0.8 } else { 0.0 }));
        line(&mut g.lines, origin, dv(&tip), *c);
    }
}

/// A multi-link robot's links: each body a translucent tube of its collision radius (at least a
/// thin one), each joint a dark cube with the link's frame axes.
fn links(g: &mut Geometry, s: &Scenario, frames: &[Frame], extent: f64) {
    let Some(chain) = &s.robot.chain else { return };
    let (mut bodies, mut joints) = (Tris::default(), Tris::default());
    let (min_r, j) = (extent * 0.006, extent * 0.012);
    for (link, (p, r)) in chain.links.iter().zip(frames) {
        let (a, b) = (dv(&(p + r * link.body[0])), dv(&(p + r * link.body[1])));
        if (b - a).length() > 1e-12 {
            tessellate::tube(&mut bodies, a, b, link.radius.max(min_r), 16);
        }
        let o = dv(p);
        tessellate::cuboid(&mut joints, std::array::from_fn(|i| o + DVec3::new(bit(i, 0), bit(i, 1), bit(i, 2)) * j));
        for (k, c) in AXES.iter().enumerate() {
            let tip = p + r * Vector3::from_fn(|i, _| if i == k { extent * 0.05 } else { 0.0 });
            line(&mut g.lines, o, dv(&tip), *c);
        }
    }
    push_tris(&mut g.translucent, &bodies, PLATFORM);
    push_tris(&mut g.solid, &joints, ANCHOR);
}

fn pick(i: usize, axis: usize, lo: &Vector3<f64>, hi: &Vector3<f64>) -> f64 {
    if i >> axis & 1 == 0 { lo[axis] } else { hi[axis] }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clearance_tubes_name_the_constraints_cables() {
        let s = crate::logic::parse_scenario(crate::presets::PRESETS[crate::presets::find("cdpr7-tree").unwrap()].json).unwrap();
        assert_eq!(clearance_tubes(&s, "cable 3 - crown"), [(2, s.clearance.cable_obstacle)]);
        assert_eq!(clearance_tubes(&s, "cables 1-7"), [(0, s.clearance.cable_cable / 2.0), (6, s.clearance.cable_cable / 2.0)]);
        assert!(clearance_tubes(&s, "cable 2 length").is_empty());
        assert!(clearance_tubes(&s, "cable 9 - crown").is_empty(), "no such cable");
        // a routed cable's segments name their cables: the whole cable gets the tube
        assert_eq!(clearance_tubes(&s, "cable 3 segment 2 - crown"), [(2, s.clearance.cable_obstacle)]);
        assert_eq!(clearance_tubes(&s, "cable 1 segment 1 - cable 4"), [(0, s.clearance.cable_cable / 2.0), (3, s.clearance.cable_cable / 2.0)]);
    }
    use crate::logic;
    use crate::presets::PRESETS;
    use cablenav::verify::profile::cable_states;

    fn scenario(id: &str) -> Scenario {
        logic::parse_scenario(PRESETS[crate::presets::find(id).unwrap()].json).unwrap()
    }

    /// Colours of the triangles in `data`, one per vertex.
    fn colours(data: &[f32]) -> Vec<Rgba> {
        data.chunks(STRIDE).map(|v| [v[6], v[7], v[8], v[9]]).collect()
    }

    #[test]
    fn cable_looks() {
        let st = |interfering, length_ok, tension_margin| CableState { interfering, length_ok, tension_margin, tension_span: 1.0 };
        assert_eq!(cable_look(&st(true, true, Some(0.5))), ("interfering", RED));
        assert_eq!(cable_look(&st(false, false, None)), ("length", RED));
        assert_eq!(cable_look(&st(false, true, None)), ("plain", CABLE));
        assert_eq!(cable_look(&st(false, true, Some(-0.1))).0, "tension-out");
        assert_eq!(cable_look(&st(false, true, Some(0.0))).0, "tension-out");
        assert_eq!(cable_look(&st(false, true, Some(0.3))).1, CABLE_EASY);
        let mid = cable_look(&st(false, true, Some(0.125))).1;
        assert!((mid[0] - (CABLE_TIGHT[0] + CABLE_EASY[0]) / 2.0).abs() < 1e-6);
    }

    #[test]
    fn trajectory_pieces_follow_the_sections_exactly() {
        let s = scenario("cdpr7-tree");
        let traj = &s.trajectories[0];
        let report = logic::verify(&s, 0).unwrap();
        let model = logic::strip(&report);
        let pieces = section_polylines(&model, |t| traj.pose_at(t));
        assert_eq!(pieces.len(), model.sections.len());
        assert!(pieces.len() >= 2, "the tree preset has an infeasible section");
        for (p, sec) in pieces.iter().zip(&model.sections) {
            assert_eq!(p.colour, kind_colour(sec.kind));
            assert_eq!(p.poses.first().unwrap().position, traj.pose_at(sec.t0).position);
            assert_eq!(p.poses.last().unwrap().position, traj.pose_at(sec.t1).position);
        }
    }

    #[test]
    fn the_scene_has_every_part() {
        let s = scenario("cdpr7-tree");
        let traj = &s.trajectories[0];
        let report = logic::verify(&s, 0).unwrap();
        let pieces = section_polylines(&logic::strip(&report), |t| traj.pose_at(t));
        let pose = traj.pose_at(0.3);
        let states = cable_states(&s, &pose);
        let g = build(&SceneInput { scenario: &s, shown: Some(Shown::Platform(pose)), cables: &states, trajectory: &pieces, paths: &[], lattice: &[], handles: &[], selected: None, axis: None, tubes: &[] }, bounds(&s));
        assert_eq!(g.solid.len() % STRIDE, 0);
        assert_eq!(g.lines.len() % (2 * STRIDE), 0);
        // the platform box translucent; the three obstacles in the backdrop, translucent too
        assert_eq!(g.translucent.len(), 12 * 3 * STRIDE);
        let b = backdrop(&BackdropKey::of(&s));
        let expect: usize = s.obstacles.iter().map(|o| tessellate::shape(&o.shape).len()).sum::<usize>();
        assert_eq!(b.geometry.translucent.len(), expect * 3 * STRIDE);
        assert_eq!(b.bounds, bounds(&s));
        let solid = colours(&g.solid);
        // cable 3 meets the crown at t = 0.3: drawn red, 12 triangles of its tube
        assert!(states[2].interfering);
        assert!(solid.iter().filter(|c| **c == RED).count() >= 36);
        assert!(solid.contains(&GREEN), "the feasible section");
        assert!(!solid.contains(&PATH), "no path given");
        // without a pose: no cables, no platform
        let bare = build(&SceneInput { scenario: &s, shown: None, cables: &[], trajectory: &[], paths: &[], lattice: &[], handles: &[], selected: None, axis: None, tubes: &[] }, bounds(&s));
        assert!(bare.solid.len() < g.solid.len());
        assert!(!colours(&bare.solid).contains(&RED));
    }

    #[test]
    fn the_lattice_is_drawn_in_the_panels_colours() {
        let s = scenario("cdpr7-box");
        let spec = cablenav::lattice::LatticeSpec::new(vec![cablenav::model::Coord::X, cablenav::model::Coord::Z], vec![[0.2, 3.8], [0.3, 3.7]], vec![7], s.pose("fig310").unwrap().coords()).unwrap();
        let l = crate::worker::protocol::LatticeResult::of(&s, &cablenav::lattice::Lattice::build(&s, spec).report().unwrap());
        let all = lattice_polylines(&s, &l, true);
        let feasible = lattice_polylines(&s, &l, false);
        assert!(feasible.len() < all.len() && feasible.iter().all(|p| p.colour != lattice_red()));
        // the x-ray at z = 0.8667: red from x = 0.2, then green from x ≈ 2.0016, at y = 2
        let ray: Vec<&Polyline> = all.iter().filter(|p| (p.poses[0].position.z - 0.8666666666666667).abs() < 1e-12 && p.poses[0].position.x != p.poses[1].position.x).collect();
        assert_eq!(ray.len(), 2);
        assert_eq!((ray[0].colour, ray[1].colour), (lattice_red(), crate::palette::component_rgba(Some(0))));
        assert!((ray[1].poses[0].position.x - 2.0016).abs() < 1e-3 && ray[1].poses[0].position.y == 2.0);
        let bare = build(&SceneInput { scenario: &s, shown: None, cables: &[], trajectory: &[], paths: &[], lattice: &[], handles: &[], selected: None, axis: None, tubes: &[] }, bounds(&s));
        let g = build(&SceneInput { scenario: &s, shown: None, cables: &[], trajectory: &[], paths: &[], lattice: &all, handles: &[], selected: None, axis: None, tubes: &[] }, bounds(&s));
        assert_eq!(g.lines.len() - bare.lines.len(), all.len() * 2 * STRIDE, "a line per position-ray piece");
    }

    #[test]
    fn a_multi_link_robot_is_drawn_with_its_links() {
        let s = scenario("bmarm-x4-2");
        let chain = s.robot.chain.as_ref().unwrap();
        let along = cablenav::verify::all_along(&s)[0];
        let report = logic::verify(&s, 0).unwrap();
        let model = logic::strip(&report);
        let pieces = section_polylines(&model, |t| end_pose(chain, &along.config_at(&s, t)));
        assert_eq!(pieces.iter().map(|p| p.colour).collect::<Vec<_>>(), [GREEN, RED, GREEN], "across the gap");
        // in the gap (cables 2 and 3 too close) the two cables are drawn red
        let gap = model.sections[1].t0 / 2.0 + model.sections[1].t1 / 2.0;
        let q = along.config_at(&s, gap);
        let states = cablenav::verify::profile::cable_states_at(&s, &q);
        let shown = Shown::config(chain, &q);
        // the lower arm's cables end on the lower arm, at its joint's height and above
        let frames = chain.frames(&q);
        for (i, c) in s.robot.cables.iter().enumerate() {
            let end = shown.cable_end(&s, i);
            assert!((end - (frames[c.link].0 + frames[c.link].1 * c.platform)).norm() < 1e-15);
        }
        let input = |shown| SceneInput { scenario: &s, shown, cables: &states, trajectory: &pieces, paths: &[], lattice: &[], handles: &[], selected: None, axis: None, tubes: &[] };
        let g = build(&input(Some(shown.clone())), bounds(&s));
        let red = colours(&g.solid).iter().filter(|c| **c == RED).count();
        let bare = build(&input(None), bounds(&s));
        assert_eq!(red - colours(&bare.solid).iter().filter(|c| **c == RED).count(), 2 * 12 * 3, "two red cable tubes of 12 triangles");
        // two link bodies, translucent
        assert!(g.translucent.len() > bare.translucent.len());
        // the scene's box holds every configuration's links
        let (min, max) = bounds(&s);
        assert!(max.z >= 1.19 && min.z <= 0.0, "{min} {max}");
    }

    #[test]
    fn a_routed_cable_is_drawn_through_its_anchors() {
        let text = PRESETS[crate::presets::find("bmarm-x4-2").unwrap()].json;
        let mut v: serde_json::Value = serde_json::from_str(text).unwrap();
        v["format"] = serde_json::json!("cablenav-scenario/6");
        // cable 1 over a point of the upper arm to the lower arm; a lower-arm cable from the upper arm
        v["robot"]["cables"][0]["via"] = serde_json::json!([{"link": "Upper Arm", "point": [0.05, 0.0, 0.2]}]);
        v["robot"]["cables"][0]["link"] = serde_json::json!("Lower Arm");
        let j = (1..5).find(|&j| v["robot"]["cables"][j]["link"] == "Lower Arm").unwrap();
        v["robot"]["cables"][j]["from"] = serde_json::json!("Upper Arm");
        let s = Scenario::from_json(&v.to_string()).unwrap();
        let chain = s.robot.chain.as_ref().unwrap();
        let q = s.config("initial").unwrap();
        let shown = Shown::config(chain, &q);
        let frames = chain.frames(&q);
        let points = shown.cable_points(&s, 0);
        assert_eq!(points.len(), 3);
        assert!((points[1] - (frames[0].0 + frames[0].1 * nalgebra::Vector3::new(0.05, 0.0, 0.2))).norm() < 1e-15);
        assert!((points[2] - shown.cable_end(&s, 0)).norm() < 1e-15);
        let from = shown.cable_points(&s, j)[0];
        assert!((from - (frames[0].0 + frames[0].1 * s.robot.cables[j].base)).norm() < 1e-15, "the base anchor moves with its link");
        // one tube per segment: cable 1's two of 12 triangles each beside the others' one
        let input = SceneInput { scenario: &s, shown: Some(shown), cables: &[], trajectory: &[], paths: &[], lattice: &[], handles: &[], selected: None, axis: None, tubes: &[] };
        let straight = scenario("bmarm-x4-2");
        let plain = SceneInput { scenario: &straight, shown: Some(Shown::config(chain, &q)), ..input };
        let cables = |g: &Geometry| colours(&g.solid).iter().filter(|c| **c == CABLE).count();
        assert_eq!(cables(&build(&input, bounds(&s))) - cables(&build(&plain, bounds(&straight))), 12 * 3, "one more segment");
        // the backdrop's base anchors leave out the one now on the upper arm
        assert_eq!(BackdropKey::of(&s).bases.len() + 1, BackdropKey::of(&straight).bases.len());
    }

    fn lattice_red() -> Rgba {
        crate::palette::component_rgba(None)
    }

    #[test]
    fn the_backdrop_follows_its_key_only() {
        let s = scenario("cdpr7-tree");
        let mut moved = s.clone();
        // a trajectory's change leaves the key (and so the backdrop) as it was
        moved.trajectories.pop();
        assert_eq!(BackdropKey::of(&s), BackdropKey::of(&moved));
        // an obstacle's, an anchor's or a pose's does not
        let mut o = s.clone();
        o.obstacles.pop();
        assert_ne!(BackdropKey::of(&s), BackdropKey::of(&o));
        let mut a = s.clone();
        a.robot.cables[0].base.x += 0.1;
        assert_ne!(BackdropKey::of(&s), BackdropKey::of(&a));
        let mut p = s.clone();
        p.poses[0].1.position.z += 0.1;
        assert_ne!(BackdropKey::of(&s), BackdropKey::of(&p));
    }

    #[test]
    fn bounds_hold_the_anchors_and_poses() {
        let s = scenario("robocrane");
        let (min, max) = bounds(&s);
        for c in &s.robot.cables {
            let b = dv(&c.base);
            assert!(b.cmpge(min).all() && b.cmple(max).all());
        }
        assert!(max.z >= 2.0, "the platform at z = 2 is inside");
    }
}
