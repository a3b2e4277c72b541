//! The cablenav web page (Leptos, client-side rendering). `app` holds the page and its result
//! components, `editor` the scenario editor, `persist` sharing and autosave, `help` the help
//! panel; `logic` and `edit_logic` hold what they show as plain, natively tested functions. All
//! maths is in the `cablenav` core crate.

pub mod app;
pub mod edit_logic;
pub mod editor;
pub mod help;
pub mod logic;
pub mod persist;
pub mod presets;

/// Mounts the page on `<body>`.
pub fn start() {
    console_error_panic_hook::set_once();
    leptos::mount::mount_to_body(app::App);
}
