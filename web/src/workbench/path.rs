//! The path the workbench follows — a scenario trajectory or the planned path — resolved from
//! the page's signals, sampled for the plots and exports, and a multi-link robot's path over a
//! cross-section.

use crate::logic::{self, StripModel};
use crate::palette::kind_colour;
use crate::plots::section::Overlay;
use crate::state::{Follow, Parsed, Planned, Shared};
use cablenav::model::{Pose, Trajectory};
use cablenav::Scenario;
use leptos::prelude::*;

/// The path being followed, resolved.
pub enum PathRef<'a> {
    /// A scenario trajectory.
    Trajectory(&'a Trajectory),
    /// The planned path.
    Planned(&'a Planned),
}

impl PathRef<'_> {
    /// The pose at fraction `u` ∈ [0, 1]: the trajectory at t = u, or the planned path's pose
    /// nearest to fraction u of its poses (the path is the planner's own dense sequence).
    pub fn pose_at(&self, u: f64) -> Option<Pose> {
        match self {
            PathRef::Trajectory(t) => Some(t.pose_at(u.clamp(0.0, 1.0))),
            PathRef::Planned(p) => {
                let n = p.poses.len();
                (n > 0).then(|| p.poses[((u.clamp(0.0, 1.0) * (n - 1) as f64).round() as usize).min(n - 1)])
            }
        }
    }

    /// `(parameter, pose)` samples for plots and exports: t for a trajectory, the fraction of
    /// poses for a planned path (all of them).
    pub fn samples(&self, n: usize) -> Vec<(f64, Pose)> {
        match self {
            PathRef::Trajectory(t) => (0..=n).map(|k| k as f64 / n as f64).map(|u| (u, t.pose_at(u))).collect(),
            PathRef::Planned(p) => {
                let m = p.poses.len().max(2) - 1;
                p.poses.iter().enumerate().map(|(k, pose)| (k as f64 / m as f64, *pose)).collect()
            }
        }
    }

    /// What the path is called in plot labels.
    pub fn name(&self) -> String {
        match self {
            PathRef::Trajectory(t) => format!("trajectory “{}”", t.name),
            PathRef::Planned(p) => format!("planned path {}", p.query),
        }
    }

    /// The scenario trajectory followed (its name and duration), if the path is one.
    pub fn timed(&self) -> Option<(String, Option<f64>)> {
        match self {
            PathRef::Trajectory(t) => Some((t.name.clone(), t.duration)),
            PathRef::Planned(_) => None,
        }
    }

    /// The name of the path's parameter: t, or the fraction of its poses.
    pub fn param(&self) -> &'static str {
        match self {
            PathRef::Trajectory(_) => "t",
            PathRef::Planned(_) => "fraction",
        }
    }
}

/// The scenario, if it parsed.
pub fn scenario_of(parsed: &Parsed) -> Option<&Scenario> {
    parsed.0.as_ref().as_ref().ok()
}

/// Runs `f` on the followed path of the parsed scenario: the planned path when it is followed
/// and exists, else trajectory `traj` (clamped to the scenario's).
pub fn on_path<T>(parsed: &Parsed, planned: Option<&Shared<Planned>>, follow: Follow, traj: usize, f: impl FnOnce(&Scenario, PathRef) -> Option<T>) -> Option<T> {
    let s = scenario_of(parsed)?;
    match (follow, planned) {
        (Follow::Planned, Some(p)) => f(s, PathRef::Planned(&p.0)),
        _ => f(s, PathRef::Trajectory(s.trajectories.get(traj.min(s.trajectories.len().saturating_sub(1)))?)),
    }
}

/// Configurations per unit of t when drawing a multi-link robot's path on a cross-section.
const CONFIGS_PER_T: f64 = 120.0;

/// A multi-link robot's path over a cross-section: its verified sections as coloured pieces of
/// configurations, and its ends.
pub fn joint_overlay(s: &Scenario, along: cablenav::verify::Along, model: &StripModel) -> Overlay {
    let joint_pieces = model
        .sections
        .iter()
        .map(|sec| {
            let n = (((sec.t1 - sec.t0) * CONFIGS_PER_T).ceil() as usize).max(1);
            let qs = (0..=n).map(|k| along.config_at(s, sec.t0 + (sec.t1 - sec.t0) * k as f64 / n as f64)).collect();
            (kind_colour(sec.kind), qs)
        })
        .collect();
    Overlay { joint_pieces, joint_ends: [Some(along.config_at(s, 0.0)), Some(along.config_at(s, 1.0))], ..Overlay::default() }
}

/// Whether the parsed scenario is a multi-link robot.
pub fn is_chain(parsed: &Parsed) -> bool {
    scenario_of(parsed).is_some_and(|s| s.robot.chain.is_some())
}

/// Whether the scenario parsed is a planar robot's (format 5 `robot.mobility`), which moves in
/// the plane z = 0.
pub fn is_planar(parsed: &Parsed) -> bool {
    scenario_of(parsed).is_some_and(|s| s.robot.mobility == cablenav::model::Mobility::Planar)
}

/// A multi-link robot's path `index` (clamped to its paths), if it has any.
pub fn joint_path(s: &Scenario, index: usize) -> Option<cablenav::verify::Along<'_>> {
    let all = cablenav::verify::all_along(s);
    logic::trajectory_index(s, index).filter(|_| s.robot.chain.is_some()).map(|i| all[i])
}

/// The signals that choose the followed path: the scenario, the planned path, which of the two
/// is followed, and the selected trajectory.
#[derive(Clone, Copy)]
pub struct PathSignals {
    /// The parsed scenario.
    pub parsed: Memo<Parsed>,
    /// The planned path, if any.
    pub planned: RwSignal<Option<Shared<Planned>>>,
    /// Whether the planned path or the trajectory is followed.
    pub follow: RwSignal<Follow>,
    /// The selected trajectory's index.
    pub trajectory: RwSignal<usize>,
}

impl PathSignals {
    /// [`on_path`] reading (and so tracking) the signals.
    pub fn followed<T>(&self, f: impl FnOnce(&Scenario, PathRef) -> Option<T>) -> Option<T> {
        on_path(&self.parsed.get(), self.planned.get().as_ref(), self.follow.get(), self.trajectory.get(), f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets::{find, PRESETS};

    fn robocrane() -> Scenario {
        logic::parse_scenario(PRESETS[find("robocrane").unwrap()].json).unwrap()
    }

    #[test]
    fn a_trajectory_is_followed_in_t() {
        let s = robocrane();
        let t = &s.trajectories[0];
        let path = PathRef::Trajectory(t);
        assert_eq!(path.pose_at(0.25), Some(t.pose_at(0.25)));
        assert_eq!(path.pose_at(7.0), Some(t.pose_at(1.0)), "clamped");
        let samples = path.samples(4);
        assert_eq!(samples.iter().map(|x| x.0).collect::<Vec<_>>(), [0.0, 0.25, 0.5, 0.75, 1.0]);
        assert_eq!(samples[2].1, t.pose_at(0.5));
        assert_eq!(path.param(), "t");
    }

    #[test]
    fn a_planned_path_is_followed_pose_by_pose() {
        let s = robocrane();
        let poses: Vec<Pose> = (0..5).map(|k| s.trajectories[0].pose_at(k as f64 / 4.0)).collect();
        let p = Planned { query: "q1-q2".into(), start: poses[0], goal: poses[4], poses: poses.clone(), polyline: vec![], motion: None, atlas: None };
        let path = PathRef::Planned(&p);
        assert_eq!(path.pose_at(0.0), Some(poses[0]));
        assert_eq!(path.pose_at(0.5), Some(poses[2]));
        assert_eq!(path.pose_at(0.6), Some(poses[2]), "the nearest pose, not an interpolation");
        assert_eq!(path.pose_at(1.0), Some(poses[4]));
        let samples = path.samples(200);
        assert_eq!(samples.len(), 5, "every pose, whatever the sample count");
        assert_eq!(samples[4], (1.0, poses[4]));
        assert_eq!(path.param(), "fraction");
        let empty = Planned { poses: vec![], ..p };
        assert_eq!(PathRef::Planned(&empty).pose_at(0.5), None);
    }

    #[test]
    fn the_followed_path_falls_back_to_the_trajectory() {
        let s = robocrane();
        let parsed: Parsed = Shared::new(Ok(s.clone()));
        let name = |follow, planned: Option<&Shared<Planned>>| on_path(&parsed, planned, follow, 9, |_, p| Some(p.name()));
        assert_eq!(name(Follow::Planned, None).as_deref(), Some("trajectory “slerp q1-q2”"), "no plan: the (clamped) trajectory");
        let pose = s.trajectories[0].pose_at(0.0);
        let plan = Shared::new(Planned { query: "q1-q2".into(), start: pose, goal: pose, poses: vec![pose], polyline: vec![], motion: None, atlas: None });
        assert_eq!(name(Follow::Planned, Some(&plan)).as_deref(), Some("planned path q1-q2"));
        assert_eq!(name(Follow::Trajectory, Some(&plan)).as_deref(), Some("trajectory “slerp q1-q2”"));
        let broken: Parsed = Shared::new(Err("bad".into()));
        assert_eq!(on_path(&broken, None, Follow::Trajectory, 0, |_, p| Some(p.name())), None);
    }
}
