#!/usr/bin/env bash
# README command 2: every test. Installs what is missing (scripts/install.sh), then runs, stopping
# at the first failure:
#   1. cargo test --workspace          native unit, integration and doc tests (core + web logic)
#   2. wasm-pack test --node           the core's tests compiled to wasm32, run in node
#   3. scripts/build-page.sh           the page, built as `trunk serve` builds it (no trunk needed)
#   4. tests/browser/smoke.mjs         the built page in headless Chromium
#   5. tests/browser/e2e-view.mjs      the page's 3-D view, plots, exports and planning end to end
#                                      (compares with the CLI: builds the release binary if missing)
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

step "build the page"
scripts/build-page.sh target/page

step "browser smoke test"
node tests/browser/smoke.mjs target/page

step "browser end-to-end test of the analysis area"
node tests/browser/e2e-view.mjs target/page

step "all tests passed in $((SECONDS - started)) s"
