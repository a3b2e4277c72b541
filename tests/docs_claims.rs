//! Numbers and lists the docs state, checked against the code and the scripts they describe
//! (claims checked elsewhere: the page weight by tests/browser/first-load.mjs, Robocrane's wrench
//! margins by tests/wrench.rs).
//!
//! Native only: it reads the repository's files.
#![cfg(not(target_arch = "wasm32"))]

use std::path::Path;

fn read(relative: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(relative)).unwrap_or_else(|e| panic!("{relative}: {e}"))
}

#[test]
fn angle_rays_are_cut_where_the_docs_say() {
    assert_eq!(cablenav::model::motion::ANGLE_PIECE, std::f64::consts::PI / 8.0);
    let doc = read("docs/verification.md");
    let row = doc.lines().find(|l| l.starts_with("| ray in φ, θ or σ |")).expect("the angle ray's row");
    assert!(row.contains("π/8"), "docs/verification.md: {row}");
}

#[test]
fn the_readme_lists_every_step_of_the_test_script() {
    let script = read("scripts/test.sh");
    let readme = read("README.md");
    let list_start = readme.find("What `scripts/test.sh` runs").expect("README: the list of test steps");
    let list = &readme[list_start..];
    let steps: Vec<&str> = script
        .lines()
        .filter(|l| l.starts_with("node tests/browser/") || l.starts_with("cargo run --release --manifest-path fuzz/"))
        .collect();
    assert!(steps.len() >= 9, "scripts/test.sh: {steps:?}");
    for step in steps {
        // the browser tests are named by their script; the fuzz step by its whole command
        let name = step.split_whitespace().find(|w| w.ends_with(".mjs")).unwrap_or(step);
        assert!(list.contains(name), "README's list of test steps omits `{step}`");
    }
}
