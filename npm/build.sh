#!/usr/bin/env bash
# Builds the npm package `cablenav` in npm/: the core compiled to WebAssembly by wasm-pack
# (crate npm/, wasm-bindgen API in npm/src/lib.rs) for two targets,
#   npm/web/      --target web      (ES module + init(); browsers without a bundler, node)
#   npm/bundler/  --target bundler  (webpack, Vite, Rollup: the package's main entry)
# and packs it with `npm pack` into target/npm/cablenav-VERSION.tgz when given --pack.
# wasm-opt is off (its download is not reachable here: Cargo.toml's wasm-pack metadata).
set -euo pipefail
cd "$(dirname "$0")"
export PATH="$HOME/.cargo/bin:$PATH"
for target in web bundler; do
  wasm-pack build --quiet --release --target "$target" --out-dir "$target" --out-name cablenav --no-pack
  # wasm-pack's own .gitignore would hide the build from `npm pack`; package.json is ours.
  rm -f "$target/.gitignore" "$target/package.json" "$target/README.md"
done
if [ "${1:-}" = "--pack" ]; then
  mkdir -p ../target/npm
  npm pack --silent --pack-destination ../target/npm >/dev/null
  ls ../target/npm/cablenav-*.tgz
fi
