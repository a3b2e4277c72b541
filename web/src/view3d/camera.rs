//! The orbit camera of the 3-D view (z up) and the pointer gestures that move it: one pointer
//! (left mouse button, one finger) orbits, the right button, shift-drag or two fingers pan, the
//! wheel or a pinch zooms. Plain maths over glam, no DOM, so it is tested natively.

use glam::{DMat4, DVec3};
use std::collections::BTreeMap;

/// Radians of orbit per pixel dragged.
const ORBIT_PER_PX: f64 = 0.008;
/// The pitch stays inside ±this (radians), short of the poles where "up" is undefined.
const MAX_PITCH: f64 = 1.55;

/// A camera looking at `target` from `distance` away, at azimuth `yaw` and elevation `pitch`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    /// The point looked at (and orbited around).
    pub target: DVec3,
    /// Azimuth about +z, radians.
    pub yaw: f64,
    /// Elevation above the xy plane, radians.
    pub pitch: f64,
    /// Distance from the eye to the target.
    pub distance: f64,
    /// Vertical field of view, radians.
    pub fov_y: f64,
    /// Viewport width / height.
    pub aspect: f64,
}

impl Default for Camera {
    fn default() -> Self {
        Camera { target: DVec3::ZERO, yaw: -1.1, pitch: 0.45, distance: 10.0, fov_y: 0.8, aspect: 1.5 }
    }
}

impl Camera {
    /// Where the eye is.
    pub fn eye(&self) -> DVec3 {
        let (sy, cy) = self.yaw.sin_cos();
        let (sp, cp) = self.pitch.sin_cos();
        self.target + self.distance * DVec3::new(cp * cy, cp * sy, sp)
    }

    /// World → clip space (OpenGL conventions).
    pub fn view_projection(&self) -> DMat4 {
        let view = DMat4::look_at_rh(self.eye(), self.target, DVec3::Z);
        let near = self.distance * 0.01;
        let far = self.distance * 100.0;
        DMat4::perspective_rh_gl(self.fov_y, self.aspect.max(1e-3), near, far) * view
    }

    /// Turns by a drag of (dx, dy) pixels.
    pub fn orbit(&mut self, dx: f64, dy: f64) {
        self.yaw -= dx * ORBIT_PER_PX;
        self.pitch = (self.pitch + dy * ORBIT_PER_PX).clamp(-MAX_PITCH, MAX_PITCH);
    }

    /// Moves closer (factor < 1) or away (factor > 1); the distance stays within [1e-3, 1e4].
    pub fn zoom(&mut self, factor: f64) {
        if factor.is_finite() && factor > 0.0 {
            self.distance = (self.distance * factor).clamp(1e-3, 1e4);
        }
    }

    /// Slides the target so that the scene follows a drag of (dx, dy) pixels in a viewport
    /// `height` pixels tall (points at the target's depth move with the pointer).
    pub fn pan(&mut self, dx: f64, dy: f64, height: f64) {
        let per_px = 2.0 * self.distance * (self.fov_y / 2.0).tan() / height.max(1.0);
        let forward = (self.target - self.eye()).normalize();
        let right = forward.cross(DVec3::Z).normalize();
        let up = right.cross(forward);
        self.target += (-dx * right + dy * up) * per_px;
    }

    /// Looks at the box [min, max] from the current direction, from just far enough that its
    /// bounding sphere fits the view.
    pub fn fit(&mut self, min: DVec3, max: DVec3) {
        self.target = (min + max) / 2.0;
        let radius = ((max - min).length() / 2.0).max(1e-3);
        let half_y = self.fov_y / 2.0;
        let half_x = (half_y.tan() * self.aspect.max(1e-3)).atan();
        self.distance = radius / half_y.min(half_x).sin() * 1.05;
    }
}

/// What a gesture asks of the camera.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CameraOp {
    /// [`Camera::orbit`] by (dx, dy) pixels.
    Orbit(f64, f64),
    /// [`Camera::pan`] by (dx, dy) pixels.
    Pan(f64, f64),
    /// [`Camera::zoom`] by a factor.
    Zoom(f64),
}

impl CameraOp {
    /// Applies the operation to `camera` in a viewport `height` pixels tall.
    pub fn apply(self, camera: &mut Camera, height: f64) {
        match self {
            CameraOp::Orbit(dx, dy) => camera.orbit(dx, dy),
            CameraOp::Pan(dx, dy) => camera.pan(dx, dy, height),
            CameraOp::Zoom(f) => camera.zoom(f),
        }
    }
}

/// The zoom factor of a wheel turn of `delta_y` pixels (positive: away).
pub fn wheel_zoom(delta_y: f64) -> CameraOp {
    CameraOp::Zoom((delta_y.clamp(-500.0, 500.0) * 0.0015).exp())
}

/// The camera operation of a key on the focused view: arrows orbit, shift+arrows pan, `+`/`-`
/// zoom; `None` for other keys.
pub fn key_op(key: &str, shift: bool) -> Option<CameraOp> {
    const STEP: f64 = 24.0;
    let (dx, dy) = match key {
        "ArrowLeft" => (-STEP, 0.0),
        "ArrowRight" => (STEP, 0.0),
        "ArrowUp" => (0.0, -STEP),
        "ArrowDown" => (0.0, STEP),
        "+" | "=" => return Some(CameraOp::Zoom(0.85)),
        "-" | "_" => return Some(CameraOp::Zoom(1.0 / 0.85)),
        _ => return None,
    };
    Some(if shift { CameraOp::Pan(dx, dy) } else { CameraOp::Orbit(dx, dy) })
}

/// The pointers currently pressed on the view (mouse buttons, fingers, pens), by pointer id.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Pointers {
    down: BTreeMap<i32, (f64, f64, bool)>,
}

impl Pointers {
    /// A pointer went down at (x, y); `pan` for the right button or shift.
    pub fn press(&mut self, id: i32, x: f64, y: f64, pan: bool) {
        self.down.insert(id, (x, y, pan));
    }

    /// A pointer went up or was cancelled.
    pub fn release(&mut self, id: i32) {
        self.down.remove(&id);
    }

    /// A pointer moved to (x, y): the camera operations this makes. One pointer orbits (or pans
    /// if pressed for panning); with two, the change of their distance zooms and their midpoint
    /// pans. Pointers that are not down are ignored.
    pub fn moved(&mut self, id: i32, x: f64, y: f64) -> Vec<CameraOp> {
        let Some(&(px, py, pan)) = self.down.get(&id) else { return vec![] };
        let mut ops = Vec::new();
        if self.down.len() == 1 {
            let (dx, dy) = (x - px, y - py);
            ops.push(if pan { CameraOp::Pan(dx, dy) } else { CameraOp::Orbit(dx, dy) });
        } else if let Some(&(ox, oy, _)) = self.down.iter().find(|(k, _)| **k != id).map(|(_, v)| v) {
            let before = ((px - ox).powi(2) + (py - oy).powi(2)).sqrt();
            let after = ((x - ox).powi(2) + (y - oy).powi(2)).sqrt();
            if before > 1.0 && after > 1.0 {
                ops.push(CameraOp::Zoom(before / after));
            }
            // the midpoint moves by half the moving pointer's displacement
            ops.push(CameraOp::Pan((x - px) / 2.0, (y - py) / 2.0));
        }
        self.down.insert(id, (x, y, pan));
        ops
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Clip → normalised device coordinates.
    fn ndc(c: &Camera, p: DVec3) -> DVec3 {
        c.view_projection().project_point3(p)
    }

    #[test]
    fn the_target_is_at_the_centre_of_the_view() {
        let mut c = Camera { target: DVec3::new(1.0, 2.0, 3.0), ..Camera::default() };
        for (yaw, pitch) in [(0.0, 0.0), (1.0, 0.5), (-2.0, -1.2)] {
            c.yaw = yaw;
            c.pitch = pitch;
            let p = ndc(&c, c.target);
            assert!(p.x.abs() < 1e-12 && p.y.abs() < 1e-12, "{p}");
            assert!(((c.eye() - c.target).length() - c.distance).abs() < 1e-12);
        }
    }

    #[test]
    fn up_is_up_on_screen() {
        let c = Camera::default();
        let above = ndc(&c, c.target + DVec3::Z);
        assert!(above.y > 0.0 && above.x.abs() < 1e-9, "{above}");
    }

    #[test]
    fn orbit_keeps_the_distance_and_clamps_the_pitch() {
        let mut c = Camera::default();
        c.orbit(100.0, 10_000.0);
        assert_eq!(c.pitch, MAX_PITCH);
        assert!((c.yaw - (-1.1 - 0.8)).abs() < 1e-12);
        assert!(((c.eye() - c.target).length() - c.distance).abs() < 1e-9);
    }

    #[test]
    fn zoom_scales_and_ignores_nonsense() {
        let mut c = Camera::default();
        c.zoom(0.5);
        assert_eq!(c.distance, 5.0);
        c.zoom(f64::NAN);
        c.zoom(-1.0);
        assert_eq!(c.distance, 5.0);
        c.zoom(1e9);
        assert_eq!(c.distance, 1e4);
        assert!(matches!(wheel_zoom(100.0), CameraOp::Zoom(f) if f > 1.0));
        assert!(matches!(wheel_zoom(-100.0), CameraOp::Zoom(f) if f < 1.0));
    }

    #[test]
    fn pan_moves_a_point_at_the_target_depth_with_the_pointer() {
        let mut c = Camera::default();
        let h = 600.0;
        let p = c.target;
        let before = ndc(&c, p);
        c.pan(30.0, -20.0, h);
        let after = ndc(&c, p);
        // NDC spans 2 over h pixels vertically and 2 over h·aspect horizontally
        let dx_px = (after.x - before.x) / 2.0 * h * c.aspect;
        let dy_px = -(after.y - before.y) / 2.0 * h;
        assert!((dx_px - 30.0).abs() < 1e-6 && (dy_px + 20.0).abs() < 1e-6, "{dx_px} {dy_px}");
    }

    #[test]
    fn fit_shows_every_corner_of_the_box() {
        for aspect in [0.5, 1.0, 2.5] {
            let mut c = Camera { aspect, ..Camera::default() };
            let (min, max) = (DVec3::new(-1.0, 0.0, 0.0), DVec3::new(4.0, 4.0, 4.0));
            c.fit(min, max);
            for i in 0..8 {
                let corner = DVec3::new(
                    if i & 1 == 0 { min.x } else { max.x },
                    if i & 2 == 0 { min.y } else { max.y },
                    if i & 4 == 0 { min.z } else { max.z },
                );
                let p = ndc(&c, corner);
                assert!(p.x.abs() <= 1.0 && p.y.abs() <= 1.0 && p.z.abs() <= 1.0, "aspect {aspect}: {corner} → {p}");
            }
        }
    }

    #[test]
    fn keys_move_the_camera() {
        assert_eq!(key_op("ArrowLeft", false), Some(CameraOp::Orbit(-24.0, 0.0)));
        assert_eq!(key_op("ArrowDown", true), Some(CameraOp::Pan(0.0, 24.0)));
        assert!(matches!(key_op("+", false), Some(CameraOp::Zoom(f)) if f < 1.0));
        assert!(matches!(key_op("-", false), Some(CameraOp::Zoom(f)) if f > 1.0));
        assert_eq!(key_op("a", false), None);
    }

    #[test]
    fn one_pointer_orbits_or_pans_two_pinch() {
        let mut p = Pointers::default();
        assert!(p.moved(1, 5.0, 5.0).is_empty(), "not pressed");
        p.press(1, 0.0, 0.0, false);
        assert_eq!(p.moved(1, 10.0, -4.0), [CameraOp::Orbit(10.0, -4.0)]);
        p.release(1);
        p.press(2, 0.0, 0.0, true);
        assert_eq!(p.moved(2, 3.0, 4.0), [CameraOp::Pan(3.0, 4.0)]);
        p.press(3, 103.0, 4.0, false);
        // pointer 3 moves away from pointer 2 (at 3, 4): distance 100 → 200, zoom in by 2
        assert_eq!(p.moved(3, 203.0, 4.0), [CameraOp::Zoom(0.5), CameraOp::Pan(50.0, 0.0)]);
        p.release(2);
        p.release(3);
        assert!(p.moved(3, 0.0, 0.0).is_empty(), "released");
    }
}
