#!/usr/bin/env bash
# Builds the web page without trunk: the same app, HTML, CSS and assets that `trunk serve` builds
# from web/index.html, into an output directory (default target/page): the page as deployed, built
# for size (Cargo.toml's `page` profile, which the rust link names in data-cargo-profile-release)
# and shrunk by wasm-opt -Oz.
#   scripts/build-page.sh [OUT_DIR]
# Needs the wasm32 target, wasm-bindgen-cli 0.2.130 and npm's binaryen in scripts/wasm-opt/;
# scripts/install.sh installs them. Prints the gzip size.
#
# Each `<link data-trunk ...>` line of web/index.html is handled as Trunk handles it:
#   rel="rust"      -> cargo build --profile P (P from data-cargo-profile-release) + wasm-bindgen
#                      --target web + wasm-opt -Oz; a module script that inits it
#   rel="css"       -> copied; a plain stylesheet link
#   rel="copy-dir"  -> the directory copied into OUT_DIR under its own name
#   rel="copy-file" -> the file copied into OUT_DIR
# (no content hashes in the file names). Trunk's own wasm-opt stays off (data-wasm-opt="0"): it
# would download binaryen, which this network refuses; `trunk serve` is the quick dev loop.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

OUT=${1:-target/page}
SRC_DIR=web
SRC_HTML=$SRC_DIR/index.html
CRATE=cablenav-web
TARGET_DIR=${CARGO_TARGET_DIR:-target}

say() { printf '[build-page] %s\n' "$*" >&2; }
die() { say "error: $*"; exit 1; }

attr() { # attr NAME LINE: the value of NAME="..." in LINE
  sed -nE "s/.*[[:space:]]$1=\"([^\"]*)\".*/\1/p" <<<"$2"
}

command -v wasm-bindgen >/dev/null || die "wasm-bindgen not found: run scripts/install.sh"
WASM_OPT=scripts/wasm-opt/node_modules/.bin/wasm-opt   # npm's binaryen, pinned in scripts/wasm-opt/
[ -x "$WASM_OPT" ] || die "$WASM_OPT not found: run scripts/install.sh"

RUST_LINK=$(grep '<link[^>]*data-trunk[^>]*rel="rust"' "$SRC_HTML" || true)
PROFILE=$(attr data-cargo-profile-release "$RUST_LINK")
[ -n "$PROFILE" ] || die "web/index.html: the rust link must name its data-cargo-profile-release"

# The wasm features rustc emits for wasm32-unknown-unknown; wasm-opt must accept them all.
WASM_FEATURES=(--enable-bulk-memory --enable-sign-ext --enable-mutable-globals
  --enable-nontrapping-float-to-int --enable-reference-types --enable-multivalue)

say "cargo build --profile $PROFILE --target wasm32-unknown-unknown -p $CRATE"
cargo build --profile "$PROFILE" --target wasm32-unknown-unknown -p "$CRATE"
WASM="$TARGET_DIR/wasm32-unknown-unknown/$PROFILE/$CRATE.wasm"
[ -f "$WASM" ] || die "no $WASM after the build"

rm -rf "$OUT"
mkdir -p "$OUT"
say "wasm-bindgen --target web --no-typescript -> $OUT"
wasm-bindgen --target web --no-typescript --out-dir "$OUT" --out-name "$CRATE" "$WASM"
say "wasm-opt -Oz ($("$WASM_OPT" --version))"
"$WASM_OPT" -Oz "${WASM_FEATURES[@]}" "$OUT/${CRATE}_bg.wasm" -o "$OUT/${CRATE}_bg.opt.wasm"
mv "$OUT/${CRATE}_bg.opt.wasm" "$OUT/${CRATE}_bg.wasm"

# Derive OUT/index.html from web/index.html, line by line.
HTML_OUT="$OUT/index.html"
: >"$HTML_OUT"
rust_links=0
while IFS= read -r line || [ -n "$line" ]; do
  if ! grep -q '<link[^>]*data-trunk' <<<"$line"; then
    printf '%s\n' "$line" >>"$HTML_OUT"
    continue
  fi
  indent=$(sed -E 's/^([[:space:]]*).*/\1/' <<<"$line")
  rel=$(attr rel "$line")
  href=$(attr href "$line")
  case "$rel" in
    rust)
      rust_links=$((rust_links + 1))
      [ "$(attr data-wasm-opt "$line")" = "0" ] || die "web/index.html: the rust link must keep data-wasm-opt=\"0\""
      {
        printf '%s<link rel="modulepreload" href="./%s.js" />\n' "$indent" "$CRATE"
        printf '%s<link rel="preload" href="./%s_bg.wasm" as="fetch" type="application/wasm" crossorigin="" />\n' "$indent" "$CRATE"
        printf '%s<script type="module">\n' "$indent"
        printf '%s  import init, * as bindings from "./%s.js";\n' "$indent" "$CRATE"
        printf '%s  const wasm = await init({ module_or_path: "./%s_bg.wasm" });\n' "$indent" "$CRATE"
        printf '%s  window.wasmBindings = bindings;\n' "$indent"
        printf '%s  dispatchEvent(new CustomEvent("TrunkApplicationStarted", { detail: { wasm } }));\n' "$indent"
        printf '%s</script>\n' "$indent"
      } >>"$HTML_OUT"
      ;;
    css)
      [ -f "$SRC_DIR/$href" ] || die "web/index.html: css $href not found"
      cp "$SRC_DIR/$href" "$OUT/$(basename "$href")"
      printf '%s<link rel="stylesheet" href="./%s" />\n' "$indent" "$(basename "$href")" >>"$HTML_OUT"
      ;;
    copy-dir)
      [ -d "$SRC_DIR/$href" ] || die "web/index.html: directory $href not found"
      cp -r "$SRC_DIR/$href" "$OUT/$(basename "$href")"
      ;;
    copy-file)
      [ -f "$SRC_DIR/$href" ] || die "web/index.html: file $href not found"
      cp "$SRC_DIR/$href" "$OUT/$(basename "$href")"
      ;;
    *) die "web/index.html: unsupported data-trunk link rel=\"$rel\" (teach scripts/build-page.sh)" ;;
  esac
done <"$SRC_HTML"
[ "$rust_links" = 1 ] || die "web/index.html must have exactly one data-trunk rust link, found $rust_links"

gz() { gzip -9 -c "$1" | wc -c; }
wasm_raw=$(wc -c <"$OUT/${CRATE}_bg.wasm")
wasm_gz=$(gz "$OUT/${CRATE}_bg.wasm")
js_raw=$(wc -c <"$OUT/$CRATE.js")
js_gz=$(gz "$OUT/$CRATE.js")
say "built $OUT/"
total_gz=$((wasm_gz + js_gz))
printf 'page weight: wasm %d B (gzip %d B), js %d B (gzip %d B); wasm+js gzip %d B = %s KiB\n' \
  "$wasm_raw" "$wasm_gz" "$js_raw" "$js_gz" "$total_gz" "$(awk -v b="$total_gz" 'BEGIN { printf "%.1f", b / 1024 }')"
