//! The cablenav web page (Leptos, client-side rendering). See `app` for the components and
//! `logic` for what they show; all maths is in the `cablenav` core crate.

mod app;
mod logic;
mod planning;
mod plots;
mod presets;
mod view3d;
mod workbench;

fn main() {
    console_error_panic_hook::set_once();
    leptos::mount::mount_to_body(app::App);
}
