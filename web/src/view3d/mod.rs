//! The 3-D view: a WebGL2 canvas drawing a [`scene::Geometry`], with an orbit camera driven by
//! mouse, touch, wheel and keys, redrawn on demand (never in a busy loop) and resized with the
//! page. What to draw is decided in [`scene`]; the camera maths is in [`camera`].

pub mod camera;
pub mod drag;
mod gl;
pub mod scene;
pub mod tessellate;

use crate::state::Shared;
use camera::{key_op, wheel_zoom, Camera, Pointers};
use drag::{Constraint, Drag};
use glam::DVec3;
use leptos::prelude::*;
use std::cell::RefCell;
use std::rc::Rc;

/// Everything the view shows, computed off the DOM.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneView {
    /// What does not move (uploaded only when it is not the one drawn already).
    pub backdrop: crate::state::Shared<scene::Backdrop>,
    /// The vertex data of what moves.
    pub geometry: scene::Geometry,
    /// The box to fit the camera to when the scenario changes.
    pub bounds: (DVec3, DVec3),
    /// The drawn trajectory sections, `kind:t0:t1` joined by spaces (`data-sections`, for tests).
    pub sections: String,
    /// The cables' looks (see [`scene::cable_look`]), joined by spaces (`data-cables`).
    pub cables: String,
    /// Poses in the drawn planned path (0: none).
    pub path_poses: usize,
    /// Poses in the drawn A* polyline of the lattice planner (0: none; `data-polyline-poses`).
    pub polyline_poses: usize,
    /// Ray lattice pieces drawn (`data-lattice-pieces`).
    pub lattice_pieces: usize,
    /// Section pieces of the scenario's other trajectories drawn beside the selected one.
    pub other_pieces: usize,
    /// The clearance tubes drawn, `cable:radius` (1-based cables) joined by spaces (`data-tubes`).
    pub tubes: String,
}

/// The canvas's mutable state, shared by its event handlers.
struct ViewState {
    renderer: Option<gl::Renderer>,
    /// The backdrop in the renderer.
    backdrop: Option<crate::state::Shared<scene::Backdrop>>,
    camera: Camera,
    pointers: Pointers,
    fitted: Option<(DVec3, DVec3)>,
    frame_pending: bool,
    draws: u32,
    /// The drag in progress: pointer id, handle index and the drag.
    drag: Option<(i32, usize, Drag)>,
    /// The handles' points, to report where they show (`data-handle-px`).
    handle_points: Vec<DVec3>,
}

/// What the user does to a handle in the view.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HandleEvent {
    /// Pressed on handle `i`: a drag begins.
    Begin(usize),
    /// Handle `i` dragged to a point (m, world frame).
    Move(usize, [f64; 3]),
    /// The drag ended.
    End,
}

/// The draggable points the view offers and what it reports of them.
#[derive(Clone, Copy)]
pub struct Handles {
    /// Where the handles are (m, world frame).
    pub points: Signal<Vec<DVec3>>,
    /// The selected handle.
    pub selected: RwSignal<Option<usize>>,
    /// Where a drag may move a handle.
    pub constraint: RwSignal<Constraint>,
    /// Receives the drags.
    pub on_event: Callback<HandleEvent>,
}

type State = Rc<RefCell<ViewState>>;

/// Draws now: sizes the canvas to its box (times the device pixel ratio), then renders.
fn draw(state: &State, canvas: &web_sys::HtmlCanvasElement) {
    let mut st = state.borrow_mut();
    let ratio = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio()).clamp(1.0, 3.0);
    let (w, h) = ((canvas.client_width() as f64 * ratio).round() as u32, (canvas.client_height() as f64 * ratio).round() as u32);
    if w == 0 || h == 0 {
        return;
    }
    if canvas.width() != w || canvas.height() != h {
        canvas.set_width(w);
        canvas.set_height(h);
    }
    st.camera.aspect = w as f64 / h as f64;
    let vp = st.camera.view_projection().as_mat4();
    if let Some(r) = &st.renderer {
        r.draw(vp, w as i32, h as i32);
        st.draws += 1;
        let _ = canvas.set_attribute("data-draws", &st.draws.to_string());
        // where each handle shows, in CSS pixels from the canvas's corner (for tests and tools)
        let (cw, ch) = (canvas.client_width() as f64, canvas.client_height() as f64);
        let px: Vec<String> = st
            .handle_points
            .iter()
            .map(|p| drag::to_screen(&st.camera, *p, cw, ch).map_or_else(|| "-".to_string(), |(x, y)| format!("{x:.1},{y:.1}")))
            .collect();
        let _ = canvas.set_attribute("data-handle-px", &px.join(" "));
    }
}

/// How far a key press nudges the selected handle (m).
pub const NUDGE_M: f64 = 0.05;

/// The pointer's position in the canvas (CSS pixels) and the canvas's size.
fn local(c: &web_sys::HtmlCanvasElement, ev: &web_sys::PointerEvent) -> (f64, f64, f64, f64) {
    let r = c.get_bounding_client_rect();
    (ev.client_x() as f64 - r.left(), ev.client_y() as f64 - r.top(), r.width(), r.height())
}

/// A pointer went up or was cancelled: ends its drag, or its orbit.
fn release(state: &State, id: i32, handles: Handles) {
    let mut s = state.borrow_mut();
    if s.drag.is_some_and(|d| d.0 == id) {
        s.drag = None;
        drop(s);
        handles.on_event.run(HandleEvent::End);
    } else {
        s.pointers.release(id);
    }
}

/// Draws at the next animation frame (once, however often it is asked before then).
fn schedule(state: &State, canvas: &web_sys::HtmlCanvasElement) {
    if std::mem::replace(&mut state.borrow_mut().frame_pending, true) {
        return;
    }
    let (state, canvas) = (state.clone(), canvas.clone());
    request_animation_frame(move || {
        state.borrow_mut().frame_pending = false;
        draw(&state, &canvas);
    });
}

/// The 3-D view of `scene`.
#[component]
pub fn View3d(scene: Memo<Option<Shared<SceneView>>>, handles: Handles) -> impl IntoView {
    let canvas_ref = NodeRef::<leptos::html::Canvas>::new();
    let error = RwSignal::new(None::<String>);
    let state: State = Rc::new(RefCell::new(ViewState {
        renderer: None,
        backdrop: None,
        camera: Camera::default(),
        pointers: Pointers::default(),
        fitted: None,
        frame_pending: false,
        draws: 0,
        drag: None,
        handle_points: Vec::new(),
    }));

    // create the renderer once the canvas exists; upload and redraw whenever the scene changes
    let st = state.clone();
    Effect::new(move |_| {
        let Some(canvas) = canvas_ref.get() else { return };
        let view = scene.get();
        let mut s = st.borrow_mut();
        if s.renderer.is_none() && error.get_untracked().is_none() {
            match gl::Renderer::new(&canvas) {
                Ok(r) => s.renderer = Some(r),
                Err(e) => error.set(Some(format!("The 3-D view needs WebGL2: {e}"))),
            }
        }
        if let Some(view) = view {
            if s.backdrop.as_ref() != Some(&view.0.backdrop) {
                if let Some(r) = s.renderer.as_mut() {
                    r.upload(gl::BACKDROP, &view.0.backdrop.0.geometry);
                    s.backdrop = Some(view.0.backdrop.clone());
                }
            }
            if let Some(r) = s.renderer.as_mut() {
                r.upload(gl::MOVING, &view.0.geometry);
            }
            if s.fitted != Some(view.0.bounds) {
                s.fitted = Some(view.0.bounds);
                s.camera.aspect = (canvas.client_width().max(1) as f64) / (canvas.client_height().max(1) as f64);
                s.camera.fit(view.0.bounds.0, view.0.bounds.1);
            }
        }
        drop(s);
        schedule(&st, &canvas);
    });

    let st = state.clone();
    Effect::new(move |_| {
        let points = handles.points.get();
        st.borrow_mut().handle_points = points;
        if let Some(canvas) = canvas_ref.get_untracked() {
            schedule(&st, &canvas);
        }
    });

    let st = state.clone();
    let resize = window_event_listener(leptos::ev::resize, move |_| {
        if let Some(canvas) = canvas_ref.get_untracked() {
            schedule(&st, &canvas);
        }
    });
    on_cleanup(move || resize.remove());

    // camera operations from events, then a redraw
    let apply = {
        let st = state.clone();
        move |ops: Vec<camera::CameraOp>| {
            let Some(canvas) = canvas_ref.get_untracked() else { return };
            if ops.is_empty() {
                return;
            }
            let h = canvas.client_height() as f64;
            for op in ops {
                op.apply(&mut st.borrow_mut().camera, h);
            }
            schedule(&st, &canvas);
        }
    };
    let (st1, st2, st3, st4) = (state.clone(), state.clone(), state.clone(), state.clone());
    let (ap1, ap2, ap3) = (apply.clone(), apply.clone(), apply);
    let reset = move |_| {
        let Some(canvas) = canvas_ref.get_untracked() else { return };
        let mut s = st4.borrow_mut();
        s.camera = Camera { aspect: s.camera.aspect, ..Camera::default() };
        if let Some((lo, hi)) = s.fitted {
            s.camera.fit(lo, hi);
        }
        drop(s);
        schedule(&st4, &canvas);
    };

    let attr = move |f: fn(&SceneView) -> String| move || scene.get().map(|v| f(&v.0)).unwrap_or_default();
    view! {
        <div class="view3d">
            <canvas
                node_ref=canvas_ref
                data-testid="view3d"
                tabindex="0"
                role="img"
                aria-label="3-D view: drag a yellow handle to move it (a via point, a pose or an obstacle), drag elsewhere to orbit, right-drag or shift-drag to pan, wheel or pinch to zoom; arrow keys orbit, + and - zoom, x y z nudge the selected handle (shift: back)"
                data-sections=attr(|v| v.sections.clone())
                data-cables=attr(|v| v.cables.clone())
                data-path-poses=attr(|v| v.path_poses.to_string())
                data-polyline-poses=attr(|v| v.polyline_poses.to_string())
                data-lattice-pieces=attr(|v| v.lattice_pieces.to_string())
                data-other-pieces=attr(|v| v.other_pieces.to_string())
                data-tubes=attr(|v| v.tubes.clone())
                on:pointerdown=move |ev: web_sys::PointerEvent| {
                    let Some(c) = canvas_ref.get_untracked() else { return };
                    let pan = ev.button() == 2 || ev.shift_key();
                    let (x, y, w, h) = local(&c, &ev);
                    let mut s = st1.borrow_mut();
                    // a press on a handle (one pointer, not panning) drags it; anywhere else orbits
                    let grabbed = (!pan && s.drag.is_none())
                        .then(|| handles.points.with_untracked(|p| drag::pick(&s.camera, p, x, y, w, h).map(|i| (i, p[i]))))
                        .flatten()
                        .and_then(|(i, at)| Drag::begin(&s.camera, at, handles.constraint.get_untracked(), x, y, w, h).map(|d| (i, d)));
                    match grabbed {
                        Some((i, d)) => {
                            s.drag = Some((ev.pointer_id(), i, d));
                            drop(s);
                            handles.selected.set(Some(i));
                            handles.on_event.run(HandleEvent::Begin(i));
                        }
                        None => s.pointers.press(ev.pointer_id(), ev.client_x() as f64, ev.client_y() as f64, pan),
                    }
                    let _ = c.set_pointer_capture(ev.pointer_id());
                }
                on:pointermove=move |ev: web_sys::PointerEvent| {
                    let Some(c) = canvas_ref.get_untracked() else { return };
                    let dragged = {
                        let s = st2.borrow();
                        s.drag.filter(|d| d.0 == ev.pointer_id()).map(|(_, i, d)| {
                            let (x, y, w, h) = local(&c, &ev);
                            (i, d.to(&s.camera, x, y, w, h))
                        })
                    };
                    match dragged {
                        Some((i, Some(p))) => handles.on_event.run(HandleEvent::Move(i, p.to_array())),
                        Some((_, None)) => {}
                        None => {
                            let ops = st2.borrow_mut().pointers.moved(ev.pointer_id(), ev.client_x() as f64, ev.client_y() as f64);
                            ap1(ops)
                        }
                    }
                }
                on:pointerup=move |ev: web_sys::PointerEvent| release(&st3, ev.pointer_id(), handles)
                on:pointercancel={
                    let st = state.clone();
                    move |ev: web_sys::PointerEvent| release(&st, ev.pointer_id(), handles)
                }
                on:wheel=move |ev: web_sys::WheelEvent| {
                    ev.prevent_default();
                    ap2(vec![wheel_zoom(ev.delta_y())])
                }
                on:keydown=move |ev: web_sys::KeyboardEvent| {
                    // with a handle selected, x y z nudge it (+), X Y Z (shift) back (−)
                    if let (Some(i), Some(axis)) = (handles.selected.get_untracked(), ["x", "y", "z"].iter().position(|k| ev.key().eq_ignore_ascii_case(k))) {
                        if let Some(at) = handles.points.with_untracked(|p| p.get(i).copied()) {
                            ev.prevent_default();
                            let step = if ev.shift_key() { -NUDGE_M } else { NUDGE_M };
                            handles.on_event.run(HandleEvent::Begin(i));
                            handles.on_event.run(HandleEvent::Move(i, drag::nudge(at.to_array(), axis, step)));
                            handles.on_event.run(HandleEvent::End);
                            return;
                        }
                    }
                    if let Some(op) = key_op(&ev.key(), ev.shift_key()) {
                        ev.prevent_default();
                        ap3(vec![op])
                    }
                }
                on:contextmenu=|ev: web_sys::MouseEvent| ev.prevent_default()
            ></canvas>
            <button class="reset-view" on:click=reset title="Fit the scene in the view">"Reset view"</button>
            {move || error.get().map(|e| view! { <p class="error" role="alert">{e}</p> })}
        </div>
    }
}
