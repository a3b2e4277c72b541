//! Poses and trajectories: the named poses (a position and one orientation form), trajectories
//! as one polynomial, Bézier or line translation with a slerp, as joined pieces (format 2) or
//! through timed knots (format 4), and their durations.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use super::{find_pose, known_poses, max_abs, needs_format, num, positive, unique_name, vec3, JOIN_TOLERANCE, MAX_PIECES, UNIT_TOLERANCE};
use crate::error::{finite, Error, Result};
use crate::model::trajectory::MAX_DEGREE;
use crate::model::{Knot, Knots, Orientation, Pose, Profile, Robot, Segment, Trajectory, Translation};
use crate::scenario::json::{Fixed, QuatRef, RawKnot, RawOrientation, RawPiece, RawPose, RawScenario, RawTrajectory, RawTranslation, FORMAT_2};

/// The named poses, in file order, named uniquely. `unoriented`: an orientation may be omitted
/// (the identity), as for a point mass, whose orientation is immaterial.
pub(super) fn poses(raw: &[(String, RawPose)], unoriented: bool, warnings: &mut Vec<String>) -> Result<Vec<(String, Pose)>> {
    let mut out: Vec<(String, Pose)> = Vec::with_capacity(raw.len());
    for (name, p) in raw {
        let path = format!("poses.{name}");
        if name.is_empty() {
            return Err(Error::new("poses", "a pose name must not be empty"));
        }
        if out.iter().any(|(n, _)| n == name) {
            return Err(Error::new(path, format!("duplicate pose name \"{name}\"")));
        }
        out.push((name.clone(), pose(&path, p, unoriented, warnings)?));
    }
    Ok(out)
}

/// The tilt-and-torsion angles of the poses `raw` gives them (already checked by [`poses`]), as
/// written: the planner's paper mode takes them as plain coordinates.
pub(super) fn written_angles(raw: &[(String, RawPose)]) -> Vec<(String, [f64; 3])> {
    raw.iter().filter_map(|(name, p)| p.tilt_torsion.as_ref().and_then(|a| angles("", a).ok()).map(|a| (name.clone(), a))).collect()
}

/// One pose at `path`: its position and exactly one orientation form (or, `unoriented`, none: the
/// identity).
fn pose(path: &str, p: &RawPose, unoriented: bool, warnings: &mut Vec<String>) -> Result<Pose> {
    let position = vec3(&format!("{path}.position"), &p.position)?;
    let given: Vec<&str> = [
        ("quaternion", p.quaternion.is_some()),
        ("tilt_torsion", p.tilt_torsion.is_some()),
        ("euler_xyz_deg", p.euler_xyz_deg.is_some()),
    ]
    .iter()
    .filter(|(_, present)| *present)
    .map(|(n, _)| *n)
    .collect();
    if given.is_empty() && unoriented {
        return Ok(Pose { position, rotation: UnitQuaternion::identity() });
    }
    if given.len() != 1 {
        let got = if given.is_empty() { "none".to_owned() } else { given.join(" and ") };
        return Err(Error::new(
            path,
            format!("give the orientation as exactly one of quaternion, tilt_torsion, euler_xyz_deg; got {got}"),
        ));
    }
    let pose = if let Some(q) = &p.quaternion {
        Pose { position, rotation: unit_quaternion(&format!("{path}.quaternion"), q.0, warnings)? }
    } else if let Some(a) = &p.tilt_torsion {
        canonical(Pose::from_tilt_torsion(position, angles(&format!("{path}.tilt_torsion"), a)?))
    } else if let Some(a) = &p.euler_xyz_deg {
        canonical(Pose::from_euler_xyz_deg(position, angles(&format!("{path}.euler_xyz_deg"), a)?))
    } else {
        return Err(Error::new(path, "no orientation given"));
    };
    Ok(pose)
}

/// Three angles at `field`.
fn angles(field: &str, a: &Fixed<f64, 3>) -> Result<[f64; 3]> {
    let v = vec3(field, a)?;
    Ok([v.x, v.y, v.z])
}

/// The quaternion of an orientation given by angles, with its sign chosen so that w ≥ 0 (the
/// sign is otherwise an artefact of the conversion, and slerps between named poses should
/// not take the long way round because of it).
fn canonical(p: Pose) -> Pose {
    if p.rotation.quaternion().w < 0.0 {
        Pose { position: p.position, rotation: UnitQuaternion::new_unchecked(-p.rotation.into_inner()) }
    } else {
        p
    }
}

/// The unit quaternion for `[w, x, y, z]` at `field`: zero is an error, a non-unit one is
/// normalised with a warning.
fn unit_quaternion(field: &str, q: [f64; 4], warnings: &mut Vec<String>) -> Result<UnitQuaternion<f64>> {
    for (i, x) in q.iter().enumerate() {
        num(&format!("{field}[{i}]"), *x)?;
    }
    let m = max_abs(&q);
    if m == 0.0 {
        return Err(Error::new(field, "zero quaternion: it describes no rotation"));
    }
    // Scale first so that the norm neither overflows nor underflows.
    let s = q.map(|x| x / m);
    let ns = s.iter().map(|x| x * x).sum::<f64>().sqrt();
    let norm = ns * m;
    if (norm - 1.0).abs() > UNIT_TOLERANCE {
        warnings.push(format!("{field}: quaternion of norm {norm} is not unit; normalised"));
    }
    let u = s.map(|x| x / ns);
    Ok(UnitQuaternion::from_quaternion(Quaternion::new(u[0], u[1], u[2], u[3])))
}

/// A cable of zero length at a named pose has no direction: an error.
pub(super) fn check_cable_lengths(robot: &Robot, poses: &[(String, Pose)]) -> Result<()> {
    for (name, pose) in poses {
        for (i, c) in robot.cables.iter().enumerate() {
            let end = pose.transform(&c.platform);
            let scale = 1.0 + c.base.norm().max(end.norm());
            if (end - c.base).norm() <= 1e-12 * scale {
                return Err(Error::new(
                    format!("poses.{name}"),
                    format!("cable {} has zero length at pose {name}", i + 1),
                ));
            }
        }
    }
    Ok(())
}

/// The trajectories of a platform robot, named uniquely; `version_2`: pieces are allowed;
/// `unoriented`: orientations may be omitted (a constant identity), as for a point mass.
pub(super) fn trajectories(
    raw: &[RawTrajectory],
    version_2: bool,
    poses: &[(String, Pose)],
    unoriented: bool,
    warnings: &mut Vec<String>,
) -> Result<Vec<Trajectory>> {
    let mut out: Vec<Trajectory> = Vec::with_capacity(raw.len());
    for (k, t) in raw.iter().enumerate() {
        let path = format!("trajectories[{k}]");
        unique_name(&path, &t.name, "trajectory", "trajectories", out.iter().map(|o| o.name.as_str()))?;
        if t.knots.is_some() || t.spline.is_some() {
            if t.pieces.is_some() || t.translation.is_some() || t.orientation.is_some() {
                return Err(Error::new(format!("{path}.knots"), "give either knots or translation and orientation (or pieces), not both"));
            }
            out.push(through_knots(&path, t, poses, unoriented, warnings)?);
            continue;
        }
        let traj = match (&t.pieces, &t.translation, &t.orientation) {
            (Some(pieces), None, None) => {
                if !version_2 {
                    return Err(Error::new(
                        format!("{path}.pieces"),
                        format!("piecewise trajectories need \"format\": \"{}\"", FORMAT_2),
                    ));
                }
                piecewise(&path, &t.name, pieces, poses, unoriented, warnings)?
            }
            (Some(_), _, _) => {
                return Err(Error::new(format!("{path}.pieces"), "give either pieces or translation and orientation, not both"));
            }
            (None, Some(tr), or) => Trajectory::single(
                t.name.clone(),
                translation(&format!("{path}.translation"), tr)?,
                orientation(&format!("{path}.orientation"), or.as_ref(), poses, unoriented, warnings)?,
            ),
            (None, None, _) => return Err(Error::new(format!("{path}.translation"), "missing field `translation`")),
        };
        out.push(traj);
    }
    Ok(out)
}

/// A piecewise trajectory: 1 to [`MAX_PIECES`] pieces, each starting where the previous ends
/// (position and rotation within [`JOIN_TOLERANCE`]).
fn piecewise(path: &str, name: &str, raw: &[RawPiece], poses: &[(String, Pose)], unoriented: bool, warnings: &mut Vec<String>) -> Result<Trajectory> {
    let field = format!("{path}.pieces");
    if raw.is_empty() || raw.len() > MAX_PIECES {
        return Err(Error::new(field, format!("needs 1 to {MAX_PIECES} pieces, got {}", raw.len())));
    }
    let mut pieces: Vec<Segment> = Vec::with_capacity(raw.len());
    for (j, p) in raw.iter().enumerate() {
        let pf = format!("{field}[{j}]");
        let seg = Segment {
            translation: translation(&format!("{pf}.translation"), &p.translation)?,
            orientation: orientation(&format!("{pf}.orientation"), p.orientation.as_ref(), poses, unoriented, warnings)?,
        };
        if let Some(prev) = pieces.last() {
            let (a, b) = (prev.pose_at(1.0), seg.pose_at(0.0));
            let scale = a.position.amax().max(1.0);
            let gap = (a.position - b.position).norm();
            if gap > JOIN_TOLERANCE * scale {
                return Err(Error::new(
                    format!("{pf}.translation"),
                    format!("starts {gap:.3e} away from where piece {} ends: the pieces of a trajectory must join", j - 1),
                ));
            }
            let angle = a.rotation.angle_to(&b.rotation);
            if angle > JOIN_TOLERANCE {
                return Err(Error::new(
                    format!("{pf}.orientation"),
                    format!("starts {angle:.3e} rad away from the rotation where piece {} ends: the pieces of a trajectory must join", j - 1),
                ));
            }
        }
        pieces.push(seg);
    }
    Trajectory::piecewise(name, pieces).ok_or_else(|| Error::new(field, "needs at least one piece"))
}

/// A translation: exactly one of a polynomial (per coordinate, degree at most [`MAX_DEGREE`]), a
/// Bézier curve or a line.
fn translation(path: &str, t: &RawTranslation) -> Result<Translation> {
    let count = [t.polynomial.is_some(), t.bezier.is_some(), t.line.is_some()].iter().filter(|b| **b).count();
    if count != 1 {
        return Err(Error::new(path, format!("give exactly one of polynomial, bezier, line; got {count}")));
    }
    if let Some(rows) = &t.polynomial {
        let field = format!("{path}.polynomial");
        if rows.len() != 3 {
            return Err(Error::new(field, format!("expected 3 rows of coefficients (x, y, z), got {}", rows.len())));
        }
        let mut out: [Vec<f64>; 3] = Default::default();
        for (i, (row, slot)) in rows.iter().zip(out.iter_mut()).enumerate() {
            let rf = format!("{field}[{i}]");
            if row.is_empty() {
                return Err(Error::new(rf, "empty row: give at least the constant coefficient"));
            }
            let mut coeffs =
                row.iter().enumerate().map(|(j, x)| num(&format!("{rf}[{j}]"), *x)).collect::<Result<Vec<f64>>>()?;
            // Trailing zero coefficients do not raise the degree.
            while coeffs.len() > 1 && coeffs.last() == Some(&0.0) {
                coeffs.pop();
            }
            let degree = coeffs.len() - 1;
            if degree > MAX_DEGREE {
                return Err(Error::new(
                    rf,
                    format!(
                        "degree {degree} is above the maximum {MAX_DEGREE}: the exact interference conditions \
                         have several times the trajectory's degree, and the limit keeps exact verification \
                         tractable"
                    ),
                ));
            }
            *slot = coeffs;
        }
        return Ok(Translation::Polynomial(out));
    }
    if let Some(points) = &t.bezier {
        let field = format!("{path}.bezier");
        let n = points.len();
        if n < 2 {
            return Err(Error::new(field, format!("a Bézier curve needs at least 2 control points, got {n}")));
        }
        if n > MAX_DEGREE + 1 {
            return Err(Error::new(
                field,
                format!(
                    "at most {} control points (degree {MAX_DEGREE}) are supported, got {n}: the exact \
                     interference conditions have several times the trajectory's degree, and the limit keeps \
                     exact verification tractable",
                    MAX_DEGREE + 1
                ),
            ));
        }
        let pts =
            points.iter().enumerate().map(|(i, p)| vec3(&format!("{field}[{i}]"), p)).collect::<Result<Vec<_>>>()?;
        return Ok(Translation::Bezier(pts));
    }
    if let Some(Fixed([a, b])) = &t.line {
        let field = format!("{path}.line");
        return Ok(Translation::Line(vec3(&format!("{field}[0]"), a)?, vec3(&format!("{field}[1]"), b)?));
    }
    Err(Error::new(path, "give exactly one of polynomial, bezier, line"))
}

/// A slerp between two quaternions, each given or a named pose's; when none is given and
/// `unoriented`, the constant identity.
fn orientation(
    path: &str,
    o: Option<&RawOrientation>,
    poses: &[(String, Pose)],
    unoriented: bool,
    warnings: &mut Vec<String>,
) -> Result<Orientation> {
    let o = match o {
        Some(o) => o,
        None if unoriented => return Ok(Orientation::Slerp(UnitQuaternion::identity(), UnitQuaternion::identity())),
        None => return Err(Error::new(path, "missing field `orientation`")),
    };
    let field = format!("{path}.slerp");
    let mut ends = Vec::with_capacity(2);
    for (i, r) in o.slerp.0.iter().enumerate() {
        let f = format!("{field}[{i}]");
        let q = match r {
            QuatRef::Quat(q) => unit_quaternion(&f, *q, warnings)?,
            QuatRef::Pose(name) => match find_pose(poses, name) {
                Some(p) => p.rotation,
                None => {
                    return Err(Error::new(f, format!("unknown pose \"{name}\"; {}", known_poses(poses))));
                }
            },
        };
        ends.push(q);
    }
    let (Some(qs), Some(qe)) = (ends.first().copied(), ends.get(1).copied()) else {
        return Err(Error::new(field, "expected 2 orientations"));
    };
    let dot = qs.coords.dot(&qe.coords);
    if dot <= -1.0 + 1e-12 {
        return Err(Error::new(
            field,
            "Qs·Qe = −1: the two quaternions are the same rotation with opposite signs, so the slerp between \
             them is undefined; give both with the same sign",
        ));
    }
    if dot < 0.0 {
        warnings.push(format!(
            "{field}: Qs·Qe = {dot} is negative, so the slerp takes the long way round (cos θ = Qs·Qe is used as \
             given); negate one quaternion for the short way"
        ));
    }
    Ok(Orientation::Slerp(qs, qe))
}

/// Sets each trajectory's duration from its `duration` (a positive number of seconds); one
/// through knots takes its time from them.
pub(super) fn durations(raw: &RawScenario, version: u8, trajectories: &mut [Trajectory]) -> Result<()> {
    for (k, (t, out)) in raw.trajectories.iter().zip(trajectories.iter_mut()).enumerate() {
        if t.knots.is_some() {
            needs_format(version, 4, &format!("trajectories[{k}].knots"))?;
            if t.duration.is_some() {
                return Err(Error::new(format!("trajectories[{k}].duration"), "a trajectory through knots takes its time from them: drop duration"));
            }
        }
        if let Some(d) = t.duration {
            let field = format!("trajectories[{k}].duration");
            needs_format(version, 4, &field)?;
            out.duration = Some(positive(&field, d)?);
        }
    }
    Ok(())
}

/// A trajectory through timed knots (format 4 `spline` and `knots`): two or more knots, the
/// first at time 0, times strictly increasing; each knot's pose a named pose or a position and
/// one orientation form; velocities and accelerations (quintic only) finite, zero when absent.
fn through_knots(path: &str, raw: &RawTrajectory, poses: &[(String, Pose)], unoriented: bool, warnings: &mut Vec<String>) -> Result<Trajectory> {
    let profile = match raw.spline.as_deref() {
        None | Some("quintic") => Profile::Quintic,
        Some("cubic") => Profile::Cubic,
        Some(other) => {
            return Err(Error::new(format!("{path}.spline"), format!("\"{other}\" is not a spline cablenav takes: give \"quintic\" or \"cubic\"")));
        }
    };
    let field = format!("{path}.knots");
    let Some(list) = &raw.knots else { return Err(Error::new(field, "a spline needs its knots")) };
    if list.len() < 2 || list.len() > MAX_PIECES + 1 {
        return Err(Error::new(field, format!("needs 2 to {} knots, got {}", MAX_PIECES + 1, list.len())));
    }
    let mut points: Vec<Knot> = Vec::with_capacity(list.len());
    for (j, k) in list.iter().enumerate() {
        let kf = format!("{field}[{j}]");
        let time = finite(&format!("{kf}.time"), k.time)?;
        match points.last() {
            None if time != 0.0 => return Err(Error::new(format!("{kf}.time"), format!("the first knot is at time 0 (seconds count from it), not {time}"))),
            Some(prev) if time <= prev.time => {
                return Err(Error::new(format!("{kf}.time"), format!("knots out of order: {time} s is not after knot {}'s {} s", j - 1, prev.time)));
            }
            _ => {}
        }
        let pose = knot_pose(&kf, k, poses, unoriented, warnings)?;
        let velocity = k.velocity.as_ref().map(|v| vec3(&format!("{kf}.velocity"), v)).transpose()?.unwrap_or_else(Vector3::zeros);
        let acceleration = match (&k.acceleration, profile) {
            (Some(_), Profile::Cubic) => {
                return Err(Error::new(format!("{kf}.acceleration"), "a cubic spline meets positions and velocities only: drop the acceleration or use \"spline\": \"quintic\""));
            }
            (Some(a), Profile::Quintic) => vec3(&format!("{kf}.acceleration"), a)?,
            (None, _) => Vector3::zeros(),
        };
        points.push(Knot { time, pose, velocity, acceleration });
    }
    Trajectory::through_knots(raw.name.clone(), Knots { profile, points }).ok_or_else(|| Error::new(field, "needs at least two knots"))
}

/// A knot's pose: the named pose `pose`, or `position` with one orientation form.
fn knot_pose(kf: &str, k: &RawKnot, poses: &[(String, Pose)], unoriented: bool, warnings: &mut Vec<String>) -> Result<Pose> {
    let inline = k.position.is_some() || k.quaternion.is_some() || k.tilt_torsion.is_some() || k.euler_xyz_deg.is_some();
    match (&k.pose, inline) {
        (Some(_), true) => Err(Error::new(format!("{kf}.pose"), "give a pose name or a position and orientation, not both")),
        (Some(name), false) => poses
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, p)| *p)
            .ok_or_else(|| Error::new(format!("{kf}.pose"), format!("no pose named \"{name}\""))),
        (None, _) => {
            let Some(position) = k.position.clone() else { return Err(Error::new(format!("{kf}.position"), "a knot needs a pose name or a position")) };
            let raw = RawPose { position, quaternion: k.quaternion.clone(), tilt_torsion: k.tilt_torsion.clone(), euler_xyz_deg: k.euler_xyz_deg.clone() };
            pose(kf, &raw, unoriented, warnings)
        }
    }
}

/// Largest |z| of a position and largest x, y component of a unit quaternion accepted as "in the
/// plane z = 0" for a planar robot.
const PLANE_TOLERANCE: f64 = 1e-12;

/// For a planar robot: every pose and trajectory stays in the plane z = 0 — positions (and knot
/// velocities and accelerations) with z = 0, rotations about the z axis only.
pub(super) fn in_plane(poses: &[(String, Pose)], trajectories: &[Trajectory]) -> Result<()> {
    let flat = |field: String, v: &Vector3<f64>| -> Result<()> {
        if v.z.abs() > PLANE_TOLERANCE {
            return Err(Error::new(format!("{field}[2]"), format!("a planar robot moves in the plane z = 0, got z = {}", v.z)));
        }
        Ok(())
    };
    let about_z = |field: String, q: &UnitQuaternion<f64>| -> Result<()> {
        if q.i.abs() > PLANE_TOLERANCE || q.j.abs() > PLANE_TOLERANCE {
            let axis = q.axis().map_or(Vector3::z(), |a| a.into_inner());
            return Err(Error::new(field, format!("a planar robot turns about the z axis only, got a rotation about [{:.6}, {:.6}, {:.6}]", axis.x, axis.y, axis.z)));
        }
        Ok(())
    };
    for (name, p) in poses {
        flat(format!("poses.{name}.position"), &p.position)?;
        about_z(format!("poses.{name}"), &p.rotation)?;
    }
    for (k, t) in trajectories.iter().enumerate() {
        let path = format!("trajectories[{k}]");
        if let Some(knots) = &t.knots {
            for (j, knot) in knots.points.iter().enumerate() {
                let kf = format!("{path}.knots[{j}]");
                flat(format!("{kf}.position"), &knot.pose.position)?;
                flat(format!("{kf}.velocity"), &knot.velocity)?;
                flat(format!("{kf}.acceleration"), &knot.acceleration)?;
                about_z(kf, &knot.pose.rotation)?;
            }
            continue;
        }
        let segments = std::iter::once((&t.translation, &t.orientation)).chain(t.more.iter().map(|s| (&s.translation, &s.orientation)));
        for (j, (translation, orientation)) in segments.enumerate() {
            let pf = if t.more.is_empty() { path.clone() } else { format!("{path}.pieces[{j}]") };
            let points: Vec<Vector3<f64>> = match translation {
                Translation::Polynomial(c) => c[2].iter().map(|z| Vector3::new(0.0, 0.0, *z)).collect(),
                Translation::Bezier(ps) => ps.clone(),
                Translation::Line(a, b) => vec![*a, *b],
            };
            for p in &points {
                flat(format!("{pf}.translation"), p)?;
            }
            // (a turn comes from knots alone, checked above)
            if let Orientation::Slerp(qs, qe) = orientation {
                about_z(format!("{pf}.orientation.slerp[0]"), qs)?;
                about_z(format!("{pf}.orientation.slerp[1]"), qe)?;
            }
        }
    }
    Ok(())
}
