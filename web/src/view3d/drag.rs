//! Dragging points in the 3-D view: which handle is under the pointer, and where a drag moves
//! it — in the plane facing the camera, along one axis, or in one axis plane. Plain maths over
//! glam and the [`Camera`], no DOM, so it is tested natively.

use super::camera::Camera;
use glam::DVec3;

/// How far from a handle's centre (CSS pixels) a press still grabs it.
pub const GRAB_PX: f64 = 14.0;

/// Where a dragged point may go.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Constraint {
    /// The plane through the point facing the camera.
    View,
    /// The line through the point along axis 0, 1 or 2 (x, y, z).
    Axis(usize),
    /// The plane through the point normal to axis 0, 1 or 2 (yz, xz, xy).
    Plane(usize),
}

impl Constraint {
    /// Every choice with its id and label, for the page's picker.
    pub const CHOICES: [(Constraint, &'static str, &'static str); 7] = [
        (Constraint::View, "view", "facing the camera"),
        (Constraint::Axis(0), "x", "along x"),
        (Constraint::Axis(1), "y", "along y"),
        (Constraint::Axis(2), "z", "along z"),
        (Constraint::Plane(2), "xy", "in the xy plane"),
        (Constraint::Plane(1), "xz", "in the xz plane"),
        (Constraint::Plane(0), "yz", "in the yz plane"),
    ];

    /// The choice with id `id` (`view`, `x`, `y`, `z`, `xy`, `xz`, `yz`).
    pub fn from_id(id: &str) -> Option<Constraint> {
        Self::CHOICES.iter().find(|c| c.1 == id).map(|c| c.0)
    }
}

/// Where world point `p` shows, in CSS pixels from the canvas's top-left corner (`None` behind
/// the eye).
pub fn to_screen(camera: &Camera, p: DVec3, width: f64, height: f64) -> Option<(f64, f64)> {
    let clip = camera.view_projection() * p.extend(1.0);
    (clip.w > 1e-12).then(|| ((clip.x / clip.w + 1.0) * 0.5 * width, (1.0 - clip.y / clip.w) * 0.5 * height))
}

/// The ray from the eye through pixel (x, y): origin and unit direction.
pub fn ray(camera: &Camera, x: f64, y: f64, width: f64, height: f64) -> (DVec3, DVec3) {
    let inv = camera.view_projection().inverse();
    let (nx, ny) = (2.0 * x / width.max(1.0) - 1.0, 1.0 - 2.0 * y / height.max(1.0));
    let near = inv.project_point3(DVec3::new(nx, ny, -1.0));
    let far = inv.project_point3(DVec3::new(nx, ny, 1.0));
    (near, (far - near).normalize())
}

/// The handle nearest to pixel (x, y) among `points`, if one is within [`GRAB_PX`].
pub fn pick(camera: &Camera, points: &[DVec3], x: f64, y: f64, width: f64, height: f64) -> Option<usize> {
    points
        .iter()
        .enumerate()
        .filter_map(|(i, p)| {
            let (sx, sy) = to_screen(camera, *p, width, height)?;
            let d = ((sx - x).powi(2) + (sy - y).powi(2)).sqrt();
            (d <= GRAB_PX).then_some((i, d))
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(i, _)| i)
}

/// Where the ray `(o, d)` meets the constraint through `p0`: the plane's intersection, or the
/// axis line's point nearest to the ray. `None` when the ray runs (nearly) parallel to the plane
/// or the axis, or meets the plane behind the eye.
pub fn constrained(camera: &Camera, c: Constraint, p0: DVec3, o: DVec3, d: DVec3) -> Option<DVec3> {
    let unit = |k: usize| DVec3::from_array(std::array::from_fn(|i| if i == k { 1.0 } else { 0.0 }));
    let plane = |n: DVec3| {
        let den = d.dot(n);
        if den.abs() < 1e-9 {
            return None;
        }
        let t = (p0 - o).dot(n) / den;
        (t > 0.0).then(|| o + t * d)
    };
    match c {
        Constraint::View => plane((camera.target - camera.eye()).normalize()),
        Constraint::Plane(k) => plane(unit(k)),
        Constraint::Axis(k) => {
            // nearest points of the lines p0 + s a and o + t d
            let a = unit(k);
            let w = p0 - o;
            let (b, dd, e) = (a.dot(d), a.dot(w), d.dot(w));
            let den = 1.0 - b * b;
            if den < 1e-9 {
                return None;
            }
            let s = (b * e - dd) / den;
            Some(p0 + s * a)
        }
    }
}

/// A drag in progress: the point where it began and where the pointer's ray first met the
/// constraint, so the point keeps its offset from the pointer (it never jumps to it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Drag {
    /// The dragged point where the drag began.
    pub start: DVec3,
    /// The constraint's point under the pointer when the drag began.
    pub grab: DVec3,
    /// The constraint.
    pub constraint: Constraint,
}

impl Drag {
    /// Begins a drag of `start` under pixel (x, y); `None` if the pointer's ray misses the
    /// constraint.
    pub fn begin(camera: &Camera, start: DVec3, constraint: Constraint, x: f64, y: f64, w: f64, h: f64) -> Option<Drag> {
        let (o, d) = ray(camera, x, y, w, h);
        Some(Drag { start, grab: constrained(camera, constraint, start, o, d)?, constraint })
    }

    /// Where the point is with the pointer at pixel (x, y) (`None`: the ray misses, keep it).
    pub fn to(&self, camera: &Camera, x: f64, y: f64, w: f64, h: f64) -> Option<DVec3> {
        let (o, d) = ray(camera, x, y, w, h);
        let hit = constrained(camera, self.constraint, self.start, o, d)?;
        Some(self.start + (hit - self.grab))
    }
}

/// The step of a keyboard nudge along `axis` (0, 1, 2) of `step` metres, signed.
pub fn nudge(at: [f64; 3], axis: usize, step: f64) -> [f64; 3] {
    let mut p = at;
    p[axis] += step;
    p
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cam() -> Camera {
        let mut c = Camera { target: DVec3::new(1.0, 2.0, 1.0), distance: 6.0, aspect: 800.0 / 600.0, ..Camera::default() };
        c.yaw = 0.7;
        c.pitch = 0.4;
        c
    }

    #[test]
    fn screen_and_ray_are_inverse() {
        let c = cam();
        let p = DVec3::new(1.3, 2.4, 0.8);
        let (x, y) = to_screen(&c, p, 800.0, 600.0).unwrap();
        let (o, d) = ray(&c, x, y, 800.0, 600.0);
        let off = (p - o) - d * (p - o).dot(d);
        assert!(off.length() < 1e-9, "the ray through p's pixel passes through p: {off}");
        assert_eq!(pick(&c, &[DVec3::new(9.0, 9.0, 9.0), p], x + 5.0, y - 5.0, 800.0, 600.0), Some(1));
        assert_eq!(pick(&c, &[p], x + 30.0, y, 800.0, 600.0), None);
    }

    #[test]
    fn a_drag_follows_the_pointer_under_each_constraint() {
        let c = cam();
        let (w, h) = (800.0, 600.0);
        let p = DVec3::new(1.0, 2.0, 1.0);
        let (x, y) = to_screen(&c, p, w, h).unwrap();
        for (con, _, _) in Constraint::CHOICES {
            let d = Drag::begin(&c, p, con, x + 3.0, y + 2.0, w, h).unwrap();
            assert!((d.to(&c, x + 3.0, y + 2.0, w, h).unwrap() - p).length() < 1e-9, "{con:?}: no jump at the start");
            let q = d.to(&c, x + 60.0, y - 40.0, w, h).unwrap();
            let moved = q - p;
            assert!(moved.length() > 1e-3, "{con:?}: it moves");
            match con {
                Constraint::Axis(k) => assert!((0..3).all(|i| i == k || moved[i].abs() < 1e-9), "{con:?}: {moved}"),
                Constraint::Plane(k) => assert!(moved[k].abs() < 1e-9, "{con:?}: {moved}"),
                Constraint::View => assert!(moved.dot(c.target - c.eye()).abs() < 1e-9, "{con:?}: {moved}"),
            }
            if con == Constraint::View {
                // facing the camera, the point stays under the pointer (up to the grab offset)
                let (sx, sy) = to_screen(&c, q, w, h).unwrap();
                assert!((sx - (x + 57.0)).abs() < 0.5 && (sy - (y - 42.0)).abs() < 0.5, "({sx}, {sy})");
            }
        }
        assert_eq!(Constraint::from_id("xz"), Some(Constraint::Plane(1)));
        assert_eq!(nudge([1.0, 2.0, 3.0], 2, -0.5), [1.0, 2.0, 2.5]);
    }
}
