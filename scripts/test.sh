#!/usr/bin/env bash
# README command 2: every test. Installs what is missing (scripts/install.sh), then runs, stopping
# at the first failure:
#   1. cargo test --workspace          native unit, integration and doc tests (core + web logic)
#   1b. fuzz/ on stable            1e5 seeded inputs per fuzz target (scenario, verify, CASPR, URL
#                                      fragment), no panic allowed; prints the counts
#   2. wasm-pack test --node           the core's tests compiled to wasm32, run in node
#   3. wasm-pack test --chrome web     the editor's component tests, in headless Chromium (chromedriver)
#   4. scripts/build-page.sh           the page as deployed (profile `page`, wasm-opt -Oz; no trunk needed)
#   4b. tests/browser/first-load.mjs   its first load on a throttled network (slow 4G): wasm + js over
#                                      the wire at most 1.0 MB, the time to the first strip printed
#   5. tests/browser/smoke.mjs         the built page in headless Chromium
#   6. tests/browser/e2e-edit.mjs      editing, reload, shared link, embed, files, CASPR (checked
#                                      against the CLI that step 1 built)
#   7. tests/browser/e2e-view.mjs      the page's 3-D view, plots, exports and planning end to end
#                                      (compares with the CLI step 1 built, brought up to date)
#   8. tests/browser/e2e-workbench.mjs the layout at 1366×768 and 390×844, the results tabs,
#                                      dragging a via point in 3-D (against the CLI), undo/redo,
#                                      planning in a Web Worker while typing and orbiting (frames
#                                      compared with idle ones of the same run)
#   8b. tests/browser/e2e-lattice.mjs  the ray lattice panel and 3-D drawing against `cablenav lattice`,
#                                      Cancel, lattice planning in a worker (cdpr7-box over-box,
#                                      Robocrane q1-q2) against `cablenav verify`
#   8c. tests/browser/e2e-multilink.mjs the 4-DoF arm: strip, 3-D view, joint sliders, the α–β
#                                      slice map and ray lattice against `cablenav verify|check|slice|lattice`
#   8d. tests/browser/e2e-timing.mjs   timed trajectories and the platform's mass: sections in
#                                      seconds and the fastest uniform timing, the tension plot
#                                      against time, the fastest safe timing and its Cancel, a
#                                      duration, a timed spline and a mass edited, against
#                                      `cablenav verify|envelope|time`
#   9. python/ (maturin, pytest)       the wheel built and installed into target/venv; pytest
#                                      compares it with the CLI that step 1 built, runs the sweep
#                                      example serially, on threads and on a Dask LocalCluster
#  10. npm/ (wasm-pack, node --test)   the npm package built for --target web and bundler, packed,
#                                      unpacked as a user installs it and tested in node against
#                                      the CLI; docs/course-page.html (the package without Leptos)
#                                      in headless Chromium
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

step() { printf '\n==> %s\n' "$*" >&2; }
started=$SECONDS

step "install missing tools"
scripts/install.sh

step "cargo test --workspace"
cargo test --workspace

step "stable fuzzing: 1e5 inputs per target (fuzz/src/bin/stable.rs)"
cargo run --release --manifest-path fuzz/Cargo.toml --bin stable -- --runs 100000 --seed 1

step "wasm-pack test --node (core crate on wasm32)"
wasm-pack test --node

step "wasm-pack test --chrome --headless web (editor component tests in Chromium)"
# --chromedriver: use Debian's driver (scripts/install.sh), never a download. web/webdriver.json
# passes Chromium its flags (no sandbox as root, headless).
wasm-pack test --chrome --headless --chromedriver "$(command -v chromedriver)" web

step "build the page"
scripts/build-page.sh target/page

step "the page's first load on a throttled network"
node tests/browser/first-load.mjs target/page

step "browser smoke test"
node tests/browser/smoke.mjs target/page

step "browser end-to-end test of the editor and sharing"
node tests/browser/e2e-edit.mjs target/page

step "browser end-to-end test of the analysis area"
node tests/browser/e2e-view.mjs target/page

step "browser end-to-end test of the workbench (layout, drag, undo, workers)"
node tests/browser/e2e-workbench.mjs target/page

step "browser end-to-end test of the ray lattice and lattice planning"
node tests/browser/e2e-lattice.mjs target/page

step "browser end-to-end test of a multi-link robot (the 4-DoF arm)"
node tests/browser/e2e-multilink.mjs target/page

step "browser end-to-end test of timed trajectories and the platform's mass"
node tests/browser/e2e-timing.mjs target/page

step "Python package: build the wheel, install it into target/venv, pytest"
# The dev profile (opt-level 2) reuses step 1's build of the core; --force-reinstall replaces
# an older build of the same version.
rm -f target/wheels/cablenav-*.whl
target/venv/bin/maturin build --quiet -m python/Cargo.toml -o target/wheels
target/venv/bin/pip install --quiet --disable-pip-version-check --force-reinstall --no-deps target/wheels/cablenav-*.whl
(cd python && CABLENAV="$PWD/../target/debug/cablenav" ../target/venv/bin/python -m pytest -q -p no:cacheprovider tests)

step "npm package: wasm-pack (web, bundler), npm pack, node test, the course page in Chromium"
# After step 4: the release wasm32 build of the core's dependencies is reused.
rm -f target/npm/cablenav-*.tgz
npm/build.sh --pack
(cd npm && CABLENAV="$PWD/../target/debug/cablenav" node --test test/)
node tests/browser/course-page.mjs

step "all tests passed in $((SECONDS - started)) s"
