//! The result plots, all SVG with presentation attributes (so an exported file looks as on the
//! page): the t-strip, the tension envelope, the clearances along a path, the slice map and a 3-D
//! slice's atlas; plus exports. Each plot's geometry is built by plain functions, tested natively.

pub mod atlas_space;
pub mod distance;
pub mod export;
pub mod geom;
pub mod lattice;
pub mod section;
pub mod slice;
pub mod strip;
pub mod tension;
pub mod timing;

use leptos::prelude::*;

/// Font of every plot (set on the SVG so exports keep it).
pub const FONT: &str = "system-ui, -apple-system, Segoe UI, Roboto, sans-serif";

/// SVG and PNG export buttons for the SVG element behind `svg_ref`, `width` × `height` in
/// viewBox units; files are named `cablenav-<id>.svg|png`.
#[component]
pub fn ExportButtons(id: &'static str, svg_ref: NodeRef<leptos::svg::Svg>, width: f64, height: f64) -> impl IntoView {
    let file = move |ext: &str| format!("cablenav-{id}.{ext}");
    let save_svg = move |_| {
        if let Some(svg) = svg_ref.get_untracked() {
            export::save(&file("svg"), "image/svg+xml", export::svg_text(&svg).as_bytes());
        }
    };
    let save_png = move |_| {
        if let Some(svg) = svg_ref.get_untracked() {
            export::save_svg_as_png(&svg, &file("png"), width, height);
        }
    };
    view! {
        <button class="small" data-testid=format!("export-{id}-svg") on:click=save_svg title="Save this plot as SVG">"SVG"</button>
        <button class="small" data-testid=format!("export-{id}-png") on:click=save_png title="Save this plot as PNG">"PNG"</button>
    }
}

/// A titled SVG figure `width` × `height` (viewBox units) with SVG and PNG export buttons.
#[component]
pub fn Chart(id: &'static str, title: String, width: f64, height: f64, children: Children) -> impl IntoView {
    let svg_ref = NodeRef::<leptos::svg::Svg>::new();
    view! {
        <figure class="chart" data-testid=format!("chart-{id}")>
            <figcaption>
                <span>{title}</span>
                <ExportButtons id svg_ref width height />
            </figcaption>
            <svg
                node_ref=svg_ref
                xmlns="http://www.w3.org/2000/svg"
                viewBox=format!("0 0 {width} {height}")
                font-family=FONT
                role="img"
                aria-label=id
            >
                {children()}
            </svg>
        </figure>
    }
}
