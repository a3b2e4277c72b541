//! Embeds every scenario file of `static/scenarios/` as a preset: writes `$OUT_DIR/presets.rs`,
//! a list of `Preset { id, json: include_str!(..) }`, the thesis presets first, then the rest by name.

use std::path::Path;
use std::{env, fs};

/// Shown first, in this order; the first is loaded when the page opens.
const FIRST: &[&str] = &["cdpr7", "cdpr7-box", "cdpr7-tree"];

fn main() {
    let dir = Path::new(&env::var("CARGO_MANIFEST_DIR").unwrap()).join("../static/scenarios");
    println!("cargo:rerun-if-changed={}", dir.display());
    let mut ids: Vec<String> = fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("reading {}: {e}", dir.display()))
        .filter_map(|entry| {
            let path = entry.ok()?.path();
            (path.extension()? == "json").then(|| path.file_stem()?.to_str().map(str::to_string))?
        })
        .collect();
    ids.sort_by_key(|id| (FIRST.iter().position(|f| f == id).unwrap_or(FIRST.len()), id.clone()));
    assert!(!ids.is_empty(), "no scenario file in {}", dir.display());

    let mut out = String::from("&[\n");
    for id in &ids {
        let path = dir.join(format!("{id}.json"));
        out += &format!("    Preset {{ id: {id:?}, json: include_str!({:?}) }},\n", path.display().to_string());
    }
    out += "]\n";
    fs::write(Path::new(&env::var("OUT_DIR").unwrap()).join("presets.rs"), out).unwrap();
}
