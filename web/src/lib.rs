//! The cablenav web page (Leptos, client-side rendering). `state` holds the page's state types,
//! `app` the page and its top bar, `editor` the scenario editor, `persist` sharing and
//! autosave, `help` the help panel, `workbench` the analysis area (`view3d` the WebGL view,
//! `plots` the SVG plots, `planning` the planning controls, `joints` a multi-link robot's joint
//! sliders, `live` the verification during a drag), `palette` the colours they share, `rays` a lattice's rays
//! in pieces, `results` the verdict's strip and tables, `tabs` the results tabs, `worker` the Web Workers that run planning and slice maps; `logic` and
//! `edit_logic` hold what they show as plain, natively tested functions. All maths is in the
//! `cablenav` core crate.

pub mod app;
pub mod edit_logic;
pub mod editor;
pub mod help;
mod joints;
mod live;
pub mod logic;
mod palette;
pub mod persist;
mod planning;
mod plots;
pub mod presets;
mod rays;
mod results;
pub mod state;
mod tabs;
mod view3d;
mod workbench;
pub mod worker;

/// Mounts the page on `<body>`.
pub fn start() {
    console_error_panic_hook::set_once();
    leptos::mount::mount_to_body(app::App);
}
