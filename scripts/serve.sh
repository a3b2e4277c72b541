#!/usr/bin/env bash
# README command 1: serve the web page on http://127.0.0.1:8080 (the cdpr7 preset loads first).
# Installs what is missing (scripts/install.sh --serve: the wasm target, wasm-bindgen, trunk;
# trunk compiles once, about 13 minutes on 2 cores), then runs `trunk serve` (Trunk.toml), which
# rebuilds and reloads the page when web/, src/ or static/ change. Extra arguments go to trunk.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

scripts/install.sh --serve
# Fetch the crates now so that trunk can run offline: offline, it uses the installed
# wasm-bindgen 0.2.130 and never tries to download tools (which this network does not allow).
cargo fetch
echo "[serve] http://127.0.0.1:8080 (first build takes a few minutes; Ctrl-C stops)" >&2
exec trunk serve --offline "$@"
