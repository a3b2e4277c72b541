//! The scenario presets the page offers, embedded at compile time from `static/scenarios/` and
//! `static/multilink/`.

/// One embedded scenario file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Preset {
    /// File stem, e.g. `cdpr7-box`; also the preset's id in the picker.
    pub id: &'static str,
    /// The file's text (scenario JSON).
    pub json: &'static str,
}

/// Every scenario file of `static/scenarios/` and `static/multilink/` (see `build.rs`): the thesis
/// presets `cdpr7`, `cdpr7-box`, `cdpr7-tree` first, then the other platform robots by name, then
/// the multi-link robots. The first is loaded on start.
pub const PRESETS: &[Preset] = include!(concat!(env!("OUT_DIR"), "/presets.rs"));

/// The name the picker shows for preset `id` (the id itself for a file without one).
pub fn label(id: &str) -> &str {
    match id {
        "cdpr7" => "7-cable (thesis Table 3.1)",
        "cdpr7-box" => "7-cable + box",
        "cdpr7-tree" => "7-cable + tree",
        "robocrane" => "Robocrane (NIST)",
        "robocrane-timed" => "Robocrane, timed, with mass",
        "blank" => "Blank (8-cable frame, to start from)",
        "thesis-fig4-4" => "Thesis Fig. 4.4: paths",
        "thesis-fig4-6-vertical" => "Thesis Fig. 4.6a: vertical",
        "thesis-fig4-6-horizontal" => "Thesis Fig. 4.6b: horizontal",
        "thesis-fig4-7-circle" => "Thesis Fig. 4.7: 1 m circle",
        "laval-cspr3dof" => "Laval CSPR, point mass",
        "bmarm-x4-2" => "4-DoF arm, multi-link",
        other => other,
    }
}

/// The preset with this id, if any.
pub fn find(id: &str) -> Option<usize> {
    PRESETS.iter().position(|p| p.id == id)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_thesis_presets_come_first() {
        let ids: Vec<_> = PRESETS.iter().map(|p| p.id).collect();
        assert_eq!(ids[..3], ["cdpr7", "cdpr7-box", "cdpr7-tree"]);
        assert_eq!(find("cdpr7-box"), Some(1));
        assert_eq!(find("nope"), None);
        assert_eq!(ids.last(), Some(&"bmarm-x4-2"), "the multi-link robots last");
        // the page's own presets, each with its own label
        for id in ["cdpr7", "cdpr7-box", "cdpr7-tree", "robocrane", "robocrane-timed", "laval-cspr3dof", "blank", "bmarm-x4-2"] {
            assert!(find(id).is_some(), "{id}");
            assert_ne!(label(id), id);
        }
    }
}
