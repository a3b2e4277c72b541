//! Embeds every scenario file of `static/scenarios/` and `static/multilink/` as a preset: writes
//! `$OUT_DIR/presets.rs`, a list of `Preset { id, json: include_str!(..) }`, the thesis presets
//! first, then the other platform robots by name, then the multi-link robots by name.

use std::path::{Path, PathBuf};
use std::{env, fs};

/// Shown first, in this order; the first is loaded when the page opens.
const FIRST: &[&str] = &["cdpr7", "cdpr7-box", "cdpr7-tree"];
/// The preset directories under `static/`, in the order their files are offered.
const DIRS: &[&str] = &["scenarios", "multilink"];

fn main() {
    let root = Path::new(&env::var("CARGO_MANIFEST_DIR").unwrap()).join("../static");
    let mut files: Vec<(usize, usize, String, PathBuf)> = Vec::new();
    for (d, name) in DIRS.iter().enumerate() {
        let dir = root.join(name);
        println!("cargo:rerun-if-changed={}", dir.display());
        for entry in fs::read_dir(&dir).unwrap_or_else(|e| panic!("reading {}: {e}", dir.display())) {
            let path = entry.unwrap().path();
            if path.extension().is_none_or(|e| e != "json") {
                continue;
            }
            let Some(id) = path.file_stem().and_then(|s| s.to_str()).map(str::to_string) else { continue };
            let first = FIRST.iter().position(|f| *f == id).unwrap_or(FIRST.len());
            files.push((first, d, id, path));
        }
    }
    files.sort();
    assert!(!files.is_empty(), "no scenario file in {}", root.display());
    for w in files.windows(2) {
        assert_ne!(w[0].2, w[1].2, "two presets named {}", w[0].2);
    }

    let mut out = String::from("&[\n");
    for (_, _, id, path) in &files {
        out += &format!("    Preset {{ id: {id:?}, json: include_str!({:?}) }},\n", path.display().to_string());
    }
    out += "]\n";
    fs::write(Path::new(&env::var("OUT_DIR").unwrap()).join("presets.rs"), out).unwrap();
}
