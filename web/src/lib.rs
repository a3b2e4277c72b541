//! The cablenav web page (Leptos, client-side rendering). `app` holds the page and its result
//! components, `editor` the scenario editor, `persist` sharing and autosave, `help` the help
//! panel, `workbench` the analysis area (`view3d` the WebGL view, `plots` the SVG plots,
//! `planning` the planner driven between frames); `logic` and `edit_logic` hold what they show as plain, natively tested functions. All
//! maths is in the `cablenav` core crate.

pub mod app;
pub mod edit_logic;
pub mod editor;
pub mod help;
pub mod logic;
pub mod persist;
mod planning;
mod plots;
pub mod presets;
mod view3d;
mod workbench;

/// Mounts the page on `<body>`.
pub fn start() {
    console_error_panic_hook::set_once();
    leptos::mount::mount_to_body(app::App);
}
