#!/usr/bin/env bash
# README command 2: every test. Installs what is missing (scripts/install.sh), then runs, stopping
# at the first failure:
#   1. cargo test --workspace          native unit, integration and doc tests (core + web logic)
#   2. wasm-pack test --node           the core's tests compiled to wasm32, run in node
#   3. wasm-pack test --chrome web     the editor's component tests, in headless Chromium (chromedriver)
#   4. scripts/build-page.sh           the page, built as `trunk serve` builds it (no trunk needed)
#   5. tests/browser/smoke.mjs         the built page in headless Chromium
#   6. tests/browser/e2e-edit.mjs      editing, reload, shared link, embed, files, CASPR (checked
#                                      against the CLI that step 1 built)
#   7. tests/browser/e2e-view.mjs      the page's 3-D view, plots, exports and planning end to end
#                                      (compares with the CLI: builds the release binary if missing)
#   8. tests/browser/e2e-workbench.mjs the layout at 1366×768 and 390×844, dragging a via point in
#                                      3-D (against the CLI), undo/redo, planning in a Web Worker
#                                      while typing and orbiting
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

step() { printf '\n==> %s\n' "$*" >&2; }
started=$SECONDS

step "install missing tools"
scripts/install.sh

step "cargo test --workspace"
cargo test --workspace

step "wasm-pack test --node (core crate on wasm32)"
wasm-pack test --node

step "wasm-pack test --chrome --headless web (editor component tests in Chromium)"
# --chromedriver: use Debian's driver (scripts/install.sh), never a download. web/webdriver.json
# passes Chromium its flags (no sandbox as root, headless).
wasm-pack test --chrome --headless --chromedriver "$(command -v chromedriver)" web

step "build the page"
scripts/build-page.sh target/page

step "browser smoke test"
node tests/browser/smoke.mjs target/page

step "browser end-to-end test of the editor and sharing"
node tests/browser/e2e-edit.mjs target/page

step "browser end-to-end test of the analysis area"
node tests/browser/e2e-view.mjs target/page

step "browser end-to-end test of the workbench (layout, drag, undo, workers)"
node tests/browser/e2e-workbench.mjs target/page

step "all tests passed in $((SECONDS - started)) s"
