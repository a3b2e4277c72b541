//! The page's colours, in one place: the sections' green, red and grey, the 3-D scene's cables,
//! platform, obstacles and handles, the ray lattice's component colours — as RGBA for WebGL and
//! as CSS for the SVG plots, so the strip, the plots and the 3-D view agree.

use crate::logic::SectionKind;

/// An RGBA colour.
pub type Rgba = [f32; 4];

/// Feasible sections (the page's green).
pub const GREEN: Rgba = [0.18, 0.62, 0.29, 1.0];
/// Infeasible sections and interfering cables (the page's red).
pub const RED: Rgba = [0.83, 0.23, 0.23, 1.0];
/// Uncertain sections.
pub const GREY: Rgba = [0.6, 0.6, 0.6, 1.0];
/// The planned path.
pub const PATH: Rgba = [0.42, 0.23, 0.83, 1.0];
/// Cables when there is no tension information.
pub const CABLE: Rgba = [0.2, 0.25, 0.3, 1.0];
/// Cable colour at a comfortable tension margin (a quarter of the bounds' span or more).
pub const CABLE_EASY: Rgba = [0.23, 0.44, 0.85, 1.0];
/// Cable colour at zero tension margin.
pub const CABLE_TIGHT: Rgba = [0.9, 0.57, 0.12, 1.0];
/// Cable colour when its tension range leaves its bounds.
pub const CABLE_OUT: Rgba = [0.56, 0.23, 0.83, 1.0];
pub const PLATFORM: Rgba = [0.35, 0.4, 0.47, 0.6];
pub const ANCHOR: Rgba = [0.12, 0.14, 0.16, 1.0];
/// Clearance tubes at a boundary.
pub const TUBE: Rgba = [0.83, 0.23, 0.23, 0.3];
/// Draggable handles, and the selected one.
pub const HANDLE: Rgba = [0.95, 0.78, 0.1, 1.0];
pub const HANDLE_SELECTED: Rgba = [1.0, 0.45, 0.0, 1.0];
pub const GRID: Rgba = [0.8, 0.83, 0.86, 1.0];
pub const AXES: [Rgba; 3] = [[0.85, 0.2, 0.2, 1.0], [0.2, 0.65, 0.25, 1.0], [0.2, 0.35, 0.9, 1.0]];
/// Obstacle colours, by obstacle index, translucent.
pub const OBSTACLES: [Rgba; 5] =
    [[0.55, 0.45, 0.3, 0.55], [0.3, 0.55, 0.5, 0.55], [0.6, 0.5, 0.2, 0.55], [0.45, 0.45, 0.65, 0.55], [0.6, 0.35, 0.45, 0.55]];

/// The colour of a section kind.
pub fn kind_colour(kind: SectionKind) -> Rgba {
    match kind {
        SectionKind::Feasible => GREEN,
        SectionKind::Infeasible => RED,
        SectionKind::Uncertain => GREY,
    }
}

/// A colour as CSS `rgb(..)`.
pub fn css(c: Rgba) -> String {
    format!("rgb({}, {}, {})", (c[0] * 255.0).round(), (c[1] * 255.0).round(), (c[2] * 255.0).round())
}

/// Colour of infeasible ray parts.
pub const INFEASIBLE: &str = "#d03b3b";
/// Component colours, in turn (the first is the thesis' green).
pub const COMPONENTS: [&str; 8] = ["#2ea043", "#3b6fd8", "#8e44ad", "#e0a800", "#16a2b8", "#c2185b", "#6d8b00", "#795548"];

/// The colour of a ray piece: its component's, or [`INFEASIBLE`]; as CSS.
pub fn component_colour(component: Option<usize>) -> &'static str {
    component.map_or(INFEASIBLE, |c| COMPONENTS[c % COMPONENTS.len()])
}

/// The same colour for the 3-D view.
pub fn component_rgba(component: Option<usize>) -> Rgba {
    let hex = component_colour(component);
    let byte = |k: usize| u8::from_str_radix(&hex[1 + 2 * k..3 + 2 * k], 16).unwrap_or(0) as f32 / 255.0;
    [byte(0), byte(1), byte(2), 1.0]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn component_colours_are_the_same_in_both_views() {
        assert_eq!(component_rgba(None), [208.0 / 255.0, 59.0 / 255.0, 59.0 / 255.0, 1.0]);
        assert_eq!(component_rgba(Some(0)), [46.0 / 255.0, 160.0 / 255.0, 67.0 / 255.0, 1.0]);
        assert_eq!(component_colour(Some(COMPONENTS.len() + 1)), COMPONENTS[1], "colours repeat");
    }
}
