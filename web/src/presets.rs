//! The scenario presets the page offers, embedded at compile time from `static/scenarios/`.

/// One embedded scenario file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Preset {
    /// File stem, e.g. `cdpr7-box`; also the preset's id in the picker.
    pub id: &'static str,
    /// The file's text (scenario JSON).
    pub json: &'static str,
}

/// Every scenario file of `static/scenarios/` (see `build.rs`): the thesis presets `cdpr7`,
/// `cdpr7-box`, `cdpr7-tree` first, then the others by name. The first is loaded on start.
pub const PRESETS: &[Preset] = include!(concat!(env!("OUT_DIR"), "/presets.rs"));

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
    }
}
